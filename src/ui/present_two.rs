//! Presenting a lesson on two screens: "Present on two screens" opens the room's window (the
//! page, projector styles, no notes; the teacher moves it to the projector, where a click or a
//! key makes it full screen) and turns this window into the presenter view: this step's note,
//! the next step's title and a live picture of it, the step list and the elapsed time. The
//! lesson is walked in this window ([`crate::ui::lesson_present`] with a `Relay`); the two windows keep in
//! step over a `BroadcastChannel` (same origin, works offline): each step is shown in the
//! room's window, and keys pressed there come here. Closing either window, or Escape in either,
//! ends the presentation in both. In the presenting chunk, fetched on first use.

use std::cell::{Cell, RefCell};

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::{BroadcastChannel, Element, Event, MessageEvent, Window};

use crate::i18n::Lang;
use crate::ui::lesson_present::{self, Hooks, Perform, Relay};
use crate::ui::page::ShellRequest;
use crate::ui::{ctx, dom, lesson_focus, router, schedule};
use crate::view::lesson::Lesson;
use crate::view::url;

/// The channel both windows of a presentation share.
const CHANNEL: &str = "bsv-present";
/// The name of the room's window (`window.name`, kept across its reloads).
pub(crate) const AUDIENCE_NAME: &str = "bsv-audience";
/// The presenter view's element id (`data-testid="presenter-window"`).
const VIEW_ID: &str = "presenter-window";
/// How long the room's window waits for the presenter's answer before it is a plain window
/// again (its presenter's window was closed while it reloaded).
const ANSWER_WAIT_MS: i32 = 3000;

/// The presenter's window of a presentation.
struct PresenterSide {
    channel: BroadcastChannel,
    audience: Window,
    started_ms: f64,
    perform: Perform,
    /// The route the picture of the next step shows.
    picture: RefCell<String>,
    _listeners: Vec<dom::Listener>,
    ticker: Option<Ticker>,
}

/// The room's window of a presentation.
struct AudienceSide {
    channel: BroadcastChannel,
    perform: Perform,
    answered: Cell<bool>,
    _listeners: Vec<dom::Listener>,
}

enum Side {
    Presenter(PresenterSide),
    Audience(AudienceSide),
}

thread_local! {
    static SIDE: RefCell<Option<Side>> = const { RefCell::new(None) };
}

/// A `setInterval` that is cleared when dropped.
struct Ticker {
    id: i32,
    _tick: Closure<dyn FnMut()>,
}

impl Ticker {
    fn every(ms: i32, tick: impl FnMut() + 'static) -> Result<Ticker, JsValue> {
        let tick = Closure::<dyn FnMut()>::new(tick);
        let id = dom::window()?.set_interval_with_callback_and_timeout_and_arguments_0(
            tick.as_ref().unchecked_ref(),
            ms,
        )?;
        Ok(Ticker { id, _tick: tick })
    }
}

impl Drop for Ticker {
    fn drop(&mut self) {
        if let Some(window) = web_sys::window() {
            window.clear_interval_with_handle(self.id);
        }
    }
}

/// The presenting chunk's entry points (this module and [`crate::ui::lesson_present`]).
#[derive(Clone, Copy)]
pub(crate) struct PresentEntry {
    /// Presents a lesson from step `index` in this window: what the shell should do first.
    pub present: fn(Lesson, usize) -> Result<Vec<ShellRequest>, JsValue>,
    /// Opens the room's window and presents a lesson on two screens; `Err` is the localized
    /// reason it could not.
    pub start_two: fn(Lesson, Perform) -> Result<(), String>,
    /// This window is the room's window of a presentation: joins it.
    pub join: fn(Perform) -> Result<(), JsValue>,
    /// What the shell calls while presenting.
    pub hooks: Hooks,
}

/// The presenting chunk's entry points.
pub(crate) const ENTRY: PresentEntry = PresentEntry {
    present: lesson_present::present,
    start_two: start,
    join,
    hooks: lesson_present::HOOKS,
};

