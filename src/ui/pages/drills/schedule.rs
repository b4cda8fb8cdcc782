//! Deferred work: a debounced `setTimeout` ([`Timer`]) for validation-driven runs and URL
//! writes, and [`after_paint`], which runs a callback after the browser has painted the
//! current DOM (a `requestAnimationFrame` whose callback sets a zero `setTimeout`), so that a
//! "Running…" state is on screen before a long computation blocks the tab.

use std::cell::{Cell, RefCell};

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;

/// A debounced `setTimeout`: [`Timer::schedule`] restarts it.
pub struct Timer {
    id: Cell<Option<i32>>,
    callback: RefCell<Option<Closure<dyn FnMut()>>>,
}

impl Timer {
    pub fn new() -> Timer {
        Timer {
            id: Cell::new(None),
            callback: RefCell::new(None),
        }
    }

    /// What the timer runs (call [`Timer::fired`] first thing in it).
    pub fn set_callback(&self, f: impl FnMut() + 'static) {
        *self.callback.borrow_mut() = Some(Closure::new(f));
    }

    /// (Re)starts the timer: the callback runs `ms` after the last call.
    pub fn schedule(&self, ms: i32) {
        let Some(window) = web_sys::window() else {
            return;
        };
        self.cancel();
        if let Some(cb) = self.callback.borrow().as_ref() {
            if let Ok(id) = window.set_timeout_with_callback_and_timeout_and_arguments_0(
                cb.as_ref().unchecked_ref(),
                ms,
            ) {
                self.id.set(Some(id));
            }
        }
    }

    /// Stops the timer if it is waiting.
    pub fn cancel(&self) {
        if let (Some(id), Some(window)) = (self.id.take(), web_sys::window()) {
            window.clear_timeout_with_handle(id);
        }
    }

    /// Marks the timer as no longer waiting (the callback is running).
    pub fn fired(&self) {
        self.id.set(None);
    }
}

/// Runs `f` once the browser has painted what is on the page now.
pub fn after_paint(f: impl FnOnce() + 'static) -> Result<(), JsValue> {
    let window = web_sys::window().ok_or_else(|| JsValue::from_str("no window"))?;
    let run = Closure::once_into_js(f);
    let frame = Closure::once_into_js(move || {
        if let Some(window) = web_sys::window() {
            let _ = window
                .set_timeout_with_callback_and_timeout_and_arguments_0(run.unchecked_ref(), 0);
        }
    });
    window.request_animation_frame(frame.unchecked_ref())?;
    Ok(())
}
