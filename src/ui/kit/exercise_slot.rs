//! A page's exercises section as the page builds it: a heading (`data-section="exercises"`,
//! `data-testid="exercises"`) that costs the page's first load next to nothing. The list
//! itself ([`crate::ui::exercises`]: its cards, the progress, their strings and style) is a
//! wasm chunk of its own, fetched when the section comes within 400 px of the
//! viewport (an `IntersectionObserver`); if the chunk cannot be fetched the section says so,
//! and asks again when it next comes into view. The page lends the list its exercises and
//! model ([`PageLink`]) and owns the slot: dropping the page drops the list and its listeners.
//!
//! Every call here is made without a `Result` chain and the observer is made and driven
//! through `Reflect` (as [`crate::ui::kit::input_file`] reads files): this code is in every
//! page's first load, and bindings and error paths would be most of it.

use std::cell::{Cell, RefCell};
use std::rc::{Rc, Weak};

use js_sys::{Array, Function, Object, Reflect};
use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::Element;

use crate::ui::dom;
use crate::ui::kit::exercise_link::{ExerciseList, ListChunk, PageLink, WithModel};
use crate::ui::page::SplitLoaderError;
use crate::view::exercises::Exercise;

/// The section: its heading, then the line that says the list could not be loaded.
const MARKUP: &str = "<section class=\"exercises\" data-testid=\"exercises\" \
data-section=\"exercises\" aria-labelledby=\"exercises-heading\">\
<h2 class=\"ex-heading\" id=\"exercises-heading\" data-i18n=\"section-exercises\"></h2>\
<p class=\"ex-status\" role=\"alert\" hidden></p></section>";

/// An `IntersectionObserver` and its callback.
type Observer = (JsValue, Closure<dyn FnMut(Array)>);

/// The section's state: the list once here, the observer.
struct Slot {
    link: Rc<PageLink>,
    list: RefCell<Option<Box<dyn ExerciseList>>>,
    /// Whether the list's chunk is asked for or here (cleared by a failure).
    asked: Cell<bool>,
    observer: RefCell<Option<Observer>>,
}

/// A page's exercises section; dropping it drops its list.
pub struct ExerciseSlot(Rc<Slot>);

/// Lends a page's model (made from its live part `T`) to the exercises' `use_model`.
pub type Lend<T> = fn(&T, &mut dyn FnMut(&crate::view::exercises::PageModel));

impl ExerciseSlot {
    /// [`ExerciseSlot::new`] for a page whose live part `page` (held weakly: no model once the
    /// page is gone) makes its model with `lend`.
    pub fn lending<T: 'static>(
        root: &Element,
        exercises: &'static [Exercise],
        page: &Rc<T>,
        lend: Lend<T>,
    ) -> Result<ExerciseSlot, JsValue> {
        let page = Rc::downgrade(page);
        let with_model: WithModel = Box::new(move |use_model| {
            if let Some(page) = page.upgrade() {
                lend(&page, use_model);
            }
        });
        ExerciseSlot::new(root, exercises, with_model)
    }

    /// The section of `exercises` (a page's), last in the page's outer element under `root`
    /// (`<main>`), the list lent the page's model by `with_model` (see [`WithModel`]).
    pub fn new(
        root: &Element,
        exercises: &'static [Exercise],
        with_model: WithModel,
    ) -> Result<ExerciseSlot, JsValue> {
        let outer = root.first_element_child().unwrap_or_else(|| root.clone());
        outer.insert_adjacent_html("beforeend", MARKUP)?;
        let section = outer
            .last_element_child()
            .ok_or_else(|| JsValue::from_str("exercises"))?;
        dom::relocalize(&section)?;
        let slot = Rc::new(Slot {
            link: Rc::new(PageLink {
                exercises,
                root: root.clone(),
                section,
                with_model,
                opened_hash: dom::window()?.location().hash()?,
            }),
            list: RefCell::new(None),
            asked: Cell::new(false),
            observer: RefCell::new(None),
        });
        observe(&slot);
        Ok(ExerciseSlot(slot))
    }

    /// The page's state changed without an input on the page (see [`ExerciseList::changed`]).
    pub fn changed(&self) {
        if let Some(list) = self.0.list.borrow().as_ref() {
            list.changed();
        }
    }
}

impl Drop for ExerciseSlot {
    fn drop(&mut self) {
        if let Some((observer, _)) = self.0.observer.take() {
            call(&observer, "disconnect", &JsValue::UNDEFINED);
        }
    }
}

/// `target[name](arg)`, its result (`undefined` when it is no function or throws).
fn call(target: &JsValue, name: &str, arg: &JsValue) -> JsValue {
    Reflect::get(target, &JsValue::from_str(name))
        .ok()
        .and_then(|f| f.dyn_into::<Function>().ok())
        .and_then(|f| f.call1(target, arg).ok())
        .unwrap_or_default()
}

/// Asks for the list whenever the section comes within 400 px of the viewport.
fn observe(slot: &Rc<Slot>) {
    let weak = Rc::downgrade(slot);
    let callback = Closure::<dyn FnMut(Array)>::new(move |entries: Array| {
        let near = entries.iter().any(|entry| {
            Reflect::get(&entry, &JsValue::from_str("isIntersecting")).is_ok_and(|v| v.is_truthy())
        });
        if near {
            ask(&weak);
        }
    });
    let options = Object::new();
    let _ = Reflect::set(&options, &"rootMargin".into(), &"400px 0px".into());
    let class = Reflect::get(&js_sys::global(), &"IntersectionObserver".into())
        .ok()
        .and_then(|c| c.dyn_into::<Function>().ok());
    let Some(class) = class else { return };
    let Ok(observer) = Reflect::construct(&class, &Array::of2(callback.as_ref(), &options)) else {
        return;
    };
    call(&observer, "observe", &slot.link.section);
    *slot.observer.borrow_mut() = Some((observer, callback));
}

/// The exercises list: a wasm chunk of its own.
#[cfg(feature = "split")]
#[wasm_split_helpers::wasm_split(exercises, fallible)]
fn list_chunk() -> Result<ListChunk, SplitLoaderError> {
    Ok(crate::ui::exercises::CHUNK)
}

/// Without the `split` feature the list is in the one wasm.
#[cfg(not(feature = "split"))]
async fn list_chunk() -> Result<ListChunk, SplitLoaderError> {
    Ok(crate::ui::exercises::CHUNK)
}

/// Fetches the list's chunk once, then mounts the list (unless the page is gone); if the
/// chunk cannot be fetched, says so and lets the next sight of the section ask again.
fn ask(slot: &Weak<Slot>) {
    let Some(slot) = slot.upgrade() else { return };
    if slot.asked.replace(true) {
        return;
    }
    let weak = Rc::downgrade(&slot);
    wasm_bindgen_futures::spawn_local(async move {
        let chunk = list_chunk().await;
        let Some(slot) = weak.upgrade() else { return };
        let list = chunk.ok().and_then(|c| (c.mount)(slot.link.clone()).ok());
        slot.asked.set(list.is_some());
        if let Some(status) = slot.link.section.last_element_child() {
            // Its text only now: a live region says what changes in it.
            if list.is_none() {
                let _ = dom::set_i18n(&status, "exercises-load-failed");
            }
            dom::show(&status, list.is_none());
        }
        *slot.list.borrow_mut() = list;
    });
}
