//! Mounting and unmounting the page: building it from its markup and the URL (values the URL
//! gave that do not pass are named in the notice), wiring its controls (delegated listeners on
//! stable containers) and timers, relocalizing it, and taking it all down again.

use std::cell::RefCell;
use std::rc::{Rc, Weak};

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::{Element, Event, KeyboardEvent};

use super::background::Background;
use super::form;
use super::markup::{self, PREFIX};
use super::state::{Els, Page, Slot, State, Status, UrlNotes};
use crate::recipes;
use crate::ui::dom::{self, Listener};
use crate::ui::kit::exports::Exports;
use crate::ui::kit::readouts::Readouts;
use crate::ui::kit::scope::Scope;
use crate::ui::kit::url_state::{IgnoredKey, UrlNotice, UrlState, UrlWriter};
use crate::ui::page::MountCtx;
use crate::ui::page_frame;
use crate::ui::schedule::Timer;
use crate::view::drills::DrillsQuery;
use crate::view::form::recipe_fields;

/// Builds the page into the shell's main element.
pub(super) fn mount(ctx: MountCtx) -> Result<Rc<Page>, JsValue> {
    Page::build(ctx)
}

fn find<T: JsCast>(root: &Element, selector: &str) -> Result<T, JsValue> {
    dom::find(root, selector, "drills")
}

fn role<T: JsCast>(root: &Element, name: &str) -> Result<T, JsValue> {
    find(root, &format!("[data-drills=\"{name}\"]"))
}

impl Page {
    fn build(mount: MountCtx) -> Result<Rc<Page>, JsValue> {
        let root = mount.root.clone();
        page_frame::fill(&root, &markup::page())?;
        let els = Els {
            page: find(&root, ".drills")?,
            recipe: role(&root, "recipe")?,
            recipe_title: role(&root, "recipe-title")?,
            recipe_blurb: role(&root, "recipe-blurb")?,
            form: role(&root, "form")?,
            run: role(&root, "run")?,
            status: role(&root, "status")?,
            error: role(&root, "error")?,
            about: role(&root, "about")?,
            quirk: role(&root, "quirk")?,
            output: role(&root, "output")?,
            stale: role(&root, "stale")?,
            empty: role(&root, "empty")?,
            result: role(&root, "result")?,
            summary: role(&root, "summary")?,
            warnings: role(&root, "warnings")?,
            files: role(&root, "files")?,
        };
        let exports = Exports::find(&root, PREFIX)?;
        let readouts = Readouts::find(&root)?;
        let url_notice = UrlNotice::new(role(&root, "url-notice")?, Vec::new())?;
        dom::relocalize(&root)?;

        let (url, ignored) = DrillsQuery::read(&mount.query);
        let recipe = url.recipe;
        let field_list = recipe_fields(recipe);
        let mut texts = url.texts(&field_list);
        let mut missing_file = None;
        for (field, text) in field_list.iter().zip(texts.iter_mut()) {
            if field.is_file() {
                missing_file = text.take().filter(|t| !t.trim().is_empty());
            }
        }
        let form = form::build(&els.form, recipe, &texts)?;
        let state = State {
            recipe,
            texts,
            remembered: Vec::new(),
            input: None,
            missing_file: missing_file.clone(),
            file_problem: None,
            reading: None,
            read_generation: 0,
            errors: Vec::new(),
            marked: Vec::new(),
            plan: None,
            failed: None,
            shown: None,
            runs: 0,
            status: Status::Idle,
            url: UrlNotes {
                unknown_recipe: url.unknown_recipe.clone(),
                keys: ignored,
            },
            exact: false,
        };
        let page = Rc::new_cyclic(|weak: &Weak<Page>| {
            let mut scope = Scope::new();
            let url = UrlWriter::new(&mut scope, weak, Page::url_pairs);
            Page {
                els,
                st: RefCell::new(state),
                form: RefCell::new(form),
                exports,
                readouts,
                listeners: RefCell::new(Vec::new()),
                auto_timer: Timer::default(),
                scope: RefCell::new(scope),
                url,
                url_notice,
                weak: RefCell::new(weak.clone()),
                background: RefCell::new(None),
            }
        });
        // Big runs: the worker's progress panel, under the status line (background.rs).
        let weak = Rc::downgrade(&page);
        let background = Background::new(move || {
            if let Some(page) = weak.upgrade() {
                page.cancel_background();
            }
        })?;
        page.els
            .status
            .after_with_node_1(background.panel.element())?;
        *page.background.borrow_mut() = Some(Rc::new(background));
        page.install()?;
        page.els.recipe.set_value(recipe.id);
        page.render_recipe_texts()?;
        page.validate();
        {
            // Values from the URL that do not pass: name them in the notice (sorted as the
            // fields are), then the file the link used.
            let form = page.form.borrow();
            let mut st = page.st.borrow_mut();
            let flagged: Vec<IgnoredKey> = st
                .errors
                .iter()
                .filter_map(|(slot, _)| match slot {
                    Slot::Field(i) => form.fields.get(*i).map(|f| f.name().to_string()),
                    Slot::General => None,
                })
                .filter(|name| url.values.iter().any(|(k, _)| k == name))
                .map(IgnoredKey::flagged)
                .collect();
            st.url.keys.extend(flagged);
            st.url.keys.extend(missing_file.map(IgnoredKey::file));
        }
        page.render_notice();
        page.render_file_status();
        page.auto_run();
        page.render_output()?;
        page.render_status();
        Ok(page)
    }

