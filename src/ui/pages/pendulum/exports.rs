//! Exports (the kit's panel): `pendulum_energy.csv` (the recipe's own run with the page's
//! arguments, so it is byte for byte what `bsv pendulum-energy` writes), a PNG of the plots,
//! and the command lines: `bsv` with every flag, `python` only when just the duration differs
//! from the defaults (the Python recipe takes nothing else).

use wasm_bindgen::JsValue;
use web_sys::Element;

use crate::recipes::pendulum_energy::{run, PendulumParams, CSV_NAME, INFO};
use crate::ui::ctx;
use crate::ui::kit::exports::{self as kit, Exports as KitExports};
use crate::view::command_line::shell_word;
use crate::view::pendulum::python_equivalent;

/// The PNG of the plots.
pub const PNG_NAME: &str = "pendulum_energy_plots.png";

/// The panel's markup: the two downloads, then the kit's command lines.
pub fn markup() -> String {
    format!(
        "<div class=\"pend-buttons\">{csv}\
         <button type=\"button\" class=\"button kit-download pend-download\" data-download=\"{PNG_NAME}\" \
         data-i18n=\"pendulum-download-png\"></button></div>{lines}",
        csv = kit::download_button("pend", CSV_NAME),
        lines = kit::markup("pend"),
    )
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

/// The exports component.
pub struct Exports {
    pub kit: KitExports,
    pub csv: Element,
    pub png: Element,
}

impl Exports {
    /// Finds the panel under `root`.
    pub fn find(root: &Element) -> Result<Exports, JsValue> {
        let f =
            |sel: &str| -> Result<Element, JsValue> { crate::ui::dom::find(root, sel, "pendulum") };
        Ok(Exports {
            kit: KitExports::find(root, "pend")?,
            csv: f(&format!("[data-download=\"{CSV_NAME}\"]"))?,
            png: f(&format!("[data-download=\"{PNG_NAME}\"]"))?,
        })
    }

    /// Shows the command lines of `params` run with `args` (the CLI's, every flag).
    pub fn update(&self, params: &PendulumParams, args: &[String]) {
        let python = python_equivalent(params).then(|| {
            let duration = args.first().map(|d| shell_word(d)).unwrap_or_default();
            format!("python {} {duration}", INFO.python)
        });
        self.kit
            .show_lines(&bsv_line(args), python.as_deref(), "pendulum-python-none");
    }

    /// Downloads the CSV of `params`.
    pub fn download_csv(&self, params: &PendulumParams) {
        match run(params) {
            Ok(out) => self
                .kit
                .download(CSV_NAME, out.file(CSV_NAME).unwrap_or_default()),
            // The page runs only validated parameters; say so if that ever fails.
            Err(e) => web_sys::console::warn_1(&JsValue::from_str(&ctx::error_text(&e))),
        }
    }

    /// The CSV button's label in the current language (the kit localizes it when built).
    pub fn relocalize(&self) {
        let label = ctx::t_strings("kit-exports-download", &[("file", CSV_NAME.to_string())]);
        self.csv.set_text_content(Some(&label));
        self.kit.relocalize();
    }
}
