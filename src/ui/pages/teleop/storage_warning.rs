//! The warning that the session is not saved (`data-testid="storage-warning"`, `role=alert`):
//! the browser refused to store it (its storage full, or turned off). The recording goes on
//! in memory; the warning offers the evidence, the episodes table and every episode's CSV at
//! once (`data-save-now`), and goes away when a later save succeeds.

use std::cell::Cell;

use wasm_bindgen::JsValue;
use web_sys::Element;

use crate::teleop::session::{EPISODES_NAME, EVIDENCE_NAME};
use crate::ui::{ctx, dom};

use super::markup::find;

/// `data-save-now` of the button that downloads every episode's CSV.
pub const EPISODE_CSVS: &str = "episode-csvs";

/// The warning.
pub struct StorageWarning {
    root: Element,
    evidence: Element,
    table: Element,
    episodes: Element,
    shown: Cell<bool>,
}

impl StorageWarning {
    /// Finds the warning under `root`.
    pub fn find(root: &Element) -> Result<StorageWarning, JsValue> {
        let button = |file: &str| find(root, &format!("[data-save-now=\"{file}\"]"));
        Ok(StorageWarning {
            root: find(root, "[data-testid=\"storage-warning\"]")?,
            evidence: button(EVIDENCE_NAME)?,
            table: button(EPISODES_NAME)?,
            episodes: button(EPISODE_CSVS)?,
            shown: Cell::new(false),
        })
    }

    /// Shown while the session is not saved (`unsaved`), with the downloads of a session of
    /// `episodes` episodes.
    pub fn render(&self, unsaved: bool, episodes: usize) {
        if unsaved {
            let file =
                |name: &str| ctx::t_strings("teleop-download-file", &[("file", name.into())]);
            self.evidence.set_text_content(Some(&file(EVIDENCE_NAME)));
            self.table.set_text_content(Some(&file(EPISODES_NAME)));
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
