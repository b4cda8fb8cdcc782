//! The page table: every page the shell can route to, in navigation order, each with its place
//! in the navigation. A page's code is reached only through its line here; the shell lends the
//! table to the pages that list others ([`crate::ui::page::ShellLink`]). Which recipe runs on
//! which page is a recipe fact (`RecipeInfo::page`); every recipe also runs on the drills page
//! (`#/drills?recipe=<id>`).

use crate::ui::kit::signal_page::Signal;
use crate::ui::page::{page, Nav, PageDef};
use crate::ui::router::{DRILLS_ID, HOME_ID};

mod class;
mod cubic_path;
mod dh_fk;
mod drills;
mod home;
mod home_arm;
mod home_cards;
mod home_picture;
mod home_progress;
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

// Each page's head as its markup opens it (`PageDef::head`): the frame while its code loads.
const HOME_HEAD: &str = "<section class=\"hero\"><div class=\"hero-text\"><h1 class=\"headline\" data-i18n=\"home-headline\"></h1><p class=\"intro\" data-i18n=\"home-intro\"></p></div></section>";
const IK2R_HEAD: &str = "<div class=\"ik2r\"><header class=\"ik2r-head\"><h1 data-i18n=\"ik2r-title\"></h1><p class=\"ik2r-lede\" data-i18n=\"ik2r-lede\"></p></header></div>";
const DH_HEAD: &str = "<div class=\"kit-page dh\"><header class=\"dh-head\"><h1 data-i18n=\"dh-title\"></h1><p class=\"dh-lede\" data-i18n=\"recipe-dh-fk-blurb\"></p></header></div>";
const SE3_HEAD: &str = "<div class=\"kit-page se3\"><header class=\"se3-head\"><h1 data-i18n=\"se3-title\"></h1><p class=\"se3-lede\" data-i18n=\"se3-lede\"></p></header></div>";
const UMEYAMA_HEAD: &str = "<div class=\"sig ume\"><header class=\"sig-head\"><h1 data-i18n=\"umeyama-title\"></h1><p class=\"sig-lede\" data-i18n=\"umeyama-lede\"></p></header></div>";
const PENDULUM_HEAD: &str = "<div class=\"kit-page pend\"><header class=\"pend-head\"><h1 data-i18n=\"pendulum-title\"></h1><p class=\"pend-lede\" data-i18n=\"pendulum-lede\"></p></header></div>";
const PID_HEAD: &str = "<div class=\"sig\"><header class=\"sig-head\"><h1 data-i18n=\"pid-title\"></h1><p class=\"sig-lede\" data-i18n=\"recipe-pid-step-blurb\"></p></header></div>";
const CUBIC_HEAD: &str = "<div class=\"sig\"><header class=\"sig-head\"><h1 data-i18n=\"cubic-title\"></h1><p class=\"sig-lede\" data-i18n=\"recipe-cubic-path-blurb\"></p></header></div>";
const TRAP_HEAD: &str = "<div class=\"sig\"><header class=\"sig-head\"><h1 data-i18n=\"trap-title\"></h1><p class=\"sig-lede\" data-i18n=\"recipe-trapezoid-profile-blurb\"></p></header></div>";
const TRAJ_HEAD: &str = "<div class=\"kit-page traj\"><header class=\"traj-head\"><h1 data-i18n=\"traj-title\"></h1><p class=\"traj-lede\" data-i18n=\"traj-lede\"></p></header></div>";
const RRT_HEAD: &str = "<div class=\"kit-page rrt\"><header class=\"rrt-head\"><h1 data-i18n=\"rrt-title\"></h1><p class=\"rrt-lede\" data-i18n=\"rrt-lede\"></p></header></div>";
const TELEOP_HEAD: &str = "<div class=\"tele\"><header class=\"tele-head\"><h1 data-i18n=\"teleop-title\"></h1><p class=\"tele-task\" data-i18n=\"teleop-head-lede\"></p></header></div>";
const SO101_HEAD: &str = "<div class=\"so101-page\"><h1 data-i18n=\"so101-title\"></h1><p class=\"so101-task\" data-i18n=\"so101-head-lede\"></p></div>";
const DRILLS_HEAD: &str = "<div class=\"drills\"><header class=\"drills-head\"><h1 data-i18n=\"drills-title\"></h1><p class=\"drills-lede\" data-i18n=\"drills-lede\"></p></header></div>";
const CLASS_HEAD: &str = "<div class=\"lesson class-page\"><h1 data-i18n=\"class-title\"></h1><p class=\"lesson-intro\" data-i18n=\"class-lede\"></p></div>";
const LESSON_HEAD: &str = "<div class=\"lesson\"><h1 data-i18n=\"lesson-title\"></h1><p class=\"lesson-intro\" data-i18n=\"lesson-intro\"></p></div>";

