//! The SO-101 page's pure view model (`#/so101`): the 3D scene of the arm (each link's box
//! from [`crate::so101::scene`], the table, the cube, the goal square, the obstacle, the tool
//! frame), the wrist camera (a camera at the tool frame looking along the gripper), the
//! clutch gizmo on the tool (three translation arrows and a yaw ring: a press on one is a
//! handle, dragging it commands motion along that axis only while held) and the readout texts.

use glam::{DMat3, DVec2, DVec3};

use crate::camera3d::{hit_point, Camera};
use crate::so101::kinematics::{Chain, Frame};
use crate::so101::model::joint_limits;
use crate::so101::scene::{base_box, link_boxes, obstacle_box, Obb, GOAL_HALF, TABLE_Z};
use crate::view::scene3d::{AxisPalette, Layer, Scene, Shape3, Stroke};

/// The point the world view looks at and the radius it frames, m.
pub const VIEW_TARGET: [f64; 3] = [0.15, 0.02, 0.07];
/// See [`VIEW_TARGET`].
pub const VIEW_RADIUS: f64 = 0.2;
/// Gizmo arrow length, m.
pub const GIZMO_M: f64 = 0.06;
/// Yaw ring radius, m.
pub const RING_M: f64 = 0.045;
/// Points on the yaw ring.
pub const RING_POINTS: usize = 24;
/// Hit radius of a gizmo handle, CSS px (a 44 px target).
pub const HIT_PX: f64 = 22.0;
/// Screen distance of a drag that commands full speed, px.
pub const FULL_DRAG_PX: f64 = 60.0;

const LINK: Stroke = Stroke::solid("#b7791f", 2.5);
const BASE: Stroke = Stroke::solid("#6b7280", 2.0);
const JAW: Stroke = Stroke::solid("#92400e", 2.5);
const CUBE: Stroke = Stroke::solid("#0072b2", 2.5);
const GOAL: Stroke = Stroke::solid("#009e73", 3.0);
const WALL: Stroke = Stroke::solid("#d55e00", 2.5);
const TABLE: Stroke = Stroke::solid("#cbd5e1", 1.0);
const RING: Stroke = Stroke::solid("#7c3aed", 2.0);

/// A gizmo handle: a translation arrow (0 x, 1 y, 2 z) or the yaw ring.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Handle {
    /// Along world axis 0, 1 or 2.
    Axis(usize),
    /// About world z.
    Yaw,
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

/// The twelve edges of a box.
pub fn box_edges(scene: &mut Scene, b: &Obb, stroke: Stroke) {
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
        scene.line(v(&c[i]), v(&c[j]), stroke);
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

/// The arm, the cube, the goal and the wall (what both views show).
fn things(scene: &mut Scene, look: &Look) {
    square(scene, look.goal, GOAL_HALF, GOAL);
    if look.obstacle {
        box_edges(scene, &obstacle_box(), WALL);
    }
    box_edges(scene, &base_box(look.chain), BASE);
    let boxes = link_boxes(look.chain);
    for (i, b) in boxes.iter().enumerate() {
        box_edges(scene, b, if i == 5 { JAW } else { LINK });
    }
    box_edges(scene, &look.cube, CUBE);
}

/// The world view's scene.
pub fn world(scene: &mut Scene, look: &Look, palette: AxisPalette) {
    scene.clear();
    scene.grid(8, 0.05, TABLE);
    things(scene, look);
    let tool = &look.chain.tool;
    scene.triad(v(&tool.pos), rot(tool), 0.035, palette, 2.0, None);
    if look.gizmo {
        gizmo(scene, v(&tool.pos), look.active, palette);
    }
}

/// The wrist camera's scene (no gizmo).
pub fn wrist(scene: &mut Scene, look: &Look) {
    scene.clear();
    scene.grid(8, 0.05, TABLE);
    things(scene, look);
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
    let ring = ring_points(at);
    let stroke = if active == Some(Handle::Yaw) {
        Stroke::solid(RING.color, 4.0)
    } else {
        RING
    };
    for k in 0..RING_POINTS {
        scene.push(
            Layer::Overlay,
            Shape3::Line {
                a: ring[k],
                b: ring[(k + 1) % RING_POINTS],
            },
            stroke,
        );
    }
}

fn axis(k: usize) -> DVec3 {
    match k {
        0 => DVec3::X,
        1 => DVec3::Y,
        _ => DVec3::Z,
    }
}

/// The yaw ring's points about `at`.
pub fn ring_points(at: DVec3) -> Vec<DVec3> {
    (0..RING_POINTS)
        .map(|k| {
            let a = std::f64::consts::TAU * k as f64 / RING_POINTS as f64;
            at + DVec3::new(a.cos(), a.sin(), 0.0) * RING_M
        })
        .collect()
}

/// The handle under `cursor` (CSS px): an arrow's tip or middle first, then the ring.
pub fn handle_at(camera: &Camera, tool: DVec3, cursor: DVec2) -> Option<Handle> {
    let mut points = Vec::new();
    for k in 0..3 {
        points.push(camera.project(tool + axis(k) * GIZMO_M));
        points.push(camera.project(tool + axis(k) * GIZMO_M * 0.6));
    }
    if let Some(i) = hit_point(&points, cursor, HIT_PX) {
        return Some(Handle::Axis(i / 2));
    }
    let ring: Vec<_> = ring_points(tool)
        .iter()
        .map(|p| camera.project(*p))
        .collect();
    hit_point(&ring, cursor, HIT_PX / 2.0).map(|_| Handle::Yaw)
}

/// The command axes of a drag of `handle` from `start` to `now` (CSS px) with the tool at
/// `tool`: along the arrow's screen direction (full speed at [`FULL_DRAG_PX`]), or around the
/// ring's centre for yaw (counter-clockwise on screen is +yaw when looking from above).
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
        Handle::Yaw => {
            let (a, b) = (start - c.at, now - c.at);
            if a.length() < 1.0 || b.length() < 1.0 {
                return out;
            }
            // Screen y points down: a clockwise turn on screen is a positive angle here.
            let turn = (a.x * b.y - a.y * b.x).atan2(a.dot(b));
            let above = camera.elevation >= 0.0;
            let sign = if above { -1.0 } else { 1.0 };
            out[5] = (sign * turn / 0.5).clamp(-1.0, 1.0);
        }
    }
    out
}

