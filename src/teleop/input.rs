//! The pilot's input devices, mapped as Isaac Lab's teleop devices map theirs, so a pilot's
//! habits carry over: key codes, gamepad snapshots and pointer positions in, the operator's
//! normalised axis values out (each in [-1, 1], before sensitivity: the simulation multiplies
//! by the sensitivity and the step, see [`crate::teleop::Command`]). This module maps the
//! planar arm's three axes (`#/teleop`); `crate::so101::input` maps the SO-101's six with the
//! same held keys, gamepad snapshots and dead zone.
//!
//! **Keyboard** (Isaac Lab `Se3Keyboard`): a held key adds its unit delta, a release takes it
//! back; W/S ±x, Q/E ±z, T/G ±phi (Isaac Lab's pitch keys), K toggles the gripper, R resets
//! the episode, L clears the held commands; the arrow keys are an alternative for x and z in
//! the screen's directions (→/← ±x, ↑/↓ ±z); Space engages or pauses control (Isaac
//! Teleop's RUNNING / PAUSED). Keys are taken by their physical position (`KeyboardEvent.code`),
//! as Isaac Lab's carb keyboard names do, so a Japanese layout or an active IME gives the same
//! keys. Several held keys on one axis add up and clamp to [-1, 1] (W held with → is still 1).
//!
//! **Gamepad** (Isaac Lab `Se3Gamepad`, Web Gamepad API standard mapping): left stick up/down
//! ±x (`axes[1]`, negative up), right stick up/down ±z (`axes[3]`), D-pad down/up ±phi
//! (buttons 13/12: Isaac Lab's D-pad down is +pitch, as its T key, at 0.8 of the rotation
//! sensitivity), X (button 2) toggles the gripper on its press. A stick value below the dead
//! zone (Isaac Lab's 0.01) counts as 0; above it the value is used as it is (Isaac Lab does not
//! rescale). Isaac Lab's gamepad sensitivities (1.0 and 1.6) are the gamepad's defaults.
//!
//! **Pointer / touch**: a clutch: the tip follows a drag target only while it is held; the
//! command points from the tip to the target, full speed from [`CLUTCH_FULL_SPEED_M`] away.
#![warn(missing_docs)]

/// A device's default sensitivities, as Isaac Lab's device configurations give them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sensitivities {
    /// The position sensitivity.
    pub pos: f64,
    /// The rotation sensitivity.
    pub rot: f64,
}

/// Isaac Lab `Se3KeyboardCfg`'s (the pointer's clutch uses them too).
pub const KEYBOARD_SENSITIVITIES: Sensitivities = Sensitivities { pos: 0.4, rot: 0.8 };
/// Isaac Lab `Se3GamepadCfg`'s.
pub const GAMEPAD_SENSITIVITIES: Sensitivities = Sensitivities { pos: 1.0, rot: 1.6 };
/// Isaac Lab `Se3GamepadCfg`'s dead zone.
pub const GAMEPAD_DEAD_ZONE: f64 = 0.01;
/// Isaac Lab's D-pad gives 0.8 of the rotation sensitivity.
pub const DPAD_SCALE: f64 = 0.8;
/// A button counts as pressed above this value (Isaac Lab's 0.5).
pub const PAD_PRESS: f64 = 0.5;
/// Distance from the tip to the clutch target at which the command is full (1), m.
pub const CLUTCH_FULL_SPEED_M: f64 = 0.02;

/// The sticks' axes of the standard mapping, by their index in `axes`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Stick {
    /// `axes[0]`: left stick horizontal, right positive.
    LeftX,
    /// `axes[1]`: left stick vertical, up negative.
    LeftY,
    /// `axes[2]`: right stick horizontal, right positive.
    RightX,
    /// `axes[3]`: right stick vertical, up negative.
    RightY,
}

/// The buttons of the standard mapping that the mappings read, by their index in `buttons`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Button {
    /// X (the left face button): toggles the gripper.
    X = 2,
    /// D-pad up.
    DpadUp = 12,
    /// D-pad down.
    DpadDown = 13,
    /// D-pad left.
    DpadLeft = 14,
    /// D-pad right.
    DpadRight = 15,
}

/// A task-space axis of the planar arm's command.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Axis {
    /// Horizontal.
    X,
    /// Vertical.
    Z,
    /// The gripper's angle in the plane.
    Phi,
}

