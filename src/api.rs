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
