//! Line and scatter plots on plotters + plotters-canvas: one or more panels stacked over one
//! shared x axis (tick labels and title under the bottom panel only), each with its y axis
//! (title and unit), named series and a legend; a movable vertical cursor; data replaced or
//! appended incrementally.
//!
//! Three stacked layers: the axes (frame, mesh, ticks, titles, legends; plotters draws them,
//! only when the spec, the size or the language change), the data (series drawn straight on
//! the 2D context with the same pixel mapping; [`Plot::append`] draws only the new points, so
//! a live trace costs what it adds, not its history; long series are min/max-decimated per
//! pixel column) and the cursor (redrawn alone when it moves).
//!
//! A panel's y axis may be logarithmic ([`Plot::set_log_y`]): its range and data stay in
//! data units (positive), the axis is drawn in decades (`10⁻⁶`), and a value ≤ 0 sits on the
//! bottom edge. Series with an empty name have no legend entry.
//!
//! ```ignore
//! let mut plot = Plot::new(&stage)?;                 // a stage with three <canvas>
//! plot.set_spec(spec);                               // axes, panels, series
//! plot.set_series(0, 0, points);                     // or plot.append(0, 0, &new_points)
//! plot.set_cursor(Some(t));
//! plot.draw(Ink::current())?;                        // in the page's animation frame
//! ```

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters_canvas::CanvasBackend;
use web_sys::Element;

use super::canvas::{font_px, solid, Ink, LayeredCanvas};
use crate::view::drag::HandleShape;
use crate::view::plot::{
    axis_desc, axis_title, decimate, legend_layout, log_axis_range, log_tick_label, nice_step,
    tick_label, LinearScale,
};

use glam::DVec2;

/// One axis: title, unit (shown as `title [unit]`) and range.
#[derive(Debug, Clone, PartialEq)]
pub struct AxisSpec {
    pub title: String,
    pub unit: String,
    pub range: (f64, f64),
}

impl AxisSpec {
    fn desc(&self) -> String {
        axis_desc(&self.title, &self.unit)
    }
}

/// What the layout leaves around a panel's plotting area, CSS px: the y-axis title fits in it.
#[derive(Clone, Copy)]
struct TitleRoom {
    /// One legend row's height.
    legend_row: f64,
    /// The chart's margin.
    margin: f64,
    /// The y labels' band (ticks and title).
    y_label: f64,
    /// The x labels' band under the last panel.
    x_label: f64,
}

/// How a series is marked.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Mark {
    Line,
    Points,
    /// A line, with its points as dots while there are few of them.
    LineAndPoints,
}

/// One named series.
#[derive(Debug, Clone, PartialEq)]
pub struct SeriesSpec {
    pub name: String,
    /// CSS colour components.
    pub rgb: (u8, u8, u8),
    pub mark: Mark,
    /// Line width, CSS px before the line scale.
    pub width: f64,
    /// Opacity 0..1.
    pub alpha: f64,
}

/// One panel: its y axis and series (drawn in order: later series on top).
#[derive(Debug, Clone, PartialEq)]
pub struct PanelSpec {
    pub y: AxisSpec,
    pub series: Vec<SeriesSpec>,
}

/// The whole plot.
#[derive(Debug, Clone, PartialEq)]
pub struct PlotSpec {
    pub x: AxisSpec,
    pub panels: Vec<PanelSpec>,
    /// The cursor's CSS colour components.
    pub cursor_rgb: (u8, u8, u8),
}

/// A panel's plotting area, CSS px.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Area {
    x0: f64,
    x1: f64,
    y0: f64,
    y1: f64,
}

/// The widget.
pub struct Plot {
    pub canvas: LayeredCanvas,
    spec: Option<PlotSpec>,
    /// `data[panel][series]`: the points, x ascending for lines.
    data: Vec<Vec<Vec<(f64, f64)>>>,
    /// How many points of each series the data layer shows.
    drawn: Vec<Vec<usize>>,
    areas: Vec<Area>,
    /// Panels whose y axis is logarithmic.
    log_y: Vec<bool>,
    cursor: Option<f64>,
    markers: Vec<(usize, (f64, f64))>,
    axes_dirty: bool,
    data_dirty: bool,
    cursor_dirty: bool,
}

