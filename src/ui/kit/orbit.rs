//! A 3D view: layered HiDPI canvases on a stage, looked at through the shared orbit camera
//! ([`crate::view::camera3d::Camera`]). Dragging the background orbits (mouse, pen and touch
//! through Pointer Events with pointer capture), the wheel and a two-finger pinch zoom. On a
//! touch screen the stage has `touch-action: pan-y`: a finger that first moves up or down
//! scrolls the page (the browser cancels the pointer; the few pixels it orbited are undone),
//! one that first moves sideways orbits, and one that lands on a claimed handle drags it (its
//! `touchstart` is default-prevented, so the page does not scroll under it). The
//! preset buttons turn to the iso, top, front and side views
//! (`data-action="view-iso"` …, `aria-pressed` on the current one), and with the canvas
//! focused the arrow keys orbit and `+` / `-` zoom ([`KEYS`], for the page's `?` list; the
//! page forwards its keys to [`OrbitView::on_key`]).
//!
//! The page supplies the drawing: `draw(canvas, camera, ink)` runs once per animation frame
//! after any change ([`OrbitView::request_redraw`] coalesces), on resizes and projector
//! changes. A page that drags things in the view (gizmos) gives a `claim` hit test: a press
//! it claims (`Some(handle)`) becomes that page's drag ([`DragEvent`] `Start`/`Move`/`End`,
//! plus `Hover`/`Leave` for a mouse), any other press orbits.
//! [`paint`] draws the marks of a [`crate::view::scene3d::Scene`] with the projector's ink.

use std::cell::{Cell, RefCell};
use std::rc::{Rc, Weak};

use glam::{DVec2, DVec3};
use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::{CanvasRenderingContext2d, Element, Event, KeyboardEvent, PointerEvent};

use super::canvas::{dash, focus_without_scroll, solid, Ink, LayeredCanvas};
use super::drag::{client, DragEvent, PointerKind};
use super::form::escape;
use super::scope::{FrameLoop, Scope};
use crate::ui::dom;
use crate::ui::page::Shortcut;
use crate::view::camera3d::{Camera, Preset};
use crate::view::scene3d::{Mark, Shape2};

/// The keys of a focused 3D view, for the page's `?` list.
pub const KEYS: &[Shortcut] = &[
    Shortcut {
        keys: "← ↑ → ↓",
        message_id: "kit-orbit-key-orbit",
    },
    Shortcut {
        keys: "+  -",
        message_id: "kit-orbit-key-zoom",
    },
];

/// Pixels of drag one arrow key press stands for (about 8.6°).
const KEY_ORBIT_PX: f64 = 15.0;
/// Zoom factor of one `+` press.
const KEY_ZOOM: f64 = 1.15;
/// Wheel delta units: `deltaMode` 1 (lines) and 2 (pages) in pixels.
const WHEEL_LINE_PX: f64 = 16.0;
const WHEEL_PAGE_PX: f64 = 400.0;

/// A page's hit test of a press (position on the canvas, CSS px): the handle it takes.
pub type Claim<H> = Box<dyn Fn(DVec2, PointerKind, &Camera) -> Option<H>>;

/// How a view is set up.
pub struct OrbitOptions<H> {
    /// `data-testid` of the top canvas.
    pub testid: &'static str,
    /// Fluent id of the canvas's accessible name.
    pub label_id: &'static str,
    /// Extra class of the stage (the page sizes it).
    pub stage_class: &'static str,
    /// Number of stacked canvases (at least 1; the draw callback gets them all).
    pub layers: usize,
    /// The view at start.
    pub preset: Preset,
    /// The azimuth the iso view looks from, rad (about world z, from +x): a page turns it so
    /// that what matters in its scene stands clear at the start.
    pub iso_azimuth: f64,
    /// The point looked at and the radius of the scene (framing and zoom limits), metres.
    pub target: DVec3,
    pub radius: f64,
    /// A press the page takes first: `Some(handle)` drags that handle, `None` orbits.
    pub claim: Option<Claim<H>>,
    /// The page's drags of claimed handles (and mouse hovers while nothing is held).
    pub on_handle: Option<Box<dyn Fn(DragEvent<H>)>>,
    /// The view changed by the user (a preset, or the end of an orbit, zoom or key), with
    /// the preset it still is, if any (for the page's URL).
    pub on_view: Option<Box<dyn Fn(Option<Preset>)>>,
}

