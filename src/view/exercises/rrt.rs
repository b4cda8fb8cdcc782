//! The RRT page's exercises (`#/rrt-2d`): move the boxes until seed 7 needs more than 300
//! iterations, wall the goal off, predict the found path's length, and why an edge may cut
//! a box's corner. The checks run the kernel ([`rrt_2d::run_setup`]) on the page's setup.

use super::exercise::{model_of, CheckError, Exercise, PageModel, Tolerance};
use crate::recipes::kernel::Progress;
use crate::recipes::rrt_2d::{self, Rrt, RrtSetup, DEFAULT_MAX_ITER};

/// The page's route id.
pub const PAGE: &str = "rrt-2d";

/// `rrt-300`: the seed of the run.
pub const HARD_SEED: u64 = 7;
/// `rrt-300`: the goal must take more iterations than this.
pub const HARD_ITERATIONS: usize = 300;

/// The page's exercises, in the order it lists them.
#[rustfmt::skip]
pub const EXERCISES: [Exercise; 4] = [
    Exercise::goal("rrt-300", PAGE, hard_met),
    Exercise::predict("rrt-path-length", PAGE, "", Tolerance::Relative(0.15), path_length_truth),
    // 0: only 12 points of each edge are checked.
    Exercise::choose("rrt-corner", PAGE, 4, 0),
    Exercise::goal("rrt-wall", PAGE, wall_met),
];

/// The page's run to its end (goal reached or budget spent).
pub fn finished_run(setup: &RrtSetup) -> Result<Rrt, CheckError> {
    Ok(rrt_2d::run_setup(setup, &mut Progress::silent())?)
}

/// `rrt-300`: with seed [`HARD_SEED`] (the page's seed must be it), the run to its end
/// reaches the goal, and only after more than [`HARD_ITERATIONS`] iterations (a goal never
/// reached does not count: the world must stay solvable).
pub fn needs_over_300(setup: &RrtSetup) -> Result<bool, CheckError> {
    if setup.params.seed != HARD_SEED {
        return Ok(false);
    }
    let run = finished_run(setup)?;
    Ok(run.found().is_some() && run.iterations() > HARD_ITERATIONS)
}

fn hard_met(model: &PageModel) -> Result<bool, CheckError> {
    needs_over_300(model_of!(model, Rrt, "rrt-300"))
}

/// `rrt-path-length`: the length of the path the page's run finds (in units of the square's
/// side); no truth when the run does not reach the goal.
pub fn path_length(setup: &RrtSetup) -> Result<f64, CheckError> {
    let run = finished_run(setup)?;
    if run.found().is_none() {
        return Err(CheckError::NoTruth {
            exercise: "rrt-path-length",
        });
    }
    Ok(run.path_length())
}

fn path_length_truth(model: &PageModel) -> Result<f64, CheckError> {
    path_length(model_of!(model, Rrt, "rrt-path-length"))
}

/// `rrt-wall`: the boxes keep the tree from the goal: with a budget at least the recipe's
/// (800) and the goal outside every box (a goal inside a box is unreachable trivially), the
/// run ends without reaching it.
pub fn walled_off(setup: &RrtSetup) -> Result<bool, CheckError> {
    if setup.params.max_iter < DEFAULT_MAX_ITER || setup.world.collides(setup.params.goal) {
        return Ok(false);
    }
    Ok(finished_run(setup)?.found().is_none())
}

