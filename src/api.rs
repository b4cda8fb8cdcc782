//! The `#[wasm_bindgen]` surface of the kernels: thin and typed; every error becomes a JS
//! `Error` whose message is the same one-liner the CLI prints.

use serde::{Deserialize, Serialize};
use wasm_bindgen::prelude::*;

use crate::args::{ArgKind, ArgSpec, Bound};
use crate::error::RecipeWarning;
use crate::recipes::{self, pendulum_energy, rrt_2d, RecipeOutput};

/// One file of a recipe run, as JS sees it: `{ name, text }`.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct JsFile {
    pub name: String,
    pub text: String,
}

/// A warning of a run, as JS sees it: `{ id, args: { name: value }, text }` (the Fluent id
/// and its arguments in `errors.ftl`, and the CLI's English line).
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct JsWarning {
    pub id: String,
    pub args: std::collections::BTreeMap<String, String>,
    pub text: String,
}

impl From<&RecipeWarning> for JsWarning {
    fn from(w: &RecipeWarning) -> Self {
        JsWarning {
            id: w.message_id().to_string(),
            args: w
                .message_args()
                .into_iter()
                .map(|(k, v)| (k.to_string(), v))
                .collect(),
            text: w.to_string(),
        }
    }
}

/// A recipe run, as JS sees it: `{ files: [{ name, text }], summary, warnings }`.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct JsRun {
    pub files: Vec<JsFile>,
    pub summary: String,
    #[serde(default)]
    pub warnings: Vec<JsWarning>,
}

impl From<RecipeOutput> for JsRun {
    fn from(out: RecipeOutput) -> Self {
        JsRun {
            warnings: out.warnings.iter().map(JsWarning::from).collect(),
            files: out
                .files
                .into_iter()
                .map(|f| JsFile {
                    name: f.name,
                    text: f.text,
                })
                .collect(),
            summary: out.summary,
        }
    }
}

/// `runRecipe(id, args, inputs?)`: runs a recipe with command-line style arguments (strings,
/// as after `bsv <id>`). `inputs` optionally maps file names used as path arguments to their
/// text (`{ "my.csv": "t_s,q1\n..." }`). Returns `{ files: [{ name, text }], summary }`.
#[wasm_bindgen(js_name = runRecipe)]
pub fn run_recipe(
    id: &str,
    args: Vec<String>,
    inputs: Option<js_sys::Object>,
) -> Result<JsValue, JsError> {
    let files = input_files(inputs);
    let out =
        recipes::run_with_inputs(id, &args, files).map_err(|e| JsError::new(&e.to_string()))?;
    serde_wasm_bindgen::to_value(&JsRun::from(out)).map_err(|e| JsError::new(&e.to_string()))
}

/// `{ "name": "text" }` as `(name, text)` pairs (other values are skipped).
fn input_files(inputs: Option<js_sys::Object>) -> Vec<(String, String)> {
    let mut files = Vec::new();
    if let Some(obj) = inputs {
        for entry in js_sys::Object::entries(&obj).iter() {
            let pair = js_sys::Array::from(&entry);
            if let (Some(name), Some(text)) = (pair.get(0).as_string(), pair.get(1).as_string()) {
                files.push((name, text));
            }
        }
    }
    files
}

/// `runRecipeWithProgress(id, args, inputs, onProgress)`: [`run_recipe`] calling
/// `onProgress(done, total)` (rows of work) at most every ~1 %; the result is identical.
#[wasm_bindgen(js_name = runRecipeWithProgress)]
pub fn run_recipe_with_progress(
    id: &str,
    args: Vec<String>,
    inputs: Option<js_sys::Object>,
    on_progress: &js_sys::Function,
) -> Result<JsValue, JsError> {
    let files = input_files(inputs);
    let mut report = |done: u64, total: u64| {
        // A throwing callback must not abort the run.
        let _ = on_progress.call2(
            &JsValue::NULL,
            &JsValue::from_f64(done as f64),
            &JsValue::from_f64(total as f64),
        );
    };
    let out = recipes::run_with_progress(id, &args, files, &mut report)
        .map_err(|e| JsError::new(&e.to_string()))?;
    serde_wasm_bindgen::to_value(&JsRun::from(out)).map_err(|e| JsError::new(&e.to_string()))
}

