//! The result panel: the recipe's printed summary (verbatim, monospace), one block per CSV file
//! (name, size, a download button whose bytes are the run's, a table preview of the header and
//! first rows), and the equivalent command lines with copy buttons. Everything here describes
//! the last run, which stays on screen while the form is edited; a note says when the form no
//! longer matches it.

use wasm_bindgen::JsValue;

use super::command::RunArgs;
use super::preview::{preview, Preview, PREVIEW_ROWS};
use super::texts::{escape, group, size_text};
use super::Page;
use crate::i18n::FluentArg;
use crate::recipes::{self, CsvFile, RecipeOutput};
use crate::ui::ctx::{self, t_strings};
use crate::ui::dom::show;
use crate::ui::kit::worker::{WorkerFile, WorkerOutput};

/// The last successful run.
pub struct Shown {
    /// The arguments it ran with.
    pub args: RunArgs,
    /// The input file it read (traj-resample), by name.
    pub input_name: Option<String>,
    pub output: RecipeOutput,
    /// One preview per file of `output`.
    pub previews: Vec<Preview>,
    /// A worker run's files as Blobs (then `output`'s texts are only their first lines;
    /// background.rs).
    pub blobs: Vec<WorkerFile>,
}

impl Shown {
    /// A run's result, with its previews (one scan of each file for its row count).
    pub fn new(args: RunArgs, input_name: Option<String>, output: RecipeOutput) -> Shown {
        let previews = output.files.iter().map(|f| preview(&f.text)).collect();
        Shown {
            args,
            input_name,
            output,
            previews,
            blobs: Vec::new(),
        }
    }

    /// A worker run's result: previews from each file's head, sizes and row counts from the
    /// worker, the bytes left in the Blobs.
    pub fn from_worker(args: RunArgs, input_name: Option<String>, out: WorkerOutput) -> Shown {
        let previews = out
            .files
            .iter()
            .map(|f| Preview {
                total_rows: f.rows as usize,
                ..preview(&f.head)
            })
            .collect();
        let output = RecipeOutput {
            files: out
                .files
                .iter()
                .map(|f| CsvFile {
                    name: f.name.clone(),
                    text: f.head.clone(),
                })
                .collect(),
            summary: out.summary,
            warnings: Vec::new(),
        };
        Shown {
            args,
            input_name,
            output,
            previews,
            blobs: out.files,
        }
    }

    /// The size in bytes of file `name`.
    fn bytes(&self, name: &str, text: &str) -> u64 {
        self.blobs
            .iter()
            .find(|b| b.name == name)
            .map_or(text.len() as u64, |b| b.bytes)
    }
}

/// A count for Fluent: the number (plural selection) as `$<name>` and its grouped text as
/// `$<name>_text`.
fn count(name: &'static str, text_name: &'static str, n: usize) -> [(&'static str, FluentArg); 2] {
    [
        (name, FluentArg::from(n)),
        (text_name, FluentArg::from(group(n as u64))),
    ]
}

/// The table of a preview: a row-number column, the header, the first rows.
fn table_html(p: &Preview) -> String {
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
            html.push_str(&format!("<td>{}</td>", escape(cell)));
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

fn file_html(name: &str, bytes: u64, p: &Preview) -> String {
    let name_attr = escape(name);
    let mut size_args = count("rows", "rows_text", p.total_rows).to_vec();
    size_args.push(("columns", FluentArg::from(p.total_columns)));
    size_args.push(("size", FluentArg::from(size_text(bytes))));
    let size = ctx::t_args("drills-file-size", &size_args);
    let download = t_strings("drills-download", &[("file", name.to_string())]);
    let region = t_strings("drills-preview-label", &[("file", name.to_string())]);
    format!(
        "<article class=\"drills-file\" data-file=\"{name_attr}\">\
         <div class=\"drills-file-head\"><h3><code>{name_attr}</code></h3>\
         <span class=\"drills-file-size\">{size}</span>\
         <button type=\"button\" class=\"button primary\" data-download=\"{name_attr}\">{download}</button></div>\
         <div class=\"drills-table-box\" tabindex=\"0\" role=\"region\" aria-label=\"{region}\" \
         data-preview=\"{name_attr}\">{table}</div>\
         <p class=\"drills-hint drills-preview-note\">{note}</p></article>",
        size = escape(&size),
        download = escape(&download),
        region = escape(&region),
        table = table_html(p),
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
        let mut html = String::new();
        for (file, p) in shown.output.files.iter().zip(&shown.previews) {
            html.push_str(&file_html(
                &file.name,
                shown.bytes(&file.name, &file.text),
                p,
            ));
        }
        els.files.set_inner_html(&html);
        let script = recipes::find(shown.args.recipe).map_or("", |r| r.info.python);
        els.cmd_python
            .set_text_content(Some(&shown.args.python_command(script)));
        els.cmd_bsv
            .set_text_content(Some(&shown.args.bsv_command()));
        if shown.args.flags.is_empty() {
            show(&els.python_note, false);
        } else {
            let options: Vec<String> = shown
                .args
                .flags
                .iter()
                .map(|(n, v)| format!("--{n} {v}"))
                .collect();
            els.python_note.set_text_content(Some(&t_strings(
                "drills-python-no-options",
                &[("options", options.join(" "))],
            )));
            show(&els.python_note, true);
        }
        match &shown.input_name {
            Some(name) => {
                els.file_note.set_text_content(Some(&t_strings(
                    "drills-file-note",
                    &[("name", name.clone())],
                )));
                show(&els.file_note, true);
            }
            None => show(&els.file_note, false),
        }
        let copy = st.copy_status.map(ctx::t).unwrap_or_default();
        els.copy_status.set_text_content(Some(&copy));
        els.output.set_attribute("data-run", &st.runs.to_string())?;
        els.output.set_attribute("data-recipe", shown.args.recipe)?;
        Ok(())
    }
}
