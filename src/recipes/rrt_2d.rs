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
//! A segment is clear when none of its 12 check points ([`check_points`]) lies in a box.
//! [`RrtWorld`] holds the boxes and the options beyond the recipe; [`Rrt`] is the stepping
//! handle, [`RrtCursor`] reads a run as it stood earlier; the nearest-node search is a bucket
//! quadtree ([`NearestIndex`]) that returns exactly the recipe's node.

use glam::DVec2;

use super::info::RecipeInfo;
use super::kernel::{plan_of, Kernel, Progress, RunResult};
use super::output::{CsvFile, RecipeOutput};
use super::picture::{
    pairs,
    series::{GREY, ORANGE},
    Mark, Picture, Table, UnitFrame,
};
use crate::args::{parse_i64, parse_seed, ArgSpec, Args, Bound};
use crate::error::{RecipeError, RecipeWarning};
use crate::pyfmt::{fixed, Cell, CsvText};

mod geometry;
mod iteration;
mod nearest_index;
mod tree;
mod world;

pub use geometry::{check_points, nearest_linear, path_length, segment_clear};
pub use iteration::{Hit, RejectReason, RrtCounts, RrtIteration, RrtOutcome, RrtStep};
pub use nearest_index::NearestIndex;
pub use tree::{Rrt, RrtAt, RrtCursor, CHECKPOINT_EVERY};
use world::check_box;
pub use world::{
    Obstacle, RrtParams, RrtSetup, RrtWorld, DEFAULT_GOAL, DEFAULT_MAX_ITER, DEFAULT_SEED,
    FLAG_GOAL, FLAG_GOAL_BIAS, FLAG_GOAL_TOL, FLAG_OBSTACLE, FLAG_START, FLAG_STEP, GOAL_BIAS,
    GOAL_TOL, MAX_ITER_LIMIT, MAX_OBSTACLES, MIN_EXTENSION, OBSTACLE, SEGMENT_CHECKS, START, STEP,
};

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

/// The goal's coordinates (`--goal-x`, `--goal-y`): aliases of `--goal`'s coordinates.
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
};

const PATH_CSV: &str = "rrt_path.csv";
const NODES_CSV: &str = "rrt_nodes.csv";

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

/// A run in any world, reporting iterations to `progress` (each costs about the same:
/// the nearest-node search is a quadtree).
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
    fn rows(setup: &RrtSetup, _args: &Args) -> Result<u64, RecipeError> {
        Ok((setup.params.max_iter as u64 * ROWS_PER_ITERATION).max(1))
    }

    fn run(setup: &RrtSetup, _args: &Args, progress: &mut Progress) -> RunResult {
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
mod tests;
