//! The page table: every page the shell can route to (and lists in its navigation). Only pages
//! that work are listed. Which recipe runs on which page is a recipe fact (`RecipeInfo::page`,
//! read by the home cards); every recipe also runs on the drills page
//! (`#/drills?recipe=<id>`).

use crate::ui::page::PageDef;

pub mod cubic_path;
pub mod dh_fk;
pub mod drills;
pub mod home;
mod home_picture;
pub mod ik2r;
pub mod lesson;
pub mod pendulum;
pub mod pid_step;
pub mod rrt;
pub mod se3;
pub mod teleop;
pub mod traj_resample;
pub mod trapezoid_profile;
pub mod umeyama;

/// Route id of the home page (`#/`, `#/home`).
pub const HOME_ID: &str = home::PAGE.id;

/// All pages, in navigation order.
pub const PAGES: &[PageDef] = &[
    home::PAGE,
    ik2r::PAGE,
    pendulum::PAGE,
    traj_resample::PAGE,
    rrt::PAGE,
    se3::PAGE,
    cubic_path::PAGE,
    pid_step::PAGE,
    trapezoid_profile::PAGE,
    dh_fk::PAGE,
    umeyama::PAGE,
    teleop::PAGE,
    drills::PAGE,
    lesson::PAGE,
];

/// The navigation's "Drills" menu: groups of drill pages (the Fluent id of each group's
/// heading, then page ids in order). Ids of pages not (yet) in [`PAGES`] are skipped; pages in
/// no group are top-level links of the header.
pub const NAV_GROUPS: &[(&str, &[&str])] = &[
    (
        "nav-group-kinematics",
        &["ik-2r", "dh-fk", "se3-relative", "umeyama-2d"],
    ),
    ("nav-group-dynamics", &["pendulum-energy", "pid-step"]),
    (
        "nav-group-trajectories",
        &["cubic-path", "trapezoid-profile", "traj-resample"],
    ),
    ("nav-group-planning", &["rrt-2d"]),
];

/// Whether page `id` is listed in the drills menu rather than as a top-level link.
pub fn in_nav_group(id: &str) -> bool {
    NAV_GROUPS.iter().any(|(_, ids)| ids.contains(&id))
}

/// The page with route id `id`.
pub fn find(id: &str) -> Option<&'static PageDef> {
    PAGES.iter().find(|def| def.id == id)
}
