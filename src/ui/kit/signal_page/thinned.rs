//! A run's plotted columns thinned to the plot: each pixel column of the time axis keeps its
//! first, lowest, highest and last point ([`crate::view::signal::thin_columns`]), so that
//! showing a run of a million rows draws a few thousand points. The thinning is keyed by the
//! time axis and the plotting area's left and right edges: a run computed in slices is thinned
//! as its rows come, to the axes it will be shown on; any other key is thinned when asked.

use std::cell::RefCell;
use std::rc::Rc;

use crate::ui::kit::plot::Plot;
use crate::view::plot::LinearScale;
use crate::view::signal::ColumnsThin;

/// A page's thinning hook: pushes a row's time and plotted values (one a column) into the
/// thinner.
pub type ThinRow<R> = fn(&mut ColumnsThin, &R);

/// Thinned columns, one a plotted value of the rows.
pub type Columns = Rc<[Vec<(f64, f64)>]>;

/// A run's thinnings, each with its key.
pub type Kept = Vec<(ThinKey, Columns)>;

/// What thinned columns were thinned to: the time axis and the plotting area's left and right
/// edges, CSS px.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ThinKey {
    pub x: (f64, f64),
    pub px: (f64, f64),
}

impl ThinKey {
    /// The key of time axis `x` on `plot` as it stands (`None` before it has a plotting area).
    pub fn of(plot: &Plot, x: (f64, f64)) -> Option<ThinKey> {
        let (x0, x1, _, _) = plot.panel_px(0)?;
        Some(ThinKey { x, px: (x0, x1) })
    }

    /// A thinner to this key's pixel columns.
    pub fn thinner(&self) -> ColumnsThin {
        ColumnsThin::new(Some(LinearScale::new(self.x, self.px)))
    }
}

/// Keys a run keeps the thinning of (the axes while a slider is held, when it is let go, and
/// one more).
const KEPT: usize = 3;

/// The thinnings of one run's rows, the latest last.
pub struct ThinCache<R> {
    thin: ThinRow<R>,
    kept: RefCell<Vec<(ThinKey, Columns)>>,
}

impl<R> ThinCache<R> {
    /// The cache of a run thinned by `thin`, holding the thinnings `kept` already made.
    pub fn new(thin: ThinRow<R>, kept: Kept) -> ThinCache<R> {
        ThinCache {
            thin,
            kept: RefCell::new(kept),
        }
    }

    /// The columns of `rows` (this cache's run) thinned to time axis `x` on `plot`: kept ones,
    /// else thinned now (and kept); every point before the plot has a plotting area.
    pub fn columns(&self, plot: &Plot, x: (f64, f64), rows: &[R]) -> Columns {
        let Some(key) = ThinKey::of(plot, x) else {
            return thin_all(self.thin, ColumnsThin::new(None), rows);
        };
        if let Some((_, columns)) = self.kept.borrow().iter().find(|(k, _)| *k == key) {
            return columns.clone();
        }
        let columns = thin_all(self.thin, key.thinner(), rows);
        let mut kept = self.kept.borrow_mut();
        if kept.len() >= KEPT {
            kept.remove(0);
        }
        kept.push((key, columns.clone()));
        columns
    }
}

fn thin_all<R>(thin: ThinRow<R>, mut to: ColumnsThin, rows: &[R]) -> Columns {
    for row in rows {
        thin(&mut to, row);
    }
    to.finish().into()
}
