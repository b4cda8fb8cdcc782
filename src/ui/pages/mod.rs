//! The page table: every page the shell can route to (and lists in its navigation). Only pages
//! that work are listed. Which recipe runs on which page is a recipe fact (`RecipeInfo::page`,
//! read by the home cards); every recipe also runs on the drills page
//! (`#/drills?recipe=<id>`).

use crate::ui::page::PageDef;

pub mod cubic_path;
pub mod drills;
pub mod home;
pub mod ik2r;
pub mod pendulum;
pub mod pid_step;
pub mod rrt;
pub mod teleop;
pub mod traj_resample;
pub mod trapezoid_profile;

/// Route id of the home page (`#/`, `#/home`).
pub const HOME_ID: &str = home::PAGE.id;

/// All pages, in navigation order.
pub const PAGES: &[PageDef] = &[
    home::PAGE,
    ik2r::PAGE,
    pendulum::PAGE,
    traj_resample::PAGE,
    rrt::PAGE,
    cubic_path::PAGE,
    pid_step::PAGE,
    trapezoid_profile::PAGE,
    teleop::PAGE,
    drills::PAGE,
];

/// The page with route id `id`.
pub fn find(id: &str) -> Option<&'static PageDef> {
    PAGES.iter().find(|def| def.id == id)
}
