//! The plots: s, v and a over t on three panels of one kit plot; the accelerate / cruise /
//! brake phases shaded across every panel and labelled over the first, the asked vmax as a
//! dashed line on the velocity panel, and two drag handles there: vmax (drag up and down) and
//! the ramp's corner (its slope is amax). Layers: axes, data, marks (bands, labels, handles),
//! cursor. The axes keep their ranges while a drag lasts and refit when it ends.

use std::rc::Weak;

use glam::DVec2;
use wasm_bindgen::JsValue;
use web_sys::Element;

use super::Inner;
use crate::pyfmt::py_round;
use crate::recipes::trapezoid_profile::{TrapParams, TrapSample};
use crate::ui::ctx;
use crate::ui::kit::canvas::{dash, focus_without_scroll, solid, Ink};
use crate::ui::kit::drag::{Drag, DragEvent};
use crate::ui::kit::plot::{AxisSpec, Mark, PanelSpec, Plot, PlotSpec, SeriesSpec};
use crate::ui::kit::recipe_controls::thinned_columns;
use crate::view::drag::HandleShape;
use crate::view::plot::auto_range;
use crate::view::signal::{extents, nearest_row, nice_range, snap};
use crate::view::trapezoid_profile::{amax_from_corner, bands, Phases};

const C_LINE: (u8, u8, u8) = (26, 77, 143);
const BANDS: [(&str, &str); 3] = [
    ("rgba(21, 128, 61, 0.10)", "trap-phase-accel"),
    ("rgba(120, 128, 140, 0.08)", "trap-phase-cruise"),
    ("rgba(194, 65, 12, 0.10)", "trap-phase-brake"),
];

/// Which handle.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Grab {
    Vmax,
    Corner,
}

/// The plots component.
pub struct Plots {
    plot: Plot,
    drag: Option<Drag<Grab>>,
    x_range: (f64, f64),
    y_ranges: [(f64, f64); 3],
    dragging: bool,
    /// The hovered time (`None`: none yet, the cursor stands mid-move).
    cursor_t: Option<f64>,
}

impl Plots {
    pub fn new(stage: &Element) -> Result<Plots, JsValue> {
        Ok(Plots {
            plot: Plot::new(stage)?,
            drag: None,
            x_range: (0.0, 1.0),
            y_ranges: [(-1.0, 1.0); 3],
            dragging: false,
            cursor_t: None,
        })
    }

    /// The two handles' drags.
    pub fn attach(&mut self, me: &Weak<Inner>, stage: &Element) -> Result<(), JsValue> {
        let surface = self.plot.canvas.top().canvas.clone();
        let (hit_me, on_me) = (me.clone(), me.clone());
        self.drag = Some(Drag::attach(
            stage,
            &surface,
            move |at, kind| {
                let page = hit_me.upgrade()?;
                let reach = if kind.is_coarse() { 24.0 } else { 12.0 };
                let handles = page.plots.borrow().handles(&page.profile.borrow().0)?;
                handles
                    .into_iter()
                    .find(|(_, px)| px.distance(at) <= reach)
                    .map(|(g, _)| g)
            },
            move |ev| {
                if let Some(page) = on_me.upgrade() {
                    Plots::on_drag(&page, ev);
                }
            },
        )?);
        Ok(())
    }

    fn on_drag(page: &Inner, ev: DragEvent<Grab>) {
        match ev {
            DragEvent::Start { handle, at, .. } | DragEvent::Move { handle, at } => {
                if matches!(ev, DragEvent::Start { .. }) {
                    page.plots.borrow_mut().dragging = true;
                    focus_without_scroll(&page.plots.borrow().plot.canvas.top().canvas);
                }
                let Some((t, v)) = page.plots.borrow().plot.from_px(1, at) else {
                    return;
                };
                let next = match handle {
                    Grab::Vmax => page
                        .controls
                        .set_text("vmax", &snap(v.max(0.01), 0.01), false),
                    Grab::Corner => match amax_from_corner(t, v) {
                        Some(a) => page
                            .controls
                            .set_text("amax", &snap(a.max(0.01), 0.01), false),
                        None => None,
                    },
                };
                if let Some(p) = next {
                    page.changed(p);
                }
            }
            DragEvent::End { .. } => {
                page.plots.borrow_mut().dragging = false;
                page.redraw(true, false);
                if let Some(url) = page.url.borrow().as_ref() {
                    url.write_now();
                }
            }
            DragEvent::Hover(at) | DragEvent::Tap { at } => {
                let t = page.plots.borrow().plot.from_px(0, at).map(|(t, _)| t);
                if t.is_some() {
                    page.plots.borrow_mut().cursor_t = t;
                    page.show_cursor();
                }
            }
            DragEvent::Leave => {}
        }
    }

    /// The sample of `samples` under the cursor (mid-move before any hover), its time as the
    /// CSV writes it (`round(t, 5)`), and draws the cursor there.
    pub fn cursor(&mut self, samples: &[TrapSample]) -> Option<TrapSample> {
        let mid = samples.last().map_or(0.0, |s| s.t / 2.0);
        let sample = nearest_row(samples, self.cursor_t.unwrap_or(mid), |s| s.t).copied();
        self.plot.set_cursor(sample.map(|s| s.t));
        let _ = self.plot.draw(Ink::current());
        sample.map(|s| TrapSample {
            t: py_round(s.t, 5),
            ..s
        })
    }

    /// Whether a handle is being dragged.
    pub fn dragging(&self) -> bool {
        self.dragging
    }

