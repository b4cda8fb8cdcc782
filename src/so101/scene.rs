//! The SO-101's scene: the table its base stands on (top at z = 0), a 25 mm cube, a square
//! goal region on the table, and (in `pick-place-obstacle`) a wall between the cube and the
//! goal; and [`SceneConfig`], everything an episode is run with. The world frame is the
//! MJCF's: x forward from the base, y to the arm's left, z up, metres.
//!
//! Contact uses the boxes of [`super::model`] (oriented with their bodies) against the table
//! top, the obstacle and the cube, by the separating-axis test.

use serde::{Deserialize, Serialize};

use super::kinematics::{cross, mat_vec, norm, Chain, Frame, Mat3};
use super::model::{joint_limits, BODIES, JAW};
use crate::teleop::control::ControlParams;
use crate::teleop::scene::{
    check, check_control, check_run, DEFAULT_POS_SENSITIVITY, DEFAULT_ROT_SENSITIVITY,
    POS_SPEED_PER_SENSITIVITY, ROT_SPEED_PER_SENSITIVITY,
};
use crate::teleop::TeleopError;

/// `embodiment` of the session evidence.
pub const EMBODIMENT: &str = "so101-sim";
/// Height of the table top, m.
pub const TABLE_Z: f64 = 0.0;
/// Half the cube's edge, m.
pub const CUBE_HALF: f64 = 0.0125;
/// Half the goal square's side, m.
pub const GOAL_HALF: f64 = 0.04;
/// Closing the gripper grasps the cube when its centre is this close to the tool frame's
/// origin (between the jaws), m.
pub const GRASP_TOLERANCE_M: f64 = 0.02;
/// Closing the gripper grasps the cube only when the jaws close across two opposite faces:
/// the closing direction within this angle of one of the cube's face normals, degrees.
pub const GRASP_ALIGN_DEG: f64 = 25.0;
/// A released cube whose bottom is at most this high above what is under it is set down,
/// not dropped, m.
pub const PLACE_HEIGHT_M: f64 = 0.005;
/// Penetration allowed before a contact counts, m.
pub const CONTACT_SLOP_M: f64 = 0.002;
/// The obstacle wall: centre and half sizes, m.
pub const OBSTACLE: ([f64; 3], [f64; 3]) = ([0.22, 0.01, 0.02], [0.05, 0.008, 0.02]);
/// Jaw angles for drawing, rad: open, closed on nothing, closed on the cube.
pub const JAW_OPEN: f64 = 0.9;
/// See [`JAW_OPEN`].
pub const JAW_CLOSED: f64 = 0.0;
/// See [`JAW_OPEN`].
pub const JAW_HOLDING: f64 = 0.3;

/// An oriented box: centre, axes (columns of `rot`) and half sizes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Obb {
    /// Centre, m.
    pub centre: [f64; 3],
    /// Orientation (columns are the box's axes).
    pub rot: Mat3,
    /// Half sizes along its axes, m.
    pub half: [f64; 3],
}

