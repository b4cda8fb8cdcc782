//! The Robot Pilot page's pure view models (`#/teleop`): its settings (task, IK method, λ,
//! latency, noise, time box, the active device's sensitivities, the gamepad's dead zone, the
//! pilot id), each field checked with a Fluent message beside it, and turned into the
//! kernel's [`SceneConfig`]; the readout texts; the world ↔ screen transform of the arm view;
//! the repeatability table's cells. No web-sys: `cargo test` runs all of it.

use crate::teleop::input::{GAMEPAD_DEAD_ZONE, GAMEPAD_SENSITIVITIES, KEYBOARD_SENSITIVITIES};
use crate::teleop::session::{clean_pilot_id, InputDevice, PILOT_ID_MAX};
use crate::teleop::{ControlParams, IkMethod, SceneConfig, Task};

/// The settings fields, in the form's order (`data-field` names).
pub const FIELDS: [&str; 10] = [
    "pilot",
    "task",
    "ik",
    "lambda",
    "latency_ms",
    "noise",
    "time_box_s",
    "pos_sensitivity",
    "rot_sensitivity",
    "dead_zone",
];

/// The IK methods' ids, in the form's order.
pub const IK_IDS: [&str; 4] = ["dls", "pinv", "trans", "adaptive-dls"];

/// The settings as typed.
#[derive(Debug, Clone, PartialEq)]
pub struct SettingsTexts {
    pub pilot: String,
    pub task: String,
    pub ik: String,
    pub lambda: String,
    pub latency_ms: String,
    pub noise: String,
    pub time_box_s: String,
    pub pos_sensitivity: String,
    pub rot_sensitivity: String,
    pub dead_zone: String,
}

impl SettingsTexts {
    /// The defaults for `device` (Isaac Lab's sensitivities of that device).
    pub fn defaults(device: InputDevice) -> SettingsTexts {
        let (pos, rot) = sensitivity_defaults(device);
        SettingsTexts {
            pilot: "pilot".into(),
            task: "pick-place".into(),
            ik: "dls".into(),
            lambda: "0.01".into(),
            latency_ms: "0".into(),
            noise: "0".into(),
            time_box_s: "60".into(),
            pos_sensitivity: pos.to_string(),
            rot_sensitivity: rot.to_string(),
            dead_zone: GAMEPAD_DEAD_ZONE.to_string(),
        }
    }

    /// The text of field `name`.
    pub fn get(&self, name: &str) -> &str {
        match name {
            "pilot" => &self.pilot,
            "task" => &self.task,
            "ik" => &self.ik,
            "lambda" => &self.lambda,
            "latency_ms" => &self.latency_ms,
            "noise" => &self.noise,
            "time_box_s" => &self.time_box_s,
            "pos_sensitivity" => &self.pos_sensitivity,
            "rot_sensitivity" => &self.rot_sensitivity,
            "dead_zone" => &self.dead_zone,
            _ => "",
        }
    }

    /// Sets the text of field `name`.
    pub fn set(&mut self, name: &str, text: &str) {
        let slot = match name {
            "pilot" => &mut self.pilot,
            "task" => &mut self.task,
            "ik" => &mut self.ik,
            "lambda" => &mut self.lambda,
            "latency_ms" => &mut self.latency_ms,
            "noise" => &mut self.noise,
            "time_box_s" => &mut self.time_box_s,
            "pos_sensitivity" => &mut self.pos_sensitivity,
            "rot_sensitivity" => &mut self.rot_sensitivity,
            "dead_zone" => &mut self.dead_zone,
            _ => return,
        };
        *slot = text.to_string();
    }
}

/// Isaac Lab's `(pos_sensitivity, rot_sensitivity)` of a device (the pointer's clutch uses the
/// keyboard's).
pub fn sensitivity_defaults(device: InputDevice) -> (f64, f64) {
    let defaults = match device {
        InputDevice::Gamepad => GAMEPAD_SENSITIVITIES,
        InputDevice::Keyboard | InputDevice::Pointer => KEYBOARD_SENSITIVITIES,
    };
    (defaults.pos, defaults.rot)
}

