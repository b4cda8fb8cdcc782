//! The plot of a signal page: the kit [`Plot`] of the stage with panels sharing the time axis,
//! the axes' ranges as the last [`Fit`] left them, the drag handles the page drew (hit by
//! reach, written on the canvas for tests), the hovered time of the cursor and the PNG.

use std::rc::Weak;

use glam::DVec2;
use wasm_bindgen::JsValue;
use web_sys::{CanvasRenderingContext2d, Element};

use crate::ui::ctx;
use crate::ui::kit::canvas::Ink;
use crate::ui::kit::drag::{Drag, DragEvent, PointerKind};
use crate::ui::kit::plot::{AxisSpec, Mark, PanelSpec, Plot, PlotSpec, SeriesSpec};
use crate::ui::kit::recipe_controls::thinned_columns;
use crate::view::drag::HandleShape;
use crate::view::signal::{held_range, held_ranges, nearest_row};

/// What a signal page's axes do on a redraw.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Fit {
    /// Keep their ranges (a drag of a plot handle: the point stays under the pointer).
    Keep,
    /// Grow to hold the data, never shrink (a slider being moved:
    /// [`crate::view::signal::held_range`]); refitted when it is let go.
    Hold,
    /// Fit the data.
    Refit,
}

impl Fit {
    /// For a new run: `Keep` while a plot handle is dragged, `Hold` while a slider is moved,
    /// else `Refit`.
    pub fn for_change(dragging: bool, sliding: bool) -> Fit {
        if dragging {
            Fit::Keep
        } else if sliding {
            Fit::Hold
        } else {
            Fit::Refit
        }
    }
}

/// Radius of a handle's hit area, CSS px (a finger's width).
const HANDLE_REACH_PX: f64 = 22.0;

/// How far from a handle a press still grabs it, CSS px (wider for touch and pen).
fn reach(kind: PointerKind) -> f64 {
    if kind.is_coarse() {
        24.0
    } else {
        12.0
    }
}

/// The plot of a signal page with handles `H` (`()` for a plot with none).
pub struct SignalPlot<H: Copy + PartialEq + 'static> {
    pub plot: Plot,
    drag: Option<Drag<H>>,
    /// The handles drawn last, CSS px, in the order a press tries them.
    handles: Vec<(H, DVec2)>,
    /// Whether a handle is being dragged.
    pub dragging: bool,
    /// The hovered time (`None`: none yet, the cursor stands where the page says).
    pub cursor_t: Option<f64>,
    /// The time axis and, for a plot of three panels, their value axes, as the last
    /// [`SignalPlot::fit_axes`] left them.
    pub x_range: (f64, f64),
    pub y_ranges: [(f64, f64); 3],
}

