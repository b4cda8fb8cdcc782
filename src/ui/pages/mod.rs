//! The page table: every page the shell can route to, in navigation order, each with its place
//! in the navigation. A page's code is reached only through its line here; the shell lends the
//! table to the pages that list others ([`crate::ui::page::ShellLink`]). Which recipe runs on
//! which page is a recipe fact (`RecipeInfo::page`); every recipe also runs on the drills page
//! (`#/drills?recipe=<id>`).

use crate::ui::kit::signal_page::Signal;
use crate::ui::page::{page, Nav, PageDef};
use crate::ui::router::{DRILLS_ID, HOME_ID};

mod cubic_path;
mod dh_fk;
mod drills;
mod home;
mod home_arm;
mod home_cards;
mod home_picture;
mod ik2r;
mod lesson;
mod pendulum;
mod pid_step;
mod rrt;
mod se3;
mod so101;
mod teleop;
mod traj_resample;
mod trapezoid_profile;
mod umeyama;

/// All pages, in navigation order (the Drills menu lists its groups' pages in this order), each
/// with the wasm chunk its code is split into.
#[rustfmt::skip]
pub const PAGES: &[PageDef] = &[
    page!(home_page, home::HomePage, HOME_ID, "home-page-title", "home-intro", Nav::Top, ["home.ftl", "recipes.ftl"]),
    page!(ik2r_page, ik2r::Ik2rPage, "ik-2r", "ik2r-title", "ik2r-blurb", Nav::Kinematics, ["ik2r.ftl", "recipes.ftl"]),
    page!(dh_fk_page, dh_fk::DhPage, "dh-fk", "dh-title", "dh-blurb", Nav::Kinematics, ["dh.ftl", "recipes.ftl"]),
    page!(se3_page, se3::Se3Page, "se3-relative", "se3-title", "se3-blurb", Nav::Kinematics, ["se3.ftl", "recipes.ftl"]),
    page!(umeyama_page, umeyama::UmeyamaPage, "umeyama-2d", "umeyama-title", "umeyama-blurb", Nav::Kinematics, ["umeyama.ftl", "recipes.ftl"]),
    page!(pendulum_page, pendulum::PendulumPage, "pendulum-energy", "pendulum-title", "pendulum-blurb", Nav::Dynamics, ["pendulum.ftl", "recipes.ftl"]),
    page!(pid_step_page, Signal<pid_step::PidPage>, "pid-step", "pid-title", "pid-blurb", Nav::Dynamics, ["signals.ftl", "recipes.ftl"]),
    page!(cubic_path_page, Signal<cubic_path::CubicPage>, "cubic-path", "cubic-title", "cubic-blurb", Nav::Trajectories, ["signals.ftl", "recipes.ftl"]),
    page!(trapezoid_profile_page, Signal<trapezoid_profile::TrapPage>, "trapezoid-profile", "trap-title", "trap-blurb", Nav::Trajectories, ["signals.ftl", "recipes.ftl"]),
    page!(traj_resample_page, traj_resample::TrajResample, "traj-resample", "traj-title", "traj-blurb", Nav::Trajectories, ["traj.ftl", "recipes.ftl"]),
    page!(rrt_page, rrt::RrtPage, "rrt-2d", "rrt-title", "rrt-blurb", Nav::Planning, ["rrt.ftl", "drills.ftl", "recipes.ftl"]),
    page!(teleop_page, teleop::TeleopPage, "teleop", "teleop-nav", "teleop-blurb", Nav::Top, ["teleop.ftl"]),
    page!(so101_page, so101::So101Page, "so101", "so101-nav", "so101-blurb", Nav::Top, ["so101.ftl", "teleop.ftl"]),
    page!(drills_page, drills::DrillsPage, DRILLS_ID, "drills-title", "drills-blurb", Nav::Top, ["drills.ftl", "traj.ftl", "recipes.ftl"]),
    page!(lesson_page, lesson::LessonPage, "lesson", "lesson-title", "lesson-blurb", Nav::Top, ["lesson.ftl", "recipes.ftl"]),
];
