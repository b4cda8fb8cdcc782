//! Recipe `rrt-2d` (`rrt_2d_grid.py`): a toy RRT in the unit square growing from the start
//! (0.1, 0.1) to the goal around the box obstacle [0.35, 0.65] x [0.25, 0.75].
//!
//! One iteration, as the recipe does it with numpy's `default_rng(seed)`:
//! - sample `q = goal` if `random() < 0.1`, else `q = (random(), random())`;
//! - nearest node `i = argmin_k |n_k - q|` (first minimum), `d = q - n_i`;
//!   skip when `|d| < 1e-12`;
//! - candidate `c = n_i + d / |d| * min(STEP, |d|)` with `STEP = 0.05`; skip when `c` leaves
//!   [0, 1]^2 or the segment `n_i -> c` is not clear;
//! - add `c` with parent `i`; when `|c - goal| < 0.06` and `c -> goal` is clear, add the goal
//!   with parent `c` and stop.
//!
//! A segment `a -> b` is clear when none of the 12 points `a (1 - t) + b t`,
//! `t = np.linspace(0, 1, 12)`, lies in a (closed) box, so a thin corner can be cut.
//! `|v|` is `sqrt(vx * vx + vy * vy)`.
//!
//! Beyond the recipe ([`RrtWorld`]): `--obstacle X0,Y0,X1,Y1` (repeatable; the boxes given
//! replace the recipe's, `none` for no box), `--start X,Y`, `--goal X,Y`, `--step`,
//! `--goal-bias`, `--goal-tol`. `--goal-x`/`--goal-y` stay as aliases of `--goal`'s
//! coordinates with their first meaning: a goal set only through them may lie inside a box
//! (it is never reached; the run warns). A start, or a goal given with `--goal`, inside a box
//! is refused.
//!
//! The nearest-node search uses a bucket quadtree ([`NearestIndex`]) that returns exactly the
//! recipe's node (numpy's `argmin`: the first index among equal distances, each distance
//! computed as the recipe does), so a run of 1,000,000 iterations takes under two seconds.
//!
//! [`Rrt`] is the stepping handle: one call of [`Rrt::step`] / [`Rrt::step_record`] = one
//! loop iteration, with its sub-steps in an [`RrtIteration`]; [`Rrt::seek`] goes to the state
//! after any iteration, backwards too (an RNG checkpoint every [`CHECKPOINT_EVERY`]
//! iterations, then an exact replay of at most that many). The recipe run drives the same
//! handle to the end, so a stepped tree equals the batch tree. An [`RrtCursor`] reads a run
//! as it stood at any earlier iteration without copying it (its tree is a prefix of the
//! run's; the run logs each iteration's nearest node, so a replay needs no search).

use super::info::RecipeInfo;
use super::kernel::{plan_of, Kernel, Progress};
use super::output::{CsvFile, RecipeOutput};
use super::picture::{
    pairs,
    series::{GREY, ORANGE},
    Mark, Picture, Table, UnitFrame,
};
use crate::args::{finite, in_range, parse_i64, parse_seed, ArgKind, ArgSpec, Args, Bound, Plan};
use crate::error::{RecipeError, RecipeWarning};
use crate::pyfmt::{fixed, Cell, CsvText};
use crate::rng::{check_seed, NumpyRng};
use glam::DVec2;

mod nearest_index;
pub use nearest_index::NearestIndex;

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
/// Iterations between two RNG checkpoints of [`Rrt`] (a step back replays at most this many).
pub const CHECKPOINT_EVERY: usize = 64;

/// Nearest-node distance checks that cost about as much as one output row of the other
/// recipes (kept for the record: the search was linear before the quadtree).
pub const NEAREST_CHECKS_PER_ROW: u64 = 500;
/// Rows of the other recipes that one iteration costs about as much as (quadtree search,
/// segment checks, CSV rows; `make bench`: ~1 µs an iteration, ~0.1 µs a manip-grid row).
pub const ROWS_PER_ITERATION: u64 = 10;

/// Positional arguments of `rrt_2d_grid.py`.
pub const ARGS: [ArgSpec; 2] = [
    ArgSpec::seed(
        "seed",
        "7",
        "RNG seed of np.random.default_rng, an integer in [0, 2^63)",
    )
    .hint("recipe-hint-seed"),
    ArgSpec::integer(
        "max_iter",
        "800",
        "iteration budget, 0 to 1000000",
        0,
        MAX_ITER_LIMIT as i64,
    )
    .hint("recipe-rrt-2d-hint-max_iter"),
];

/// The goal's coordinates (`--goal-x`, `--goal-y`), the first options of this port: aliases
/// of `--goal`'s coordinates.
pub const FLAGS: [ArgSpec; 2] = [
    ArgSpec::number(
        "goal-x",
        "0.9",
        "goal x in [0, 1] (alias of --goal's x; inside a box makes it unreachable)",
    )
    .limits(Bound::Incl(0.0), Bound::Incl(1.0))
    .hint("recipe-rrt-2d-hint-goal-x"),
    ArgSpec::number("goal-y", "0.9", "goal y in [0, 1] (alias of --goal's y)")
        .limits(Bound::Incl(0.0), Bound::Incl(1.0))
        .hint("recipe-rrt-2d-hint-goal-y"),
];

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

/// Every option, in `bsv --help` and form order.
pub const OPTIONS: [ArgSpec; 8] = [
    FLAG_OBSTACLE,
    FLAG_START,
    FLAG_GOAL,
    FLAG_STEP,
    FLAG_GOAL_BIAS,
    FLAG_GOAL_TOL,
    FLAGS[0],
    FLAGS[1],
];

pub const INFO: RecipeInfo = RecipeInfo {
    id: "rrt-2d",
    python: "rrt_2d_grid.py",
    args: &ARGS,
    flags: &OPTIONS,
    writes: &[PATH_CSV, NODES_CSV],
    quirks_id: "recipe-rrt-2d-quirks",
    plan: plan_of::<Entry>,
    page: Some("rrt-2d"),
    picture,
};

