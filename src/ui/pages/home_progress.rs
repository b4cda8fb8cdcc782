//! The home page's progress on the exercises, at its foot: each page's count of exercises done
//! (`data-testid="home-progress"`, a row per page with `data-page`), the same count on the
//! tiles of pages where the learner has done some, the progress file's panel (name, export,
//! import: [`ProgressPanel`]) and, for teachers, the link to the class page (which has no
//! link in the header). It comes with the tiles' chunk, once its strings
//! (`progress.ftl`) and style are in: below everything, so nothing moves when it comes.

use std::rc::{Rc, Weak};

use wasm_bindgen::prelude::*;
use web_sys::Element;

use crate::i18n::fluent_args;
use crate::ui::dom::{self, append, el, el_class};
use crate::ui::kit::lang_follow::{draw_texts, LangFollow};
use crate::ui::kit::progress_panel::ProgressPanel;
use crate::ui::kit::{late_style, progress_store};
use crate::ui::page::ShellLink;
use crate::ui::{ctx, lang_files, router};
use crate::view::exercises::PAGE_IDS;

/// The section's Fluent file.
const FILES: [&str; 1] = ["progress.ftl"];

/// What the home page keeps while it is shown (its parts' listeners).
pub type Keep = Rc<std::cell::RefCell<Vec<Box<dyn std::any::Any>>>>;

/// The section once built.
struct HomeProgress {
    root: Element,
    list: Element,
    shell: ShellLink,
    panel: Rc<ProgressPanel>,
    _follow: Option<LangFollow>,
}

/// Fetches the section's strings and style, then builds it at the end of `root` and counts
/// on the tiles; `keep` holds it while the page is shown.
pub fn build(root: &Element, shell: ShellLink, keep: &Keep) {
    let (root, keep) = (root.clone(), Rc::downgrade(keep));
    wasm_bindgen_futures::spawn_local(async move {
        if lang_files::load(ctx::lang(), &FILES).await.is_err() {
            return;
        }
        late_style::linked("progress").await;
        let (Some(keep), true) = (keep.upgrade(), root.is_connected()) else {
            return;
        };
        match HomeProgress::new(&root, shell) {
            Ok(part) => keep.borrow_mut().push(Box::new(part)),
            Err(error) => web_sys::console::error_2(&"BSV Playground: progress".into(), &error),
        }
    });
}

impl HomeProgress {
    fn new(root: &Element, shell: ShellLink) -> Result<Rc<HomeProgress>, JsValue> {
        let section = el_class("section", "home-progress")?;
        section.set_attribute("data-testid", "home-progress")?;
        section.set_attribute("aria-labelledby", "home-progress-heading")?;
        let heading = el("h2")?;
        heading.set_id("home-progress-heading");
        heading.set_attribute("data-l10n", "home-progress-heading")?;
        append(&section, &heading)?;
        let intro = el_class("p", "section-intro")?;
        intro.set_attribute("data-l10n", "home-progress-intro")?;
        append(&section, &intro)?;
        let list = el_class("ul", "home-progress-list")?;
        append(&section, &list)?;
        let class = el_class("p", "home-progress-class")?;
        let link = el("a")?;
        link.set_attribute("href", &router::build_hash("class", &[]))?;
        link.set_attribute("data-l10n", "home-progress-class")?;
        append(&class, &link)?;
        append(&section, &class)?;
        let me = std::cell::RefCell::new(Weak::<HomeProgress>::new());
        let me = Rc::new(me);
        let imported = me.clone();
        let panel = ProgressPanel::new(move || {
            if let Some(part) = imported.borrow().upgrade() {
                part.draw();
            }
        })?;
        append(&section, panel.element())?;
        append(root, &section)?;
        let redraw = me.clone();
        let follow = LangFollow::new(&FILES, move || {
            if let Some(part) = redraw.borrow().upgrade() {
                part.panel.relocalize();
                part.draw();
            }
        })
        .ok();
        let part = Rc::new(HomeProgress {
            root: root.clone(),
            list,
            shell,
            panel,
            _follow: follow,
        });
        *me.borrow_mut() = Rc::downgrade(&part);
        part.draw();
        Ok(part)
    }

    /// Each page's count, in the list and on its tile, from the stored record.
    fn draw(&self) {
        if let Err(error) = self.try_draw() {
            web_sys::console::error_2(&"BSV Playground: progress".into(), &error);
        }
    }

    fn try_draw(&self) -> Result<(), JsValue> {
        if let Some(section) = self.list.parent_element() {
            draw_texts(&section)?;
        }
        let record = progress_store::load();
        dom::clear(&self.list);
        for (page, ids) in PAGE_IDS {
            let Some(def) = self.shell.find(page) else {
                continue;
            };
            let done = ids.iter().filter(|id| record.get(id).done).count();
            let counts = fluent_args(vec![
                ("done", done.to_string()),
                ("total", ids.len().to_string()),
                ("page", ctx::t(def.title_id)),
            ]);
            let all = done == ids.len();
            let item = el("li")?;
            item.set_attribute("data-page", page)?;
            if all {
                item.set_attribute("data-all-done", "")?;
            }
            let link = el_class("a", "")?;
            link.set_attribute("href", &router::build_hash(page, &[]))?;
            link.set_text_content(Some(&ctx::t(def.title_id)));
            append(&item, &link)?;
            let count = el_class("span", "count")?;
            count.set_text_content(Some(&ctx::t_args("home-progress-page", &counts)));
            count.set_attribute(
                "aria-label",
                &ctx::t_args("home-progress-page-label", &counts),
            )?;
            append(&item, &count)?;
            append(&self.list, &item)?;
            self.draw_tile(page, done, &counts, all)?;
        }
        Ok(())
    }

    /// The count on `page`'s tile, when some of its exercises are done.
    fn draw_tile(
        &self,
        page: &str,
        done: usize,
        counts: &[(&str, crate::i18n::FluentArg)],
        all: bool,
    ) -> Result<(), JsValue> {
        let selector = format!("[data-testid=\"featured-{page}\"]");
        let Some(tile) = self.root.query_selector(&selector)? else {
            return Ok(());
        };
        let badge = match tile.query_selector(".featured-progress")? {
            Some(badge) => badge,
            None => {
                let badge = el_class("span", "featured-progress")?;
                append(&tile, &badge)?;
                badge
            }
        };
        dom::show(&badge, done > 0);
        badge.set_text_content(Some(&ctx::t_args("home-progress-page", counts)));
        badge.set_attribute("title", &ctx::t_args("home-progress-page-label", counts))?;
        if all {
            badge.set_attribute("data-all-done", "")?;
        } else {
            badge.remove_attribute("data-all-done")?;
        }
        Ok(())
    }
}
