//! The scene of the Robot Pilot practice: a table, a block, a goal region, optional obstacle
//! boxes and reach targets; the tasks; the configuration of one session ([`SceneConfig`]) and
//! its validation; the geometry the page draws ([`SceneGeometry`]) and the collision tests.
//!
//! Coordinates: metres, x to the right, z up, the shoulder at the origin. The table top is the
//! line `z = TABLE_Z` across the whole scene (the base stands on a pedestal above it).
//!
//! | task | id | goal condition (held [`SceneConfig::success_steps`] consecutive steps) |
//! |------|----|------|
//! | reach | `reach` | the tip inside the current target's circle; then the next target |
//! | pick and place | `pick-place` | the block released, at rest on the table, its centre in the goal's x range |
//! | pick and place around an obstacle | `pick-place-obstacle` | the same, with a wall between block and goal |

#![warn(missing_docs)]

use serde::{Deserialize, Serialize};

use super::arm::{fk, ArmParams, Pose2};
use super::control::{ControlParams, IkMethod};
use super::error::TeleopError;

/// Height of the table top, m.
pub const TABLE_Z: f64 = -0.04;
/// Half the side of the (square) block, m.
pub const BLOCK_HALF: f64 = 0.012;
/// Length of the gripper's fingers along the last link, m (the palm is this far behind the
/// tip).
pub const FINGER_LENGTH: f64 = 0.025;
/// Half the opening of the open gripper (finger axis to gripper axis), m.
pub const OPEN_HALF_WIDTH: f64 = 0.02;
/// Half the opening of the closed, empty gripper, m.
pub const CLOSED_HALF_WIDTH: f64 = 0.003;
/// Radius of the finger capsules, m.
pub const FINGER_RADIUS: f64 = 0.003;
/// A grasp succeeds when the block's centre is within this distance of the tip …
pub const GRASP_TOLERANCE_M: f64 = 0.01;
/// … and the fingers are within this angle of a pair of the block's faces, rad (20°).
pub const GRASP_ANGLE_TOLERANCE_RAD: f64 = 0.35;
/// How far a carried block may press into the table before it counts as a collision, m.
pub const CONTACT_SLOP_M: f64 = 0.001;
/// The most targets a reach task takes.
pub const MAX_TARGETS: usize = 20;
/// The largest latency, steps (500 ms at 100 Hz).
pub const MAX_LATENCY_STEPS: u32 = 50;

/// Position sensitivity default, Isaac Lab's `Se3Keyboard` `pos_sensitivity`.
pub const DEFAULT_POS_SENSITIVITY: f64 = 0.4;
/// Rotation sensitivity default, Isaac Lab's `Se3Keyboard` `rot_sensitivity`.
pub const DEFAULT_ROT_SENSITIVITY: f64 = 0.8;
/// Tip speed per unit of position sensitivity at full deflection, (m/s): the default 0.4
/// gives 0.1 m/s, a third of the arm's reach per second (Isaac Lab's `Se3Gamepad` default
/// 1.0 gives 0.25 m/s).
pub const POS_SPEED_PER_SENSITIVITY: f64 = 0.25;
/// Gripper angular speed per unit of rotation sensitivity at full deflection, (rad/s): the
/// default 0.8 gives 0.8 rad/s (46°/s; `Se3Gamepad`'s 1.6 gives 1.6 rad/s).
pub const ROT_SPEED_PER_SENSITIVITY: f64 = 1.0;

/// One reach target: a circle the tip must stay inside.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Target {
    /// Centre x, m.
    pub x: f64,
    /// Centre z, m.
    pub z: f64,
    /// Radius, m.
    pub radius: f64,
}

/// The task of a session.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub enum Task {
    /// Reach the targets in order (Fitts-style: several sizes and distances).
    Reach {
        /// The targets, in the order to reach them.
        targets: Vec<Target>,
    },
    /// Pick the block up and place it in the goal region.
    PickPlace,
    /// Pick the block up and place it in the goal region beyond a wall.
    PickPlaceObstacle,
}

