//! The exports panel of a page: download buttons for the run's files (`data-download="<file>"`,
//! exactly the run's bytes) and the `bsv` and `python` command lines of the run, built from the
//! recipe's facts and the arguments ([`crate::view::command_line::RunArgs`]), each with a copy
//! button (`data-copy="bsv|python"`), the notes they need (options the Python recipe lacks,
//! the folder of an input file) and one status line for copies and failed downloads.
//!
//! Hooks: `data-cmd="python|bsv"` with `data-testid="<prefix>-cmd-…"`, notes
//! `data-<prefix>="python-note|file-note"`, status `data-testid="<prefix>-copy-status"`.

use std::cell::RefCell;
use std::rc::Rc;

use wasm_bindgen::JsValue;
use web_sys::Element;

use super::form::escape;
use crate::ui::ctx::{self, t_strings};
use crate::ui::dom::{self, show};
use crate::view::command_line::RunArgs;

/// A download button for `file` (its label is localized when built; pages rebuild their file
/// list on a language switch).
pub fn download_button(prefix: &str, file: &str) -> String {
    let label = t_strings("kit-exports-download", &[("file", file.to_string())]);
    format!(
        "<button type=\"button\" class=\"button primary kit-download {p}-download\" \
         data-download=\"{f}\">{label}</button>",
        p = escape(prefix),
        f = escape(file),
        label = escape(&label),
    )
}

/// The command-lines block: both lines with their copy buttons, notes and status line.
pub fn markup(prefix: &str) -> String {
    let p = escape(prefix);
    let line = |kind: &str, label: &str| {
        format!(
            "<div class=\"kit-cmd {p}-cmd\"><span class=\"kit-cmd-label {p}-cmd-label\" data-i18n=\"{label}\"></span>\
             <code data-cmd=\"{kind}\" data-testid=\"{p}-cmd-{kind}\"></code>\
             <button type=\"button\" class=\"button kit-copy {p}-copy\" data-copy=\"{kind}\" data-i18n=\"kit-exports-copy\"></button></div>"
        )
    };
    format!(
        "<div class=\"kit-exports {p}-commands\"><h3 class=\"kit-sub {p}-sub\" data-i18n=\"kit-exports-title\"></h3>\
         <p class=\"kit-hint {p}-hint\" data-i18n=\"kit-exports-hint\"></p>\
         {python}\
         <p class=\"kit-hint {p}-hint kit-cmd-note {p}-cmd-note\" data-{p}=\"python-note\" hidden></p>\
         {bsv}\
         <p class=\"kit-hint {p}-hint kit-cmd-note {p}-cmd-note\" data-{p}=\"file-note\" hidden></p>\
         <p class=\"kit-copy-status {p}-copy-status\" data-testid=\"{p}-copy-status\" role=\"status\"></p>\
         </div>",
        python = line("python", "kit-exports-python"),
        bsv = line("bsv", "kit-exports-bsv"),
    )
}

/// What the status line says.
#[derive(Debug, Clone, PartialEq)]
enum Status {
    Copied,
    CopyFailed,
    DownloadFailed { file: String, error: String },
}

impl Status {
    fn text(&self) -> String {
        match self {
            Status::Copied => ctx::t("kit-exports-copied"),
            Status::CopyFailed => ctx::t("kit-exports-copy-failed"),
            Status::DownloadFailed { file, error } => t_strings(
                "kit-exports-download-failed",
                &[("file", file.clone()), ("error", error.clone())],
            ),
        }
    }
}

/// The run the lines describe.
struct Shown {
    args: RunArgs,
    python: &'static str,
    input_name: Option<String>,
}

/// Command lines a page wrote itself ([`Exports::show_lines`]).
struct Lines {
    bsv: String,
    python: Option<String>,
    /// Fluent id of the note shown when there is no Python line.
    python_note_id: &'static str,
}

/// The panel's elements and what it shows.
pub struct Exports {
    cmd_python: Element,
    cmd_bsv: Element,
    python_note: Element,
    file_note: Element,
    status_line: Element,
    status: Rc<RefCell<Option<Status>>>,
    shown: RefCell<Option<Shown>>,
    lines: RefCell<Option<Lines>>,
}

impl Exports {
    /// Finds the block of [`markup`] under `root`.
    pub fn find(root: &Element, prefix: &str) -> Result<Exports, JsValue> {
        let find = |selector: String| dom::find::<Element>(root, &selector, "exports");
        Ok(Exports {
            cmd_python: find("[data-cmd=\"python\"]".into())?,
            cmd_bsv: find("[data-cmd=\"bsv\"]".into())?,
            python_note: find(format!("[data-{prefix}=\"python-note\"]"))?,
            file_note: find(format!("[data-{prefix}=\"file-note\"]"))?,
            status_line: find(format!("[data-testid=\"{prefix}-copy-status\"]"))?,
            status: Rc::new(RefCell::new(None)),
            shown: RefCell::new(None),
            lines: RefCell::new(None),
        })
    }