type DrawArea = DrawingArea<CanvasBackend, Shift>;

/// The axes layer's measures, device px.
#[derive(Debug, Clone, Copy)]
struct AxesLayout {
    dpr: f64,
    margin: i32,
    /// The x labels' band under the last panel and the y labels' band.
    x_label: i32,
    y_label: i32,
    /// The tick labels' size.
    font: f64,
    /// One legend row's height.
    legend_row: i32,
    /// Each panel's plotting height and one legend row.
    each: i32,
}

impl AxesLayout {
    /// The measures on a canvas `w` px wide; `None` when the margins leave no room to speak
    /// of. On a very narrow canvas with projector type the full label area would leave
    /// plotters a plotting area of negative width, where it lays the labels out as if on the
    /// right and measures them through an inline-styled <span> (blocked by the CSP), so the
    /// labels take at most half of the room.
    fn of(w: f64, dpr: f64, ink: Ink) -> Option<AxesLayout> {
        let k = dpr * ink.text;
        let margin = (8.0 * dpr * ink.text.sqrt()).round() as i32;
        let font = ink.text_px(12.0) * dpr;
        let room = w as i32 - 2 * margin - (1.2 * font) as i32;
        if room < (4.0 * font) as i32 {
            return None;
        }
        Some(AxesLayout {
            dpr,
            margin,
            x_label: (34.0 * k).round() as i32,
            y_label: ((74.0 * k).round() as i32).min(room / 2),
            font,
            legend_row: (ink.text_px(12.0) * 1.5 * dpr).round() as i32,
            each: 0,
        })
    }
}

/// A legend entry's line swatch, CSS px.
fn legend_swatch(ink: Ink) -> f64 {
    18.0 * ink.line
}

/// The gap between two legend entries, CSS px.
fn legend_gap(ink: Ink) -> f64 {
    14.0 * ink.text
}

/// `root` cut into one area per panel, top to bottom: each the panel's plotting height and
/// its `rows` legend rows, the last taking what remains.
fn split_panels(root: DrawArea, rows: &[i32], lay: &AxesLayout) -> Vec<DrawArea> {
    let mut rest = root;
    let mut panels = Vec::new();
    for (i, r) in rows.iter().enumerate() {
        if i + 1 == rows.len() {
            panels.push(rest.clone());
        } else {
            let (upper, lower) = rest.split_vertically(lay.each + lay.legend_row * r);
            panels.push(upper);
            rest = lower;
        }
    }
    panels
}

fn err<E: std::fmt::Debug>(e: E) -> String {
    format!("{e:?}")
}

/// Lines of more points than this are min/max-decimated per pixel column before drawing.
const DECIMATE_FROM: usize = 32;

/// Dots are drawn for a [`Mark::LineAndPoints`] series of at most this many points.
const DOTS_MAX: usize = 60;

impl Plot {
    /// Wraps the canvases of `stage`: axes, data, cursor (a stage with two canvases draws the
    /// cursor on the data layer).
    pub fn new(stage: &Element) -> Result<Plot, wasm_bindgen::JsValue> {
        Ok(Plot {
            canvas: LayeredCanvas::from_stage(stage)?,
            spec: None,
            data: Vec::new(),
            drawn: Vec::new(),
            areas: Vec::new(),
            log_y: Vec::new(),
            cursor: None,
            markers: Vec::new(),
            axes_dirty: true,
            data_dirty: true,
            cursor_dirty: true,
        })
    }

