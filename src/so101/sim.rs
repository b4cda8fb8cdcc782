//! One 10 ms step of the SO-101 scene ([`Sim::step`]): latency, noise, differential IK,
//! joint speed and position limits, contact, the gripper rules, the cube, the goal and the
//! time box, as the planar arm's [`crate::teleop::Sim`] does them, in 3D. The events are the
//! planar arm's [`Event`]s: links 1–6 in a collision are shoulder, upper arm, lower arm,
//! wrist, gripper and moving jaw, 7 the carried cube; joints 1–5 in chain order.

use std::collections::VecDeque;

use serde::{Deserialize, Serialize};

use super::control::ik_step;
use super::kinematics::{
    chain, jacobian_of, manipulability, mat_vec, mul_t, rotation_matrix, rotation_vector, Chain,
    Mat3,
};
use super::model::joint_limits;
use super::scene::{
    jaw_aligned, link_boxes, obstacle_box, table_or_obstacle_contact, Obb, SceneConfig,
    CONTACT_SLOP_M, CUBE_HALF, GOAL_HALF, GRASP_TOLERANCE_M, JAW_CLOSED, JAW_HOLDING, JAW_OPEN,
    OBSTACLE, PLACE_HEIGHT_M, TABLE_Z,
};
use crate::rng::NumpyRng;
use crate::teleop::rules::{
    clamp_to_limits, fall, goal_held, limit_speed, new_contacts, run_parts, step, Steps,
};
use crate::teleop::sim::{Event, Outcome};
use crate::teleop::TeleopError;

/// Below this smallest singular value of the Jacobian a commanded motion is near a
/// singularity ([`Event::Singularity`]).
pub const SINGULAR_SIGMA: f64 = 0.01;

/// The operator's input for one step: each axis normalised to [−1, 1] before sensitivity
/// (Isaac Lab's Se3Keyboard gives ±1 per held key, Se3Gamepad the stick's deflection after
/// the dead zone), in the world frame, and the gripper's commanded state.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Command {
    /// Along x (W/S).
    pub dx: f64,
    /// Along y (A/D).
    pub dy: f64,
    /// Along z (Q/E).
    pub dz: f64,
    /// About x (Z/X).
    pub droll: f64,
    /// About y (T/G).
    pub dpitch: f64,
    /// About z (C/V).
    pub dyaw: f64,
    /// The commanded gripper state (K toggles it).
    pub gripper_closed: bool,
}

impl Command {
    /// No motion, gripper in the given state.
    pub fn idle(gripper_closed: bool) -> Command {
        Command {
            gripper_closed,
            ..Command::default()
        }
    }

    /// The six axes in order.
    pub fn axes(&self) -> [f64; 6] {
        [
            self.dx,
            self.dy,
            self.dz,
            self.droll,
            self.dpitch,
            self.dyaw,
        ]
    }

    /// A command with these axes.
    pub fn with_axes(a: [f64; 6], gripper_closed: bool) -> Command {
        Command {
            dx: a[0],
            dy: a[1],
            dz: a[2],
            droll: a[3],
            dpitch: a[4],
            dyaw: a[5],
            gripper_closed,
        }
    }

    /// Axes clamped to [−1, 1], NaN read as 0.
    pub fn sanitized(&self) -> Command {
        let axis = |v: f64| if v.is_nan() { 0.0 } else { v.clamp(-1.0, 1.0) };
        Command::with_axes(self.axes().map(axis), self.gripper_closed)
    }

    /// Whether any axis asks for motion.
    pub fn moves(&self) -> bool {
        self.axes().iter().any(|v| *v != 0.0)
    }
}

/// Where the cube sits in the gripper while held: its centre and orientation in the tool
/// frame.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Grasp {
    /// Centre in the tool frame, m.
    pub offset: [f64; 3],
    /// Orientation in the tool frame.
    pub rel: Mat3,
}

/// The cube.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Cube {
    /// Centre, m.
    pub pos: [f64; 3],
    /// Orientation.
    pub rot: Mat3,
    /// Vertical speed while falling, m/s.
    pub vz: f64,
    /// In the gripper.
    pub held: bool,
    /// At rest on the table or the obstacle.
    pub resting: bool,
    /// Where it sits in the gripper (while held).
    pub grasp: Option<Grasp>,
}

