//! The SO-101 page's pure view model (`#/so101`): the 3D scene (the arm as its
//! [`PARTS`], boxes around the collision meshes of each body drawn as shaded solids; the
//! table's grid, the cube, the goal square, the obstacle, the tool frame), the wrist camera
//! (on the gripper behind the fingers, looking along the approach: the fixed finger below, the
//! table and the cube ahead), the clutch gizmo on the tool (three translation arrows and three
//! rotation rings, roll about x, pitch about y, yaw about z: a press on one is a handle,
//! dragging it commands motion along or about that axis only while held) and the readout
//! texts.

use crate::math;
use glam::{DMat3, DVec2, DVec3};

use crate::camera3d::{hit_point, Camera};
use crate::numtext::fixed_minus;
use crate::so101::kinematics::{Chain, Frame};
use crate::so101::model::{joint_limits, FIXED_FINGER, PARTS};
use crate::so101::scene::{obstacle_box, Obb, SceneConfig, GOAL_HALF, TABLE_Z};
use crate::teleop::control::IkMethod;
use crate::view::scene3d::{AxisPalette, Layer, Scene, Shape3, Stroke};

/// The point the world view looks at and the radius it frames, m.
pub const VIEW_TARGET: [f64; 3] = [0.13, 0.02, 0.085];
/// See [`VIEW_TARGET`].
pub const VIEW_RADIUS: f64 = 0.215;
/// The azimuth the world view's iso preset looks from, rad: from the front right (−30°,
/// the cube's side), so that at the start the cube stands in front of the gripper and the
/// goal beyond it, both clear of the gizmo.
pub const VIEW_AZIMUTH: f64 = -std::f64::consts::FRAC_PI_6;
/// Gizmo arrow length, m.
pub const GIZMO_M: f64 = 0.06;
/// Rotation ring radius, m.
pub const RING_M: f64 = 0.045;
/// Points on each rotation ring.
pub const RING_POINTS: usize = 24;
/// Hit radius of a gizmo handle, CSS px (a 44 px target).
pub const HIT_PX: f64 = 22.0;
/// Screen distance of a drag that commands full speed, px.
pub const FULL_DRAG_PX: f64 = 60.0;

/// A solid's three shades (lit, side, shadow) by how squarely a face meets the light. The
/// arm, its base and the wall let a little of what is behind them through (the cube stays
/// in sight behind the gripper); the cube is opaque.
type Shades = [&'static str; 3];
const LINK: Shades = [
    "rgba(227, 172, 92, 0.82)",
    "rgba(183, 121, 31, 0.82)",
    "rgba(122, 79, 18, 0.82)",
];
const BASE: Shades = [
    "rgba(176, 182, 192, 0.82)",
    "rgba(107, 114, 128, 0.82)",
    "rgba(71, 76, 86, 0.82)",
];
const JAW: Shades = [
    "rgba(200, 105, 58, 0.82)",
    "rgba(146, 64, 14, 0.82)",
    "rgba(95, 42, 9, 0.82)",
];
const CUBE: Shades = ["#56a8dc", "#0072b2", "#004d78"];
const WALL: Shades = [
    "rgba(243, 148, 73, 0.82)",
    "rgba(213, 94, 0, 0.82)",
    "rgba(154, 67, 0, 0.82)",
];
/// The cube's outline seen through what stands in front of it.
const CUBE_SEEN: Stroke = Stroke::dashed("#0072b2", 1.5);
/// The solids' edges.
const EDGE: &str = "rgba(15, 23, 42, 0.55)";
/// Where the light comes from (unit: above, in front and to the side of the arm).
const LIGHT: [f64; 3] = [0.408, -0.302, 0.862];
/// The fingers as the wrist camera sees them, close in front of it: light enough to show
/// the table through.
const FINGER_SEEN: Shades = [
    "rgba(200, 105, 58, 0.4)",
    "rgba(146, 64, 14, 0.4)",
    "rgba(95, 42, 9, 0.4)",
];
const GOAL: Stroke = Stroke::solid("#009e73", 3.0);
const TABLE: Stroke = Stroke::solid("#cbd5e1", 1.0);

/// A gizmo handle: a translation arrow or a rotation ring, about world axis 0 (x, roll),
/// 1 (y, pitch) or 2 (z, yaw).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Handle {
    /// Along world axis 0, 1 or 2.
    Axis(usize),
    /// About world axis 0, 1 or 2.
    Turn(usize),
}

/// What the world view shows.
pub struct Look<'a> {
    /// The arm's frames.
    pub chain: &'a Chain,
    /// The cube's box.
    pub cube: Obb,
    /// The goal square's centre.
    pub goal: [f64; 2],
    /// Whether the wall stands.
    pub obstacle: bool,
    /// Draw the gizmo (live control, not a replay).
    pub gizmo: bool,
    /// The handle held or hovered.
    pub active: Option<Handle>,
}

