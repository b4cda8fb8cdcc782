//! The relative SE(3) pose (`#/se3-relative`): frames A and B in a 3D view with the relative
//! transform `T_A⁻¹ T_B` as an arrow from A to B expressed in A; the two poses' fields with a
//! rad/deg switch (radians are the recipe's: the URL, the command lines and the CSV stay in
//! radians); drag an origin in the view (in the plane facing the camera) or a yaw ring (the
//! frame turns about the world's vertical: its yaw alone), orbit by dragging elsewhere, zoom
//! with the wheel, a pinch or `+`/`-`, preset views (the kit's orbit view); the 4×4 matrices, the result
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
use crate::recipes::run_raw_of;
use crate::recipes::se3_relative::{self, Se3Params, CSV_NAME, INFO};
use crate::ui::kit::canvas::{Ink, LayeredCanvas};
use crate::ui::kit::drag::{DragEvent, PointerKind};
use crate::ui::kit::exercise_slot::ExerciseSlot;
use crate::ui::kit::exports::Exports;
use crate::ui::kit::keymap;
use crate::ui::kit::orbit::{self, OrbitOptions, OrbitView};
use crate::ui::kit::page_root::PageRoot;
use crate::ui::kit::readouts::Readouts;
use crate::ui::kit::scope::Scope;
use crate::ui::kit::url_state::{UrlNotice, UrlWriter};
use crate::ui::page::{MountCtx, Page, Shortcut};
use crate::ui::schedule::now_ms;
use crate::ui::{ctx, dom};
use crate::view::camera3d::{Camera, Preset};
use crate::view::exercises::se3_relative::EXERCISES;
use crate::view::exercises::PageModel;
use crate::view::se3_relative::{
    dragged_origin, hit_gizmo, position_texts, ring_radius, scene_frame, solve, wrap_angle, yaw_at,
    yaw_text, AngleUnit, Grab, PoseFields, Solved, VIEW_KEY,
};
use crate::view::signal::sig;
use markup::{P, PNG};

/// The page's keys besides the orbit view's.
const KEYS: [Shortcut; 3] = [
    keymap::key("1 2 3 4", "se3-key-views"),
    keymap::key("u", "se3-key-unit"),
    keymap::key("r", "se3-key-reset"),
];
/// The camera frames this share of the scene's radius: the frames fill the view (their axis
/// tips may reach its edge).
const CLOSER: f64 = 0.8;

/// A drag of an origin or a yaw ring under way: which, the pointer where it began, the
/// frame's origin and yaw then; for a ring, the yaw so far and the pointer's last angle
/// about the vertical through the origin.
#[derive(Debug, Clone, Copy)]
struct DragStart {
    grab: Grab,
    start_px: DVec2,
    origin: DVec3,
    yaw: f64,
    last_angle: Option<f64>,
}

/// The mounted page.
pub struct Se3Page {
    inner: Rc<Inner>,
    _exercises: ExerciseSlot,
}

struct Inner {
    me: Weak<Inner>,
    root: PageRoot,
    poses: RefCell<poses::Poses>,
    solved: RefCell<Solved>,
    /// The 3D view (camera, orbit, zoom, presets), made once the page exists.
    view: RefCell<Option<OrbitView<Grab>>>,
    /// The radius of the scene framed (axis lengths, zoom limits).
    radius: Cell<f64>,
    /// The preset the view still shows (the URL's `view`).
    preset: Cell<Option<Preset>>,
    rotations: RefCell<rotations::Rotations>,
    source: HtmlSelectElement,
    tables: tables::Matrices,
    readouts: Readouts,
    exports: Exports,
    notice: UrlNotice,
    url: RefCell<Option<UrlWriter>>,
    dragging: Cell<Option<DragStart>>,
    hover: Cell<Option<Grab>>,
    timings: bench::Timings,
    /// What the ground layer and the rotations panel were last drawn for (skipped while it
    /// stays the same, e.g. during a drag of an origin); `None` after a language switch.
    ground_drawn: Cell<Option<(Camera, f64, bool, u32)>>,
    rotations_drawn: Cell<Option<[f64; 7]>>,
    scope: RefCell<Scope>,
}

