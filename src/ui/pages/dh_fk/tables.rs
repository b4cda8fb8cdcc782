//! The two tables: the modified-DH parameters of the chain with the current joint angles
//! (θ_i = q_i + offset), the walked row marked, and the pose of every frame as the CSV's rows
//! write it (the same cells, but a negative zero shown as `0.0`: [`numtext::unsigned_zero`]).

use wasm_bindgen::JsValue;
use web_sys::Element;

use crate::numtext;
use crate::recipes::dh_fk::{DEMO_CHAIN, JOINTS};
use crate::ui::dom;
use crate::view::dh_fk::cell;

/// α as written in the table: the number, and −π/2 by name.
fn alpha_text(alpha: f64) -> String {
    if (alpha + std::f64::consts::FRAC_PI_2).abs() < 1e-12 {
        format!("{} (−π/2)", cell(alpha))
    } else {
        cell(alpha)
    }
}

/// The DH table.
pub struct DhTable {
    /// Per row: the θ cell, the row element, its Show button.
    rows: Vec<(Element, Element, Element)>,
}

impl DhTable {
    /// Finds the table under `root` and writes the fixed columns.
    pub fn find(root: &Element) -> Result<DhTable, JsValue> {
        let mut rows = Vec::new();
        for (i, link) in DEMO_CHAIN.iter().enumerate() {
            let row: Element = dom::find(root, &format!("[data-dh-row=\"{}\"]", i + 1), "dh")?;
            let cellf =
                |name: &str| dom::find::<Element>(&row, &format!("[data-cell=\"{name}\"]"), "dh");
            cellf("alpha")?.set_text_content(Some(&alpha_text(link.alpha)));
            cellf("a")?.set_text_content(Some(&cell(link.a)));
            cellf("d")?.set_text_content(Some(&cell(link.d)));
            let button: Element = dom::find(&row, "[data-row]", "dh")?;
            rows.push((cellf("theta")?, row, button));
        }
        Ok(DhTable { rows })
    }

    /// θ of each row at joint angles `q`, and the walked row `row` (1-based) marked.
    pub fn show(&self, q: &[f64; JOINTS], row: usize) {
        for (i, ((theta, tr, button), link)) in self.rows.iter().zip(&DEMO_CHAIN).enumerate() {
            let text = cell(q[i] + link.theta_offset);
            if theta.text_content().as_deref() != Some(text.as_str()) {
                theta.set_text_content(Some(&text));
            }
            let on = i + 1 == row;
            let _ = tr.class_list().toggle_with_force("is-walked", on);
            let _ = button.set_attribute("aria-pressed", if on { "true" } else { "false" });
        }
    }
}

/// The frame-pose table.
pub struct PoseTable {
    /// Cells by row (frame 0..=3), 7 each.
    cells: Vec<Vec<Element>>,
}

impl PoseTable {
    pub fn find(root: &Element) -> Result<PoseTable, JsValue> {
        let mut cells = Vec::new();
        for i in 0..=JOINTS {
            let row: Element = dom::find(root, &format!("[data-pose-row=\"{i}\"]"), "dh")?;
            cells.push(dom::matching(&row, "td")?);
        }
        Ok(PoseTable { cells })
    }

    /// The CSV's data rows, cell for cell.
    pub fn show(&self, rows: &[Vec<String>]) {
        for (tds, row) in self.cells.iter().zip(rows) {
            for (td, text) in tds.iter().zip(row) {
                let text = numtext::unsigned_zero(text.clone());
                if td.text_content().as_deref() != Some(text.as_str()) {
                    td.set_text_content(Some(&text));
                }
            }
        }
    }
}