/// `planRecipe(id, args, inputs?)`: the rows of work of a run, without running it (argument
/// errors are thrown as `runRecipe` would).
#[wasm_bindgen(js_name = planRecipe)]
pub fn plan_recipe(
    id: &str,
    args: Vec<String>,
    inputs: Option<js_sys::Object>,
) -> Result<f64, JsError> {
    let plan =
        recipes::plan(id, &args, input_files(inputs)).map_err(|e| JsError::new(&e.to_string()))?;
    Ok(plan.rows as f64)
}

/// A limit as JS sees it: `{ value, inclusive }`, or `null` for none.
#[derive(Serialize)]
struct JsBound {
    value: f64,
    inclusive: bool,
}

fn js_bound(b: Bound) -> Option<JsBound> {
    match b {
        Bound::None => None,
        Bound::Incl(value) => Some(JsBound {
            value,
            inclusive: true,
        }),
        Bound::Excl(value) => Some(JsBound {
            value,
            inclusive: false,
        }),
    }
}

/// `listRecipes()`: every recipe's facts, in the order of the BSV page: `{ id, python, args,
/// flags, writes, quirksId, page, titleId, blurbId }` with each argument as `{ name, default,
/// help, kind ("number" | "integer" | "seed" | "list" | "file" | "choice" | "points"), len (lists),
/// choices, unit, min, max ({ value, inclusive } or null), hintId, labelId, repeat (a flag that
/// may be given several times) }`.
#[wasm_bindgen(js_name = listRecipes)]
pub fn list_recipes() -> Result<JsValue, JsError> {
    #[derive(Serialize)]
    #[serde(rename_all = "camelCase")]
    struct Arg {
        name: &'static str,
        default: &'static str,
        help: &'static str,
        kind: &'static str,
        len: Option<usize>,
        choices: &'static [&'static str],
        unit: Option<&'static str>,
        min: Option<JsBound>,
        max: Option<JsBound>,
        hint_id: &'static str,
        label_id: String,
        repeat: bool,
    }
    #[derive(Serialize)]
    #[serde(rename_all = "camelCase")]
    struct Info {
        id: &'static str,
        python: &'static str,
        args: Vec<Arg>,
        flags: Vec<Arg>,
        writes: &'static [&'static str],
        quirks_id: &'static str,
        page: Option<&'static str>,
        title_id: String,
        blurb_id: String,
    }
    let arg = |recipe: &str, a: &ArgSpec, flag: bool| {
        let (kind, len, choices): (_, _, &'static [&'static str]) = match a.kind {
            ArgKind::Number => ("number", None, &[]),
            ArgKind::Integer => ("integer", None, &[]),
            ArgKind::Seed => ("seed", None, &[]),
            ArgKind::List { len } => ("list", Some(len), &[]),
            ArgKind::File => ("file", None, &[]),
            ArgKind::Choice(c) => ("choice", None, c),
            ArgKind::Points => ("points", None, &[]),
        };
        Arg {
            name: a.name,
            default: a.default,
            help: a.help,
            kind,
            len,
            choices,
            unit: a.unit,
            min: js_bound(a.min),
            max: js_bound(a.max),
            hint_id: a.hint_id,
            label_id: a.label_id(recipe, flag),
            repeat: a.repeat,
        }
    };
    let list: Vec<Info> = recipes::RECIPES
        .iter()
        .map(|r| Info {
            id: r.info.id,
            python: r.info.python,
            args: r
                .info
                .args
                .iter()
                .map(|a| arg(r.info.id, a, false))
                .collect(),
            flags: r
                .info
                .flags
                .iter()
                .map(|a| arg(r.info.id, a, true))
                .collect(),
            writes: r.info.writes,
            quirks_id: r.info.quirks_id,
            page: r.info.page,
            title_id: r.info.title_id(),
            blurb_id: r.info.blurb_id(),
        })
        .collect();
    Ok(serde_wasm_bindgen::to_value(&list)?)
}

