//! The relative SE(3) pose page (`#/se3-relative`), plain Rust: the twelve fields in the
//! recipe's units or in degrees, the URL, the 4×4 matrices' text, intrinsic and extrinsic
//! rotations, the composition check, and the 3D view's scene, gizmo hit tests and drag maths
//! (through [`crate::camera3d`]).
//!
//! The recipe takes radians. The page's rad/deg switch changes only how the six angle
//! fields are shown and typed: the page keeps each field's text **in the recipe's units**
//! (what the URL, the command lines and the CSV use); in degree mode a field shows that
//! value in degrees, and what the user types there is converted to radians for that field
//! alone, so switching back and forth never changes a value nobody touched.
//!
//! Rotations: `R(roll, pitch, yaw) = Rz(yaw) · Ry(pitch) · Rx(roll)` is *extrinsic* x → y → z
//! (about the fixed world axes: first roll about x, then pitch about y, then yaw about z),
//! which is the same as *intrinsic* z → y′ → x″ (about the moving axes: yaw first). Applied
//! as intrinsic x → y′ → z″ the same three numbers give `Rx · Ry · Rz`, another rotation.

use glam::{DVec2, DVec3};
use nalgebra::{Matrix3, Matrix4};

use crate::camera3d::{hit_point, Camera, Projected};
use crate::pyfmt::py_float;
use crate::recipes::se3_relative::{relative_transform, rpy_to_rotation, Pose, Se3Params, INFO};
use crate::view::url::IgnoredKey;

/// The number of fields: A's x, y, z, roll, pitch, yaw, then B's.
pub const FIELDS: usize = 12;

/// The URL key of the rad/deg switch (`angles=deg`; radians are the default).
pub const UNIT_KEY: &str = "angles";
/// The URL key of the preset view (`view=top`).
pub const VIEW_KEY: &str = "view";

/// How the angle fields are shown and typed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum AngleUnit {
    /// The recipe's unit.
    #[default]
    Rad,
    Deg,
}

impl AngleUnit {
    /// The id in the URL and test hooks (`rad`, `deg`).
    pub fn id(self) -> &'static str {
        match self {
            AngleUnit::Rad => "rad",
            AngleUnit::Deg => "deg",
        }
    }

    pub fn from_id(id: &str) -> Option<AngleUnit> {
        match id {
            "rad" => Some(AngleUnit::Rad),
            "deg" => Some(AngleUnit::Deg),
            _ => None,
        }
    }

    /// An angle in radians, in this unit.
    pub fn from_rad(self, rad: f64) -> f64 {
        match self {
            AngleUnit::Rad => rad,
            AngleUnit::Deg => rad.to_degrees(),
        }
    }
}

/// Whether field `index` (argument order) is an angle.
pub fn is_angle(index: usize) -> bool {
    index % 6 >= 3
}

/// The argument name of field `index` (`ax` … `bw`): its `data-field` and URL key.
pub fn field_name(index: usize) -> &'static str {
    INFO.args.get(index).map_or("", |a| a.name)
}

/// Degrees as a field shows them: at most 10 decimals, no trailing zeros, no `-0`
/// (`0.2 rad` → `11.4591559026`, `π/6` → `30`).
pub fn deg_text(deg: f64) -> String {
    if !deg.is_finite() {
        return py_float(deg);
    }
    let mut text = format!("{deg:.10}");
    if text.contains('.') {
        while text.ends_with('0') {
            text.pop();
        }
        if text.ends_with('.') {
            text.pop();
        }
    }
    crate::numtext::unsigned_zero(text)
}

fn finite_number(text: &str) -> Option<f64> {
    text.trim().parse::<f64>().ok().filter(|v| v.is_finite())
}

/// A recipe text (radians) as typed in degree mode; a text that is no finite number is
/// left as it is (its message is the recipe's).
pub fn rad_to_deg_text(rad_text: &str) -> String {
    match finite_number(rad_text) {
        Some(rad) => deg_text(rad.to_degrees()),
        None => rad_text.to_string(),
    }
}

/// A text typed in degrees as the recipe's radians (Python's `repr`, so the command line
/// and the URL carry every digit); a text that is no finite number is left as it is.
pub fn deg_to_rad_text(deg_text: &str) -> String {
    match finite_number(deg_text) {
        Some(deg) => py_float(deg.to_radians()),
        None => deg_text.to_string(),
    }
}

/// The fields' texts in the recipe's units (`None`: blank, the default) and the unit the
/// angle fields are shown in.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct PoseFields {
    /// What the recipe is given, field by field (radians for angles).
    pub recipe: Vec<Option<String>>,
    pub unit: AngleUnit,
}

