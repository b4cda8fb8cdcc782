//! The Robot Pilot practice simulation: a planar three-joint arm with a parallel gripper in
//! the vertical plane, teleoperated through Isaac Lab's differential IK controller in relative
//! mode, stepped at a fixed 100 Hz, deterministic bit for bit natively and in wasm. Plain Rust,
//! no web-sys: the `#/teleop` page, `bsv teleop-replay` and the native tests drive one [`Sim`].
//!
//! From the bottom up: [`arm`] (kinematics, Jacobian, manipulability), [`control`] (the four IK
//! methods), [`scene`] (tasks, layout, [`SceneConfig`]), [`sim`] (one 10 ms [`Sim::step`] and
//! its [`Event`]s), [`metrics`](mod@metrics) (an episode's figures from its records),
//! [`episode`] (recording, CSV, exact [`replay`], the proposed [`Label`]), [`pilot`] (a scripted
//! pilot) and [`session`] (the page's practice session and its files); [`input`] maps the
//! pilot's keyboard, gamepad and pointer to commands as Isaac Lab's devices do.
//!
//! Every number comes from `+ − × ÷`, `sqrt` and the correctly rounded functions of
//! [`crate::math`], and input noise from the seeded [`crate::rng::NumpyRng`]; nothing reads a
//! clock and no hash-map order is involved, so a start state plus a command stream replays
//! exactly.

// Each of this kernel's files warns about missing docs itself (`session` is the page's).
pub mod arm;
pub mod control;
pub mod episode;
pub mod events;
pub mod input;
pub mod metrics;
pub mod pilot;
pub mod recording;
pub mod rules;
pub mod scene;
pub mod session;
pub mod sim;

mod error;

pub use arm::{fk, jacobian, manipulability, ArmParams, Pose2};
pub use control::{ik_step, ControlParams, IkMethod};
pub use episode::{
    episode_csv, episode_csv_head, metrics, parse_episode_csv, proposed_label,
    push_episode_csv_rows, replay, Episode, EpisodeRecorder, FailureCategory, Label,
    ReplayMismatch,
};
pub use error::TeleopError;
pub use metrics::{EpisodeMetrics, Fitts};
pub use scene::{
    Box2, Capsule, SceneConfig, SceneGeometry, Segment, Target, TargetStatus, TargetView, Task,
};
pub use sim::{Block, Command, Event, Outcome, Sim, State, StepRecord};
