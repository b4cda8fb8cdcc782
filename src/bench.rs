//! The benchmark cases of `make bench`, shared by the native runner (`examples/bench.rs`) and
//! the wasm runner (`scripts/bench-wasm.mjs`, through `benchCase` when built with the `bench`
//! feature). Each case is a whole recipe run through the same entry point as the CLI and
//! `runRecipe`: arguments parsed, kernel run, CSV text formatted.

use crate::recipes::{self, RecipeOutput};
use crate::RecipeError;

/// The typed-kernel half of a case: inputs in, a count of results out.
pub type KernelFn = fn(&[(String, String)]) -> Result<usize, RecipeError>;

/// One benchmark: a recipe with its arguments (and an input file for traj-resample).
#[derive(Debug, Clone)]
pub struct BenchCase {
    pub name: &'static str,
    pub id: &'static str,
    pub args: &'static [&'static str],
    /// `(rows, joints)` of a generated trajectory CSV passed as `traj.csv`.
    pub trajectory: Option<(usize, usize)>,
    /// The same work through the typed API, without formatting CSV text (what a page calls).
    pub kernel: KernelFn,
}

/// The cases of the kernels issue: sizes that a page or a learner can really ask for.
pub const CASES: &[BenchCase] = &[
    BenchCase {
        name: "ik-workspace 401x401 (1 mm over ±200 mm)",
        id: "ik-workspace",
        args: &["0.12", "0.10", "200", "1"],
        trajectory: None,
        kernel: kernel_ik,
    },
    BenchCase {
        name: "manip-grid n=512",
        id: "manip-grid",
        args: &["0.12", "0.10", "512"],
        trajectory: None,
        kernel: kernel_manip,
    },
    BenchCase {
        name: "jacobian-2r 62,800 samples",
        id: "jacobian-2r",
        args: &["0.12", "0.10", "0", "6.27995", "0.0001", "0.8"],
        trajectory: None,
        kernel: kernel_jacobian,
    },
    BenchCase {
        name: "rrt-2d 20,000 iterations (goal unreachable)",
        id: "rrt-2d",
        args: &["7", "20000", "--goal-x", "0.5", "--goal-y", "0.5"],
        trajectory: None,
        kernel: kernel_rrt,
    },
    BenchCase {
        name: "rrt-2d 20,000 iterations, goal walled in (kernel: linear scan, the old search)",
        id: "rrt-2d",
        args: WALLED_20K,
        trajectory: None,
        kernel: kernel_rrt_walled_linear,
    },
    BenchCase {
        name: "rrt-2d 20,000 iterations, goal walled in (quadtree)",
        id: "rrt-2d",
        args: WALLED_20K,
        trajectory: None,
        kernel: kernel_rrt_walled,
    },
    BenchCase {
        name: "rrt-2d 1,000,000 iterations, goal walled in",
        id: "rrt-2d",
        args: WALLED_1M,
        trajectory: None,
        kernel: kernel_rrt_walled_1m,
    },
    BenchCase {
        name: "pendulum-energy 60 s at 2 ms",
        id: "pendulum-energy",
        args: &["60"],
        trajectory: None,
        kernel: kernel_pendulum,
    },
    BenchCase {
        name: "teleop 6,000 steps (a 60 s episode at 100 Hz, DLS, 5-step latency, noise)",
        id: TELEOP_CASE_ID,
        args: &[],
        trajectory: None,
        kernel: kernel_teleop,
    },
    BenchCase {
        name: "traj-resample 1,000,000 rows x 6 joints",
        id: "traj-resample",
        args: &["traj.csv", "0.001"],
        trajectory: Some((1_000_000, 6)),
        kernel: kernel_resample,
    },
];

fn kernel_ik(_: &[(String, String)]) -> Result<usize, RecipeError> {
    use crate::recipes::ik_workspace::{compute, WorkspaceParams};
    let params = WorkspaceParams {
        l1: 0.12,
        l2: 0.10,
        half_mm: 200.0,
        step_mm: 1.0,
    };
    Ok(compute(&params)?.reachable_count())
}

fn kernel_manip(_: &[(String, String)]) -> Result<usize, RecipeError> {
    use crate::recipes::manip_grid::{grid, GridParams};
    Ok(grid(&GridParams {
        l1: 0.12,
        l2: 0.10,
        n: 512,
    })?
    .det_j
    .len())
}

fn kernel_jacobian(_: &[(String, String)]) -> Result<usize, RecipeError> {
    use crate::recipes::jacobian_2r::{sweep, SweepParams};
    let params = SweepParams {
        q1_stop: 6.27995,
        q1_step: 0.0001,
        ..SweepParams::default()
    };
    Ok(sweep(&params)?.len())
}

