//! Exports: `pendulum_energy.csv` (the recipe's own run with the page's arguments, so it is
//! byte for byte what `bsv pendulum-energy` writes), a PNG of the plots, and the command
//! lines (`bsv` with every flag; `python` only when just the duration differs).

use wasm_bindgen::JsValue;
use web_sys::Element;

use crate::recipes::pendulum_energy::{run, PendulumParams, CSV_NAME, INFO};
use crate::ui::command_line::shell_word;
use crate::ui::{ctx, dom};
use crate::view::pendulum::python_equivalent;

/// The exports component.
pub struct Exports {
    pub csv: Element,
    pub png: Element,
    pub copy_bsv: Element,
    pub copy_python: Element,
    bsv: Element,
    python: Element,
    python_note: Element,
    pub status: Element,
}

/// `bsv pendulum-energy …` for `args`.
pub fn bsv_line(args: &[String]) -> String {
    let mut line = format!("bsv {}", INFO.id);
    for a in args {
        line.push(' ');
        line.push_str(&shell_word(a));
    }
    line
}

impl Exports {
    /// Finds the elements under `root`.
    pub fn find(root: &Element) -> Result<Exports, JsValue> {
        let f = |sel: &str| -> Result<Element, JsValue> { dom::find(root, sel, "pendulum") };
        Ok(Exports {
            csv: f("[data-download=\"pendulum_energy.csv\"]")?,
            png: f("[data-download=\"pendulum_energy_plots.png\"]")?,
            copy_bsv: f("[data-action=\"copy-bsv\"]")?,
            copy_python: f("[data-action=\"copy-python\"]")?,
            bsv: f("[data-command=\"bsv\"]")?,
            python: f("[data-command=\"python\"]")?,
            python_note: f("[data-pend=\"python-note\"]")?,
            status: f("[data-pend=\"copy-status\"]")?,
        })
    }

    /// Shows the command lines of `params` run with `args`.
    pub fn update(&self, params: &PendulumParams, args: &[String]) {
        self.bsv.set_text_content(Some(&bsv_line(args)));
        let python = python_equivalent(params);
        let line = args
            .first()
            .map(|d| format!("python {} {}", INFO.python, shell_word(d)))
            .unwrap_or_default();
        self.python
            .set_text_content(Some(if python { line.as_str() } else { "" }));
        dom::show(&self.python_note, !python);
        dom::show(&self.copy_python, python);
    }

    /// The Python line, if the Python recipe makes the same CSV.
    pub fn python_line(&self) -> Option<String> {
        self.python.text_content().filter(|t| !t.is_empty())
    }

    /// The `bsv` line.
    pub fn bsv_text(&self) -> String {
        self.bsv.text_content().unwrap_or_default()
    }

    /// Downloads the CSV of `params`.
    pub fn download_csv(&self, params: &PendulumParams) -> Result<(), JsValue> {
        let out = run(params).map_err(|e| JsValue::from_str(&ctx::error_text(&e)))?;
        let text = out.file(CSV_NAME).unwrap_or_default();
        crate::ui::download::download_text(CSV_NAME, text, "text/csv")
    }
}
