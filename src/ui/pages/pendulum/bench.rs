//! Timing hooks for `tests/bench/pendulum.bench.mjs`, built only with the `bench` cargo feature
//! (`scripts/bench.sh` builds such a dist; the app build has none of this):
//!
//! - every real frame's work (advance the tracks, draw the pendulum, append to the plots,
//!   readouts), ms, is pushed to `window.__pendulumFrameMs` (last 5000);
//! - `window.__pendulumBench.frame(steps)` runs one frame's work synchronously, `steps`
//!   timesteps further (from the start again once the run is over), and returns its
//!   duration (`performance.now()`).
//!
//! Without the feature, [`record`] and [`remove_hooks`] do nothing.

#[cfg(not(feature = "bench"))]
pub(super) fn record(_ms: f64) {}

#[cfg(not(feature = "bench"))]
pub(super) fn remove_hooks() {}

#[cfg(feature = "bench")]
pub(super) use hooks::{install_hooks, record, remove_hooks};

#[cfg(feature = "bench")]
mod hooks {
    use wasm_bindgen::prelude::*;

    const FRAMES: &str = "__pendulumFrameMs";
    const HOOKS: &str = "__pendulumBench";
    const KEEP: u32 = 5000;

    /// Records one frame's work.
    pub(crate) fn record(ms: f64) {
        crate::ui::kit::bench_log::push_ms(FRAMES, ms, KEEP);
    }

    /// Installs `window.__pendulumBench` (and an empty `__pendulumFrameMs`): its
    /// `frame(steps)` calls `frame` with `steps` clamped to 1..=1e6 (1 if not finite).
    pub(crate) fn install_hooks(frame: impl Fn(u64) -> f64 + 'static) {
        let Some(window) = web_sys::window() else {
            return;
        };
        let _ = js_sys::Reflect::set(&window, &FRAMES.into(), &js_sys::Array::new());
        let hooks = js_sys::Object::new();
        let frame = Closure::<dyn FnMut(f64) -> f64>::new(move |steps: f64| {
            let steps = if steps.is_finite() {
                steps.clamp(1.0, 1e6) as u64
            } else {
                1
            };
            frame(steps)
        });
        let _ = js_sys::Reflect::set(&hooks, &"frame".into(), &frame.into_js_value());
        let _ = js_sys::Reflect::set(&window, &HOOKS.into(), &hooks);
    }

    /// Removes `window.__pendulumBench` (the page unmounted).
    pub(crate) fn remove_hooks() {
        if let Some(window) = web_sys::window() {
            let _ = js_sys::Reflect::delete_property(&window, &HOOKS.into());
        }
    }
}
