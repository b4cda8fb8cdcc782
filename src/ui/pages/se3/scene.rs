//! The 3D view: the world frame, frame A and frame B as triads (x red, y green, z blue) over a
//! ground grid, and the relative transform drawn as an arrow from A's origin to B's, labelled
//! as expressed in A, with the path along A's own axes by the relative translation (dashed,
//! in A's axis colours), and each frame's yaw ring (a circle about the vertical through its
//! origin: dragging it turns the frame about the world's z axis, its yaw alone), on the two
//! layers of the kit's orbit view
//! ([`crate::ui::kit::orbit::OrbitView`], which owns the camera, orbit, zoom and presets):
//! the ground and the world triad, then the frames. Hit tests and drags are
//! [`crate::view::se3_relative`]'s.

use std::f64::consts::TAU;

use glam::{DVec2, DVec3};
use web_sys::CanvasRenderingContext2d;

use crate::ui::ctx;
use crate::ui::kit::canvas::{dash, disc, solid, Ink, LayeredCanvas};
use crate::view::camera3d::{ground_grid, Camera, Preset};
use crate::view::palette;
use crate::view::se3_relative::{
    axis_length, path_in_a, ring_radius, yaw_ring, Grab, Solved, Triad, RING_POINTS,
};

const BG: &str = "#fbfcfe";
const GRID: &str = "#e3e8ef";
/// x, y, z.
/// x, y, z: the Okabe–Ito vermilion, bluish green and blue of the DH page's colour-blind-safe
/// axes (still red, green, blue to most eyes; red and green alone are one colour to many).
pub const AXIS_COLOURS: [&str; 3] = [
    palette::VERMILION.hex,
    palette::BLUISH_GREEN.hex,
    palette::BLUE.hex,
];
const LABEL: &str = "#111827";
const ARROW: &str = "#7c3aed";
const HOVER: &str = "#f59e0b";
const RING: &str = "rgba(180, 83, 9, 0.55)";
const RING_HOT: &str = "#b45309";

/// A line from `a` to `b` in world coordinates, if both are in front of the eye.
fn line(c: &CanvasRenderingContext2d, cam: &Camera, a: DVec3, b: DVec3) -> Option<(DVec2, DVec2)> {
    let (pa, pb) = (cam.project(a)?.at, cam.project(b)?.at);
    c.begin_path();
    c.move_to(pa.x, pa.y);
    c.line_to(pb.x, pb.y);
    c.stroke();
    Some((pa, pb))
}

/// An arrowhead at `tip` pointing away from `from`, `size` px.
fn arrowhead(c: &CanvasRenderingContext2d, from: DVec2, tip: DVec2, size: f64, fill: &str) {
    let d = (tip - from).normalize_or_zero();
    if d == DVec2::ZERO {
        return;
    }
    let n = DVec2::new(-d.y, d.x);
    let base = tip - d * size;
    c.set_fill_style_str(fill);
    c.begin_path();
    c.move_to(tip.x, tip.y);
    c.line_to(base.x + n.x * size * 0.45, base.y + n.y * size * 0.45);
    c.line_to(base.x - n.x * size * 0.45, base.y - n.y * size * 0.45);
    c.close_path();
    c.fill();
}

/// Where a triad's name goes beside its origin.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LabelSide {
    /// Below and to the right (frames A and B).
    BelowRight,
    /// Above and to the left (the world frame, so that a frame at the origin stays readable).
    AboveLeft,
}

/// Draws a triad of axis length `len` with its name beside the origin.
pub fn draw_triad(
    c: &CanvasRenderingContext2d,
    cam: &Camera,
    triad: &Triad,
    len: f64,
    name: Option<(&str, LabelSide)>,
    ink: Ink,
) {
    c.set_line_cap("round");
    for (axis, colour) in triad.axes.iter().zip(AXIS_COLOURS) {
        c.set_stroke_style_str(colour);
        c.set_line_width(3.0 * ink.line);
        if let Some((pa, pb)) = line(c, cam, triad.origin, triad.origin + *axis * len) {
            arrowhead(c, pa, pb, 9.0 * ink.line, colour);
        }
    }
    if let (Some((name, side)), Some(o)) = (name, cam.project(triad.origin)) {
        c.set_fill_style_str(LABEL);
        c.set_font(&ink.font(13.0, true));
        let (x, y) = match side {
            LabelSide::BelowRight => (o.at.x + 9.0 * ink.line, o.at.y + ink.text_px(13.0) + 4.0),
            LabelSide::AboveLeft => {
                let width = c.measure_text(name).map_or(0.0, |m| m.width());
                (o.at.x - width - 9.0 * ink.line, o.at.y - 8.0 * ink.line)
            }
        };
        let _ = c.fill_text(name, x, y);
    }
}