    /// Sets axes, panels and series; the data of series that still exist is kept.
    pub fn set_spec(&mut self, spec: PlotSpec) {
        if self.spec.as_ref() == Some(&spec) {
            return;
        }
        self.data.resize_with(spec.panels.len(), Vec::new);
        self.drawn.resize_with(spec.panels.len(), Vec::new);
        for (k, panel) in spec.panels.iter().enumerate() {
            self.data[k].resize_with(panel.series.len(), Vec::new);
            self.drawn[k].resize(panel.series.len(), 0);
        }
        self.spec = Some(spec);
        self.axes_dirty = true;
        self.data_dirty = true;
        self.cursor_dirty = true;
    }

    /// The spec set last, if any.
    pub fn spec(&self) -> Option<&PlotSpec> {
        self.spec.as_ref()
    }

    /// Makes the y axis of `panel` logarithmic (base 10) or linear (the default). The panel's
    /// range stays in data units and must be positive to be logarithmic (else it is widened to
    /// `1e-12..1`).
    pub fn set_log_y(&mut self, panel: usize, log: bool) {
        if self.log_y.len() <= panel {
            self.log_y.resize(panel + 1, false);
        }
        if self.log_y[panel] != log {
            self.log_y[panel] = log;
            self.axes_dirty = true;
            self.data_dirty = true;
        }
    }

    /// Whether the y axis of `panel` is logarithmic.
    pub fn is_log_y(&self, panel: usize) -> bool {
        self.log_y.get(panel).copied().unwrap_or(false)
    }

    /// The y range of `panel` on its axis (log₁₀ of the data range on a log axis).
    fn axis_y(&self, panel: usize, range: (f64, f64)) -> (f64, f64) {
        if self.is_log_y(panel) {
            log_axis_range(range)
        } else {
            range
        }
    }

    /// Replaces the points of one series.
    pub fn set_series(&mut self, panel: usize, series: usize, points: Vec<(f64, f64)>) {
        if let Some(s) = self.data.get_mut(panel).and_then(|p| p.get_mut(series)) {
            *s = points;
            self.data_dirty = true;
        }
    }

    /// Appends points to one series (drawn incrementally by the next [`Plot::draw`]).
    pub fn append(&mut self, panel: usize, series: usize, points: &[(f64, f64)]) {
        if let Some(s) = self.data.get_mut(panel).and_then(|p| p.get_mut(series)) {
            s.extend_from_slice(points);
        }
    }

    /// The points of one series.
    pub fn series(&self, panel: usize, series: usize) -> &[(f64, f64)] {
        self.data
            .get(panel)
            .and_then(|p| p.get(series))
            .map_or(&[], |s| s.as_slice())
    }

    /// Empties every series.
    pub fn clear(&mut self) {
        for p in &mut self.data {
            for s in p.iter_mut() {
                s.clear();
            }
        }
        self.data_dirty = true;
    }

    /// Moves (or hides) the cursor, an x value.
    pub fn set_cursor(&mut self, x: Option<f64>) {
        if self.cursor != x {
            self.cursor = x;
            self.cursor_dirty = true;
        }
    }

    /// Rings drawn on the cursor layer at `(panel, (x, y))` data points (the current state of
    /// a phase portrait, say); cheap to move, like the cursor.
    pub fn set_markers(&mut self, markers: Vec<(usize, (f64, f64))>) {
        if self.markers != markers {
            self.markers = markers;
            self.cursor_dirty = true;
        }
    }

    /// The pixel row of `y` in `panel` (log axes included; a value ≤ 0 on a log axis is the
    /// bottom edge).
    fn y_pixel(&self, panel: usize, y: f64) -> f64 {
        let Some((_, ys, _)) = self.scales(panel) else {
            return f64::NAN;
        };
        let v = if !self.is_log_y(panel) {
            y
        } else if y > 0.0 {
            y.log10()
        } else if y.is_nan() {
            f64::NAN
        } else {
            ys.domain.0.min(ys.domain.1)
        };
        ys.map(v)
    }

    /// The layers changed size or the language or the mode changed: redraw everything.
    pub fn invalidate_all(&mut self) {
        self.canvas.fit();
        self.redraw_all();
    }