    /// Wires the controls (delegated on stable containers, so rebuilding the form or the
    /// result needs no new listeners) and the timers.
    fn install(&self) -> Result<(), JsValue> {
        let weak = self.weak.borrow().clone();
        self.auto_timer.set_callback(&weak, Page::auto_run);

        let reset: Element = find(&self.els.page, "[data-drills=\"reset\"]")?;
        *self.listeners.borrow_mut() = vec![
            Listener::for_page(&self.els.recipe, "change", &weak, |p, _| {
                let id = p.els.recipe.value();
                if let Some(recipe) = recipes::find_info(&id) {
                    p.switch_recipe(recipe);
                }
            })?,
            Listener::for_page(&self.els.form, "input", &weak, |p, e| {
                if let Some(el) = target_element(e).filter(|el| el.has_attribute("data-field")) {
                    p.form.borrow().note_edit(&el);
                    p.on_edit();
                }
            })?,
            Listener::for_page(&self.els.form, "change", &weak, |p, e| {
                let Some(el) = target_element(e) else {
                    return;
                };
                // Text fields and selects report through "input"; the file picker here.
                if el.has_attribute("data-file-input") {
                    p.on_file_chosen();
                }
            })?,
            Listener::for_page(&self.els.form, "keydown", &weak, |p, e| {
                let Some(key) = e.dyn_ref::<KeyboardEvent>() else {
                    return;
                };
                let in_field = target_element(e).is_some_and(|el| el.has_attribute("data-field"));
                if key.key() == "Enter" && in_field && !key.is_composing() {
                    e.prevent_default();
                    p.request_run();
                }
            })?,
            Listener::for_page(&self.els.form, "submit", &weak, |_, e| e.prevent_default())?,
            Listener::for_page(&self.els.form, "click", &weak, |p, e| {
                if target_element(e)
                    .is_some_and(|el| el.closest("[data-use-sample]").ok().flatten().is_some())
                {
                    p.use_sample();
                }
            })?,
            Listener::for_page(&self.els.run, "click", &weak, |p, _| p.request_run())?,
            Listener::for_page(&reset, "click", &weak, |p, _| p.reset())?,
            Listener::for_page(&self.els.output, "click", &weak, |p, e| {
                let Some(el) = target_element(e) else {
                    return;
                };
                if let Some(button) = el.closest("[data-download]").ok().flatten() {
                    let file = button.get_attribute("data-download").unwrap_or_default();
                    p.download(&file);
                } else if let Some(button) = el.closest("[data-copy]").ok().flatten() {
                    let kind = button.get_attribute("data-copy").unwrap_or_default();
                    p.exports.copy(&kind);
                }
            })?,
            Listener::for_page(&self.els.output, "change", &weak, |p, e| {
                let Some(el) = target_element(e).filter(|el| el.has_attribute("data-exact")) else {
                    return;
                };
                if let Ok(input) = el.dyn_into::<web_sys::HtmlInputElement>() {
                    p.set_exact(input.checked());
                }
            })?,
        ];
        Ok(())
    }

    pub(super) fn relocalize(&self) {
        self.form.borrow().relocalize();
        self.exports.relocalize();
        self.render_errors();
        self.render_status();
        self.render_notice();
        self.render_file_status();
        if let Err(e) = self.render_output() {
            web_sys::console::error_2(&"drills: result".into(), &e);
        }
        if let Some(bg) = self.background.borrow().as_ref() {
            bg.panel.relocalize();
        }
        self.render_background_error();
    }

    pub(super) fn unmount(&self) {
        if let Some(bg) = self.background.borrow_mut().take() {
            bg.stop();
        }
        self.auto_timer.cancel();
        *self.scope.borrow_mut() = Scope::new();
        self.listeners.borrow_mut().clear();
        let mut st = self.st.borrow_mut();
        st.read_generation += 1;
        st.shown = None;
        st.input = None;
    }
}

/// The element an event happened on.
fn target_element(event: &Event) -> Option<Element> {
    event.target().and_then(|t| t.dyn_into::<Element>().ok())
}
