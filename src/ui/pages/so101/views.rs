//! The two views: the world (the kit's orbit view, `data-testid="so101-canvas"`, with the
//! clutch gizmo on the tool) and the wrist camera (`data-testid="so101-wrist"`); both draw
//! `crate::view::so101`'s scene of the live state or of the replayed step. And the readouts.
//!
//! A view is drawn again only when what it shows changed (the arm, the cube, the camera, the
//! held handle, the ink); the world's table and goal sit on a canvas of their own under the
//! rest, drawn again only when the camera, the ink or the goal change. The wrist canvas is
//! sized when it is built and when its stage is resized, not in every frame.

use std::cell::{Cell, RefCell};
use std::rc::{Rc, Weak};

use glam::{DVec2, DVec3};
use wasm_bindgen::JsValue;
use web_sys::{Element, KeyboardEvent};

use super::devices::Devices;
use super::practice::Practice;
use crate::so101::kinematics::chain;
use crate::so101::scene::{Obb, JAW_CLOSED, JAW_HOLDING, JAW_OPEN};
use crate::so101::sim::StepRecord;
use crate::ui::kit::canvas::{Ink, LayeredCanvas};
use crate::ui::kit::drag::DragEvent;
use crate::ui::kit::orbit::{paint, OrbitOptions, OrbitView};
use crate::ui::kit::readouts::Readouts;
use crate::ui::{ctx, dom};
use crate::view::camera3d::{Camera, Preset};
use crate::view::scene3d::{AxisPalette, Scene};
use crate::view::so101::{
    deg, ground, handle_at, manipulability_text, mm, ring_grips, world, wrist, wrist_view, Handle,
    Look, VIEW_AZIMUTH, VIEW_RADIUS, VIEW_TARGET,
};

/// The state the views draw: the practice and the devices (the gizmo held).
#[derive(Clone)]
pub struct Shared {
    pub practice: Rc<RefCell<Practice>>,
    pub devices: Rc<RefCell<Devices>>,
}

/// The views.
pub struct Views {
    pub orbit: OrbitView<Handle>,
    wrist: RefCell<LayeredCanvas>,
    wrist_scene: RefCell<Scene>,
    /// What the wrist canvas shows (`None`: nothing yet, or cleared by a resize).
    wrist_shown: RefCell<Option<Shown>>,
    shared: Weak<Shared>,
}

/// What a view shows, as numbers (a view is drawn again only when one of them changed): the
/// gripper closed, the cube held, the wall, the gizmo and its held handle, the ink's line
/// scale, the goal; the joints; the cube's centre and axes; the camera.
type Shown = [f64; 34];

/// The camera as numbers.
fn camera_key(c: &Camera) -> [f64; 9] {
    let t = c.target;
    [
        t.x,
        t.y,
        t.z,
        c.azimuth,
        c.elevation,
        c.distance,
        c.fov_y,
        c.width,
        c.height,
    ]
}

/// [`Shown`] of `record` and `cube`, with the wall, the gizmo and its held handle, seen
/// through `camera` with `ink`.
fn shown_key(
    record: &StepRecord,
    cube: &Obb,
    p: &Practice,
    active: Option<Handle>,
    camera: &Camera,
    ink: Ink,
) -> Shown {
    let flag = |b: bool| if b { 1.0 } else { 0.0 };
    let active = match active {
        None => -1.0,
        Some(Handle::Axis(k)) => k as f64,
        Some(Handle::Turn(k)) => 3.0 + k as f64,
    };
    let mut k = [0.0; 34];
    k[..8].copy_from_slice(&[
        flag(record.gripper_closed),
        flag(record.held),
        flag(p.config.obstacle),
        flag(p.replay.is_none()),
        active,
        ink.line,
        p.config.goal[0],
        p.config.goal[1],
    ]);
    k[8..13].copy_from_slice(&record.q);
    k[13..16].copy_from_slice(&cube.centre);
    for (i, row) in cube.rot.iter().enumerate() {
        k[16 + 3 * i..19 + 3 * i].copy_from_slice(row);
    }
    k[25..].copy_from_slice(&camera_key(camera));
    k
}

/// The world view's drawing state: its scene and what its two canvases show (the ground:
/// the camera, the ink's line scale and the goal).
struct WorldState {
    scene: Scene,
    shown: Option<Shown>,
    ground: Option<[f64; 12]>,
}

/// The record the views and readouts show and the cube's box: the replayed step, else the
/// live state.
pub fn shown(p: &Practice) -> (StepRecord, Obb) {
    if let Some(replay) = p.replay.as_ref().and_then(|r| r.try_borrow().ok()) {
        if let Some(sim) = replay.sim() {
            return (sim.snapshot(), sim.state().cube.obb());
        }
    }
    let sim = p.recorder.sim();
    (sim.snapshot(), sim.state().cube.obb())
}

/// The record the views and readouts show.
pub fn shown_record(p: &Practice) -> StepRecord {
    shown(p).0
}

