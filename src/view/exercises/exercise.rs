//! What one exercise is: its kind and tolerance, the page model its check reads, the
//! learner's answer, the verdict and why a check can fail. The pages' exercises
//! (`super::ik2r::EXERCISES`...) are built from these; [`super::catalog`] lists them all.

use crate::error::RecipeError;
use crate::recipes::cubic_path::CubicParams;
use crate::recipes::dh_fk::DhParams;
use crate::recipes::pendulum_energy::PendulumParams;
use crate::recipes::pid_step::PidParams;
use crate::recipes::rrt_2d::RrtSetup;
use crate::recipes::se3_relative::Se3Params;
use crate::recipes::traj_resample::Trajectory;
use crate::recipes::trapezoid_profile::TrapParams;
use crate::recipes::umeyama_2d::UmeyamaSetup;
use crate::teleop::ArmParams;

/// How far a prediction may be from the truth and still be right (bounds included).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Tolerance {
    /// `|prediction − truth| ≤ r · |truth|` (`0.25`: within 25 %).
    Relative(f64),
    /// `|prediction − truth| ≤ a`, in the exercise's unit.
    Absolute(f64),
}

impl Tolerance {
    /// Whether `prediction` is within this tolerance of `truth` (never for a value that is
    /// not finite).
    pub fn accepts(self, prediction: f64, truth: f64) -> bool {
        if !prediction.is_finite() || !truth.is_finite() {
            return false;
        }
        let off = (prediction - truth).abs();
        match self {
            Tolerance::Relative(r) => off <= r * truth.abs(),
            Tolerance::Absolute(a) => off <= a,
        }
    }
}

/// What an exercise asks for.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Kind {
    /// A number in `unit` (as the page writes it: `%`, `s`, `m²`, `deg`, `m/s`; empty for a
    /// pure number), right within `tolerance`.
    Predict {
        unit: &'static str,
        tolerance: Tolerance,
    },
    /// A condition on the page's state.
    Goal,
    /// One of `choices` answers; `right` counts from 0.
    Choose { choices: usize, right: usize },
}

