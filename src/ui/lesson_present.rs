//! Presenting a lesson (a wasm chunk of its own, fetched when presenting starts: no page's
//! first load needs it): full screen, projector styles, a bar at the foot with the step's
//! title and note, a progress strip, and the keys of presenter remotes, whatever has focus
//! (PageDown / → next, PageUp / ← back, a step that asks for it first stepping the page's own
//! stepper; B / . black the screen and bring it back; S shares; Escape ends); each step brings
//! its focus section into view above the bar ([`crate::ui::lesson_focus`]). What presenting
//! needs of the shell (step the page, mount it again, projector mode) is returned as
//! [`ShellRequest`]s for the shell to carry out. The shell reaches this chunk through its
//! `Hooks`. Presenting on two screens ([`crate::ui::present_two`], in this chunk too) walks
//! the lesson here, with a `Relay` that shows each step in the room's window instead of this
//! one.

use std::cell::{Cell, RefCell};

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::{Element, Event};

use crate::ui::kit::exercise_link::{
    EXERCISES_SECTION, PRESENT_EXERCISE_ATTR, PRESENT_EXERCISE_EVENT,
};
use crate::ui::page::ShellRequest;
use crate::ui::{ctx, dom, lesson_focus, router};
use crate::view::embed;
use crate::view::lesson::{Lesson, LessonStep, Presenter, PresenterAction};
use crate::view::lesson_goal::{self, GoalCondition, GoalOp};

const BAR_ID: &str = "lesson-bar";

thread_local! {
    static PRESENTING: RefCell<Option<(Lesson, Presenter)>> = const { RefCell::new(None) };
    /// Set while a lesson is presented on two screens, in both windows.
    static RELAY: Cell<Option<fn(Relay)>> = const { Cell::new(None) };
    /// Whether the room's screen is black (the presenter's window of two).
    static BLACK: Cell<bool> = const { Cell::new(false) };
}

/// What a request to the shell does (the shell's `perform`).
pub(crate) type Perform = fn(ShellRequest) -> Result<(), JsValue>;

/// What a presenter key asks of the shell: `None` if the key is not taken.
pub(crate) type KeyTaken = Result<Option<Vec<ShellRequest>>, JsValue>;

/// What the shell calls in this chunk once it is here.
#[derive(Clone, Copy)]
pub(crate) struct Hooks {
    /// A key, named, and whether a text field being edited has focus: `None` if not taken.
    pub on_key: fn(&str, bool) -> KeyTaken,
    /// A click in the presenter bar.
    pub on_bar_click: fn(&Event) -> Result<Vec<ShellRequest>, JsValue>,
    /// Redraws the bar (a page mounted, the language switched).
    pub render: fn() -> Result<(), JsValue>,
}

/// The shell's hooks into this chunk.
pub(crate) const HOOKS: Hooks = Hooks {
    on_key: on_named_key,
    on_bar_click,
    render,
};

