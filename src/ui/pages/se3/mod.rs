//! The relative SE(3) pose (`#/se3-relative`): frames A and B in a 3D view with the relative
//! transform `T_A⁻¹ T_B` as an arrow from A to B expressed in A; the two poses' fields with a
//! rad/deg switch (radians are the recipe's: the URL, the command lines and the CSV stay in
//! radians); drag an origin in the view (in the plane facing the camera), orbit by dragging
//! elsewhere, zoom with the wheel or the buttons, preset views; the 4×4 matrices, the result
//! row as the CSV has it, the check `T_A (T_A⁻¹ T_B) = T_B`; the same roll, pitch, yaw as
//! extrinsic and intrinsic rotations side by side; `se3_relative.csv` byte for byte what
//! `bsv se3-relative` writes with the page's arguments.
//!
//! Components, one file each: `scene` (the 3D view), `poses` (the form and the unit switch),
//! `tables` (the matrices and the CSV row), `rotations` (the teaching panel), `markup`;
//! readouts and command lines are the kit's. The numbers come from the pure
//! `crate::view::se3_relative`.

mod bench;
mod markup;
mod poses;
mod rotations;
mod scene;
mod tables;

use std::cell::{Cell, RefCell};
use std::rc::{Rc, Weak};

use glam::{DVec2, DVec3};
use wasm_bindgen::prelude::*;
use web_sys::{Element, HtmlInputElement, HtmlSelectElement, KeyboardEvent};

use crate::pyfmt::py_float;
use crate::recipes::se3_relative::{Se3Params, CSV_NAME, INFO};
use crate::ui::kit::canvas::{focus_without_scroll, Ink};
use crate::ui::kit::drag::{Drag, DragEvent, PointerKind};
use crate::ui::kit::exports::Exports;
use crate::ui::kit::readouts::Readouts;
use crate::ui::kit::scope::Scope;
use crate::ui::kit::url_state::{UrlNotice, UrlWriter};
use crate::ui::page::{MountCtx, Page, PageDef, Shortcut};
use crate::ui::schedule::now_ms;
use crate::ui::{ctx, dom};
use crate::view::camera3d::{Camera, Preset};
use crate::view::se3_relative::{
    dragged_origin, hit_frame, position_texts, solve, AngleUnit, Grab, PoseFields, Solved, VIEW_KEY,
};
use crate::view::signal::sig;

/// The page, as the shell's page table lists it.
pub const PAGE: PageDef = PageDef::of::<Se3Page>("se3-relative", "se3-title", "se3-blurb");

const P: &str = "se3";
const PNG: &str = "se3_relative.png";
/// Zoom per button press or `+`/`-`.
const ZOOM_STEP: f64 = 1.25;
/// Orbit per arrow key, px of drag (Shift: five times).
const ORBIT_KEY_PX: f64 = 8.0;

/// A drag under way: what, the pointer where it began, the origin then.
#[derive(Debug, Clone, Copy)]
struct DragStart {
    grab: Grab,
    start_px: DVec2,
    last_px: DVec2,
    origin: DVec3,
}

/// The mounted page.
pub struct Se3Page(Rc<Inner>);

struct Inner {
    me: Weak<Inner>,
    root: Element,
    poses: RefCell<poses::Poses>,
    solved: RefCell<Solved>,
    scene: RefCell<scene::Scene>,
    rotations: RefCell<rotations::Rotations>,
    source: HtmlSelectElement,
    tables: tables::Matrices,
    readouts: Readouts,
    exports: Exports,
    notice: UrlNotice,
    url: RefCell<Option<UrlWriter>>,
    drag: RefCell<Option<Drag<Grab>>>,
    dragging: Cell<Option<DragStart>>,
    hover: Cell<Option<Grab>>,
    timings: bench::Timings,
    scope: RefCell<Scope>,
}

fn js_error(e: &crate::error::RecipeError) -> JsValue {
    JsValue::from_str(&ctx::error_text(e))
}

