//! An episode's frames: the episode replayed from its start state, sampled every
//! [`STEPS_PER_FRAME`] steps, each frame the joints measured before its step
//! (`observation.state`), the joints that step commanded (`action`) and the cube and goal
//! (`observation.environment_state`), in LeRobot's SO follower units.

use super::error::DatasetError;
use crate::so101::model::JAW;
use crate::so101::scene::{JAW_CLOSED, JAW_OPEN};
use crate::so101::sim::{jaw_of, Sim};
use crate::so101::Episode;

/// Frames per second of the dataset.
pub const FPS: u32 = 25;

/// Simulation steps per frame (100 Hz / [`FPS`]).
pub const STEPS_PER_FRAME: usize = (Sim::RATE_HZ / FPS) as usize;

/// The names of `observation.state` and `action`: the SO follower's motors, `.pos`.
pub const JOINT_NAMES: [&str; 6] = [
    "shoulder_pan.pos",
    "shoulder_lift.pos",
    "elbow_flex.pos",
    "wrist_flex.pos",
    "wrist_roll.pos",
    "gripper.pos",
];

/// The names of `observation.environment_state`: the cube's centre (m), its yaw about the
/// vertical (rad, in (−π, π]) and the goal square's centre (m), in the world frame.
pub const ENVIRONMENT_NAMES: [&str; 6] = [
    "cube.x_m",
    "cube.y_m",
    "cube.z_m",
    "cube.yaw_rad",
    "goal.x_m",
    "goal.y_m",
];

/// One frame's vectors (the per-frame indices and flags follow from its place).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Frame {
    /// Joint positions before the frame's step: five joints in degrees, the gripper 0–100.
    pub state: [f32; 6],
    /// The joint positions the frame's step commanded, same units.
    pub action: [f32; 6],
    /// The cube and the goal ([`ENVIRONMENT_NAMES`]).
    pub environment: [f32; 6],
}

/// A jaw angle (rad) as LeRobot's `RANGE_0_100` gripper reads it: 0 at the low end of the
/// jaw's range, 100 at the high end (open).
pub fn gripper_percent(jaw_rad: f64) -> f64 {
    let (lo, hi) = JAW.range;
    (jaw_rad - lo) / (hi - lo) * 100.0
}

/// Five joint angles (rad) and a jaw angle (rad) as the SO follower reports them with
/// `use_degrees`: degrees from the middle of the calibrated range (the MJCF's zero), and the
/// gripper 0–100.
fn follower_units(q: &[f64; 5], jaw_rad: f64) -> [f32; 6] {
    let mut out = [0.0f32; 6];
    for (o, a) in out.iter_mut().zip(q) {
        *o = a.to_degrees() as f32;
    }
    out[5] = gripper_percent(jaw_rad) as f32;
    out
}

/// The episode's frames: its commands replayed from its start state (which must be the
/// config's, and every step must reproduce its record, as [`crate::so101::replay`] checks),
/// one frame before every [`STEPS_PER_FRAME`]th step, `ceil(steps / STEPS_PER_FRAME)` in all.
pub fn episode_frames(episode: &Episode) -> Result<Vec<Frame>, DatasetError> {
    let mut replay = FrameReplay::new(episode)?;
    while !replay.advance(episode, usize::MAX)? {}
    Ok(replay.into_frames())
}

/// [`episode_frames`] in pieces: a page replays a long episode a few hundred steps per task.
#[derive(Debug, Clone)]
pub struct FrameReplay {
    sim: Sim,
    next: usize,
    frames: Vec<Frame>,
}

impl FrameReplay {
    /// The replay of `episode` from its start, refused if the episode is empty, has not one
    /// record a command or does not start from its configuration's start state.
    pub fn new(episode: &Episode) -> Result<FrameReplay, DatasetError> {
        let steps = episode.commands.len();
        if steps == 0 {
            return Err(DatasetError::EmptyEpisode);
        }
        if episode.records.len() != steps {
            return Err(DatasetError::NotReplayed { step: 0 });
        }
        let sim =
            Sim::new(episode.config.clone()).map_err(|_| DatasetError::NotReplayed { step: 0 })?;
        if *sim.start_state() != episode.start {
            return Err(DatasetError::NotReplayed { step: 0 });
        }
        Ok(FrameReplay {
            sim,
            next: 0,
            frames: Vec::with_capacity(steps.div_ceil(STEPS_PER_FRAME)),
        })
    }

    /// Steps replayed so far.
    pub fn steps_done(&self) -> usize {
        self.next
    }

    /// Replays up to `max_steps` more steps of `episode` (the one [`FrameReplay::new`] was
    /// given); `true` once every step is replayed.
    pub fn advance(&mut self, episode: &Episode, max_steps: usize) -> Result<bool, DatasetError> {
        let goal = episode.config.goal;
        let end = self
            .next
            .saturating_add(max_steps)
            .min(episode.commands.len());
        for i in self.next..end {
            let (cmd, record) = (&episode.commands[i], &episode.records[i]);
            let sim = &mut self.sim;
            let sample = i % STEPS_PER_FRAME == 0;
            let before = sample.then(|| {
                let s = sim.state();
                let cube = &s.cube;
                let yaw = crate::math::atan2(cube.rot[1][0], cube.rot[0][0]);
                (
                    follower_units(&s.q, jaw_of(s)),
                    [
                        cube.pos[0] as f32,
                        cube.pos[1] as f32,
                        cube.pos[2] as f32,
                        yaw as f32,
                        goal[0] as f32,
                        goal[1] as f32,
                    ],
                )
            });
            let step = i as u64 + 1;
            if sim.done().is_some() || sim.step(cmd) != *record {
                return Err(DatasetError::NotReplayed { step });
            }
            if let Some((state, environment)) = before {
                let jaw = if sim.state().gripper_closed {
                    JAW_CLOSED
                } else {
                    JAW_OPEN
                };
                self.frames.push(Frame {
                    state,
                    action: follower_units(&sim.target_q(), jaw),
                    environment,
                });
            }
        }
        self.next = end;
        Ok(self.next == episode.commands.len())
    }

    /// The frames replayed.
    pub fn into_frames(self) -> Vec<Frame> {
        self.frames
    }
}
