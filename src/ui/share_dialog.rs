//! The share dialog: the page's full address (`location.href`: the page's state is in its
//! hash) as a QR code large enough to scan from the back of a room, dark on white in every
//! mode, with the address as selectable text beside it. A modal dialog like the `?` overlay:
//! the rest of the app is `inert`, Tab stays inside, `Escape`, the Close button or a click on
//! the backdrop close it, and focus goes back to where it was. While it is open it takes every
//! key before the shell and the page (a capture listener on the window), so `Escape` closes it
//! and does not also end a presentation. The address is the one of the moment "Share" was
//! pressed: a page that rewrites its address on its own (the pendulum's time while it plays)
//! does not change a code that the room is scanning or a link it is typing.
//!
//! A wasm chunk of its own with the QR encoder ([`crate::view::qr_code`]), loaded by
//! [`crate::ui::share`].

use std::cell::RefCell;

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::{Element, KeyboardEvent};

use crate::ui::dom;
use crate::view::qr_code::{qr_picture, QrPicture};

const SVG_NS: &str = "http://www.w3.org/2000/svg";

struct Open {
    backdrop: Element,
    dialog: Element,
    previous_focus: Option<Element>,
    _listeners: Vec<dom::Listener>,
}

thread_local! {
    static OPEN: RefCell<Option<Open>> = const { RefCell::new(None) };
}

fn is_open() -> bool {
    OPEN.with(|open| open.try_borrow().map(|o| o.is_some()).unwrap_or(false))
}

/// Opens the dialog on `link`, the page's address (does nothing if it is open).
pub(crate) fn open(link: &str) -> Result<(), JsValue> {
    if is_open() {
        return Ok(());
    }
    let window = dom::window()?;
    let document = dom::document()?;
    let previous_focus = document.active_element();

    let backdrop = dom::el_class("div", "overlay-backdrop")?;
    let dialog = dom::el_class("div", "overlay-dialog share-dialog")?;
    dialog.set_attribute("role", "dialog")?;
    dialog.set_attribute("aria-modal", "true")?;
    dialog.set_attribute("aria-labelledby", "share-title")?;
    dialog.set_attribute("data-testid", "share-dialog")?;
    dialog.set_attribute("tabindex", "-1")?;

    let head = dom::el_class("div", "overlay-head")?;
    let title = dom::el_i18n("h2", "", "share-title")?;
    title.set_id("share-title");
    dom::append(&head, &title)?;
    let close_button = dom::el_i18n("button", "tool-button", "overlay-close")?;
    close_button.set_attribute("type", "button")?;
    close_button.set_attribute("data-testid", "share-close")?;
    dom::append(&head, &close_button)?;
    dom::append(&dialog, &head)?;

    let body = dom::el_class("div", "share-body")?;
    show_link(&body, link)?;
    dom::append(&dialog, &body)?;
    dom::append(&backdrop, &dialog)?;

    document
        .body()
        .ok_or_else(|| JsValue::from_str("no body"))?
        .append_child(&backdrop)?;
    if let Some(app) = document.get_element_by_id("app") {
        app.set_attribute("inert", "")?;
        app.set_attribute("aria-hidden", "true")?;
    }

    let listeners = vec![
        dom::Listener::new(&close_button, "click", |_| close())?,
        dom::Listener::new(&backdrop, "click", {
            let backdrop = backdrop.clone();
            move |event| {
                let on_backdrop = event
                    .target()
                    .and_then(|t| t.dyn_into::<Element>().ok())
                    .is_some_and(|t| t == backdrop);
                if on_backdrop {
                    close();
                }
            }
        })?,
        dom::Listener::capture(&window, "keydown", |event| {
            if let Some(key) = event.dyn_ref::<KeyboardEvent>() {
                on_key(key);
            }
        })?,
    ];
    dom::focus(&close_button);
    OPEN.with(|open| {
        if let Ok(mut open) = open.try_borrow_mut() {
            *open = Some(Open {
                backdrop,
                dialog,
                previous_focus,
                _listeners: listeners,
            });
        }
    });
    Ok(())
}