const PATH_CSV: &str = "rrt_path.csv";
const NODES_CSV: &str = "rrt_nodes.csv";

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

fn check_box(i: usize, b: &Obstacle) -> Result<(), RecipeError> {
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
/// alone it is allowed, as before, and the run warns).
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

/// Why a candidate node was not added.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RejectReason {
    /// The candidate lies outside the unit square.
    OutOfBounds,
    /// A check point of the segment from the nearest node lies in an obstacle.
    Collision,
}

/// What one iteration did.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum RrtStep {
    /// The sample fell on its nearest node (`|d| < 1e-12`): nothing to extend.
    Sampled { sample: [f64; 2], nearest: usize },
    /// Node `id` at `point` was added with parent `nearest`.
    Added {
        sample: [f64; 2],
        nearest: usize,
        id: usize,
        point: [f64; 2],
    },
    /// The candidate `point` (extended from `nearest`) was not added.
    Rejected {
        sample: [f64; 2],
        nearest: usize,
        point: [f64; 2],
        reason: RejectReason,
    },
    /// Node `id` at `point` was added and reaches the goal, which became node `goal_id`.
    Found {
        sample: [f64; 2],
        nearest: usize,
        id: usize,
        point: [f64; 2],
        goal_id: usize,
    },
    /// No iteration ran: the budget is spent or the goal was already reached.
    Exhausted,
}

/// How an iteration ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RrtOutcome {
    /// Node `id` was added.
    Added { id: usize },
    /// The candidate left the unit square.
    OutOfSquare,
    /// A check point of the segment lies in a box.
    Collision,
    /// The sample lies on its nearest node (`|d| < 1e-12`).
    ZeroLength,
    /// Node `id` was added and the goal, node `goal_id`, with it: the search is over.
    GoalReached { id: usize, goal_id: usize },
}

impl RrtOutcome {
    /// A short stable name: `added`, `out-of-square`, `collision`, `zero-length`,
    /// `goal-reached`.
    pub fn name(&self) -> &'static str {
        match self {
            RrtOutcome::Added { .. } => "added",
            RrtOutcome::OutOfSquare => "out-of-square",
            RrtOutcome::Collision => "collision",
            RrtOutcome::ZeroLength => "zero-length",
            RrtOutcome::GoalReached { .. } => "goal-reached",
        }
    }
}

/// A segment check that failed: the first of the 12 points inside a box.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Hit {
    /// Which check point (0 = the segment's start, 11 = its end).
    pub point: usize,
    /// Which box (0-based, the first containing the point).
    pub obstacle: usize,
}

/// The sub-steps of one iteration: sample → nearest → steer → check → add.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RrtIteration {
    /// 1-based number of this iteration.
    pub iteration: usize,
    /// The sample `q`.
    pub sample: [f64; 2],
    /// Whether `q` is the goal itself (the goal-biased draw).
    pub goal_sample: bool,
    /// Index of the nearest node and its position.
    pub nearest: usize,
    pub from: [f64; 2],
    /// `|q - n_i|`, as the recipe computes it.
    pub distance: f64,
    /// The steered candidate (`None` when the extension has zero length).
    pub candidate: Option<[f64; 2]>,
    /// Whether the 12-point segment check ran (the candidate is in the square).
    pub checked: bool,
    /// The first colliding check point, if the check failed.
    pub hit: Option<Hit>,
    /// For an added node: its distance to the goal, and, when within the tolerance, the
    /// goal segment's first colliding point (`Some(None)` = clear: goal reached).
    pub to_goal: Option<f64>,
    pub goal_hit: Option<Option<Hit>>,
    pub outcome: RrtOutcome,
}

impl RrtIteration {
    /// The 12 check points of the segment nearest → candidate, as the recipe computes them
    /// (`None` when there is no candidate).
    pub fn check_points(&self) -> Option<[[f64; 2]; SEGMENT_CHECKS]> {
        self.candidate.map(|c| check_points(self.from, c))
    }

    /// The same iteration as the plain [`RrtStep`].
    pub fn as_step(&self) -> RrtStep {
        let (sample, nearest) = (self.sample, self.nearest);
        let point = self.candidate.unwrap_or(self.sample);
        match self.outcome {
            RrtOutcome::ZeroLength => RrtStep::Sampled { sample, nearest },
            RrtOutcome::Added { id } => RrtStep::Added {
                sample,
                nearest,
                id,
                point,
            },
            RrtOutcome::OutOfSquare | RrtOutcome::Collision => RrtStep::Rejected {
                sample,
                nearest,
                point,
                reason: if self.outcome == RrtOutcome::Collision {
                    RejectReason::Collision
                } else {
                    RejectReason::OutOfBounds
                },
            },
            RrtOutcome::GoalReached { id, goal_id } => RrtStep::Found {
                sample,
                nearest,
                id,
                point,
                goal_id,
            },
        }
    }
}

/// Iterations by outcome so far.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct RrtCounts {
    pub added: usize,
    pub out_of_square: usize,
    pub collision: usize,
    pub zero_length: usize,
}

impl RrtCounts {
    /// Counts one iteration's outcome (the goal reached counts as an added node).
    fn note(&mut self, outcome: RrtOutcome) {
        match outcome {
            RrtOutcome::Added { .. } | RrtOutcome::GoalReached { .. } => self.added += 1,
            RrtOutcome::OutOfSquare => self.out_of_square += 1,
            RrtOutcome::Collision => self.collision += 1,
            RrtOutcome::ZeroLength => self.zero_length += 1,
        }
    }
}

#[derive(Debug, Clone)]
struct Checkpoint {
    rng: NumpyRng,
    nodes: usize,
    counts: RrtCounts,
}

