//! The `?` shortcut overlay: a modal dialog listing the keys it is given (the shell passes the
//! app keymap's shell keys, then the mounted page's `shortcuts()`). While it is open the rest of the app is `inert`, Tab and Shift+Tab cycle
//! inside the dialog, and `Escape`, `?`, the close button or a click on the backdrop close it
//! and give focus back to where it was.

use std::cell::RefCell;

use wasm_bindgen::prelude::*;
use web_sys::{Element, KeyboardEvent};

use crate::ui::dom;
use crate::ui::modal::{self, Draft, Modal, Names};
use crate::ui::page::Shortcut;

thread_local! {
    static OPEN: RefCell<Option<Modal>> = const { RefCell::new(None) };
}

/// Whether the overlay is showing.
pub fn is_open() -> bool {
    modal::is_open(&OPEN)
}

/// Opens the overlay (does nothing if it is open).
pub(crate) fn open(shell_keys: &[Shortcut], page_keys: &[Shortcut]) -> Result<(), JsValue> {
    if is_open() {
        return Ok(());
    }
    let draft = Draft::new(&Names {
        dialog: ("overlay-dialog", "shortcut-overlay"),
        title: ("overlay-title", "overlay-title"),
        close: ("tool-button overlay-close", "overlay-close"),
    })?;
    let dialog = &draft.dialog;
    dom::append(dialog, &dom::el_i18n("h3", "", "overlay-shell-heading")?)?;
    dom::append(dialog, &key_list(shell_keys, "shell-keys")?)?;

    dom::append(dialog, &dom::el_i18n("h3", "", "overlay-page-heading")?)?;
    if page_keys.is_empty() {
        dom::append(
            dialog,
            &dom::el_i18n("p", "overlay-empty", "overlay-page-none")?,
        )?;
    } else {
        dom::append(dialog, &key_list(page_keys, "page-keys")?)?;
    }
    dom::append(dialog, &dom::el_i18n("p", "overlay-note", "overlay-note")?)?;
    dom::append(
        dialog,
        &dom::el_i18n("p", "overlay-note", "overlay-access")?,
    )?;
    modal::keep(&OPEN, draft.show(close, Vec::new())?);
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
    modal::close(&OPEN);
}

/// A key while the overlay is open: `Escape` and `?` close it, Tab stays inside it; other
/// keys do nothing (the page underneath must not react).
pub(crate) fn on_key(event: &KeyboardEvent) -> Result<(), JsValue> {
    match event.key().as_str() {
        "Escape" | "Esc" | "?" => {
            event.prevent_default();
            close();
        }
        "Tab" => modal::trap_tab(&OPEN, event),
        _ => {}
    }
    Ok(())
}
