//! The IK page's exercises (`#/ik-2r`): a near-singular pose inside the workspace, the
//! manipulability of the pose on screen, the elbow angle of the best-conditioned pose, and
//! where a 2R arm is singular.
//!
//! For the 2R arm with links `l1`, `l2`: `w = sqrt(det(J Jᵀ)) = |det J| = l1 l2 |sin q2|`,
//! and the tip lies at `r² = l1² + l2² + 2 l1 l2 cos q2` from the base: the singular poses
//! (`q2 = 0` or `π`) are exactly those on the workspace's outer circle `r = l1 + l2` and inner
//! circle `r = |l1 − l2|`.

use std::f64::consts::PI;

use super::exercise::{model_of, CheckError, Exercise, PageModel, Tolerance};
use crate::planar2r::Arm;
use crate::view::ik2r::State;

/// The page's route id.
pub const PAGE: &str = "ik-2r";

/// `ik-singular`: manipulability below this, m².
pub const SINGULAR_W_M2: f64 = 0.001;

/// How far inside the annulus the tip must be to count as inside the workspace, m: a
/// micrometre, far below the page's readouts but above rounding, so a tip pinned to the
/// boundary (a drag beyond reach keeps it 1e-12 of the reach inside) is on the boundary.
pub const WORKSPACE_MARGIN_M: f64 = 1e-6;

/// The page's exercises, in the order it lists them.
#[rustfmt::skip]
pub const EXERCISES: [Exercise; 4] = [
    Exercise::goal("ik-singular", PAGE, singular_met),
    Exercise::predict("ik-w-pose", PAGE, "m²", Tolerance::Relative(0.1), w_pose_truth),
    Exercise::predict("ik-best-elbow", PAGE, "deg", Tolerance::Absolute(5.0), best_elbow_truth),
    // 1: on the outer and the inner circle of the workspace.
    Exercise::choose("ik-singular-where", PAGE, 4, 1),
];

/// Whether the tip of `arm` at `(q1, q2)` is inside its workspace: its distance `r` from the
/// base strictly between the annulus' radii `|l1 − l2|` and `l1 + l2`, by at least
/// [`WORKSPACE_MARGIN_M`] on each side.
pub fn tip_inside_workspace(arm: &Arm, q1: f64, q2: f64) -> bool {
    let (x, y) = arm.fk(q1, q2);
    let r = x.hypot(y);
    let (inner, outer) = arm.reach();
    inner + WORKSPACE_MARGIN_M < r && r < outer - WORKSPACE_MARGIN_M
}

/// `ik-singular`: the pose's manipulability `w` is below [`SINGULAR_W_M2`] with the tip
/// inside the workspace ([`tip_inside_workspace`]), for the page's link lengths.
pub fn singular_inside(state: &State) -> bool {
    let arm = state.params.arm();
    let w = arm.report(state.q1, state.q2).manipulability;
    w < SINGULAR_W_M2 && tip_inside_workspace(&arm, state.q1, state.q2)
}

fn singular_met(model: &PageModel) -> Result<bool, CheckError> {
    Ok(singular_inside(model_of!(model, Ik2r, "ik-singular")))
}

/// `ik-w-pose`: the manipulability of the pose on the page, m² (its `manipulability`
/// readout, hidden until the reveal).
pub fn w_pose(state: &State) -> f64 {
    state.params.arm().report(state.q1, state.q2).manipulability
}

fn w_pose_truth(model: &PageModel) -> Result<f64, CheckError> {
    Ok(w_pose(model_of!(model, Ik2r, "ik-w-pose")))
}

/// Tenths of a degree scanned by [`best_elbow_deg`] (0° to 180°).
const ELBOW_SCAN_TENTHS: u32 = 1800;

/// `ik-best-elbow`: the elbow angle in [0°, 180°] (to a tenth of a degree, the first of a
/// tie) at which the page's arm has the largest manipulability, from the kernel's `w`
/// (it does not depend on `q1`).
pub fn best_elbow_deg(arm: &Arm) -> f64 {
    let mut best = (0.0, f64::NEG_INFINITY);
    for k in 0..=ELBOW_SCAN_TENTHS {
        let deg = f64::from(k) / 10.0;
        let w = arm.report(0.0, deg * PI / 180.0).manipulability;
        if w > best.1 {
            best = (deg, w);
        }
    }
    best.0
}

