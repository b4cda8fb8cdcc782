//! A page's root element, as every page mounts it: filled with the page's markup and
//! localized (every `data-i18n`), its parts then found by their `data-<prefix>` role.

use std::ops::Deref;

use wasm_bindgen::{JsCast, JsValue};
use web_sys::Element;

use crate::ui::dom;
use crate::ui::page_frame;

/// The page's root (`<main>`), derefs to the element.
#[derive(Clone)]
pub struct PageRoot {
    element: Element,
    /// The `data-` attribute of the page's parts: `data-<prefix>="stage"`.
    prefix: &'static str,
    /// Who is missing an element, in the error ("umeyama: missing …").
    owner: &'static str,
}

impl PageRoot {
    /// Fills `root` with `html` and localizes it.
    pub fn fill(
        root: &Element,
        html: &str,
        prefix: &'static str,
        owner: &'static str,
    ) -> Result<PageRoot, JsValue> {
        page_frame::fill(root, html)?;
        dom::relocalize(root)?;
        Ok(PageRoot {
            element: root.clone(),
            prefix,
            owner,
        })
    }

    /// The part `data-<prefix>="<name>"`.
    pub fn role<T: JsCast>(&self, name: &str) -> Result<T, JsValue> {
        self.find(&format!("[data-{}=\"{name}\"]", self.prefix))
    }

    /// The first element matching `selector`.
    pub fn find<T: JsCast>(&self, selector: &str) -> Result<T, JsValue> {
        dom::find(&self.element, selector, self.owner)
    }
}

impl Deref for PageRoot {
    type Target = Element;

    fn deref(&self) -> &Element {
        &self.element
    }
}
