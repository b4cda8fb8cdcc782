//! One 10 ms step of the Robot Pilot scene, and the state it changes.
//!
//! Events of a condition that lasts (limits, collisions, singularity) are reported once, when
//! the condition starts.

#![warn(missing_docs)]

use std::collections::VecDeque;

use serde::{Deserialize, Serialize};

use super::arm::{fk, jacobian, manipulability};
use super::control::ik_step;
use super::error::TeleopError;
use super::rules::{
    clamp_to_limits, fall, goal_held, limit_speed, new_contacts, run_parts, step, Steps,
};
use super::scene::{
    arm_capsules, first_contact, point_box_distance, segment_box_distance, Box2, Capsule, Layout,
    SceneConfig, SceneGeometry, Segment, TargetStatus, TargetView, Task, BLOCK_HALF,
    CLOSED_HALF_WIDTH, CONTACT_SLOP_M, GRASP_ANGLE_TOLERANCE_RAD, GRASP_TOLERANCE_M,
    OPEN_HALF_WIDTH, TABLE_Z,
};
use crate::rng::NumpyRng;

pub use super::events::{Event, Outcome, GRAVITY, LIMIT_REARM_RAD};
/// A block let go with its bottom at most this high above the surface under it is set
/// down, not dropped: outside the goal that is a goal miss (see
/// [`super::episode::proposed_label`]), not [`Event::Drop`], m.
pub const PLACE_HEIGHT_M: f64 = 0.005;
/// Below this manipulability, relative to `l1 l2` (|sin q2| < 0.1, q2 within 5.7° of
/// stretched out or folded), a commanded motion reports [`Event::Singularity`].
pub const SINGULAR_RATIO: f64 = 0.1;

/// The operator's input for one 10 ms step: normalised device output, each axis in [−1, 1]
/// (a held key is ±1, a stick its deflection after the dead zone), before sensitivity. The
/// simulation turns it into motion: `dx × pos_sensitivity × POS_SPEED_PER_SENSITIVITY` m/s
/// along x (so Isaac Lab's keyboard default 0.4 moves the tip at 0.1 m/s), the same for z,
/// `dphi × rot_sensitivity × ROT_SPEED_PER_SENSITIVITY` rad/s for the gripper angle
/// ([`super::scene`]). `gripper_closed` is the gripper's commanded state (K toggles it).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Command {
    /// Tip motion along x (W/S, left stick x), [−1, 1].
    pub dx: f64,
    /// Tip motion along z (Q/E, right stick vertical), [−1, 1].
    pub dz: f64,
    /// Gripper angle motion (T/G, D-pad up/down), [−1, 1].
    pub dphi: f64,
    /// The commanded gripper state.
    pub gripper_closed: bool,
}

impl Command {
    /// No motion, gripper in the given state.
    pub fn idle(gripper_closed: bool) -> Command {
        Command {
            dx: 0.0,
            dz: 0.0,
            dphi: 0.0,
            gripper_closed,
        }
    }

    /// Axes clamped to [−1, 1], NaN read as 0.
    pub fn sanitized(&self) -> Command {
        let axis = |v: f64| if v.is_nan() { 0.0 } else { v.clamp(-1.0, 1.0) };
        Command {
            dx: axis(self.dx),
            dz: axis(self.dz),
            dphi: axis(self.dphi),
            gripper_closed: self.gripper_closed,
        }
    }

    /// Whether any axis asks for motion.
    pub fn moves(&self) -> bool {
        self.dx != 0.0 || self.dz != 0.0 || self.dphi != 0.0
    }
}

/// Where the block sits in the gripper while held: its centre in the gripper's frame
/// (along, across the gripper axis) and its angle relative to the gripper.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct GraspFrame {
    /// Along the gripper axis from the tip, m.
    pub along: f64,
    /// Across the gripper axis (to its left), m.
    pub across: f64,
    /// Block angle minus gripper angle, rad.
    pub angle: f64,
}

