//! The live readouts beside the arm: q1, q2 (rad, deg), tip x, y (mm), det J, Yoshikawa
//! manipulability `w = sqrt(det(J Jᵀ))`, the singular values and the 2×2 Jacobian. Each number
//! is the text of an element `[data-readout="<name>"]`, plain (parseable) digits with the unit
//! in a sibling element; an element is only written when its text changes.

use wasm_bindgen::JsValue;
use web_sys::Element;

use crate::planar2r::PoseReport;

/// The readout names, in the order [`values`] returns them.
pub const NAMES: [&str; 14] = [
    "q1",
    "q2",
    "q1_deg",
    "q2_deg",
    "x_mm",
    "y_mm",
    "det_j",
    "manipulability",
    "sigma_min",
    "sigma_max",
    "j11",
    "j12",
    "j21",
    "j22",
];

/// An angle in radians: at least six significant digits and at least six decimals.
pub fn fmt_rad(x: f64) -> String {
    if !x.is_finite() {
        return x.to_string();
    }
    let a = x.abs();
    let decimals = if a > 0.0 {
        (5 - a.log10().floor() as i32).clamp(6, 12) as usize
    } else {
        6
    };
    clean_zero(format!("{x:.decimals$}"))
}

/// `x` with `sig` significant digits; scientific notation below 1e-4 and from 1e6.
pub fn fmt_sig(x: f64, sig: usize) -> String {
    if !x.is_finite() {
        return x.to_string();
    }
    let a = x.abs();
    if a == 0.0 {
        return "0".to_string();
    }
    if !(1e-4..1e6).contains(&a) {
        let d = sig.saturating_sub(1);
        return format!("{x:.d$e}");
    }
    let decimals = (sig as i32 - 1 - a.log10().floor() as i32).max(0) as usize;
    clean_zero(format!("{x:.decimals$}"))
}

/// `x` with a fixed number of decimals.
pub fn fmt_fixed(x: f64, decimals: usize) -> String {
    clean_zero(format!("{x:.decimals$}"))
}

/// `-0.000` → `0.000`.
fn clean_zero(s: String) -> String {
    match s.strip_prefix('-') {
        Some(rest) if rest.bytes().all(|b| b == b'0' || b == b'.') => rest.to_string(),
        _ => s,
    }
}

/// The readout texts of a pose, in [`NAMES`] order.
pub fn values(rep: &PoseReport) -> [String; 14] {
    let j = rep.jacobian;
    [
        fmt_rad(rep.q1),
        fmt_rad(rep.q2),
        fmt_fixed(rep.q1.to_degrees(), 3),
        fmt_fixed(rep.q2.to_degrees(), 3),
        fmt_fixed(rep.x * 1000.0, 3),
        fmt_fixed(rep.y * 1000.0, 3),
        fmt_sig(rep.det_j, 6),
        fmt_sig(rep.manipulability, 6),
        fmt_sig(rep.ellipse.sigma_min, 6),
        fmt_sig(rep.ellipse.sigma_max, 6),
        fmt_sig(j[0][0], 6),
        fmt_sig(j[0][1], 6),
        fmt_sig(j[1][0], 6),
        fmt_sig(j[1][1], 6),
    ]
}

/// The readout elements and the text each shows now.
pub struct Readouts {
    elements: Vec<Option<Element>>,
    shown: Vec<String>,
}

impl Readouts {
    /// Finds the `[data-readout]` elements under `root`.
    pub fn find(root: &Element) -> Result<Readouts, JsValue> {
        let mut elements = Vec::with_capacity(NAMES.len());
        for name in NAMES {
            elements.push(root.query_selector(&format!("[data-readout=\"{name}\"]"))?);
        }
        Ok(Readouts {
            elements,
            shown: vec![String::new(); NAMES.len()],
        })
    }

    /// Writes the pose's numbers (only those that changed).
    pub fn update(&mut self, rep: &PoseReport) {
        for ((text, element), shown) in values(rep)
            .into_iter()
            .zip(&self.elements)
            .zip(self.shown.iter_mut())
        {
            if *shown != text {
                if let Some(e) = element {
                    e.set_text_content(Some(&text));
                }
                *shown = text;
            }
        }
    }
}
