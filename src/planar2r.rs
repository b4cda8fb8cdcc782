//! Planar two-link (2R) arm kinematics: FK, IK with both elbow branches, the Jacobian, its
//! determinant, Yoshikawa manipulability, singular values and the manipulability ellipse.
//!
//! With link lengths `L1`, `L2` and joint angles `q1`, `q2`:
//!
//! ```text
//! x = L1 cos q1 + L2 cos(q1 + q2)        J = [ -L1 s1 - L2 s12   -L2 s12 ]
//! y = L1 sin q1 + L2 sin(q1 + q2)            [  L1 c1 + L2 c12    L2 c12 ]
//! det J = L1 L2 sin q2                   w = sqrt(det(J Jᵀ)) = |det J|
//! ```
//!
//! IK: `c2 = (x² + y² − L1² − L2²) / (2 L1 L2)`, reachable when `|c2| ≤ 1`;
//! `q2 = ±acos(c2)`, `q1 = atan2(y, x) − atan2(L2 sin q2, L1 + L2 cos q2)`. The recipes' branch is
//! `q2 = +acos(c2)` ("elbow-down"); `q2 = −acos(c2)` is elbow-up.
//!
//! Determinants are computed as numpy does (LU with partial pivoting), so that recipe CSVs
//! agree with `np.linalg.det` to the last digits.

/// Which of the two IK solutions to take.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Elbow {
    /// `q2 = +acos(c2)`: the recipes' branch.
    #[default]
    Down,
    /// `q2 = -acos(c2)`.
    Up,
}

impl Elbow {
    /// The other branch.
    pub fn flipped(self) -> Elbow {
        match self {
            Elbow::Down => Elbow::Up,
            Elbow::Up => Elbow::Down,
        }
    }
}

/// Link lengths in metres.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Arm {
    pub l1: f64,
    pub l2: f64,
}

/// A 2×2 matrix, row-major: `m[row][col]`.
pub type Mat2 = [[f64; 2]; 2];

/// The manipulability (velocity) ellipse at the tip: semi-axes are the singular values of J,
/// the major axis points along the first left singular vector.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ellipse {
    pub sigma_max: f64,
    pub sigma_min: f64,
    /// Angle of the major axis from +x, radians, in (-pi/2, pi/2].
    pub angle_rad: f64,
}

/// Everything the IK page shows for one pose.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PoseReport {
    pub q1: f64,
    pub q2: f64,
    pub x: f64,
    pub y: f64,
    pub jacobian: Mat2,
    pub det_j: f64,
    pub manipulability: f64,
    pub ellipse: Ellipse,
}

impl Arm {
    /// The arm of the recipes' defaults (0.12 m, 0.10 m).
    pub const DEFAULT: Arm = Arm { l1: 0.12, l2: 0.10 };

    /// Tip position.
    pub fn fk(&self, q1: f64, q2: f64) -> (f64, f64) {
        let x = self.l1 * q1.cos() + self.l2 * (q1 + q2).cos();
        let y = self.l1 * q1.sin() + self.l2 * (q1 + q2).sin();
        (x, y)
    }

    /// Elbow (joint 2) position.
    pub fn elbow(&self, q1: f64) -> (f64, f64) {
        (self.l1 * q1.cos(), self.l1 * q1.sin())
    }

    /// Inner and outer radius of the reachable annulus.
    pub fn reach(&self) -> (f64, f64) {
        ((self.l1 - self.l2).abs(), self.l1 + self.l2)
    }

    /// IK for one branch, exactly as the recipe computes it; `None` outside the annulus
    /// (`|c2| > 1`).
    pub fn ik(&self, x: f64, y: f64, elbow: Elbow) -> Option<(f64, f64)> {
        let (l1, l2) = (self.l1, self.l2);
        let r2 = x * x + y * y;
        let c2 = (r2 - l1 * l1 - l2 * l2) / (2.0 * l1 * l2);
        if c2.abs() > 1.0 || c2.is_nan() {
            return None;
        }
        let mut q2 = c2.clamp(-1.0, 1.0).acos();
        if elbow == Elbow::Up {
            q2 = -q2;
        }
        let q1 = y.atan2(x) - (l2 * q2.sin()).atan2(l1 + l2 * q2.cos());
        Some((q1, q2))
    }

