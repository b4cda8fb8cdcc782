//! Timing hooks for `tests/bench/teleop.bench.mjs`, built only with the `bench` cargo feature:
//! every live frame's work (poll the devices, step the simulation, draw, readouts), ms, is
//! pushed to `window.__teleopFrameMs`, and every slice of a file written in slices (an
//! episode's CSV, the evidence) to `window.__teleopExportMs`, and every slice of a stored
//! session simulated again on load to `window.__teleopLoadMs` (the last 5000 of each). Without
//! the feature, [`record`], [`record_export`] and [`record_load`] do nothing.

#[cfg(not(feature = "bench"))]
pub(super) fn record(_ms: f64) {}

#[cfg(not(feature = "bench"))]
pub(super) fn record_export(_ms: f64) {}

#[cfg(not(feature = "bench"))]
pub(super) fn record_load(_ms: f64) {}

#[cfg(feature = "bench")]
pub(super) fn record_load(ms: f64) {
    push("__teleopLoadMs", ms);
}

#[cfg(feature = "bench")]
pub(super) fn record(ms: f64) {
    push("__teleopFrameMs", ms);
}

#[cfg(feature = "bench")]
pub(super) fn record_export(ms: f64) {
    push("__teleopExportMs", ms);
}

#[cfg(feature = "bench")]
fn push(name: &str, ms: f64) {
    crate::ui::kit::bench_log::push_ms(name, ms, 5000);
}