impl Task {
    /// The ids, in the page's order.
    pub const IDS: [&'static str; 3] = ["reach", "pick-place", "pick-place-obstacle"];

    /// `reach`, `pick-place`, `pick-place-obstacle`.
    pub fn id(&self) -> &'static str {
        match self {
            Task::Reach { .. } => "reach",
            Task::PickPlace => "pick-place",
            Task::PickPlaceObstacle => "pick-place-obstacle",
        }
    }

    /// The task with this id; `reach` gets [`default_targets`].
    pub fn from_id(id: &str) -> Option<Task> {
        match id {
            "reach" => Some(Task::Reach {
                targets: default_targets(),
            }),
            "pick-place" => Some(Task::PickPlace),
            "pick-place-obstacle" => Some(Task::PickPlaceObstacle),
            _ => None,
        }
    }

    /// The reach targets (empty for the pick tasks).
    pub fn targets(&self) -> &[Target] {
        match self {
            Task::Reach { targets } => targets,
            _ => &[],
        }
    }
}

/// The default reach sequence: six targets of radius 8 to 20 mm, 73 to 304 mm apart (from
/// the start tip, then from each target to the next), so Fitts' index of difficulty
/// `log2(D/W + 1)` spans 1.5 to 4.3 bits. Every target can be reached with the gripper
/// pointing straight down, as it starts (the wrist stays within 0.2 m of the shoulder).
pub fn default_targets() -> Vec<Target> {
    [
        (0.17, 0.04, 0.020),
        (0.04, 0.12, 0.012),
        (0.12, 0.09, 0.008),
        (0.03, 0.02, 0.020),
        (0.19, -0.01, 0.012),
        (-0.10, 0.08, 0.008),
    ]
    .iter()
    .map(|&(x, z, radius)| Target { x, z, radius })
    .collect()
}

/// An axis-aligned box (obstacle, goal region), corners `(x0, z0)`–`(x1, z1)`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Box2 {
    /// Left edge, m.
    pub x0: f64,
    /// Bottom edge, m.
    pub z0: f64,
    /// Right edge, m.
    pub x1: f64,
    /// Top edge, m.
    pub z1: f64,
}

impl Box2 {
    /// A box standing on the table from `x0` to `x1`, its top at `z1`.
    pub fn on_table(x0: f64, x1: f64, z1: f64) -> Box2 {
        Box2 {
            x0,
            z0: TABLE_Z,
            x1,
            z1,
        }
    }
}

/// A line segment.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Segment {
    /// Start x, m.
    pub x0: f64,
    /// Start z, m.
    pub z0: f64,
    /// End x, m.
    pub x1: f64,
    /// End z, m.
    pub z1: f64,
}

/// A segment with a radius: a link or a finger.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Capsule {
    /// The axis.
    pub segment: Segment,
    /// The radius around it, m.
    pub radius: f64,
}

/// Where the table, block, goal and obstacles of a task are.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Layout {
    /// The block's centre at the start (resting on the table).
    pub block_start: (f64, f64),
    /// The goal region (x range on the table; z range for drawing), pick tasks only.
    pub goal: Option<Box2>,
    /// Obstacle boxes standing on the table.
    pub obstacles: Vec<Box2>,
}

impl Layout {
    /// The layout of `task`.
    pub fn of(task: &Task) -> Layout {
        let on_table = TABLE_Z + BLOCK_HALF;
        match task {
            Task::Reach { .. } => Layout {
                block_start: (-0.16, on_table),
                goal: None,
                obstacles: Vec::new(),
            },
            Task::PickPlace => Layout {
                block_start: (0.08, on_table),
                goal: Some(Box2::on_table(0.16, 0.22, TABLE_Z + 0.04)),
                obstacles: Vec::new(),
            },
            Task::PickPlaceObstacle => Layout {
                block_start: (0.05, on_table),
                goal: Some(Box2::on_table(0.14, 0.19, TABLE_Z + 0.04)),
                obstacles: vec![Box2::on_table(0.095, 0.11, 0.02)],
            },
        }
    }
}