/// Opens the room's window and presents `lesson` from its first step; `Err` is the localized
/// reason it could not (the browser blocked the window).
fn start(lesson: Lesson, perform: Perform) -> Result<(), String> {
    let blocked = || ctx::t("present-two-blocked");
    let Some(first) = lesson.steps.first() else {
        return Ok(());
    };
    let window = dom::window().map_err(|_| blocked())?;
    if lesson_present::presenting() {
        lesson_present::stop().map_err(|_| blocked())?;
    }
    // The room's window speaks the presenter's language.
    let url = format!(
        "{}{}",
        page_base(&window),
        with_shell_keys(&first.route, false, Some(ctx::lang()))
    );
    let audience = window
        .open_with_url_and_target_and_features(&url, AUDIENCE_NAME, "popup,width=1280,height=800")
        .ok()
        .flatten()
        .ok_or_else(blocked)?;
    open_presenter(lesson, audience, perform).map_err(|_| blocked())
}

/// `route` as the app writes its links, with the shell's keys it should carry (`embed=1`,
/// `lang`) in place of any it had.
fn with_shell_keys(route: &str, embedded: bool, lang: Option<Lang>) -> String {
    let parsed = url::parse_hash(route);
    url::build_hash(
        &parsed.page,
        &url::with_shell_keys(&parsed.query, embedded, lang),
    )
}

/// The address of this app without its route.
fn page_base(window: &Window) -> String {
    let href = window.location().href().unwrap_or_default();
    href.split('#').next().unwrap_or_default().to_owned()
}

/// Hands each message of `channel` to `handle`, reporting what fails.
fn on_messages(
    channel: &BroadcastChannel,
    handle: fn(&JsValue) -> Result<(), JsValue>,
) -> Result<dom::Listener, JsValue> {
    dom::Listener::new(channel, "message", move |event| {
        if let Some(message) = event.dyn_ref::<MessageEvent>() {
            report(handle(&message.data()));
        }
    })
}

fn open_presenter(lesson: Lesson, audience: Window, perform: Perform) -> Result<(), JsValue> {
    let channel = BroadcastChannel::new(CHANNEL)?;
    let window = dom::window()?;
    let listeners = vec![
        on_messages(&channel, on_presenter_message)?,
        // Closing or reloading this window ends the presentation in the room's too.
        dom::Listener::new(&window, "pagehide", |_| report(lesson_present::stop()))?,
    ];
    let view = build_view()?;
    reveal_when_styled(&view)?;
    dom::document()?
        .body()
        .ok_or_else(|| JsValue::from_str("no body"))?
        .append_child(&view)?;
    SIDE.with_borrow_mut(|side| {
        *side = Some(Side::Presenter(PresenterSide {
            channel,
            audience,
            started_ms: schedule::now_ms(),
            perform,
            picture: RefCell::new(String::new()),
            _listeners: listeners,
            ticker: None,
        }));
    });
    // Every second: the elapsed time, and whether the room's window was closed.
    let ticker = Ticker::every(1000, || report(tick()))?;
    SIDE.with_borrow_mut(|side| {
        if let Some(Side::Presenter(p)) = side {
            p.ticker = Some(ticker);
        }
    });
    lesson_present::set_relay(Some(presenter_relay));
    lesson_present::present_on_two(lesson, 0)
}

/// What the lesson walk asks of the presenter's window.
fn presenter_relay(relay: Relay) {
    let sent = match relay {
        Relay::Show(route, focus, exercise) => post(&[
            ("kind", "show".into()),
            ("route", route.into()),
            ("focus", focus.map_or(JsValue::NULL, JsValue::from_str)),
            (
                "exercise",
                exercise.map_or(JsValue::NULL, JsValue::from_str),
            ),
            ("lang", ctx::lang().code().into()),
        ]),
        Relay::Reveal(exercise) => {
            post(&[("kind", "reveal".into()), ("exercise", exercise.into())])
        }
        Relay::StepPage => post(&[("kind", "step".into())]),
        Relay::Black(on) => post(&[("kind", "black".into()), ("on", on.into())]),
        Relay::Share => post(&[("kind", "share".into())]),
        Relay::Redraw => render(),
        Relay::Key(_) => Ok(()),
        Relay::End => end_presenter(),
    };
    report(sent);
}

/// Posts a message of fields `fields` on this window's channel.
fn post(fields: &[(&str, JsValue)]) -> Result<(), JsValue> {
    let message = js_sys::Object::new();
    for (name, value) in fields {
        js_sys::Reflect::set(&message, &JsValue::from_str(name), value)?;
    }
    SIDE.with_borrow(|side| match side {
        Some(Side::Presenter(p)) => p.channel.post_message(&message),
        Some(Side::Audience(a)) => a.channel.post_message(&message),
        None => Ok(()),
    })
}

