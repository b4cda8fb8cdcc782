//! The Jacobian sweep plot (the kit plot): det J and w (m², top panel) and σ_min, σ_max (m,
//! bottom panel) along the jacobian-2r recipe's q1 sweep at the current q2, sharing the q1
//! axis, with the current q1 as the cursor. The axes (fixed by the arm and the sweep range,
//! so a drag never rescales them) are drawn only when those, the size or the language change;
//! the series follow q2 every frame, the cursor follows q1.

use wasm_bindgen::prelude::*;
use web_sys::Element;

use super::markup::role;
use crate::ui::ctx;
use crate::ui::kit::canvas::Ink;
use crate::ui::kit::plot::{AxisSpec, Mark, PanelSpec, Plot, PlotSpec, SeriesSpec};
use crate::view::ik2r::{marker_in_range, sweep_points, sweep_ranges, Params, State};
use crate::view::palette;

/// Series colours (top: det J, w; bottom: σ_min, σ_max) and the cursor's, Okabe–Ito: the
/// pairs of a panel and the cursor stay apart with every common colour-vision deficiency (the
/// light orange is the wide line).
const C_DET: (u8, u8, u8) = palette::BLUE.rgb;
const C_W: (u8, u8, u8) = palette::ORANGE.rgb;
const C_SMIN: (u8, u8, u8) = palette::BLUISH_GREEN.rgb;
const C_SMAX: (u8, u8, u8) = palette::REDDISH_PURPLE.rgb;
const C_NOW: (u8, u8, u8) = palette::VERMILION.rgb;

/// The sweep plot component.
pub(super) struct SweepPlot {
    plot: Plot,
    /// The (params, q2) the plotted series were computed for.
    key: Option<(Params, f64)>,
}

fn series(id: &str, rgb: (u8, u8, u8), wide: bool) -> SeriesSpec {
    SeriesSpec {
        name: ctx::t(id),
        rgb,
        mark: Mark::LineAndPoints,
        // The second series of a panel is drawn first, wide and pale, so that the first stays
        // visible where they coincide (det J = w whenever q2 > 0).
        width: if wide { 6.0 } else { 2.0 },
        alpha: if wide { 0.55 } else { 1.0 },
    }
}

impl SweepPlot {
    pub fn find(root: &Element) -> Result<SweepPlot, JsValue> {
        let stage: Element = role(root, "plot-stage")?;
        Ok(SweepPlot {
            plot: Plot::new(&stage)?,
            key: None,
        })
    }

    /// The canvases changed size.
    pub fn resized(&mut self) {
        self.plot.invalidate_all();
    }

    /// Axes, panels and series names for `p` in the current language.
    pub fn set_axes(&mut self, p: &Params) {
        let [x, top, bottom] = sweep_ranges(p);
        let axis = |id: &str, range| AxisSpec {
            title: ctx::t(id),
            unit: String::new(),
            range,
        };
        self.plot.set_spec(PlotSpec {
            x: axis("ik2r-plot-x", x),
            panels: vec![
                PanelSpec {
                    y: axis("ik2r-plot-top", top),
                    series: vec![
                        series("ik2r-plot-w", C_W, true),
                        series("ik2r-plot-det", C_DET, false),
                    ],
                },
                PanelSpec {
                    y: axis("ik2r-plot-bottom", bottom),
                    series: vec![
                        series("ik2r-plot-smax", C_SMAX, true),
                        series("ik2r-plot-smin", C_SMIN, false),
                    ],
                },
            ],
            cursor_rgb: C_NOW,
        });
        self.key = None;
    }

    pub fn relocalize(&mut self, p: &Params) {
        self.set_axes(p);
    }

    /// The series at the current q2 (recomputed when it or the parameters changed) and the
    /// cursor at the current q1.
    pub fn draw(&mut self, st: &State, ink: Ink) {
        let key = (st.params, st.q2);
        if self.key != Some(key) {
            let pts = sweep_points(&st.params, st.q2);
            let col = |f: fn(&crate::view::ik2r::SweepPoint) -> f64| {
                pts.iter().map(|p| (p.q1, f(p))).collect()
            };
            self.plot.set_series(0, 0, col(|p| p.manipulability));
            self.plot.set_series(0, 1, col(|p| p.det_j));
            self.plot.set_series(1, 0, col(|p| p.sigma_max));
            self.plot.set_series(1, 1, col(|p| p.sigma_min));
            self.key = Some(key);
        }
        let [x, _, _] = sweep_ranges(&st.params);
        self.plot.set_cursor(marker_in_range(st.q1, x));
        if let Err(e) = self.plot.draw(ink) {
            web_sys::console::warn_1(&format!("ik-2r plot: {e}").into());
        }
    }
}
