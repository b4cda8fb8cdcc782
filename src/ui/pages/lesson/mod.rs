//! The lesson page (`#/lesson`): the lesson being built (steps added from any page with the
//! header's "Add this view"), edited here (title, each step's title, note and page steps,
//! focus, reorder, delete), presented, exported and imported as `.json`, and shared as a link (the
//! page's own URL is the lesson). The three built-in lessons load from here; while the user
//! has no lesson of their own, the first one is shown ready to present (not stored until edited).
//!
//! A file is refused from its size above [`MAX_FILE_BYTES`] (unread), else read and checked
//! by [`crate::view::lesson_file`]; a refusal names what and where, and the current lesson is
//! kept. The lines under the intro say what the browser's storage did: the lesson is not saved
//! (storage full: it stays in memory), or the stored text could not be read and is kept aside
//! (download, discard); a notice names the keys of the link that hold no part of the lesson,
//! and another each step's focus that its page does not have (dropped: the step shows the
//! page's main view). A step's focus is chosen among its page's sections
//! ([`crate::view::sections`]), known without the page being open.
//!
//! Components: `builtin` (the built-in lessons); this file holds the page, its markup and the
//! editor's actions. The lesson model is [`crate::view::lesson`]; storage and presenting are the
//! shell's [`crate::ui::lesson_bar`], on the kit's [`crate::ui::kit::store`].

mod builtin;

use std::cell::{Cell, RefCell};
use std::rc::Rc;

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::{Element, Event, HtmlInputElement, HtmlSelectElement, HtmlTextAreaElement};

use crate::ui::dom::{self, Listener};
use crate::ui::kit::input_file;
use crate::ui::kit::store;
use crate::ui::kit::url_state::UrlNotice;
use crate::ui::lesson_bar::{self, LESSON_STORAGE_KEY};
use crate::ui::page::{MountCtx, Page, ShellLink};
use crate::ui::page_frame;
use crate::ui::{ctx, download, lang_files, router};
use crate::view::embed::parse_number;
use crate::view::exercises::ids_of_page;
use crate::view::lesson::{Lesson, LessonError, UnknownFocus, MAX_FILE_BYTES, MAX_PAGE_STEPS};
use crate::view::lesson_file;
use crate::view::lesson_goal::{self, GoalCondition, GoalOp, MAX_GOALS};
use crate::view::sections;

/// The download of the stored text that could not be read.
const UNREADABLE_FILE: &str = "lesson-unreadable.json";

/// The lesson page.
pub struct LessonPage(Rc<Editor>);

/// The lesson being edited, its elements and listeners.
struct Editor {
    root: Element,
    /// The page table (a step must name a page) and the shell's requests.
    shell: ShellLink,
    lesson: RefCell<Lesson>,
    /// The lesson shown is the built-in one opened for a user without a lesson (not stored).
    builtin_shown: Cell<bool>,
    /// The keys of the opened link that hold no part of the lesson.
    url_notice: UrlNotice,
    /// The problem of the last file or link refused (said again on a language switch).
    error: RefCell<Option<LessonError>>,
    /// The focuses of the last lesson read that its steps' pages do not have.
    unknown_focuses: RefCell<Vec<UnknownFocus>>,
    listeners: RefCell<Vec<Listener>>,
    steps_listeners: RefCell<Vec<Listener>>,
}

impl Page for LessonPage {
    fn mount(ctx: MountCtx) -> Result<LessonPage, JsValue> {
        mount(ctx).map(LessonPage)
    }

    fn relocalize(&self) {
        if self.0.builtin_shown.get() {
            let _ = self.0.show_first_builtin();
        }
        let _ = self.0.render_steps();
        let _ = self.0.render_store_notes();
        let _ = self.0.render_focus_notice();
        self.0.url_notice.relocalize();
        let error = self.0.error.borrow().clone();
        if let Some(error) = error {
            let _ = self.0.show_error(&error);
        }
    }
}