/// Everything that defines a session's scene and controller: the config plus the command
/// stream replays an episode exactly.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SceneConfig {
    /// The arm.
    pub arm: ArmParams,
    /// The IK controller.
    pub control: ControlParams,
    /// What the pilot has to do.
    pub task: Task,
    /// Joint angles at the start (default: shoulder up, forearm level, gripper pointing
    /// down, tip at (0.10, 0.06)).
    pub start_q: [f64; 3],
    /// Commands reach the arm this many 10 ms steps late (0 to 50, i.e. 0 to 500 ms).
    pub latency_steps: u32,
    /// Standard deviation of the Gaussian noise added to each command axis (in the
    /// normalised units of [`super::sim::Command`]; 0 = none; at most 1).
    pub noise_sigma: f64,
    /// Seed of the noise (`np.random.default_rng(seed)`), at most 2^63 − 1.
    pub noise_seed: u64,
    /// The time box of an episode, s (default 60; 1 to 600).
    pub time_box_s: f64,
    /// Steps the goal condition must hold (default 10, Isaac Lab's `record_demos.py`
    /// `--num_success_steps`; 1 to 1000).
    pub success_steps: u32,
    /// Position sensitivity (Isaac Lab `Se3Keyboard` default 0.4): full deflection moves the
    /// tip at `pos_sensitivity × POS_SPEED_PER_SENSITIVITY` m/s.
    pub pos_sensitivity: f64,
    /// Rotation sensitivity (default 0.8): full deflection turns the gripper at
    /// `rot_sensitivity × ROT_SPEED_PER_SENSITIVITY` rad/s.
    pub rot_sensitivity: f64,
}

impl Default for SceneConfig {
    fn default() -> Self {
        use std::f64::consts::FRAC_PI_2;
        SceneConfig {
            arm: ArmParams::DEFAULT,
            control: ControlParams::DEFAULT,
            task: Task::PickPlace,
            start_q: [FRAC_PI_2, -FRAC_PI_2, -FRAC_PI_2],
            latency_steps: 0,
            noise_sigma: 0.0,
            noise_seed: 0,
            time_box_s: 60.0,
            success_steps: 10,
            pos_sensitivity: DEFAULT_POS_SENSITIVITY,
            rot_sensitivity: DEFAULT_ROT_SENSITIVITY,
        }
    }
}

/// Checks the IK controller's parameters (any arm's).
pub fn check_control(c: &ControlParams) -> Result<(), TeleopError> {
    check("lambda", c.lambda, 0.0, 1.0)?;
    check("pinv_gain", c.pinv_gain, 0.0, 10.0)?;
    check("trans_gain", c.trans_gain, 0.0, 1000.0)?;
    check("lambda_min", c.lambda_min, 0.0, 1.0)?;
    check("lambda_max", c.lambda_max, 0.0, 1.0)?;
    check("sigma_threshold", c.sigma_threshold, 0.0, 1.0)
}

/// Checks latency, noise and its seed, time box, success steps and the position and rotation
/// sensitivities (any arm's).
pub fn check_run(
    latency_steps: u32,
    noise_sigma: f64,
    noise_seed: u64,
    time_box_s: f64,
    success_steps: u32,
    pos_sensitivity: f64,
    rot_sensitivity: f64,
) -> Result<(), TeleopError> {
    check(
        "latency_steps",
        f64::from(latency_steps),
        0.0,
        f64::from(MAX_LATENCY_STEPS),
    )?;
    check("noise_sigma", noise_sigma, 0.0, 1.0)?;
    if noise_seed > crate::rng::SEED_MAX {
        return Err(TeleopError::OutOfRange {
            field: "noise_seed".to_string(),
            value: noise_seed as f64,
            min: 0.0,
            max: crate::rng::SEED_MAX as f64,
        });
    }
    check("time_box_s", time_box_s, 1.0, 600.0)?;
    check("success_steps", f64::from(success_steps), 1.0, 1000.0)?;
    check("pos_sensitivity", pos_sensitivity, 0.01, 10.0)?;
    check("rot_sensitivity", rot_sensitivity, 0.01, 10.0)
}

