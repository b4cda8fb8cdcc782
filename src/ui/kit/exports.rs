//! The exports panel of a page: download buttons for the run's files (`data-download="<file>"`,
//! exactly the run's bytes) and the `bsv` and `python` command lines of the run, built from the
//! recipe's facts and the arguments ([`crate::view::command_line::RunArgs`]), each with a copy
//! button (`data-copy="bsv|python"`), the notes they need (options the Python recipe lacks,
//! the folder of an input file) and one status line for copies and failed downloads.
//!
//! Hooks: `data-cmd="python|bsv"` with `data-testid="<prefix>-cmd-…"`, notes
//! `data-<prefix>="python-note|file-note"`, status `data-testid="<prefix>-copy-status"` (and
//! `data-<prefix>="copy-status"`).
//!
//! A panel of several runs ([`runs_markup`], the IK page's three recipes) keys each run by
//! its file: `data-download="<file>"`, `data-cmd="<file>:python|bsv"`, `data-copy=` the same,
//! `data-cmd-note="<file>"`; [`Exports::find_runs`] finds them and [`Exports::show_run_for`]
//! writes one run's lines (only the texts that changed).

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
         {status}</div>",
        python = line("python", "kit-exports-python"),
        bsv = line("bsv", "kit-exports-bsv"),
        status = status_markup(prefix),
    )
}

/// The status line of a panel (copies, failed downloads).
pub fn status_markup(prefix: &str) -> String {
    let p = escape(prefix);
    format!(
        "<p class=\"kit-copy-status {p}-copy-status\" data-testid=\"{p}-copy-status\" \
         data-{p}=\"copy-status\" role=\"status\"></p>"
    )
}

/// One run of a panel of several: the file it downloads (its key) and the Fluent id of the
/// download button.
#[derive(Debug, Clone, Copy)]
pub struct RunEntry {
    pub file: &'static str,
    pub label_id: &'static str,
}

