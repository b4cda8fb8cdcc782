//! The seed's "next step" chain of drills, shown at the foot of every drill page: pendulum →
//! IK workspace → resample → DH → Jacobian → cubic → SE(3) → RRT → PID → manipulability grid →
//! trapezoid → Umeyama → Robot Pilot practice → Robot Pilot on the SO-101. Each step is a
//! recipe (or one of the two Robot Pilot pages); its link goes to the recipe's own page when
//! it has one, else to the drills page.

/// A step of the chain: a recipe id, or a page of [`PAGE_STEPS`].
pub const CHAIN: [&str; 14] = [
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
    SO101,
];

/// Robot Pilot practice (the `teleop` page).
pub const TELEOP: &str = "teleop";

/// The last step: Robot Pilot on the SO-101 (the `so101` page).
pub const SO101: &str = "so101";

/// The steps that are pages, not recipes.
pub const PAGE_STEPS: [&str; 2] = [TELEOP, SO101];

/// Where a step's link goes: `(page id, query)`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct StepLink {
    pub page: &'static str,
    pub query: Vec<(String, String)>,
}

/// The link of `step`, given which recipe runs on which page (`page_of`, i.e.
/// `RecipeInfo::page`) and which pages exist (`exists`). `None` for a page step while its page
/// does not exist.
pub fn link(
    step: &str,
    page_of: impl Fn(&str) -> Option<&'static str>,
    exists: impl Fn(&str) -> bool,
) -> Option<StepLink> {
    if let Some(page) = PAGE_STEPS.iter().find(|p| **p == step) {
        return exists(page).then_some(StepLink {
            page,
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
            if PAGE_STEPS.contains(step) {
                page == **step
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
        let mut ids: Vec<&str> = CHAIN
            .iter()
            .copied()
            .filter(|s| !PAGE_STEPS.contains(s))
            .collect();
        ids.sort_unstable();
        let mut recipes: Vec<&str> = crate::recipes::RECIPES.iter().map(|r| r.info.id).collect();
        recipes.sort_unstable();
        assert_eq!(ids, recipes);
        assert_eq!(CHAIN[0], "pendulum-energy");
        assert_eq!(CHAIN[12], TELEOP);
        assert_eq!(CHAIN[13], SO101);
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
        assert_eq!(link(SO101, page_of, |_| true).unwrap().page, SO101);
    }

    #[test]
    fn a_page_stands_for_every_recipe_it_hosts() {
        assert_eq!(positions_of_page("ik-2r", page_of), vec![1, 4, 9]);
        assert_eq!(primary_position("ik-2r", page_of), Some(1));
        assert_eq!(primary_position("rrt-2d", page_of), Some(7));
        assert_eq!(primary_position(TELEOP, page_of), Some(12));
        assert_eq!(primary_position(SO101, page_of), Some(13));
        assert_eq!(primary_position("home", page_of), None);
        assert_eq!(label_id("dh-fk"), "chain-step-dh-fk");
        assert_eq!(next_sentence_id(TELEOP), "chain-next-teleop");
    }
}
