//! An input file the user opens (a trajectory CSV, or several progress files): the file (or
//! files) chosen in an `<input type="file">` or dropped on the page, its name and size (checked against the kernel's limit
//! before anything is read), then its bytes decoded by the kernels' one policy,
//! [`crate::recipes::decode_input`] (UTF-8, a byte-order mark allowed, anything else refused
//! with the byte offset), exactly as `bsv` decodes the file it reads from disk. Only `Blob` of
//! web-sys is needed: the `File`, its list and the drop's `dataTransfer` are read through
//! `Reflect`.

use std::cell::RefCell;
use std::rc::Rc;

use js_sys::{Reflect, Uint8Array};
use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::{Blob, Event, HtmlInputElement};

use crate::error::RecipeError;
use crate::recipes::decode_input;
use crate::ui::dom;

/// A file the user picked: its name, size in bytes and the file itself.
pub struct Picked {
    pub name: String,
    pub bytes: u64,
    pub blob: Blob,
}

/// Why an opened file gave no text.
#[derive(Debug, Clone, PartialEq)]
pub enum ReadProblem {
    /// The browser could not read it (its message).
    Browser(String),
    /// Not UTF-8 ([`RecipeError::InputNotUtf8`], with the byte offset).
    Decode(RecipeError),
}

fn first_file(files: &JsValue) -> Option<Picked> {
    nth_file(files, 0)
}

/// File `n` of a `FileList` (`None` past its end).
fn nth_file(files: &JsValue, n: u32) -> Option<Picked> {
    if files.is_null() || files.is_undefined() {
        return None;
    }
    let file = Reflect::get_u32(files, n).ok()?;
    if file.is_null() || file.is_undefined() {
        return None;
    }
    let name = Reflect::get(&file, &JsValue::from_str("name"))
        .ok()
        .and_then(|n| n.as_string())
        .unwrap_or_default();
    let blob: Blob = file.dyn_into().ok()?;
    let size = blob.size();
    let bytes = if size.is_finite() && size > 0.0 {
        size as u64
    } else {
        0
    };
    Some(Picked { name, bytes, blob })
}

/// The file chosen in `input`.
pub fn chosen(input: &HtmlInputElement) -> Option<Picked> {
    let files = Reflect::get(input, &JsValue::from_str("files")).ok()?;
    first_file(&files)
}

/// The first file of a `drop` event (`None` for dropped text or links).
pub fn dropped(event: &Event) -> Option<Picked> {
    first_file(&dropped_files(event)?)
}

/// The `FileList` of a `drop` event.
fn dropped_files(event: &Event) -> Option<JsValue> {
    let transfer = Reflect::get(event, &JsValue::from_str("dataTransfer")).ok()?;
    if transfer.is_null() || transfer.is_undefined() {
        return None;
    }
    Reflect::get(&transfer, &JsValue::from_str("files")).ok()
}

/// Every file of a `FileList`, in order.
fn every_file(files: &JsValue) -> Vec<Picked> {
    (0..).map_while(|n| nth_file(files, n)).collect()
}

/// Every file chosen in `input` (an `<input type="file" multiple>`), in order.
pub fn all_chosen(input: &HtmlInputElement) -> Vec<Picked> {
    Reflect::get(input, &JsValue::from_str("files"))
        .map(|files| every_file(&files))
        .unwrap_or_default()
}

/// Every file of a `drop` event, in order (none for dropped text or links).
pub fn all_dropped(event: &Event) -> Vec<Picked> {
    dropped_files(event)
        .map(|files| every_file(&files))
        .unwrap_or_default()
}

/// Whether a drag carries files (for `dragover`: only then is the drop taken).
pub fn drags_files(event: &Event) -> bool {
    let Ok(transfer) = Reflect::get(event, &JsValue::from_str("dataTransfer")) else {
        return false;
    };
    let Ok(types) = Reflect::get(&transfer, &JsValue::from_str("types")) else {
        return false;
    };
    js_sys::Array::from(&types)
        .iter()
        .any(|t| t.as_string().as_deref() == Some("Files"))
}

/// Reads `blob` (the file `name`) and decodes it as the CLI does; `done` gets the text or
/// the problem.
pub fn read_text(
    name: &str,
    blob: &Blob,
    done: impl FnOnce(Result<String, ReadProblem>) + 'static,
) {
    let done = Rc::new(RefCell::new(Some(done)));
    let finish = {
        let done = done.clone();
        move |result: Result<String, ReadProblem>| {
            if let Some(done) = done.borrow_mut().take() {
                done(result);
            }
        }
    };
    let finish = Rc::new(finish);
    let name = name.to_string();
    let ok = {
        let finish = finish.clone();
        Closure::once_into_js(move |buffer: JsValue| {
            let bytes = Uint8Array::new(&buffer).to_vec();
            finish(decode_input(&name, &bytes).map_err(ReadProblem::Decode))
        })
    };
    let fail = Closure::once_into_js(move |error: JsValue| {
        let reason = Reflect::get(&error, &JsValue::from_str("message"))
            .ok()
            .and_then(|m| m.as_string())
            .or_else(|| error.as_string())
            .unwrap_or_default();
        finish(Err(ReadProblem::Browser(reason)))
    });
    dom::then(&blob.array_buffer(), &ok, &fail);
}