    /// The reachable point nearest to `(x, y)` and whether it had to move.
    pub fn clamp_to_reach(&self, x: f64, y: f64) -> (f64, f64, bool) {
        let (inner, outer) = self.reach();
        let r = x.hypot(y);
        // A hair inside the boundary, so that IK of the pinned point succeeds.
        let eps = 1e-12 * outer.max(1e-300);
        let target = if r > outer - eps {
            outer - eps
        } else if r < inner + eps {
            inner + eps
        } else {
            return (x, y, false);
        };
        let moved = r > outer || r < inner;
        if r < 1e-300 {
            return (target, 0.0, moved);
        }
        (x / r * target, y / r * target, moved)
    }

    /// Geometric Jacobian d(x, y)/d(q1, q2).
    pub fn jacobian(&self, q1: f64, q2: f64) -> Mat2 {
        let (s1, c1) = (q1.sin(), q1.cos());
        let (s12, c12) = ((q1 + q2).sin(), (q1 + q2).cos());
        [
            [-self.l1 * s1 - self.l2 * s12, -self.l2 * s12],
            [self.l1 * c1 + self.l2 * c12, self.l2 * c12],
        ]
    }

    /// All the numbers of one pose.
    pub fn report(&self, q1: f64, q2: f64) -> PoseReport {
        let (x, y) = self.fk(q1, q2);
        let j = self.jacobian(q1, q2);
        PoseReport {
            q1,
            q2,
            x,
            y,
            jacobian: j,
            det_j: det(&j),
            manipulability: manipulability(&j),
            ellipse: ellipse(&j),
        }
    }

    /// `det J` as the manip-grid recipe writes it out by hand (not via LU).
    pub fn det_explicit(&self, q1: f64, q2: f64) -> f64 {
        let (l1, l2) = (self.l1, self.l2);
        let (s1, c1) = (q1.sin(), q1.cos());
        let (s12, c12) = ((q1 + q2).sin(), (q1 + q2).cos());
        (-l1 * s1 - l2 * s12) * (l2 * c12) - (-l2 * s12) * (l1 * c1 + l2 * c12)
    }
}

/// Determinant the way `np.linalg.det` gets it: LU with partial pivoting (LAPACK `getrf`).
pub fn det(m: &Mat2) -> f64 {
    let [[a, b], [c, d]] = *m;
    let (p, q, r, s, sign) = if c.abs() > a.abs() {
        (c, d, a, b, -1.0)
    } else {
        (a, b, c, d, 1.0)
    };
    if p == 0.0 {
        return 0.0 * sign;
    }
    let l = r * (1.0 / p);
    let u22 = s - l * q;
    sign * p * u22
}

/// `J Jᵀ`.
pub fn j_jt(j: &Mat2) -> Mat2 {
    let [[a, b], [c, d]] = *j;
    [
        [a * a + b * b, a * c + b * d],
        [c * a + d * b, c * c + d * d],
    ]
}

/// Yoshikawa manipulability `sqrt(max(0, det(J Jᵀ)))`, as the jacobian-2r recipe computes it.
pub fn manipulability(j: &Mat2) -> f64 {
    det(&j_jt(j)).max(0.0).sqrt()
}

/// Singular values `(sigma_min, sigma_max)` of a 2×2 matrix.
pub fn singular_values(m: &Mat2) -> (f64, f64) {
    let e = ellipse(m);
    (e.sigma_min, e.sigma_max)
}