fn best_elbow_truth(model: &PageModel) -> Result<f64, CheckError> {
    Ok(best_elbow_deg(
        &model_of!(model, Ik2r, "ik-best-elbow").params.arm(),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::view::exercises::exercise::test_attribute::test;
    crate::view::exercises::exercise::page_check!(|state: &State| PageModel::Ik2r(state));

    fn pose(q1: f64, q2: f64) -> State {
        State {
            q1,
            q2,
            ..State::default()
        }
    }

    #[test]
    fn ik_singular_needs_a_small_w_inside_the_workspace() {
        // Nearly stretched: w = 0.012 sin 0.05 = 6.0e-4 m², the tip 0.07 mm inside the reach.
        let near = pose(0.3, 0.05);
        let arm = near.params.arm();
        let report = arm.report(near.q1, near.q2);
        assert!(report.manipulability < SINGULAR_W_M2, "{report:?}");
        assert!(tip_inside_workspace(&arm, near.q1, near.q2));
        assert_eq!(
            check("ik-singular", &near, Answer::PageState),
            Verdict::Goal { met: true }
        );
        // Nearly folded (q2 near π) is singular inside the workspace too.
        assert!(singular_inside(&pose(0.0, PI - 0.05)));
        // The page's start pose: w = 0.012 sin 0.8 = 8.6e-3 m².
        assert_eq!(
            check("ik-singular", &State::default(), Answer::PageState),
            Verdict::Goal { met: false }
        );
        // Stretched exactly (w = 0) or pinned to the boundary by a drag: not inside.
        assert!(!singular_inside(&pose(0.3, 0.0)));
        let (x, y, moved) = arm.clamp_to_reach(1.0, 0.0);
        assert!(moved);
        let (q1, q2) = arm.ik(x, y, crate::planar2r::Elbow::Down).unwrap();
        assert!(arm.report(q1, q2).manipulability < SINGULAR_W_M2);
        assert!(!singular_inside(&pose(q1, q2)));
        // Just above the threshold: sin q2 = 0.09 gives w = 1.08e-3 m².
        assert!(!singular_inside(&pose(0.3, 0.09f64.asin())));
    }

    #[test]
    fn ik_w_pose_is_the_readout_of_the_pose() {
        let state = State::default();
        let truth = w_pose(&state);
        assert!((truth - 0.012 * 0.8f64.sin()).abs() < 1e-15, "{truth}");
        assert_eq!(
            check("ik-w-pose", &state, Answer::Number(0.0086)),
            Verdict::Predicted { right: true, truth }
        );
        // l1 l2 (the largest w) is 40 % off at this pose.
        assert!(!check("ik-w-pose", &state, Answer::Number(0.012)).right());
    }

    #[test]
    fn ik_best_elbow_is_a_right_angle() {
        let state = State::default();
        assert_eq!(best_elbow_deg(&state.params.arm()), 90.0);
        assert!(check("ik-best-elbow", &state, Answer::Number(87.0)).right());
        // Stretched out is the worst pose, not the best.
        assert!(!check("ik-best-elbow", &state, Answer::Number(0.0)).right());
        assert!(!check("ik-best-elbow", &state, Answer::Number(45.0)).right());
    }

    #[test]
    fn ik_singular_where_is_the_boundary_of_the_workspace() {
        let arm = State::default().params.arm();
        let (inner, outer) = arm.reach();
        // On both circles w vanishes (to rounding)...
        for (q2, r) in [(0.0, outer), (PI, inner)] {
            let (x, y) = arm.fk(0.7, q2);
            assert!((x.hypot(y) - r).abs() < 1e-15);
            assert!(arm.report(0.7, q2).manipulability < 1e-15);
        }
        // ...and nowhere else: not on the x axis (choice 3), not at the base (choice 1).
        let (q1, q2) = arm.ik(0.15, 0.0, crate::planar2r::Elbow::Down).unwrap();
        assert!(arm.report(q1, q2).manipulability > 1e-3);
        let state = State::default();
        assert_eq!(
            check("ik-singular-where", &state, Answer::Choice(1)),
            Verdict::Chose { right: true }
        );
        for wrong in [0, 2, 3] {
            assert!(!check("ik-singular-where", &state, Answer::Choice(wrong)).right());
        }
    }
}
