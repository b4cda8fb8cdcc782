//! Small DOM helpers shared by the shell and the pages: element builders and look-ups, localized
//! text (`data-i18n="msg-id"` and `data-i18n-attr="title=msg-id;aria-label=msg-id"`,
//! re-rendered by [`relocalize`], which also names every `data-section`), showing and hiding, localStorage that never throws (private
//! mode, disabled storage), event listeners that remove themselves when dropped, and
//! `promise.then` for the browser's promise-returning calls.

use std::rc::Weak;

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::{Document, Element, Event, EventTarget, HtmlElement, Window};

use crate::ui::ctx;

/// The browser window.
pub fn window() -> Result<Window, JsValue> {
    web_sys::window().ok_or_else(|| JsValue::from_str("no window"))
}

/// The document of the window.
pub fn document() -> Result<Document, JsValue> {
    window()?
        .document()
        .ok_or_else(|| JsValue::from_str("no document"))
}

/// A new element `<tag>`.
pub fn el(tag: &str) -> Result<Element, JsValue> {
    document()?.create_element(tag)
}

/// A new element `<tag class="class">`.
pub fn el_class(tag: &str, class: &str) -> Result<Element, JsValue> {
    let element = el(tag)?;
    element.set_class_name(class);
    Ok(element)
}

/// A new element with fixed (not localized) text, such as a command line.
pub fn el_text(tag: &str, class: &str, text: &str) -> Result<Element, JsValue> {
    let element = el_class(tag, class)?;
    element.set_text_content(Some(text));
    Ok(element)
}

/// A new element whose text is message `id`, kept in the current language.
pub fn el_i18n(tag: &str, class: &str, id: &str) -> Result<Element, JsValue> {
    let element = el_class(tag, class)?;
    set_i18n(&element, id)?;
    Ok(element)
}

/// The height of `window`'s viewport in CSS pixels (0 when the browser does not say).
pub fn viewport_height(window: &Window) -> f64 {
    window
        .inner_height()
        .ok()
        .and_then(|h| h.as_f64())
        .unwrap_or(0.0)
}

/// A tool button (`type="button"`) whose text is message `label_id`, marked
/// `data-action="<action>"` for the click handler of the bar it is in.
pub fn action_button(action: &str, label_id: &str) -> Result<Element, JsValue> {
    let button = el_i18n("button", "tool-button", label_id)?;
    button.set_attribute("type", "button")?;
    button.set_attribute("data-action", action)?;
    Ok(button)
}

/// A landmark the shell places hidden (`<nav>`, `<aside>`): `name` is its class, its id and
/// its `data-testid`; its `aria-label` is message `label_id`.
pub fn hidden_landmark(tag: &str, name: &str, label_id: &str) -> Result<Element, JsValue> {
    let element = el_class(tag, name)?;
    element.set_id(name);
    element.set_attribute("data-testid", name)?;
    set_i18n_attrs(&element, &[("aria-label", label_id)])?;
    show(&element, false);
    Ok(element)
}

/// Makes `element`'s text message `id`, now and after every language switch.
pub fn set_i18n(element: &Element, id: &str) -> Result<(), JsValue> {
    element.set_attribute("data-i18n", id)?;
    element.set_text_content(Some(&ctx::t(id)));
    Ok(())
}

/// Makes attributes of `element` localized messages (`[("title", "msg-id")]`), now and after
/// every language switch.
pub fn set_i18n_attrs(element: &Element, attrs: &[(&str, &str)]) -> Result<(), JsValue> {
    let spec: Vec<String> = attrs.iter().map(|(a, id)| format!("{a}={id}")).collect();
    element.set_attribute("data-i18n-attr", &spec.join(";"))?;
    for (attr, id) in attrs {
        element.set_attribute(attr, &ctx::t(id))?;
    }
    Ok(())
}

/// Marks `element` as section `id` of its page ([`crate::view::sections`]), named in the
/// current language now and after every language switch.
pub fn mark_section(element: &Element, id: &str) -> Result<(), JsValue> {
    element.set_attribute("data-section", id)?;
    name_section(element)
}

