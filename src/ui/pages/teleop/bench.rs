//! Timing hooks for `tests/e2e/teleop.bench.mjs`, built only with the `bench` cargo feature:
//! every live frame's work (poll the devices, step the simulation, draw, readouts), ms, is
//! pushed to `window.__teleopFrameMs` (the last 5000). Without the feature, [`record`] does
//! nothing.

#[cfg(not(feature = "bench"))]
pub(super) fn record(_ms: f64) {}

#[cfg(feature = "bench")]
pub(super) fn record(ms: f64) {
    use wasm_bindgen::prelude::*;
    use wasm_bindgen::JsCast;
    const FRAMES: &str = "__teleopFrameMs";
    const KEEP: u32 = 5000;
    let Some(window) = web_sys::window() else {
        return;
    };
    let key = JsValue::from_str(FRAMES);
    let list = js_sys::Reflect::get(&window, &key)
        .ok()
        .and_then(|v| v.dyn_into::<js_sys::Array>().ok())
        .unwrap_or_else(|| {
            let a = js_sys::Array::new();
            let _ = js_sys::Reflect::set(&window, &key, &a);
            a
        });
    list.push(&JsValue::from_f64(ms));
    if list.length() > KEEP {
        list.shift();
    }
}
