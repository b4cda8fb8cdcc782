//! Timings for the page benchmarks (`tests/bench/*.bench.mjs`), in bench builds only: each
//! record is pushed, in milliseconds, to the array `window.<name>` (made on first use), which
//! the benchmark reads. Without the `bench` cargo feature [`push_ms`] does nothing, so the app
//! build carries none of it.

/// No cap on the array: every record is kept.
pub const KEEP_ALL: u32 = u32::MAX;

/// Pushes `ms` to `window.<name>`, dropping the oldest record once it holds more than `keep`.
#[cfg(feature = "bench")]
pub fn push_ms(name: &str, ms: f64, keep: u32) {
    use wasm_bindgen::{JsCast, JsValue};
    let Some(window) = web_sys::window() else {
        return;
    };
    let key = JsValue::from_str(name);
    let list = js_sys::Reflect::get(&window, &key)
        .ok()
        .and_then(|v| v.dyn_into::<js_sys::Array>().ok())
        .unwrap_or_else(|| {
            let a = js_sys::Array::new();
            let _ = js_sys::Reflect::set(&window, &key, &a);
            a
        });
    list.push(&JsValue::from_f64(ms));
    if list.length() > keep {
        list.shift();
    }
}

/// Without the `bench` feature: nothing.
#[cfg(not(feature = "bench"))]
pub fn push_ms(_name: &str, _ms: f64, _keep: u32) {}
