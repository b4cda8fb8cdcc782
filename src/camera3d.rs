//! The orbit camera of the 3D drill views (DH chain, SE(3) frames): a perspective projection of
//! world points (metres, z up, right-handed) onto a canvas (CSS pixels, y down), orbit by
//! pixel drags, zoom by wheel or pinch, preset views, and hit tests in screen space.
//!
//! Plain Rust so `cargo test` covers it; the pages draw the projected points with the
//! canvas 2D API (no WebGL, no JS framework).

use crate::math;
use glam::{DVec2, DVec3};

/// ln 1.15: the log of one wheel notch's zoom.
const LN_ZOOM_STEP: f64 = 0.139_761_942_375_158_63;

/// The named views a page offers as buttons.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Preset {
    /// Isometric-like: looking down at 35° from the +x+y quadrant.
    Iso,
    /// From above (+z), x to the right, y up the screen.
    Top,
    /// From the front (−y looking along +y), x to the right, z up.
    Front,
    /// From the side (+x looking along −x), y to the right, z up.
    Side,
}

impl Preset {
    pub const ALL: [Preset; 4] = [Preset::Iso, Preset::Top, Preset::Front, Preset::Side];

    /// The id used in URLs, test hooks and Fluent ids (`iso`, `top`, `front`, `side`).
    pub fn id(self) -> &'static str {
        match self {
            Preset::Iso => "iso",
            Preset::Top => "top",
            Preset::Front => "front",
            Preset::Side => "side",
        }
    }

    pub fn from_id(id: &str) -> Option<Preset> {
        Preset::ALL.into_iter().find(|p| p.id() == id)
    }

    /// (azimuth, elevation) in radians.
    fn angles(self) -> (f64, f64) {
        use std::f64::consts::FRAC_PI_2;
        match self {
            Preset::Iso => (Camera::ISO_AZIMUTH, 35f64.to_radians()),
            // Straight down would make the up vector degenerate: stop just short of it.
            Preset::Top => (-FRAC_PI_2, Camera::MAX_ELEVATION),
            Preset::Front => (-FRAC_PI_2, 0.0),
            Preset::Side => (0.0, 0.0),
        }
    }
}

/// A projected point: canvas position (CSS px) and its depth along the view direction
/// (metres from the eye; larger is farther), for painter's-order sorting.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Projected {
    pub at: DVec2,
    pub depth: f64,
}

/// An orbit camera looking at `target` from `distance` metres, at `azimuth` (about world z,
/// from +x) and `elevation` (above the xy plane), with a vertical field of view `fov_y`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Camera {
    pub target: DVec3,
    pub azimuth: f64,
    pub elevation: f64,
    pub distance: f64,
    pub fov_y: f64,
    /// Canvas size, CSS px.
    pub width: f64,
    pub height: f64,
}

impl Camera {
    /// The azimuth the iso preset looks from (45°), rad.
    pub const ISO_AZIMUTH: f64 = std::f64::consts::FRAC_PI_4;
    /// Elevation is kept inside ±89.9° so the view never flips over the pole.
    pub const MAX_ELEVATION: f64 = 89.9 * std::f64::consts::PI / 180.0;
    /// Radians of orbit per CSS pixel dragged.
    pub const ORBIT_RAD_PER_PX: f64 = 0.01;
    /// Zoom limits as multiples of the scene radius given to [`Camera::framing`].
    pub const MIN_DISTANCE_FACTOR: f64 = 0.5;
    pub const MAX_DISTANCE_FACTOR: f64 = 20.0;
    /// Nearest depth drawn: points closer than this to the eye are not projected.
    pub const NEAR: f64 = 1e-3;

