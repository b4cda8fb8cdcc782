//! An embedded page's postMessage API and frame (the wasm chunk `embed_api`, fetched on the
//! first message or when the tab is embedded; [`crate::ui::embed`] is its door). The
//! protocol, its replies and their checks are [`crate::view::embed`]; this file carries them.
//!
//! - Requests are answered in the order they came, once the page is settled: `getState` (the
//!   page's query), `setState` (the query changed and the page mounted again from it: it reads
//!   the new state as it reads a link; keys it does not take keep their last good value and
//!   are named in an error reply), `getReadouts` (every `[data-readout]` of the page: its
//!   `data-value`, else the number its text starts with, and its unit), `step(n)` and `reset`
//!   (the page's stepper: its scrub slider, else its buttons).
//! - Events go to the parent window of an embedded tab: `ready` once its first page is
//!   settled, `statechange` once the page's state has rested for [`STATE_REST_MS`] (not for a
//!   host's own `setState`), `readouts` when they changed, at most every [`READOUTS_GAP_MS`].
//! - The frame: "Open in BSV Playground ↗" (`data-testid="embed-open"`, a new tab, the same
//!   route and state without `embed=1`); the page's main view (the box of its first canvas)
//!   sized to fill the frame below what stands above it; wheel turns over a canvas that is
//!   being used (pressed since the pointer came into the frame) do not scroll the frame or the
//!   host, and then neither do touches (`html.embed-in-use`).

use std::cell::{Cell, RefCell};
use std::collections::VecDeque;
use std::rc::Rc;

use serde_json::Value;
use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::{Element, HtmlElement, HtmlInputElement, MessageEvent};

use crate::ui::kit::url_state;
use crate::ui::schedule::{now_ms, Timer};
use crate::ui::{dom, router};
use crate::view::embed::{self as protocol, Message, Method, Request};
use crate::view::url::{build_hash, IgnoredKey, EMBED_KEY};

/// What the API's chunk gives the shell.
#[derive(Clone, Copy)]
pub(crate) struct ApiFns {
    /// Sets the API up (once, when its chunk has come) with what the shell lends it.
    pub start: fn(ShellFns),
    /// Answers these messages after the ones still waiting (now, or once the page is settled).
    pub answer: fn(Vec<MessageEvent>),
    /// The page wrote its state to the address.
    pub state_written: fn(),
    /// A page was mounted.
    pub mounted: fn(),
}

/// What the shell lends the API.
#[derive(Clone, Copy)]
pub(crate) struct ShellFns {
    /// The `<main>` element pages mount into.
    pub main: fn() -> Result<Element, JsValue>,
    /// Whether the route is settled (its page built and answering input, or no page).
    pub settled: fn() -> bool,
    /// Mounts the route of the address again.
    pub remount: fn() -> Result<(), JsValue>,
}

/// What the shell calls.
pub(crate) const FNS: ApiFns = ApiFns {
    start,
    answer,
    state_written,
    mounted,
};

/// How long the page's state rests before `statechange` tells it, ms.
pub const STATE_REST_MS: i32 = 250;
/// Shortest time between two `readouts` events, ms (at most 10 a second).
pub const READOUTS_GAP_MS: f64 = 100.0;
/// How often a request waiting for the page to settle looks again, ms.
const SETTLE_POLL_MS: i32 = 50;
/// How long requests wait for a page that does not settle (its code could not be fetched)
/// before they are answered anyway, ms.
const SETTLE_WAIT_MS: f64 = 10_000.0;
/// The least height of the main view, CSS px (a frame lower than that scrolls).
const MIN_VIEW_PX: f64 = 150.0;
/// Room kept under the main view, CSS px.
const VIEW_MARGIN_PX: f64 = 8.0;
/// The most clicks of a stepper without a scrub slider that one `step(n)` makes.
const MAX_CLICKS: i64 = 10_000;
/// The class on `<html>` while a canvas is being used.
const IN_USE_CLASS: &str = "embed-in-use";

/// A page's id and its state (its query).
type PageState = (String, Vec<(String, String)>);