impl PoseFields {
    /// All defaults, shown in `unit`.
    pub fn new(unit: AngleUnit) -> PoseFields {
        PoseFields {
            recipe: vec![None; FIELDS],
            unit,
        }
    }

    /// The recipe's text of field `index`, the default filled in.
    pub fn recipe_text(&self, index: usize) -> String {
        match self.recipe.get(index).and_then(|t| t.as_deref()) {
            Some(t) if !t.trim().is_empty() => t.trim().to_string(),
            _ => INFO
                .args
                .get(index)
                .map_or(String::new(), |a| a.default.to_string()),
        }
    }

    /// What field `index` shows in the current unit.
    pub fn shown(&self, index: usize) -> String {
        let text = self.recipe_text(index);
        if is_angle(index) && self.unit == AngleUnit::Deg {
            rad_to_deg_text(&text)
        } else {
            text
        }
    }

    /// The twelve texts the form shows.
    pub fn shown_all(&self) -> Vec<String> {
        (0..FIELDS).map(|i| self.shown(i)).collect()
    }

    /// The user typed `text` in field `index` (in the current unit).
    pub fn set_shown(&mut self, index: usize, text: &str) {
        if index >= FIELDS {
            return;
        }
        if self.recipe.len() < FIELDS {
            self.recipe.resize(FIELDS, None);
        }
        let recipe = if is_angle(index) && self.unit == AngleUnit::Deg {
            deg_to_rad_text(text)
        } else {
            text.trim().to_string()
        };
        self.recipe[index] = Some(recipe);
    }

    /// Reads the fields and the unit from the URL; keys that are neither are reported.
    pub fn read(query: &[(String, String)]) -> (PoseFields, Vec<IgnoredKey>) {
        let mut fields = PoseFields::new(AngleUnit::Rad);
        let mut ignored = Vec::new();
        for (key, value) in query {
            if key == UNIT_KEY {
                match AngleUnit::from_id(value) {
                    Some(u) => fields.unit = u,
                    None => ignored.push(IgnoredKey::invalid(key.clone())),
                }
            } else if key == VIEW_KEY {
                // The view's own key; read by the page.
            } else if let Some(i) = (0..FIELDS).find(|&i| field_name(i) == key) {
                fields.recipe[i] = Some(value.clone());
            } else {
                ignored.push(IgnoredKey::unknown(key.clone()));
            }
        }
        (fields, ignored)
    }

    /// The URL pairs: the fields that differ from the defaults (radians), then the unit when
    /// it is degrees.
    pub fn write(&self) -> Vec<(String, String)> {
        let mut pairs: Vec<(String, String)> = (0..FIELDS)
            .filter_map(|i| {
                let text = self.recipe_text(i);
                let default = INFO.args.get(i)?.default;
                (text != default).then(|| (field_name(i).to_string(), text))
            })
            .collect();
        if self.unit == AngleUnit::Deg {
            pairs.push((UNIT_KEY.into(), AngleUnit::Deg.id().into()));
        }
        pairs
    }
}

/// A matrix entry as the page prints it: `digits` decimals, no `-0.0000`.
pub fn entry_text(x: f64, digits: usize) -> String {
    crate::numtext::fixed(x, digits)
}

/// The rows of a 4×4 matrix as text.
pub fn matrix_rows(m: &Matrix4<f64>, digits: usize) -> [[String; 4]; 4] {
    std::array::from_fn(|r| std::array::from_fn(|c| entry_text(m[(r, c)], digits)))
}

/// The rows of a 3×3 matrix as text.
pub fn rotation_rows(m: &Matrix3<f64>, digits: usize) -> [[String; 3]; 3] {
    std::array::from_fn(|r| std::array::from_fn(|c| entry_text(m[(r, c)], digits)))
}

/// A coordinate axis.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Axis {
    X,
    Y,
    Z,
}

impl Axis {
    fn unit(self) -> DVec3 {
        match self {
            Axis::X => DVec3::X,
            Axis::Y => DVec3::Y,
            Axis::Z => DVec3::Z,
        }
    }
}

/// The rotation by `angle` about the unit vector `axis` (Rodrigues).
pub fn axis_angle(axis: DVec3, angle: f64) -> Matrix3<f64> {
    let (s, c) = angle.sin_cos();
    let k = axis.normalize_or_zero();
    #[rustfmt::skip]
    let kx = Matrix3::new(
        0.0, -k.z, k.y,
        k.z, 0.0, -k.x,
        -k.y, k.x, 0.0,
    );
    Matrix3::identity() + kx * s + kx * kx * (1.0 - c)
}

