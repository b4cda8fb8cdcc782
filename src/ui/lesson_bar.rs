//! Lessons in the shell: the header's "Add this view to the lesson" button, and presenting a
//! lesson over every page: full screen, projector styles, a bar at the foot with the step's
//! title and note, a progress strip, and the keys of presenter remotes, whatever has focus
//! (PageDown / → next, PageUp / ← back, a step that asks for it first stepping the page's own
//! stepper; B / . black the screen and bring it back; Escape ends); each step brings its focus
//! section into view above the bar ([`crate::ui::lesson_focus`]). The lesson
//! itself is [`crate::view::lesson`]; it is kept in localStorage (`bsv.lesson`) so it survives
//! a reload; the `#/lesson` page edits it. What presenting needs of the shell (step the page,
//! mount it again, projector mode) is returned as [`ShellRequest`]s for the shell to carry out.
//! Presenting on two screens ([`crate::ui::present_two`]) walks the lesson here too, with a
//! [`Relay`] that shows each step in the room's window instead of this one.

use std::cell::{Cell, RefCell};

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::{Element, Event, KeyboardEvent};

use crate::ui::kit::store::{self, Refused, Stored};
use crate::ui::page::SplitLoaderError;
use crate::ui::page::{ShellLink, ShellRequest};
use crate::ui::present_two::{self, TwoScreens};
use crate::ui::{ctx, dom, lesson_focus, router};
use crate::view::lesson::{Lesson, LessonStep, Presenter, PresenterAction};
use crate::view::lesson_file;
use crate::view::url::Route;

/// localStorage key of the current lesson (its `.json` text).
pub const LESSON_STORAGE_KEY: &str = "bsv.lesson";
const BAR_ID: &str = "lesson-bar";

thread_local! {
    /// The current lesson when the browser refused to store it.
    static UNSAVED: RefCell<Option<Lesson>> = const { RefCell::new(None) };
    static PRESENTING: RefCell<Option<(Lesson, Presenter)>> = const { RefCell::new(None) };
    /// Set while a lesson is presented on two screens, in both windows.
    static RELAY: Cell<Option<fn(Relay)>> = const { Cell::new(None) };
    /// Whether the room's screen is black (the presenter's window of two).
    static BLACK: Cell<bool> = const { Cell::new(false) };
}

/// What a two-screen presentation does in place of this window's page and bar: in the
/// presenter's window every step is shown in the room's window and the presenter view is
/// redrawn; in the room's window its presenter keys go to the presenter's.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Relay<'a> {
    /// Show this route (a lesson step) in the room's window, with its focus section.
    Show(&'a str, Option<&'a str>),
    /// Step the page in the room's window.
    StepPage,
    /// Black the room's screen out, or bring it back.
    Black(bool),
    /// Open Share in the room's window.
    Share,
    /// A presenter key pressed in the room's window.
    Key(&'a str),
    /// The lesson or its step changed: redraw the presenter view.
    Redraw,
    /// The presentation ended.
    End,
}

/// Hands presenting to `relay` (both windows of a two-screen presentation), or takes it back.
pub(crate) fn set_relay(relay: Option<fn(Relay)>) {
    RELAY.set(relay);
    BLACK.set(false);
}

