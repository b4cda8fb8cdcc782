//! The readouts panel of a page: named values (`data-readout="<key>"`) and one visually hidden
//! `aria-live="polite"` summary for screen readers, throttled so that a drag or a key held
//! down does not flood them: at most one announcement per [`ANNOUNCE_GAP_MS`], always the
//! latest text.

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
pub fn markup(prefix: &str, items: &[(&str, &str)]) -> String {
    let p = escape(prefix);
    let mut html = format!("<dl class=\"kit-readouts {p}-readouts\">");
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

/// The live summary region (put it once in the page).
pub fn live_markup(prefix: &str) -> String {
    format!(
        "<p class=\"kit-visually-hidden\" data-readout-live data-testid=\"{}-live\" \
         role=\"status\" aria-live=\"polite\"></p>",
        escape(prefix)
    )
}

/// The readouts and the live region of a page.
pub struct Readouts {
    values: Vec<(String, Element)>,
    pending: Rc<RefCell<Option<String>>>,
    last_ms: Rc<Cell<f64>>,
    timer: Rc<Cell<Option<i32>>>,
    flush: Closure<dyn FnMut()>,
}

impl Readouts {
    /// Finds every `[data-readout]` and the `[data-readout-live]` region under `root`.
    pub fn find(root: &Element) -> Result<Readouts, JsValue> {
        let mut values = Vec::new();
        for el in crate::ui::dom::matching(root, "[data-readout]")? {
            if let Some(key) = el.get_attribute("data-readout") {
                values.push((key, el));
            }
        }
        let live = root.query_selector("[data-readout-live]")?;
        let pending: Rc<RefCell<Option<String>>> = Rc::new(RefCell::new(None));
        let last_ms = Rc::new(Cell::new(f64::NEG_INFINITY));
        let timer = Rc::new(Cell::new(None));
        let flush = {
            let (pending, last_ms, timer, live) = (
                pending.clone(),
                last_ms.clone(),
                timer.clone(),
                live.clone(),
            );
            Closure::new(move || {
                timer.set(None);
                if let (Some(text), Some(live)) = (pending.borrow_mut().take(), live.as_ref()) {
                    live.set_text_content(Some(&text));
                    last_ms.set(now_ms());
                }
            })
        };
        Ok(Readouts {
            values,
            pending,
            last_ms,
            timer,
            flush,
        })
    }

    /// Sets the value shown under `key`.
    pub fn set(&self, key: &str, text: &str) {
        for (k, el) in &self.values {
            if k == key {
                el.set_text_content(Some(text));
            }
        }
    }

    /// Sets the value shown under `key` and its exact value (`data-value`, e.g. the CSV's
    /// full-precision number) for whoever needs more digits than are shown.
    pub fn set_exact(&self, key: &str, text: &str, exact: &str) {
        for (k, el) in &self.values {
            if k == key {
                el.set_text_content(Some(text));
                let _ = el.set_attribute("data-value", exact);
            }
        }
    }

    /// Says `text` to screen readers, politely and throttled (a newer text replaces one that
    /// is still waiting).
    pub fn announce(&self, text: &str) {
        *self.pending.borrow_mut() = Some(text.to_string());
        if self.timer.get().is_some() {
            return;
        }
        let wait = (self.last_ms.get() + ANNOUNCE_GAP_MS - now_ms()).max(0.0);
        let Some(window) = web_sys::window() else {
            return;
        };
        if let Ok(id) = window.set_timeout_with_callback_and_timeout_and_arguments_0(
            self.flush.as_ref().unchecked_ref(),
            wait as i32,
        ) {
            self.timer.set(Some(id));
        }
    }
}

impl Drop for Readouts {
    fn drop(&mut self) {
        if let (Some(id), Some(window)) = (self.timer.take(), web_sys::window()) {
            window.clear_timeout_with_handle(id);
        }
    }
}