/// The runs of a panel of several, each a download button and its two command lines with copy
/// buttons and a note (options the Python line lacks). Put [`status_markup`] once after them.
pub fn runs_markup(prefix: &str, runs: &[RunEntry]) -> String {
    let p = escape(prefix);
    let mut html = String::new();
    for run in runs {
        let f = escape(run.file);
        let line = |kind: &str, label: &str| {
            format!(
                "<div class=\"kit-cmd {p}-cmd\"><span class=\"kit-cmd-label {p}-cmd-label\" data-i18n=\"{label}\"></span>\
                 <code data-cmd=\"{f}:{kind}\"></code>\
                 <button type=\"button\" class=\"button kit-copy {p}-copy\" data-copy=\"{f}:{kind}\" \
                 data-i18n=\"kit-exports-copy\"></button></div>"
            )
        };
        html.push_str(&format!(
            "<div class=\"kit-run {p}-run\">\
             <button type=\"button\" class=\"button primary kit-download {p}-download\" data-download=\"{f}\" \
             data-i18n=\"{label}\"></button>{python}{bsv}\
             <p class=\"kit-hint {p}-hint kit-cmd-note {p}-cmd-note\" data-cmd-note=\"{f}\" hidden></p></div>",
            label = escape(run.label_id),
            python = line("python", "kit-exports-python"),
            bsv = line("bsv", "kit-exports-bsv"),
        ));
    }
    html
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

/// What the lines describe.
enum Shown {
    /// A recipe run: both lines built from its arguments.
    Run {
        args: RunArgs,
        python: &'static str,
        input_name: Option<String>,
    },
    /// Lines the page wrote itself ([`Exports::show_lines`]).
    Written {
        bsv: String,
        /// `None`: no Python line makes the same files.
        python: Option<String>,
        /// Fluent id of the note shown when there is no Python line.
        python_note_id: &'static str,
    },
}

/// The elements of one run's lines and the texts they show.
struct Lines {
    /// The run's key (`None` for the one run of [`markup`]).
    key: Option<String>,
    python: Element,
    bsv: Element,
    /// The note on options the Python line lacks.
    python_note: Option<Element>,
    /// The note on the input file's folder (one-run panels).
    file_note: Option<Element>,
    shown: Option<Shown>,
    /// The texts written (python, bsv, note), to skip unchanged writes.
    written: [String; 3],
    /// Whether the Python line's copy button shows (`None`: not set yet).
    python_copy_shown: Option<bool>,
}

/// The panel's elements and what it shows.
pub struct Exports {
    lines: RefCell<Vec<Lines>>,
    status_line: Element,
    status: Rc<RefCell<Option<Status>>>,
}

impl Exports {
    /// Finds the block of [`markup`] under `root`.
    pub fn find(root: &Element, prefix: &str) -> Result<Exports, JsValue> {
        let find = |selector: String| dom::find::<Element>(root, &selector, "exports");
        Ok(Exports {
            lines: RefCell::new(vec![Lines {
                key: None,
                python: find("[data-cmd=\"python\"]".into())?,
                bsv: find("[data-cmd=\"bsv\"]".into())?,
                python_note: Some(find(format!("[data-{prefix}=\"python-note\"]"))?),
                file_note: Some(find(format!("[data-{prefix}=\"file-note\"]"))?),
                shown: None,
                written: Default::default(),
                python_copy_shown: None,
            }]),
            status_line: find(format!("[data-testid=\"{prefix}-copy-status\"]"))?,
            status: Rc::new(RefCell::new(None)),
        })
    }

    /// Finds the runs of [`runs_markup`] (`files` in order) and the [`status_markup`] line
    /// under `root`.
    pub fn find_runs(root: &Element, prefix: &str, files: &[&str]) -> Result<Exports, JsValue> {
        let find = |selector: String| dom::find::<Element>(root, &selector, "exports");
        let mut lines = Vec::with_capacity(files.len());
        for file in files {
            lines.push(Lines {
                key: Some(file.to_string()),
                python: find(format!("[data-cmd=\"{file}:python\"]"))?,
                bsv: find(format!("[data-cmd=\"{file}:bsv\"]"))?,
                python_note: root.query_selector(&format!("[data-cmd-note=\"{file}\"]"))?,
                file_note: None,
                shown: None,
                written: Default::default(),
                python_copy_shown: None,
            });
        }
        Ok(Exports {
            lines: RefCell::new(lines),
            status_line: find(format!("[data-testid=\"{prefix}-copy-status\"]"))?,
            status: Rc::new(RefCell::new(None)),
        })
    }

    /// Shows the command lines of `args` (recipe script `python`); `input_name` is the input
    /// file the run read, if any.
    pub fn show_run(&self, args: &RunArgs, python: &'static str, input_name: Option<&str>) {
        if let Some(lines) = self.lines.borrow_mut().first_mut() {
            lines.show(args, python, input_name);
        }
    }

    /// Shows the command lines of the run keyed `file` (a panel of several runs).
    pub fn show_run_for(&self, file: &str, args: &RunArgs, python: &'static str) {
        let mut lines = self.lines.borrow_mut();
        if let Some(lines) = lines.iter_mut().find(|l| l.key.as_deref() == Some(file)) {
            lines.show(args, python, None);
        }
    }

    /// Whether the run keyed `file` shows the lines of `args` already.
    pub fn shows(&self, file: &str, args: &RunArgs) -> bool {
        self.lines
            .borrow()
            .iter()
            .find(|l| l.key.as_deref() == Some(file))
            .and_then(|l| l.shown.as_ref())
            .is_some_and(|s| matches!(s, Shown::Run { args: shown, .. } if shown == args))
    }

    /// Shows command lines the page wrote: `bsv` as given, and `python` only when the Python
    /// recipe makes the same files; with `None` the Python line and its copy button are hidden
    /// and `python_note_id` (a Fluent id) says why.
    pub fn show_lines(&self, bsv: &str, python: Option<&str>, python_note_id: &'static str) {
        if let Some(lines) = self.lines.borrow_mut().first_mut() {
            lines.shown = Some(Shown::Written {
                bsv: bsv.to_string(),
                python: python.map(str::to_string),
                python_note_id,
            });
            lines.render();
        }
    }

    fn render(&self) {
        for lines in self.lines.borrow_mut().iter_mut() {
            lines.render();
        }
        let status = self.status.borrow().as_ref().map(Status::text);
        self.status_line
            .set_text_content(Some(&status.unwrap_or_default()));
    }

    /// Clears the status line (the form changed).
    pub fn clear_status(&self) {
        // Called on every edit (a drag's every frame): the line is written only when it said
        // something.
        if self.status.borrow_mut().take().is_some() {
            self.status_line.set_text_content(None);
        }
    }

    /// A copy button (`data-copy`: `python`, `bsv`, or `<file>:python|bsv` in a panel of
    /// several runs): its command line to the clipboard, and the outcome in the status line.
    pub fn copy(&self, kind: &str) {
        let (key, kind) = match kind.rsplit_once(':') {
            Some((key, kind)) => (Some(key), kind),
            None => (None, kind),
        };
        let text = {
            let lines = self.lines.borrow();
            let Some(lines) = lines
                .iter()
                .find(|l| key.is_none() || l.key.as_deref() == key)
            else {
                return;
            };
            let code = if kind == "python" {
                &lines.python
            } else {
                &lines.bsv
            };
            code.text_content().unwrap_or_default()
        };
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
            self.download_failed(file, &e);
        }
    }

    /// Says in the status line that `file` could not be made or saved (`error`: a message or
    /// a JS error).
    pub fn download_failed(&self, file: &str, error: &JsValue) {
        let error = error.as_string().unwrap_or_else(|| format!("{error:?}"));
        let now = Status::DownloadFailed {
            file: file.to_string(),
            error,
        };
        self.status_line.set_text_content(Some(&now.text()));
        *self.status.borrow_mut() = Some(now);
    }

    /// Re-renders the notes and the status line in the current language.
    pub fn relocalize(&self) {
        self.render();
    }
}

