//! The plots: q, qd, qdd over t on three panels of the kit's signal plot sharing the time
//! axis, the recipe's samples as dots (while few) on the line, the overlays under them, a
//! cursor at the hovered time, and the end point (T, q1) as a drag handle on the position
//! panel (mouse, pen and touch; a touch elsewhere scrolls the page). The axes keep their
//! ranges while a drag lasts, so the point stays under the pointer, and refit when it ends.
//! Layers: axes, data, marks (the handle), cursor.

use std::rc::Weak;

use glam::DVec2;
use wasm_bindgen::JsValue;
use web_sys::Element;

use super::{CubicPage, OVERLAYS};
use crate::recipes::cubic_path::{CubicParams, CubicPath, CubicSample};
use crate::ui::kit::canvas::{focus_without_scroll, Ink};
use crate::ui::kit::drag::{DragEvent, PointerKind};
use crate::ui::kit::plot::{Mark, PanelSpec, PlotSpec};
use crate::ui::kit::recipe_controls::thinned_columns;
use crate::ui::kit::signal_page::{self, axis, draw_handle, reach, series, Fit, SignalPlot};
use crate::view::cubic_path::{panel_range, quintic, time_range, trapezoid};
use crate::view::palette;
use crate::view::signal::{held_range, held_ranges, nice_range, snap};

/// Colours: the cubic, the quintic, the trapezoid, the cursor.
/// The three curves meet at both ends: Okabe–Ito blue, reddish purple and bluish green stay
/// apart with every common colour-vision deficiency.
const C_CUBIC: (u8, u8, u8) = palette::BLUE.rgb;
const C_OVERLAY: [(u8, u8, u8); 2] = [palette::REDDISH_PURPLE.rgb, palette::BLUISH_GREEN.rgb];
const C_CURSOR: (u8, u8, u8) = (194, 65, 12);

/// The plots component.
pub struct Plots {
    sp: SignalPlot<()>,
    /// What the series show (params, overlays), to skip unchanged updates.
    shown: Option<(CubicParams, [bool; 2])>,
    x_range: (f64, f64),
    y_ranges: [(f64, f64); 3],
}

impl Plots {
    pub fn new(stage: &Element) -> Result<Plots, JsValue> {
        Ok(Plots {
            sp: SignalPlot::new(stage)?,
            shown: None,
            x_range: (0.0, 1.0),
            y_ranges: [(-1.0, 1.0); 3],
        })
    }

    /// The end-point drag, the hover cursor and focus on press.
    pub fn attach(&mut self, me: &Weak<CubicPage>, stage: &Element) -> Result<(), JsValue> {
        self.sp.attach(stage, me, Plots::hit, Plots::on_drag)
    }

    fn hit(page: &CubicPage, at: DVec2, kind: PointerKind) -> Option<()> {
        let end = page.plots.borrow().end_px(&page.path.borrow().0)?;
        (end.distance(at) <= reach(kind)).then_some(())
    }

