//! The page table: every page the shell can route to (and lists in its navigation), and which
//! recipes have a page of their own in the browser. Only pages that work are listed; every
//! recipe also runs on the drills page (`#/drills?recipe=<id>`).

use crate::ui::page::PageDef;

pub mod cubic_path;
pub mod drills;
pub mod home;
pub mod ik2r;
pub mod pendulum;
pub mod pid_step;
pub mod rrt;
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
    drills::PAGE,
];

/// Recipe id → the page where it runs in the browser. The IK page computes and exports the
/// CSVs of three recipes; the RRT stepper those of rrt-2d; each signal page and traj-resample
/// has its own page.
pub const RECIPE_PAGES: &[(&str, &str)] = &[
    ("ik-workspace", "ik-2r"),
    ("jacobian-2r", "ik-2r"),
    ("manip-grid", "ik-2r"),
    ("rrt-2d", "rrt-2d"),
    ("cubic-path", "cubic-path"),
    ("pid-step", "pid-step"),
    ("trapezoid-profile", "trapezoid-profile"),
    ("traj-resample", "traj-resample"),
];

/// The page with route id `id`.
pub fn find(id: &str) -> Option<&'static PageDef> {
    PAGES.iter().find(|def| def.id == id)
}

/// The page where recipe `recipe_id` runs in the browser, if any.
pub fn page_for_recipe(recipe_id: &str) -> Option<&'static PageDef> {
    RECIPE_PAGES
        .iter()
        .find(|(recipe, _)| *recipe == recipe_id)
        .and_then(|(_, page)| find(page))
}
