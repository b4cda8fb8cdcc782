//! The view: one HiDPI canvas with the world's grid and axes, the source points X (numbered,
//! draggable), the noisy targets Y, the aligned points `s R X + t` with their residual lines,
//! the true similarity's handles (translation and rotation/scale), and what the current
//! teaching step adds (centroids, centred sets, the covariance's columns, the SVD's axes, the
//! scale circles, the translation arrow). Redrawn whole on every change: the marks of one
//! kind and colour go in one path (one stroke or fill for all the residuals, all the points),
//! and the label font is set once a frame, so a drag's frame makes a few dozen canvas calls.

use glam::DVec2;
use wasm_bindgen::JsValue;
use web_sys::{CanvasRenderingContext2d, Element};

use crate::ui::kit::canvas::{dash, ring, solid, Ink, LayeredCanvas};
use crate::view::drag::HandleShape;
use crate::view::umeyama_2d::{rotation_handle, svd, Frame, Grab, Scene, Step};

const BG: &str = "#fbfcfe";
const GRID: &str = "#e6eaf0";
const AXIS: &str = "#9aa4b2";
const X_COL: &str = "#1a4d8f";
const Y_COL: &str = "#c2410c";
const ALIGNED: &str = "#15803d";
const RESIDUAL: &str = "#b91c1c";
const TRUTH: &str = "#7c3aed";
const FAINT: &str = "rgba(74, 83, 96, 0.25)";
const SELECT: &str = "#f59e0b";

/// Margin around what is shown, CSS px.
const MARGIN: f64 = 34.0;

/// What is highlighted.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Marks {
    pub selected: Option<usize>,
    pub hover: Option<Grab>,
}

/// The view component.
pub struct SceneView {
    pub canvas: LayeredCanvas,
    pub frame: Frame,
}

fn line(c: &CanvasRenderingContext2d, a: DVec2, b: DVec2, stroke: &str, width: f64) {
    c.set_stroke_style_str(stroke);
    c.set_line_width(width);
    c.begin_path();
    c.move_to(a.x, a.y);
    c.line_to(b.x, b.y);
    c.stroke();
}

fn arrow(c: &CanvasRenderingContext2d, a: DVec2, b: DVec2, stroke: &str, width: f64) {
    line(c, a, b, stroke, width);
    let d = b - a;
    let len = d.length();
    if len < 1.0 {
        return;
    }
    let u = d / len;
    let n = DVec2::new(-u.y, u.x);
    let head = (4.0 * width).min(len * 0.4);
    c.set_fill_style_str(stroke);
    c.begin_path();
    c.move_to(b.x, b.y);
    let p1 = b - u * head * 2.0 + n * head;
    let p2 = b - u * head * 2.0 - n * head;
    c.line_to(p1.x, p1.y);
    c.line_to(p2.x, p2.y);
    c.close_path();
    c.fill();
}

/// Segments `a`–`b`, one path stroked once.
fn segments(
    c: &CanvasRenderingContext2d,
    pairs: impl Iterator<Item = (DVec2, DVec2)>,
    stroke: &str,
    width: f64,
) {
    c.set_stroke_style_str(stroke);
    c.set_line_width(width);
    c.begin_path();
    for (a, b) in pairs {
        c.move_to(a.x, a.y);
        c.line_to(b.x, b.y);
    }
    c.stroke();
}

/// Circles of radius `r` around `centres`, one path.
fn circles(c: &CanvasRenderingContext2d, centres: impl Iterator<Item = DVec2>, r: f64) {
    c.begin_path();
    for p in centres {
        c.move_to(p.x + r, p.y);
        let _ = c.arc(p.x, p.y, r, 0.0, std::f64::consts::TAU);
    }
}

/// Filled discs (the source points).
fn discs(c: &CanvasRenderingContext2d, centres: impl Iterator<Item = DVec2>, r: f64, fill: &str) {
    c.set_fill_style_str(fill);
    circles(c, centres, r);
    c.fill();
}

/// Stroked circles (the aligned points, the centred X).
fn rings(
    c: &CanvasRenderingContext2d,
    centres: impl Iterator<Item = DVec2>,
    r: f64,
    stroke: &str,
    width: f64,
) {
    c.set_stroke_style_str(stroke);
    c.set_line_width(width);
    circles(c, centres, r);
    c.stroke();
}

/// Filled squares of half side `half` (the targets), one path.
fn squares(
    c: &CanvasRenderingContext2d,
    centres: impl Iterator<Item = DVec2>,
    half: f64,
    fill: &str,
) {
    c.set_fill_style_str(fill);
    c.begin_path();
    for p in centres {
        c.rect(p.x - half, p.y - half, 2.0 * half, 2.0 * half);
    }
    c.fill();
}