/// Elementary rotations applied one after the other about the **fixed** world axes: each
/// new rotation multiplies from the left.
pub fn extrinsic(steps: &[(Axis, f64)]) -> Matrix3<f64> {
    steps.iter().fold(Matrix3::identity(), |r, &(axis, angle)| {
        axis_angle(axis.unit(), angle) * r
    })
}

/// Elementary rotations applied one after the other about the **moving** axes of the frame
/// being turned: each one turns about the frame's current axis (the column of the rotation
/// so far), done geometrically.
pub fn intrinsic(steps: &[(Axis, f64)]) -> Matrix3<f64> {
    steps.iter().fold(Matrix3::identity(), |r, &(axis, angle)| {
        let k = match axis {
            Axis::X => 0,
            Axis::Y => 1,
            Axis::Z => 2,
        };
        let moving = DVec3::new(r[(0, k)], r[(1, k)], r[(2, k)]);
        axis_angle(moving, angle) * r
    })
}

/// The two readings of the same roll, pitch, yaw the teaching panel puts side by side.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RpyReadings {
    /// The recipe's: extrinsic x → y → z (= intrinsic z → y′ → x″) = `Rz Ry Rx`.
    pub recipe: Matrix3<f64>,
    /// The same numbers as intrinsic x → y′ → z″ = `Rx Ry Rz`.
    pub intrinsic_xyz: Matrix3<f64>,
}

/// Both readings of `(roll, pitch, yaw)`.
pub fn rpy_readings(roll: f64, pitch: f64, yaw: f64) -> RpyReadings {
    RpyReadings {
        recipe: rpy_to_rotation(roll, pitch, yaw),
        intrinsic_xyz: intrinsic(&[(Axis::X, roll), (Axis::Y, pitch), (Axis::Z, yaw)]),
    }
}

/// Largest entry of `|a − b|`.
pub fn max_abs_diff3(a: &Matrix3<f64>, b: &Matrix3<f64>) -> f64 {
    (a - b).abs().max()
}

/// What the page computes from the two poses.
#[derive(Debug, Clone, PartialEq)]
pub struct Solved {
    pub params: Se3Params,
    pub t_a: Matrix4<f64>,
    pub t_b: Matrix4<f64>,
    /// `T_A⁻¹ T_B`.
    pub t_rel: Matrix4<f64>,
    /// The recipe's row: the relative pose.
    pub rel: Pose,
    /// `max |T_A (T_A⁻¹ T_B) − T_B|`.
    pub check_error: f64,
}

/// Solves the recipe for `params` (already validated).
pub fn solve(params: &Se3Params) -> Solved {
    let t_a = params.a.to_matrix();
    let t_b = params.b.to_matrix();
    let t_rel = relative_transform(&params.a, &params.b);
    let rel = Pose::from_matrix(&t_rel);
    let check_error = (t_a * t_rel - t_b).abs().max();
    Solved {
        params: *params,
        t_a,
        t_b,
        t_rel,
        rel,
        check_error,
    }
}

/// A frame drawn in the view: origin and its three unit axes in world coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Triad {
    pub origin: DVec3,
    pub axes: [DVec3; 3],
}

impl Triad {
    /// The frame of a homogeneous transform.
    pub fn of(t: &Matrix4<f64>) -> Triad {
        let col = |c: usize| DVec3::new(t[(0, c)], t[(1, c)], t[(2, c)]);
        Triad {
            origin: col(3),
            axes: [col(0), col(1), col(2)],
        }
    }

    /// The frame of a rotation placed at `origin`.
    pub fn rotated(r: &Matrix3<f64>, origin: DVec3) -> Triad {
        let col = |c: usize| DVec3::new(r[(0, c)], r[(1, c)], r[(2, c)]);
        Triad {
            origin,
            axes: [col(0), col(1), col(2)],
        }
    }

    pub fn world() -> Triad {
        Triad {
            origin: DVec3::ZERO,
            axes: [DVec3::X, DVec3::Y, DVec3::Z],
        }
    }
}

/// The corners of the path from A's origin to B's along A's own axes: A, then
/// `+x_rel · x_A`, `+y_rel · y_A`, `+z_rel · z_A`, which ends at B's origin ("expressed in
/// A").
pub fn path_in_a(solved: &Solved) -> [DVec3; 4] {
    let a = Triad::of(&solved.t_a);
    let p = [solved.rel.x, solved.rel.y, solved.rel.z];
    let p1 = a.origin + a.axes[0] * p[0];
    let p2 = p1 + a.axes[1] * p[1];
    let p3 = p2 + a.axes[2] * p[2];
    [a.origin, p1, p2, p3]
}