/// `new RrtHandle(args)`: the rrt-2d tree grown step by step, backwards too (for the RRT
/// page), with the recipe's own arguments and options (`["7", "800", "--obstacle",
/// "0.2,0.2,0.4,0.6", "--goal", "0.9,0.5"]`). The finished tree is identical to
/// `runRecipe("rrt-2d", args)`'s, and the state at any iteration to that of a run stopped
/// there.
#[wasm_bindgen]
pub struct RrtHandle {
    rrt: rrt_2d::Rrt,
}

/// The sub-steps of one iteration, as JS sees it (`RrtHandle.record()`).
#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct JsIteration {
    iteration: usize,
    sample: [f64; 2],
    goal_sample: bool,
    nearest: usize,
    from: [f64; 2],
    distance: f64,
    candidate: Option<[f64; 2]>,
    /// The 12 check points, flat `[x0, y0, ...]`, when the segment check ran.
    checks: Option<Vec<f64>>,
    /// Index (0..12) of the first colliding check point, and the box (0-based) it is in.
    hit_point: Option<usize>,
    hit_obstacle: Option<usize>,
    to_goal: Option<f64>,
    /// Within the goal tolerance: whether the segment to the goal was clear.
    goal_clear: Option<bool>,
    /// `added` | `out-of-square` | `collision` | `zero-length` | `goal-reached`.
    outcome: &'static str,
    /// The node added (and the goal node when reached).
    node: Option<usize>,
    goal_node: Option<usize>,
}

#[wasm_bindgen]
impl RrtHandle {
    #[wasm_bindgen(constructor)]
    pub fn new(args: Vec<String>) -> Result<RrtHandle, JsError> {
        let setup = rrt_2d::setup_from_args(&recipes::parse_args(rrt_2d::INFO.id, &args)?)?;
        Ok(RrtHandle {
            rrt: rrt_2d::Rrt::with_setup(&setup)?,
        })
    }

    /// Runs up to `iterations` more iterations (fewer when the goal is reached or the budget
    /// is spent); returns the number of nodes.
    pub fn step(&mut self, iterations: u32) -> usize {
        for _ in 0..iterations {
            if self.rrt.step_record().is_none() {
                break;
            }
        }
        self.rrt.nodes().len()
    }

    /// Goes to the state after iteration `k` (0 = only the start; backwards exactly, by an
    /// RNG checkpoint and a replay of at most 64 iterations); returns the iteration reached
    /// (less than `k` when the run ends first).
    pub fn seek(&mut self, k: u32) -> usize {
        self.rrt.seek(k as usize)
    }

    /// Steps back `n` iterations; returns the iteration reached.
    pub fn back(&mut self, n: u32) -> usize {
        self.rrt.back(n as usize)
    }

    /// The sub-steps of the last iteration run, or `null` at iteration 0: `{ iteration,
    /// sample: [x, y], goalSample, nearest, from: [x, y], distance, candidate: [x, y] | null,
    /// checks: [x0, y0, ... x11, y11] | null, hitPoint, hitObstacle, toGoal, goalClear,
    /// outcome, node, goalNode }`.
    pub fn record(&self) -> Result<JsValue, JsError> {
        let Some(r) = self.rrt.last() else {
            return Ok(JsValue::NULL);
        };
        let (node, goal_node) = match r.outcome {
            rrt_2d::RrtOutcome::Added { id } => (Some(id), None),
            rrt_2d::RrtOutcome::GoalReached { id, goal_id } => (Some(id), Some(goal_id)),
            _ => (None, None),
        };
        let js = JsIteration {
            iteration: r.iteration,
            sample: r.sample,
            goal_sample: r.goal_sample,
            nearest: r.nearest,
            from: r.from,
            distance: r.distance,
            candidate: r.candidate,
            checks: r
                .checked
                .then(|| r.check_points())
                .flatten()
                .map(|points| points.iter().flatten().copied().collect()),
            hit_point: r.hit.map(|h| h.point),
            hit_obstacle: r.hit.map(|h| h.obstacle),
            to_goal: r.to_goal,
            goal_clear: r.goal_hit.map(|h| h.is_none()),
            outcome: r.outcome.name(),
            node,
            goal_node,
        };
        Ok(serde_wasm_bindgen::to_value(&js)?)
    }

