//! The cue that the navigation strip scrolls: at phone width the links are one row that
//! scrolls sideways, and the strip marks the side where links are hidden
//! (`data-more-after`, `data-more-before` on the `<nav>`; the stylesheet fades that edge and
//! shows an arrow there). Kept up to date on the strip's scroll and on any change of its
//! size or its links' sizes (a narrower window, the other language).

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::{Element, ResizeObserver};

use crate::ui::dom::{self, Listener};

/// A pixel of slack: a strip scrolled to within a pixel of an end counts as at that end.
const SLACK_PX: i32 = 1;

/// Watches `list` (the strip that scrolls) for the life of the page and marks `nav`.
pub(crate) fn install(nav: &Element, list: &Element) -> Result<(), JsValue> {
    let update = {
        let (nav, list) = (nav.clone(), list.clone());
        move || mark(&nav, &list)
    };
    let on_scroll = update.clone();
    Listener::new(list, "scroll", move |_| on_scroll()).map(Listener::forever)?;
    let callback = Closure::<dyn FnMut(JsValue)>::new(move |_entries: JsValue| update());
    let observer = ResizeObserver::new(callback.as_ref().unchecked_ref())?;
    observer.observe(list);
    for item in dom::matching(list, ":scope > li")? {
        observer.observe(&item);
    }
    // The shell's header lives as long as the page: so do its observer and callback.
    callback.forget();
    std::mem::forget(observer);
    Ok(())
}

/// Sets the two marks from the strip's scroll position.
fn mark(nav: &Element, list: &Element) {
    let hidden = list.scroll_width() - list.client_width();
    let left = list.scroll_left();
    set_flag(
        nav,
        "data-more-before",
        hidden > SLACK_PX && left > SLACK_PX,
    );
    set_flag(
        nav,
        "data-more-after",
        hidden > SLACK_PX && left < hidden - SLACK_PX,
    );
}

fn set_flag(element: &Element, name: &str, on: bool) {
    let has = element.has_attribute(name);
    if on && !has {
        let _ = element.set_attribute(name, "");
    } else if !on && has {
        let _ = element.remove_attribute(name);
    }
}