/// The text field `name` of a message, if it has one.
fn field(data: &JsValue, name: &str) -> Option<String> {
    js_sys::Reflect::get(data, &JsValue::from_str(name))
        .ok()?
        .as_string()
}

fn on_presenter_message(data: &JsValue) -> Result<(), JsValue> {
    match field(data, "kind").as_deref() {
        // The room's window (re)opened: what it should show.
        Some("hello") => {
            let step = lesson_present::current()
                .and_then(|(lesson, p)| lesson.steps.get(p.index).cloned());
            if let Some(step) = step {
                presenter_relay(Relay::Show(
                    &step.route,
                    step.focus.as_deref(),
                    step.exercise.as_deref(),
                ));
            }
            if lesson_present::blacked_out()? {
                post(&[("kind", "black".into()), ("on", true.into())])?;
            }
            Ok(())
        }
        Some("key") => {
            let Some(key) = field(data, "key") else {
                return Ok(());
            };
            let requests = lesson_present::on_named_key(&key, false)?.unwrap_or_default();
            let perform = SIDE.with_borrow(|side| match side {
                Some(Side::Presenter(p)) => Some(p.perform),
                _ => None,
            });
            match perform {
                Some(perform) => requests.into_iter().try_for_each(perform),
                None => Ok(()),
            }
        }
        Some("end") => lesson_present::stop(),
        _ => Ok(()),
    }
}

/// The elapsed time, and the end of the presentation if the room's window was closed.
fn tick() -> Result<(), JsValue> {
    let state = SIDE.with_borrow(|side| match side {
        Some(Side::Presenter(p)) => Some((p.audience.closed().unwrap_or(true), p.started_ms)),
        _ => None,
    });
    let Some((closed, started_ms)) = state else {
        return Ok(());
    };
    if closed {
        return lesson_present::stop();
    }
    if let Some(clock) = dom::document()?.get_element_by_id("presenter-elapsed") {
        clock.set_text_content(Some(&elapsed_text(schedule::now_ms() - started_ms)));
    }
    Ok(())
}

/// `m:ss`, or `h:mm:ss` from an hour on.
fn elapsed_text(ms: f64) -> String {
    let s = (ms.max(0.0) / 1000.0) as u64;
    let (h, m, s) = (s / 3600, s / 60 % 60, s % 60);
    if h > 0 {
        format!("{h}:{m:02}:{s:02}")
    } else {
        format!("{m}:{s:02}")
    }
}

/// The presentation ended: the room's window is told and closed, the presenter view goes.
fn end_presenter() -> Result<(), JsValue> {
    post(&[("kind", "end".into())])?;
    let side = SIDE.with_borrow_mut(Option::take);
    if let Some(Side::Presenter(p)) = &side {
        let _ = p.audience.close();
    }
    // Dropped after this task: one of its listeners may be the caller.
    wasm_bindgen_futures::spawn_local(async move { drop(side) });
    if let Some(view) = dom::document()?.get_element_by_id(VIEW_ID) {
        view.remove();
    }
    Ok(())
}

/// The presenter view's stylesheet (`www/present_two.css`, from `present_two.late.css`): in no
/// page's first load, linked on first use.
const SHEET_ID: &str = "present-two-css";

/// Links the presenter view's stylesheet if it is not yet; `view` stays hidden until it has
/// loaded (or failed to: the view then shows unstyled, still working).
fn reveal_when_styled(view: &Element) -> Result<(), JsValue> {
    let document = dom::document()?;
    if document.get_element_by_id(SHEET_ID).is_some() {
        return Ok(());
    }
    let link = dom::el("link")?;
    link.set_id(SHEET_ID);
    link.set_attribute("rel", "stylesheet")?;
    link.set_attribute("href", "www/present_two.css")?;
    dom::show(view, false);
    for event in ["load", "error"] {
        dom::Listener::new(&link, event, |_| {
            if let Some(view) = dom::document()
                .ok()
                .and_then(|d| d.get_element_by_id(VIEW_ID))
            {
                dom::show(&view, true);
            }
        })?
        .forever();
    }
    document
        .query_selector("head")?
        .ok_or_else(|| JsValue::from_str("no head"))?
        .append_child(&link)?;
    Ok(())
}