fn js_error(e: &crate::error::RecipeError) -> JsValue {
    JsValue::from_str(&ctx::error_text(e))
}

impl Page for Se3Page {
    fn mount(ctx: MountCtx) -> Result<Se3Page, JsValue> {
        let exercises_root = ctx.root.clone();
        let root = PageRoot::fill(&ctx.root, &markup::page(), P, P)?;
        let (fields, ignored) = PoseFields::read(&ctx.query);
        let preset = ctx.get(VIEW_KEY).and_then(Preset::from_id);
        let mut ignored = ignored;
        if ctx.get(VIEW_KEY).is_some() && preset.is_none() {
            ignored.push(crate::view::url::IgnoredKey::invalid(VIEW_KEY));
        }
        let notice = UrlNotice::new(root.role("url-notice")?, ignored)?;
        let poses = poses::Poses::build(root.role("form")?, fields)?;
        let params = poses.params();
        params.validate().map_err(|e| js_error(&e))?;
        let solved = solve(&params);
        let rotations = rotations::Rotations::find(&root, &root.role("rot-stage")?)?;
        let source: HtmlSelectElement = root.role("rot-source")?;
        let tables = tables::Matrices::find(&root)?;
        let readouts = Readouts::find(&root)?;
        let exports = Exports::find(&root, P)?;
        let unit = poses.fields.unit;
        let slot: Element = root.role("view")?;
        let preset = preset.unwrap_or(Preset::Iso);
        let (target, radius) = scene_frame(&params);
        let inner = Rc::new_cyclic(|me: &Weak<Inner>| {
            let mut scope = Scope::new();
            let url = UrlWriter::new(&mut scope, me, Inner::query);
            Inner {
                me: me.clone(),
                root,
                poses: RefCell::new(poses),
                solved: RefCell::new(solved),
                view: RefCell::new(None),
                radius: Cell::new(radius),
                preset: Cell::new(Some(preset)),
                rotations: RefCell::new(rotations),
                source,
                tables,
                readouts,
                exports,
                notice,
                url: RefCell::new(Some(url)),
                dragging: Cell::new(None),
                hover: Cell::new(None),
                timings: bench::Timings::install(),
                ground_drawn: Cell::new(None),
                rotations_drawn: Cell::new(None),
                scope: RefCell::new(scope),
            }
        });
        inner.set_unit_radios(unit);
        inner.build_view(&slot, preset, target, radius)?;
        inner.install()?;
        inner.rotations.borrow_mut().canvas.fit();
        inner.show_commands();
        inner.show_numbers();
        inner.redraw();
        let exercises = ExerciseSlot::lending(&exercises_root, &EXERCISES, &inner, lend_model)?;
        Ok(Se3Page {
            inner,
            _exercises: exercises,
        })
    }

    fn relocalize(&self) {
        let p = &self.inner;
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
        p.ground_drawn.set(None);
        p.rotations_drawn.set(None);
        if let Some(view) = p.view.borrow().as_ref() {
            view.relocalize();
        }
        p.show_numbers();
    }

    fn set_projector(&self, _on: bool) {
        self.inner.relayout();
    }

    fn shortcuts(&self) -> Vec<Shortcut> {
        orbit::KEYS.iter().chain(&KEYS).copied().collect()
    }

    fn on_key(&self, event: &KeyboardEvent) -> bool {
        self.inner.on_key(event)
    }
}

impl Inner {
    /// The URL: the poses (radians), the unit, the view.
    fn query(&self) -> Vec<(String, String)> {
        let mut pairs = self.poses.borrow().url_pairs();
        if let Some(preset) = self.preset.get().filter(|p| *p != Preset::Iso) {
            pairs.push((VIEW_KEY.into(), preset.id().into()));
        }
        pairs
    }

