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
//! computed as the recipe does), so a run of 1,000,000 iterations takes about a second.
//!
//! [`Rrt`] is the stepping handle: one call of [`Rrt::step`] / [`Rrt::step_record`] = one
//! loop iteration, with its sub-steps in an [`RrtIteration`]; [`Rrt::seek`] goes to the state
//! after any iteration, backwards too (an RNG checkpoint every [`CHECKPOINT_EVERY`]
//! iterations, then an exact replay of at most that many). The recipe run drives the same
//! handle to the end, so a stepped tree equals the batch tree.

use super::{plan_of, CsvFile, Kernel, Plan, Progress, RecipeInfo, RecipeOutput};
use crate::args::{finite, in_range, parse_i64, parse_seed, ArgKind, ArgSpec, Args, Bound};
use crate::error::{RecipeError, RecipeWarning};
use crate::pyfmt::{fixed, Cell, CsvText};
use crate::rng::{check_seed, NumpyRng};

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
/// iteration): 1,000,000 iterations take about a second.
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
    page: None,
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
        let goal_sample = self.rng.random() < self.world.goal_bias;
        let sample = if goal_sample {
            self.goal
        } else {
            let x = self.rng.random();
            let y = self.rng.random();
            [x, y]
        };
        let nearest = if self.linear {
            nearest_linear(&self.nodes, sample)
        } else if goal_sample {
            match self.goal_nearest {
                Some((i, _)) => i,
                None => {
                    let i = self.index.nearest(sample);
                    self.goal_nearest = Some((i, distance(self.nodes[i], self.goal)));
                    i
                }
            }
        } else {
            self.index.nearest(sample)
        };
        let from = self.nodes[nearest];
        let direction = [sample[0] - from[0], sample[1] - from[1]];
        let distance = norm(direction);
        let mut record = RrtIteration {
            iteration: self.iterations,
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
            self.counts.zero_length += 1;
            return record;
        }
        let reach = self.world.step.min(distance);
        let point = [
            from[0] + direction[0] / distance * reach,
            from[1] + direction[1] / distance * reach,
        ];
        record.candidate = Some(point);
        if !(0.0..=1.0).contains(&point[0]) || !(0.0..=1.0).contains(&point[1]) {
            record.outcome = RrtOutcome::OutOfSquare;
            self.counts.out_of_square += 1;
            return record;
        }
        record.checked = true;
        record.hit = first_hit(&self.world, from, point);
        if record.hit.is_some() {
            record.outcome = RrtOutcome::Collision;
            self.counts.collision += 1;
            return record;
        }
        let id = self.nodes.len();
        self.nodes.push(point);
        self.parents.push(Some(nearest));
        self.index.insert(&self.nodes, id);
        self.note_goal_distance(id);
        self.counts.added += 1;
        record.outcome = RrtOutcome::Added { id };
        let to_goal = norm([point[0] - self.goal[0], point[1] - self.goal[1]]);
        record.to_goal = Some(to_goal);
        if to_goal < self.world.goal_tol {
            let hit = first_hit(&self.world, point, self.goal);
            record.goal_hit = Some(hit);
            if hit.is_none() {
                let goal_id = self.nodes.len();
                self.nodes.push(self.goal);
                self.parents.push(Some(id));
                self.index.insert(&self.nodes, goal_id);
                self.note_goal_distance(goal_id);
                self.found = Some(goal_id);
                record.outcome = RrtOutcome::GoalReached { id, goal_id };
            }
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
        let mut path = Vec::new();
        let mut next = self.found;
        while let Some(i) = next {
            let (Some(point), Some(parent)) = (self.nodes.get(i), self.parents.get(i)) else {
                break;
            };
            path.push(*point);
            next = *parent;
        }
        path.reverse();
        path
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

/// Points per quadtree leaf before it splits.
const LEAF_CAPACITY: usize = 16;
/// Deepest level (cells of 2^-24): beyond it a leaf just grows (coincident nodes).
const MAX_DEPTH: u8 = 24;
/// Slack on the pruning bound: a cell is skipped only when every point in it is farther than
/// the best distance by more than any rounding of the recipe's distance (< 1e-15 in the unit
/// square), so a tie with a smaller index is never skipped.
const PRUNE_SLACK: f64 = 1e-9;

/// A cell of the quadtree; its bounds are not stored but derived on the way down (the root
/// is [0, 1]^2), so that a search touches less memory.
#[derive(Debug, Clone, Default)]
struct Quad {
    /// Index of the first of 4 children (0 = a leaf).
    children: u32,
    /// A leaf's nodes: id and position (kept here so that a search reads one array).
    items: Vec<(u32, [f64; 2])>,
}

/// A cell's bounds `[x0, y0, x1, y1]`.
type Rect = [f64; 4];

const ROOT: Rect = [0.0, 0.0, 1.0, 1.0];

/// Which child (0..4) of cell `r` holds `p`, and that child's bounds.
#[inline]
fn child_of(r: &Rect, p: [f64; 2]) -> (u32, Rect) {
    let (mx, my) = (0.5 * (r[0] + r[2]), 0.5 * (r[1] + r[3]));
    let k = u32::from(p[0] >= mx) + 2 * u32::from(p[1] >= my);
    (k, child_rect(r, k))
}

/// The bounds of child `k` of cell `r`.
#[inline]
fn child_rect(r: &Rect, k: u32) -> Rect {
    let (mx, my) = (0.5 * (r[0] + r[2]), 0.5 * (r[1] + r[3]));
    let (x0, x1) = if k & 1 == 0 { (r[0], mx) } else { (mx, r[2]) };
    let (y0, y1) = if k & 2 == 0 { (r[1], my) } else { (my, r[3]) };
    [x0, y0, x1, y1]
}

/// Distance from `q` to cell `r` (0 inside).
#[inline]
fn gap(r: &Rect, q: [f64; 2]) -> f64 {
    let dx = (r[0] - q[0]).max(q[0] - r[2]).max(0.0);
    let dy = (r[1] - q[1]).max(q[1] - r[3]).max(0.0);
    (dx * dx + dy * dy).sqrt()
}

/// The nearest-node index of [`Rrt`]: a bucket quadtree over the unit square. Its
/// [`NearestIndex::nearest`] is exactly [`nearest_linear`]: the same distances, the first
/// index among equal ones, only without looking at cells that cannot hold the answer.
#[derive(Debug, Clone)]
pub struct NearestIndex {
    quads: Vec<Quad>,
    stack: Vec<(u32, f64, Rect)>,
}

impl Default for NearestIndex {
    fn default() -> Self {
        NearestIndex::new()
    }
}

impl NearestIndex {
    /// An empty index over [0, 1]^2 (points outside still work, in the border cells).
    pub fn new() -> NearestIndex {
        NearestIndex {
            quads: vec![Quad::default()],
            stack: Vec::new(),
        }
    }

    /// An index of every node.
    pub fn of(nodes: &[[f64; 2]]) -> NearestIndex {
        let mut index = NearestIndex::new();
        for id in 0..nodes.len() {
            index.insert(nodes, id);
        }
        index
    }

    /// The leaf holding `p`, its bounds and depth.
    fn leaf_of(&self, p: [f64; 2]) -> (usize, Rect, u8) {
        let (mut q, mut r, mut depth) = (0, ROOT, 0);
        while self.quads[q].children != 0 {
            let (k, child) = child_of(&r, p);
            q = (self.quads[q].children + k) as usize;
            r = child;
            depth += 1;
        }
        (q, r, depth)
    }

    /// Adds node `id` (at `nodes[id]`).
    pub fn insert(&mut self, nodes: &[[f64; 2]], id: usize) {
        let Some(&p) = nodes.get(id) else {
            return;
        };
        let (leaf, r, depth) = self.leaf_of(p);
        self.quads[leaf].items.push((id as u32, p));
        if self.quads[leaf].items.len() > LEAF_CAPACITY && depth < MAX_DEPTH {
            self.split(leaf, r, depth);
        }
    }

    fn split(&mut self, leaf: usize, r: Rect, depth: u8) {
        let first = self.quads.len() as u32;
        self.quads.extend((0..4).map(|_| Quad::default()));
        let items = std::mem::take(&mut self.quads[leaf].items);
        self.quads[leaf].children = first;
        for item in items {
            let (k, _) = child_of(&r, item.1);
            self.quads[(first + k) as usize].items.push(item);
        }
        for k in 0..4 {
            let child = (first + k) as usize;
            if self.quads[child].items.len() > LEAF_CAPACITY && depth + 1 < MAX_DEPTH {
                self.split(child, child_rect(&r, k), depth + 1);
            }
        }
    }

    /// Removes every node from `len` on (`nodes` still holds them), as after
    /// `nodes.truncate(len)`.
    pub fn truncate(&mut self, nodes: &[[f64; 2]], len: usize) {
        for id in (len..nodes.len()).rev() {
            let (leaf, _, _) = self.leaf_of(nodes[id]);
            self.quads[leaf].items.retain(|&(i, _)| (i as usize) < len);
        }
    }

    /// The index of the node nearest to `q`: exactly [`nearest_linear`] (0 when empty).
    pub fn nearest(&mut self, q: [f64; 2]) -> usize {
        let mut best = (u32::MAX, f64::INFINITY);
        let mut stack = std::mem::take(&mut self.stack);
        stack.clear();
        stack.push((0, gap(&ROOT, q), ROOT));
        while let Some((qi, g, r)) = stack.pop() {
            if g - PRUNE_SLACK > best.1 {
                continue;
            }
            let quad = &self.quads[qi as usize];
            if quad.children == 0 {
                for &(id, p) in &quad.items {
                    let d = distance(p, q);
                    if d < best.1 || (d == best.1 && id < best.0) {
                        best = (id, d);
                    }
                }
                continue;
            }
            // The child nearest q first (pushed last), its two neighbours, the diagonal one.
            let (own, _) = child_of(&r, q);
            for k in [own ^ 3, own ^ 2, own ^ 1, own] {
                let cr = child_rect(&r, k);
                let cg = gap(&cr, q);
                if cg - PRUNE_SLACK <= best.1 {
                    stack.push((quad.children + k, cg, cr));
                }
            }
        }
        self.stack = stack;
        if best.0 == u32::MAX {
            0
        } else {
            best.0 as usize
        }
    }
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

/// The two CSVs and the summary line of a finished run, exactly as the recipe writes them.
pub fn output(rrt: &Rrt) -> RecipeOutput {
    let mut nodes = CsvText::with_header(&["id", "x", "y", "parent"]);
    for (i, (p, parent)) in rrt.nodes().iter().zip(rrt.parents()).enumerate() {
        let parent = parent.map_or(-1, |j| j as i64);
        nodes.row(&[
            Cell::Int(i as i64),
            Cell::Float(p[0]),
            Cell::Float(p[1]),
            Cell::Int(parent),
        ]);
    }
    let path = rrt.path();
    let mut path_csv = CsvText::with_header(&["x", "y"]);
    for p in &path {
        path_csv.floats(p);
    }
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
                text: path_csv.finish(),
            },
            CsvFile {
                name: NODES_CSV.to_string(),
                text: nodes.finish(),
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

/// Runs the recipe from command-line style arguments.
pub fn run_args(args: &Args) -> Result<RecipeOutput, RecipeError> {
    super::run_of::<Entry>(args)
}

#[cfg(test)]
mod tests {
    // The same tests run natively and, under `wasm-pack test --node`, as wasm.
    #[cfg(target_arch = "wasm32")]
    use wasm_bindgen_test::wasm_bindgen_test as test;

    use super::*;
    use crate::recipes::run_strs;

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

        let out = run_strs(INFO.id, &["7", "300", "--goal-x", "0.5", "--goal-y=0.5"]).unwrap();
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
    fn zero_iterations_write_only_the_start() {
        let out = run_strs(INFO.id, &["7", "0"]).unwrap();
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
        let err = |v: &[&str]| run_strs(INFO.id, v).unwrap_err();
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
