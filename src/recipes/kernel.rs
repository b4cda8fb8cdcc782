//! The one shape of every recipe ([`Kernel`]: parse and validate, plan, run with progress),
//! the generic entry points built from it, and the progress of a run.

use super::info::RecipeInfo;
use super::output::RecipeOutput;
use super::picture::Picture;
use crate::args::{Args, Plan};
use crate::error::RecipeError;
use crate::pyfmt::CsvText;

/// Progress of a run: `report(done, total)` rows of work, called at most every ~1 % of
/// `total` (and once at the end). Counting never changes what a recipe computes.
pub struct Progress<'a> {
    report: Option<&'a mut dyn FnMut(u64, u64)>,
    total: u64,
    every: u64,
    next: u64,
}

impl<'a> Progress<'a> {
    /// Reports to `report`, `total` rows of work in all.
    pub fn new(report: &'a mut dyn FnMut(u64, u64), total: u64) -> Progress<'a> {
        let every = total.div_ceil(100).max(1);
        Progress {
            report: Some(report),
            total,
            every,
            next: every,
        }
    }

    /// Reports nothing (the plain `run`).
    pub fn silent() -> Progress<'static> {
        Progress {
            report: None,
            total: 0,
            every: u64::MAX,
            next: u64::MAX,
        }
    }

    /// The total rows of work.
    pub fn total(&self) -> u64 {
        self.total
    }

    /// `done` rows of work are done; reports when another ~1 % has passed.
    #[inline]
    pub fn at(&mut self, done: u64) {
        if done >= self.next {
            self.next = done.saturating_add(self.every);
            if let Some(report) = self.report.as_mut() {
                report(done.min(self.total), self.total);
            }
        }
    }

    /// Row `k` of `n` of phase `phase` (0-based) of `phases` equal phases (e.g. computing the
    /// rows, then writing their CSV text).
    #[inline]
    pub fn phase_at(&mut self, phase: u64, phases: u64, k: u64, n: u64) {
        if self.report.is_some() && n > 0 && phases > 0 {
            let share = self.total as f64 / phases as f64;
            let done = share * phase as f64 + share * (k as f64 / n as f64);
            self.at(done as u64);
        }
    }

    /// The run is over: reports `total` of `total`.
    pub fn finish(&mut self) {
        if let Some(report) = self.report.as_mut() {
            report(self.total, self.total);
        }
        self.next = u64::MAX;
    }
}

/// The one shape of every recipe: parse and validate the arguments, estimate the work, run
/// with progress. A module implements it on a unit struct `Entry`; its [`Recipe`] and its
/// `INFO.plan` are instances of the generic functions below.
pub trait Kernel {
    /// The recipe's facts.
    const INFO: &'static RecipeInfo;
    /// The typed, validated arguments.
    type Params;
    /// Parses and validates: every argument error a run would give, before any work.
    fn params(args: &Args) -> Result<Self::Params, RecipeError>;
    /// Rows of work of a run with `params` (`args` holds attached inputs).
    fn rows(params: &Self::Params, args: &Args) -> Result<u64, RecipeError>;
    /// Runs, reporting rows done to `progress` (total = [`Kernel::rows`]).
    fn run(params: &Self::Params, args: &Args, progress: &mut Progress) -> RunResult;
}

/// What a run gives: the recipe's files and summary, or why it could not run.
pub type RunResult = Result<RecipeOutput, RecipeError>;

/// [`Kernel::params`] then [`Kernel::rows`].
pub fn plan_of<K: Kernel>(args: &Args) -> Result<Plan, RecipeError> {
    let rows = K::rows(&K::params(args)?, args)?;
    Ok(Plan { rows })
}

/// A run without progress.
pub fn run_of<K: Kernel>(args: &Args) -> Result<RecipeOutput, RecipeError> {
    K::run(&K::params(args)?, args, &mut Progress::silent())
}

/// A run reporting `progress(done, total)` rows (total from [`Kernel::rows`]).
pub fn run_progress_of<K: Kernel>(
    args: &Args,
    progress: &mut dyn FnMut(u64, u64),
) -> Result<RecipeOutput, RecipeError> {
    let params = K::params(args)?;
    let rows = K::rows(&params, args)?;
    let mut tracker = Progress::new(progress, rows.max(1));
    let out = K::run(&params, args, &mut tracker)?;
    tracker.finish();
    Ok(out)
}

/// A run reporting `progress(done, total)` rows of work.
pub type RunWithProgress = fn(&Args, &mut dyn FnMut(u64, u64)) -> Result<RecipeOutput, RecipeError>;

/// A recipe: its facts and its entry points (instances of [`run_of`] / [`run_progress_of`]).
#[derive(Debug, Clone, Copy)]
pub struct Recipe {
    pub info: &'static RecipeInfo,
    pub run: fn(&Args) -> Result<RecipeOutput, RecipeError>,
    pub run_progress: RunWithProgress,
    /// The home card's picture of a run's output, for a canvas `aspect` (width / height)
    /// wide (`None` for an output without the expected columns).
    pub picture: fn(&RecipeOutput, f64) -> Option<Picture>,
}

impl Recipe {
    /// The recipe of kernel `K`, with its home card's `picture`.
    pub const fn of<K: Kernel>(picture: fn(&RecipeOutput, f64) -> Option<Picture>) -> Recipe {
        Recipe {
            info: K::INFO,
            run: run_of::<K>,
            run_progress: run_progress_of::<K>,
            picture,
        }
    }
}

/// A run from command-line style arguments and the input files `(name, text)` its path
/// arguments name: what `bsv <id> <args>` writes (an instance of [`run_raw_of`]).
pub type RunRaw = fn(&[String], Vec<(String, String)>) -> Result<RecipeOutput, RecipeError>;

/// A page's own recipe: its facts and its kernel's run (and no other kernel).
#[derive(Debug, Clone, Copy)]
pub struct PageRecipe {
    pub info: &'static RecipeInfo,
    pub run: RunRaw,
}

impl PageRecipe {
    /// The recipe of kernel `K`.
    pub const fn of<K: Kernel>() -> PageRecipe {
        PageRecipe {
            info: K::INFO,
            run: run_raw_of::<K>,
        }
    }
}

/// Runs kernel `K` on command-line style arguments and input files: how a page reaches its
/// own kernel, and no other.
pub fn run_raw_of<K: Kernel>(
    raw: &[String],
    inputs: Vec<(String, String)>,
) -> Result<RecipeOutput, RecipeError> {
    run_of::<K>(&K::INFO.parse(raw)?.with_inputs(inputs))
}

/// A CSV of `header` and one row of floats (as Python prints them) per item of `rows`,
/// reporting its rows as the second half of `progress`: the writing phase of a run that
/// computes its rows first.
pub fn float_csv_with<const N: usize>(
    header: &[&str],
    rows: impl ExactSizeIterator<Item = [f64; N]>,
    progress: &mut Progress,
) -> String {
    let mut csv = CsvText::with_header(header);
    let n = rows.len() as u64;
    for (k, row) in rows.enumerate() {
        progress.phase_at(1, 2, k as u64, n);
        csv.floats(&row);
    }
    csv.finish()
}