impl Cube {
    /// The cube's box.
    pub fn obb(&self) -> Obb {
        Obb {
            centre: self.pos,
            rot: self.rot,
            half: [CUBE_HALF; 3],
        }
    }
}

/// The whole state of the scene between steps; equal states are the same scene bit for bit.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct State {
    /// Time since the start, s.
    pub t_s: f64,
    /// Steps taken.
    pub step: u64,
    /// Joint angles, rad.
    pub q: [f64; 5],
    /// The gripper's state.
    pub gripper_closed: bool,
    /// The cube.
    pub cube: Cube,
    /// Consecutive steps the cube has rested in the goal.
    pub success_count: u32,
    /// Set when the episode ended; later steps change nothing.
    pub done: Option<Outcome>,
    /// Commands given but not yet applied (length `latency_steps`).
    pub pending: VecDeque<Command>,
    /// Links (1–6, 7 the carried cube) stopped by contact on the last step.
    pub contact: [bool; 7],
    /// Joints stopped at a position limit.
    pub at_limit: [bool; 5],
    /// Whether the last step was cut by a joint speed limit.
    pub speed_limited: bool,
    /// Whether the last step was commanded near a singularity.
    pub singular: bool,
    /// Whether the cube has been grasped this episode.
    pub ever_grasped: bool,
    /// The tool orientation the rotation commands asked for since they began (`None` while
    /// no rotation is commanded).
    pub rot_target: Option<Mat3>,
    /// The angle between that orientation and the tool's, rad: the rotation asked for that a
    /// five-joint arm did not follow.
    pub orientation_error: f64,
}

/// What one step did.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StepRecord {
    /// The step's number, from 1.
    pub step: u64,
    /// Time after the step, s.
    pub t_s: f64,
    /// The operator's command (sanitized).
    pub cmd: Command,
    /// The command applied (after latency and noise).
    pub applied: Command,
    /// Joint angles after the step, rad.
    pub q: [f64; 5],
    /// Tool position, m.
    pub tool: [f64; 3],
    /// Tool roll, pitch, yaw from pointing straight down
    /// ([`super::kinematics::Frame::rpy_from_down`]), rad.
    pub rpy: [f64; 3],
    /// Gripper state.
    pub gripper_closed: bool,
    /// Whether the cube is held.
    pub held: bool,
    /// Cube centre, m.
    pub cube: [f64; 3],
    /// Position manipulability at `q`, m³.
    pub manipulability: f64,
    /// [`State::orientation_error`], rad.
    pub orientation_error: f64,
    /// What the step detected, in order.
    pub events: Vec<Event>,
}

/// The simulation.
#[derive(Debug, Clone)]
pub struct Sim {
    config: SceneConfig,
    start: State,
    state: State,
    rng: NumpyRng,
    /// The joint angles the last step commanded ([`Sim::target_q`]), rad.
    target_q: [f64; 5],
}

const IDENTITY: Mat3 = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];

impl Sim {
    /// Step length, s.
    pub const DT: f64 = 0.01;
    /// Steps per second.
    pub const RATE_HZ: u32 = 100;

    /// A simulation of a validated config, at its start state.
    pub fn new(config: SceneConfig) -> Result<Sim, TeleopError> {
        config.validate()?;
        let start = State {
            t_s: 0.0,
            step: 0,
            q: config.start_q,
            gripper_closed: false,
            cube: Cube {
                pos: [
                    config.cube_start[0],
                    config.cube_start[1],
                    TABLE_Z + CUBE_HALF,
                ],
                rot: IDENTITY,
                vz: 0.0,
                held: false,
                resting: true,
                grasp: None,
            },
            success_count: 0,
            done: None,
            pending: (0..config.latency_steps)
                .map(|_| Command::idle(false))
                .collect(),
            contact: [false; 7],
            at_limit: [false; 5],
            speed_limited: false,
            singular: false,
            ever_grasped: false,
            rot_target: None,
            orientation_error: 0.0,
        };
        Ok(Sim {
            rng: NumpyRng::new(config.noise_seed),
            config,
            target_q: start.q,
            state: start.clone(),
            start,
        })
    }

    /// The config.
    pub fn config(&self) -> &SceneConfig {
        &self.config
    }

