//! One `requestAnimationFrame` loop per page with dirty flags: components mark what changed
//! ([`FrameLoop::invalidate`] with the page's own bit constants), and the page's draw
//! function runs once in the next animation frame with every bit collected since, so a burst
//! of pointer events costs one draw. [`FrameLoop::set_animating`] keeps frames coming (a
//! simulation playing); the draw then also gets frames with no bit set. Dropping the loop
//! cancels the pending frame.

use std::cell::{Cell, RefCell};
use std::rc::{Rc, Weak};

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;

/// The `requestAnimationFrame` callback.
type FrameCallback = Closure<dyn FnMut(f64)>;

struct Shared {
    dirty: Cell<u32>,
    raf_id: Cell<Option<i32>>,
    animating: Cell<bool>,
    callback: RefCell<Option<FrameCallback>>,
}

impl Shared {
    fn request(&self) {
        if self.raf_id.get().is_some() {
            return;
        }
        let Some(window) = web_sys::window() else {
            return;
        };
        if let Some(cb) = self.callback.borrow().as_ref() {
            if let Ok(id) = window.request_animation_frame(cb.as_ref().unchecked_ref()) {
                self.raf_id.set(Some(id));
            }
        }
    }
}

/// The frame loop.
pub struct FrameLoop {
    shared: Rc<Shared>,
}

impl FrameLoop {
    /// A loop that calls `draw(page, dirty_bits, time_ms)` on the page behind `page` (held
    /// weakly: the page owns its loop).
    pub fn new<P: 'static>(page: &Weak<P>, draw: impl Fn(&P, u32, f64) + 'static) -> FrameLoop {
        let shared = Rc::new(Shared {
            dirty: Cell::new(0),
            raf_id: Cell::new(None),
            animating: Cell::new(false),
            callback: RefCell::new(None),
        });
        let weak_shared: Weak<Shared> = Rc::downgrade(&shared);
        let page = page.clone();
        *shared.callback.borrow_mut() = Some(Closure::new(move |t: f64| {
            let Some(shared) = weak_shared.upgrade() else {
                return;
            };
            shared.raf_id.set(None);
            let bits = shared.dirty.replace(0);
            if let Some(page) = page.upgrade() {
                if bits != 0 || shared.animating.get() {
                    draw(&page, bits, t);
                }
            }
            if shared.animating.get() || shared.dirty.get() != 0 {
                shared.request();
            }
        }));
        FrameLoop { shared }
    }

    /// Marks `bits` dirty and asks for a frame.
    pub fn invalidate(&self, bits: u32) {
        self.shared.dirty.set(self.shared.dirty.get() | bits);
        self.shared.request();
    }

    /// The bits waiting for the next frame.
    pub fn pending(&self) -> u32 {
        self.shared.dirty.get()
    }

    /// Keeps requesting frames (every frame calls draw) while `on`.
    pub fn set_animating(&self, on: bool) {
        self.shared.animating.set(on);
        if on {
            self.shared.request();
        }
    }

    /// Cancels the pending frame and forgets the dirty bits.
    pub fn cancel(&self) {
        self.shared.animating.set(false);
        self.shared.dirty.set(0);
        if let (Some(id), Some(window)) = (self.shared.raf_id.take(), web_sys::window()) {
            let _ = window.cancel_animation_frame(id);
        }
    }
}

impl Drop for FrameLoop {
    fn drop(&mut self) {
        self.cancel();
    }
}
