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
//! `t = np.linspace(0, 1, 12)`, lies in the (closed) box, so a thin corner can be cut.
//! `|v|` is `sqrt(vx * vx + vy * vy)`. Beyond the recipe, `--goal-x`/`--goal-y` move the goal
//! (e.g. into the obstacle, so that the planner exhausts its budget).
//!
//! [`Rrt`] is the stepping handle (one call of [`Rrt::step`] = one loop iteration); the recipe
//! run drives the same handle to the end, so a stepped tree equals the batch tree.

use super::{plan_of, CsvFile, Kernel, Plan, Progress, RecipeInfo, RecipeOutput};
use crate::args::{finite, in_range, parse_i64, parse_seed, ArgSpec, Args, Bound};
use crate::error::{RecipeError, RecipeWarning};
use crate::pyfmt::{fixed, Cell, CsvText};
use crate::rng::{check_seed, NumpyRng};

/// The axis-aligned obstacle of the recipe, closed on all sides.
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
/// Largest `max_iter` accepted: the nearest-neighbour scan is linear in the tree size, so a
/// run costs O(max_iter^2) distance evaluations (50 000 iterations is about 1.25e9).
pub const MAX_ITER_LIMIT: usize = 50_000;

/// Nearest-node distance checks that cost about as much as one output row of the other
/// recipes (for [`Kernel::plan`]).
pub const NEAREST_CHECKS_PER_ROW: u64 = 500;

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
        "iteration budget, 0 to 50000",
        0,
        MAX_ITER_LIMIT as i64,
    )
    .hint("recipe-rrt-2d-hint-max_iter"),
];

/// Options beyond the recipe: the goal position.
pub const FLAGS: [ArgSpec; 2] = [
    ArgSpec::number(
        "goal-x",
        "0.9",
        "goal x in [0, 1] (inside the obstacle makes it unreachable)",
    )
    .limits(Bound::Incl(0.0), Bound::Incl(1.0))
    .hint("recipe-rrt-2d-hint-goal-x"),
    ArgSpec::number("goal-y", "0.9", "goal y in [0, 1]")
        .limits(Bound::Incl(0.0), Bound::Incl(1.0))
        .hint("recipe-rrt-2d-hint-goal-y"),
];

pub const INFO: RecipeInfo = RecipeInfo {
    id: "rrt-2d",
    python: "rrt_2d_grid.py",
    args: &ARGS,
    flags: &FLAGS,
    writes: &[PATH_CSV, NODES_CSV],
    quirks_id: "recipe-rrt-2d-quirks",
    plan: plan_of::<Entry>,
    page: None,
};

const PATH_CSV: &str = "rrt_path.csv";
const NODES_CSV: &str = "rrt_nodes.csv";

/// Parameters of one RRT run.
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

/// Why a candidate node was not added.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RejectReason {
    /// The candidate lies outside the unit square.
    OutOfBounds,
    /// A check point of the segment from the nearest node lies in the obstacle.
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

/// An RRT being grown one iteration at a time.
#[derive(Debug, Clone)]
pub struct Rrt {
    rng: NumpyRng,
    goal: [f64; 2],
    max_iter: usize,
    iterations: usize,
    nodes: Vec<[f64; 2]>,
    parents: Vec<Option<usize>>,
    found: Option<usize>,
}

impl Rrt {
    /// A tree holding only the start node, after validating `params`.
    pub fn new(params: &RrtParams) -> Result<Rrt, RecipeError> {
        params.validate()?;
        Ok(Rrt {
            rng: NumpyRng::new(params.seed),
            goal: params.goal,
            max_iter: params.max_iter,
            iterations: 0,
            nodes: vec![START],
            parents: vec![None],
            found: None,
        })
    }