    fn write_url(&self) {
        if let Some(url) = self.url.borrow().as_ref() {
            url.schedule();
        }
    }

    /// The 3D view in `slot`: the page draws it, claims presses on the origins and hears
    /// their drags and the view's changes.
    fn build_view(
        &self,
        slot: &Element,
        preset: Preset,
        target: DVec3,
        radius: f64,
    ) -> Result<(), JsValue> {
        let mut options = OrbitOptions::new(
            "se3-relative-canvas",
            "se3-canvas-label",
            target,
            radius * CLOSER,
        );
        options.layers = 2;
        options.stage_class = "se3-stage";
        options.preset = preset;
        let me = self.me.clone();
        options.claim = Some(Box::new(move |at, kind: PointerKind, camera: &Camera| {
            let p = me.upgrade()?;
            let params = p.solved.try_borrow().ok()?.params;
            let ring = ring_radius(p.radius.get());
            hit_gizmo(
                camera,
                &params,
                ring,
                at,
                scene::hit_radius(kind.is_coarse()),
            )
        }));
        let me = self.me.clone();
        options.on_handle = Some(Box::new(move |ev| {
            if let Some(p) = me.upgrade() {
                p.on_drag(ev);
            }
        }));
        let me = self.me.clone();
        options.on_view = Some(Box::new(move |preset| {
            if let Some(p) = me.upgrade() {
                p.preset.set(preset);
                p.write_url();
            }
        }));
        let me = self.me.clone();
        let view = OrbitView::new(slot, options, move |canvas, camera, ink| {
            if let Some(p) = me.upgrade() {
                p.draw(canvas, camera, ink);
            }
        })?;
        // The poses' readouts are the view's text alternative.
        view.canvas_element()
            .set_attribute("aria-describedby", &format!("{P}-readouts"))?;
        *self.view.borrow_mut() = Some(view);
        Ok(())
    }

    fn install(&self) -> Result<(), JsValue> {
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
        scope.listen_for(&self.source, "change", me, |p, _| p.show_rotations(None))?;
        let csv: Element = self.root.find(&format!("[data-download=\"{CSV_NAME}\"]"))?;
        scope.listen_for(&csv, "click", me, |p, _| p.download())?;
        let png: Element = self.root.find(&format!("[data-download=\"{PNG}\"]"))?;
        scope.listen_for(&png, "click", me, |p, _| {
            if let Some(view) = p.view.borrow().as_ref() {
                view.png(PNG);
            }
        })?;
        for kind in ["python", "bsv"] {
            let button: Element = self.root.find(&format!("[data-copy=\"{kind}\"]"))?;
            scope.listen_for(&button, "click", me, move |p, _| p.exports.copy(kind))?;
        }
        let rot_stage = self.rotations.borrow().canvas.stage.clone();
        scope.observe_resize(&[&rot_stage], me, |p| {
            p.rotations.borrow_mut().canvas.fit();
            p.rotations_drawn.set(None);
            p.show_rotations(None);
        })?;
        Ok(())
    }

    /// The camera now (the view's).
    fn camera(&self) -> Option<Camera> {
        self.view.try_borrow().ok()?.as_ref().map(OrbitView::camera)
    }