    /// The start state.
    pub fn start_state(&self) -> &State {
        &self.start
    }

    /// The current state.
    pub fn state(&self) -> &State {
        &self.state
    }

    /// Back to the start state (and the noise to its seed).
    pub fn reset(&mut self) {
        self.state = self.start.clone();
        self.rng = NumpyRng::new(self.config.noise_seed);
        self.target_q = self.start.q;
    }

    /// The joint angles the last step commanded, rad: the angles before it plus the IK's
    /// joint step after the speed and position limits, before contact could stop the move
    /// (what a position-controlled arm is told to go to; the start angles before any step, and
    /// unchanged by steps after the episode ended). The jaw's command is the state's
    /// `gripper_closed`.
    pub fn target_q(&self) -> [f64; 5] {
        self.target_q
    }

    /// How the episode ended, once it has.
    pub fn done(&self) -> Option<Outcome> {
        self.state.done
    }

    /// The jaw angle drawn for the current state.
    pub fn jaw(&self) -> f64 {
        jaw_of(&self.state)
    }

    /// Every frame of the arm now.
    pub fn chain(&self) -> Chain {
        chain(&self.state.q, self.jaw())
    }

    /// A record of the current state with no command and no events.
    pub fn snapshot(&self) -> StepRecord {
        let idle = Command::idle(self.state.gripper_closed);
        self.record(idle, idle, Vec::new())
    }

    fn record(&self, cmd: Command, applied: Command, events: Vec<Event>) -> StepRecord {
        let s = &self.state;
        let c = chain(&s.q, jaw_of(s));
        StepRecord {
            step: s.step,
            t_s: s.t_s,
            cmd,
            applied,
            q: s.q,
            tool: c.tool.pos,
            rpy: c.tool.rpy_from_down(),
            gripper_closed: s.gripper_closed,
            held: s.cube.held,
            cube: s.cube.pos,
            manipulability: manipulability(&jacobian_of(&c)),
            orientation_error: s.orientation_error,
            events,
        }
    }

    /// Advances one 10 ms step (after the episode ended nothing changes):
    /// 1. the command (sanitized) enters the latency queue and the one `latency_steps` old
    ///    leaves it;
    /// 2. `noise_sigma × N(0, 1)` is added to each of its six axes (six draws per step, in
    ///    axis order, from numpy's `default_rng(noise_seed)`);
    /// 3. the task step `(dx v, dy v, dz v, droll ω, dpitch ω, dyaw ω) × DT` becomes a joint
    ///    step by the IK method ([`super::control`]); [`Event::Singularity`] when it is
    ///    commanded with the Jacobian's smallest singular value under [`SINGULAR_SIGMA`] or
    ///    the method cannot solve;
    /// 4. joint speed limits scale the whole step ([`Event::SpeedLimit`]), position limits
    ///    clamp each joint ([`Event::JointLimit`]);
    /// 5. a move that puts a link into the table or the obstacle, links 1–4 newly into the
    ///    cube at rest, or the carried cube into the table or the obstacle, does not happen
    ///    ([`Event::Collision`]);
    /// 6. the gripper: closing with the cube's centre within [`GRASP_TOLERANCE_M`] of the
    ///    tool and the jaws across two of its faces ([`jaw_aligned`]: within
    ///    [`super::scene::GRASP_ALIGN_DEG`]) grasps it, any other close is a miss; opening
    ///    lets go ([`Event::Drop`] when the cube is not over the goal and not set down); a
    ///    released cube falls and rests flat;
    /// 7. the cube resting in the goal square for `success_steps` steps is
    ///    [`Event::Success`]; then the time box ([`Event::Timeout`]).
    pub fn step(&mut self, cmd: &Command) -> StepRecord {
        let (cmd, applied, events) = step(self, cmd);
        self.record(cmd, applied, events)
    }

