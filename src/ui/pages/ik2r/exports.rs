//! The downloads panel: the three recipe CSVs for the current parameters, made by the same
//! code path as `bsv <recipe-id> <args>` (so the bytes are the CLI's), the equivalent command
//! lines (Python recipe and `bsv`) with copy buttons, the arm view as PNG, and the status of
//! the last copy. What a CSV needs (arguments, command lines) is the pure
//! `crate::view::ik2r` export model.

use std::cell::Cell;
use std::rc::{Rc, Weak};

use wasm_bindgen::prelude::*;
use web_sys::Element;

use super::{role, Page};
use crate::ui::clipboard;
use crate::ui::ctx::{self, t_strings};
use crate::ui::dom::{self, show, Listener};
use crate::view::ik2r::{
    export_commands, export_csv, ExportError, Params, State, ARM_PNG, EXPORTS,
};

/// The exports component.
pub(super) struct Exports {
    root: Element,
    copy_status: Element,
    /// The last copy result's message id.
    copied: Rc<Cell<Option<&'static str>>>,
    /// The command lines as shown (python, bsv for each export), to skip unchanged writes.
    shown: Vec<String>,
    /// The parameters and q2 the shown command lines were made for (a drag frame that
    /// changed neither formats nothing).
    shown_for: Option<(Params, f64)>,
    /// The last download error per file (re-rendered on a language switch).
    failed: Vec<(String, String)>,
}

impl Exports {
    pub fn find(root: &Element) -> Result<Exports, JsValue> {
        Ok(Exports {
            root: root.clone(),
            copy_status: role(root, "copy-status")?,
            copied: Rc::new(Cell::new(None)),
            shown: Vec::new(),
            shown_for: None,
            failed: Vec::new(),
        })
    }

    pub fn attach(&self, weak: &Weak<Page>, out: &mut Vec<Listener>) -> Result<(), JsValue> {
        for button in dom::matching(&self.root, "[data-download]")? {
            let file = button.get_attribute("data-download").unwrap_or_default();
            out.push(Listener::for_page(&button, "click", weak, move |p, _| {
                let st = *p.state.borrow();
                let result = if file == ARM_PNG {
                    p.arm
                        .borrow()
                        .flatten()
                        .and_then(|c| crate::ui::kit::png::download(&c, ARM_PNG))
                } else {
                    csv_download(&file, &st)
                };
                p.exports.borrow_mut().show_result(&file, result);
            })?);
        }
        for button in dom::matching(&self.root, "[data-copy]")? {
            let key = button.get_attribute("data-copy").unwrap_or_default();
            out.push(Listener::for_page(&button, "click", weak, move |p, _| {
                p.exports.borrow().copy_command(&key)
            })?);
        }
        Ok(())
    }

    /// Shows or clears the error slot under a download button.
    fn show_result(&mut self, file: &str, result: Result<(), JsValue>) {
        self.failed.retain(|(f, _)| f != file);
        if let Err(e) = result {
            let msg = e.as_string().unwrap_or_else(|| format!("{e:?}"));
            self.failed.push((file.to_string(), msg));
        }
        self.render_errors(file);
    }

    fn render_errors(&self, file: &str) {
        let Ok(Some(slot)) = self
            .root
            .query_selector(&format!("[data-dl-error=\"{file}\"]"))
        else {
            return;
        };
        match self.failed.iter().find(|(f, _)| f == file) {
            Some((_, msg)) => {
                slot.set_text_content(Some(&t_strings(
                    "ik2r-dl-failed",
                    &[("error", msg.clone())],
                )));
                show(&slot, true);
            }
            None => show(&slot, false),
        }
    }

    /// A copy button: the command line beside it to the clipboard.
    fn copy_command(&self, key: &str) {
        let Ok(Some(code)) = self.root.query_selector(&format!("[data-cmd=\"{key}\"]")) else {
            return;
        };
        let text = code.text_content().unwrap_or_default();
        let element = self.copy_status.clone();
        let status = self.copied.clone();
        clipboard::copy_text(&text, move |ok| {
            let id = if ok {
                "ik2r-copied"
            } else {
                "ik2r-copy-failed"
            };
            status.set(Some(id));
            element.set_text_content(Some(&ctx::t(id)));
        });
    }

    /// The command lines under the downloads (only the changed ones are written; the
    /// jacobian-2r one follows the pose's q2).
    pub fn update_commands(&mut self, st: &State) {
        let key = (st.params, st.q2);
        if self.shown_for == Some(key) {
            return;
        }
        self.shown_for = Some(key);
        let mut shown = Vec::with_capacity(2 * EXPORTS.len());
        for export in EXPORTS {
            let (python, bsv) = export_commands(&export, &st.params, st.q2);
            shown.push(python);
            shown.push(bsv);
        }
        if self.shown == shown {
            return;
        }
        let mut texts = shown.iter();
        for export in EXPORTS {
            for kind in ["python", "bsv"] {
                let text = texts.next().map_or("", String::as_str);
                let selector = format!("[data-cmd=\"{}:{kind}\"]", export.file);
                if let Ok(Some(code)) = self.root.query_selector(&selector) {
                    if code.text_content().as_deref() != Some(text) {
                        code.set_text_content(Some(text));
                    }
                }
            }
        }
        self.shown = shown;
    }

    pub fn relocalize(&self) {
        let status = self.copied.get().map(ctx::t).unwrap_or_default();
        self.copy_status.set_text_content(Some(&status));
        for (file, _) in &self.failed {
            self.render_errors(file);
        }
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