/// The observer of the readouts and its callback.
type Observer = (web_sys::MutationObserver, Closure<dyn FnMut()>);

struct Api {
    shell: ShellFns,
    /// Messages waiting for the page to settle, in the order they came.
    pending: RefCell<VecDeque<MessageEvent>>,
    /// The page and state the host was last told of (`ready`, `statechange`, `setState`).
    told_state: RefCell<Option<PageState>>,
    /// The readouts the host was last told of, as JSON text.
    told_readouts: RefCell<String>,
    told_readouts_ms: Cell<f64>,
    ready_told: Cell<bool>,
    /// Whether [`answer`] is answering (a page it mounts again calls it back).
    answering: Cell<bool>,
    /// Since when requests wait for the page to settle (ms; `None`: not waiting).
    waiting_since: Cell<Option<f64>>,
    state_timer: Timer,
    readouts_timer: Timer,
    /// Fits the main view once the page is laid out.
    fit_timer: Timer,
    answer_timer: Timer,
    /// "Open in BSV Playground ↗" (embedded tabs only).
    link: Option<Element>,
    /// Whether a canvas is being used.
    in_use: Cell<bool>,
    observer: RefCell<Option<Observer>>,
}

thread_local! {
    static API: RefCell<Option<Rc<Api>>> = const { RefCell::new(None) };
}

fn with_api(f: impl FnOnce(&Rc<Api>)) {
    let api = API.with_borrow(Clone::clone);
    if let Some(api) = api {
        f(&api);
    }
}

fn start(shell: ShellFns) {
    if let Err(error) = install(shell) {
        web_sys::console::warn_2(&"BSV Playground: embedding:".into(), &error);
    }
}

fn install(shell: ShellFns) -> Result<(), JsValue> {
    let embedded = router::embedded();
    let link = if embedded { Some(build_link()?) } else { None };
    let api = Rc::new(Api {
        shell,
        pending: RefCell::new(VecDeque::new()),
        told_state: RefCell::new(None),
        told_readouts: RefCell::new(String::new()),
        told_readouts_ms: Cell::new(f64::NEG_INFINITY),
        ready_told: Cell::new(false),
        answering: Cell::new(false),
        waiting_since: Cell::new(None),
        state_timer: Timer::default(),
        readouts_timer: Timer::default(),
        fit_timer: Timer::default(),
        answer_timer: Timer::default(),
        link,
        in_use: Cell::new(false),
        observer: RefCell::new(None),
    });
    let weak = Rc::downgrade(&api);
    api.state_timer.set_callback(&weak, Api::tell_state);
    api.readouts_timer.set_callback(&weak, Api::tell_readouts);
    api.answer_timer.set_callback(&weak, |_| answer_pending());
    api.fit_timer.set_callback(&weak, |_| fit_view());
    API.with_borrow_mut(|slot| *slot = Some(api.clone()));
    if embedded {
        api.observe_readouts()?;
        install_frame_listeners()?;
    }
    mounted();
    Ok(())
}

/// "Open in BSV Playground ↗", at the top right of the frame.
fn build_link() -> Result<Element, JsValue> {
    let link = dom::el_i18n("a", "embed-open", "embed-open")?;
    link.set_attribute("data-testid", "embed-open")?;
    link.set_attribute("target", "_blank")?;
    link.set_attribute("rel", "noopener")?;
    dom::set_i18n_attrs(&link, &[("title", "embed-open-title")])?;
    dom::relocalize(&link)?;
    let app = dom::document()?
        .get_element_by_id("app")
        .ok_or_else(|| JsValue::from_str("no #app"))?;
    dom::append(&app, &link)?;
    Ok(link)
}

/// The address of the page as it is, without `embed=1`.
fn open_href() -> Result<String, JsValue> {
    let location = dom::window()?.location();
    let route = router::current_route();
    let query: Vec<(String, String)> = route
        .query
        .into_iter()
        .filter(|(k, _)| k != EMBED_KEY)
        .collect();
    Ok(format!(
        "{}{}{}{}",
        location.origin()?,
        location.pathname()?,
        location.search()?,
        build_hash(&route.page, &query)
    ))
}

