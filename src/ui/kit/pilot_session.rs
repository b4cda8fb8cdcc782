//! What the Robot Pilot pages (`#/teleop`, `#/so101`) share of their session panel, whatever
//! the arm: the repeatability table (the first session beside the second,
//! [`render_comparison`]), the warning that the session is not saved ([`StorageWarning`],
//! `data-testid="storage-warning"`, `role=alert`: the browser refused to store it, its storage
//! full or turned off; the recording goes on in memory and the warning offers the evidence, the
//! episodes table and every episode's CSV at once, `data-save-now`), and the saved-files opener
//! ([`read_files`], [`open_error_text`]), and the line of a page that waits for the code
//! reading its stored session ([`RESTORE_TEXTS`]).

use std::cell::{Cell, RefCell};
use std::rc::Rc;

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::Element;

use crate::teleop::session::{category_from_id, compare, SessionError, Summary, EVIDENCE_NAME};
use crate::ui::kit::late_page::LateTexts;
use crate::ui::{ctx, dom};
use crate::view::teleop::comparison_cell;

/// The line above a pilot page while it waits for the code that reads its stored session
/// (`crate::ui::kit::late_page`).
pub const RESTORE_TEXTS: LateTexts = LateTexts {
    loading: "pilot-restore-loading",
    failed: "pilot-restore-failed",
};

/// `data-save-now` of the button that downloads every episode's CSV.
pub const EPISODE_CSVS: &str = "episode-csvs";

/// The storage warning's markup (hidden): the note and its three downloads, the session's
/// table being `table`; `box_class`, `row_class` and `button_class` are the page's classes of
/// the notice, its row of buttons and a button.
#[inline(never)]
pub fn storage_warning_markup(
    table: &str,
    box_class: &str,
    row_class: &str,
    button_class: &str,
) -> String {
    format!(
        "<div class=\"{box_class}\" data-testid=\"storage-warning\" role=\"alert\" hidden>\
         <p data-i18n=\"teleop-storage-full\"></p><div class=\"{row_class}\">\
         <button type=\"button\" class=\"{button_class} primary\" data-save-now=\"{EVIDENCE_NAME}\" \
         data-testid=\"storage-download-evidence\"></button>\
         <button type=\"button\" class=\"{button_class}\" data-save-now=\"{table}\" \
         data-testid=\"storage-download-table\"></button>\
         <button type=\"button\" class=\"{button_class}\" data-save-now=\"{EPISODE_CSVS}\" \
         data-testid=\"storage-download-episodes\"></button></div></div>"
    )
}

/// The warning.
pub struct StorageWarning {
    root: Element,
    evidence: Element,
    table: Element,
    table_name: String,
    episodes: Element,
    shown: Cell<bool>,
}

impl StorageWarning {
    /// Finds the warning under `root` (the session's table being `table`).
    #[inline(never)]
    pub fn find(root: &Element, table: &str) -> Result<StorageWarning, JsValue> {
        let button =
            |file: &str| dom::find(root, &format!("[data-save-now=\"{file}\"]"), "storage");
        Ok(StorageWarning {
            root: dom::find(root, "[data-testid=\"storage-warning\"]", "storage")?,
            evidence: button(EVIDENCE_NAME)?,
            table: button(table)?,
            table_name: table.to_string(),
            episodes: button(EPISODE_CSVS)?,
            shown: Cell::new(false),
        })
    }

    /// Shown while the session is not saved (`unsaved`), with the downloads of a session of
    /// `episodes` episodes.
    #[inline(never)]
    pub fn render(&self, unsaved: bool, episodes: usize) {
        if unsaved {
            let file =
                |name: &str| ctx::t_strings("teleop-download-file", &[("file", name.into())]);
            self.evidence.set_text_content(Some(&file(EVIDENCE_NAME)));
            self.table.set_text_content(Some(&file(&self.table_name)));
            self.episodes.set_text_content(Some(&ctx::t_args(
                "teleop-storage-episodes",
                &[("count", episodes.into())],
            )));
            dom::show(&self.episodes, episodes > 0);
        }
        if unsaved != self.shown.get() {
            self.shown.set(unsaved);
            dom::show(&self.root, unsaved);
        }
    }
}

