//! Opening an input CSV (a file argument, traj-resample's) from an `<input type="file">`: the chosen file's name and
//! size (checked against the kernel's limit before anything is read), then its text through
//! `Blob.text()` (UTF-8, a byte-order mark dropped). Only `Blob` of web-sys is needed: the
//! `File` and its list are read through `Reflect`.

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::{Blob, HtmlInputElement};

use crate::error::RecipeError;
use crate::recipes::traj_resample::Shape;
use crate::ui::dom;

/// Input files up to this size are attached to every check of the form (so that their errors
/// show at once and the run size is known); bigger ones are checked by the run itself.
pub const PRECHECK_MAX_BYTES: u64 = 4 * 1024 * 1024;

/// A CSV the user opened.
pub struct InputFile {
    /// The file's name (the recipe's `csv_path`).
    pub name: String,
    /// Size in bytes.
    pub bytes: u64,
    pub text: String,
    /// Its shape (rows, joint columns), read when opened.
    pub shape: Result<Shape, RecipeError>,
}

/// The file chosen in `input`: its name, size in bytes and the file itself.
pub fn chosen(input: &HtmlInputElement) -> Option<(String, u64, Blob)> {
    let files = js_sys::Reflect::get(input, &JsValue::from_str("files")).ok()?;
    if files.is_null() || files.is_undefined() {
        return None;
    }
    let file = js_sys::Reflect::get_u32(&files, 0).ok()?;
    if file.is_null() || file.is_undefined() {
        return None;
    }
    let name = js_sys::Reflect::get(&file, &JsValue::from_str("name"))
        .ok()
        .and_then(|n| n.as_string())
        .unwrap_or_default();
    let blob: Blob = file.unchecked_into();
    let size = blob.size();
    let bytes = if size.is_finite() && size > 0.0 {
        size as u64
    } else {
        0
    };
    Some((name, bytes, blob))
}

/// Reads `blob` as UTF-8 text; `done` gets the text or the browser's reason for failing.
pub fn read_text(blob: &Blob, done: impl FnOnce(Result<String, String>) + 'static) {
    let done = std::rc::Rc::new(std::cell::RefCell::new(Some(done)));
    let finish = move |result: Result<String, String>| {
        if let Some(done) = done.borrow_mut().take() {
            done(result);
        }
    };
    let finish = std::rc::Rc::new(finish);
    let ok = {
        let finish = finish.clone();
        Closure::once_into_js(move |text: JsValue| {
            finish(text.as_string().ok_or_else(|| "not text".to_string()))
        })
    };
    let fail = Closure::once_into_js(move |error: JsValue| {
        let reason = js_sys::Reflect::get(&error, &JsValue::from_str("message"))
            .ok()
            .and_then(|m| m.as_string())
            .or_else(|| error.as_string())
            .unwrap_or_default();
        finish(Err(reason))
    });
    dom::then(&blob.text(), &ok, &fail);
}