    /// The handles, CSS px: vmax at mid-move, the corner at (t_acc, v_peak).
    fn handles(&self, p: &TrapParams) -> Option<[(Grab, DVec2); 2]> {
        let ph = crate::view::trapezoid_profile::phases(p);
        Some([
            (Grab::Vmax, self.plot.to_px(1, ph.t_total / 2.0, ph.vmax)?),
            (Grab::Corner, self.plot.to_px(1, ph.t_acc, ph.v_peak)?),
        ])
    }

    /// Shows the `samples`; `refit` rescales the axes, `resized` refits the canvases.
    pub fn show(
        &mut self,
        p: &TrapParams,
        samples: &[TrapSample],
        ph: &Phases,
        refit: bool,
        resized: bool,
    ) {
        let ink = Ink::current();
        if refit {
            self.x_range = (0.0, (ph.t_total * 1.1).max(1e-9));
            let [s, v, a] = extents(samples.iter().map(|s| [s.s, s.v, s.a]));
            let r = |(lo, hi): (f64, f64), with: f64| {
                nice_range(auto_range([lo, hi, 0.0, with], 0.08).unwrap_or((-1.0, 1.0)))
            };
            self.y_ranges = [r(s, ph.distance), r(v, ph.vmax * 1.3), r(a, ph.amax)];
            let axis = |title: &str, unit: &str, range| AxisSpec {
                title: ctx::t(title),
                unit: if unit.is_empty() {
                    String::new()
                } else {
                    ctx::t(unit)
                },
                range,
            };
            let line = SeriesSpec {
                name: ctx::t("trap-series-profile"),
                rgb: C_LINE,
                mark: Mark::LineAndPoints,
                width: 2.0,
                alpha: 1.0,
            };
            let panel = |title: &str, unit: &str, range| PanelSpec {
                y: axis(title, unit, range),
                series: vec![line.clone()],
            };
            self.plot.set_spec(PlotSpec {
                x: axis("signals-ax-t", "signals-unit-s", self.x_range),
                panels: vec![
                    panel("trap-ax-s", "", self.y_ranges[0]),
                    panel("trap-ax-v", "", self.y_ranges[1]),
                    panel("trap-ax-a", "", self.y_ranges[2]),
                ],
                cursor_rgb: (194, 65, 12),
            });
        }
        if resized {
            self.plot.invalidate_all();
        }
        let rows = samples.iter().map(|s| (s.t, [s.s, s.v, s.a]));
        let columns = thinned_columns(&self.plot, self.x_range, rows);
        for (panel, pts) in columns.into_iter().enumerate() {
            self.plot.set_series(panel, 0, pts);
        }
        let _ = self.plot.draw(ink);
        self.draw_marks(p, ph, ink);
    }

    /// Bands, labels, the asked vmax and the handles on the marks layer.
    fn draw_marks(&self, p: &TrapParams, ph: &Phases, ink: Ink) {
        let marks = self.plot.canvas.layer(2);
        marks.begin();
        let c = &marks.ctx;
        let Some(top) = self.plot.panel_px(0) else {
            return;
        };
        c.set_font(&ink.font(12.0, true));
        c.set_text_align("center");
        c.set_text_baseline("top");
        for ((t0, t1), (fill, label)) in bands(ph).into_iter().zip(BANDS) {
            let (Some(a), Some(b)) = (self.plot.to_px(0, t0, 0.0), self.plot.to_px(0, t1, 0.0))
            else {
                continue;
            };
            if b.x - a.x < 0.5 {
                continue;
            }
            c.set_fill_style_str(fill);
            for (_, _, y0, y1) in (0..3).filter_map(|k| self.plot.panel_px(k)) {
                c.fill_rect(a.x, y0, b.x - a.x, y1 - y0);
            }
            c.set_fill_style_str("#3a4250");
            let _ = c.fill_text(&ctx::t(label), (a.x + b.x) / 2.0, top.2 + 4.0);
        }
        // The asked vmax, dashed, on the velocity panel.
        if let (Some(l), Some(r)) = (
            self.plot.to_px(1, self.x_range.0, ph.vmax),
            self.plot.to_px(1, self.x_range.1, ph.vmax),
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
        // Where the handles are, for tests (CSS px of the canvas).
        let top = &self.plot.canvas.top().canvas;
        for (name, (_, at)) in ["vmax", "corner"].iter().zip(handles) {
            let _ = top.set_attribute(&format!("data-{name}-x"), &format!("{:.1}", at.x));
            let _ = top.set_attribute(&format!("data-{name}-y"), &format!("{:.1}", at.y));
        }
        for (_, at) in handles {
            c.set_fill_style_str("rgba(194, 65, 12, 0.18)");
            c.set_stroke_style_str("#c2410c");
            c.set_line_width(2.0 * ink.line);
            c.begin_path();
            let _ = c.arc(at.x, at.y, 9.0 * ink.line, 0.0, std::f64::consts::TAU);
            c.fill();
            c.stroke();
        }
        if let Some(drag) = &self.drag {
            let shapes = handles.map(|(_, centre)| HandleShape::Circle {
                centre,
                radius: 22.0,
            });
            drag.set_handles(&shapes);
        }
    }

    /// Saves the plots as a PNG.
    pub fn png(&self, file: &str) {
        if let Ok(canvas) = self.plot.canvas.flatten("#ffffff") {
            let _ = crate::ui::kit::png::download(&canvas, file);
        }
    }
}
