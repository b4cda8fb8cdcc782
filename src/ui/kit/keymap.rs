//! The one keymap of the app: which key does what, where, and the list the `?` overlay shows.
//!
//! - Shell keys ([`SHELL`]: `?`, `P`, `L`, `Esc` for the overlay) work everywhere except while
//!   the user types in a field (input, textarea, select, contenteditable).
//! - Page keys ([`crate::ui::page::Page::on_key`], and the stepper's [`STEPPER`]) act only
//!   when the page itself has focus: the page body (nothing focused, `<main>`, or any
//!   non-control element in it) or a page canvas (`tabindex="0"`, with a visible focus ring).
//!   Never while a control has focus (button, input, select, textarea, link, summary, an ARIA
//!   widget role): there Space, Enter and the arrows belong to the control, and a focused Reset
//!   button must not let the arrow keys move the arm. A page whose held keys drive something
//!   (the pilot pages) also takes those keys over a control that is not a text entry
//!   ([`page_may_take_over_control`]).
//! - Keys with Ctrl, Alt or Meta are the browser's (print, find, reload...), never ours.
//! - Presenter remotes send PageUp/PageDown: a page that steps takes them; elsewhere the shell
//!   moves to the previous/next section of the page, and past either end to the neighbouring
//!   drill ([`crate::ui::section_keys`]). While a lesson is presented its keys come first,
//!   whatever has focus (`crate::ui::lesson_bar`): PageDown / → next, PageUp / ← back, `b` /
//!   `.` black the screen, Esc ends; in a text field being edited ← and → stay the caret's.

use wasm_bindgen::JsCast;
use web_sys::{Element, EventTarget, HtmlElement, KeyboardEvent};

use crate::ui::page::Shortcut;

/// A key of the shell.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ShellKey {
    /// `?`: the shortcut list.
    Help,
    /// `p`: projector mode.
    Projector,
    /// `l`: the other language.
    Lang,
}

/// The shell's keys, as the overlay lists them (`Esc` closes the overlay).
pub const SHELL: &[Shortcut] = &[
    Shortcut {
        keys: "?",
        message_id: "key-help",
    },
    Shortcut {
        keys: "P",
        message_id: "key-projector",
    },
    Shortcut {
        keys: "L",
        message_id: "key-lang",
    },
    Shortcut {
        keys: "Esc",
        message_id: "key-escape",
    },
    Shortcut {
        keys: "PgDn / PgUp",
        message_id: "key-sections",
    },
];

/// One key of a page's list: the key as shown and the Fluent id of what it does.
pub const fn key(keys: &'static str, message_id: &'static str) -> Shortcut {
    Shortcut { keys, message_id }
}

/// The stepper's keys, then the page's `own` keys.
pub fn with_stepper(own: &[Shortcut]) -> Vec<Shortcut> {
    STEPPER.iter().chain(own).copied().collect()
}

/// The stepper's keys (`crate::ui::kit::stepper`); a page that has a stepper lists them with
/// its own.
pub const STEPPER: &[Shortcut] = &[
    Shortcut {
        keys: "→  PageDown",
        message_id: "kit-stepper-key-step",
    },
    Shortcut {
        keys: "←  PageUp",
        message_id: "kit-stepper-key-back",
    },
    Shortcut {
        keys: "Space",
        message_id: "kit-stepper-key-run",
    },
    Shortcut {
        keys: "Home  End",
        message_id: "kit-stepper-key-ends",
    },
    Shortcut {
        keys: "r",
        message_id: "kit-stepper-key-reset",
    },
];

/// Whether a modifier that makes the key the browser's is held.
pub fn has_command_modifier(event: &KeyboardEvent) -> bool {
    event.ctrl_key() || event.meta_key() || event.alt_key()
}

/// The shell key `event` is, if any (not while typing, not with Ctrl/Alt/Meta).
pub fn shell_key(event: &KeyboardEvent) -> Option<ShellKey> {
    if has_command_modifier(event) || event.default_prevented() || is_typing(event.target()) {
        return None;
    }
    let plain = !event.shift_key();
    match event.key().as_str() {
        "?" => Some(ShellKey::Help),
        "p" | "P" if plain => Some(ShellKey::Projector),
        "l" | "L" if plain => Some(ShellKey::Lang),
        _ => None,
    }
}