    /// One frame of the view (the kit calls it): ground, frames, hooks, and the rotations
    /// panel seen from the same direction.
    fn draw(&self, canvas: &LayeredCanvas, camera: &Camera, ink: Ink) {
        let t0 = now_ms();
        let Ok(solved) = self.solved.try_borrow() else {
            return;
        };
        let radius = self.radius.get();
        let ground = (
            *camera,
            radius,
            ink.projector,
            canvas.layer(0).canvas.width(),
        );
        if self.ground_drawn.get() != Some(ground) {
            scene::draw_ground(canvas, camera, radius, ink);
            self.ground_drawn.set(Some(ground));
        }
        scene::draw_frames(canvas, camera, &solved, self.hover.get(), radius, ink);
        scene::write_hooks(canvas, camera, &solved, self.preset.get(), radius);
        drop(solved);
        self.show_rotations(Some(camera));
        // A drag of an origin records its whole frame itself.
        if self.dragging.get().is_none() {
            self.timings.push(now_ms() - t0);
        }
    }

    /// Redraws the view now.
    fn redraw(&self) {
        if let Ok(view) = self.view.try_borrow() {
            if let Some(view) = view.as_ref() {
                view.redraw_now();
            }
        }
    }

    fn on_drag(&self, ev: DragEvent<Grab>) {
        let t0 = now_ms();
        match ev {
            DragEvent::Hover(at) => {
                let ring = ring_radius(self.radius.get());
                let hit = self.camera().and_then(|camera| {
                    hit_gizmo(
                        &camera,
                        &self.solved.borrow().params,
                        ring,
                        at,
                        scene::hit_radius(false),
                    )
                });
                if hit != self.hover.get() {
                    self.hover.set(hit);
                    self.redraw();
                }
            }
            DragEvent::Leave => {
                if self.hover.take().is_some() {
                    self.redraw();
                }
            }
            DragEvent::Start { handle, at, .. } => {
                let params = self.solved.borrow().params;
                let pose = if handle.is_a() { params.a } else { params.b };
                let origin = DVec3::new(pose.x, pose.y, pose.z);
                self.dragging.set(Some(DragStart {
                    grab: handle,
                    start_px: at,
                    origin,
                    yaw: pose.yaw,
                    last_angle: self.camera().and_then(|c| yaw_at(&c, origin, at)),
                }));
                self.hover.set(Some(handle));
            }
            DragEvent::Move { at, .. } => {
                let Some(d) = self.dragging.get() else {
                    return;
                };
                let first = if d.grab.is_a() { 0 } else { 6 };
                let values: Vec<(usize, String)> = match d.grab {
                    Grab::A | Grab::B => self
                        .camera()
                        .and_then(|camera| dragged_origin(&camera, d.origin, d.start_px, at))
                        .map(|p| {
                            position_texts(p)
                                .into_iter()
                                .enumerate()
                                .map(|(k, t)| (first + k, t))
                                .collect()
                        })
                        .unwrap_or_default(),
                    Grab::YawA | Grab::YawB => self.turn(d, at).into_iter().collect(),
                };
                if !values.is_empty() {
                    let changed = self.poses.borrow_mut().set(&values);
                    if let Some(params) = changed {
                        self.changed(params, false);
                    }
                }
                self.timings.push(now_ms() - t0);
            }
            DragEvent::End { .. } => {
                self.dragging.set(None);
                self.hover.set(None);
                self.redraw();
                if let Some(url) = self.url.borrow().as_ref() {
                    url.write_now();
                }
            }
            DragEvent::Tap { .. } => {}
        }
    }

    /// A yaw ring dragged to `at`: the pointer's turn about the vertical since the last move
    /// (wrapped, so a full turn and more keeps counting) added to the yaw; the yaw field's
    /// new text.
    fn turn(&self, mut d: DragStart, at: DVec2) -> Option<(usize, String)> {
        let angle = self.camera().and_then(|c| yaw_at(&c, d.origin, at))?;
        if let Some(last) = d.last_angle {
            d.yaw += wrap_angle(angle - last);
        }
        d.last_angle = Some(angle);
        self.dragging.set(Some(d));
        let unit = self.poses.borrow().fields.unit;
        let index = if d.grab.is_a() { 5 } else { 11 };
        Some((index, yaw_text(d.yaw, unit)))
    }

