//! Lessons in the shell: the header's "Add this view to the lesson" button, the presenter
//! bar's place, and the shell's way into presenting ([`crate::ui::lesson_present`], a chunk
//! fetched when presenting starts, in one window or on two screens): once it is here, the
//! shell's keys, bar clicks and redraws go to it through `Hooks`. The lesson itself is
//! [`crate::view::lesson`]; it is kept in localStorage (`bsv.lesson`) so it survives a reload;
//! the `#/lesson` page edits it.

use std::cell::{Cell, RefCell};

use wasm_bindgen::prelude::*;
use web_sys::{Element, Event, KeyboardEvent};

use crate::ui::kit::store::{self, Refused, Stored};
use crate::ui::lesson_present::{Hooks, KeyTaken};
use crate::ui::page::SplitLoaderError;
use crate::ui::page::{ShellLink, ShellRequest};
use crate::ui::present_two::{self, PresentEntry};
use crate::ui::split_point::split_point;
use crate::ui::{ctx, dom, lesson_focus, router};
use crate::view::lesson::{Lesson, LessonStep};
use crate::view::lesson_file;
use crate::view::url::Route;

/// localStorage key of the current lesson (its `.json` text).
pub const LESSON_STORAGE_KEY: &str = "bsv.lesson";
const BAR_ID: &str = "lesson-bar";

thread_local! {
    /// The current lesson when the browser refused to store it.
    static UNSAVED: RefCell<Option<Lesson>> = const { RefCell::new(None) };
    /// Presenting's hooks, once its chunk is here.
    static HOOKS: Cell<Option<Hooks>> = const { Cell::new(None) };
}

// Presenting: a wasm chunk of its own, fetched when it starts.
split_point!(lesson_present, fn presenting_chunk() -> PresentEntry = present_two::ENTRY);

/// Presenting's code, its hooks handed the shell's keys, bar clicks and redraws.
async fn presenting() -> Result<PresentEntry, SplitLoaderError> {
    let entry = presenting_chunk().await?;
    HOOKS.set(Some(entry.hooks));
    Ok(entry)
}

/// Presents `lesson` from step `index` in this window, once presenting's code is here; `Err`
/// is the localized reason it could not be fetched.
pub(crate) async fn present(lesson: Lesson, index: usize, shell: ShellLink) -> Result<(), String> {
    let entry = presenting()
        .await
        .map_err(|_| ctx::t("lesson-present-failed"))?;
    let requests = (entry.present)(lesson, index).map_err(|_| ctx::t("lesson-present-failed"))?;
    for request in requests {
        if let Err(error) = (shell.request)(request) {
            web_sys::console::error_1(&error);
        }
    }
    Ok(())
}

/// Presents `lesson` on two screens: the room's window opens on its first step and this
/// window shows the presenter view. `Err` is the localized reason it could not.
pub(crate) async fn present_two(lesson: Lesson, shell: ShellLink) -> Result<(), String> {
    let entry = presenting()
        .await
        .map_err(|_| ctx::t("lesson-present-failed"))?;
    (entry.start_two)(lesson, shell.request)
}

/// Joins a two-screen presentation if this window was opened as its room's window.
pub(crate) fn join_if_audience(shell: ShellLink) {
    let named = web_sys::window().and_then(|w| w.name().ok());
    if named.as_deref() != Some(present_two::AUDIENCE_NAME) {
        return;
    }
    wasm_bindgen_futures::spawn_local(async move {
        if let Ok(entry) = presenting().await {
            if let Err(error) = (entry.join)(shell.request) {
                web_sys::console::error_1(&error);
            }
        }
    });
}

/// A key while a lesson is presented (the shell asks before the page and the focused control
/// see it): `None` if not taken, else what the presenter asks of the shell.
pub(crate) fn on_key(event: &KeyboardEvent) -> KeyTaken {
    let Some(hooks) = HOOKS.get() else {
        return Ok(None);
    };
    if crate::ui::kit::keymap::has_command_modifier(event) {
        return Ok(None);
    }
    let typing = crate::ui::kit::keymap::is_text_entry(event.target());
    (hooks.on_key)(&event.key(), typing)
}

/// A click in the presenter bar: what the presenter asks of the shell.
pub(crate) fn on_bar_click(event: &Event) -> Result<Vec<ShellRequest>, JsValue> {
    HOOKS
        .get()
        .map_or(Ok(Vec::new()), |hooks| (hooks.on_bar_click)(event))
}

/// Redraws the presenter bar, if a lesson is presented.
pub(crate) fn render() -> Result<(), JsValue> {
    HOOKS.get().map_or(Ok(()), |hooks| (hooks.render)())
}