/// The block: its centre, angle, and whether it is held, falling or at rest.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Block {
    /// Centre x, m.
    pub x: f64,
    /// Centre z, m.
    pub z: f64,
    /// Angle of its faces from the axes, rad (0 at rest).
    pub angle: f64,
    /// Vertical speed while falling, m/s.
    pub vz: f64,
    /// In the gripper.
    pub held: bool,
    /// At rest on the table or an obstacle.
    pub resting: bool,
    /// Where it sits in the gripper (while held).
    pub grasp: Option<GraspFrame>,
}

impl Outcome {
    /// How the steps of `records` ended: the last [`Event::Success`] or [`Event::Timeout`]
    /// among them (`None`: ended by the pilot or interrupted).
    pub fn of(records: &[StepRecord]) -> Option<Outcome> {
        Outcome::of_events(records.iter().map(|r| &r.events[..]))
    }
}

/// The whole state of the scene between steps. Two states compare equal exactly when the
/// scene is the same bit for bit (the page's reset check compares against
/// [`Sim::start_state`]).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct State {
    /// Time since the episode started, s (`step / 100`).
    pub t_s: f64,
    /// Steps taken.
    pub step: u64,
    /// Joint angles, rad.
    pub q: [f64; 3],
    /// The gripper's state.
    pub gripper_closed: bool,
    /// The block.
    pub block: Block,
    /// The reach target to reach now (= the number reached).
    pub target_index: usize,
    /// Consecutive steps the goal condition has held.
    pub success_count: u32,
    /// Set when the episode ended; later steps change nothing.
    pub done: Option<Outcome>,
    /// Commands given but not yet applied (length `latency_steps`).
    pub pending: VecDeque<Command>,
    /// Which links (1–3, and 4 = carried block) were stopped by contact on the last step.
    pub contact: [bool; 4],
    /// Which joints are stopped at a position limit (until they move `LIMIT_REARM_RAD` away).
    pub at_limit: [bool; 3],
    /// Whether the last step was cut by a joint speed limit.
    pub speed_limited: bool,
    /// Whether the last step was commanded near a singularity.
    pub singular: bool,
    /// Whether the block has been grasped at least once this episode.
    pub ever_grasped: bool,
}

/// What one step did: the operator's command, the command the arm got (after latency and
/// noise), the resulting pose and gripper, and the events.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StepRecord {
    /// The step's number, from 1.
    pub step: u64,
    /// Time after the step, s.
    pub t_s: f64,
    /// The operator's command (sanitized).
    pub cmd: Command,
    /// The command applied this step (after latency and noise).
    pub applied: Command,
    /// Joint angles after the step, rad.
    pub q: [f64; 3],
    /// Tip x after the step, m.
    pub x: f64,
    /// Tip z after the step, m.
    pub z: f64,
    /// Gripper angle after the step, rad.
    pub phi: f64,
    /// Gripper state after the step.
    pub gripper_closed: bool,
    /// Whether the block is held after the step.
    pub held: bool,
    /// Block centre x after the step, m.
    pub block_x: f64,
    /// Block centre z after the step, m.
    pub block_z: f64,
    /// [`super::arm::manipulability`] at `q`.
    pub manipulability: f64,
    /// What the step detected, in the order detected.
    pub events: Vec<Event>,
}

/// The simulation: a validated config, the start state and the current state.
#[derive(Debug, Clone)]
pub struct Sim {
    config: SceneConfig,
    layout: Layout,
    start: State,
    state: State,
    rng: NumpyRng,
}

impl Sim {
    /// The fixed step, s (100 Hz).
    pub const DT: f64 = 0.01;
    /// Steps per second.
    pub const RATE_HZ: u32 = 100;

    /// A simulation at the start state of `config` (validated first).
    pub fn new(config: SceneConfig) -> Result<Sim, TeleopError> {
        config.validate()?;
        let layout = Layout::of(&config.task);
        let start = start_state(&config, &layout);
        let rng = NumpyRng::new(config.noise_seed);
        Ok(Sim {
            state: start.clone(),
            start,
            rng,
            layout,
            config,
        })
    }

    /// The config.
    pub fn config(&self) -> &SceneConfig {
        &self.config
    }

    /// Where the block, goal and obstacles are.
    pub fn layout(&self) -> &Layout {
        &self.layout
    }

    /// The state every episode starts from.
    pub fn start_state(&self) -> &State {
        &self.start
    }

    /// The current state.
    pub fn state(&self) -> &State {
        &self.state
    }