impl Page for Se3Page {
    fn mount(ctx: MountCtx) -> Result<Se3Page, JsValue> {
        let root = ctx.root.clone();
        root.set_inner_html(&markup::page());
        dom::relocalize(&root)?;
        let find = |sel: &str| -> Result<Element, JsValue> { dom::find(&root, sel, P) };
        let (fields, ignored) = PoseFields::read(&ctx.query);
        let preset = ctx.get(VIEW_KEY).and_then(Preset::from_id);
        let mut ignored = ignored;
        if ctx.get(VIEW_KEY).is_some() && preset.is_none() {
            ignored.push(crate::view::url::IgnoredKey::invalid(VIEW_KEY));
        }
        let notice = UrlNotice::new(find(&format!("[data-{P}=\"url-notice\"]"))?, ignored)?;
        let poses = poses::Poses::build(find(&format!("[data-{P}=\"form\"]"))?, fields)?;
        let params = poses.params();
        params.validate().map_err(|e| js_error(&e))?;
        let solved = solve(&params);
        let stage = find(&format!("[data-{P}=\"stage\"]"))?;
        let scene = scene::Scene::find(&stage, &solved, preset.unwrap_or(Preset::Iso))?;
        let rotations =
            rotations::Rotations::find(&root, &find(&format!("[data-{P}=\"rot-stage\"]"))?)?;
        let source: HtmlSelectElement = dom::find(&root, &format!("[data-{P}=\"rot-source\"]"), P)?;
        let tables = tables::Matrices::find(&root)?;
        let readouts = Readouts::find(&root)?;
        let exports = Exports::find(&root, P)?;
        let unit = poses.fields.unit;
        let inner = Rc::new_cyclic(|me: &Weak<Inner>| {
            let mut scope = Scope::new();
            let url = UrlWriter::new(&mut scope, me, Inner::query);
            Inner {
                me: me.clone(),
                root,
                poses: RefCell::new(poses),
                solved: RefCell::new(solved),
                scene: RefCell::new(scene),
                rotations: RefCell::new(rotations),
                source,
                tables,
                readouts,
                exports,
                notice,
                url: RefCell::new(Some(url)),
                drag: RefCell::new(None),
                dragging: Cell::new(None),
                hover: Cell::new(None),
                timings: bench::Timings::install(),
                scope: RefCell::new(scope),
            }
        });
        inner.set_unit_radios(unit);
        inner.install(&stage)?;
        {
            let mut scene = inner.scene.borrow_mut();
            scene.fit();
            let solved = inner.solved.borrow();
            let preset = scene.preset;
            scene.frame(&solved, preset);
        }
        inner.rotations.borrow_mut().canvas.fit();
        inner.show_commands();
        inner.redraw(true);
        inner.show_numbers();
        Ok(Se3Page(inner))
    }

    fn relocalize(&self) {
        let p = &self.0;
        p.poses.borrow_mut().relocalize();
        p.exports.relocalize();
        p.notice.relocalize();
        if let Ok(Some(button)) = p
            .root
            .query_selector(&format!("[data-download=\"{CSV_NAME}\"]"))
        {
            let label = ctx::t_strings("kit-exports-download", &[("file", CSV_NAME.to_string())]);
            button.set_text_content(Some(&label));
        }
        p.show_numbers();
        p.redraw(true);
    }

    fn set_projector(&self, _on: bool) {
        self.0.relayout();
    }

    fn shortcuts(&self) -> Vec<Shortcut> {
        vec![
            Shortcut {
                keys: "← → ↑ ↓",
                message_id: "se3-key-orbit",
            },
            Shortcut {
                keys: "+ −",
                message_id: "se3-key-zoom",
            },
            Shortcut {
                keys: "1 2 3 4",
                message_id: "se3-key-views",
            },
            Shortcut {
                keys: "u",
                message_id: "se3-key-unit",
            },
            Shortcut {
                keys: "r",
                message_id: "se3-key-reset",
            },
        ]
    }

    fn on_key(&self, event: &KeyboardEvent) -> bool {
        self.0.on_key(event)
    }
}

impl Inner {
    /// The URL: the poses (radians), the unit, the view.
    fn query(&self) -> Vec<(String, String)> {
        let mut pairs = self.poses.borrow().url_pairs();
        let preset = self.scene.borrow().preset;
        if preset != Preset::Iso {
            pairs.push((VIEW_KEY.into(), preset.id().into()));
        }
        pairs
    }

    fn write_url(&self) {
        if let Some(url) = self.url.borrow().as_ref() {
            url.schedule();
        }
    }

