//! What the recipes' unit tests share: running a recipe from string slices, checking that the
//! defaults live in one place, and that a rejection names the right argument.

use std::fmt::Debug;

use super::{parse_args, run, Kernel};
use crate::args::Args;
use crate::error::RecipeError;

pub(crate) fn strings(raw: &[&str]) -> Vec<String> {
    raw.iter().map(|s| s.to_string()).collect()
}

/// [`super::run`] with string slices.
pub(crate) fn run_strs(id: &str, raw: &[&str]) -> Result<super::RecipeOutput, RecipeError> {
    run(id, &strings(raw))
}

/// [`super::parse_args`] with string slices.
pub(crate) fn args_strs(id: &str, raw: &[&str]) -> Result<Args, RecipeError> {
    parse_args(id, &strings(raw))
}

/// The recipe's arguments left off give its `Params::default()`: the defaults are stated once
/// (the `ArgSpec` defaults and `Default` agree).
pub(crate) fn assert_defaults_in_one_place<K: Kernel>()
where
    K::Params: Default + PartialEq + Debug,
{
    assert_eq!(K::params(&Args::default()).unwrap(), K::Params::default());
}

/// Recipe `id` rejects `raw` with an error that `ok` accepts, naming `param` first.
pub(crate) fn assert_rejects(id: &str, raw: &[&str], param: &str, ok: fn(&RecipeError) -> bool) {
    let e = run_strs(id, raw).unwrap_err();
    assert!(ok(&e), "{id} {raw:?}: {e:?}");
    assert_eq!(e.param(), Some(param), "{id} {raw:?}");
}
