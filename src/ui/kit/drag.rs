//! Pointer drags for mouse, pen and touch alike (Pointer Events with `setPointerCapture`,
//! `pointercancel`), with a page that still scrolls under a finger.
//!
//! The listeners sit on the stage element that holds a widget's canvases. The canvases take
//! no pointer events (`pointer-events: none`, the page's CSS); the stage has
//! `touch-action: manipulation`, so a swipe that starts anywhere on the widget scrolls the page
//! as usual; only the handles (the draggable parts, given as [`HandleShape`]s with
//! [`Drag::set_handles`]) are covered by small overlay elements with `touch-action: none`, so
//! a finger that lands on a handle drags it instead. A short still touch elsewhere is a
//! [`DragEvent::Tap`]. Mouse and pen presses anywhere are offered to the widget's hit test
//! (a mouse cannot scroll by dragging anyway).

use std::cell::{Cell, RefCell};
use std::rc::Rc;

use glam::DVec2;
use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::{Element, Event, HtmlElement, PointerEvent};

use crate::ui::dom::{self, Listener};
use crate::ui::schedule::now_ms;
use crate::view::drag::{is_tap, HandleShape};

/// What kind of pointer.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PointerKind {
    Mouse,
    Pen,
    Touch,
}

impl PointerKind {
    fn of(e: &PointerEvent) -> PointerKind {
        match e.pointer_type().as_str() {
            "mouse" => PointerKind::Mouse,
            "pen" => PointerKind::Pen,
            _ => PointerKind::Touch,
        }
    }

    /// Touch and pen get wider hit targets than a mouse.
    pub fn is_coarse(self) -> bool {
        self != PointerKind::Mouse
    }
}

/// What the widget hears, positions in CSS px of the surface element.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum DragEvent<H> {
    /// A mouse or pen moving with nothing held.
    Hover(DVec2),
    /// The mouse left the stage with nothing held.
    Leave,
    /// A press on a handle (for a mouse or pen: wherever the hit test said so).
    Start {
        handle: H,
        at: DVec2,
        kind: PointerKind,
    },
    Move {
        handle: H,
        at: DVec2,
    },
    /// The drag ended (`cancelled`: the browser took the pointer away).
    End {
        handle: H,
        cancelled: bool,
    },
    /// A short, still touch that did not start on a handle.
    Tap {
        at: DVec2,
    },
}

struct Inner<H> {
    stage: Element,
    surface: Element,
    active: Cell<Option<(i32, H)>>,
    /// A touch that may become a tap: pointer id, where, when.
    maybe_tap: Cell<Option<(i32, DVec2, f64)>>,
    overlay: RefCell<Vec<HtmlElement>>,
    /// The style values last written to each overlay element (only changes are written).
    written: RefCell<Vec<[String; 7]>>,
    /// The surface's offset in the stage's padding box, measured once per layout (a
    /// `getBoundingClientRect` after the frame's writes would force a synchronous layout).
    offset: Cell<Option<DVec2>>,
}

/// A stage listener's body.
type Handler<H> = Box<dyn Fn(&Inner<H>, &PointerEvent)>;

/// Pointer drags on one stage; listeners and overlay elements go away on drop.
pub struct Drag<H: Copy + PartialEq + 'static> {
    inner: Rc<Inner<H>>,
    _listeners: Vec<Listener>,
}

/// The event's client position, CSS px (fractional where the browser gives it).
pub fn client(e: &PointerEvent) -> DVec2 {
    let coord = |name: &str, fallback: i32| {
        js_sys::Reflect::get(e, &JsValue::from_str(name))
            .ok()
            .and_then(|v| v.as_f64())
            .unwrap_or(f64::from(fallback))
    };
    DVec2::new(
        coord("clientX", e.client_x()),
        coord("clientY", e.client_y()),
    )
}

/// The pointer's position on `surface`, CSS px (fractional where the browser gives it).
fn local(surface: &Element, e: &PointerEvent) -> DVec2 {
    let r = surface.get_bounding_client_rect();
    client(e) - DVec2::new(r.left(), r.top())
}