/// A field's problem: its name, the Fluent id of the message and the message's arguments.
#[derive(Debug, Clone, PartialEq)]
pub struct FieldProblem {
    pub field: &'static str,
    pub message_id: &'static str,
    pub args: Vec<(&'static str, String)>,
}

/// Valid settings.
#[derive(Debug, Clone, PartialEq)]
pub struct Settings {
    pub pilot_id: String,
    pub config: SceneConfig,
    pub dead_zone: f64,
}

/// Limits of the numeric fields: `(field, min, max)`.
pub const LIMITS: [(&str, f64, f64); 7] = [
    ("lambda", 0.0, 1.0),
    ("latency_ms", 0.0, 500.0),
    ("noise", 0.0, 1.0),
    ("time_box_s", 5.0, 600.0),
    ("pos_sensitivity", 0.01, 10.0),
    ("rot_sensitivity", 0.01, 10.0),
    ("dead_zone", 0.0, 0.5),
];

fn limits(field: &str) -> (f64, f64) {
    LIMITS
        .iter()
        .find(|(f, _, _)| *f == field)
        .map_or((0.0, 0.0), |(_, a, b)| (*a, *b))
}

fn field_name(field: &str) -> &'static str {
    FIELDS.iter().find(|f| **f == field).copied().unwrap_or("")
}

/// A number of field `field` within its limits.
fn number(field: &str, text: &str) -> Result<f64, FieldProblem> {
    let name = field_name(field);
    let (min, max) = limits(field);
    let t = text.trim();
    let problem = |id: &'static str| FieldProblem {
        field: name,
        message_id: id,
        args: vec![("min", fmt_limit(min)), ("max", fmt_limit(max))],
    };
    if t.is_empty() {
        return Err(problem("teleop-err-empty"));
    }
    let v: f64 = t.parse().map_err(|_| problem("teleop-err-number"))?;
    if !v.is_finite() {
        return Err(problem("teleop-err-number"));
    }
    if v < min || v > max {
        return Err(problem("teleop-err-range"));
    }
    Ok(v)
}

fn fmt_limit(v: f64) -> String {
    crate::pyfmt::human(v)
}

/// Checks every field: the settings, or every field's problem.
pub fn check(texts: &SettingsTexts) -> Result<Settings, Vec<FieldProblem>> {
    let mut problems = Vec::new();
    let pilot = clean_pilot_id(&texts.pilot);
    let pilot_ok = !pilot.is_empty()
        && texts.pilot.trim().chars().count() <= PILOT_ID_MAX
        && pilot
            .chars()
            .all(|c| c.is_alphanumeric() || c == '-' || c == '_' || c == ' ' || c == '.');
    if !pilot_ok {
        problems.push(FieldProblem {
            field: "pilot",
            message_id: "teleop-err-pilot",
            args: vec![("max", PILOT_ID_MAX.to_string())],
        });
    }
    // A choice that is none of the list's.
    let unknown = |field| FieldProblem {
        field,
        message_id: "teleop-err-choice",
        args: Vec::new(),
    };
    let task = Task::from_id(&texts.task);
    if task.is_none() {
        problems.push(unknown("task"));
    }
    let method = IkMethod::from_id(&texts.ik);
    if method.is_none() {
        problems.push(unknown("ik"));
    }
    let mut values = [0.0; 7];
    for (i, (field, _, _)) in LIMITS.iter().enumerate() {
        match number(field, texts.get(field)) {
            Ok(v) => values[i] = v,
            Err(p) => problems.push(p),
        }
    }
    let [lambda, latency_ms, noise, time_box_s, pos, rot, dead_zone] = values;
    if problems.iter().all(|p| p.field != "latency_ms") && latency_ms % 10.0 != 0.0 {
        problems.push(FieldProblem {
            field: "latency_ms",
            message_id: "teleop-err-latency-step",
            args: Vec::new(),
        });
    }
    let (Some(task), Some(method), true) = (task, method, problems.is_empty()) else {
        return Err(problems);
    };
    let config = SceneConfig {
        task,
        control: ControlParams {
            method,
            lambda,
            ..ControlParams::default()
        },
        latency_steps: (latency_ms / 10.0) as u32,
        noise_sigma: noise,
        time_box_s,
        pos_sensitivity: pos,
        rot_sensitivity: rot,
        ..SceneConfig::default()
    };
    if let Err(e) = config.validate() {
        let field = match e.field() {
            Some("lambda") => "lambda",
            Some("latency_steps") => "latency_ms",
            Some("noise_sigma") => "noise",
            Some("time_box_s") => "time_box_s",
            Some("pos_sensitivity") => "pos_sensitivity",
            Some("rot_sensitivity") => "rot_sensitivity",
            _ => "task",
        };
        return Err(vec![FieldProblem {
            field,
            message_id: "teleop-err-kernel",
            args: vec![("detail", e.to_string())],
        }]);
    }
    Ok(Settings {
        pilot_id: pilot,
        config,
        dead_zone,
    })
}