fn v(p: &[f64; 3]) -> DVec3 {
    DVec3::from_array(*p)
}

fn rot(f: &Frame) -> DMat3 {
    let r = &f.rot;
    DMat3::from_cols(
        DVec3::new(r[0][0], r[1][0], r[2][0]),
        DVec3::new(r[0][1], r[1][1], r[2][1]),
        DVec3::new(r[0][2], r[1][2], r[2][2]),
    )
}

/// A box as six shaded faces (each face's shade from its outward normal against
/// `LIGHT`; the view leaves out the faces turned away and paints the farther boxes first).
pub fn box_faces(scene: &mut Scene, b: &Obb, shades: Shades) {
    let c = b.corners();
    // Corner k has bit 0, 1, 2 set on the + side of the box's x, y, z axis; each face's
    // corners go counter-clockwise seen from outside.
    for (axis, bit, others) in [(0, 1, [2, 4]), (1, 2, [4, 1]), (2, 4, [1, 2])] {
        for side in [0, bit] {
            let [u, w] = if side == 0 {
                [others[1], others[0]]
            } else {
                others
            };
            let idx = [side, side | u, side | u | w, side | w];
            let sign = if side == 0 { -1.0 } else { 1.0 };
            let normal = DVec3::new(b.rot[0][axis], b.rot[1][axis], b.rot[2][axis]) * sign;
            let lit = normal.dot(DVec3::from(LIGHT));
            let shade = if lit > 0.6 {
                shades[0]
            } else if lit > 0.0 {
                shades[1]
            } else {
                shades[2]
            };
            scene.push(
                Layer::Scene,
                Shape3::Quad {
                    corners: idx.map(|i| v(&c[i])),
                    edge: EDGE,
                    sort: v(&b.centre),
                },
                Stroke::solid(shade, 1.0),
            );
        }
    }
}

/// A square outline on the table.
fn square(scene: &mut Scene, centre: [f64; 2], half: f64, stroke: Stroke) {
    let z = TABLE_Z + 0.0005;
    let p = |sx: f64, sy: f64| DVec3::new(centre[0] + sx * half, centre[1] + sy * half, z);
    let corners = [p(-1.0, -1.0), p(1.0, -1.0), p(1.0, 1.0), p(-1.0, 1.0)];
    for k in 0..4 {
        scene.push(
            Layer::Ground,
            Shape3::Line {
                a: corners[k],
                b: corners[(k + 1) % 4],
            },
            stroke,
        );
    }
}

/// The table's grid: a cell's side, m.
pub const TABLE_CELL_M: f64 = 0.05;
/// The table's grid: cells on a side, about the base (the arm's reach, the cube and the goal).
pub const TABLE_CELLS: usize = 14;

/// The twelve edges of a box, in `layer`.
fn box_edges(scene: &mut Scene, b: &Obb, stroke: Stroke, layer: Layer) {
    let c = b.corners();
    for (i, j) in [
        (0, 1),
        (2, 3),
        (4, 5),
        (6, 7),
        (0, 2),
        (1, 3),
        (4, 6),
        (5, 7),
        (0, 4),
        (1, 5),
        (2, 6),
        (3, 7),
    ] {
        scene.push(
            layer,
            Shape3::Line {
                a: v(&c[i]),
                b: v(&c[j]),
            },
            stroke,
        );
    }
}

/// The boxes of the drawn parts ([`PARTS`]) at `chain`, each with its body (0 the base, 6
/// the moving jaw).
pub fn part_boxes(chain: &Chain) -> impl Iterator<Item = (usize, Obb)> + '_ {
    PARTS.iter().map(|p| {
        let frame = if p.body == 6 {
            &chain.jaw
        } else {
            &chain.bodies[usize::from(p.body)]
        };
        let (centre, half) = (p.centre.map(f64::from), p.half.map(f64::from));
        (usize::from(p.body), Obb::of(frame, &centre, &half))
    })
}

/// The arm, the cube and the wall (what both views show over the ground; the wrist camera,
/// mounted on the gripper, sees of the arm only the fingers).
fn things(scene: &mut Scene, look: &Look, wrist: bool) {
    if look.obstacle {
        box_faces(scene, &obstacle_box(), WALL);
    }
    for (i, (body, b)) in part_boxes(look.chain).enumerate() {
        if wrist && body != 6 && i != FIXED_FINGER {
            continue;
        }
        let shades = match body {
            0 => BASE,
            _ if wrist => FINGER_SEEN,
            5 | 6 => JAW,
            _ => LINK,
        };
        box_faces(scene, &b, shades);
    }
    box_faces(scene, &look.cube, CUBE);
    // The cube's outline over everything: it stays in sight behind the gripper.
    box_edges(scene, &look.cube, CUBE_SEEN, Layer::Overlay);
}