    /// Back to the start state, bit for bit (the noise generator restarts too).
    pub fn reset(&mut self) {
        self.state = self.start.clone();
        self.rng = NumpyRng::new(self.config.noise_seed);
    }

    /// Whether the episode has ended.
    pub fn done(&self) -> Option<Outcome> {
        self.state.done
    }

    /// The record of the current state without stepping (no events): what the page shows
    /// before the first step.
    pub fn snapshot(&self) -> StepRecord {
        self.record(
            Command::idle(self.state.gripper_closed),
            Command::idle(self.state.gripper_closed),
            Vec::new(),
        )
    }

    fn record(&self, cmd: Command, applied: Command, events: Vec<Event>) -> StepRecord {
        let s = &self.state;
        let pose = fk(&self.config.arm, &s.q);
        StepRecord {
            step: s.step,
            t_s: s.t_s,
            cmd,
            applied,
            q: s.q,
            x: pose.x,
            z: pose.z,
            phi: pose.phi,
            gripper_closed: s.gripper_closed,
            held: s.block.held,
            block_x: s.block.x,
            block_z: s.block.z,
            manipulability: manipulability(&self.config.arm, &s.q),
            events,
        }
    }

    /// Advances one 10 ms step; after the episode ended, nothing changes and the record has
    /// no events. A step, in order:
    /// 1. the operator's [`Command`] (axes clamped to [−1, 1], NaN → 0) enters the latency queue
    ///    and the command `latency_steps` steps old leaves it (the queue starts full of idle
    ///    commands with the start gripper state), so a command acts exactly `latency_steps` steps
    ///    after it was given;
    /// 2. with `noise_sigma > 0`, `sigma × N(0, 1)` is added to each of its three axes (three draws
    ///    per step, dx then dz then dphi, from `np.random.default_rng(noise_seed)`);
    /// 3. the task step `Δx = (dx v, dz v, dphi ω) × DT` (`v`, `ω`: the speeds of
    ///    [`SceneConfig::tip_speed_m_per_s`] and [`SceneConfig::turn_speed_rad_per_s`]) becomes a
    ///    joint step by the IK method ([`super::control`]);
    /// 4. joint speed limits scale the whole step down (its direction is kept) and
    ///    [`Event::SpeedLimit`] names the joint that limited it; joint position limits then clamp
    ///    each joint ([`Event::JointLimit`]);
    /// 5. if the new pose puts a link, a finger or the carried block into the table or an obstacle,
    ///    or a link (1–3, not a finger) into the block lying at rest (on the table or an obstacle,
    ///    not grasped), the arm does not move this step ([`Event::Collision`]): contact stops it,
    ///    as a real arm's safety stop would. Touching the resting block with a link is a contact,
    ///    as the Academy's task rules count it; pushing it is not modelled (the block does not
    ///    move). The fingers are left to the gripper rules of step 6 (a grasp within the
    ///    tolerances, else a miss), and a link the block came to rest against may move away from it
    ///    (a move counts only when it brings the link closer);
    /// 6. the gripper follows the command: closing with the block's centre within
    ///    `GRASP_TOLERANCE_M` of the tip and the fingers within `GRASP_ANGLE_TOLERANCE_RAD` of a
    ///    pair of faces grasps it ([`Event::Grasp`]), closing on nothing is [`Event::GraspMiss`];
    ///    opening lets go ([`Event::Release`], and [`Event::Drop`] when the block's centre is not
    ///    over the goal region and its bottom is more than `PLACE_HEIGHT_M` above the surface under
    ///    it: a block set down outside the goal is a goal miss, not a drop); a released block falls
    ///    (g = 9.81 m/s², explicit Euler) onto the table or an obstacle top and settles face down;
    /// 7. the task's goal condition is counted ([`SceneConfig::success_steps`] consecutive steps →
    ///    [`Event::TargetReached`] / [`Event::Success`]), then the time box ([`Event::Timeout`]).
    pub fn step(&mut self, cmd: &Command) -> StepRecord {
        let (cmd, applied, events) = step(self, cmd);
        self.record(cmd, applied, events)
    }

