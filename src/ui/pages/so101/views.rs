//! The two views: the world (the kit's orbit view, `data-testid="so101-canvas"`, with the
//! clutch gizmo on the tool) and the wrist camera (`data-testid="so101-wrist"`); both draw
//! `crate::view::so101`'s scene of the live state or of the replayed step. And the readouts.

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
    deg, handle_at, joint_text, mm, ring_grips, world, wrist, wrist_view, Handle, Look,
    VIEW_RADIUS, VIEW_TARGET,
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
    shared: Weak<Shared>,
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
    scene: &RefCell<Scene>,
) {
    let Some(shared) = shared.upgrade() else {
        return;
    };
    let Ok(p) = shared.practice.try_borrow() else {
        return;
    };
    let (record, cube) = shown(&p);
    let c = chain_of(&record);
    let active = shared
        .devices
        .try_borrow()
        .ok()
        .and_then(|d| d.clutch.map(|c| c.handle));
    let look = Look {
        chain: &c,
        cube,
        goal: p.config.goal,
        obstacle: p.config.obstacle,
        gizmo: p.replay.is_none(),
        active,
    };
    let Ok(mut scene) = scene.try_borrow_mut() else {
        return;
    };
    world(&mut scene, &look, AxisPalette::Classic);
    let marks = scene.project(camera);
    let layer = canvas.top();
    layer.begin();
    paint(&layer.ctx, &marks, ink);
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
        options.stage_class = "so101-stage";
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
        let scene = RefCell::new(Scene::new());
        let weak = Rc::downgrade(shared);
        let t = tool;
        let orbit = OrbitView::new(&slot, options, move |canvas, camera, ink| {
            if let Some(s) = weak.upgrade() {
                if let Ok(p) = s.practice.try_borrow() {
                    t.set(DVec3::from_array(shown_record(&p).tool));
                }
            }
            draw_world(&weak, canvas, camera, ink, &scene);
        })?;
        orbit
            .canvas_element()
            .set_attribute("aria-describedby", "so101-readouts")?;
        let stage: Element = dom::find(root, "[data-so101=\"wrist-stage\"]", "so101")?;
        let wrist = LayeredCanvas::from_stage(&stage)?;
        Ok(Views {
            orbit,
            wrist: RefCell::new(wrist),
            wrist_scene: RefCell::new(Scene::new()),
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
        self.redraw();
    }

    /// Both views again, now (the page's frame).
    pub fn redraw(&self) {
        self.orbit.redraw_now();
        self.draw_wrist();
    }

    fn draw_wrist(&self) {
        let Some(shared) = self.shared.upgrade() else {
            return;
        };
        let Ok(p) = shared.practice.try_borrow() else {
            return;
        };
        let Ok(mut canvas) = self.wrist.try_borrow_mut() else {
            return;
        };
        canvas.fit();
        let (w, h) = canvas.size();
        let (record, cube) = shown(&p);
        let c = chain_of(&record);
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
        // The image turns with the wrist (its square camera covers the turned corners).
        let (camera, roll) = wrist_view(&c, w, h);
        let marks = scene.project(&camera);
        let layer = canvas.top();
        layer.begin();
        let ctx = &layer.ctx;
        ctx.save();
        let _ = ctx.translate(w / 2.0, h / 2.0);
        let _ = ctx.rotate(-roll);
        let _ = ctx.translate(-camera.width / 2.0, -camera.height / 2.0);
        paint(ctx, &marks, Ink::current());
        ctx.restore();
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
        r.set_with_value(k, &format!("{} mm", mm(v)), &v.to_string());
    }
    for (k, v) in ["roll", "pitch", "yaw"].iter().zip(record.rpy) {
        r.set_with_value(k, &format!("{}°", deg(v)), &v.to_string());
    }
    for (i, q) in record.q.iter().enumerate() {
        r.set_with_value(&format!("q{}", i + 1), &joint_text(i, *q), &q.to_string());
    }
    r.set_with_value(
        "manipulability",
        &format!("{:.2e} m³", record.manipulability),
        &record.manipulability.to_string(),
    );
    r.set_with_value(
        "orientation-error",
        &format!("{}°", deg(record.orientation_error)),
        &record.orientation_error.to_string(),
    );
    r.set("time", &format!("{:.2} s", record.t_s));
}
