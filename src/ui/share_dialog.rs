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
use crate::ui::modal::{self, Draft, Modal, Names};
use crate::view::qr_code::{qr_picture, QrPicture};

const SVG_NS: &str = "http://www.w3.org/2000/svg";

thread_local! {
    static OPEN: RefCell<Option<Modal>> = const { RefCell::new(None) };
}

/// Opens the dialog on `link`, the page's address (does nothing if it is open).
pub(crate) fn open(link: &str) -> Result<(), JsValue> {
    if modal::is_open(&OPEN) {
        return Ok(());
    }
    let window = dom::window()?;
    let draft = Draft::new(&Names {
        dialog: ("overlay-dialog share-dialog", "share-dialog"),
        title: ("share-title", ""),
        close: ("tool-button", "share-close"),
    })?;
    let body = dom::el_class("div", "share-body")?;
    show_link(&body, link)?;
    dom::append(&draft.dialog, &body)?;
    let keys = dom::Listener::capture(&window, "keydown", |event| {
        if let Some(key) = event.dyn_ref::<KeyboardEvent>() {
            on_key(key);
        }
    })?;
    modal::keep(&OPEN, draft.show(close, vec![keys])?);
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
    modal::close(&OPEN);
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
        "Tab" => modal::trap_tab(&OPEN, event),
        _ => {}
    }
}
