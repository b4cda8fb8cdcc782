//! Pure view models of the browser pages: plain Rust, no web-sys, so `cargo test` covers them
//! natively (the wasm-only `crate::ui` module draws what these compute).
//!
//! Shared by the pages: the URL codec ([`url`]), the parameter form ([`field`], [`form`]) and
//! its command lines ([`command_line`]), CSV previews and envelopes ([`table`], [`envelope`]),
//! the stepper, plots, heatmaps, colours, 3D scenes and drag handles, progress, lessons, the
//! drill chain, the exercises and their checks ([`exercises`]), one exercise's state on its
//! page ([`exercise_state`]) and its typed prediction ([`prediction_text`]), a learner's
//! progress on them ([`learner_progress`]) and a class's ([`class_summary`]). One module per page holds that
//! page's state, URL keys, readouts and hit tests ([`ik2r`], [`rrt`], [`pendulum`],
//! [`se3_relative`], [`umeyama_2d`], [`teleop`], ...).
//! Each module's first line says what it owns.

pub use crate::camera3d;
pub mod card_picture;
pub mod class_summary;
pub mod command_line;
pub mod cubic_path;
pub mod dh_fk;
pub mod drag;
pub mod drill_chain;
pub mod drills;
pub mod embed;
pub mod envelope;
pub mod exercise_state;
pub mod exercises;
pub mod field;
pub mod form;
pub mod heatmap;
pub mod ik2r;
pub mod json_file;
pub mod learner_progress;
pub mod lesson;
pub mod lesson_file;
pub mod lesson_goal;
pub mod palette;
pub mod pendulum;
pub mod pid_step;
pub mod pilot_picture;
pub mod plot;
pub mod prediction_text;
pub mod progress;
pub mod qr_code;
pub mod replay;
pub mod rrt;
pub mod scene3d;
pub mod se3_relative;
pub mod sections;
pub mod signal;
pub mod so101;
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
