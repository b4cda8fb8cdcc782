//! The `?` shortcut overlay: a modal dialog listing the keys it is given (the shell passes the
//! app keymap's shell keys, then the mounted page's `shortcuts()`). While it is open the rest of the app is `inert`, Tab and Shift+Tab cycle
//! inside the dialog, and `Escape`, `?`, the close button or a click on the backdrop close it
//! and give focus back to where it was.

use std::cell::RefCell;

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::{Element, KeyboardEvent};

use crate::ui::dom;
use crate::ui::page::Shortcut;

struct Open {
    backdrop: Element,
    dialog: Element,
    previous_focus: Option<Element>,
    _listeners: Vec<dom::Listener>,
}

thread_local! {
    static OPEN: RefCell<Option<Open>> = const { RefCell::new(None) };
}

/// Whether the overlay is showing.
pub fn is_open() -> bool {
    OPEN.with(|open| open.try_borrow().map(|o| o.is_some()).unwrap_or(false))
}

/// Opens the overlay (does nothing if it is open).
pub(crate) fn open(shell_keys: &[Shortcut], page_keys: &[Shortcut]) -> Result<(), JsValue> {
    if is_open() {
        return Ok(());
    }
    let document = dom::document()?;
    let previous_focus = document.active_element();

    let backdrop = dom::el_class("div", "overlay-backdrop")?;
    let dialog = dom::el_class("div", "overlay-dialog")?;
    dialog.set_attribute("role", "dialog")?;
    dialog.set_attribute("aria-modal", "true")?;
    dialog.set_attribute("aria-labelledby", "overlay-title")?;
    dialog.set_attribute("data-testid", "shortcut-overlay")?;
    dialog.set_attribute("tabindex", "-1")?;

    let head = dom::el_class("div", "overlay-head")?;
    let title = dom::el_i18n("h2", "overlay-title", "overlay-title")?;
    title.set_id("overlay-title");
    dom::append(&head, &title)?;
    let close_button = dom::el_i18n("button", "tool-button overlay-close", "overlay-close")?;
    close_button.set_attribute("type", "button")?;
    close_button.set_attribute("data-testid", "overlay-close")?;
    dom::append(&head, &close_button)?;
    dom::append(&dialog, &head)?;

    dom::append(&dialog, &dom::el_i18n("h3", "", "overlay-shell-heading")?)?;
    dom::append(&dialog, &key_list(shell_keys, "shell-keys")?)?;

    dom::append(&dialog, &dom::el_i18n("h3", "", "overlay-page-heading")?)?;
    if page_keys.is_empty() {
        dom::append(
            &dialog,
            &dom::el_i18n("p", "overlay-empty", "overlay-page-none")?,
        )?;
    } else {
        dom::append(&dialog, &key_list(page_keys, "page-keys")?)?;
    }
    dom::append(&dialog, &dom::el_i18n("p", "overlay-note", "overlay-note")?)?;
    dom::append(
        &dialog,
        &dom::el_i18n("p", "overlay-note", "overlay-access")?,
    )?;
    dom::append(&backdrop, &dialog)?;

    let body = document
        .body()
        .ok_or_else(|| JsValue::from_str("no body"))?;
    body.append_child(&backdrop)?;
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

/// `<dl>` of keys (`<kbd>`) and what they do.
fn key_list(shortcuts: &[Shortcut], testid: &str) -> Result<Element, JsValue> {
    let list = dom::el_class("dl", "key-list")?;
    list.set_attribute("data-testid", testid)?;
    for shortcut in shortcuts {
        let keys = dom::el("dt")?;
        dom::append(&keys, &dom::el_text("kbd", "", shortcut.keys)?)?;
        dom::append(&list, &keys)?;
        dom::append(&list, &dom::el_i18n("dd", "", shortcut.message_id)?)?;
    }
    Ok(list)
}

/// Closes the overlay and gives focus back.
pub(crate) fn close() {
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

/// A key while the overlay is open: `Escape` and `?` close it, Tab stays inside it; other
/// keys do nothing (the page underneath must not react).
pub(crate) fn on_key(event: &KeyboardEvent) -> Result<(), JsValue> {
    match event.key().as_str() {
        "Escape" | "Esc" | "?" => {
            event.prevent_default();
            close();
        }
        "Tab" => trap_tab(event)?,
        _ => {}
    }
    Ok(())
}

/// Keeps Tab / Shift+Tab cycling through the dialog's focusable elements.
fn trap_tab(event: &KeyboardEvent) -> Result<(), JsValue> {
    let Some(dialog) = OPEN.with(|open| {
        open.try_borrow()
            .ok()
            .and_then(|o| o.as_ref().map(|o| o.dialog.clone()))
    }) else {
        return Ok(());
    };
    let focusable = dom::matching(&dialog, "button, a[href], [tabindex]:not([tabindex='-1'])")?;
    let (Some(first), Some(last)) = (focusable.first(), focusable.last()) else {
        event.prevent_default();
        dom::focus(&dialog);
        return Ok(());
    };
    let active = dom::document()?.active_element();
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
    Ok(())
}