/// The ground: the table's grid and the goal square (in the world view, what stays while
/// the arm moves: the page draws it under the rest, again only when the view turns).
pub fn ground(scene: &mut Scene, goal: [f64; 2]) {
    scene.clear();
    scene.grid(TABLE_CELLS, TABLE_CELL_M, TABLE);
    square(scene, goal, GOAL_HALF, GOAL);
}

/// The world view's scene over the [`ground`].
pub fn world(scene: &mut Scene, look: &Look, palette: AxisPalette) {
    scene.clear();
    things(scene, look, false);
    let tool = &look.chain.tool;
    scene.triad(v(&tool.pos), rot(tool), 0.035, palette, 2.0, None);
    if look.gizmo {
        gizmo(scene, v(&tool.pos), look.active, palette);
    }
}

/// The wrist camera's scene: the ground and what stands on it (no gizmo).
pub fn wrist(scene: &mut Scene, look: &Look) {
    ground(scene, look.goal);
    things(scene, look, true);
}

fn gizmo(scene: &mut Scene, at: DVec3, active: Option<Handle>, palette: AxisPalette) {
    let colors = palette.colors();
    for (k, color) in colors.iter().enumerate() {
        let width = if active == Some(Handle::Axis(k)) {
            5.0
        } else {
            3.0
        };
        scene.push(
            Layer::Overlay,
            Shape3::Arrow {
                a: at,
                b: at + axis(k) * GIZMO_M,
            },
            Stroke::solid(color, width),
        );
    }
    for (k, color) in colors.iter().enumerate() {
        let width = if active == Some(Handle::Turn(k)) {
            4.5
        } else {
            2.0
        };
        let ring = ring_points(at, k);
        for i in 0..RING_POINTS {
            scene.push(
                Layer::Overlay,
                Shape3::Line {
                    a: ring[i],
                    b: ring[(i + 1) % RING_POINTS],
                },
                Stroke::solid(color, width),
            );
        }
    }
}

fn axis(k: usize) -> DVec3 {
    match k {
        0 => DVec3::X,
        1 => DVec3::Y,
        _ => DVec3::Z,
    }
}

/// The points of the ring about world axis `k` (0 x, 1 y, 2 z) centred on `at`, counter-
/// clockwise seen from the axis's + side.
pub fn ring_points(at: DVec3, k: usize) -> Vec<DVec3> {
    let (u, v) = (axis((k + 1) % 3), axis((k + 2) % 3));
    (0..RING_POINTS)
        .map(|i| {
            let a = std::f64::consts::TAU * i as f64 / RING_POINTS as f64;
            let (sin, cos) = math::sincos(a);
            at + (u * cos + v * sin) * RING_M
        })
        .collect()
}

/// Distance from `p` to the segment `a`–`b`, px.
fn segment_distance(p: DVec2, a: DVec2, b: DVec2) -> f64 {
    let ab = b - a;
    let t = if ab.length_squared() > 0.0 {
        ((p - a).dot(ab) / ab.length_squared()).clamp(0.0, 1.0)
    } else {
        0.0
    };
    p.distance(a + ab * t)
}

/// The handle under `cursor` (CSS px): an arrow's tip or middle first, then the nearest ring
/// (each within [`HIT_PX`] of its drawn line: a 44 px target).
pub fn handle_at(camera: &Camera, tool: DVec3, cursor: DVec2) -> Option<Handle> {
    let mut points = Vec::new();
    for k in 0..3 {
        points.push(camera.project(tool + axis(k) * GIZMO_M));
        points.push(camera.project(tool + axis(k) * GIZMO_M * 0.6));
    }
    if let Some(i) = hit_point(&points, cursor, HIT_PX) {
        return Some(Handle::Axis(i / 2));
    }
    let mut best: Option<(usize, f64)> = None;
    for k in 0..3 {
        let ring: Vec<_> = ring_points(tool, k)
            .iter()
            .map(|p| camera.project(*p))
            .collect();
        for i in 0..RING_POINTS {
            let (Some(a), Some(b)) = (&ring[i], &ring[(i + 1) % RING_POINTS]) else {
                continue;
            };
            let d = segment_distance(cursor, a.at, b.at);
            if d <= HIT_PX && best.is_none_or(|(_, bd)| d < bd) {
                best = Some((k, d));
            }
        }
    }
    best.map(|(k, _)| Handle::Turn(k))
}