impl Obb {
    /// An axis-aligned box.
    pub fn aligned(centre: [f64; 3], half: [f64; 3]) -> Obb {
        Obb {
            centre,
            rot: [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
            half,
        }
    }

    /// The box of a body whose frame is `f`.
    pub fn of(f: &Frame, centre: &[f64; 3], half: &[f64; 3]) -> Obb {
        Obb {
            centre: f.apply(centre),
            rot: f.rot,
            half: *half,
        }
    }

    /// The eight corners.
    pub fn corners(&self) -> [[f64; 3]; 8] {
        let mut out = [[0.0; 3]; 8];
        for (k, o) in out.iter_mut().enumerate() {
            let s = [
                if k & 1 == 0 { -1.0 } else { 1.0 },
                if k & 2 == 0 { -1.0 } else { 1.0 },
                if k & 4 == 0 { -1.0 } else { 1.0 },
            ];
            let local = [
                s[0] * self.half[0],
                s[1] * self.half[1],
                s[2] * self.half[2],
            ];
            let w = mat_vec(&self.rot, &local);
            *o = [
                self.centre[0] + w[0],
                self.centre[1] + w[1],
                self.centre[2] + w[2],
            ];
        }
        out
    }

    /// The lowest z of the box.
    pub fn bottom(&self) -> f64 {
        let r = &self.rot;
        let reach: f64 = (0..3).map(|k| r[2][k].abs() * self.half[k]).sum();
        self.centre[2] - reach
    }

    /// Whether the two boxes overlap by more than `slop` (separating-axis test on the 15
    /// axes).
    pub fn overlaps(&self, other: &Obb, slop: f64) -> bool {
        let axis = |m: &Mat3, k: usize| [m[0][k], m[1][k], m[2][k]];
        let mut axes: Vec<[f64; 3]> = Vec::with_capacity(15);
        for k in 0..3 {
            axes.push(axis(&self.rot, k));
            axes.push(axis(&other.rot, k));
        }
        for a in 0..3 {
            for b in 0..3 {
                let c = super::kinematics::cross(&axis(&self.rot, a), &axis(&other.rot, b));
                if super::kinematics::norm(&c) > 1e-9 {
                    axes.push(c);
                }
            }
        }
        let d = super::kinematics::sub(&other.centre, &self.centre);
        axes.iter().all(|n| {
            let len = super::kinematics::norm(n);
            let dot = |v: &[f64; 3]| (v[0] * n[0] + v[1] * n[1] + v[2] * n[2]) / len;
            let reach = |b: &Obb| -> f64 {
                (0..3)
                    .map(|k| dot(&axis(&b.rot, k)).abs() * b.half[k])
                    .sum()
            };
            dot(&d).abs() < reach(self) + reach(other) - slop
        })
    }
}

/// The boxes of the arm's links at `chain`: shoulder, upper arm, lower arm, wrist, gripper,
/// moving jaw (links 1–6 of the collision events; the base does not move).
pub fn link_boxes(chain: &Chain) -> [Obb; 6] {
    let mut out = [Obb::aligned([0.0; 3], [0.0; 3]); 6];
    for (i, o) in out.iter_mut().take(5).enumerate() {
        let b = &BODIES[i + 1];
        *o = Obb::of(&chain.bodies[i + 1], &b.box_centre, &b.box_half);
    }
    out[5] = Obb::of(&chain.jaw, &JAW.box_centre, &JAW.box_half);
    out
}

/// The obstacle wall's box.
pub fn obstacle_box() -> Obb {
    Obb::aligned(OBSTACLE.0, OBSTACLE.1)
}

/// Everything an episode is run with.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SceneConfig {
    /// The IK method and its parameters.
    pub control: ControlParams,
    /// Whether the obstacle wall stands between the cube and the goal.
    pub obstacle: bool,
    /// The five joint angles at the start, rad.
    pub start_q: [f64; 5],
    /// The cube's start centre on the table (x, y), m.
    pub cube_start: [f64; 2],
    /// The goal square's centre (x, y), m.
    pub goal: [f64; 2],
    /// Steps a command waits before it acts (10 ms each), ≤ 50.
    pub latency_steps: u32,
    /// Standard deviation of the noise added to each normalised axis, in [0, 1].
    pub noise_sigma: f64,
    /// Seed of the noise (numpy `default_rng`).
    pub noise_seed: u64,
    /// The time box, s.
    pub time_box_s: f64,
    /// Consecutive steps the cube must rest in the goal for success.
    pub success_steps: u32,
    /// Isaac Lab's `pos_sensitivity` (0.4).
    pub pos_sensitivity: f64,
    /// Isaac Lab's `rot_sensitivity` (0.8).
    pub rot_sensitivity: f64,
    /// Joint speed limits, rad/s.
    pub qd_max: [f64; 5],
}