impl<H: Copy + PartialEq + 'static> Drag<H> {
    /// Listens on `stage`; positions are relative to `surface` (the widget's top canvas).
    /// `hit(at, kind)` says which handle a press grabs (`None`: nothing; for a touch, only
    /// real handles should answer, or the page could not scroll); `on` hears the events.
    pub fn attach(
        stage: &Element,
        surface: &Element,
        hit: impl Fn(DVec2, PointerKind) -> Option<H> + 'static,
        on: impl Fn(DragEvent<H>) + 'static,
    ) -> Result<Drag<H>, JsValue> {
        if let Some(s) = stage.dyn_ref::<HtmlElement>() {
            s.style().set_property("touch-action", "manipulation")?;
        }
        let inner = Rc::new(Inner {
            stage: stage.clone(),
            surface: surface.clone(),
            active: Cell::new(None),
            maybe_tap: Cell::new(None),
            overlay: RefCell::new(Vec::new()),
            written: RefCell::new(Vec::new()),
            offset: Cell::new(None),
        });
        let hit = Rc::new(hit);
        let on = Rc::new(on);
        let mut listeners = Vec::new();
        let pointer = |f: Handler<H>| {
            let inner = inner.clone();
            move |e: Event| {
                if let Some(pe) = e.dyn_ref::<PointerEvent>() {
                    f(&inner, pe);
                }
            }
        };
        {
            let (hit, on) = (hit.clone(), on.clone());
            listeners.push(Listener::new(
                stage,
                "pointerdown",
                pointer(Box::new(move |s, e| {
                    let kind = PointerKind::of(e);
                    if !e.is_primary() || (kind == PointerKind::Mouse && e.button() != 0) {
                        return;
                    }
                    let at = local(&s.surface, e);
                    let grabbed = hit(at, kind);
                    match grabbed {
                        Some(handle) => {
                            e.prevent_default();
                            s.maybe_tap.set(None);
                            let _ = s.stage.set_pointer_capture(e.pointer_id());
                            s.active.set(Some((e.pointer_id(), handle)));
                            set_cursor(&s.stage, "grabbing");
                            on(DragEvent::Start { handle, at, kind });
                        }
                        None if kind == PointerKind::Touch => {
                            s.maybe_tap.set(Some((e.pointer_id(), at, now_ms())));
                        }
                        None => {}
                    }
                })),
            )?);
        }
        {
            let on = on.clone();
            listeners.push(Listener::new(
                stage,
                "pointermove",
                pointer(Box::new(move |s, e| match s.active.get() {
                    Some((id, handle)) if id == e.pointer_id() => {
                        e.prevent_default();
                        on(DragEvent::Move {
                            handle,
                            at: local(&s.surface, e),
                        });
                    }
                    None if PointerKind::of(e) != PointerKind::Touch => {
                        on(DragEvent::Hover(local(&s.surface, e)));
                    }
                    _ => {}
                })),
            )?);
        }
        for (name, cancelled) in [
            ("pointerup", false),
            ("pointercancel", true),
            ("lostpointercapture", true),
        ] {
            let on = on.clone();
            listeners.push(Listener::new(
                stage,
                name,
                pointer(Box::new(move |s, e| {
                    let id = e.pointer_id();
                    if let Some((active, handle)) = s.active.get() {
                        if active == id {
                            s.active.set(None);
                            let _ = s.stage.release_pointer_capture(id);
                            set_cursor(&s.stage, "");
                            on(DragEvent::End { handle, cancelled });
                        }
                        return;
                    }
                    if let Some((tap_id, down, t0)) = s.maybe_tap.take() {
                        if tap_id == id && !cancelled {
                            let at = local(&s.surface, e);
                            if is_tap(down, at, now_ms() - t0) {
                                on(DragEvent::Tap { at });
                            }
                        }
                    }
                })),
            )?);
        }
        {
            let on = on.clone();
            listeners.push(Listener::new(
                stage,
                "pointerleave",
                pointer(Box::new(move |s, e| {
                    if s.active.get().is_none() && PointerKind::of(e) != PointerKind::Touch {
                        on(DragEvent::Leave);
                    }
                })),
            )?);
        }
        // A long press on a phone must not open the context menu over a widget.
        listeners.push(Listener::new(stage, "contextmenu", |e: Event| {
            e.prevent_default()
        })?);
        Ok(Drag {
            inner,
            _listeners: listeners,
        })
    }

    /// The handle being dragged, if any.
    pub fn active(&self) -> Option<H> {
        self.inner.active.get().map(|(_, h)| h)
    }

    /// Places the touch overlay over `shapes` (CSS px of the surface): a touch that lands
    /// inside one drags; anywhere else it scrolls the page.
    pub fn set_handles(&self, shapes: &[HandleShape]) {
        let mut overlay = self.inner.overlay.borrow_mut();
        while overlay.len() < shapes.len() {
            let Ok(el) = dom::el_class("div", "kit-handle") else {
                return;
            };
            let _ = el.set_attribute("aria-hidden", "true");
            let _ = dom::append(&self.inner.stage, &el);
            let Ok(el) = el.dyn_into::<HtmlElement>() else {
                return;
            };
            let st = el.style();
            for (k, v) in [
                ("position", "absolute"),
                ("touch-action", "none"),
                ("z-index", "2"),
                ("-webkit-tap-highlight-color", "transparent"),
            ] {
                let _ = st.set_property(k, v);
            }
            overlay.push(el);
        }
        let offset = match self.inner.offset.get() {
            Some(o) => o,
            None => {
                // The surface may sit inside the stage's border: offset by its position.
                let s = self.inner.stage.get_bounding_client_rect();
                let c = self.inner.surface.get_bounding_client_rect();
                let o = DVec2::new(
                    c.left() - s.left() - f64::from(self.inner.stage.client_left()),
                    c.top() - s.top() - f64::from(self.inner.stage.client_top()),
                );
                self.inner.offset.set(Some(o));
                o
            }
        };
        let mut written = self.inner.written.borrow_mut();
        written.resize_with(overlay.len(), Default::default);
        for ((i, el), last) in overlay.iter().enumerate().zip(written.iter_mut()) {
            let next: [String; 7] = match shapes.get(i) {
                Some(shape) => {
                    let b = shape.overlay_box();
                    [
                        "block".to_string(),
                        format!("{:.1}px", b.left + offset.x),
                        format!("{:.1}px", b.top + offset.y),
                        format!("{:.1}px", b.width),
                        format!("{:.1}px", b.height),
                        format!("{:.1}px", b.radius),
                        format!("rotate({:.4}rad)", b.angle_rad),
                    ]
                }
                None => {
                    let mut hidden: [String; 7] = last.clone();
                    hidden[0] = "none".to_string();
                    hidden
                }
            };
            let st = el.style();
            for (k, (value, prev)) in OVERLAY_PROPS.iter().zip(next.iter().zip(last.iter())) {
                if value != prev {
                    let _ = st.set_property(k, value);
                }
            }
            *last = next;
        }
    }

    /// The stage or surface moved or changed size (a layout): the next
    /// [`Drag::set_handles`] measures the surface's offset again.
    pub fn relayout(&self) {
        self.inner.offset.set(None);
    }

    /// The stage's cursor while nothing is held (`""`: the stylesheet's).
    pub fn set_hover_cursor(&self, cursor: &str) {
        if self.inner.active.get().is_none() {
            set_cursor(&self.inner.stage, cursor);
        }
    }
}

/// The overlay style properties [`Drag::set_handles`] writes, in its value order.
const OVERLAY_PROPS: [&str; 7] = [
    "display",
    "left",
    "top",
    "width",
    "height",
    "border-radius",
    "transform",
];

fn set_cursor(stage: &Element, cursor: &str) {
    if let Some(s) = stage.dyn_ref::<HtmlElement>() {
        let style = s.style();
        let _ = if cursor.is_empty() {
            style.remove_property("cursor").map(|_| ())
        } else {
            style.set_property("cursor", cursor)
        };
    }
}

impl<H: Copy + PartialEq + 'static> Drop for Drag<H> {
    fn drop(&mut self) {
        for el in self.inner.overlay.borrow_mut().drain(..) {
            el.remove();
        }
    }
}
