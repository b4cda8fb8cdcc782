//! The PID page's exercises (`#/pid-step`): tune the gains for a fast, clean step on the
//! recipe's plant, predict where the run ends, where P alone settles, and predict the
//! overshoot of the page's gains. Every figure is the page's own
//! ([`crate::view::pid_step::figures`]: overshoot in %, settling in the 2 % band).

use super::exercise::{model_of, CheckError, Exercise, PageModel, Tolerance};
use crate::recipes::pid_step::{simulate, PidParams};
use crate::view::pid_step::{figures, StepFigures};

/// The page's route id.
pub const PAGE: &str = "pid-step";

/// `pid-tune`: the overshoot must stay below this, %.
pub const TUNE_OVERSHOOT_PCT: f64 = 5.0;
/// `pid-tune`: the 2 % settling time must be below this, s.
pub const TUNE_SETTLING_S: f64 = 1.5;

/// The page's exercises, in the order it lists them.
#[rustfmt::skip]
pub const EXERCISES: [Exercise; 4] = [
    Exercise::goal("pid-tune", PAGE, tune_met),
    Exercise::predict("pid-final-y", PAGE, "", Tolerance::Absolute(0.05), final_y_truth),
    // 1: below r, at Kp / (1 + Kp) of it.
    Exercise::choose("pid-p-only", PAGE, 4, 1),
    Exercise::predict("pid-overshoot", PAGE, "%", Tolerance::Absolute(3.0), overshoot_truth),
];

/// The page's figures of the run of `p`.
pub fn step_figures(p: &PidParams) -> Result<StepFigures, CheckError> {
    Ok(figures(&simulate(p)?))
}

/// `pid-tune`: on the recipe's plant (`tau` as [`PidParams::default`], 0.8 s: the gains are
/// the learner's to choose, not the plant) and a run at least as long as the recipe's (80
/// steps, 4 s, so a settled response has stayed settled), the overshoot is below
/// [`TUNE_OVERSHOOT_PCT`] and the response settles in the 2 % band before
/// [`TUNE_SETTLING_S`].
pub fn tuned(p: &PidParams) -> Result<bool, CheckError> {
    let recipe = PidParams::default();
    if p.tau != recipe.tau || p.steps < recipe.steps {
        return Ok(false);
    }
    let f = step_figures(p)?;
    Ok(f.overshoot_pct.is_some_and(|o| o < TUNE_OVERSHOOT_PCT)
        && f.settling_time.is_some_and(|t| t < TUNE_SETTLING_S))
}

fn tune_met(model: &PageModel) -> Result<bool, CheckError> {
    tuned(model_of!(model, PidStep, "pid-tune"))
}

/// `pid-final-y`: y of the run's last row (the page's `final_y`); no truth for an empty or
/// diverged run.
pub fn final_y(p: &PidParams) -> Result<f64, CheckError> {
    step_figures(p)?.final_y.ok_or(CheckError::NoTruth {
        exercise: "pid-final-y",
    })
}

fn final_y_truth(model: &PageModel) -> Result<f64, CheckError> {
    final_y(model_of!(model, PidStep, "pid-final-y"))
}

/// `pid-overshoot`: the page's overshoot figure, % (0 when y stays below r).
pub fn overshoot_pct(p: &PidParams) -> Result<f64, CheckError> {
    step_figures(p)?.overshoot_pct.ok_or(CheckError::NoTruth {
        exercise: "pid-overshoot",
    })
}