impl SceneConfig {
    /// The page's defaults: DLS with λ = 0.01, Isaac Lab's sensitivities, no latency or noise,
    /// a 60 s time box, success held 10 steps.
    pub fn default_for(obstacle: bool) -> SceneConfig {
        SceneConfig {
            control: ControlParams::DEFAULT,
            obstacle,
            start_q: [0.0, 0.0, 0.0, 1.57, 0.0],
            cube_start: [0.22, -0.08],
            goal: [0.22, 0.1],
            latency_steps: 0,
            noise_sigma: 0.0,
            noise_seed: 0,
            time_box_s: 60.0,
            success_steps: 10,
            pos_sensitivity: DEFAULT_POS_SENSITIVITY,
            rot_sensitivity: DEFAULT_ROT_SENSITIVITY,
            qd_max: [3.0; 5],
        }
    }

    /// `pick-place` or `pick-place-obstacle` (the Academy's task ids).
    pub fn task_id(&self) -> &'static str {
        if self.obstacle {
            "pick-place-obstacle"
        } else {
            "pick-place"
        }
    }

    /// Tool speed at full deflection, m/s.
    pub fn tool_speed_m_per_s(&self) -> f64 {
        self.pos_sensitivity * POS_SPEED_PER_SENSITIVITY
    }

    /// Tool turn rate at full deflection, rad/s.
    pub fn turn_speed_rad_per_s(&self) -> f64 {
        self.rot_sensitivity * ROT_SPEED_PER_SENSITIVITY
    }

    /// Checks every field (names the first bad one).
    pub fn validate(&self) -> Result<(), TeleopError> {
        check_control(&self.control)?;
        check_run(
            self.latency_steps,
            self.noise_sigma,
            self.noise_seed,
            self.time_box_s,
            self.success_steps,
            self.pos_sensitivity,
            self.rot_sensitivity,
        )?;
        for (q, (lo, hi)) in self.start_q.iter().zip(joint_limits()) {
            check("start_q", *q, lo, hi)?;
        }
        for v in self.cube_start.iter().chain(&self.goal) {
            check("cube_start", *v, -0.5, 0.5)?;
        }
        for v in self.qd_max {
            check("qd_max", v, 0.01, 20.0)?;
        }
        let chain = super::kinematics::chain(&self.start_q, JAW_OPEN);
        if let Some(link) = table_or_obstacle_contact(&link_boxes(&chain), self.obstacle) {
            return Err(TeleopError::StartInCollision { link });
        }
        Ok(())
    }
}

/// The first link (1–6) of `boxes` in the table or the obstacle.
pub fn table_or_obstacle_contact(boxes: &[Obb; 6], obstacle: bool) -> Option<u8> {
    let wall = obstacle_box();
    boxes.iter().enumerate().find_map(|(i, b)| {
        let hit = b.bottom() < TABLE_Z - CONTACT_SLOP_M
            || (obstacle && b.overlaps(&wall, CONTACT_SLOP_M));
        hit.then_some(i as u8 + 1)
    })
}

/// The direction the jaws close along at `chain` (unit): across the gripper's approach (the
/// tool frame's x axis) and the jaw's hinge axis (its body's z axis).
pub fn jaw_closing(chain: &Chain) -> [f64; 3] {
    let col = |m: &Mat3, k: usize| [m[0][k], m[1][k], m[2][k]];
    let c = cross(&col(&chain.tool.rot, 0), &col(&chain.jaw.rot, 2));
    let n = norm(&c);
    if n > 0.0 {
        [c[0] / n, c[1] / n, c[2] / n]
    } else {
        c
    }
}

/// Whether the jaws at `chain` close across two opposite faces of a cube of orientation
/// `cube_rot`: [`jaw_closing`] within [`GRASP_ALIGN_DEG`] of one of its face normals.
pub fn jaw_aligned(chain: &Chain, cube_rot: &Mat3) -> bool {
    let close = jaw_closing(chain);
    let best = (0..3)
        .map(|k| {
            (close[0] * cube_rot[0][k] + close[1] * cube_rot[1][k] + close[2] * cube_rot[2][k])
                .abs()
        })
        .fold(0.0, f64::max);
    best >= crate::math::sincos(GRASP_ALIGN_DEG.to_radians()).1
}
