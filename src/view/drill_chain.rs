//! The seed's "next step" chain of drills, shown at the foot of every drill page: pendulum →
//! IK workspace → resample → DH → Jacobian → cubic → SE(3) → RRT → PID → manipulability grid →
//! trapezoid → Umeyama → Robot Pilot practice. Each step is a recipe (or the teleop practice
//! page); its link goes to the recipe's own page when it has one, else to the drills page.

/// A step of the chain: a recipe id, or [`TELEOP`].
pub const CHAIN: [&str; 13] = [
    "pendulum-energy",
    "ik-workspace",
    "traj-resample",
    "dh-fk",
    "jacobian-2r",
    "cubic-path",
    "se3-relative",
    "rrt-2d",
    "pid-step",
    "manip-grid",
    "trapezoid-profile",
    "umeyama-2d",
    TELEOP,
];

/// The last step: Robot Pilot practice (the `teleop` page).
pub const TELEOP: &str = "teleop";

/// Where a step's link goes: `(page id, query)`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct StepLink {
    pub page: &'static str,
    pub query: Vec<(String, String)>,
}

/// The link of `step`, given which recipe runs on which page (`page_of`, i.e.
/// `RecipeInfo::page`) and which pages exist (`exists`). `None` for the teleop step while its
/// page does not exist.
pub fn link(
    step: &str,
    page_of: impl Fn(&str) -> Option<&'static str>,
    exists: impl Fn(&str) -> bool,
) -> Option<StepLink> {
    if step == TELEOP {
        return exists(TELEOP).then_some(StepLink {
            page: TELEOP,
            query: Vec::new(),
        });
    }
    match page_of(step) {
        Some(page) if exists(page) => Some(StepLink {
            page,
            query: Vec::new(),
        }),
        _ => Some(StepLink {
            page: "drills",
            query: vec![("recipe".to_owned(), step.to_owned())],
        }),
    }
}

/// The chain positions a page stands for (a page may host several recipes: the IK page hosts
/// the IK workspace, the Jacobian and the manipulability grid). Empty on pages off the chain.
pub fn positions_of_page(page: &str, page_of: impl Fn(&str) -> Option<&'static str>) -> Vec<usize> {
    CHAIN
        .iter()
        .enumerate()
        .filter(|(_, step)| {
            if **step == TELEOP {
                page == TELEOP
            } else {
                page_of(step) == Some(page)
            }
        })
        .map(|(i, _)| i)
        .collect()
}

/// The step whose "next step" sentence the page shows: the first chain position it stands for.
pub fn primary_position(
    page: &str,
    page_of: impl Fn(&str) -> Option<&'static str>,
) -> Option<usize> {
    positions_of_page(page, page_of).first().copied()
}

/// Fluent id of a step's short label in the chain strip.
pub fn label_id(step: &str) -> String {
    format!("chain-step-{step}")
}

/// Fluent id of the seed's "next step" sentence of a step.
pub fn next_sentence_id(step: &str) -> String {
    format!("chain-next-{step}")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn page_of(recipe: &str) -> Option<&'static str> {
        match recipe {
            "ik-workspace" | "jacobian-2r" | "manip-grid" => Some("ik-2r"),
            "rrt-2d" => Some("rrt-2d"),
            "dh-fk" => Some("dh-fk"),
            _ => None,
        }
    }

    #[test]
    fn the_chain_is_the_seeds_and_covers_every_recipe_once() {
        let mut ids: Vec<&str> = CHAIN.iter().copied().filter(|s| *s != TELEOP).collect();
        ids.sort_unstable();
        let mut recipes: Vec<&str> = crate::recipes::RECIPES.iter().map(|r| r.info.id).collect();
        recipes.sort_unstable();
        assert_eq!(ids, recipes);
        assert_eq!(CHAIN[0], "pendulum-energy");
        assert_eq!(CHAIN[12], TELEOP);
    }

    #[test]
    fn links_go_to_the_page_or_the_drills_page() {
        let exists = |p: &str| p == "ik-2r" || p == "rrt-2d";
        assert_eq!(link("rrt-2d", page_of, exists).unwrap().page, "rrt-2d");
        // dh-fk names a page that does not exist here: the drills page runs it.
        let l = link("dh-fk", page_of, exists).unwrap();
        assert_eq!(l.page, "drills");
        assert_eq!(l.query, vec![("recipe".to_owned(), "dh-fk".to_owned())]);
        assert_eq!(link(TELEOP, page_of, exists), None);
        assert_eq!(link(TELEOP, page_of, |_| true).unwrap().page, TELEOP);
    }

    #[test]
    fn a_page_stands_for_every_recipe_it_hosts() {
        assert_eq!(positions_of_page("ik-2r", page_of), vec![1, 4, 9]);
        assert_eq!(primary_position("ik-2r", page_of), Some(1));
        assert_eq!(primary_position("rrt-2d", page_of), Some(7));
        assert_eq!(primary_position(TELEOP, page_of), Some(12));
        assert_eq!(primary_position("home", page_of), None);
        assert_eq!(label_id("dh-fk"), "chain-step-dh-fk");
        assert_eq!(next_sentence_id(TELEOP), "chain-next-teleop");
    }
}
