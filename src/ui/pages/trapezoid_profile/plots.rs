//! The plots: s, v and a over t on three panels of the kit's signal plot; the accelerate /
//! cruise / brake phases shaded across every panel and labelled over the first, the asked vmax
//! as a dashed line on the velocity panel, and two drag handles there: vmax (drag up and down)
//! and the ramp's corner (its slope is amax). Layers: axes, data, marks (bands, labels,
//! handles), cursor. The axes keep their ranges while a drag lasts and refit when it ends; the
//! time axis snaps to 1-2-5 steps, so a slider drag redraws the axes only when the move
//! outgrows them.

use std::rc::Weak;

use glam::DVec2;
use wasm_bindgen::JsValue;
use web_sys::Element;

use super::TrapPage;
use crate::pyfmt::py_round;
use crate::recipes::trapezoid_profile::{TrapParams, TrapSample};
use crate::ui::ctx;
use crate::ui::kit::canvas::{dash, focus_without_scroll, solid, Ink};
use crate::ui::kit::drag::{DragEvent, PointerKind};
use crate::ui::kit::plot::{Mark, PanelSpec, PlotSpec};
use crate::ui::kit::recipe_controls::thinned_columns;
use crate::ui::kit::signal_page::{self, axis, draw_handle, reach, series, Fit, SignalPlot};
use crate::view::plot::{auto_range, place_labels};
use crate::view::signal::{held_range, held_ranges, nice_range, snap, y_extent};
use crate::view::trapezoid_profile::{amax_from_corner, bands, phases, Phases};

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

/// The plots component.
pub struct Plots {
    sp: SignalPlot<Grab>,
    x_range: (f64, f64),
    y_ranges: [(f64, f64); 3],
    /// The phase labels in the current language (Fluent lookups kept out of every frame).
    labels: Option<[String; 3]>,
}

impl Plots {
    pub fn new(stage: &Element) -> Result<Plots, JsValue> {
        Ok(Plots {
            sp: SignalPlot::new(stage)?,
            x_range: (0.0, 1.0),
            y_ranges: [(-1.0, 1.0); 3],
            labels: None,
        })
    }

    /// The language or the mode changed: texts are looked up again.
    pub fn relocalize(&mut self) {
        self.labels = None;
    }

    /// The two handles' drags.
    pub fn attach(&mut self, me: &Weak<TrapPage>, stage: &Element) -> Result<(), JsValue> {
        self.sp.attach(stage, me, Plots::hit, Plots::on_drag)
    }

    fn hit(page: &TrapPage, at: DVec2, kind: PointerKind) -> Option<Grab> {
        let handles = page.plots.borrow().handles(&page.profile.borrow().0)?;
        handles
            .into_iter()
            .find(|(_, px)| px.distance(at) <= reach(kind))
            .map(|(g, _)| g)
    }

    fn on_drag(page: &TrapPage, ev: DragEvent<Grab>) {
        match ev {
            DragEvent::Start { handle, at, .. } | DragEvent::Move { handle, at } => {
                if matches!(ev, DragEvent::Start { .. }) {
                    page.plots.borrow_mut().sp.dragging = true;
                    focus_without_scroll(&page.plots.borrow().sp.plot.canvas.top().canvas);
                }
                let Some((t, v)) = page.plots.borrow().sp.plot.from_px(1, at) else {
                    return;
                };
                let controls = &page.shell.controls;
                let next = match handle {
                    Grab::Vmax => controls.set_text("vmax", &snap(v.max(0.01), 0.01), false),
                    Grab::Corner => amax_from_corner(t, v)
                        .and_then(|a| controls.set_text("amax", &snap(a.max(0.01), 0.01), false)),
                };
                if let Some(p) = next {
                    signal_page::change(page, p);
                }
            }
            DragEvent::End { .. } => {
                page.plots.borrow_mut().sp.dragging = false;
                page.redraw(Fit::Refit, false);
                page.shell.url.write_now();
            }
            DragEvent::Hover(at) | DragEvent::Tap { at } => {
                if page.plots.borrow_mut().sp.hover(at) {
                    page.show_cursor();
                }
            }
            DragEvent::Leave => {}
        }
    }

    /// The sample of `samples` under the cursor, drawn there.
    pub fn cursor(&mut self, samples: &[TrapSample]) -> Option<TrapSample> {
        let sample = self.cursor_sample(samples);
        let _ = self.sp.plot.draw(Ink::current());
        sample
    }

    /// The sample of `samples` under the cursor (mid-move before any hover), its time as the
    /// CSV writes it (`round(t, 5)`); the cursor is set there.
    fn cursor_sample(&mut self, samples: &[TrapSample]) -> Option<TrapSample> {
        let mid = samples.last().map_or(0.0, |s| s.t / 2.0);
        let sample = self.sp.cursor_row(samples, mid, |s| s.t).copied();
        sample.map(|s| TrapSample {
            t: py_round(s.t, 5),
            ..s
        })
    }