fn overshoot_truth(model: &PageModel) -> Result<f64, CheckError> {
    overshoot_pct(model_of!(model, PidStep, "pid-overshoot"))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::view::exercises::exercise::test_attribute::test;
    use crate::view::pid_step::TUNED_GAINS;
    crate::view::exercises::exercise::page_check!(|p: &PidParams| PageModel::PidStep(p));

    fn gains(kp: f64, ki: f64, kd: f64) -> PidParams {
        PidParams {
            kp,
            ki,
            kd,
            ..PidParams::default()
        }
    }

    #[test]
    fn pid_tune_is_met_by_the_tuned_gains_not_the_recipes() {
        let [(_, kp), (_, ki), (_, kd)] = TUNED_GAINS;
        let tuned_gains = gains(
            kp.parse().unwrap(),
            ki.parse().unwrap(),
            kd.parse().unwrap(),
        );
        let f = step_figures(&tuned_gains).unwrap();
        assert!(
            f.overshoot_pct.unwrap() < 5.0 && f.settling_time.unwrap() < 1.5,
            "{f:?}"
        );
        assert_eq!(
            check("pid-tune", &tuned_gains, Answer::PageState),
            Verdict::Goal { met: true }
        );
        // The recipe's gains have not settled within the run.
        let recipe = PidParams::default();
        assert_eq!(step_figures(&recipe).unwrap().settling_time, None);
        assert!(!check("pid-tune", &recipe, Answer::PageState).right());
        // Without the derivative, Kp 4, Ki 8 just makes it (4.9 %, 1.35 s)...
        let pi_only = gains(4.0, 8.0, 0.0);
        assert!(tuned(&pi_only).unwrap());
        // ...and Kp 3, Ki 10 overshoots.
        let hot = gains(3.0, 10.0, 0.0);
        let f = step_figures(&hot).unwrap();
        assert!(f.overshoot_pct.unwrap() >= 5.0, "{f:?}");
        assert!(!check("pid-tune", &hot, Answer::PageState).right());
        // The plant is not the learner's to change, nor the run to cut short.
        let quick_plant = PidParams {
            tau: 0.1,
            ..tuned_gains
        };
        assert!(!tuned(&quick_plant).unwrap());
        let short = PidParams {
            steps: 30,
            ..tuned_gains
        };
        assert!(!tuned(&short).unwrap());
    }

    #[test]
    fn pid_final_y_is_the_last_row() {
        let recipe = PidParams::default();
        let truth = final_y(&recipe).unwrap();
        // The recipe prints final_y=0.7967.
        assert!((truth - 0.7967).abs() < 5e-5, "{truth}");
        assert!(check("pid-final-y", &recipe, Answer::Number(0.76)).right());
        // "It reaches the setpoint" is wrong within this run.
        assert!(!check("pid-final-y", &recipe, Answer::Number(1.0)).right());
        let empty = PidParams { steps: 0, ..recipe };
        assert!(matches!(
            find("pid-final-y")
                .unwrap()
                .check(&PageModel::PidStep(&empty), Answer::Number(0.0)),
            Err(CheckError::NoTruth { .. })
        ));
    }

    #[test]
    fn pid_p_only_settles_below_the_setpoint() {
        // P alone (and the derivative, which vanishes at rest): y → Kp / (1 + Kp).
        let p_only = PidParams {
            ki: 0.0,
            steps: 2000,
            ..PidParams::default()
        };
        let y = final_y(&p_only).unwrap();
        assert!((y - 1.2 / 2.2).abs() < 1e-9, "{y}");
        assert!(check("pid-p-only", &p_only, Answer::Choice(1)).right());
        for wrong in [0, 2, 3] {
            assert!(!check("pid-p-only", &p_only, Answer::Choice(wrong)).right());
        }
    }

    #[test]
    fn pid_overshoot_is_the_pages_figure() {
        let hot = gains(3.0, 10.0, 0.0);
        let truth = overshoot_pct(&hot).unwrap();
        assert!((truth - 12.88).abs() < 0.01, "{truth}");
        assert!(check("pid-overshoot", &hot, Answer::Number(truth - 2.5)).right());
        assert!(!check("pid-overshoot", &hot, Answer::Number(0.0)).right());
        // The recipe's gains never pass r.
        assert_eq!(overshoot_pct(&PidParams::default()).unwrap(), 0.0);
    }
}
