//! The arm view: world (metres, y up) ↔ screen (CSS pixels, y down) transform, the static
//! background layer (millimetre grid, reachable annulus `|L1 − L2| ≤ r ≤ L1 + L2`, workspace
//! overlay) and the per-frame layer (links, joints, tip, manipulability ellipse, ghost pose).
//!
//! The ellipse is the image of the unit joint-speed circle, `{ J q̇ : |q̇| ≤ 1 }`: semi-axes
//! `σ_max`, `σ_min` along the left singular vectors of `J`, drawn at [`ELLIPSE_SCALE`] so that
//! it fits beside the arm (σ is in m per rad, like the links, so one scale suits every arm).

use std::f64::consts::PI;

use glam::{DAffine2, DVec2};
use web_sys::CanvasRenderingContext2d;

use super::canvas::{dash, font, solid, Layer};
use crate::planar2r::{Arm, PoseReport};

/// Drawn semi-axis = `ELLIPSE_SCALE · σ` metres.
pub const ELLIPSE_SCALE: f64 = 0.25;

/// Colours of the arm view.
mod colour {
    pub const BG: &str = "#fbfcfe";
    pub const GRID: &str = "#e4e8ef";
    pub const AXIS: &str = "#9aa5b5";
    pub const LABEL: &str = "#5b6575";
    pub const ANNULUS: &str = "rgba(46, 125, 209, 0.08)";
    pub const ANNULUS_EDGE: &str = "rgba(46, 125, 209, 0.55)";
    pub const LINK1: &str = "#1f4e8c";
    pub const LINK2: &str = "#2e7dd1";
    pub const JOINT_FILL: &str = "#ffffff";
    pub const JOINT_EDGE: &str = "#1d2633";
    pub const TIP: &str = "#d9480f";
    pub const ELLIPSE_FILL: &str = "rgba(217, 72, 15, 0.12)";
    pub const ELLIPSE_EDGE: &str = "rgba(217, 72, 15, 0.85)";
    pub const GHOST: &str = "rgba(90, 100, 115, 0.55)";
    pub const PIN: &str = "rgba(217, 72, 15, 0.7)";
    pub const HOVER: &str = "rgba(255, 196, 0, 0.45)";
}

/// World (m) ↔ screen (CSS px) for the arm view: the base at the centre, y up.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ViewXf {
    pub to_screen: DAffine2,
    pub to_world: DAffine2,
    /// CSS pixels per metre.
    pub px_per_m: f64,
}

impl ViewXf {
    /// Fits a disc of radius `extent_m` around the base into a `w × h` CSS-pixel view.
    pub fn fit(w: f64, h: f64, extent_m: f64) -> ViewXf {
        let extent = if extent_m.is_finite() && extent_m > 0.0 {
            extent_m
        } else {
            1.0
        };
        let s = (w.min(h) / 2.0 - 6.0).max(1.0) / extent;
        let origin = DVec2::new((w / 2.0).round(), (h / 2.0).round());
        let to_screen = DAffine2::from_cols(DVec2::new(s, 0.0), DVec2::new(0.0, -s), origin);
        ViewXf {
            to_screen,
            to_world: to_screen.inverse(),
            px_per_m: s,
        }
    }

    /// Screen point of a world point.
    pub fn screen(&self, x: f64, y: f64) -> DVec2 {
        self.to_screen.transform_point2(DVec2::new(x, y))
    }

    /// World point of a screen point.
    pub fn world(&self, p: DVec2) -> DVec2 {
        self.to_world.transform_point2(p)
    }

    /// The base (world origin) on screen.
    pub fn origin(&self) -> DVec2 {
        self.to_screen.translation
    }
}

/// The view radius (m) for an arm, widened to show the workspace grid when it is on.
pub fn extent_m(arm: &Arm, ws_half_m: Option<f64>) -> f64 {
    let reach = arm.l1 + arm.l2;
    // A grid far larger than the arm would shrink the arm to a dot: show at most 3 reaches.
    let ws = ws_half_m.map_or(0.0, |h| h.min(3.0 * reach));
    reach.max(ws) * 1.08
}

/// A 1-2-5 step (mm) giving about six grid lines from the base to the edge.
pub fn grid_step_mm(extent_m: f64) -> f64 {
    let target = extent_m * 1000.0 / 6.0;
    let mag = 10f64.powf(target.log10().floor());
    for m in [1.0, 2.0, 5.0, 10.0] {
        if m * mag >= target {
            return m * mag;
        }
    }
    10.0 * mag
}

/// The workspace grid, rendered at one pixel per cell, and the world rectangle it covers
/// (cell edges, metres).
pub struct WorkspaceImage {
    pub layer: Layer,
    pub x_min: f64,
    pub x_max: f64,
    pub y_min: f64,
    pub y_max: f64,
}

