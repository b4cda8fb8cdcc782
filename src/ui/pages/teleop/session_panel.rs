//! The session panel: the module bar and the preflight (`module_bar`), the episodes and
//! repeatability tables (`episode_table`), the restored notice, the file opener and its
//! error, and the status line; which of its buttons a click hit.

use std::cell::{Cell, RefCell};
use std::rc::Rc;

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::{Element, Event as DomEvent};

use crate::teleop::session::SessionError;
use crate::ui::{ctx, dom};

use super::episode_table::EpisodeTables;
use super::loading::Stored;
use super::markup::role;
use super::module_bar::ModuleBar;
use super::sessions::Sessions;
use super::storage_warning::EPISODE_CSVS;

/// A click on one of the panel's buttons.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum PanelAction {
    /// Replay episode n (`data-replay`).
    Replay(usize),
    /// Label episode n again (`data-relabel`).
    Relabel(usize),
    /// Download a file (`data-download`, or `data-save-now` of the storage warning).
    Download(String),
    /// Download every episode's CSV (the storage warning).
    DownloadEpisodeCsvs,
    SecondSession,
    NewSession,
}

/// The panel.
pub struct SessionPanel {
    pub bar: ModuleBar,
    tables: EpisodeTables,
    pub open: Element,
    restored: Element,
    open_error: Element,
    status: Element,
}

impl SessionPanel {
    /// Finds the panel's parts under `root`.
    pub fn find(root: &Element) -> Result<SessionPanel, JsValue> {
        Ok(SessionPanel {
            bar: ModuleBar::find(root)?,
            tables: EpisodeTables::find(root)?,
            open: role(root, "open")?,
            restored: role(root, "restored")?,
            open_error: role(root, "open-error")?,
            status: role(root, "status")?,
        })
    }

    /// The tables for the sessions, and which modules are open.
    pub fn render_session(&self, sessions: &Sessions) {
        {
            let s = sessions.current.borrow();
            let first = sessions.first.borrow();
            self.tables.render(&s, first.as_ref());
        }
        self.bar.render_open(sessions);
    }

    /// The notice of what became of the stored session (none: left as it is).
    pub fn show_restored(&self, stored: Stored) {
        let id = match stored {
            Stored::Restored => "teleop-restored",
            Stored::Unreadable => "teleop-store-unreadable",
            Stored::None => return,
        };
        let _ = dom::set_i18n(&self.restored, id);
        dom::show(&self.restored, true);
    }

    /// The restored notice hidden.
    pub fn hide_restored(&self) {
        dom::show(&self.restored, false);
    }

    /// The status line: message `id`.
    pub fn show_status(&self, id: &str) {
        self.status.set_text_content(Some(&ctx::t(id)));
    }

    /// The saved files' problem (`None`: hidden).
    pub fn show_open_error(&self, text: Option<String>) {
        if let Some(text) = &text {
            self.open_error.set_text_content(Some(text));
        }
        dom::show(&self.open_error, text.is_some());
    }

    /// The panel's button under a click, if any.
    pub fn action_of(e: &DomEvent) -> Option<PanelAction> {
        let target = e.target().and_then(|t| t.dyn_into::<Element>().ok())?;
        let button = target.closest("button").ok()??;
        let num = |attr: &str| {
            button
                .get_attribute(attr)
                .and_then(|v| v.parse::<usize>().ok())
        };
        if let Some(n) = num("data-replay") {
            Some(PanelAction::Replay(n))
        } else if let Some(n) = num("data-relabel") {
            Some(PanelAction::Relabel(n))
        } else if let Some(file) = button.get_attribute("data-download") {
            Some(PanelAction::Download(file))
        } else if let Some(file) = button.get_attribute("data-save-now") {
            Some(if file == EPISODE_CSVS {
                PanelAction::DownloadEpisodeCsvs
            } else {
                PanelAction::Download(file)
            })
        } else {
            match button.get_attribute("data-action").as_deref() {
                Some("second-session") => Some(PanelAction::SecondSession),
                Some("new-session") => Some(PanelAction::NewSession),
                _ => None,
            }
        }
    }

    /// Reads the files chosen in the opener; `done` gets each file's name and text, or the
    /// name of one the browser could not read, once all are read.
    pub fn read_chosen(&self, done: impl Fn(&[(String, String)], Option<String>) + 'static) {
        let files = js_sys::Reflect::get(&self.open, &JsValue::from_str("files"))
            .unwrap_or(JsValue::UNDEFINED);
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

    /// The opener emptied (the same files can be chosen again).
    pub fn clear_chosen(&self) {
        let _ = js_sys::Reflect::set(
            &self.open,
            &JsValue::from_str("value"),
            &JsValue::from_str(""),
        );
    }
}

/// A saved-files problem in the current language.
pub fn open_error_text(e: &SessionError) -> String {
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
            &[("row", row.to_string()), ("column", column.clone())],
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