/// The arm's frames for `record`.
fn chain_of(record: &StepRecord) -> crate::so101::Chain {
    let jaw = match (record.gripper_closed, record.held) {
        (false, _) => JAW_OPEN,
        (true, true) => JAW_HOLDING,
        (true, false) => JAW_CLOSED,
    };
    chain(&record.q, jaw)
}

fn draw_world(
    shared: &Weak<Shared>,
    canvas: &LayeredCanvas,
    camera: &Camera,
    ink: Ink,
    state: &RefCell<WorldState>,
    tool: &Cell<DVec3>,
) {
    let Some(shared) = shared.upgrade() else {
        return;
    };
    let Ok(p) = shared.practice.try_borrow() else {
        return;
    };
    let Ok(mut state) = state.try_borrow_mut() else {
        return;
    };
    let (record, cube) = shown(&p);
    tool.set(DVec3::from_array(record.tool));
    let active = shared
        .devices
        .try_borrow()
        .ok()
        .and_then(|d| d.clutch.map(|c| c.handle));
    let now = shown_key(&record, &cube, &p, active, camera, ink);
    let mut ground_now = [0.0; 12];
    ground_now[..9].copy_from_slice(&camera_key(camera));
    ground_now[9..].copy_from_slice(&[ink.line, p.config.goal[0], p.config.goal[1]]);
    if state.ground != Some(ground_now) {
        let state = &mut *state;
        ground(&mut state.scene, p.config.goal);
        let marks = state.scene.project(camera);
        let layer = canvas.layer(0);
        layer.begin();
        paint(&layer.ctx, &marks, ink);
        state.ground = Some(ground_now);
    }
    if state.shown.as_ref() == Some(&now) {
        return;
    }
    let c = chain_of(&record);
    let look = Look {
        chain: &c,
        cube,
        goal: p.config.goal,
        obstacle: p.config.obstacle,
        gizmo: p.replay.is_none(),
        active,
    };
    world(&mut state.scene, &look, AxisPalette::Classic);
    let marks = state.scene.project(camera);
    let layer = canvas.top();
    layer.begin();
    paint(&layer.ctx, &marks, ink);
    state.shown = Some(now);
    // Where each ring can be taken, for the page's tests.
    let grips: Vec<String> = ring_grips(camera, DVec3::from_array(record.tool))
        .iter()
        .map(|g| {
            g.filter(|_| look.gizmo).map_or("-".into(), |(at, d)| {
                format!("{:.1},{:.1},{:.3},{:.3}", at.x, at.y, d.x, d.y)
            })
        })
        .collect();
    let grips = grips.join("|");
    if layer.canvas.get_attribute("data-ring-grips").as_deref() != Some(grips.as_str()) {
        let _ = layer.canvas.set_attribute("data-ring-grips", &grips);
    }
}

impl Views {
    /// Builds the world view in its slot and finds the wrist canvas; `on_gizmo` hears the
    /// drags of the gizmo's handles with the tool's position.
    pub fn new(
        root: &Element,
        shared: &Rc<Shared>,
        on_gizmo: impl Fn(DragEvent<Handle>, DVec3) + 'static,
    ) -> Result<Views, JsValue> {
        let slot: Element = dom::find(root, "[data-so101=\"world\"]", "so101")?;
        let tool = Rc::new(Cell::new(DVec3::ZERO));
        let mut options: OrbitOptions<Handle> = OrbitOptions::new(
            "so101-canvas",
            "so101-canvas-label",
            DVec3::from_array(VIEW_TARGET),
            VIEW_RADIUS,
        );
        options.preset = Preset::Iso;
        options.iso_azimuth = VIEW_AZIMUTH;
        options.stage_class = "so101-stage";
        // The table and the goal below, the rest above.
        options.layers = 2;
        let t = tool.clone();
        let weak = Rc::downgrade(shared);
        options.claim = Some(Box::new(move |at: DVec2, _kind, camera: &Camera| {
            let live = weak
                .upgrade()
                .and_then(|s| s.practice.try_borrow().ok().map(|p| p.replay.is_none()));
            if live != Some(true) {
                return None;
            }
            handle_at(camera, t.get(), at)
        }));
        let t = tool.clone();
        options.on_handle = Some(Box::new(move |e: DragEvent<Handle>| on_gizmo(e, t.get())));
        let state = RefCell::new(WorldState {
            scene: Scene::new(),
            shown: None,
            ground: None,
        });
        let weak = Rc::downgrade(shared);
        let orbit = OrbitView::new(&slot, options, move |canvas, camera, ink| {
            draw_world(&weak, canvas, camera, ink, &state, &tool);
        })?;
        orbit
            .canvas_element()
            .set_attribute("aria-describedby", "so101-readouts")?;
        let stage: Element = dom::find(root, "[data-so101=\"wrist-stage\"]", "so101")?;
        // Sized on its first draw, as the world view is (not while the page is built).
        let wrist = LayeredCanvas::from_stage(&stage)?;
        Ok(Views {
            orbit,
            wrist: RefCell::new(wrist),
            wrist_scene: RefCell::new(Scene::new()),
            wrist_shown: RefCell::new(None),
            shared: Rc::downgrade(shared),
        })
    }