fn mount(ctx: MountCtx) -> Result<Rc<Editor>, JsValue> {
    let root = ctx.root.clone();
    page_frame::fill(&root, MARKUP)?;
    dom::relocalize(&root)?;
    let is_page = |id: &str| ctx.shell.is_page(id);
    let url_notice = UrlNotice::new(
        dom::find(&root, "[data-testid=\"lesson-url-notice\"]", "lesson")?,
        Lesson::ignored_keys(&ctx.query),
    )?;
    let page = Rc::new(Editor {
        url_notice,
        root,
        shell: ctx.shell,
        lesson: RefCell::new(lesson_bar::stored(is_page)),
        builtin_shown: Cell::new(false),
        error: RefCell::new(None),
        unknown_focuses: RefCell::new(Vec::new()),
        listeners: RefCell::new(Vec::new()),
        steps_listeners: RefCell::new(Vec::new()),
    });
    // A lesson in the URL becomes the current one; a bad one is named, the current one kept.
    match Lesson::from_query(&ctx.query, is_page) {
        Ok(Some(lesson)) => {
            // Refused by the browser: said by the store notes, the lesson kept in memory.
            let _ = lesson_bar::store(&lesson);
            *page.lesson.borrow_mut() = lesson;
        }
        Ok(None) => {}
        Err(error) => page.show_error(&error)?,
    }
    let unknown = page.lesson.borrow_mut().take_unknown_focuses();
    if !unknown.is_empty() {
        // Stored without them (refused by the browser: said by the store notes).
        let _ = lesson_bar::store(&page.lesson.borrow());
    }
    *page.unknown_focuses.borrow_mut() = unknown;
    if page.lesson.borrow().steps.is_empty() {
        page.show_first_builtin()?;
    }
    page.wire()?;
    page.render_steps()?;
    page.render_store_notes()?;
    page.render_focus_notice()?;
    // The exercises' prompts name them in the steps' exercise fields (the ids until then).
    let weak = Rc::downgrade(&page);
    wasm_bindgen_futures::spawn_local(async move {
        if lang_files::load(ctx::lang(), &[EXERCISE_STRINGS])
            .await
            .is_ok()
        {
            if let Some(page) = weak.upgrade() {
                let _ = page.render_steps();
            }
        }
    });
    Ok(page)
}

/// The Fluent file of the exercises' prompts.
const EXERCISE_STRINGS: &str = "exercises.ftl";

const MARKUP: &str = "<div class=\"lesson\"><h1 data-i18n=\"lesson-title\"></h1>\
<p class=\"lesson-intro\" data-i18n=\"lesson-intro\"></p>\
<p class=\"lesson-store-note lesson-url-notice\" data-testid=\"lesson-url-notice\" hidden></p>\
<ul class=\"lesson-store-note\" role=\"status\" data-testid=\"lesson-focus-notice\" hidden></ul>\
<p class=\"lesson-store-note\" role=\"status\" data-testid=\"lesson-unsaved\" data-i18n=\"lesson-unsaved\" hidden></p>\
<div class=\"lesson-store-note\" role=\"status\" data-testid=\"lesson-unreadable\" hidden>\
<p data-testid=\"lesson-unreadable-text\"></p>\
<button type=\"button\" class=\"tool-button\" data-download=\"lesson-unreadable.json\" data-i18n=\"lesson-unreadable-download\"></button>\
<button type=\"button\" class=\"tool-button\" data-action=\"lesson-forget-unreadable\" data-i18n=\"lesson-unreadable-forget\"></button>\
</div>\
<section class=\"lesson-card\" data-section=\"lessons\" aria-labelledby=\"lesson-builtin-heading\">\
<h2 id=\"lesson-builtin-heading\" data-i18n=\"lesson-builtin-heading\"></h2>\
<div class=\"lesson-builtins\">\
<button type=\"button\" class=\"tool-button\" data-builtin=\"ik\" data-i18n=\"lesson-builtin-ik-title\"></button>\
<button type=\"button\" class=\"tool-button\" data-builtin=\"energy\" data-i18n=\"lesson-builtin-energy-title\"></button>\
<button type=\"button\" class=\"tool-button\" data-builtin=\"planning\" data-i18n=\"lesson-builtin-planning-title\"></button>\
</div></section>\
<section class=\"lesson-card\" data-section=\"steps\" aria-labelledby=\"lesson-edit-heading\">\
<h2 id=\"lesson-edit-heading\" data-i18n=\"lesson-edit-heading\"></h2>\
<label class=\"lesson-field\"><span data-i18n=\"lesson-name-label\"></span>\
<input type=\"text\" data-field=\"lesson-title\" maxlength=\"120\"></label>\
<p class=\"lesson-builtin-note\" data-testid=\"lesson-builtin-note\" data-i18n=\"lesson-builtin-shown\" hidden></p>\
<p class=\"lesson-empty\" data-testid=\"lesson-empty\" data-i18n=\"lesson-empty\"></p>\
<ol class=\"lesson-steps\" data-testid=\"lesson-steps\"></ol>\
<div class=\"lesson-actions\">\
<button type=\"button\" class=\"tool-button lesson-present\" data-action=\"lesson-present\" data-i18n=\"lesson-present\"></button>\
<button type=\"button\" class=\"tool-button\" data-action=\"lesson-present-two\" data-i18n=\"lesson-present-two\"></button>\
<button type=\"button\" class=\"tool-button\" data-download=\"lesson.json\" data-i18n=\"lesson-export\"></button>\
<label class=\"tool-button lesson-import\"><span data-i18n=\"lesson-import\"></span>\
<input type=\"file\" accept=\".json,application/json\" data-action=\"lesson-import\" class=\"visually-hidden\"></label>\
<button type=\"button\" class=\"tool-button\" data-action=\"lesson-clear\" data-i18n=\"lesson-clear\"></button>\
</div>\
<p class=\"lesson-error\" role=\"alert\" data-field-error=\"lesson-file\" hidden></p>\
<p class=\"lesson-error\" role=\"alert\" data-field-error=\"lesson-present\" hidden></p>\
<label class=\"lesson-field\"><span data-i18n=\"lesson-link-label\"></span>\
<input type=\"text\" readonly data-readout=\"lesson-link\"></label>\
</section></div>";

