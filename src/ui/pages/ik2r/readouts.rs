//! The live numbers, on the kit's readouts ([`crate::ui::kit::readouts`]): q1, q2 (rad, deg),
//! tip x, y (mm), det J, Yoshikawa manipulability `w = sqrt(det(J Jᵀ))`, the singular values
//! and the 2×2 Jacobian. Each number is the text of an element `[data-readout="<name>"]`, plain
//! (parseable) digits with the unit in a sibling element, written only when it changes.
//!
//! Two more views of the same numbers: a compact strip over the arm view (`data-strip`: q1, q2,
//! x, y, w; shown at phone width, where the panel sits far below the arm, and written only
//! while it shows) and, for screen
//! readers, the kit's polite live region, which says the pose once the arm has been still for
//! a moment (a drag or a run of key presses is one sentence, not fifty).

use wasm_bindgen::JsValue;
use web_sys::Element;

use super::markup::role;
use crate::planar2r::PoseReport;
use crate::ui::ctx::{self, t_strings};
use crate::ui::kit::readouts::{self as kit, ReadoutRow};
use crate::view::ik2r::{fmt_fixed, fmt_sig, readout_values, PoseSummary, READOUTS};

/// How long the pose must stay still before the live region speaks, ms.
const SPEAK_AFTER_MS: f64 = 700.0;

/// The strip's entries: `data-strip` name, Fluent id of its label, Fluent id of its unit.
const STRIP: [(&str, &str, &str); 5] = [
    ("q1", "ik2r-strip-q1", "ik2r-unit-deg"),
    ("q2", "ik2r-strip-q2", "ik2r-unit-deg"),
    ("x", "ik2r-strip-x", "ik2r-unit-mm"),
    ("y", "ik2r-strip-y", "ik2r-unit-mm"),
    ("w", "ik2r-strip-w", "ik2r-unit-m2"),
];

/// The panel's rows: label and `(readout, unit)` pairs (the Jacobian is a matrix below).
const ROWS: [ReadoutRow<'static>; 6] = [
    ReadoutRow {
        label_id: "ik2r-ro-q1",
        values: &[("q1", "ik2r-unit-rad"), ("q1_deg", "ik2r-unit-deg")],
    },
    ReadoutRow {
        label_id: "ik2r-ro-q2",
        values: &[("q2", "ik2r-unit-rad"), ("q2_deg", "ik2r-unit-deg")],
    },
    ReadoutRow {
        label_id: "ik2r-ro-tip",
        values: &[("x_mm", "ik2r-unit-mm"), ("y_mm", "ik2r-unit-mm")],
    },
    ReadoutRow {
        label_id: "ik2r-ro-det",
        values: &[("det_j", "ik2r-unit-m2")],
    },
    ReadoutRow {
        label_id: "ik2r-ro-w",
        values: &[("manipulability", "ik2r-unit-m2")],
    },
    ReadoutRow {
        label_id: "ik2r-ro-sigma",
        values: &[("sigma_min", "ik2r-unit-m"), ("sigma_max", "ik2r-unit-m")],
    },
];

/// The readouts panel's markup.
pub fn markup() -> String {
    format!(
        "<section class=\"ik2r-card ik2r-readouts\" data-section=\"readouts\" aria-live=\"off\">\
         <h2 data-i18n=\"ik2r-readouts-title\"></h2>{rows}\
         <div class=\"ik2r-jac\"><span class=\"ik2r-jac-label\" id=\"ik2r-jac-label\" data-i18n=\"ik2r-ro-jac\"></span>\
         <div class=\"ik2r-matrix\" role=\"table\" aria-labelledby=\"ik2r-jac-label\">\
         <div class=\"ik2r-matrix-row\" role=\"row\"><span data-readout=\"j11\" role=\"cell\"></span><span data-readout=\"j12\" role=\"cell\"></span></div>\
         <div class=\"ik2r-matrix-row\" role=\"row\"><span data-readout=\"j21\" role=\"cell\"></span><span data-readout=\"j22\" role=\"cell\"></span></div>\
         </div><span class=\"ik2r-unit\" data-i18n=\"ik2r-unit-m-per-rad\"></span></div>\
         <p class=\"ik2r-hint\" data-i18n=\"ik2r-ro-hint\"></p></section>",
        rows = kit::markup_rows("ik2r", &ROWS),
    )
}