    /// New data and axes at the same size: redraw everything at the next [`Plot::draw`] (which
    /// sizes the layers first if they never were, so a plot made while its page is being built
    /// does not lay the page out then).
    pub fn redraw_all(&mut self) {
        self.axes_dirty = true;
        self.data_dirty = true;
        self.cursor_dirty = true;
    }

    /// The x value under CSS px `px` (for dragging the cursor), clamped to the axis.
    pub fn x_at(&self, px: f64) -> Option<f64> {
        let (spec, area) = (self.spec.as_ref()?, self.areas.first()?);
        let (a, b) = spec.x.range;
        let v = LinearScale::new((a, b), (area.x0, area.x1)).invert(px);
        Some(v.clamp(a.min(b), a.max(b)))
    }

    /// The cursor as a drag handle (a thin capsule over every panel), CSS px.
    pub fn cursor_handle(&self, radius: f64) -> Option<HandleShape> {
        let (spec, x) = (self.spec.as_ref()?, self.cursor?);
        let (first, last) = (self.areas.first()?, self.areas.last()?);
        let px = LinearScale::new(spec.x.range, (first.x0, first.x1)).map(x);
        Some(HandleShape::Capsule {
            a: DVec2::new(px, first.y0),
            b: DVec2::new(px, last.y1),
            radius,
        })
    }

    /// The CSS px of data point `(x, y)` in panel `panel` (for drag handles on the data),
    /// once the axes have been drawn.
    pub fn to_px(&self, panel: usize, x: f64, y: f64) -> Option<DVec2> {
        let (xs, ys, _) = self.scales(panel)?;
        Some(DVec2::new(xs.map(x), ys.map(y)))
    }

    /// The data point under CSS px `at` in panel `panel` (not clamped).
    pub fn from_px(&self, panel: usize, at: DVec2) -> Option<(f64, f64)> {
        let (xs, ys, _) = self.scales(panel)?;
        Some((xs.invert(at.x), ys.invert(at.y)))
    }

    /// The plotting area of panel `panel`, CSS px: `(left, right, top, bottom)`.
    pub fn panel_px(&self, panel: usize) -> Option<(f64, f64, f64, f64)> {
        self.areas.get(panel).map(|a| (a.x0, a.x1, a.y0, a.y1))
    }

    /// Draws whatever changed.
    pub fn draw(&mut self, ink: Ink) -> Result<(), String> {
        if self.spec.is_none() {
            return Ok(());
        }
        if !self.canvas.is_fitted() {
            self.canvas.fit();
        }
        if self.axes_dirty {
            self.draw_axes(ink)?;
            self.axes_dirty = false;
            self.data_dirty = true;
        }
        let two_layers = self.canvas.layers.len() < 3;
        if self.data_dirty || (two_layers && self.cursor_dirty) {
            self.draw_data(ink, true);
            self.data_dirty = false;
            self.cursor_dirty = true;
        } else {
            self.draw_data(ink, false);
        }
        if self.cursor_dirty {
            self.draw_cursor(ink, !two_layers);
            self.cursor_dirty = false;
        }
        Ok(())
    }

