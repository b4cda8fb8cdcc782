//! The stylesheet of what only a chunk builds: `<name>.late.css` beside its Rust is
//! `www/<name>.css` in dist/ (`scripts/build-dist.sh`), not in app.css, linked on first use.
//! [`linked`] resolves once it has loaded, or failed to (the part then shows unstyled, still
//! working), so that a part is never drawn before its style. A page's own stylesheet
//! ([`crate::ui::page::PageDef::sheet`]) is one: the shell links it ([`link`]) when it asks for
//! the page's code, and mounts the page once both are in.

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use wasm_bindgen_futures::JsFuture;

use crate::ui::dom;

/// The property of a link this module made: a promise that resolves once its sheet has loaded
/// or failed to.
const SETTLED: &str = "bsvSettled";

/// Links `www/<name>.css` unless it is linked already: its `<link>`.
pub fn link(name: &str) -> Option<web_sys::Element> {
    let document = dom::document().ok()?;
    let id = format!("late-css-{name}");
    if let Some(link) = document.get_element_by_id(&id) {
        return Some(link);
    }
    let link = dom::el("link").ok()?;
    link.set_id(&id);
    let _ = link.set_attribute("rel", "stylesheet");
    let _ = link.set_attribute("href", &format!("www/{name}.css"));
    let settled = js_sys::Promise::new(&mut |resolve, _| {
        for event in ["load", "error"] {
            let _ = link.add_event_listener_with_callback(event, &resolve);
        }
    });
    let _ = js_sys::Reflect::set(&link, &JsValue::from_str(SETTLED), &settled);
    document
        .query_selector("head")
        .ok()
        .flatten()?
        .append_child(&link)
        .ok()?;
    Some(link)
}

/// Links `www/<name>.css` unless it is linked already, and waits until it has loaded.
pub async fn linked(name: &str) {
    let Some(link) = link(name) else {
        return;
    };
    if has_sheet(&link) {
        return;
    }
    let settled = js_sys::Reflect::get(&link, &JsValue::from_str(SETTLED))
        .ok()
        .and_then(|promise| promise.dyn_into::<js_sys::Promise>().ok());
    if let Some(settled) = settled {
        let _ = JsFuture::from(settled).await;
    }
}

/// Whether `link`'s stylesheet has loaded (`link.sheet` is set once it has).
pub fn has_sheet(link: &web_sys::Element) -> bool {
    js_sys::Reflect::get(link, &JsValue::from_str("sheet")).is_ok_and(|s| s.is_object())
}