/// Reads the files chosen in the file input `input`; `done` gets each file's name and text,
/// or the name of one the browser could not read, once all are read.
#[inline(never)]
pub fn read_files(input: &Element, done: impl Fn(&[(String, String)], Option<String>) + 'static) {
    let files =
        js_sys::Reflect::get(input, &JsValue::from_str("files")).unwrap_or(JsValue::UNDEFINED);
    let len = js_sys::Reflect::get(&files, &JsValue::from_str("length"))
        .ok()
        .and_then(|v| v.as_f64())
        .unwrap_or(0.0) as u32;
    if len == 0 {
        return;
    }
    let done = Rc::new(done);
    let collected: Rc<RefCell<Vec<(String, String)>>> = Rc::new(RefCell::new(Vec::new()));
    let left = Rc::new(Cell::new(len));
    let failed: Rc<RefCell<Option<String>>> = Rc::new(RefCell::new(None));
    for i in 0..len {
        let Ok(file) = js_sys::Reflect::get_u32(&files, i) else {
            continue;
        };
        let name = js_sys::Reflect::get(&file, &JsValue::from_str("name"))
            .ok()
            .and_then(|n| n.as_string())
            .unwrap_or_default();
        let Ok(blob) = file.dyn_into::<web_sys::Blob>() else {
            left.set(left.get() - 1);
            continue;
        };
        let (done, collected, left, failed) = (
            done.clone(),
            collected.clone(),
            left.clone(),
            failed.clone(),
        );
        let file_name = name.clone();
        crate::ui::kit::input_file::read_text(&name, &blob, move |result| {
            match result {
                Ok(text) => collected.borrow_mut().push((file_name, text)),
                Err(_) => *failed.borrow_mut() = Some(file_name),
            }
            left.set(left.get().saturating_sub(1));
            if left.get() == 0 {
                let bad = failed.borrow().clone();
                done(&collected.borrow(), bad);
            }
        });
    }
}

/// The file input emptied (the same files can be chosen again).
#[inline(never)]
pub fn clear_files(input: &Element) {
    let _ = js_sys::Reflect::set(input, &JsValue::from_str("value"), &JsValue::from_str(""));
}

/// A saved-files problem in the current language (`table`: the session's episodes table).
#[inline(never)]
pub fn open_error_text(e: &SessionError, table: &str) -> String {
    use crate::teleop::session::EvidenceProblem as P;
    match e {
        SessionError::MissingFile { name } => {
            ctx::t_strings("teleop-open-missing", &[("name", name.clone())])
        }
        SessionError::NotJson { file, line, column } => ctx::t_strings(
            "teleop-open-json",
            &[
                ("name", file.clone()),
                ("line", line.to_string()),
                ("column", column.to_string()),
            ],
        ),
        SessionError::Evidence { problem } => {
            let id = match problem {
                P::NotObject => "teleop-open-ev-object",
                P::Missing { .. } => "teleop-open-ev-missing",
                P::Unexpected { .. } => "teleop-open-ev-unexpected",
                P::Type { .. } => "teleop-open-ev-type",
                P::Value { .. } => "teleop-open-ev-value",
            };
            ctx::t_strings(id, &[("field", problem.field().to_string())])
        }
        SessionError::Sha256Mismatch { name } => {
            ctx::t_strings("teleop-open-sha", &[("name", name.clone())])
        }
        SessionError::NotListed { name } => {
            ctx::t_strings("teleop-open-unlisted", &[("name", name.clone())])
        }
        SessionError::Table { row, column } => ctx::t_strings(
            "teleop-open-table",
            &[
                ("name", table.to_string()),
                ("row", row.to_string()),
                ("column", column.clone()),
            ],
        ),
        SessionError::Episode { file, detail } => ctx::t_strings(
            "teleop-open-episode",
            &[("name", file.clone()), ("detail", detail.clone())],
        ),
        SessionError::Replay { file } => {
            ctx::t_strings("teleop-open-replay", &[("name", file.clone())])
        }
    }
}

fn cell(row: &Element, text: &str, i18n: bool) -> Result<(), JsValue> {
    let td = if i18n {
        dom::el_i18n("td", "", text)?
    } else {
        dom::el_text("td", "", text)?
    };
    dom::append(row, &td)
}

/// Rebuilds the repeatability table's body: `first` (if any) beside `second`, one row per
/// figure (`data-compare`), then the failures by category; with no first session the current
/// one stands in the first column.
#[inline(never)]
pub fn render_comparison(
    tbody: &Element,
    first: Option<&Summary>,
    second: &Summary,
) -> Result<(), JsValue> {
    dom::clear(tbody);
    let empty = Summary::empty();
    let (a, b) = match first {
        Some(f) => (f, second),
        None => (second, &empty),
    };
    for row in compare(a, b) {
        let tr = dom::el("tr")?;
        tr.set_attribute("data-compare", &row.id)?;
        let name = if category_from_id(&row.id).is_some() {
            format!("teleop-cat-{}", row.id)
        } else {
            format!("teleop-cmp-{}", row.id)
        };
        cell(&tr, &name, true)?;
        cell(&tr, &comparison_cell(&row.id, row.first), false)?;
        let second = if first.is_some() { row.second } else { None };
        cell(&tr, &comparison_cell(&row.id, second), false)?;
        dom::append(tbody, &tr)?;
    }
    Ok(())
}

/// The input device a new session starts with: the pointer (touch) on a device whose only
/// pointers are coarse (a phone, a tablet without a mouse), else the keyboard.
pub fn default_device() -> crate::teleop::session::InputDevice {
    use crate::teleop::session::InputDevice;
    let matches = |query: &str| {
        web_sys::window()
            .and_then(|w| w.match_media(query).ok().flatten())
            .is_some_and(|m| m.matches())
    };
    if matches("(any-pointer: coarse)") && !matches("(any-pointer: fine)") {
        InputDevice::Pointer
    } else {
        InputDevice::Keyboard
    }
}
