//! Recipe `traj-resample`: PLACEHOLDER until its kernel lands (replace this whole file).

use super::{RecipeInfo, RecipeOutput};
use crate::args::Args;
use crate::error::RecipeError;

pub const INFO: RecipeInfo = RecipeInfo {
    id: "traj-resample",
    python: "TODO.py",
    args: &[],
    flags: &[],
    writes: &[],
};

pub fn run_args(_args: &Args) -> Result<RecipeOutput, RecipeError> {
    Err(RecipeError::UnknownRecipe {
        id: INFO.id.to_string(),
    })
}
