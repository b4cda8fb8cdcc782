//! The joint-space manipulability heatmap: `|det J|` over `q1, q2 ∈ [−π, π]` on an `n × n`
//! grid sampled like the manip-grid recipe (`q_i = −π + 2π i / (n − 1)`), painted once into an
//! `n × n` image (ImageData) and drawn scaled on the heatmap's background layer; the pose
//! marker, the hovered cell and nothing else are drawn per frame on the top layer.
//!
//! `det J = (−L1 s1 − L2 s12) L2 c12 + L2 s12 (L1 c1 + L2 c12)`, which is `L1 L2 sin q2`: the
//! map is a set of horizontal bands, zero (singular) on `q2 = 0` and `q2 = ±π`.

use std::f64::consts::PI;

use wasm_bindgen::{Clamped, JsValue};
use web_sys::ImageData;

use super::canvas::{dash, font, solid, Layer};
use crate::error::RecipeError;
use crate::planar2r::{wrap_angle, Arm};
use crate::recipes::manip_grid;

/// `|det J|` on the grid, `values[i * n + j]` for `q1 = q_i`, `q2 = q_j`.
pub struct HeatGrid {
    pub n: usize,
    pub values: Vec<f32>,
    /// The colour scale's top: `L1 · L2`, the largest `|det J|` any pose reaches.
    pub scale_max: f64,
}

/// The grid's joint angle `i` (manip-grid's sampling).
pub fn grid_q(i: usize, n: usize) -> f64 {
    let d = (n.max(2) - 1) as f64;
    -PI + 2.0 * PI * i as f64 / d
}

/// Fills the grid with the manip-grid kernel's fast path (one sin/cos table, angle-sum
/// identities), reusing `grid`'s buffer.
pub fn fill(arm: &Arm, n: usize, grid: &mut HeatGrid) -> Result<(), RecipeError> {
    let n = n.max(2);
    grid.values.resize(n * n, 0.0);
    manip_grid::fill_abs_det(arm.l1, arm.l2, n as i64, &mut grid.values)?;
    grid.n = n;
    grid.scale_max = (arm.l1 * arm.l2).max(f64::MIN_POSITIVE);
    Ok(())
}

/// A viridis-like colour map: 256 RGB entries.
pub fn colour_lut() -> Vec<[u8; 3]> {
    const STOPS: [[f64; 3]; 5] = [
        [68.0, 1.0, 84.0],
        [59.0, 82.0, 139.0],
        [33.0, 145.0, 140.0],
        [94.0, 201.0, 98.0],
        [253.0, 231.0, 37.0],
    ];
    (0..256)
        .map(|k| {
            let t = k as f64 / 255.0 * 4.0;
            let i = (t.floor() as usize).min(3);
            let f = t - i as f64;
            let (a, b) = (STOPS[i], STOPS[i + 1]);
            [0, 1, 2].map(|c| (a[c] + (b[c] - a[c]) * f).round().clamp(0.0, 255.0) as u8)
        })
        .collect()
}

/// Paints the grid into `image` (resized to `n × n`, one pixel per cell, `q2 = +π` at the top).
pub fn paint(grid: &HeatGrid, lut: &[[u8; 3]], image: &mut Layer) -> Result<(), JsValue> {
    let n = grid.n;
    image.resize(n as f64, n as f64, 1.0);
    let mut rgba = vec![255u8; n * n * 4];
    let inv = 255.0 / grid.scale_max as f32;
    for (i, col) in grid.values.chunks_exact(n).enumerate() {
        for (j, v) in col.iter().enumerate() {
            let k = ((v * inv).round() as usize).min(255);
            let [r, g, b] = lut.get(k).copied().unwrap_or([0, 0, 0]);
            let px = ((n - 1 - j) * n + i) * 4;
            if let Some(p) = rgba.get_mut(px..px + 3) {
                p.copy_from_slice(&[r, g, b]);
            }
        }
    }
    let data = ImageData::new_with_u8_clamped_array_and_sh(Clamped(&rgba), n as u32, n as u32)?;
    let _ = image.ctx.set_transform(1.0, 0.0, 0.0, 1.0, 0.0, 0.0);
    image.ctx.put_image_data(&data, 0.0, 0.0)
}

/// Where the plot square and the legend sit on the heatmap canvas (CSS px).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HeatLayout {
    pub x: f64,
    pub y: f64,
    pub size: f64,
    pub legend_x: f64,
    pub legend_w: f64,
}

impl HeatLayout {
    /// Lays out a canvas of `w × h` CSS px with type scale `scale`.
    pub fn new(w: f64, h: f64, scale: f64) -> HeatLayout {
        let left = 44.0 * scale;
        let bottom = 38.0 * scale;
        let top = 10.0 * scale;
        let legend_w = 14.0 * scale;
        let legend_room = legend_w + 78.0 * scale;
        let size = (w - left - legend_room - 8.0)
            .min(h - top - bottom)
            .max(10.0);
        HeatLayout {
            x: left,
            y: top,
            size,
            legend_x: left + size + 12.0 * scale,
            legend_w,
        }
    }