/// Draws the background layer: grid with millimetre labels, the annulus, the workspace.
pub fn draw_background(
    layer: &Layer,
    xf: &ViewXf,
    arm: &Arm,
    workspace: Option<&WorkspaceImage>,
    scale: f64,
    unit_mm: &str,
) {
    layer.begin();
    let ctx = &layer.ctx;
    let (w, h) = (layer.css_w, layer.css_h);
    ctx.set_fill_style_str(colour::BG);
    ctx.fill_rect(0.0, 0.0, w, h);

    if let Some(ws) = workspace {
        let a = xf.screen(ws.x_min, ws.y_max);
        let b = xf.screen(ws.x_max, ws.y_min);
        ctx.set_image_smoothing_enabled(false);
        let _ = ctx.draw_image_with_html_canvas_element_and_dw_and_dh(
            &ws.layer.canvas,
            a.x,
            a.y,
            b.x - a.x,
            b.y - a.y,
        );
        ctx.set_image_smoothing_enabled(true);
    }

    // Grid: lines every `step` mm, labels on the axes.
    let step_mm = grid_step_mm(w.min(h) / 2.0 / xf.px_per_m);
    let step = step_mm / 1000.0;
    let o = xf.origin();
    let n_x = ((w / 2.0) / (step * xf.px_per_m)).ceil() as i64 + 1;
    let n_y = ((h / 2.0) / (step * xf.px_per_m)).ceil() as i64 + 1;
    ctx.set_line_width(1.0);
    ctx.set_stroke_style_str(colour::GRID);
    ctx.begin_path();
    for i in -n_x..=n_x {
        let x = (o.x + i as f64 * step * xf.px_per_m).round() + 0.5;
        ctx.move_to(x, 0.0);
        ctx.line_to(x, h);
    }
    for j in -n_y..=n_y {
        let y = (o.y - j as f64 * step * xf.px_per_m).round() + 0.5;
        ctx.move_to(0.0, y);
        ctx.line_to(w, y);
    }
    ctx.stroke();

    ctx.set_stroke_style_str(colour::AXIS);
    ctx.set_line_width(1.0 * scale);
    ctx.begin_path();
    ctx.move_to(0.0, o.y.round() + 0.5);
    ctx.line_to(w, o.y.round() + 0.5);
    ctx.move_to(o.x.round() + 0.5, 0.0);
    ctx.line_to(o.x.round() + 0.5, h);
    ctx.stroke();

    // Reachable annulus.
    let (inner, outer) = arm.reach();
    let r_out = outer * xf.px_per_m;
    let r_in = inner * xf.px_per_m;
    ctx.set_fill_style_str(colour::ANNULUS);
    ctx.begin_path();
    let _ = ctx.arc(o.x, o.y, r_out, 0.0, 2.0 * PI);
    if r_in > 0.0 {
        ctx.move_to(o.x + r_in, o.y);
        let _ = ctx.arc_with_anticlockwise(o.x, o.y, r_in, 0.0, 2.0 * PI, true);
    }
    ctx.fill();
    ctx.set_stroke_style_str(colour::ANNULUS_EDGE);
    ctx.set_line_width(1.5 * scale);
    let _ = ctx.set_line_dash(&dash(6.0 * scale, 4.0 * scale));
    ctx.begin_path();
    let _ = ctx.arc(o.x, o.y, r_out, 0.0, 2.0 * PI);
    ctx.stroke();
    if r_in > 0.5 {
        ctx.begin_path();
        let _ = ctx.arc(o.x, o.y, r_in, 0.0, 2.0 * PI);
        ctx.stroke();
    }
    let _ = ctx.set_line_dash(&solid());

    // Millimetre labels along the axes (every other line when crowded).
    ctx.set_fill_style_str(colour::LABEL);
    ctx.set_font(&font(11.0, scale, false));
    let label_every = if step * xf.px_per_m < 38.0 * scale {
        2
    } else {
        1
    };
    ctx.set_text_align("center");
    ctx.set_text_baseline("top");
    for i in -n_x..=n_x {
        if i == 0 || i % label_every != 0 {
            continue;
        }
        let x = o.x + i as f64 * step * xf.px_per_m;
        let _ = ctx.fill_text(&format_mm(i as f64 * step_mm), x, o.y + 4.0);
    }
    ctx.set_text_align("right");
    ctx.set_text_baseline("middle");
    for j in -n_y..=n_y {
        if j == 0 || j % label_every != 0 {
            continue;
        }
        let y = o.y - j as f64 * step * xf.px_per_m;
        let _ = ctx.fill_text(&format_mm(j as f64 * step_mm), o.x - 5.0, y);
    }
    ctx.set_font(&font(12.0, scale, true));
    ctx.set_text_align("right");
    ctx.set_text_baseline("bottom");
    let _ = ctx.fill_text(&format!("x [{unit_mm}]"), w - 6.0, o.y - 4.0);
    ctx.set_text_align("left");
    ctx.set_text_baseline("top");
    let _ = ctx.fill_text(&format!("y [{unit_mm}]"), o.x + 6.0, 6.0);
}

