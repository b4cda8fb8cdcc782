//! The plots: the setpoint r and the output y (top) and the controller output u (bottom) over
//! the CSV's t, the kit's signal plot sharing the time axis; the ghost (the previous gains' y
//! and u) pale underneath. Axes snap to 1-2-5 ranges, so a small change redraws only the
//! series. Nothing on it is dragged: a hover or a tap moves the cursor.

use crate::recipes::pid_step::{PidParams, PidSample, DT_S};
use crate::ui::kit::plot::{Mark, PanelSpec, PlotSpec, SeriesSpec};
use crate::ui::kit::signal_page::{axis, series, time_axis, Run, SignalPlot};
use crate::view::pid_step::{plot_extent, plot_range};

const C_Y: (u8, u8, u8) = (26, 77, 143);
const C_R: (u8, u8, u8) = (194, 65, 12);
const C_U: (u8, u8, u8) = (21, 128, 61);
const C_GHOST: (u8, u8, u8) = (120, 128, 140);

/// The ghost's ranges and thinned series, kept while the ghost, the time axis and the panel
/// are the same (the ghost does not change during a drag).
#[derive(Default)]
pub struct Plots {
    ghost: Option<GhostCache>,
}

/// A ghost's generation, the time range and the panel in px (`Plot::panel_px`).
type GhostKey = (u64, (f64, f64), Option<(f64, f64, f64, f64)>);

/// What is drawn of one ghost: its key, its y and u ranges, its thinned y and u.
struct GhostCache {
    key: GhostKey,
    y_range: (f64, f64),
    u_range: (f64, f64),
    y: Vec<(f64, f64)>,
    u: Vec<(f64, f64)>,
}

/// The time of the last sample of the run of `p` (the kernel's step k is at k·dt), if any.
pub fn last_t(p: &PidParams) -> Option<f64> {
    (p.steps >= 1).then(|| (p.steps - 1) as f64 * DT_S)
}

/// The time axis of a run ending at `now_end` over a ghost ending at `ghost_end`, s: from 0
/// to the later end (at least one step).
pub fn time_axis_of(now_end: Option<f64>, ghost_end: Option<f64>) -> (f64, f64) {
    (
        0.0,
        [now_end, ghost_end]
            .into_iter()
            .flatten()
            .fold(DT_S, f64::max),
    )
}

impl Plots {
    /// Sets the axes and series of the run `now` over the `ghost` (`generation` names it: a
    /// new ghost, a new number); `resized` refits the canvases.
    pub fn set_data<M>(
        &mut self,
        sp: &mut SignalPlot<()>,
        now: &Run<PidParams, PidSample, M>,
        ghost: Option<(u64, &Run<PidParams, PidSample, M>)>,
        resized: bool,
    ) {
        let end = |r: &Run<PidParams, PidSample, M>| r.rows.last().map(|s| s.t);
        let x = time_axis_of(end(now), ghost.and_then(|g| end(g.1)));
        // The ghost's series (first, under the others) only while there is one.
        let g = usize::from(ghost.is_some());
        let ghost_series = |id: &str| ghost.map(|_| series(id, C_GHOST, Mark::Line, 2.0, 0.55));
        let mut top: Vec<SeriesSpec> = ghost_series("pid-series-ghost-y").into_iter().collect();
        top.push(series("pid-series-r", C_R, Mark::Line, 1.5, 1.0));
        top.push(series("pid-series-y", C_Y, Mark::LineAndPoints, 2.0, 1.0));
        let mut bottom: Vec<SeriesSpec> = ghost_series("pid-series-ghost-u").into_iter().collect();
        bottom.push(series("pid-series-u", C_U, Mark::LineAndPoints, 2.0, 1.0));
        // The ghost thinned once (a new ghost, a new x range or a new size), its ranges from
        // its thinned points (each pixel column keeps its lowest and highest: the same extents
        // as the run's, without another pass over a million rows).
        if let Some((generation, run)) = ghost {
            let key = (generation, x, sp.plot.panel_px(0));
            if self.ghost.as_ref().map(|c| c.key) != Some(key) {
                let [y, u] = run.thinned(&sp.plot, x);
                self.ghost = Some(GhostCache {
                    key,
                    y_range: plot_extent(&y),
                    u_range: plot_extent(&u),
                    y,
                    u,
                });
            }
        }
        let none = (f64::INFINITY, f64::NEG_INFINITY);
        let cache = self.ghost.as_ref().filter(|_| ghost.is_some());
        let (ghost_y, ghost_u) = cache.map_or((none, none), |c| (c.y_range, c.u_range));
        let [y, u] = now.thinned(&sp.plot, x);
        let (now_y, now_u) = (plot_extent(&y), plot_extent(&u));
        sp.plot.set_spec(PlotSpec {
            x: time_axis(x),
            panels: vec![
                PanelSpec {
                    y: axis("pid-ax-y", "", plot_range(now_y, ghost_y, 1.0)),
                    series: top,
                },
                PanelSpec {
                    y: axis("pid-ax-u", "", plot_range(now_u, ghost_u, 0.0)),
                    series: bottom,
                },
            ],
            cursor_rgb: C_R,
        });
        if let Some(cache) = cache {
            sp.plot.set_series(0, 0, cache.y.clone());
            sp.plot.set_series(1, 0, cache.u.clone());
        }
        // r is the recipe's constant setpoint: its two ends draw it.
        let r = match (now.rows.first(), now.rows.last()) {
            (Some(a), Some(b)) => vec![(a.t, a.r), (b.t, b.r)],
            _ => Vec::new(),
        };
        sp.plot.set_series(0, g, r);
        sp.plot.set_series(0, g + 1, y);
        sp.plot.set_series(1, g, u);
        if resized {
            sp.plot.invalidate_all();
        }
    }
}