    fn draw_axes(&mut self, ink: Ink) -> Result<(), String> {
        let Some(spec) = self.spec.clone() else {
            return Ok(());
        };
        let layer = self.canvas.layer(0);
        let _ = layer.ctx.set_transform(1.0, 0.0, 0.0, 1.0, 0.0, 0.0);
        layer.ctx.set_fill_style_str("#fbfcfe");
        let (w, h) = (
            f64::from(layer.canvas.width()),
            f64::from(layer.canvas.height()),
        );
        layer.ctx.fill_rect(0.0, 0.0, w, h);
        let Some(mut lay) = AxesLayout::of(w, layer.dpr, ink) else {
            self.areas.clear();
            return Ok(());
        };
        let backend =
            CanvasBackend::with_canvas_object(layer.canvas.clone()).ok_or("no canvas backend")?;
        let root = backend.into_drawing_area();
        let total = layer.canvas.height() as i32;
        let legends = self.legends(&spec, ink, &lay);
        // Every panel gets the same plotting height; a panel whose legend wraps to more rows
        // is that much taller (its rows are added, not taken from its data).
        let n = spec.panels.len().max(1) as i32;
        let rows: Vec<i32> = legends
            .iter()
            .map(|r| r.len().max(1) as i32)
            .chain(std::iter::repeat(1))
            .take(n as usize)
            .collect();
        lay.each = (total - lay.x_label - lay.legend_row * rows.iter().sum::<i32>()) / n;
        let panels = split_panels(root, &rows, &lay);
        self.areas.clear();
        for (i, (area, panel)) in panels.iter().zip(&spec.panels).enumerate() {
            let rows = rows.get(i).copied().unwrap_or(1);
            let plotting = self.draw_mesh(area, i, &spec, panel, rows, &lay)?;
            self.areas.push(plotting);
        }
        // Legends: one row above each panel's plotting area, right-aligned, so they never
        // cover the data.
        let dpr = lay.dpr;
        let _ = layer.ctx.set_transform(dpr, 0.0, 0.0, dpr, 0.0, 0.0);
        let css = |px: i32| f64::from(px) / dpr;
        let room = TitleRoom {
            legend_row: css(lay.legend_row),
            margin: css(lay.margin),
            y_label: css(lay.y_label),
            x_label: css(lay.x_label),
        };
        self.draw_y_titles(ink, &spec, &rows, room);
        self.draw_legends(ink, &spec, &legends, &lay);
        Ok(())
    }

    /// Each panel's legend rows: its named series' entries `(series, text width)` packed in
    /// order into rows as wide as the plotting area, so many series (or a narrow screen, or
    /// projector type) wrap, never overflow.
    fn legends(&self, spec: &PlotSpec, ink: Ink, lay: &AxesLayout) -> Vec<Vec<Vec<(usize, f64)>>> {
        let layer = self.canvas.layer(0);
        layer.ctx.set_font(&ink.font(12.0, false));
        let dpr = lay.dpr;
        let css_width = f64::from(layer.canvas.width()) / dpr;
        // The plotting area's width: less the margins, the y labels and the right-hand room.
        let legend_width =
            css_width - (f64::from(2 * lay.margin + lay.y_label) + 1.2 * lay.font) / dpr;
        spec.panels
            .iter()
            .map(|panel| {
                let entries: Vec<(usize, f64)> = panel
                    .series
                    .iter()
                    .enumerate()
                    .filter(|(_, s)| !s.name.is_empty())
                    .map(|(i, s)| {
                        let w = layer.ctx.measure_text(&s.name).map_or(40.0, |m| m.width());
                        (i, w)
                    })
                    .collect();
                legend_layout(
                    &entries,
                    legend_swatch(ink) + 6.0,
                    legend_gap(ink),
                    legend_width,
                )
            })
            .collect()
    }