    /// Canvas x of `q1` (wrapped into `[−π, π]`).
    pub fn x_of(&self, q1: f64) -> f64 {
        self.x + (wrap_angle(q1) + PI) / (2.0 * PI) * self.size
    }

    /// Canvas y of `q2` (wrapped; `+π` at the top).
    pub fn y_of(&self, q2: f64) -> f64 {
        self.y + (PI - wrap_angle(q2)) / (2.0 * PI) * self.size
    }

    /// The grid cell `(i, j)` under canvas point `(px, py)`, if it is inside the plot.
    pub fn cell_at(&self, px: f64, py: f64, n: usize) -> Option<(usize, usize)> {
        let u = (px - self.x) / self.size;
        let v = (py - self.y) / self.size;
        let pad = 0.5 / (n.max(2) - 1) as f64;
        if !(-pad..=1.0 + pad).contains(&u) || !(-pad..=1.0 + pad).contains(&v) {
            return None;
        }
        let d = (n.max(2) - 1) as f64;
        let i = (u * d).round().clamp(0.0, d) as usize;
        let j = ((1.0 - v) * d).round().clamp(0.0, d) as usize;
        Some((i, j))
    }
}

/// Canvas text of the heatmap, already localized.
pub struct HeatLabels {
    pub q1_axis: String,
    pub q2_axis: String,
    pub legend_title: String,
    pub singular: String,
}

/// The painted heatmap and its colour scale.
#[derive(Clone, Copy)]
pub struct HeatPicture<'a> {
    /// The `n × n` image ([`paint`]), if painted yet.
    pub image: Option<&'a Layer>,
    pub grid_n: usize,
    pub lut: &'a [[u8; 3]],
    /// The colour scale's top, m² (`L1 L2`).
    pub scale_max: f64,
}

/// Draws the background layer: the painted grid, axes, the singular lines, the legend.
pub fn draw_background(
    layer: &Layer,
    lay: &HeatLayout,
    picture: &HeatPicture,
    labels: &HeatLabels,
    scale: f64,
) {
    let HeatPicture {
        image,
        grid_n,
        lut,
        scale_max,
    } = *picture;
    layer.begin();
    let ctx = &layer.ctx;
    ctx.set_fill_style_str("#fbfcfe");
    ctx.fill_rect(0.0, 0.0, layer.css_w, layer.css_h);
    if let Some(img) = image {
        // Cell centres sit exactly on their q: the image extends half a cell past ±π.
        let cell = lay.size / (grid_n.max(2) - 1) as f64;
        ctx.save();
        ctx.begin_path();
        ctx.rect(lay.x, lay.y, lay.size, lay.size);
        ctx.clip();
        ctx.set_image_smoothing_enabled(false);
        let _ = ctx.draw_image_with_html_canvas_element_and_dw_and_dh(
            &img.canvas,
            lay.x - cell / 2.0,
            lay.y - cell / 2.0,
            lay.size + cell,
            lay.size + cell,
        );
        ctx.restore();
    }
    ctx.set_stroke_style_str("#5b6575");
    ctx.set_line_width(1.0);
    ctx.stroke_rect(lay.x + 0.5, lay.y + 0.5, lay.size - 1.0, lay.size - 1.0);

    // Singular lines q2 = 0 and q2 = ±π.
    ctx.set_stroke_style_str("rgba(255, 80, 80, 0.95)");
    ctx.set_line_width(1.5 * scale);
    let _ = ctx.set_line_dash(&dash(5.0 * scale, 4.0 * scale));
    for q2 in [-PI + 1e-12, 0.0, PI] {
        let y =
            (lay.y + (PI - q2) / (2.0 * PI) * lay.size).clamp(lay.y + 1.0, lay.y + lay.size - 1.0);
        ctx.begin_path();
        ctx.move_to(lay.x, y);
        ctx.line_to(lay.x + lay.size, y);
        ctx.stroke();
    }
    let _ = ctx.set_line_dash(&solid());
    ctx.set_fill_style_str("rgba(255, 255, 255, 0.92)");
    ctx.set_font(&font(10.5, scale, true));
    ctx.set_text_align("left");
    ctx.set_text_baseline("bottom");
    let _ = ctx.fill_text(&labels.singular, lay.x + 4.0, lay.y + lay.size / 2.0 - 3.0);

    // Ticks at −π, −π/2, 0, π/2, π.
    ctx.set_fill_style_str("#3a4250");
    ctx.set_font(&font(11.0, scale, false));
    let ticks = [
        (-PI, "−π"),
        (-PI / 2.0, "−π/2"),
        (0.0, "0"),
        (PI / 2.0, "π/2"),
        (PI, "π"),
    ];
    ctx.set_text_align("center");
    ctx.set_text_baseline("top");
    for (q, label) in ticks {
        let x = lay.x + (q + PI) / (2.0 * PI) * lay.size;
        let _ = ctx.fill_text(label, x, lay.y + lay.size + 4.0);
    }
    ctx.set_text_align("right");
    ctx.set_text_baseline("middle");
    for (q, label) in ticks {
        let y = lay.y + (PI - q) / (2.0 * PI) * lay.size;
        let _ = ctx.fill_text(label, lay.x - 5.0, y);
    }
    ctx.set_text_align("center");
    ctx.set_text_baseline("bottom");
    let _ = ctx.fill_text(
        &labels.q1_axis,
        lay.x + lay.size / 2.0,
        lay.y + lay.size + 36.0 * scale,
    );
    ctx.save();
    let _ = ctx.translate(12.0 * scale, lay.y + lay.size / 2.0);
    let _ = ctx.rotate(-PI / 2.0);
    ctx.set_text_baseline("middle");
    let _ = ctx.fill_text(&labels.q2_axis, 0.0, 0.0);
    ctx.restore();

    // Legend: colour bar 0 … L1·L2 (m²).
    let (lx, lw) = (lay.legend_x, lay.legend_w);
    let steps = 64;
    for k in 0..steps {
        let t = k as f64 / (steps - 1) as f64;
        let idx = ((t * 255.0).round() as usize).min(255);
        let [r, g, b] = lut.get(idx).copied().unwrap_or([0, 0, 0]);
        ctx.set_fill_style_str(&format!("rgb({r},{g},{b})"));
        let y0 = lay.y + lay.size * (1.0 - (k + 1) as f64 / steps as f64);
        ctx.fill_rect(lx, y0, lw, lay.size / steps as f64 + 0.5);
    }
    ctx.set_stroke_style_str("#5b6575");
    ctx.stroke_rect(lx + 0.5, lay.y + 0.5, lw - 1.0, lay.size - 1.0);
    ctx.set_fill_style_str("#3a4250");
    ctx.set_text_align("left");
    ctx.set_text_baseline("middle");
    let mut widest: f64 = 0.0;
    for t in [0.0, 0.5, 1.0] {
        let y = (lay.y + lay.size * (1.0 - t))
            .clamp(lay.y + 6.0 * scale, lay.y + lay.size - 6.0 * scale);
        let text = legend_value(t * scale_max);
        if let Ok(m) = ctx.measure_text(&text) {
            widest = widest.max(m.width());
        }
        let _ = ctx.fill_text(&text, lx + lw + 4.0, y);
    }
    ctx.save();
    let _ = ctx.translate(lx + lw + widest + 16.0 * scale, lay.y + lay.size / 2.0);
    let _ = ctx.rotate(-PI / 2.0);
    ctx.set_text_align("center");
    let _ = ctx.fill_text(&labels.legend_title, 0.0, 0.0);
    ctx.restore();
}