/// For each ring (about x, y, z): a point of it on screen that only that ring takes (where it
/// runs longest on screen) and the unit screen direction of a positive turn there; `None`
/// where no such point is in view. The page writes them on the canvas
/// (`data-ring-grips`) for its tests.
pub fn ring_grips(camera: &Camera, tool: DVec3) -> [Option<(DVec2, DVec2)>; 3] {
    std::array::from_fn(|k| {
        let ring: Vec<_> = ring_points(tool, k)
            .iter()
            .map(|p| camera.project(*p))
            .collect();
        // The ring's segments, longest on screen first; the first one only it takes.
        let mut segments: Vec<(f64, DVec2, DVec2)> = (0..RING_POINTS)
            .filter_map(|i| {
                let (Some(a), Some(b)) = (&ring[i], &ring[(i + 1) % RING_POINTS]) else {
                    return None;
                };
                let step = b.at - a.at;
                let len = step.length();
                (len >= 1.0).then(|| (len, a.at + step / 2.0, step / len))
            })
            .collect();
        while let Some(i) =
            (0..segments.len()).reduce(|a, b| if segments[b].0 > segments[a].0 { b } else { a })
        {
            let (_, mid, dir) = segments.swap_remove(i);
            if handle_at(camera, tool, mid) == Some(Handle::Turn(k)) {
                return Some((mid, dir));
            }
        }
        None
    })
}

/// The command axes of a drag of `handle` from `start` to `now` (CSS px) with the tool at
/// `tool`: along the arrow's screen direction (full speed at [`FULL_DRAG_PX`]), or around the
/// ring's centre for a turn (counter-clockwise on screen is a positive turn when the camera
/// looks at the ring from its axis's + side; full speed at half a radian).
pub fn drag_axes(
    camera: &Camera,
    handle: Handle,
    tool: DVec3,
    start: DVec2,
    now: DVec2,
) -> [f64; 6] {
    let mut out = [0.0; 6];
    let Some(c) = camera.project(tool) else {
        return out;
    };
    match handle {
        Handle::Axis(k) => {
            let Some(tip) = camera.project(tool + axis(k) * GIZMO_M) else {
                return out;
            };
            let dir = tip.at - c.at;
            let len = dir.length();
            if len < 1.0 {
                return out;
            }
            let along = (now - start).dot(dir / len);
            out[k] = (along / FULL_DRAG_PX).clamp(-1.0, 1.0);
        }
        Handle::Turn(k) => {
            let (a, b) = (start - c.at, now - c.at);
            if a.length() < 1.0 || b.length() < 1.0 {
                return out;
            }
            // Screen y points down: a clockwise turn on screen is a positive angle here.
            let turn = math::atan2(a.x * b.y - a.y * b.x, a.dot(b));
            let from_plus = (camera.eye() - tool).dot(axis(k)) >= 0.0;
            let sign = if from_plus { -1.0 } else { 1.0 };
            out[3 + k.min(2)] = (sign * turn / 0.5).clamp(-1.0, 1.0);
        }
    }
    out
}

/// The world view's camera at its start (the iso preset from [`VIEW_AZIMUTH`]),
/// `width`×`height` CSS px.
pub fn world_camera(width: f64, height: f64) -> Camera {
    Camera {
        azimuth: VIEW_AZIMUTH,
        ..Camera::framing(
            DVec3::from_array(VIEW_TARGET),
            VIEW_RADIUS,
            crate::camera3d::Preset::Iso,
            width,
            height,
        )
    }
}

/// The wrist camera's eye in the tool frame, m: behind the fingers, looking along the
/// approach axis (x) from 3 cm towards the side the jaw opens to (z), so the fixed finger
/// shows in the lower part of the image, the moving jaw above it, open or closed, and the
/// table and the cube ahead. Looking along the axis wrist_roll turns about, the image turns
/// with the wrist.
pub const WRIST_EYE: [f64; 3] = [-0.14, 0.0, 0.03];
/// The point the wrist camera looks at, in the tool frame, m: past the finger tips.
pub const WRIST_AIM: [f64; 3] = [0.04, 0.0, 0.03];
/// The wrist camera's vertical field of view, degrees.
pub const WRIST_FOV_DEG: f64 = 80.0;

/// The wrist camera: from [`WRIST_EYE`] towards [`WRIST_AIM`] on the tool,
/// `width`×`height` CSS px, [`WRIST_FOV_DEG`] vertical field of view.
pub fn wrist_camera(chain: &Chain, width: f64, height: f64) -> Camera {
    let t = &chain.tool;
    let r = rot(t);
    let eye = v(&t.pos) + r * DVec3::from(WRIST_EYE);
    let target = v(&t.pos) + r * DVec3::from(WRIST_AIM);
    let back = eye - target;
    let distance = back.length();
    let back = back / distance;
    let elevation =
        math::asin(back.z.clamp(-1.0, 1.0)).clamp(-Camera::MAX_ELEVATION, Camera::MAX_ELEVATION);
    let azimuth = math::atan2(back.y, back.x);
    Camera {
        target,
        azimuth,
        elevation,
        distance,
        fov_y: WRIST_FOV_DEG.to_radians(),
        width,
        height,
    }
}

/// The settings' keys, in the URL and as the form's `data-field`s.
pub const SETTING_KEYS: [&str; 6] = [
    "ik",
    "latency_ms",
    "noise",
    "pos_sensitivity",
    "rot_sensitivity",
    "obstacle",
];

