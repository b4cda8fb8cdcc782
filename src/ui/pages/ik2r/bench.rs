//! Timing hooks for `tests/bench/ik2r.bench.mjs`, built only with the `bench` cargo feature
//! (`scripts/bench.sh` builds such a dist; the app build has none of this): the page records
//! what each real frame cost in `window.__ik2rTimings` (`frame`, `plot`, `heatmap`,
//! `workspace`: arrays of milliseconds, last 5000 each), and `window.__ik2rBench` runs one
//! piece of work synchronously and returns its duration (`performance.now()`):
//!
//! - `frame(x_mm, y_mm)`: a drag frame to that tip target: IK, Jacobian, readouts, arm layer,
//!   ellipse, heatmap marker;
//! - `plot()`: the sweep series redraw;
//! - `heatmap(n)`: an `n × n` heatmap recompute, paint and background draw.
//!
//! The page does the work through [`BenchHost`]; without the feature, [`Timings::push`] and
//! the hook functions do nothing.

/// The work the hooks time, done by the page.
#[cfg(feature = "bench")]
pub(super) trait BenchHost: 'static {
    /// A drag frame to tip target `(x, y)` metres.
    fn bench_frame(&self, x: f64, y: f64);
    /// The sweep series redraw.
    fn bench_plot(&self);
    /// An `n × n` heatmap recompute and background draw; `false` if it could not run. The
    /// page goes back to its own resolution afterwards.
    fn bench_heatmap(&self, n: usize) -> bool;
}

/// The `window.__ik2rTimings` object (bench builds).
pub(super) struct Timings {
    #[cfg(feature = "bench")]
    object: Option<js_sys::Object>,
}

#[cfg(not(feature = "bench"))]
impl Timings {
    pub fn install() -> Timings {
        Timings {}
    }

    pub fn push(&self, _kind: &str, _ms: f64) {}
}

#[cfg(not(feature = "bench"))]
pub(super) fn install_hooks<H>(_host: &std::rc::Weak<H>) -> Result<(), wasm_bindgen::JsValue> {
    Ok(())
}

#[cfg(not(feature = "bench"))]
pub(super) fn remove_hooks() {}

#[cfg(feature = "bench")]
pub(super) use hooks::{install_hooks, remove_hooks};

#[cfg(feature = "bench")]
mod hooks {
    use std::rc::Weak;

    use wasm_bindgen::prelude::*;
    use wasm_bindgen::JsCast;

    use crate::ui::pages::ik2r::bench::{BenchHost, Timings};
    use crate::ui::schedule::now_ms;

    const TIMINGS: &str = "__ik2rTimings";
    const HOOKS: &str = "__ik2rBench";
    const KINDS: [&str; 4] = ["frame", "plot", "heatmap", "workspace"];
    const KEEP: u32 = 5000;

    impl Timings {
        /// Creates (or reuses) `window.__ik2rTimings`.
        pub fn install() -> Timings {
            let Some(window) = web_sys::window() else {
                return Timings { object: None };
            };
            let existing = js_sys::Reflect::get(&window, &TIMINGS.into())
                .ok()
                .and_then(|v| v.dyn_into::<js_sys::Object>().ok());
            let object = existing.unwrap_or_default();
            for kind in KINDS {
                let has = js_sys::Reflect::get(&object, &kind.into())
                    .map(|v| v.is_instance_of::<js_sys::Array>())
                    .unwrap_or(false);
                if !has {
                    let _ = js_sys::Reflect::set(&object, &kind.into(), &js_sys::Array::new());
                }
            }
            let _ = js_sys::Reflect::set(&window, &TIMINGS.into(), &object);
            Timings {
                object: Some(object),
            }
        }

        /// Records one duration of `kind`.
        pub fn push(&self, kind: &str, ms: f64) {
            let Some(object) = &self.object else {
                return;
            };
            if let Ok(array) = js_sys::Reflect::get(object, &kind.into())
                .and_then(|v| v.dyn_into::<js_sys::Array>())
            {
                array.push(&JsValue::from_f64(ms));
                if array.length() > KEEP {
                    array.shift();
                }
            }
        }
    }

    /// Installs `window.__ik2rBench`.
    pub fn install_hooks<H: BenchHost>(weak: &Weak<H>) -> Result<(), JsValue> {
        let window = web_sys::window().ok_or_else(|| JsValue::from_str("no window"))?;
        let hooks = js_sys::Object::new();
        let w = weak.clone();
        let frame = Closure::<dyn FnMut(f64, f64) -> f64>::new(move |x_mm: f64, y_mm: f64| {
            let Some(page) = w.upgrade() else {
                return f64::NAN;
            };
            let t0 = now_ms();
            page.bench_frame(x_mm / 1000.0, y_mm / 1000.0);
            now_ms() - t0
        });
        let w = weak.clone();
        let plot = Closure::<dyn FnMut() -> f64>::new(move || {
            let Some(page) = w.upgrade() else {
                return f64::NAN;
            };
            let t0 = now_ms();
            page.bench_plot();
            now_ms() - t0
        });
        let w = weak.clone();
        let heat = Closure::<dyn FnMut(f64) -> f64>::new(move |n: f64| {
            let Some(page) = w.upgrade() else {
                return f64::NAN;
            };
            let n = if n.is_finite() {
                n.clamp(2.0, 1024.0) as usize
            } else {
                256
            };
            let t0 = now_ms();
            if page.bench_heatmap(n) {
                now_ms() - t0
            } else {
                f64::NAN
            }
        });
        js_sys::Reflect::set(&hooks, &"frame".into(), &frame.into_js_value())?;
        js_sys::Reflect::set(&hooks, &"plot".into(), &plot.into_js_value())?;
        js_sys::Reflect::set(&hooks, &"heatmap".into(), &heat.into_js_value())?;
        js_sys::Reflect::set(&window, &HOOKS.into(), &hooks)?;
        Ok(())
    }

    /// Removes `window.__ik2rBench` (the page unmounted).
    pub fn remove_hooks() {
        if let Some(window) = web_sys::window() {
            let _ = js_sys::Reflect::delete_property(&window, &HOOKS.into());
        }
    }
}
