//! The drill picker: the current recipe's title, blurb, explanation and quirks (the recipe's
//! facts: `RecipeInfo::quirks_id`), changing to another drill (this one's values remembered,
//! the other's restored or its defaults), the previous / next drill, and back to the recipe's
//! defaults.

use wasm_bindgen::prelude::*;

use super::state::{Page, Status, UrlNotes};
use super::{form, texts};
use crate::recipes::{RecipeInfo, INFOS};
use crate::ui::dom;

impl Page {
    /// Title, blurb, explanation and quirks of the current recipe (kept localized by the
    /// shell through `data-i18n`).
    pub(super) fn render_recipe_texts(&self) -> Result<(), JsValue> {
        let info = self.st.borrow().recipe;
        dom::set_i18n(&self.els.recipe_title, &info.title_id())?;
        dom::set_i18n(&self.els.recipe_blurb, &info.blurb_id())?;
        dom::set_i18n(&self.els.about, &texts::about_id(info.id))?;
        dom::set_i18n(&self.els.quirk, info.quirks_id)?;
        self.els.page.set_attribute("data-recipe", info.id)
    }

    /// Another drill: remember this one's values, restore the other's (or its defaults).
    pub(super) fn switch_recipe(&self, recipe: &'static RecipeInfo) {
        if self.st.borrow().recipe.id == recipe.id {
            return;
        }
        self.auto_timer.cancel();
        let texts = {
            let mut st = self.st.borrow_mut();
            let current = (st.recipe.id, st.texts.clone());
            st.remembered.retain(|(id, _)| *id != current.0);
            st.remembered.push(current);
            st.recipe = recipe;
            st.shown = None;
            st.failed = None;
            st.status = Status::Idle;
            st.url = UrlNotes::default();
            st.remembered
                .iter()
                .find(|(id, _)| *id == recipe.id)
                .map(|(_, t)| t.clone())
                .unwrap_or_default()
        };
        match form::build(&self.els.form, recipe, &texts) {
            Ok(built) => *self.form.borrow_mut() = built,
            Err(e) => web_sys::console::error_2(&"drills: form".into(), &e),
        }
        self.exports.clear_status();
        self.els.recipe.set_value(recipe.id);
        if let Err(e) = self.render_recipe_texts() {
            web_sys::console::error_2(&"drills: texts".into(), &e);
        }
        self.validate();
        self.render_notice();
        self.render_file_status();
        self.write_url();
        self.auto_run();
        if let Err(e) = self.render_output() {
            web_sys::console::error_2(&"drills: result".into(), &e);
        }
        self.render_status();
    }

    /// `[` / `]`: the previous / next drill.
    pub(super) fn switch_by(&self, delta: i32) {
        let id = self.st.borrow().recipe.id;
        let n = INFOS.len() as i32;
        let index = INFOS.iter().position(|r| r.id == id).unwrap_or(0) as i32;
        let next = (index + delta).rem_euclid(n) as usize;
        if let Some(recipe) = INFOS.get(next) {
            self.switch_recipe(recipe);
        }
    }

    /// Back to the recipe's defaults (the labeled sample for traj-resample).
    pub(super) fn reset(&self) {
        self.auto_timer.cancel();
        {
            let mut st = self.st.borrow_mut();
            st.input = None;
            st.missing_file = None;
            st.file_problem = None;
            st.failed = None;
            st.url = UrlNotes::default();
            st.status = Status::Idle;
        }
        self.form.borrow().reset();
        self.validate();
        self.render_notice();
        self.render_file_status();
        self.write_url();
        self.auto_run();
        self.render_status();
    }
}