/// `data-section-name`: the localized name of the element's `data-section`.
fn name_section(element: &Element) -> Result<(), JsValue> {
    if let Some(id) = element.get_attribute("data-section") {
        let name = ctx::t(&crate::view::sections::name_id(&id));
        element.set_attribute("data-section-name", &name)?;
    }
    Ok(())
}

/// Appends `child` to `parent`.
pub fn append(parent: &Element, child: &Element) -> Result<(), JsValue> {
    parent.append_child(child).map(|_| ())
}

/// Re-renders every `[data-i18n]` text and `[data-i18n-attr]` attribute in `root` (and root
/// itself) in the current language.
pub fn relocalize(root: &Element) -> Result<(), JsValue> {
    for element in matching(root, "[data-i18n]")? {
        if let Some(id) = element.get_attribute("data-i18n") {
            let text = ctx::t(&id);
            // Text that is already shown stays as it is (its node is not replaced).
            if element.text_content().as_deref() != Some(text.as_str()) {
                element.set_text_content(Some(&text));
            }
        }
    }
    for element in matching(root, "[data-section]")? {
        name_section(&element)?;
    }
    for element in matching(root, "[data-i18n-attr]")? {
        let Some(spec) = element.get_attribute("data-i18n-attr") else {
            continue;
        };
        for pair in spec.split(';') {
            if let Some((attr, id)) = pair.split_once('=') {
                element.set_attribute(attr.trim(), &ctx::t(id.trim()))?;
            }
        }
    }
    Ok(())
}

/// `root` (if it matches) and its descendants matching `selector`.
pub fn matching(root: &Element, selector: &str) -> Result<Vec<Element>, JsValue> {
    let mut out = Vec::new();
    if root.matches(selector)? {
        out.push(root.clone());
    }
    let list = root.query_selector_all(selector)?;
    for index in 0..list.length() {
        if let Some(element) = list.get(index).and_then(|n| n.dyn_into::<Element>().ok()) {
            out.push(element);
        }
    }
    Ok(out)
}

/// The element of `root` matching `selector`, as a `T`; the error names `owner` (the page)
/// and the selector.
pub fn find<T: JsCast>(root: &Element, selector: &str, owner: &str) -> Result<T, JsValue> {
    root.query_selector(selector)?
        .ok_or_else(|| JsValue::from_str(&format!("{owner}: missing {selector}")))?
        .dyn_into::<T>()
        .map_err(|_| JsValue::from_str(&format!("{owner}: wrong element type for {selector}")))
}

/// Shows or hides `element` (its `hidden` attribute).
pub fn show(element: &Element, visible: bool) {
    if visible {
        let _ = element.remove_attribute("hidden");
    } else {
        let _ = element.set_attribute("hidden", "");
    }
}

/// Removes every child of `element`.
pub fn clear(element: &Element) {
    while let Some(child) = element.first_child() {
        if element.remove_child(&child).is_err() {
            break;
        }
    }
}

/// Focuses `element` if it is an HTML element.
pub fn focus(element: &Element) {
    if let Some(html) = element.dyn_ref::<HtmlElement>() {
        let _ = html.focus();
    }
}

/// The value stored under `key` in localStorage; `None` when absent or when storage is
/// unavailable (private mode, disabled cookies, sandboxed frames).
pub fn storage_get(key: &str) -> Option<String> {
    let storage = web_sys::window()?.local_storage().ok()??;
    storage.get_item(key).ok()?
}

/// Stores `value` under `key` in localStorage; failures (quota, private mode) are ignored:
/// the choice then lasts only for this visit.
pub fn storage_set(key: &str, value: &str) {
    if let Some(Ok(Some(storage))) = web_sys::window().map(|w| w.local_storage()) {
        let _ = storage.set_item(key, value);
    }
}

