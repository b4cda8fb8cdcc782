//! The downloads panel, on the kit's exports ([`crate::ui::kit::exports`]): the three recipe
//! CSVs for the current parameters, made by the same code path as `bsv <recipe-id> <args>` (so
//! the bytes are the CLI's), each with its Python and `bsv` command lines (built from the
//! recipe's facts, [`RunArgs`]) and copy buttons, the arm view as PNG, and one status line for
//! copies and failed downloads. What a CSV needs is the pure `crate::view::ik2r` export model.

use std::cell::Cell;
use std::rc::Weak;

use wasm_bindgen::prelude::*;
use web_sys::Element;

use crate::ui::ctx::{self, t_strings};
use crate::ui::dom;
use crate::ui::kit::exports::{self as kit, RunEntry};
use crate::ui::kit::scope::Scope;
use crate::view::command_line::RunArgs;
use crate::view::form::{recipe_fields, FieldDef};
use crate::view::ik2r::{export_args, export_csv, ExportError, Params, State, ARM_PNG, EXPORTS};

/// The panel's markup: the three runs, the PNG, the status line (hidden until the page's
/// second stage wires it).
pub fn markup() -> String {
    let runs: Vec<RunEntry> = EXPORTS
        .iter()
        .map(|e| RunEntry {
            file: e.file,
            label_id: e.label_id,
        })
        .collect();
    format!(
        "<section class=\"ik2r-card ik2r-downloads ik2r-later\" data-section=\"exports\" hidden><h2 data-i18n=\"ik2r-downloads-title\"></h2>\
         <p class=\"ik2r-hint\" data-i18n=\"ik2r-downloads-hint\"></p><div class=\"ik2r-dl-grid\">{runs}\
         <div class=\"kit-run ik2r-run\"><button type=\"button\" class=\"button kit-download ik2r-download\" \
         data-download=\"{ARM_PNG}\" data-i18n=\"ik2r-dl-png\"></button>\
         <p class=\"ik2r-hint\" data-i18n=\"ik2r-dl-png-hint\"></p></div></div>{status}</section>",
        runs = kit::runs_markup("ik2r", &runs),
        status = kit::status_markup("ik2r"),
    )
}

/// The exports component.
pub(super) struct Exports {
    root: Element,
    panel: kit::Exports,
    /// Each recipe's fields (for its command lines), in [`EXPORTS`] order.
    fields: Vec<Vec<FieldDef>>,
    /// The parameters and q2 the lines show (a frame that changed neither writes nothing).
    shown_for: Cell<Option<(Params, f64)>>,
}

impl Exports {
    pub fn find(root: &Element) -> Result<Exports, JsValue> {
        let files: Vec<&str> = EXPORTS.iter().map(|e| e.file).collect();
        let fields = EXPORTS.iter().map(|e| recipe_fields(e.recipe)).collect();
        Ok(Exports {
            root: root.clone(),
            panel: kit::Exports::find_runs(root, "ik2r", &files)?,
            fields,
            shown_for: Cell::new(None),
        })
    }

    /// The download and copy buttons' listeners: a download goes to `on_download` with its
    /// file name, a copy to `on_copy` with its key.
    pub fn attach<H: 'static>(
        &self,
        host: &Weak<H>,
        scope: &mut Scope,
        on_download: impl Fn(&H, &str) + Clone + 'static,
        on_copy: impl Fn(&H, &str) + Clone + 'static,
    ) -> Result<(), JsValue> {
        for button in dom::matching(&self.root, "[data-download]")? {
            let file = button.get_attribute("data-download").unwrap_or_default();
            let on_download = on_download.clone();
            scope.listen_for(&button, "click", host, move |h, _| on_download(h, &file))?;
        }
        for button in dom::matching(&self.root, "[data-copy]")? {
            let key = button.get_attribute("data-copy").unwrap_or_default();
            let on_copy = on_copy.clone();
            scope.listen_for(&button, "click", host, move |h, _| on_copy(h, &key))?;
        }
        Ok(())
    }

    /// Copies the command line `key` (the panel says so on its status line).
    pub fn copy(&self, key: &str) {
        self.panel.copy(key);
    }

    /// Downloads `file`: a recipe CSV of `st`, or the arm view (`arm`, flattened) as PNG; a
    /// failure is said on the status line.
    pub fn download(
        &self,
        file: &str,
        st: &State,
        arm: impl FnOnce() -> Result<web_sys::HtmlCanvasElement, JsValue>,
    ) {
        let result = if file == ARM_PNG {
            arm().and_then(|c| crate::ui::kit::png::download(&c, ARM_PNG))
        } else {
            csv_download(file, st)
        };
        if let Err(e) = result {
            self.panel.download_failed(file, &e);
        }
    }

    /// The command lines of the current parameters (the jacobian-2r ones follow the pose's
    /// q2); only the lines that changed are written.
    pub fn update_commands(&self, st: &State) {
        let was = self.shown_for.replace(Some((st.params, st.q2)));
        let params_same = was.is_some_and(|(p, _)| p == st.params);
        if params_same && was.is_some_and(|(_, q2)| q2 == st.q2) {
            return;
        }
        for (export, fields) in EXPORTS.iter().zip(&self.fields) {
            if params_same && !export.follows_q2 {
                continue;
            }
            let texts: Vec<Option<String>> = export_args(export, &st.params, st.q2)
                .into_iter()
                .map(Some)
                .collect();
            let args = RunArgs::new(export.recipe.id, fields, &texts);
            if self.panel.shows(export.file, &args) {
                continue;
            }
            let script = export.recipe.python;
            self.panel.show_run_for(export.file, &args, script);
        }
    }

    pub fn relocalize(&self) {
        self.panel.relocalize();
    }
}

/// Makes and saves one CSV.
fn csv_download(file: &str, st: &State) -> Result<(), JsValue> {
    let Some(export) = EXPORTS.iter().find(|e| e.file == file) else {
        return Ok(());
    };
    match export_csv(export, &st.params, st.q2) {
        Ok(text) => crate::ui::download::download_text(file, &text, "text/csv"),
        Err(ExportError::Recipe(e)) => Err(JsValue::from_str(&ctx::error_text(&e))),
        Err(ExportError::MissingFile { recipe, file }) => Err(JsValue::from_str(&t_strings(
            "ik2r-dl-missing-file",
            &[("recipe", recipe.to_string()), ("file", file.to_string())],
        ))),
    }
}
