//! The "a new version is ready — reload to update" offer of the offline install. The service
//! worker registration (`www/bootstrap.js`) fires `bsv-update-ready` on the document when a
//! newer build has been cached in full; this banner then shows, and its button calls
//! `window.bsvApplyUpdate()` (the new worker takes over, the page reloads once). Until the
//! user accepts, the page keeps running the build it started with.

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::Element;

use crate::ui::dom;

/// The hidden banner, listening for the update event (the shell appends it to `#app`).
pub(crate) fn build() -> Result<Element, JsValue> {
    let banner = dom::el_class("div", "update-banner")?;
    banner.set_attribute("role", "status")?;
    banner.set_attribute("data-testid", "update-banner")?;
    let text = dom::el_i18n("p", "update-text", "update-ready")?;
    dom::append(&banner, &text)?;
    let button = dom::el_i18n("button", "tool-button update-button", "update-reload")?;
    button.set_attribute("type", "button")?;
    button.set_attribute("data-action", "apply-update")?;
    dom::append(&banner, &button)?;
    dom::show(&banner, false);

    dom::Listener::new(&button, "click", |_| apply_update())?.forever();
    let shown = banner.clone();
    let document = dom::document()?;
    dom::Listener::new(&document, "bsv-update-ready", move |_| {
        dom::show(&shown, true);
    })?
    .forever();
    Ok(banner)
}

fn apply_update() {
    let Some(window) = web_sys::window() else {
        return;
    };
    let apply = js_sys::Reflect::get(&window, &JsValue::from_str("bsvApplyUpdate"))
        .ok()
        .and_then(|f| f.dyn_into::<js_sys::Function>().ok());
    if let Some(apply) = apply {
        if let Err(error) = apply.call0(&window) {
            web_sys::console::error_2(&"BSV Playground: update failed".into(), &error);
        }
    }
}