impl Lines {
    fn show(&mut self, args: &RunArgs, python: &'static str, input_name: Option<&str>) {
        self.shown = Some(Shown::Run {
            args: args.clone(),
            python,
            input_name: input_name.map(str::to_string),
        });
        self.render();
    }

    /// Writes the lines and notes (only texts that changed).
    fn render(&mut self) {
        let Some(shown) = self.shown.as_ref() else {
            return;
        };
        let (python, bsv, note, input_name) = match shown {
            Shown::Run {
                args,
                python,
                input_name,
            } => {
                let options = args.options_text();
                let note = if options.is_empty() {
                    String::new()
                } else {
                    t_strings("kit-exports-python-no-options", &[("options", options)])
                };
                (
                    args.python_command(python),
                    args.bsv_command(),
                    note,
                    input_name.clone(),
                )
            }
            Shown::Written {
                bsv,
                python,
                python_note_id,
            } => {
                let note = match python {
                    Some(_) => String::new(),
                    None => ctx::t(python_note_id),
                };
                (python.clone().unwrap_or_default(), bsv.clone(), note, None)
            }
        };
        let copy_shown = !python.is_empty();
        if self.python_copy_shown != Some(copy_shown) {
            if let Some(Ok(Some(copy))) = self
                .python
                .parent_element()
                .map(|row| row.query_selector("[data-copy=\"python\"], [data-copy$=\":python\"]"))
            {
                show(&copy, copy_shown);
            }
            self.python_copy_shown = Some(copy_shown);
        }
        if self.written[0] != python {
            self.python.set_text_content(Some(&python));
            self.written[0] = python;
        }
        if self.written[1] != bsv {
            self.bsv.set_text_content(Some(&bsv));
            self.written[1] = bsv;
        }
        if let Some(note_el) = &self.python_note {
            if self.written[2] != note {
                note_el.set_text_content(Some(&note));
                show(note_el, !note.is_empty());
                self.written[2] = note;
            }
        }
        if let Some(file_note) = &self.file_note {
            match input_name {
                Some(name) => {
                    file_note.set_text_content(Some(&t_strings(
                        "kit-exports-file-note",
                        &[("name", name)],
                    )));
                    show(file_note, true);
                }
                None => show(file_note, false),
            }
        }
    }
}
