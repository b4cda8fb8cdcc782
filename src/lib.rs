//! BSV Playground: the twelve BotShelf Vampire robotics recipes as plain-Rust kernels,
//! a command line (`bsv`), a thin wasm API and a bilingual canvas UI.
//!
//! - [`recipes`]: one kernel per recipe, numbers in, tables out; no web-sys.
//! - [`planar2r`]: planar two-link kinematics shared by the 2R recipes and the IK page.
//! - [`camera3d`]: the orbit camera of the 3D views and the 3D card pictures.
//! - [`teleop`]: the Robot Pilot practice simulation (planar 3R arm, gripper, block, differential
//!   IK, latency, noise, episodes, exact replay); no web-sys.
//! - [`so101`]: the SO-101 practice simulation (five-joint arm in 3D, MuJoCo-checked kinematics,
//!   differential IK on the 6×5 Jacobian, table, cube, goal, episodes, exact replay); no web-sys.
//! - [`rng`]: numpy-compatible `default_rng` (PCG64 + SeedSequence + ziggurat normal).
//! - [`math`]: correctly rounded sin, cos, atan2 … : the same bits natively and in wasm.
//! - [`numpy`]: `np.arange` and friends, operation for operation.
//! - [`pyfmt`]: numbers printed exactly as Python prints them.
//! - [`numtext`]: numbers as the app shows them (no negative zero).
//! - [`args`]: command-line style argument parsing shared by the CLI and `runRecipe`.
//! - [`bench`](mod@bench): the cases of `make bench`.
//! - [`error`]: the one error type every kernel returns.
//! - [`i18n`]: Fluent bundles embedded from `locales/`.
//! - `api` (feature `api`, on by default, off in the app build): the `#[wasm_bindgen]` surface
//!   for the kernels.
//! - [`view`]: pure view models of the pages (URL codec, stepper, hit tests, scales), tested
//!   natively.
//! - `ui` (wasm32 only): the pages.

#[cfg(feature = "api")]
pub mod api;
pub mod args;
pub mod bench;
pub mod camera3d;
pub mod error;
pub mod i18n;
pub mod math;
pub mod numpy;
pub mod numtext;
pub mod planar2r;
pub mod pyfmt;
pub mod recipes;
pub mod rng;
pub mod so101;
pub mod teleop;
pub mod view;

#[cfg(target_arch = "wasm32")]
pub mod ui;

pub use error::RecipeError;
