//! The pendulum drawn to scale: the hinge, the capsule (length and radius), a trail of the
//! tip, the angle arc from hanging straight down; in compare mode the other integrator's
//! pendulum as a ghost.

use wasm_bindgen::JsValue;
use web_sys::Element;

use crate::ui::kit::canvas::{solid, Ink, LayeredCanvas};
use crate::view::pendulum::Track;

/// Tip positions kept in the trail.
const TRAIL: usize = 240;

/// The view component.
pub struct PendulumView {
    pub canvas: LayeredCanvas,
}

impl PendulumView {
    /// Wraps the canvas of `stage`.
    pub fn find(stage: &Element) -> Result<PendulumView, JsValue> {
        Ok(PendulumView {
            canvas: LayeredCanvas::from_stage(stage)?,
        })
    }

    /// Draws the tracks after `index` steps (the first solid, the second a ghost).
    pub fn draw(&mut self, tracks: &[Track], index: usize, ink: Ink) {
        let layer = self.canvas.top();
        layer.begin();
        let c = &layer.ctx;
        let (w, h) = (layer.css_w, layer.css_h);
        let Some(first) = tracks.first() else {
            return;
        };
        let p = *first.start().params();
        let scale = 0.42 * w.min(h) / (p.length_m + p.radius_m);
        let (cx, cy) = (w / 2.0, h / 2.0);
        let at = |theta: f64, r: f64| (cx + r * theta.sin() * scale, cy + r * theta.cos() * scale);
        // Circle of the tip.
        c.set_stroke_style_str("#d5dbe3");
        c.set_line_width(ink.line);
        c.begin_path();
        let _ = c.arc(cx, cy, p.length_m * scale, 0.0, std::f64::consts::TAU);
        c.stroke();
        for (k, track) in tracks.iter().enumerate().rev() {
            let ghost = k > 0;
            let (theta, _, _) = track.state(index);
            let (stroke, trail) = if ghost {
                ("rgba(124, 58, 237, 0.45)", "rgba(124, 58, 237, 0.35)")
            } else {
                ("#1a4d8f", "rgba(194, 65, 12, 0.55)")
            };
            // Trail of the tip.
            let rows = track.rows();
            let end = index.min(rows.len());
            let from = end.saturating_sub(TRAIL);
            c.set_stroke_style_str(trail);
            c.set_line_width(1.5 * ink.line);
            c.begin_path();
            for (i, r) in rows[from..end].iter().enumerate() {
                let (x, y) = at(r.theta, p.length_m);
                if i == 0 {
                    c.move_to(x, y);
                } else {
                    c.line_to(x, y);
                }
            }
            c.stroke();
            // The capsule.
            let (tx, ty) = at(theta, p.length_m);
            c.set_line_cap("round");
            c.set_stroke_style_str(stroke);
            c.set_line_width((2.0 * p.radius_m * scale).max(5.0 * ink.line));
            c.begin_path();
            c.move_to(cx, cy);
            c.line_to(tx, ty);
            c.stroke();
            if !ghost {
                // Angle arc from straight down.
                c.set_stroke_style_str("#c2410c");
                c.set_line_width(2.0 * ink.line);
                c.begin_path();
                let down = std::f64::consts::FRAC_PI_2;
                let wrapped = theta.sin().atan2(theta.cos());
                let _ = c.arc_with_anticlockwise(
                    cx,
                    cy,
                    0.3 * p.length_m * scale,
                    down,
                    down - wrapped,
                    wrapped > 0.0,
                );
                c.stroke();
            }
        }
        let _ = c.set_line_dash(&solid());
        c.set_fill_style_str("#111827");
        c.begin_path();
        let _ = c.arc(cx, cy, 4.0 * ink.line, 0.0, std::f64::consts::TAU);
        c.fill();
    }
}
