//! The plots: the setpoint r and the output y (top) and the controller output u (bottom) over
//! the CSV's t, one kit plot sharing the time axis; the ghost (the previous gains' y and u)
//! pale underneath. Axes snap to 1-2-5 ranges, so a small change redraws only the series.

use wasm_bindgen::JsValue;
use web_sys::Element;

use crate::recipes::pid_step::{PidSample, DT_S};
use crate::ui::ctx;
use crate::ui::kit::canvas::Ink;
use crate::ui::kit::plot::{AxisSpec, Mark, PanelSpec, Plot, PlotSpec, SeriesSpec};
use crate::ui::kit::recipe_controls::thinned;
use crate::view::plot::auto_range;
use crate::view::signal::nice_range;

const C_Y: (u8, u8, u8) = (26, 77, 143);
const C_R: (u8, u8, u8) = (194, 65, 12);
const C_U: (u8, u8, u8) = (21, 128, 61);
const C_GHOST: (u8, u8, u8) = (120, 128, 140);

/// The plots component.
pub struct Plots {
    plot: Plot,
}

fn series(id: &str, rgb: (u8, u8, u8), mark: Mark, width: f64, alpha: f64) -> SeriesSpec {
    SeriesSpec {
        name: ctx::t(id),
        rgb,
        mark,
        width,
        alpha,
    }
}

/// A column of finite values (an overflowed run plots up to where it broke).
fn range(rows: &[&[PidSample]], f: fn(&PidSample) -> f64, with: f64) -> (f64, f64) {
    let values = rows.iter().flat_map(|r| r.iter().map(f)).chain([with]);
    let r = auto_range(values.map(|v| v.clamp(-1e12, 1e12)), 0.06).unwrap_or((-1.0, 1.0));
    nice_range(r)
}

impl Plots {
    pub fn new(stage: &Element) -> Result<Plots, JsValue> {
        Ok(Plots {
            plot: Plot::new(stage)?,
        })
    }

    /// Shows the run `now` over the `ghost`; `resized` refits the canvases.
    pub fn show(&mut self, now: &[PidSample], ghost: Option<&[PidSample]>, resized: bool) {
        let mut all = vec![now];
        all.extend(ghost);
        let t_end = all
            .iter()
            .filter_map(|r| r.last())
            .map(|s| s.t)
            .fold(DT_S, f64::max);
        let axis = |title: &str, unit: &str, range| AxisSpec {
            title: ctx::t(title),
            unit: if unit.is_empty() {
                String::new()
            } else {
                ctx::t(unit)
            },
            range,
        };
        // The ghost's series (first, under the others) only while there is one.
        let g = usize::from(ghost.is_some());
        let ghost_series = |id| ghost.map(|_| series(id, C_GHOST, Mark::Line, 2.0, 0.55));
        let mut top: Vec<SeriesSpec> = ghost_series("pid-series-ghost-y").into_iter().collect();
        top.push(series("pid-series-r", C_R, Mark::Line, 1.5, 1.0));
        top.push(series("pid-series-y", C_Y, Mark::LineAndPoints, 2.0, 1.0));
        let mut bottom: Vec<SeriesSpec> = ghost_series("pid-series-ghost-u").into_iter().collect();
        bottom.push(series("pid-series-u", C_U, Mark::LineAndPoints, 2.0, 1.0));
        self.plot.set_spec(PlotSpec {
            x: axis("signals-ax-t", "signals-unit-s", (0.0, t_end)),
            panels: vec![
                PanelSpec {
                    y: axis("pid-ax-y", "", range(&all, |s| s.y, 1.0)),
                    series: top,
                },
                PanelSpec {
                    y: axis("pid-ax-u", "", range(&all, |s| s.u, 0.0)),
                    series: bottom,
                },
            ],
            cursor_rgb: C_R,
        });
        let x = (0.0, t_end);
        let pts = |plot: &Plot, rows: &[PidSample], f: fn(&PidSample) -> f64| {
            thinned(plot, x, rows.iter().map(|s| (s.t, f(s))))
        };
        if let Some(ghost) = ghost {
            let (y, u) = (
                pts(&self.plot, ghost, |s| s.y),
                pts(&self.plot, ghost, |s| s.u),
            );
            self.plot.set_series(0, 0, y);
            self.plot.set_series(1, 0, u);
        }
        let (r, y, u) = (
            pts(&self.plot, now, |s| s.r),
            pts(&self.plot, now, |s| s.y),
            pts(&self.plot, now, |s| s.u),
        );
        self.plot.set_series(0, g, r);
        self.plot.set_series(0, g + 1, y);
        self.plot.set_series(1, g, u);
        if resized {
            self.plot.invalidate_all();
        }
        let _ = self.plot.draw(Ink::current());
    }

    /// Saves the plots as a PNG.
    pub fn png(&self, file: &str) {
        if let Ok(canvas) = self.plot.canvas.flatten("#ffffff") {
            let _ = crate::ui::kit::png::download(&canvas, file);
        }
    }
}