impl Axis {
    fn index(self) -> usize {
        match self {
            Axis::X => 0,
            Axis::Z => 1,
            Axis::Phi => 2,
        }
    }
}

/// What a key does.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum KeyAction {
    /// Held: `sign` on `axis` while down.
    Hold {
        /// The axis the key moves.
        axis: Axis,
        /// ±1.
        sign: i8,
    },
    /// K: open / close the gripper.
    ToggleGripper,
    /// R: reset the episode.
    Reset,
    /// L: forget the held commands.
    Clear,
    /// Space: engage / pause.
    Engage,
}

/// The action of the key at physical position `code` (`KeyboardEvent.code`).
pub fn key_action(code: &str) -> Option<KeyAction> {
    let hold = |axis, sign| Some(KeyAction::Hold { axis, sign });
    match code {
        "KeyW" | "ArrowRight" => hold(Axis::X, 1),
        "KeyS" | "ArrowLeft" => hold(Axis::X, -1),
        "KeyQ" | "ArrowUp" => hold(Axis::Z, 1),
        "KeyE" | "ArrowDown" => hold(Axis::Z, -1),
        "KeyT" => hold(Axis::Phi, 1),
        "KeyG" => hold(Axis::Phi, -1),
        "KeyK" => Some(KeyAction::ToggleGripper),
        "KeyR" => Some(KeyAction::Reset),
        "KeyL" => Some(KeyAction::Clear),
        "Space" => Some(KeyAction::Engage),
        _ => None,
    }
}

/// The keys held down (physical codes), in press order, each with the axis (an index) and
/// sign it holds: the planar arm's three axes, or the SO-101's six (`crate::so101::input`).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct HeldKeys {
    held: Vec<(String, usize, i8)>,
}

impl HeldKeys {
    /// A key went down; `true` if it is a hold key that was not held yet (auto-repeat gives
    /// `false`).
    pub fn press(&mut self, code: &str) -> bool {
        let Some(KeyAction::Hold { axis, sign }) = key_action(code) else {
            return false;
        };
        self.press_axis(code, axis.index(), sign)
    }

    /// Key `code` went down holding `sign` on axis `axis`; `true` if it was not held yet.
    pub fn press_axis(&mut self, code: &str, axis: usize, sign: i8) -> bool {
        if self.held.iter().any(|(c, _, _)| c == code) {
            return false;
        }
        self.held.push((code.to_string(), axis, sign));
        true
    }

    /// A key went up.
    pub fn release(&mut self, code: &str) {
        self.held.retain(|(c, _, _)| c != code);
    }

    /// L (or focus lost): nothing held.
    pub fn clear(&mut self) {
        self.held.clear();
    }

    /// Whether any hold key is down.
    pub fn any(&self) -> bool {
        !self.held.is_empty()
    }

    /// The held keys' axes `[x, z, phi]`, each the sum of its keys clamped to [-1, 1].
    pub fn axes(&self) -> [f64; 3] {
        self.axes_of()
    }

    /// The held keys' N axes, each the sum of its keys clamped to [-1, 1].
    pub fn axes_of<const N: usize>(&self) -> [f64; N] {
        let mut out = [0.0; N];
        for (_, axis, sign) in &self.held {
            if let Some(v) = out.get_mut(*axis) {
                *v += f64::from(*sign);
            }
        }
        out.map(|v: f64| v.clamp(-1.0, 1.0))
    }
}

/// One poll of a gamepad (`navigator.getGamepads()[i]`).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct PadSnapshot {
    /// The pad's name, as the browser gives it.
    pub id: String,
    /// `"standard"` when the browser knows the layout.
    pub mapping: String,
    /// Axis values (-1..1).
    pub axes: Vec<f64>,
    /// Button values (0..1; digital buttons give 0 or 1).
    pub buttons: Vec<f64>,
}

impl PadSnapshot {
    /// The value of `stick` with the dead zone applied (0 for a pad without that axis).
    pub fn stick(&self, stick: Stick, dead_zone: f64) -> f64 {
        dead_zoned(
            self.axes.get(stick as usize).copied().unwrap_or(0.0),
            dead_zone,
        )
    }

