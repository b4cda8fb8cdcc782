//! Keyboard control (the shell forwards keys when no field has focus): `r` runs the drill,
//! `d` downloads its first CSV, `[` / `]` switch to the previous / next drill. `Enter` in a
//! field runs too (handled by the form).

use web_sys::KeyboardEvent;

use super::state::Page;
use crate::ui::page::Shortcut;

/// The page's keys for the `?` overlay.
pub fn shortcuts() -> Vec<Shortcut> {
    vec![
        Shortcut {
            keys: "r",
            message_id: "drills-key-run",
        },
        Shortcut {
            keys: "Enter",
            message_id: "drills-key-enter",
        },
        Shortcut {
            keys: "d",
            message_id: "drills-key-download",
        },
        Shortcut {
            keys: "[  ]",
            message_id: "drills-key-switch",
        },
    ]
}

/// Handles one key; `true` when it was the page's.
pub(super) fn on_key(page: &Page, event: &KeyboardEvent) -> bool {
    if event.ctrl_key() || event.meta_key() || event.alt_key() || event.repeat() {
        return false;
    }
    match event.key().as_str() {
        "r" | "R" => page.request_run(),
        "d" | "D" => page.download_first(),
        "[" | "{" => page.switch_by(-1),
        "]" | "}" => page.switch_by(1),
        _ => return false,
    }
    true
}