/// The lesson being presented and where it stands.
pub(crate) fn current() -> Option<(Lesson, Presenter)> {
    PRESENTING.with(|p| p.borrow().clone())
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

/// "+ Lesson": a wasm chunk of its own (it reads and writes the lesson file's JSON, which no
/// page needs before its first frame), fetched on the first click.
#[cfg(feature = "split")]
#[wasm_split_helpers::wasm_split(lesson_add, fallible)]
fn adder() -> Result<AddFn, SplitLoaderError> {
    Ok(add_current_view)
}

/// Without the `split` feature "+ Lesson" is in the one wasm.
#[cfg(not(feature = "split"))]
async fn adder() -> Result<AddFn, SplitLoaderError> {
    Ok(add_current_view)
}

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

/// Presenting on two screens: a wasm chunk of its own, fetched on first use (or when this
/// window opens as the room's window of a presentation).
#[cfg(feature = "split")]
#[wasm_split_helpers::wasm_split(present_two, fallible)]
fn two_screens() -> Result<TwoScreens, SplitLoaderError> {
    Ok(present_two::ENTRY)
}

/// Without the `split` feature presenting on two screens is in the one wasm.
#[cfg(not(feature = "split"))]
async fn two_screens() -> Result<TwoScreens, SplitLoaderError> {
    Ok(present_two::ENTRY)
}

/// Presents `lesson` on two screens: the room's window opens on its first step and this
/// window shows the presenter view. `Err` is the localized reason it could not.
pub(crate) async fn present_two(lesson: Lesson, shell: ShellLink) -> Result<(), String> {
    let two = two_screens()
        .await
        .map_err(|_| ctx::t("present-two-failed"))?;
    (two.start)(lesson, shell.request)
}

/// Joins a two-screen presentation if this window was opened as its room's window.
pub(crate) fn join_if_audience(shell: ShellLink) {
    let named = web_sys::window().and_then(|w| w.name().ok());
    if named.as_deref() != Some(present_two::AUDIENCE_NAME) {
        return;
    }
    wasm_bindgen_futures::spawn_local(async move {
        if let Ok(two) = two_screens().await {
            if let Err(error) = (two.join)(shell.request) {
                web_sys::console::error_1(&error);
            }
        }
    });
}

/// The (hidden) presenter bar the shell places in `#app`.
pub(crate) fn build_bar() -> Result<Element, JsValue> {
    let bar = dom::el_class("aside", "lesson-bar")?;
    bar.set_id(BAR_ID);
    bar.set_attribute("data-testid", "lesson-bar")?;
    dom::set_i18n_attrs(&bar, &[("aria-label", "lesson-bar-label")])?;
    dom::show(&bar, false);
    Ok(bar)
}

/// A click in the bar (its buttons are redrawn at every step, so the shell listens on the
/// bar): what the presenter asks of the shell.
pub(crate) fn on_bar_click(event: &Event) -> Result<Vec<ShellRequest>, JsValue> {
    let target = event
        .target()
        .and_then(|t| t.dyn_into::<Element>().ok())
        .and_then(|e| e.closest("[data-action]").ok().flatten());
    let Some(target) = target else {
        return Ok(Vec::new());
    };
    match target.get_attribute("data-action").as_deref() {
        Some("lesson-next") => press(true),
        Some("lesson-prev") => press(false),
        Some("lesson-end") => stop().map(|()| Vec::new()),
        Some("lesson-black") => black_out(!blacked_out()?).map(|()| Vec::new()),
        Some("lesson-go") => {
            let i = target
                .get_attribute("data-index")
                .and_then(|i| i.parse::<usize>().ok())
                .unwrap_or(0);
            let action = PRESENTING.with(|p| {
                let mut p = p.borrow_mut();
                p.as_mut().map(|(l, pr)| pr.go(l, i))
            });
            action.map_or(Ok(Vec::new()), apply)
        }
        _ => Ok(Vec::new()),
    }
}

/// Starts presenting `lesson` at step `index`; projector mode on, then what the step asks.
pub fn present(lesson: Lesson, index: usize) -> Result<Vec<ShellRequest>, JsValue> {
    let mut presenter = Presenter::default();
    let action = presenter.go(&lesson, index);
    PRESENTING.with(|p| *p.borrow_mut() = Some((lesson, presenter)));
    if let Some(root) = dom::document()?.document_element() {
        // Full screen needs a user gesture; without one the lesson still runs in the window.
        let _ = root.request_fullscreen();
    }
    let mut requests = vec![ShellRequest::Projector(true)];
    requests.extend(apply(action)?);
    Ok(requests)
}

/// Starts presenting `lesson` at step `index` in the room's window of a two-screen
/// presentation ([`set_relay`] first): this window shows the presenter view.
pub(crate) fn present_on_two(lesson: Lesson, index: usize) -> Result<(), JsValue> {
    let mut presenter = Presenter::default();
    let action = presenter.go(&lesson, index);
    PRESENTING.with(|p| *p.borrow_mut() = Some((lesson, presenter)));
    apply(action).map(drop)
}

/// Stops presenting (on two screens: in both windows).
pub fn stop() -> Result<(), JsValue> {
    PRESENTING.with(|p| *p.borrow_mut() = None);
    lesson_focus::stop();
    if let Some(relay) = RELAY.take() {
        BLACK.set(false);
        relay(Relay::End);
    }
    black_out(false)?;
    let document = dom::document()?;
    if document.fullscreen_element().is_some() {
        document.exit_fullscreen();
    }
    if let Some(bar) = document.get_element_by_id(BAR_ID) {
        dom::show(&bar, false);
    }
    Ok(())
}

/// Whether a lesson is being presented.
pub fn presenting() -> bool {
    PRESENTING.with(|p| p.borrow().is_some())
}

/// Next / back while presenting (buttons and keys).
fn press(forward: bool) -> Result<Vec<ShellRequest>, JsValue> {
    let action = PRESENTING.with(|p| {
        let mut p = p.borrow_mut();
        let (lesson, presenter) = p.as_mut()?;
        Some(if forward {
            presenter.next(lesson)
        } else {
            presenter.back()
        })
    });
    match action {
        Some(action) => apply(action),
        None => Ok(Vec::new()),
    }
}

/// Shows what the presenter moved to; a step of the page's stepper or showing the current
/// route again is the shell's to do.
fn apply(action: PresenterAction) -> Result<Vec<ShellRequest>, JsValue> {
    let mut requests = Vec::new();
    let relay = RELAY.get();
    match action {
        PresenterAction::Stay => {}
        PresenterAction::StepPage => match relay {
            Some(relay) => relay(Relay::StepPage),
            None => requests.push(ShellRequest::StepPage),
        },
        PresenterAction::Show(i) => {
            let step = PRESENTING.with(|p| {
                p.borrow()
                    .as_ref()
                    .and_then(|(l, _)| l.steps.get(i).cloned())
            });
            if let (Some(step), Some(relay)) = (&step, relay) {
                relay(Relay::Show(&step.route, step.focus.as_deref()));
            } else if let Some(LessonStep { route, focus, .. }) = step {
                if let Some(bar) = dom::document()?.get_element_by_id(BAR_ID) {
                    lesson_focus::show(&bar, crate::view::url::parse_hash(&route).page, focus);
                }
                let window = dom::window()?;
                if window.location().hash()? == route {
                    // Same state: re-mount it from the start.
                    requests.push(ShellRequest::Remount);
                } else {
                    // The page shown writes no more of its state to the URL: on the same page
                    // (a step to another state of it) that write would replace the step's.
                    router::set_shown_page("");
                    window.location().set_hash(&route)?;
                }
            }
        }
    }
    render()?;
    Ok(requests)
}

/// A key while presenting, whatever has focus (the shell asks before the page and the focused
/// control): PageDown / → next, PageUp / ← back, B / . black the screen and bring it back, S
/// shares the page, Escape brings the screen back or ends. In a text or number field being
/// edited ← and → (and B, ., S) stay the field's; PageDown / PageUp still go on and back.
/// `None` if not taken, else what the presenter asks of the shell.
pub(crate) fn on_key(event: &KeyboardEvent) -> Result<Option<Vec<ShellRequest>>, JsValue> {
    if crate::ui::kit::keymap::has_command_modifier(event) {
        return Ok(None);
    }
    let typing = crate::ui::kit::keymap::is_text_entry(event.target());
    on_named_key(&event.key(), typing)
}

/// [`on_key`] for the key named `key` (`typing`: a text field being edited has focus); also a
/// key pressed in the room's window of a two-screen presentation.
pub(crate) fn on_named_key(key: &str, typing: bool) -> Result<Option<Vec<ShellRequest>>, JsValue> {
    if !presenting() {
        // The room's window of two: its presenter keys go to the presenter's window.
        return Ok(match RELAY.get() {
            Some(relay) if is_presenter_key(key, typing) => {
                relay(Relay::Key(key));
                Some(Vec::new())
            }
            _ => None,
        });
    }
    let black = blacked_out()?;
    let requests = match key {
        "PageDown" | "PageUp" | "ArrowRight" | "ArrowLeft" | "b" | "B" | "." if black => {
            black_out(false)?;
            Vec::new()
        }
        "PageDown" => press(true)?,
        "PageUp" => press(false)?,
        "ArrowRight" if !typing => press(true)?,
        "ArrowLeft" if !typing => press(false)?,
        "b" | "B" | "." if !typing => {
            black_out(true)?;
            Vec::new()
        }
        "Escape" | "Esc" if black => {
            black_out(false)?;
            Vec::new()
        }
        "Escape" | "Esc" => {
            stop()?;
            Vec::new()
        }
        "s" | "S" if !typing => {
            match RELAY.get() {
                Some(relay) => relay(Relay::Share),
                None => crate::ui::share::open(),
            }
            Vec::new()
        }
        _ => return Ok(None),
    };
    Ok(Some(requests))
}

/// Whether `key` is one of the presenter's keys ([`on_named_key`]).
fn is_presenter_key(key: &str, typing: bool) -> bool {
    match key {
        "PageDown" | "PageUp" | "Escape" | "Esc" => true,
        "ArrowRight" | "ArrowLeft" | "b" | "B" | "." | "s" | "S" => !typing,
        _ => false,
    }
}

/// The black screen's element id (`data-testid="blackout"`).
const BLACKOUT_ID: &str = "lesson-blackout";

/// Whether the screen is blacked out (on two screens: the room's).
pub(crate) fn blacked_out() -> Result<bool, JsValue> {
    if RELAY.get().is_some() {
        return Ok(BLACK.get());
    }
    Ok(dom::document()?
        .get_element_by_id(BLACKOUT_ID)
        .is_some_and(|b| !b.has_attribute("hidden")))
}

/// Blacks the screen out (`on`) or brings it back, as a presentation program's B and . do;
/// on two screens, the room's.
fn black_out(on: bool) -> Result<(), JsValue> {
    match RELAY.get() {
        Some(relay) if presenting() => {
            BLACK.set(on);
            relay(Relay::Black(on));
            relay(Relay::Redraw);
            Ok(())
        }
        _ => cover(on),
    }
}

/// Blacks this window's screen out (`on`) or brings it back.
pub(crate) fn cover(on: bool) -> Result<(), JsValue> {
    let document = dom::document()?;
    let cover = match document.get_element_by_id(BLACKOUT_ID) {
        Some(cover) => cover,
        None if !on => return Ok(()),
        None => {
            let cover = dom::el_class("div", "lesson-blackout")?;
            cover.set_id(BLACKOUT_ID);
            cover.set_attribute("data-testid", "blackout")?;
            cover.set_attribute("aria-hidden", "true")?;
            if let Some(body) = document.body() {
                body.append_child(&cover)?;
            }
            cover
        }
    };
    dom::show(&cover, on);
    Ok(())
}

/// Redraws the bar: progress strip, step title and note, buttons.
pub(crate) fn render() -> Result<(), JsValue> {
    let document = dom::document()?;
    let Some(bar) = document.get_element_by_id(BAR_ID) else {
        return Ok(());
    };
    let state = PRESENTING.with(|p| p.borrow().clone());
    let Some((lesson, presenter)) = state else {
        dom::show(&bar, false);
        return Ok(());
    };
    if let Some(relay) = RELAY.get() {
        // The presenter view stands for the bar.
        dom::show(&bar, false);
        relay(Relay::Redraw);
        return Ok(());
    }
    dom::clear(&bar);
    dom::show(&bar, true);
    bar.set_attribute("data-step", &(presenter.index + 1).to_string())?;
    bar.set_attribute("data-steps", &lesson.steps.len().to_string())?;
    let strip = dom::el_class("ol", "lesson-progress")?;
    strip.set_attribute("data-testid", "lesson-progress")?;
    for (i, step) in lesson.steps.iter().enumerate() {
        let item = dom::el("li")?;
        let dot = dom::el_class("button", "lesson-dot")?;
        dot.set_attribute("type", "button")?;
        dot.set_attribute(
            "aria-label",
            &format!("{} {}: {}", ctx::t("lesson-step"), i + 1, step.title),
        )?;
        if i == presenter.index {
            dot.set_attribute("aria-current", "step")?;
        }
        dot.set_attribute("data-action", "lesson-go")?;
        dot.set_attribute("data-index", &i.to_string())?;
        dom::append(&item, &dot)?;
        dom::append(&strip, &item)?;
    }
    dom::append(&bar, &strip)?;
    if let Some(step) = lesson.steps.get(presenter.index) {
        let text = dom::el_class("div", "lesson-text")?;
        let title = dom::el_text(
            "p",
            "lesson-step-title",
            &format!(
                "{} / {} · {}",
                presenter.index + 1,
                lesson.steps.len(),
                step.title
            ),
        )?;
        title.set_attribute("data-testid", "lesson-step-title")?;
        dom::append(&text, &title)?;
        if !step.note.is_empty() {
            let note = dom::el_text("p", "lesson-note", &step.note)?;
            note.set_attribute("data-testid", "lesson-note")?;
            dom::append(&text, &note)?;
        }
        if step.page_steps > 0 {
            let left = step.page_steps.saturating_sub(presenter.page_steps_done);
            let steps = dom::el_text(
                "p",
                "lesson-page-steps",
                &ctx::t_strings("lesson-page-steps-left", &[("count", left.to_string())]),
            )?;
            dom::append(&text, &steps)?;
        }
        dom::append(&bar, &text)?;
    }
    let buttons = dom::el_class("div", "lesson-buttons")?;
    for action in ["lesson-prev", "lesson-next", "lesson-end"] {
        let b = dom::el_i18n("button", "tool-button", action)?;
        b.set_attribute("type", "button")?;
        b.set_attribute("data-action", action)?;
        dom::append(&buttons, &b)?;
    }
    dom::append(&bar, &buttons)?;
    Ok(())
}