/// A length in m with 4 decimals (0.1 mm), `-0.0000` written `0.0000`.
pub fn metres(v: f64) -> String {
    fixed_clean(v, 4)
}

/// An angle in rad with 3 decimals.
pub fn radians(v: f64) -> String {
    fixed_clean(v, 3)
}

/// `v` with `digits` decimals, never `-0.000` ([`crate::numtext::fixed`]).
pub fn fixed_clean(v: f64, digits: usize) -> String {
    crate::numtext::fixed(v, digits)
}

/// The arm view's transform: world `(x, z)` in m ↔ CSS px, `z` up, the scene's bounds fitted
/// with a margin and equal scales.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ViewTransform {
    /// px per m.
    pub scale: f64,
    /// Screen position of world (0, 0).
    pub origin: (f64, f64),
}

impl ViewTransform {
    /// Fits `bounds` `(x0, z0, x1, z1)` into `w × h` px with `margin` px around.
    pub fn fit(bounds: (f64, f64, f64, f64), w: f64, h: f64, margin: f64) -> ViewTransform {
        let (x0, z0, x1, z1) = bounds;
        let bw = (x1 - x0).abs().max(1e-6);
        let bh = (z1 - z0).abs().max(1e-6);
        let scale = ((w - 2.0 * margin) / bw)
            .min((h - 2.0 * margin) / bh)
            .max(1e-6);
        let cx = w / 2.0 - scale * (x0 + x1) / 2.0;
        let cy = h / 2.0 + scale * (z0 + z1) / 2.0;
        ViewTransform {
            scale,
            origin: (cx, cy),
        }
    }

    /// World → screen.
    pub fn to_screen(&self, x: f64, z: f64) -> (f64, f64) {
        (
            self.origin.0 + self.scale * x,
            self.origin.1 - self.scale * z,
        )
    }

    /// Screen → world.
    pub fn to_world(&self, px: f64, py: f64) -> (f64, f64) {
        (
            (px - self.origin.0) / self.scale,
            (self.origin.1 - py) / self.scale,
        )
    }
}

