//! The plots: s, v and a over t on three panels of the kit's signal plot; the accelerate /
//! cruise / brake phases shaded across every panel and labelled over the first, the asked vmax
//! as a dashed line on the velocity panel, and two drag handles there: vmax (drag up and down)
//! and the ramp's corner (its slope is amax). Layers: axes, data, marks (bands, labels,
//! handles), cursor. The axes keep their ranges while a drag lasts and refit when it ends; the
//! time axis snaps to 1-2-5 steps, so a slider drag redraws the axes only when the move
//! outgrows them.

use glam::DVec2;

use crate::recipes::trapezoid_profile::{TrapParams, TrapSample};
use crate::ui::ctx;
use crate::ui::kit::canvas::{dash, solid, Ink};
use crate::ui::kit::plot::Mark;
use crate::ui::kit::signal_page::{draw_handle, series, Draw, Fit, Run, SignalPlot};
use crate::view::plot::{auto_range, place_labels};
use crate::view::signal::{nice_range, y_extent};
use crate::view::trapezoid_profile::{amax_from_corner, bands, Phases};

const C_LINE: (u8, u8, u8) = (26, 77, 143);
const C_CURSOR: (u8, u8, u8) = (194, 65, 12);
const BANDS: [(&str, &str); 3] = [
    // Okabe–Ito blue and vermilion tints (accelerate, brake), apart with every common
    // colour-vision deficiency; the phases are also labelled over the first panel.
    ("rgba(0, 114, 178, 0.10)", "trap-phase-accel"),
    ("rgba(120, 128, 140, 0.08)", "trap-phase-cruise"),
    ("rgba(213, 94, 0, 0.10)", "trap-phase-brake"),
];

/// Which handle.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Grab {
    Vmax,
    Corner,
}

/// The phase labels in the current language (Fluent lookups kept out of every frame).
#[derive(Default)]
pub struct Plots {
    labels: Option<[String; 3]>,
}

/// The argument a drag of `handle` to CSS px `at` sets, and its value (before snapping).
pub fn dragged(sp: &SignalPlot<Grab>, handle: Grab, at: DVec2) -> Option<(&'static str, f64)> {
    let (t, v) = sp.plot.from_px(1, at)?;
    match handle {
        Grab::Vmax => Some(("vmax", v)),
        Grab::Corner => amax_from_corner(t, v).map(|a| ("amax", a)),
    }
}

/// The time axis of the profile of phases `ph` with `fit`.
pub fn time_axis(sp: &SignalPlot<Grab>, ph: &Phases, fit: Fit) -> (f64, f64) {
    sp.x_for(fit, nice_range((0.0, (ph.t_total * 1.1).max(1e-9))))
}

/// Sets the axes and the thinned samples of `run`, the profile of phases `ph`.
pub fn set_data(
    sp: &mut SignalPlot<Grab>,
    run: &Run<TrapParams, TrapSample, ()>,
    ph: &Phases,
    draw: Draw,
) {
    // The time axis first (it comes from the phases), then the rows thinned to it (as they
    // were computed), then the value axes from the thinned points (each pixel column keeps its
    // lowest and highest: the same extents as the rows', without another pass over a
    // million).
    let x = time_axis(sp, ph, draw.fit);
    let columns: [_; 3] = run.thinned(&sp.plot, x);
    let [s, v, a] = std::array::from_fn(|k| y_extent(&columns[k]));
    let r = |(lo, hi): (f64, f64), with: f64| {
        nice_range(auto_range([lo, hi, 0.0, with], 0.08).unwrap_or((-1.0, 1.0)))
    };
    let fitted = [r(s, ph.distance), r(v, ph.vmax * 1.3), r(a, ph.amax)];
    if sp.fit_axes(draw.fit, x, fitted) || draw.resized {
        let line = series("trap-series-profile", C_LINE, Mark::LineAndPoints, 2.0, 1.0);
        let axes = [("trap-ax-s", ""), ("trap-ax-v", ""), ("trap-ax-a", "")];
        sp.set_panels(axes, vec![line], C_CURSOR);
    }
    if draw.resized {
        sp.plot.invalidate_all();
    }
    for (panel, pts) in columns.into_iter().enumerate() {
        sp.plot.set_series(panel, 0, pts);
    }
}