/// `config` with each setting of `pairs` (by [`SETTING_KEYS`]) that reads and keeps the
/// configuration valid; the others (other keys, unreadable or refused values) leave it as it
/// was. The latency is in ms, rounded to whole 10 ms steps.
pub fn apply_settings(config: &SceneConfig, pairs: &[(String, String)]) -> SceneConfig {
    let mut out = config.clone();
    for (key, value) in pairs {
        let value = value.trim();
        let number = value.parse::<f64>().ok().filter(|v| v.is_finite());
        let mut next = out.clone();
        let read = match (key.as_str(), number) {
            ("ik", _) => match IkMethod::from_id(value) {
                Some(m) => {
                    next.control.method = m;
                    true
                }
                None => false,
            },
            ("latency_ms", Some(ms)) if (0.0..=10_000.0).contains(&ms) => {
                next.latency_steps = (ms / 10.0).round() as u32;
                true
            }
            ("noise", Some(v)) => {
                next.noise_sigma = v;
                true
            }
            ("pos_sensitivity", Some(v)) => {
                next.pos_sensitivity = v;
                true
            }
            ("rot_sensitivity", Some(v)) => {
                next.rot_sensitivity = v;
                true
            }
            ("obstacle", _) => match value {
                "true" | "1" | "yes" => {
                    next.obstacle = true;
                    true
                }
                "false" | "0" | "no" => {
                    next.obstacle = false;
                    true
                }
                _ => false,
            },
            _ => false,
        };
        if read && next.validate().is_ok() {
            out = next;
        }
    }
    out
}

/// The settings of `config` as texts, by [`SETTING_KEYS`] (what [`apply_settings`] reads).
pub fn settings_texts(config: &SceneConfig) -> Vec<(&'static str, String)> {
    vec![
        ("ik", config.control.method.id().to_string()),
        ("latency_ms", (config.latency_steps * 10).to_string()),
        ("noise", config.noise_sigma.to_string()),
        ("pos_sensitivity", config.pos_sensitivity.to_string()),
        ("rot_sensitivity", config.rot_sensitivity.to_string()),
        ("obstacle", config.obstacle.to_string()),
    ]
}

/// The wrist camera's image as drawn: a square camera of the `width`×`height` image's
/// diagonal at the same scale (so that turning it leaves no corner empty), and the angle
/// (rad, counter-clockwise on screen) to turn it by about the image's centre so that the
/// tool's z axis (ahead of the gripper, away from the base at the start pose) points up: the
/// image rolls with the tool, wrist_roll included, as a camera on the wrist does.
pub fn wrist_view(chain: &Chain, width: f64, height: f64) -> (Camera, f64) {
    let base = wrist_camera(chain, width, height);
    let side = (width * width + height * height).sqrt();
    let fov_y = 2.0 * math::atan(math::tan(base.fov_y / 2.0) * side / height.max(1.0));
    let camera = Camera {
        fov_y,
        width: side,
        height: side,
        ..base
    };
    let t = &chain.tool;
    let ahead_up = DVec3::new(t.rot[0][2], t.rot[1][2], t.rot[2][2]);
    let (right, up, _) = camera.basis();
    let roll = math::atan2(ahead_up.dot(right), ahead_up.dot(up));
    (camera, roll)
}

/// A joint's limits as the readouts show them, `"−110.0 … 110.0"` (degrees).
pub fn joint_limits_text(i: usize) -> String {
    let (lo, hi) = joint_limits()[i.min(4)];
    format!("{} … {}", deg(lo), deg(hi))
}

/// The manipulability as the readouts show it, `"7.03e-3"` (never a negative zero).
pub fn manipulability_text(m: f64) -> String {
    crate::numtext::unsigned_zero(format!("{m:.2e}"))
}

/// Millimetres with one decimal, `"123.4"` (minus sign as typeset).
pub fn mm(m: f64) -> String {
    fixed_minus(m * 1000.0, 1)
}

/// Degrees with one decimal (minus sign as typeset).
pub fn deg(rad: f64) -> String {
    fixed_minus(rad.to_degrees(), 1)
}

#[cfg(test)]
mod tests {
    #[cfg(target_arch = "wasm32")]
    use wasm_bindgen_test::wasm_bindgen_test as test;

    use super::*;
    use crate::so101::scene::{JAW_CLOSED, JAW_HOLDING, JAW_OPEN};
    use crate::so101::{SceneConfig, Sim};

    /// The moving jaw's finger among [`PARTS`].
    const MOVING_FINGER: usize = 17;

    fn look_at(sim: &Sim) -> (Chain, Obb) {
        (sim.chain(), sim.state().cube.obb())
    }

