//! The plots: q, qd, qdd over t on three panels of one kit plot sharing the time axis, the
//! recipe's samples as dots (while few) on the line, the overlays under them, a cursor at the
//! hovered time, and the end point (T, q1) as a drag handle on the position panel (mouse,
//! pen and touch; a touch elsewhere scrolls the page). The axes keep their ranges while a
//! drag lasts, so the point stays under the pointer, and refit when it ends. Layers: axes,
//! data, marks (the handle), cursor.

use std::rc::Weak;

use glam::DVec2;
use wasm_bindgen::JsValue;
use web_sys::Element;

use super::{Inner, OVERLAYS};
use crate::recipes::cubic_path::{CubicParams, CubicPath, CubicSample};
use crate::ui::ctx;
use crate::ui::kit::canvas::{focus_without_scroll, Ink};
use crate::ui::kit::drag::{Drag, DragEvent};
use crate::ui::kit::plot::{AxisSpec, Mark, PanelSpec, Plot, PlotSpec, SeriesSpec};
use crate::ui::kit::recipe_controls::thinned_columns;
use crate::view::cubic_path::{quintic, ranges, time_range, trapezoid};
use crate::view::drag::HandleShape;
use crate::view::plot::nearest_index;
use crate::view::signal::{nice_range, snap};

/// Colours: the cubic, the quintic, the trapezoid, the cursor.
const C_CUBIC: (u8, u8, u8) = (26, 77, 143);
const C_OVERLAY: [(u8, u8, u8); 2] = [(124, 58, 237), (21, 128, 61)];
const C_CURSOR: (u8, u8, u8) = (194, 65, 12);

/// The plots component.
pub struct Plots {
    plot: Plot,
    drag: Option<Drag<()>>,
    /// What the series show (params, overlays), to skip unchanged updates.
    shown: Option<(CubicParams, [bool; 2])>,
    x_range: (f64, f64),
    y_ranges: [(f64, f64); 3],
    cursor_t: Option<f64>,
    dragging: bool,
}

fn series(id: &str, rgb: (u8, u8, u8), mark: Mark, width: f64) -> SeriesSpec {
    SeriesSpec {
        name: ctx::t(id),
        rgb,
        mark,
        width,
        alpha: 1.0,
    }
}

impl Plots {
    pub fn new(stage: &Element) -> Result<Plots, JsValue> {
        Ok(Plots {
            plot: Plot::new(stage)?,
            drag: None,
            shown: None,
            x_range: (0.0, 1.0),
            y_ranges: [(-1.0, 1.0); 3],
            cursor_t: None,
            dragging: false,
        })
    }

    /// The end-point drag, the hover cursor and focus on press.
    pub fn attach(&mut self, me: &Weak<Inner>, stage: &Element) -> Result<(), JsValue> {
        let surface = self.plot.canvas.top().canvas.clone();
        let (hit_me, on_me) = (me.clone(), me.clone());
        self.drag = Some(Drag::attach(
            stage,
            &surface,
            move |at, kind| {
                let page = hit_me.upgrade()?;
                let plots = page.plots.borrow();
                let end = plots.end_px(&page.path.borrow().0)?;
                let reach = if kind.is_coarse() { 24.0 } else { 12.0 };
                (end.distance(at) <= reach).then_some(())
            },
            move |ev| {
                if let Some(page) = on_me.upgrade() {
                    Plots::on_drag(&page, ev);
                }
            },
        )?);
        Ok(())
    }

