//! The pilot's input devices, read the way `crate::view::teleop_input` maps them: the held
//! keys, the gamepad (polled once per frame through `navigator.getGamepads()`, read with
//! `Reflect` so no Gamepad web-sys feature is needed), the pointer's clutch and the gripper's
//! open / closed state they all toggle.

use wasm_bindgen::JsValue;

use crate::view::teleop_input::{clutch_axes, HeldKeys, PadMapper, PadOutput, PadSnapshot};

/// The devices' state.
#[derive(Default)]
pub struct Devices {
    pub keys: HeldKeys,
    pub pad: PadMapper,
    /// The connected pad's name (`Gamepad.id`), `None` when no pad has shown itself.
    pub pad_name: Option<String>,
    /// The last poll's output.
    pub pad_out: PadOutput,
    /// Clutch: the pointer's target for the tip while held, and where the press began
    /// (pointer and tip, world m).
    pub clutch: Option<Clutch>,
    pub gripper_closed: bool,
    /// An input arrived since the last frame (a step is then due even between two steps).
    pub fresh: bool,
}

/// A pointer holding the clutch.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Clutch {
    pub pointer_id: i32,
    pub pointer_start: (f64, f64),
    pub tip_start: (f64, f64),
    pub target: (f64, f64),
}

impl Devices {
    /// The command axes `[x, z, phi]` of all devices together (each clamped to [-1, 1]).
    pub fn axes(&self, tip: (f64, f64)) -> [f64; 3] {
        let k = self.keys.axes();
        let p = self.pad_out.axes;
        let c = self
            .clutch
            .map_or([0.0; 3], |cl| clutch_axes(tip, cl.target));
        [0, 1, 2].map(|i| (k[i] + p[i] + c[i]).clamp(-1.0, 1.0))
    }

    /// Polls the first connected gamepad; returns whether its name changed and whether its X
    /// button toggled the gripper.
    pub fn poll_pad(&mut self, dead_zone: f64) -> (bool, bool) {
        let snap = first_pad();
        let name = snap.as_ref().map(|s| s.id.clone());
        let changed = name != self.pad_name;
        self.pad_name = name;
        let mut toggled = false;
        match snap {
            Some(s) => {
                let out = self.pad.map(&s, dead_zone);
                if out.toggle_gripper {
                    toggled = true;
                    self.gripper_closed = !self.gripper_closed;
                    self.fresh = true;
                }
                if out.active && out.axes != self.pad_out.axes {
                    self.fresh = true;
                }
                self.pad_out = out;
            }
            None => self.pad_out = PadOutput::default(),
        }
        (changed, toggled)
    }

    /// Forgets held keys and the clutch (L, focus lost, reset).
    pub fn clear(&mut self) {
        self.keys.clear();
        self.clutch = None;
    }

    /// A key of `code` went down (a new one is an input).
    pub fn press_key(&mut self, code: &str) {
        if self.keys.press(code) {
            self.fresh = true;
        }
    }

    /// Opens or closes the gripper.
    pub fn toggle_gripper(&mut self) {
        self.gripper_closed = !self.gripper_closed;
        self.fresh = true;
    }

    /// Pointer `pointer_id` took the clutch at `at` (world m) with the tip at `tip`.
    pub fn grab(&mut self, pointer_id: i32, at: (f64, f64), tip: (f64, f64)) {
        self.clutch = Some(Clutch {
            pointer_id,
            pointer_start: at,
            tip_start: tip,
            target: tip,
        });
        self.fresh = true;
    }

    /// Pointer `pointer_id` moved to `at`: the clutch's target follows it if that pointer
    /// holds it (`true`).
    pub fn drag(&mut self, pointer_id: i32, at: (f64, f64)) -> bool {
        let Some(c) = self.clutch.as_mut() else {
            return false;
        };
        if c.pointer_id != pointer_id {
            return false;
        }
        c.target = (
            c.tip_start.0 + at.0 - c.pointer_start.0,
            c.tip_start.1 + at.1 - c.pointer_start.1,
        );
        self.fresh = true;
        true
    }

    /// Pointer `pointer_id` let go (the clutch opens if it held it).
    pub fn release(&mut self, pointer_id: i32) {
        if self.clutch.is_some_and(|c| c.pointer_id == pointer_id) {
            self.clutch = None;
        }
    }

    /// Back to the start: no clutch, the gripper open.
    pub fn reset(&mut self) {
        self.clutch = None;
        self.gripper_closed = false;
    }
}

fn get(target: &JsValue, key: &str) -> JsValue {
    js_sys::Reflect::get(target, &JsValue::from_str(key)).unwrap_or(JsValue::UNDEFINED)
}

fn numbers(list: &JsValue, each: impl Fn(&JsValue) -> f64) -> Vec<f64> {
    if list.is_undefined() || list.is_null() {
        return Vec::new();
    }
    let len = get(list, "length").as_f64().unwrap_or(0.0).clamp(0.0, 64.0) as u32;
    (0..len)
        .map(|i| {
            js_sys::Reflect::get_u32(list, i)
                .map(|v| each(&v))
                .unwrap_or(0.0)
        })
        .collect()
}

/// The first connected pad of `navigator.getGamepads()`, if any.
pub(crate) fn first_pad() -> Option<PadSnapshot> {
    let navigator = web_sys::window()?.navigator();
    let f = get(&navigator, "getGamepads");
    let f: &js_sys::Function = wasm_bindgen::JsCast::dyn_ref(&f)?;
    let pads = f.call0(&navigator).ok()?;
    let len = get(&pads, "length")
        .as_f64()
        .unwrap_or(0.0)
        .clamp(0.0, 16.0) as u32;
    for i in 0..len {
        let pad = js_sys::Reflect::get_u32(&pads, i).ok()?;
        if pad.is_null() || pad.is_undefined() {
            continue;
        }
        if get(&pad, "connected").as_bool() == Some(false) {
            continue;
        }
        return Some(PadSnapshot {
            id: get(&pad, "id").as_string().unwrap_or_default(),
            mapping: get(&pad, "mapping").as_string().unwrap_or_default(),
            axes: numbers(&get(&pad, "axes"), |v| v.as_f64().unwrap_or(0.0)),
            buttons: numbers(&get(&pad, "buttons"), |b| {
                let value = get(b, "value").as_f64().unwrap_or(0.0);
                if get(b, "pressed").as_bool() == Some(true) {
                    value.max(1.0)
                } else {
                    value
                }
            }),
        });
    }
    None
}