/// An RRT being grown one iteration at a time, backwards too.
#[derive(Debug, Clone)]
pub struct Rrt {
    rng: NumpyRng,
    goal: [f64; 2],
    max_iter: usize,
    world: RrtWorld,
    iterations: usize,
    nodes: Vec<[f64; 2]>,
    parents: Vec<Option<usize>>,
    found: Option<usize>,
    index: NearestIndex,
    counts: RrtCounts,
    /// The state before iteration `k * CHECKPOINT_EVERY + 1`, for every `k` reached.
    checkpoints: Vec<Checkpoint>,
    last: Option<RrtIteration>,
    /// The node nearest the goal and its distance (`None`: not known, ask the index). Every
    /// goal-biased sample asks for it; a new node replaces it only when strictly nearer, as
    /// `argmin` keeps the first index.
    goal_nearest: Option<(usize, f64)>,
    /// Search by [`nearest_linear`] instead of the index (the reference, for tests and the
    /// benchmark's "before").
    linear: bool,
    /// The nearest node of each iteration (iteration `k` at `k - 1`): a [`RrtCursor`] replays
    /// an iteration from it without a search.
    nearest_log: Vec<u32>,
}

impl Rrt {
    /// A tree holding only the start node in the recipe's world, after validating `params`
    /// (a goal inside the box is allowed: it is never reached).
    pub fn new(params: &RrtParams) -> Result<Rrt, RecipeError> {
        Rrt::with_setup(&RrtSetup {
            params: *params,
            ..RrtSetup::default()
        })
    }

    /// A tree holding only `setup.world.start`, after validating `setup`.
    pub fn with_setup(setup: &RrtSetup) -> Result<Rrt, RecipeError> {
        setup.validate()?;
        let start = setup.world.start;
        let mut index = NearestIndex::new();
        index.insert(&[start], 0);
        let rng = NumpyRng::new(setup.params.seed);
        Ok(Rrt {
            checkpoints: vec![Checkpoint {
                rng: rng.clone(),
                nodes: 1,
                counts: RrtCounts::default(),
            }],
            rng,
            goal: setup.params.goal,
            max_iter: setup.params.max_iter,
            world: setup.world.clone(),
            iterations: 0,
            nodes: vec![start],
            parents: vec![None],
            found: None,
            index,
            counts: RrtCounts::default(),
            last: None,
            goal_nearest: None,
            linear: false,
            nearest_log: Vec::new(),
        })
    }

    /// Runs one iteration of the recipe's loop (or returns [`RrtStep::Exhausted`] when done).
    pub fn step(&mut self) -> RrtStep {
        self.step_record()
            .map_or(RrtStep::Exhausted, |r| r.as_step())
    }

    /// Runs one iteration and returns its sub-steps (`None` when done).
    pub fn step_record(&mut self) -> Option<RrtIteration> {
        if self.is_done() {
            return None;
        }
        if self.iterations % CHECKPOINT_EVERY == 0
            && self.checkpoints.len() == self.iterations / CHECKPOINT_EVERY
        {
            self.checkpoints.push(Checkpoint {
                rng: self.rng.clone(),
                nodes: self.nodes.len(),
                counts: self.counts,
            });
        }
        let record = self.iterate();
        self.last = Some(record);
        Some(record)
    }

    fn iterate(&mut self) -> RrtIteration {
        self.iterations += 1;
        let (index, nodes, goal, linear) = (&mut self.index, &self.nodes, self.goal, self.linear);
        let goal_nearest = &mut self.goal_nearest;
        let record = plan_iteration(
            &self.world,
            goal,
            &mut self.rng,
            self.iterations,
            nodes,
            |sample, goal_sample| {
                if linear {
                    nearest_linear(nodes, sample)
                } else if goal_sample {
                    match *goal_nearest {
                        Some((i, _)) => i,
                        None => {
                            let i = index.nearest(sample);
                            *goal_nearest = Some((i, distance(nodes[i], goal)));
                            i
                        }
                    }
                } else {
                    index.nearest(sample)
                }
            },
        );
        self.nearest_log.push(record.nearest as u32);
        self.counts.note(record.outcome);
        let added = match record.outcome {
            RrtOutcome::Added { id } => [Some((id, record.nearest)), None],
            RrtOutcome::GoalReached { id, goal_id } => {
                self.found = Some(goal_id);
                [Some((id, record.nearest)), Some((goal_id, id))]
            }
            _ => [None, None],
        };
        for (id, parent) in added.into_iter().flatten() {
            let point = if Some(id) == self.found {
                self.goal
            } else {
                record.candidate.unwrap_or(record.sample)
            };
            self.nodes.push(point);
            self.parents.push(Some(parent));
            self.index.insert(&self.nodes, id);
            self.note_goal_distance(id);
        }
        record
    }

    /// Node `id` was added: it becomes the goal's nearest when strictly nearer.
    fn note_goal_distance(&mut self, id: usize) {
        if let Some((_, best)) = self.goal_nearest {
            let d = distance(self.nodes[id], self.goal);
            if d < best {
                self.goal_nearest = Some((id, d));
            }
        }
    }

    /// Goes to the state after iteration `k` (0 = only the start), forwards by stepping or
    /// backwards by restoring the last checkpoint before `k` and replaying: the tree, the
    /// counters and [`Self::last`] are exactly those of a run stopped at `k`. Stops early at
    /// the end of the run; returns the iteration reached.
    pub fn seek(&mut self, k: usize) -> usize {
        if k < self.iterations {
            // Restore the checkpoint before iteration k (k >= 1: replay at least one, so that
            // `last` is iteration k's record).
            let c = k.saturating_sub(1) / CHECKPOINT_EVERY;
            let Some(cp) = self.checkpoints.get(c).cloned() else {
                return self.iterations;
            };
            self.checkpoints.truncate(c + 1);
            self.index.truncate(&self.nodes, cp.nodes);
            self.nodes.truncate(cp.nodes);
            self.parents.truncate(cp.nodes);
            self.rng = cp.rng;
            self.counts = cp.counts;
            self.iterations = c * CHECKPOINT_EVERY;
            self.nearest_log.truncate(self.iterations);
            self.found = None;
            self.last = None;
            self.goal_nearest = None;
        }
        while self.iterations < k && self.step_record().is_some() {}
        self.iterations
    }