    /// The mesh of panel `i` (`rows` legend rows above it) in `area`: frame, grid, ticks and
    /// their labels, and the x title under the last panel. Its plotting area, CSS px.
    fn draw_mesh(
        &self,
        area: &DrawArea,
        i: usize,
        spec: &PlotSpec,
        panel: &PanelSpec,
        rows: i32,
        lay: &AxesLayout,
    ) -> Result<Area, String> {
        let AxesLayout {
            dpr,
            margin,
            x_label,
            y_label,
            font,
            legend_row,
            each,
        } = *lay;
        // Label decimals from a finer step than plotters' ticks, so no two ticks read alike.
        let x_step = nice_step(spec.x.range.0, spec.x.range.1, 12);
        let x_desc = spec.x.desc();
        let bottom = i + 1 == spec.panels.len();
        let log = self.is_log_y(i);
        let y = self.axis_y(i, panel.y.range);
        let y_step = nice_step(y.0, y.1, 10);
        // A log axis: ticks on whole decades where the span allows (plotters picks 1-2-5
        // steps of at most this many labels).
        // No more labels than fit the panel's height (projector type is large).
        let fit = ((f64::from(each + legend_row) / (2.2 * font)).floor() as usize).max(2);
        let y_labels = if log {
            ((y.1 - y.0).abs().floor() as usize + 1).clamp(2, 8)
        } else {
            5
        }
        .min(fit);
        let mut chart = ChartBuilder::on(area)
            .margin(margin)
            .margin_top(margin + legend_row * rows)
            // Room for half of the last x tick label, centred on the right edge.
            .margin_right(margin + (1.2 * font) as i32)
            .x_label_area_size(if bottom { x_label } else { 0 })
            .y_label_area_size(y_label)
            .build_cartesian_2d(spec.x.range.0..spec.x.range.1, y.0..y.1)
            .map_err(err)?;
        let tick = (FontFamily::SansSerif, font)
            .into_font()
            .color(&RGBColor(58, 66, 80));
        let x_fmt = |v: &f64| tick_label(*v, x_step);
        let y_fmt = |v: &f64| {
            if log {
                return log_tick_label(*v);
            }
            // Ticks computed as sums can miss zero by a rounding error.
            if v.abs() < (y.1 - y.0).abs() * 1e-9 {
                "0".to_string()
            } else {
                tick_label(*v, y_step)
            }
        };
        let mut mesh = chart.configure_mesh();
        mesh.x_labels(6)
            .y_labels(y_labels)
            .x_label_formatter(&x_fmt)
            .y_label_formatter(&y_fmt)
            .label_style(tick.clone())
            .axis_desc_style(tick)
            .light_line_style(RGBColor(235, 238, 243))
            .bold_line_style(RGBColor(214, 219, 227));
        if bottom {
            mesh.x_desc(x_desc.as_str());
        }
        if log {
            // Linear subdivisions of decades would mislead.
            mesh.y_max_light_lines(0);
        }
        mesh.draw().map_err(err)?;
        let (xr, yr) = chart.plotting_area().get_pixel_range();
        Ok(Area {
            x0: f64::from(xr.start) / dpr,
            x1: f64::from(xr.end) / dpr,
            y0: f64::from(yr.start) / dpr,
            y1: f64::from(yr.end) / dpr,
        })
    }

    /// The legends' rows above each panel's plotting area, each row's last series ending at
    /// the right edge (CSS px transform set).
    fn draw_legends(
        &self,
        ink: Ink,
        spec: &PlotSpec,
        legends: &[Vec<Vec<(usize, f64)>>],
        lay: &AxesLayout,
    ) {
        let ctx = &self.canvas.layer(0).ctx;
        let (swatch, gap) = (legend_swatch(ink), legend_gap(ink));
        ctx.set_font(&ink.font(12.0, false));
        ctx.set_text_baseline("middle");
        ctx.set_text_align("left");
        let row_h = f64::from(lay.legend_row) / lay.dpr;
        for ((area, panel), rows) in self.areas.iter().zip(&spec.panels).zip(legends) {
            for (r, row) in rows.iter().enumerate() {
                let cy = area.y0 - row_h * (rows.len() - r) as f64 + row_h / 2.0 - 1.0;
                let mut x = area.x1;
                // Right to left, so the row's last series ends at the right edge.
                for &(i, w) in row.iter().rev() {
                    let Some(s) = panel.series.get(i) else {
                        continue;
                    };
                    x -= w;
                    ctx.set_fill_style_str("#3a4250");
                    let _ = ctx.fill_text(&s.name, x, cy);
                    x -= swatch + 6.0;
                    let (r, g, b) = s.rgb;
                    ctx.set_stroke_style_str(&format!("rgb({r},{g},{b})"));
                    ctx.set_line_width(3.0 * ink.line);
                    ctx.begin_path();
                    ctx.move_to(x, cy);
                    ctx.line_to(x + swatch, cy);
                    ctx.stroke();
                    x -= gap;
                }
            }
        }
    }

