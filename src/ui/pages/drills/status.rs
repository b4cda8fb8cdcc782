//! The page's texts around the form: the current recipe's title, blurb, explanation and
//! quirks, the status line beside Run (with the page's `data-state` and Run's `aria-busy`),
//! and the note that the form has moved on from the result shown.

use wasm_bindgen::prelude::*;

use super::command::RunArgs;
use super::{texts, Page, Status};
use crate::ui::ctx::{self, t_strings};
use crate::ui::dom::{self, show};

impl Page {
    /// Title, blurb, explanation and quirks of the current recipe (kept localized by the
    /// shell through `data-i18n`).
    pub(super) fn render_recipe_texts(&self) -> Result<(), JsValue> {
        let id = self.st.borrow().recipe.info.id;
        dom::set_i18n(&self.els.recipe_title, &format!("recipe-{id}-title"))?;
        dom::set_i18n(&self.els.recipe_blurb, &format!("recipe-{id}-blurb"))?;
        dom::set_i18n(&self.els.about, &texts::about_id(id))?;
        match texts::quirk_id(id) {
            Some(quirk) => {
                dom::set_i18n(&self.els.quirk, &quirk)?;
                show(&self.els.quirk_box, true);
            }
            None => show(&self.els.quirk_box, false),
        }
        self.els.page.set_attribute("data-recipe", id)
    }

    /// The status line beside Run and the page's `data-state`.
    pub(super) fn render_status(&self) {
        let st = self.st.borrow();
        let (text, bad) = match &st.status {
            Status::Idle => (String::new(), false),
            Status::Running => (ctx::t("drills-running"), false),
            Status::Large => (ctx::t("drills-large"), false),
            Status::Invalid => (ctx::t("drills-invalid"), true),
            Status::Reading(name) => (
                t_strings("drills-reading", &[("name", name.clone())]),
                false,
            ),
            Status::Done(ms) => (
                t_strings("drills-done", &[("ms", format!("{}", ms.max(0.0).round()))]),
                false,
            ),
            Status::Failed => (ctx::t("drills-failed"), true),
        };
        self.els.status.set_text_content(Some(&text));
        let _ = self
            .els
            .status
            .class_list()
            .toggle_with_force("drills-status-bad", bad);
        let running = st.status == Status::Running;
        let _ = self
            .els
            .page
            .set_attribute("data-state", if running { "running" } else { "ready" });
        let _ = self
            .els
            .run
            .set_attribute("aria-busy", if running { "true" } else { "false" });
        drop(st);
        self.render_stale();
    }

    /// The "values changed since this result" note.
    pub(super) fn render_stale(&self) {
        let st = self.st.borrow();
        let stale = match &st.shown {
            Some(shown) => {
                let texts = &st.texts;
                let form = self.form.try_borrow();
                match form {
                    Ok(form) => shown.args != RunArgs::new(form.recipe, &form.fields, texts),
                    Err(_) => false,
                }
            }
            None => false,
        };
        show(&self.els.stale, stale && st.status != Status::Running);
    }
}