/// The compact strip of key numbers over the arm view (shown at phone width).
pub fn strip_markup() -> String {
    let mut html =
        String::from("<div class=\"ik2r-strip\" data-ik2r=\"strip\" aria-hidden=\"true\">");
    for (name, label, unit) in STRIP {
        html.push_str(&format!(
            "<span class=\"ik2r-strip-item\"><span class=\"ik2r-strip-label\" data-i18n=\"{label}\"></span> \
             <span class=\"ik2r-val\" data-strip=\"{name}\"></span>\
             <span class=\"ik2r-unit\" data-i18n=\"{unit}\"></span></span>"
        ));
    }
    html.push_str("</div>");
    html
}

/// The readouts component.
pub(super) struct Readouts {
    /// The panel's numbers and the live region.
    panel: kit::Readouts,
    strip: kit::Readouts,
    strip_element: Element,
    /// The strip shows (phone width): its numbers are written only then.
    strip_shown: bool,
    /// The first pose (on screen when the page opens) is not announced.
    started: bool,
}

impl Readouts {
    /// Finds the panel (with the page's live region) and the strip under `root`.
    pub fn find(root: &Element) -> Result<Readouts, JsValue> {
        let strip_element: Element = role(root, "strip")?;
        Ok(Readouts {
            panel: kit::Readouts::find(root)?,
            strip: kit::Readouts::find_by(&strip_element, "data-strip")?,
            strip_element,
            strip_shown: true,
            started: false,
        })
    }

    /// The layout changed: whether the strip shows now (its stylesheet shows it at phone
    /// width only).
    pub fn layout(&mut self) {
        self.strip_shown = web_sys::window()
            .and_then(|w| w.get_computed_style(&self.strip_element).ok().flatten())
            .and_then(|s| s.get_property_value("display").ok())
            .is_none_or(|d| d != "none");
    }

    /// Writes the pose's numbers (only those that changed) and queues the summary.
    pub fn update(&mut self, rep: &PoseReport, pinned: bool) {
        for (name, text) in READOUTS.iter().zip(readout_values(rep)) {
            self.panel.set(name, &text);
        }
        if self.strip_shown {
            let strip = [
                fmt_fixed(rep.q1.to_degrees(), 1),
                fmt_fixed(rep.q2.to_degrees(), 1),
                fmt_fixed(rep.x * 1000.0, 1),
                fmt_fixed(rep.y * 1000.0, 1),
                fmt_sig(rep.manipulability, 3),
            ];
            for ((name, _, _), text) in STRIP.iter().zip(strip) {
                self.strip.set(name, &text);
            }
        }
        if !self.started {
            // The pose the page opened with is on screen; nothing to announce.
            self.started = true;
            self.panel.mark_said(&sentence(rep, pinned));
            return;
        }
        let rep = *rep;
        self.panel
            .announce_settled(SPEAK_AFTER_MS, move || sentence(&rep, pinned));
    }

    /// The sentence said last, in the current language (`rep` is the pose now).
    pub fn relocalize(&self, rep: &PoseReport, pinned: bool) {
        self.panel.resay(&sentence(rep, pinned));
    }
}

/// What the live region says about a pose.
fn sentence(rep: &PoseReport, pinned: bool) -> String {
    let s = PoseSummary::of(rep, pinned);
    let text = t_strings("ik2r-live-summary", &s.args());
    if s.pinned {
        format!("{} {}", ctx::t("ik2r-clamped"), text)
    } else {
        text
    }
}
