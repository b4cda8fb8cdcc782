//! Keyboard control (the shell forwards keys when no field has focus): arrow keys nudge the
//! tip 1 mm by IK (Shift: 10 mm), `[` / `]` turn q1 and `-` / `=` turn q2 by 0.01 rad
//! (Shift: 0.1 rad), `e` flips the elbow, `r` resets, `w` shows or hides the workspace grid. A tip move out of
//! reach shows the out-of-reach note, as a drag does. On the focused heatmap the arrow keys
//! move its marker instead (← → q1, ↓ ↑ q2, 0.01 rad; Shift: 0.1 rad): what a click there does.

use web_sys::KeyboardEvent;

use super::Page;
use crate::ui::page::Shortcut;

/// Tip nudge, metres (Shift: ten times).
const NUDGE_M: f64 = 0.001;
/// Joint nudge, radians (Shift: ten times).
const TURN_RAD: f64 = 0.01;

/// The page's keys for the `?` overlay.
pub fn shortcuts() -> Vec<Shortcut> {
    vec![
        Shortcut {
            keys: "← ↑ → ↓",
            message_id: "ik2r-key-nudge",
        },
        Shortcut {
            keys: "← ↑ → ↓",
            message_id: "ik2r-key-heatmap",
        },
        Shortcut {
            keys: "[  ]",
            message_id: "ik2r-key-q1",
        },
        Shortcut {
            keys: "-  =",
            message_id: "ik2r-key-q2",
        },
        Shortcut {
            keys: "e",
            message_id: "ik2r-key-elbow",
        },
        Shortcut {
            keys: "r",
            message_id: "ik2r-key-reset",
        },
        Shortcut {
            keys: "w",
            message_id: "ik2r-key-workspace",
        },
    ]
}

/// Handles one key; `true` when it was the page's.
pub(super) fn on_key(page: &Page, event: &KeyboardEvent) -> bool {
    if event.ctrl_key() || event.meta_key() || event.alt_key() {
        return false;
    }
    let k = if event.shift_key() { 10.0 } else { 1.0 };
    let key = event.key();
    let nudge = |dx: f64, dy: f64| page.nudge_tip(dx * NUDGE_M * k, dy * NUDGE_M * k);
    let turn = |d1: f64, d2: f64| page.turn(d1 * TURN_RAD * k, d2 * TURN_RAD * k);
    if page.is_heatmap(event.target()) {
        match key.as_str() {
            "ArrowLeft" => turn(-1.0, 0.0),
            "ArrowRight" => turn(1.0, 0.0),
            "ArrowUp" => turn(0.0, 1.0),
            "ArrowDown" => turn(0.0, -1.0),
            _ => return on_any_view(page, key.as_str(), turn),
        }
        return true;
    }
    match key.as_str() {
        "ArrowLeft" => nudge(-1.0, 0.0),
        "ArrowRight" => nudge(1.0, 0.0),
        "ArrowUp" => nudge(0.0, 1.0),
        "ArrowDown" => nudge(0.0, -1.0),
        other => return on_any_view(page, other, turn),
    }
    true
}

/// The keys that do the same on the arm view, the heatmap and the page body.
fn on_any_view(page: &Page, key: &str, turn: impl Fn(f64, f64)) -> bool {
    match key {
        "[" | "{" => turn(-1.0, 0.0),
        "]" | "}" => turn(1.0, 0.0),
        "-" | "_" => turn(0.0, -1.0),
        "=" | "+" => turn(0.0, 1.0),
        "e" | "E" => {
            let elbow = page.state.borrow().elbow.flipped();
            page.set_elbow(elbow);
        }
        "r" | "R" => page.reset(),
        "w" | "W" => {
            let on = !page.state.borrow().show_ws;
            page.set_workspace_visible(on);
        }
        _ => return false,
    }
    true
}
