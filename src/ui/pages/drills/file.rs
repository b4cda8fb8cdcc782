//! The input CSV the page holds (a file argument, traj-resample's), opened and decoded by the
//! kit's [`crate::ui::kit::input_file`] (the CLI's decoding policy).

use crate::error::RecipeError;
use crate::recipes::traj_resample::Shape;

/// Input files up to this size are attached to every check of the form (so that their errors
/// show at once and the run size is known); bigger ones are checked by the run itself.
pub const PRECHECK_MAX_BYTES: u64 = 4 * 1024 * 1024;

/// A CSV the user opened.
pub struct InputFile {
    /// The file's name (the recipe's `csv_path`).
    pub name: String,
    /// Size in bytes.
    pub bytes: u64,
    pub text: String,
    /// Its shape (rows, joint columns), read when opened.
    pub shape: Result<Shape, RecipeError>,
}