    #[test]
    fn the_world_scene_has_every_box_and_the_gizmo() {
        let sim = Sim::new(SceneConfig::default_for(true)).unwrap();
        let (chain, cube) = look_at(&sim);
        let look = Look {
            chain: &chain,
            cube,
            goal: [0.22, 0.1],
            obstacle: true,
            gizmo: true,
            active: None,
        };
        let mut scene = Scene::new();
        // The ground: the table's grid (2 × 15 lines), the goal 4.
        ground(&mut scene, look.goal);
        assert_eq!(scene.len(), 2 * (TABLE_CELLS + 1) + 4);
        world(&mut scene, &look, AxisPalette::Classic);
        // The wall, the arm's parts and the cube as boxes of 6 faces, the cube's outline 12,
        // triad 3, gizmo 3 arrows + 3 rings of 24 segments.
        let boxes = 1 + PARTS.len() + 1;
        assert_eq!(scene.len(), boxes * 6 + 12 + 3 + 3 + 3 * RING_POINTS);
        let camera = world_camera(800.0, 500.0);
        assert!(!scene.project(&camera).is_empty());
    }

    #[test]
    fn the_start_view_shows_the_cube_and_the_goal_clear_of_the_gizmo() {
        let config = SceneConfig::default_for(false);
        let sim = Sim::new(config.clone()).unwrap();
        let tool = DVec3::from_array(sim.chain().tool.pos);
        let camera = world_camera(760.0, 460.0);
        let at = |p: DVec3| camera.project(p).unwrap().at;
        let centre = at(tool);
        // The farthest any handle reaches on screen.
        let reach = (0..3)
            .flat_map(|k| {
                let ring = ring_points(tool, k);
                ring.into_iter()
                    .chain([tool + axis(k) * GIZMO_M])
                    .collect::<Vec<_>>()
            })
            .map(|p| at(p).distance(centre))
            .fold(0.0, f64::max);
        let cube = at(DVec3::from_array(sim.state().cube.pos));
        let [gx, gy] = config.goal;
        let goal = at(DVec3::new(gx, gy, TABLE_Z));
        // The cube's and the goal's centres beyond the gizmo's handles (the cube by more than
        // a handle's hit radius: a press on it orbits the view).
        assert!(
            cube.distance(centre) > reach + HIT_PX,
            "{cube:?} {centre:?} {reach}"
        );
        assert!(
            goal.distance(centre) > reach + 10.0,
            "{goal:?} {centre:?} {reach}"
        );
    }

    #[test]
    fn a_press_on_an_arrow_takes_it_and_dragging_it_commands_its_axis() {
        let sim = Sim::new(SceneConfig::default_for(false)).unwrap();
        let tool = DVec3::from_array(sim.chain().tool.pos);
        let camera = world_camera(800.0, 500.0);
        for k in 0..3 {
            let tip = camera.project(tool + axis(k) * GIZMO_M).unwrap().at;
            assert_eq!(handle_at(&camera, tool, tip), Some(Handle::Axis(k)));
            let c = camera.project(tool).unwrap().at;
            let dir = (tip - c).normalize();
            let a = drag_axes(&camera, Handle::Axis(k), tool, tip, tip + dir * 30.0);
            assert!((a[k] - 0.5).abs() < 1e-9, "{k}: {a:?}");
            assert_eq!(a.iter().filter(|x| **x != 0.0).count(), 1);
        }
        assert_eq!(handle_at(&camera, tool, DVec2::new(1.0, 1.0)), None);
    }

    #[test]
    fn each_ring_is_a_handle_and_turning_it_commands_its_axis_only() {
        let sim = Sim::new(SceneConfig::default_for(false)).unwrap();
        let tool = DVec3::from_array(sim.chain().tool.pos);
        let camera = world_camera(800.0, 500.0);
        let c = camera.project(tool).unwrap().at;
        for k in 0..3 {
            let (u, v) = (axis((k + 1) % 3), axis((k + 2) % 3));
            let point = |a: f64| tool + (u * a.cos() + v * a.sin()) * RING_M;
            // Where the rings cross on screen the nearest takes the press: most of each ring
            // is its own.
            let own: Vec<f64> = (0..48)
                .map(|i| std::f64::consts::TAU * i as f64 / 48.0)
                .filter(|a| {
                    let at = camera.project(point(*a)).unwrap().at;
                    handle_at(&camera, tool, at) == Some(Handle::Turn(k))
                })
                .collect();
            assert!(own.len() >= 20, "ring {k}: {} of 48", own.len());
            let a = own[own.len() / 2];
            let at = camera.project(point(a)).unwrap().at;
            // 20 px off the line still takes it (a 44 px target).
            let off = at + (at - c).normalize() * 20.0;
            assert!(handle_at(&camera, tool, off).is_some(), "ring {k} +20 px");
            // Dragging along the ring, in the direction of a positive turn, commands +turn.
            let ahead = tool + (u * (a + 0.3).cos() + v * (a + 0.3).sin()) * RING_M;
            let to = camera.project(ahead).unwrap().at;
            let out = drag_axes(&camera, Handle::Turn(k), tool, at, to);
            assert!(out[3 + k] > 0.0, "ring {k}: {out:?}");
            assert_eq!(out.iter().filter(|x| **x != 0.0).count(), 1, "{out:?}");
            let back = drag_axes(&camera, Handle::Turn(k), tool, to, at);
            assert!(back[3 + k] < 0.0, "ring {k}: {back:?}");
        }
    }