    fn on_drag(page: &Inner, ev: DragEvent<()>) {
        match ev {
            DragEvent::Start { at, .. } | DragEvent::Move { at, .. } => {
                if let DragEvent::Start { .. } = ev {
                    page.plots.borrow_mut().dragging = true;
                    focus_without_scroll(&page.plots.borrow().plot.canvas.top().canvas);
                }
                let point = page.plots.borrow().plot.from_px(0, at);
                let Some((t, q)) = point else {
                    return;
                };
                let (x0, x1) = page.plots.borrow().x_range;
                let t = snap(t.clamp(x0.max(0.01), x1), 0.01);
                let q = snap(q, 0.01);
                if let Some(p) = page.controls.set_texts(&[("q1", &q), ("T", &t)], None) {
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
                page.plots.borrow_mut().cursor_t = t;
                page.redraw(false, false);
            }
            DragEvent::Leave => {}
        }
    }

    /// Whether the end point is being dragged.
    pub fn dragging(&self) -> bool {
        self.dragging
    }

    fn end_px(&self, p: &CubicParams) -> Option<DVec2> {
        self.plot.to_px(0, p.duration_s, p.q1)
    }

    /// Shows `path` (and the overlays that are on); `refit` rescales the axes, `resized`
    /// refits the canvases.
    pub fn show(
        &mut self,
        p: &CubicParams,
        path: &CubicPath,
        overlays: [bool; 2],
        refit: bool,
        resized: bool,
    ) {
        let ink = Ink::current();
        if refit || self.shown != Some((*p, overlays)) {
            let quint = overlays[0].then(|| quintic(p, 200));
            let trap = overlays[1].then(|| trapezoid(p, 300)).flatten();
            let on = [quint.is_some(), trap.is_some()];
            let extra: Vec<Vec<CubicSample>> = [quint, trap].into_iter().flatten().collect();
            let mut all: Vec<&[CubicSample]> = vec![&path.samples];
            all.extend(extra.iter().map(Vec::as_slice));
            if refit {
                self.x_range = time_range(p);
                self.y_ranges = ranges(&all).map(nice_range);
            }
            self.set_spec(on);
            let series = extra
                .iter()
                .map(Vec::as_slice)
                .chain([path.samples.as_slice()]);
            for (k, v) in series.enumerate() {
                let rows = v.iter().map(|s| (s.t, [s.q, s.qd, s.qdd]));
                let columns = thinned_columns(&self.plot, self.x_range, rows);
                for (panel, pts) in columns.into_iter().enumerate() {
                    self.plot.set_series(panel, k, pts);
                }
            }
            self.shown = Some((*p, overlays));
        }
        if resized {
            self.plot.invalidate_all();
        }
        let t = self.cursor_sample(path).map(|s| s.t);
        self.plot.set_cursor(t);
        let _ = self.plot.draw(ink);
        let Some(end) = self.end_px(p) else {
            return;
        };
        if let Some(drag) = &self.drag {
            drag.set_handles(&[HandleShape::Circle {
                centre: end,
                radius: 22.0,
            }]);
        }
        // Where the handle is, for tests and assistive tools (CSS px of the canvas).
        let top = &self.plot.canvas.top().canvas;
        let _ = top.set_attribute("data-end-x", &format!("{:.1}", end.x));
        let _ = top.set_attribute("data-end-y", &format!("{:.1}", end.y));
        // The end point, on the marks layer (between the data and the cursor).
        let marks = self.plot.canvas.layer(2);
        marks.begin();
        let c = &marks.ctx;
        c.set_fill_style_str("rgba(194, 65, 12, 0.18)");
        c.set_stroke_style_str("#c2410c");
        c.set_line_width(2.0 * ink.line);
        c.begin_path();
        let _ = c.arc(end.x, end.y, 9.0 * ink.line, 0.0, std::f64::consts::TAU);
        c.fill();
        c.stroke();
    }

    fn set_spec(&mut self, overlays: [bool; 2]) {
        let y = self.y_ranges;
        let axis = |title: &str, unit: &str, range| AxisSpec {
            title: ctx::t(title),
            unit: ctx::t(unit),
            range,
        };
        let mut names = Vec::new();
        for (k, on) in overlays.iter().enumerate() {
            if *on {
                names.push(series(
                    &format!("cubic-series-{}", OVERLAYS[k]),
                    C_OVERLAY[k],
                    Mark::Line,
                    2.0,
                ));
            }
        }
        names.push(series(
            "cubic-series-cubic",
            C_CUBIC,
            Mark::LineAndPoints,
            2.0,
        ));
        let panel = |title: &str, unit: &str, range| PanelSpec {
            y: axis(title, unit, range),
            series: names.clone(),
        };
        self.plot.set_spec(PlotSpec {
            x: axis("signals-ax-t", "signals-unit-s", self.x_range),
            panels: vec![
                panel("cubic-ax-q", "cubic-unit-rad", y[0]),
                panel("cubic-ax-qd", "cubic-unit-rad-s", y[1]),
                panel("cubic-ax-qdd", "cubic-unit-rad-s2", y[2]),
            ],
            cursor_rgb: C_CURSOR,
        });
    }

    /// The sample nearest the cursor (mid-move before any hover).
    pub fn cursor_sample(&self, path: &CubicPath) -> Option<CubicSample> {
        let t = self.cursor_t.unwrap_or(path.duration_s / 2.0);
        let s = &path.samples;
        let i = s.partition_point(|x| x.t < t);
        let near = [i.saturating_sub(1), i.min(s.len().saturating_sub(1))];
        let pick = nearest_index(&near.map(|k| s.get(k).map_or(f64::NAN, |x| x.t)), t)?;
        s.get(near[pick]).copied()
    }

    /// Saves the three panels as a PNG.
    pub fn png(&self, file: &str) {
        if let Ok(canvas) = self.plot.canvas.flatten("#ffffff") {
            let _ = crate::ui::kit::png::download(&canvas, file);
        }
    }
}