impl Editor {
    fn is_page(&self, id: &str) -> bool {
        self.shell.is_page(id)
    }

    /// The first built-in lesson in the editor, in the current language, without storing it
    /// (the user's storage is untouched until they edit it).
    fn show_first_builtin(&self) -> Result<(), JsValue> {
        let Some(lesson) = builtin::lesson(builtin::FIRST, |id| self.is_page(id)) else {
            return Ok(());
        };
        *self.lesson.borrow_mut() = lesson;
        self.builtin_shown.set(true);
        let title: HtmlInputElement = self.find("[data-field=\"lesson-title\"]")?;
        title.set_value(&self.lesson.borrow().title);
        Ok(())
    }

    /// Presents the lesson from step `index`, once presenting's code is here; what stopped
    /// it is said under the buttons.
    fn present(&self, index: usize) -> Result<(), JsValue> {
        let lesson = self.lesson.borrow().clone();
        let slot: Element = self.find("[data-field-error=\"lesson-present\"]")?;
        dom::show(&slot, false);
        let shell = self.shell;
        wasm_bindgen_futures::spawn_local(async move {
            if let Err(reason) = lesson_bar::present(lesson, index, shell).await {
                slot.set_text_content(Some(&reason));
                dom::show(&slot, true);
            }
        });
        Ok(())
    }

    /// Presents the lesson on two screens; what stopped it is said under the buttons.
    fn present_two(&self) -> Result<(), JsValue> {
        let lesson = self.lesson.borrow().clone();
        let slot: Element = self.find("[data-field-error=\"lesson-present\"]")?;
        dom::show(&slot, false);
        let shell = self.shell;
        wasm_bindgen_futures::spawn_local(async move {
            if let Err(reason) = lesson_bar::present_two(lesson, shell).await {
                slot.set_text_content(Some(&reason));
                dom::show(&slot, true);
            }
        });
        Ok(())
    }

    fn find<T: JsCast>(&self, selector: &str) -> Result<T, JsValue> {
        dom::find(&self.root, selector, "lesson")
    }

    fn show_error(&self, error: &LessonError) -> Result<(), JsValue> {
        *self.error.borrow_mut() = Some(error.clone());
        let slot: Element = self.find("[data-field-error=\"lesson-file\"]")?;
        let args: Vec<(&str, String)> = match error {
            LessonError::Decode(decode) => vec![("detail", ctx::error_text(decode))],
            _ => error.args(),
        };
        slot.set_text_content(Some(&ctx::t_strings(error.message_id(), &args)));
        dom::show(&slot, true);
        Ok(())
    }

    fn clear_error(&self) -> Result<(), JsValue> {
        *self.error.borrow_mut() = None;
        let slot: Element = self.find("[data-field-error=\"lesson-file\"]")?;
        dom::show(&slot, false);
        Ok(())
    }

    /// The lesson changed: store it, write the URL and the link, redraw the list when asked.
    fn changed(self: &Rc<Self>, redraw: bool) -> Result<(), JsValue> {
        self.builtin_shown.set(false);
        let note: Element = self.find("[data-testid=\"lesson-builtin-note\"]")?;
        dom::show(&note, false);
        let lesson = self.lesson.borrow().clone();
        // Refused by the browser: the lesson stays in memory and the store notes say so.
        let _ = lesson_bar::store(&lesson);
        self.render_store_notes()?;
        router::replace_query(&lesson.to_query());
        if redraw {
            self.render_steps()?;
        } else {
            self.write_link()?;
        }
        Ok(())
    }

    fn write_link(&self) -> Result<(), JsValue> {
        let link: HtmlInputElement = self.find("[data-readout=\"lesson-link\"]")?;
        let location = dom::window()?.location();
        let base = format!("{}{}", location.origin()?, location.pathname()?);
        let hash = crate::view::url::build_hash("lesson", &self.lesson.borrow().to_query());
        link.set_value(&format!("{base}{hash}"));
        Ok(())
    }

