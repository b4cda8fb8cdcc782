//! The readouts: `data-readout` values of the state shown (the CSV's row `k` after `k`
//! steps), each with its full-precision value in `data-value`.

use wasm_bindgen::JsValue;
use web_sys::Element;

use crate::pyfmt::py_float;
use crate::ui::dom;

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

/// The readouts' markup.
pub fn markup() -> String {
    let mut html = String::from("<dl class=\"pend-readouts\">");
    for (key, label, unit) in READOUTS {
        html.push_str(&format!(
            "<div class=\"pend-ro\" data-ro-row=\"{key}\"><dt data-i18n=\"{label}\"></dt>\
             <dd><output data-readout=\"{key}\"></output> <span class=\"pend-unit\" data-i18n=\"{unit}\"></span></dd></div>"
        ));
    }
    html.push_str("</dl><p class=\"pend-sr\" data-pend=\"summary\" aria-live=\"polite\"></p>");
    html
}

/// The values shown.
#[derive(Debug, Clone, Copy, Default)]
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

/// The readouts component.
pub struct Readouts {
    outs: Vec<(&'static str, Element)>,
    rows: Vec<(&'static str, Element)>,
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
    format!("{x:.decimals$}")
}

impl Readouts {
    /// Finds the outputs under `root`.
    pub fn find(root: &Element) -> Result<Readouts, JsValue> {
        let mut outs = Vec::new();
        let mut rows = Vec::new();
        for (key, _, _) in READOUTS {
            outs.push((
                key,
                dom::find(root, &format!("[data-readout=\"{key}\"]"), "pendulum")?,
            ));
            rows.push((
                key,
                dom::find(root, &format!("[data-ro-row=\"{key}\"]"), "pendulum")?,
            ));
        }
        Ok(Readouts { outs, rows })
    }

    /// Shows `v`.
    pub fn show(&self, v: &Values) {
        for (key, out) in &self.outs {
            let value = match *key {
                "t" => Some(v.t),
                "theta" => Some(v.theta),
                "omega" => Some(v.omega),
                "ke" => Some(v.ke),
                "pe" => Some(v.pe),
                "total" => Some(v.total),
                "true-energy" => Some(v.true_energy),
                "drift" => Some(v.drift),
                "period" => v.period,
                "drift-euler" => v.drifts.map(|d| d.0),
                _ => v.drifts.map(|d| d.1),
            };
            let digits = if key.starts_with("drift") { 3 } else { 6 };
            out.set_text_content(Some(
                &value.map_or_else(|| "—".to_string(), |x| sig(x, digits)),
            ));
            let _ = out.set_attribute("data-value", &value.map_or_else(String::new, py_float));
        }
        for (key, row) in &self.rows {
            if key.starts_with("drift-") {
                dom::show(row, v.drifts.is_some());
            }
        }
    }
}