    #[test]
    fn each_ring_has_a_grip_that_turns_it_the_positive_way() {
        let sim = Sim::new(SceneConfig::default_for(false)).unwrap();
        let tool = DVec3::from_array(sim.chain().tool.pos);
        let camera = world_camera(800.0, 500.0);
        for (k, grip) in ring_grips(&camera, tool).iter().enumerate() {
            let (at, dir) = grip.expect("in view");
            assert_eq!(handle_at(&camera, tool, at), Some(Handle::Turn(k)));
            let out = drag_axes(&camera, Handle::Turn(k), tool, at, at + dir * 20.0);
            assert!(out[3 + k] > 0.0, "ring {k}: {out:?}");
        }
    }

    /// `p` as the 320×240 wrist image shows it: projected by `camera`, turned by `roll` about
    /// the image's centre.
    fn wrist_image_point(camera: &Camera, roll: f64, p: DVec3) -> Option<DVec2> {
        let at = camera.project(p)?.at - DVec2::splat(camera.width / 2.0);
        let (sin, cos) = roll.sin_cos();
        let turned = DVec2::new(at.x * cos + at.y * sin, -at.x * sin + at.y * cos);
        Some(turned + DVec2::new(160.0, 120.0))
    }

    #[test]
    fn the_wrist_camera_sees_the_fingers_and_the_cube_at_the_start_pose() {
        let sim = Sim::new(SceneConfig::default_for(false)).unwrap();
        let chain = sim.chain();
        let (camera, roll) = wrist_view(&chain, 320.0, 240.0);
        let shown = |p: DVec3| wrist_image_point(&camera, roll, p);
        let inside = |at: DVec2| (0.0..320.0).contains(&at.x) && (0.0..240.0).contains(&at.y);
        // The cube on the table ahead.
        let cube = shown(DVec3::from_array(sim.state().cube.pos)).unwrap();
        assert!(inside(cube), "{cube:?}");
        // The fixed finger, in the lower half.
        let (_, finger) = part_boxes(&chain).nth(FIXED_FINGER).unwrap();
        let finger = shown(v(&finger.centre)).unwrap();
        assert!(inside(finger) && finger.y > 120.0, "{finger:?}");
        // Both fingers whole in the image, the jaw open, holding or closed.
        for jaw in [JAW_OPEN, JAW_HOLDING, JAW_CLOSED] {
            let chain = crate::so101::chain(&sim.state().q, jaw);
            let (camera, roll) = wrist_view(&chain, 320.0, 240.0);
            for (i, (body, b)) in part_boxes(&chain).enumerate() {
                if i == FIXED_FINGER || i == MOVING_FINGER {
                    assert_eq!(body == 6, i == MOVING_FINGER);
                    for corner in b.corners() {
                        let at = wrist_image_point(&camera, roll, v(&corner)).unwrap();
                        assert!(inside(at), "jaw {jaw}, part {i}: {at:?}");
                    }
                }
            }
        }
        // The sky does not project.
        assert!(camera
            .project(DVec3::new(chain.tool.pos[0], chain.tool.pos[1], 1.0))
            .is_none());
    }

    #[test]
    fn settings_read_back_and_bad_ones_are_left_out() {
        let base = SceneConfig::default_for(false);
        let pairs = |p: &[(&str, &str)]| -> Vec<(String, String)> {
            p.iter()
                .map(|(k, v)| (k.to_string(), v.to_string()))
                .collect()
        };
        let c = apply_settings(
            &base,
            &pairs(&[
                ("ik", "pinv"),
                ("latency_ms", "123"),
                ("noise", "0.25"),
                ("pos_sensitivity", "1"),
                ("rot_sensitivity", "1.6"),
                ("obstacle", "true"),
            ]),
        );
        assert_eq!(c.control.method, IkMethod::Pinv);
        assert_eq!(c.latency_steps, 12);
        assert_eq!(
            (c.noise_sigma, c.pos_sensitivity, c.rot_sensitivity),
            (0.25, 1.0, 1.6)
        );
        assert!(c.obstacle);
        let texts: Vec<(String, String)> = settings_texts(&c)
            .into_iter()
            .map(|(k, v)| (k.to_string(), v))
            .collect();
        assert_eq!(apply_settings(&base, &texts), c);
        let bad = apply_settings(
            &c,
            &pairs(&[
                ("ik", "magic"),
                ("latency_ms", "NaN"),
                ("noise", "-1"),
                ("pos_sensitivity", "1e300"),
                ("obstacle", "maybe"),
                ("lang", "ja"),
            ]),
        );
        assert_eq!(bad, c);
    }

