//! The live numbers: q1, q2 (rad, deg), tip x, y (mm), det J, Yoshikawa manipulability
//! `w = sqrt(det(J Jᵀ))`, the singular values and the 2×2 Jacobian. Each number is the text of
//! an element `[data-readout="<name>"]`, plain (parseable) digits with the unit in a sibling
//! element; an element is only written when its text changes.
//!
//! Two more views of the same numbers: a compact strip over the arm view (q1, q2, x, y, w;
//! shown at phone width, where the panel sits far below the arm) and, for screen readers, a
//! polite live region that says the pose once the arm has been still for a moment (a drag or
//! a run of key presses is one sentence, not fifty).

use std::cell::RefCell;
use std::rc::Rc;

use wasm_bindgen::JsValue;
use web_sys::Element;

use super::role;
use crate::planar2r::PoseReport;
use crate::ui::ctx::{self, t_strings};
use crate::ui::schedule::Timer;
use crate::view::ik2r::{fmt_fixed, fmt_sig, readout_values, PoseSummary, READOUTS};

/// How long the pose must stay still before the live region speaks, ms.
const SPEAK_AFTER_MS: i32 = 700;

/// The strip's entries: `data-strip` name, Fluent id of its label, Fluent id of its unit.
pub(super) const STRIP: [(&str, &str, &str); 5] = [
    ("q1", "ik2r-strip-q1", "ik2r-unit-deg"),
    ("q2", "ik2r-strip-q2", "ik2r-unit-deg"),
    ("x", "ik2r-strip-x", "ik2r-unit-mm"),
    ("y", "ik2r-strip-y", "ik2r-unit-mm"),
    ("w", "ik2r-strip-w", "ik2r-unit-m2"),
];

/// The readouts component.
pub(super) struct Readouts {
    elements: Vec<Option<Element>>,
    shown: Vec<String>,
    strip: Vec<Option<Element>>,
    strip_shown: Vec<String>,
    live: Element,
    /// What the live region will say (and said last).
    pending: Rc<RefCell<Option<PoseSummary>>>,
    said: Rc<RefCell<Option<PoseSummary>>>,
    /// Speaks the pending summary (a timer of the page's scope).
    timer: Option<Rc<Timer>>,
}

impl Readouts {
    /// Finds the `[data-readout]` elements, the strip and the live region under `root`.
    pub fn find(root: &Element) -> Result<Readouts, JsValue> {
        let mut elements = Vec::with_capacity(READOUTS.len());
        for name in READOUTS {
            elements.push(root.query_selector(&format!("[data-readout=\"{name}\"]"))?);
        }
        let mut strip = Vec::new();
        for (name, _, _) in STRIP {
            strip.push(root.query_selector(&format!("[data-strip=\"{name}\"]"))?);
        }
        Ok(Readouts {
            elements,
            shown: vec![String::new(); READOUTS.len()],
            strip,
            strip_shown: vec![String::new(); STRIP.len()],
            live: role(root, "live")?,
            pending: Rc::new(RefCell::new(None)),
            said: Rc::new(RefCell::new(None)),
            timer: None,
        })
    }

    /// The live region's timer (it calls [`Readouts::speak`]).
    pub fn set_timer(&mut self, timer: Rc<Timer>) {
        self.timer = Some(timer);
    }

    /// Writes the pose's numbers (only those that changed) and queues the summary.
    pub fn update(&mut self, rep: &PoseReport, pinned: bool) {
        for ((text, element), shown) in readout_values(rep)
            .into_iter()
            .zip(&self.elements)
            .zip(self.shown.iter_mut())
        {
            if *shown != text {
                if let Some(e) = element {
                    e.set_text_content(Some(&text));
                }
                *shown = text;
            }
        }
        let strip = [
            fmt_fixed(rep.q1.to_degrees(), 1),
            fmt_fixed(rep.q2.to_degrees(), 1),
            fmt_fixed(rep.x * 1000.0, 1),
            fmt_fixed(rep.y * 1000.0, 1),
            fmt_sig(rep.manipulability, 3),
        ];
        for ((text, element), shown) in strip
            .into_iter()
            .zip(&self.strip)
            .zip(self.strip_shown.iter_mut())
        {
            if *shown != text {
                if let Some(e) = element {
                    e.set_text_content(Some(&text));
                }
                *shown = text;
            }
        }
        let summary = PoseSummary::of(rep, pinned);
        let first = self.said.borrow().is_none() && self.pending.borrow().is_none();
        if first {
            // The pose the page opened with is on screen; nothing to announce.
            *self.said.borrow_mut() = Some(summary);
            return;
        }
        if self.said.borrow().as_ref() != Some(&summary) {
            *self.pending.borrow_mut() = Some(summary);
            if let Some(t) = &self.timer {
                t.schedule(SPEAK_AFTER_MS);
            }
        }
    }

    /// Says the pending summary.
    pub fn speak(&self) {
        let Some(summary) = self.pending.borrow_mut().take() else {
            return;
        };
        self.live.set_text_content(Some(&sentence(&summary)));
        *self.said.borrow_mut() = Some(summary);
    }

    /// The last sentence, in the current language.
    pub fn relocalize(&self) {
        if self.live.text_content().is_some_and(|t| !t.is_empty()) {
            if let Some(s) = self.said.borrow().as_ref() {
                self.live.set_text_content(Some(&sentence(s)));
            }
        }
    }
}

fn sentence(s: &PoseSummary) -> String {
    let text = t_strings("ik2r-live-summary", &s.args());
    if s.pinned {
        format!("{} {}", ctx::t("ik2r-clamped"), text)
    } else {
        text
    }
}