/// What a two-screen presentation does in place of this window's page and bar: in the
/// presenter's window every step is shown in the room's window and the presenter view is
/// redrawn; in the room's window its presenter keys go to the presenter's.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Relay<'a> {
    /// Show this route (a lesson step) in the room's window, with its focus section and its
    /// exercise.
    Show(&'a str, Option<&'a str>, Option<&'a str>),
    /// Reveal this exercise's answer in the room's window.
    Reveal(&'a str),
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
pub(crate) fn present(lesson: Lesson, index: usize) -> Result<Vec<ShellRequest>, JsValue> {
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
    check_goals_live(false)?;
    lesson_focus::stop();
    set_presented_exercise(None)?;
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
        PresenterAction::RevealExercise => {
            let exercise = PRESENTING.with(|p| {
                p.borrow()
                    .as_ref()
                    .and_then(|(l, pr)| l.steps.get(pr.index)?.exercise.clone())
            });
            if let Some(exercise) = exercise {
                match relay {
                    Some(relay) => relay(Relay::Reveal(&exercise)),
                    // Nothing to reveal (a goal, an answer on screen): "next" goes on.
                    None if !reveal_exercise(&exercise)? => return press(true),
                    None => {}
                }
            }
        }
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
                relay(Relay::Show(
                    &step.route,
                    step.focus.as_deref(),
                    step.exercise.as_deref(),
                ));
            } else if let Some(LessonStep {
                route,
                focus,
                exercise,
                ..
            }) = step
            {
                set_presented_exercise(exercise.as_deref())?;
                if let Some(bar) = dom::document()?.get_element_by_id(BAR_ID) {
                    let page = crate::view::url::parse_hash(&route).page;
                    lesson_focus::show(&bar, page, focus_of(focus, exercise.as_deref()));
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

/// What a step brings into view: its exercise's card when it has an exercise, else its focus
/// section.
pub(crate) fn focus_of(focus: Option<String>, exercise: Option<&str>) -> Option<String> {
    match exercise {
        Some(_) => Some(EXERCISES_SECTION.to_owned()),
        None => focus,
    }
}

/// Marks `exercise` as the one presented (its answer hidden until revealed, its card brought
/// into view: [`PRESENT_EXERCISE_ATTR`] on the document element), or none, and tells the
/// page's exercises list ([`PRESENT_EXERCISE_EVENT`]).
pub(crate) fn set_presented_exercise(exercise: Option<&str>) -> Result<(), JsValue> {
    let document = dom::document()?;
    let Some(root) = document.document_element() else {
        return Ok(());
    };
    match exercise {
        Some(id) => root.set_attribute(PRESENT_EXERCISE_ATTR, id)?,
        None => root.remove_attribute(PRESENT_EXERCISE_ATTR)?,
    }
    dom::window()?.dispatch_event(&Event::new(PRESENT_EXERCISE_EVENT)?)?;
    Ok(())
}

/// Reveals exercise `id`'s answer on its card ("Show the answer") and brings the card into
/// view again; whether there was one to reveal (not for a goal, nor for an answer already
/// shown, nor before the list is here).
pub(crate) fn reveal_exercise(id: &str) -> Result<bool, JsValue> {
    let selector = format!("#app-main [data-exercise=\"{id}\"] [data-action=\"reveal\"]");
    let button = dom::document()?
        .query_selector(&selector)?
        .and_then(|b| b.dyn_into::<web_sys::HtmlElement>().ok());
    match button {
        Some(button) if !button.hidden() => {
            button.click();
            // The card has grown by its answer: brought into view again, whole.
            if let Some(bar) = dom::document()?.get_element_by_id(BAR_ID) {
                let page = router::current_route().page;
                lesson_focus::show(&bar, page, Some(EXERCISES_SECTION.to_owned()));
            }
            Ok(true)
        }
        _ => Ok(false),
    }
}

/// The teacher's goal of the shown step (`data-testid="lesson-goals"`): each condition
/// (`data-goal="<n>"`, `data-goal-met`), checked live on the page's readouts ([`draw_goals`]).
fn goals_list(page: &str, goals: &[GoalCondition]) -> Result<Element, JsValue> {
    let list = dom::el_class("ul", "lesson-goals")?;
    list.set_attribute("data-testid", "lesson-goals")?;
    list.set_attribute("aria-label", &ctx::t("lesson-goals-label"))?;
    for (j, goal) in goals.iter().enumerate() {
        let item = dom::el("li")?;
        item.set_attribute("data-goal", &(j + 1).to_string())?;
        let unit = lesson_goal::unit_of(page, &goal.readout);
        let mut args = vec![
            ("readout", goal.readout.clone()),
            ("value", lesson_goal::number_text(goal.value)),
            ("unit", unit.to_owned()),
        ];
        let id = match goal.op {
            GoalOp::Below => "lesson-goal-below",
            GoalOp::Above => "lesson-goal-above",
            GoalOp::Within => {
                let tolerance = goal.tolerance.unwrap_or(0.0);
                args.push(("tolerance", lesson_goal::number_text(tolerance)));
                "lesson-goal-within"
            }
        };
        dom::append(
            &item,
            &dom::el_text("span", "lesson-goal-text", &ctx::t_strings(id, &args))?,
        )?;
        dom::append(&item, &dom::el_class("span", "lesson-goal-state")?)?;
        dom::append(&list, &item)?;
    }
    Ok(list)
}

/// A repeating check: its interval's handle and its callback.
type Interval = (i32, Closure<dyn FnMut()>);

thread_local! {
    /// The live check of the shown step's goal.
    static GOALS_CHECK: RefCell<Option<Interval>> = const { RefCell::new(None) };
}

/// How often the shown step's goal is checked, ms.
const GOALS_CHECK_MS: i32 = 250;

/// Checks the shown step's goal now and every [`GOALS_CHECK_MS`] (`on`), or no more.
fn check_goals_live(on: bool) -> Result<(), JsValue> {
    let window = dom::window()?;
    if let Some((id, _)) = GOALS_CHECK.take() {
        window.clear_interval_with_handle(id);
    }
    if on {
        draw_goals()?;
        let callback = Closure::<dyn FnMut()>::new(|| {
            if let Err(error) = draw_goals() {
                web_sys::console::error_2(&"BSV Playground: lesson goal".into(), &error);
            }
        });
        let id = window.set_interval_with_callback_and_timeout_and_arguments_0(
            callback.as_ref().unchecked_ref(),
            GOALS_CHECK_MS,
        )?;
        GOALS_CHECK.set(Some((id, callback)));
    }
    Ok(())
}

/// Marks each condition of the shown step's goal met or not on the numbers its page shows
/// now (none while another page is shown), and the goal met when all are.
fn draw_goals() -> Result<(), JsValue> {
    let document = dom::document()?;
    let Some(list) = document.query_selector("[data-testid=\"lesson-goals\"]")? else {
        return Ok(());
    };
    // The shown step's page and goal only: this runs every tick.
    let shown = PRESENTING.with(|p| {
        let p = p.borrow();
        let (lesson, presenter) = p.as_ref()?;
        let step = lesson.steps.get(presenter.index)?;
        Some((step.page(), step.goals.clone()))
    });
    let Some((page, goals)) = shown else {
        return Ok(());
    };
    let on_page = router::current_route().page == page;
    let mut all = true;
    for (j, goal) in goals.iter().enumerate() {
        let reading = on_page
            .then(|| readout_value(&document, &goal.readout))
            .flatten();
        let met = goal.met(reading);
        all &= met;
        let selector = format!("[data-goal=\"{}\"]", j + 1);
        if let Some(item) = list.query_selector(&selector)? {
            let word = if met { "true" } else { "false" };
            if item.get_attribute("data-goal-met").as_deref() != Some(word) {
                item.set_attribute("data-goal-met", word)?;
                if let Some(state) = item.query_selector(".lesson-goal-state")? {
                    let id = if met {
                        "lesson-goal-met"
                    } else {
                        "lesson-goal-open"
                    };
                    state.set_text_content(Some(&ctx::t(id)));
                }
            }
        }
    }
    list.set_attribute("data-goals-met", if all { "true" } else { "false" })
}

/// The number readout `key` of the page shows, read as the embedding API reads readouts.
fn readout_value(document: &web_sys::Document, key: &str) -> Option<f64> {
    let selector = format!("#app-main [data-readout=\"{key}\"]");
    let readout = document.query_selector(&selector).ok()??;
    let text = readout.text_content().unwrap_or_default();
    embed::readout_number(readout.get_attribute("data-value").as_deref(), &text)
}

/// A key while presenting, whatever has focus (the shell asks before the page and the focused
/// control): PageDown / → next, PageUp / ← back, B / . black the screen and bring it back, S
/// shares the page, Escape brings the screen back or ends. In a text or number field being
/// edited ← and → (and B, ., S) stay the field's; PageDown / PageUp still go on and back.
/// The key is named `key` (`typing`: a text field being edited has focus); also a key pressed
/// in the room's window of a two-screen presentation. `None` if not taken, else what the
/// presenter asks of the shell.
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

/// Step `index`'s heading: its place in the lesson and its title (`2 / 4 · Title`).
pub(crate) fn step_heading(lesson: &Lesson, index: usize) -> String {
    let title = lesson.steps.get(index).map_or("", |s| s.title.as_str());
    format!("{} / {} · {}", index + 1, lesson.steps.len(), title)
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
            &step_heading(&lesson, presenter.index),
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
        if !step.goals.is_empty() {
            dom::append(&text, &goals_list(&step.page(), &step.goals)?)?;
        }
        dom::append(&bar, &text)?;
    }
    let has_goals = lesson
        .steps
        .get(presenter.index)
        .is_some_and(|s| !s.goals.is_empty());
    check_goals_live(has_goals)?;
    let buttons = dom::el_class("div", "lesson-buttons")?;
    for action in ["lesson-prev", "lesson-next", "lesson-end"] {
        dom::append(&buttons, &dom::action_button(action, action)?)?;
    }
    dom::append(&bar, &buttons)?;
    Ok(())
}