    /// Each panel's y-axis title, rotated, at the left of its label area and centred on its
    /// plotting area where it fits: on a short panel (projector type) it may use the panel's
    /// legend rows and margins, then goes on two lines (title and unit), then shrinks, then is
    /// cut (`view::plot::axis_title`), so it never runs into the next panel's title.
    fn draw_y_titles(&self, ink: Ink, spec: &PlotSpec, rows: &[i32], room: TitleRoom) {
        let TitleRoom {
            legend_row: row_h,
            margin,
            y_label: label_w,
            x_label,
        } = room;
        let ctx = &self.canvas.layer(0).ctx;
        let px = ink.text_px(12.0);
        ctx.set_font(&font_px(px, false));
        let line_h = 1.2 * px;
        let measure = |s: &str| ctx.measure_text(s).map_or(0.0, |m| m.width());
        let two_lines = label_w >= 5.0 * px;
        ctx.set_fill_style_str("#3a4250");
        ctx.set_text_align("center");
        ctx.set_text_baseline("middle");
        let last = self.areas.len().saturating_sub(1);
        for (i, ((area, panel), r)) in self.areas.iter().zip(&spec.panels).zip(rows).enumerate() {
            // The panel's own slot: its legend rows and margins, and under the last panel the
            // x labels' band (its left part, under the y ticks, is empty).
            let top = area.y0 - row_h * f64::from(*r) - margin + 3.0;
            let bottom = area.y1 + if i == last { x_label } else { margin } - 3.0;
            let room = (bottom - top).max(0.0);
            let title = axis_title(&panel.y.title, &panel.y.unit, room, two_lines, measure);
            if title.scale < 1.0 {
                ctx.set_font(&font_px(px * title.scale, false));
            }
            let length = title.lines.iter().map(|l| measure(l)).fold(0.0, f64::max);
            let half = length / 2.0;
            let cy = ((area.y0 + area.y1) / 2.0)
                .min(area.y1 - half)
                .max(top + half);
            for (k, line) in title.lines.iter().enumerate() {
                let cx = margin + line_h * title.scale * (0.6 + k as f64);
                ctx.save();
                let _ = ctx.translate(cx, cy);
                let _ = ctx.rotate(-std::f64::consts::FRAC_PI_2);
                let _ = ctx.fill_text(line, 0.0, 0.0);
                ctx.restore();
            }
            if title.scale < 1.0 {
                ctx.set_font(&font_px(px, false));
            }
        }
    }

    fn scales(&self, panel: usize) -> Option<(LinearScale, LinearScale, Area)> {
        let spec = self.spec.as_ref()?;
        let area = *self.areas.get(panel)?;
        let y = self.axis_y(panel, spec.panels.get(panel)?.y.range);
        Some((
            LinearScale::new(spec.x.range, (area.x0, area.x1)),
            LinearScale::new(y, (area.y1, area.y0)),
            area,
        ))
    }

