//! The planar 3R arm of the Robot Pilot scene: shoulder, elbow and wrist in the vertical
//! (x, z) plane, base at the origin, angles from +x, counter-clockwise positive.
//!
//! ```text
//! x   = l1 c1 + l2 c12 + l3 c123          J = [ -(l1 s1 + l2 s12 + l3 s123)  -(l2 s12 + l3 s123)  -l3 s123 ]
//! z   = l1 s1 + l2 s12 + l3 s123              [   l1 c1 + l2 c12 + l3 c123     l2 c12 + l3 c123     l3 c123 ]
//! phi = q1 + q2 + q3                          [   1                            1                    1       ]
//! ```
//! (`s12 = sin(q1 + q2)` and so on). Subtracting neighbouring columns leaves
//! `det J = l1 l2 sin q2`: the wrist never changes the determinant, so the 3R arm is singular
//! exactly where the 2R drills' arm (links l1, l2) is, at `q2 = 0` (stretched out) and
//! `q2 = ±π` (folded). [`manipulability`] is therefore the IK drill's number,
//! `|det J| = sqrt(det(J Jᵀ)) = l1 l2 |sin q2|`, computed by [`crate::planar2r`] exactly as
//! the IK page computes it, so both pages show the same digits for the same `q1, q2`.

#![warn(missing_docs)]

use serde::{Deserialize, Serialize};

/// Link lengths, joint limits and the capsule radius of the links.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct ArmParams {
    /// Link lengths l1, l2, l3 in metres (l3: wrist to the point between the fingertips).
    pub links: [f64; 3],
    /// Lower joint position limits, radians.
    pub q_min: [f64; 3],
    /// Upper joint position limits, radians.
    pub q_max: [f64; 3],
    /// Joint speed limits, rad/s.
    pub qd_max: [f64; 3],
    /// Radius of the capsules around the links (collision and drawing), metres.
    pub link_radius: f64,
}

impl ArmParams {
    /// The default arm: links 0.12, 0.10, 0.06 m (the first two are the 2R drills' arm).
    pub const DEFAULT: ArmParams = ArmParams {
        links: [0.12, 0.10, 0.06],
        q_min: [-0.6, -2.7, -2.7],
        q_max: [3.2, 2.7, 2.7],
        qd_max: [2.0, 2.5, 3.0],
        link_radius: 0.008,
    };

    /// Base, elbow, wrist and tip positions `(x, z)` for joint angles `q`.
    pub fn joint_points(&self, q: &[f64; 3]) -> [(f64, f64); 4] {
        let [l1, l2, l3] = self.links;
        let (s1, c1) = crate::math::sincos(q[0]);
        let (s12, c12) = crate::math::sincos(q[0] + q[1]);
        let (s123, c123) = crate::math::sincos(q[0] + q[1] + q[2]);
        let elbow = (l1 * c1, l1 * s1);
        let wrist = (elbow.0 + l2 * c12, elbow.1 + l2 * s12);
        let tip = (wrist.0 + l3 * c123, wrist.1 + l3 * s123);
        [(0.0, 0.0), elbow, wrist, tip]
    }
}

impl Default for ArmParams {
    fn default() -> Self {
        ArmParams::DEFAULT
    }
}

/// A task-space pose in the plane: tip position (m) and gripper angle from +x (rad).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Pose2 {
    /// Tip x, m.
    pub x: f64,
    /// Tip z (up), m.
    pub z: f64,
    /// Gripper angle from +x, rad (`q1 + q2 + q3`).
    pub phi: f64,
}

/// Forward kinematics: the tip pose for joint angles `q` (the tip is the point between the
/// fingertips, the grasp point). `phi = q1 + q2 + q3`, not wrapped.
pub fn fk(arm: &ArmParams, q: &[f64; 3]) -> Pose2 {
    let [_, _, _, (x, z)] = arm.joint_points(q);
    Pose2 {
        x,
        z,
        phi: q[0] + q[1] + q[2],
    }
}

/// The 3×3 Jacobian `d(x, z, phi)/d(q1, q2, q3)`, row-major (`j[row][col]`).
pub fn jacobian(arm: &ArmParams, q: &[f64; 3]) -> [[f64; 3]; 3] {
    let [l1, l2, l3] = arm.links;
    let (s1, c1) = crate::math::sincos(q[0]);
    let (s12, c12) = crate::math::sincos(q[0] + q[1]);
    let (s123, c123) = crate::math::sincos(q[0] + q[1] + q[2]);
    let x3 = -l3 * s123;
    let z3 = l3 * c123;
    let x2 = -l2 * s12 + x3;
    let z2 = l2 * c12 + z3;
    let x1 = -l1 * s1 + x2;
    let z1 = l1 * c1 + z2;
    [[x1, x2, x3], [z1, z2, z3], [1.0, 1.0, 1.0]]
}

/// The manipulability the page shows: `|det J| = l1 l2 |sin q2|` of the first two links,
/// which equals `sqrt(det(J Jᵀ))` of the full 3×3 Jacobian (see the module docs), computed by
/// [`crate::planar2r::manipulability`] as the IK drill does.
pub fn manipulability(arm: &ArmParams, q: &[f64; 3]) -> f64 {
    let two_link = crate::planar2r::Arm {
        l1: arm.links[0],
        l2: arm.links[1],
    };
    crate::planar2r::manipulability(&two_link.jacobian(q[0], q[1]))
}

#[cfg(test)]
mod tests {
    #[cfg(target_arch = "wasm32")]
    use wasm_bindgen_test::wasm_bindgen_test as test;

    use super::*;

    #[test]
    fn jacobian_matches_finite_differences() {
        let arm = ArmParams::DEFAULT;
        let q = [0.7, -1.1, 0.4];
        let j = jacobian(&arm, &q);
        let h = 1e-7;
        for col in 0..3 {
            let mut qp = q;
            let mut qm = q;
            qp[col] += h;
            qm[col] -= h;
            let (p, m) = (fk(&arm, &qp), fk(&arm, &qm));
            let d = [
                (p.x - m.x) / (2.0 * h),
                (p.z - m.z) / (2.0 * h),
                (p.phi - m.phi) / (2.0 * h),
            ];
            for row in 0..3 {
                assert!((d[row] - j[row][col]).abs() < 1e-7, "J[{row}][{col}]");
            }
        }
    }

    #[test]
    fn manipulability_is_the_determinant_of_the_full_jacobian() {
        let arm = ArmParams::DEFAULT;
        for q in [[0.3, 0.9, -0.4], [1.4, -1.48, -1.49], [2.0, 0.01, 1.0]] {
            let j = jacobian(&arm, &q);
            let det = j[0][0] * (j[1][1] * j[2][2] - j[1][2] * j[2][1])
                - j[0][1] * (j[1][0] * j[2][2] - j[1][2] * j[2][0])
                + j[0][2] * (j[1][0] * j[2][1] - j[1][1] * j[2][0]);
            let w = manipulability(&arm, &q);
            assert!((det.abs() - w).abs() < 1e-15, "{q:?}: {det} vs {w}");
            assert!((w - 0.12 * 0.10 * q[1].sin().abs()).abs() < 1e-15);
        }
    }
}
