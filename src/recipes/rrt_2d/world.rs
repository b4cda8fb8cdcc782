//! The world an RRT grows in and what a run takes: the recipe's box, start, goal and planner
//! constants, the options that change them, and the checks of both.
//!
//! Beyond the recipe ([`RrtWorld`]): `--obstacle X0,Y0,X1,Y1` (repeatable; the boxes given
//! replace the recipe's, `none` for no box), `--start X,Y`, `--goal X,Y`, `--step`,
//! `--goal-bias`, `--goal-tol`. `--goal-x`/`--goal-y` are aliases of `--goal`'s coordinates:
//! a goal set only through them may lie inside a box (it is never reached; the run warns). A
//! start, or a goal given with `--goal`, inside a box is refused.

use crate::args::{finite, in_range, ArgKind, ArgSpec, Bound};
use crate::error::RecipeError;
use crate::rng::check_seed;

/// An axis-aligned obstacle box, closed on all sides.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Obstacle {
    pub x_min: f64,
    pub y_min: f64,
    pub x_max: f64,
    pub y_max: f64,
}

impl Obstacle {
    /// Whether point `p` lies in the box (edges included), the recipe's `collides`.
    pub fn contains(&self, p: [f64; 2]) -> bool {
        self.x_min <= p[0] && p[0] <= self.x_max && self.y_min <= p[1] && p[1] <= self.y_max
    }

    /// The box as `--obstacle` takes it: `[x0, y0, x1, y1]`.
    pub fn corners(&self) -> [f64; 4] {
        [self.x_min, self.y_min, self.x_max, self.y_max]
    }
}

/// The recipe's obstacle `OBS = (0.35, 0.25, 0.65, 0.75)`.
pub const OBSTACLE: Obstacle = Obstacle {
    x_min: 0.35,
    y_min: 0.25,
    x_max: 0.65,
    y_max: 0.75,
};
/// Root of the tree.
pub const START: [f64; 2] = [0.1, 0.1];
/// The recipe's goal (the default of `--goal-x` / `--goal-y`).
pub const DEFAULT_GOAL: [f64; 2] = [0.9, 0.9];
/// Longest extension per iteration.
pub const STEP: f64 = 0.05;
/// Probability of sampling the goal itself.
pub const GOAL_BIAS: f64 = 0.1;
/// A new node closer than this to the goal (with a clear segment) finishes the search.
pub const GOAL_TOL: f64 = 0.06;
/// Points checked per segment (`np.linspace(0, 1, 12)`).
pub const SEGMENT_CHECKS: usize = 12;
/// Extensions shorter than this are skipped (sample on top of its nearest node).
pub const MIN_EXTENSION: f64 = 1e-12;
/// The recipe's default seed.
pub const DEFAULT_SEED: u64 = 7;
/// The recipe's default iteration budget.
pub const DEFAULT_MAX_ITER: usize = 800;
/// Largest `max_iter` accepted. The nearest-node search is a quadtree (about log n per
/// iteration): 1,000,000 iterations take under two seconds, in wasm too.
pub const MAX_ITER_LIMIT: usize = 1_000_000;
/// Most `--obstacle` boxes in one world.
pub const MAX_OBSTACLES: usize = 32;
const UNIT: (Bound, Bound) = (Bound::Incl(0.0), Bound::Incl(1.0));

/// `--obstacle X0,Y0,X1,Y1` (repeatable).
pub const FLAG_OBSTACLE: ArgSpec = ArgSpec::number(
    "obstacle",
    "0.35,0.25,0.65,0.75",
    "an obstacle box x0,y0,x1,y1 in [0, 1] (repeatable, at most 32; the boxes given replace the recipe's; 'none' for no box)",
)
.kind(ArgKind::List { len: 4 })
.limits(UNIT.0, UNIT.1)
.hint("recipe-rrt-2d-hint-obstacle")
.repeatable();
/// `--start X,Y`.
pub const FLAG_START: ArgSpec = ArgSpec::number("start", "0.1,0.1", "the tree's root x,y")
    .kind(ArgKind::List { len: 2 })
    .limits(UNIT.0, UNIT.1)
    .hint("recipe-rrt-2d-hint-start");
/// `--goal X,Y`.
pub const FLAG_GOAL: ArgSpec = ArgSpec::number("goal", "0.9,0.9", "the goal x,y")
    .kind(ArgKind::List { len: 2 })
    .limits(UNIT.0, UNIT.1)
    .hint("recipe-rrt-2d-hint-goal");
/// `--step S`.
pub const FLAG_STEP: ArgSpec = ArgSpec::number("step", "0.05", "longest extension per iteration")
    .limits(Bound::Incl(0.001), Bound::Incl(1.0))
    .hint("recipe-rrt-2d-hint-step");
/// `--goal-bias P`.
pub const FLAG_GOAL_BIAS: ArgSpec = ArgSpec::number(
    "goal-bias",
    "0.1",
    "probability of sampling the goal itself",
)
.limits(Bound::Incl(0.0), Bound::Incl(1.0))
.hint("recipe-rrt-2d-hint-goal-bias");
/// `--goal-tol D`.
pub const FLAG_GOAL_TOL: ArgSpec = ArgSpec::number(
    "goal-tol",
    "0.06",
    "a new node nearer than this to the goal (clear segment) finishes",
)
.limits(Bound::Incl(0.001), Bound::Incl(1.5))
.hint("recipe-rrt-2d-hint-goal-tol");