/// The page's id and state now.
fn page_state() -> PageState {
    let route = router::current_route();
    let query = route.page_query();
    (route.page, query)
}

fn main_element() -> Option<Element> {
    let shell = API.with_borrow(|api| api.as_ref().map(|api| api.shell))?;
    (shell.main)().ok()
}

/// The parent window of an embedded tab (`None` at the top).
fn parent_window() -> Option<web_sys::Window> {
    let window = web_sys::window()?;
    let parent = window.parent().ok().flatten()?;
    (!js_sys::Object::is(&parent, &window)).then_some(parent)
}

/// Posts `message` (an object) to `target` for `origin`.
fn post(target: &JsValue, message: &Value, as_text: bool, origin: &str) {
    let text = message.to_string();
    let data = if as_text {
        JsValue::from_str(&text)
    } else {
        match js_sys::JSON::parse(&text) {
            Ok(data) => data,
            Err(_) => return,
        }
    };
    let target: &web_sys::Window = target.unchecked_ref();
    let _ = target.post_message(&data, origin);
}

/// Posts an event to the parent window.
fn tell(event: Value) {
    if router::embedded() {
        if let Some(parent) = parent_window() {
            post(&parent, &event, false, "*");
        }
    }
}

impl Api {
    fn tell_state(&self) {
        if let (Some(link), Ok(href)) = (&self.link, open_href()) {
            let _ = link.set_attribute("href", &href);
        }
        let now = page_state();
        if self.told_state.borrow().as_ref() == Some(&now) {
            return;
        }
        let event = protocol::event(
            "statechange",
            vec![
                ("page", Value::String(now.0.clone())),
                ("state", protocol::state_object(&now.1)),
            ],
        );
        *self.told_state.borrow_mut() = Some(now);
        if self.ready_told.get() {
            tell(event);
        }
    }

    fn tell_readouts(&self) {
        if !self.ready_told.get() {
            return;
        }
        let readouts = readouts();
        let text = readouts.to_string();
        if *self.told_readouts.borrow() == text {
            return;
        }
        *self.told_readouts.borrow_mut() = text;
        self.told_readouts_ms.set(now_ms());
        tell(protocol::event("readouts", vec![("readouts", readouts)]));
    }

    /// A readout may have changed: tell the host, at most every [`READOUTS_GAP_MS`].
    fn readouts_changed(&self) {
        let wait = self.told_readouts_ms.get() + READOUTS_GAP_MS - now_ms();
        self.readouts_timer.schedule(wait.max(0.0).ceil() as i32);
    }

    fn observe_readouts(self: &Rc<Self>) -> Result<(), JsValue> {
        let Some(main) = main_element() else {
            return Ok(());
        };
        let weak = Rc::downgrade(self);
        let callback = Closure::<dyn FnMut()>::new(move || {
            if let Some(api) = weak.upgrade() {
                api.readouts_changed();
            }
        });
        let observer = web_sys::MutationObserver::new(callback.as_ref().unchecked_ref())?;
        let options = web_sys::MutationObserverInit::new();
        options.set_subtree(true);
        options.set_child_list(true);
        options.set_character_data(true);
        options.set_attribute_filter(&js_sys::Array::of1(&"data-value".into()));
        observer.observe_with_options(&main, &options)?;
        *self.observer.borrow_mut() = Some((observer, callback));
        Ok(())
    }
}

fn state_written() {
    with_api(|api| api.state_timer.schedule(STATE_REST_MS));
}

/// A page was mounted: its main view fitted to the frame, the link and the host told.
fn mounted() {
    with_api(|api| {
        if let (Some(link), Ok(href)) = (&api.link, open_href()) {
            let _ = link.set_attribute("href", &href);
        }
        if router::embedded() {
            api.fit_timer.schedule(0);
        }
    });
    answer_pending();
}

