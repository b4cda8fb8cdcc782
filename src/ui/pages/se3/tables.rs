//! The matrices: `T_A`, `T_B` and `T_A⁻¹ T_B` as 4×4 tables, and the result row exactly as
//! the CSV has it (the kernel's own text).

use wasm_bindgen::JsValue;
use web_sys::Element;

use crate::recipes::se3_relative::{run, CSV_NAME};
use crate::ui::dom;
use crate::view::se3_relative::{matrix_rows, Solved};

/// Writes `rows` into the cells of `table` (only the cells whose text changed).
pub fn fill<const N: usize>(table: &Element, rows: &[[String; N]; N]) {
    let Ok(cells) = dom::matching(table, "td") else {
        return;
    };
    for (cell, text) in cells.iter().zip(rows.iter().flatten()) {
        if cell.text_content().as_deref() != Some(text.as_str()) {
            cell.set_text_content(Some(text));
        }
    }
}

/// The matrices component.
pub struct Matrices {
    a: Element,
    b: Element,
    rel: Element,
    row: Element,
}

impl Matrices {
    /// Finds the tables and the row under `root`.
    pub fn find(root: &Element) -> Result<Matrices, JsValue> {
        let f = |sel: &str| -> Result<Element, JsValue> { dom::find(root, sel, "se3") };
        Ok(Matrices {
            a: f("[data-matrix=\"a\"]")?,
            b: f("[data-matrix=\"b\"]")?,
            rel: f("[data-matrix=\"rel\"]")?,
            row: f("[data-se3=\"csv-row\"]")?,
        })
    }

    /// Shows `solved`.
    pub fn show(&self, solved: &Solved) {
        fill(&self.a, &matrix_rows(&solved.t_a, 4));
        fill(&self.b, &matrix_rows(&solved.t_b, 4));
        fill(&self.rel, &matrix_rows(&solved.t_rel, 4));
        // The poses passed the recipe's check, so the run succeeds.
        if let Ok(out) = run(&solved.params) {
            let text = out.file(CSV_NAME).unwrap_or_default().replace("\r\n", "\n");
            let text = text.trim_end();
            if self.row.text_content().as_deref() != Some(text) {
                self.row.set_text_content(Some(text));
            }
        }
    }
}
