//! The Umeyama page's exercises (`#/umeyama-2d`): predict the estimated rotation, make the fit
//! exact, and what the fit does with mirrored targets. The fit is the page's
//! ([`Scene::fit`], the kernel's estimate from the run's points).

use super::exercise::{model_of, CheckError, Exercise, PageModel, Tolerance};
use crate::recipes::umeyama_2d::{Alignment, UmeyamaSetup};
use crate::view::umeyama_2d::Scene;

/// The page's route id.
pub const PAGE: &str = "umeyama-2d";

/// `umeyama-exact`: the fit's RMSE must be below this (rounding only).
pub const EXACT_RMSE: f64 = 1e-9;

/// The page's exercises, in the order it lists them.
#[rustfmt::skip]
pub const EXERCISES: [Exercise; 3] = [
    Exercise::predict("umeyama-angle", PAGE, "deg", Tolerance::Absolute(2.0), angle_truth),
    Exercise::goal("umeyama-exact", PAGE, exact_met),
    // 1: the best rotation, with a large error.
    Exercise::choose("umeyama-mirror", PAGE, 4, 1),
];

/// The fit of the page's run.
pub fn fit(setup: &UmeyamaSetup) -> Result<Alignment, CheckError> {
    setup.validate()?;
    Scene::new(setup)
        .map(|scene| scene.fit())
        .ok_or(CheckError::NoTruth {
            exercise: "umeyama-angle",
        })
}

/// `umeyama-angle`: the estimated rotation, degrees.
pub fn estimated_angle_deg(setup: &UmeyamaSetup) -> Result<f64, CheckError> {
    Ok(fit(setup)?.rotation_deg)
}

fn angle_truth(model: &PageModel) -> Result<f64, CheckError> {
    estimated_angle_deg(model_of!(model, Umeyama, "umeyama-angle"))
}

/// `umeyama-exact`: the fit's RMSE is below [`EXACT_RMSE`].
pub fn exact_fit(setup: &UmeyamaSetup) -> Result<bool, CheckError> {
    Ok(fit(setup)?.rmse < EXACT_RMSE)
}

fn exact_met(model: &PageModel) -> Result<bool, CheckError> {
    exact_fit(model_of!(model, Umeyama, "umeyama-exact"))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::recipes::umeyama_2d::UmeyamaParams;
    use crate::view::exercises::exercise::test_attribute::test;
    crate::view::exercises::exercise::page_check!(|setup: &UmeyamaSetup| PageModel::Umeyama(setup));

    fn noise(sigma: f64) -> UmeyamaSetup {
        UmeyamaSetup::recipe(UmeyamaParams {
            sigma,
            ..UmeyamaParams::default()
        })
    }

    #[test]
    fn umeyama_angle_is_near_the_true_35_degrees() {
        let setup = UmeyamaSetup::default();
        let truth = estimated_angle_deg(&setup).unwrap();
        assert!((truth - 35.0).abs() < 1.0, "{truth}");
        assert!(check("umeyama-angle", &setup, Answer::Number(35.0)).right());
        // The angle of the translation (−0.2, 0.4 → −26.6°) is not the rotation.
        assert!(!check("umeyama-angle", &setup, Answer::Number(-26.6)).right());
        // Large noise moves the estimate.
        let noisy = noise(0.5);
        let noisy_truth = estimated_angle_deg(&noisy).unwrap();
        assert!((noisy_truth - 35.0).abs() > 2.0, "{noisy_truth}");
        assert!(!check("umeyama-angle", &noisy, Answer::Number(35.0)).right());
    }

    #[test]
    fn umeyama_exact_needs_no_noise() {
        assert!(!check("umeyama-exact", &UmeyamaSetup::default(), Answer::PageState).right());
        let clean = noise(0.0);
        assert_eq!(
            check("umeyama-exact", &clean, Answer::PageState),
            Verdict::Goal { met: true }
        );
        // Mirrored targets cannot be fitted by a rotation, even without noise.
        let mut mirrored = clean.clone();
        mirrored.truth.mirror = true;
        assert!(!exact_fit(&mirrored).unwrap());
        let bad = noise(-1.0);
        assert!(matches!(
            find("umeyama-exact")
                .unwrap()
                .check(&PageModel::Umeyama(&bad), Answer::PageState),
            Err(CheckError::Kernel(_))
        ));
    }

    #[test]
    fn umeyama_mirror_keeps_a_rotation() {
        let mut mirrored = noise(0.0);
        mirrored.truth.mirror = true;
        mirrored.validate().unwrap();
        let scene = Scene::new(&mirrored).unwrap();
        let f = scene.fit();
        // A proper rotation with a positive scale, the reflection fixed, a large error.
        assert!(scene.steps.reflection_fixed());
        assert!(f.scale > 0.0 && f.rmse > 0.5, "{f:?}");
        let setup = UmeyamaSetup::default();
        assert!(check("umeyama-mirror", &setup, Answer::Choice(1)).right());
        for wrong in [0, 2, 3] {
            assert!(!check("umeyama-mirror", &setup, Answer::Choice(wrong)).right());
        }
    }
}