/// Fills the dialog's `body` with the code of `link` (or why there is none) and the link as
/// text.
fn show_link(body: &Element, link: &str) -> Result<(), JsValue> {
    match qr_picture(link) {
        Some(picture) => dom::append(body, &qr_svg(&picture)?)?,
        None => dom::append(
            body,
            &dom::el_i18n("p", "share-too-long", "share-too-long")?,
        )?,
    }
    let text = dom::el_class("div", "share-text")?;
    dom::append(
        &text,
        &dom::el_i18n("p", "share-link-label", "share-link-label")?,
    )?;
    let address = dom::el_text("p", "share-link", link)?;
    address.set_attribute("data-testid", "share-link")?;
    address.set_attribute("translate", "no")?;
    dom::append(&text, &address)?;
    dom::append(body, &text)
}

/// The code as an `<svg>`: a white square of `side` modules and the dark modules' path, drawn
/// with crisp edges; its size comes from the stylesheet.
fn qr_svg(picture: &QrPicture) -> Result<Element, JsValue> {
    let document = dom::document()?;
    let svg = document.create_element_ns(Some(SVG_NS), "svg")?;
    svg.set_attribute("class", "share-qr")?;
    svg.set_attribute("data-testid", "share-qr")?;
    svg.set_attribute("viewBox", &format!("0 0 {0} {0}", picture.side))?;
    svg.set_attribute("shape-rendering", "crispEdges")?;
    svg.set_attribute("role", "img")?;
    dom::set_i18n_attrs(&svg, &[("aria-label", "share-qr-label")])?;
    let light = document.create_element_ns(Some(SVG_NS), "rect")?;
    light.set_attribute("width", &picture.side.to_string())?;
    light.set_attribute("height", &picture.side.to_string())?;
    light.set_attribute("fill", "#fff")?;
    svg.append_child(&light)?;
    let dark = document.create_element_ns(Some(SVG_NS), "path")?;
    dark.set_attribute("d", &picture.dark_path)?;
    dark.set_attribute("fill", "#000")?;
    svg.append_child(&dark)?;
    Ok(svg)
}

/// Closes the dialog and gives focus back.
fn close() {
    let Some(open) = OPEN.with(|open| open.try_borrow_mut().ok().and_then(|mut o| o.take())) else {
        return;
    };
    open.backdrop.remove();
    if let Some(app) = dom::document()
        .ok()
        .and_then(|d| d.get_element_by_id("app"))
    {
        let _ = app.remove_attribute("inert");
        let _ = app.remove_attribute("aria-hidden");
    }
    if let Some(previous) = open.previous_focus {
        dom::focus(&previous);
    }
}

/// Every key while the dialog is open: `Escape` closes it, Tab stays inside it, and no key
/// reaches the shell or the page underneath (their defaults, such as copying the selected
/// address, stay).
fn on_key(event: &KeyboardEvent) {
    event.stop_immediate_propagation();
    match event.key().as_str() {
        "Escape" | "Esc" => {
            event.prevent_default();
            close();
        }
        "Tab" => trap_tab(event),
        _ => {}
    }
}

/// Keeps Tab / Shift+Tab cycling through the dialog's focusable elements.
fn trap_tab(event: &KeyboardEvent) {
    let Some(dialog) = OPEN.with(|open| {
        open.try_borrow()
            .ok()
            .and_then(|o| o.as_ref().map(|o| o.dialog.clone()))
    }) else {
        return;
    };
    let focusable = dom::matching(&dialog, "button, a[href], [tabindex]:not([tabindex='-1'])")
        .unwrap_or_default();
    let (Some(first), Some(last)) = (focusable.first(), focusable.last()) else {
        event.prevent_default();
        dom::focus(&dialog);
        return;
    };
    let active = dom::document().ok().and_then(|d| d.active_element());
    let inside = active.as_ref().is_some_and(|a| dialog.contains(Some(a)));
    if event.shift_key() {
        if !inside || active.as_ref() == Some(first) {
            event.prevent_default();
            dom::focus(last);
        }
    } else if !inside || active.as_ref() == Some(last) {
        event.prevent_default();
        dom::focus(first);
    }
}
