//! Checking a drill's arguments without running it, and estimating how big the run is: the page
//! validates on every keystroke with this, runs small drills at once and leaves big ones to the
//! Run button.
//!
//! Each recipe is checked with its own parser and `validate` (the same code the run calls
//! first), so the messages are the kernels'. The work estimate is in output rows (or steps):
//!
//! ```text
//! pendulum-energy   int(duration / timestep)          ik-workspace  len(xs) · len(ys)
//! jacobian-2r       len(arange(start, stop, step))    cubic-path    len(arange(0, T, dt))
//! pid-step          steps                             manip-grid    n²
//! trapezoid-profile t_total / dt                      umeyama-2d    n
//! traj-resample     len(arange(t0, tN, dt)) · joints  rrt-2d        max_iter² / 500 (the
//! dh-fk, se3-relative: a few rows                       nearest-node search is quadratic)
//! ```
//!
//! traj-resample needs the shape of its input (first and last time, joint count): the page
//! parses a file once when it is opened ([`shape_of`]) if it is small enough, and otherwise
//! leaves the whole check to the run.

use crate::args::Args;
use crate::error::RecipeError;
use crate::numpy::arange_len;
use crate::recipes::{
    cubic_path, dh_fk, ik_workspace, jacobian_2r, manip_grid, pendulum_energy, pid_step, rrt_2d,
    se3_relative, traj_resample, trapezoid_profile, umeyama_2d,
};

/// Runs whose estimated work is at most this many rows run as the user types; bigger ones
/// wait for the Run button (they may take from a fraction of a second to a few seconds).
pub const AUTO_RUN_MAX_WORK: u64 = 50_000;

/// rrt-2d's work per iteration grows with the tree (a linear nearest-node search): `max_iter²`
/// divided by this is about the cost of as many output rows of the other drills.
const RRT_NEAREST_CHECKS_PER_ROW: f64 = 500.0;

/// Input files up to this size are parsed once when opened, so that their errors show at once
/// and the run size is known; bigger ones are checked by the run itself.
pub const PRECHECK_MAX_BYTES: u64 = 4 * 1024 * 1024;

/// What a valid set of arguments will cost.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Plan {
    /// Estimated rows (or steps) of work; `None` when it is only known after parsing a large
    /// input file.
    pub work: Option<u64>,
}

impl Plan {
    /// Whether the page may run it while the user types.
    pub fn is_small(&self) -> bool {
        self.work.is_some_and(|w| w <= AUTO_RUN_MAX_WORK)
    }
}

/// The shape of a trajectory CSV, enough to size its resampling.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Shape {
    /// Data rows.
    pub rows: usize,
    /// Joint columns (without `t_s` and `note`).
    pub joints: usize,
    pub t_first: f64,
    pub t_last: f64,
}

/// Parses a trajectory CSV (as the recipe does) and keeps its shape.
pub fn shape_of(text: &str) -> Result<Shape, RecipeError> {
    let traj = traj_resample::parse_trajectory(text)?;
    Ok(Shape {
        rows: traj.len(),
        joints: traj.columns.len(),
        t_first: traj.t.first().copied().unwrap_or(0.0),
        t_last: traj.t.last().copied().unwrap_or(0.0),
    })
}

/// What the page knows about traj-resample's input file.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum InputCheck<'a> {
    /// No file attached (a path argument then names a file that is not open).
    None,
    /// A file attached, parsed when it was opened.
    Parsed(&'a Result<Shape, RecipeError>),
    /// A file attached but too large to parse before the run.
    Unchecked,
}