    /// The first link (1–3; the fingers are left to the gripper rules) that the move from `q`
    /// to the pose of `moved` (its capsules) brings into the block lying at rest: closer to it
    /// than the link's radius, and closer than at `q` (a link the block came to rest against
    /// may move away). `None` while the block is held or falling.
    fn resting_block_contact(&self, q: &[f64; 3], moved: &[Capsule; 5]) -> Option<u8> {
        let b = &self.state.block;
        if b.held || !b.resting {
            return None;
        }
        // At rest the block lies face down (angle 0): an axis-aligned square.
        let block = Box2 {
            x0: b.x - BLOCK_HALF,
            z0: b.z - BLOCK_HALF,
            x1: b.x + BLOCK_HALF,
            z1: b.z + BLOCK_HALF,
        };
        let gap = |cap: &Capsule| segment_box_distance(&cap.segment, &block) - cap.radius;
        let mut before: Option<[Capsule; 5]> = None;
        (0..3).find_map(|i| {
            let now = gap(&moved[i]);
            if now >= 0.0 {
                return None;
            }
            let was = before
                .get_or_insert_with(|| arm_capsules(&self.config.arm, q, self.finger_half_width()));
            (now < gap(&was[i])).then_some(i as u8 + 1)
        })
    }

    /// Whether the block, carried at pose `q`, would press into the table or an obstacle
    /// (the block counts as the circle inside it).
    fn held_block_contact(&self, q: &[f64; 3]) -> bool {
        let Some(grasp) = self.state.block.grasp else {
            return false;
        };
        let (x, z, _) = carried(&fk(&self.config.arm, q), &grasp);
        z - BLOCK_HALF < TABLE_Z - CONTACT_SLOP_M
            || self
                .layout
                .obstacles
                .iter()
                .any(|b| point_box_distance(x, z, b) < BLOCK_HALF - CONTACT_SLOP_M)
    }

    fn finger_half_width(&self) -> f64 {
        if !self.state.gripper_closed {
            OPEN_HALF_WIDTH
        } else if self.state.block.held {
            BLOCK_HALF
        } else {
            CLOSED_HALF_WIDTH
        }
    }

    /// What the page draws for the current state.
    pub fn geometry(&self) -> SceneGeometry {
        geometry(&self.config, &self.layout, &self.state)
    }
}

// Each part has one caller, `step`: inlined there, the step is one function.
impl Steps for Sim {
    type Command = Command;

    run_parts!(Command);

    #[inline(always)]
    fn noisy(mut cmd: Command, noise: impl FnOnce(&mut [f64])) -> Command {
        let mut axes = [cmd.dx, cmd.dz, cmd.dphi];
        noise(&mut axes);
        [cmd.dx, cmd.dz, cmd.dphi] = axes;
        cmd
    }

    /// Steps 3–5: IK, speed and position limits, contact.
    #[inline(always)]
    fn move_arm(&mut self, applied: &Command, events: &mut Vec<Event>) {
        let arm = self.config.arm;
        let q = self.state.q;
        let v = self.config.tip_speed_m_per_s() * Sim::DT;
        let w = self.config.turn_speed_rad_per_s() * Sim::DT;
        let dx = [applied.dx * v, applied.dz * v, applied.dphi * w];
        let commanded = dx.iter().any(|d| *d != 0.0);

        let singular_now =
            commanded && manipulability(&arm, &q) < SINGULAR_RATIO * arm.links[0] * arm.links[1];
        let solved = if commanded {
            ik_step(&self.config.control, &jacobian(&arm, &q), &dx)
        } else {
            Some([0.0; 3])
        };
        let singular_now = singular_now || solved.is_none();
        if singular_now && !self.state.singular {
            events.push(Event::Singularity);
        }
        self.state.singular = singular_now;
        let mut dq = solved.unwrap_or([0.0; 3]);

        // Speed limits: scale the whole step.
        let was = self.state.speed_limited;
        self.state.speed_limited = limit_speed(&mut dq, &arm.qd_max, Sim::DT, was, events);

        // Position limits: clamp each joint (a joint resting against its limit is one stop
        // until it leaves the limit).
        let mut q_new = [0.0; 3];
        let limits: [(f64, f64); 3] = std::array::from_fn(|i| (arm.q_min[i], arm.q_max[i]));
        clamp_to_limits(
            &q,
            &dq,
            &limits,
            &mut self.state.at_limit,
            &mut q_new,
            events,
        );

        // Contact: a move into the table or an obstacle does not happen.
        let mut contact = [false; 4];
        if q_new != q {
            let capsules = arm_capsules(&arm, &q_new, self.finger_half_width());
            if let Some(link) = first_contact(&capsules, &self.layout.obstacles)
                .or_else(|| self.resting_block_contact(&q, &capsules))
            {
                contact[usize::from(link) - 1] = true;
            } else if self.state.block.held && self.held_block_contact(&q_new) {
                contact[3] = true;
            }
        }
        new_contacts(&contact, &mut self.state.contact, events);
        if !contact.iter().any(|c| *c) {
            self.state.q = q_new;
        }
    }