    /// Searches the nearest node by the linear scan of the recipe (`true`) instead of the
    /// quadtree: the same tree, in O(n) per iteration (the reference and the benchmark's
    /// "before").
    pub fn set_linear_search(&mut self, linear: bool) {
        self.linear = linear;
    }

    /// Steps back `n` iterations (to 0 at most); returns the iteration reached.
    pub fn back(&mut self, n: usize) -> usize {
        self.seek(self.iterations.saturating_sub(n))
    }

    /// The sub-steps of the last iteration run (`None` at iteration 0).
    pub fn last(&self) -> Option<&RrtIteration> {
        self.last.as_ref()
    }

    /// Iterations by outcome so far.
    pub fn counts(&self) -> RrtCounts {
        self.counts
    }

    /// The world of this run.
    pub fn world(&self) -> &RrtWorld {
        &self.world
    }

    /// The iteration budget.
    pub fn max_iter(&self) -> usize {
        self.max_iter
    }

    /// Tree nodes, the start first.
    pub fn nodes(&self) -> &[[f64; 2]] {
        &self.nodes
    }

    /// Parent of each node (`None` for the start; `-1` in the CSV).
    pub fn parents(&self) -> &[Option<usize>] {
        &self.parents
    }

    /// Start-to-goal waypoints, empty until the goal is reached.
    pub fn path(&self) -> Vec<[f64; 2]> {
        tree_path(&self.nodes, &self.parents, self.found)
    }

    /// Sum of the path's segment lengths, NaN when the goal was not reached.
    pub fn path_length(&self) -> f64 {
        path_length(&self.path())
    }

    /// Id of the goal node once reached.
    pub fn found(&self) -> Option<usize> {
        self.found
    }

    /// Iterations run so far.
    pub fn iterations(&self) -> usize {
        self.iterations
    }

    /// The goal of this run.
    pub fn goal(&self) -> [f64; 2] {
        self.goal
    }

    /// Whether the goal was reached or the iteration budget is spent.
    pub fn is_done(&self) -> bool {
        self.found.is_some() || self.iterations >= self.max_iter
    }
}

/// One iteration of the recipe's loop over the tree `nodes`, the nearest node of the sample
/// given by `nearest(sample, goal_sample)`: its sub-steps and outcome (a node added gets the
/// id `nodes.len()`, the goal the next). The tree is not changed: [`Rrt`] adds the nodes, a
/// [`RrtCursor`] replays a run's iteration with the nearest node it logged.
fn plan_iteration(
    world: &RrtWorld,
    goal: [f64; 2],
    rng: &mut NumpyRng,
    iteration: usize,
    nodes: &[[f64; 2]],
    nearest: impl FnOnce([f64; 2], bool) -> usize,
) -> RrtIteration {
    let goal_sample = rng.random() < world.goal_bias;
    let sample = if goal_sample {
        goal
    } else {
        let x = rng.random();
        let y = rng.random();
        [x, y]
    };
    let nearest = nearest(sample, goal_sample);
    let from = nodes[nearest];
    let direction = [sample[0] - from[0], sample[1] - from[1]];
    let distance = norm(direction);
    let mut record = RrtIteration {
        iteration,
        sample,
        goal_sample,
        nearest,
        from,
        distance,
        candidate: None,
        checked: false,
        hit: None,
        to_goal: None,
        goal_hit: None,
        outcome: RrtOutcome::ZeroLength,
    };
    if distance < MIN_EXTENSION {
        return record;
    }
    let reach = world.step.min(distance);
    let point = [
        from[0] + direction[0] / distance * reach,
        from[1] + direction[1] / distance * reach,
    ];
    record.candidate = Some(point);
    if !(0.0..=1.0).contains(&point[0]) || !(0.0..=1.0).contains(&point[1]) {
        record.outcome = RrtOutcome::OutOfSquare;
        return record;
    }
    record.checked = true;
    record.hit = first_hit(world, from, point);
    if record.hit.is_some() {
        record.outcome = RrtOutcome::Collision;
        return record;
    }
    let id = nodes.len();
    record.outcome = RrtOutcome::Added { id };
    let to_goal = norm([point[0] - goal[0], point[1] - goal[1]]);
    record.to_goal = Some(to_goal);
    if to_goal < world.goal_tol {
        let hit = first_hit(world, point, goal);
        record.goal_hit = Some(hit);
        if hit.is_none() {
            record.outcome = RrtOutcome::GoalReached {
                id,
                goal_id: id + 1,
            };
        }
    }
    record
}

/// Where a run stood after some iteration, read from the run grown at least that far: the
/// tree then is a prefix of the run's (nodes are only ever added), so a cursor holds only the
/// counters, the RNG and the last iteration's record. [`Rrt::seek_cursor`] moves it in at
/// most [`CHECKPOINT_EVERY`] replayed iterations, each without a search (the run logged its
/// nearest nodes); [`Rrt::at`] reads the run as it stood there.
#[derive(Debug, Clone)]
pub struct RrtCursor {
    rng: NumpyRng,
    iterations: usize,
    nodes: usize,
    counts: RrtCounts,
    last: Option<RrtIteration>,
}

impl Rrt {
    /// A cursor at iteration 0 of this run (only the start).
    pub fn cursor(&self) -> RrtCursor {
        let mut cursor = RrtCursor {
            rng: NumpyRng::new(0),
            iterations: usize::MAX,
            nodes: 1,
            counts: RrtCounts::default(),
            last: None,
        };
        self.seek_cursor(&mut cursor, 0);
        cursor
    }

