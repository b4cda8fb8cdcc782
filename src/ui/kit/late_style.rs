//! The stylesheet of what only a chunk builds: `<name>.late.css` beside its Rust is
//! `www/<name>.css` in dist/ (`scripts/build-dist.sh`), in no page's first load, linked on first
//! use. [`linked`] resolves once it has loaded, or failed to (the part then shows unstyled,
//! still working), so that a part is never drawn before its style.

use wasm_bindgen::prelude::*;
use wasm_bindgen_futures::JsFuture;

use crate::ui::dom;

/// Links `www/<name>.css` unless it is linked already, and waits until it has loaded.
pub async fn linked(name: &str) {
    let Ok(document) = dom::document() else {
        return;
    };
    let id = format!("late-css-{name}");
    let link = match document.get_element_by_id(&id) {
        Some(link) if link.has_attribute("data-loaded") || has_sheet(&link) => return,
        Some(link) => link,
        None => {
            let Ok(link) = dom::el("link") else { return };
            link.set_id(&id);
            let _ = link.set_attribute("rel", "stylesheet");
            let _ = link.set_attribute("href", &format!("www/{name}.css"));
            let head = document.query_selector("head").ok().flatten();
            if head.and_then(|h| h.append_child(&link).ok()).is_none() {
                return;
            }
            link
        }
    };
    let done = js_sys::Promise::new(&mut |resolve, _| {
        for event in ["load", "error"] {
            let _ = link.add_event_listener_with_callback(event, &resolve);
        }
    });
    let _ = JsFuture::from(done).await;
    let _ = link.set_attribute("data-loaded", "");
}

/// Whether `link`'s stylesheet has loaded (`link.sheet` is set once it has).
fn has_sheet(link: &web_sys::Element) -> bool {
    js_sys::Reflect::get(link, &JsValue::from_str("sheet")).is_ok_and(|s| s.is_object())
}
