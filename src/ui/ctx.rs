//! The app context of this browser tab: the Fluent bundles (each file added when it is
//! loaded, [`crate::ui::lang_files`]), the current language and whether projector mode is on.
//! One per thread (the wasm main thread), held in `thread_local!` cells so that pages read it
//! from anywhere without threading a handle through every call.
//!
//! Reading never panics: the language and projector flags are `Cell`s, the bundles only grow,
//! and missing messages are logged with `console.warn` (once each).

use std::cell::Cell;

use crate::error::RecipeError;
use crate::i18n::{FluentArg, I18n, Lang};

thread_local! {
    /// The app starts with no language and loads its first before the shell is built; unit
    /// tests have both at once.
    static I18N: I18n = first_bundles();
    static LANG: Cell<Lang> = const { Cell::new(Lang::En) };
    static PROJECTOR: Cell<bool> = const { Cell::new(false) };
}

#[cfg(not(test))]
fn first_bundles() -> I18n {
    I18n::empty()
}

#[cfg(test)]
fn first_bundles() -> I18n {
    I18n::new()
}

/// The current UI language.
pub fn lang() -> Lang {
    LANG.with(Cell::get)
}

/// Sets the current language. Only the shell calls this (it also re-renders the page).
pub(crate) fn set_lang(lang: Lang) {
    LANG.with(|cell| cell.set(lang));
}

/// Whether `lang`'s Fluent file `name` is loaded.
pub fn has_file(lang: Lang, name: &str) -> bool {
    I18N.try_with(|i18n| i18n.has_file(lang, name))
        .unwrap_or(false)
}

/// Adds `lang`'s Fluent files (file name, text) to the bundles.
pub(crate) fn add_files(lang: Lang, files: &[(&str, &str)]) {
    let _ = I18N.try_with(|i18n| i18n.add_files(lang, files));
}

/// Parses a piece (a few KB) of `lang`'s added Fluent files that no message has needed yet;
/// whether more are waiting ([`crate::i18n::I18n::build_next`]).
pub(crate) fn build_next_piece(lang: Lang) -> bool {
    I18N.try_with(|i18n| i18n.build_next(lang)).unwrap_or(false)
}

/// Whether projector mode (larger type, thicker lines, high contrast) is on.
pub fn projector() -> bool {
    PROJECTOR.with(Cell::get)
}

/// Sets projector mode. Only the shell calls this (it also tells the page).
pub(crate) fn set_projector(on: bool) {
    PROJECTOR.with(|cell| cell.set(on));
}

/// Message `id` in the current language.
pub fn t(id: &str) -> String {
    t_in(lang(), id)
}

/// Message `id` in the current language, with arguments (numbers may be passed as numbers:
/// `("n", 3.into())`).
pub fn t_args(id: &str, args: &[(&str, FluentArg)]) -> String {
    let lang = lang();
    with_i18n(|i18n| i18n.t_args(lang, id, args)).unwrap_or_else(|| id.to_string())
}

/// [`t_args`] with text arguments: `("name", value)`.
pub fn t_strings(id: &str, args: &[(&str, String)]) -> String {
    let args: Vec<(&str, FluentArg)> = args.iter().map(|(k, v)| (*k, v.clone().into())).collect();
    t_args(id, &args)
}

/// Whether message `id` exists in the current language (both languages have the same ids;
/// the other language may not be loaded yet).
pub fn has_message(id: &str) -> bool {
    let lang = lang();
    I18N.try_with(|i18n| i18n.has_message(lang, id))
        .unwrap_or(false)
}

/// Message `id` in a given language.
pub fn t_in(lang: Lang, id: &str) -> String {
    with_i18n(|i18n| i18n.t(lang, id)).unwrap_or_else(|| id.to_string())
}

/// The localized message of a kernel error, in the current language.
pub fn error_text(error: &RecipeError) -> String {
    let lang = lang();
    with_i18n(|i18n| i18n.recipe_error(lang, error)).unwrap_or_else(|| error.to_string())
}

/// Runs `f` on the bundles and logs any new warnings with `console.warn`. `None` only while
/// the thread is shutting down.
fn with_i18n<R>(f: impl FnOnce(&I18n) -> R) -> Option<R> {
    I18N.try_with(|i18n| {
        let result = f(i18n);
        for warning in i18n.take_warnings() {
            web_sys::console::warn_1(&format!("i18n: {warning}").into());
        }
        result
    })
    .ok()
}

/// Smallest type in projector mode, CSS px: every text, canvas labels included, is at least
/// this big at 1920×1080.
pub const PROJECTOR_MIN_FONT_PX: f64 = 24.0;

/// The canvas font size for a label of `base_px` CSS px: `base_px` normally, in projector mode
/// 1.6 × `base_px` but never under [`PROJECTOR_MIN_FONT_PX`] (an 11 px tick label becomes
/// 24 px, a 16 px title 25.6 px).
pub fn canvas_font_px(base_px: f64) -> f64 {
    scaled_font_px(base_px, projector())
}

/// [`canvas_font_px`] for a given projector state.
pub fn scaled_font_px(base_px: f64, projector: bool) -> f64 {
    if projector {
        (base_px * 1.6).max(PROJECTOR_MIN_FONT_PX)
    } else {
        base_px
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use wasm_bindgen_test::wasm_bindgen_test as test;

    #[test]
    fn projector_type_is_never_under_24_px() {
        assert_eq!(scaled_font_px(11.0, false), 11.0);
        assert_eq!(scaled_font_px(11.0, true), 24.0);
        assert_eq!(scaled_font_px(16.0, true), 25.6);
        for base in [8.0, 10.0, 12.0, 14.0, 20.0] {
            assert!(scaled_font_px(base, true) >= PROJECTOR_MIN_FONT_PX);
        }
    }
}