    /// Moves `cursor` (a cursor of this run) to the state after iteration `k`, at most the
    /// iterations run so far: from the RNG checkpoint before `k` unless `k` lies a little
    /// ahead, then replaying; returns the iteration reached.
    pub fn seek_cursor(&self, cursor: &mut RrtCursor, k: usize) -> usize {
        let k = k.min(self.iterations);
        if k < cursor.iterations || k - cursor.iterations > CHECKPOINT_EVERY {
            // Replay at least one iteration (k >= 1), so that `last` is iteration k's.
            let c = k.saturating_sub(1) / CHECKPOINT_EVERY;
            let Some(cp) = self.checkpoints.get(c) else {
                return cursor.iterations;
            };
            *cursor = RrtCursor {
                rng: cp.rng.clone(),
                iterations: c * CHECKPOINT_EVERY,
                nodes: cp.nodes,
                counts: cp.counts,
                last: None,
            };
        }
        while cursor.iterations < k {
            let iteration = cursor.iterations + 1;
            let Some(&nearest) = self.nearest_log.get(iteration - 1) else {
                break;
            };
            let Some(tree) = self.nodes.get(..cursor.nodes) else {
                break;
            };
            let record = plan_iteration(
                &self.world,
                self.goal,
                &mut cursor.rng,
                iteration,
                tree,
                |_, _| nearest as usize,
            );
            cursor.iterations = iteration;
            cursor.counts.note(record.outcome);
            cursor.nodes += match record.outcome {
                RrtOutcome::Added { .. } => 1,
                RrtOutcome::GoalReached { .. } => 2,
                _ => 0,
            };
            cursor.last = Some(record);
        }
        cursor.iterations
    }

    /// This run as it stood at `cursor`.
    pub fn at<'a>(&'a self, cursor: &'a RrtCursor) -> RrtAt<'a> {
        RrtAt { rrt: self, cursor }
    }
}

/// A run as it stood at a cursor ([`Rrt::at`]): the same readers as [`Rrt`]'s.
#[derive(Debug, Clone, Copy)]
pub struct RrtAt<'a> {
    rrt: &'a Rrt,
    cursor: &'a RrtCursor,
}

impl<'a> RrtAt<'a> {
    /// Tree nodes, the start first.
    pub fn nodes(&self) -> &'a [[f64; 2]] {
        let nodes = self.rrt.nodes();
        &nodes[..self.cursor.nodes.min(nodes.len())]
    }

    /// Parent of each node.
    pub fn parents(&self) -> &'a [Option<usize>] {
        let parents = self.rrt.parents();
        &parents[..self.cursor.nodes.min(parents.len())]
    }

    /// The sub-steps of the last iteration (`None` at iteration 0).
    pub fn last(&self) -> Option<&'a RrtIteration> {
        self.cursor.last.as_ref()
    }

    /// Iterations by outcome so far.
    pub fn counts(&self) -> RrtCounts {
        self.cursor.counts
    }

    /// Iterations run so far.
    pub fn iterations(&self) -> usize {
        self.cursor.iterations
    }

    /// Id of the goal node once reached (the run's last iteration reached it).
    pub fn found(&self) -> Option<usize> {
        match self.cursor.last.map(|r| r.outcome) {
            Some(RrtOutcome::GoalReached { goal_id, .. }) => Some(goal_id),
            _ => None,
        }
    }

    /// Start-to-goal waypoints, empty until the goal is reached.
    pub fn path(&self) -> Vec<[f64; 2]> {
        tree_path(self.nodes(), self.parents(), self.found())
    }

    /// Sum of the path's segment lengths, NaN when the goal was not reached.
    pub fn path_length(&self) -> f64 {
        path_length(&self.path())
    }

    /// The run's world.
    pub fn world(&self) -> &'a RrtWorld {
        self.rrt.world()
    }

    /// The run's iteration budget.
    pub fn max_iter(&self) -> usize {
        self.rrt.max_iter()
    }
}

/// The waypoints from the root to node `found` (empty for `None`).
fn tree_path(nodes: &[[f64; 2]], parents: &[Option<usize>], found: Option<usize>) -> Vec<[f64; 2]> {
    let mut path = Vec::new();
    let mut next = found;
    while let Some(i) = next {
        let (Some(point), Some(parent)) = (nodes.get(i), parents.get(i)) else {
            break;
        };
        path.push(*point);
        next = *parent;
    }
    path.reverse();
    path
}

/// `np.linalg.norm` of a 2-vector.
fn norm(v: [f64; 2]) -> f64 {
    (v[0] * v[0] + v[1] * v[1]).sqrt()
}

/// The recipe's distance from node `p` to the sample `q`: `norm(p - q)`.
#[inline]
fn distance(p: [f64; 2], q: [f64; 2]) -> f64 {
    norm([p[0] - q[0], p[1] - q[1]])
}

/// The recipe's nearest node by a linear scan: `np.argmin` of the distances (the first index
/// among equal ones). The reference [`NearestIndex`] is tested against.
pub fn nearest_linear(nodes: &[[f64; 2]], q: [f64; 2]) -> usize {
    let mut best = (0, f64::INFINITY);
    for (i, node) in nodes.iter().enumerate() {
        let d = distance(*node, q);
        if d < best.1 {
            best = (i, d);
        }
    }
    best.0
}

/// The 12 points `a (1 - t) + b t`, `t = np.linspace(0, 1, 12)`.
pub fn check_points(a: [f64; 2], b: [f64; 2]) -> [[f64; 2]; SEGMENT_CHECKS] {
    let last = SEGMENT_CHECKS - 1;
    let spacing = 1.0 / last as f64;
    std::array::from_fn(|k| {
        // np.linspace: k * step (+ 0.0), with the end point set to exactly 1.
        let t = if k == last { 1.0 } else { k as f64 * spacing };
        [a[0] * (1.0 - t) + b[0] * t, a[1] * (1.0 - t) + b[1] * t]
    })
}

/// The first of the 12 check points of `a -> b` inside a box of `world`.
fn first_hit(world: &RrtWorld, a: [f64; 2], b: [f64; 2]) -> Option<Hit> {
    if world.obstacles.is_empty() {
        return None;
    }
    check_points(a, b)
        .iter()
        .enumerate()
        .find_map(|(point, p)| world.box_at(*p).map(|obstacle| Hit { point, obstacle }))
}

