//! The pendulum page's exercises (`#/pendulum-energy`): Euler's energy drift at the page's
//! step, the period of the large swing, which integrator keeps the energy, and a step large
//! enough for Euler to swing the pendulum over the top.
//!
//! The relative energy drift over a run is the page's energy error at its end (see
//! [`crate::view::pendulum`]): `e(T) = (E(T) + W(T) − E(0)) / E(0)`, the capsule's true
//! energy plus the work the damper took out, against the start, here in % of `E(0)`.

use super::exercise::{model_of, CheckError, Exercise, PageModel, Tolerance};
use crate::recipes::pendulum_energy::{simulate, Integrator, PendulumParams};
use crate::view::pendulum::Track;

/// The page's route id.
pub const PAGE: &str = "pendulum-energy";

/// The page's exercises, in the order it lists them.
#[rustfmt::skip]
pub const EXERCISES: [Exercise; 4] = [
    Exercise::predict("pendulum-euler-dt", PAGE, "%", Tolerance::Relative(0.25), euler_drift_truth),
    Exercise::predict("pendulum-period", PAGE, "s", Tolerance::Relative(0.1), period_truth),
    // 1: RK4.
    Exercise::choose("pendulum-integrator", PAGE, 3, 1),
    Exercise::goal("pendulum-over-top", PAGE, over_top_met),
];

/// The run of `params` to its end: the track and its number of steps.
fn full_run(params: &PendulumParams) -> Result<(Track, usize), CheckError> {
    let steps = usize::try_from(params.validate()?).unwrap_or(usize::MAX);
    let mut track = Track::new(params)?;
    track.extend_to(steps);
    Ok((track, steps))
}

/// The energy error at the end of the run of `params`, in % of `E(0)`.
pub fn drift_over_run_percent(params: &PendulumParams) -> Result<f64, CheckError> {
    let (track, steps) = full_run(params)?;
    Ok(100.0 * track.energy_error(steps))
}

/// `pendulum-euler-dt`: Euler's relative energy drift over the run at the page's step `h`
/// and duration (the page's other parameters too, whatever integrator it shows), % of `E(0)`.
pub fn euler_drift_percent(params: &PendulumParams) -> Result<f64, CheckError> {
    drift_over_run_percent(&PendulumParams {
        integrator: Integrator::Euler,
        ..*params
    })
}

fn euler_drift_truth(model: &PageModel) -> Result<f64, CheckError> {
    euler_drift_percent(model_of!(model, Pendulum, "pendulum-euler-dt"))
}

/// `pendulum-period`: the page's period estimate at the end of the run (the time between
/// the last zero crossing of θ and the one two before it), s; no truth before two crossings.
pub fn period_s(params: &PendulumParams) -> Result<f64, CheckError> {
    let (track, steps) = full_run(params)?;
    track.period(steps).ok_or(CheckError::NoTruth {
        exercise: "pendulum-period",
    })
}

fn period_truth(model: &PageModel) -> Result<f64, CheckError> {
    period_s(model_of!(model, Pendulum, "pendulum-period"))
}

/// `pendulum-over-top`: starting below the top (`|angle| < 180°`), the page's run passes
/// over it (`|θ| > π` after some step). Damping only takes energy out, so only the
/// integrator's error can do that.
pub fn goes_over_top(params: &PendulumParams) -> Result<bool, CheckError> {
    if params.angle_deg.abs() >= 180.0 {
        return Ok(false);
    }
    let rows = simulate(params)?;
    Ok(rows.iter().any(|r| r.theta.abs() > std::f64::consts::PI))
}