    /// The link (1–7) the move from `before` to `moved` brings into contact, if any.
    fn contact(&self, before: &Chain, moved: &Chain) -> Option<u8> {
        let boxes = link_boxes(moved);
        if let Some(link) = table_or_obstacle_contact(&boxes, self.config.obstacle) {
            return Some(link);
        }
        let cube = &self.state.cube;
        if cube.resting && !cube.held {
            let c = cube.obb();
            let was = link_boxes(before);
            for i in 0..4 {
                if boxes[i].overlaps(&c, CONTACT_SLOP_M) && !was[i].overlaps(&c, CONTACT_SLOP_M) {
                    return Some(i as u8 + 1);
                }
            }
        }
        if let Some(g) = cube.grasp.filter(|_| cube.held) {
            let carried = carried(moved, &g);
            let wall = self.config.obstacle && carried.overlaps(&obstacle_box(), CONTACT_SLOP_M);
            if carried.bottom() < TABLE_Z - CONTACT_SLOP_M || wall {
                return Some(7);
            }
        }
        None
    }
}

// Each part has one caller, `step`: inlined there, the step is one function.
impl Steps for Sim {
    type Command = Command;

    run_parts!(Command);

    #[inline(always)]
    fn noisy(cmd: Command, noise: impl FnOnce(&mut [f64])) -> Command {
        let mut axes = cmd.axes();
        noise(&mut axes);
        Command::with_axes(axes, cmd.gripper_closed)
    }

    /// Steps 3–5, and the orientation error.
    #[inline(always)]
    fn move_arm(&mut self, applied: &Command, events: &mut Vec<Event>) {
        let q = self.state.q;
        let before = chain(&q, jaw_of(&self.state));
        let v = self.config.tool_speed_m_per_s() * Sim::DT;
        let w = self.config.turn_speed_rad_per_s() * Sim::DT;
        let a = applied.axes();
        let dx = [a[0] * v, a[1] * v, a[2] * v, a[3] * w, a[4] * w, a[5] * w];
        let commanded = dx.iter().any(|d| *d != 0.0);
        let j = jacobian_of(&before);
        let solved = if commanded {
            ik_step(&self.config.control, &j, &dx)
        } else {
            Some([0.0; 5])
        };
        let singular_now =
            commanded && (solved.is_none() || super::control::sigma_min(&j) < SINGULAR_SIGMA);
        if singular_now && !self.state.singular {
            events.push(Event::Singularity);
        }
        self.state.singular = singular_now;
        let mut dq = solved.unwrap_or([0.0; 5]);

        let was = self.state.speed_limited;
        let qd_max = self.config.qd_max;
        self.state.speed_limited = limit_speed(&mut dq, &qd_max, Sim::DT, was, events);
        let mut q_new = q;
        let limits = joint_limits();
        clamp_to_limits(
            &q,
            &dq,
            &limits,
            &mut self.state.at_limit,
            &mut q_new,
            events,
        );

        self.target_q = q_new;
        let mut contact = [false; 7];
        if q_new != q {
            let moved = chain(&q_new, jaw_of(&self.state));
            if let Some(link) = self.contact(&before, &moved) {
                contact[usize::from(link) - 1] = true;
            }
        }
        new_contacts(&contact, &mut self.state.contact, events);
        if !contact.iter().any(|c| *c) {
            self.state.q = q_new;
        }

        let rot = [a[3] * w, a[4] * w, a[5] * w];
        if rot.iter().any(|r| *r != 0.0) {
            let from = self.state.rot_target.unwrap_or(before.tool.rot);
            let target = mat_mul(&rotation_matrix(&rot), &from);
            let now = chain(&self.state.q, 0.0).tool.rot;
            let err = rotation_vector(&mul_t(&target, &now));
            self.state.orientation_error = super::kinematics::norm(&err);
            self.state.rot_target = Some(target);
        } else {
            self.state.rot_target = None;
            self.state.orientation_error = 0.0;
        }
    }

