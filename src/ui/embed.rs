//! Embedding, the part every route loads: whether the tab shows its page embedded (the first
//! route had `embed=1`: class `embed` on `<html>` hides the site's chrome, and the router
//! keeps `embed=1` in the address), and the door of the postMessage API, a `message` listener
//! that queues what may be a request and hands it to the API's chunk
//! ([`crate::ui::embed_api`]), fetched on the first such message, or at once when embedded.

use std::cell::{Cell, RefCell};

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::MessageEvent;

use crate::ui::page::SplitLoaderError;
use crate::ui::{dom, embed_api, router};

/// The class on `<html>` of an embedded tab.
const EMBED_CLASS: &str = "embed";

/// What the API's chunk gives the shell.
#[derive(Clone, Copy)]
pub(crate) struct ApiFns {
    /// Sets the API up (once, when its chunk has come).
    pub start: fn(),
    /// Answers the queued messages (now, or once the page is settled).
    pub answer: fn(),
    /// The page wrote its state to the address.
    pub state_written: fn(),
    /// A page was mounted.
    pub mounted: fn(),
}

thread_local! {
    static QUEUE: RefCell<Vec<MessageEvent>> = const { RefCell::new(Vec::new()) };
    static API: Cell<Option<ApiFns>> = const { Cell::new(None) };
    static LOADING: Cell<bool> = const { Cell::new(false) };
    static EMBEDDED: Cell<bool> = const { Cell::new(false) };
}

/// Whether the tab shows its page embedded.
pub(crate) fn embedded() -> bool {
    EMBEDDED.get()
}

/// Marks the tab embedded if the address asks for it, and listens for the API's messages.
pub(crate) fn install() -> Result<(), JsValue> {
    let window = dom::window()?;
    if router::current_route().embedded() {
        EMBEDDED.set(true);
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

/// The next queued message.
pub(crate) fn next_message() -> Option<MessageEvent> {
    QUEUE.with_borrow_mut(|queue| (!queue.is_empty()).then(|| queue.remove(0)))
}

/// Tells the API (if it is here) that the page wrote its state.
pub(crate) fn state_written() {
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
        (api.answer)();
        return;
    }
    if LOADING.replace(true) {
        return;
    }
    wasm_bindgen_futures::spawn_local(async {
        let loaded = api_fns().await;
        LOADING.set(false);
        if let Ok(api) = loaded {
            API.set(Some(api));
            (api.start)();
            (api.answer)();
        }
    });
}

/// The API: a wasm chunk of its own, fetched on the first message or when embedded.
#[cfg(feature = "split")]
#[wasm_split_helpers::wasm_split(embed_api, fallible)]
fn api_fns() -> Result<ApiFns, SplitLoaderError> {
    Ok(embed_api::FNS)
}

/// Without the `split` feature the API is in the one wasm.
#[cfg(not(feature = "split"))]
async fn api_fns() -> Result<ApiFns, SplitLoaderError> {
    Ok(embed_api::FNS)
}