    /// Iterations by outcome so far: `[added, outOfSquare, collision, zeroLength]` (a
    /// `Uint32Array`).
    pub fn counts(&self) -> Vec<u32> {
        let c = self.rrt.counts();
        [c.added, c.out_of_square, c.collision, c.zero_length]
            .iter()
            .map(|&v| u32::try_from(v).unwrap_or(u32::MAX))
            .collect()
    }

    /// Number of nodes.
    #[wasm_bindgen(js_name = nodeCount)]
    pub fn node_count(&self) -> usize {
        self.rrt.nodes().len()
    }

    /// Node positions, flat: `[x0, y0, x1, y1, ...]` (a `Float64Array`).
    pub fn nodes(&self) -> Vec<f64> {
        self.rrt.nodes().iter().flatten().copied().collect()
    }

    /// Nodes from index `from` on, flat (for drawing only the new edges).
    #[wasm_bindgen(js_name = nodesFrom)]
    pub fn nodes_from(&self, from: usize) -> Vec<f64> {
        let nodes = self.rrt.nodes();
        nodes[from.min(nodes.len())..]
            .iter()
            .flatten()
            .copied()
            .collect()
    }

    /// Parent of each node, `-1` for the root (an `Int32Array`).
    pub fn parents(&self) -> Vec<i32> {
        self.parents_from(0)
    }

    /// Parents from node `from` on (an `Int32Array`).
    #[wasm_bindgen(js_name = parentsFrom)]
    pub fn parents_from(&self, from: usize) -> Vec<i32> {
        let parents = self.rrt.parents();
        parents[from.min(parents.len())..]
            .iter()
            .map(|p| p.and_then(|i| i32::try_from(i).ok()).unwrap_or(-1))
            .collect()
    }

    /// The start-to-goal path, flat like `nodes` (empty until the goal is reached).
    pub fn path(&self) -> Vec<f64> {
        self.rrt.path().iter().flatten().copied().collect()
    }

    /// The path's length (NaN until the goal is reached).
    #[wasm_bindgen(js_name = pathLength)]
    pub fn path_length(&self) -> f64 {
        self.rrt.path_length()
    }

    /// The obstacle boxes, flat `[x0, y0, x1, y1, ...]` (a `Float64Array`).
    pub fn obstacles(&self) -> Vec<f64> {
        self.rrt
            .world()
            .obstacles
            .iter()
            .flat_map(|b| b.corners())
            .collect()
    }

    /// `[start x, start y, goal x, goal y, step, goal bias, goal tolerance, max_iter]` (a
    /// `Float64Array`).
    pub fn world(&self) -> Vec<f64> {
        let w = self.rrt.world();
        let g = self.rrt.goal();
        vec![
            w.start[0],
            w.start[1],
            g[0],
            g[1],
            w.step,
            w.goal_bias,
            w.goal_tol,
            self.rrt.max_iter() as f64,
        ]
    }

    /// Iterations run so far.
    pub fn iterations(&self) -> usize {
        self.rrt.iterations()
    }

    /// Whether no further iteration will run.
    pub fn done(&self) -> bool {
        self.rrt.is_done()
    }

    /// Whether the goal was reached.
    pub fn found(&self) -> bool {
        self.rrt.found().is_some()
    }

