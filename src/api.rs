//! The `#[wasm_bindgen]` surface of the kernels: thin and typed; every error becomes a JS
//! `Error` whose message is the same one-liner the CLI prints.

use serde::{Deserialize, Serialize};
use wasm_bindgen::prelude::*;

use crate::recipes::{self, RecipeOutput};

/// One file of a recipe run, as JS sees it: `{ name, text }`.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct JsFile {
    pub name: String,
    pub text: String,
}

/// A recipe run, as JS sees it: `{ files: [{ name, text }], summary }`.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct JsRun {
    pub files: Vec<JsFile>,
    pub summary: String,
}

impl From<RecipeOutput> for JsRun {
    fn from(out: RecipeOutput) -> Self {
        JsRun {
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
    let mut files = Vec::new();
    if let Some(obj) = inputs {
        for entry in js_sys::Object::entries(&obj).iter() {
            let pair = js_sys::Array::from(&entry);
            if let (Some(name), Some(text)) = (pair.get(0).as_string(), pair.get(1).as_string()) {
                files.push((name, text));
            }
        }
    }
    let out =
        recipes::run_with_inputs(id, &args, files).map_err(|e| JsError::new(&e.to_string()))?;
    serde_wasm_bindgen::to_value(&JsRun::from(out)).map_err(|e| JsError::new(&e.to_string()))
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