/// The world view's camera at its start (the iso preset), `width`×`height` CSS px.
pub fn world_camera(width: f64, height: f64) -> Camera {
    Camera::framing(
        DVec3::from_array(VIEW_TARGET),
        VIEW_RADIUS,
        crate::camera3d::Preset::Iso,
        width,
        height,
    )
}

/// The wrist camera: at the tool frame's origin looking along its x axis (the gripper's
/// approach direction), `width`×`height` CSS px, 70° vertical field of view.
pub fn wrist_camera(chain: &Chain, width: f64, height: f64) -> Camera {
    let t = &chain.tool;
    let ahead = DVec3::new(t.rot[0][0], t.rot[1][0], t.rot[2][0]);
    // Back off 1 cm behind the tool frame, between the jaws, so the jaw tips show.
    let eye = v(&t.pos) - ahead * 0.01;
    let distance = 0.1;
    let back = -ahead;
    let elevation = back
        .z
        .clamp(-1.0, 1.0)
        .asin()
        .clamp(-Camera::MAX_ELEVATION, Camera::MAX_ELEVATION);
    let azimuth = back.y.atan2(back.x);
    Camera {
        target: eye + ahead * distance,
        azimuth,
        elevation,
        distance,
        fov_y: 70f64.to_radians(),
        width,
        height,
    }
}

/// A joint's readout: its angle in degrees and its limits, `"12.3° (−110.0…110.0)"`.
pub fn joint_text(i: usize, q: f64) -> String {
    let (lo, hi) = joint_limits()[i.min(4)];
    format!(
        "{:.1}° ({:.1}…{:.1})",
        q.to_degrees(),
        lo.to_degrees(),
        hi.to_degrees()
    )
    .replace('-', "−")
}

/// Millimetres with one decimal, `"123.4"` (minus sign as typeset).
pub fn mm(m: f64) -> String {
    format!("{:.1}", m * 1000.0).replace('-', "−")
}

/// Degrees with one decimal.
pub fn deg(rad: f64) -> String {
    format!("{:.1}", rad.to_degrees()).replace('-', "−")
}

#[cfg(test)]
mod tests {
    #[cfg(target_arch = "wasm32")]
    use wasm_bindgen_test::wasm_bindgen_test as test;

    use super::*;
    use crate::so101::{SceneConfig, Sim};

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
        world(&mut scene, &look, AxisPalette::Classic);
        // Grid (2 × 9 lines), goal 4, wall/base/6 links/cube 9 boxes × 12, triad 3,
        // gizmo 3 arrows + 24 ring segments.
        assert_eq!(scene.len(), 18 + 4 + 9 * 12 + 3 + 3 + RING_POINTS);
        let camera = world_camera(800.0, 500.0);
        assert!(!scene.project(&camera).is_empty());
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
    fn the_wrist_camera_sees_the_cube_below_the_start_pose() {
        let sim = Sim::new(SceneConfig::default_for(false)).unwrap();
        let chain = sim.chain();
        let cam = wrist_camera(&chain, 320.0, 240.0);
        // The tool points down at the start: the table under it projects, the sky does not.
        let under = DVec3::new(chain.tool.pos[0], chain.tool.pos[1], 0.0);
        let p = cam.project(under).unwrap();
        assert!(
            (p.at.x - 160.0).abs() < 40.0 && (p.at.y - 120.0).abs() < 40.0,
            "{p:?}"
        );
        assert!(cam
            .project(DVec3::new(chain.tool.pos[0], chain.tool.pos[1], 1.0))
            .is_none());
    }

    #[test]
    fn readout_texts() {
        assert_eq!(mm(-0.0123), "−12.3");
        assert_eq!(deg(std::f64::consts::PI), "180.0");
        assert_eq!(joint_text(0, 0.0), "0.0° (−110.0…110.0)");
    }
}
