//! Timing hooks for `tests/bench/se3.bench.mjs`, built only with the `bench` cargo feature
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
    pub fn push(&self, ms: f64) {
        crate::ui::kit::bench_log::push_ms("__se3FrameMs", ms, 5000);
    }
}
