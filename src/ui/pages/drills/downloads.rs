//! The result panel's buttons: downloading a file of the last run (exactly its bytes; `d`
//! takes the first), and copying a command line to the clipboard.

use super::Page;
use crate::ui::clipboard;
use crate::ui::ctx::{self, t_strings};
use crate::ui::dom::show;

impl Page {
    /// A download button: the last run's file, exactly its bytes.
    pub(super) fn download(&self, file: &str) {
        let result = {
            let st = self.st.borrow();
            let shown = st.shown.as_ref();
            // A worker run's file is a Blob (background.rs).
            match shown.and_then(|s| s.blobs.iter().find(|b| b.name == file)) {
                Some(blob) => crate::ui::kit::worker::download(blob),
                None => match shown.and_then(|s| s.output.file(file)) {
                    Some(text) => crate::ui::download::download_text(file, text, "text/csv"),
                    None => Ok(()),
                },
            }
        };
        if let Err(e) = result {
            let reason = e.as_string().unwrap_or_else(|| format!("{e:?}"));
            self.els.error.set_text_content(Some(&t_strings(
                "drills-download-failed",
                &[("file", file.to_string()), ("error", reason)],
            )));
            show(&self.els.error, true);
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

    /// A copy button: its command line to the clipboard.
    pub(super) fn copy_command(&self, kind: &str) {
        let code = if kind == "python" {
            &self.els.cmd_python
        } else {
            &self.els.cmd_bsv
        };
        let text = code.text_content().unwrap_or_default();
        let weak = self.weak.borrow().clone();
        clipboard::copy_text(&text, move |ok| {
            let Some(page) = weak.upgrade() else {
                return;
            };
            let id = if ok {
                "drills-copied"
            } else {
                "drills-copy-failed"
            };
            page.st.borrow_mut().copy_status = Some(id);
            page.els.copy_status.set_text_content(Some(&ctx::t(id)));
        });
    }
}
