//! The session panel: the module bar and the preflight (`module_bar`), the episodes and
//! repeatability tables (`episode_table`), the restored notice, the file opener and its
//! error, and the status line; which of its buttons a click hit.

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::{Element, Event as DomEvent};

use crate::ui::{ctx, dom};

use super::episode_table::EpisodeTables;
use super::loading::Stored;
use super::markup::role;
use super::module_bar::ModuleBar;
use super::sessions::Sessions;
use crate::ui::kit::pilot_session::EPISODE_CSVS;

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
        crate::ui::kit::pilot_session::read_files(&self.open, done);
    }

    /// The opener emptied (the same files can be chosen again).
    pub fn clear_chosen(&self) {
        crate::ui::kit::pilot_session::clear_files(&self.open);
    }
}