fn diamond(c: &CanvasRenderingContext2d, p: DVec2, r: f64, stroke: &str, width: f64) {
    c.set_stroke_style_str(stroke);
    c.set_line_width(width);
    c.begin_path();
    c.move_to(p.x, p.y - r);
    c.line_to(p.x + r, p.y);
    c.line_to(p.x, p.y + r);
    c.line_to(p.x - r, p.y);
    c.close_path();
    c.stroke();
}

fn cross(c: &CanvasRenderingContext2d, p: DVec2, r: f64, stroke: &str, width: f64) {
    line(
        c,
        p - DVec2::new(r, 0.0),
        p + DVec2::new(r, 0.0),
        stroke,
        width,
    );
    line(
        c,
        p - DVec2::new(0.0, r),
        p + DVec2::new(0.0, r),
        stroke,
        width,
    );
}

/// Text beside `p` in the label font ([`SceneView::draw`] sets it once a frame).
fn label(c: &CanvasRenderingContext2d, p: DVec2, text: &str, fill: &str) {
    c.set_fill_style_str(fill);
    let _ = c.fill_text(text, p.x + 8.0, p.y - 8.0);
}

impl SceneView {
    /// Wraps the canvas of `stage`.
    pub fn find(stage: &Element) -> Result<SceneView, JsValue> {
        Ok(SceneView {
            canvas: LayeredCanvas::from_stage(stage)?,
            frame: Frame::fit(([-1.0, -1.0], [1.0, 1.0]), (100.0, 100.0), 0.0),
        })
    }

    /// Sizes the canvas to the stage and fits the frame to `scene`.
    pub fn fit(&mut self, scene: &Scene) {
        self.canvas.fit();
        self.refit(scene);
    }

    /// Fits the frame to `scene` (not the canvas size).
    pub fn refit(&mut self, scene: &Scene) {
        self.frame = Frame::fit(scene.bounds(), self.canvas.size(), MARGIN);
    }

    /// Whether the frame still shows all of `scene`.
    pub fn shows(&self, scene: &Scene) -> bool {
        self.frame.shows(scene.bounds(), self.canvas.size())
    }

    /// Fits the frame to `scene` when it no longer shows it well
    /// ([`crate::view::umeyama_2d::Frame::needs_refit`]).
    pub fn refit_if_needed(&mut self, scene: &Scene) {
        if self.frame.needs_refit(scene.bounds(), self.canvas.size()) {
            self.refit(scene);
        }
    }

    /// Hit radius of handles, px.
    pub fn hit_radius(coarse: bool) -> f64 {
        if coarse {
            22.0
        } else {
            12.0
        }
    }

    /// The touch handles: the points and the truth's two handles.
    pub fn handles(&self, scene: &Scene) -> Vec<HandleShape> {
        let radius = SceneView::hit_radius(true);
        let truth = scene.truth();
        scene
            .x
            .iter()
            .copied()
            .chain([truth.t, rotation_handle(&truth)])
            .map(|p| HandleShape::Circle {
                centre: self.frame.px(p),
                radius,
            })
            .collect()
    }

    fn grid(&self, c: &CanvasRenderingContext2d, ink: Ink) {
        let (w, h) = self.canvas.size();
        let f = &self.frame;
        let lo = f.world(DVec2::new(0.0, h));
        let hi = f.world(DVec2::new(w, 0.0));
        let span = (hi[0] - lo[0]).max(hi[1] - lo[1]);
        let step = crate::view::plot::nice_step(0.0, span, 8);
        if !(step.is_finite() && step > 0.0) {
            return;
        }
        c.set_stroke_style_str(GRID);
        c.set_line_width(ink.line);
        c.begin_path();
        let mut x = (lo[0] / step).floor() * step;
        while x <= hi[0] {
            let p = f.px([x, 0.0]);
            c.move_to(p.x, 0.0);
            c.line_to(p.x, h);
            x += step;
        }
        let mut y = (lo[1] / step).floor() * step;
        while y <= hi[1] {
            let p = f.px([0.0, y]);
            c.move_to(0.0, p.y);
            c.line_to(w, p.y);
            y += step;
        }
        c.stroke();
        let o = f.px([0.0, 0.0]);
        line(c, DVec2::new(0.0, o.y), DVec2::new(w, o.y), AXIS, ink.line);
        line(c, DVec2::new(o.x, 0.0), DVec2::new(o.x, h), AXIS, ink.line);
        // The grid step, as a scale bar's label.
        c.set_font(&ink.font(12.0, false));
        c.set_fill_style_str(AXIS);
        let _ = c.fill_text(
            &crate::pyfmt::human(step),
            o.x + 4.0,
            o.y + ink.text_px(12.0) + 2.0,
        );
    }

