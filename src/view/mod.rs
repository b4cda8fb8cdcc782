//! Pure view models of the browser pages: plain Rust, no web-sys, so `cargo test` covers them
//! natively (the wasm-only `crate::ui` module draws what these compute).
//!
//! - [`url`]: the URL codec (`#/<page>?k=v`, percent-encoding, `lang`).
//! - [`field`], [`form`]: the parameter form's fields and validation; [`command_line`]:
//!   `bsv` / `python` lines of a run; [`table`]: CSV previews and rounded cells.
//! - [`stepper`]: the stepper's state machine (step, back, play at a speed, scrub).
//! - [`plot`]: scales, ticks, y ranges, cursor lookup, min/max decimation of the kit plot.
//! - [`heatmap`]: colour map, RGBA fill, node grid and layout of the kit heatmap.
//! - [`palette`]: the Okabe–Ito colours of plot series and view marks (colour-blind safe).
//! - [`card_picture`]: the home page's recipe-card pictures, drawn from each kernel's defaults.
//! - [`camera3d`]: the orbit camera of the 3D views ([`crate::camera3d`], re-exported).
//! - [`drill_chain`]: the seed's "next step" chain of drills at the foot of each drill page.
//! - [`lesson`]: lessons (steps of page states), their URL and file forms, the presenter.
//! - [`scene3d`]: what a 3D view draws (lines, arrows, triads, grid), projected and
//!   sorted for the painter's algorithm.
//! - [`dh_fk`]: the DH page: frames to draw, the row walk through its four elementary
//!   transforms, slider edits of `angles`, URL keys.
//! - [`drag`]: hit shapes of drag handles and their touch overlay boxes; taps.
//! - [`envelope`]: min/max plot envelope of a CSV table (a million rows in a few thousand points).
//! - [`drills`]: the drills page's URL state (recipe and the fields' texts).
//! - [`ik2r`]: the IK page: state and URL, validation, arm view geometry, exports.
//! - [`pendulum`]: the pendulum page: kept rows, energy error and drift, period, separatrix, URL.
//! - [`rrt`]: the RRT stepper page: state and URL, command lines, world editor hit tests and
//!   edits, sub-step texts and pseudocode lines.
//! - [`se3_relative`]: the relative SE(3) pose page: fields in rad or deg, URL, matrices,
//!   intrinsic vs extrinsic rotations, the 3D scene's gizmo hits and drags.
//! - [`signal`]: what the signal pages share (URL keys = argument names, sliders, snapping);
//!   [`cubic_path`]: the cubic page's coefficients, peaks and overlays;
//!   [`pid_step`]: rise time, overshoot, settling, steady-state error and peak u;
//!   [`trapezoid_profile`]: the phases of a profile, triangles, the ramp-corner drag.
//! - [`traj_resample`]: the trajectory-resampling page: URL, readouts.
//! - [`umeyama_2d`]: the Umeyama page: the fit's steps and their matrices, the SVD's
//!   factors, the point editor, the truth's handles, the view frame and hit tests.
//! - [`teleop`]: the Robot Pilot page: settings and their checks, readout texts, view transform.
//! - [`teleop_input`]: the Robot Pilot page's input mapping (Isaac Lab keyboard and gamepad, clutch),
//!   the fixed-step accumulator.
//! - [`teleop_export`]: the Robot Pilot page's episode CSV and evidence written in slices.
//! - [`progress`]: the progress panel of long runs (percent, rows, time left).
//! - [`worker`]: the preview head of a file a worker run sends back.

pub use crate::camera3d;
pub mod card_picture;
pub mod command_line;
pub mod cubic_path;
pub mod dh_fk;
pub mod drag;
pub mod drill_chain;
pub mod drills;
pub mod envelope;
pub mod field;
pub mod form;
pub mod heatmap;
pub mod ik2r;
pub mod lesson;
pub mod palette;
pub mod pendulum;
pub mod pid_step;
pub mod plot;
pub mod progress;
pub mod rrt;
pub mod scene3d;
pub mod se3_relative;
pub mod signal;
pub mod stepper;
pub mod table;
pub mod teleop;
pub mod teleop_export;
pub mod teleop_input;
pub mod traj_resample;
pub mod trapezoid_profile;
pub mod umeyama_2d;
pub mod url;
pub mod worker;
