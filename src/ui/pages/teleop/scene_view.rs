//! The arm view: the kernel's [`SceneGeometry`] drawn to scale on one HiDPI canvas (table,
//! goal region, obstacles, reach targets, block, the three links as capsules, the gripper's
//! fingers), the tip's trail, and the clutch target while a pointer holds it. The transform
//! (`crate::view::teleop::ViewTransform`) fits the scene's bounds once per size.

use wasm_bindgen::JsValue;
use web_sys::{CanvasRenderingContext2d, Element};

use crate::teleop::{Box2, Capsule, SceneGeometry, TargetStatus};
use crate::ui::kit::canvas::{dash, solid, Ink, LayeredCanvas};
use crate::view::teleop::ViewTransform;

/// Most trail points kept (10 s at 100 Hz).
pub const TRAIL_MAX: usize = 1000;

/// The arm view.
pub struct SceneView {
    pub canvas: LayeredCanvas,
    pub transform: ViewTransform,
    bounds: Option<(f64, f64, f64, f64)>,
    /// Tip positions of the current episode (or replay), oldest first.
    pub trail: Vec<(f64, f64)>,
}

impl SceneView {
    /// Wraps the canvas in `stage`.
    pub fn find(stage: &Element) -> Result<SceneView, JsValue> {
        Ok(SceneView {
            canvas: LayeredCanvas::from_stage(stage)?,
            transform: ViewTransform::fit((-0.3, -0.1, 0.3, 0.3), 1.0, 1.0, 0.0),
            bounds: None,
            trail: Vec::new(),
        })
    }

    /// Sizes the canvas to its box and refits the transform.
    pub fn fit(&mut self) {
        self.canvas.fit();
        self.refit();
    }

    fn refit(&mut self) {
        if let Some(b) = self.bounds {
            let (w, h) = self.canvas.size();
            self.transform = ViewTransform::fit(b, w, h, 12.0);
        }
    }

    /// Adds the tip's position to the trail.
    pub fn push_trail(&mut self, x: f64, z: f64) {
        if self.trail.len() >= TRAIL_MAX {
            self.trail.drain(..TRAIL_MAX / 4);
        }
        self.trail.push((x, z));
    }