impl<H> OrbitOptions<H> {
    /// A view of a sphere of `radius` about `target` from `preset`, without claims.
    pub fn new(
        testid: &'static str,
        label_id: &'static str,
        target: DVec3,
        radius: f64,
    ) -> OrbitOptions<H> {
        OrbitOptions {
            testid,
            label_id,
            stage_class: "",
            layers: 1,
            preset: Preset::Iso,
            iso_azimuth: Camera::ISO_AZIMUTH,
            target,
            radius,
            claim: None,
            on_handle: None,
            on_view: None,
        }
    }
}

/// The page's drawing of one frame.
type Draw = Box<dyn Fn(&LayeredCanvas, &Camera, Ink)>;

/// What the pointers are doing.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Gesture<H> {
    Idle,
    /// One pointer orbiting, at its last client position.
    Orbit {
        id: i32,
        last: DVec2,
    },
    /// Two pointers: their distance and the camera distance when the pinch began.
    Pinch {
        start_px: f64,
        start_distance: f64,
    },
    /// A claimed handle dragged by pointer `id`.
    Handle {
        id: i32,
        handle: H,
    },
}

/// `camera` at `preset`, the iso view looking from `iso_azimuth`.
fn turn_iso(camera: &mut Camera, preset: Preset, iso_azimuth: f64) {
    if preset == Preset::Iso {
        camera.azimuth = iso_azimuth;
    }
}

struct Inner<H: Copy + PartialEq + 'static> {
    canvas: RefCell<LayeredCanvas>,
    stage: Element,
    presets: Vec<(Preset, Element)>,
    camera: Cell<Camera>,
    /// The preset the camera still shows (cleared by an orbit).
    preset: Cell<Option<Preset>>,
    /// See [`OrbitOptions::iso_azimuth`].
    iso_azimuth: f64,
    radius: Cell<f64>,
    /// Pointers down: id and client position.
    pointers: RefCell<Vec<(i32, DVec2)>>,
    gesture: Cell<Gesture<H>>,
    /// The top canvas's client rect at the press (left, top), for positions during a drag.
    origin: Cell<DVec2>,
    /// The camera and preset when a touch began to orbit: restored if the browser takes the
    /// finger to scroll the page (`pointercancel`).
    touch_orbit_from: Cell<Option<(Camera, Option<Preset>)>>,
    draw: RefCell<Option<Draw>>,
    claim: Option<Claim<H>>,
    on_handle: Option<Box<dyn Fn(DragEvent<H>)>>,
    on_view: Option<Box<dyn Fn(Option<Preset>)>>,
    frame: RefCell<Option<FrameLoop>>,
}

/// A 3D view; its listeners, observer and frame loop go away on drop. Hooks: the top canvas
/// carries the page's `data-testid` and `tabindex="0"`; the preset buttons
/// `data-action="view-<preset>"`; the stage `data-orbit="stage"`.
pub struct OrbitView<H: Copy + PartialEq + 'static = ()> {
    inner: Rc<Inner<H>>,
    root: Element,
    _scope: Scope,
}

fn kind_of(e: &PointerEvent) -> PointerKind {
    match e.pointer_type().as_str() {
        "mouse" => PointerKind::Mouse,
        "pen" => PointerKind::Pen,
        _ => PointerKind::Touch,
    }
}

fn markup<H>(options: &OrbitOptions<H>) -> String {
    let mut html = String::from(
        "<div class=\"kit-orbit-presets\" role=\"group\" data-i18n-attr=\"aria-label=kit-orbit-presets\">",
    );
    for p in Preset::ALL {
        html.push_str(&format!(
            "<button type=\"button\" class=\"tool-button kit-orbit-preset\" data-action=\"view-{id}\" \
             aria-pressed=\"false\" data-i18n=\"kit-orbit-view-{id}\"></button>",
            id = p.id()
        ));
    }
    html.push_str(&format!(
        "</div><div class=\"kit-orbit-stage {class}\" data-orbit=\"stage\">",
        class = escape(options.stage_class)
    ));
    let n = options.layers.max(1);
    for i in 0..n {
        if i + 1 < n {
            html.push_str("<canvas class=\"kit-orbit-layer\" aria-hidden=\"true\"></canvas>");
        } else {
            html.push_str(&format!(
                "<canvas class=\"kit-orbit-layer\" data-testid=\"{t}\" role=\"img\" tabindex=\"0\" \
                 data-i18n-attr=\"aria-label={l}\"></canvas>",
                t = escape(options.testid),
                l = escape(options.label_id),
            ));
        }
    }
    html.push_str(
        "</div><ul class=\"kit-orbit-hint\"><li data-i18n=\"kit-orbit-hint-mouse\"></li>\
         <li data-i18n=\"kit-orbit-hint-touch\"></li><li data-i18n=\"kit-orbit-hint-keys\"></li></ul>",
    );
    html
}

