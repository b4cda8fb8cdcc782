//! The plots: q, qd, qdd over t on three panels of the kit's signal plot sharing the time
//! axis, the recipe's samples as dots (while few) on the line, the overlays under them, a
//! cursor at the hovered time, and the end point (T, q1) as a drag handle on the position
//! panel (mouse, pen and touch; a touch elsewhere scrolls the page). The axes keep their
//! ranges while a drag lasts, so the point stays under the pointer, and refit when it ends.
//! Layers: axes, data, marks (the handle), cursor.

use glam::DVec2;

use crate::recipes::cubic_path::{CubicParams, CubicSample};
use crate::ui::kit::canvas::Ink;
use crate::ui::kit::plot::{Mark, PanelSpec, PlotSpec};
use crate::ui::kit::signal_page::{axis, draw_handle, series, time_axis, Draw, SignalPlot};
use crate::view::cubic_path::{panel_range, quintic, time_range, trapezoid};
use crate::view::palette;
use crate::view::signal::{nice_range, snap};

/// The overlays (URL key = `data-overlay`).
pub const OVERLAYS: [&str; 2] = ["quintic", "trapezoid"];

/// Colours: the cubic, the quintic, the trapezoid, the cursor.
/// The three curves meet at both ends: Okabe–Ito blue, reddish purple and bluish green stay
/// apart with every common colour-vision deficiency.
const C_CUBIC: (u8, u8, u8) = palette::BLUE.rgb;
const C_OVERLAY: [(u8, u8, u8); 2] = [palette::REDDISH_PURPLE.rgb, palette::BLUISH_GREEN.rgb];
const C_CURSOR: (u8, u8, u8) = (194, 65, 12);

/// What the series show (params, overlays), to skip unchanged updates.
#[derive(Default)]
pub struct Plots {
    shown: Option<(CubicParams, [bool; 2])>,
}

/// The end point's place, CSS px.
fn end_px(sp: &SignalPlot<()>, p: &CubicParams) -> Option<DVec2> {
    sp.plot.to_px(0, p.duration_s, p.q1)
}

/// The texts of q1 and T for the end point dragged to CSS px `at`, T kept on the time axis.
pub fn dragged_end(sp: &SignalPlot<()>, at: DVec2) -> Option<(String, String)> {
    let (t, q) = sp.plot.from_px(0, at)?;
    let (x0, x1) = sp.x_range;
    // max then min: with T under 0.01 s the axis ends before 0.01, where clamp's bounds would
    // cross and panic.
    Some((snap(q, 0.01), snap(t.max(x0.max(0.01)).min(x1), 0.01)))
}

/// The end point as a handle, on the marks layer (between the data and the cursor).
pub fn draw_end(sp: &mut SignalPlot<()>, p: &CubicParams) {
    let Some(end) = end_px(sp, p) else {
        return;
    };
    sp.set_handles(&[((), "end", end)]);
    let marks = sp.plot.canvas.layer(2);
    marks.begin();
    draw_handle(&marks.ctx, end, Ink::current());
}

impl Plots {
    /// Sets the axes and the thinned `samples` of `p` (and of the overlays that are on).
    pub fn set_data(
        &mut self,
        sp: &mut SignalPlot<()>,
        p: &CubicParams,
        samples: &[CubicSample],
        overlays: [bool; 2],
        draw: Draw,
    ) {
        if draw.fit != crate::ui::kit::signal_page::Fit::Keep || self.shown != Some((*p, overlays))
        {
            let quint = overlays[0].then(|| quintic(p, 200));
            let trap = overlays[1].then(|| trapezoid(p, 300)).flatten();
            let on = [quint.is_some(), trap.is_some()];
            let extra: Vec<Vec<CubicSample>> = [quint, trap].into_iter().flatten().collect();
            // The time axis first, then every series thinned to it, then the value axes from
            // the thinned points (no other pass over a million samples).
            let x = sp.x_for(draw.fit, time_range(p));
            let thinned: Vec<[Vec<(f64, f64)>; 3]> = extra
                .iter()
                .map(Vec::as_slice)
                .chain([samples])
                .map(|v| sp.thin(x, v.iter().map(|s| (s.t, [s.q, s.qd, s.qdd]))))
                .collect();
            let fitted: [(f64, f64); 3] = std::array::from_fn(|k| {
                nice_range(panel_range(
                    thinned.iter().flat_map(|c| c[k].iter().map(|p| p.1)),
                ))
            });
            sp.fit_axes(draw.fit, x, fitted);
            set_spec(sp, on);
            for (k, columns) in thinned.into_iter().enumerate() {
                for (panel, pts) in columns.into_iter().enumerate() {
                    sp.plot.set_series(panel, k, pts);
                }
            }
            self.shown = Some((*p, overlays));
        }
        if draw.resized {
            sp.plot.invalidate_all();
        }
    }
}

fn set_spec(sp: &mut SignalPlot<()>, overlays: [bool; 2]) {
    let y = sp.y_ranges;
    let mut names = Vec::new();
    for (k, on) in overlays.iter().enumerate() {
        if *on {
            let id = format!("cubic-series-{}", OVERLAYS[k]);
            names.push(series(&id, C_OVERLAY[k], Mark::Line, 2.0, 1.0));
        }
    }
    names.push(series(
        "cubic-series-cubic",
        C_CUBIC,
        Mark::LineAndPoints,
        2.0,
        1.0,
    ));
    let panel = |title: &str, unit: &str, range| PanelSpec {
        y: axis(title, unit, range),
        series: names.clone(),
    };
    sp.plot.set_spec(PlotSpec {
        x: time_axis(sp.x_range),
        panels: vec![
            panel("cubic-ax-q", "cubic-unit-rad", y[0]),
            panel("cubic-ax-qd", "cubic-unit-rad-s", y[1]),
            panel("cubic-ax-qdd", "cubic-unit-rad-s2", y[2]),
        ],
        cursor_rgb: C_CURSOR,
    });
}