/// Hit radius of the origins, px.
pub fn hit_radius(coarse: bool) -> f64 {
    if coarse {
        24.0
    } else {
        12.0
    }
}

/// Whether the world origin or a frame's origin lies outside the canvas (after a typed
/// value the view is framed again; never during a drag).
pub fn out_of_view(camera: &Camera, solved: &Solved) -> bool {
    let (w, h) = (camera.width, camera.height);
    let inside = |p: DVec3| {
        camera
            .project(p)
            .is_some_and(|q| q.at.x >= 0.0 && q.at.x <= w && q.at.y >= 0.0 && q.at.y <= h)
    };
    let a = Triad::of(&solved.t_a).origin;
    let b = Triad::of(&solved.t_b).origin;
    !(inside(DVec3::ZERO) && inside(a) && inside(b))
}

/// Layer 0: background, ground grid, the world triad (`radius`: the scene framed).
pub fn draw_ground(canvas: &LayeredCanvas, cam: &Camera, radius: f64, ink: Ink) {
    let layer = canvas.layer(0);
    layer.begin();
    let c = &layer.ctx;
    c.set_fill_style_str(BG);
    c.fill_rect(0.0, 0.0, layer.css_w, layer.css_h);
    let cell = crate::view::plot::nice_step(0.0, 2.0 * radius, 8);
    let n = ((2.0 * (radius + cam.target.truncate().length()) / cell).ceil() as usize).clamp(2, 40);
    let n = n + n % 2;
    c.set_stroke_style_str(GRID);
    c.set_line_width(ink.line);
    for (a, b) in ground_grid(n, cell) {
        line(c, cam, a, b);
    }
    let world = ctx::t("se3-view-world");
    draw_triad(
        c,
        cam,
        &Triad::world(),
        axis_length(radius) * 1.2,
        Some((&world, LabelSide::AboveLeft)),
        ink,
    );
}

