//! The Robot Pilot practice simulation (issue 13): a planar three-joint arm with a parallel
//! gripper in the vertical plane, teleoperated through Isaac Lab's differential IK controller
//! in relative mode, stepped at a fixed 100 Hz, deterministic bit for bit natively and in wasm.
//!
//! Plain Rust, no web-sys: the `#/teleop` page, the `bsv teleop-replay` command line and the
//! native tests all drive the same [`Sim`].
//!
//! - [`arm`]: the arm ([`ArmParams`]), forward kinematics `(x, z, phi)`, the 3×3 Jacobian and
//!   the manipulability the IK drill shows.
//! - [`control`]: the four IK methods ([`IkMethod`]: `dls`, `pinv`, `trans`, `adaptive-dls`)
//!   turning a task-space step into a joint step.
//! - [`scene`]: the tasks, the table, block, goal and obstacle layout, [`SceneConfig`] and its
//!   validation, the drawing geometry.
//! - [`sim`]: the operator's [`Command`], the [`State`], one 10 ms [`Sim::step`] with its
//!   [`Event`]s (grasp, drop, collision, joint limit, singularity, success, timeout …).
//! - [`episode`]: an [`Episode`] (config + start state + command stream + records), its CSV,
//!   exact [`replay`], and the proposed [`Label`] / [`FailureCategory`].
//! - [`pilot`]: a scripted pilot flying waypoints (tests, benchmark, parity check).
//! - [`metrics`](mod@metrics): the per-episode figures ([`EpisodeMetrics`]): duration, path, efficiency,
//!   stops, minimum manipulability, Fitts' index of difficulty and throughput.
//!
//! Every number comes from `+ − × ÷`, `sqrt` and the correctly rounded functions of
//! [`crate::math`], and input noise from the seeded [`crate::rng::NumpyRng`]; nothing reads a
//! clock, and no hash-map order is involved, so a start state plus a command stream replays
//! exactly.

// Each of this kernel's files warns about missing docs itself (`session.rs` is the page's).
pub mod arm;
pub mod control;
pub mod episode;
pub mod metrics;
pub mod pilot;
pub mod scene;
pub mod session;
pub mod sim;

mod error;

pub use arm::{fk, jacobian, manipulability, ArmParams, Pose2};
pub use control::{ik_step, ControlParams, IkMethod};
pub use episode::{
    episode_csv, episode_csv_head, parse_episode_csv, proposed_label, push_episode_csv_rows,
    replay, Episode, EpisodeRecorder, FailureCategory, Label, ReplayMismatch,
};
pub use error::TeleopError;
pub use metrics::{metrics, EpisodeMetrics, Fitts};
pub use scene::{
    Box2, Capsule, SceneConfig, SceneGeometry, Segment, Target, TargetStatus, TargetView, Task,
};
pub use sim::{Block, Command, Event, Outcome, Sim, State, StepRecord};