/// A comparison cell: a rate as a percentage, a time in s, an efficiency, a count; `—` when
/// there is nothing to show.
pub fn comparison_cell(id: &str, v: Option<f64>) -> String {
    match v {
        None => "—".to_string(),
        Some(v) => match id {
            "success-rate" => format!("{} %", fixed_clean(100.0 * v, 0)),
            "mean-time" => format!("{} s", fixed_clean(v, 2)),
            "efficiency" => fixed_clean(v, 3),
            _ => fixed_clean(v, 0),
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_check_and_give_isaac_lab_sensitivities() {
        let s = check(&SettingsTexts::defaults(InputDevice::Keyboard)).expect("defaults");
        assert_eq!(s.config.pos_sensitivity, 0.4);
        assert_eq!(s.config.rot_sensitivity, 0.8);
        assert_eq!(s.config.control.method, IkMethod::Dls);
        assert_eq!(s.config.control.lambda, 0.01);
        assert_eq!(s.config.latency_steps, 0);
        assert_eq!(s.dead_zone, 0.01);
        let g = check(&SettingsTexts::defaults(InputDevice::Gamepad)).expect("gamepad");
        assert_eq!(
            (g.config.pos_sensitivity, g.config.rot_sensitivity),
            (1.0, 1.6)
        );
    }

    #[test]
    fn every_field_is_checked_with_its_message() {
        let mut t = SettingsTexts::defaults(InputDevice::Keyboard);
        t.set("pilot", "  ");
        t.set("task", "juggle");
        t.set("ik", "magic");
        t.set("lambda", "abc");
        t.set("latency_ms", "600");
        t.set("noise", "");
        t.set("time_box_s", "1");
        t.set("pos_sensitivity", "0");
        t.set("rot_sensitivity", "inf");
        t.set("dead_zone", "0.9");
        let problems = check(&t).expect_err("all bad");
        let got: Vec<(&str, &str)> = problems.iter().map(|p| (p.field, p.message_id)).collect();
        assert_eq!(
            got,
            vec![
                ("pilot", "teleop-err-pilot"),
                ("task", "teleop-err-choice"),
                ("ik", "teleop-err-choice"),
                ("lambda", "teleop-err-number"),
                ("latency_ms", "teleop-err-range"),
                ("noise", "teleop-err-empty"),
                ("time_box_s", "teleop-err-range"),
                ("pos_sensitivity", "teleop-err-range"),
                ("rot_sensitivity", "teleop-err-number"),
                ("dead_zone", "teleop-err-range"),
            ]
        );
        let range = &problems[4];
        assert_eq!(
            range.args,
            vec![("min", "0".to_string()), ("max", "500".to_string())]
        );
    }

    #[test]
    fn latency_is_whole_steps() {
        let mut t = SettingsTexts::defaults(InputDevice::Keyboard);
        t.set("latency_ms", "125");
        let p = check(&t).expect_err("not a multiple of 10");
        assert_eq!(p[0].message_id, "teleop-err-latency-step");
        t.set("latency_ms", "120");
        assert_eq!(check(&t).expect("ok").config.latency_steps, 12);
        t.set("task", "reach");
        t.set("ik", "adaptive-dls");
        let s = check(&t).expect("ok");
        assert_eq!(s.config.task.id(), "reach");
        assert_eq!(s.config.control.method, IkMethod::AdaptiveDls);
    }

    #[test]
    fn view_transform_round_trips_and_keeps_z_up() {
        let v = ViewTransform::fit((-0.3, -0.1, 0.3, 0.3), 600.0, 400.0, 20.0);
        let (px, py) = v.to_screen(0.1, 0.2);
        let (x, z) = v.to_world(px, py);
        assert!((x - 0.1).abs() < 1e-12 && (z - 0.2).abs() < 1e-12);
        assert!(v.to_screen(0.0, 0.2).1 < v.to_screen(0.0, 0.0).1, "z up");
        assert_eq!(v.scale, 900.0);
    }

    #[test]
    fn readout_texts() {
        assert_eq!(metres(-0.00001), "0.0000");
        assert_eq!(metres(0.12346), "0.1235");
        assert_eq!(radians(-1.2344), "-1.234");
        assert_eq!(comparison_cell("success-rate", Some(0.7)), "70 %");
        assert_eq!(comparison_cell("mean-time", Some(12.345)), "12.35 s");
        assert_eq!(comparison_cell("collisions", Some(3.0)), "3");
        assert_eq!(comparison_cell("efficiency", None), "—");
    }
}