/// Layer 1: frames A and B, the arrow A → B and the path along A's axes; `hover` rings
/// the origin under the pointer.
pub fn draw_frames(
    canvas: &LayeredCanvas,
    cam: &Camera,
    solved: &Solved,
    hover: Option<Grab>,
    radius: f64,
    ink: Ink,
) {
    let layer = canvas.layer(1);
    layer.begin();
    let c = &layer.ctx;
    let len = axis_length(radius);
    let a = Triad::of(&solved.t_a);
    let b = Triad::of(&solved.t_b);
    // The path along A's axes: x_rel along x_A, then y_rel along y_A, then z_rel along z_A.
    let path = path_in_a(solved);
    let _ = c.set_line_dash(&dash(4.0 * ink.line, 4.0 * ink.line));
    c.set_line_width(1.5 * ink.line);
    for (k, colour) in AXIS_COLOURS.iter().enumerate() {
        c.set_stroke_style_str(colour);
        line(c, cam, path[k], path[k + 1]);
    }
    let _ = c.set_line_dash(&solid());
    draw_triad(c, cam, &a, len, Some(("A", LabelSide::BelowRight)), ink);
    draw_triad(c, cam, &b, len, Some(("B", LabelSide::BelowRight)), ink);
    // The arrow A → B.
    c.set_stroke_style_str(ARROW);
    c.set_line_width(2.5 * ink.line);
    if let (Some(pa), Some(pb)) = (cam.project(a.origin), cam.project(b.origin)) {
        let (pa, pb) = (pa.at, pb.at);
        let d = (pb - pa).normalize_or_zero();
        let end = pb - d * 7.0 * ink.line;
        c.begin_path();
        c.move_to(pa.x, pa.y);
        c.line_to(end.x, end.y);
        c.stroke();
        arrowhead(c, pa, end, 12.0 * ink.line, ARROW);
        // The label beside the arrow's middle, on the side away from the arrow (to the
        // right of a steep arrow, under a flat one).
        let mid = (pa + pb) / 2.0;
        let text = ctx::t("se3-view-arrow");
        c.set_font(&ink.font(13.0, true));
        c.set_fill_style_str(ARROW);
        let width = c.measure_text(&text).map_or(0.0, |m| m.width());
        let text_h = ink.text_px(13.0);
        let steep = d.y.abs() > d.x.abs();
        let (x, y) = if steep {
            (mid.x + 12.0 * ink.line, mid.y + text_h / 2.0)
        } else {
            (mid.x - width / 2.0, mid.y + text_h + 10.0 * ink.line)
        };
        let x = x.min(layer.css_w - width - 4.0).max(4.0);
        let y = y.min(layer.css_h - 4.0).max(text_h + 2.0);
        let _ = c.fill_text(&text, x, y);
    }
    // The yaw rings (turn a frame about the vertical through its origin).
    let ring = ring_radius(radius);
    for (grab, triad) in [(Grab::YawA, &a), (Grab::YawB, &b)] {
        let hot = hover == Some(grab);
        c.set_stroke_style_str(if hot { RING_HOT } else { RING });
        c.set_line_width(if hot { 3.5 } else { 2.0 } * ink.line);
        c.begin_path();
        let mut drawing = false;
        for p in yaw_ring(triad.origin, ring, RING_POINTS)
            .into_iter()
            .chain(std::iter::once(triad.origin + DVec3::X * ring))
        {
            match cam.project(p) {
                Some(q) if drawing => c.line_to(q.at.x, q.at.y),
                Some(q) => {
                    c.move_to(q.at.x, q.at.y);
                    drawing = true;
                }
                None => drawing = false,
            }
        }
        c.stroke();
    }
    // The origins (the drag handles).
    for (grab, triad) in [(Grab::A, &a), (Grab::B, &b)] {
        if let Some(p) = cam.project(triad.origin) {
            disc(c, p.at, 5.5 * ink.line, LABEL);
            if hover == Some(grab) {
                c.set_stroke_style_str(HOVER);
                c.set_line_width(2.5 * ink.line);
                c.begin_path();
                let _ = c.arc(p.at.x, p.at.y, hit_radius(false), 0.0, TAU);
                c.stroke();
            }
        }
    }
}

/// Test hooks on the top canvas: where each origin is drawn (CSS px).
pub fn write_hooks(
    canvas: &LayeredCanvas,
    cam: &Camera,
    solved: &Solved,
    preset: Option<Preset>,
    radius: f64,
) {
    let top = &canvas.top().canvas;
    for (key, t) in [("a", &solved.t_a), ("b", &solved.t_b)] {
        if let Some(p) = cam.project(Triad::of(t).origin) {
            let _ = top.set_attribute(&format!("data-{key}-x"), &format!("{:.2}", p.at.x));
            let _ = top.set_attribute(&format!("data-{key}-y"), &format!("{:.2}", p.at.y));
        }
    }
    // A point on each yaw ring, clear of the axes (for tests).
    let ring = ring_radius(radius);
    for (key, pose) in [("a", &solved.params.a), ("b", &solved.params.b)] {
        let t = pose.yaw + 2.4;
        let origin = DVec3::new(pose.x, pose.y, pose.z);
        if let Some(p) = cam.project(origin + DVec3::new(t.cos(), t.sin(), 0.0) * ring) {
            let _ = top.set_attribute(&format!("data-{key}-ring-x"), &format!("{:.2}", p.at.x));
            let _ = top.set_attribute(&format!("data-{key}-ring-y"), &format!("{:.2}", p.at.y));
        }
    }
    let _ = top.set_attribute("data-view", preset.map_or("custom", Preset::id));
    let _ = top.set_attribute("data-azimuth", &format!("{:.4}", cam.azimuth));
}