    /// Draws `scene` at teaching `step`.
    pub fn draw(&self, scene: &Scene, step: Step, marks: Marks, ink: Ink) {
        let layer = self.canvas.top();
        layer.begin();
        let c = &layer.ctx;
        let (w, h) = self.canvas.size();
        c.set_fill_style_str(BG);
        c.fill_rect(0.0, 0.0, w, h);
        self.grid(c, ink);
        let f = &self.frame;
        let s = &scene.steps;
        let lw = ink.line;
        let r = 5.0 * lw;
        let centred = matches!(
            step,
            Step::Centred | Step::Covariance | Step::Svd | Step::Reflection
        );
        let faded = centred || step == Step::Centroids;
        // Correspondences X_i → Y_i.
        if step == Step::Overview || step == Step::Centroids {
            let pairs = scene.x.iter().zip(&scene.y);
            segments(c, pairs.map(|(p, q)| (f.px(*p), f.px(*q))), FAINT, lw);
        }
        c.set_global_alpha(if faded { 0.3 } else { 1.0 });
        // Aligned points and residuals (the fit's result).
        if !faded {
            c.set_line_dash(&dash(5.0 * lw, 4.0 * lw)).ok();
            let width = if step == Step::Rmse {
                3.0 * lw
            } else {
                1.6 * lw
            };
            let pairs = s.aligned.iter().zip(&scene.y);
            segments(c, pairs.map(|(a, q)| (f.px(*a), f.px(*q))), RESIDUAL, width);
            c.set_line_dash(&solid()).ok();
        }
        squares(c, scene.y.iter().map(|q| f.px(*q)), 0.9 * r, Y_COL);
        discs(c, scene.x.iter().map(|p| f.px(*p)), r, X_COL);
        if let Some(p) = marks.selected.and_then(|i| scene.x.get(i)) {
            ring(c, f.px(*p), r + 4.0 * lw, SELECT, 2.5 * lw);
        }
        if let Some(Grab::Point(i)) = marks.hover {
            if marks.selected != Some(i) {
                if let Some(p) = scene.x.get(i) {
                    ring(c, f.px(*p), r + 3.0 * lw, X_COL, 1.5 * lw);
                }
            }
        }
        if !faded {
            let aligned = s.aligned.iter().map(|a| f.px(*a));
            rings(c, aligned, r + 1.5 * lw, ALIGNED, 2.0 * lw);
        }
        c.set_global_alpha(1.0);
        // The truth's handles: t, and t + s (cos θ, sin θ).
        let truth = scene.truth();
        let t = f.px(truth.t);
        let rh = f.px(rotation_handle(&truth));
        c.set_line_dash(&dash(3.0 * lw, 3.0 * lw)).ok();
        line(c, t, rh, TRUTH, 1.5 * lw);
        c.set_line_dash(&solid()).ok();
        let hover_w = |g: Grab| if marks.hover == Some(g) { 3.5 } else { 2.0 };
        diamond(c, t, 8.0 * lw, TRUTH, hover_w(Grab::Translation) * lw);
        ring(c, rh, 6.0 * lw, TRUTH, hover_w(Grab::Rotation) * lw);
        c.set_font(&ink.font(13.0, true));
        label(c, t, "t", TRUTH);
        label(c, rh, "s·R", TRUTH);
        self.draw_step(c, scene, step, ink);
    }