fn wall_met(model: &PageModel) -> Result<bool, CheckError> {
    walled_off(model_of!(model, Rrt, "rrt-wall"))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::recipes::rrt_2d::{check_points, segment_clear, Obstacle, OBSTACLE};
    use crate::view::exercises::exercise::test_attribute::test;
    crate::view::exercises::exercise::page_check!(|setup: &RrtSetup| PageModel::Rrt(setup));

    fn with_boxes(boxes: &[[f64; 4]]) -> RrtSetup {
        let mut setup = RrtSetup::default();
        setup.world.obstacles = boxes
            .iter()
            .map(|&[x_min, y_min, x_max, y_max]| Obstacle {
                x_min,
                y_min,
                x_max,
                y_max,
            })
            .collect();
        setup
    }

    #[test]
    fn rrt_300_needs_a_harder_world_for_seed_7() {
        let recipe = RrtSetup::default();
        let run = finished_run(&recipe).unwrap();
        assert!(run.found().is_some());
        assert_eq!(run.iterations(), 120);
        assert!(!check("rrt-300", &recipe, Answer::PageState).right());
        // The recipe's box made a tall thin wall: the tree must go round its top.
        let harder = with_boxes(&[[0.35, 0.0, 0.4, 0.9]]);
        let run = finished_run(&harder).unwrap();
        assert_eq!(run.iterations(), 481);
        assert_eq!(
            check("rrt-300", &harder, Answer::PageState),
            Verdict::Goal { met: true }
        );
        // Another seed is not the exercise's run.
        let mut other_seed = harder.clone();
        other_seed.params.seed = 8;
        assert!(!needs_over_300(&other_seed).unwrap());
        // A second box beside the goal is not enough (244 iterations).
        let beside = with_boxes(&[[0.35, 0.25, 0.65, 0.75], [0.7, 0.6, 1.0, 0.7]]);
        assert_eq!(finished_run(&beside).unwrap().iterations(), 244);
        assert!(!needs_over_300(&beside).unwrap());
    }

    #[test]
    fn rrt_wall_needs_the_goal_cut_off() {
        let recipe = RrtSetup::default();
        assert!(!check("rrt-wall", &recipe, Answer::PageState).right());
        // A wall across the square below the goal.
        let walled = with_boxes(&[[0.0, 0.7, 1.0, 0.75]]);
        assert_eq!(
            check("rrt-wall", &walled, Answer::PageState),
            Verdict::Goal { met: true }
        );
        // A box on the goal itself does not count, nor does a budget cut short.
        let on_goal = with_boxes(&[[0.85, 0.85, 0.95, 0.95]]);
        assert!(!walled_off(&on_goal).unwrap());
        let mut short = RrtSetup::default();
        short.params.max_iter = 10;
        assert!(finished_run(&short).unwrap().found().is_none());
        assert!(!walled_off(&short).unwrap());
    }

    #[test]
    fn rrt_path_length_is_the_found_paths() {
        let recipe = RrtSetup::default();
        let truth = path_length(&recipe).unwrap();
        let straight = (2.0f64 * 0.8 * 0.8).sqrt();
        // 1.604 against the straight line's 1.131 (blocked by the box).
        assert!((truth - 1.60423).abs() < 1e-5, "{truth}");
        assert!(check("rrt-path-length", &recipe, Answer::Number(truth * 1.1)).right());
        assert!(!check("rrt-path-length", &recipe, Answer::Number(straight)).right());
        let walled = with_boxes(&[[0.0, 0.7, 1.0, 0.75]]);
        assert!(matches!(
            path_length(&walled),
            Err(CheckError::NoTruth { .. })
        ));
    }

    #[test]
    fn rrt_corner_is_cut_between_check_points() {
        // An edge of about one step (0.05) across the box's top-left corner (0.35, 0.75):
        // its 12 points, 0.0045 apart, all miss the box...
        let (a, b) = ([0.33, 0.728], [0.3654, 0.7634]);
        assert!(check_points(a, b).iter().all(|p| !OBSTACLE.contains(*p)));
        assert!(segment_clear(a, b));
        // ...yet the segment passes through it: at x = 0.351 it is at y = 0.749.
        let t = (0.351 - a[0]) / (b[0] - a[0]);
        let on_segment = [0.351, a[1] + t * (b[1] - a[1])];
        assert!(OBSTACLE.contains(on_segment), "{on_segment:?}");
        let recipe = RrtSetup::default();
        assert!(check("rrt-corner", &recipe, Answer::Choice(0)).right());
        for wrong in 1..4 {
            assert!(!check("rrt-corner", &recipe, Answer::Choice(wrong)).right());
        }
    }
}