    fn wire(self: &Rc<Self>) -> Result<(), JsValue> {
        let mut listeners = self.listeners.borrow_mut();
        let title: HtmlInputElement = self.find("[data-field=\"lesson-title\"]")?;
        title.set_value(&self.lesson.borrow().title);
        let weak = Rc::downgrade(self);
        listeners.push(Listener::new(&title.clone(), "input", move |_| {
            if let Some(page) = weak.upgrade() {
                page.lesson.borrow_mut().title = title.value();
                let _ = page.changed(false);
            }
        })?);

        let weak = Rc::downgrade(self);
        listeners.push(Listener::new(&self.root, "click", move |event: Event| {
            let Some(page) = weak.upgrade() else { return };
            let target = event
                .target()
                .and_then(|t| t.dyn_into::<Element>().ok())
                .and_then(|e| {
                    e.closest("[data-builtin], [data-action], [data-download], [data-step-action]")
                        .ok()
                        .flatten()
                });
            let Some(target) = target else { return };
            if let Err(error) = page.on_click(&target) {
                web_sys::console::error_2(&"BSV Playground: lesson".into(), &error);
            }
        })?);

        let import: HtmlInputElement = self.find("input[data-action=\"lesson-import\"]")?;
        let weak = Rc::downgrade(self);
        let input = import.clone();
        listeners.push(Listener::new(&import, "change", move |_| {
            let Some(page) = weak.upgrade() else { return };
            if let Some(picked) = input_file::chosen(&input) {
                // A file over the limit is refused from its size, unread.
                if picked.bytes > MAX_FILE_BYTES {
                    let _ = page.imported(Err(LessonError::TooBig {
                        bytes: picked.bytes,
                    }));
                } else {
                    let weak = Rc::downgrade(&page);
                    input_file::read_text(&picked.name, &picked.blob, move |result| {
                        if let Some(page) = weak.upgrade() {
                            let _ = page.imported(result.map_err(|p| match p {
                                input_file::ReadProblem::Browser(detail) => {
                                    LessonError::NotText { detail }
                                }
                                input_file::ReadProblem::Decode(error) => {
                                    LessonError::Decode(error)
                                }
                            }));
                        }
                    });
                }
            }
            input.set_value("");
        })?);
        Ok(())
    }

    /// A whole new lesson (imported or built in): its title in the field, no error shown, the
    /// focuses its pages do not have named.
    fn replace(self: &Rc<Self>, mut lesson: Lesson) -> Result<(), JsValue> {
        self.clear_error()?;
        *self.unknown_focuses.borrow_mut() = lesson.take_unknown_focuses();
        self.render_focus_notice()?;
        *self.lesson.borrow_mut() = lesson;
        let title: HtmlInputElement = self.find("[data-field=\"lesson-title\"]")?;
        title.set_value(&self.lesson.borrow().title);
        self.changed(true)
    }

    /// A file's text (or why there is none): the lesson it holds replaces the current one,
    /// else the problem is named and the current lesson kept.
    fn imported(self: &Rc<Self>, text: Result<String, LessonError>) -> Result<(), JsValue> {
        let parsed = text.and_then(|t| lesson_file::from_json(&t, |id| self.is_page(id)));
        match parsed {
            Ok(lesson) => self.replace(lesson),
            Err(error) => self.show_error(&error),
        }
    }

    fn on_click(self: &Rc<Self>, target: &Element) -> Result<(), JsValue> {
        if let Some(key) = target.get_attribute("data-builtin") {
            let replace = self.lesson.borrow().steps.is_empty()
                || self.builtin_shown.get()
                || dom::window()?.confirm_with_message(&ctx::t("lesson-replace-confirm"))?;
            if replace {
                if let Some(lesson) = builtin::lesson(&key, |id| self.is_page(id)) {
                    self.replace(lesson)?;
                }
            }
            return Ok(());
        }
        if target.get_attribute("data-download").as_deref() == Some(UNREADABLE_FILE) {
            let kept = store::aside(LESSON_STORAGE_KEY).unwrap_or_default();
            return download::download_text(UNREADABLE_FILE, &kept, "application/json");
        }
        if target.get_attribute("data-download").as_deref() == Some("lesson.json") {
            return download::download_text(
                "lesson.json",
                &lesson_file::to_json(&self.lesson.borrow()),
                "application/json",
            );
        }
        match target.get_attribute("data-action").as_deref() {
            Some("lesson-present-two") => {
                if !self.lesson.borrow().steps.is_empty() {
                    self.present_two()?;
                }
                return Ok(());
            }
            Some("lesson-present") => {
                if !self.lesson.borrow().steps.is_empty() {
                    self.present(0)?;
                }
                return Ok(());
            }
            Some("lesson-forget-unreadable") => {
                store::forget_aside(LESSON_STORAGE_KEY);
                return self.render_store_notes();
            }
            Some("lesson-clear") => {
                if dom::window()?.confirm_with_message(&ctx::t("lesson-clear-confirm"))? {
                    self.lesson.borrow_mut().steps.clear();
                    self.changed(true)?;
                }
                return Ok(());
            }
            _ => {}
        }
        if let Some(action) = target.get_attribute("data-step-action") {
            let i: usize = target
                .get_attribute("data-index")
                .and_then(|i| i.parse().ok())
                .unwrap_or(usize::MAX);
            let len = self.lesson.borrow().steps.len();
            if i >= len {
                return Ok(());
            }
            match action.as_str() {
                "up" if i > 0 => self.lesson.borrow_mut().move_step(i, i - 1),
                "down" if i + 1 < len => self.lesson.borrow_mut().move_step(i, i + 1),
                "delete" => {
                    self.lesson.borrow_mut().steps.remove(i);
                }
                "present" => {
                    return self.present(i);
                }
                _ => return Ok(()),
            }
            self.changed(true)?;
        }
        Ok(())
    }