    /// A camera at `preset` framing a sphere of `radius` metres about `target` in a
    /// `width`×`height` canvas.
    pub fn framing(target: DVec3, radius: f64, preset: Preset, width: f64, height: f64) -> Camera {
        let fov_y = 40f64.to_radians();
        let (azimuth, elevation) = preset.angles();
        let r = radius.max(1e-6);
        let aspect = if height > 0.0 { width / height } else { 1.0 };
        // Fit the sphere in the narrower of the two fields of view.
        let half = math::tan(fov_y / 2.0) * aspect.min(1.0);
        // sin(atan h) = h / √(1 + h²)
        let distance = r * (1.0 + half * half).sqrt() / half;
        Camera {
            target,
            azimuth,
            elevation,
            distance,
            fov_y,
            width,
            height,
        }
    }

    /// Turn to a preset view, keeping target and distance.
    pub fn set_preset(&mut self, preset: Preset) {
        let (a, e) = preset.angles();
        self.azimuth = a;
        self.elevation = e;
    }

    /// The eye position.
    pub fn eye(&self) -> DVec3 {
        let (se, ce) = math::sincos(self.elevation);
        let (sa, ca) = math::sincos(self.azimuth);
        self.target + self.distance * DVec3::new(ce * ca, ce * sa, se)
    }

    /// Unit vectors (right, up, forward) of the view; forward points from the eye to the target.
    pub fn basis(&self) -> (DVec3, DVec3, DVec3) {
        let forward = (self.target - self.eye()).normalize();
        let right = forward.cross(DVec3::Z).normalize();
        let up = right.cross(forward);
        (right, up, forward)
    }

    /// Pixels per metre at unit depth.
    fn focal_px(&self) -> f64 {
        (self.height / 2.0) / math::tan(self.fov_y / 2.0)
    }

    /// Where a world point lands on the canvas, or `None` when it is behind the eye.
    pub fn project(&self, p: DVec3) -> Option<Projected> {
        let (right, up, forward) = self.basis();
        let v = p - self.eye();
        let depth = v.dot(forward);
        if depth.is_nan() || depth <= Self::NEAR {
            return None;
        }
        let f = self.focal_px() / depth;
        Some(Projected {
            at: DVec2::new(
                self.width / 2.0 + v.dot(right) * f,
                self.height / 2.0 - v.dot(up) * f,
            ),
            depth,
        })
    }

    /// Canvas pixels per metre at the depth of world point `p` (for sizing markers), or 0 when
    /// it is behind the eye.
    pub fn scale_at(&self, p: DVec3) -> f64 {
        let (_, _, forward) = self.basis();
        let depth = (p - self.eye()).dot(forward);
        if depth > Self::NEAR {
            self.focal_px() / depth
        } else {
            0.0
        }
    }

    /// The world displacement, in the plane through `at_world` facing the camera, that moves
    /// its projection by `delta_px` (for dragging a point in the view).
    pub fn screen_delta_to_world(&self, at_world: DVec3, delta_px: DVec2) -> DVec3 {
        let s = self.scale_at(at_world);
        if s <= 0.0 {
            return DVec3::ZERO;
        }
        let (right, up, _) = self.basis();
        right * (delta_px.x / s) - up * (delta_px.y / s)
    }

    /// Orbit by a pointer drag of `delta_px` (right drag turns the scene right, down drag
    /// looks from higher).
    pub fn orbit(&mut self, delta_px: DVec2) {
        self.azimuth -= delta_px.x * Self::ORBIT_RAD_PER_PX;
        self.azimuth = self.azimuth.rem_euclid(std::f64::consts::TAU);
        self.elevation = (self.elevation + delta_px.y * Self::ORBIT_RAD_PER_PX)
            .clamp(-Self::MAX_ELEVATION, Self::MAX_ELEVATION);
    }

    /// Zoom by `factor` (> 1 moves closer), within `[MIN, MAX]_DISTANCE_FACTOR × radius`.
    pub fn zoom(&mut self, factor: f64, radius: f64) {
        if !(factor.is_finite() && factor > 0.0) {
            return;
        }
        let r = radius.max(1e-6);
        self.distance = (self.distance / factor)
            .clamp(Self::MIN_DISTANCE_FACTOR * r, Self::MAX_DISTANCE_FACTOR * r);
    }

