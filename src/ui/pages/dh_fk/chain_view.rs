//! The 3D view of the chain (the kit's orbit view): the ground grid, the links, each joint's
//! axis (dashed, through its frame's origin along its z), every frame's axes triad coloured x
//! / y / z and numbered `{0}` … `{3}`, the tip; while a row is walked, the moving frame (large,
//! labelled, over everything) and the path its origin took.

use glam::{DMat3, DMat4, DVec3};
use wasm_bindgen::JsValue;
use web_sys::Element;

use super::markup::P;
use crate::ui::kit::canvas::{Ink, LayeredCanvas};
use crate::ui::kit::orbit::{paint, OrbitOptions, OrbitView};
use crate::view::camera3d::{Camera, Preset};
use crate::view::dh_fk::{DrawFrame, VIEW_RADIUS, VIEW_TARGET};
use crate::view::scene3d::{AxisPalette, Layer, Scene, Shape3, Stroke};

/// Ground grid: cells and cell size, m.
const GRID_CELLS: usize = 6;
const GRID_CELL_M: f64 = 0.1;
/// Triad arrow length, m, and width, px; the moving frame's.
const TRIAD_M: f64 = 0.06;
const TRIAD_PX: f64 = 2.5;
const MOVING_M: f64 = 0.085;
const MOVING_PX: f64 = 4.0;
/// Half length of a drawn joint axis, m.
const AXIS_HALF_M: f64 = 0.07;

const GRID: Stroke = Stroke::solid("#d9dfe7", 1.0);
const LINK: Stroke = Stroke::solid("#64748b", 9.0);
const JOINT_AXIS: Stroke = Stroke::dashed("#7c3aed", 1.6);
const TRAIL: Stroke = Stroke::dashed("#c2410c", 2.0);
const JOINT_DOT: &str = "#1e293b";
const TIP_DOT: &str = "#c2410c";
const FRAME_LABEL: &str = "#1e293b";

/// The moving frame of a row walk, as drawn.
pub struct Moving {
    /// Base to the moving frame.
    pub pose: DMat4,
    /// Origins the frame passed through (M_0 … now).
    pub trail: Vec<DVec3>,
}

/// What the view shows.
pub struct Look<'a> {
    pub frames: &'a [DrawFrame],
    pub palette: AxisPalette,
    pub moving: Option<Moving>,
}

/// The scene of `look`.
pub fn build(scene: &mut Scene, look: &Look) {
    scene.clear();
    scene.grid(GRID_CELLS, GRID_CELL_M, GRID);
    let frames = look.frames;
    // Links: the base column to frame 1, then joint to joint (zero-length ones skipped).
    for pair in frames.windows(2) {
        let (a, b) = (pair[0].origin, pair[1].origin);
        if a.distance(b) > 1e-9 {
            scene.line(a, b, LINK);
        }
    }
    for f in frames.iter().skip(1) {
        let z = f.rotation.col(2);
        scene.line(
            f.origin - z * AXIS_HALF_M,
            f.origin + z * AXIS_HALF_M,
            JOINT_AXIS,
        );
        scene.dot(f.origin, 5.0, JOINT_DOT);
    }
    for f in frames {
        scene.triad(f.origin, f.rotation, TRIAD_M, look.palette, TRIAD_PX, None);
    }
    // Frame numbers beside the origins, on the side away from the frame's x and y; frames
    // sharing an origin (1 and 2 here: a = d = 0 between them) share one label, "{1} {2}".
    let mut start = 0;
    while start < frames.len() {
        let mut end = start + 1;
        while end < frames.len() && frames[end].origin.distance(frames[start].origin) < 1e-9 {
            end += 1;
        }
        let f = &frames[start];
        let text = frames[start..end]
            .iter()
            .map(|g| format!("{{{}}}", g.index))
            .collect::<Vec<_>>()
            .join(" ");
        let off = -(f.rotation.col(0) + f.rotation.col(1)) * 0.02;
        scene.label(f.origin + off, text, FRAME_LABEL);
        start = end;
    }
    if let Some(tip) = frames.last() {
        scene.dot(tip.origin, 6.5, TIP_DOT);
    }
    if let Some(m) = &look.moving {
        for pair in m.trail.windows(2) {
            if pair[0].distance(pair[1]) > 1e-9 {
                scene.push(
                    Layer::Overlay,
                    Shape3::Line {
                        a: pair[0],
                        b: pair[1],
                    },
                    TRAIL,
                );
            }
        }
        scene.triad_in(
            Layer::Overlay,
            m.pose.w_axis.truncate(),
            DMat3::from_mat4(m.pose),
            MOVING_M,
            look.palette,
            MOVING_PX,
            Some(["x", "y", "z"]),
        );
    }
}

/// The view component: the orbit widget and the scene it draws (kept to reuse its storage).
pub struct ChainView {
    pub orbit: OrbitView,
    scene: std::cell::RefCell<Scene>,
}

impl ChainView {
    /// Builds the view in `slot` at `preset`; `draw` paints a frame (the page's), `on_view`
    /// hears the user's view changes (the preset still shown, if any).
    pub fn new(
        slot: &Element,
        preset: Preset,
        draw: impl Fn(&LayeredCanvas, &Camera, Ink) + 'static,
        on_view: impl Fn(Option<Preset>) + 'static,
    ) -> Result<ChainView, JsValue> {
        let mut options = OrbitOptions::new(
            "dh-fk-canvas",
            "dh-canvas-label",
            DVec3::from_array(VIEW_TARGET),
            VIEW_RADIUS,
        );
        options.preset = preset;
        options.stage_class = "dh-stage";
        options.on_view = Some(Box::new(on_view));
        let orbit = OrbitView::new(slot, options, draw)?;
        // The readouts (every frame's pose, the tip) are the view's text alternative.
        orbit
            .canvas_element()
            .set_attribute("aria-describedby", &format!("{P}-readouts"))?;
        Ok(ChainView {
            orbit,
            scene: std::cell::RefCell::new(Scene::new()),
        })
    }

    /// Paints `look` through `camera` on the canvas.
    pub fn paint(&self, canvas: &LayeredCanvas, camera: &Camera, ink: Ink, look: &Look) {
        let Ok(mut scene) = self.scene.try_borrow_mut() else {
            return;
        };
        build(&mut scene, look);
        let marks = scene.project(camera);
        let layer = canvas.top();
        layer.begin();
        paint(&layer.ctx, &marks, ink);
    }
}
