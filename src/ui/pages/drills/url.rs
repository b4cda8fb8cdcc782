//! The page and its URL: the form written into the URL (at once; edits schedule it through
//! the page's URL timer), and the notice about what the URL the page was opened with asked for
//! that the page could not do as asked.

use super::{query, Page};
use crate::ui::ctx::{self, t_strings};
use crate::ui::dom::show;
use crate::ui::router;

impl Page {
    /// Writes the form into the URL now.
    pub(super) fn write_url(&self) {
        self.url_timer.cancel();
        let texts = self.current_texts();
        let form = self.form.borrow();
        let recipe = self.st.borrow().recipe.info.id;
        let pairs = query::pairs(recipe, &form.fields, &texts);
        router::replace_query(&pairs);
    }

    /// The notice about the URL the page was opened with.
    pub(super) fn render_notice(&self) {
        let st = self.st.borrow();
        let url = &st.url;
        if url.is_empty() {
            show(&self.els.url_notice, false);
            return;
        }
        let mut parts = Vec::new();
        if let Some(id) = &url.unknown_recipe {
            let title = ctx::t(&format!("recipe-{}-title", st.recipe.info.id));
            parts.push(t_strings(
                "drills-url-unknown-recipe",
                &[("id", id.clone()), ("title", title)],
            ));
        }
        if !url.ignored.is_empty() {
            parts.push(t_strings(
                "drills-url-ignored",
                &[("keys", url.ignored.join(", "))],
            ));
        }
        if !url.invalid.is_empty() {
            parts.push(t_strings(
                "drills-url-invalid",
                &[("keys", url.invalid.join(", "))],
            ));
        }
        if let Some(name) = &url.missing_file {
            parts.push(t_strings("drills-url-file", &[("name", name.clone())]));
        }
        self.els.url_notice.set_text_content(Some(&parts.join(" ")));
        show(&self.els.url_notice, true);
    }
}
