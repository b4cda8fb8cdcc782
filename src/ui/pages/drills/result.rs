//! The result panel: the recipe's printed summary (verbatim, monospace), its warnings beside it
//! (diverged, goal not reached, ...: the CSV stays the recipe's), one block per CSV file (name,
//! size, a download button whose bytes are the run's, a table preview of the header and first
//! rows, numbers rounded unless "exact" is on), and the kit's exports panel with the equivalent
//! command lines. Everything here describes the last run, which stays on screen while the form
//! is edited; a note says when the form no longer matches it.

use wasm_bindgen::JsValue;

use super::markup::PREFIX;
use super::state::Page;
use super::texts::{group, size_text};
use crate::i18n::FluentArg;
use crate::recipes;
use crate::ui::ctx::{self, t_strings};
use crate::ui::dom::show;
use crate::ui::kit::exports::download_button;
use crate::ui::kit::form::escape;
use crate::view::table::{rounded, Preview, PREVIEW_ROWS};

/// A count for Fluent: the number (plural selection) as `$<name>` and its grouped text as
/// `$<name>_text`.
fn count(name: &'static str, text_name: &'static str, n: usize) -> [(&'static str, FluentArg); 2] {
    [
        (name, FluentArg::from(n)),
        (text_name, FluentArg::from(group(n as u64))),
    ]
}

/// One cell: rounded (the exact text in its tooltip) unless `exact`.
fn cell_html(tag: &str, cell: &str, exact: bool) -> String {
    let shown = if exact {
        cell.to_string()
    } else {
        rounded(cell)
    };
    if shown == cell {
        format!("<{tag}>{}</{tag}>", escape(cell))
    } else {
        format!(
            "<{tag} title=\"{}\">{}</{tag}>",
            escape(cell),
            escape(&shown)
        )
    }
}

/// The table of a preview: a row-number column, the header, the first rows.
fn table_html(p: &Preview, exact: bool) -> String {
    let mut html = String::from(
        "<table class=\"drills-table\"><thead><tr><th class=\"drills-rownum\" scope=\"col\">#</th>",
    );
    for cell in &p.header {
        html.push_str(&format!("<th scope=\"col\">{}</th>", escape(cell)));
    }
    html.push_str("</tr></thead><tbody>");
    for (i, row) in p.rows.iter().enumerate() {
        html.push_str(&format!("<tr><td class=\"drills-rownum\">{}</td>", i + 1));
        for cell in row {
            html.push_str(&cell_html("td", cell, exact));
        }
        html.push_str("</tr>");
    }
    html.push_str("</tbody></table>");
    html
}

/// The note under a preview: how many rows (and columns) it shows of how many.
fn preview_note(p: &Preview) -> String {
    let mut text = if p.total_rows == 0 {
        ctx::t("drills-preview-empty")
    } else if p.total_rows <= PREVIEW_ROWS {
        ctx::t_args(
            "drills-preview-all",
            &count("rows", "rows_text", p.total_rows),
        )
    } else {
        let mut args = count("rows", "rows_text", p.total_rows).to_vec();
        args.push(("shown", FluentArg::from(p.rows.len())));
        ctx::t_args("drills-preview-some", &args)
    };
    if p.header.len() < p.total_columns {
        text.push(' ');
        text.push_str(&ctx::t_args(
            "drills-preview-columns",
            &[
                ("shown", FluentArg::from(p.header.len())),
                ("columns", FluentArg::from(p.total_columns)),
            ],
        ));
    }
    text
}

fn file_html(name: &str, bytes: u64, p: &Preview, exact: bool) -> String {
    let name_attr = escape(name);
    let mut size_args = count("rows", "rows_text", p.total_rows).to_vec();
    size_args.push(("columns", FluentArg::from(p.total_columns)));
    size_args.push(("size", FluentArg::from(size_text(bytes))));
    let size = ctx::t_args("drills-file-size", &size_args);
    let region = t_strings("drills-preview-label", &[("file", name.to_string())]);
    format!(
        "<article class=\"drills-file\" data-file=\"{name_attr}\">\
         <div class=\"drills-file-head\"><h3><code>{name_attr}</code></h3>\
         <span class=\"drills-file-size\">{size}</span>{download}</div>\
         <div class=\"drills-table-box\" tabindex=\"0\" role=\"region\" aria-label=\"{region}\" \
         data-preview=\"{name_attr}\">{table}</div>\
         <p class=\"drills-hint drills-preview-note\">{note}</p></article>",
        size = escape(&size),
        download = download_button(PREFIX, name),
        region = escape(&region),
        table = table_html(p, exact),
        note = escape(&preview_note(p)),
    )
}

impl Page {
    /// Re-renders the result panel from the last run (also on a language switch).
    pub(super) fn render_output(&self) -> Result<(), JsValue> {
        let st = self.st.borrow();
        let els = &self.els;
        let Some(shown) = st.shown.as_ref() else {
            show(&els.empty, true);
            show(&els.result, false);
            els.files.set_inner_html("");
            els.output.set_attribute("data-run", &st.runs.to_string())?;
            return Ok(());
        };
        show(&els.empty, false);
        show(&els.result, true);
        els.summary.set_text_content(Some(&shown.output.summary));
        let warnings = shown.warnings();
        if warnings.is_empty() {
            els.warnings.set_inner_html("");
            show(&els.warnings, false);
        } else {
            let mut html = format!(
                "<h3 class=\"drills-sub\">{}</h3><ul>",
                escape(&ctx::t("drills-warnings-title"))
            );
            for w in &warnings {
                html.push_str(&format!("<li>{}</li>", escape(w)));
            }
            html.push_str("</ul>");
            els.warnings.set_inner_html(&html);
            show(&els.warnings, true);
        }
        let mut html = String::new();
        for (file, p) in shown.output.files.iter().zip(&shown.previews) {
            html.push_str(&file_html(
                &file.name,
                shown.bytes(&file.name, &file.text),
                p,
                st.exact,
            ));
        }
        els.files.set_inner_html(&html);
        let script = recipes::find_info(shown.args.recipe).map_or("", |r| r.python);
        self.exports
            .show_run(&shown.args, script, shown.input_name.as_deref());
        els.output.set_attribute("data-run", &st.runs.to_string())?;
        els.output.set_attribute("data-recipe", shown.args.recipe)?;
        Ok(())
    }

    /// What the live region says after a run: its warnings (the status line says "Done").
    pub(super) fn announce_result(&self) {
        let st = self.st.borrow();
        let Some(shown) = st.shown.as_ref() else {
            return;
        };
        let text = shown.warnings();
        if !text.is_empty() {
            self.readouts.announce(&text.join(" "));
        }
    }

    /// The "exact values" switch: tables show the CSV's text, or rounded numbers.
    pub(super) fn set_exact(&self, exact: bool) {
        self.st.borrow_mut().exact = exact;
        if let Err(e) = self.render_output() {
            web_sys::console::error_2(&"drills: result".into(), &e);
        }
    }

    /// A download button: the last run's file, exactly its bytes.
    pub(super) fn download(&self, file: &str) {
        let st = self.st.borrow();
        let shown = st.shown.as_ref();
        // A worker run's file is a Blob (background.rs).
        if let Some(blob) = shown.and_then(|s| s.blobs.iter().find(|b| b.name == file)) {
            if let Err(e) = crate::ui::kit::worker::download(blob) {
                web_sys::console::error_2(&"drills: download".into(), &e);
            }
        } else if let Some(text) = shown.and_then(|s| s.output.file(file)) {
            self.exports.download(file, text);
        }
    }

    /// `d`: the first file of the last run.
    pub(super) fn download_first(&self) {
        let first = self
            .st
            .borrow()
            .shown
            .as_ref()
            .and_then(|s| s.output.files.first())
            .map(|f| f.name.clone());
        if let Some(name) = first {
            self.download(&name);
        }
    }
}