    /// Shows the command lines of `args` (recipe script `python`); `input_name` is the input
    /// file the run read, if any.
    pub fn show_run(&self, args: &RunArgs, python: &'static str, input_name: Option<&str>) {
        *self.shown.borrow_mut() = Some(Shown {
            args: args.clone(),
            python,
            input_name: input_name.map(str::to_string),
        });
        self.lines.borrow_mut().take();
        self.render();
    }

    /// Shows command lines the page wrote: `bsv` as given, and `python` only when the Python
    /// recipe makes the same files; with `None` the Python line and its copy button are hidden
    /// and `python_note_id` (a Fluent id) says why.
    pub fn show_lines(&self, bsv: &str, python: Option<&str>, python_note_id: &'static str) {
        self.shown.borrow_mut().take();
        *self.lines.borrow_mut() = Some(Lines {
            bsv: bsv.to_string(),
            python: python.map(str::to_string),
            python_note_id,
        });
        self.render();
    }

    fn render_lines(&self, lines: &Lines) {
        self.cmd_bsv.set_text_content(Some(&lines.bsv));
        self.cmd_python
            .set_text_content(Some(lines.python.as_deref().unwrap_or_default()));
        if let Some(Ok(Some(copy))) = self
            .cmd_python
            .parent_element()
            .map(|row| row.query_selector("[data-copy=\"python\"]"))
        {
            show(&copy, lines.python.is_some());
        }
        if lines.python.is_some() {
            show(&self.python_note, false);
        } else {
            self.python_note
                .set_text_content(Some(&ctx::t(lines.python_note_id)));
            show(&self.python_note, true);
        }
        show(&self.file_note, false);
    }

    fn render(&self) {
        if let Some(lines) = self.lines.borrow().as_ref() {
            self.render_lines(lines);
            let status = self.status.borrow().as_ref().map(Status::text);
            self.status_line
                .set_text_content(Some(&status.unwrap_or_default()));
            return;
        }
        let shown = self.shown.borrow();
        let Some(shown) = shown.as_ref() else {
            return;
        };
        self.cmd_python
            .set_text_content(Some(&shown.args.python_command(shown.python)));
        self.cmd_bsv
            .set_text_content(Some(&shown.args.bsv_command()));
        let options = shown.args.options_text();
        if options.is_empty() {
            show(&self.python_note, false);
        } else {
            self.python_note.set_text_content(Some(&t_strings(
                "kit-exports-python-no-options",
                &[("options", options)],
            )));
            show(&self.python_note, true);
        }
        match &shown.input_name {
            Some(name) => {
                self.file_note.set_text_content(Some(&t_strings(
                    "kit-exports-file-note",
                    &[("name", name.clone())],
                )));
                show(&self.file_note, true);
            }
            None => show(&self.file_note, false),
        }
        let status = self.status.borrow().as_ref().map(Status::text);
        self.status_line
            .set_text_content(Some(&status.unwrap_or_default()));
    }

    /// Clears the status line (the form changed).
    pub fn clear_status(&self) {
        *self.status.borrow_mut() = None;
        self.status_line.set_text_content(None);
    }

    /// A copy button: its command line to the clipboard, and the outcome in the status line.
    pub fn copy(&self, kind: &str) {
        let code = if kind == "python" {
            &self.cmd_python
        } else {
            &self.cmd_bsv
        };
        let text = code.text_content().unwrap_or_default();
        let status = self.status.clone();
        let line = self.status_line.clone();
        crate::ui::clipboard::copy_text(&text, move |ok| {
            let now = if ok {
                Status::Copied
            } else {
                Status::CopyFailed
            };
            line.set_text_content(Some(&now.text()));
            *status.borrow_mut() = Some(now);
        });
    }

    /// A download button: `text` saved as `file` (a CSV), exactly its bytes; a failure is
    /// said in the status line.
    pub fn download(&self, file: &str, text: &str) {
        if let Err(e) = crate::ui::download::download_text(file, text, "text/csv") {
            let error = e.as_string().unwrap_or_else(|| format!("{e:?}"));
            let now = Status::DownloadFailed {
                file: file.to_string(),
                error,
            };
            self.status_line.set_text_content(Some(&now.text()));
            *self.status.borrow_mut() = Some(now);
        }
    }

    /// Re-renders the notes and the status line in the current language.
    pub fn relocalize(&self) {
        self.render();
    }
}
