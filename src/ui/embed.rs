//! Embedding, the part every route loads: the tab is marked embedded when its first route has
//! `embed=1` (class `embed` on `<html>` hides the site's chrome; the router keeps `embed=1` in
//! the address), and the door of the postMessage API: a `message` listener that queues what
//! may be a request and hands the queue to the API's chunk ([`crate::ui::embed_api`]),
//! fetched on the first such message, or at once when embedded, with what the shell lends it.

use std::cell::{Cell, RefCell};

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::MessageEvent;

use crate::ui::embed_api::{self, ApiFns, ShellFns};
use crate::ui::split_point::split_point;
use crate::ui::{dom, router};

/// The class on `<html>` of an embedded tab.
const EMBED_CLASS: &str = "embed";

thread_local! {
    static QUEUE: RefCell<Vec<MessageEvent>> = const { RefCell::new(Vec::new()) };
    static API: Cell<Option<ApiFns>> = const { Cell::new(None) };
    static SHELL: Cell<Option<ShellFns>> = const { Cell::new(None) };
    static LOADING: Cell<bool> = const { Cell::new(false) };
}

/// Marks the tab embedded if the address asks for it, and listens for the API's messages;
/// `shell` is what the API may ask of the shell.
pub(crate) fn install(shell: ShellFns) -> Result<(), JsValue> {
    SHELL.set(Some(shell));
    let window = dom::window()?;
    router::on_write(state_written);
    if router::current_route().embedded() {
        router::set_embedded();
        if let Some(html) = dom::document()?.document_element() {
            html.class_list().toggle_with_force(EMBED_CLASS, true)?;
        }
        answer();
    }
    dom::Listener::new(&window, "message", |event| {
        if let Ok(event) = event.dyn_into::<MessageEvent>() {
            if may_be_request(&event.data()) {
                QUEUE.with_borrow_mut(|queue| queue.push(event));
                answer();
            }
        }
    })?
    .forever();
    Ok(())
}

/// A message the API may answer: an object whose `namespace` is `"bsv"`, or JSON text of an
/// object (the chunk reads it); the rest is for someone else.
fn may_be_request(data: &JsValue) -> bool {
    match data.as_string() {
        Some(text) => text.as_bytes().first() == Some(&b'{'),
        None => {
            data.is_object()
                && js_sys::Reflect::get(data, &JsValue::from_str("namespace"))
                    .ok()
                    .and_then(|ns| ns.as_string())
                    .is_some_and(|ns| ns == crate::view::embed::NAMESPACE)
        }
    }
}

/// Tells the API (if it is here) that the page wrote its state.
fn state_written() {
    if let Some(api) = API.get() {
        (api.state_written)();
    }
}

/// Tells the API (if it is here) that a page was mounted.
pub(crate) fn mounted() {
    if let Some(api) = API.get() {
        (api.mounted)();
    }
}

/// Has the API answer the queued messages: at once if its chunk is here, else once it has
/// come (fetched on the first call; a failed fetch is tried again on the next).
fn answer() {
    if let Some(api) = API.get() {
        (api.answer)(QUEUE.take());
        return;
    }
    if LOADING.replace(true) {
        return;
    }
    wasm_bindgen_futures::spawn_local(async {
        let loaded = api_fns().await;
        LOADING.set(false);
        if let (Ok(api), Some(shell)) = (loaded, SHELL.get()) {
            API.set(Some(api));
            (api.start)(shell);
            (api.answer)(QUEUE.take());
        }
    });
}

// The API: a wasm chunk of its own, fetched on the first message or when embedded.
split_point!(embed_api, fn api_fns() -> ApiFns = embed_api::FNS);
