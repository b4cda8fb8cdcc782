//! A modal dialog over the app, as the `?` overlay and the share dialog are: a backdrop holding
//! the dialog, whose head is its title and a Close button. While it is open the rest of the app
//! is `inert` (and hidden from screen readers), Tab and Shift+Tab stay inside the dialog
//! (`trap_tab`), and the Close button or a click on the backdrop closes it; closing gives
//! focus back to where it was.

use std::cell::RefCell;
use std::thread::LocalKey;

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::{Element, KeyboardEvent};

use crate::ui::dom;

/// The names of a dialog's parts.
pub(crate) struct Names {
    /// The dialog's classes and `data-testid`.
    pub dialog: (&'static str, &'static str),
    /// The title's Fluent message id, also its element id (the dialog's `aria-labelledby`),
    /// and its classes.
    pub title: (&'static str, &'static str),
    /// The Close button's classes and `data-testid`.
    pub close: (&'static str, &'static str),
}

/// A dialog being built: its head is in; the caller appends the rest to `Draft::dialog`,
/// then shows it.
pub(crate) struct Draft {
    /// The dialog element.
    pub dialog: Element,
    backdrop: Element,
    close_button: Element,
    previous_focus: Option<Element>,
}

/// A dialog on the page, until `Modal::close`.
pub(crate) struct Modal {
    backdrop: Element,
    dialog: Element,
    previous_focus: Option<Element>,
    _listeners: Vec<dom::Listener>,
}

impl Draft {
    /// The backdrop and the dialog with its head, not on the page yet; the element that has
    /// the focus now gets it back when the dialog closes.
    pub fn new(names: &Names) -> Result<Draft, JsValue> {
        let previous_focus = dom::document()?.active_element();
        let backdrop = dom::el_class("div", "overlay-backdrop")?;
        let (dialog_class, dialog_testid) = names.dialog;
        let (title_id, title_class) = names.title;
        let (close_class, close_testid) = names.close;
        let dialog = dom::el_class("div", dialog_class)?;
        dialog.set_attribute("role", "dialog")?;
        dialog.set_attribute("aria-modal", "true")?;
        dialog.set_attribute("aria-labelledby", title_id)?;
        dialog.set_attribute("data-testid", dialog_testid)?;
        dialog.set_attribute("tabindex", "-1")?;

        let head = dom::el_class("div", "overlay-head")?;
        let title = dom::el_i18n("h2", title_class, title_id)?;
        title.set_id(title_id);
        dom::append(&head, &title)?;
        let close_button = dom::el_i18n("button", close_class, "overlay-close")?;
        close_button.set_attribute("type", "button")?;
        close_button.set_attribute("data-testid", close_testid)?;
        dom::append(&head, &close_button)?;
        dom::append(&dialog, &head)?;
        Ok(Draft {
            dialog,
            backdrop,
            close_button,
            previous_focus,
        })
    }

    /// Puts the dialog on the page over the inert app and focuses its Close button. The Close
    /// button and a click on the backdrop call `close`; `more` listeners live as long as the
    /// dialog.
    pub fn show(self, close: fn(), more: Vec<dom::Listener>) -> Result<Modal, JsValue> {
        let Draft {
            dialog,
            backdrop,
            close_button,
            previous_focus,
        } = self;
        dom::append(&backdrop, &dialog)?;
        let document = dom::document()?;
        document
            .body()
            .ok_or_else(|| JsValue::from_str("no body"))?
            .append_child(&backdrop)?;
        if let Some(app) = document.get_element_by_id("app") {
            app.set_attribute("inert", "")?;
            app.set_attribute("aria-hidden", "true")?;
        }
        let mut listeners = vec![
            dom::Listener::new(&close_button, "click", move |_| close())?,
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
        listeners.extend(more);
        dom::focus(&close_button);
        Ok(Modal {
            backdrop,
            dialog,
            previous_focus,
            _listeners: listeners,
        })
    }
}

impl Modal {
    /// Takes the dialog off the page, lets the app be used again and gives the focus back.
    pub fn close(self) {
        self.backdrop.remove();
        if let Some(app) = dom::document()
            .ok()
            .and_then(|d| d.get_element_by_id("app"))
        {
            let _ = app.remove_attribute("inert");
            let _ = app.remove_attribute("aria-hidden");
        }
        if let Some(previous) = self.previous_focus {
            dom::focus(&previous);
        }
    }
}

/// Where a dialog keeps itself while it is open: a `thread_local!` of its module.
pub(crate) type Slot = LocalKey<RefCell<Option<Modal>>>;

/// Whether the dialog of `slot` is open.
pub(crate) fn is_open(slot: &'static Slot) -> bool {
    slot.with(|open| open.try_borrow().map(|o| o.is_some()).unwrap_or(false))
}

/// Keeps `modal` in `slot` until `close`.
pub(crate) fn keep(slot: &'static Slot, modal: Modal) {
    slot.with(|open| {
        if let Ok(mut open) = open.try_borrow_mut() {
            *open = Some(modal);
        }
    });
}

/// Closes the dialog of `slot`, if it is open (`Modal::close`).
pub(crate) fn close(slot: &'static Slot) {
    if let Some(open) = slot.with(|open| open.try_borrow_mut().ok().and_then(|mut o| o.take())) {
        open.close();
    }
}

/// Tab or Shift+Tab while the dialog of `slot` is open: keeps the focus cycling through its
/// focusable elements.
pub(crate) fn trap_tab(slot: &'static Slot, event: &KeyboardEvent) {
    let dialog = slot.with(|open| {
        open.try_borrow()
            .ok()
            .and_then(|o| o.as_ref().map(|o| o.dialog.clone()))
    });
    let Some(dialog) = dialog else {
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