    /// The zoom factor of a wheel event's `deltaY` (pixels): one notch (100 px) is ×1.15
    /// (`exp(ln 1.15 · notches)`).
    pub fn wheel_factor(delta_y: f64) -> f64 {
        if delta_y.is_finite() {
            math::exp(LN_ZOOM_STEP * -delta_y.clamp(-500.0, 500.0) / 100.0)
        } else {
            1.0
        }
    }

    /// Resize the canvas the camera draws into.
    pub fn resize(&mut self, width: f64, height: f64) {
        self.width = width;
        self.height = height;
    }
}

/// The index of the projected point nearest to `cursor` within `radius_px`, the nearest to the
/// eye winning among points at equal screen distance. Points behind the eye are skipped.
pub fn hit_point(points: &[Option<Projected>], cursor: DVec2, radius_px: f64) -> Option<usize> {
    let mut best: Option<(usize, f64, f64)> = None;
    for (i, p) in points.iter().enumerate() {
        let Some(p) = p else { continue };
        let d = p.at.distance(cursor);
        if d > radius_px {
            continue;
        }
        let better = match best {
            None => true,
            Some((_, bd, bdepth)) => d < bd || (d == bd && p.depth < bdepth),
        };
        if better {
            best = Some((i, d, p.depth));
        }
    }
    best.map(|(i, _, _)| i)
}