    fn draw_step(&self, c: &CanvasRenderingContext2d, scene: &Scene, step: Step, ink: Ink) {
        let f = &self.frame;
        let s = &scene.steps;
        let lw = ink.line;
        let r = 5.0 * lw;
        let o = f.px([0.0, 0.0]);
        let at_origin = |v: [f64; 2]| f.px(v);
        match step {
            Step::Overview => {}
            Step::Centroids => {
                for (p, col) in [(s.mu_x, X_COL), (s.mu_y, Y_COL)] {
                    let at = f.px(p);
                    ring(c, at, 9.0 * lw, col, 2.5 * lw);
                    cross(c, at, 13.0 * lw, col, 2.0 * lw);
                }
                label(c, f.px(s.mu_x), "μx", X_COL);
                label(c, f.px(s.mu_y), "μy", Y_COL);
                let (mx, my) = (f.px(s.mu_x), f.px(s.mu_y));
                let to_mx = scene.x.iter().map(|p| (f.px(*p), mx));
                segments(c, to_mx, "rgba(26, 77, 143, 0.25)", lw);
                let to_my = scene.y.iter().map(|q| (f.px(*q), my));
                segments(c, to_my, "rgba(194, 65, 12, 0.25)", lw);
            }
            Step::Centred | Step::Covariance | Step::Svd | Step::Reflection => {
                let pairs = s.centred_x.iter().zip(&s.centred_y);
                segments(
                    c,
                    pairs.map(|(p, q)| (at_origin(*p), at_origin(*q))),
                    FAINT,
                    lw,
                );
                let centred_x = s.centred_x.iter().map(|p| at_origin(*p));
                rings(c, centred_x, r, X_COL, 2.0 * lw);
                c.set_stroke_style_str(Y_COL);
                c.set_line_width(2.0 * lw);
                c.begin_path();
                for q in &s.centred_y {
                    let at = at_origin(*q);
                    c.rect(at.x - r, at.y - r, 2.0 * r, 2.0 * r);
                }
                c.stroke();
                cross(c, o, 10.0 * lw, "#111827", 1.5 * lw);
                if step == Step::Covariance {
                    // C's columns: where C sends the axes.
                    let col = |j: usize| [s.cov[0][j], s.cov[1][j]];
                    arrow(c, o, at_origin(col(0)), "#0f766e", 3.0 * lw);
                    arrow(c, o, at_origin(col(1)), "#0f766e", 3.0 * lw);
                    label(c, at_origin(col(0)), "C e₁", "#0f766e");
                    label(c, at_origin(col(1)), "C e₂", "#0f766e");
                }
                if step == Step::Svd || step == Step::Reflection {
                    let d = svd(s);
                    let u = if step == Step::Reflection {
                        d.u_fixed
                    } else {
                        d.u
                    };
                    for (k, (v_name, u_name)) in
                        [("v₁", "S₁u₁"), ("v₂", "S₂u₂")].into_iter().enumerate()
                    {
                        // C v_k = S_k u_k: V's axes (unit, blue) go to U's axes (scaled).
                        let v = [d.vt[k][0], d.vt[k][1]];
                        let uk = [u[0][k] * d.s[k], u[1][k] * d.s[k]];
                        arrow(c, o, at_origin(v), X_COL, 2.5 * lw);
                        arrow(c, o, at_origin(uk), Y_COL, 2.5 * lw);
                        label(c, at_origin(v), v_name, X_COL);
                        label(c, at_origin(uk), u_name, Y_COL);
                    }
                    if step == Step::Reflection && s.reflection_fixed() {
                        // The column the fix negated, as it was.
                        let old = [d.u[0][1] * d.s[1], d.u[1][1] * d.s[1]];
                        c.set_line_dash(&dash(4.0 * lw, 4.0 * lw)).ok();
                        arrow(c, o, at_origin(old), RESIDUAL, 2.0 * lw);
                        c.set_line_dash(&solid()).ok();
                    }
                }
            }
            Step::Scale => {
                let rx = s.var_x.sqrt() * f.scale;
                let ry = s.scale * s.var_x.sqrt() * f.scale;
                ring(c, f.px(s.mu_x), rx, X_COL, 2.0 * lw);
                ring(c, f.px(s.mu_y), ry, Y_COL, 2.0 * lw);
                label(
                    c,
                    f.px(s.mu_x) + DVec2::new(rx * 0.7, -rx * 0.7),
                    "√var_x",
                    X_COL,
                );
                label(
                    c,
                    f.px(s.mu_y) + DVec2::new(ry * 0.7, -ry * 0.7),
                    "s·√var_x",
                    Y_COL,
                );
            }
            Step::Translation => {
                // s R X before the translation, and t carrying it onto the targets.
                let rot = s.rotation;
                let srx = |p: &[f64; 2]| {
                    [
                        s.scale * (rot[0][0] * p[0] + rot[0][1] * p[1]),
                        s.scale * (rot[1][0] * p[0] + rot[1][1] * p[1]),
                    ]
                };
                let moved = scene.x.iter().map(|p| f.px(srx(p)));
                rings(c, moved, r, "rgba(21, 128, 61, 0.5)", 1.5 * lw);
                let from = srx(&s.mu_x);
                arrow(c, f.px(from), f.px(s.mu_y), ALIGNED, 3.0 * lw);
                arrow(c, o, f.px(s.t), ALIGNED, 2.0 * lw);
                label(c, f.px(s.t), "t̂", ALIGNED);
            }
            Step::Rmse => {}
        }
    }
}
