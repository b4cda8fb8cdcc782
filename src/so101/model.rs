//! The SO-101's kinematic description as data, from TheRobotStudio's `SO-ARM100` repository
//! (Apache-2.0), `Simulation/SO101/so101_new_calib.xml` (the MuJoCo model; the URDF
//! `so101_new_calib.urdf` beside it has the same chain with its angles rounded to 1.5708) at
//! [`SOURCE_COMMIT`]; a copy of the file is `tests/golden/so101/so101_new_calib.xml`.
//!
//! Every body is placed in its parent by `pos` and the unit quaternion `quat` (w, x, y, z), as
//! the MJCF writes them (MuJoCo normalises them when it compiles the model; so does
//! [`super::kinematics`]). The five arm joints and the jaw are hinges about the body's z axis
//! at its origin, with the MJCF's `range`. The tool frame is the MJCF site `gripperframe`,
//! the URDF's `gripper_frame_link`.
//!
//! The collision shapes of the model are meshes; for drawing and contact each body has the
//! axis-aligned box (in its own frame) around the vertices of its collision meshes, as
//! `tests/so101/golden_fk.py --boxes` computes them from the repository's `assets/` STL files
//! (the base from its visual meshes: it has no collision geom). Drawn, each body is its
//! [`PARTS`]: a box around each of its collision meshes, which follow the links' shapes more
//! closely than the one box around them all.

// The numbers are the file's, as written (0.707107 is not 1/√2).
#![allow(clippy::approx_constant)]

/// The repository the numbers come from.
pub const SOURCE_REPO: &str = "TheRobotStudio/SO-ARM100";
/// The file the numbers come from.
pub const SOURCE_FILE: &str = "Simulation/SO101/so101_new_calib.xml";
/// The commit of [`SOURCE_REPO`] read.
pub const SOURCE_COMMIT: &str = "fda892cba81032c46c40976a48c9ceadbf40a9ca";

/// One body of the chain: its place in the parent body and its joint (none for the base).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Body {
    /// The MJCF body name.
    pub name: &'static str,
    /// The joint's name (a hinge about the body's z axis at its origin), if any.
    pub joint: Option<&'static str>,
    /// Position in the parent body, m.
    pub pos: [f64; 3],
    /// Orientation in the parent body, quaternion (w, x, y, z) as written.
    pub quat: [f64; 4],
    /// Joint range, rad (lower, upper).
    pub range: (f64, f64),
    /// Box around the body's collision meshes, in its frame: centre, m.
    pub box_centre: [f64; 3],
    /// Box half sizes, m.
    pub box_half: [f64; 3],
}

/// The bodies, parent before child: base, shoulder … gripper form the chain; the moving jaw
/// hangs on the gripper ([`JAW`]).
pub const BODIES: [Body; 6] = [
    Body {
        name: "base",
        joint: None,
        pos: [0.0, 0.0, 0.0],
        quat: [1.0, 0.0, 0.0, 0.0],
        range: (0.0, 0.0),
        box_centre: [0.0168, -0.0000, 0.0336],
        box_half: [0.0478, 0.0555, 0.0360],
    },
    Body {
        name: "shoulder",
        joint: Some("shoulder_pan"),
        pos: [0.0388353, -8.97657e-09, 0.0624],
        quat: [3.56167e-16, 1.22818e-15, -1.0, -4.14635e-16],
        range: (-1.9198621771937616, 1.9198621771937634),
        box_centre: [-0.0192, 0.0012, -0.0091],
        box_half: [0.0314, 0.0275, 0.0553],
    },
    Body {
        name: "upper_arm",
        joint: Some("shoulder_lift"),
        pos: [-0.0303992, -0.0182778, -0.0542],
        quat: [0.5, -0.5, -0.5, -0.5],
        range: (-1.7453292519943224, 1.7453292519943366),
        box_centre: [-0.0591, -0.0131, 0.0201],
        box_half: [0.0711, 0.0251, 0.0336],
    },
    Body {
        name: "lower_arm",
        joint: Some("elbow_flex"),
        pos: [-0.11257, -0.028, 1.73763e-16],
        quat: [0.707107, -5.98613e-17, -2.58051e-17, 0.707107],
        range: (-1.69, 1.69),
        box_centre: [-0.0665, 0.0035, 0.0202],
        box_half: [0.0786, 0.0184, 0.0322],
    },
    Body {
        name: "wrist",
        joint: Some("wrist_flex"),
        pos: [-0.1349, 0.0052, 3.62355e-17],
        quat: [0.707107, 9.58722e-16, -7.51313e-16, -0.707107],
        range: (-1.6580628494556928, 1.6580627293335335),
        box_centre: [-0.0022, -0.0269, 0.0222],
        box_half: [0.0178, 0.0389, 0.0312],
    },
    Body {
        name: "gripper",
        joint: Some("wrist_roll"),
        pos: [5.55112e-17, -0.0611, 0.0181],
        quat: [0.0172091, -0.0172091, 0.706897, 0.706897],
        range: (-2.7438472969992493, 2.841206309382605),
        box_centre: [-0.0024, -0.0020, -0.0517],
        box_half: [0.0328, 0.0260, 0.0527],
    },
];

