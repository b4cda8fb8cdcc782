//! A run too big for one frame: the kernel's rows pulled a slice per animation frame (at most
//! [`SLICE_MS`] each), the last run staying on the plot and in the readouts meanwhile, and the
//! line under the plot that says how far it is.

use crate::ui::ctx;
use crate::ui::schedule::now_ms;
use crate::view::progress::group_digits;

/// Runs of more rows than this are computed a slice per animation frame, a newer big change
/// computed after the one under way (only the latest kept), a newer small one replacing it.
/// Smaller runs are recomputed within the input's frame (about 15 ms at this size: kernel,
/// readouts and plot).
pub const LIVE_ROWS: u64 = 150_000;
/// The kernel work of one slice, ms.
pub const SLICE_MS: f64 = 8.0;
/// Rows pulled between two looks at the clock.
const CLOCK_EVERY: usize = 2048;

/// The kernel's rows of one run, yielded one at a time, and how many there are (about: the
/// recipe's own estimate).
pub type Rows<R> = (Box<dyn Iterator<Item = R>>, u64);

/// [`Rows`] of a kernel's iterator and its row count.
pub fn boxed<I: Iterator + 'static>((rows, total): (I, u64)) -> Rows<I::Item> {
    (Box::new(rows), total)
}

/// Where a run comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RunFrom {
    /// The page's first run (the URL's arguments).
    Mount,
    /// A change, computed within its input's frame.
    Input,
    /// A change computed in slices, shown once finished (the input may be over).
    Slices,
}

/// A run being computed in slices.
pub struct Sliced<P, R> {
    pub params: P,
    source: Box<dyn Iterator<Item = R>>,
    pub rows: Vec<R>,
    pub total: u64,
    pub from: RunFrom,
    /// The latest big change that came meanwhile: computed once this run is shown.
    pub next: Option<P>,
}

impl<P, R> Sliced<P, R> {
    /// The run of `params` whose rows `source` yields (`total` of them); a change's run is
    /// [`RunFrom::Slices`].
    pub fn new(params: P, (source, total): Rows<R>, from: RunFrom) -> Sliced<P, R> {
        Sliced {
            params,
            source,
            rows: Vec::with_capacity(total as usize),
            total,
            from: if from == RunFrom::Mount {
                from
            } else {
                RunFrom::Slices
            },
            next: None,
        }
    }

    /// Pulls rows until the slice begun at `t0` (ms) is spent; whether the run is complete.
    pub fn pull(&mut self, t0: f64) -> bool {
        while now_ms() - t0 < SLICE_MS {
            for _ in 0..CLOCK_EVERY {
                match self.source.next() {
                    Some(row) => self.rows.push(row),
                    None => return true,
                }
            }
        }
        false
    }

    /// The line under the plot: how many rows, how far.
    pub fn progress(&self) -> String {
        let done = self.rows.len() as f64;
        let pct = (done / self.total.max(1) as f64 * 100.0).floor().min(99.0);
        ctx::t_strings(
            "signals-computing",
            &[
                ("rows", group_digits(self.total)),
                ("percent", format!("{pct:.0}")),
            ],
        )
    }
}