/// Whether a page may act on `event`: no Ctrl/Alt/Meta, not handled yet, and the focus is on
/// the page body or a page canvas, not on a control.
pub fn page_may_take(event: &KeyboardEvent) -> bool {
    !has_command_modifier(event) && !event.default_prevented() && !is_control(event.target())
}

/// Whether a page that drives something with held keys may take `event` although a control
/// has focus ([`crate::ui::page::Page::on_key_over_control`]): no Ctrl/Alt/Meta, not handled
/// yet, a control that is not a text entry (a button, tab, check box, slider, select), and no
/// dialog open.
pub fn page_may_take_over_control(event: &KeyboardEvent) -> bool {
    !has_command_modifier(event)
        && !event.default_prevented()
        && is_control(event.target())
        && !is_text_entry(event.target())
        && !crate::ui::overlay::is_open()
        && !dialog_open()
}

/// Whether a modal `<dialog>` or an element with `aria-modal="true"` is open.
pub fn dialog_open() -> bool {
    web_sys::window()
        .and_then(|w| w.document())
        .and_then(|d| {
            d.query_selector("dialog[open], [aria-modal=\"true\"]:not([hidden])")
                .ok()
                .flatten()
        })
        .is_some()
}

/// Input types whose keys edit a value as text.
const TEXT_INPUT_TYPES: &[&str] = &[
    "text",
    "number",
    "search",
    "email",
    "url",
    "tel",
    "password",
    "date",
    "time",
    "datetime-local",
    "month",
    "week",
];

/// Whether `target` is a field being edited as text: a text-like `<input>` (text, number,
/// search, ...), a `<textarea>` or contenteditable. Check boxes, sliders, selects and
/// buttons are not.
pub fn is_text_entry(target: Option<EventTarget>) -> bool {
    let Some(element) = target.and_then(|t| t.dyn_into::<Element>().ok()) else {
        return false;
    };
    match element.tag_name().to_ascii_lowercase().as_str() {
        "textarea" => true,
        "input" => {
            let kind = element
                .get_attribute("type")
                .unwrap_or_default()
                .to_ascii_lowercase();
            kind.is_empty() || TEXT_INPUT_TYPES.contains(&kind.as_str())
        }
        _ => element
            .dyn_ref::<HtmlElement>()
            .is_some_and(|h| h.is_content_editable()),
    }
}

/// Whether a key event comes from a place where the user types text (input, textarea,
/// select, contenteditable).
pub fn is_typing(target: Option<EventTarget>) -> bool {
    let Some(element) = target.and_then(|t| t.dyn_into::<Element>().ok()) else {
        return false;
    };
    let tag = element.tag_name().to_ascii_lowercase();
    matches!(tag.as_str(), "input" | "textarea" | "select")
        || element
            .dyn_ref::<HtmlElement>()
            .is_some_and(|h| h.is_content_editable())
}

/// ARIA roles of widgets that handle keys themselves.
const CONTROL_ROLES: &[&str] = &[
    "button",
    "checkbox",
    "combobox",
    "link",
    "listbox",
    "menuitem",
    "option",
    "radio",
    "scrollbar",
    "slider",
    "spinbutton",
    "switch",
    "tab",
    "textbox",
];

/// Whether the focused `target` is a control: a typing target, a button, a link, a summary,
/// or an element with a widget role. `<body>`, `<main>`, a canvas and plain content are not.
pub fn is_control(target: Option<EventTarget>) -> bool {
    let Some(element) = target.and_then(|t| t.dyn_into::<Element>().ok()) else {
        return false;
    };
    if is_typing(Some(element.clone().into())) {
        return true;
    }
    let tag = element.tag_name().to_ascii_lowercase();
    match tag.as_str() {
        "button" | "summary" | "details" | "audio" | "video" | "iframe" => return true,
        "a" | "area" if element.has_attribute("href") => return true,
        _ => {}
    }
    element
        .get_attribute("role")
        .is_some_and(|role| CONTROL_ROLES.contains(&role.trim()))
}