/// The presenter view's frame, filled by [`render`].
fn build_view() -> Result<Element, JsValue> {
    let view = dom::el_class("section", "presenter-window")?;
    view.set_id(VIEW_ID);
    view.set_attribute("data-testid", "presenter-window")?;
    dom::set_i18n_attrs(&view, &[("aria-label", "present-two-label")])?;
    dom::Listener::new(&view, "click", |event: Event| {
        let perform = SIDE.with_borrow(|side| match side {
            Some(Side::Presenter(p)) => Some(p.perform),
            _ => None,
        });
        if let Some(perform) = perform {
            report(
                lesson_present::on_bar_click(&event)
                    .and_then(|requests| requests.into_iter().try_for_each(perform)),
            );
        }
    })?
    .forever();
    Ok(view)
}

/// Redraws the presenter view: the lesson's title and the elapsed time, this step's title and
/// note, the next step's title and picture, the step list and the buttons.
fn render() -> Result<(), JsValue> {
    let document = dom::document()?;
    let (Some(view), Some((lesson, presenter))) = (
        document.get_element_by_id(VIEW_ID),
        lesson_present::current(),
    ) else {
        return Ok(());
    };
    let started_ms = SIDE.with_borrow(|side| match side {
        Some(Side::Presenter(p)) => p.started_ms,
        _ => schedule::now_ms(),
    });
    let black = lesson_present::blacked_out()?;
    let picture = document
        .get_element_by_id("presenter-picture")
        .filter(|p| p.parent_element().is_some());
    // The picture's frame is kept across redraws: it reloads only when its route changes.
    if let Some(picture) = &picture {
        picture.remove();
    }
    dom::clear(&view);
    view.set_attribute("data-step", &(presenter.index + 1).to_string())?;
    view.set_attribute("data-steps", &lesson.steps.len().to_string())?;

    let head = dom::el_class("header", "presenter-head")?;
    dom::append(
        &head,
        &dom::el_text("h1", "presenter-title", &lesson.title)?,
    )?;
    let clock = dom::el_text(
        "p",
        "presenter-elapsed",
        &elapsed_text(schedule::now_ms() - started_ms),
    )?;
    clock.set_id("presenter-elapsed");
    clock.set_attribute("data-testid", "presenter-elapsed")?;
    dom::set_i18n_attrs(&clock, &[("title", "present-two-elapsed")])?;
    dom::append(&head, &clock)?;
    dom::append(&view, &head)?;

    let now = dom::el_class("div", "presenter-now")?;
    if let Some(step) = lesson.steps.get(presenter.index) {
        dom::append(
            &now,
            &dom::el_i18n("p", "presenter-label", "present-two-now")?,
        )?;
        let title = dom::el_text(
            "h2",
            "presenter-step-title",
            &lesson_present::step_heading(&lesson, presenter.index),
        )?;
        title.set_attribute("data-testid", "presenter-step-title")?;
        dom::append(&now, &title)?;
        let note = dom::el_text("p", "presenter-note", &step.note)?;
        note.set_attribute("data-testid", "presenter-note")?;
        dom::append(&now, &note)?;
        if step.page_steps > 0 {
            let left = step.page_steps.saturating_sub(presenter.page_steps_done);
            dom::append(
                &now,
                &dom::el_text(
                    "p",
                    "presenter-page-steps",
                    &ctx::t_strings("lesson-page-steps-left", &[("count", left.to_string())]),
                )?,
            )?;
        }
    }
    if black {
        let status = dom::el_i18n("p", "presenter-black", "present-two-blacked")?;
        status.set_attribute("role", "status")?;
        dom::append(&now, &status)?;
    }
    dom::append(&view, &now)?;

    let next = dom::el_class("div", "presenter-next")?;
    dom::append(
        &next,
        &dom::el_i18n("p", "presenter-label", "present-two-next")?,
    )?;
    match lesson.steps.get(presenter.index + 1) {
        Some(step) => {
            let title = dom::el_text(
                "h2",
                "presenter-step-title",
                &format!("{} · {}", presenter.index + 2, step.title),
            )?;
            title.set_attribute("data-testid", "presenter-next-title")?;
            dom::append(&next, &title)?;
            let picture = match picture {
                Some(picture) => picture,
                None => build_picture()?,
            };
            dom::append(&next, &picture)?;
            show_in_picture(&picture, &step.route, &step.title)?;
        }
        None => {
            let last = dom::el_i18n("h2", "presenter-step-title", "present-two-last")?;
            last.set_attribute("data-testid", "presenter-next-title")?;
            dom::append(&next, &last)?;
        }
    }
    dom::append(&view, &next)?;

    let list = dom::el_class("ol", "presenter-steps")?;
    list.set_attribute("data-testid", "presenter-steps")?;
    for (i, step) in lesson.steps.iter().enumerate() {
        let item = dom::el("li")?;
        let go = dom::el_text("button", "presenter-go", &step.title)?;
        go.set_attribute("type", "button")?;
        go.set_attribute("data-action", "lesson-go")?;
        go.set_attribute("data-index", &i.to_string())?;
        if i == presenter.index {
            go.set_attribute("aria-current", "step")?;
        }
        dom::append(&item, &go)?;
        dom::append(&list, &item)?;
    }
    dom::append(&view, &list)?;

    let buttons = dom::el_class("div", "presenter-buttons")?;
    for (action, label) in [
        ("lesson-prev", "lesson-prev"),
        ("lesson-next", "lesson-next"),
        (
            "lesson-black",
            if black {
                "present-two-unblack"
            } else {
                "present-two-black"
            },
        ),
        ("lesson-end", "lesson-end"),
    ] {
        dom::append(&buttons, &dom::action_button(action, label)?)?;
    }
    dom::append(&view, &buttons)?;
    Ok(())
}