/// Sizes the page's main view (the box of its first canvas) to fill the frame under what
/// stands above it.
fn fit_view() {
    let Some(window) = web_sys::window() else {
        return;
    };
    let Some(view) = main_element()
        .and_then(|main| main.query_selector("canvas").ok().flatten())
        .and_then(|canvas| canvas.parent_element())
        .and_then(|view| view.dyn_into::<HtmlElement>().ok())
    else {
        return;
    };
    let height = dom::viewport_height(&window);
    let scrolled = window.scroll_y().unwrap_or(0.0);
    let top = view.get_bounding_client_rect().top() + scrolled;
    let fill = (height - top - VIEW_MARGIN_PX).floor().max(MIN_VIEW_PX);
    let _ = view.set_attribute("data-embed-view", "");
    let _ = view.style().set_property("height", &format!("{fill}px"));
}

/// Wheel and touch over a canvas being used stay in the frame; the frame's size refits the
/// main view.
fn install_frame_listeners() -> Result<(), JsValue> {
    let window = dom::window()?;
    let document = dom::document()?;
    dom::Listener::capture(&document, "pointerdown", |event| {
        let on_canvas = event
            .target()
            .and_then(|t| t.dyn_into::<Element>().ok())
            .is_some_and(|t| is_canvas_area(&t));
        set_in_use(on_canvas);
    })?
    .forever();
    if let Some(html) = document.document_element() {
        dom::Listener::new(&html, "pointerleave", |_| set_in_use(false))?.forever();
    }
    // On an element (not the window), so that the listener may cancel the turn.
    if let Some(main) = main_element() {
        dom::Listener::new(&main, "wheel", |event| {
            let in_use = API.with_borrow(|api| api.as_ref().is_some_and(|a| a.in_use.get()));
            let on_canvas = event
                .target()
                .and_then(|t| t.dyn_into::<Element>().ok())
                .is_some_and(|t| is_canvas_area(&t));
            if in_use && on_canvas {
                event.prevent_default();
            }
        })?
        .forever();
    }
    dom::Listener::new(&window, "resize", |_| fit_view())?.forever();
    Ok(())
}

fn set_in_use(on: bool) {
    with_api(|api| {
        if api.in_use.replace(on) != on {
            if let Some(html) = dom::document().ok().and_then(|d| d.document_element()) {
                let _ = html.class_list().toggle_with_force(IN_USE_CLASS, on);
            }
        }
    });
}

/// Whether `element` is a canvas or inside the box of one (a stage and its handles).
fn is_canvas_area(element: &Element) -> bool {
    let mut node = Some(element.clone());
    for _ in 0..4 {
        let Some(el) = node else {
            return false;
        };
        if el.tag_name().eq_ignore_ascii_case("canvas")
            || el
                .query_selector(":scope > canvas")
                .ok()
                .flatten()
                .is_some()
        {
            return true;
        }
        node = el.parent_element();
    }
    false
}

// ---------- Requests ----------

/// Answers `messages` after the ones still waiting.
fn answer(messages: Vec<MessageEvent>) {
    with_api(|api| api.pending.borrow_mut().extend(messages));
    answer_pending();
}

/// Answers the waiting messages in order, once the page is settled (or has not settled for
/// [`SETTLE_WAIT_MS`]); a request that mounts the page again waits for it to settle before
/// the next is answered.
fn answer_pending() {
    let Some(api) = API.with_borrow(Clone::clone) else {
        return;
    };
    if api.answering.replace(true) {
        return;
    }
    answer_queue(&api);
    api.answering.set(false);
}

fn answer_queue(api: &Api) {
    loop {
        if (api.shell.settled)() {
            api.waiting_since.set(None);
        } else {
            let since = api.waiting_since.get().unwrap_or_else(now_ms);
            api.waiting_since.set(Some(since));
            if now_ms() - since < SETTLE_WAIT_MS {
                api.answer_timer.schedule(SETTLE_POLL_MS);
                return;
            }
        }
        if !api.ready_told.get() {
            api.ready_told.set(true);
            let now = page_state();
            let ready = protocol::event(
                "ready",
                vec![
                    ("page", Value::String(now.0.clone())),
                    ("state", protocol::state_object(&now.1)),
                ],
            );
            *api.told_state.borrow_mut() = Some(now);
            tell(ready);
        }
        let next = api.pending.borrow_mut().pop_front();
        let Some(event) = next else {
            return;
        };
        answer_one(api, &event);
    }
}

