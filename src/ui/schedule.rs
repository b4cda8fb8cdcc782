//! Deferred work and its clock: a debounced `setTimeout` ([`Timer`]) for recomputes, runs and
//! URL writes (cheap to restart every frame); [`after_paint`], which runs a callback after the browser has painted the current
//! DOM (a `requestAnimationFrame` whose callback sets a zero `setTimeout`), so that a
//! "Running…" state is on screen before a long computation blocks the tab; [`idle`], which
//! waits for the browser's idle time; and [`now_ms`], the clock pages time their work with.

use std::cell::{Cell, RefCell};
use std::rc::{Rc, Weak};

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;

/// A debounced `setTimeout`: [`Timer::schedule`] restarts it. `Timer::default()` has nothing
/// to run until [`Timer::set_callback`].
///
/// A restart that only moves the deadline later (a drag or a key held down schedules it every
/// frame) keeps the pending timeout: when it fires early, it waits out the rest. So a frame
/// that reschedules costs a clock read, not a `clearTimeout` and a `setTimeout`.
#[derive(Default)]
pub struct Timer {
    state: Rc<TimerState>,
}

#[derive(Default)]
struct TimerState {
    /// The pending timeout and when it fires (ms, [`now_ms`] clock).
    id: Cell<Option<i32>>,
    fires_at: Cell<f64>,
    /// When the callback is due (the last `schedule` asked for it then).
    due_at: Cell<f64>,
    /// The timeout's callback (holds this state weakly).
    tick: RefCell<Option<Closure<dyn FnMut()>>>,
    /// What the timer runs when due.
    run: RefCell<Option<Rc<dyn Fn()>>>,
}

impl TimerState {
    fn arm(&self, ms: f64) {
        let Some(window) = web_sys::window() else {
            return;
        };
        if let Some(tick) = self.tick.borrow().as_ref() {
            if let Ok(id) = window.set_timeout_with_callback_and_timeout_and_arguments_0(
                tick.as_ref().unchecked_ref(),
                ms.max(0.0).ceil() as i32,
            ) {
                self.id.set(Some(id));
                self.fires_at.set(now_ms() + ms.max(0.0));
            }
        }
    }

    /// The timeout fired: run the callback if it is due, else wait the rest.
    fn on_timeout(&self) {
        self.id.set(None);
        let left = self.due_at.get() - now_ms();
        if left > 0.5 {
            self.arm(left);
            return;
        }
        let run = self.run.borrow().clone();
        if let Some(run) = run {
            run();
        }
    }
}

impl Timer {
    /// What the timer runs: `f` on the page behind `page`, if it is still mounted (the page
    /// owns its timers, so the callback holds it weakly).
    pub fn set_callback<P: 'static>(&self, page: &Weak<P>, f: impl Fn(&P) + 'static) {
        let page = page.clone();
        *self.state.run.borrow_mut() = Some(Rc::new(move || {
            if let Some(page) = page.upgrade() {
                f(&page);
            }
        }));
        let state = Rc::downgrade(&self.state);
        *self.state.tick.borrow_mut() = Some(Closure::new(move || {
            if let Some(state) = state.upgrade() {
                state.on_timeout();
            }
        }));
    }

    /// (Re)starts the timer: the callback runs `ms` after the last call.
    pub fn schedule(&self, ms: i32) {
        let now = now_ms();
        let due = now + f64::from(ms.max(0));
        let state = &self.state;
        state.due_at.set(due);
        if state.id.get().is_some() && state.fires_at.get() <= due {
            // The pending timeout fires first and waits out the rest.
            return;
        }
        self.clear();
        state.arm(due - now);
    }

    /// Stops the timer if it is waiting.
    pub fn cancel(&self) {
        self.clear();
    }

    fn clear(&self) {
        if let (Some(id), Some(window)) = (self.state.id.take(), web_sys::window()) {
            window.clear_timeout_with_handle(id);
        }
    }
}