fn kernel_rrt(_: &[(String, String)]) -> Result<usize, RecipeError> {
    use crate::recipes::rrt_2d::{run, RrtParams};
    let params = RrtParams {
        seed: 7,
        max_iter: 20_000,
        goal: [0.5, 0.5],
    };
    Ok(run(&params)?.nodes().len())
}

/// Four boxes around the goal (0.8, 0.8), 0.02 thick, leaving no gap: the goal is never
/// reached and the tree fills the rest of the square.
const WALLS: [&str; 8] = [
    "--obstacle",
    "0.7,0.7,0.9,0.72",
    "--obstacle",
    "0.7,0.88,0.9,0.9",
    "--obstacle",
    "0.7,0.7,0.72,0.9",
    "--obstacle",
    "0.88,0.7,0.9,0.9",
];
/// The command line of `max_iter` iterations in the walled-in world of `WALLS`.
const fn walled(max_iter: &'static str) -> [&'static str; 12] {
    let mut args = [
        "7", max_iter, "", "", "", "", "", "", "", "", "--goal", "0.8,0.8",
    ];
    let mut i = 0;
    while i < WALLS.len() {
        args[2 + i] = WALLS[i];
        i += 1;
    }
    args
}
const WALLED_20K: &[&str] = &walled("20000");
const WALLED_1M: &[&str] = &walled("1000000");

/// The walled-in world of `WALLS` with `max_iter` iterations.
pub fn walled_setup(max_iter: usize) -> crate::recipes::rrt_2d::RrtSetup {
    use crate::recipes::rrt_2d::{Obstacle, RrtParams, RrtSetup, RrtWorld};
    let boxes = WALLS.chunks(2).map(|pair| {
        let v: Vec<f64> = pair[1].split(',').filter_map(|t| t.parse().ok()).collect();
        Obstacle {
            x_min: v[0],
            y_min: v[1],
            x_max: v[2],
            y_max: v[3],
        }
    });
    RrtSetup {
        params: RrtParams {
            seed: 7,
            max_iter,
            goal: [0.8, 0.8],
        },
        world: RrtWorld {
            obstacles: boxes.collect(),
            ..RrtWorld::default()
        },
        goal_checked: true,
    }
}

fn walled_run(max_iter: usize, linear: bool) -> Result<usize, RecipeError> {
    use crate::recipes::rrt_2d::Rrt;
    let mut rrt = Rrt::with_setup(&walled_setup(max_iter))?;
    rrt.set_linear_search(linear);
    while rrt.step_record().is_some() {}
    Ok(rrt.nodes().len())
}

fn kernel_rrt_walled_linear(_: &[(String, String)]) -> Result<usize, RecipeError> {
    walled_run(20_000, true)
}

fn kernel_rrt_walled(_: &[(String, String)]) -> Result<usize, RecipeError> {
    walled_run(20_000, false)
}

fn kernel_rrt_walled_1m(_: &[(String, String)]) -> Result<usize, RecipeError> {
    walled_run(1_000_000, false)
}

fn kernel_pendulum(_: &[(String, String)]) -> Result<usize, RecipeError> {
    use crate::recipes::pendulum_energy::{Pendulum, PendulumParams};
    let params = PendulumParams {
        duration_s: 60.0,
        ..PendulumParams::default()
    };
    let steps = params.validate()?;
    let mut pendulum = Pendulum::new(&params)?;
    let mut rows = 0;
    for _ in 0..steps {
        let row = pendulum.step();
        rows += usize::from(row.total.is_finite());
    }
    Ok(rows)
}

/// The id of the teleop case: not a recipe; its "recipe + CSV" half records the episode and
/// writes `teleop_episode_1.csv` ([`teleop_output`]).
pub const TELEOP_CASE_ID: &str = "teleop-replay";

/// The teleop case's scene: pick and place (the gripper never closes, so the episode runs its
/// whole 60 s time box), 50 ms latency, input noise.
fn teleop_config() -> crate::teleop::SceneConfig {
    crate::teleop::SceneConfig {
        latency_steps: 5,
        noise_sigma: 0.05,
        noise_seed: 7,
        ..crate::teleop::SceneConfig::default()
    }
}

/// A teleop config error as the bench runners report errors (never happens with the case's
/// constant, valid config).
fn scene_error(e: crate::teleop::TeleopError) -> RecipeError {
    RecipeError::BadChoice {
        param: "teleop scene".to_string(),
        value: e.to_string(),
        choices: "a valid SceneConfig".to_string(),
    }
}

