//! The trapezoid page's exercises (`#/trapezoid-profile`): make the profile a triangle,
//! predict when the ramp ends and how long the move takes, and the peak speed of a short
//! move. The phases are the page's ([`crate::view::trapezoid_profile::phases`], the kernel's
//! operations).

use super::exercise::{model_of, CheckError, Exercise, PageModel, Tolerance};
use crate::recipes::trapezoid_profile::TrapParams;
use crate::view::trapezoid_profile::{phases, Phases};

/// The page's route id.
pub const PAGE: &str = "trapezoid-profile";

/// The page's exercises, in the order it lists them.
#[rustfmt::skip]
pub const EXERCISES: [Exercise; 4] = [
    Exercise::goal("trap-triangle", PAGE, triangle_met),
    Exercise::predict("trap-accel-end", PAGE, "s", Tolerance::Relative(0.05), accel_end_truth),
    Exercise::predict("trap-total-time", PAGE, "s", Tolerance::Relative(0.05), total_time_truth),
    // 1: sqrt(D · amax) = 0.447 m/s (a triangle, below vmax).
    Exercise::choose("trap-short-peak", PAGE, 4, 1),
];

/// The phases of the page's move (after the kernel's checks).
pub fn checked_phases(p: &TrapParams) -> Result<Phases, CheckError> {
    p.validate()?;
    Ok(phases(p))
}

/// `trap-triangle`: the profile has no cruise phase (the distance is too short to reach
/// vmax: `vmax² / amax ≥ D`, the kernel's test).
pub fn is_triangle(p: &TrapParams) -> Result<bool, CheckError> {
    Ok(checked_phases(p)?.triangle)
}

fn triangle_met(model: &PageModel) -> Result<bool, CheckError> {
    is_triangle(model_of!(model, Trapezoid, "trap-triangle"))
}

/// `trap-accel-end`: when the profile stops accelerating, `t_acc`, s.
pub fn accel_end_s(p: &TrapParams) -> Result<f64, CheckError> {
    Ok(checked_phases(p)?.t_acc)
}

fn accel_end_truth(model: &PageModel) -> Result<f64, CheckError> {
    accel_end_s(model_of!(model, Trapezoid, "trap-accel-end"))
}

/// `trap-total-time`: the move's duration `t_total = 2 t_acc + t_flat`, s.
pub fn total_time_s(p: &TrapParams) -> Result<f64, CheckError> {
    Ok(checked_phases(p)?.t_total)
}

fn total_time_truth(model: &PageModel) -> Result<f64, CheckError> {
    total_time_s(model_of!(model, Trapezoid, "trap-total-time"))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::recipes::trapezoid_profile::compute;
    use crate::view::exercises::exercise::test_attribute::test;
    crate::view::exercises::exercise::page_check!(|p: &TrapParams| PageModel::Trapezoid(p));

    fn with_distance(distance: f64) -> TrapParams {
        TrapParams {
            distance,
            ..TrapParams::default()
        }
    }

    #[test]
    fn trap_triangle_needs_a_short_move() {
        // vmax² / amax = 0.25: a move of 0.2 never cruises; the recipe's 1.0 does.
        let short = with_distance(0.2);
        assert!(compute(&short).unwrap().triangle);
        assert_eq!(
            check("trap-triangle", &short, Answer::PageState),
            Verdict::Goal { met: true }
        );
        assert!(!compute(&TrapParams::default()).unwrap().triangle);
        assert!(!check("trap-triangle", &TrapParams::default(), Answer::PageState).right());
        // A higher speed limit makes the recipe's own move a triangle.
        let fast = TrapParams {
            vmax: 1.5,
            ..TrapParams::default()
        };
        assert!(is_triangle(&fast).unwrap());
        // Invalid parameters are the kernel's error.
        let bad = TrapParams {
            dt: 0.0,
            ..TrapParams::default()
        };
        assert!(matches!(
            find("trap-triangle")
                .unwrap()
                .check(&PageModel::Trapezoid(&bad), Answer::PageState),
            Err(CheckError::Kernel(_))
        ));
    }

    #[test]
    fn trap_accel_end_is_vmax_over_amax_or_earlier() {
        let p = TrapParams::default();
        assert_eq!(accel_end_s(&p).unwrap(), 0.5);
        assert!(check("trap-accel-end", &p, Answer::Number(0.49)).right());
        // Half the total time is the answer for a triangle, not here.
        assert!(!check("trap-accel-end", &p, Answer::Number(1.25)).right());
        // The sampled profile: the last row at amax is at t < t_acc, the next one cruises.
        let rows = compute(&p).unwrap().samples;
        let last_acc = rows.iter().rposition(|r| r.a > 0.0).unwrap();
        assert!(rows[last_acc].t <= 0.5 && rows[last_acc + 1].a == 0.0);
        // A triangle stops accelerating at sqrt(D / amax).
        let short = with_distance(0.2);
        assert!((accel_end_s(&short).unwrap() - 0.2f64.sqrt()).abs() < 1e-15);
        assert!(!check("trap-accel-end", &short, Answer::Number(0.5)).right());
    }

    #[test]
    fn trap_total_time_is_the_kernels() {
        let p = TrapParams::default();
        let truth = total_time_s(&p).unwrap();
        assert_eq!(truth, compute(&p).unwrap().t_total);
        assert_eq!(truth, 2.5);
        assert!(check("trap-total-time", &p, Answer::Number(2.45)).right());
        // D / vmax forgets the ramps.
        assert!(!check("trap-total-time", &p, Answer::Number(2.0)).right());
    }

    #[test]
    fn trap_short_peak_is_below_vmax() {
        let short = with_distance(0.2);
        let profile = compute(&short).unwrap();
        assert!((profile.vmax_used - 0.2f64.sqrt()).abs() < 1e-15);
        let v_max_sampled = profile.samples.iter().map(|r| r.v).fold(0.0, f64::max);
        assert!(v_max_sampled < 0.5 && v_max_sampled > 0.44);
        assert!(check("trap-short-peak", &short, Answer::Choice(1)).right());
        for wrong in [0, 2, 3] {
            assert!(!check("trap-short-peak", &short, Answer::Choice(wrong)).right());
        }
    }
}
