//! What a 3D view draws, as plain data: lines, arrows, dots, labels and filled quads (a
//! box's faces) in world coordinates
//! (metres, z up), grouped in layers (the ground first, the scene, overlays last), projected
//! through a [`Camera`] into canvas marks sorted for the painter's algorithm (within a layer,
//! the farthest mark first). Segments that cross the camera's near plane are clipped there;
//! anything wholly behind the eye is left out.
//!
//! Helpers build the usual pieces: a ground grid ([`Scene::grid`]), a frame's axes triad
//! coloured x / y / z ([`Scene::triad`], [`AxisPalette`]) and arrows whose heads are sized in
//! screen pixels. The kit's `orbit` widget paints the marks with the canvas 2D API; this
//! module is pure so `cargo test` covers the projection, clipping and ordering.

use crate::math;
use glam::{DMat3, DVec2, DVec3};

use crate::camera3d::{ground_grid, Camera};

/// How a mark is stroked (widths in CSS px before the projector scale).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Stroke {
    pub color: &'static str,
    pub width_px: f64,
    pub dashed: bool,
}

impl Stroke {
    /// A solid stroke.
    pub const fn solid(color: &'static str, width_px: f64) -> Stroke {
        Stroke {
            color,
            width_px,
            dashed: false,
        }
    }

    /// A dashed stroke.
    pub const fn dashed(color: &'static str, width_px: f64) -> Stroke {
        Stroke {
            color,
            width_px,
            dashed: true,
        }
    }
}

/// Drawing order between groups of marks: every ground mark is painted before any scene
/// mark, every overlay mark after; depth orders marks within a layer.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum Layer {
    Ground,
    Scene,
    Overlay,
}

/// A shape in world coordinates.
#[derive(Debug, Clone, PartialEq)]
pub enum Shape3 {
    Line {
        a: DVec3,
        b: DVec3,
    },
    /// A line from `a` with a head at `b`.
    Arrow {
        a: DVec3,
        b: DVec3,
    },
    /// A filled disc of a fixed screen radius.
    Dot {
        at: DVec3,
        radius_px: f64,
    },
    /// Text centred at a point.
    Label {
        at: DVec3,
        text: String,
    },
    /// A flat face of a solid, filled with the stroke's colour and outlined with `edge`: its
    /// corners counter-clockwise seen from outside (a face turned away from the camera is
    /// left out), sorted by the depth of `sort` (the solid's centre, so that a solid's faces
    /// are painted together).
    Quad {
        corners: [DVec3; 4],
        edge: &'static str,
        sort: DVec3,
    },
}

/// A shape on the canvas (CSS px).
#[derive(Debug, Clone, PartialEq)]
pub enum Shape2 {
    Line {
        from: DVec2,
        to: DVec2,
    },
    /// A line and the two ends of its head's wings (drawn from `to`).
    Arrow {
        from: DVec2,
        to: DVec2,
        wings: [DVec2; 2],
    },
    Dot {
        at: DVec2,
        radius_px: f64,
    },
    Label {
        at: DVec2,
        text: String,
    },
    Quad {
        corners: [DVec2; 4],
        edge: &'static str,
    },
}

/// One projected mark: its shape, stroke, and mean depth (metres from the eye).
#[derive(Debug, Clone, PartialEq)]
pub struct Mark {
    pub shape: Shape2,
    pub stroke: Stroke,
    pub layer: Layer,
    pub depth: f64,
}

/// Colours of a triad's x, y and z axes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum AxisPalette {
    /// The convention: x red, y green, z blue.
    #[default]
    Classic,
    /// Okabe–Ito vermilion, bluish green and blue: told apart with the common colour-vision
    /// deficiencies (the axes are also labelled).
    ColorBlindSafe,
}

impl AxisPalette {
    /// The colours of x, y, z.
    pub fn colors(self) -> [&'static str; 3] {
        match self {
            AxisPalette::Classic => ["#d62728", "#1a9e3a", "#1f5fd6"],
            AxisPalette::ColorBlindSafe => ["#d55e00", "#009e73", "#0072b2"],
        }
    }

    /// The id used in URLs (`classic`, `cb`).
    pub fn id(self) -> &'static str {
        match self {
            AxisPalette::Classic => "classic",
            AxisPalette::ColorBlindSafe => "cb",
        }
    }

    pub fn from_id(id: &str) -> Option<AxisPalette> {
        [AxisPalette::Classic, AxisPalette::ColorBlindSafe]
            .into_iter()
            .find(|p| p.id() == id)
    }
}

