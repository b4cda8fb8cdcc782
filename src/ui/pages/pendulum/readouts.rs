//! The readouts (the kit's panel): `data-readout` values of the state shown (the CSV's row
//! `k` after `k` steps), each with its unit and its full-precision value in `data-value`;
//! the drift of each integrator in compare mode; a polite screen-reader summary when the
//! state stops moving.

use wasm_bindgen::JsValue;
use web_sys::Element;

use crate::pyfmt::py_float;
use crate::ui::ctx;
use crate::ui::dom;
use crate::ui::kit::readouts::{self as kit, Readouts as KitReadouts};

/// `(key, Fluent id of the label, Fluent id of the unit)`; `drift-euler`/`drift-rk4` only show
/// in compare mode.
pub const READOUTS: [(&str, &str, &str); 11] = [
    ("t", "pendulum-ro-t", "pendulum-unit-s"),
    ("theta", "pendulum-ro-theta", "pendulum-unit-rad"),
    ("omega", "pendulum-ro-omega", "pendulum-unit-rad-s"),
    ("ke", "pendulum-ro-ke", "pendulum-unit-j"),
    ("pe", "pendulum-ro-pe", "pendulum-unit-j"),
    ("total", "pendulum-ro-total", "pendulum-unit-j"),
    ("true-energy", "pendulum-ro-true", "pendulum-unit-j"),
    ("drift", "pendulum-ro-drift", "pendulum-unit-drift"),
    ("period", "pendulum-ro-period", "pendulum-unit-s"),
    (
        "drift-euler",
        "pendulum-ro-drift-euler",
        "pendulum-unit-drift",
    ),
    ("drift-rk4", "pendulum-ro-drift-rk4", "pendulum-unit-drift"),
];

/// The readouts' markup (the kit's list and live region).
pub fn markup() -> String {
    let items: Vec<(&str, &str)> = READOUTS.iter().map(|(k, l, _)| (*k, *l)).collect();
    format!(
        "{}{}",
        kit::markup("pend", &items),
        kit::live_markup("pend")
    )
}

/// The values shown.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Values {
    pub t: f64,
    pub theta: f64,
    pub omega: f64,
    pub ke: f64,
    pub pe: f64,
    pub total: f64,
    pub true_energy: f64,
    pub drift: f64,
    pub period: Option<f64>,
    /// Compare mode: (Euler's, RK4's) drift.
    pub drifts: Option<(f64, f64)>,
}

impl Values {
    fn get(&self, key: &str) -> Option<f64> {
        match key {
            "t" => Some(self.t),
            "theta" => Some(self.theta),
            "omega" => Some(self.omega),
            "ke" => Some(self.ke),
            "pe" => Some(self.pe),
            "total" => Some(self.total),
            "true-energy" => Some(self.true_energy),
            "drift" => Some(self.drift),
            "period" => self.period,
            "drift-euler" => self.drifts.map(|d| d.0),
            _ => self.drifts.map(|d| d.1),
        }
    }
}

/// The readouts component.
pub struct Readouts {
    kit: KitReadouts,
    /// The rows of the compare-mode drifts.
    compare_rows: Vec<Element>,
    /// Each readout's unit in the current language.
    units: Vec<String>,
    /// What is shown (nothing is rewritten when it has not changed).
    shown: Option<Values>,
}

/// `x` with `digits` significant digits (plain notation between 1e-4 and 1e6).
pub fn sig(x: f64, digits: usize) -> String {
    if !x.is_finite() {
        return "—".to_string();
    }
    if x == 0.0 {
        return "0".to_string();
    }
    let mag = x.abs().log10().floor() as i32;
    if !(-4..6).contains(&mag) {
        return format!("{:.*e}", digits.saturating_sub(1), x);
    }
    let decimals = (digits as i32 - 1 - mag).max(0) as usize;
    crate::numtext::fixed(x, decimals)
}

fn units() -> Vec<String> {
    READOUTS.iter().map(|(_, _, u)| ctx::t(u)).collect()
}

impl Readouts {
    /// Finds the panel under `root`.
    pub fn find(root: &Element) -> Result<Readouts, JsValue> {
        let kit = KitReadouts::find(root)?;
        let compare_rows = ["drift-euler", "drift-rk4"]
            .iter()
            .filter_map(|k| kit.element(k).and_then(|e| e.parent_element()))
            .collect();
        Ok(Readouts {
            kit,
            compare_rows,
            units: units(),
            shown: None,
        })
    }

    /// Shows `v`.
    pub fn show(&mut self, v: &Values) {
        if self.shown.as_ref() == Some(v) {
            return;
        }
        for ((key, _, _), unit) in READOUTS.iter().zip(&self.units) {
            let value = v.get(key);
            let digits = if key.starts_with("drift") { 3 } else { 6 };
            let text =
                value.map_or_else(|| "—".to_string(), |x| format!("{} {unit}", sig(x, digits)));
            self.kit
                .set_with_value(key, &text, &value.map_or_else(String::new, py_float));
        }
        for row in &self.compare_rows {
            dom::show(row, v.drifts.is_some());
        }
        self.shown = Some(*v);
    }

    /// Tells screen readers where the pendulum stopped (throttled by the kit).
    pub fn announce(&self, v: &Values) {
        self.kit.announce(&ctx::t_strings(
            "pendulum-live",
            &[
                ("t", sig(v.t, 6)),
                ("theta", sig(v.theta, 4)),
                ("total", sig(v.total, 4)),
            ],
        ));
    }

    /// The language changed: units again, values redrawn.
    pub fn relocalize(&mut self) {
        self.units = units();
        if let Some(v) = self.shown.take() {
            self.show(&v);
        }
    }
}