/// The recipe's `segment_clear(a, b)`: no point `a (1 - t) + b t`, `t = np.linspace(0, 1, 12)`,
/// in the recipe's obstacle.
pub fn segment_clear(a: [f64; 2], b: [f64; 2]) -> bool {
    check_points(a, b).iter().all(|p| !OBSTACLE.contains(*p))
}

/// Sum of segment lengths in order; NaN for an empty path (the recipe prints `length=nan`).
pub fn path_length(path: &[[f64; 2]]) -> f64 {
    if path.is_empty() {
        return f64::NAN;
    }
    path.windows(2)
        .map(|w| norm([w[1][0] - w[0][0], w[1][1] - w[0][1]]))
        .fold(0.0, |sum, d| sum + d)
}

/// Grows the tree until it reaches the goal or spends `max_iter` iterations.
pub fn run(params: &RrtParams) -> Result<Rrt, RecipeError> {
    run_with(params, &mut Progress::silent())
}

/// [`run`] reporting iterations to `progress`.
pub fn run_with(params: &RrtParams, progress: &mut Progress) -> Result<Rrt, RecipeError> {
    run_setup(
        &RrtSetup {
            params: *params,
            ..RrtSetup::default()
        },
        progress,
    )
}

/// A run in any world, reporting iterations to `progress` (each costs about the same now
/// that the nearest-node search is a quadtree).
pub fn run_setup(setup: &RrtSetup, progress: &mut Progress) -> Result<Rrt, RecipeError> {
    let mut rrt = Rrt::with_setup(setup)?;
    let n = setup.params.max_iter as u64;
    while rrt.step_record().is_some() {
        // phase_at scales k / n to the plan's total.
        progress.phase_at(0, 1, rrt.iterations() as u64, n);
    }
    Ok(rrt)
}

/// What looks wrong with a finished run: a goal inside a box (never reachable), or a goal
/// not reached within the budget.
pub fn warnings(rrt: &Rrt) -> Vec<RecipeWarning> {
    let goal = rrt.goal();
    if rrt.world().collides(goal) {
        vec![RecipeWarning::GoalInObstacle {
            x: goal[0],
            y: goal[1],
        }]
    } else if rrt.found().is_none() {
        vec![RecipeWarning::GoalNotReached {
            iterations: rrt.iterations() as u64,
        }]
    } else {
        Vec::new()
    }
}

/// Rows `rows` of `rrt_nodes.csv` (with the header when they start at node 0), exactly the
/// bytes [`output`] writes there: the page writes a big tree's file in slices.
pub fn nodes_csv_part(rrt: &Rrt, rows: std::ops::Range<usize>) -> String {
    let mut csv = if rows.start == 0 {
        CsvText::with_header(&["id", "x", "y", "parent"])
    } else {
        CsvText::default()
    };
    let end = rows.end.min(rrt.nodes().len());
    let start = rows.start.min(end);
    for (i, (p, parent)) in rrt.nodes()[start..end]
        .iter()
        .zip(&rrt.parents()[start..end])
        .enumerate()
    {
        let parent = parent.map_or(-1, |j| j as i64);
        csv.row(&[
            Cell::Int((start + i) as i64),
            Cell::Float(p[0]),
            Cell::Float(p[1]),
            Cell::Int(parent),
        ]);
    }
    csv.finish()
}

/// `rrt_path.csv` of the waypoints `path` ([`Rrt::path`]).
pub fn path_csv(path: &[[f64; 2]]) -> String {
    let mut csv = CsvText::with_header(&["x", "y"]);
    for p in path {
        csv.floats(p);
    }
    csv.finish()
}

/// The two CSVs and the summary line of a finished run, exactly as the recipe writes them.
pub fn output(rrt: &Rrt) -> RecipeOutput {
    let nodes = nodes_csv_part(rrt, 0..rrt.nodes().len());
    let path = rrt.path();
    let summary = format!(
        "RRT nodes={} path_pts={} length={} -> {PATH_CSV}, {NODES_CSV}",
        rrt.nodes().len(),
        path.len(),
        fixed(path_length(&path), 3)
    );
    RecipeOutput {
        files: vec![
            CsvFile {
                name: PATH_CSV.to_string(),
                text: path_csv(&path),
            },
            CsvFile {
                name: NODES_CSV.to_string(),
                text: nodes,
            },
        ],
        summary,
        warnings: warnings(rrt),
    }
}

/// Parses `seed max_iter [--goal-x X] [--goal-y Y]` into parameters (any whole-number notation
/// for the seed and `max_iter`) and validates them (the world's options are read by
/// [`setup_from_args`]).
pub fn params_from_args(args: &Args) -> Result<RrtParams, RecipeError> {
    Ok(setup_from_args(args)?.params)
}

/// A flag's one value as a point `x,y`.
fn point_flag(args: &Args, spec: &ArgSpec) -> Result<[f64; 2], RecipeError> {
    let v = spec.list(args.flag_text(spec))?;
    Ok([v[0], v[1]])
}