/// Largest scene the view frames, metres (positions beyond are still computed, not framed).
pub const MAX_SCENE_RADIUS: f64 = 1e6;

/// The centre and radius of a sphere holding the world origin and both frames' origins with
/// room for their axes: what the camera frames.
pub fn scene_frame(params: &Se3Params) -> (DVec3, f64) {
    let points = [
        DVec3::ZERO,
        DVec3::new(params.a.x, params.a.y, params.a.z),
        DVec3::new(params.b.x, params.b.y, params.b.z),
    ];
    let lo = points.iter().fold(DVec3::INFINITY, |m, p| m.min(*p));
    let hi = points.iter().fold(DVec3::NEG_INFINITY, |m, p| m.max(*p));
    let centre = (lo + hi) / 2.0;
    let far = points
        .iter()
        .map(|p| p.distance(centre))
        .fold(0.0, f64::max);
    let radius = far.max(0.05) * 1.3;
    if centre.is_finite() && radius.is_finite() && radius <= MAX_SCENE_RADIUS {
        (centre, radius)
    } else {
        (DVec3::ZERO, MAX_SCENE_RADIUS)
    }
}

/// Length of the frames' axes drawn, metres: a fixed share of the scene radius.
pub fn axis_length(radius: f64) -> f64 {
    0.4 * radius
}

/// What a press in the view grabs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Grab {
    /// Frame A's origin (moves A's x, y, z).
    A,
    /// Frame B's origin.
    B,
    /// Frame A's yaw ring (turns A about the world's vertical: only its yaw changes).
    YawA,
    /// Frame B's yaw ring.
    YawB,
}

impl Grab {
    /// Whether this is frame A's (origin or ring).
    pub fn is_a(self) -> bool {
        matches!(self, Grab::A | Grab::YawA)
    }
}

/// Which frame origin a press at `cursor` grabs (`radius_px` of it; the nearer to the eye
/// wins a tie), else `None`.
pub fn hit_frame(
    camera: &Camera,
    params: &Se3Params,
    cursor: DVec2,
    radius_px: f64,
) -> Option<Grab> {
    let points: Vec<Option<Projected>> = [params.a, params.b]
        .iter()
        .map(|p| camera.project(DVec3::new(p.x, p.y, p.z)))
        .collect();
    match hit_point(&points, cursor, radius_px) {
        Some(0) => Some(Grab::A),
        Some(1) => Some(Grab::B),
        _ => None,
    }
}

/// The radius of the yaw rings, metres, for a scene of `radius`.
pub fn ring_radius(radius: f64) -> f64 {
    0.7 * axis_length(radius)
}

/// A yaw ring: `n` points of the circle of `radius` metres about the vertical through
/// `origin`, in its horizontal plane (the recipe's yaw turns about the world's z axis, the
/// last of its rotations, so turning a frame about that vertical changes its yaw alone).
pub fn yaw_ring(origin: DVec3, radius: f64, n: usize) -> Vec<DVec3> {
    (0..n)
        .map(|k| {
            let t = std::f64::consts::TAU * k as f64 / n as f64;
            origin + DVec3::new(t.cos(), t.sin(), 0.0) * radius
        })
        .collect()
}

/// Points of a yaw ring drawn and hit-tested.
pub const RING_POINTS: usize = 48;

/// Whether `cursor` lies within `radius_px` of the projected yaw ring about `origin`.
pub fn hit_ring(
    camera: &Camera,
    origin: DVec3,
    radius: f64,
    cursor: DVec2,
    radius_px: f64,
) -> Option<f64> {
    let pts: Vec<Option<DVec2>> = yaw_ring(origin, radius, RING_POINTS)
        .into_iter()
        .map(|p| camera.project(p).map(|q| q.at))
        .collect();
    let mut best: Option<f64> = None;
    for k in 0..pts.len() {
        let (Some(a), Some(b)) = (pts[k], pts[(k + 1) % pts.len()]) else {
            continue;
        };
        let d = crate::view::drag::dist_to_segment(cursor, a, b);
        if d <= radius_px && best.is_none_or(|m| d < m) {
            best = Some(d);
        }
    }
    best
}

