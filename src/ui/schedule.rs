//! Deferred work and its clock: a debounced `setTimeout` ([`Timer`]) for recomputes, runs and
//! URL writes; [`after_paint`], which runs a callback after the browser has painted the current
//! DOM (a `requestAnimationFrame` whose callback sets a zero `setTimeout`), so that a
//! "Running…" state is on screen before a long computation blocks the tab; and [`now_ms`],
//! the clock pages time their work with.

use std::cell::{Cell, RefCell};
use std::rc::{Rc, Weak};

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;

/// A debounced `setTimeout`: [`Timer::schedule`] restarts it. `Timer::default()` has nothing
/// to run until [`Timer::set_callback`].
#[derive(Default)]
pub struct Timer {
    /// The pending timeout (cleared by the callback as it starts).
    id: Rc<Cell<Option<i32>>>,
    callback: RefCell<Option<Closure<dyn FnMut()>>>,
}

impl Timer {
    /// What the timer runs: `f` on the page behind `page`, if it is still mounted (the page
    /// owns its timers, so the callback holds it weakly).
    pub fn set_callback<P: 'static>(&self, page: &Weak<P>, f: impl Fn(&P) + 'static) {
        let id = self.id.clone();
        let page = page.clone();
        *self.callback.borrow_mut() = Some(Closure::new(move || {
            id.set(None);
            if let Some(page) = page.upgrade() {
                f(&page);
            }
        }));
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

/// `performance.now()` in milliseconds (0 where there is no clock).
pub fn now_ms() -> f64 {
    web_sys::window()
        .and_then(|w| w.performance())
        .map_or(0.0, |p| p.now())
}
