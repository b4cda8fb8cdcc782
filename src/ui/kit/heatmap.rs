//! A colour-map heatmap with a legend: a node grid of values painted once into an image (one
//! pixel per node, [`crate::view::heatmap::fill_rgba`]) and drawn scaled on the background
//! layer with tick labels, axis titles and a colour bar; the top layer is left to the page for
//! per-frame marks ([`Heatmap::draw_marker`] draws the usual ring and crosshair).
//!
//! ```ignore
//! let mut map = Heatmap::new(&stage, (-PI, PI), (-PI, PI))?;
//! map.paint(&values, n, n, (0.0, top))?;     // when the data change
//! map.fit(ink);                               // after a resize
//! map.draw_background(&spec, ink, |_, _| {}); // axes, legend, page extras
//! map.draw_marker(x, y, hover, ink);          // per frame
//! ```

use std::f64::consts::PI;

use glam::DVec2;
use wasm_bindgen::{Clamped, JsValue};
use web_sys::{CanvasRenderingContext2d, Element, ImageData};

use super::canvas::{dash, solid, Ink, Layer, LayeredCanvas};
use crate::ui::dom;
use crate::view::heatmap::{fill_rgba, legend_value, viridis, HeatLayout, Rgb};

/// The heatmap's text, already localized, and its ticks.
pub struct HeatmapSpec<'a> {
    pub x_title: &'a str,
    pub y_title: &'a str,
    pub legend_title: &'a str,
    /// Tick positions (axis values) and their labels.
    pub x_ticks: &'a [(f64, &'a str)],
    pub y_ticks: &'a [(f64, &'a str)],
}

/// The widget.
pub struct Heatmap {
    pub canvas: LayeredCanvas,
    image: Layer,
    /// The painted grid's size and colour scale, once painted.
    painted: Option<(usize, usize, (f64, f64))>,
    pub layout: HeatLayout,
    lut: Vec<Rgb>,
}

impl Heatmap {
    /// Wraps the canvases of `stage` (background, then top) for a map of `x_range` ×
    /// `y_range`.
    pub fn new(
        stage: &Element,
        x_range: (f64, f64),
        y_range: (f64, f64),
    ) -> Result<Heatmap, JsValue> {
        Ok(Heatmap {
            canvas: LayeredCanvas::from_stage(stage)?,
            image: Layer::offscreen(&dom::document()?)?,
            painted: None,
            layout: HeatLayout::new(100.0, 100.0, 1.0, x_range, y_range),
            lut: viridis(),
        })
    }

    /// The colour map.
    pub fn lut(&self) -> &[Rgb] {
        &self.lut
    }

    /// The painted grid's node counts (0 before the first paint).
    pub fn grid(&self) -> (usize, usize) {
        self.painted.map_or((0, 0), |(nx, ny, _)| (nx, ny))
    }

    /// Paints `values` (`values[i * ny + j]`) coloured over `scale`.
    pub fn paint(
        &mut self,
        values: &[f32],
        nx: usize,
        ny: usize,
        scale: (f64, f64),
    ) -> Result<(), JsValue> {
        if nx == 0 || ny == 0 {
            return Err(JsValue::from_str("kit heatmap: empty grid"));
        }
        let rgba = fill_rgba(values, nx, ny, scale, &self.lut);
        self.image.resize(nx as f64, ny as f64, 1.0);
        let data =
            ImageData::new_with_u8_clamped_array_and_sh(Clamped(&rgba), nx as u32, ny as u32)?;
        let _ = self.image.ctx.set_transform(1.0, 0.0, 0.0, 1.0, 0.0, 0.0);
        self.image.ctx.put_image_data(&data, 0.0, 0.0)?;
        self.painted = Some((nx, ny, scale));
        Ok(())
    }

    /// Sizes the layers from the stage and lays out the square and legend.
    pub fn fit(&mut self, ink: Ink) {
        self.canvas.fit();
        let (w, h) = self.canvas.size();
        self.layout = HeatLayout::new(w, h, ink.text, self.layout.x_range, self.layout.y_range);
    }

    /// The top layer (per-frame marks).
    pub fn top(&self) -> &Layer {
        self.canvas.top()
    }

    /// The node under `p` (CSS px of the top layer).
    pub fn node_at(&self, p: DVec2) -> Option<(usize, usize)> {
        let (nx, ny) = self.grid();
        if nx == 0 {
            return None;
        }
        self.layout.node_at(p.x, p.y, nx, ny)
    }

