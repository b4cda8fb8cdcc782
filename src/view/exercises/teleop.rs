//! The Robot Pilot's exercises (`#/teleop`): drive the 3R arm near its singularity, which
//! joint decides it, and which IK method keeps the joints calm there. The numbers are the
//! pilot's kernels' ([`crate::teleop::manipulability`], [`crate::teleop::ik_step`]).
//!
//! For the planar 3R arm `det J = l1 l2 sin q2`: neither the shoulder nor the wrist changes
//! it, so the arm is singular where the 2R drills' arm is, at `q2 = 0` and `q2 = ±π`.

use super::exercise::{CheckError, Exercise, PageModel};
use crate::teleop::{manipulability, ArmParams};

/// The page's route id.
pub const PAGE: &str = "teleop";

/// `teleop-near-singular`: manipulability below this, m² (the IK drill's threshold).
pub const NEAR_SINGULAR_W_M2: f64 = 0.001;

/// The page's exercises, in the order it lists them.
#[rustfmt::skip]
pub const EXERCISES: [Exercise; 3] = [
    Exercise::goal("teleop-near-singular", PAGE, near_singular_met),
    // 1: the elbow, q2.
    Exercise::choose("teleop-which-joint", PAGE, 3, 1),
    // 1: DLS.
    Exercise::choose("teleop-calm-method", PAGE, 3, 1),
];

/// `teleop-near-singular`: the arm's manipulability is below [`NEAR_SINGULAR_W_M2`] with every
/// joint within its limits (the pilot keeps them there; a pose from elsewhere may not be).
pub fn near_singular(arm: &ArmParams, q: &[f64; 3]) -> bool {
    let within = (0..3).all(|k| arm.q_min[k] <= q[k] && q[k] <= arm.q_max[k]);
    within && manipulability(arm, q) < NEAR_SINGULAR_W_M2
}

fn near_singular_met(model: &PageModel) -> Result<bool, CheckError> {
    match *model {
        PageModel::Teleop { arm, q } => Ok(near_singular(arm, &q)),
        other => Err(CheckError::OtherPage {
            exercise: "teleop-near-singular",
            page: other.page(),
        }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::teleop::{ik_step, jacobian, ControlParams, IkMethod};
    use crate::view::exercises::exercise::test_attribute::test;
    crate::view::exercises::exercise::page_check!(|q: [f64; 3]| PageModel::Teleop {
        arm: &ArmParams::DEFAULT,
        q
    });

    #[test]
    fn teleop_near_singular_needs_the_elbow_almost_straight() {
        // sin q2 = 0.05: w = 0.012 × 0.05 = 6e-4 m².
        let straight = [0.5, 0.05f64.asin(), -0.3];
        assert_eq!(
            check("teleop-near-singular", straight, Answer::PageState),
            Verdict::Goal { met: true }
        );
        assert!(!check("teleop-near-singular", [0.5, 1.0, -0.3], Answer::PageState).right());
        // A pose beyond the shoulder's limit does not count.
        assert!(!near_singular(&ArmParams::DEFAULT, &[-1.0, 0.05, 0.0]));
    }

    #[test]
    fn teleop_which_joint_is_the_elbow() {
        let arm = ArmParams::DEFAULT;
        let w = |q: [f64; 3]| manipulability(&arm, &q);
        // The shoulder and the wrist leave w as it is; the elbow sets it.
        assert!((w([0.2, 0.8, -1.0]) - w([2.0, 0.8, 1.5])).abs() < 1e-15);
        assert!((w([0.2, 0.8, 0.0]) - 0.012 * 0.8f64.sin()).abs() < 1e-15);
        assert!(w([0.2, 0.0, 1.0]) < 1e-15);
        assert!(check("teleop-which-joint", [0.0; 3], Answer::Choice(1)).right());
        assert!(!check("teleop-which-joint", [0.0; 3], Answer::Choice(0)).right());
        assert!(!check("teleop-which-joint", [0.0; 3], Answer::Choice(2)).right());
    }

    #[test]
    fn teleop_calm_method_is_damped_least_squares() {
        let arm = ArmParams::DEFAULT;
        let j = jacobian(&arm, &[0.3, 0.01, 0.2]);
        // 1 mm toward the base, the arm nearly straight.
        let dx = [-0.001 * 0.3f64.cos(), -0.001 * 0.3f64.sin(), 0.0];
        let size = |method| {
            let params = ControlParams {
                method,
                ..ControlParams::DEFAULT
            };
            let dq = ik_step(&params, &j, &dx).unwrap();
            dq.iter().map(|v| v * v).sum::<f64>().sqrt()
        };
        let (pinv, dls) = (size(IkMethod::Pinv), size(IkMethod::Dls));
        assert!(pinv > 10.0 * dls, "pinv {pinv} dls {dls}");
        assert!(check("teleop-calm-method", [0.0; 3], Answer::Choice(1)).right());
        assert!(!check("teleop-calm-method", [0.0; 3], Answer::Choice(0)).right());
        assert!(!check("teleop-calm-method", [0.0; 3], Answer::Choice(2)).right());
    }
}