    /// Whether a handle is being dragged.
    pub fn dragging(&self) -> bool {
        self.sp.dragging
    }

    /// The handles, CSS px: vmax at mid-move, the corner at (t_acc, v_peak).
    fn handles(&self, p: &TrapParams) -> Option<[(Grab, DVec2); 2]> {
        let ph = phases(p);
        Some([
            (
                Grab::Vmax,
                self.sp.plot.to_px(1, ph.t_total / 2.0, ph.vmax)?,
            ),
            (Grab::Corner, self.sp.plot.to_px(1, ph.t_acc, ph.v_peak)?),
        ])
    }

    /// Shows the `samples` and the cursor; `fit` says what the axes do, `resized` refits the
    /// canvases. The sample under the cursor.
    pub fn show(
        &mut self,
        p: &TrapParams,
        samples: &[TrapSample],
        ph: &Phases,
        fit: Fit,
        resized: bool,
    ) -> Option<TrapSample> {
        let ink = Ink::current();
        // The time axis first (it comes from the phases), then the rows thinned to it, then
        // the value axes from the thinned points (each pixel column keeps its lowest and
        // highest: the same extents as the rows', without another pass over a million).
        let x_range = match fit {
            Fit::Keep => self.x_range,
            Fit::Hold => held_range(self.x_range, fitted_x(ph)),
            Fit::Refit => fitted_x(ph),
        };
        let rows = samples.iter().map(|s| (s.t, [s.s, s.v, s.a]));
        let columns = thinned_columns(&self.sp.plot, x_range, rows);
        if fit != Fit::Keep {
            let [s, v, a] = std::array::from_fn(|k| y_extent(&columns[k]));
            let r = |(lo, hi): (f64, f64), with: f64| {
                nice_range(auto_range([lo, hi, 0.0, with], 0.08).unwrap_or((-1.0, 1.0)))
            };
            let fitted = [r(s, ph.distance), r(v, ph.vmax * 1.3), r(a, ph.amax)];
            let y_ranges = if fit == Fit::Hold {
                held_ranges(self.y_ranges, fitted)
            } else {
                fitted
            };
            self.x_range = x_range;
            let same = self.sp.plot.spec().is_some_and(|spec| {
                spec.x.range == self.x_range && spec.panels.iter().map(|p| p.y.range).eq(y_ranges)
            });
            self.y_ranges = y_ranges;
            if !same || resized {
                self.set_spec();
            }
        }
        if resized {
            self.sp.plot.invalidate_all();
        }
        for (panel, pts) in columns.into_iter().enumerate() {
            self.sp.plot.set_series(panel, 0, pts);
        }
        let cursor = self.cursor_sample(samples);
        let _ = self.sp.plot.draw(ink);
        self.draw_marks(p, ph, ink);
        cursor
    }

    fn set_spec(&mut self) {
        let line = series("trap-series-profile", C_LINE, Mark::LineAndPoints, 2.0, 1.0);
        let panel = |title: &str, range| PanelSpec {
            y: axis(title, "", range),
            series: vec![line.clone()],
        };
        self.sp.plot.set_spec(PlotSpec {
            x: axis("signals-ax-t", "signals-unit-s", self.x_range),
            panels: vec![
                panel("trap-ax-s", self.y_ranges[0]),
                panel("trap-ax-v", self.y_ranges[1]),
                panel("trap-ax-a", self.y_ranges[2]),
            ],
            cursor_rgb: C_CURSOR,
        });
    }

    /// Bands, labels, the asked vmax and the handles on the marks layer.
    fn draw_marks(&mut self, p: &TrapParams, ph: &Phases, ink: Ink) {
        let labels = self
            .labels
            .get_or_insert_with(|| BANDS.map(|(_, id)| ctx::t(id)));
        let plot = &self.sp.plot;
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
            plot.to_px(1, self.x_range.0, ph.vmax),
            plot.to_px(1, self.x_range.1, ph.vmax),
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
        let Some(handles) = self.handles(p) else {
            return;
        };
        for (_, at) in handles {
            draw_handle(c, at, ink);
        }
        self.sp
            .set_handles(&["vmax", "corner"], &handles.map(|(_, at)| at));
    }

    /// Saves the plots as a PNG.
    pub fn png(&self, file: &str) {
        self.sp.png(file);
    }
}

/// The time axis that holds the whole move.
fn fitted_x(ph: &Phases) -> (f64, f64) {
    nice_range((0.0, (ph.t_total * 1.1).max(1e-9)))
}
