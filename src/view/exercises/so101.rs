//! The SO-101 pilot's exercises (`#/so101`): bring the arm near a singular pose, what the
//! shoulder pan does to the manipulability, and what five joints mean for a six-number tool
//! pose. `w` is the pilot's ([`crate::so101::manipulability`]: Yoshikawa's measure of the
//! tool's position, `sqrt(det(Jv Jvᵀ))`, m³).

use super::exercise::{CheckError, Exercise, PageModel};
use crate::so101::model::joint_limits;
use crate::so101::{jacobian, manipulability};

/// The page's route id.
pub const PAGE: &str = "so101";

/// `so101-low-w`: manipulability below this, m³ (about a fourteenth of the home pose's).
pub const LOW_W_M3: f64 = 0.001;

/// The page's exercises, in the order it lists them.
#[rustfmt::skip]
pub const EXERCISES: [Exercise; 3] = [
    Exercise::goal("so101-low-w", PAGE, low_w_met),
    // 0: it stays the same.
    Exercise::choose("so101-pan", PAGE, 3, 0),
    // 1: not every orientation at every position.
    Exercise::choose("so101-five-joints", PAGE, 3, 1),
];

/// The manipulability at joint angles `q`, m³.
pub fn w_m3(q: &[f64; 5]) -> f64 {
    manipulability(&jacobian(q))
}

/// `so101-low-w`: `w` below [`LOW_W_M3`] with every joint within its range.
pub fn low_w(q: &[f64; 5]) -> bool {
    let within = q
        .iter()
        .zip(joint_limits())
        .all(|(v, (lo, hi))| lo <= *v && *v <= hi);
    within && w_m3(q) < LOW_W_M3
}

fn low_w_met(model: &PageModel) -> Result<bool, CheckError> {
    match *model {
        PageModel::So101 { q } => Ok(low_w(&q)),
        other => Err(CheckError::OtherPage {
            exercise: "so101-low-w",
            page: other.page(),
        }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::so101::kinematics::jt_j;
    use crate::teleop::control::smallest_eigenvalue;
    use crate::view::exercises::exercise::test_attribute::test;
    crate::view::exercises::exercise::page_check!(|q: [f64; 5]| PageModel::So101 { q });

    #[test]
    fn so101_low_w_needs_a_folded_elbow() {
        let home = [0.0; 5];
        assert!((w_m3(&home) - 0.013686).abs() < 1e-6);
        assert!(!check("so101-low-w", home, Answer::PageState).right());
        // The elbow flexed far: w = 4.8e-4 m³.
        let folded = [0.0, 0.0, -1.5, 0.0, 0.0];
        assert!(w_m3(&folded) < LOW_W_M3);
        assert_eq!(
            check("so101-low-w", folded, Answer::PageState),
            Verdict::Goal { met: true }
        );
        // Beyond a joint's range does not count.
        let (_, hi) = joint_limits()[2];
        assert!(!low_w(&[0.0, 0.0, hi + 1.0, 0.0, 0.0]));
    }

    #[test]
    fn so101_pan_keeps_w() {
        for pan in [0.4, 1.2, -1.0] {
            let q = [pan, -0.5, 0.5, 0.3, 0.2];
            let q0 = [0.0, -0.5, 0.5, 0.3, 0.2];
            assert!((w_m3(&q) - w_m3(&q0)).abs() < 1e-12, "{pan}");
        }
        assert!(check("so101-pan", [0.0; 5], Answer::Choice(0)).right());
        assert!(!check("so101-pan", [0.0; 5], Answer::Choice(1)).right());
        assert!(!check("so101-pan", [0.0; 5], Answer::Choice(2)).right());
    }

    #[test]
    fn so101_five_joints_leave_a_direction_missing() {
        // Six rows (vx, vy, vz, ωx, ωy, ωz), five columns: J Jᵀ (6×6) is singular while
        // Jᵀ J (5×5) is not, at the home pose and at another.
        for q in [[0.0; 5], [0.3, -0.5, 0.5, 0.3, 0.2]] {
            let j = jacobian(&q);
            let mut j_jt = [[0.0; 6]; 6];
            for (r, row) in j_jt.iter_mut().enumerate() {
                for (c, v) in row.iter_mut().enumerate() {
                    *v = (0..5).map(|k| j[r][k] * j[c][k]).sum();
                }
            }
            assert!(smallest_eigenvalue(j_jt, 30).abs() < 1e-12);
            assert!(smallest_eigenvalue(jt_j(&j), 30) > 1e-4);
        }
        assert!(check("so101-five-joints", [0.0; 5], Answer::Choice(1)).right());
        assert!(!check("so101-five-joints", [0.0; 5], Answer::Choice(0)).right());
        assert!(!check("so101-five-joints", [0.0; 5], Answer::Choice(2)).right());
    }
}