    /// The recipe's files and summary for the tree as it is now, like `runRecipe`.
    pub fn output(&self) -> Result<JsValue, JsError> {
        Ok(serde_wasm_bindgen::to_value(&JsRun::from(rrt_2d::output(
            &self.rrt,
        )))?)
    }
}

/// `new PendulumHandle(args)`: the pendulum-energy simulation advanced frame by frame, with the
/// recipe's own arguments and options (`["5", "--integrator", "rk4"]`).
#[wasm_bindgen]
pub struct PendulumHandle {
    pendulum: pendulum_energy::Pendulum,
}

/// Values per row of [`PendulumHandle::advance`].
pub const PENDULUM_ROW_LEN: usize = 7;

#[wasm_bindgen]
impl PendulumHandle {
    #[wasm_bindgen(constructor)]
    pub fn new(args: Vec<String>) -> Result<PendulumHandle, JsError> {
        let raw = recipes::parse_args(pendulum_energy::INFO.id, &args)?;
        let params = pendulum_energy::PendulumParams::from_args(&raw)?;
        params.validate()?;
        Ok(PendulumHandle {
            pendulum: pendulum_energy::Pendulum::new(&params)?,
        })
    }

    /// Takes `steps` integrator steps; returns their rows flat, 7 values each:
    /// `t_s, theta, omega, ke, pe, total` (the recipe's columns) and the true rigid-body
    /// energy (a `Float64Array`).
    pub fn advance(&mut self, steps: u32) -> Vec<f64> {
        let mut out = Vec::with_capacity(steps as usize * PENDULUM_ROW_LEN);
        for _ in 0..steps {
            let r = self.pendulum.step();
            out.extend_from_slice(&[r.t_s, r.theta, r.omega, r.ke, r.pe, r.total, r.true_energy]);
        }
        out
    }

    /// Current angle from hanging down, radians.
    pub fn theta(&self) -> f64 {
        self.pendulum.theta()
    }

    /// Current angular velocity, rad/s.
    pub fn omega(&self) -> f64 {
        self.pendulum.omega()
    }

    /// Simulated time, seconds.
    #[wasm_bindgen(js_name = timeS)]
    pub fn time_s(&self) -> f64 {
        self.pendulum.time_s()
    }
}

/// `benchCase(index, reps, kernelOnly)`: runs `bench::CASES[index]` `reps` times (the typed
/// kernel only, or the whole recipe with CSV text), returning the times in milliseconds (only
/// in builds with the `bench` feature, for `make bench`).
#[cfg(feature = "bench")]
#[wasm_bindgen(js_name = benchCase)]
pub fn bench_case(index: usize, reps: u32, kernel_only: bool) -> Result<Vec<f64>, JsError> {
    let case = crate::bench::CASES
        .get(index)
        .ok_or_else(|| JsError::new("no such case"))?;
    let no_clock = |_| JsError::new("no performance.now");
    let perf = js_sys::Reflect::get(&js_sys::global(), &"performance".into()).map_err(no_clock)?;
    let now_fn: js_sys::Function = js_sys::Reflect::get(&perf, &"now".into())
        .map_err(no_clock)?
        .unchecked_into();
    let now = || {
        now_fn
            .call0(&perf)
            .ok()
            .and_then(|v| v.as_f64())
            .unwrap_or(f64::NAN)
    };
    let mut times = Vec::new();
    for _ in 0..reps {
        let inputs = crate::bench::inputs(case);
        let start = now();
        if kernel_only {
            (case.kernel)(&inputs).map_err(|e| JsError::new(&e.to_string()))?;
        } else {
            crate::bench::run(case, inputs).map_err(|e| JsError::new(&e.to_string()))?;
        }
        times.push(now() - start);
    }
    Ok(times)
}

/// `benchCaseNames()`: the names of the benchmark cases, in order.
#[cfg(feature = "bench")]
#[wasm_bindgen(js_name = benchCaseNames)]
pub fn bench_case_names() -> Vec<String> {
    crate::bench::CASES
        .iter()
        .map(|c| c.name.to_string())
        .collect()
}