/// Arrow heads: length in px per px of stroke width, plus a base, and the wing angle.
const HEAD_BASE_PX: f64 = 6.0;
const HEAD_PER_WIDTH: f64 = 2.0;
const HEAD_HALF_ANGLE: f64 = 0.45;
/// A head never takes more than this fraction of its arrow's screen length.
const HEAD_MAX_FRACTION: f64 = 0.45;

/// A list of shapes to draw.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Scene {
    items: Vec<(Shape3, Stroke, Layer)>,
}

impl Scene {
    pub fn new() -> Scene {
        Scene::default()
    }

    /// Number of shapes.
    pub fn len(&self) -> usize {
        self.items.len()
    }

    pub fn is_empty(&self) -> bool {
        self.items.is_empty()
    }

    /// Removes every shape (keeps the allocation).
    pub fn clear(&mut self) {
        self.items.clear();
    }

    pub fn push(&mut self, layer: Layer, shape: Shape3, stroke: Stroke) {
        self.items.push((shape, stroke, layer));
    }

    pub fn line(&mut self, a: DVec3, b: DVec3, stroke: Stroke) {
        self.push(Layer::Scene, Shape3::Line { a, b }, stroke);
    }

    pub fn arrow(&mut self, a: DVec3, b: DVec3, stroke: Stroke) {
        self.push(Layer::Scene, Shape3::Arrow { a, b }, stroke);
    }

    pub fn dot(&mut self, at: DVec3, radius_px: f64, color: &'static str) {
        self.push(
            Layer::Scene,
            Shape3::Dot { at, radius_px },
            Stroke::solid(color, 0.0),
        );
    }

    /// A label drawn over the scene (overlay layer).
    pub fn label(&mut self, at: DVec3, text: impl Into<String>, color: &'static str) {
        self.push(
            Layer::Overlay,
            Shape3::Label {
                at,
                text: text.into(),
            },
            Stroke::solid(color, 0.0),
        );
    }

    /// A square ground grid in the z = 0 plane ([`ground_grid`]), on the ground layer.
    pub fn grid(&mut self, n: usize, cell: f64, stroke: Stroke) {
        for (a, b) in ground_grid(n, cell) {
            self.push(Layer::Ground, Shape3::Line { a, b }, stroke);
        }
    }

    /// A frame's axes: arrows of `length` metres from `origin` along the columns of
    /// `rotation` (x, y, z), coloured by `palette`, `width_px` wide; with `labels`, each tip
    /// says its axis name (e.g. `["x1", "y1", "z1"]`).
    pub fn triad(
        &mut self,
        origin: DVec3,
        rotation: DMat3,
        length: f64,
        palette: AxisPalette,
        width_px: f64,
        labels: Option<[&str; 3]>,
    ) {
        self.triad_in(
            Layer::Scene,
            origin,
            rotation,
            length,
            palette,
            width_px,
            labels,
        );
    }

    /// [`Scene::triad`] on `layer` (an [`Layer::Overlay`] triad is drawn over everything: a
    /// frame being taught, a gizmo).
    #[allow(clippy::too_many_arguments)]
    pub fn triad_in(
        &mut self,
        layer: Layer,
        origin: DVec3,
        rotation: DMat3,
        length: f64,
        palette: AxisPalette,
        width_px: f64,
        labels: Option<[&str; 3]>,
    ) {
        let colors = palette.colors();
        for k in 0..3 {
            let tip = origin + rotation.col(k) * length;
            self.push(
                layer,
                Shape3::Arrow { a: origin, b: tip },
                Stroke::solid(colors[k], width_px),
            );
            if let Some(names) = labels {
                self.label(
                    origin + rotation.col(k) * (length * 1.18),
                    names[k],
                    colors[k],
                );
            }
        }
    }