/// Parses every argument and option of rrt-2d and validates them: without options, exactly
/// the recipe's world.
pub fn setup_from_args(args: &Args) -> Result<RrtSetup, RecipeError> {
    let [seed_spec, max_iter_spec] = &ARGS;
    let [goal_x_spec, goal_y_spec] = &FLAGS;
    let seed = parse_seed(seed_spec.name, args.text(0, seed_spec))?;
    let out_of_range = |value: f64| RecipeError::OutOfRange {
        param: max_iter_spec.name.to_string(),
        value,
        min: 0.0,
        max: MAX_ITER_LIMIT as f64,
    };
    let max_iter = match parse_i64(max_iter_spec.name, args.text(1, max_iter_spec)) {
        Ok(v) => v,
        Err(RecipeError::OutOfRange { value, .. }) => return Err(out_of_range(value)),
        Err(e) => return Err(e),
    };
    let max_iter = usize::try_from(max_iter).map_err(|_| out_of_range(max_iter as f64))?;
    let mut world = RrtWorld::default();
    let boxes = args.flag_texts(&FLAG_OBSTACLE);
    if !boxes.is_empty() {
        if boxes.len() > MAX_OBSTACLES {
            return Err(RecipeError::TooManyValues {
                param: FLAG_OBSTACLE.name.to_string(),
                count: boxes.len(),
                limit: MAX_OBSTACLES,
            });
        }
        world.obstacles.clear();
        for text in boxes {
            if text.trim().eq_ignore_ascii_case("none") {
                continue;
            }
            let v = FLAG_OBSTACLE.list(text)?;
            let b = Obstacle {
                x_min: v[0],
                y_min: v[1],
                x_max: v[2],
                y_max: v[3],
            };
            check_box(world.obstacles.len(), &b)?;
            world.obstacles.push(b);
        }
    }
    if args.has_flag(&FLAG_START) {
        world.start = point_flag(args, &FLAG_START)?;
    }
    let goal_checked = args.has_flag(&FLAG_GOAL);
    let mut goal = if goal_checked {
        point_flag(args, &FLAG_GOAL)?
    } else {
        DEFAULT_GOAL
    };
    // The aliases replace one coordinate each (after --goal).
    if args.has_flag(goal_x_spec) {
        goal[0] = goal_x_spec.check(args.flag_f64(goal_x_spec)?)?;
    }
    if args.has_flag(goal_y_spec) {
        goal[1] = goal_y_spec.check(args.flag_f64(goal_y_spec)?)?;
    }
    world.step = FLAG_STEP.check(args.flag_f64(&FLAG_STEP)?)?;
    world.goal_bias = FLAG_GOAL_BIAS.check(args.flag_f64(&FLAG_GOAL_BIAS)?)?;
    world.goal_tol = FLAG_GOAL_TOL.check(args.flag_f64(&FLAG_GOAL_TOL)?)?;
    let setup = RrtSetup {
        params: RrtParams {
            seed,
            max_iter,
            goal,
        },
        world,
        goal_checked,
    };
    setup.validate()?;
    Ok(setup)
}

/// The recipe's uniform entry ([`Kernel`]).
pub struct Entry;

impl Kernel for Entry {
    type Params = RrtSetup;
    const INFO: &'static RecipeInfo = &INFO;

    fn params(args: &Args) -> Result<RrtSetup, RecipeError> {
        setup_from_args(args)
    }

    /// Rows of work: the iteration budget times [`ROWS_PER_ITERATION`] (each iteration
    /// costs about the same with the quadtree search). A run may stop earlier, at the goal.
    fn plan(setup: &RrtSetup, _args: &Args) -> Result<Plan, RecipeError> {
        Ok(Plan {
            rows: (setup.params.max_iter as u64 * ROWS_PER_ITERATION).max(1),
        })
    }

    fn run(
        setup: &RrtSetup,
        _args: &Args,
        progress: &mut Progress,
    ) -> Result<RecipeOutput, RecipeError> {
        Ok(output(&run_setup(setup, progress)?))
    }
}

/// The home card's picture: the tree's edges and the path found, in the unit square.
pub fn picture(output: &RecipeOutput, aspect: f64) -> Option<Picture> {
    let nodes = Table::parse(output.file(NODES_CSV)?)?;
    let path = Table::parse(output.file(PATH_CSV)?)?;
    let pts = pairs(&nodes.col("x")?, &nodes.col("y")?);
    let parent = nodes.col("parent")?;
    let frame = UnitFrame::fit([DVec2::ZERO, DVec2::ONE].into_iter(), Some(aspect));
    let edges = pts
        .iter()
        .zip(&parent)
        .filter(|(_, p)| **p >= 0.0)
        .filter_map(|(c, p)| Some((frame.map(*c), frame.map(*pts.get(*p as usize)?))))
        .collect();
    Some(Picture {
        marks: vec![
            Mark::Segments {
                series: GREY,
                pairs: edges,
            },
            Mark::Line {
                series: ORANGE,
                points: pairs(&path.col("x")?, &path.col("y")?)
                    .into_iter()
                    .map(|p| frame.map(p))
                    .collect(),
            },
        ],
    })
}

#[cfg(test)]
mod tests {
    // The same tests run natively and, under `wasm-pack test --node`, as wasm.
    #[cfg(target_arch = "wasm32")]
    use wasm_bindgen_test::wasm_bindgen_test as test;

    use super::*;
    use crate::recipes::testkit::run_strs;

    /// Steps a tree to the end, checking that each event changes the tree as it says.
    fn step_to_end(params: &RrtParams) -> (Rrt, Vec<RrtStep>) {
        let mut rrt = Rrt::new(params).unwrap();
        let mut events = Vec::new();
        while !rrt.is_done() {
            let before = rrt.nodes().len();
            let event = rrt.step();
            let added = match event {
                RrtStep::Added {
                    nearest, id, point, ..
                } => {
                    assert_eq!(id, before);
                    assert_eq!(rrt.nodes()[id], point);
                    assert_eq!(rrt.parents()[id], Some(nearest));
                    1
                }
                RrtStep::Found { id, goal_id, .. } => {
                    assert_eq!((id, goal_id), (before, before + 1));
                    assert_eq!(rrt.nodes()[goal_id], params.goal);
                    2
                }
                RrtStep::Rejected { .. } | RrtStep::Sampled { .. } => 0,
                RrtStep::Exhausted => panic!("Exhausted before done"),
            };
            assert_eq!(rrt.nodes().len(), before + added);
            events.push(event);
        }
        assert_eq!(rrt.step(), RrtStep::Exhausted);
        (rrt, events)
    }