    /// The lines about the browser's storage: the lesson is not saved (storage refused it);
    /// the stored text could not be read and is kept aside (with its download and discard).
    fn render_store_notes(&self) -> Result<(), JsValue> {
        let unsaved: Element = self.find("[data-testid=\"lesson-unsaved\"]")?;
        dom::show(&unsaved, lesson_bar::unsaved());
        let unreadable: Element = self.find("[data-testid=\"lesson-unreadable\"]")?;
        let kept = store::aside(LESSON_STORAGE_KEY).is_some();
        if kept {
            let text: Element = self.find("[data-testid=\"lesson-unreadable-text\"]")?;
            let key = store::aside_key(LESSON_STORAGE_KEY);
            text.set_text_content(Some(&ctx::t_strings("lesson-unreadable", &[("key", key)])));
        }
        dom::show(&unreadable, kept);
        Ok(())
    }

    /// The notice naming each step's focus that its page does not have.
    fn render_focus_notice(&self) -> Result<(), JsValue> {
        let notice: Element = self.find("[data-testid=\"lesson-focus-notice\"]")?;
        dom::clear(&notice);
        let unknown = self.unknown_focuses.borrow();
        for focus in unknown.iter() {
            let line = ctx::t_strings(UnknownFocus::MESSAGE_ID, &focus.args());
            dom::append(&notice, &dom::el_text("li", "", &line)?)?;
        }
        dom::show(&notice, !unknown.is_empty());
        Ok(())
    }

    /// The list of steps, each with its fields and buttons.
    fn render_steps(self: &Rc<Self>) -> Result<(), JsValue> {
        let list: Element = self.find("[data-testid=\"lesson-steps\"]")?;
        dom::clear(&list);
        let mut listeners = self.steps_listeners.borrow_mut();
        listeners.clear();
        let lesson = self.lesson.borrow().clone();
        let empty: Element = self.find("[data-testid=\"lesson-empty\"]")?;
        dom::show(&empty, lesson.steps.is_empty());
        let note: Element = self.find("[data-testid=\"lesson-builtin-note\"]")?;
        dom::show(&note, self.builtin_shown.get());
        for action in ["lesson-present", "lesson-present-two"] {
            let present: Element = self.find(&format!("[data-action=\"{action}\"]"))?;
            if lesson.steps.is_empty() {
                present.set_attribute("disabled", "")?;
            } else {
                present.remove_attribute("disabled")?;
            }
        }
        for (i, step) in lesson.steps.iter().enumerate() {
            let item = dom::el_class("li", "lesson-step")?;
            item.set_attribute("data-testid", &format!("lesson-step-{}", i + 1))?;
            let head = dom::el_class("div", "lesson-step-head")?;
            let link = dom::el_text("a", "lesson-step-route", &step.route)?;
            link.set_attribute("href", &step.route)?;
            dom::append(&head, &link)?;
            for (action, label) in [
                ("up", "lesson-step-up"),
                ("down", "lesson-step-down"),
                ("present", "lesson-step-present"),
                ("delete", "lesson-step-delete"),
            ] {
                let b = dom::el_i18n("button", "tool-button lesson-step-button", label)?;
                b.set_attribute("type", "button")?;
                b.set_attribute("data-step-action", action)?;
                b.set_attribute("data-index", &i.to_string())?;
                // The label names the step: "Move step 2 up".
                b.set_attribute(
                    "aria-label",
                    &ctx::t_strings(&format!("{label}-label"), &[("n", (i + 1).to_string())]),
                )?;
                dom::append(&head, &b)?;
            }
            dom::append(&item, &head)?;

            let title = field(&item, "lesson-step-title-label", "step-title", "input", i)?;
            let title: HtmlInputElement = title.dyn_into()?;
            title.set_value(&step.title);
            title.set_attribute("maxlength", "120")?;
            let note = field(&item, "lesson-step-note-label", "step-note", "textarea", i)?;
            let note: HtmlTextAreaElement = note.dyn_into()?;
            note.set_value(&step.note);
            note.set_attribute("maxlength", "1000")?;
            let steps = field(
                &item,
                "lesson-step-page-steps-label",
                "step-page-steps",
                "input",
                i,
            )?;
            let steps: HtmlInputElement = steps.dyn_into()?;
            steps.set_attribute("inputmode", "numeric")?;
            steps.set_value(&step.page_steps.to_string());
            let focus = focus_field(&item, &step.page(), step.focus.as_deref())?;
            let exercise = exercise_field(&item, &step.page(), step.exercise.as_deref())?;
            if let Some(goals) = goals_field(&item, &step.page(), &step.goals)? {
                self.listen_goals(&goals, i, &mut listeners)?;
            }
            let error = dom::el_class("p", "lesson-step-error")?;
            error.set_attribute("data-field-error", &format!("step-page-steps-{}", i + 1))?;
            dom::show(&error, false);
            dom::append(&item, &error)?;

            let weak = Rc::downgrade(self);
            let input = title.clone();
            listeners.push(Listener::new(&title, "input", move |_| {
                if let Some(page) = weak.upgrade() {
                    if let Some(s) = page.lesson.borrow_mut().steps.get_mut(i) {
                        s.title = input.value();
                    }
                    let _ = page.changed(false);
                }
            })?);
            let weak = Rc::downgrade(self);
            let input = note.clone();
            listeners.push(Listener::new(&note, "input", move |_| {
                if let Some(page) = weak.upgrade() {
                    if let Some(s) = page.lesson.borrow_mut().steps.get_mut(i) {
                        s.note = input.value();
                    }
                    let _ = page.changed(false);
                }
            })?);
            let weak = Rc::downgrade(self);
            let select = focus.clone();
            listeners.push(Listener::new(&focus, "change", move |_| {
                if let Some(page) = weak.upgrade() {
                    if let Some(s) = page.lesson.borrow_mut().steps.get_mut(i) {
                        let value = select.value();
                        s.focus = (!value.is_empty()).then_some(value);
                    }
                    let _ = page.changed(false);
                }
            })?);
            if let Some(exercise) = exercise {
                let weak = Rc::downgrade(self);
                let select = exercise.clone();
                listeners.push(Listener::new(&exercise, "change", move |_| {
                    if let Some(page) = weak.upgrade() {
                        if let Some(s) = page.lesson.borrow_mut().steps.get_mut(i) {
                            let value = select.value();
                            s.exercise = (!value.is_empty()).then_some(value);
                        }
                        let _ = page.changed(false);
                    }
                })?);
            }
            let weak = Rc::downgrade(self);
            let input = steps.clone();
            listeners.push(Listener::new(&steps, "input", move |_| {
                let Some(page) = weak.upgrade() else { return };
                match input.value().trim().parse::<u32>() {
                    Ok(k) if k <= MAX_PAGE_STEPS => {
                        dom::show(&error, false);
                        if let Some(s) = page.lesson.borrow_mut().steps.get_mut(i) {
                            s.page_steps = k;
                        }
                        let _ = page.changed(false);
                    }
                    _ => {
                        error.set_text_content(Some(&ctx::t_strings(
                            "lesson-page-steps-invalid",
                            &[("max", MAX_PAGE_STEPS.to_string())],
                        )));
                        dom::show(&error, true);
                    }
                }
            })?);
            dom::append(&list, &item)?;
        }
        drop(listeners);
        self.write_link()
    }
}