/// The current lesson (empty when none, or when the stored text could not be read: that text
/// is then kept under [`store::aside_key`]); `is_page` says which page ids exist (a lesson step
/// must name one). A lesson the browser refused to store is the one in this tab's memory.
pub fn stored(is_page: impl Fn(&str) -> bool) -> Lesson {
    if let Some(lesson) = UNSAVED.with_borrow(|l| l.clone()) {
        return lesson;
    }
    match store::read(LESSON_STORAGE_KEY, |text| {
        lesson_file::from_stored(text, is_page)
    }) {
        Stored::Read(lesson) => lesson,
        Stored::Nothing | Stored::SetAside => Lesson::default(),
    }
}

/// Saves `lesson` as the current one; `Err` when the browser refused (it is then kept in
/// this tab's memory, and [`unsaved`] says so, until a save succeeds).
pub fn store(lesson: &Lesson) -> Result<(), Refused> {
    let saved = store::save(LESSON_STORAGE_KEY, &lesson_file::to_json(lesson));
    UNSAVED.with_borrow_mut(|l| *l = saved.is_err().then(|| lesson.clone()));
    saved
}

/// Whether the current lesson lives only in this tab (the browser refused to store it).
pub fn unsaved() -> bool {
    UNSAVED.with_borrow(Option::is_some)
}

/// The header button and its live status line.
pub(crate) fn build_add_button(shell: ShellLink) -> Result<Element, JsValue> {
    let wrap = dom::el_class("span", "lesson-add-wrap tool-wrap")?;
    // "+ Lesson" at every width: a bare "+" would not say what it adds to.
    let button = dom::el_class("button", "tool-button lesson-add")?;
    dom::append(&button, &dom::el_i18n("span", "tool-full", "lesson-add")?)?;
    button.set_attribute("type", "button")?;
    button.set_attribute("data-testid", "lesson-add")?;
    dom::set_i18n_attrs(&button, &[("title", "lesson-add-title")])?;
    let status = dom::el_class("span", "lesson-add-status tool-status visually-hidden")?;
    status.set_attribute("role", "status")?;
    status.set_attribute("data-testid", "lesson-add-status")?;
    let shown = status.clone();
    dom::Listener::new(&button, "click", move |_| {
        // The view of the click, whenever the chunk arrives.
        let (shown, route) = (shown.clone(), router::current_route());
        wasm_bindgen_futures::spawn_local(async move {
            let (text, failed) = match adder().await {
                Ok(add) => match add(shell, &route) {
                    Some((count, true)) => (
                        ctx::t_strings("lesson-added", &[("count", count.to_string())]),
                        false,
                    ),
                    Some((count, false)) => (
                        ctx::t_strings("lesson-added-unsaved", &[("count", count.to_string())]),
                        false,
                    ),
                    None => return,
                },
                Err(_) => (ctx::t("lesson-add-failed"), true),
            };
            // A failure is shown under the button (an alert); an added step is announced.
            let classes = shown.class_list();
            let _ = classes.toggle_with_force("visually-hidden", !failed);
            let _ = classes.toggle_with_force("tool-failed", failed);
            let _ = shown.set_attribute("role", if failed { "alert" } else { "status" });
            shown.set_text_content(Some(&text));
        });
    })?
    .forever();
    dom::append(&wrap, &button)?;
    dom::append(&wrap, &status)?;
    Ok(wrap)
}

/// What "+ Lesson" does ([`add_current_view`]).
type AddFn = fn(ShellLink, &Route) -> Option<(usize, bool)>;

// "+ Lesson": a wasm chunk of its own (it reads and writes the lesson file's JSON, which no
// page needs before its first frame), fetched on the first click.
split_point!(lesson_add, fn adder() -> AddFn = add_current_view);

/// Appends the view of `route` to the current lesson; the number of steps after it, and
/// whether the browser stored it.
fn add_current_view(shell: ShellLink, route: &Route) -> Option<(usize, bool)> {
    let def = shell.find(&route.page)?;
    if def.id == "lesson" {
        return None;
    }
    let hash = crate::view::url::build_hash(&route.page, &route.page_query());
    let is_page = |id: &str| shell.is_page(id);
    let mut lesson = stored(is_page);
    if lesson.title.is_empty() {
        lesson.title = ctx::t("lesson-untitled");
    }
    let mut step = LessonStep::of_route(&hash, &ctx::t(def.title_id));
    step.focus = lesson_focus::middle_section();
    lesson.steps.push(step);
    lesson.validate(is_page).ok()?;
    let saved = store(&lesson).is_ok();
    Some((lesson.steps.len(), saved))
}

/// The (hidden) presenter bar the shell places in `#app`.
pub(crate) fn build_bar() -> Result<Element, JsValue> {
    dom::hidden_landmark("aside", BAR_ID, "lesson-bar-label")
}
