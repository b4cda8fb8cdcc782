//! The page's downloads: the three recipe CSVs for the current parameters, made by the same
//! code path as `bsv <recipe-id> <args>` (so the bytes are the CLI's), the equivalent command
//! lines (Python recipe and `bsv`) with copy buttons, and the arm view as PNG.

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;

use super::state::{num, Params};
use crate::error::RecipeError;

/// One CSV the page offers.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Export {
    /// File name (also the button's `data-download`).
    pub file: &'static str,
    /// Recipe id on the command line.
    pub recipe: &'static str,
}

/// The page's CSVs, in the order of the panel.
pub const EXPORTS: [Export; 3] = [
    Export {
        file: "ik_workspace.csv",
        recipe: "ik-workspace",
    },
    Export {
        file: "jacobian_2r.csv",
        recipe: "jacobian-2r",
    },
    Export {
        file: "manip_ellipse.csv",
        recipe: "manip-grid",
    },
];

/// File name of the arm view PNG.
pub const ARM_PNG: &str = "ik_2r_arm.png";

/// The positional arguments of `export` for parameters `p` and the current `q2` (the
/// Jacobian sweep is taken at the pose's q2).
pub fn args(export: &Export, p: &Params, q2: f64) -> Vec<String> {
    match export.recipe {
        "ik-workspace" => vec![num(p.l1), num(p.l2), num(p.half_mm), num(p.step_mm)],
        "jacobian-2r" => vec![
            num(p.l1),
            num(p.l2),
            num(p.q1_start),
            num(p.q1_stop),
            num(p.q1_step),
            num(q2),
        ],
        _ => vec![num(p.l1), num(p.l2), p.manip_n.to_string()],
    }
}

/// The CSV text, exactly as `bsv <recipe> <args>` writes it.
pub fn csv(export: &Export, p: &Params, q2: f64) -> Result<String, RecipeError> {
    let out = crate::recipes::run(export.recipe, &args(export, p, q2))?;
    out.file(export.file)
        .map(str::to_string)
        .ok_or_else(|| RecipeError::UnknownRecipe {
            id: export.recipe.to_string(),
        })
}

/// The equivalent command lines: `python <script> <args>` and `bsv <recipe> <args>`.
pub fn commands(export: &Export, p: &Params, q2: f64) -> (String, String) {
    let args = args(export, p, q2).join(" ");
    let script = crate::recipes::find(export.recipe).map_or("", |r| r.info.python);
    (
        format!("python {script} {args}"),
        format!("bsv {} {args}", export.recipe),
    )
}

/// Copies `text` to the clipboard; calls `done(true)` on success, `done(false)` when neither
/// the Clipboard API nor the `execCommand("copy")` fallback worked (the caller then selects
/// the text so that the user can copy it by hand).
pub fn copy_text(text: &str, done: impl Fn(bool) + 'static) {
    let Some(window) = web_sys::window() else {
        done(false);
        return;
    };
    let navigator = window.navigator();
    let has_clipboard = js_sys::Reflect::get(&navigator, &JsValue::from_str("clipboard"))
        .map(|c| !c.is_undefined() && !c.is_null())
        .unwrap_or(false);
    if has_clipboard {
        let promise = navigator.clipboard().write_text(text);
        let done = std::rc::Rc::new(done);
        let text = text.to_string();
        let ok = {
            let done = done.clone();
            Closure::once_into_js(move |_: JsValue| done(true))
        };
        let fail = Closure::once_into_js(move |_: JsValue| done(exec_copy(&text)));
        // promise.then(ok, fail), called through Reflect to stay independent of js-sys's
        // generic Promise signatures.
        let then = js_sys::Reflect::get(&promise, &JsValue::from_str("then"))
            .ok()
            .and_then(|f| f.dyn_into::<js_sys::Function>().ok());
        if let Some(then) = then {
            let _ = then.call2(&promise, &ok, &fail);
        }
    } else {
        done(exec_copy(text));
    }
}

/// `document.execCommand("copy")` on a temporary input holding `text`.
fn exec_copy(text: &str) -> bool {
    let Some(document) = web_sys::window().and_then(|w| w.document()) else {
        return false;
    };
    let Some(body) = document.body() else {
        return false;
    };
    let Ok(input) = document
        .create_element("input")
        .map(|e| e.unchecked_into::<web_sys::HtmlInputElement>())
    else {
        return false;
    };
    input.set_value(text);
    let _ = input.set_attribute("readonly", "");
    let _ = input.set_attribute("style", "position:fixed;left:-9999px;top:0");
    if body.append_child(&input).is_err() {
        return false;
    }
    input.select();
    let copied = js_sys::Reflect::get(&document, &JsValue::from_str("execCommand"))
        .ok()
        .and_then(|f| f.dyn_into::<js_sys::Function>().ok())
        .and_then(|f| f.call1(&document, &JsValue::from_str("copy")).ok())
        .and_then(|v| v.as_bool())
        .unwrap_or(false);
    input.remove();
    copied
}
