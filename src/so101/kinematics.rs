//! Forward kinematics, the geometric Jacobian and the manipulability of the SO-101, computed
//! as MuJoCo's `mj_kinematics` does from the data of [`super::model`]: each body's world
//! position is its parent's plus the parent's rotation times `pos`, its orientation the
//! parent's quaternion times `quat` times the joint's axis-angle quaternion, normalised; the
//! tool frame (site `gripperframe`) is placed in the gripper body the same way. Arithmetic,
//! `sqrt` and [`crate::math`]'s correctly rounded `sin`/`cos` only: the same bits natively and
//! in wasm.

use super::model::{Body, BODIES, JAW, TOOL_POS, TOOL_QUAT};

/// A 3×3 matrix, row-major.
pub type Mat3 = [[f64; 3]; 3];
/// A quaternion (w, x, y, z).
pub type Quat = [f64; 4];
/// The 6×5 geometric Jacobian of the tool frame: rows vx, vy, vz, ωx, ωy, ωz (world frame),
/// columns the five joints.
pub type Jacobian = [[f64; 5]; 6];

/// A frame in the world: origin and orientation (columns are the frame's axes).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Frame {
    /// Origin, m.
    pub pos: [f64; 3],
    /// Orientation, unit quaternion.
    pub quat: Quat,
    /// Orientation as a rotation matrix.
    pub rot: Mat3,
}

impl Frame {
    const WORLD: Frame = Frame {
        pos: [0.0; 3],
        quat: [1.0, 0.0, 0.0, 0.0],
        rot: [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
    };

    /// The point `p` of this frame in the world.
    pub fn apply(&self, p: &[f64; 3]) -> [f64; 3] {
        add(&self.pos, &mat_vec(&self.rot, p))
    }

    /// Roll, pitch, yaw (rad) with `R = Rz(yaw) Ry(pitch) Rx(roll)`.
    pub fn rpy(&self) -> [f64; 3] {
        rpy_of(&self.rot)
    }

    /// Roll, pitch, yaw (rad) of the tool's turn from pointing straight down (its x axis along
    /// −z, its z axis along +z of the world turned a quarter about y): `R Ry(π/2)ᵀ = Rz(yaw)
    /// Ry(pitch) Rx(roll)`. The page's readouts and the episode CSV use these, zero with the
    /// gripper straight down, far from the gimbal lock plain `rpy` has there.
    pub fn rpy_from_down(&self) -> [f64; 3] {
        let r = &self.rot;
        // Ry(π/2)ᵀ = [[0, 0, −1], [0, 1, 0], [1, 0, 0]].
        let m = [
            [r[0][2], r[0][1], -r[0][0]],
            [r[1][2], r[1][1], -r[1][0]],
            [r[2][2], r[2][1], -r[2][0]],
        ];
        rpy_of(&m)
    }
}

/// Roll, pitch, yaw (rad) of `r = Rz(yaw) Ry(pitch) Rx(roll)`.
pub fn rpy_of(r: &Mat3) -> [f64; 3] {
    [
        crate::math::atan2(r[2][1], r[2][2]),
        crate::math::asin((-r[2][0]).clamp(-1.0, 1.0)),
        crate::math::atan2(r[1][0], r[0][0]),
    ]
}

/// Every frame of the arm at one joint vector.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Chain {
    /// The frames of [`BODIES`], after their joints.
    pub bodies: [Frame; 6],
    /// The moving jaw's frame.
    pub jaw: Frame,
    /// The tool frame.
    pub tool: Frame,
}

/// `a b`.
pub fn quat_mul(a: &Quat, b: &Quat) -> Quat {
    [
        a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
        a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
        a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
        a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0],
    ]
}

/// `q / |q|` (the identity for a zero quaternion).
pub fn quat_normalize(q: &Quat) -> Quat {
    let n = (q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]).sqrt();
    if n < 1e-15 {
        return [1.0, 0.0, 0.0, 0.0];
    }
    [q[0] / n, q[1] / n, q[2] / n, q[3] / n]
}

/// The rotation matrix of a unit quaternion.
pub fn quat_mat(q: &Quat) -> Mat3 {
    let [w, x, y, z] = *q;
    let (ww, xx, yy, zz) = (w * w, x * x, y * y, z * z);
    [
        [
            ww + xx - yy - zz,
            2.0 * (x * y - w * z),
            2.0 * (x * z + w * y),
        ],
        [
            2.0 * (x * y + w * z),
            ww - xx + yy - zz,
            2.0 * (y * z - w * x),
        ],
        [
            2.0 * (x * z - w * y),
            2.0 * (y * z + w * x),
            ww - xx - yy + zz,
        ],
    ]
}

/// The quaternion of a rotation by `angle` about the body z axis.
fn z_rotation(angle: f64) -> Quat {
    if angle == 0.0 {
        return [1.0, 0.0, 0.0, 0.0];
    }
    let (s, c) = crate::math::sincos(angle / 2.0);
    [c, 0.0, 0.0, s]
}

/// `M v`.
pub fn mat_vec(m: &Mat3, v: &[f64; 3]) -> [f64; 3] {
    [
        m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2],
        m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
        m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2],
    ]
}

