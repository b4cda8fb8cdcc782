//! The Jacobian sweep plots (plotters on canvas): det J and w (m², top) and σ_min, σ_max (m,
//! bottom) along the jacobian-2r recipe's q1 sweep at the current q2, with the current q1
//! marked.
//!
//! Two stacked canvases: the background (axes, grid, tick labels, legend) is drawn only when
//! the sweep range, the arm, the size or the language changes; the series and the marker are
//! redrawn on the top canvas once per animation frame. Both use the same fixed label areas and
//! y ranges (`|det J| ≤ L1 L2`, `σ ≤ sqrt((L1 + L2)² + L2²)`), so their plot areas coincide and
//! no text is measured during a drag (plotters' web font backend measures text through the DOM).

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters_canvas::CanvasBackend;
use web_sys::HtmlCanvasElement;

use super::canvas::Layer;

/// One sample of the sweep.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SweepPoint {
    pub q1: f64,
    pub det_j: f64,
    pub manipulability: f64,
    pub sigma_min: f64,
    pub sigma_max: f64,
}

/// Axis ranges of both charts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlotSpec {
    pub x: (f64, f64),
    pub top_y: (f64, f64),
    pub bottom_y: (f64, f64),
}

impl PlotSpec {
    /// Ranges for a sweep `q1_start..=q1_stop` of an arm with lengths `l1`, `l2`.
    pub fn new(q1_start: f64, q1_stop: f64, l1: f64, l2: f64) -> PlotSpec {
        let (mut a, mut b) = (q1_start.min(q1_stop), q1_start.max(q1_stop));
        if b - a < 1e-9 {
            a -= 0.5;
            b += 0.5;
        }
        let det_max = (l1 * l2).max(1e-300) * 1.08;
        let sigma_max = ((l1 + l2).powi(2) + l2 * l2).sqrt().max(1e-300) * 1.08;
        PlotSpec {
            x: (a, b),
            top_y: (-det_max, det_max),
            bottom_y: (0.0, sigma_max),
        }
    }
}

/// Localized axis titles of the plots (the legend is HTML beside the canvas).
pub struct PlotLabels {
    pub x_desc: String,
    pub top_desc: String,
    pub bottom_desc: String,
}

/// Series colours; the HTML legend uses the same ones ([`LEGEND`]).
const C_DET: RGBColor = RGBColor(31, 119, 180);
const C_W: RGBColor = RGBColor(240, 150, 40);
const C_SMIN: RGBColor = RGBColor(44, 160, 44);
const C_SMAX: RGBColor = RGBColor(148, 103, 189);
const C_MARK: RGBColor = RGBColor(217, 72, 15);

/// The HTML legend: (Fluent id, CSS colour).
pub const LEGEND: [(&str, &str); 5] = [
    ("ik2r-plot-det", "rgb(31,119,180)"),
    ("ik2r-plot-w", "rgb(240,150,40)"),
    ("ik2r-plot-smin", "rgb(44,160,44)"),
    ("ik2r-plot-smax", "rgb(148,103,189)"),
    ("ik2r-plot-now", "rgb(217,72,15)"),
];

/// Pixel sizes of the chart frame for device-pixel scale `k`.
struct Frame {
    margin: i32,
    x_label: i32,
    y_label: i32,
    font: f64,
}

fn frame(k: f64) -> Frame {
    Frame {
        margin: (8.0 * k).round() as i32,
        x_label: (34.0 * k).round() as i32,
        y_label: (74.0 * k).round() as i32,
        font: 12.0 * k,
    }
}

type Area = DrawingArea<CanvasBackend, Shift>;

fn areas(canvas: &HtmlCanvasElement) -> Option<(Area, Area)> {
    let backend = CanvasBackend::with_canvas_object(canvas.clone())?;
    let root = backend.into_drawing_area();
    let h = canvas.height() as i32;
    let (top, bottom) = root.split_vertically(h / 2);
    Some((top, bottom))
}

fn err<E: std::fmt::Debug>(e: E) -> String {
    format!("{e:?}")
}

