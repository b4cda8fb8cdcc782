//! What the recipes' unit tests share: running a kernel from string slices, checking that the
//! defaults live in one place, and that a rejection names the right argument.
//!
//! The test modules alias `wasm_bindgen_test` as `test` under wasm32, so the same tests run
//! natively and, under `wasm-pack test --node`, as wasm.

use std::fmt::Debug;

use super::kernel::{run_of, Kernel};
use super::output::RecipeOutput;
use crate::args::Args;
use crate::error::RecipeError;

pub(crate) fn strings(raw: &[&str]) -> Vec<String> {
    raw.iter().map(|s| s.to_string()).collect()
}

/// Kernel `K`'s arguments parsed from string slices, as its command line parses them.
pub(crate) fn args_strs<K: Kernel>(raw: &[&str]) -> Result<Args, RecipeError> {
    Args::parse(&strings(raw), K::INFO.args, K::INFO.flags)
}

/// A run of kernel `K` with arguments from string slices.
pub(crate) fn run_strs<K: Kernel>(raw: &[&str]) -> Result<RecipeOutput, RecipeError> {
    run_of::<K>(&args_strs::<K>(raw)?)
}

/// The recipe's arguments left off give its `Params::default()`: the defaults are stated once
/// (the `ArgSpec` defaults and `Default` agree).
pub(crate) fn assert_defaults_in_one_place<K: Kernel>()
where
    K::Params: Default + PartialEq + Debug,
{
    assert_eq!(K::params(&Args::default()).unwrap(), K::Params::default());
}

/// Kernel `K` rejects `raw` with an error that `ok` accepts, naming `param` first.
pub(crate) fn assert_rejects<K: Kernel>(raw: &[&str], param: &str, ok: fn(&RecipeError) -> bool) {
    let e = run_strs::<K>(raw).unwrap_err();
    assert!(ok(&e), "{} {raw:?}: {e:?}", K::INFO.id);
    assert_eq!(e.param(), Some(param), "{} {raw:?}", K::INFO.id);
}
