//! The exercises of the drill and pilot pages: what each asks (its kind, its page, the ids of
//! its messages) and its check, a pure function of the page's view model and the kernels'
//! outputs (never of text on the page). [`exercise`] holds what an exercise is made of; one
//! file per page holds that page's exercises and checks; this module lists them all
//! ([`catalog`]).
//!
//! Three kinds:
//! - **predict**: the learner commits a number in the exercise's unit; it is right when it lies
//!   within the exercise's [`Tolerance`] of the truth the kernel computes for the page's state;
//! - **goal**: a condition on the page's live state, met by using the page;
//! - **choose**: one of `n` choices is right (the tests confirm each right choice against the
//!   kernels).
//!
//! Messages (Fluent ids, `ex-<id>-…`): `ex-<id>-prompt`, `ex-<id>-hint`, `ex-<id>-explain`;
//! a choice exercise also has `ex-<id>-choice-<n>` and `ex-<id>-why-<n>` for `n` from 1 (why
//! that choice is right or wrong).
//!
//! A check gets the page's model ([`PageModel`]) and the learner's [`Answer`] and returns a
//! [`Verdict`] (with the truth beside a prediction), or a [`CheckError`] when the model is
//! another page's, the answer does not fit the exercise, or the kernel refuses the state (the
//! page shows a goal whose check fails as not met).
//!
//! A goal is met by the state the page shows, however it got there (a teacher's link may set
//! it up); recording it done is the page's part ([`crate::view::learner_progress`]), when the
//! learner uses the page.

pub mod cubic_path;
pub mod dh_fk;
pub mod exercise;
pub mod ik2r;
pub mod pendulum;
pub mod pid_step;
pub mod rrt;
pub mod se3_relative;
pub mod so101;
pub mod teleop;
pub mod traj_resample;
pub mod trapezoid_profile;
pub mod umeyama_2d;

pub use exercise::{Answer, CheckError, Exercise, Kind, PageModel, Tolerance, Verdict};

/// The file of the exercises' messages (and of the progress file's and the class summary's):
/// `locales/<lang>/exercises.ftl`. The app's bundles do not hold it yet
/// ([`crate::i18n::FILE_NAMES`]); the pages that show exercises add it.
pub const MESSAGE_FILE: &str = "exercises.ftl";

/// [`MESSAGE_FILE`] of both languages, for the tests.
#[cfg(test)]
pub(crate) const MESSAGE_SOURCES: [(crate::i18n::Lang, &str, &str); 2] = [
    (
        crate::i18n::Lang::En,
        MESSAGE_FILE,
        include_str!("../../../locales/en/exercises.ftl"),
    ),
    (
        crate::i18n::Lang::Ja,
        MESSAGE_FILE,
        include_str!("../../../locales/ja/exercises.ftl"),
    ),
];

/// Every page's exercises, page by page.
const PAGES: [&[Exercise]; 12] = [
    &ik2r::EXERCISES,
    &dh_fk::EXERCISES,
    &se3_relative::EXERCISES,
    &umeyama_2d::EXERCISES,
    &pendulum::EXERCISES,
    &pid_step::EXERCISES,
    &cubic_path::EXERCISES,
    &trapezoid_profile::EXERCISES,
    &traj_resample::EXERCISES,
    &rrt::EXERCISES,
    &teleop::EXERCISES,
    &so101::EXERCISES,
];

/// Every exercise, page by page in the order each page lists them.
pub fn catalog() -> impl Iterator<Item = &'static Exercise> {
    PAGES.iter().flat_map(|page| page.iter())
}

/// The exercise with this id.
pub fn find(id: &str) -> Option<&'static Exercise> {
    catalog().find(|e| e.id == id)
}

/// The exercises of page `page` (a route id), in order.
pub fn of_page(page: &str) -> impl Iterator<Item = &'static Exercise> + '_ {
    catalog().filter(move |e| e.page == page)
}

#[cfg(test)]
mod tests;