/// What a press grabs: an origin first (within `radius_px`), else the nearer yaw ring
/// (rings of `ring` metres), else nothing (the view orbits).
pub fn hit_gizmo(
    camera: &Camera,
    params: &Se3Params,
    ring: f64,
    cursor: DVec2,
    radius_px: f64,
) -> Option<Grab> {
    if let Some(grab) = hit_frame(camera, params, cursor, radius_px) {
        return Some(grab);
    }
    let origin = |p: &Pose| DVec3::new(p.x, p.y, p.z);
    let a = hit_ring(camera, origin(&params.a), ring, cursor, radius_px);
    let b = hit_ring(camera, origin(&params.b), ring, cursor, radius_px);
    match (a, b) {
        (Some(da), Some(db)) if db < da => Some(Grab::YawB),
        (Some(_), _) => Some(Grab::YawA),
        (None, Some(_)) => Some(Grab::YawB),
        (None, None) => None,
    }
}

/// The angle about the vertical through `origin` (radians from +x toward +y) of the point
/// where the ray through canvas point `at` meets `origin`'s horizontal plane; `None` when
/// the ray runs (nearly) along the plane or meets it behind the eye.
pub fn yaw_at(camera: &Camera, origin: DVec3, at: DVec2) -> Option<f64> {
    let (eye, dir) = ray(camera, at)?;
    if dir.z.abs() < 1e-9 {
        return None;
    }
    let t = (origin.z - eye.z) / dir.z;
    if !(t.is_finite() && t > 0.0) {
        return None;
    }
    let p = eye + dir * t;
    let d = p - origin;
    (d.truncate().length() > 0.0).then(|| d.y.atan2(d.x))
}

/// `angle` wrapped into `(−π, π]`.
pub fn wrap_angle(angle: f64) -> f64 {
    use std::f64::consts::{PI, TAU};
    let a = (angle + PI).rem_euclid(TAU) - PI;
    if a == -PI {
        PI
    } else {
        a
    }
}

/// A dragged yaw as a field's recipe text: to 0.001 rad, or in degree mode to 0.1° (so the
/// field shows a round number of degrees).
pub fn yaw_text(yaw: f64, unit: AngleUnit) -> String {
    match unit {
        AngleUnit::Rad => mm_text(yaw),
        AngleUnit::Deg => deg_to_rad_text(&deg_text((yaw.to_degrees() * 10.0).round() / 10.0)),
    }
}

/// The eye and the direction of the ray through canvas point `at`.
fn ray(camera: &Camera, at: DVec2) -> Option<(DVec3, DVec3)> {
    let (right, up, forward) = camera.basis();
    let focal = (camera.height / 2.0) / (camera.fov_y / 2.0).tan();
    if !(focal.is_finite() && focal > 0.0) {
        return None;
    }
    let dir = forward + right * ((at.x - camera.width / 2.0) / focal)
        - up * ((at.y - camera.height / 2.0) / focal);
    Some((camera.eye(), dir))
}

/// Where the ray through canvas point `at` meets the plane through `anchor` facing the
/// camera: the world point a drag of `anchor` to `at` puts it at (exact, not first-order),
/// or `None` when the ray misses the plane in front of the eye.
pub fn drag_to(camera: &Camera, anchor: DVec3, at: DVec2) -> Option<DVec3> {
    let (eye, dir) = ray(camera, at)?;
    let (_, _, forward) = camera.basis();
    let denom = dir.dot(forward);
    let t = (anchor - eye).dot(forward) / denom;
    (t.is_finite() && t > 0.0).then(|| eye + dir * t)
}

/// The position of a grabbed origin dragged from `start_px` (where the press began, the
/// origin then at `start_world`) to `at`: the origin moves with the pointer in the plane
/// facing the camera (the offset between pointer and origin kept).
pub fn dragged_origin(
    camera: &Camera,
    start_world: DVec3,
    start_px: DVec2,
    at: DVec2,
) -> Option<DVec3> {
    let grabbed = drag_to(camera, start_world, start_px)?;
    let now = drag_to(camera, start_world, at)?;
    Some(start_world + (now - grabbed))
}

/// Frame `which`'s x, y, z after a drag, as field texts rounded to the millimetre.
pub fn position_texts(p: DVec3) -> [String; 3] {
    [p.x, p.y, p.z].map(mm_text)
}

