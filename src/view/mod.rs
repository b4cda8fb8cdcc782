//! Pure view models of the browser pages: plain Rust, no web-sys, so `cargo test` covers them
//! natively (the wasm-only `crate::ui` module draws what these compute).
//!
//! - [`url`]: the URL codec (`#/<page>?k=v`, percent-encoding, `lang`).
//! - [`form`]: the parameter form's fields and validation; [`command_line`]: `bsv` / `python`
//!   lines of a run; [`table`]: CSV previews and rounded cells.
//! - [`stepper`]: the stepper's state machine (step, back, play at a speed, scrub).
//! - [`plot`]: scales, ticks, y ranges, cursor lookup, min/max decimation of the kit plot.
//! - [`heatmap`]: colour map, RGBA fill, node grid and layout of the kit heatmap.
//! - [`camera3d`]: the orbit camera of the 3D views (projection, orbit, zoom, presets, hits).
//! - [`drag`]: hit shapes of drag handles and their touch overlay boxes; taps.
//! - [`envelope`]: min/max plot envelope of a CSV table (a million rows in a few thousand points).
//! - [`drills`]: the drills page's URL state (recipe and the fields' texts).
//! - [`ik2r`]: the IK page: state and URL, validation, arm view geometry, exports.
//! - [`pendulum`]: the pendulum page: kept rows, energy error and drift, period, separatrix, URL.
//! - [`rrt`]: the RRT stepper page: state and URL, command lines, world editor hit tests and
//!   edits, sub-step texts and pseudocode lines.
//! - [`signal`]: what the signal pages share (URL keys = argument names, sliders, snapping);
//!   [`cubic_path`]: the cubic page's coefficients, peaks and overlays;
//!   [`pid_step`]: rise time, overshoot, settling, steady-state error and peak u;
//!   [`trapezoid_profile`]: the phases of a profile, triangles, the ramp-corner drag.
//! - [`traj_resample`]: the trajectory-resampling page: URL, readouts.
//! - [`teleop`]: the Robot Pilot page: settings and their checks, readout texts, view transform.
//! - [`teleop_input`]: the Robot Pilot page's input mapping (Isaac Lab keyboard and gamepad, clutch),
//!   the fixed-step accumulator.
//! - [`progress`]: the progress panel of long runs (percent, rows, time left).
//! - [`worker`]: the preview head of a file a worker run sends back.

pub mod camera3d;
pub mod command_line;
pub mod cubic_path;
pub mod drag;
pub mod drills;
pub mod envelope;
pub mod form;
pub mod heatmap;
pub mod ik2r;
pub mod pendulum;
pub mod pid_step;
pub mod plot;
pub mod progress;
pub mod rrt;
pub mod signal;
pub mod stepper;
pub mod table;
pub mod teleop;
pub mod teleop_input;
pub mod traj_resample;
pub mod trapezoid_profile;
pub mod url;
pub mod worker;