impl<H: Copy + PartialEq + 'static> OrbitView<H> {
    /// Builds the view (preset buttons, stage, hint) at the end of `parent`. `draw` paints a
    /// frame; it may hold the page weakly (the page owns the view).
    pub fn new(
        parent: &Element,
        options: OrbitOptions<H>,
        draw: impl Fn(&LayeredCanvas, &Camera, Ink) + 'static,
    ) -> Result<OrbitView<H>, JsValue> {
        let root = dom::el_class("div", "kit-orbit")?;
        root.set_inner_html(&markup(&options));
        dom::append(parent, &root)?;
        dom::relocalize(&root)?;
        let stage: Element = dom::find(&root, "[data-orbit=\"stage\"]", "kit-orbit")?;
        // Sized on its first draw (`fit_first`): measuring here would lay the page out inside
        // its build. The camera frames a square until then.
        let canvas = LayeredCanvas::from_stage(&stage)?;
        let mut camera = Camera::framing(options.target, options.radius, options.preset, 1.0, 1.0);
        turn_iso(&mut camera, options.preset, options.iso_azimuth);
        let mut presets = Vec::new();
        for p in Preset::ALL {
            let button: Element = dom::find(
                &root,
                &format!("[data-action=\"view-{}\"]", p.id()),
                "kit-orbit",
            )?;
            presets.push((p, button));
        }
        let inner = Rc::new(Inner {
            canvas: RefCell::new(canvas),
            stage: stage.clone(),
            presets,
            camera: Cell::new(camera),
            preset: Cell::new(Some(options.preset)),
            iso_azimuth: options.iso_azimuth,
            radius: Cell::new(options.radius),
            pointers: RefCell::new(Vec::new()),
            gesture: Cell::new(Gesture::Idle),
            origin: Cell::new(DVec2::ZERO),
            touch_orbit_from: Cell::new(None),
            draw: RefCell::new(Some(Box::new(draw))),
            claim: options.claim,
            on_handle: options.on_handle,
            on_view: options.on_view,
            frame: RefCell::new(None),
        });
        let weak = Rc::downgrade(&inner);
        let mut scope = Scope::new();
        *inner.frame.borrow_mut() = Some(scope.frame_loop(&weak, |inner, _| inner.draw_now()));
        inner.install(&mut scope, &weak)?;
        inner.show_preset();
        Ok(OrbitView {
            inner,
            root,
            _scope: scope,
        })
    }

    /// The widget's element (buttons, stage, hint).
    pub fn element(&self) -> &Element {
        &self.root
    }

    /// The top canvas (focus, tests).
    pub fn canvas_element(&self) -> Element {
        self.inner.canvas.borrow().top().canvas.clone().into()
    }

    /// The camera now.
    pub fn camera(&self) -> Camera {
        self.inner.camera.get()
    }

    /// The preset the view still shows, if the user has not orbited away from it.
    pub fn preset(&self) -> Option<Preset> {
        self.inner.preset.get()
    }

    /// Turns to `preset` (keeping the zoom) and redraws.
    pub fn set_preset(&self, preset: Preset) {
        self.inner.turn_to(preset);
    }

    /// A new scene extent: the camera frames it again from the current preset (iso if the
    /// user had orbited away) and redraws.
    pub fn frame_scene(&self, target: DVec3, radius: f64) {
        self.inner.radius.set(radius);
        let (w, h) = self.inner.canvas.borrow().size();
        let preset = self.inner.preset.get().unwrap_or(Preset::Iso);
        let mut camera = Camera::framing(target, radius, preset, w, h);
        turn_iso(&mut camera, preset, self.inner.iso_azimuth);
        self.inner.camera.set(camera);
        self.inner.preset.set(Some(preset));
        self.inner.show_preset();
        self.request_redraw();
    }

    /// Asks for a redraw in the next animation frame (requests coalesce).
    pub fn request_redraw(&self) {
        self.inner.request();
    }

    /// Draws now (the page's state changed and it wants the frame at once).
    pub fn redraw_now(&self) {
        self.inner.draw_now();
    }

    /// The stage may have changed size (projector mode, a layout change): refit and redraw.
    pub fn relayout(&self) {
        self.inner.relayout();
    }

    /// The preset buttons' labels in the current language.
    pub fn relocalize(&self) {
        let _ = dom::relocalize(&self.root);
        self.inner.draw_now();
    }

    /// A key the page was given: with the canvas focused, the arrows orbit and `+` / `-`
    /// zoom; `true` if taken.
    pub fn on_key(&self, event: &KeyboardEvent) -> bool {
        let canvas: Element = self.canvas_element();
        let focused = event
            .target()
            .and_then(|t| t.dyn_into::<Element>().ok())
            .is_some_and(|t| t == canvas);
        if !focused {
            return false;
        }
        let step = KEY_ORBIT_PX * if event.shift_key() { 4.0 } else { 1.0 };
        let inner = &self.inner;
        match event.key().as_str() {
            "ArrowLeft" => inner.orbit(DVec2::new(-step, 0.0)),
            "ArrowRight" => inner.orbit(DVec2::new(step, 0.0)),
            "ArrowUp" => inner.orbit(DVec2::new(0.0, -step)),
            "ArrowDown" => inner.orbit(DVec2::new(0.0, step)),
            "+" | "=" => inner.zoom(KEY_ZOOM),
            "-" | "_" => inner.zoom(1.0 / KEY_ZOOM),
            _ => return false,
        }
        inner.view_changed();
        true
    }

    /// All layers on a white background as a PNG download.
    pub fn png(&self, file: &str) {
        let flat = self.inner.canvas.borrow().flatten("#ffffff");
        if let Err(e) = flat.and_then(|c| super::png::download(&c, file)) {
            web_sys::console::warn_1(&e);
        }
    }

    /// Orbits as a drag of `delta_px` would (benchmarks, tests), redrawing in the next frame.
    pub fn orbit_by(&self, delta_px: DVec2) {
        self.inner.orbit(delta_px);
    }
}

