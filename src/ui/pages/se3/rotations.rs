//! The teaching panel: one roll, pitch, yaw (frame B's, frame A's or the result's) applied two
//! ways, side by side: the recipe's `Rz Ry Rx` (extrinsic x → y → z about the fixed axes, the
//! same as intrinsic z → y′ → x″ about the moving ones) and intrinsic x → y′ → z″ (`Rx Ry
//! Rz`), each as a triad over faint world axes (seen from the main view's direction) and as
//! a 3×3 matrix, with the largest difference between the two.

use glam::DVec3;
use wasm_bindgen::JsValue;
use web_sys::Element;

use crate::ui::ctx;
use crate::ui::kit::canvas::{dash, solid, Ink, LayeredCanvas};
use crate::view::camera3d::{Camera, Preset};
use crate::view::se3_relative::{max_abs_diff3, rotation_rows, rpy_readings, Triad};

use super::scene::draw_triad;
use super::tables::fill;

/// Whose roll, pitch, yaw the panel shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Source {
    A,
    B,
    Relative,
}

impl Source {
    pub fn from_id(id: &str) -> Source {
        match id {
            "a" => Source::A,
            "rel" => Source::Relative,
            _ => Source::B,
        }
    }
}

/// The panel component.
pub struct Rotations {
    pub canvas: LayeredCanvas,
    recipe: Element,
    intrinsic: Element,
}

impl Rotations {
    /// Finds the canvas in `stage` and the two tables under `root`.
    pub fn find(root: &Element, stage: &Element) -> Result<Rotations, JsValue> {
        let f = |key: &str| -> Result<Element, JsValue> {
            crate::ui::dom::find(root, &format!("[data-matrix=\"{key}\"]"), "se3")
        };
        Ok(Rotations {
            canvas: LayeredCanvas::from_stage(stage)?,
            recipe: f("rot-recipe")?,
            intrinsic: f("rot-intrinsic")?,
        })
    }

    /// Draws `(roll, pitch, yaw)` both ways, seen from `azimuth`/`elevation`; returns the
    /// largest difference between the two matrices.
    pub fn show(&self, rpy: (f64, f64, f64), azimuth: f64, elevation: f64, ink: Ink) -> f64 {
        let r = rpy_readings(rpy.0, rpy.1, rpy.2);
        fill(&self.recipe, &rotation_rows(&r.recipe, 4));
        fill(&self.intrinsic, &rotation_rows(&r.intrinsic_xyz, 4));
        let layer = self.canvas.top();
        layer.begin();
        let c = &layer.ctx;
        let (w, h) = (layer.css_w, layer.css_h);
        c.set_fill_style_str("#fbfcfe");
        c.fill_rect(0.0, 0.0, w, h);
        let head = ink.text_px(13.0) * 2.0 + 10.0;
        let half = w / 2.0;
        for (k, (rot, title)) in [
            (r.recipe, ctx::t("se3-rot-recipe-short")),
            (r.intrinsic_xyz, ctx::t("se3-rot-intrinsic-short")),
        ]
        .iter()
        .enumerate()
        {
            let mut cam = Camera::framing(DVec3::ZERO, 1.15, Preset::Iso, half, h - head);
            cam.azimuth = azimuth;
            cam.elevation = elevation;
            let x0 = half * k as f64;
            c.save();
            let _ = c.translate(x0, head);
            let _ = c.set_line_dash(&dash(3.0 * ink.line, 4.0 * ink.line));
            c.set_global_alpha(0.45);
            draw_triad(c, &cam, &Triad::world(), 1.0, None, ink);
            c.set_global_alpha(1.0);
            let _ = c.set_line_dash(&solid());
            draw_triad(c, &cam, &Triad::rotated(rot, DVec3::ZERO), 0.9, None, ink);
            c.restore();
            c.set_fill_style_str("#111827");
            c.set_font(&ink.font(13.0, true));
            let _ =
                c.fill_text_with_max_width(title, x0 + 8.0, ink.text_px(13.0) + 4.0, half - 16.0);
            if k == 0 {
                c.set_font(&ink.font(12.0, false));
                c.set_fill_style_str("#15803d");
                let _ = c.fill_text_with_max_width(
                    &ctx::t("se3-rot-recipe-mark"),
                    x0 + 8.0,
                    2.0 * ink.text_px(13.0) + 6.0,
                    half - 16.0,
                );
            }
        }
        c.set_stroke_style_str("#d5dbe3");
        c.set_line_width(ink.line);
        c.begin_path();
        c.move_to(half, 6.0);
        c.line_to(half, h - 6.0);
        c.stroke();
        max_abs_diff3(&r.recipe, &r.intrinsic_xyz)
    }
}