/// The page's state a check reads: each page's own view model or kernel parameters.
#[derive(Debug, Clone, Copy)]
pub enum PageModel<'a> {
    /// `#/ik-2r`: the arm, its pose and the recipes' parameters.
    Ik2r(&'a crate::view::ik2r::State),
    /// `#/pendulum-energy`: the recipe's parameters as the page's form holds them.
    Pendulum(&'a PendulumParams),
    /// `#/pid-step`: gains, plant and run length.
    PidStep(&'a PidParams),
    /// `#/trapezoid-profile`: the move and its sampling.
    Trapezoid(&'a TrapParams),
    /// `#/rrt-2d`: the run's parameters and world (`PageState::setup`).
    Rrt(&'a RrtSetup),
    /// `#/cubic-path`: the move and its sampling.
    CubicPath(&'a CubicParams),
    /// `#/dh-fk`: the demo chain's joint angles.
    DhFk(&'a DhParams),
    /// `#/se3-relative`: the two poses.
    Se3(&'a Se3Params),
    /// `#/umeyama-2d`: the run's arguments, true similarity and points.
    Umeyama(&'a UmeyamaSetup),
    /// `#/traj-resample`: the trajectory read (the sample or the opened file) and the step
    /// `dt`, s.
    TrajResample(&'a Trajectory, f64),
    /// `#/teleop`: the Robot Pilot's arm and its joint angles, rad.
    Teleop { arm: &'a ArmParams, q: [f64; 3] },
    /// `#/so101`: the SO-101's five joint angles, rad.
    So101 { q: [f64; 5] },
}

impl PageModel<'_> {
    /// The route id of the page this model belongs to.
    pub fn page(&self) -> &'static str {
        match self {
            PageModel::Ik2r(_) => "ik-2r",
            PageModel::Pendulum(_) => "pendulum-energy",
            PageModel::PidStep(_) => "pid-step",
            PageModel::Trapezoid(_) => "trapezoid-profile",
            PageModel::Rrt(_) => "rrt-2d",
            PageModel::CubicPath(_) => "cubic-path",
            PageModel::DhFk(_) => "dh-fk",
            PageModel::Se3(_) => "se3-relative",
            PageModel::Umeyama(_) => "umeyama-2d",
            PageModel::TrajResample(..) => "traj-resample",
            PageModel::Teleop { .. } => "teleop",
            PageModel::So101 { .. } => "so101",
        }
    }
}

/// The learner's answer.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Answer {
    /// A prediction, in the exercise's unit.
    Number(f64),
    /// A choice, counting from 0.
    Choice(usize),
    /// A goal's answer is the page's state itself.
    PageState,
}

/// The outcome of a check.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Verdict {
    /// A prediction and the truth it is measured against.
    Predicted { right: bool, truth: f64 },
    /// Whether the goal is met.
    Goal { met: bool },
    /// Whether the choice is the right one.
    Chose { right: bool },
}

impl Verdict {
    /// Right, met: the exercise is done.
    pub fn right(&self) -> bool {
        match *self {
            Verdict::Predicted { right, .. } | Verdict::Chose { right } => right,
            Verdict::Goal { met } => met,
        }
    }
}

/// Why an exercise could not be checked.
#[derive(Debug, Clone, PartialEq)]
pub enum CheckError {
    /// The model is another page's.
    OtherPage {
        exercise: &'static str,
        page: &'static str,
    },
    /// The answer is not of the exercise's kind (a choice for a prediction...).
    AnswerDoesNotFit { exercise: &'static str },
    /// A choice beyond the exercise's choices.
    NoSuchChoice { choice: usize, choices: usize },
    /// The kernel refuses the page's state.
    Kernel(RecipeError),
    /// The page's run has no such number (the goal not reached, no full swing yet).
    NoTruth { exercise: &'static str },
}

impl From<RecipeError> for CheckError {
    fn from(e: RecipeError) -> Self {
        CheckError::Kernel(e)
    }
}

/// An exercise's check: the truth of a prediction, or whether a goal is met, from the model.
#[derive(Clone, Copy)]
enum Check {
    Truth(fn(&PageModel) -> Result<f64, CheckError>),
    Met(fn(&PageModel) -> Result<bool, CheckError>),
    Choice,
}

/// One exercise.
#[derive(Clone, Copy)]
pub struct Exercise {
    /// Kebab-case, unique, stable (progress files store it).
    pub id: &'static str,
    /// The route id of its page (`ik-2r`, `pid-step`...).
    pub page: &'static str,
    pub kind: Kind,
    check: Check,
}

impl std::fmt::Debug for Exercise {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Exercise")
            .field("id", &self.id)
            .field("page", &self.page)
            .field("kind", &self.kind)
            .finish_non_exhaustive()
    }
}

impl Exercise {
    pub(super) const fn predict(
        id: &'static str,
        page: &'static str,
        unit: &'static str,
        tolerance: Tolerance,
        truth: fn(&PageModel) -> Result<f64, CheckError>,
    ) -> Exercise {
        Exercise {
            id,
            page,
            kind: Kind::Predict { unit, tolerance },
            check: Check::Truth(truth),
        }
    }

    pub(super) const fn goal(
        id: &'static str,
        page: &'static str,
        met: fn(&PageModel) -> Result<bool, CheckError>,
    ) -> Exercise {
        Exercise {
            id,
            page,
            kind: Kind::Goal,
            check: Check::Met(met),
        }
    }

    pub(super) const fn choose(
        id: &'static str,
        page: &'static str,
        choices: usize,
        right: usize,
    ) -> Exercise {
        Exercise {
            id,
            page,
            kind: Kind::Choose { choices, right },
            check: Check::Choice,
        }
    }

    /// Fluent id of the prompt.
    pub fn prompt_id(&self) -> String {
        format!("ex-{}-prompt", self.id)
    }

    /// Fluent id of the hint (shown after a wrong try).
    pub fn hint_id(&self) -> String {
        format!("ex-{}-hint", self.id)
    }

    /// Fluent id of the explanation shown with the answer.
    pub fn explain_id(&self) -> String {
        format!("ex-{}-explain", self.id)
    }

    /// Fluent ids of each choice's text and of why it is right or wrong (`n` from 1); none
    /// for the other kinds.
    pub fn choice_ids(&self) -> Vec<(String, String)> {
        match self.kind {
            Kind::Choose { choices, .. } => (1..=choices)
                .map(|n| {
                    (
                        format!("ex-{}-choice-{n}", self.id),
                        format!("ex-{}-why-{n}", self.id),
                    )
                })
                .collect(),
            _ => Vec::new(),
        }
    }

    /// Every Fluent id the exercise uses.
    pub fn message_ids(&self) -> Vec<String> {
        let mut ids = vec![self.prompt_id(), self.hint_id(), self.explain_id()];
        for (choice, why) in self.choice_ids() {
            ids.push(choice);
            ids.push(why);
        }
        ids
    }

    /// The truth of a prediction for the page's state (what the reveal shows); `None` for
    /// the other kinds.
    pub fn truth(&self, model: &PageModel) -> Option<Result<f64, CheckError>> {
        match self.check {
            Check::Truth(truth) => Some(self.on_page(model).and_then(|()| truth(model))),
            _ => None,
        }
    }

    /// Checks `answer` against the page's state.
    pub fn check(&self, model: &PageModel, answer: Answer) -> Result<Verdict, CheckError> {
        self.on_page(model)?;
        let misfit = CheckError::AnswerDoesNotFit { exercise: self.id };
        match (self.kind, self.check, answer) {
            (Kind::Predict { tolerance, .. }, Check::Truth(truth), Answer::Number(p)) => {
                let truth = truth(model)?;
                Ok(Verdict::Predicted {
                    right: tolerance.accepts(p, truth),
                    truth,
                })
            }
            (Kind::Goal, Check::Met(met), Answer::PageState) => {
                Ok(Verdict::Goal { met: met(model)? })
            }
            (Kind::Choose { choices, right }, Check::Choice, Answer::Choice(choice)) => {
                if choice >= choices {
                    return Err(CheckError::NoSuchChoice { choice, choices });
                }
                Ok(Verdict::Chose {
                    right: choice == right,
                })
            }
            _ => Err(misfit),
        }
    }

    fn on_page(&self, model: &PageModel) -> Result<(), CheckError> {
        if model.page() == self.page {
            Ok(())
        } else {
            Err(CheckError::OtherPage {
                exercise: self.id,
                page: model.page(),
            })
        }
    }
}

/// The model `model` as the page a check function belongs to; any other is a bug of the
/// catalog (an exercise listed under the wrong page), reported as [`CheckError::OtherPage`].
macro_rules! model_of {
    ($model:expr, $variant:ident, $id:expr) => {
        match $model {
            $crate::view::exercises::exercise::PageModel::$variant(m) => *m,
            other => {
                return Err($crate::view::exercises::exercise::CheckError::OtherPage {
                    exercise: $id,
                    page: other.page(),
                })
            }
        }
    };
}
pub(crate) use model_of;

/// In a page's test module: `check(id, <the argument>, answer)`, the verdict of the page's
/// exercise `id` (`EXERCISES`) on the page model `$model` made of the argument, and `find`.
#[cfg(test)]
macro_rules! page_check {
    (|$arg:ident: $ty:ty| $model:expr) => {
        use crate::view::exercises::exercise::{Answer, Verdict};

        fn find(id: &str) -> Option<&'static Exercise> {
            EXERCISES.iter().find(|e| e.id == id)
        }

        fn check(id: &str, $arg: $ty, answer: Answer) -> Verdict {
            let exercise = find(id).expect("an exercise of the page");
            exercise.check(&$model, answer).unwrap()
        }
    };
}
#[cfg(test)]
pub(crate) use page_check;

/// The exercise modules' test attribute (their tests import it): wasm-bindgen-test's in wasm,
/// the standard one natively.
#[cfg(test)]
pub(crate) mod test_attribute {
    #[cfg(not(target_family = "wasm"))]
    pub(crate) use core::prelude::v1::test;
    #[cfg(target_family = "wasm")]
    pub(crate) use wasm_bindgen_test::wasm_bindgen_test as test;
}