/// Checks `args` for recipe `id` and estimates the run's size.
pub fn check(id: &str, args: &Args, input: InputCheck<'_>) -> Result<Plan, RecipeError> {
    let rows = |n: f64| Plan {
        work: Some(if n.is_finite() && n > 0.0 {
            n.min(u64::MAX as f64) as u64
        } else {
            0
        }),
    };
    match id {
        "pendulum-energy" => {
            let steps = pendulum_energy::PendulumParams::from_args(args)?.validate()?;
            Ok(rows(steps as f64))
        }
        "ik-workspace" => {
            let p = ik_workspace::params_from_args(args)?;
            p.validate()?;
            let half = p.half_mm / 1000.0;
            let per_axis = arange_len(-half, half + 1e-9, p.step_mm / 1000.0);
            Ok(rows(per_axis * per_axis))
        }
        "traj-resample" => check_resample(args, input),
        "dh-fk" => {
            dh_fk::DhParams::from_args(args)?.validate()?;
            Ok(rows(4.0))
        }
        "jacobian-2r" => {
            let p = jacobian_2r::params_from_args(args)?;
            p.validate()?;
            Ok(rows(arange_len(p.q1_start, p.q1_stop + 1e-12, p.q1_step)))
        }
        "cubic-path" => {
            let p = cubic_path::params_from_args(args)?;
            p.validate()?;
            Ok(rows(arange_len(0.0, p.duration_s + 1e-12, p.dt_s)))
        }
        "se3-relative" => {
            se3_relative::Se3Params::from_args(args)?.validate()?;
            Ok(rows(1.0))
        }
        "rrt-2d" => {
            let p = rrt_params(args)?;
            p.validate()?;
            let n = p.max_iter as f64;
            Ok(rows(n * n / RRT_NEAREST_CHECKS_PER_ROW))
        }
        "pid-step" => {
            let p = pid_step::params_from_args(args)?;
            p.validate()?;
            Ok(rows(p.steps as f64))
        }
        "manip-grid" => {
            let p = manip_grid::params_from_args(args)?;
            p.validate()?;
            Ok(rows((p.n * p.n) as f64))
        }
        "trapezoid-profile" => {
            let p = trapezoid_profile::params_from_args(args)?;
            p.validate()?;
            Ok(rows(trapezoid_rows(&p)))
        }
        "umeyama-2d" => {
            let p = umeyama_params(args)?;
            p.validate()?;
            Ok(rows(p.n as f64))
        }
        _ => Err(RecipeError::UnknownRecipe { id: id.to_string() }),
    }
}

fn check_resample(args: &Args, input: InputCheck<'_>) -> Result<Plan, RecipeError> {
    let params = traj_resample::ResampleParams::from_args(args)?;
    params.validate()?;
    let sample;
    let shape = if params.uses_sample() {
        sample = shape_of(traj_resample::SAMPLE);
        &sample
    } else {
        match input {
            InputCheck::Parsed(shape) => shape,
            InputCheck::Unchecked => return Ok(Plan { work: None }),
            InputCheck::None => {
                return Err(RecipeError::InputMissing {
                    name: params.csv_path.clone(),
                })
            }
        }
    };
    let shape = shape.as_ref().map_err(Clone::clone)?;
    let out_rows = arange_len(shape.t_first, shape.t_last + 1e-12, params.dt);
    let cells = out_rows * shape.joints as f64;
    crate::args::within_limit("dt", cells, traj_resample::MAX_OUTPUT_CELLS)?;
    let work = out_rows.max(shape.rows as f64);
    Ok(Plan {
        work: Some(work as u64),
    })
}

/// rrt-2d's arguments, read as its `run_args` reads them.
fn rrt_params(args: &Args) -> Result<rrt_2d::RrtParams, RecipeError> {
    let [seed_spec, iter_spec] = &rrt_2d::ARGS;
    let [goal_x, goal_y] = &rrt_2d::FLAGS;
    let seed = crate::rng::parse_seed(seed_spec.name, args.text(0, seed_spec))?;
    let max_iter = args.i64(1, iter_spec)?;
    let max_iter = usize::try_from(max_iter).map_err(|_| RecipeError::OutOfRange {
        param: iter_spec.name.to_string(),
        value: max_iter as f64,
        min: 0.0,
        max: rrt_2d::MAX_ITER_LIMIT as f64,
    })?;
    Ok(rrt_2d::RrtParams {
        seed,
        max_iter,
        goal: [args.flag_f64(goal_x)?, args.flag_f64(goal_y)?],
    })
}

/// umeyama-2d's arguments, read as its `run_args` reads them.
fn umeyama_params(args: &Args) -> Result<umeyama_2d::UmeyamaParams, RecipeError> {
    let [sigma_spec, seed_spec, n_spec] = &umeyama_2d::ARGS;
    let sigma = args.f64(0, sigma_spec)?;
    let seed = crate::rng::parse_seed(seed_spec.name, args.text(1, seed_spec))?;
    let n = args.i64(2, n_spec)?;
    let n = usize::try_from(n).map_err(|_| RecipeError::OutOfRange {
        param: n_spec.name.to_string(),
        value: n as f64,
        min: umeyama_2d::MIN_POINTS as f64,
        max: umeyama_2d::MAX_POINTS as f64,
    })?;
    Ok(umeyama_2d::UmeyamaParams { sigma, seed, n })
}