impl Plots {
    /// The language or the mode changed: texts are looked up again.
    pub fn relocalize(&mut self) {
        self.labels = None;
    }

    /// Bands, labels, the asked vmax and the handles on the marks layer.
    pub fn draw_marks(&mut self, sp: &mut SignalPlot<Grab>, ph: &Phases) {
        let ink = Ink::current();
        let labels = self
            .labels
            .get_or_insert_with(|| BANDS.map(|(_, id)| ctx::t(id)));
        let plot = &sp.plot;
        let marks = plot.canvas.layer(2);
        marks.begin();
        let c = &marks.ctx;
        let Some(top) = plot.panel_px(0) else {
            return;
        };
        let panels: Vec<(f64, f64)> = (0..3)
            .filter_map(|k| plot.panel_px(k))
            .map(|(_, _, y0, y1)| (y0, y1))
            .collect();
        c.set_font(&ink.font(12.0, true));
        c.set_text_align("center");
        c.set_text_baseline("top");
        // Bands first; then their labels, kept inside the plotting area and apart (a narrow
        // band's label would run over the y ticks or its neighbour's), each on a halo of the
        // background so the curve under it does not hide it.
        let mut shown = Vec::new();
        for (((t0, t1), (fill, _)), label) in bands(ph).into_iter().zip(BANDS).zip(labels.iter()) {
            let (Some(a), Some(b)) = (plot.to_px(0, t0, 0.0), plot.to_px(0, t1, 0.0)) else {
                continue;
            };
            if b.x - a.x < 0.5 {
                continue;
            }
            c.set_fill_style_str(fill);
            for (y0, y1) in &panels {
                c.fill_rect(a.x, *y0, b.x - a.x, y1 - y0);
            }
            let w = c.measure_text(label).map_or(0.0, |m| m.width());
            shown.push((label, ((a.x + b.x) / 2.0, w)));
        }
        let places: Vec<(f64, f64)> = shown.iter().map(|(_, p)| *p).collect();
        let gap = 8.0 * ink.text;
        c.set_line_width(4.0 * ink.line);
        c.set_line_join("round");
        c.set_stroke_style_str("rgba(251, 252, 254, 0.85)");
        c.set_fill_style_str("#3a4250");
        for ((label, _), x) in
            shown
                .iter()
                .zip(place_labels(&places, top.0 + 2.0, top.1 - 2.0, gap))
        {
            if let Some(x) = x {
                let _ = c.stroke_text(label, x, top.2 + 4.0);
                let _ = c.fill_text(label, x, top.2 + 4.0);
            }
        }
        // The asked vmax, dashed, on the velocity panel.
        if let (Some(l), Some(r)) = (
            plot.to_px(1, sp.x_range.0, ph.vmax),
            plot.to_px(1, sp.x_range.1, ph.vmax),
        ) {
            c.set_stroke_style_str("rgba(194, 65, 12, 0.8)");
            c.set_line_width(1.5 * ink.line);
            let _ = c.set_line_dash(&dash(6.0, 4.0));
            c.begin_path();
            c.move_to(l.x, l.y);
            c.line_to(r.x, r.y);
            c.stroke();
            let _ = c.set_line_dash(&solid());
        }
        // The handles: vmax at mid-move, the corner at (t_acc, v_peak).
        let (Some(vmax), Some(corner)) = (
            plot.to_px(1, ph.t_total / 2.0, ph.vmax),
            plot.to_px(1, ph.t_acc, ph.v_peak),
        ) else {
            return;
        };
        draw_handle(c, vmax, ink);
        draw_handle(c, corner, ink);
        sp.set_handles(&[(Grab::Vmax, "vmax", vmax), (Grab::Corner, "corner", corner)]);
    }
}
