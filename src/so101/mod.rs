//! The SO-101 practice simulation: TheRobotStudio's five-joint arm with its gripper, in 3D,
//! teleoperated through Isaac Lab's differential IK controller in relative pose mode, stepped
//! at a fixed 100 Hz, deterministic bit for bit natively and in wasm. Plain Rust, no web-sys:
//! the `#/so101` page, `bsv teleop-replay` and the native tests drive one [`Sim`].
//!
//! From the bottom up: [`model`] (the arm's numbers, with the file and commit they come
//! from), [`kinematics`] (forward kinematics as MuJoCo computes it, the Jacobian,
//! manipulability), [`control`] (the four IK methods on the 6×5 Jacobian), [`scene`] (table,
//! cube, goal, obstacle, [`SceneConfig`]), [`sim`] (one 10 ms [`Sim::step`] and its events, the
//! planar arm's [`crate::teleop::Event`]s) and [`episode`] (recording, CSV, exact replay, the
//! session's episode kind), [`input`] (Isaac Lab's keyboard and gamepad mapping), and
//! [`dataset`] (the labelled episodes as a LeRobot v3.0 dataset).

pub mod control;
pub mod dataset;
pub mod episode;
pub mod input;
pub mod kinematics;
pub mod model;
pub mod scene;
pub mod sim;

pub use control::ik_step;
pub use episode::{episode_csv, parse_episode_csv, replay, Episode, EpisodeRecorder};
pub use kinematics::{chain, fk, jacobian, manipulability, Chain, Frame, Jacobian};
pub use scene::{SceneConfig, EMBODIMENT};
pub use sim::{Command, Cube, Sim, State, StepRecord};

#[cfg(test)]
mod tests;
