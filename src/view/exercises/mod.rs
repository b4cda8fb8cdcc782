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

/// The file of the exercises' messages and of a page's exercises section:
/// `locales/<lang>/exercises.ftl`. No page's first load holds it: a page's exercises section
/// fetches it with its code (the progress file's messages are
/// [`crate::view::learner_progress::MESSAGE_FILE`]'s).
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

/// The ids of `list`, in order (evaluated when the crate is compiled: the table built from
/// them holds no check).
const fn ids<const N: usize>(list: [Exercise; N]) -> [&'static str; N] {
    let mut out = [""; N];
    let mut i = 0;
    while i < N {
        out[i] = list[i].id;
        i += 1;
    }
    out
}

const IK2R_IDS: [&str; ik2r::EXERCISES.len()] = ids(ik2r::EXERCISES);
const DH_FK_IDS: [&str; dh_fk::EXERCISES.len()] = ids(dh_fk::EXERCISES);
const SE3_IDS: [&str; se3_relative::EXERCISES.len()] = ids(se3_relative::EXERCISES);
const UMEYAMA_IDS: [&str; umeyama_2d::EXERCISES.len()] = ids(umeyama_2d::EXERCISES);
const PENDULUM_IDS: [&str; pendulum::EXERCISES.len()] = ids(pendulum::EXERCISES);
const PID_IDS: [&str; pid_step::EXERCISES.len()] = ids(pid_step::EXERCISES);
const CUBIC_IDS: [&str; cubic_path::EXERCISES.len()] = ids(cubic_path::EXERCISES);
const TRAP_IDS: [&str; trapezoid_profile::EXERCISES.len()] = ids(trapezoid_profile::EXERCISES);
const TRAJ_IDS: [&str; traj_resample::EXERCISES.len()] = ids(traj_resample::EXERCISES);
const RRT_IDS: [&str; rrt::EXERCISES.len()] = ids(rrt::EXERCISES);
const TELEOP_IDS: [&str; teleop::EXERCISES.len()] = ids(teleop::EXERCISES);
const SO101_IDS: [&str; so101::EXERCISES.len()] = ids(so101::EXERCISES);

/// Each page's route id and its exercises' ids in the order it lists them, without their
/// checks: for code that counts progress and must not hold every kernel (the home page's
/// tiles, the class table's columns).
pub const PAGE_IDS: [(&str, &[&str]); 12] = [
    (ik2r::PAGE, &IK2R_IDS),
    (dh_fk::PAGE, &DH_FK_IDS),
    (se3_relative::PAGE, &SE3_IDS),
    (umeyama_2d::PAGE, &UMEYAMA_IDS),
    (pendulum::PAGE, &PENDULUM_IDS),
    (pid_step::PAGE, &PID_IDS),
    (cubic_path::PAGE, &CUBIC_IDS),
    (trapezoid_profile::PAGE, &TRAP_IDS),
    (traj_resample::PAGE, &TRAJ_IDS),
    (rrt::PAGE, &RRT_IDS),
    (teleop::PAGE, &TELEOP_IDS),
    (so101::PAGE, &SO101_IDS),
];

/// The exercise ids of page `page` ([`PAGE_IDS`]; none for a page without exercises).
pub fn ids_of_page(page: &str) -> &'static [&'static str] {
    PAGE_IDS
        .iter()
        .find(|(p, _)| *p == page)
        .map_or(&[], |(_, ids)| ids)
}

/// Every exercise id in catalog order ([`PAGE_IDS`], without the checks).
pub fn all_ids() -> impl Iterator<Item = &'static str> {
    PAGE_IDS.iter().flat_map(|(_, ids)| ids.iter().copied())
}

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
