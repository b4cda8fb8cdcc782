//! A run too big for one frame: the kernel's rows pulled a slice per animation frame (at most
//! [`SLICE_MS`] each) and thinned to the plot as they come, the last run staying on the plot
//! and in the readouts meanwhile, and the line under the plot that says how far it is.

use super::thinned::{Kept, ThinKey, ThinRow};
use crate::ui::ctx;
use crate::ui::schedule::now_ms;
use crate::view::progress::group_digits;
use crate::view::signal::ColumnsThin;

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

/// Thinnings a run being computed makes at most (a key asked for at its end is added).
const MOST_THINNINGS: usize = 4;

/// A run being computed in slices, and its summary `M` once computed.
pub struct Sliced<P, R, M> {
    pub params: P,
    source: Box<dyn Iterator<Item = R>>,
    /// Whether `source` has yielded its last row.
    exhausted: bool,
    pub rows: Vec<R>,
    pub total: u64,
    pub from: RunFrom,
    /// The latest big change that came meanwhile: computed once this run is shown.
    pub next: Option<P>,
    /// The page's thinning hook, and the rows thinned to each key the run may be shown on.
    thin: ThinRow<R>,
    thinning: Vec<(ThinKey, ColumnsThin)>,
    /// The run's summary, computed once it is complete.
    pub summary: Option<M>,
}

impl<P, R, M> Sliced<P, R, M> {
    /// The run of `params` whose rows `source` yields (`total` of them), thinned by `thin` to
    /// the keys [`Sliced::thin_to`] adds; a change's run is [`RunFrom::Slices`].
    pub fn new(
        params: P,
        (source, total): Rows<R>,
        from: RunFrom,
        thin: ThinRow<R>,
    ) -> Sliced<P, R, M> {
        Sliced {
            params,
            source,
            exhausted: false,
            rows: Vec::with_capacity(total as usize),
            total,
            from: if from == RunFrom::Mount {
                from
            } else {
                RunFrom::Slices
            },
            next: None,
            thin,
            thinning: Vec::new(),
            summary: None,
        }
    }

    /// Thins the run to `key` too (the rows already computed over the next slices); whether
    /// it does (`false` when it already does or makes too many).
    pub fn thin_to(&mut self, key: ThinKey) -> bool {
        if self.thins_to(key) || self.thinning.len() >= MOST_THINNINGS {
            return false;
        }
        self.thinning.push((key, key.thinner()));
        true
    }

    /// Whether the run is thinned to `key`.
    pub fn thins_to(&self, key: ThinKey) -> bool {
        self.thinning.iter().any(|(k, _)| *k == key)
    }

    /// Pulls rows, each thinned as it comes, and brings a thinning added late up to them,
    /// until the slice begun at `t0` (ms) is spent; whether the run is complete and thinned.
    pub fn pull(&mut self, t0: f64) -> bool {
        let thin = self.thin;
        while now_ms() - t0 < SLICE_MS {
            let done = self.rows.len();
            if let Some((_, to)) = self.thinning.iter_mut().find(|(_, to)| to.rows() < done) {
                let from = to.rows();
                for row in &self.rows[from..done.min(from + CLOCK_EVERY)] {
                    thin(to, row);
                }
                continue;
            }
            if self.exhausted {
                return true;
            }
            for _ in 0..CLOCK_EVERY {
                let Some(row) = self.source.next() else {
                    self.exhausted = true;
                    break;
                };
                for (_, to) in &mut self.thinning {
                    thin(to, &row);
                }
                self.rows.push(row);
            }
        }
        false
    }

    /// The arguments, the rows, the summary if computed, and the rows' thinnings.
    pub fn finish(self) -> (P, Vec<R>, Option<M>, Kept) {
        let kept = (self.thinning.into_iter())
            .map(|(key, to)| (key, to.finish().into()))
            .collect();
        (self.params, self.rows, self.summary, kept)
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