    /// The marks as seen by `camera`, in painter's order (layer, then farthest first).
    pub fn project(&self, camera: &Camera) -> Vec<Mark> {
        let eye = camera.eye();
        let (_, _, forward) = camera.basis();
        // Clip a little in front of the camera's own near limit, so every kept end projects.
        let near = Camera::NEAR * 2.0;
        let depth = |p: DVec3| (p - eye).dot(forward);
        let mut marks = Vec::with_capacity(self.items.len());
        for (shape, stroke, layer) in &self.items {
            let mark = |shape: Shape2, depth: f64| Mark {
                shape,
                stroke: *stroke,
                layer: *layer,
                depth,
            };
            match shape {
                Shape3::Line { a, b } | Shape3::Arrow { a, b } => {
                    let (da, db) = (depth(*a), depth(*b));
                    let Some((ca, cb)) = clip(*a, *b, da, db, near) else {
                        continue;
                    };
                    let (Some(pa), Some(pb)) = (camera.project(ca), camera.project(cb)) else {
                        continue;
                    };
                    let d = (pa.depth + pb.depth) / 2.0;
                    // An arrow whose head was clipped away is drawn as a line.
                    let headed = matches!(shape, Shape3::Arrow { .. }) && cb == *b;
                    if headed {
                        let wings = arrow_wings(pa.at, pb.at, stroke.width_px);
                        marks.push(mark(
                            Shape2::Arrow {
                                from: pa.at,
                                to: pb.at,
                                wings,
                            },
                            d,
                        ));
                    } else {
                        marks.push(mark(
                            Shape2::Line {
                                from: pa.at,
                                to: pb.at,
                            },
                            d,
                        ));
                    }
                }
                Shape3::Quad {
                    corners,
                    edge,
                    sort,
                } => {
                    // A face turned away, or reaching behind the near plane (its solid is
                    // at the eye), is left out.
                    let outward = (corners[1] - corners[0]).cross(corners[3] - corners[0]);
                    if outward.dot(eye - corners[0]) <= 0.0
                        || corners.iter().any(|c| depth(*c) <= near)
                    {
                        continue;
                    }
                    let p = corners.map(|c| camera.project(c));
                    if let [Some(a), Some(b), Some(c), Some(d)] = p {
                        marks.push(mark(
                            Shape2::Quad {
                                corners: [a.at, b.at, c.at, d.at],
                                edge,
                            },
                            depth(*sort),
                        ));
                    }
                }
                Shape3::Dot { at, radius_px } => {
                    if let Some(p) = camera.project(*at) {
                        marks.push(mark(
                            Shape2::Dot {
                                at: p.at,
                                radius_px: *radius_px,
                            },
                            p.depth,
                        ));
                    }
                }
                Shape3::Label { at, text } => {
                    if let Some(p) = camera.project(*at) {
                        marks.push(mark(
                            Shape2::Label {
                                at: p.at,
                                text: text.clone(),
                            },
                            p.depth,
                        ));
                    }
                }
            }
        }
        // Stable: marks of equal layer and depth keep the order they were added in.
        marks.sort_by(|x, y| {
            x.layer
                .cmp(&y.layer)
                .then_with(|| y.depth.total_cmp(&x.depth))
        });
        marks
    }
}

/// The part of segment `a`–`b` (depths `da`, `db`) at depth `near` or more, if any.
fn clip(a: DVec3, b: DVec3, da: f64, db: f64, near: f64) -> Option<(DVec3, DVec3)> {
    if !(da.is_finite() && db.is_finite()) {
        return None;
    }
    match (da >= near, db >= near) {
        (true, true) => Some((a, b)),
        (false, false) => None,
        (true, false) => Some((a, a + (b - a) * ((da - near) / (da - db)))),
        (false, true) => Some((b + (a - b) * ((db - near) / (db - da)), b)),
    }
}