/// The moving jaw, a child of the gripper body (joint `gripper`: 0 closed, up to 1.745 open).
pub const JAW: Body = Body {
    name: "moving_jaw_so101_v1",
    joint: Some("gripper"),
    pos: [0.0202, 0.0188, -0.0234],
    quat: [0.707107, 0.707107, -1.85362e-08, 1.85362e-08],
    range: (-0.17453297762778586, 1.7453291995659765),
    box_centre: [-0.0012, -0.0360, 0.0189],
    box_half: [0.0111, 0.0460, 0.0240],
};

/// The tool frame (MJCF site `gripperframe`, URDF `gripper_frame_link`) in the gripper body:
/// position, m.
pub const TOOL_POS: [f64; 3] = [-0.0079, -0.000218121, -0.0981274];
/// The tool frame's orientation in the gripper body (w, x, y, z).
pub const TOOL_QUAT: [f64; 4] = [0.707107, -0.0, 0.707107, -2.37788e-17];

/// The five arm joints, in chain order.
pub const JOINT_NAMES: [&str; 5] = [
    "shoulder_pan",
    "shoulder_lift",
    "elbow_flex",
    "wrist_flex",
    "wrist_roll",
];

/// Joint position limits, rad (lower, upper), in chain order.
pub fn joint_limits() -> [(f64, f64); 5] {
    let mut out = [(0.0, 0.0); 5];
    for (o, b) in out.iter_mut().zip(&BODIES[1..]) {
        *o = b.range;
    }
    out
}

/// A drawn part of a body: a box, axis-aligned in the body's frame, around one collision mesh
/// (the base: one visual mesh), or one of the two pieces of the fixed jaw (its mount and its
/// finger), the moving jaw (its hinge and its finger) or the base's housing (its foot and its
/// raised back). Boxes inside another of the same body are left out. As
/// `tests/so101/golden_fk.py --parts` computes them from the repository's `assets/` STL files.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Part {
    /// The body: 0 the base, 1–5 the chain's bodies of [`BODIES`], 6 the moving jaw ([`JAW`]).
    pub body: u8,
    /// Centre in the body's frame, m (single precision: drawn only).
    pub centre: [f32; 3],
    /// Half sizes along the body's axes, m.
    pub half: [f32; 3],
}

/// The fixed jaw's finger: its index in [`PARTS`].
pub const FIXED_FINGER: usize = 16;

const fn part(body: u8, centre: [f32; 3], half: [f32; 3]) -> Part {
    Part { body, centre, half }
}

/// The drawn parts, body by body.
pub const PARTS: [Part; 19] = [
    part(0, [0.0129, 0.0014, 0.0514], [0.0401, 0.0238, 0.0157]),
    part(0, [0.0066, -0.0000, 0.0336], [0.0290, 0.0555, 0.0360]),
    part(0, [0.0501, -0.0000, 0.0064], [0.0145, 0.0487, 0.0088]),
    part(0, [0.0263, -0.0000, 0.0441], [0.0227, 0.0124, 0.0198]),
    part(0, [-0.0272, -0.0002, 0.0474], [0.0038, 0.0255, 0.0210]),
    part(1, [-0.0304, 0.0000, -0.0417], [0.0124, 0.0198, 0.0227]),
    part(1, [-0.0316, 0.0012, -0.0240], [0.0190, 0.0275, 0.0140]),
    part(1, [-0.0177, 0.0000, 0.0041], [0.0299, 0.0230, 0.0421]),
    part(2, [-0.1126, -0.0155, 0.0183], [0.0124, 0.0227, 0.0198]),
    part(2, [-0.0591, -0.0002, 0.0201], [0.0711, 0.0122, 0.0336]),
    part(3, [-0.0533, -0.0000, 0.0202], [0.0653, 0.0120, 0.0322]),
    part(3, [-0.1047, 0.0035, 0.0200], [0.0140, 0.0184, 0.0282]),
    part(3, [-0.1224, 0.0052, 0.0183], [0.0227, 0.0124, 0.0198]),
    part(4, [-0.0022, -0.0269, 0.0221], [0.0178, 0.0389, 0.0312]),
    part(5, [0.0077, 0.0005, -0.0234], [0.0227, 0.0198, 0.0124]),
    part(5, [-0.0026, -0.0020, -0.0254], [0.0326, 0.0260, 0.0264]),
    part(5, [-0.0200, -0.0002, -0.0781], [0.0121, 0.0102, 0.0263]),
    part(6, [-0.0030, -0.0590, 0.0189], [0.0093, 0.0230, 0.0091]),
    part(6, [-0.0000, -0.0130, 0.0189], [0.0100, 0.0230, 0.0240]),
];