impl<H: Copy + PartialEq + 'static> Inner<H> {
    fn install(&self, scope: &mut Scope, weak: &Weak<Inner<H>>) -> Result<(), JsValue> {
        for (preset, button) in &self.presets {
            let preset = *preset;
            scope.listen_for(button, "click", weak, move |inner, _| {
                inner.turn_to(preset);
            })?;
        }
        let stage = self.stage.clone();
        scope.listen_for(&stage, "pointerdown", weak, |inner, e| {
            if let Some(pe) = e.dyn_ref::<PointerEvent>() {
                inner.down(pe);
            }
        })?;
        scope.listen_for(&stage, "pointermove", weak, |inner, e| {
            if let Some(pe) = e.dyn_ref::<PointerEvent>() {
                inner.moved(pe);
            }
        })?;
        for (name, cancelled) in [("pointerup", false), ("pointercancel", true)] {
            scope.listen_for(&stage, name, weak, move |inner, e| {
                if let Some(pe) = e.dyn_ref::<PointerEvent>() {
                    inner.up(pe, cancelled);
                }
            })?;
        }
        scope.listen_for(&stage, "pointerleave", weak, |inner, e| {
            if let Some(pe) = e.dyn_ref::<PointerEvent>() {
                if inner.gesture.get() == Gesture::Idle && kind_of(pe) != PointerKind::Touch {
                    if let Some(on) = &inner.on_handle {
                        on(DragEvent::Leave);
                    }
                }
            }
        })?;
        scope.listen_for(&stage, "touchstart", weak, |inner, e| inner.touch_start(e))?;
        scope.listen_for(&stage, "wheel", weak, |inner, e| inner.wheel(e))?;
        scope.listen_for(&stage, "contextmenu", weak, |_, e| e.prevent_default())?;
        scope.observe_resize(&[&stage], weak, |inner| inner.relayout())?;
        Ok(())
    }

    fn request(&self) {
        if let Some(frame) = self.frame.borrow().as_ref() {
            frame.request();
        }
    }

    fn draw_now(&self) {
        self.fit_first();
        let Ok(canvas) = self.canvas.try_borrow() else {
            return;
        };
        let camera = self.camera.get();
        if let Ok(draw) = self.draw.try_borrow() {
            if let Some(draw) = draw.as_ref() {
                draw(&canvas, &camera, Ink::current());
            }
        }
    }

    /// Sizes the canvas if it never was, and frames the camera for that size, keeping its zoom
    /// (the distance scaled as the framing of the scene's sphere scales with the aspect).
    fn fit_first(&self) {
        let size = {
            let Ok(mut canvas) = self.canvas.try_borrow_mut() else {
                return;
            };
            if canvas.is_fitted() {
                return;
            }
            canvas.fit();
            canvas.size()
        };
        let mut camera = self.camera.get();
        let radius = self.radius.get();
        let framed = |w, h| Camera::framing(camera.target, radius, Preset::Iso, w, h).distance;
        camera.distance *= framed(size.0, size.1) / framed(camera.width, camera.height);
        camera.resize(size.0, size.1);
        self.camera.set(camera);
    }

    fn relayout(&self) {
        self.fit_first();
        let size = {
            let Ok(mut canvas) = self.canvas.try_borrow_mut() else {
                return;
            };
            canvas.fit();
            canvas.size()
        };
        let mut camera = self.camera.get();
        camera.resize(size.0, size.1);
        self.camera.set(camera);
        // Resizing a canvas clears it: draw at once, not a frame later.
        self.draw_now();
    }

    fn turn_to(&self, preset: Preset) {
        let mut camera = self.camera.get();
        camera.set_preset(preset);
        turn_iso(&mut camera, preset, self.iso_azimuth);
        self.camera.set(camera);
        self.preset.set(Some(preset));
        self.show_preset();
        self.request();
        if let Some(on) = &self.on_view {
            on(Some(preset));
        }
    }

    fn show_preset(&self) {
        let current = self.preset.get();
        for (p, button) in &self.presets {
            let pressed = if current == Some(*p) { "true" } else { "false" };
            if button.get_attribute("aria-pressed").as_deref() != Some(pressed) {
                let _ = button.set_attribute("aria-pressed", pressed);
            }
        }
    }

    fn orbit(&self, delta_px: DVec2) {
        let mut camera = self.camera.get();
        camera.orbit(delta_px);
        self.camera.set(camera);
        if self.preset.replace(None).is_some() {
            self.show_preset();
        }
        self.request();
    }

    fn zoom(&self, factor: f64) {
        let mut camera = self.camera.get();
        camera.zoom(factor, self.radius.get());
        self.camera.set(camera);
        self.request();
    }

    fn view_changed(&self) {
        if let Some(on) = &self.on_view {
            on(self.preset.get());
        }
    }

    fn local(&self, client: DVec2) -> DVec2 {
        client - self.origin.get()
    }

    fn measure_origin(&self) {
        if let Ok(canvas) = self.canvas.try_borrow() {
            let r = canvas.top().canvas.get_bounding_client_rect();
            self.origin.set(DVec2::new(r.left(), r.top()));
        }
    }

    fn down(&self, e: &PointerEvent) {
        let kind = kind_of(e);
        if kind == PointerKind::Mouse && e.button() != 0 {
            return;
        }
        e.prevent_default();
        if let Ok(canvas) = self.canvas.try_borrow() {
            focus_without_scroll(&canvas.top().canvas);
        }
        let at = client(e);
        let id = e.pointer_id();
        {
            let mut pointers = self.pointers.borrow_mut();
            pointers.retain(|(p, _)| *p != id);
            pointers.push((id, at));
        }
        let _ = self.stage.set_pointer_capture(id);
        match self.gesture.get() {
            Gesture::Idle => {
                self.measure_origin();
                let local = self.local(at);
                let claimed = self
                    .claim
                    .as_ref()
                    .and_then(|claim| claim(local, kind, &self.camera.get()));
                match claimed {
                    Some(handle) => {
                        self.gesture.set(Gesture::Handle { id, handle });
                        if let Some(on) = &self.on_handle {
                            on(DragEvent::Start {
                                handle,
                                at: local,
                                kind,
                            });
                        }
                    }
                    None => {
                        self.touch_orbit_from.set(
                            (kind == PointerKind::Touch)
                                .then(|| (self.camera.get(), self.preset.get())),
                        );
                        self.gesture.set(Gesture::Orbit { id, last: at });
                    }
                }
            }
            Gesture::Orbit { .. } => {
                let pointers = self.pointers.borrow();
                if let [(_, a), (_, b)] = pointers.as_slice() {
                    self.touch_orbit_from.set(None);
                    self.gesture.set(Gesture::Pinch {
                        start_px: a.distance(*b).max(1.0),
                        start_distance: self.camera.get().distance,
                    });
                }
            }
            // A third finger, or a second one while a handle is held: ignored.
            Gesture::Pinch { .. } | Gesture::Handle { .. } => {}
        }
    }

    fn moved(&self, e: &PointerEvent) {
        let id = e.pointer_id();
        let at = client(e);
        let known = {
            let mut pointers = self.pointers.borrow_mut();
            match pointers.iter_mut().find(|(p, _)| *p == id) {
                Some(slot) => {
                    slot.1 = at;
                    true
                }
                None => false,
            }
        };
        match self.gesture.get() {
            Gesture::Orbit { id: held, last } if held == id => {
                self.gesture.set(Gesture::Orbit { id, last: at });
                e.prevent_default();
                self.orbit(at - last);
            }
            Gesture::Pinch {
                start_px,
                start_distance,
            } if known => {
                e.prevent_default();
                let pointers = self.pointers.borrow();
                if let [(_, a), (_, b)] = pointers.as_slice() {
                    let mut camera = self.camera.get();
                    camera.distance = start_distance;
                    camera.zoom(a.distance(*b) / start_px, self.radius.get());
                    self.camera.set(camera);
                    self.request();
                }
            }
            Gesture::Handle { id: held, handle } if held == id => {
                e.prevent_default();
                if let Some(on) = &self.on_handle {
                    on(DragEvent::Move {
                        handle,
                        at: self.local(at),
                    });
                }
            }
            Gesture::Idle if kind_of(e) != PointerKind::Touch => {
                if let Some(on) = &self.on_handle {
                    self.measure_origin();
                    on(DragEvent::Hover(self.local(at)));
                }
            }
            _ => {}
        }
    }

    fn up(&self, e: &PointerEvent, cancelled: bool) {
        let id = e.pointer_id();
        let _ = self.stage.release_pointer_capture(id);
        let remaining: Vec<(i32, DVec2)> = {
            let mut pointers = self.pointers.borrow_mut();
            pointers.retain(|(p, _)| *p != id);
            pointers.clone()
        };
        match self.gesture.get() {
            Gesture::Handle { id: held, handle } if held == id => {
                self.gesture.set(Gesture::Idle);
                if let Some(on) = &self.on_handle {
                    on(DragEvent::End { handle, cancelled });
                }
            }
            Gesture::Orbit { id: held, .. } if held == id => {
                self.gesture.set(Gesture::Idle);
                match self.touch_orbit_from.take() {
                    // The browser took the finger to scroll the page: no orbit happened.
                    Some((camera, preset)) if cancelled => {
                        self.camera.set(camera);
                        self.preset.set(preset);
                        self.show_preset();
                        self.request();
                    }
                    _ => self.view_changed(),
                }
            }
            Gesture::Pinch { .. } => {
                // One finger left: it orbits from where it is.
                match remaining.first() {
                    Some(&(other, last)) => self.gesture.set(Gesture::Orbit { id: other, last }),
                    None => self.gesture.set(Gesture::Idle),
                }
                self.view_changed();
            }
            _ => {}
        }
        if remaining.is_empty() && !matches!(self.gesture.get(), Gesture::Handle { .. }) {
            self.gesture.set(Gesture::Idle);
        }
    }

    /// A finger that lands on a claimed handle, or a second finger (a pinch), keeps the
    /// gesture: the page must not scroll under it.
    fn touch_start(&self, e: &Event) {
        let touches = js_sys::Reflect::get(e, &JsValue::from_str("touches")).unwrap_or_default();
        let count = js_sys::Reflect::get(&touches, &JsValue::from_str("length"))
            .ok()
            .and_then(|v| v.as_f64())
            .unwrap_or(0.0);
        if count >= 2.0 {
            e.prevent_default();
            return;
        }
        let Some(claim) = self.claim.as_ref() else {
            return;
        };
        let first = js_sys::Reflect::get(&touches, &JsValue::from_f64(0.0)).unwrap_or_default();
        let coord = |name: &str| {
            js_sys::Reflect::get(&first, &JsValue::from_str(name))
                .ok()
                .and_then(|v| v.as_f64())
        };
        let (Some(x), Some(y)) = (coord("clientX"), coord("clientY")) else {
            return;
        };
        self.measure_origin();
        let local = self.local(DVec2::new(x, y));
        if claim(local, PointerKind::Touch, &self.camera.get()).is_some() {
            e.prevent_default();
        }
    }

    fn wheel(&self, e: &Event) {
        let number = |name: &str| {
            js_sys::Reflect::get(e, &JsValue::from_str(name))
                .ok()
                .and_then(|v| v.as_f64())
                .unwrap_or(0.0)
        };
        let unit = match number("deltaMode") as i32 {
            1 => WHEEL_LINE_PX,
            2 => WHEEL_PAGE_PX,
            _ => 1.0,
        };
        let delta = number("deltaY") * unit;
        if delta == 0.0 {
            return;
        }
        e.prevent_default();
        self.zoom(Camera::wheel_factor(delta));
        self.view_changed();
    }
}

