//! A scripted pilot: commands that drive the tip through waypoints the way a steady operator
//! would (full deflection far away, proportionally less near the waypoint), for the native
//! tests, the benchmark, the wasm parity check and demonstrations. It reads only the
//! simulation's state, so the command stream it produces is as deterministic as the scene.

#![warn(missing_docs)]

use super::arm::fk;
use super::episode::{Episode, EpisodeRecorder};
use super::error::TeleopError;
use super::scene::{Layout, SceneConfig, Task, BLOCK_HALF, TABLE_Z};
use super::sim::{Command, Sim};

/// Where to bring the tip, with which gripper state, and for how many steps to stay once
/// there.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Waypoint {
    /// Tip x, m.
    pub x: f64,
    /// Tip z, m.
    pub z: f64,
    /// Gripper angle to reach; `None` leaves it as it is.
    pub phi: Option<f64>,
    /// The gripper state to command on the way and there.
    pub gripper_closed: bool,
    /// Steps to keep commanding this waypoint after reaching it.
    pub hold_steps: u32,
}

/// How close counts as at a waypoint, m …
pub const POSITION_TOLERANCE_M: f64 = 0.0005;
/// … and rad.
pub const ANGLE_TOLERANCE_RAD: f64 = 0.005;
/// Time constant of the approach, s: the axis value is the error over the distance covered
/// at full speed in this time, clamped to [−1, 1].
pub const APPROACH_S: f64 = 0.05;
/// A waypoint not reached within this many steps is given up (the pilot moves on).
pub const PATIENCE_STEPS: u32 = 600;

/// Follows waypoints in order.
#[derive(Debug, Clone)]
pub struct Pilot {
    waypoints: Vec<Waypoint>,
    index: usize,
    held_for: u32,
    tried_for: u32,
}

impl Pilot {
    /// A pilot at the first of `waypoints`.
    pub fn new(waypoints: Vec<Waypoint>) -> Pilot {
        Pilot {
            waypoints,
            index: 0,
            held_for: 0,
            tried_for: 0,
        }
    }

    /// Whether every waypoint has been visited.
    pub fn finished(&self) -> bool {
        self.index >= self.waypoints.len()
    }

    /// The command for the next step (`None` once finished).
    pub fn command(&mut self, sim: &Sim) -> Option<Command> {
        let config = sim.config();
        let tip = fk(&config.arm, &sim.state().q);
        let w = *self.waypoints.get(self.index)?;
        let v = config.tip_speed_m_per_s() * APPROACH_S;
        let r = config.turn_speed_rad_per_s() * APPROACH_S;
        let axis = |err: f64, scale: f64| (err / scale).clamp(-1.0, 1.0);
        let (ex, ez) = (w.x - tip.x, w.z - tip.z);
        let ephi = w.phi.map_or(0.0, |phi| phi - tip.phi);
        let there = ex.abs() <= POSITION_TOLERANCE_M
            && ez.abs() <= POSITION_TOLERANCE_M
            && ephi.abs() <= ANGLE_TOLERANCE_RAD;
        if there || self.tried_for >= PATIENCE_STEPS {
            self.held_for += 1;
        }
        self.tried_for += 1;
        let cmd = Command {
            dx: axis(ex, v),
            dz: axis(ez, v),
            dphi: axis(ephi, r),
            gripper_closed: w.gripper_closed,
        };
        if self.held_for > w.hold_steps {
            self.index += 1;
            self.held_for = 0;
            self.tried_for = 0;
        }
        Some(cmd)
    }
}

/// The waypoints that solve `task` from the default start (gripper pointing down): over the
/// block, down, close, up (over the wall for the obstacle task), over the goal's centre, down,
/// open, up; or each reach target in turn.
pub fn plan(config: &SceneConfig) -> Vec<Waypoint> {
    use std::f64::consts::FRAC_PI_2;
    let down = Some(-FRAC_PI_2);
    let at = |x: f64, z: f64, closed: bool, hold: u32| Waypoint {
        x,
        z,
        phi: down,
        gripper_closed: closed,
        hold_steps: hold,
    };
    let layout = Layout::of(&config.task);
    let (bx, bz) = layout.block_start;
    let goal_x = layout.goal.map_or(bx, |g| 0.5 * (g.x0 + g.x1));
    let clear_z = layout
        .obstacles
        .iter()
        .map(|o| o.z1 + BLOCK_HALF + 0.01)
        .fold(0.03, f64::max);
    // The block is set down with its bottom half a millimetre above the table.
    let place_z = TABLE_Z + BLOCK_HALF + 0.0005;
    match &config.task {
        Task::Reach { targets } => targets
            .iter()
            .map(|t| Waypoint {
                x: t.x,
                z: t.z,
                phi: down,
                gripper_closed: false,
                hold_steps: config.success_steps + 2,
            })
            .collect(),
        Task::PickPlace | Task::PickPlaceObstacle => vec![
            at(bx, bz + 0.04, false, 0),
            at(bx, bz, false, 2),
            at(bx, bz, true, 5),
            at(bx, clear_z, true, 0),
            at(goal_x, clear_z, true, 0),
            at(goal_x, place_z, true, 2),
            at(goal_x, place_z, false, 5),
            at(goal_x, clear_z, false, config.success_steps + 5),
        ],
    }
}

/// Records the episode the scripted pilot flies through `waypoints` (until the episode ends,
/// the waypoints run out, or `max_steps`).
pub fn fly(
    config: SceneConfig,
    waypoints: Vec<Waypoint>,
    max_steps: u64,
) -> Result<Episode, TeleopError> {
    let mut recorder = EpisodeRecorder::new(config)?;
    let mut pilot = Pilot::new(waypoints);
    for _ in 0..max_steps {
        if recorder.sim().done().is_some() {
            break;
        }
        let Some(cmd) = pilot.command(recorder.sim()) else {
            break;
        };
        recorder.step(&cmd);
    }
    Ok(recorder.into_episode())
}