/// `a + b`.
pub fn add(a: &[f64; 3], b: &[f64; 3]) -> [f64; 3] {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

/// `a − b`.
pub fn sub(a: &[f64; 3], b: &[f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// `a × b`.
pub fn cross(a: &[f64; 3], b: &[f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// `|v|`.
pub fn norm(v: &[f64; 3]) -> f64 {
    (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
}

/// The frame of `body` in `parent` after its joint turned by `angle`.
fn child(parent: &Frame, body: &Body, angle: f64) -> Frame {
    let pos = parent.apply(&body.pos);
    let q = quat_mul(&parent.quat, &quat_normalize(&body.quat));
    let quat = quat_normalize(&quat_mul(&q, &z_rotation(angle)));
    Frame {
        pos,
        quat,
        rot: quat_mat(&quat),
    }
}

/// Every frame of the arm at joints `q` (rad, chain order) with the jaw at `jaw` (rad).
pub fn chain(q: &[f64; 5], jaw: f64) -> Chain {
    let mut bodies = [Frame::WORLD; 6];
    let mut parent = Frame::WORLD;
    for (i, body) in BODIES.iter().enumerate() {
        let angle = if i == 0 { 0.0 } else { q[i - 1] };
        parent = child(&parent, body, angle);
        bodies[i] = parent;
    }
    let gripper = bodies[5];
    let tool_quat = quat_normalize(&quat_mul(&gripper.quat, &quat_normalize(&TOOL_QUAT)));
    let tool = Frame {
        pos: gripper.apply(&TOOL_POS),
        quat: tool_quat,
        rot: quat_mat(&tool_quat),
    };
    Chain {
        bodies,
        jaw: child(&gripper, &JAW, jaw),
        tool,
    }
}

/// The tool frame at joints `q`.
pub fn fk(q: &[f64; 5]) -> Frame {
    chain(q, 0.0).tool
}

/// The geometric Jacobian of the tool frame at joints `q`: column `i` is `(aᵢ × (p − oᵢ), aᵢ)`
/// with `aᵢ` joint `i`'s axis and `oᵢ` its origin in the world, `p` the tool's origin.
pub fn jacobian(q: &[f64; 5]) -> Jacobian {
    jacobian_of(&chain(q, 0.0))
}

/// [`jacobian`] of an already computed chain.
pub fn jacobian_of(c: &Chain) -> Jacobian {
    let mut j = [[0.0; 5]; 6];
    for (i, f) in c.bodies[1..].iter().enumerate() {
        let axis = [f.rot[0][2], f.rot[1][2], f.rot[2][2]];
        let v = cross(&axis, &sub(&c.tool.pos, &f.pos));
        for r in 0..3 {
            j[r][i] = v[r];
            j[r + 3][i] = axis[r];
        }
    }
    j
}

/// `JᵀJ` (5×5).
pub fn jt_j(j: &Jacobian) -> [[f64; 5]; 5] {
    let mut out = [[0.0; 5]; 5];
    for (r, row) in out.iter_mut().enumerate() {
        for (c, o) in row.iter_mut().enumerate() {
            *o = (0..6).map(|k| j[k][r] * j[k][c]).sum();
        }
    }
    out
}

/// Yoshikawa's manipulability of the position part, `sqrt(det(Jv Jvᵀ))` (m³): how far the tool
/// can move in every direction; it falls to zero where the arm is stretched out or folded.
pub fn manipulability(j: &Jacobian) -> f64 {
    let mut a = [[0.0; 3]; 3];
    for (r, row) in a.iter_mut().enumerate() {
        for (c, o) in row.iter_mut().enumerate() {
            *o = (0..5).map(|k| j[r][k] * j[c][k]).sum();
        }
    }
    let det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1])
        - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
        + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    det.max(0.0).sqrt()
}

/// The rotation vector (axis × angle, rad) of the rotation matrix `r` (angle in [0, π]).
pub fn rotation_vector(r: &Mat3) -> [f64; 3] {
    let v = [r[2][1] - r[1][2], r[0][2] - r[2][0], r[1][0] - r[0][1]];
    let s = norm(&v) / 2.0;
    let c = (r[0][0] + r[1][1] + r[2][2] - 1.0) / 2.0;
    let angle = crate::math::atan2(s, c);
    if s < 1e-12 {
        if c > 0.0 {
            return [v[0] / 2.0, v[1] / 2.0, v[2] / 2.0];
        }
        // Half turn: the axis from the diagonal of (R + I) / 2.
        let d = [
            (r[0][0] + 1.0) / 2.0,
            (r[1][1] + 1.0) / 2.0,
            (r[2][2] + 1.0) / 2.0,
        ];
        let k = if d[0] >= d[1] && d[0] >= d[2] {
            0
        } else if d[1] >= d[2] {
            1
        } else {
            2
        };
        let mut axis = [0.0; 3];
        axis[k] = d[k].max(0.0).sqrt();
        for i in 0..3 {
            if i != k && axis[k] > 0.0 {
                axis[i] = (r[i][k] + r[k][i]) / (4.0 * axis[k]);
            }
        }
        return [axis[0] * angle, axis[1] * angle, axis[2] * angle];
    }
    let k = angle / (2.0 * s);
    [v[0] * k, v[1] * k, v[2] * k]
}

/// `A Bᵀ`.
pub fn mul_t(a: &Mat3, b: &Mat3) -> Mat3 {
    let mut out = [[0.0; 3]; 3];
    for (r, row) in out.iter_mut().enumerate() {
        for (c, o) in row.iter_mut().enumerate() {
            *o = a[r][0] * b[c][0] + a[r][1] * b[c][1] + a[r][2] * b[c][2];
        }
    }
    out
}

/// The rotation matrix of the rotation vector `v` (Rodrigues).
pub fn rotation_matrix(v: &[f64; 3]) -> Mat3 {
    let angle = norm(v);
    if angle == 0.0 {
        return Frame::WORLD.rot;
    }
    let (s, c) = crate::math::sincos(angle / 2.0);
    let k = s / angle;
    quat_mat(&[c, v[0] * k, v[1] * k, v[2] * k])
}
