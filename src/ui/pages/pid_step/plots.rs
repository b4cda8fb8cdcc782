//! The plots: the setpoint r and the output y (top) and the controller output u (bottom) over
//! the CSV's t, the kit's signal plot sharing the time axis; the ghost (the previous gains' y
//! and u) pale underneath. Axes snap to 1-2-5 ranges, so a small change redraws only the
//! series. Nothing on it is dragged: a hover or a tap moves the cursor.

use std::rc::Weak;

use wasm_bindgen::JsValue;
use web_sys::Element;

use super::PidPage;
use crate::recipes::pid_step::{PidSample, DT_S};
use crate::ui::kit::canvas::Ink;
use crate::ui::kit::drag::DragEvent;
use crate::ui::kit::plot::{Mark, PanelSpec, PlotSpec, SeriesSpec};
use crate::ui::kit::recipe_controls::thinned_columns;
use crate::ui::kit::signal_page::{axis, series, SignalPlot};
use crate::view::plot::auto_range;
use crate::view::signal::{nice_range, y_extent};

const C_Y: (u8, u8, u8) = (26, 77, 143);
const C_R: (u8, u8, u8) = (194, 65, 12);
const C_U: (u8, u8, u8) = (21, 128, 61);
const C_GHOST: (u8, u8, u8) = (120, 128, 140);

/// The plots component.
pub struct Plots {
    sp: SignalPlot<()>,
    /// The ghost's ranges and thinned series, kept while the ghost, the time axis and the
    /// panel are the same (the ghost does not change during a drag).
    ghost: Option<GhostCache>,
}

/// A ghost's generation, the time range and the panel in px (`Plot::panel_px`).
type GhostKey = (u64, (f64, f64), Option<(f64, f64, f64, f64)>);

/// What is drawn of one ghost: its key (generation, time range, panel in px), its y and u
/// ranges, its thinned y and u.
struct GhostCache {
    key: GhostKey,
    y_range: (f64, f64),
    u_range: (f64, f64),
    y: Vec<(f64, f64)>,
    u: Vec<(f64, f64)>,
}

/// The (lo, hi) of the finite values of a thinned series, clamped to ±1e12 (an overflowed
/// run plots up to where it broke); `(inf, -inf)` when there is none.
fn extent(points: &[(f64, f64)]) -> (f64, f64) {
    let clamp = |v: f64| v.clamp(-1e12, 1e12);
    let (lo, hi) = y_extent(points);
    (clamp(lo), clamp(hi))
}

/// The axis range of extents `a` and `b` and the value `with`, padded and snapped.
fn range(a: (f64, f64), b: (f64, f64), with: f64) -> (f64, f64) {
    let r = auto_range([a.0, a.1, b.0, b.1, with], 0.06).unwrap_or((-1.0, 1.0));
    nice_range(r)
}

impl Plots {
    pub fn new(stage: &Element) -> Result<Plots, JsValue> {
        Ok(Plots {
            sp: SignalPlot::new(stage)?,
            ghost: None,
        })
    }

    /// The hover cursor: a mouse or pen over the plots, or a tap, reads the sample there.
    pub fn attach(&mut self, me: &Weak<PidPage>, stage: &Element) -> Result<(), JsValue> {
        self.sp.attach(stage, me, |_, _, _| None, Plots::on_pointer)
    }

    fn on_pointer(page: &PidPage, ev: DragEvent<()>) {
        let (DragEvent::Hover(at) | DragEvent::Tap { at }) = ev else {
            return;
        };
        if page.plots.borrow_mut().sp.hover(at) {
            page.show_cursor();
        }
    }

    /// The sample of `now` under the cursor, drawn there.
    pub fn cursor(&mut self, now: &[PidSample]) -> Option<PidSample> {
        let sample = self.cursor_sample(now);
        let _ = self.sp.plot.draw(Ink::current());
        sample
    }

    /// The sample of `now` under the cursor (mid-run before any hover); the cursor is set
    /// there.
    fn cursor_sample(&mut self, now: &[PidSample]) -> Option<PidSample> {
        let mid = now.last().map_or(0.0, |s| s.t / 2.0);
        self.sp.cursor_row(now, mid, |s| s.t).copied()
    }

    /// Shows the run `now` over the `ghost` (`generation` names it: a new ghost, a new
    /// number) and the cursor; `resized` refits the canvases. The sample under the cursor.
    pub fn show(
        &mut self,
        now: &[PidSample],
        ghost: Option<(u64, &[PidSample])>,
        resized: bool,
    ) -> Option<PidSample> {
        let t_end = [now.last(), ghost.and_then(|g| g.1.last())]
            .into_iter()
            .flatten()
            .map(|s| s.t)
            .fold(DT_S, f64::max);
        let x = (0.0, t_end);
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
        if let Some((generation, rows)) = ghost {
            let key = (generation, x, self.sp.plot.panel_px(0));
            if self.ghost.as_ref().map(|c| c.key) != Some(key) {
                let [y, u] =
                    thinned_columns(&self.sp.plot, x, rows.iter().map(|s| (s.t, [s.y, s.u])));
                self.ghost = Some(GhostCache {
                    key,
                    y_range: extent(&y),
                    u_range: extent(&u),
                    y,
                    u,
                });
            }
        }
        let none = (f64::INFINITY, f64::NEG_INFINITY);
        let (ghost_y, ghost_u) = self
            .ghost
            .as_ref()
            .filter(|_| ghost.is_some())
            .map_or((none, none), |c| (c.y_range, c.u_range));
        let [y, u] = thinned_columns(&self.sp.plot, x, now.iter().map(|s| (s.t, [s.y, s.u])));
        let (now_y, now_u) = (extent(&y), extent(&u));
        self.sp.plot.set_spec(PlotSpec {
            x: axis("signals-ax-t", "signals-unit-s", x),
            panels: vec![
                PanelSpec {
                    y: axis("pid-ax-y", "", range(now_y, ghost_y, 1.0)),
                    series: top,
                },
                PanelSpec {
                    y: axis("pid-ax-u", "", range(now_u, ghost_u, 0.0)),
                    series: bottom,
                },
            ],
            cursor_rgb: C_R,
        });
        if let Some(cache) = self.ghost.as_ref().filter(|_| ghost.is_some()) {
            self.sp.plot.set_series(0, 0, cache.y.clone());
            self.sp.plot.set_series(1, 0, cache.u.clone());
        }
        // r is the recipe's constant setpoint: its two ends draw it.
        let r = match (now.first(), now.last()) {
            (Some(a), Some(b)) => vec![(a.t, a.r), (b.t, b.r)],
            _ => Vec::new(),
        };
        self.sp.plot.set_series(0, g, r);
        self.sp.plot.set_series(0, g + 1, y);
        self.sp.plot.set_series(1, g, u);
        if resized {
            self.sp.plot.invalidate_all();
        }
        let cursor = self.cursor_sample(now);
        let _ = self.sp.plot.draw(Ink::current());
        cursor
    }

    /// Saves the plots as a PNG.
    pub fn png(&self, file: &str) {
        self.sp.png(file);
    }
}