    /// Whether `button` is down (above [`PAD_PRESS`]).
    pub fn pressed(&self, button: Button) -> bool {
        self.buttons.get(button as usize).copied().unwrap_or(0.0) > PAD_PRESS
    }

    /// A D-pad pair as one rotation axis: [`DPAD_SCALE`] with `plus` alone down, its negative
    /// with `minus` alone, else 0.
    pub fn dpad_axis(&self, plus: Button, minus: Button) -> f64 {
        match (self.pressed(plus), self.pressed(minus)) {
            (true, false) => DPAD_SCALE,
            (false, true) => -DPAD_SCALE,
            _ => 0.0,
        }
    }
}

/// What a gamepad poll gives.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct PadOutput {
    /// `[x, z, phi]` in [-1, 1].
    pub axes: [f64; 3],
    /// X was pressed since the last poll.
    pub toggle_gripper: bool,
    /// Any stick out of the dead zone or any button down: the pad is in use.
    pub active: bool,
}

/// The gamepad mapper: remembers the gripper button between polls (a toggle on its press).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct PadMapper {
    x_was_down: bool,
}

/// `value` with the dead zone applied (Isaac Lab: below it 0, above it unchanged), clamped.
pub fn dead_zoned(value: f64, dead_zone: f64) -> f64 {
    if !value.is_finite() || value.abs() < dead_zone {
        0.0
    } else {
        value.clamp(-1.0, 1.0)
    }
}

impl PadMapper {
    /// The gripper toggle (X pressed since the last poll) and whether the pad is in use (a
    /// stick out of the dead zone or a button down), for any arm's mapping.
    pub fn buttons(&mut self, pad: &PadSnapshot, dead_zone: f64) -> (bool, bool) {
        let x_down = pad.pressed(Button::X);
        let toggle = x_down && !self.x_was_down;
        self.x_was_down = x_down;
        let active = pad.axes.iter().any(|v| dead_zoned(*v, dead_zone) != 0.0)
            || pad.buttons.iter().any(|b| *b > PAD_PRESS);
        (toggle, active)
    }

    /// Maps one poll.
    pub fn map(&mut self, pad: &PadSnapshot, dead_zone: f64) -> PadOutput {
        let (toggle_gripper, active) = self.buttons(pad, dead_zone);
        PadOutput {
            axes: [
                -pad.stick(Stick::LeftY, dead_zone) + 0.0,
                -pad.stick(Stick::RightY, dead_zone) + 0.0,
                pad.dpad_axis(Button::DpadDown, Button::DpadUp),
            ],
            toggle_gripper,
            active,
        }
    }
}

/// The clutch command: from the tip `(x, z)` towards the target, each axis clamped to
/// [-1, 1] (full speed from [`CLUTCH_FULL_SPEED_M`] away).
pub fn clutch_axes(tip: (f64, f64), target: (f64, f64)) -> [f64; 3] {
    let f = |d: f64| (d / CLUTCH_FULL_SPEED_M).clamp(-1.0, 1.0);
    [f(target.0 - tip.0), f(target.1 - tip.1), 0.0]
}

#[cfg(test)]
mod tests {
    #[cfg(target_arch = "wasm32")]
    use wasm_bindgen_test::wasm_bindgen_test as test;

    use super::*;

    #[test]
    fn isaac_lab_keys_map_to_axes() {
        let mut keys = HeldKeys::default();
        assert!(keys.press("KeyW"));
        assert!(!keys.press("KeyW"), "auto-repeat is not a new press");
        assert_eq!(keys.axes(), [1.0, 0.0, 0.0]);
        keys.press("KeyQ");
        keys.press("KeyT");
        assert_eq!(keys.axes(), [1.0, 1.0, 1.0]);
        keys.press("KeyS");
        assert_eq!(keys.axes(), [0.0, 1.0, 1.0], "W and S cancel");
        keys.release("KeyW");
        keys.release("KeyQ");
        keys.press("KeyE");
        keys.press("KeyG");
        keys.release("KeyT");
        assert_eq!(keys.axes(), [-1.0, -1.0, -1.0]);
        keys.clear();
        assert_eq!(keys.axes(), [0.0; 3]);
        assert!(!keys.any());
    }

