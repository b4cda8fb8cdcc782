//! The twelve BSV recipes, one module each: a parameter struct with the recipe's defaults,
//! validation, a typed run, and the CSV table(s) plus the summary line the Python recipe prints.
//!
//! Every recipe is reached the same way from the CLI, from `runRecipe` and from the tests:
//! [`run`] with the recipe id and command-line style arguments.

use crate::args::{ArgSpec, Args};
use crate::error::RecipeError;

pub mod cubic_path;
pub mod dh_fk;
pub mod ik_workspace;
pub mod jacobian_2r;
pub mod manip_grid;
pub mod pendulum_energy;
pub mod pid_step;
pub mod rrt_2d;
pub mod se3_relative;
pub mod traj_resample;
pub mod trapezoid_profile;
pub mod umeyama_2d;

/// What a recipe is called, which Python script it mirrors, and what it takes and writes.
#[derive(Debug, Clone, Copy)]
pub struct RecipeInfo {
    /// Recipe id, as on the command line (`ik-workspace`).
    pub id: &'static str,
    /// The Python recipe's file name.
    pub python: &'static str,
    /// Positional arguments in order, with the recipe's defaults.
    pub args: &'static [ArgSpec],
    /// `--flag value` options beyond the recipe (empty for most).
    pub flags: &'static [ArgSpec],
    /// The CSV file names it writes.
    pub writes: &'static [&'static str],
}

/// One CSV file a recipe writes.
#[derive(Debug, Clone, PartialEq)]
pub struct CsvFile {
    pub name: String,
    pub text: String,
}

/// The files and the printed summary of one recipe run.
#[derive(Debug, Clone, PartialEq)]
pub struct RecipeOutput {
    pub files: Vec<CsvFile>,
    /// Exactly what the Python recipe prints (lines joined with `\n`, no trailing newline).
    pub summary: String,
}

impl RecipeOutput {
    /// A run that wrote one file.
    pub fn single(name: &str, text: String, summary: String) -> RecipeOutput {
        RecipeOutput {
            files: vec![CsvFile {
                name: name.to_string(),
                text,
            }],
            summary,
        }
    }

    /// The text of the file called `name`, if the run wrote it.
    pub fn file(&self, name: &str) -> Option<&str> {
        self.files
            .iter()
            .find(|f| f.name == name)
            .map(|f| f.text.as_str())
    }
}

/// A recipe: its description and its entry point.
#[derive(Clone, Copy)]
pub struct Recipe {
    pub info: &'static RecipeInfo,
    pub run: fn(&Args) -> Result<RecipeOutput, RecipeError>,
}

/// All recipes, in the order of the BSV page.
pub const RECIPES: [Recipe; 12] = [
    Recipe {
        info: &pendulum_energy::INFO,
        run: pendulum_energy::run_args,
    },
    Recipe {
        info: &ik_workspace::INFO,
        run: ik_workspace::run_args,
    },
    Recipe {
        info: &traj_resample::INFO,
        run: traj_resample::run_args,
    },
    Recipe {
        info: &dh_fk::INFO,
        run: dh_fk::run_args,
    },
    Recipe {
        info: &jacobian_2r::INFO,
        run: jacobian_2r::run_args,
    },
    Recipe {
        info: &cubic_path::INFO,
        run: cubic_path::run_args,
    },
    Recipe {
        info: &se3_relative::INFO,
        run: se3_relative::run_args,
    },
    Recipe {
        info: &rrt_2d::INFO,
        run: rrt_2d::run_args,
    },
    Recipe {
        info: &pid_step::INFO,
        run: pid_step::run_args,
    },
    Recipe {
        info: &manip_grid::INFO,
        run: manip_grid::run_args,
    },
    Recipe {
        info: &trapezoid_profile::INFO,
        run: trapezoid_profile::run_args,
    },
    Recipe {
        info: &umeyama_2d::INFO,
        run: umeyama_2d::run_args,
    },
];

/// The recipe with this id.
pub fn find(id: &str) -> Option<&'static Recipe> {
    RECIPES.iter().find(|r| r.info.id == id)
}

/// Runs recipe `id` with command-line style arguments.
///
/// # Example
/// ```
/// let out = bsv_playground::recipes::run("pid-step", &[]).unwrap();
/// assert_eq!(out.summary, "wrote 80 PID samples final_y=0.7967 -> pid_step.csv");
/// ```
pub fn run(id: &str, raw: &[String]) -> Result<RecipeOutput, RecipeError> {
    run_with_inputs(id, raw, Vec::new())
}

/// Parses command-line style arguments for recipe `id` (for handles that take the recipe's
/// arguments, such as the wasm `RrtHandle`).
pub fn parse_args(id: &str, raw: &[String]) -> Result<Args, RecipeError> {
    let recipe = find(id).ok_or_else(|| RecipeError::UnknownRecipe { id: id.to_string() })?;
    Args::parse(raw, recipe.info.args, recipe.info.flags)
}

/// [`run`] with string slices, for the recipes' unit tests.
#[cfg(test)]
pub(crate) fn run_strs(id: &str, raw: &[&str]) -> Result<RecipeOutput, RecipeError> {
    run(id, &strings(raw))
}

/// [`parse_args`] with string slices, for the recipes' unit tests.
#[cfg(test)]
pub(crate) fn args_strs(id: &str, raw: &[&str]) -> Result<Args, RecipeError> {
    parse_args(id, &strings(raw))
}

#[cfg(test)]
fn strings(raw: &[&str]) -> Vec<String> {
    raw.iter().map(|s| s.to_string()).collect()
}

/// Runs recipe `id` with arguments and input files `(name, text)` that path arguments name
/// (traj-resample's CSV).
pub fn run_with_inputs(
    id: &str,
    raw: &[String],
    inputs: Vec<(String, String)>,
) -> Result<RecipeOutput, RecipeError> {
    let recipe = find(id).ok_or_else(|| RecipeError::UnknownRecipe { id: id.to_string() })?;
    (recipe.run)(&parse_args(id, raw)?.with_inputs(inputs))
}