fn answer_one(api: &Api, event: &MessageEvent) {
    let data = event.data();
    let as_text = data.is_string();
    let message = match data.as_string() {
        Some(text) => protocol::parse_text(&text),
        None => match js_sys::JSON::stringify(&data)
            .ok()
            .and_then(|text| text.as_string())
            .and_then(|text| serde_json::from_str::<Value>(&text).ok())
        {
            Some(value) => protocol::parse(&value),
            None => Message::Malformed {
                id: Value::Null,
                error: "the message is not JSON data".into(),
            },
        },
    };
    let reply = match message {
        Message::NotForUs => return,
        Message::Malformed { id, error } => protocol::error_reply(&id, &error, Vec::new()),
        Message::Request(request) => carry_out(api, request),
    };
    let Some(source) = event.source() else {
        return;
    };
    let origin = event.origin();
    let origin = if origin.is_empty() || origin == "null" {
        "*".to_string()
    } else {
        origin
    };
    post(source.as_ref(), &reply, as_text, &origin);
}

fn carry_out(api: &Api, request: Request) -> Value {
    let id = &request.id;
    let result = match request.method {
        Method::GetState => Ok(protocol::state_object(&page_state().1)),
        Method::GetReadouts => Ok(readouts()),
        Method::SetState { changes, invalid } => return set_state(api, id, changes, invalid),
        Method::Step(n) => step(n),
        Method::Reset => reset(),
    };
    match result {
        Ok(result) => protocol::reply(id, result),
        Err(error) => protocol::error_reply(id, &error, Vec::new()),
    }
}

/// Mounts the page from `query` (the shell's keys kept); the keys it did not use.
fn mount_with(api: &Api, query: &[(String, String)]) -> Result<Vec<IgnoredKey>, String> {
    router::replace_query(query);
    url_state::forget_shown_keys();
    (api.shell.remount)().map_err(|e| format!("the page could not be mounted: {e:?}"))?;
    Ok(url_state::shown_keys())
}

fn set_state(
    api: &Api,
    id: &Value,
    changes: Vec<protocol::StateChange>,
    invalid: Vec<String>,
) -> Value {
    let before = page_state().1;
    let mut refused: Vec<IgnoredKey> = invalid.into_iter().map(IgnoredKey::invalid).collect();
    let (shell_keys, changes): (Vec<_>, Vec<_>) = changes
        .into_iter()
        .partition(|(key, _)| protocol::is_shell_key(key));
    refused.extend(shell_keys.into_iter().map(|(k, _)| IgnoredKey::unknown(k)));
    let is_host_key = |key: &str| changes.iter().any(|(k, _)| k == key);
    let mounted = if changes.is_empty() {
        Ok(Vec::new())
    } else {
        mount_with(api, &protocol::apply_changes(&before, &changes))
    };
    let mut ignored = match mounted {
        Ok(ignored) => ignored,
        Err(error) => return protocol::error_reply(id, &error, Vec::new()),
    };
    if !ignored.is_empty() {
        // The host's keys the page did not take keep their last good value; keys of the
        // link before that the page did not take go.
        let is_ignored = |key: &str| ignored.iter().any(|k| k.key == key);
        let base: Vec<(String, String)> = before
            .iter()
            .filter(|(k, _)| !is_ignored(k) || is_host_key(k))
            .cloned()
            .collect();
        let taken: Vec<protocol::StateChange> = changes
            .iter()
            .filter(|(k, _)| !is_ignored(k))
            .cloned()
            .collect();
        if let Err(error) = mount_with(api, &protocol::apply_changes(&base, &taken)) {
            return protocol::error_reply(id, &error, Vec::new());
        }
        ignored.retain(|k| is_host_key(&k.key));
        refused.extend(ignored);
    }
    let now = page_state();
    let state = protocol::state_object(&now.1);
    *api.told_state.borrow_mut() = Some(now);
    if refused.is_empty() {
        protocol::reply(id, state)
    } else {
        let (error, list) = protocol::ignored_error(&refused);
        protocol::error_reply(id, &error, vec![("ignored", list), ("state", state)])
    }
}