    /// New valid poses: recompute, redraw, readouts; `typed` keeps the frames in view.
    fn changed(&self, params: Se3Params, typed: bool) {
        *self.solved.borrow_mut() = solve(&params);
        if typed {
            self.keep_in_view();
        }
        self.show_numbers();
        self.redraw();
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

    /// Frames the scene again when an origin has left the view (after a typed value).
    fn keep_in_view(&self) {
        let out = {
            let solved = self.solved.borrow();
            self.camera()
                .is_some_and(|camera| scene::out_of_view(&camera, &solved))
        };
        if out {
            self.frame_scene();
        }
    }

    /// Frames the whole scene from the current preset (iso after an orbit).
    fn frame_scene(&self) {
        let (target, radius) = scene_frame(&self.solved.borrow().params);
        self.radius.set(radius);
        if let Some(view) = self.view.borrow().as_ref() {
            view.frame_scene(target, radius * CLOSER);
            self.preset.set(view.preset());
        }
    }

    fn relayout(&self) {
        if let Some(view) = self.view.borrow().as_ref() {
            view.relayout();
        }
        self.rotations.borrow_mut().canvas.fit();
        self.rotations_drawn.set(None);
        self.show_rotations(None);
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
    }

    /// The rotations panel, seen from `camera`'s direction (the view's when `None`).
    fn show_rotations(&self, camera: Option<&Camera>) {
        let Some(camera) = camera.copied().or_else(|| self.camera()) else {
            return;
        };
        let Ok(solved) = self.solved.try_borrow() else {
            return;
        };
        let pose = match rotations::Source::from_id(&self.source.value()) {
            rotations::Source::A => solved.params.a,
            rotations::Source::B => solved.params.b,
            rotations::Source::Relative => solved.rel,
        };
        let Ok(rotations) = self.rotations.try_borrow() else {
            return;
        };
        let ink = Ink::current();
        let key = [
            pose.roll,
            pose.pitch,
            pose.yaw,
            camera.azimuth,
            camera.elevation,
            f64::from(u8::from(ink.projector)),
            f64::from(rotations.canvas.top().canvas.width()),
        ];
        if self.rotations_drawn.get() == Some(key) {
            return;
        }
        self.rotations_drawn.set(Some(key));
        let diff = rotations.show(
            (pose.roll, pose.pitch, pose.yaw),
            camera.azimuth,
            camera.elevation,
            ink,
        );
        self.readouts
            .set_with_value("rot-diff", &crate::numtext::fixed(diff, 4), &py_float(diff));
    }

    fn show_commands(&self) {
        self.exports
            .show_run(&self.poses.borrow().run_args(), INFO.python, None);
    }

    /// Saves the recipe's CSV of the last valid poses (the `bsv` bytes).
    fn download(&self) {
        let raw = self.poses.borrow().run_args().raw();
        match run_raw_of::<se3_relative::Entry>(&raw, Vec::new()) {
            Ok(out) => self
                .exports
                .download(CSV_NAME, out.file(CSV_NAME).unwrap_or_default()),
            Err(e) => self
                .exports
                .download_failed(CSV_NAME, &JsValue::from_str(&ctx::error_text(&e))),
        }
    }

    fn on_key(&self, event: &KeyboardEvent) -> bool {
        if self
            .view
            .borrow()
            .as_ref()
            .is_some_and(|view| view.on_key(event))
        {
            return true;
        }
        let preset = |p: Preset| {
            if let Some(view) = self.view.borrow().as_ref() {
                view.set_preset(p);
            }
        };
        match event.key().as_str() {
            "1" => preset(Preset::Iso),
            "2" => preset(Preset::Top),
            "3" => preset(Preset::Front),
            "4" => preset(Preset::Side),
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

/// The page's model for its exercises.
fn lend_model(inner: &Inner, lend: &mut dyn FnMut(&PageModel)) {
    lend(&PageModel::Se3(&inner.poses.borrow().params()))
}