/// Checks `value` is finite and within `[min, max]`.
pub fn check(field: &str, value: f64, min: f64, max: f64) -> Result<(), TeleopError> {
    if !value.is_finite() {
        return Err(TeleopError::NotFinite {
            field: field.to_string(),
        });
    }
    if value < min || value > max {
        return Err(TeleopError::OutOfRange {
            field: field.to_string(),
            value,
            min,
            max,
        });
    }
    Ok(())
}

impl SceneConfig {
    /// The default scene and controller with task `task`.
    pub fn with_task(task: Task) -> SceneConfig {
        SceneConfig {
            task,
            ..SceneConfig::default()
        }
    }

    /// Checks every field; the error names the first bad one (field names as in the struct,
    /// `links` for `arm.links`, `lambda` for `control.lambda` and so on).
    pub fn validate(&self) -> Result<(), TeleopError> {
        use std::f64::consts::TAU;
        let arm = &self.arm;
        for l in arm.links {
            check("links", l, 0.01, 0.5)?;
        }
        for (i, (lo, hi)) in arm.q_min.iter().zip(arm.q_max).enumerate() {
            check("q_min", *lo, -TAU, TAU)?;
            check("q_max", hi, -TAU, TAU)?;
            if *lo > hi {
                return Err(TeleopError::LimitsInverted { joint: i + 1 });
            }
        }
        for v in arm.qd_max {
            check("qd_max", v, 0.01, 50.0)?;
        }
        check("link_radius", arm.link_radius, 0.0005, 0.03)?;
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
        if let Task::Reach { targets } = &self.task {
            if targets.is_empty() || targets.len() > MAX_TARGETS {
                return Err(TeleopError::TargetCount {
                    count: targets.len(),
                    max: MAX_TARGETS,
                });
            }
            for t in targets {
                check("targets", t.x, -0.5, 0.5)?;
                check("targets", t.z, TABLE_Z, 0.5)?;
                check("targets", t.radius, 0.002, 0.1)?;
            }
        }
        for (i, q) in self.start_q.iter().enumerate() {
            check("start_q", *q, arm.q_min[i], arm.q_max[i])?;
        }
        let layout = Layout::of(&self.task);
        let capsules = arm_capsules(arm, &self.start_q, OPEN_HALF_WIDTH);
        if let Some(link) = first_contact(&capsules, &layout.obstacles) {
            return Err(TeleopError::StartInCollision { link });
        }
        Ok(())
    }

    /// Tip speed at full deflection, m/s.
    pub fn tip_speed_m_per_s(&self) -> f64 {
        self.pos_sensitivity * POS_SPEED_PER_SENSITIVITY
    }

    /// Gripper angular speed at full deflection, rad/s.
    pub fn turn_speed_rad_per_s(&self) -> f64 {
        self.rot_sensitivity * ROT_SPEED_PER_SENSITIVITY
    }

    /// The IK method (shorthand for `control.method`).
    pub fn method(&self) -> IkMethod {
        self.control.method
    }
}

/// Whether a reach target is done, the one to reach now, or still to come.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum TargetStatus {
    /// Reached.
    Done,
    /// The one to reach now.
    Current,
    /// Still to come.
    Pending,
}

/// A target as drawn.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct TargetView {
    /// Where it is.
    pub target: Target,
    /// Done, current or to come.
    pub status: TargetStatus,
}