impl<H: Copy + PartialEq + 'static> SignalPlot<H> {
    /// The plot of `stage`'s canvases.
    pub fn new(stage: &Element) -> Result<SignalPlot<H>, JsValue> {
        Ok(SignalPlot {
            plot: Plot::new(stage)?,
            drag: None,
            handles: Vec::new(),
            dragging: false,
            cursor_t: None,
            x_range: (0.0, 1.0),
            y_ranges: [(-1.0, 1.0); 3],
        })
    }

    /// Listens for drags, hovers and taps on `stage`: a press grabs the nearest handle within
    /// reach (`grab(page)` gives the page's plot), `on(page, event)` hears them.
    pub fn attach<P: 'static>(
        &mut self,
        stage: &Element,
        me: &Weak<P>,
        grab: fn(&P, DVec2, PointerKind) -> Option<H>,
        on: fn(&P, DragEvent<H>),
    ) -> Result<(), JsValue> {
        let surface = self.plot.canvas.top().canvas.clone();
        let (hit_me, on_me) = (me.clone(), me.clone());
        self.drag = Some(Drag::attach(
            stage,
            &surface,
            move |at, kind| grab(&*hit_me.upgrade()?, at, kind),
            move |ev| {
                if let Some(page) = on_me.upgrade() {
                    on(&page, ev);
                }
            },
        )?);
        Ok(())
    }

    /// The first handle within reach of a press of `kind` at `at`.
    pub fn grab(&self, at: DVec2, kind: PointerKind) -> Option<H> {
        self.handles
            .iter()
            .find(|(_, px)| px.distance(at) <= reach(kind))
            .map(|(h, _)| *h)
    }

    /// The hovered time at CSS px `at` (on the shared time axis), remembered for the cursor.
    pub fn hover(&mut self, at: DVec2) -> bool {
        let t = self.plot.from_px(0, at).map(|(t, _)| t);
        if t.is_some() {
            self.cursor_t = t;
        }
        t.is_some()
    }

    /// The row of `rows` under the cursor (`start` before any hover); the cursor is drawn
    /// there.
    pub fn cursor_row<'a, T>(
        &mut self,
        rows: &'a [T],
        start: f64,
        t_of: impl Fn(&T) -> f64,
    ) -> Option<&'a T> {
        let row = nearest_row(rows, self.cursor_t.unwrap_or(start), &t_of);
        self.plot.set_cursor(row.map(&t_of));
        row
    }

    /// The handles `(handle, name, centre)` (centres in CSS px), for the drags: a finger-wide
    /// circle each; their places are also written as `data-<name>-x` / `-y` on the top canvas
    /// (for tests and assistive tools).
    pub fn set_handles(&mut self, handles: &[(H, &str, DVec2)]) {
        self.handles = handles.iter().map(|&(h, _, at)| (h, at)).collect();
        if let Some(drag) = &self.drag {
            let shapes: Vec<HandleShape> = handles
                .iter()
                .map(|&(_, _, centre)| HandleShape::Circle {
                    centre,
                    radius: HANDLE_REACH_PX,
                })
                .collect();
            drag.set_handles(&shapes);
        }
        let top = &self.plot.canvas.top().canvas;
        for (_, name, at) in handles {
            let _ = top.set_attribute(&format!("data-{name}-x"), &format!("{:.1}", at.x));
            let _ = top.set_attribute(&format!("data-{name}-y"), &format!("{:.1}", at.y));
        }
    }

    /// The time axis `fit` gives, `fitted` being the one that holds the run.
    pub fn x_for(&self, fit: Fit, fitted: (f64, f64)) -> (f64, f64) {
        match fit {
            Fit::Keep => self.x_range,
            Fit::Hold => held_range(self.x_range, fitted),
            Fit::Refit => fitted,
        }
    }

    /// Takes time axis `x` and the value axes `fitted` as `fit` says (held: grown, never
    /// shrunk; kept: unchanged); whether they differ from the plot's spec.
    pub fn fit_axes(&mut self, fit: Fit, x: (f64, f64), fitted: [(f64, f64); 3]) -> bool {
        if fit == Fit::Keep {
            return false;
        }
        let y_ranges = if fit == Fit::Hold {
            held_ranges(self.y_ranges, fitted)
        } else {
            fitted
        };
        self.x_range = x;
        self.y_ranges = y_ranges;
        !self.plot.spec().is_some_and(|spec| {
            spec.x.range == x && spec.panels.iter().map(|p| p.y.range).eq(y_ranges)
        })
    }

    /// Sets the spec of three panels over the time axis, each of `series`, their value axes
    /// `(title id, unit id)` over [`SignalPlot::y_ranges`].
    pub fn set_panels(
        &mut self,
        axes: [(&str, &str); 3],
        series: Vec<SeriesSpec>,
        cursor_rgb: (u8, u8, u8),
    ) {
        let panels = axes
            .iter()
            .zip(self.y_ranges)
            .map(|((title, unit), range)| PanelSpec {
                y: axis(title, unit, range),
                series: series.clone(),
            })
            .collect();
        self.plot.set_spec(PlotSpec {
            x: time_axis(self.x_range),
            panels,
            cursor_rgb,
        });
    }

    /// The points of `rows` (`(t, [y; N])`) thinned to the plot over time axis `x`, one
    /// series a column.
    pub fn thin<const N: usize>(
        &self,
        x: (f64, f64),
        rows: impl Iterator<Item = (f64, [f64; N])>,
    ) -> [Vec<(f64, f64)>; N] {
        thinned_columns(&self.plot, x, rows)
    }

    /// Saves the plot's layers, on white, as `file`.
    pub fn png(&self, file: &str) {
        if let Ok(canvas) = self.plot.canvas.flatten("#ffffff") {
            let _ = crate::ui::kit::png::download(&canvas, file);
        }
    }
}

/// An axis: title and unit from Fluent (an empty unit id: no unit).
pub fn axis(title_id: &str, unit_id: &str, range: (f64, f64)) -> AxisSpec {
    AxisSpec {
        title: ctx::t(title_id),
        unit: if unit_id.is_empty() {
            String::new()
        } else {
            ctx::t(unit_id)
        },
        range,
    }
}

/// The shared time axis, s.
pub fn time_axis(range: (f64, f64)) -> AxisSpec {
    axis("signals-ax-t", "signals-unit-s", range)
}

/// A series named by Fluent id `name_id`.
pub fn series(name_id: &str, rgb: (u8, u8, u8), mark: Mark, width: f64, alpha: f64) -> SeriesSpec {
    SeriesSpec {
        name: ctx::t(name_id),
        rgb,
        mark,
        width,
        alpha,
    }
}

/// Draws a drag handle (an orange ring) at `at` on `c`.
pub fn draw_handle(c: &CanvasRenderingContext2d, at: DVec2, ink: Ink) {
    c.set_fill_style_str("rgba(194, 65, 12, 0.18)");
    c.set_stroke_style_str("#c2410c");
    c.set_line_width(2.0 * ink.line);
    c.begin_path();
    let _ = c.arc(at.x, at.y, 9.0 * ink.line, 0.0, std::f64::consts::TAU);
    c.fill();
    c.stroke();
}
