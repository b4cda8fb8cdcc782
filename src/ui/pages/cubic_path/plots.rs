//! The plots: q, qd, qdd over t on three panels of the kit's signal plot sharing the time
//! axis, the recipe's samples as dots (while few) on the line, the overlays under them, a
//! cursor at the hovered time, and the end point (T, q1) as a drag handle on the position
//! panel (mouse, pen and touch; a touch elsewhere scrolls the page). The axes keep their
//! ranges while a drag lasts, so the point stays under the pointer, and refit when it ends.
//! Layers: axes, data, marks (the handle), cursor.

use glam::DVec2;

use crate::recipes::cubic_path::{CubicParams, CubicSample};
use crate::ui::kit::canvas::Ink;
use crate::ui::kit::plot::{Mark, SeriesSpec};
use crate::ui::kit::signal_page::{draw_handle, series, Draw, Fit, Run, SignalPlot};
use crate::view::cubic_path::{panel_range, quintic, time_range, trapezoid, Readouts};
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

/// A run of the recipe: its arguments and samples.
type Path = Run<CubicParams, CubicSample, Readouts>;

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

/// The time axis of the path of `p` with `fit`.
pub fn time_axis(sp: &SignalPlot<()>, p: &CubicParams, fit: Fit) -> (f64, f64) {
    sp.x_for(fit, time_range(p))
}

/// Sets the axes and the thinned samples of `run` (and of the overlays that are on).
pub fn set_data(sp: &mut SignalPlot<()>, run: &Path, overlays: [bool; 2], draw: Draw) {
    let p = &run.params;
    let quint = overlays[0].then(|| quintic(p, 200));
    let trap = overlays[1].then(|| trapezoid(p, 300)).flatten();
    let on = [quint.is_some(), trap.is_some()];
    let extra: Vec<Vec<CubicSample>> = [quint, trap].into_iter().flatten().collect();
    // The time axis first, then every series thinned to it (the run's samples as they were
    // computed), then the value axes from the thinned points (no other pass over a million
    // samples).
    let x = time_axis(sp, p, draw.fit);
    let thinned: Vec<[Vec<(f64, f64)>; 3]> = extra
        .iter()
        .map(|v| sp.thin(x, v.iter().map(|s| (s.t, [s.q, s.qd, s.qdd]))))
        .chain([run.thinned(&sp.plot, x)])
        .collect();
    let fitted: [(f64, f64); 3] = std::array::from_fn(|k| {
        nice_range(panel_range(
            thinned.iter().flat_map(|c| c[k].iter().map(|p| p.1)),
        ))
    });
    sp.fit_axes(draw.fit, x, fitted);
    let mut series_on: Vec<SeriesSpec> = (0..2)
        .filter(|&k| on[k])
        .map(|k| {
            let id = format!("cubic-series-{}", OVERLAYS[k]);
            series(&id, C_OVERLAY[k], Mark::Line, 2.0, 1.0)
        })
        .collect();
    series_on.push(series(
        "cubic-series-cubic",
        C_CUBIC,
        Mark::LineAndPoints,
        2.0,
        1.0,
    ));
    let axes = [
        ("cubic-ax-q", "cubic-unit-rad"),
        ("cubic-ax-qd", "cubic-unit-rad-s"),
        ("cubic-ax-qdd", "cubic-unit-rad-s2"),
    ];
    sp.set_panels(axes, series_on, C_CURSOR);
    for (k, columns) in thinned.into_iter().enumerate() {
        for (panel, pts) in columns.into_iter().enumerate() {
            sp.plot.set_series(panel, k, pts);
        }
    }
    if draw.resized {
        sp.plot.invalidate_all();
    }
}