/// A legend or axis number: three significant digits, no exponent for the usual arm sizes.
pub fn legend_value(v: f64) -> String {
    if v == 0.0 {
        "0".to_string()
    } else if v.abs() >= 1e-4 && v.abs() < 1e4 {
        let digits = (2 - v.abs().log10().floor() as i32).clamp(0, 8) as usize;
        format!("{v:.digits$}")
    } else {
        format!("{v:.2e}")
    }
}

/// Draws the top layer: the current pose and the hovered cell.
pub fn draw_marker(
    layer: &Layer,
    lay: &HeatLayout,
    q1: f64,
    q2: f64,
    hover: Option<(f64, f64)>,
    scale: f64,
) {
    layer.begin();
    let ctx = &layer.ctx;
    if let Some((h1, h2)) = hover {
        let (x, y) = (lay.x_of(h1), lay.y_of(h2));
        ctx.set_stroke_style_str("rgba(255, 255, 255, 0.9)");
        ctx.set_line_width(1.5 * scale);
        let _ = ctx.set_line_dash(&dash(3.0 * scale, 3.0 * scale));
        ctx.begin_path();
        ctx.move_to(x, lay.y);
        ctx.line_to(x, lay.y + lay.size);
        ctx.move_to(lay.x, y);
        ctx.line_to(lay.x + lay.size, y);
        ctx.stroke();
        let _ = ctx.set_line_dash(&solid());
    }
    let (x, y) = (lay.x_of(q1), lay.y_of(q2));
    let r = 8.0 * scale;
    // A white ring with a dark edge reads on every colour of the map.
    ctx.set_line_width(5.0 * scale);
    ctx.set_stroke_style_str("rgba(20, 24, 30, 0.85)");
    ctx.begin_path();
    let _ = ctx.arc(x, y, r, 0.0, 2.0 * PI);
    ctx.stroke();
    ctx.set_line_width(2.5 * scale);
    ctx.set_stroke_style_str("#ffffff");
    ctx.begin_path();
    let _ = ctx.arc(x, y, r, 0.0, 2.0 * PI);
    ctx.stroke();
    ctx.set_fill_style_str("#d9480f");
    ctx.begin_path();
    let _ = ctx.arc(x, y, 2.5 * scale, 0.0, 2.0 * PI);
    ctx.fill();
}