    /// Step 6: grasp, miss, release, drop.
    #[inline(always)]
    fn operate_gripper(&mut self, close: bool, events: &mut Vec<Event>) {
        if close == self.state.gripper_closed {
            return;
        }
        self.state.gripper_closed = close;
        let tip = fk(&self.config.arm, &self.state.q);
        let block = &mut self.state.block;
        if close {
            let (dx, dz) = (block.x - tip.x, block.z - tip.z);
            let near = (dx * dx + dz * dz).sqrt() <= GRASP_TOLERANCE_M;
            let misalign = face_misalignment(tip.phi - block.angle);
            if near && misalign <= GRASP_ANGLE_TOLERANCE_RAD && !block.held {
                let (s, c) = crate::math::sincos(tip.phi);
                block.grasp = Some(GraspFrame {
                    along: dx * c + dz * s,
                    across: -dx * s + dz * c,
                    angle: block.angle - tip.phi,
                });
                block.held = true;
                block.resting = false;
                block.vz = 0.0;
                self.state.ever_grasped = true;
                events.push(Event::Grasp);
            } else {
                events.push(Event::GraspMiss);
            }
        } else if block.held {
            block.held = false;
            block.grasp = None;
            block.vz = 0.0;
            block.angle = 0.0;
            events.push(Event::Release);
            let over_goal = self
                .layout
                .goal
                .is_some_and(|g| block.x >= g.x0 && block.x <= g.x1);
            let bottom = block.z - BLOCK_HALF;
            let set_down =
                bottom - support_below(block.x, bottom, &self.layout.obstacles) <= PLACE_HEIGHT_M;
            if !over_goal && !set_down {
                events.push(Event::Drop);
            }
        }
    }

    /// The block follows the gripper, falls, or rests.
    #[inline(always)]
    fn move_object(&mut self) {
        let tip = fk(&self.config.arm, &self.state.q);
        let block = &mut self.state.block;
        if let Some(grasp) = block.grasp.filter(|_| block.held) {
            let (x, z, angle) = carried(&tip, &grasp);
            block.x = x;
            block.z = z;
            block.angle = angle;
            return;
        }
        if block.resting {
            return;
        }
        let support = support_below(block.x, block.z - BLOCK_HALF, &self.layout.obstacles);
        if fall(&mut block.z, &mut block.vz, BLOCK_HALF, support, Sim::DT) {
            block.resting = true;
        }
    }

    /// Step 7: goal condition, targets, success.
    #[inline(always)]
    fn check_goal(&mut self, events: &mut Vec<Event>) {
        let tip = fk(&self.config.arm, &self.state.q);
        let s = &mut self.state;
        let holds = match &self.config.task {
            Task::Reach { targets } => targets.get(s.target_index).is_some_and(|t| {
                let (dx, dz) = (tip.x - t.x, tip.z - t.z);
                (dx * dx + dz * dz).sqrt() <= t.radius
            }),
            Task::PickPlace | Task::PickPlaceObstacle => {
                let b = &s.block;
                let on_table = b.z == TABLE_Z + BLOCK_HALF;
                !b.held
                    && b.resting
                    && on_table
                    && self.layout.goal.is_some_and(|g| b.x >= g.x0 && b.x <= g.x1)
            }
        };
        if !goal_held(&mut s.success_count, holds, self.config.success_steps) {
            return;
        }
        if let Task::Reach { targets } = &self.config.task {
            events.push(Event::TargetReached {
                index: s.target_index,
            });
            s.target_index += 1;
            if s.target_index < targets.len() {
                return;
            }
        }
        s.done = Some(Outcome::Success);
        events.push(Event::Success);
    }
}