    /// Step 6.
    #[inline(always)]
    fn operate_gripper(&mut self, close: bool, events: &mut Vec<Event>) {
        if close == self.state.gripper_closed {
            return;
        }
        self.state.gripper_closed = close;
        let arm = chain(&self.state.q, 0.0);
        let tool = arm.tool;
        let obstacle = self.config.obstacle;
        let goal = self.config.goal;
        let cube = &mut self.state.cube;
        if close {
            let d = super::kinematics::sub(&cube.pos, &tool.pos);
            let near = super::kinematics::norm(&d) <= GRASP_TOLERANCE_M;
            if near && jaw_aligned(&arm, &cube.rot) && !cube.held {
                let rt = transpose(&tool.rot);
                cube.grasp = Some(Grasp {
                    offset: mat_vec(&rt, &d),
                    rel: mat_mul(&rt, &cube.rot),
                });
                cube.held = true;
                cube.resting = false;
                cube.vz = 0.0;
                self.state.ever_grasped = true;
                events.push(Event::Grasp);
            } else {
                events.push(Event::GraspMiss);
            }
        } else if cube.held {
            cube.held = false;
            cube.grasp = None;
            cube.vz = 0.0;
            let yaw = crate::math::atan2(cube.rot[1][0], cube.rot[0][0]);
            cube.rot = rotation_matrix(&[0.0, 0.0, yaw]);
            events.push(Event::Release);
            let over_goal = in_goal(&cube.pos, &goal);
            let bottom = cube.pos[2] - CUBE_HALF;
            let set_down = bottom - support_below(&cube.pos, obstacle) <= PLACE_HEIGHT_M;
            if !over_goal && !set_down {
                events.push(Event::Drop);
            }
        }
    }

    /// Step 6's cube: follows the gripper, falls, or rests.
    #[inline(always)]
    fn move_object(&mut self) {
        let obstacle = self.config.obstacle;
        let c = chain(&self.state.q, 0.0);
        let cube = &mut self.state.cube;
        if let Some(g) = cube.grasp.filter(|_| cube.held) {
            let b = carried(&c, &g);
            cube.pos = b.centre;
            cube.rot = b.rot;
            return;
        }
        if cube.resting {
            return;
        }
        let support = support_below(&cube.pos, obstacle);
        if fall(&mut cube.pos[2], &mut cube.vz, CUBE_HALF, support, Sim::DT) {
            cube.resting = true;
        }
    }

    /// Step 7's goal.
    #[inline(always)]
    fn check_goal(&mut self, events: &mut Vec<Event>) {
        let s = &mut self.state;
        let holds = s.cube.resting && !s.cube.held && in_goal(&s.cube.pos, &self.config.goal);
        if goal_held(&mut s.success_count, holds, self.config.success_steps) {
            s.done = Some(Outcome::Success);
            events.push(Event::Success);
        }
    }
}

/// Whether the point is over the goal square.
pub fn in_goal(p: &[f64; 3], goal: &[f64; 2]) -> bool {
    (p[0] - goal[0]).abs() <= GOAL_HALF && (p[1] - goal[1]).abs() <= GOAL_HALF
}

/// The height of what is under the point: the obstacle's top over its footprint, else the
/// table.
fn support_below(p: &[f64; 3], obstacle: bool) -> f64 {
    let (c, h) = OBSTACLE;
    let top = c[2] + h[2];
    let over = (p[0] - c[0]).abs() <= h[0] + CUBE_HALF && (p[1] - c[1]).abs() <= h[1] + CUBE_HALF;
    if obstacle && over && p[2] - CUBE_HALF >= top - CONTACT_SLOP_M {
        top
    } else {
        TABLE_Z
    }
}

/// The carried cube's box at the arm's pose `c`.
fn carried(c: &Chain, g: &Grasp) -> Obb {
    Obb {
        centre: c.tool.apply(&g.offset),
        rot: mat_mul(&c.tool.rot, &g.rel),
        half: [CUBE_HALF; 3],
    }
}

/// The jaw angle drawn for a state, rad: [`JAW_OPEN`], [`JAW_HOLDING`] on the cube or
/// [`JAW_CLOSED`] on nothing.
pub fn jaw_of(s: &State) -> f64 {
    match (s.gripper_closed, s.cube.held) {
        (false, _) => JAW_OPEN,
        (true, true) => JAW_HOLDING,
        (true, false) => JAW_CLOSED,
    }
}

/// `A B`.
pub fn mat_mul(a: &Mat3, b: &Mat3) -> Mat3 {
    let mut out = [[0.0; 3]; 3];
    for (r, row) in out.iter_mut().enumerate() {
        for (c, o) in row.iter_mut().enumerate() {
            *o = a[r][0] * b[0][c] + a[r][1] * b[1][c] + a[r][2] * b[2][c];
        }
    }
    out
}

fn transpose(m: &Mat3) -> Mat3 {
    mul_t(&IDENTITY, m)
}