fn over_top_met(model: &PageModel) -> Result<bool, CheckError> {
    goes_over_top(model_of!(model, Pendulum, "pendulum-over-top"))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::view::exercises::exercise::test_attribute::test;
    crate::view::exercises::exercise::page_check!(|params: &PendulumParams| PageModel::Pendulum(
        params
    ));

    #[test]
    fn pendulum_euler_dt_is_within_a_quarter_of_the_kernel_drift() {
        let params = PendulumParams::default();
        let truth = euler_drift_percent(&params).unwrap();
        // The same figure whatever integrator the page shows.
        let rk4 = PendulumParams {
            integrator: Integrator::Rk4,
            ..params
        };
        assert_eq!(euler_drift_percent(&rk4).unwrap(), truth);
        // 0.0015 % of E(0): the energy error after 5 s at h = 0.002 s.
        assert!((truth - 0.0015066).abs() < 1e-7, "{truth}");
        let near = truth * 1.2;
        assert_eq!(
            check("pendulum-euler-dt", &params, Answer::Number(near)),
            Verdict::Predicted { right: true, truth }
        );
        assert!(!check("pendulum-euler-dt", &params, Answer::Number(truth * 1.3)).right());
        assert!(!check("pendulum-euler-dt", &params, Answer::Number(-truth)).right());
        // A ten times larger step drifts far more: the default's truth is no answer there.
        let coarse = PendulumParams {
            timestep_s: 0.02,
            ..params
        };
        let coarse_truth = euler_drift_percent(&coarse).unwrap();
        // About h² times more: 0.14 %.
        assert!((coarse_truth - 0.14177).abs() < 1e-5, "{coarse_truth}");
        assert!(!check("pendulum-euler-dt", &coarse, Answer::Number(truth)).right());
        assert!(check(
            "pendulum-euler-dt",
            &coarse,
            Answer::Number(coarse_truth * 0.8)
        )
        .right());
    }

    #[test]
    fn pendulum_period_is_longer_than_the_small_angle_period() {
        let params = PendulumParams::default();
        let truth = period_s(&params).unwrap();
        let p = Track::new(&params).unwrap();
        let inertia = p.start().joint_inertia();
        let small_angle = 2.0
            * std::f64::consts::PI
            * (inertia / (params.mass_kg * 9.81 * params.length_m / 2.0)).sqrt();
        // 1.124 s against 0.908 s: a 120° swing is slower than a small one.
        assert!((truth - 1.1244).abs() < 1e-4 && (small_angle - 0.9077).abs() < 1e-4);
        assert!(check("pendulum-period", &params, Answer::Number(truth * 1.05)).right());
        assert!(!check("pendulum-period", &params, Answer::Number(small_angle)).right());
        // A run shorter than a half swing has no period.
        let short = PendulumParams {
            duration_s: 0.1,
            ..params
        };
        assert_eq!(
            find("pendulum-period")
                .unwrap()
                .check(&PageModel::Pendulum(&short), Answer::Number(1.0)),
            Err(CheckError::NoTruth {
                exercise: "pendulum-period"
            })
        );
    }

    #[test]
    fn pendulum_integrator_rk4_keeps_the_energy_better() {
        let params = PendulumParams::default();
        let euler = euler_drift_percent(&params).unwrap();
        let rk4 = drift_over_run_percent(&PendulumParams {
            integrator: Integrator::Rk4,
            ..params
        })
        .unwrap();
        // RK4: -8e-8 % against Euler's 1.5e-3 %.
        assert!(rk4.abs() * 10_000.0 < euler.abs(), "{euler} {rk4}");
        assert!(check("pendulum-integrator", &params, Answer::Choice(1)).right());
        assert!(!check("pendulum-integrator", &params, Answer::Choice(0)).right());
        assert!(!check("pendulum-integrator", &params, Answer::Choice(2)).right());
    }

    #[test]
    fn pendulum_over_top_needs_a_large_euler_step() {
        let params = PendulumParams::default();
        assert_eq!(
            check("pendulum-over-top", &params, Answer::PageState),
            Verdict::Goal { met: false }
        );
        // The recipe's damping at h = 0.2 s still loses energy...
        let damped = PendulumParams {
            timestep_s: 0.2,
            ..params
        };
        assert!(!goes_over_top(&damped).unwrap());
        // ...undamped, Euler gains enough to swing over.
        let large = PendulumParams {
            damping: 0.0,
            ..damped
        };
        assert_eq!(
            check("pendulum-over-top", &large, Answer::PageState),
            Verdict::Goal { met: true }
        );
        // RK4 at the same step does not; nor does a start above the top count.
        let rk4 = PendulumParams {
            integrator: Integrator::Rk4,
            ..large
        };
        assert!(!goes_over_top(&rk4).unwrap());
        let from_top = PendulumParams {
            angle_deg: 190.0,
            ..params
        };
        assert!(!goes_over_top(&from_top).unwrap());
    }
}