    fn on_drag(page: &CubicPage, ev: DragEvent<()>) {
        match ev {
            DragEvent::Start { at, .. } | DragEvent::Move { at, .. } => {
                if let DragEvent::Start { .. } = ev {
                    page.plots.borrow_mut().sp.dragging = true;
                    focus_without_scroll(&page.plots.borrow().sp.plot.canvas.top().canvas);
                }
                let point = page.plots.borrow().sp.plot.from_px(0, at);
                let Some((t, q)) = point else {
                    return;
                };
                let (x0, x1) = page.plots.borrow().x_range;
                // max then min: with T under 0.01 s the axis ends before 0.01, where
                // clamp's bounds would cross and panic.
                let t = snap(t.max(x0.max(0.01)).min(x1), 0.01);
                let q = snap(q, 0.01);
                if let Some(p) = page
                    .shell
                    .controls
                    .set_texts(&[("q1", &q), ("T", &t)], None)
                {
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

    /// Whether the end point is being dragged.
    pub fn dragging(&self) -> bool {
        self.sp.dragging
    }

    fn end_px(&self, p: &CubicParams) -> Option<DVec2> {
        self.sp.plot.to_px(0, p.duration_s, p.q1)
    }

    /// Shows `path` (and the overlays that are on) and the cursor; `fit` says what the axes
    /// do, `resized` refits the canvases. The sample under the cursor.
    pub fn show(
        &mut self,
        p: &CubicParams,
        path: &CubicPath,
        overlays: [bool; 2],
        fit: Fit,
        resized: bool,
    ) -> Option<CubicSample> {
        let ink = Ink::current();
        if fit != Fit::Keep || self.shown != Some((*p, overlays)) {
            let quint = overlays[0].then(|| quintic(p, 200));
            let trap = overlays[1].then(|| trapezoid(p, 300)).flatten();
            let on = [quint.is_some(), trap.is_some()];
            let extra: Vec<Vec<CubicSample>> = [quint, trap].into_iter().flatten().collect();
            // The time axis first, then every series thinned to it, then the value axes from
            // the thinned points (no other pass over a million samples).
            let x_range = match fit {
                Fit::Keep => self.x_range,
                Fit::Hold => held_range(self.x_range, time_range(p)),
                Fit::Refit => time_range(p),
            };
            let thinned: Vec<[Vec<(f64, f64)>; 3]> = extra
                .iter()
                .map(Vec::as_slice)
                .chain([path.samples.as_slice()])
                .map(|v| {
                    let rows = v.iter().map(|s| (s.t, [s.q, s.qd, s.qdd]));
                    thinned_columns(&self.sp.plot, x_range, rows)
                })
                .collect();
            if fit != Fit::Keep {
                let fitted: [(f64, f64); 3] = std::array::from_fn(|k| {
                    nice_range(panel_range(
                        thinned.iter().flat_map(|c| c[k].iter().map(|p| p.1)),
                    ))
                });
                self.x_range = x_range;
                self.y_ranges = if fit == Fit::Hold {
                    held_ranges(self.y_ranges, fitted)
                } else {
                    fitted
                };
            }
            self.set_spec(on);
            for (k, columns) in thinned.into_iter().enumerate() {
                for (panel, pts) in columns.into_iter().enumerate() {
                    self.sp.plot.set_series(panel, k, pts);
                }
            }
            self.shown = Some((*p, overlays));
        }
        if resized {
            self.sp.plot.invalidate_all();
        }
        let cursor = self.cursor_sample(path);
        let _ = self.sp.plot.draw(ink);
        let Some(end) = self.end_px(p) else {
            return cursor;
        };
        self.sp.set_handles(&["end"], &[end]);
        // The end point, on the marks layer (between the data and the cursor).
        let marks = self.sp.plot.canvas.layer(2);
        marks.begin();
        draw_handle(&marks.ctx, end, ink);
        cursor
    }

    fn set_spec(&mut self, overlays: [bool; 2]) {
        let y = self.y_ranges;
        let mut names = Vec::new();
        for (k, on) in overlays.iter().enumerate() {
            if *on {
                names.push(series(
                    &format!("cubic-series-{}", OVERLAYS[k]),
                    C_OVERLAY[k],
                    Mark::Line,
                    2.0,
                    1.0,
                ));
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
        self.sp.plot.set_spec(PlotSpec {
            x: axis("signals-ax-t", "signals-unit-s", self.x_range),
            panels: vec![
                panel("cubic-ax-q", "cubic-unit-rad", y[0]),
                panel("cubic-ax-qd", "cubic-unit-rad-s", y[1]),
                panel("cubic-ax-qdd", "cubic-unit-rad-s2", y[2]),
            ],
            cursor_rgb: C_CURSOR,
        });
    }

    /// The sample of `path` under the cursor (mid-move before any hover), and draws the
    /// cursor there.
    pub fn cursor(&mut self, path: &CubicPath) -> Option<CubicSample> {
        let sample = self.cursor_sample(path);
        let _ = self.sp.plot.draw(Ink::current());
        sample
    }

    fn cursor_sample(&mut self, path: &CubicPath) -> Option<CubicSample> {
        self.sp
            .cursor_row(&path.samples, path.duration_s / 2.0, |s| s.t)
            .copied()
    }

    /// Saves the three panels as a PNG.
    pub fn png(&self, file: &str) {
        self.sp.png(file);
    }
}