    #[test]
    fn arrows_are_the_screen_directions_and_clamp_with_letters() {
        let mut keys = HeldKeys::default();
        keys.press("KeyW");
        keys.press("ArrowRight");
        keys.press("ArrowUp");
        assert_eq!(keys.axes(), [1.0, 1.0, 0.0]);
        assert_eq!(
            key_action("ArrowLeft"),
            Some(KeyAction::Hold {
                axis: Axis::X,
                sign: -1
            })
        );
        assert_eq!(
            key_action("ArrowDown"),
            Some(KeyAction::Hold {
                axis: Axis::Z,
                sign: -1
            })
        );
    }

    #[test]
    fn command_keys() {
        assert_eq!(key_action("KeyK"), Some(KeyAction::ToggleGripper));
        assert_eq!(key_action("KeyR"), Some(KeyAction::Reset));
        assert_eq!(key_action("KeyL"), Some(KeyAction::Clear));
        assert_eq!(key_action("Space"), Some(KeyAction::Engage));
        assert_eq!(key_action("KeyA"), None, "no y axis in the plane");
        let mut keys = HeldKeys::default();
        assert!(!keys.press("KeyK"), "K is not held");
        assert!(!keys.any());
    }

    fn pad(axes: [f64; 4], buttons: &[(Button, f64)]) -> PadSnapshot {
        let mut b = vec![0.0; 17];
        for (button, v) in buttons {
            b[*button as usize] = *v;
        }
        PadSnapshot {
            id: "test pad".into(),
            mapping: "standard".into(),
            axes: axes.to_vec(),
            buttons: b,
        }
    }

    #[test]
    fn gamepad_sticks_with_the_dead_zone() {
        let mut m = PadMapper::default();
        let out = m.map(&pad([0.3, -0.5, 0.0, 0.25], &[]), GAMEPAD_DEAD_ZONE);
        assert_eq!(
            out.axes,
            [0.5, -0.25, 0.0],
            "up is negative in the standard mapping"
        );
        assert!(out.active);
        let out = m.map(&pad([0.0, 0.009, 0.0, -0.0099], &[]), GAMEPAD_DEAD_ZONE);
        assert_eq!(out.axes, [0.0, 0.0, 0.0]);
        assert!(!out.active);
        let out = m.map(&pad([0.0, -0.01, 0.0, 0.0], &[]), GAMEPAD_DEAD_ZONE);
        assert_eq!(
            out.axes[0], 0.01,
            "at the dead zone the value passes unchanged"
        );
        assert_eq!(dead_zoned(f64::NAN, 0.01), 0.0);
        assert_eq!(dead_zoned(-3.0, 0.01), -1.0);
    }

    #[test]
    fn gamepad_dpad_and_gripper_toggle_on_press() {
        let mut m = PadMapper::default();
        let out = m.map(&pad([0.0; 4], &[(Button::DpadDown, 1.0)]), 0.01);
        assert_eq!(out.axes[2], 0.8);
        let out = m.map(&pad([0.0; 4], &[(Button::DpadUp, 1.0)]), 0.01);
        assert_eq!(out.axes[2], -0.8);
        let out = m.map(
            &pad([0.0; 4], &[(Button::DpadUp, 1.0), (Button::DpadDown, 1.0)]),
            0.01,
        );
        assert_eq!(out.axes[2], 0.0);
        assert!(
            m.map(&pad([0.0; 4], &[(Button::X, 1.0)]), 0.01)
                .toggle_gripper
        );
        assert!(
            !m.map(&pad([0.0; 4], &[(Button::X, 1.0)]), 0.01)
                .toggle_gripper,
            "held is not a second press"
        );
        assert!(!m.map(&pad([0.0; 4], &[]), 0.01).toggle_gripper);
        assert!(
            m.map(&pad([0.0; 4], &[(Button::X, 0.9)]), 0.01)
                .toggle_gripper
        );
        let short = PadSnapshot::default();
        assert_eq!(m.map(&short, 0.01), PadOutput::default());
    }

    #[test]
    fn clutch_points_at_the_target_and_saturates() {
        let a = clutch_axes((0.1, 0.1), (0.11, 0.08));
        assert!(
            (a[0] - 0.5).abs() < 1e-12 && a[1] == -1.0 && a[2] == 0.0,
            "{a:?}"
        );
        assert_eq!(clutch_axes((0.1, 0.1), (0.1, 0.1)), [0.0, 0.0, 0.0]);
    }
}
