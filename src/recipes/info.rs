//! What a recipe is, stated once in its module's `INFO`: its id and Python script, its
//! arguments with their defaults and limits, the files it writes, its quirks and its cost. The
//! CLI's help, the pages and the home cards read it from there; its kernel and its home-card
//! picture are its [`Recipe`](super::Recipe)'s.

use crate::args::{ArgSpec, Args, Plan};
use crate::error::RecipeError;

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
    /// Fluent id (recipes.ftl) of what this port decides where the Python recipe is silent or
    /// crashes, in a sentence or two for the reader of the page: `recipe-<id>-quirks`.
    pub quirks_id: &'static str,
    /// The cost of a run with these arguments, without running it: parse + validate, then
    /// rows of work (traj-resample reads the attached input's shape, cheaply).
    pub plan: fn(&Args) -> Result<Plan, RecipeError>,
    /// Route id of the live page that runs this recipe interactively (`ik-2r`), if any.
    pub page: Option<&'static str>,
}

impl RecipeInfo {
    /// Every argument: the positional ones in order, then the `--flag` options (`true`).
    pub fn all_args(&self) -> impl Iterator<Item = (&'static ArgSpec, bool)> {
        let args: &'static [ArgSpec] = self.args;
        let flags: &'static [ArgSpec] = self.flags;
        args.iter()
            .map(|a| (a, false))
            .chain(flags.iter().map(|a| (a, true)))
    }

    /// The argument (positional or flag) called `name`, and whether it is a flag.
    pub fn arg(&self, name: &str) -> Option<(&'static ArgSpec, bool)> {
        self.all_args().find(|(a, _)| a.name == name)
    }

    /// Parses command-line style arguments as `bsv <id>` does (this recipe's arguments and
    /// flags only: a page parsing its own recipe's words reaches no other kernel).
    pub fn parse(&self, raw: &[String]) -> Result<Args, RecipeError> {
        Args::parse(raw, self.args, self.flags)
    }

    /// Fluent id of the recipe's title (recipes.ftl).
    pub fn title_id(&self) -> String {
        format!("recipe-{}-title", self.id)
    }

    /// Fluent id of the recipe's one-line description (recipes.ftl).
    pub fn blurb_id(&self) -> String {
        format!("recipe-{}-blurb", self.id)
    }
}