    /// Runs one iteration of the recipe's loop (or returns [`RrtStep::Exhausted`] when done).
    pub fn step(&mut self) -> RrtStep {
        if self.is_done() {
            return RrtStep::Exhausted;
        }
        self.iterations += 1;
        let sample = if self.rng.random() < GOAL_BIAS {
            self.goal
        } else {
            let x = self.rng.random();
            let y = self.rng.random();
            [x, y]
        };
        let (nearest, from) = nearest_node(&self.nodes, sample);
        let direction = [sample[0] - from[0], sample[1] - from[1]];
        let distance = norm(direction);
        if distance < MIN_EXTENSION {
            return RrtStep::Sampled { sample, nearest };
        }
        let reach = STEP.min(distance);
        let point = [
            from[0] + direction[0] / distance * reach,
            from[1] + direction[1] / distance * reach,
        ];
        let reason = if !(0.0..=1.0).contains(&point[0]) || !(0.0..=1.0).contains(&point[1]) {
            Some(RejectReason::OutOfBounds)
        } else if !segment_clear(from, point) {
            Some(RejectReason::Collision)
        } else {
            None
        };
        if let Some(reason) = reason {
            return RrtStep::Rejected {
                sample,
                nearest,
                point,
                reason,
            };
        }
        let id = self.nodes.len();
        self.nodes.push(point);
        self.parents.push(Some(nearest));
        let to_goal = [point[0] - self.goal[0], point[1] - self.goal[1]];
        if norm(to_goal) < GOAL_TOL && segment_clear(point, self.goal) {
            let goal_id = self.nodes.len();
            self.nodes.push(self.goal);
            self.parents.push(Some(id));
            self.found = Some(goal_id);
            return RrtStep::Found {
                sample,
                nearest,
                id,
                point,
                goal_id,
            };
        }
        RrtStep::Added {
            sample,
            nearest,
            id,
            point,
        }
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

/// Index and position of the node nearest to `q` (the first one on ties, as `np.argmin`).
fn nearest_node(nodes: &[[f64; 2]], q: [f64; 2]) -> (usize, [f64; 2]) {
    let mut best = (0, START, f64::INFINITY);
    for (i, node) in nodes.iter().enumerate() {
        let d = norm([node[0] - q[0], node[1] - q[1]]);
        if d < best.2 {
            best = (i, *node, d);
        }
    }
    (best.0, best.1)
}

/// The recipe's `segment_clear(a, b)`: no point `a (1 - t) + b t`, `t = np.linspace(0, 1, 12)`,
/// in the obstacle.
pub fn segment_clear(a: [f64; 2], b: [f64; 2]) -> bool {
    let last = SEGMENT_CHECKS - 1;
    let spacing = 1.0 / last as f64;
    (0..SEGMENT_CHECKS).all(|k| {
        // np.linspace: k * step (+ 0.0), with the end point set to exactly 1.
        let t = if k == last { 1.0 } else { k as f64 * spacing };
        let p = [a[0] * (1.0 - t) + b[0] * t, a[1] * (1.0 - t) + b[1] * t];
        !OBSTACLE.contains(p)
    })
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

/// [`run`] reporting iterations to `progress`. The nearest-node scan grows with the tree, so
/// the reported rows are weighted by their cost (iteration k costs about k): the bar moves at
/// an even pace in time.
pub fn run_with(params: &RrtParams, progress: &mut Progress) -> Result<Rrt, RecipeError> {
    let mut rrt = Rrt::new(params)?;
    let n = params.max_iter as u64;
    let total = (n as f64) * (n as f64);
    while !rrt.is_done() {
        rrt.step();
        let k = rrt.iterations() as f64;
        if total > 0.0 {
            progress.phase_at(0, 1, (k * k) as u64, total as u64);
        }
    }
    Ok(rrt)
}

/// What looks wrong with a finished run: a goal inside the obstacle (never reachable), or a
/// goal not reached within the budget.
pub fn warnings(rrt: &Rrt) -> Vec<RecipeWarning> {
    let goal = rrt.goal();
    if OBSTACLE.contains(goal) {
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
/// for the seed and `max_iter`) and validates them.
pub fn params_from_args(args: &Args) -> Result<RrtParams, RecipeError> {
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
    let goal = [args.flag_f64(goal_x_spec)?, args.flag_f64(goal_y_spec)?];
    let params = RrtParams {
        seed,
        max_iter,
        goal,
    };
    params.validate()?;
    Ok(params)
}

/// The recipe's uniform entry ([`Kernel`]).
pub struct Entry;

impl Kernel for Entry {
    type Params = RrtParams;

    fn params(args: &Args) -> Result<RrtParams, RecipeError> {
        params_from_args(args)
    }

    /// Rows of work: the iteration budget, weighted by the nearest-node search that grows
    /// with the tree (`max_iter² / 500`, comparable with the other recipes' rows), at least
    /// `max_iter`. A run may stop earlier, at the goal.
    fn plan(params: &RrtParams, _args: &Args) -> Result<Plan, RecipeError> {
        let n = params.max_iter as u64;
        Ok(Plan {
            rows: (n * n / NEAREST_CHECKS_PER_ROW).max(n),
        })
    }

    fn run(
        params: &RrtParams,
        _args: &Args,
        progress: &mut Progress,
    ) -> Result<RecipeOutput, RecipeError> {
        Ok(output(&run_with(params, progress)?))
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
            err(&["7", "50001"]),
            RecipeError::TooLarge { limit: 50_000, .. }
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