/// Parameters of one RRT run (the recipe's arguments and the goal).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RrtParams {
    /// Seed of `np.random.default_rng`, in `[0, 2^63)`.
    pub seed: u64,
    /// Iteration budget, at most [`MAX_ITER_LIMIT`].
    pub max_iter: usize,
    /// Goal position in [0, 1]^2.
    pub goal: [f64; 2],
}

impl Default for RrtParams {
    fn default() -> Self {
        RrtParams {
            seed: DEFAULT_SEED,
            max_iter: DEFAULT_MAX_ITER,
            goal: DEFAULT_GOAL,
        }
    }
}

impl RrtParams {
    /// Checks the seed range, the iteration limit and that the goal lies in [0, 1]^2.
    pub fn validate(&self) -> Result<(), RecipeError> {
        check_seed("seed", self.seed)?;
        if self.max_iter > MAX_ITER_LIMIT {
            return Err(RecipeError::TooLarge {
                param: "max_iter".to_string(),
                count: self.max_iter as u64,
                limit: MAX_ITER_LIMIT as u64,
                also: Vec::new(),
                square: false,
            });
        }
        for (param, value) in [("goal-x", self.goal[0]), ("goal-y", self.goal[1])] {
            finite(param, value)?;
            in_range(param, value, 0.0, 1.0)?;
        }
        Ok(())
    }
}

/// The world and the planner's constants: the recipe's by default.
#[derive(Debug, Clone, PartialEq)]
pub struct RrtWorld {
    /// Root of the tree, in [0, 1]^2 and outside every box.
    pub start: [f64; 2],
    /// Obstacle boxes (any number up to [`MAX_OBSTACLES`], none allowed).
    pub obstacles: Vec<Obstacle>,
    /// Longest extension per iteration.
    pub step: f64,
    /// Probability of sampling the goal.
    pub goal_bias: f64,
    /// Goal tolerance.
    pub goal_tol: f64,
}

impl Default for RrtWorld {
    fn default() -> Self {
        RrtWorld {
            start: START,
            obstacles: vec![OBSTACLE],
            step: STEP,
            goal_bias: GOAL_BIAS,
            goal_tol: GOAL_TOL,
        }
    }
}

impl RrtWorld {
    /// Whether point `p` lies in any box (edges included).
    pub fn collides(&self, p: [f64; 2]) -> bool {
        self.obstacles.iter().any(|b| b.contains(p))
    }

    /// The first box (0-based) containing `p`.
    pub fn box_at(&self, p: [f64; 2]) -> Option<usize> {
        self.obstacles.iter().position(|b| b.contains(p))
    }

    /// Checks each value against its flag's facts, the boxes' corners, and that the start
    /// (and the goal, when `goal_checked`) lie outside every box.
    pub fn validate(&self, goal: [f64; 2], goal_checked: bool) -> Result<(), RecipeError> {
        if self.obstacles.len() > MAX_OBSTACLES {
            return Err(RecipeError::TooManyValues {
                param: FLAG_OBSTACLE.name.to_string(),
                count: self.obstacles.len(),
                limit: MAX_OBSTACLES,
            });
        }
        for (i, b) in self.obstacles.iter().enumerate() {
            for v in b.corners() {
                FLAG_OBSTACLE.check(v)?;
            }
            check_box(i, b)?;
        }
        for v in self.start {
            FLAG_START.check(v)?;
        }
        FLAG_STEP.check(self.step)?;
        FLAG_GOAL_BIAS.check(self.goal_bias)?;
        FLAG_GOAL_TOL.check(self.goal_tol)?;
        let mut points = vec![(FLAG_START.name, self.start)];
        if goal_checked {
            points.push((FLAG_GOAL.name, goal));
        }
        for (param, p) in points {
            if let Some(i) = self.box_at(p) {
                return Err(RecipeError::PointInObstacle {
                    param: param.to_string(),
                    x: p[0],
                    y: p[1],
                    index: i + 1,
                });
            }
        }
        Ok(())
    }
}

pub(super) fn check_box(i: usize, b: &Obstacle) -> Result<(), RecipeError> {
    if b.x_min <= b.x_max && b.y_min <= b.y_max {
        Ok(())
    } else {
        Err(RecipeError::BoxInverted {
            param: FLAG_OBSTACLE.name.to_string(),
            index: i + 1,
            corners: b.corners(),
        })
    }
}

/// Everything a run needs: the recipe's parameters, the world, and whether the goal was
/// given with `--goal` (then a goal inside a box is refused; through `--goal-x`/`--goal-y`
/// alone it is allowed, and the run warns).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct RrtSetup {
    pub params: RrtParams,
    pub world: RrtWorld,
    pub goal_checked: bool,
}

impl RrtSetup {
    /// Validates the parameters and the world.
    pub fn validate(&self) -> Result<(), RecipeError> {
        self.params.validate()?;
        self.world.validate(self.params.goal, self.goal_checked)
    }
}