    #[test]
    fn stepping_builds_the_same_tree_as_the_recipe_run() {
        for seed in [7, 42, 3] {
            let params = RrtParams {
                seed,
                ..RrtParams::default()
            };
            let (stepped, events) = step_to_end(&params);
            let batch = run(&params).unwrap();
            assert_eq!(stepped.nodes(), batch.nodes(), "seed {seed}");
            assert_eq!(stepped.parents(), batch.parents(), "seed {seed}");
            assert_eq!(stepped.iterations(), events.len());
            assert_eq!(output(&stepped), output(&batch));
        }
        // Seed 7 is the golden run: 91 nodes, 33 path points (Python's printed line).
        let (stepped, events) = step_to_end(&RrtParams::default());
        assert_eq!((stepped.nodes().len(), stepped.path().len()), (91, 33));
        assert!(matches!(
            events.last(),
            Some(RrtStep::Found { goal_id: 90, .. })
        ));
        assert_eq!(
            output(&stepped).file("rrt_nodes.csv"),
            Some(include_str!("../../tests/golden/rrt_default/rrt_nodes.csv"))
        );
    }

    #[test]
    fn tree_respects_the_world() {
        let (rrt, events) = step_to_end(&RrtParams {
            seed: 11,
            max_iter: 400,
            ..RrtParams::default()
        });
        for (i, (p, parent)) in rrt.nodes().iter().zip(rrt.parents()).enumerate().skip(1) {
            assert!((0.0..=1.0).contains(&p[0]) && (0.0..=1.0).contains(&p[1]));
            assert!(!OBSTACLE.contains(*p), "node {i} in the obstacle");
            let parent = parent.unwrap();
            assert!(parent < i);
            let q = rrt.nodes()[parent];
            let edge = norm([p[0] - q[0], p[1] - q[1]]);
            // Tree edges are at most STEP long, except the final jump to the goal.
            assert!(
                edge <= STEP + 1e-15 || Some(i) == rrt.found(),
                "edge {i}: {edge}"
            );
            assert!(segment_clear(q, *p));
        }
        for event in events {
            if let RrtStep::Rejected {
                point,
                reason: RejectReason::Collision,
                nearest,
                ..
            } = event
            {
                assert!(!segment_clear(rrt.nodes()[nearest], point));
            }
        }
    }

    #[test]
    fn unreachable_goal_exhausts_the_budget() {
        // A goal inside the obstacle: every extension into the box is rejected.
        let params = RrtParams {
            seed: 7,
            max_iter: 300,
            goal: [0.5, 0.5],
        };
        let (rrt, events) = step_to_end(&params);
        assert_eq!(rrt.iterations(), 300);
        assert_eq!(events.len(), 300);
        assert_eq!(rrt.found(), None);
        assert!(rrt.path().is_empty());
        assert!(rrt.path_length().is_nan());
        assert!(events.iter().any(|e| matches!(
            e,
            RrtStep::Rejected {
                reason: RejectReason::Collision,
                ..
            }
        )));

        let out = run_strs::<Entry>(&["7", "300", "--goal-x", "0.5", "--goal-y=0.5"]).unwrap();
        assert_eq!(out.file("rrt_path.csv"), Some("x,y\r\n"));
        assert_eq!(
            out.summary,
            format!(
                "RRT nodes={} path_pts=0 length=nan -> rrt_path.csv, rrt_nodes.csv",
                rrt.nodes().len()
            )
        );
    }

    #[test]
    fn nodes_csv_in_parts_is_the_whole_file() {
        let rrt = run(&RrtParams::default()).unwrap();
        let whole = output(&rrt);
        let n = rrt.nodes().len();
        let parts: String = [0..1, 1..40, 40..41, 41..n + 5, n + 5..n + 9]
            .into_iter()
            .map(|rows| nodes_csv_part(&rrt, rows))
            .collect();
        assert_eq!(Some(parts.as_str()), whole.file("rrt_nodes.csv"));
    }

    #[test]
    fn zero_iterations_write_only_the_start() {
        let out = run_strs::<Entry>(&["7", "0"]).unwrap();
        assert_eq!(
            out.file("rrt_nodes.csv"),
            Some("id,x,y,parent\r\n0,0.1,0.1,-1\r\n")
        );
        assert_eq!(
            out.summary,
            "RRT nodes=1 path_pts=0 length=nan -> rrt_path.csv, rrt_nodes.csv"
        );
    }

    #[test]
    fn segment_check_uses_twelve_points() {
        // This segment is inside the box only for t in [0.5, 0.52], between the check points
        // 5/11 and 6/11, so it counts as clear although it cuts the corner (the quirk).
        let (a, b) = ([0.30, 0.302], [0.40, 0.202]);
        let t = 0.51;
        assert!(OBSTACLE.contains([a[0] * (1.0 - t) + b[0] * t, a[1] * (1.0 - t) + b[1] * t]));
        assert!(segment_clear(a, b));
        // Through the box: the check point t = 6/11 is inside.
        assert!(!segment_clear([0.30, 0.30], [0.40, 0.30]));
        assert!(segment_clear([0.1, 0.1], [0.3, 0.1]));
    }

    #[test]
    fn rejects_bad_arguments() {
        let err = |v: &[&str]| run_strs::<Entry>(v).unwrap_err();
        assert!(matches!(err(&["-1"]), RecipeError::OutOfRange { .. }));
        assert!(matches!(
            err(&["9223372036854775808"]),
            RecipeError::OutOfRange { .. }
        ));
        assert!(matches!(err(&["1.5"]), RecipeError::NotAnInteger { .. }));
        assert!(matches!(err(&["7", "-3"]), RecipeError::OutOfRange { .. }));
        assert!(matches!(
            err(&["7", "1000001"]),
            RecipeError::TooLarge {
                limit: 1_000_000,
                ..
            }
        ));
        assert!(matches!(
            err(&["7", "800", "--goal-x", "1.2"]),
            RecipeError::OutOfRange { .. }
        ));
        assert!(matches!(
            err(&["7", "800", "--goal-y", "nan"]),
            RecipeError::NotFinite { .. }
        ));
        assert!(Rrt::new(&RrtParams {
            seed: u64::MAX,
            ..RrtParams::default()
        })
        .is_err());
    }
}