/// Everything the page draws for one state.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SceneGeometry {
    /// The three links (link 3 ends at the palm), with the arm's capsule radius.
    pub links: [Capsule; 3],
    /// The two fingers, palm to fingertips.
    pub fingers: [Capsule; 2],
    /// The tip pose (between the fingertips).
    pub tip: Pose2,
    /// The table top, drawn across the scene.
    pub table: Segment,
    /// The block's four corners, counter-clockwise.
    pub block: [(f64, f64); 4],
    /// Whether the gripper holds the block.
    pub block_held: bool,
    /// The goal region (pick tasks).
    pub goal: Option<Box2>,
    /// The obstacle boxes.
    pub obstacles: Vec<Box2>,
    /// The reach targets with which is current.
    pub targets: Vec<TargetView>,
    /// The scene's extent for framing `(x0, z0, x1, z1)`: the arm's reach around the base and
    /// the table.
    pub bounds: Box2,
}

/// The palm: `FINGER_LENGTH` behind the tip along the gripper.
fn palm(tip: &Pose2) -> (f64, f64) {
    let (s, c) = crate::math::sincos(tip.phi);
    (tip.x - FINGER_LENGTH * c, tip.z - FINGER_LENGTH * s)
}

/// The arm's collision capsules: the three links (link 3 to the palm) and, as part of link 3,
/// the two fingers at `half_width` from the gripper axis. Index 0–2 links, 3–4 fingers.
pub fn arm_capsules(arm: &ArmParams, q: &[f64; 3], half_width: f64) -> [Capsule; 5] {
    let [base, elbow, wrist, _] = arm.joint_points(q);
    let tip = fk(arm, q);
    let palm = palm(&tip);
    let seg = |a: (f64, f64), b: (f64, f64)| Segment {
        x0: a.0,
        z0: a.1,
        x1: b.0,
        z1: b.1,
    };
    let link = |a, b| Capsule {
        segment: seg(a, b),
        radius: arm.link_radius,
    };
    let (s, c) = crate::math::sincos(tip.phi);
    // The normal to the gripper axis.
    let (nx, nz) = (-s * half_width, c * half_width);
    let finger = |sign: f64| Capsule {
        segment: seg(
            (palm.0 + sign * nx, palm.1 + sign * nz),
            (tip.x + sign * nx, tip.z + sign * nz),
        ),
        radius: FINGER_RADIUS,
    };
    [
        link(base, elbow),
        link(elbow, wrist),
        link(wrist, palm),
        finger(1.0),
        finger(-1.0),
    ]
}

/// The first link (1–3; fingers count as link 3) touching the table or an obstacle.
pub fn first_contact(capsules: &[Capsule; 5], obstacles: &[Box2]) -> Option<u8> {
    capsules.iter().enumerate().find_map(|(i, cap)| {
        let link = (i.min(2) + 1) as u8;
        let s = &cap.segment;
        let below_table = s.z0.min(s.z1) - cap.radius < TABLE_Z;
        let in_box = obstacles
            .iter()
            .any(|b| segment_box_distance(s, b) < cap.radius);
        (below_table || in_box).then_some(link)
    })
}

/// Distance from a point to a box (0 inside).
pub fn point_box_distance(x: f64, z: f64, b: &Box2) -> f64 {
    let dx = (b.x0 - x).max(0.0).max(x - b.x1);
    let dz = (b.z0 - z).max(0.0).max(z - b.z1);
    (dx * dx + dz * dz).sqrt()
}