/// The lines of a square ground grid in the z = 0 plane: `n` cells of `cell` metres each way,
/// centred on the origin, as (from, to) pairs.
pub fn ground_grid(n: usize, cell: f64) -> Vec<(DVec3, DVec3)> {
    let half = n as f64 * cell / 2.0;
    (0..=n)
        .flat_map(|i| {
            let c = -half + i as f64 * cell;
            [
                (DVec3::new(c, -half, 0.0), DVec3::new(c, half, 0.0)),
                (DVec3::new(-half, c, 0.0), DVec3::new(half, c, 0.0)),
            ]
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cam(preset: Preset) -> Camera {
        Camera::framing(DVec3::ZERO, 0.5, preset, 800.0, 600.0)
    }

    #[test]
    fn target_projects_to_the_centre() {
        for p in Preset::ALL {
            let c = cam(p);
            let q = c.project(DVec3::ZERO).unwrap();
            assert!((q.at - DVec2::new(400.0, 300.0)).length() < 1e-9, "{p:?}");
            assert!((q.depth - c.distance).abs() < 1e-12);
        }
    }

    #[test]
    fn framing_fits_the_sphere() {
        let c = cam(Preset::Front);
        // The sphere's top point, seen from the front, lies inside the canvas.
        for p in [
            DVec3::Z * 0.5,
            DVec3::X * 0.5,
            -DVec3::X * 0.5,
            -DVec3::Z * 0.5,
        ] {
            let q = c.project(p).unwrap();
            assert!(q.at.x >= 0.0 && q.at.x <= 800.0 && q.at.y >= 0.0 && q.at.y <= 600.0);
        }
    }

    /// Where the world's x, y and z axes (0.1 long, from the origin) point on the screen of
    /// `preset`'s view, in pixels from the origin's image.
    fn screen_axes(preset: Preset) -> [DVec2; 3] {
        let c = cam(preset);
        let o = c.project(DVec3::ZERO).unwrap().at;
        [DVec3::X, DVec3::Y, DVec3::Z].map(|axis| c.project(axis * 0.1).unwrap().at - o)
    }

    #[test]
    fn front_view_has_x_right_and_z_up() {
        let [x, _, z] = screen_axes(Preset::Front);
        assert!(x.x > 0.0 && x.y.abs() < 1e-9);
        assert!(z.y < 0.0 && z.x.abs() < 1e-9);
    }

    #[test]
    fn top_view_has_x_right_and_y_up() {
        let [x, y, _] = screen_axes(Preset::Top);
        assert!(x.x > 0.0 && x.y.abs() < 1e-3);
        assert!(y.y < 0.0 && y.x.abs() < 1e-3);
    }

    #[test]
    fn side_view_has_y_right() {
        let [_, y, _] = screen_axes(Preset::Side);
        assert!(y.x > 0.0);
    }

    #[test]
    fn points_behind_the_eye_are_not_projected() {
        let c = cam(Preset::Iso);
        let behind = c.eye() + (c.eye() - c.target);
        assert!(c.project(behind).is_none());
        assert_eq!(c.scale_at(behind), 0.0);
    }

    #[test]
    fn screen_delta_round_trips() {
        let c = cam(Preset::Iso);
        let p = DVec3::new(0.1, -0.05, 0.2);
        let d = DVec2::new(13.0, -7.0);
        let w = c.screen_delta_to_world(p, d);
        let moved = c.project(p + w).unwrap().at - c.project(p).unwrap().at;
        // Perspective makes this first-order: close for small drags.
        assert!((moved - d).length() < 0.2, "{moved:?}");
    }

    #[test]
    fn orbit_clamps_elevation_and_wraps_azimuth() {
        let mut c = cam(Preset::Iso);
        c.orbit(DVec2::new(0.0, 1e6));
        assert_eq!(c.elevation, Camera::MAX_ELEVATION);
        c.orbit(DVec2::new(0.0, -1e6));
        assert_eq!(c.elevation, -Camera::MAX_ELEVATION);
        c.orbit(DVec2::new(-1e4, 0.0));
        assert!((0.0..std::f64::consts::TAU).contains(&c.azimuth));
        // Even at the pole the basis stays finite.
        let (r, u, f) = c.basis();
        assert!(r.is_finite() && u.is_finite() && f.is_finite());
    }

    #[test]
    fn zoom_is_clamped_and_ignores_bad_factors() {
        let mut c = cam(Preset::Iso);
        let d0 = c.distance;
        c.zoom(f64::NAN, 0.5);
        c.zoom(0.0, 0.5);
        assert_eq!(c.distance, d0);
        c.zoom(1e9, 0.5);
        assert_eq!(c.distance, 0.25);
        c.zoom(1e-9, 0.5);
        assert_eq!(c.distance, 10.0);
        assert!(Camera::wheel_factor(-100.0) > 1.0 && Camera::wheel_factor(100.0) < 1.0);
        assert_eq!(Camera::wheel_factor(f64::NAN), 1.0);
    }

    #[test]
    fn hit_point_prefers_nearest_on_screen_then_nearest_to_the_eye() {
        let mk = |x: f64, depth: f64| {
            Some(Projected {
                at: DVec2::new(x, 0.0),
                depth,
            })
        };
        let pts = [
            mk(10.0, 1.0),
            None,
            mk(3.0, 2.0),
            mk(3.0, 1.5),
            mk(50.0, 0.1),
        ];
        assert_eq!(hit_point(&pts, DVec2::ZERO, 12.0), Some(3));
        assert_eq!(hit_point(&pts, DVec2::new(100.0, 0.0), 12.0), None);
        assert_eq!(hit_point(&[], DVec2::ZERO, 12.0), None);
    }

    #[test]
    fn ground_grid_lines() {
        let g = ground_grid(4, 0.1);
        assert_eq!(g.len(), 10);
        assert!(g.iter().all(|(a, b)| a.z == 0.0 && b.z == 0.0));
        assert!((g[0].0.x + 0.2).abs() < 1e-12);
    }

    #[test]
    fn presets_round_trip_their_ids() {
        for p in Preset::ALL {
            assert_eq!(Preset::from_id(p.id()), Some(p));
        }
        assert_eq!(Preset::from_id("nope"), None);
    }
}
