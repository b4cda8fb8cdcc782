//! The cubic-path page's exercises (`#/cubic-path`): predict the peak velocity, slow the move
//! down to a speed limit, and where the cubic accelerates hardest. The peaks are the page's
//! readouts ([`crate::view::cubic_path::readouts`], over the kernel's samples).
//!
//! For the cubic from `q0` to `q1` in `T` with zero end velocities: `qd` peaks at `T/2` at
//! `1.5 Δ / T`, `|qdd|` is largest at both ends, `6 |Δ| / T²`.

use super::exercise::{model_of, CheckError, Exercise, PageModel, Tolerance};
use crate::recipes::cubic_path::{compute, CubicParams};
use crate::view::cubic_path::readouts;

/// The page's route id.
pub const PAGE: &str = "cubic-path";

/// `cubic-speed-limit`: the largest |qd| allowed, rad/s.
pub const SPEED_LIMIT_RAD_S: f64 = 1.0;

/// The page's exercises, in the order it lists them.
#[rustfmt::skip]
pub const EXERCISES: [Exercise; 3] = [
    Exercise::predict("cubic-peak-velocity", PAGE, "rad/s", Tolerance::Relative(0.05), peak_velocity_truth),
    Exercise::goal("cubic-speed-limit", PAGE, speed_limit_met),
    // 1: at the start and at the end.
    Exercise::choose("cubic-peak-accel", PAGE, 4, 1),
];

/// The page's peak velocity readout: the sampled `qd` of largest magnitude, signed, rad/s.
pub fn peak_velocity(p: &CubicParams) -> Result<f64, CheckError> {
    let path = compute(p)?;
    readouts(p, &path.samples)
        .peak_velocity
        .map(|peak| peak.value)
        .ok_or(CheckError::NoTruth {
            exercise: "cubic-peak-velocity",
        })
}

fn peak_velocity_truth(model: &PageModel) -> Result<f64, CheckError> {
    peak_velocity(model_of!(model, CubicPath, "cubic-peak-velocity"))
}

/// `cubic-speed-limit`: the recipe's move (`q0`, `q1` as [`CubicParams::default`]: the
/// learner changes the time, not the move) with its peak velocity at most
/// [`SPEED_LIMIT_RAD_S`].
pub fn within_speed_limit(p: &CubicParams) -> Result<bool, CheckError> {
    let recipe = CubicParams::default();
    if (p.q0, p.q1) != (recipe.q0, recipe.q1) {
        return Ok(false);
    }
    Ok(peak_velocity(p)?.abs() <= SPEED_LIMIT_RAD_S)
}

fn speed_limit_met(model: &PageModel) -> Result<bool, CheckError> {
    within_speed_limit(model_of!(model, CubicPath, "cubic-speed-limit"))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::view::exercises::exercise::test_attribute::test;
    crate::view::exercises::exercise::page_check!(|p: &CubicParams| PageModel::CubicPath(p));

    #[test]
    fn cubic_peak_velocity_is_one_and_a_half_times_the_mean() {
        let p = CubicParams::default();
        let truth = peak_velocity(&p).unwrap();
        assert!((truth - 1.8).abs() < 1e-12, "{truth}");
        assert!(check("cubic-peak-velocity", &p, Answer::Number(1.75)).right());
        // The mean speed Δ / T is not the peak.
        assert!(!check("cubic-peak-velocity", &p, Answer::Number(1.2)).right());
    }

    #[test]
    fn cubic_speed_limit_needs_a_longer_move() {
        let p = CubicParams::default();
        assert!(!check("cubic-speed-limit", &p, Answer::PageState).right());
        let slow = CubicParams {
            duration_s: 1.8,
            ..p
        };
        assert!((peak_velocity(&slow).unwrap() - 1.0).abs() < 1e-12);
        assert_eq!(
            check("cubic-speed-limit", &slow, Answer::PageState),
            Verdict::Goal { met: true }
        );
        assert!(!within_speed_limit(&CubicParams {
            duration_s: 1.7,
            ..p
        })
        .unwrap());
        // A shorter move is not the exercise.
        let shorter = CubicParams { q1: 0.6, ..p };
        assert!(peak_velocity(&shorter).unwrap() <= 1.0);
        assert!(!within_speed_limit(&shorter).unwrap());
    }

    #[test]
    fn cubic_peak_accel_is_at_both_ends() {
        let p = CubicParams::default();
        let path = compute(&p).unwrap();
        let r = readouts(&p, &path.samples);
        let peak = r.peak_acceleration.unwrap();
        assert!(
            peak.t == 0.0 && (peak.value - 7.2).abs() < 1e-12,
            "{peak:?}"
        );
        let last = path.samples.last().unwrap();
        assert!((last.t - 1.0).abs() < 1e-12 && (last.qdd + 7.2).abs() < 1e-9);
        let middle = path
            .samples
            .iter()
            .find(|s| (s.t - 0.5).abs() < 1e-9)
            .unwrap();
        assert!(middle.qdd.abs() < 1e-12);
        assert!(check("cubic-peak-accel", &p, Answer::Choice(1)).right());
        for wrong in [0, 2, 3] {
            assert!(!check("cubic-peak-accel", &p, Answer::Choice(wrong)).right());
        }
    }
}
