//! Text the page formats itself (and re-renders on a language switch): the URL notice, the
//! view notes (annulus radii, ellipse scale), the workspace summary, the heatmap preview, the
//! copy status, the command lines under the downloads, and the toolbar controls' state.

use super::state;
use super::{downloads, readouts, view, Page};
use crate::planar2r::Elbow;
use crate::ui::ctx::{self, t_strings};
use crate::ui::dom::show;

impl Page {
    pub(super) fn update_ws_summary(&self) {
        let st = *self.state.borrow();
        let gfx = self.gfx.borrow();
        match (&gfx.ws_data, st.show_ws) {
            (Some((_, ws)), true) => {
                let (nx, ny) = (ws.xs_mm.len(), ws.ys_mm.len());
                let text = t_strings(
                    "ik2r-ws-summary",
                    &[
                        ("nx", nx.to_string()),
                        ("ny", ny.to_string()),
                        ("cells", (nx * ny).to_string()),
                        ("reachable", ws.reachable_count().to_string()),
                    ],
                );
                self.els.ws_summary.set_text_content(Some(&text));
                show(&self.els.ws_summary, true);
            }
            _ => show(&self.els.ws_summary, false),
        }
    }

    /// Texts the page formats itself: URL notice, view notes, workspace summary, hover text,
    /// copy status.
    pub(super) fn update_texts(&self) {
        let ui = self.ui.borrow();
        if ui.ignored_url_keys.is_empty() {
            show(&self.els.url_notice, false);
        } else {
            let text = t_strings(
                "ik2r-url-ignored",
                &[("keys", ui.ignored_url_keys.join(", "))],
            );
            self.els.url_notice.set_text_content(Some(&text));
            show(&self.els.url_notice, true);
        }
        drop(ui);
        let status = self.copy_status.get().map(ctx::t).unwrap_or_default();
        self.els.copy_status.set_text_content(Some(&status));
        let p = self.state.borrow().params;
        let (inner, outer) = p.arm().reach();
        let notes = t_strings(
            "ik2r-view-notes",
            &[
                ("inner", readouts::fmt_fixed(inner * 1000.0, 1)),
                ("outer", readouts::fmt_fixed(outer * 1000.0, 1)),
                ("scale", state::num(view::ELLIPSE_SCALE)),
            ],
        );
        self.els.view_notes.set_text_content(Some(&notes));
        self.update_ws_summary();
        self.update_hover_text();
    }

    pub(super) fn update_hover_text(&self) {
        let ui = self.ui.borrow();
        let text = match ui.ghost {
            Some((q1, q2)) => {
                let arm = self.state.borrow().params.arm();
                t_strings(
                    "ik2r-heatmap-hover",
                    &[
                        ("q1", readouts::fmt_fixed(q1, 3)),
                        ("q2", readouts::fmt_fixed(q2, 3)),
                        ("det", readouts::fmt_sig(arm.det_explicit(q1, q2).abs(), 4)),
                    ],
                )
            }
            None => String::new(),
        };
        self.els.heat_hover.set_text_content(Some(&text));
    }

    /// Radio buttons, checkbox and select from the state.
    pub(super) fn sync_controls(&self) {
        let st = *self.state.borrow();
        self.els.elbow_down.set_checked(st.elbow == Elbow::Down);
        self.els.elbow_up.set_checked(st.elbow == Elbow::Up);
        self.els.ws_toggle.set_checked(st.show_ws);
        self.els.ws_color.set_value(st.ws_color.key());
    }

    /// The command lines under the downloads.
    pub(super) fn update_commands(&self) {
        let st = *self.state.borrow();
        let mut gfx = self.gfx.borrow_mut();
        let mut shown = Vec::new();
        for export in downloads::EXPORTS {
            let (python, bsv) = downloads::commands(&export, &st.params, st.q2);
            shown.push(python);
            shown.push(bsv);
        }
        if gfx.commands_shown == shown {
            return;
        }
        let mut texts = shown.iter();
        for export in downloads::EXPORTS {
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
        gfx.commands_shown = shown;
    }

    /// Only the jacobian-2r command depends on the pose (its q2): refreshed per frame.
    pub(super) fn update_jacobian_command(&self) {
        let q2 = self.state.borrow().q2;
        let stale = self
            .gfx
            .borrow()
            .commands_shown
            .get(3)
            .is_none_or(|bsv| !bsv.ends_with(&format!(" {}", state::num(q2))));
        if stale {
            self.update_commands();
        }
    }
}