/// About `t_total / dt` rows of a (validated) trapezoid move.
fn trapezoid_rows(p: &trapezoid_profile::TrapParams) -> f64 {
    let (distance, vmax, amax) = (p.distance.abs(), p.vmax.abs(), p.amax.abs());
    let t_acc = vmax / amax;
    let d_acc = 0.5 * amax * t_acc * t_acc;
    let t_total = if 2.0 * d_acc >= distance {
        2.0 * (distance / amax).sqrt()
    } else {
        2.0 * t_acc + (distance - 2.0 * d_acc) / vmax
    };
    t_total / p.dt + 1.0
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::recipes::{self, RECIPES};
    use wasm_bindgen_test::wasm_bindgen_test as test;

    fn args(id: &str, raw: &[&str]) -> Args {
        let info = recipes::find(id).unwrap().info;
        let raw: Vec<String> = raw.iter().map(|s| s.to_string()).collect();
        Args::parse(&raw, info.args, info.flags).unwrap()
    }

    #[test]
    fn every_recipe_passes_with_its_defaults_and_runs_at_once() {
        for recipe in RECIPES {
            let id = recipe.info.id;
            let plan = check(id, &args(id, &[]), InputCheck::None).unwrap();
            assert!(plan.is_small(), "{id}: {plan:?}");
        }
    }

    #[test]
    fn estimates_follow_the_recipe_sizes() {
        let work = |id: &str, raw: &[&str]| {
            check(id, &args(id, raw), InputCheck::None)
                .unwrap()
                .work
                .unwrap()
        };
        assert_eq!(work("pid-step", &["1", "0", "0", "0.8", "120"]), 120);
        assert_eq!(work("manip-grid", &["0.12", "0.1", "1024"]), 1024 * 1024);
        assert_eq!(work("ik-workspace", &[]), 41 * 41);
        assert_eq!(work("pendulum-energy", &["2000"]), 1_000_000);
        assert_eq!(work("cubic-path", &[]), 51);
        assert_eq!(work("jacobian-2r", &[]), 16);
        assert!(
            !check("rrt-2d", &args("rrt-2d", &["7", "50000"]), InputCheck::None)
                .unwrap()
                .is_small()
        );
        // The labeled sample at dt = 0.02: 28 rows.
        assert_eq!(work("traj-resample", &[]), 28);
    }

    #[test]
    fn errors_are_the_kernels_and_name_the_field() {
        let err = |id: &str, raw: &[&str]| check(id, &args(id, raw), InputCheck::None).unwrap_err();
        assert_eq!(
            err("pid-step", &["1.2", "0.4", "0.05", "0.8", "abc"]).param(),
            Some("steps")
        );
        assert_eq!(
            err("manip-grid", &["0.12", "0.1", "5000"]).param(),
            Some("n")
        );
        assert_eq!(err("rrt-2d", &["7", "60000"]).param(), Some("max_iter"));
        assert_eq!(err("rrt-2d", &["-1"]).param(), Some("seed"));
        assert_eq!(
            err("pendulum-energy", &["5", "--integrator", "rk5"]).param(),
            Some("integrator")
        );
        assert_eq!(err("dh-fk", &["1,2"]).param(), Some("angles"));
        assert_eq!(
            err("jacobian-2r", &["0.12", "0.1", "1", "0"]).param(),
            Some("q1_stop")
        );
        assert_eq!(err("umeyama-2d", &["0.02", "3", "1"]).param(), Some("n"));
        assert_eq!(
            err("traj-resample", &["mine.csv"]),
            RecipeError::InputMissing {
                name: "mine.csv".into()
            }
        );
        // Every check agrees with the run on the same arguments.
        for (id, raw) in [
            ("pid-step", vec!["1", "1", "1", "-1"]),
            ("cubic-path", vec!["0", "1", "1", "0"]),
            ("trapezoid-profile", vec!["1", "0"]),
            ("se3-relative", vec!["nan"]),
        ] {
            let raw_s: Vec<String> = raw.iter().map(|s| s.to_string()).collect();
            assert_eq!(
                check(id, &args(id, &raw), InputCheck::None).unwrap_err(),
                recipes::run(id, &raw_s).unwrap_err(),
                "{id} {raw:?}"
            );
        }
    }

    #[test]
    fn a_parsed_input_file_sizes_the_resampling_and_reports_its_errors() {
        let shape = shape_of("t_s,q1\n0,0\n1,1\n");
        let a = args("traj-resample", &["mine.csv", "0.01"]);
        let plan = check("traj-resample", &a, InputCheck::Parsed(&shape)).unwrap();
        assert_eq!(plan.work, Some(101));
        let bad = shape_of("t_s,q1\n0,0\n0,1\n");
        assert_eq!(
            check("traj-resample", &a, InputCheck::Parsed(&bad)).unwrap_err(),
            RecipeError::CsvTimeNotIncreasing { row: 3 }
        );
        let tiny = args("traj-resample", &["mine.csv", "1e-9"]);
        assert_eq!(
            check("traj-resample", &tiny, InputCheck::Parsed(&shape))
                .unwrap_err()
                .param(),
            Some("dt")
        );
        let big = check("traj-resample", &a, InputCheck::Unchecked).unwrap();
        assert!(!big.is_small());
    }
}
