//! The one animation-frame loop of the kit: components mark what changed
//! ([`FrameLoop::invalidate`] with the page's own bit constants), and the draw function runs
//! once in the next animation frame with every bit collected since, so a burst of pointer
//! events costs one draw. [`FrameLoop::request`] asks for a call with no new bit (a stepper
//! playing: one tick per frame); [`FrameLoop::set_animating`] keeps frames coming.
//!
//! A page gets its loop from its scope ([`crate::ui::kit::scope::Scope::dirty_frame_loop`], or
//! [`crate::ui::kit::scope::Scope::frame_loop`] when it needs no bits), which cancels the
//! pending frame on drop; clones share one loop, and the loop also cancels its frame when the
//! last clone goes. [`reduced_motion`] says whether the user asked for less animation.

use std::cell::{Cell, RefCell};
use std::rc::{Rc, Weak};

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;

/// The `requestAnimationFrame` callback.
type FrameCallback = Closure<dyn FnMut(f64)>;

struct Shared {
    /// The next frame asked for follows a large change of the page's markup (the loop's
    /// first frame, made with its page; [`FrameLoop::invalidate_after_layout`]): the page is
    /// laid out in a task of its own ([`Shared::lay_out_before_frame`]).
    lay_out_first: Cell<bool>,
    dirty: Cell<u32>,
    /// A call was asked for with [`FrameLoop::request`] (no bit needed).
    requested: Cell<bool>,
    raf_id: Cell<Option<i32>>,
    animating: Cell<bool>,
    callback: RefCell<Option<FrameCallback>>,
}

impl Shared {
    fn schedule(self: &Rc<Self>) {
        if self.raf_id.get().is_some() {
            return;
        }
        let Some(window) = web_sys::window() else {
            return;
        };
        if let Ok(callback) = self.callback.try_borrow() {
            if let Some(cb) = callback.as_ref() {
                if let Ok(id) = window.request_animation_frame(cb.as_ref().unchecked_ref()) {
                    self.raf_id.set(Some(id));
                }
            }
        }
        if self.raf_id.get().is_some() && self.lay_out_first.replace(false) {
            self.lay_out_before_frame();
        }
    }

    /// A task that brings the document's layout up to date before the asked-for frame runs,
    /// if it runs first (as it mostly does: it is queued ahead of other tasks): the frame then
    /// draws on a laid-out page instead of laying out the whole page inside its callback, one
    /// long task on a phone made two short ones. If the frame comes first, it lays the page
    /// out itself, as it would anyway; nothing is painted in between either way.
    fn lay_out_before_frame(self: &Rc<Self>) {
        let weak = Rc::downgrade(self);
        wasm_bindgen_futures::spawn_local(async move {
            crate::ui::schedule::yield_now().await;
            if weak.upgrade().is_some_and(|s| s.raf_id.get().is_some()) {
                lay_out();
            }
        });
    }

    fn cancel(&self) {
        self.animating.set(false);
        self.requested.set(false);
        self.dirty.set(0);
        if let (Some(id), Some(window)) = (self.raf_id.take(), web_sys::window()) {
            let _ = window.cancel_animation_frame(id);
        }
    }
}

impl Drop for Shared {
    fn drop(&mut self) {
        self.cancel();
    }
}

/// The frame loop. Cloning shares it.
#[derive(Clone)]
pub struct FrameLoop {
    shared: Rc<Shared>,
}

impl FrameLoop {
    /// A loop that calls `draw(page, dirty_bits, time_ms)` on the page behind `page` (held
    /// weakly: the page owns its loop). Prefer the scope's constructors, which also cancel it
    /// when the page unmounts.
    pub fn new<P: 'static>(page: &Weak<P>, draw: impl Fn(&P, u32, f64) + 'static) -> FrameLoop {
        let shared = Rc::new(Shared {
            lay_out_first: Cell::new(true),
            dirty: Cell::new(0),
            requested: Cell::new(false),
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
            let requested = shared.requested.replace(false);
            if let Some(page) = page.upgrade() {
                if bits != 0 || requested || shared.animating.get() {
                    draw(&page, bits, t);
                }
            }
            if shared.animating.get() || shared.dirty.get() != 0 || shared.requested.get() {
                shared.schedule();
            }
        }));
        FrameLoop { shared }
    }

    /// Marks `bits` dirty and asks for a frame.
    pub fn invalidate(&self, bits: u32) {
        self.shared.dirty.set(self.shared.dirty.get() | bits);
        self.shared.schedule();
    }

    /// Marks `bits` dirty and asks for a frame, with the document laid out in a task of its own
    /// before it as for a loop's first frame: for the frame after a large change of the page's
    /// markup (a part of the page built late).
    pub fn invalidate_after_layout(&self, bits: u32) {
        self.shared.dirty.set(self.shared.dirty.get() | bits);
        if self.shared.raf_id.get().is_some() {
            self.shared.lay_out_before_frame();
        } else {
            self.shared.lay_out_first.set(true);
            self.shared.schedule();
        }
    }

    /// Asks for one call on the next animation frame, with or without dirty bits (requests in
    /// between coalesce).
    pub fn request(&self) {
        self.shared.requested.set(true);
        self.shared.schedule();
    }

    /// The bits waiting for the next frame.
    pub fn pending(&self) -> u32 {
        self.shared.dirty.get()
    }

    /// Whether a frame is asked for.
    pub fn is_scheduled(&self) -> bool {
        self.shared.raf_id.get().is_some()
    }

    /// Keeps requesting frames (every frame calls draw) while `on`.
    pub fn set_animating(&self, on: bool) {
        self.shared.animating.set(on);
        if on {
            self.shared.schedule();
        }
    }

    /// Cancels the pending frame and forgets the dirty bits and requests.
    pub fn cancel(&self) {
        self.shared.cancel();
    }
}

/// Brings the document's style and layout up to date (a layout query on the root element).
fn lay_out() {
    if let Some(root) = web_sys::window()
        .and_then(|w| w.document())
        .and_then(|d| d.document_element())
    {
        let _ = root.get_bounding_client_rect();
    }
}

/// Whether the user asked for reduced motion (`prefers-reduced-motion: reduce`): no autoplay,
/// steps jump instead of moving.
pub fn reduced_motion() -> bool {
    let Some(window) = web_sys::window() else {
        return false;
    };
    js_sys::Reflect::get(&window, &"matchMedia".into())
        .ok()
        .and_then(|f| f.dyn_into::<js_sys::Function>().ok())
        .and_then(|f| {
            f.call1(&window, &"(prefers-reduced-motion: reduce)".into())
                .ok()
        })
        .and_then(|m| js_sys::Reflect::get(&m, &"matches".into()).ok())
        .and_then(|v| v.as_bool())
        .unwrap_or(false)
}
