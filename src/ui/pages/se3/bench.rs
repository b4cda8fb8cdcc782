//! Timing hooks for `tests/e2e/se3.bench.mjs`, built only with the `bench` cargo feature
//! (`scripts/bench.sh` builds such a dist): every drag frame's work (hit, drag maths, form,
//! solve, matrices, readouts, both canvases) is pushed, in milliseconds, to
//! `window.__se3FrameMs` (the last 5000). Without the feature, nothing.

/// The recorder of drag frames.
pub(super) struct Timings;

impl Timings {
    pub fn install() -> Timings {
        Timings
    }

    /// Records one frame's work, ms.
    #[cfg(feature = "bench")]
    pub fn push(&self, ms: f64) {
        use wasm_bindgen::{JsCast, JsValue};
        let Some(window) = web_sys::window() else {
            return;
        };
        let key = JsValue::from_str("__se3FrameMs");
        let list = js_sys::Reflect::get(&window, &key)
            .ok()
            .and_then(|v| v.dyn_into::<js_sys::Array>().ok())
            .unwrap_or_else(|| {
                let a = js_sys::Array::new();
                let _ = js_sys::Reflect::set(&window, &key, &a);
                a
            });
        if list.length() >= 5000 {
            list.shift();
        }
        list.push(&JsValue::from_f64(ms));
    }

    /// Without the `bench` feature: nothing.
    #[cfg(not(feature = "bench"))]
    pub fn push(&self, _ms: f64) {}
}