    /// Draws the background: the painted grid, frame, ticks, titles, the colour legend, then
    /// `extra` (page marks such as singular lines) over the square.
    pub fn draw_background(
        &self,
        spec: &HeatmapSpec,
        ink: Ink,
        extra: impl FnOnce(&CanvasRenderingContext2d, &HeatLayout),
    ) {
        let layer = self.canvas.layer(0);
        let lay = &self.layout;
        layer.begin();
        let ctx = &layer.ctx;
        ctx.set_fill_style_str("#fbfcfe");
        ctx.fill_rect(0.0, 0.0, layer.css_w, layer.css_h);
        if let Some((nx, ny, _)) = self.painted {
            let (x, y, w, h) = lay.image_rect(nx, ny);
            ctx.save();
            ctx.begin_path();
            ctx.rect(lay.x, lay.y, lay.size, lay.size);
            ctx.clip();
            ctx.set_image_smoothing_enabled(false);
            let _ = ctx.draw_image_with_html_canvas_element_and_dw_and_dh(
                &self.image.canvas,
                x,
                y,
                w,
                h,
            );
            ctx.restore();
        }
        ctx.set_stroke_style_str("#5b6575");
        ctx.set_line_width(1.0);
        ctx.stroke_rect(lay.x + 0.5, lay.y + 0.5, lay.size - 1.0, lay.size - 1.0);
        extra(ctx, lay);

        ctx.set_fill_style_str("#3a4250");
        ctx.set_font(&ink.font(11.0, false));
        ctx.set_text_align("center");
        ctx.set_text_baseline("top");
        for (v, label) in spec.x_ticks {
            let _ = ctx.fill_text(label, lay.x_of(*v), lay.y + lay.size + 4.0);
        }
        ctx.set_text_align("right");
        ctx.set_text_baseline("middle");
        for (v, label) in spec.y_ticks {
            let _ = ctx.fill_text(label, lay.x - 5.0, lay.y_of(*v));
        }
        ctx.set_text_align("center");
        ctx.set_text_baseline("bottom");
        let _ = ctx.fill_text(
            spec.x_title,
            lay.x + lay.size / 2.0,
            lay.y + lay.size + 36.0 * ink.text,
        );
        ctx.save();
        let _ = ctx.translate(12.0 * ink.text, lay.y + lay.size / 2.0);
        let _ = ctx.rotate(-PI / 2.0);
        ctx.set_text_baseline("middle");
        let _ = ctx.fill_text(spec.y_title, 0.0, 0.0);
        ctx.restore();

        // Legend: the colour bar from the scale's bottom to its top.
        let (lx, lw) = (lay.legend_x, lay.legend_w);
        let steps = 64;
        for k in 0..steps {
            let t = k as f64 / (steps - 1) as f64;
            let idx = ((t * 255.0).round() as usize).min(255);
            let [r, g, b] = self.lut.get(idx).copied().unwrap_or([0, 0, 0]);
            ctx.set_fill_style_str(&format!("rgb({r},{g},{b})"));
            let y0 = lay.y + lay.size * (1.0 - (k + 1) as f64 / steps as f64);
            ctx.fill_rect(lx, y0, lw, lay.size / steps as f64 + 0.5);
        }
        ctx.set_stroke_style_str("#5b6575");
        ctx.stroke_rect(lx + 0.5, lay.y + 0.5, lw - 1.0, lay.size - 1.0);
        ctx.set_fill_style_str("#3a4250");
        ctx.set_text_align("left");
        ctx.set_text_baseline("middle");
        let (lo, hi) = self.painted.map_or((0.0, 1.0), |(_, _, s)| s);
        let mut widest: f64 = 0.0;
        for t in [0.0, 0.5, 1.0] {
            // max then min, not clamp: on a short panel with projector type the margins
            // cross (lo > hi), where clamp panics.
            let y = (lay.y + lay.size * (1.0 - t))
                .max(lay.y + 6.0 * ink.text)
                .min(lay.y + lay.size - 6.0 * ink.text);
            let text = legend_value(lo + t * (hi - lo));
            if let Ok(m) = ctx.measure_text(&text) {
                widest = widest.max(m.width());
            }
            let _ = ctx.fill_text(&text, lx + lw + 4.0, y);
        }
        ctx.save();
        let _ = ctx.translate(lx + lw + widest + 16.0 * ink.text, lay.y + lay.size / 2.0);
        let _ = ctx.rotate(-PI / 2.0);
        ctx.set_text_align("center");
        let _ = ctx.fill_text(spec.legend_title, 0.0, 0.0);
        ctx.restore();
    }

    /// Clears the top layer and draws a marker ring at axis values `at` and, if given, a
    /// dashed crosshair through `hover`.
    pub fn draw_marker(&self, at: (f64, f64), hover: Option<(f64, f64)>, ink: Ink) {
        let layer = self.canvas.top();
        let lay = &self.layout;
        layer.begin();
        let ctx = &layer.ctx;
        let s = ink.line;
        if let Some((hx, hy)) = hover {
            let (x, y) = (lay.x_of(hx), lay.y_of(hy));
            ctx.set_stroke_style_str("rgba(255, 255, 255, 0.9)");
            ctx.set_line_width(1.5 * s);
            let _ = ctx.set_line_dash(&dash(3.0 * s, 3.0 * s));
            ctx.begin_path();
            ctx.move_to(x, lay.y);
            ctx.line_to(x, lay.y + lay.size);
            ctx.move_to(lay.x, y);
            ctx.line_to(lay.x + lay.size, y);
            ctx.stroke();
            let _ = ctx.set_line_dash(&solid());
        }
        let (x, y) = (lay.x_of(at.0), lay.y_of(at.1));
        let r = MARKER_RADIUS_PX * s;
        // A white ring with a dark edge reads on every colour of the map.
        ctx.set_line_width(5.0 * s);
        ctx.set_stroke_style_str("rgba(20, 24, 30, 0.85)");
        ctx.begin_path();
        let _ = ctx.arc(x, y, r, 0.0, 2.0 * PI);
        ctx.stroke();
        ctx.set_line_width(2.5 * s);
        ctx.set_stroke_style_str("#ffffff");
        ctx.begin_path();
        let _ = ctx.arc(x, y, r, 0.0, 2.0 * PI);
        ctx.stroke();
        ctx.set_fill_style_str("#d9480f");
        ctx.begin_path();
        let _ = ctx.arc(x, y, 2.5 * s, 0.0, 2.0 * PI);
        ctx.fill();
    }
}

/// The marker ring's radius before the line scale, CSS px.
pub const MARKER_RADIUS_PX: f64 = 8.0;
