//! Copying text (a command line) to the clipboard: the Clipboard API where the page may use it,
//! else `document.execCommand("copy")` on a temporary read-only field.

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;

use crate::ui::dom;

/// Copies `text`; calls `done(true)` on success and `done(false)` when neither way worked (the
/// page then asks the user to select and copy by hand).
pub fn copy_text(text: &str, done: impl Fn(bool) + 'static) {
    let Some(window) = web_sys::window() else {
        done(false);
        return;
    };
    let navigator = window.navigator();
    let has_clipboard = js_sys::Reflect::get(&navigator, &JsValue::from_str("clipboard"))
        .map(|c| !c.is_undefined() && !c.is_null())
        .unwrap_or(false);
    if !has_clipboard {
        done(exec_copy(text));
        return;
    }
    let promise = navigator.clipboard().write_text(text);
    let done = std::rc::Rc::new(done);
    let ok = {
        let done = done.clone();
        Closure::once_into_js(move |_: JsValue| done(true))
    };
    let text = text.to_string();
    let fail = Closure::once_into_js(move |_: JsValue| done(exec_copy(&text)));
    dom::then(&promise, &ok, &fail);
}

/// `document.execCommand("copy")` on a temporary read-only field holding `text`.
fn exec_copy(text: &str) -> bool {
    let Some(document) = web_sys::window().and_then(|w| w.document()) else {
        return false;
    };
    let Some(body) = document.body() else {
        return false;
    };
    let Ok(input) = document
        .create_element("input")
        .map(|e| e.unchecked_into::<web_sys::HtmlInputElement>())
    else {
        return false;
    };
    input.set_value(text);
    let _ = input.set_attribute("readonly", "");
    // CSSOM, not a style attribute: the strict CSP blocks inline style attributes.
    let style = input.style();
    let _ = style.set_property("position", "fixed");
    let _ = style.set_property("left", "-9999px");
    let _ = style.set_property("top", "0");
    if body.append_child(&input).is_err() {
        return false;
    }
    input.select();
    let copied = js_sys::Reflect::get(&document, &JsValue::from_str("execCommand"))
        .ok()
        .and_then(|f| f.dyn_into::<js_sys::Function>().ok())
        .and_then(|f| f.call1(&document, &JsValue::from_str("copy")).ok())
        .and_then(|v| v.as_bool())
        .unwrap_or(false);
    input.remove();
    copied
}
