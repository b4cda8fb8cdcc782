//! The page and its URL, on the kit's [`crate::ui::kit::url_state`]: the form written into the
//! URL by the page's [`crate::ui::kit::url_state::UrlWriter`] (at once, or debounced while
//! typing), and the kit's notice about what the opened link asked for that the page could not
//! do as asked, led by the page's own sentence about an unknown drill.

use super::state::Page;
use crate::ui::ctx::{self, t_strings};
use crate::ui::kit::url_state::{NoticeLead, UrlState};
use crate::view::drills::DrillsQuery;

impl Page {
    /// The URL pairs of the form now.
    pub(super) fn url_pairs(&self) -> Vec<(String, String)> {
        let texts = self.current_texts();
        let form = self.form.borrow();
        let recipe = self.st.borrow().recipe;
        DrillsQuery::from_form(recipe, &form.fields, &texts).write()
    }

    /// Writes the form into the URL now.
    pub(super) fn write_url(&self) {
        self.url.write_now();
    }

    /// The notice about the URL the page was opened with.
    pub(super) fn render_notice(&self) {
        let st = self.st.borrow();
        let lead = st.url.unknown_recipe.clone().map(|id| {
            let title_id = st.recipe.title_id();
            let lead: NoticeLead = Box::new(move || {
                t_strings(
                    "drills-url-unknown-recipe",
                    &[("id", id.clone()), ("title", ctx::t(&title_id))],
                )
            });
            lead
        });
        let keys = st.url.keys.clone();
        drop(st);
        self.url_notice.set_all(keys, lead);
    }
}
