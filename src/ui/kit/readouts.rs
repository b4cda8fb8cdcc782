//! The readouts panel of a page: named values (`data-readout="<key>"`, each written only when
//! its text changes) and one visually hidden `aria-live="polite"` summary for screen readers,
//! paced so that a drag or a key held down does not flood them: [`Readouts::announce`] says at
//! most one text per [`ANNOUNCE_GAP_MS`], always the latest; [`Readouts::announce_settled`]
//! says the latest text once nothing new came for a moment (a drag is one sentence), and
//! formats it only then. Neither restarts a timer per call: a frame that announces costs a
//! clock read and a box.
//!
//! [`markup_rows`] lays out rows of several values with units (q1 in rad and degrees);
//! [`Readouts::find_by`] reads another attribute than `data-readout` (a compact strip of the
//! same numbers, `data-strip`).

use std::cell::{Cell, RefCell};
use std::rc::Rc;

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::Element;

use super::form::escape;
use crate::ui::schedule::now_ms;

/// Shortest time between two announcements.
pub const ANNOUNCE_GAP_MS: f64 = 1000.0;

/// A `<dl>` of readouts: `(key, label Fluent id)` each, values filled by [`Readouts::set`].
/// Its element id is `<prefix>-readouts` (a canvas's `aria-describedby`: the readouts are
/// its text alternative).
pub fn markup(prefix: &str, items: &[(&str, &str)]) -> String {
    let p = escape(prefix);
    let mut html = format!("<dl class=\"kit-readouts {p}-readouts\" id=\"{p}-readouts\">");
    for (key, label) in items {
        html.push_str(&format!(
            "<div class=\"kit-readout {p}-readout\"><dt data-i18n=\"{label}\"></dt>\
             <dd data-readout=\"{key}\"></dd></div>",
            key = escape(key),
            label = escape(label),
        ));
    }
    html.push_str("</dl>");
    html
}

/// One row of [`markup_rows`]: the Fluent id of its label and its values, each a key and the
/// Fluent id of its unit.
#[derive(Debug, Clone, Copy)]
pub struct ReadoutRow<'a> {
    pub label_id: &'a str,
    pub values: &'a [(&'a str, &'a str)],
}

/// A `<dl>` of rows of readouts, each value followed by its unit (classes `kit-*` and
/// `<prefix>-*`; element id `<prefix>-readouts-list`).
pub fn markup_rows(prefix: &str, rows: &[ReadoutRow]) -> String {
    let p = escape(prefix);
    let mut html =
        format!("<dl class=\"kit-readouts {p}-readouts-list\" id=\"{p}-readouts-list\">");
    for row in rows {
        html.push_str(&format!(
            "<div class=\"kit-readout {p}-readout\"><dt data-i18n=\"{}\"></dt><dd>",
            escape(row.label_id)
        ));
        for (key, unit) in row.values {
            html.push_str(&format!(
                "<span class=\"kit-num {p}-num\"><span class=\"kit-val {p}-val\" data-readout=\"{}\"></span>\
                 <span class=\"kit-unit {p}-unit\" data-i18n=\"{}\"></span></span>",
                escape(key),
                escape(unit),
            ));
        }
        html.push_str("</dd></div>");
    }
    html.push_str("</dl>");
    html
}

/// The live summary region (put it once in the page).
pub fn live_markup(prefix: &str) -> String {
    format!(
        "<p class=\"kit-visually-hidden\" data-readout-live data-testid=\"{}-live\" \
         role=\"status\" aria-live=\"polite\"></p>",
        escape(prefix)
    )
}

/// How the live region paces what it is given.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Pace {
    /// At most one text per gap.
    Throttle,
    /// The latest text once nothing new came for this long, ms.
    Settle(f64),
}

struct Live {
    region: Option<Element>,
    /// The text waiting to be said.
    pending: RefCell<Option<String>>,
    /// The text to say once settled, formatted when it is said.
    pending_settled: RefCell<Option<Box<dyn FnOnce() -> String>>>,
    /// The last text said (or counted as said).
    said: RefCell<Option<String>>,
    /// When the last text was said / the last new text came, ms.
    last_said_ms: Cell<f64>,
    last_change_ms: Cell<f64>,
    pace: Cell<Pace>,
    timer: Cell<Option<i32>>,
    /// The timer's callback (it holds this state weakly).
    flush: RefCell<Option<Closure<dyn FnMut()>>>,
}

impl Live {
    /// The timer fired: say the pending text, or wait the rest of the quiet time.
    fn on_timer(&self) {
        self.timer.set(None);
        if let Pace::Settle(quiet) = self.pace.get() {
            let left = self.last_change_ms.get() + quiet - now_ms();
            if left > 1.0 {
                self.arm(left);
                return;
            }
        }
        let settled = self.pending_settled.borrow_mut().take();
        let (text, settled) = match settled {
            Some(make) => (make(), true),
            None => match self.pending.borrow_mut().take() {
                Some(text) => (text, false),
                None => return,
            },
        };
        if settled && self.said.borrow().as_deref() == Some(text.as_str()) {
            // Back where it was said last: nothing new to say.
            return;
        }
        if let Some(region) = &self.region {
            region.set_text_content(Some(&text));
        }
        *self.said.borrow_mut() = Some(text);
        self.last_said_ms.set(now_ms());
    }

    fn arm(&self, wait_ms: f64) {
        let Some(window) = web_sys::window() else {
            return;
        };
        let flush = self.flush.borrow();
        let Some(flush) = flush.as_ref() else {
            return;
        };
        if let Ok(id) = window.set_timeout_with_callback_and_timeout_and_arguments_0(
            flush.as_ref().unchecked_ref(),
            wait_ms.max(0.0) as i32,
        ) {
            self.timer.set(Some(id));
        }
    }
}