/// A pilot's wandering hand: triangle waves of periods 2 s, 3 s and 5 s on x, z and phi.
fn teleop_command(step: u64) -> crate::teleop::Command {
    let tri = |period: u64| {
        let phase = (step % period) as f64 / period as f64;
        1.0 - 4.0 * (phase - 0.5).abs()
    };
    crate::teleop::Command {
        dx: tri(200),
        dz: tri(300),
        dphi: 0.5 * tri(500),
        gripper_closed: false,
    }
}

/// The 6000 steps of the teleop case, through [`crate::teleop::Sim::step`] (what a page's
/// frame calls).
fn kernel_teleop(_: &[(String, String)]) -> Result<usize, RecipeError> {
    let mut sim = crate::teleop::Sim::new(teleop_config()).map_err(scene_error)?;
    let mut steps = 0;
    while sim.done().is_none() {
        sim.step(&teleop_command(steps as u64));
        steps += 1;
    }
    Ok(steps)
}

/// The teleop case recorded as an episode and written as its CSV.
pub fn teleop_output() -> Result<RecipeOutput, RecipeError> {
    use crate::teleop::{episode_csv, EpisodeRecorder};
    let mut recorder = EpisodeRecorder::new(teleop_config()).map_err(scene_error)?;
    let mut step = 0;
    while recorder.sim().done().is_none() {
        recorder.step(&teleop_command(step));
        step += 1;
    }
    let text = episode_csv(recorder.episode());
    Ok(RecipeOutput::single(
        "teleop_episode_1.csv",
        text,
        format!("{step} steps"),
    ))
}

fn kernel_resample(inputs: &[(String, String)]) -> Result<usize, RecipeError> {
    use crate::recipes::traj_resample::{parse_trajectory, resample};
    let text = inputs.first().map(|(_, t)| t.as_str()).unwrap_or("");
    let trajectory = parse_trajectory(text)?;
    Ok(resample(&trajectory, 0.001)?.t.len())
}

/// A smooth, irregularly sampled trajectory CSV with `rows` rows and `joints` joint columns.
pub fn trajectory_csv(rows: usize, joints: usize) -> String {
    let mut text = String::with_capacity(rows * (10 + joints * 12));
    text.push_str("t_s");
    for j in 1..=joints {
        text.push_str(&format!(",q{j}"));
    }
    text.push('\n');
    for i in 0..rows {
        // Jittered timestamps, strictly increasing, about 1 ms apart.
        let t = i as f64 * 0.001 + 0.0002 * ((i * 7919) % 5) as f64;
        text.push_str(&format!("{t:.6}"));
        for j in 0..joints {
            let q = (t * (0.5 + j as f64 * 0.3)).sin() * (1.0 + j as f64 * 0.1);
            text.push_str(&format!(",{q:.6}"));
        }
        text.push('\n');
    }
    text
}

/// Prepares a case's inputs (outside the timed part).
pub fn inputs(case: &BenchCase) -> Vec<(String, String)> {
    match case.trajectory {
        Some((rows, joints)) => vec![("traj.csv".to_string(), trajectory_csv(rows, joints))],
        None => Vec::new(),
    }
}

/// Runs a case once: the timed part.
pub fn run(case: &BenchCase, inputs: Vec<(String, String)>) -> Result<RecipeOutput, RecipeError> {
    if case.id == TELEOP_CASE_ID {
        return teleop_output();
    }
    let args: Vec<String> = case.args.iter().map(|s| s.to_string()).collect();
    recipes::run_with_inputs(case.id, &args, inputs)
}

/// Median of a list of timings.
pub fn median(times: &mut [f64]) -> f64 {
    times.sort_by(f64::total_cmp);
    match times.len() {
        0 => f64::NAN,
        n if n % 2 == 1 => times[n / 2],
        n => 0.5 * (times[n / 2 - 1] + times[n / 2]),
    }
}

#[cfg(test)]
mod tests {
    #[cfg(target_arch = "wasm32")]
    use wasm_bindgen_test::wasm_bindgen_test as test;

    use super::*;

    #[test]
    fn the_teleop_case_runs_a_whole_60_s_episode_that_replays() {
        let case = CASES.iter().find(|c| c.id == TELEOP_CASE_ID).unwrap();
        assert_eq!((case.kernel)(&[]), Ok(6000));
        let output = run(case, inputs(case)).unwrap();
        assert_eq!(output.summary, "6000 steps");
        let episode = crate::teleop::parse_episode_csv(&output.files[0].text).unwrap();
        let metrics = crate::teleop::replay(&episode).unwrap();
        assert_eq!(metrics.outcome, Some(crate::teleop::Outcome::Timeout));
    }
}