    fn install(&self, stage: &Element) -> Result<(), JsValue> {
        let mut scope = self.scope.borrow_mut();
        let me = &self.me;
        let form = self.poses.borrow().element.clone();
        scope.listen_for(&form, "input", me, |p, e| {
            let Some(target) = e.target().and_then(|t| t.dyn_into::<Element>().ok()) else {
                return;
            };
            let changed = p.poses.borrow_mut().edited(&target);
            if let Some(params) = changed {
                p.changed(params, true);
            }
        })?;
        scope.listen_for(&form, "submit", me, |_, e| e.prevent_default())?;
        for radio in dom::matching(&self.root, "[data-angle-unit]")? {
            scope.listen_for(&radio, "change", me, |p, e| {
                let unit = e
                    .target()
                    .and_then(|t| t.dyn_into::<HtmlInputElement>().ok())
                    .filter(|i| i.checked())
                    .and_then(|i| AngleUnit::from_id(&i.value()));
                if let Some(unit) = unit {
                    p.set_unit(unit);
                }
            })?;
        }
        for preset in Preset::ALL {
            let button: Element =
                dom::find(&self.root, &format!("[data-view=\"{}\"]", preset.id()), P)?;
            scope.listen_for(&button, "click", me, move |p, _| p.view(preset))?;
        }
        for (dir, factor) in [("in", ZOOM_STEP), ("out", 1.0 / ZOOM_STEP)] {
            let button: Element = dom::find(&self.root, &format!("[data-zoom=\"{dir}\"]"), P)?;
            scope.listen_for(&button, "click", me, move |p, _| p.zoom(factor))?;
        }
        scope.listen_for(&self.source, "change", me, |p, _| p.show_rotations())?;
        let csv: Element = dom::find(&self.root, &format!("[data-download=\"{CSV_NAME}\"]"), P)?;
        scope.listen_for(&csv, "click", me, |p, _| p.download())?;
        let png: Element = dom::find(&self.root, &format!("[data-download=\"{PNG}\"]"), P)?;
        scope.listen_for(&png, "click", me, |p, _| {
            if let Ok(canvas) = p.scene.borrow().canvas.flatten("#ffffff") {
                let _ = crate::ui::kit::png::download(&canvas, PNG);
            }
        })?;
        for kind in ["python", "bsv"] {
            let button: Element = dom::find(&self.root, &format!("[data-copy=\"{kind}\"]"), P)?;
            scope.listen_for(&button, "click", me, move |p, _| p.exports.copy(kind))?;
        }
        scope.listen_for(stage, "wheel", me, |p, e| {
            let dy = js_sys::Reflect::get(e, &"deltaY".into())
                .ok()
                .and_then(|v| v.as_f64())
                .unwrap_or(0.0);
            e.prevent_default();
            p.zoom(Camera::wheel_factor(dy));
        })?;
        let rot_stage = self.rotations.borrow().canvas.stage.clone();
        scope.observe_resize(&[stage, &rot_stage], me, |p| p.relayout())?;
        let top = self.scene.borrow().canvas.top().canvas.clone();
        scope.listen_for(&top, "pointerdown", me, |p, _| {
            focus_without_scroll(&p.scene.borrow().canvas.top().canvas);
        })?;
        drop(scope);
        let (w_hit, w_on) = (self.me.clone(), self.me.clone());
        *self.drag.borrow_mut() = Some(Drag::attach(
            stage,
            &top,
            move |at, kind| {
                let p = w_hit.upgrade()?;
                let scene = p.scene.borrow();
                let solved = p.solved.borrow();
                let radius = scene::Scene::hit_radius(kind.is_coarse());
                match hit_frame(&scene.camera, &solved.params, at, radius) {
                    Some(grab) => Some(grab),
                    // A finger off the origins scrolls the page; a mouse or pen orbits.
                    None if kind == PointerKind::Touch => None,
                    None => Some(Grab::Orbit),
                }
            },
            move |ev| {
                if let Some(p) = w_on.upgrade() {
                    p.on_drag(ev);
                }
            },
        )?);
        self.update_handles();
        Ok(())
    }

    fn update_handles(&self) {
        if let Some(drag) = self.drag.borrow().as_ref() {
            drag.set_handles(&self.scene.borrow().handles(&self.solved.borrow()));
        }
    }