fn format_mm(v: f64) -> String {
    let r = (v * 1000.0).round() / 1000.0;
    if r == r.trunc() {
        format!("{}", r as i64)
    } else {
        format!("{r}")
    }
}

/// What a pointer grabbed on the arm.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Grab {
    /// The tip: IK follows the pointer.
    Tip,
    /// The elbow joint or link 1: q1 follows.
    Q1,
    /// Link 2: q2 follows.
    Q2,
}

/// Everything drawn on the per-frame layer.
pub struct Scene<'a> {
    pub arm: Arm,
    pub report: &'a PoseReport,
    /// A previewed pose (heatmap hover), drawn as a ghost.
    pub ghost: Option<(f64, f64)>,
    /// The pointer, when it is outside the reach and the tip is pinned.
    pub pinned_pointer: Option<DVec2>,
    /// The part under the pointer or being dragged.
    pub hover: Option<Grab>,
}

/// Screen positions of base, elbow and tip.
pub fn joints_on_screen(xf: &ViewXf, arm: &Arm, q1: f64, q2: f64) -> [DVec2; 3] {
    let (ex, ey) = arm.elbow(q1);
    let (tx, ty) = arm.fk(q1, q2);
    [xf.origin(), xf.screen(ex, ey), xf.screen(tx, ty)]
}

/// Draws the per-frame layer.
pub fn draw_foreground(layer: &Layer, xf: &ViewXf, scene: &Scene, scale: f64) {
    layer.begin();
    let ctx = &layer.ctx;
    let rep = scene.report;
    let [base, elbow, tip] = joints_on_screen(xf, &scene.arm, rep.q1, rep.q2);

    if let Some((g1, g2)) = scene.ghost {
        let [gb, ge, gt] = joints_on_screen(xf, &scene.arm, g1, g2);
        ctx.set_stroke_style_str(colour::GHOST);
        ctx.set_line_width(5.0 * scale);
        ctx.set_line_cap("round");
        let _ = ctx.set_line_dash(&dash(8.0 * scale, 6.0 * scale));
        ctx.begin_path();
        ctx.move_to(gb.x, gb.y);
        ctx.line_to(ge.x, ge.y);
        ctx.line_to(gt.x, gt.y);
        ctx.stroke();
        let _ = ctx.set_line_dash(&solid());
        circle(ctx, gt, 5.0 * scale, Some(colour::GHOST), None, 0.0);
    }

    // Manipulability ellipse at the tip.
    let e = rep.ellipse;
    let rx = (ELLIPSE_SCALE * e.sigma_max * xf.px_per_m).max(0.0);
    let ry = (ELLIPSE_SCALE * e.sigma_min * xf.px_per_m).max(0.0);
    let rot = -e.angle_rad;
    ctx.set_fill_style_str(colour::ELLIPSE_FILL);
    ctx.set_stroke_style_str(colour::ELLIPSE_EDGE);
    ctx.set_line_width(1.5 * scale);
    ctx.begin_path();
    if ctx
        .ellipse(tip.x, tip.y, rx, ry.max(0.01), rot, 0.0, 2.0 * PI)
        .is_ok()
    {
        ctx.fill();
        ctx.stroke();
    }
    // Singular directions: major axis solid, minor axis dashed.
    let (c, s) = (rot.cos(), rot.sin());
    ctx.begin_path();
    ctx.move_to(tip.x - rx * c, tip.y - rx * s);
    ctx.line_to(tip.x + rx * c, tip.y + rx * s);
    ctx.stroke();
    let _ = ctx.set_line_dash(&dash(3.0 * scale, 3.0 * scale));
    ctx.begin_path();
    ctx.move_to(tip.x + ry * s, tip.y - ry * c);
    ctx.line_to(tip.x - ry * s, tip.y + ry * c);
    ctx.stroke();
    let _ = ctx.set_line_dash(&solid());

    // Pointer outside the reach: a dashed line from the pinned tip to the pointer.
    if let Some(p) = scene.pinned_pointer {
        let sp = xf.screen(p.x, p.y);
        ctx.set_stroke_style_str(colour::PIN);
        ctx.set_line_width(1.5 * scale);
        let _ = ctx.set_line_dash(&dash(4.0 * scale, 4.0 * scale));
        ctx.begin_path();
        ctx.move_to(tip.x, tip.y);
        ctx.line_to(sp.x, sp.y);
        ctx.stroke();
        let _ = ctx.set_line_dash(&solid());
        circle(ctx, sp, 4.0 * scale, None, Some(colour::PIN), 1.5 * scale);
    }

    // Hover / drag highlight under the links.
    if let Some(grab) = scene.hover {
        ctx.set_stroke_style_str(colour::HOVER);
        ctx.set_line_cap("round");
        ctx.set_line_width(22.0 * scale);
        ctx.begin_path();
        match grab {
            Grab::Q1 => {
                ctx.move_to(base.x, base.y);
                ctx.line_to(elbow.x, elbow.y);
            }
            Grab::Q2 => {
                ctx.move_to(elbow.x, elbow.y);
                ctx.line_to(tip.x, tip.y);
            }
            Grab::Tip => {
                ctx.move_to(tip.x, tip.y);
                ctx.line_to(tip.x + 0.01, tip.y);
            }
        }
        ctx.stroke();
    }

    // Base.
    ctx.set_fill_style_str(colour::JOINT_EDGE);
    ctx.begin_path();
    ctx.move_to(base.x, base.y);
    ctx.line_to(base.x - 13.0 * scale, base.y + 18.0 * scale);
    ctx.line_to(base.x + 13.0 * scale, base.y + 18.0 * scale);
    ctx.close_path();
    ctx.fill();

    // Links.
    ctx.set_line_cap("round");
    ctx.set_line_width(10.0 * scale);
    ctx.set_stroke_style_str(colour::LINK1);
    ctx.begin_path();
    ctx.move_to(base.x, base.y);
    ctx.line_to(elbow.x, elbow.y);
    ctx.stroke();
    ctx.set_stroke_style_str(colour::LINK2);
    ctx.begin_path();
    ctx.move_to(elbow.x, elbow.y);
    ctx.line_to(tip.x, tip.y);
    ctx.stroke();

    // Joints and tip.
    for joint in [base, elbow] {
        circle(
            ctx,
            joint,
            7.0 * scale,
            Some(colour::JOINT_FILL),
            Some(colour::JOINT_EDGE),
            2.5 * scale,
        );
    }
    circle(
        ctx,
        tip,
        9.0 * scale,
        Some(colour::TIP),
        Some(colour::JOINT_FILL),
        2.5 * scale,
    );
    ctx.set_font(&font(12.0, scale, true));
    ctx.set_fill_style_str(colour::JOINT_EDGE);
    ctx.set_text_align("left");
    ctx.set_text_baseline("bottom");
    let mid1 = (base + elbow) / 2.0;
    let mid2 = (elbow + tip) / 2.0;
    let _ = ctx.fill_text("L1", mid1.x + 8.0 * scale, mid1.y - 6.0 * scale);
    let _ = ctx.fill_text("L2", mid2.x + 8.0 * scale, mid2.y - 6.0 * scale);
}