/// Every `[data-readout]` of the page: `{key: {"value": number or null, "unit": text}}`.
fn readouts() -> Value {
    let mut out = serde_json::Map::new();
    let elements = main_element()
        .and_then(|main| dom::matching(&main, "[data-readout]").ok())
        .unwrap_or_default();
    for element in elements {
        let Some(key) = element.get_attribute("data-readout") else {
            continue;
        };
        let text = element.text_content().unwrap_or_default();
        let data_value = element.get_attribute("data-value");
        let value = protocol::readout_number(data_value.as_deref(), &text);
        let unit = element
            .get_attribute("data-unit")
            .or_else(|| Some(protocol::split_number(&text).1).filter(|u| !u.is_empty()))
            .or_else(|| unit_beside(&element))
            .unwrap_or_default();
        out.insert(key, protocol::readout(value, &unit));
    }
    Value::Object(out)
}

/// The unit element (a class ending in `-unit`) after a readout, before any other readout;
/// else the one after the row or table that holds it (a matrix's unit).
fn unit_beside(readout: &Element) -> Option<String> {
    let mut node = readout.clone();
    for _ in 0..3 {
        let mut sibling = node.next_element_sibling();
        while let Some(el) = sibling {
            if el.has_attribute("data-readout")
                || el.query_selector("[data-readout]").ok().flatten().is_some()
            {
                break;
            }
            if el
                .class_name()
                .split_whitespace()
                .any(|c| c.ends_with("-unit"))
            {
                return el.text_content().map(|t| t.trim().to_string());
            }
            sibling = el.next_element_sibling();
        }
        node = node.parent_element()?;
    }
    None
}

/// The page's stepper, if it steps.
fn stepper() -> Result<Element, String> {
    main_element()
        .and_then(|main| main.query_selector(".kit-stepper").ok().flatten())
        .ok_or_else(|| "this page does not step (step and reset work where it does)".to_string())
}

fn scrub(stepper: &Element) -> Option<HtmlInputElement> {
    stepper
        .query_selector("[data-stepper=\"scrub\"]")
        .ok()
        .flatten()
        .and_then(|el| el.dyn_into::<HtmlInputElement>().ok())
}

/// The stepper's position (steps done).
fn position(stepper: &Element) -> Value {
    scrub(stepper)
        .map(|s| s.value_as_number())
        .filter(|x| x.is_finite())
        .and_then(serde_json::Number::from_f64)
        .map_or(Value::Null, Value::Number)
}

fn click(stepper: &Element, action: &str) -> bool {
    let button = stepper
        .query_selector(&format!("[data-action=\"{action}\"]"))
        .ok()
        .flatten()
        .and_then(|el| el.dyn_into::<HtmlElement>().ok());
    match button {
        Some(button) if !button.has_attribute("disabled") => {
            button.click();
            true
        }
        _ => false,
    }
}

/// `n` steps on (back when negative): the scrub slider moved by `n` where it shows, else `|n|`
/// clicks of step or back (fewer at either end).
fn step(n: i64) -> Result<Value, String> {
    let stepper = stepper()?;
    match scrub(&stepper).filter(|s| !s.hidden()) {
        Some(scrub) => {
            let max = scrub.max().parse::<f64>().unwrap_or(0.0);
            let target = (scrub.value_as_number() + n as f64).clamp(0.0, max.max(0.0));
            scrub.set_value_as_number(target);
            let input = web_sys::Event::new("input").map_err(|_| "no input event".to_string())?;
            let _ = scrub.dispatch_event(&input);
        }
        None if n.abs() > MAX_CLICKS => {
            return Err(format!(
                "step(n): this page steps at most {MAX_CLICKS} at once"
            ));
        }
        None => {
            let action = if n < 0 { "back" } else { "step" };
            for _ in 0..n.abs() {
                if !click(&stepper, action) {
                    break;
                }
            }
        }
    }
    Ok(position(&stepper))
}

fn reset() -> Result<Value, String> {
    let stepper = stepper()?;
    click(&stepper, "reset");
    Ok(position(&stepper))
}
