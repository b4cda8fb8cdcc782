//! The label panel shown right after a recorded episode ends: SUCCESS / FAILURE / PARTIAL
//! (`data-label`), one of the Academy's ten failure categories (`data-category`, not for a
//! SUCCESS), a note, and Confirm. The kernel's proposal (the label and the first event it
//! detected; FAILURE / operator-abort for an interrupted episode) is preselected. Confirm
//! writes the label into the session.

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::{Element, Event as DomEvent};

use crate::teleop::session::{
    category_from_id, label_from_id, label_id, EpisodeEntry, Session, CATEGORIES,
};
use crate::teleop::{FailureCategory, Label};
use crate::ui::{ctx, dom};
use crate::view::teleop::fixed_clean;

use super::markup::bool_text;

/// The panel.
pub struct LabelPanel {
    pub root: Element,
    title: Element,
    summary: Element,
    proposal: Element,
    labels: Vec<(Label, Element)>,
    categories: Vec<(FailureCategory, Element)>,
    note: Element,
    /// The episode being labelled (number from 1).
    episode: Option<usize>,
    label: Label,
    category: Option<FailureCategory>,
    proposed: (Label, Option<FailureCategory>),
    summary_args: Vec<(&'static str, String)>,
    interrupted: bool,
}

impl LabelPanel {
    /// Finds the panel under `root`.
    pub fn find(root: &Element) -> Result<LabelPanel, JsValue> {
        let panel: Element = dom::find(root, "[data-tele=\"label-panel\"]", "teleop")?;
        let f = |sel: &str| -> Result<Element, JsValue> { dom::find(&panel, sel, "teleop") };
        let mut labels = Vec::new();
        for l in [Label::Success, Label::Failure, Label::Partial] {
            labels.push((l, f(&format!("[data-label=\"{}\"]", label_id(l)))?));
        }
        let mut categories = Vec::new();
        for c in CATEGORIES {
            categories.push((c, f(&format!("[data-category=\"{}\"]", c.id()))?));
        }
        Ok(LabelPanel {
            title: f("[data-tele=\"label-title\"]")?,
            summary: f("[data-tele=\"label-summary\"]")?,
            proposal: f("[data-tele=\"label-proposal\"]")?,
            note: f("[data-field=\"note\"]")?,
            root: panel,
            labels,
            categories,
            episode: None,
            label: Label::Success,
            category: None,
            proposed: (Label::Success, None),
            summary_args: Vec::new(),
            interrupted: false,
        })
    }

    /// Opens the panel for episode `n` (from 1) of `session`, if it has one.
    pub fn open_episode(&mut self, session: &Session, n: usize) {
        if let Some(entry) = session.episodes.get(n.wrapping_sub(1)) {
            self.open(entry);
        }
    }

    /// Opens the panel for `entry` (its label if it has one, else the proposal).
    fn open(&mut self, entry: &EpisodeEntry) {
        self.episode = Some(entry.number);
        self.proposed = entry.proposal();
        let (label, category) = match entry.label {
            Some(l) => (l, entry.category),
            None => self.proposed,
        };
        self.label = label;
        self.category = category;
        self.interrupted = entry.interrupted;
        let m = &entry.metrics;
        self.summary_args = vec![
            ("n", entry.number.to_string()),
            ("duration", fixed_clean(m.duration_s, 2)),
            ("path", fixed_clean(m.path_m, 3)),
            ("collisions", m.collisions.to_string()),
        ];
        let _ = js_sys::Reflect::set(
            &self.note,
            &JsValue::from_str("value"),
            &JsValue::from_str(&entry.note),
        );
        self.render();
        dom::show(&self.root, true);
    }

    /// Closes the panel.
    pub fn close(&mut self) {
        self.episode = None;
        dom::show(&self.root, false);
    }

    /// A click in the panel: a label or a category picked; `true` on Confirm while an
    /// episode is open (then [`LabelPanel::confirm`]).
    pub fn click(&mut self, e: &DomEvent) -> bool {
        let Some(target) = e.target().and_then(|t| t.dyn_into::<Element>().ok()) else {
            return false;
        };
        let Ok(Some(button)) = target.closest("button") else {
            return false;
        };
        if let Some(id) = button.get_attribute("data-label") {
            if let Some(l) = label_from_id(&id) {
                self.pick_label(l);
            }
        } else if let Some(id) = button.get_attribute("data-category") {
            if let Some(c) = category_from_id(&id) {
                self.pick_category(c);
            }
        } else if button.get_attribute("data-action").as_deref() == Some("confirm-label") {
            return self.episode.is_some();
        }
        false
    }

    /// Writes the label picked, its category and the note into `session`'s episode and
    /// closes the panel.
    pub fn confirm(&mut self, session: &mut Session) {
        let Some(n) = self.episode else {
            return;
        };
        let note = self.note_text();
        if let Some(entry) = session.episodes.get_mut(n - 1) {
            entry.set_label(self.label, self.category, &note);
        }
        self.close();
    }

    /// The note typed.
    fn note_text(&self) -> String {
        js_sys::Reflect::get(&self.note, &JsValue::from_str("value"))
            .ok()
            .and_then(|v| v.as_string())
            .unwrap_or_default()
    }

    /// Picks a label (a SUCCESS drops the category; a failure without one takes the
    /// proposal's, or operator-abort).
    fn pick_label(&mut self, label: Label) {
        self.label = label;
        if label == Label::Success {
            self.category = None;
        } else if self.category.is_none() {
            self.category = Some(self.proposed.1.unwrap_or(FailureCategory::OperatorAbort));
        }
        self.render();
    }

    /// Picks a category (and FAILURE if SUCCESS was picked).
    fn pick_category(&mut self, category: FailureCategory) {
        self.category = Some(category);
        if self.label == Label::Success {
            self.label = Label::Failure;
        }
        self.render();
    }

    /// Texts and pressed states in the current language.
    pub fn render(&self) {
        let Some(n) = self.episode else {
            return;
        };
        self.title.set_text_content(Some(&ctx::t_strings(
            "teleop-label-title",
            &[("n", n.to_string())],
        )));
        let mut summary = ctx::t_strings("teleop-label-summary", &self.summary_args);
        if self.interrupted {
            summary.push(' ');
            summary.push_str(&ctx::t("teleop-label-interrupted"));
        }
        self.summary.set_text_content(Some(&summary));
        let proposal = match self.proposed.1 {
            Some(c) => ctx::t_strings(
                "teleop-label-proposal-failure",
                &[
                    ("label", ctx::t(&label_message(self.proposed.0))),
                    ("category", ctx::t(&format!("teleop-cat-{}", c.id()))),
                ],
            ),
            None => ctx::t_strings(
                "teleop-label-proposal",
                &[("label", ctx::t(&label_message(self.proposed.0)))],
            ),
        };
        self.proposal.set_text_content(Some(&proposal));
        for (l, el) in &self.labels {
            let _ = el.set_attribute("aria-pressed", bool_text(*l == self.label));
        }
        for (c, el) in &self.categories {
            let _ = el.set_attribute("aria-pressed", bool_text(Some(*c) == self.category));
            let _ = el.set_attribute("aria-disabled", bool_text(self.label == Label::Success));
        }
    }
}

/// The Fluent id of a label's name.
pub fn label_message(label: Label) -> String {
    format!("teleop-label-{}", label_id(label).to_ascii_lowercase())
}