    /// Draws `g`, the trail and the clutch target.
    pub fn draw(&mut self, g: &SceneGeometry, clutch: Option<(f64, f64)>, ink: Ink) {
        let b = (g.bounds.x0, g.bounds.z0, g.bounds.x1, g.bounds.z1);
        if self.bounds != Some(b) {
            self.bounds = Some(b);
            self.refit();
        }
        let layer = self.canvas.top();
        layer.begin();
        let c = &layer.ctx;
        let t = self.transform;
        let (w, h) = (layer.css_w, layer.css_h);
        c.set_fill_style_str("#f7f9fc");
        c.fill_rect(0.0, 0.0, w, h);
        // The table: everything below its top.
        let (_, ty) = t.to_screen(0.0, g.table.z0);
        c.set_fill_style_str("#d9cbb3");
        c.fill_rect(0.0, ty, w, h - ty);
        c.set_stroke_style_str("#8a7556");
        c.set_line_width(2.0 * ink.line);
        line(c, &t, (g.table.x0, g.table.z0), (g.table.x1, g.table.z1));
        if let Some(goal) = &g.goal {
            fill_box(c, &t, goal, "rgba(29,107,53,0.18)", "#1d6b35", ink);
        }
        for o in &g.obstacles {
            fill_box(c, &t, o, "#8d96a3", "#3b4450", ink);
        }
        for tv in &g.targets {
            let (x, y) = t.to_screen(tv.target.x, tv.target.z);
            let r = (tv.target.radius * t.scale).max(2.0);
            c.begin_path();
            let _ = c.arc(x, y, r, 0.0, std::f64::consts::TAU);
            match tv.status {
                TargetStatus::Current => {
                    c.set_fill_style_str("rgba(194,65,12,0.22)");
                    c.fill();
                    c.set_stroke_style_str("#c2410c");
                    c.set_line_width(2.5 * ink.line);
                    c.stroke();
                }
                TargetStatus::Pending => {
                    c.set_stroke_style_str("#6b7480");
                    c.set_line_width(1.2 * ink.line);
                    let _ = c.set_line_dash(&dash(4.0, 4.0));
                    c.stroke();
                    let _ = c.set_line_dash(&solid());
                }
                TargetStatus::Done => {
                    c.set_fill_style_str("rgba(29,107,53,0.25)");
                    c.fill();
                }
            }
        }
        // Trail.
        if self.trail.len() > 1 {
            c.set_stroke_style_str("rgba(26,77,143,0.45)");
            c.set_line_width(1.5 * ink.line);
            c.begin_path();
            for (i, (x, z)) in self.trail.iter().enumerate() {
                let (px, py) = t.to_screen(*x, *z);
                if i == 0 {
                    c.move_to(px, py);
                } else {
                    c.line_to(px, py);
                }
            }
            c.stroke();
        }
        // Block.
        c.begin_path();
        for (i, (x, z)) in g.block.iter().enumerate() {
            let (px, py) = t.to_screen(*x, *z);
            if i == 0 {
                c.move_to(px, py);
            } else {
                c.line_to(px, py);
            }
        }
        c.close_path();
        c.set_fill_style_str(if g.block_held { "#e07a1f" } else { "#f0a04b" });
        c.fill();
        c.set_stroke_style_str("#7a3e00");
        c.set_line_width(1.2 * ink.line);
        c.stroke();
        // Links, then fingers.
        for (i, cap) in g.links.iter().enumerate() {
            let colour = ["#1a4d8f", "#2f6db5", "#4a88cf"][i.min(2)];
            capsule(c, &t, cap, colour);
        }
        for cap in &g.fingers {
            capsule(c, &t, cap, "#1b1f24");
        }
        // Joints.
        c.set_fill_style_str("#ffffff");
        for cap in &g.links {
            let (px, py) = t.to_screen(cap.segment.x0, cap.segment.z0);
            c.begin_path();
            let _ = c.arc(px, py, 3.0 * ink.line, 0.0, std::f64::consts::TAU);
            c.fill();
        }
        // Tip.
        let (px, py) = t.to_screen(g.tip.x, g.tip.z);
        c.set_stroke_style_str("#c2410c");
        c.set_line_width(1.5 * ink.line);
        c.begin_path();
        c.move_to(px - 6.0, py);
        c.line_to(px + 6.0, py);
        c.move_to(px, py - 6.0);
        c.line_to(px, py + 6.0);
        c.stroke();
        if let Some((x, z)) = clutch {
            let (cx, cy) = t.to_screen(x, z);
            c.set_stroke_style_str("#7c3aed");
            c.set_line_width(2.0 * ink.line);
            c.begin_path();
            let _ = c.arc(cx, cy, 10.0 * ink.line, 0.0, std::f64::consts::TAU);
            c.stroke();
            let _ = c.set_line_dash(&dash(3.0, 3.0));
            line_px(c, (px, py), (cx, cy));
            let _ = c.set_line_dash(&solid());
        }
    }
}

fn line(c: &CanvasRenderingContext2d, t: &ViewTransform, a: (f64, f64), b: (f64, f64)) {
    line_px(c, t.to_screen(a.0, a.1), t.to_screen(b.0, b.1));
}

fn line_px(c: &CanvasRenderingContext2d, a: (f64, f64), b: (f64, f64)) {
    c.begin_path();
    c.move_to(a.0, a.1);
    c.line_to(b.0, b.1);
    c.stroke();
}

fn fill_box(
    c: &CanvasRenderingContext2d,
    t: &ViewTransform,
    b: &Box2,
    fill: &str,
    stroke: &str,
    ink: Ink,
) {
    let (x0, y0) = t.to_screen(b.x0.min(b.x1), b.z0.max(b.z1));
    let (x1, y1) = t.to_screen(b.x0.max(b.x1), b.z0.min(b.z1));
    c.set_fill_style_str(fill);
    c.fill_rect(x0, y0, x1 - x0, y1 - y0);
    c.set_stroke_style_str(stroke);
    c.set_line_width(1.5 * ink.line);
    c.stroke_rect(x0, y0, x1 - x0, y1 - y0);
}

fn capsule(c: &CanvasRenderingContext2d, t: &ViewTransform, cap: &Capsule, colour: &str) {
    let s = &cap.segment;
    c.set_stroke_style_str(colour);
    c.set_line_width((2.0 * cap.radius * t.scale).max(2.0));
    c.set_line_cap("round");
    line(c, t, (s.x0, s.z0), (s.x1, s.z1));
    c.set_line_cap("butt");
}