    /// Draws the series: all of them (`full`), or only the points appended since.
    fn draw_data(&mut self, ink: Ink, full: bool) {
        let Some(spec) = self.spec.clone() else {
            return;
        };
        let layer = self.canvas.layer(1);
        if full {
            layer.begin();
        } else {
            let _ = layer
                .ctx
                .set_transform(layer.dpr, 0.0, 0.0, layer.dpr, 0.0, 0.0);
        }
        let ctx = &layer.ctx;
        for (p, panel) in spec.panels.iter().enumerate() {
            let Some((xs, ys, area)) = self.scales(p) else {
                continue;
            };
            let log = self.is_log_y(p);
            // A log axis: log₁₀ of the value; a value ≤ 0 (no logarithm) on the bottom edge.
            let bottom = ys.domain.0.min(ys.domain.1);
            let y_px = |y: f64| {
                if !log {
                    ys.map(y)
                } else if y > 0.0 {
                    ys.map(y.log10())
                } else {
                    ys.map(bottom)
                }
            };
            ctx.save();
            ctx.begin_path();
            ctx.rect(area.x0, area.y0, area.x1 - area.x0, area.y1 - area.y0);
            ctx.clip();
            for (s, series) in panel.series.iter().enumerate() {
                let pts = self.series(p, s);
                let from = if full {
                    0
                } else {
                    self.drawn[p][s].min(pts.len())
                };
                if from >= pts.len() {
                    continue;
                }
                // Continue the line from the last point already drawn.
                let start = from.saturating_sub(1);
                let (r, g, b) = series.rgb;
                let colour = format!("rgba({r},{g},{b},{})", series.alpha);
                if series.mark != Mark::Points {
                    let part = &pts[start..];
                    // Decimated whenever there are more points than a few per pixel column
                    // could need (an appended frame of 167 steps may span 8 columns): the
                    // same pixels for far fewer canvas calls.
                    let thin;
                    let line: &[(f64, f64)] = if part.len() > DECIMATE_FROM {
                        thin = decimate(part, &xs);
                        &thin
                    } else {
                        part
                    };
                    ctx.set_stroke_style_str(&colour);
                    ctx.set_line_width(series.width * ink.line);
                    ctx.set_line_join("round");
                    ctx.begin_path();
                    let mut pen_down = false;
                    for &(x, y) in line {
                        if !x.is_finite() || !y.is_finite() {
                            pen_down = false;
                            continue;
                        }
                        let (px, py) = (xs.map(x), y_px(y).clamp(-1e6, 1e6));
                        if pen_down {
                            ctx.line_to(px, py);
                        } else {
                            ctx.move_to(px, py);
                            pen_down = true;
                        }
                    }
                    ctx.stroke();
                }
                let dots = match series.mark {
                    Mark::Points => true,
                    Mark::LineAndPoints => pts.len() <= DOTS_MAX,
                    Mark::Line => false,
                };
                if dots {
                    ctx.set_fill_style_str(&colour);
                    let radius = (series.width + 1.0) * ink.line;
                    for &(x, y) in &pts[from..] {
                        if x.is_finite() && y.is_finite() {
                            ctx.begin_path();
                            let _ = ctx.arc(xs.map(x), y_px(y), radius, 0.0, std::f64::consts::TAU);
                            ctx.fill();
                        }
                    }
                }
                self.drawn[p][s] = pts.len();
            }
            ctx.restore();
        }
        if full {
            for (p, panel) in self.drawn.iter_mut().enumerate() {
                for (s, n) in panel.iter_mut().enumerate() {
                    *n = self.data.get(p).and_then(|d| d.get(s)).map_or(0, Vec::len);
                }
            }
        }
    }

    /// Draws the cursor on the top layer (`own_layer`) or over the data.
    fn draw_cursor(&self, ink: Ink, own_layer: bool) {
        let Some(spec) = &self.spec else {
            return;
        };
        let layer = self.canvas.top();
        if own_layer {
            layer.begin();
        }
        let ctx = &layer.ctx;
        let (r, g, b) = spec.cursor_rgb;
        ctx.set_stroke_style_str(&format!("rgba({r},{g},{b},0.85)"));
        ctx.set_line_width(1.5 * ink.line);
        let _ = ctx.set_line_dash(&solid());
        for &(p, (x, y)) in &self.markers {
            let Some((xs, _, area)) = self.scales(p) else {
                continue;
            };
            let (px, py) = (xs.map(x), self.y_pixel(p, y));
            let inside = (area.x0..=area.x1).contains(&px) && (area.y0..=area.y1).contains(&py);
            if inside {
                ctx.begin_path();
                let _ = ctx.arc(px, py, 5.0 * ink.line, 0.0, std::f64::consts::TAU);
                ctx.stroke();
            }
        }
        let Some(x) = self.cursor else {
            return;
        };
        for p in 0..self.areas.len() {
            let Some((xs, _, area)) = self.scales(p) else {
                continue;
            };
            if !(spec.x.range.0.min(spec.x.range.1)..=spec.x.range.0.max(spec.x.range.1))
                .contains(&x)
            {
                continue;
            }
            let px = xs.map(x);
            ctx.begin_path();
            ctx.move_to(px, area.y0);
            ctx.line_to(px, area.y1);
            ctx.stroke();
        }
    }
}