/// The next step's picture: the step's page itself, embedded, shrunk and out of reach of the
/// keyboard and the pointer.
fn build_picture() -> Result<Element, JsValue> {
    let wrap = dom::el_class("div", "presenter-picture")?;
    wrap.set_id("presenter-picture");
    wrap.set_attribute("inert", "")?;
    let frame = dom::el("iframe")?;
    frame.set_attribute("tabindex", "-1")?;
    dom::append(&wrap, &frame)?;
    Ok(wrap)
}

/// Points the picture at `route` (reloaded only when it changes).
fn show_in_picture(picture: &Element, route: &str, title: &str) -> Result<(), JsValue> {
    let Some(frame) = picture.first_element_child() else {
        return Ok(());
    };
    frame.set_attribute(
        "title",
        &ctx::t_strings("present-two-picture", &[("title", title.to_owned())]),
    )?;
    let embedded = with_shell_keys(route, true, None);
    let changed = SIDE.with_borrow(|side| match side {
        Some(Side::Presenter(p)) if *p.picture.borrow() != embedded => {
            *p.picture.borrow_mut() = embedded.clone();
            true
        }
        _ => false,
    });
    if changed || !frame.has_attribute("src") {
        let window = dom::window()?;
        frame.set_attribute("src", &format!("{}{embedded}", page_base(&window)))?;
    }
    Ok(())
}

/// Joins the presentation as the room's window: projector styles, presenter keys sent to the
/// presenter's window, each step shown as it says; full screen at the first click or key.
fn join(perform: Perform) -> Result<(), JsValue> {
    let channel = BroadcastChannel::new(CHANNEL)?;
    let window = dom::window()?;
    let listeners = vec![
        on_messages(&channel, on_audience_message)?,
        dom::Listener::capture(&window, "pointerdown", |_| full_screen())?,
        dom::Listener::capture(&window, "keydown", |_| full_screen())?,
    ];
    if let Some(body) = dom::document()?.body() {
        body.set_attribute("data-testid", "audience")?;
    }
    SIDE.with_borrow_mut(|side| {
        *side = Some(Side::Audience(AudienceSide {
            channel,
            perform,
            answered: Cell::new(false),
            _listeners: listeners,
        }));
    });
    lesson_present::set_relay(Some(audience_relay));
    perform(ShellRequest::ProjectorHere)?;
    post(&[("kind", "hello".into())])?;
    // No answer: the presenter's window is gone; this is a plain window again.
    let wait = Closure::once_into_js(|| {
        let answered = SIDE.with_borrow(|side| match side {
            Some(Side::Audience(a)) => a.answered.get(),
            _ => true,
        });
        if !answered {
            report(leave_audience(false));
        }
    });
    window.set_timeout_with_callback_and_timeout_and_arguments_0(
        wait.unchecked_ref(),
        ANSWER_WAIT_MS,
    )?;
    Ok(())
}

