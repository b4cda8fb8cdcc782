//! Pure view models of the browser pages: plain Rust, no web-sys, so `cargo test` covers them
//! natively (the wasm-only `crate::ui` module draws what these compute).
//!
//! - [`url`]: the URL codec (`#/<page>?k=v`, percent-encoding, `lang`).
//! - [`stepper`]: the stepper's state machine (step, back, play at a speed, scrub).
//! - [`plot`]: scales, ticks, y ranges, cursor lookup, min/max decimation of the kit plot.
//! - [`heatmap`]: colour map, RGBA fill, node grid and layout of the kit heatmap.
//! - [`drag`]: hit shapes of drag handles and their touch overlay boxes; taps.
//! - [`ik2r`]: the IK page: state and URL, validation, arm view geometry, exports.
//! - [`pendulum`]: the pendulum page: kept rows, energy error and drift, period, separatrix, URL.

pub mod drag;
pub mod heatmap;
pub mod ik2r;
pub mod pendulum;
pub mod plot;
pub mod stepper;
pub mod url;