    fn on_drag(&self, ev: DragEvent<Grab>) {
        let t0 = now_ms();
        match ev {
            DragEvent::Hover(at) => {
                let hit = {
                    let scene = self.scene.borrow();
                    hit_frame(
                        &scene.camera,
                        &self.solved.borrow().params,
                        at,
                        scene::Scene::hit_radius(false),
                    )
                };
                if hit != self.hover.get() {
                    self.hover.set(hit);
                    if let Some(drag) = self.drag.borrow().as_ref() {
                        drag.set_hover_cursor(if hit.is_some() { "grab" } else { "default" });
                    }
                    self.redraw(false);
                }
            }
            DragEvent::Leave => {
                if self.hover.take().is_some() {
                    self.redraw(false);
                }
            }
            DragEvent::Start { handle, at, .. } => {
                let params = self.solved.borrow().params;
                let origin = match handle {
                    Grab::A => DVec3::new(params.a.x, params.a.y, params.a.z),
                    Grab::B => DVec3::new(params.b.x, params.b.y, params.b.z),
                    Grab::Orbit => DVec3::ZERO,
                };
                self.dragging.set(Some(DragStart {
                    grab: handle,
                    start_px: at,
                    last_px: at,
                    origin,
                }));
            }
            DragEvent::Move { at, .. } => {
                let Some(mut d) = self.dragging.get() else {
                    return;
                };
                match d.grab {
                    Grab::Orbit => {
                        self.scene.borrow_mut().camera.orbit(at - d.last_px);
                        d.last_px = at;
                        self.dragging.set(Some(d));
                        self.redraw(true);
                        self.show_rotations();
                    }
                    Grab::A | Grab::B => {
                        let moved = {
                            let scene = self.scene.borrow();
                            dragged_origin(&scene.camera, d.origin, d.start_px, at)
                        };
                        if let Some(p) = moved {
                            let first = if d.grab == Grab::A { 0 } else { 6 };
                            let values: Vec<(usize, String)> = position_texts(p)
                                .into_iter()
                                .enumerate()
                                .map(|(k, t)| (first + k, t))
                                .collect();
                            let changed = self.poses.borrow_mut().set(&values);
                            if let Some(params) = changed {
                                self.changed(params, false);
                            }
                        }
                    }
                }
                self.timings.push(now_ms() - t0);
            }
            DragEvent::End { .. } => {
                self.dragging.set(None);
                self.update_handles();
                if let Some(url) = self.url.borrow().as_ref() {
                    url.write_now();
                }
            }
            DragEvent::Tap { .. } => {}
        }
    }

    /// New valid poses: recompute, redraw, readouts; `typed` keeps the frames in view.
    fn changed(&self, params: Se3Params, typed: bool) {
        *self.solved.borrow_mut() = solve(&params);
        if typed {
            self.scene.borrow_mut().keep_in_view(&self.solved.borrow());
            self.redraw(true);
            self.update_handles();
        } else {
            self.redraw(false);
        }
        self.show_numbers();
        self.show_commands();
        self.exports.clear_status();
        let rel = self.solved.borrow().rel;
        self.readouts.announce(&ctx::t_strings(
            "se3-live",
            &[
                ("x", sig(rel.x, 4)),
                ("y", sig(rel.y, 4)),
                ("z", sig(rel.z, 4)),
            ],
        ));
        self.write_url();
    }

    fn set_unit(&self, unit: AngleUnit) {
        self.poses.borrow_mut().set_unit(unit);
        self.set_unit_radios(unit);
        self.show_numbers();
        self.write_url();
    }

    fn set_unit_radios(&self, unit: AngleUnit) {
        if let Ok(radios) = dom::matching(&self.root, "[data-angle-unit]") {
            for r in radios {
                if let Ok(input) = r.dyn_into::<HtmlInputElement>() {
                    input.set_checked(input.value() == unit.id());
                }
            }
        }
        let _ = self.root.set_attribute("data-angle-unit", unit.id());
    }

    fn view(&self, preset: Preset) {
        {
            let mut scene = self.scene.borrow_mut();
            let solved = self.solved.borrow();
            scene.frame(&solved, preset);
        }
        self.redraw(true);
        self.update_handles();
        self.show_rotations();
        self.write_url();
    }

    fn zoom(&self, factor: f64) {
        {
            let mut scene = self.scene.borrow_mut();
            let radius = scene.radius;
            scene.camera.zoom(factor, radius);
        }
        self.redraw(true);
        self.update_handles();
    }

    fn relayout(&self) {
        self.scene.borrow_mut().fit();
        self.rotations.borrow_mut().canvas.fit();
        self.redraw(true);
        self.update_handles();
        if let Some(drag) = self.drag.borrow().as_ref() {
            drag.relayout();
        }
        self.show_rotations();
    }