/// The readouts and the live region of a page.
pub struct Readouts {
    values: Vec<(String, Element)>,
    /// The text each value shows now.
    shown: RefCell<Vec<String>>,
    /// The `data-value` each has now (`None`: not set yet).
    exact: RefCell<Vec<Option<String>>>,
    live: Rc<Live>,
}

impl Readouts {
    /// Finds every `[data-readout]` and the `[data-readout-live]` region under `root`.
    pub fn find(root: &Element) -> Result<Readouts, JsValue> {
        Readouts::find_by(root, "data-readout")
    }

    /// Finds every element with `attribute` (its value is the key) and the
    /// `[data-readout-live]` region, if any, under `root`.
    pub fn find_by(root: &Element, attribute: &str) -> Result<Readouts, JsValue> {
        let mut values = Vec::new();
        for el in crate::ui::dom::matching(root, &format!("[{attribute}]"))? {
            if let Some(key) = el.get_attribute(attribute) {
                values.push((key, el));
            }
        }
        let live = Rc::new(Live {
            region: root.query_selector("[data-readout-live]")?,
            pending: RefCell::new(None),
            pending_settled: RefCell::new(None),
            said: RefCell::new(None),
            last_said_ms: Cell::new(f64::NEG_INFINITY),
            last_change_ms: Cell::new(f64::NEG_INFINITY),
            pace: Cell::new(Pace::Throttle),
            timer: Cell::new(None),
            flush: RefCell::new(None),
        });
        let weak = Rc::downgrade(&live);
        *live.flush.borrow_mut() = Some(Closure::new(move || {
            if let Some(live) = weak.upgrade() {
                live.on_timer();
            }
        }));
        let shown = RefCell::new(vec![String::new(); values.len()]);
        let exact = RefCell::new(vec![None; values.len()]);
        Ok(Readouts {
            values,
            shown,
            exact,
            live,
        })
    }

    /// Sets the value shown under `key` (written only when its text changes).
    pub fn set(&self, key: &str, text: &str) {
        let mut shown = self.shown.borrow_mut();
        for ((k, el), was) in self.values.iter().zip(shown.iter_mut()) {
            if k == key && was != text {
                el.set_text_content(Some(text));
                text.clone_into(was);
            }
        }
    }

    /// Sets the value shown under `key` and its exact value in `data-value` (for tests and
    /// copy tools: the text may be rounded, `value` is not); each written only when it changes.
    pub fn set_with_value(&self, key: &str, text: &str, value: &str) {
        let mut shown = self.shown.borrow_mut();
        let mut exact = self.exact.borrow_mut();
        let rows = self
            .values
            .iter()
            .zip(shown.iter_mut())
            .zip(exact.iter_mut());
        for (((k, el), was), was_value) in rows {
            if k != key {
                continue;
            }
            if was != text {
                el.set_text_content(Some(text));
                text.clone_into(was);
            }
            if was_value.as_deref() != Some(value) {
                let _ = el.set_attribute("data-value", value);
                *was_value = Some(value.to_string());
            }
        }
    }

    /// The element showing `key` (to hide its row, say).
    pub fn element(&self, key: &str) -> Option<&Element> {
        self.values.iter().find(|(k, _)| k == key).map(|(_, el)| el)
    }

    /// Says `text` to screen readers, politely and throttled (a newer text replaces one that
    /// is still waiting).
    pub fn announce(&self, text: &str) {
        self.live.pace.set(Pace::Throttle);
        *self.live.pending_settled.borrow_mut() = None;
        *self.live.pending.borrow_mut() = Some(text.to_string());
        if self.live.timer.get().is_some() {
            return;
        }
        let wait = self.live.last_said_ms.get() + ANNOUNCE_GAP_MS - now_ms();
        self.live.arm(wait);
    }

    /// Says the text `make` formats once nothing new came for `quiet_ms` (the latest call's
    /// text; nothing if it is the text said last).
    pub fn announce_settled(&self, quiet_ms: f64, make: impl FnOnce() -> String + 'static) {
        let live = &self.live;
        live.pace.set(Pace::Settle(quiet_ms));
        *live.pending.borrow_mut() = None;
        *live.pending_settled.borrow_mut() = Some(Box::new(make));
        live.last_change_ms.set(now_ms());
        if live.timer.get().is_none() {
            live.arm(quiet_ms);
        }
    }

    /// Counts `text` as said without saying it (what the page opened with is on screen).
    pub fn mark_said(&self, text: &str) {
        *self.live.said.borrow_mut() = Some(text.to_string());
    }

    /// Whether the live region has said anything.
    pub fn has_spoken(&self) -> bool {
        self.live
            .region
            .as_ref()
            .and_then(|r| r.text_content())
            .is_some_and(|t| !t.is_empty())
    }

    /// Replaces what the live region shows (the same sentence in another language) without
    /// queueing an announcement.
    pub fn resay(&self, text: &str) {
        if self.has_spoken() {
            if let Some(region) = &self.live.region {
                region.set_text_content(Some(text));
            }
        }
        *self.live.said.borrow_mut() = Some(text.to_string());
    }
}

impl Drop for Readouts {
    fn drop(&mut self) {
        if let (Some(id), Some(window)) = (self.live.timer.take(), web_sys::window()) {
            window.clear_timeout_with_handle(id);
        }
    }
}