/// Draws the axes, tick labels, axis titles and legends on `layer` (device pixels; `scale`
/// is the projector scale).
pub fn draw_background(
    layer: &Layer,
    spec: &PlotSpec,
    labels: &PlotLabels,
    scale: f64,
) -> Result<(), String> {
    let _ = layer.ctx.set_transform(1.0, 0.0, 0.0, 1.0, 0.0, 0.0);
    layer.ctx.set_fill_style_str("#fbfcfe");
    layer.ctx.fill_rect(
        0.0,
        0.0,
        f64::from(layer.canvas.width()),
        f64::from(layer.canvas.height()),
    );
    let k = layer.dpr * scale;
    let f = frame(k);
    let (top, bottom) = areas(&layer.canvas).ok_or("no canvas backend")?;
    let charts = [
        (&top, spec.top_y, &labels.top_desc),
        (&bottom, spec.bottom_y, &labels.bottom_desc),
    ];
    for (area, y, desc) in charts {
        let mut chart = ChartBuilder::on(area)
            .margin(f.margin)
            .x_label_area_size(f.x_label)
            .y_label_area_size(f.y_label)
            .build_cartesian_2d(spec.x.0..spec.x.1, y.0..y.1)
            .map_err(err)?;
        let tick = ("sans-serif", f.font)
            .into_font()
            .color(&RGBColor(58, 66, 80));
        chart
            .configure_mesh()
            .x_labels(6)
            .y_labels(5)
            .x_label_formatter(&|v| format!("{v:.2}"))
            .y_label_formatter(&|v| {
                // Ticks computed as sums can miss zero by a rounding error.
                if v.abs() < (y.1 - y.0).abs() * 1e-9 {
                    "0".to_string()
                } else {
                    super::heatmap::legend_value(*v)
                }
            })
            .x_desc(labels.x_desc.as_str())
            .y_desc(desc.as_str())
            .label_style(tick.clone())
            .axis_desc_style(tick)
            .light_line_style(RGBColor(235, 238, 243))
            .bold_line_style(RGBColor(214, 219, 227))
            .draw()
            .map_err(err)?;
    }
    Ok(())
}

/// Draws the series and the current-q1 marker on the transparent `layer`.
pub fn draw_series(
    layer: &Layer,
    spec: &PlotSpec,
    points: &[SweepPoint],
    q1_marker: Option<f64>,
    scale: f64,
) -> Result<(), String> {
    let _ = layer.ctx.set_transform(1.0, 0.0, 0.0, 1.0, 0.0, 0.0);
    layer.ctx.clear_rect(
        0.0,
        0.0,
        f64::from(layer.canvas.width()),
        f64::from(layer.canvas.height()),
    );
    let k = layer.dpr * scale;
    let f = frame(k);
    let width = (2.0 * k).round().max(1.0) as u32;
    let (top, bottom) = areas(&layer.canvas).ok_or("no canvas backend")?;
    type Pick = fn(&SweepPoint) -> f64;
    type Chart<'a> = (&'a Area, (f64, f64), [(Pick, RGBColor); 2]);
    let charts: [Chart; 2] = [
        (
            &top,
            spec.top_y,
            [(|p| p.det_j, C_DET), (|p| p.manipulability, C_W)],
        ),
        (
            &bottom,
            spec.bottom_y,
            [(|p| p.sigma_min, C_SMIN), (|p| p.sigma_max, C_SMAX)],
        ),
    ];
    for (area, y, series) in charts {
        let mut chart = ChartBuilder::on(area)
            .margin(f.margin)
            .x_label_area_size(f.x_label)
            .y_label_area_size(f.y_label)
            .build_cartesian_2d(spec.x.0..spec.x.1, y.0..y.1)
            .map_err(err)?;
        if let Some(q1) = q1_marker {
            chart
                .draw_series(LineSeries::new(
                    [(q1, y.0), (q1, y.1)],
                    C_MARK
                        .mix(0.8)
                        .stroke_width((1.5 * k).round().max(1.0) as u32),
                ))
                .map_err(err)?;
        }
        // The second series of each chart is drawn first, wide and pale, so that the first
        // stays visible where they coincide (det J = w whenever q2 > 0).
        for (i, (pick, colour)) in series.into_iter().enumerate().rev() {
            let data = points.iter().map(|p| (p.q1, pick(p)));
            let style = if i == 1 {
                colour.mix(0.55).stroke_width(width * 3)
            } else {
                colour.stroke_width(width)
            };
            chart
                .draw_series(LineSeries::new(data, style))
                .map_err(err)?;
            if points.len() <= 60 {
                let r = (2.5 * k).round() as i32;
                chart
                    .draw_series(
                        points
                            .iter()
                            .map(|p| Circle::new((p.q1, pick(p)), r, colour.filled())),
                    )
                    .map_err(err)?;
            }
        }
    }
    Ok(())
}

/// The q1 to mark: the current q1, or the same angle ±2π, if it lies in the sweep.
pub fn marker_in_range(q1: f64, spec: &PlotSpec) -> Option<f64> {
    let tau = std::f64::consts::TAU;
    [q1, q1 - tau, q1 + tau, crate::planar2r::wrap_angle(q1)]
        .into_iter()
        .find(|q| (spec.x.0..=spec.x.1).contains(q))
}