/// The state `config` starts from.
fn start_state(config: &SceneConfig, layout: &Layout) -> State {
    let (x, z) = layout.block_start;
    State {
        t_s: 0.0,
        step: 0,
        q: config.start_q,
        gripper_closed: false,
        block: Block {
            x,
            z,
            angle: 0.0,
            vz: 0.0,
            held: false,
            resting: true,
            grasp: None,
        },
        target_index: 0,
        success_count: 0,
        done: None,
        pending: (0..config.latency_steps)
            .map(|_| Command::idle(false))
            .collect(),
        contact: [false; 4],
        at_limit: [false; 3],
        speed_limited: false,
        singular: false,
        ever_grasped: false,
    }
}

/// The carried block's centre and angle for a tip pose.
fn carried(tip: &super::arm::Pose2, grasp: &GraspFrame) -> (f64, f64, f64) {
    let (s, c) = crate::math::sincos(tip.phi);
    (
        tip.x + grasp.along * c - grasp.across * s,
        tip.z + grasp.along * s + grasp.across * c,
        tip.phi + grasp.angle,
    )
}

/// How far `angle` is from the nearest multiple of π/2 (a square's faces), rad.
fn face_misalignment(angle: f64) -> f64 {
    use std::f64::consts::FRAC_PI_2;
    let r = angle.rem_euclid(FRAC_PI_2);
    r.min(FRAC_PI_2 - r)
}

/// The highest surface under a block centred at `x` whose bottom is at `bottom`: the table or
/// the top of an obstacle the block overlaps in x and is above.
fn support_below(x: f64, bottom: f64, obstacles: &[Box2]) -> f64 {
    obstacles
        .iter()
        .filter(|b| x + BLOCK_HALF > b.x0 && x - BLOCK_HALF < b.x1 && b.z1 <= bottom + 1e-12)
        .map(|b| b.z1)
        .fold(TABLE_Z, f64::max)
}

fn geometry(config: &SceneConfig, layout: &Layout, state: &State) -> SceneGeometry {
    let arm = &config.arm;
    let half_width = if !state.gripper_closed {
        OPEN_HALF_WIDTH
    } else if state.block.held {
        BLOCK_HALF
    } else {
        CLOSED_HALF_WIDTH
    };
    let caps: [Capsule; 5] = arm_capsules(arm, &state.q, half_width);
    let b = &state.block;
    let (s, c) = crate::math::sincos(b.angle);
    let corner = |u: f64, v: f64| {
        (
            b.x + (u * c - v * s) * BLOCK_HALF,
            b.z + (u * s + v * c) * BLOCK_HALF,
        )
    };
    let reach: f64 = arm.links.iter().sum();
    let targets = config
        .task
        .targets()
        .iter()
        .enumerate()
        .map(|(i, t)| TargetView {
            target: *t,
            status: match i.cmp(&state.target_index) {
                std::cmp::Ordering::Less => TargetStatus::Done,
                std::cmp::Ordering::Equal => TargetStatus::Current,
                std::cmp::Ordering::Greater => TargetStatus::Pending,
            },
        })
        .collect();
    SceneGeometry {
        links: [caps[0], caps[1], caps[2]],
        fingers: [caps[3], caps[4]],
        tip: fk(arm, &state.q),
        table: Segment {
            x0: -reach - 0.02,
            z0: TABLE_Z,
            x1: reach + 0.02,
            z1: TABLE_Z,
        },
        block: [
            corner(-1.0, -1.0),
            corner(1.0, -1.0),
            corner(1.0, 1.0),
            corner(-1.0, 1.0),
        ],
        block_held: b.held,
        goal: layout.goal,
        obstacles: layout.obstacles.clone(),
        targets,
        bounds: Box2 {
            x0: -reach - 0.02,
            z0: TABLE_Z - 0.02,
            x1: reach + 0.02,
            z1: reach + 0.02,
        },
    }
}

#[cfg(test)]
mod tests;