/// What the lesson walk asks of the room's window: only its keys, sent on.
fn audience_relay(relay: Relay) {
    if let Relay::Key(key) = relay {
        report(post(&[("kind", "key".into()), ("key", key.into())]));
    }
}

/// Full screen at the first gesture in the room's window (a browser needs one).
fn full_screen() {
    let Ok(document) = dom::document() else {
        return;
    };
    if document.fullscreen_element().is_none() {
        if let Some(root) = document.document_element() {
            let _ = root.request_fullscreen();
        }
    }
}

fn on_audience_message(data: &JsValue) -> Result<(), JsValue> {
    let Some(perform) = SIDE.with_borrow(|side| match side {
        Some(Side::Audience(a)) => Some(a.perform),
        _ => None,
    }) else {
        return Ok(());
    };
    match field(data, "kind").as_deref() {
        Some("show") => {
            let Some(route) = field(data, "route") else {
                return Ok(());
            };
            let first = SIDE.with_borrow(|side| match side {
                Some(Side::Audience(a)) => !a.answered.replace(true),
                _ => false,
            });
            if let Some(lang) = field(data, "lang").as_deref().and_then(Lang::parse) {
                if lang != ctx::lang() {
                    perform(ShellRequest::Lang(lang))?;
                }
            }
            let document = dom::document()?;
            let exercise = field(data, "exercise");
            lesson_present::set_presented_exercise(exercise.as_deref())?;
            if let Some(bar) = document.get_element_by_id("lesson-bar") {
                // Its focus section (or exercise) in view, as in one window.
                let page = url::parse_hash(&route).page;
                let focus = lesson_present::focus_of(field(data, "focus"), exercise.as_deref());
                lesson_focus::show(&bar, page, focus);
            }
            let location = dom::window()?.location();
            if !same_route(&location.hash()?, &route) {
                // The page shown writes no more of its state to the URL (see lesson_bar).
                router::set_shown_page("");
                location.set_hash(&route)?;
            } else if !first {
                // The same step again: its page state from the start.
                perform(ShellRequest::Remount)?;
            }
            Ok(())
        }
        Some("step") => perform(ShellRequest::StepPage),
        Some("reveal") => {
            if let Some(exercise) = field(data, "exercise") {
                lesson_present::reveal_exercise(&exercise)?;
            }
            Ok(())
        }
        Some("black") => {
            let on = js_sys::Reflect::get(data, &JsValue::from_str("on"))?.is_truthy();
            lesson_present::cover(on)
        }
        Some("share") => {
            crate::ui::share::open();
            Ok(())
        }
        Some("end") => {
            lesson_focus::stop();
            lesson_present::set_presented_exercise(None)?;
            leave_audience(true)
        }
        _ => Ok(()),
    }
}

/// Whether the address's route `hash` is `route`, whatever shell keys (the language the room's
/// window was opened with) either carries.
fn same_route(hash: &str, route: &str) -> bool {
    let (shown, asked) = (url::parse_hash(hash), url::parse_hash(route));
    shown.page == asked.page && shown.page_query() == asked.page_query()
}

/// This window is no longer the room's: projector styles off, and closed if `close` (a window
/// a script opened closes when asked).
fn leave_audience(close: bool) -> Result<(), JsValue> {
    lesson_present::set_relay(None);
    lesson_present::cover(false)?;
    let side = SIDE.with_borrow_mut(Option::take);
    wasm_bindgen_futures::spawn_local(async move { drop(side) });
    let window = dom::window()?;
    window.set_name("")?;
    if let Some(body) = dom::document()?.body() {
        body.remove_attribute("data-testid")?;
    }
    if close {
        window.close()?;
    }
    Ok(())
}

/// Logs an error of a handler (the shell's way: nothing is thrown at the browser).
fn report(result: Result<(), JsValue>) {
    if let Err(error) = result {
        web_sys::console::error_1(&error);
    }
}