impl Drop for TimerState {
    fn drop(&mut self) {
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

/// Resolves once `ask` has had the browser call the resolver it is given; at once if `ask`
/// could not ask (it returns `false`: no window, a call that threw).
async fn resolved_by(ask: impl FnOnce(&js_sys::Function) -> bool) {
    let mut ask = Some(ask);
    let promise = js_sys::Promise::new(&mut |resolve, _| {
        let asked = ask.take().is_some_and(|ask| ask(&resolve));
        if !asked {
            let _ = resolve.call0(&JsValue::UNDEFINED);
        }
    });
    let _ = wasm_bindgen_futures::JsFuture::from(promise).await;
}

/// A zero-or-more `setTimeout` that calls `f`; whether it was set.
fn timeout(f: &js_sys::Function, ms: i32) -> bool {
    web_sys::window().is_some_and(|window| {
        window
            .set_timeout_with_callback_and_timeout_and_arguments_0(f, ms)
            .is_ok()
    })
}

/// Resolves in a later task (a zero `setTimeout`): what follows runs after the browser has
/// handled what waits, input first.
pub async fn next_task() {
    resolved_by(|resolve| timeout(resolve, 0)).await;
}

/// Resolves in a later task as [`next_task`] does, but without the clamp browsers put on
/// timers set from timers (4 ms after five): `scheduler.yield()` where the browser has it (what
/// follows goes before other waiting tasks, after input and rendering), else a zero
/// `setTimeout`. For work cut into many short tasks in a row.
pub async fn yield_now() {
    let promise = web_sys::window().and_then(|window| {
        let scheduler = js_sys::Reflect::get(&window, &JsValue::from_str("scheduler"))
            .ok()
            .filter(JsValue::is_object)?;
        let call = js_sys::Reflect::get(&scheduler, &JsValue::from_str("yield"))
            .ok()?
            .dyn_into::<js_sys::Function>()
            .ok()?;
        call.call0(&scheduler)
            .ok()?
            .dyn_into::<js_sys::Promise>()
            .ok()
    });
    match promise {
        Some(promise) => {
            let _ = wasm_bindgen_futures::JsFuture::from(promise).await;
        }
        None => next_task().await,
    }
}

/// Resolves `ms` milliseconds later (a `setTimeout`).
pub async fn sleep_ms(ms: i32) {
    resolved_by(|resolve| timeout(resolve, ms)).await;
}

/// Resolves once the browser has painted what is on the page now ([`after_paint`]).
pub async fn painted() {
    resolved_by(|resolve| {
        let resolve = resolve.clone();
        after_paint(move || {
            let _ = resolve.call0(&JsValue::UNDEFINED);
        })
        .is_ok()
    })
    .await;
}

/// Resolves in the browser's next idle period (`requestIdleCallback`, at the latest
/// `IDLE_TIMEOUT_MS` later), or after a short `setTimeout` where there is no such call: work the
/// visitor did not ask for runs there, a slice at a time, never in a frame's way.
pub async fn idle() {
    resolved_by(|resolve| {
        let Some(window) = web_sys::window() else {
            return false;
        };
        let request = js_sys::Reflect::get(&window, &JsValue::from_str("requestIdleCallback"))
            .ok()
            .and_then(|f| f.dyn_into::<js_sys::Function>().ok());
        match request {
            Some(request) => {
                let options = js_sys::Object::new();
                let _ = js_sys::Reflect::set(
                    &options,
                    &JsValue::from_str("timeout"),
                    &JsValue::from_f64(IDLE_TIMEOUT_MS),
                );
                request.call2(&window, resolve, &options).is_ok()
            }
            None => timeout(resolve, 50),
        }
    })
    .await;
}

/// How long idle work waits for an idle period at most (ms): a page that animates every frame
/// leaves few.
const IDLE_TIMEOUT_MS: f64 = 3000.0;

/// Runs `f` on the page `me` once the browser has painted, if the page is still there.
pub fn after_paint_for<P: 'static>(me: &std::rc::Weak<P>, f: fn(&P)) -> Result<(), JsValue> {
    let me = me.clone();
    after_paint(move || {
        if let Some(page) = me.upgrade() {
            f(&page);
        }
    })
}

thread_local! {
    /// The window's `performance`, looked up once: pages read the clock several times a
    /// frame, and each lookup would be two calls into JS.
    static PERFORMANCE: Option<web_sys::Performance> =
        web_sys::window().and_then(|w| w.performance());
}

/// `performance.now()` in milliseconds (0 where there is no clock).
pub fn now_ms() -> f64 {
    PERFORMANCE.with(|p| p.as_ref().map_or(0.0, web_sys::Performance::now))
}
