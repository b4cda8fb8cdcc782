//! Keyboard control (the shell forwards keys when no field has focus): arrow keys nudge the
//! tip 1 mm by IK (Shift: 10 mm), `[` / `]` turn q1 and `-` / `=` turn q2 by 0.01 rad
//! (Shift: 0.1 rad), `e` flips the elbow, `r` resets, `w` shows or hides the workspace grid. A tip move out of
//! reach shows the out-of-reach note, as a drag does. On the focused heatmap the arrow keys
//! move its marker instead (← → q1, ↓ ↑ q2, 0.01 rad; Shift: 0.1 rad): what a click there does.

use web_sys::KeyboardEvent;

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

/// What a key asks of the page.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum KeyAction {
    /// Move the tip by `(dx, dy)` metres by IK.
    Nudge(f64, f64),
    /// Turn the joints by `(d1, d2)` radians.
    Turn(f64, f64),
    FlipElbow,
    Reset,
    ToggleWorkspace,
}

/// The page's action for one key (`on_heatmap`: the key's target is the heatmap, whose arrows
/// turn the joints); `None` when the key is not the page's.
pub(super) fn action(event: &KeyboardEvent, on_heatmap: bool) -> Option<KeyAction> {
    if event.ctrl_key() || event.meta_key() || event.alt_key() {
        return None;
    }
    let k = if event.shift_key() { 10.0 } else { 1.0 };
    let nudge = |dx: f64, dy: f64| KeyAction::Nudge(dx * NUDGE_M * k, dy * NUDGE_M * k);
    let turn = |d1: f64, d2: f64| KeyAction::Turn(d1 * TURN_RAD * k, d2 * TURN_RAD * k);
    let key = event.key();
    let arrow = match key.as_str() {
        "ArrowLeft" => Some((-1.0, 0.0)),
        "ArrowRight" => Some((1.0, 0.0)),
        "ArrowUp" => Some((0.0, 1.0)),
        "ArrowDown" => Some((0.0, -1.0)),
        _ => None,
    };
    if let Some((x, y)) = arrow {
        // On the heatmap ← → turn q1 and ↑ ↓ turn q2; elsewhere the arrows move the tip.
        return Some(if on_heatmap { turn(x, y) } else { nudge(x, y) });
    }
    Some(match key.as_str() {
        "[" | "{" => turn(-1.0, 0.0),
        "]" | "}" => turn(1.0, 0.0),
        "-" | "_" => turn(0.0, -1.0),
        "=" | "+" => turn(0.0, 1.0),
        "e" | "E" => KeyAction::FlipElbow,
        "r" | "R" => KeyAction::Reset,
        "w" | "W" => KeyAction::ToggleWorkspace,
        _ => return None,
    })
}
