//! A [`Scope`] owns what a page or a component hooks into the browser: event listeners,
//! debounced timers, an animation-frame loop and resize observers. Dropping the scope removes
//! every one of them, so unmounting a page is dropping it.
//!
//! Callbacks hold the page weakly (`Weak<P>`, upgraded on each call): the page owns its scope,
//! the scope owns the closures, and nothing keeps a dropped page alive.
//!
//! ```ignore
//! let mut scope = Scope::new();
//! scope.listen_for(&canvas, "pointerdown", &weak_page, |page, event| page.on_down(event))?;
//! let url = scope.timer(&weak_page, Page::write_url);   // url.schedule(300)
//! let frame = scope.dirty_frame_loop(&weak_page, Page::frame); // frame.invalidate(bits)
//! scope.observe_resize(&[&stage], &weak_page, |page| page.relayout())?;
//! ```

use std::rc::{Rc, Weak};

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::{Element, Event, EventTarget, ResizeObserver};

use crate::ui::dom::Listener;
pub use crate::ui::kit::frame::FrameLoop;
use crate::ui::schedule::Timer;

/// A resize observer and the callback it calls.
type Observer = (ResizeObserver, Closure<dyn FnMut(JsValue)>);

/// Listeners, timers, a frame loop and observers, removed on drop.
#[derive(Default)]
pub struct Scope {
    listeners: Vec<Listener>,
    timers: Vec<Rc<Timer>>,
    frames: Vec<FrameLoop>,
    observers: Vec<Observer>,
}

impl Scope {
    /// An empty scope.
    pub fn new() -> Scope {
        Scope::default()
    }

    /// Calls `handler` on every `event` on `target` while the scope lives.
    pub fn listen(
        &mut self,
        target: &EventTarget,
        event: &'static str,
        handler: impl FnMut(Event) + 'static,
    ) -> Result<(), JsValue> {
        self.listeners.push(Listener::new(target, event, handler)?);
        Ok(())
    }

    /// [`Scope::listen`] with the page behind `page` (skipped once it is gone).
    pub fn listen_for<P: 'static>(
        &mut self,
        target: &EventTarget,
        event: &'static str,
        page: &Weak<P>,
        handler: impl Fn(&P, &Event) + 'static,
    ) -> Result<(), JsValue> {
        self.listeners
            .push(Listener::for_page(target, event, page, handler)?);
        Ok(())
    }

    /// Keeps an existing listener until the scope drops.
    pub fn keep(&mut self, listener: Listener) {
        self.listeners.push(listener);
    }

    /// A debounced timer running `f` on the page; `schedule(ms)` (re)starts it, the scope
    /// cancels it on drop.
    pub fn timer<P: 'static>(&mut self, page: &Weak<P>, f: impl Fn(&P) + 'static) -> Rc<Timer> {
        let timer = Rc::new(Timer::default());
        timer.set_callback(page, f);
        self.timers.push(timer.clone());
        timer
    }

    /// The page's animation-frame loop ([`crate::ui::kit::frame`]) calling `f(page,
    /// timestamp_ms)` once per [`FrameLoop::request`]ed frame (requests in between coalesce);
    /// cancelled on drop.
    pub fn frame_loop<P: 'static>(
        &mut self,
        page: &Weak<P>,
        f: impl Fn(&P, f64) + 'static,
    ) -> FrameLoop {
        self.dirty_frame_loop(page, move |p: &P, _bits, time| f(p, time))
    }

    /// The same loop with dirty bits: `f(page, bits, timestamp_ms)` runs once in the next
    /// animation frame with every bit [`FrameLoop::invalidate`]d since; cancelled on drop.
    pub fn dirty_frame_loop<P: 'static>(
        &mut self,
        page: &Weak<P>,
        f: impl Fn(&P, u32, f64) + 'static,
    ) -> FrameLoop {
        let frame = FrameLoop::new(page, f);
        self.frames.push(frame.clone());
        frame
    }

    /// Calls `f` on the page whenever any of `elements` changes size; disconnected on drop.
    pub fn observe_resize<P: 'static>(
        &mut self,
        elements: &[&Element],
        page: &Weak<P>,
        f: impl Fn(&P) + 'static,
    ) -> Result<(), JsValue> {
        let page = page.clone();
        let callback = Closure::<dyn FnMut(JsValue)>::new(move |_entries: JsValue| {
            if let Some(page) = page.upgrade() {
                f(&page);
            }
        });
        let observer = ResizeObserver::new(callback.as_ref().unchecked_ref())?;
        for element in elements {
            observer.observe(element);
        }
        self.observers.push((observer, callback));
        Ok(())
    }
}

impl Drop for Scope {
    fn drop(&mut self) {
        for timer in &self.timers {
            timer.cancel();
        }
        for frame in &self.frames {
            frame.cancel();
        }
        for (observer, _) in &self.observers {
            observer.disconnect();
        }
        // Listeners remove themselves as the Vec drops.
    }
}