/// The wing ends of an arrow head at `to`, pointing from `from`, for a stroke `width_px`.
pub fn arrow_wings(from: DVec2, to: DVec2, width_px: f64) -> [DVec2; 2] {
    let v = to - from;
    let len = v.length();
    if len.is_nan() || len <= 1e-9 {
        return [to, to];
    }
    let head = (HEAD_BASE_PX + HEAD_PER_WIDTH * width_px).min(HEAD_MAX_FRACTION * len);
    let back = -v / len * head;
    let (s, c) = math::sincos(HEAD_HALF_ANGLE);
    let rot = |w: DVec2, s: f64| DVec2::new(w.x * c - w.y * s, w.x * s + w.y * c);
    [to + rot(back, s), to + rot(back, -s)]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::camera3d::Preset;

    fn cam(preset: Preset) -> Camera {
        Camera::framing(DVec3::ZERO, 0.5, preset, 800.0, 600.0)
    }

    const INK: Stroke = Stroke::solid("#000", 2.0);

    #[test]
    fn ground_comes_first_then_far_before_near_then_overlays() {
        let c = cam(Preset::Front);
        let mut s = Scene::new();
        s.label(DVec3::ZERO, "o", "#000");
        // Seen from the front (−y), +y is farther.
        s.line(DVec3::new(0.0, -0.2, 0.0), DVec3::new(0.1, -0.2, 0.0), INK);
        s.line(DVec3::new(0.0, 0.2, 0.0), DVec3::new(0.1, 0.2, 0.0), INK);
        s.grid(2, 0.1, Stroke::solid("#ccc", 1.0));
        let marks = s.project(&c);
        assert_eq!(marks.len(), 1 + 2 + 6);
        assert!(marks[..6].iter().all(|m| m.layer == Layer::Ground));
        assert_eq!(marks[6].layer, Layer::Scene);
        assert!(marks[6].depth > marks[7].depth);
        assert_eq!(marks[8].layer, Layer::Overlay);
        assert!(matches!(marks[8].shape, Shape2::Label { .. }));
    }

    #[test]
    fn segments_behind_the_eye_are_clipped_or_dropped() {
        let c = cam(Preset::Iso);
        let eye = c.eye();
        let (_, _, f) = c.basis();
        let mut s = Scene::new();
        // Wholly behind.
        s.line(eye - f, eye - f * 2.0, INK);
        // Crossing the eye plane: clipped to the part in front.
        s.arrow(eye - f * 0.5, c.target, INK);
        let marks = s.project(&c);
        assert_eq!(marks.len(), 1);
        match &marks[0].shape {
            Shape2::Arrow { to, .. } => {
                assert!((*to - DVec2::new(400.0, 300.0)).length() < 1e-9);
            }
            other => panic!("expected an arrow, got {other:?}"),
        }
        // The clipped end lies on the near plane, every coordinate finite.
        assert!(marks[0].depth.is_finite());
        // Head clipped away: a line.
        let mut s = Scene::new();
        s.arrow(c.target, eye - f * 0.5, INK);
        assert!(matches!(s.project(&c)[0].shape, Shape2::Line { .. }));
    }

    #[test]
    fn triad_arrows_follow_the_rotation_columns() {
        let c = cam(Preset::Front);
        let mut s = Scene::new();
        // Rotated 90° about y: x → −z, z → +x.
        let r = DMat3::from_rotation_y(std::f64::consts::FRAC_PI_2);
        s.triad(
            DVec3::ZERO,
            r,
            0.1,
            AxisPalette::Classic,
            2.0,
            Some(["x", "y", "z"]),
        );
        assert_eq!(s.len(), 6);
        let marks = s.project(&c);
        let o = c.project(DVec3::ZERO).unwrap().at;
        let arrow_to = |color: &str| {
            marks
                .iter()
                .find_map(|m| match m.shape {
                    Shape2::Arrow { to, .. } if m.stroke.color == color => Some(to),
                    _ => None,
                })
                .unwrap()
        };
        let [xc, _, zc] = AxisPalette::Classic.colors();
        // x now points down the screen, z to the right (front view: x right, z up).
        let x = arrow_to(xc);
        assert!(x.y > o.y + 10.0 && (x.x - o.x).abs() < 1e-6);
        let z = arrow_to(zc);
        assert!(z.x > o.x + 10.0 && (z.y - o.y).abs() < 1e-6);
        let labels = marks
            .iter()
            .filter(|m| matches!(m.shape, Shape2::Label { .. }))
            .count();
        assert_eq!(labels, 3);
    }

    #[test]
    fn arrow_wings_are_symmetric_and_short_for_short_arrows() {
        let [a, b] = arrow_wings(DVec2::ZERO, DVec2::new(100.0, 0.0), 2.0);
        assert!(a.x < 100.0 && b.x < 100.0);
        assert!((a.y + b.y).abs() < 1e-12 && (a.x - b.x).abs() < 1e-12);
        let head = (DVec2::new(100.0, 0.0) - a).length();
        assert!((head - (HEAD_BASE_PX + HEAD_PER_WIDTH * 2.0)).abs() < 1e-9);
        let [a, _] = arrow_wings(DVec2::ZERO, DVec2::new(4.0, 0.0), 2.0);
        assert!((DVec2::new(4.0, 0.0) - a).length() <= 4.0 * HEAD_MAX_FRACTION + 1e-12);
        // Degenerate arrow: no wings.
        assert_eq!(arrow_wings(DVec2::ONE, DVec2::ONE, 2.0), [DVec2::ONE; 2]);
    }

    #[test]
    fn palettes_round_trip_and_differ() {
        for p in [AxisPalette::Classic, AxisPalette::ColorBlindSafe] {
            assert_eq!(AxisPalette::from_id(p.id()), Some(p));
        }
        assert_ne!(
            AxisPalette::Classic.colors(),
            AxisPalette::ColorBlindSafe.colors()
        );
        assert_eq!(AxisPalette::from_id("x"), None);
    }
}
