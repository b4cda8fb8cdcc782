//! The plot of every joint (the kit's plot widget): one panel per joint, every joint of the
//! file however many, sharing the time axis of the input's span, with the input's samples as
//! dots and the resampled series as a line. The stage grows with the joints (the CSS reads
//! `--traj-panels`), so each panel keeps a readable height; the page scrolls past it.
//! Both come as plot envelopes (at most four points per bucket, [`crate::view::envelope`]), so
//! a million rows draw in one frame; the widget decimates again to its pixel columns.

use wasm_bindgen::{JsCast, JsValue};
use web_sys::{Element, HtmlElement};

use crate::ui::ctx;
use crate::ui::kit::canvas::Ink;
use crate::ui::kit::plot::{AxisSpec, Mark, PanelSpec, Plot, PlotSpec, SeriesSpec};
use crate::view::envelope::Envelope;
use crate::view::plot::{auto_range, decimate, LinearScale};
use crate::view::traj_resample::joint_columns;

/// Buckets of the sample dots of a dense input: each dot is its own canvas path (about 10 µs
/// in headless Chromium), so a million-row file keeps at most four dots per bucket (its first,
/// lowest, highest and last sample: every spike stays) and draws in a frame; the resampled
/// line keeps the envelope's full resolution.
const DOT_BUCKETS: f64 = 100.0;

/// `points` (x ascending) thinned to at most four per dot bucket of `x_range`.
fn thin_dots(points: &[(f64, f64)], x_range: (f64, f64)) -> Vec<(f64, f64)> {
    if points.len() <= 4 * DOT_BUCKETS as usize {
        return points.to_vec();
    }
    decimate(points, &LinearScale::new(x_range, (0.0, DOT_BUCKETS)))
}

/// Up to this many joints the stage keeps its height (the CSS's); each one more adds a panel's
/// height.
const GROW_FROM: usize = 6;

/// A series' points, `(t, q)`.
type Points = Vec<(f64, f64)>;

/// The plot component.
pub struct Joints {
    pub plot: Plot,
    /// The stage (its height follows the number of panels) and the panels set last.
    stage: Element,
    panels: usize,
    /// Per panel: the resampled line and the sample dots, until [`Joints::fill`].
    pending: Vec<(Points, Points)>,
}

impl Joints {
    /// Wraps the stage (three canvases).
    pub fn new(stage: &Element) -> Result<Joints, JsValue> {
        let mut plot = Plot::new(stage)?;
        plot.canvas.fit();
        Ok(Joints {
            plot,
            stage: stage.clone(),
            panels: 0,
            pending: Vec::new(),
        })
    }

    /// New axes for `input` (samples) and `output` (resampled), labels in the current
    /// language, the data emptied; their series wait for [`Joints::fill`].
    pub fn set(&mut self, input: &Envelope, output: &Envelope) {
        let shown = joint_columns(&output.header);
        self.set_panels(shown.len());
        // 2 % either side, so the first and last samples are not cut by the frame.
        let x_range = match input.x_span.or(output.x_span) {
            Some((a, b)) if b > a => (a - 0.02 * (b - a), b + 0.02 * (b - a)),
            Some((a, _)) => (a - 0.5, a + 0.5),
            None => (0.0, 1.0),
        };
        let samples_name = ctx::t("traj-series-samples");
        let resampled_name = ctx::t("traj-series-resampled");
        let panels = shown
            .iter()
            .map(|name| {
                let ys = input
                    .column(name)
                    .iter()
                    .chain(output.column(name))
                    .map(|p| p.1);
                PanelSpec {
                    y: AxisSpec {
                        title: name.clone(),
                        unit: String::new(),
                        range: auto_range(ys, 0.08).unwrap_or((-1.0, 1.0)),
                    },
                    series: vec![
                        SeriesSpec {
                            name: resampled_name.clone(),
                            rgb: (31, 119, 180),
                            mark: Mark::Line,
                            width: 1.6,
                            alpha: 1.0,
                        },
                        SeriesSpec {
                            name: samples_name.clone(),
                            rgb: (214, 39, 40),
                            mark: Mark::Points,
                            width: 1.6,
                            alpha: 0.9,
                        },
                    ],
                }
            })
            .collect();
        self.plot.clear();
        self.plot.set_spec(PlotSpec {
            x: AxisSpec {
                title: ctx::t("traj-axis-time"),
                unit: "s".into(),
                range: x_range,
            },
            panels,
            cursor_rgb: (90, 90, 90),
        });
        self.pending = shown
            .iter()
            .map(|name| {
                (
                    output.column(name).to_vec(),
                    thin_dots(input.column(name), x_range),
                )
            })
            .collect();
        // No refit here: reading the layout right after the page's texts changed forced a
        // full layout (130 ms after a big result); the stage's resize observer refits.
    }

    /// `n` panels: past [`GROW_FROM`] the stage grows (`--traj-panels`, read by the CSS);
    /// written only when the count changes (a style change costs a layout of the page).
    fn set_panels(&mut self, n: usize) {
        if n == self.panels {
            return;
        }
        self.panels = n;
        if let Some(stage) = self.stage.dyn_ref::<HtmlElement>() {
            let style = stage.style();
            let _ = if n > GROW_FROM {
                style.set_property("--traj-panels", &n.to_string())
            } else {
                style.remove_property("--traj-panels").map(|_| ())
            };
        }
        // How many panels, for tests and assistive tools.
        let top = &self.plot.canvas.top().canvas;
        let _ = top.set_attribute("data-panels", &n.to_string());
    }

    /// Hands the series kept by [`Joints::set`] to the plot (drawn by the next
    /// [`Joints::draw`]): the page draws the axes and the data in two tasks, so neither of a
    /// million-row result's frames is long.
    pub fn fill(&mut self) {
        for (k, (line, dots)) in std::mem::take(&mut self.pending).into_iter().enumerate() {
            self.plot.set_series(k, 0, line);
            self.plot.set_series(k, 1, dots);
        }
    }

    /// The stage changed size (or projector mode): refit and redraw everything.
    pub fn relayout(&mut self) {
        self.plot.invalidate_all();
    }

    /// Draws what changed.
    pub fn draw(&mut self, ink: Ink) -> Result<(), String> {
        self.plot.draw(ink)
    }
}