    /// The world canvas (keys, focus).
    pub fn canvas(&self) -> Element {
        self.orbit.canvas_element()
    }

    /// The view's own keys (arrows orbit, + / − zoom).
    pub fn on_key(&self, event: &KeyboardEvent) -> bool {
        self.orbit.on_key(event)
    }

    pub fn relocalize(&self) {
        self.orbit.relocalize();
    }

    pub fn relayout(&self) {
        self.orbit.relayout();
        self.fit_wrist();
    }

    /// The wrist camera's stage (its size is watched).
    pub fn wrist_stage(&self) -> Option<Element> {
        self.wrist.try_borrow().ok().map(|w| w.stage.clone())
    }

    /// Sizes the wrist canvas to its stage again and draws both views.
    pub fn fit_wrist(&self) {
        if let Ok(mut canvas) = self.wrist.try_borrow_mut() {
            if canvas.fit() {
                self.wrist_shown.replace(None);
            }
        }
        self.redraw();
    }

    /// Both views again, now (the page's frame).
    pub fn redraw(&self) {
        self.orbit.redraw_now();
        self.draw_wrist();
    }

    fn draw_wrist(&self) {
        if let Ok(mut canvas) = self.wrist.try_borrow_mut() {
            if !canvas.is_fitted() {
                canvas.fit();
            }
        }
        let Some(shared) = self.shared.upgrade() else {
            return;
        };
        let Ok(p) = shared.practice.try_borrow() else {
            return;
        };
        let Ok(canvas) = self.wrist.try_borrow() else {
            return;
        };
        let (w, h) = canvas.size();
        let (record, cube) = shown(&p);
        let c = chain_of(&record);
        // The image turns with the wrist (its square camera covers the turned corners).
        let (camera, roll) = wrist_view(&c, w, h);
        let ink = Ink::current();
        let now = shown_key(&record, &cube, &p, None, &camera, ink);
        let Ok(mut shown_now) = self.wrist_shown.try_borrow_mut() else {
            return;
        };
        if shown_now.as_ref() == Some(&now) {
            return;
        }
        let look = Look {
            chain: &c,
            cube,
            goal: p.config.goal,
            obstacle: p.config.obstacle,
            gizmo: false,
            active: None,
        };
        let Ok(mut scene) = self.wrist_scene.try_borrow_mut() else {
            return;
        };
        wrist(&mut scene, &look);
        let marks = scene.project(&camera);
        let layer = canvas.top();
        layer.begin();
        let ctx = &layer.ctx;
        ctx.save();
        let _ = ctx.translate(w / 2.0, h / 2.0);
        let _ = ctx.rotate(-roll);
        let _ = ctx.translate(-camera.width / 2.0, -camera.height / 2.0);
        paint(ctx, &marks, ink);
        ctx.restore();
        *shown_now = Some(now);
        // How far the image is turned, rad (for the page's tests).
        let turned = format!("{roll:.4}");
        if layer.canvas.get_attribute("data-roll").as_deref() != Some(turned.as_str()) {
            let _ = layer.canvas.set_attribute("data-roll", &turned);
        }
    }
}

/// Writes every readout for `record`.
pub fn write_readouts(r: &Readouts, p: &Practice, record: &StepRecord) {
    let (state, id) = if p.replay.is_some() {
        ("replay", "so101-state-replay")
    } else if p.recorder.sim().done().is_some() || p.ended.is_some() && !p.engaged {
        ("ended", "so101-state-ended")
    } else if p.engaged {
        ("engaged", "teleop-state-engaged")
    } else {
        ("paused", "teleop-state-paused")
    };
    r.set_with_value("state", &ctx::t(id), state);
    let n = (p.session.episodes.len() + 1).to_string();
    if p.records() {
        r.set_with_value("episode", &n, &n);
    } else {
        r.set_with_value("episode", &ctx::t("teleop-episode-practice"), "0");
    }
    let (gripper, id) = if record.gripper_closed {
        ("closed", "teleop-gripper-closed")
    } else {
        ("open", "teleop-gripper-open")
    };
    r.set_with_value("gripper", &ctx::t(id), gripper);
    let keys = ["x", "y", "z"];
    for (k, v) in keys.iter().zip(record.tool) {
        r.set_with_value(k, &mm(v), &v.to_string());
    }
    for (k, v) in ["roll", "pitch", "yaw"].iter().zip(record.rpy) {
        r.set_with_value(k, &deg(v), &v.to_string());
    }
    for (i, q) in record.q.iter().enumerate() {
        r.set_with_value(&format!("q{}", i + 1), &deg(*q), &q.to_string());
    }
    r.set_with_value(
        "manipulability",
        &manipulability_text(record.manipulability),
        &record.manipulability.to_string(),
    );
    r.set_with_value(
        "orientation-error",
        &deg(record.orientation_error),
        &record.orientation_error.to_string(),
    );
    r.set("time", &format!("{:.2}", record.t_s));
}