fn circle(
    ctx: &CanvasRenderingContext2d,
    c: DVec2,
    r: f64,
    fill: Option<&str>,
    stroke: Option<&str>,
    width: f64,
) {
    ctx.begin_path();
    let _ = ctx.arc(c.x, c.y, r, 0.0, 2.0 * PI);
    if let Some(f) = fill {
        ctx.set_fill_style_str(f);
        ctx.fill();
    }
    if let Some(s) = stroke {
        ctx.set_stroke_style_str(s);
        ctx.set_line_width(width);
        ctx.stroke();
    }
}

/// Distance from `p` to the segment `a`–`b`.
pub fn dist_to_segment(p: DVec2, a: DVec2, b: DVec2) -> f64 {
    let ab = b - a;
    let len2 = ab.length_squared();
    let t = if len2 > 0.0 {
        ((p - a).dot(ab) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (a + ab * t - p).length()
}

/// Which part of the arm a pointer at `p` grabs; `touch` widens the targets. Empty space
/// grabs the tip (the tip jumps there by IK), so a tap anywhere moves the arm.
pub fn hit_test(xf: &ViewXf, arm: &Arm, q1: f64, q2: f64, p: DVec2, touch: bool) -> Grab {
    let [base, elbow, tip] = joints_on_screen(xf, arm, q1, q2);
    let r = if touch { 26.0 } else { 16.0 };
    if p.distance(tip) <= r {
        Grab::Tip
    } else if p.distance(elbow) <= r * 0.8 {
        Grab::Q1
    } else if dist_to_segment(p, elbow, tip) <= r * 0.7 {
        Grab::Q2
    } else if dist_to_segment(p, base, elbow) <= r * 0.7 {
        Grab::Q1
    } else {
        Grab::Tip
    }
}