/// All pages, in navigation order (the Drills menu lists its groups' pages in this order), each
/// with the wasm chunk its code is split into.
#[rustfmt::skip]
pub const PAGES: &[PageDef] = &[
    page!(home_page, home::HomePage, HOME_ID, "home-page-title", HOME_HEAD, Nav::Top, ["home.ftl", "recipes.ftl"]),
    page!(ik2r_page, ik2r::Ik2rPage, "ik-2r", "ik2r-title", IK2R_HEAD, Nav::Kinematics, ["ik2r.ftl", "recipes.ftl"], "ik2r"),
    page!(dh_fk_page, dh_fk::DhPage, "dh-fk", "dh-title", DH_HEAD, Nav::Kinematics, ["dh.ftl", "recipes.ftl"], "dh_fk"),
    page!(se3_page, se3::Se3Page, "se3-relative", "se3-title", SE3_HEAD, Nav::Kinematics, ["se3.ftl", "recipes.ftl"]),
    page!(umeyama_page, umeyama::UmeyamaPage, "umeyama-2d", "umeyama-title", UMEYAMA_HEAD, Nav::Kinematics, ["umeyama.ftl", "recipes.ftl"], "umeyama"),
    page!(pendulum_page, pendulum::PendulumPage, "pendulum-energy", "pendulum-title", PENDULUM_HEAD, Nav::Dynamics, ["pendulum.ftl", "recipes.ftl"]),
    page!(pid_step_page, Signal<pid_step::PidPage>, "pid-step", "pid-title", PID_HEAD, Nav::Dynamics, ["signals.ftl", "recipes.ftl"]),
    page!(cubic_path_page, Signal<cubic_path::CubicPage>, "cubic-path", "cubic-title", CUBIC_HEAD, Nav::Trajectories, ["signals.ftl", "recipes.ftl"]),
    page!(trapezoid_profile_page, Signal<trapezoid_profile::TrapPage>, "trapezoid-profile", "trap-title", TRAP_HEAD, Nav::Trajectories, ["signals.ftl", "recipes.ftl"]),
    page!(traj_resample_page, traj_resample::TrajResample, "traj-resample", "traj-title", TRAJ_HEAD, Nav::Trajectories, ["traj.ftl", "recipes.ftl"]),
    page!(rrt_page, rrt::RrtPage, "rrt-2d", "rrt-title", RRT_HEAD, Nav::Planning, ["rrt.ftl", "drills.ftl", "recipes.ftl"], "rrt"),
    page!(teleop_page, teleop::TeleopPage, "teleop", "teleop-nav", TELEOP_HEAD, Nav::Top, ["teleop.ftl"], "teleop"),
    page!(so101_page, so101::So101Page, "so101", "so101-nav", SO101_HEAD, Nav::Top, ["so101.ftl", "teleop.ftl"]),
    page!(drills_page, drills::DrillsPage, DRILLS_ID, "drills-title", DRILLS_HEAD, Nav::Top, ["drills.ftl", "traj.ftl", "recipes.ftl"], "drills"),
    page!(lesson_page, lesson::LessonPage, "lesson", "lesson-title", LESSON_HEAD, Nav::Top, ["lesson.ftl", "recipes.ftl"]),
    page!(class_page, class::ClassPage, "class", "class-nav", CLASS_HEAD, Nav::Tool, ["progress.ftl"]),
];