    /// The view: the ground when the camera moved (`ground`), the frames always.
    fn redraw(&self, ground: bool) {
        let ink = Ink::current();
        let scene = self.scene.borrow();
        let solved = self.solved.borrow();
        if ground {
            scene.draw_ground(ink);
        }
        scene.draw_frames(&solved, self.hover.get(), ink);
        scene.write_hooks(&solved);
    }

    /// Readouts (in the unit shown), matrices, the CSV row, the check, the rotations panel.
    fn show_numbers(&self) {
        let unit = self.poses.borrow().fields.unit;
        let solved = self.solved.borrow();
        let rel = solved.rel;
        let ro = &self.readouts;
        let metres = |key: &str, v: f64| ro.set_with_value(key, &sig(v, 5), &py_float(v));
        metres("x", rel.x);
        metres("y", rel.y);
        metres("z", rel.z);
        for (key, v) in [("roll", rel.roll), ("pitch", rel.pitch), ("yaw", rel.yaw)] {
            ro.set_with_value(key, &sig(unit.from_rad(v), 5), &py_float(v));
            if let Some(dt) = ro.element(key).and_then(|dd| dd.previous_element_sibling()) {
                let id = match unit {
                    AngleUnit::Rad => format!("se3-ro-{key}"),
                    AngleUnit::Deg => format!("se3-ro-{key}-deg"),
                };
                if dt.get_attribute("data-i18n").as_deref() != Some(id.as_str()) {
                    let _ = dom::set_i18n(&dt, &id);
                }
            }
        }
        ro.set_with_value(
            "check-error",
            &if solved.check_error == 0.0 {
                "0".to_string()
            } else {
                format!("{:.1e}", solved.check_error)
            },
            &py_float(solved.check_error),
        );
        self.tables.show(&solved);
        drop(solved);
        self.show_rotations();
    }

    fn show_rotations(&self) {
        let solved = self.solved.borrow();
        let pose = match rotations::Source::from_id(&self.source.value()) {
            rotations::Source::A => solved.params.a,
            rotations::Source::B => solved.params.b,
            rotations::Source::Relative => solved.rel,
        };
        let (az, el) = {
            let cam = &self.scene.borrow().camera;
            (cam.azimuth, cam.elevation)
        };
        let diff =
            self.rotations
                .borrow()
                .show((pose.roll, pose.pitch, pose.yaw), az, el, Ink::current());
        self.readouts
            .set_with_value("rot-diff", &format!("{diff:.4}"), &py_float(diff));
    }

    fn show_commands(&self) {
        self.exports
            .show_run(&self.poses.borrow().run_args(), INFO.python, None);
    }

    /// Saves the recipe's CSV of the last valid poses (the `bsv` bytes).
    fn download(&self) {
        let raw = self.poses.borrow().run_args().raw();
        match crate::recipes::run(INFO.id, &raw) {
            Ok(out) => self
                .exports
                .download(CSV_NAME, out.file(CSV_NAME).unwrap_or_default()),
            Err(e) => self
                .exports
                .download_failed(CSV_NAME, &JsValue::from_str(&ctx::error_text(&e))),
        }
    }

    fn on_key(&self, event: &KeyboardEvent) -> bool {
        let k = if event.shift_key() { 5.0 } else { 1.0 };
        let orbit = |d: DVec2| {
            self.scene.borrow_mut().camera.orbit(d * ORBIT_KEY_PX * k);
            self.redraw(true);
            self.update_handles();
            self.show_rotations();
        };
        match event.key().as_str() {
            "ArrowLeft" => orbit(DVec2::new(-1.0, 0.0)),
            "ArrowRight" => orbit(DVec2::new(1.0, 0.0)),
            "ArrowUp" => orbit(DVec2::new(0.0, -1.0)),
            "ArrowDown" => orbit(DVec2::new(0.0, 1.0)),
            "+" | "=" => self.zoom(ZOOM_STEP),
            "-" | "_" => self.zoom(1.0 / ZOOM_STEP),
            "1" => self.view(Preset::Iso),
            "2" => self.view(Preset::Top),
            "3" => self.view(Preset::Front),
            "4" => self.view(Preset::Side),
            "u" | "U" => {
                let unit = match self.poses.borrow().fields.unit {
                    AngleUnit::Rad => AngleUnit::Deg,
                    AngleUnit::Deg => AngleUnit::Rad,
                };
                self.set_unit(unit);
            }
            "r" | "R" => {
                let changed = self.poses.borrow_mut().reset();
                if let Some(params) = changed {
                    self.changed(params, true);
                }
            }
            _ => return false,
        }
        true
    }
}