/// The step's focus (`data-field="focus"`): the main view, or one of the sections of `page`,
/// each by its name; appended to `item`.
fn focus_field(
    item: &Element,
    page: &str,
    focus: Option<&str>,
) -> Result<HtmlSelectElement, JsValue> {
    let label = dom::el_class("label", "lesson-field")?;
    dom::append(
        &label,
        &dom::el_i18n("span", "", "lesson-step-focus-label")?,
    )?;
    let select: HtmlSelectElement = dom::el("select")?.dyn_into()?;
    select.set_attribute("data-field", "focus")?;
    let main = dom::el_i18n("option", "", "lesson-step-focus-main")?;
    main.set_attribute("value", "")?;
    dom::append(&select, &main)?;
    for section in sections::of(page) {
        let option = dom::el_i18n("option", "", &sections::name_id(section))?;
        option.set_attribute("value", section)?;
        dom::append(&select, &option)?;
    }
    select.set_value(focus.unwrap_or(""));
    dom::append(&label, &select)?;
    dom::append(item, &label)?;
    Ok(select)
}

impl Editor {
    /// The acts on step `i`'s goal: add a condition, remove one, edit one (kept once it is
    /// well formed; until then the row says what is wrong and the last good one stays).
    fn listen_goals(
        self: &Rc<Self>,
        goals: &Element,
        i: usize,
        listeners: &mut Vec<Listener>,
    ) -> Result<(), JsValue> {
        let weak = Rc::downgrade(self);
        listeners.push(Listener::new(goals, "click", move |event| {
            let Some(page) = weak.upgrade() else { return };
            let Some(button) = event
                .target()
                .and_then(|t| t.dyn_into::<Element>().ok())
                .and_then(|t| t.closest("button[data-action]").ok().flatten())
            else {
                return;
            };
            let row = goal_row_index(&button);
            {
                let mut lesson = page.lesson.borrow_mut();
                let Some(step) = lesson.steps.get_mut(i) else {
                    return;
                };
                match button.get_attribute("data-action").as_deref() {
                    Some("goal-add") if step.goals.len() < MAX_GOALS => {
                        let page_id = step.page();
                        let Some((readout, _)) = lesson_goal::readouts_of(&page_id).first() else {
                            return;
                        };
                        step.goals.push(GoalCondition {
                            readout: (*readout).to_owned(),
                            op: GoalOp::Below,
                            value: 0.0,
                            tolerance: None,
                        });
                    }
                    Some("goal-remove") => {
                        if let Some(j) = row.filter(|j| *j < step.goals.len()) {
                            step.goals.remove(j);
                        }
                    }
                    _ => return,
                }
            }
            let _ = page.changed(true);
        })?);
        let weak = Rc::downgrade(self);
        for kind in ["change", "input"] {
            let weak = weak.clone();
            listeners.push(Listener::new(goals, kind, move |event| {
                let Some(page) = weak.upgrade() else { return };
                let Some(row) = event
                    .target()
                    .and_then(|t| t.dyn_into::<Element>().ok())
                    .and_then(|t| t.closest("[data-goal-row]").ok().flatten())
                else {
                    return;
                };
                let Some(j) = goal_row_index(&row) else {
                    return;
                };
                let read = read_goal_row(&row);
                show_goal_row(&row, read.as_ref());
                if let Some(goal) = read {
                    if let Some(step) = page.lesson.borrow_mut().steps.get_mut(i) {
                        if let Some(old) = step.goals.get_mut(j) {
                            *old = goal;
                        }
                    }
                    let _ = page.changed(false);
                }
            })?);
        }
        Ok(())
    }
}

