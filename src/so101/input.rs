//! The SO-101 page's input mapping, as Isaac Lab's `Se3Keyboard` and `Se3Gamepad` map theirs
//! (six axes: x, y, z, roll, pitch, yaw, each normalised to [−1, 1] before sensitivity; the
//! simulation multiplies by the sensitivity and the step, see [`super::Command`]). Pure: the
//! page feeds it key codes (`KeyboardEvent.code`, the physical key) and gamepad snapshots.
//!
//! **Keyboard**: W/S ±x, A/D ±y, Q/E ±z, Z/X ±roll, T/G ±pitch, C/V ±yaw (held keys add up and
//! clamp), K toggles the gripper, R resets, Space engages or pauses.
//!
//! **Gamepad** (standard mapping): left stick up/down ±x (`axes[1]`, negative up), left stick
//! right/left ±y (`axes[0]`), right stick up/down ±z (`axes[3]`), right stick right/left ±yaw
//! (`axes[2]`), D-pad down/up ±pitch and left/right ±roll at 0.8 (buttons 13/12, 14/15), X
//! (button 2) toggles the gripper on its press; values under the dead zone (0.01) count as 0.

pub use crate::teleop::input::HeldKeys;
use crate::teleop::input::{self, Button, PadSnapshot, Stick};

/// What a key does.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum KeyAction {
    /// Held: `sign` on axis `axis` (0 x … 5 yaw) while down.
    Hold {
        /// 0 x, 1 y, 2 z, 3 roll, 4 pitch, 5 yaw.
        axis: usize,
        /// ±1.
        sign: i8,
    },
    /// K.
    ToggleGripper,
    /// R.
    Reset,
    /// Space.
    Engage,
}

/// The keys that hold an axis, in the axes' order (x, y, z, roll, pitch, yaw): the first of
/// each pair holds +1, the second −1.
pub const AXIS_KEYS: [(&str, &str); 6] = [
    ("KeyW", "KeyS"),
    ("KeyA", "KeyD"),
    ("KeyQ", "KeyE"),
    ("KeyZ", "KeyX"),
    ("KeyT", "KeyG"),
    ("KeyC", "KeyV"),
];

/// The action of the key at physical position `code`.
pub fn key_action(code: &str) -> Option<KeyAction> {
    for (axis, (plus, minus)) in AXIS_KEYS.into_iter().enumerate() {
        if code == plus || code == minus {
            let sign = if code == plus { 1 } else { -1 };
            return Some(KeyAction::Hold { axis, sign });
        }
    }
    match code {
        "KeyK" => Some(KeyAction::ToggleGripper),
        "KeyR" => Some(KeyAction::Reset),
        "Space" => Some(KeyAction::Engage),
        _ => None,
    }
}

/// Key `code` went down: `true` if it is a hold key not held yet (auto-repeat gives
/// `false`).
pub fn press(keys: &mut HeldKeys, code: &str) -> bool {
    match key_action(code) {
        Some(KeyAction::Hold { axis, sign }) => keys.press_axis(code, axis, sign),
        _ => false,
    }
}

/// What one gamepad poll gives.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct PadOutput {
    /// The six axes in [−1, 1].
    pub axes: [f64; 6],
    /// X was pressed since the last poll.
    pub toggle_gripper: bool,
    /// A stick out of the dead zone or a button down.
    pub active: bool,
}

/// The gamepad mapper (the planar page's remembers X between polls: the gripper toggles on
/// its press).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct PadMapper {
    buttons: input::PadMapper,
}

impl PadMapper {
    /// Maps one poll with `dead_zone`.
    pub fn map(&mut self, pad: &PadSnapshot, dead_zone: f64) -> PadOutput {
        let (toggle_gripper, active) = self.buttons.buttons(pad, dead_zone);
        PadOutput {
            axes: [
                -pad.stick(Stick::LeftY, dead_zone) + 0.0,
                pad.stick(Stick::LeftX, dead_zone),
                -pad.stick(Stick::RightY, dead_zone) + 0.0,
                pad.dpad_axis(Button::DpadLeft, Button::DpadRight),
                pad.dpad_axis(Button::DpadDown, Button::DpadUp),
                pad.stick(Stick::RightX, dead_zone),
            ],
            toggle_gripper,
            active,
        }
    }
}

#[cfg(test)]
mod tests {
    #[cfg(target_arch = "wasm32")]
    use wasm_bindgen_test::wasm_bindgen_test as test;

    use super::*;

    #[test]
    fn every_isaac_lab_key_holds_its_axis() {
        // Isaac Lab's Se3Keyboard: +/- x, y, z, roll, pitch, yaw.
        let keys = [
            "KeyW", "KeyS", "KeyA", "KeyD", "KeyQ", "KeyE", "KeyZ", "KeyX", "KeyT", "KeyG", "KeyC",
            "KeyV",
        ];
        for (i, code) in keys.into_iter().enumerate() {
            let (axis, sign) = (i / 2, if i % 2 == 0 { 1.0 } else { -1.0 });
            let mut held = HeldKeys::default();
            assert!(press(&mut held, code));
            assert!(!press(&mut held, code), "auto-repeat is not a new press");
            let mut want = [0.0; 6];
            want[axis] = sign;
            assert_eq!(held.axes_of::<6>(), want, "{code}");
            held.release(code);
            assert!(!held.any());
        }
        assert_eq!(key_action("KeyK"), Some(KeyAction::ToggleGripper));
        assert_eq!(key_action("KeyR"), Some(KeyAction::Reset));
        assert_eq!(key_action("Space"), Some(KeyAction::Engage));
        assert_eq!(key_action("KeyL"), None);
    }

    #[test]
    fn the_gamepad_maps_as_se3_gamepad() {
        let mut m = PadMapper::default();
        let mut pad = PadSnapshot {
            id: "pad".into(),
            mapping: "standard".into(),
            axes: vec![0.5, -0.8, 0.005, 0.3],
            buttons: vec![0.0; 17],
        };
        pad.buttons[13] = 1.0;
        pad.buttons[15] = 1.0;
        pad.buttons[2] = 1.0;
        let out = m.map(&pad, 0.01);
        assert_eq!(out.axes, [0.8, 0.5, -0.3, -0.8, 0.8, 0.0]);
        assert!(out.toggle_gripper && out.active);
        assert!(!m.map(&pad, 0.01).toggle_gripper, "held X toggles once");
    }
}