    #[test]
    fn the_wrist_image_rolls_with_wrist_roll() {
        let sim = Sim::new(SceneConfig::default_for(false)).unwrap();
        let mut q = sim.state().q;
        let roll_at = |q5: f64, q: &mut [f64; 5]| {
            q[4] = q5;
            let chain = crate::so101::chain(q, 0.0);
            let (camera, roll) = wrist_view(&chain, 320.0, 240.0);
            // Turned by `roll`, the tool's z axis points straight up in the image.
            let t = &chain.tool;
            let z = DVec3::new(t.rot[0][2], t.rot[1][2], t.rot[2][2]);
            let eye = v(&t.pos);
            let (a, b) = (
                camera.project(eye + z * 0.0 + rot(t).col(0) * 0.05),
                camera.project(eye + z * 0.02 + rot(t).col(0) * 0.05),
            );
            let d = b.unwrap().at - a.unwrap().at;
            let (sin, cos) = roll.sin_cos();
            // Screen y points down; a counter-clockwise turn by `roll`.
            let turned = DVec2::new(d.x * cos + d.y * sin, -d.x * sin + d.y * cos);
            assert!(
                turned.x.abs() < 1e-6 * d.length().max(1.0) + 1e-6,
                "{q5}: {turned:?}"
            );
            assert!(turned.y < 0.0, "{q5}: {turned:?}");
            roll
        };
        let r0 = roll_at(0.0, &mut q);
        let r1 = roll_at(0.5, &mut q);
        let turned = (r1 - r0).sin().atan2((r1 - r0).cos());
        assert!((turned.abs() - 0.5).abs() < 0.05, "{r0} {r1}");
        // The square camera keeps the image's scale.
        let chain = sim.chain();
        let (square, _) = wrist_view(&chain, 320.0, 240.0);
        let plain = wrist_camera(&chain, 320.0, 240.0);
        let p = DVec3::new(chain.tool.pos[0] + 0.01, chain.tool.pos[1] + 0.02, 0.0);
        let side = 320f64.hypot(240.0);
        let (a, b) = (square.project(p).unwrap().at, plain.project(p).unwrap().at);
        let centred = a - DVec2::splat(side / 2.0) + DVec2::new(160.0, 120.0);
        assert!(centred.distance(b) < 1e-6, "{centred:?} {b:?}");
    }

    #[test]
    fn a_box_is_six_faces_facing_out_lit_from_above() {
        let mut scene = Scene::new();
        let b = Obb::aligned([0.1, 0.0, 0.05], [0.02, 0.01, 0.03]);
        box_faces(&mut scene, &b, CUBE);
        assert_eq!(scene.len(), 6);
        let camera = world_camera(800.0, 500.0);
        let marks = scene.project(&camera);
        // Seen from a corner above, three faces turn towards the camera.
        assert_eq!(marks.len(), 3);
        let mut top = None;
        for m in &marks {
            let crate::view::scene3d::Shape2::Quad { corners, .. } = &m.shape else {
                panic!("{m:?}");
            };
            // Every face is a real quadrilateral on screen (or edge-on).
            let area: f64 = (0..4)
                .map(|i| corners[i].perp_dot(corners[(i + 1) % 4]))
                .sum::<f64>()
                / 2.0;
            assert!(area.is_finite());
            if area.abs() > 1.0 && m.stroke.color == CUBE[0] {
                top = Some(m.depth);
            }
        }
        // The top face is the lit one, and the nearer of the two z faces seen from above.
        assert!(top.is_some());
        assert_eq!(
            marks.iter().filter(|m| m.stroke.color == CUBE[0]).count(),
            1,
            "{marks:?}"
        );
    }

    #[test]
    fn readout_texts() {
        assert_eq!(mm(-0.0123), "−12.3");
        assert_eq!(deg(std::f64::consts::PI), "180.0");
        assert_eq!(joint_limits_text(0), "−110.0 … 110.0");
        assert_eq!(manipulability_text(0.00703), "7.03e-3");
        assert_eq!(manipulability_text(-0.0), "0.00e0");
    }

    #[test]
    fn a_readout_that_rounds_to_zero_has_no_minus() {
        // The start pose's tool y and pitch: a few µm and µrad below zero.
        assert_eq!(mm(-0.000_004), "0.0");
        assert_eq!(deg(-0.000_1), "0.0");
        assert_eq!(mm(-0.0), "0.0");
        assert_eq!(deg(-0.000_1), "0.0");
        assert_eq!(mm(-0.000_06), "−0.1");
    }
}