/// The manipulability ellipse of `J`: singular values and the major axis direction.
pub fn ellipse(m: &Mat2) -> Ellipse {
    let [[a, b], [c, d]] = *m;
    // sigma_max = Q + R, sigma_min = |Q - R| with the stable product form for sigma_min.
    let e = (a + d) / 2.0;
    let f = (a - d) / 2.0;
    let g = (c + b) / 2.0;
    let h = (c - b) / 2.0;
    let q = e.hypot(h);
    let r = f.hypot(g);
    let sigma_max = q + r;
    let det_abs = (a * d - b * c).abs();
    let sigma_min = if sigma_max > 0.0 {
        det_abs / sigma_max
    } else {
        0.0
    };
    // Major axis: eigenvector of J Jᵀ for the larger eigenvalue.
    let [[p, pq], [_, s]] = j_jt(m);
    let angle_rad = 0.5 * (2.0 * pq).atan2(p - s);
    Ellipse {
        sigma_max,
        sigma_min,
        angle_rad,
    }
}

/// Wraps an angle to (-pi, pi].
pub fn wrap_angle(q: f64) -> f64 {
    use std::f64::consts::PI;
    let w = (q + PI).rem_euclid(2.0 * PI) - PI;
    if w <= -PI {
        w + 2.0 * PI
    } else {
        w
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() <= 1e-12 + 1e-9 * b.abs()
    }

    #[test]
    fn ik_round_trips_both_branches() {
        let arm = Arm::DEFAULT;
        for &(x, y) in &[(0.15, 0.05), (-0.1, 0.12), (0.03, -0.2), (0.21, 0.0)] {
            for elbow in [Elbow::Down, Elbow::Up] {
                let (q1, q2) = arm.ik(x, y, elbow).unwrap();
                let (fx, fy) = arm.fk(q1, q2);
                assert!(close(fx, x) && close(fy, y), "{x} {y} {elbow:?}");
                assert_eq!(q2 >= 0.0, elbow == Elbow::Down);
            }
        }
        assert!(arm.ik(0.3, 0.0, Elbow::Down).is_none());
        assert!(arm.ik(0.0, 0.01, Elbow::Down).is_none());
    }

    #[test]
    fn jacobian_numbers() {
        let arm = Arm::DEFAULT;
        let rep = arm.report(0.0, 0.8);
        // golden/jacobian_default first row
        assert!(close(rep.det_j, 0.008608273090794276));
        assert!(close(rep.manipulability, 0.008608273090794276));
        assert!(close(rep.ellipse.sigma_min, 0.03864146032693336));
        assert!(close(rep.ellipse.sigma_max, 0.22277297539902366));
        assert!(close(rep.det_j, arm.l1 * arm.l2 * 0.8f64.sin()));
    }

    #[test]
    fn ellipse_axis_is_the_stretched_direction() {
        let arm = Arm::DEFAULT;
        let j = arm.jacobian(0.4, 1.1);
        let e = ellipse(&j);
        // |Jᵀ u| = sigma_max for the unit vector u along the major axis.
        let (u0, u1) = (e.angle_rad.cos(), e.angle_rad.sin());
        let jt_u = (j[0][0] * u0 + j[1][0] * u1, j[0][1] * u0 + j[1][1] * u1);
        assert!(close(jt_u.0.hypot(jt_u.1), e.sigma_max));
    }

    #[test]
    fn clamp_pins_to_annulus() {
        let arm = Arm::DEFAULT;
        let (x, y, moved) = arm.clamp_to_reach(1.0, 0.0);
        assert!(moved && arm.ik(x, y, Elbow::Down).is_some());
        let (x, y, moved) = arm.clamp_to_reach(0.0, 0.001);
        assert!(moved && arm.ik(x, y, Elbow::Up).is_some());
        assert_eq!(arm.clamp_to_reach(0.1, 0.1), (0.1, 0.1, false));
        let (x, y, _) = arm.clamp_to_reach(0.0, 0.0);
        assert!(arm.ik(x, y, Elbow::Down).is_some());
    }

    #[test]
    fn wraps() {
        use std::f64::consts::PI;
        assert!(close(wrap_angle(3.0 * PI / 2.0), -PI / 2.0));
        assert!(close(wrap_angle(-PI), PI));
    }
}