/// The index (from 0) of the goal row `element` is in.
fn goal_row_index(element: &Element) -> Option<usize> {
    element
        .closest("[data-goal-row]")
        .ok()??
        .get_attribute("data-goal-row")?
        .parse::<usize>()
        .ok()?
        .checked_sub(1)
}

/// The condition a goal row holds, if it is well formed.
fn read_goal_row(row: &Element) -> Option<GoalCondition> {
    let value_of = |field: &str| -> Option<String> {
        let element = row
            .query_selector(&format!("[data-field=\"{field}\"]"))
            .ok()??;
        if let Some(select) = element.dyn_ref::<HtmlSelectElement>() {
            return Some(select.value());
        }
        Some(element.dyn_ref::<HtmlInputElement>()?.value())
    };
    let op = GoalOp::of_word(&value_of("goal-op")?)?;
    let goal = GoalCondition {
        readout: value_of("goal-readout")?,
        op,
        value: parse_number(&value_of("goal-value")?)?,
        tolerance: match op {
            GoalOp::Within => Some(parse_number(&value_of("goal-tolerance")?)?),
            _ => None,
        },
    };
    goal.is_valid().then_some(goal)
}

/// Shows the row's tolerance only for within, its unit, and its error while it is not a
/// condition.
fn show_goal_row(row: &Element, read: Option<&GoalCondition>) {
    let within = row
        .query_selector("[data-field=\"goal-op\"]")
        .ok()
        .flatten()
        .and_then(|e| e.dyn_into::<HtmlSelectElement>().ok())
        .is_some_and(|s| s.value() == GoalOp::Within.word());
    if let Ok(Some(tolerance)) = row.query_selector(".lesson-goal-tolerance") {
        dom::show(&tolerance, within);
    }
    if let Ok(Some(error)) = row.query_selector(".lesson-step-error") {
        dom::show(&error, read.is_none());
    }
}

