//! A part of a page that has Fluent files of its own, beyond its page's `page!` line (the
//! exercises list, the home page's progress), follows the language: when the shell switches it
//! (`<html lang>` changes), the part's files are fetched in the new language, then the part is
//! drawn again. Its fixed texts are marked `data-l10n="<id>"` ([`draw_texts`]), not the
//! shell's `data-i18n`: the shell draws those at once, before the part's files are in.

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::{MutationObserver, MutationObserverInit};

use crate::ui::{ctx, dom, lang_files};

/// Draws every `[data-l10n]` text of `root` in the current language (text already shown is
/// left as it is).
pub fn draw_texts(root: &web_sys::Element) -> Result<(), JsValue> {
    for element in dom::matching(root, "[data-l10n]")? {
        if let Some(id) = element.get_attribute("data-l10n") {
            let text = ctx::t(&id);
            if element.text_content().as_deref() != Some(text.as_str()) {
                element.set_text_content(Some(&text));
            }
        }
    }
    Ok(())
}

/// Follows the language while it lives.
pub struct LangFollow {
    observer: MutationObserver,
    _callback: Closure<dyn FnMut()>,
}

impl LangFollow {
    /// Calls `redraw` after every switch of language, once `files` are loaded in it.
    pub fn new(
        files: &'static [&'static str],
        redraw: impl Fn() + 'static,
    ) -> Result<LangFollow, JsValue> {
        let redraw = std::rc::Rc::new(redraw);
        let callback = Closure::<dyn FnMut()>::new(move || {
            let redraw = redraw.clone();
            wasm_bindgen_futures::spawn_local(async move {
                if lang_files::load(ctx::lang(), files).await.is_ok() {
                    redraw();
                }
            });
        });
        let observer = MutationObserver::new(callback.as_ref().unchecked_ref())?;
        let options = MutationObserverInit::new();
        // A filter alone observes the attributes it names.
        options.set_attribute_filter(&js_sys::Array::of1(&JsValue::from_str("lang")));
        if let Some(html) = dom::document()?.document_element() {
            observer.observe_with_options(&html, &options)?;
        }
        Ok(LangFollow {
            observer,
            _callback: callback,
        })
    }
}

impl Drop for LangFollow {
    fn drop(&mut self) {
        self.observer.disconnect();
    }
}