/// Distance from a point to a segment.
pub fn point_segment_distance(x: f64, z: f64, s: &Segment) -> f64 {
    let (ux, uz) = (s.x1 - s.x0, s.z1 - s.z0);
    let len_sq = ux * ux + uz * uz;
    let t = if len_sq > 0.0 {
        (((x - s.x0) * ux + (z - s.z0) * uz) / len_sq).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let (px, pz) = (s.x0 + t * ux - x, s.z0 + t * uz - z);
    (px * px + pz * pz).sqrt()
}

/// Whether the segment crosses the box (Liang–Barsky clipping).
fn segment_hits_box(s: &Segment, b: &Box2) -> bool {
    let (dx, dz) = (s.x1 - s.x0, s.z1 - s.z0);
    let mut t0: f64 = 0.0;
    let mut t1: f64 = 1.0;
    for (p, q) in [
        (-dx, s.x0 - b.x0),
        (dx, b.x1 - s.x0),
        (-dz, s.z0 - b.z0),
        (dz, b.z1 - s.z0),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return false;
            }
        } else {
            let r = q / p;
            if p < 0.0 {
                t0 = t0.max(r);
            } else {
                t1 = t1.min(r);
            }
            if t0 > t1 {
                return false;
            }
        }
    }
    true
}

/// Distance between a segment and a box (0 when they touch or cross): for two convex shapes
/// that do not cross, the nearest pair includes an endpoint of the segment or a corner of the
/// box.
pub fn segment_box_distance(s: &Segment, b: &Box2) -> f64 {
    if segment_hits_box(s, b) {
        return 0.0;
    }
    let ends = point_box_distance(s.x0, s.z0, b).min(point_box_distance(s.x1, s.z1, b));
    [(b.x0, b.z0), (b.x1, b.z0), (b.x1, b.z1), (b.x0, b.z1)]
        .iter()
        .map(|&(x, z)| point_segment_distance(x, z, s))
        .fold(ends, f64::min)
}

#[cfg(test)]
mod tests {
    #[cfg(target_arch = "wasm32")]
    use wasm_bindgen_test::wasm_bindgen_test as test;

    use super::*;

    #[test]
    fn default_config_is_valid_and_starts_clear() {
        for id in Task::IDS {
            let config = SceneConfig {
                task: Task::from_id(id).unwrap(),
                ..SceneConfig::default()
            };
            assert_eq!(config.validate(), Ok(()), "{id}");
            assert_eq!(config.task.id(), id);
        }
        let tip = fk(&ArmParams::DEFAULT, &SceneConfig::default().start_q);
        assert!((tip.x - 0.10).abs() < 1e-12 && (tip.z - 0.06).abs() < 1e-12);
    }

    #[test]
    fn validate_names_the_field() {
        let bad = SceneConfig {
            latency_steps: 51,
            ..SceneConfig::default()
        };
        assert_eq!(bad.validate().unwrap_err().field(), Some("latency_steps"));
        let bad = SceneConfig {
            pos_sensitivity: f64::NAN,
            ..SceneConfig::default()
        };
        assert_eq!(
            bad.validate().unwrap_err(),
            TeleopError::NotFinite {
                field: "pos_sensitivity".into()
            }
        );
        let bad = SceneConfig {
            task: Task::Reach { targets: vec![] },
            ..SceneConfig::default()
        };
        assert_eq!(bad.validate().unwrap_err().field(), Some("targets"));
        let bad = SceneConfig {
            start_q: [-0.5, 0.0, 0.0],
            ..SceneConfig::default()
        };
        assert_eq!(
            bad.validate().unwrap_err(),
            TeleopError::StartInCollision { link: 1 }
        );
    }

    #[test]
    fn segment_box_distances() {
        let b = Box2 {
            x0: 0.0,
            z0: 0.0,
            x1: 1.0,
            z1: 1.0,
        };
        let distance = |(x0, z0): (f64, f64), (x1, z1): (f64, f64)| {
            segment_box_distance(&Segment { x0, z0, x1, z1 }, &b)
        };
        assert_eq!(distance((-1.0, 0.5), (2.0, 0.5)), 0.0, "crossing");
        assert_eq!(distance((-1.0, 1.5), (2.0, 1.5)), 0.5, "above");
        let diagonal = distance((2.0, 1.0), (1.0, 2.0));
        assert!((diagonal - 0.5f64.sqrt()).abs() < 1e-15);
    }
}