/// The step's goal (`data-field="goals"`): its conditions, one row each (`data-goal-row`: the
/// readout, `<`, `>` or within, the value and, for within, the tolerance, in the readout's
/// unit; Remove), and "Add a goal" up to [`MAX_GOALS`]; appended to `item`. `None` for a page
/// without readouts.
fn goals_field(
    item: &Element,
    page: &str,
    goals: &[GoalCondition],
) -> Result<Option<Element>, JsValue> {
    let readouts = lesson_goal::readouts_of(page);
    if readouts.is_empty() {
        return Ok(None);
    }
    let field = dom::el_class("fieldset", "lesson-goals-edit")?;
    field.set_attribute("data-field", "goals")?;
    dom::append(
        &field,
        &dom::el_i18n("legend", "", "lesson-step-goals-label")?,
    )?;
    for (j, goal) in goals.iter().enumerate() {
        let row = dom::el_class("div", "lesson-goal-row")?;
        row.set_attribute("data-goal-row", &(j + 1).to_string())?;
        let readout: HtmlSelectElement =
            goal_control("select", "goal-readout", "lesson-goal-readout-label")?.dyn_into()?;
        for (key, unit) in readouts {
            let text = if unit.is_empty() {
                (*key).to_owned()
            } else {
                format!("{key} ({unit})")
            };
            let option = dom::el_text("option", "", &text)?;
            option.set_attribute("value", key)?;
            dom::append(&readout, &option)?;
        }
        readout.set_value(&goal.readout);
        dom::append(&row, &readout)?;
        let op: HtmlSelectElement =
            goal_control("select", "goal-op", "lesson-goal-op-label")?.dyn_into()?;
        for (value, id) in [
            (GoalOp::Below, "lesson-goal-op-below"),
            (GoalOp::Above, "lesson-goal-op-above"),
            (GoalOp::Within, "lesson-goal-op-within"),
        ] {
            let option = dom::el_i18n("option", "", id)?;
            option.set_attribute("value", value.word())?;
            dom::append(&op, &option)?;
        }
        op.set_value(goal.op.word());
        dom::append(&row, &op)?;
        let value = goal_number("goal-value", "lesson-goal-value-label", goal.value)?;
        dom::append(&row, &value)?;
        let tolerance = dom::el_class("span", "lesson-goal-tolerance")?;
        dom::append(&tolerance, &dom::el_text("span", "", "±")?)?;
        let tol = goal.tolerance.unwrap_or(0.0);
        let tol = goal_number("goal-tolerance", "lesson-goal-tolerance-label", tol)?;
        dom::append(&tolerance, &tol)?;
        dom::append(&row, &tolerance)?;
        let unit = lesson_goal::unit_of(page, &goal.readout);
        dom::append(&row, &dom::el_text("span", "lesson-goal-unit", unit)?)?;
        let remove = dom::el_i18n("button", "tool-button", "lesson-goal-remove")?;
        remove.set_attribute("type", "button")?;
        remove.set_attribute("data-action", "goal-remove")?;
        dom::append(&row, &remove)?;
        let error = dom::el_i18n("p", "lesson-step-error", "lesson-goal-invalid")?;
        error.set_attribute("role", "alert")?;
        dom::append(&row, &error)?;
        show_goal_row(&row, Some(goal));
        dom::append(&field, &row)?;
    }
    if goals.len() < MAX_GOALS {
        let add = dom::el_i18n("button", "tool-button", "lesson-goal-add")?;
        add.set_attribute("type", "button")?;
        add.set_attribute("data-action", "goal-add")?;
        dom::append(&field, &add)?;
    }
    dom::append(item, &field)?;
    Ok(Some(field))
}

/// A control of a goal row: a `tag` element marked `data-field="<field>"`, named by the
/// message `label_id`.
fn goal_control(tag: &str, field: &str, label_id: &str) -> Result<Element, JsValue> {
    let control = dom::el(tag)?;
    control.set_attribute("data-field", field)?;
    control.set_attribute("aria-label", &ctx::t(label_id))?;
    Ok(control)
}

/// A number field of a goal row ([`goal_control`]) holding `value`.
fn goal_number(field: &str, label_id: &str, value: f64) -> Result<Element, JsValue> {
    let input: HtmlInputElement = goal_control("input", field, label_id)?.dyn_into()?;
    input.set_attribute("inputmode", "decimal")?;
    input.set_value(&lesson_goal::number_text(value));
    Ok(input.into())
}

/// The step's exercise (`data-field="exercise"`): none, or one of the exercises of `page`,
/// each by its prompt (by its id until the prompts are here); appended to `item`. `None` for a
/// page without exercises.
fn exercise_field(
    item: &Element,
    page: &str,
    exercise: Option<&str>,
) -> Result<Option<HtmlSelectElement>, JsValue> {
    let ids = ids_of_page(page);
    if ids.is_empty() {
        return Ok(None);
    }
    let label = dom::el_class("label", "lesson-field")?;
    dom::append(
        &label,
        &dom::el_i18n("span", "", "lesson-step-exercise-label")?,
    )?;
    let select: HtmlSelectElement = dom::el("select")?.dyn_into()?;
    select.set_attribute("data-field", "exercise")?;
    let none = dom::el_i18n("option", "", "lesson-step-exercise-none")?;
    none.set_attribute("value", "")?;
    dom::append(&select, &none)?;
    for id in ids {
        let prompt = format!("ex-{id}-prompt");
        let text = if ctx::has_message(&prompt) {
            ctx::t(&prompt)
        } else {
            (*id).to_owned()
        };
        let option = dom::el_text("option", "", &text)?;
        option.set_attribute("value", id)?;
        dom::append(&select, &option)?;
    }
    select.set_value(exercise.unwrap_or(""));
    dom::append(&label, &select)?;
    dom::append(item, &label)?;
    Ok(Some(select))
}

/// A labelled field `name`-`n` of step `n` (`tag`: input or textarea), appended to `item`.
fn field(
    item: &Element,
    label_id: &str,
    name: &str,
    tag: &str,
    i: usize,
) -> Result<Element, JsValue> {
    let label = dom::el_class("label", "lesson-field")?;
    dom::append(&label, &dom::el_i18n("span", "", label_id)?)?;
    let control = dom::el(tag)?;
    control.set_attribute("data-field", &format!("{name}-{}", i + 1))?;
    dom::append(&label, &control)?;
    dom::append(item, &label)?;
    Ok(control)
}
