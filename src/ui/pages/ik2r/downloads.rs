//! The page's downloads: the three recipe CSVs for the current parameters, made by the same
//! code path as `bsv <recipe-id> <args>` (so the bytes are the CLI's), the equivalent command
//! lines (Python recipe and `bsv`) shown with copy buttons, and the arm view as PNG.

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