/// Metres rounded to the millimetre, without trailing zeros (`0.1`, `-0.025`, `0`).
pub fn mm_text(v: f64) -> String {
    let mut text = crate::view::signal::snap(v, 0.001);
    if text.contains('.') {
        while text.ends_with('0') {
            text.pop();
        }
        if text.ends_with('.') {
            text.pop();
        }
    }
    text
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::camera3d::Preset;

    #[test]
    fn degrees_round_trip_and_keep_untouched_radians() {
        assert_eq!(deg_text(30.0), "30");
        assert_eq!(deg_text(-0.0), "0");
        assert_eq!(deg_text(0.2f64.to_degrees()), "11.4591559026");
        assert_eq!(rad_to_deg_text("0.5235987755982988"), "30");
        assert_eq!(deg_to_rad_text("30"), "0.5235987755982988");
        assert_eq!(deg_to_rad_text("abc"), "abc", "errors stay the user's text");
        assert_eq!(rad_to_deg_text("inf"), "inf");
        // Shown in degrees, typed in degrees, kept in radians.
        let mut f = PoseFields::new(AngleUnit::Deg);
        assert_eq!(f.shown(9), "11.4591559026", "B roll 0.2 rad");
        assert_eq!(f.shown(6), "0.1", "positions are metres in both units");
        f.set_shown(3, "90");
        assert_eq!(f.recipe_text(3), "1.5707963267948966");
        assert_eq!(f.shown(3), "90");
        // Switching units never changes a value nobody typed.
        f.unit = AngleUnit::Rad;
        assert_eq!(f.shown(9), "0.2");
        f.unit = AngleUnit::Deg;
        f.unit = AngleUnit::Rad;
        assert_eq!(f.recipe_text(9), "0.2");
        // Any number of degrees round-trips through the field to within rounding.
        for k in -720..=720 {
            let deg = f64::from(k) * 0.5;
            let rad: f64 = deg_to_rad_text(&deg_text(deg)).parse().unwrap();
            assert!((rad - deg.to_radians()).abs() < 1e-15, "{deg}");
            assert_eq!(rad_to_deg_text(&py_float(rad)), deg_text(deg), "{deg}");
        }
    }

    #[test]
    fn url_holds_radians_and_the_unit() {
        let q = |pairs: &[(&str, &str)]| -> Vec<(String, String)> {
            pairs
                .iter()
                .map(|(k, v)| (k.to_string(), v.to_string()))
                .collect()
        };
        let (f, ignored) = PoseFields::read(&q(&[
            ("ax", "0.3"),
            ("bw", "1.2"),
            ("angles", "deg"),
            ("view", "top"),
            ("zz", "1"),
        ]));
        assert_eq!(f.unit, AngleUnit::Deg);
        assert_eq!(f.recipe_text(0), "0.3");
        assert_eq!(f.recipe_text(11), "1.2");
        assert_eq!(f.recipe_text(6), "0.1", "default");
        assert_eq!(ignored, vec![IgnoredKey::unknown("zz")]);
        assert_eq!(
            f.write(),
            q(&[("ax", "0.3"), ("bw", "1.2"), ("angles", "deg")])
        );
        let (_, bad) = PoseFields::read(&q(&[("angles", "grad")]));
        assert_eq!(bad, vec![IgnoredKey::invalid("angles")]);
        // Defaults write nothing; a typed default is not written either.
        let mut d = PoseFields::new(AngleUnit::Rad);
        assert!(d.write().is_empty());
        d.set_shown(6, " 0.1 ");
        assert!(d.write().is_empty());
        let mut g = PoseFields::new(AngleUnit::Deg);
        g.set_shown(10, "45");
        assert_eq!(
            g.write(),
            q(&[("bp", "0.7853981633974483"), ("angles", "deg")])
        );
    }

    #[test]
    fn matrices_print_without_negative_zero() {
        assert_eq!(entry_text(-0.00001, 4), "0.0000");
        assert_eq!(entry_text(-0.5, 4), "-0.5000");
        let m = Matrix4::identity();
        assert_eq!(matrix_rows(&m, 3)[0], ["1.000", "0.000", "0.000", "0.000"]);
    }

    #[test]
    fn solve_matches_the_recipe_and_composes_back() {
        let solved = solve(&Se3Params::default());
        let out = crate::recipes::se3_relative::run(&Se3Params::default()).unwrap();
        assert_eq!(solved.rel, Se3Params::default().relative().unwrap());
        assert!(out.summary.contains("0.1000,0.0500,0.0200"));
        assert!(solved.check_error < 1e-15, "{}", solved.check_error);
        let params = Se3Params {
            a: Pose::from_array([0.4, -0.1, 0.25, -0.7, 0.3, 2.0]),
            b: Pose::from_array([-0.2, 0.5, 0.05, 0.1, -1.1, -2.5]),
        };
        let s = solve(&params);
        assert!(s.check_error < 1e-14);
        // The path along A's axes by the relative translation ends at B's origin.
        let end = path_in_a(&s)[3];
        assert!(
            (end - DVec3::new(-0.2, 0.5, 0.05)).length() < 1e-14,
            "{end}"
        );
    }

    #[test]
    fn the_recipes_rpy_is_extrinsic_xyz_and_intrinsic_zyx() {
        let (r, p, y) = (0.2, 0.1, -0.3);
        let recipe = rpy_to_rotation(r, p, y);
        let ex = extrinsic(&[(Axis::X, r), (Axis::Y, p), (Axis::Z, y)]);
        let inz = intrinsic(&[(Axis::Z, y), (Axis::Y, p), (Axis::X, r)]);
        assert!(max_abs_diff3(&recipe, &ex) < 1e-15);
        assert!(max_abs_diff3(&recipe, &inz) < 1e-15);
        let other = rpy_readings(r, p, y).intrinsic_xyz;
        assert!(
            max_abs_diff3(&recipe, &other) > 1e-2,
            "intrinsic x-y-z is another rotation"
        );
    }

    fn camera() -> Camera {
        Camera::framing(DVec3::ZERO, 0.2, Preset::Iso, 640.0, 480.0)
    }

    #[test]
    fn gizmo_hits_the_frame_origins() {
        let c = camera();
        let params = Se3Params::default();
        let a = c.project(DVec3::ZERO).unwrap().at;
        let b = c.project(DVec3::new(0.1, 0.05, 0.02)).unwrap().at;
        assert_eq!(hit_frame(&c, &params, a, 10.0), Some(Grab::A));
        assert_eq!(
            hit_frame(&c, &params, b + DVec2::new(4.0, -3.0), 10.0),
            Some(Grab::B)
        );
        assert_eq!(
            hit_frame(&c, &params, (a + b) / 2.0 + DVec2::new(0.0, 200.0), 10.0),
            None
        );
        // Both under the cursor: the nearer on screen wins.
        let same = Se3Params {
            b: Pose::default(),
            ..params
        };
        assert_eq!(
            hit_frame(&c, &same, a + DVec2::new(1.0, 0.0), 10.0),
            Some(Grab::A)
        );
    }

    #[test]
    fn a_dragged_origin_follows_the_pointer_exactly() {
        let c = camera();
        let start = DVec3::new(0.1, 0.05, 0.02);
        let start_px = c.project(start).unwrap().at + DVec2::new(3.0, 2.0);
        for d in [
            DVec2::new(40.0, -25.0),
            DVec2::new(-120.0, 80.0),
            DVec2::ZERO,
        ] {
            let moved = dragged_origin(&c, start, start_px, start_px + d).unwrap();
            let (_, _, forward) = c.basis();
            assert!(
                (moved - start).dot(forward).abs() < 1e-12,
                "stays in the view plane"
            );
            let seen = c.project(moved).unwrap().at - c.project(start).unwrap().at;
            assert!((seen - d).length() < 1e-9, "{seen} vs {d}");
        }
        assert_eq!(
            position_texts(DVec3::new(0.12345, -0.0004, 1.0)),
            ["0.123", "0", "1"]
        );
    }

    #[test]
    fn yaw_rings_turn_a_frame_about_the_vertical_only() {
        let c = camera();
        let params = Se3Params::default();
        let b = DVec3::new(0.1, 0.05, 0.02);
        let ring = ring_radius(0.2);
        // A point of B's ring (away from both origins) grabs B's ring; its angle is read back.
        let t: f64 = 2.0;
        let on_ring = b + DVec3::new(t.cos(), t.sin(), 0.0) * ring;
        let px = c.project(on_ring).unwrap().at;
        assert_eq!(hit_gizmo(&c, &params, ring, px, 8.0), Some(Grab::YawB));
        assert!((yaw_at(&c, b, px).unwrap() - t).abs() < 1e-9);
        // Origins come first; empty space grabs nothing.
        let pb = c.project(b).unwrap().at;
        assert_eq!(hit_gizmo(&c, &params, ring, pb, 8.0), Some(Grab::B));
        assert_eq!(
            hit_gizmo(&c, &params, ring, DVec2::new(5.0, 5.0), 8.0),
            None
        );
        // Turning about the world's z axis changes the recipe's yaw alone: Rz(Δ) R(r, p, y)
        // = R(r, p, y + Δ).
        let r = rpy_to_rotation(0.2, 0.1, -0.3);
        let turned = extrinsic(&[(Axis::Z, 0.7)]) * r;
        assert!(max_abs_diff3(&turned, &rpy_to_rotation(0.2, 0.1, 0.4)) < 1e-15);
        // Seen exactly from the side, the ray runs along the plane: no angle.
        let side = Camera::framing(DVec3::ZERO, 0.2, Preset::Front, 640.0, 480.0);
        assert_eq!(yaw_at(&side, DVec3::ZERO, DVec2::new(320.0, 240.0)), None);
    }

    #[test]
    fn wrapped_angles_and_yaw_texts() {
        use std::f64::consts::PI;
        assert!((wrap_angle(3.0 * PI / 2.0) + PI / 2.0).abs() < 1e-15);
        assert_eq!(wrap_angle(-PI), PI);
        assert_eq!(wrap_angle(0.25), 0.25);
        assert_eq!(yaw_text(0.12345, AngleUnit::Rad), "0.123");
        assert_eq!(
            yaw_text(30.04f64.to_radians(), AngleUnit::Deg),
            deg_to_rad_text("30")
        );
        assert_eq!(rad_to_deg_text(&yaw_text(-0.5, AngleUnit::Deg)), "-28.6");
    }

    #[test]
    fn the_scene_frame_holds_every_origin() {
        let (centre, radius) = scene_frame(&Se3Params::default());
        assert!((centre - DVec3::new(0.05, 0.025, 0.01)).length() < 1e-15);
        assert!((radius - 0.0129f64.sqrt() / 2.0 * 1.3).abs() < 1e-12);
        let huge = Se3Params {
            a: Pose::from_array([1e300, 1e300, 0.0, 0.0, 0.0, 0.0]),
            ..Se3Params::default()
        };
        assert_eq!(scene_frame(&huge), (DVec3::ZERO, MAX_SCENE_RADIUS));
        let same = Se3Params {
            a: Pose::default(),
            b: Pose::default(),
        };
        let (c, r) = scene_frame(&same);
        assert!(c == DVec3::ZERO && (r - 0.065).abs() < 1e-15);
    }

    #[cfg(not(target_arch = "wasm32"))]
    mod properties {
        use super::super::*;
        use proptest::prelude::*;

        fn axis() -> impl Strategy<Value = Axis> {
            prop_oneof![Just(Axis::X), Just(Axis::Y), Just(Axis::Z)]
        }

        proptest! {
            /// Turning about the moving axes in one order is turning about the fixed axes in
            /// the reverse order.
            #[test]
            fn intrinsic_is_extrinsic_reversed(
                steps in proptest::collection::vec((axis(), -7.0..7.0f64), 0..6)
            ) {
                let mut reversed = steps.clone();
                reversed.reverse();
                let err = max_abs_diff3(&intrinsic(&steps), &extrinsic(&reversed));
                prop_assert!(err < 1e-12, "{err}");
            }

            /// The recipe's R = Rz Ry Rx is extrinsic x → y → z and intrinsic z → y′ → x″.
            #[test]
            fn recipe_convention(
                roll in -7.0..7.0f64, pitch in -7.0..7.0f64, yaw in -7.0..7.0f64,
            ) {
                let recipe = rpy_to_rotation(roll, pitch, yaw);
                let ex = extrinsic(&[(Axis::X, roll), (Axis::Y, pitch), (Axis::Z, yaw)]);
                let inz = intrinsic(&[(Axis::Z, yaw), (Axis::Y, pitch), (Axis::X, roll)]);
                prop_assert!(max_abs_diff3(&recipe, &ex) < 1e-12);
                prop_assert!(max_abs_diff3(&recipe, &inz) < 1e-12);
                // And intrinsic x → y′ → z″ is Rx Ry Rz.
                let xyz = rpy_readings(roll, pitch, yaw).intrinsic_xyz;
                let rx = extrinsic(&[(Axis::X, roll)]);
                let ry = extrinsic(&[(Axis::Y, pitch)]);
                let rz = extrinsic(&[(Axis::Z, yaw)]);
                prop_assert!(max_abs_diff3(&xyz, &(rx * ry * rz)) < 1e-12);
            }

            /// Degrees typed and shown again read the same; radians never drift.
            #[test]
            fn deg_rad_round_trip(deg in -1e4..1e4f64) {
                let shown = deg_text(deg);
                let rad: f64 = deg_to_rad_text(&shown).parse().unwrap();
                prop_assert!((rad.to_degrees() - deg).abs() < 1e-9);
                prop_assert_eq!(rad_to_deg_text(&py_float(rad)), shown);
            }

            /// T_A (T_A⁻¹ T_B) = T_B.
            #[test]
            fn composition_check(
                a in proptest::array::uniform6(-5.0..5.0f64),
                b in proptest::array::uniform6(-5.0..5.0f64),
            ) {
                let s = solve(&Se3Params { a: Pose::from_array(a), b: Pose::from_array(b) });
                prop_assert!(s.check_error < 1e-12, "{}", s.check_error);
            }
        }
    }
}