/// Paints projected scene marks (lines, arrows, dots, labels, already in painter's order) on
/// `ctx`, with line widths and label sizes scaled by `ink`.
pub fn paint(ctx: &CanvasRenderingContext2d, marks: &[Mark], ink: Ink) {
    let mut color = "";
    let mut width = f64::NAN;
    let mut dashed: Option<bool> = None;
    ctx.set_line_cap("round");
    ctx.set_line_join("round");
    let label_font = ink.font(13.0, true);
    ctx.set_text_align("center");
    ctx.set_text_baseline("middle");
    for mark in marks {
        let s = mark.stroke;
        if s.color != color {
            color = s.color;
            ctx.set_stroke_style_str(color);
            ctx.set_fill_style_str(color);
        }
        let w = s.width_px * ink.line;
        if w != width && w > 0.0 {
            width = w;
            ctx.set_line_width(w);
        }
        if dashed != Some(s.dashed) {
            dashed = Some(s.dashed);
            let _ = ctx.set_line_dash(&if s.dashed {
                dash(6.0 * ink.line, 5.0 * ink.line)
            } else {
                solid()
            });
        }
        match &mark.shape {
            Shape2::Line { from, to } => {
                ctx.begin_path();
                ctx.move_to(from.x, from.y);
                ctx.line_to(to.x, to.y);
                ctx.stroke();
            }
            Shape2::Arrow { from, to, wings } => {
                ctx.begin_path();
                ctx.move_to(from.x, from.y);
                ctx.line_to(to.x, to.y);
                ctx.stroke();
                ctx.begin_path();
                ctx.move_to(wings[0].x, wings[0].y);
                ctx.line_to(to.x, to.y);
                ctx.line_to(wings[1].x, wings[1].y);
                ctx.close_path();
                ctx.fill();
                ctx.stroke();
            }
            Shape2::Dot { at, radius_px } => {
                ctx.begin_path();
                let _ = ctx.arc(at.x, at.y, radius_px * ink.line, 0.0, std::f64::consts::TAU);
                ctx.fill();
            }
            Shape2::Quad { corners, edge } => {
                ctx.begin_path();
                ctx.move_to(corners[0].x, corners[0].y);
                for c in &corners[1..] {
                    ctx.line_to(c.x, c.y);
                }
                ctx.close_path();
                ctx.fill();
                ctx.set_stroke_style_str(edge);
                ctx.stroke();
                // The edge changed the stroke: set it again for the next mark.
                color = "";
            }
            Shape2::Label { at, text } => {
                ctx.set_font(&label_font);
                // A white halo keeps the label readable over lines.
                ctx.set_stroke_style_str("rgba(255, 255, 255, 0.9)");
                ctx.set_line_width(3.0 * ink.line);
                let _ = ctx.stroke_text(text, at.x, at.y);
                let _ = ctx.fill_text(text, at.x, at.y);
                // The halo changed the stroke: set it again for the next mark.
                color = "";
                width = f64::NAN;
            }
        }
    }
    let _ = ctx.set_line_dash(&solid());
}