/// Whether a key event comes from a place where the user types text (input, textarea,
/// select, contenteditable): shell and page keys must not fire there.
pub fn is_typing_target(target: Option<EventTarget>) -> bool {
    let Some(element) = target.and_then(|t| t.dyn_into::<Element>().ok()) else {
        return false;
    };
    let tag = element.tag_name().to_ascii_lowercase();
    if matches!(tag.as_str(), "input" | "textarea" | "select") {
        return true;
    }
    element
        .dyn_ref::<HtmlElement>()
        .is_some_and(|h| h.is_content_editable())
}

/// An event listener that stays attached while this value lives and is removed on drop.
pub struct Listener {
    target: EventTarget,
    event: &'static str,
    closure: Closure<dyn FnMut(Event)>,
    capture: bool,
}

impl Listener {
    /// Attaches `handler` for `event` on `target`.
    pub fn new(
        target: &EventTarget,
        event: &'static str,
        handler: impl FnMut(Event) + 'static,
    ) -> Result<Listener, JsValue> {
        Listener::attach(target, event, Closure::new(handler), false)
    }

    /// [`Listener::new`] in the capture phase: it runs before the listeners of the elements
    /// inside `target` and the bubbling ones on `target`, and may keep the event from them.
    pub fn capture(
        target: &EventTarget,
        event: &'static str,
        handler: impl FnMut(Event) + 'static,
    ) -> Result<Listener, JsValue> {
        Listener::attach(target, event, Closure::new(handler), true)
    }

    fn attach(
        target: &EventTarget,
        event: &'static str,
        closure: Closure<dyn FnMut(Event)>,
        capture: bool,
    ) -> Result<Listener, JsValue> {
        target.add_event_listener_with_callback_and_bool(
            event,
            closure.as_ref().unchecked_ref(),
            capture,
        )?;
        Ok(Listener {
            target: target.clone(),
            event,
            closure,
            capture,
        })
    }

    /// [`Listener::for_page`] in the capture phase: it runs before the listeners of the
    /// elements inside `target`, and may keep the event from them (`stopPropagation`).
    pub fn capture_for_page<P: 'static>(
        target: &EventTarget,
        event: &'static str,
        page: &Weak<P>,
        handler: impl Fn(&P, &Event) + 'static,
    ) -> Result<Listener, JsValue> {
        Listener::capture(target, event, while_mounted(page, handler))
    }

    /// Attaches `handler` for `event` on `target`, called with the page behind `page` while it
    /// is mounted (the page owns its listeners, so they hold it weakly).
    pub fn for_page<P: 'static>(
        target: &EventTarget,
        event: &'static str,
        page: &Weak<P>,
        handler: impl Fn(&P, &Event) + 'static,
    ) -> Result<Listener, JsValue> {
        Listener::new(target, event, while_mounted(page, handler))
    }

    /// Keeps the listener for the life of the page (shell listeners).
    pub fn forever(self) {
        std::mem::forget(self);
    }
}

/// `handler` called with the page behind `page` while it is mounted.
fn while_mounted<P: 'static>(
    page: &Weak<P>,
    handler: impl Fn(&P, &Event) + 'static,
) -> impl FnMut(Event) + 'static {
    let page = page.clone();
    move |e: Event| {
        if let Some(page) = page.upgrade() {
            handler(&page, &e);
        }
    }
}

impl Drop for Listener {
    fn drop(&mut self) {
        let _ = self.target.remove_event_listener_with_callback_and_bool(
            self.event,
            self.closure.as_ref().unchecked_ref(),
            self.capture,
        );
    }
}

/// `promise.then(ok, fail)`, called through `Reflect` to stay independent of js-sys's generic
/// `Promise` signatures.
pub fn then(promise: &js_sys::Promise, ok: &JsValue, fail: &JsValue) {
    let method = js_sys::Reflect::get(promise, &JsValue::from_str("then"))
        .ok()
        .and_then(|f| f.dyn_into::<js_sys::Function>().ok());
    if let Some(method) = method {
        let _ = method.call2(promise, ok, fail);
    }
}
