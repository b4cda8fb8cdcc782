//! Saving files from the page: a Blob (text or CSV made on the page, or a file a worker run
//! built) through a temporary object URL, and a canvas as PNG, both by clicking a temporary
//! `<a download>`; no server round trip. One helper, [`download_blob`], serves every Blob.

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::{Blob, BlobPropertyBag, HtmlAnchorElement, HtmlCanvasElement, Url};

fn click_link(href: &str, file_name: &str) -> Result<(), JsValue> {
    let document = web_sys::window()
        .and_then(|w| w.document())
        .ok_or_else(|| JsValue::from_str("no document"))?;
    let anchor = document
        .create_element("a")?
        .dyn_into::<HtmlAnchorElement>()?;
    anchor.set_href(href);
    anchor.set_download(file_name);
    anchor.set_attribute("hidden", "")?;
    let body = document
        .body()
        .ok_or_else(|| JsValue::from_str("no body"))?;
    body.append_child(&anchor)?;
    anchor.click();
    anchor.remove();
    Ok(())
}

/// How long an object URL of a download lives, ms: the browser reads it after the click
/// returns, and a large Blob may take a while to be written.
const REVOKE_AFTER_MS: i32 = 60_000;

/// Offers `text` for download as `file_name` with MIME type `mime` (e.g. `text/csv`). The
/// bytes are exactly the UTF-8 of `text`.
pub fn download_text(file_name: &str, text: &str, mime: &str) -> Result<(), JsValue> {
    let parts = js_sys::Array::new();
    parts.push(&JsValue::from_str(text));
    let options = BlobPropertyBag::new();
    options.set_type(mime);
    let blob = Blob::new_with_str_sequence_and_options(&parts, &options)?;
    download_blob(&blob, file_name)
}

/// Offers `blob` for download as `file_name`: an object URL on a temporary `<a download>`,
/// revoked a minute later. Nothing is read or copied on the main thread, whatever the size.
pub fn download_blob(blob: &Blob, file_name: &str) -> Result<(), JsValue> {
    let url = Url::create_object_url_with_blob(blob)?;
    let result = click_link(&url, file_name);
    let revoke = Closure::once_into_js(move || {
        let _ = Url::revoke_object_url(&url);
    });
    if let Some(window) = web_sys::window() {
        window.set_timeout_with_callback_and_timeout_and_arguments_0(
            revoke.unchecked_ref(),
            REVOKE_AFTER_MS,
        )?;
    }
    result
}

/// Offers the pixels of `canvas` as a PNG called `file_name`.
pub fn download_canvas_png(canvas: &HtmlCanvasElement, file_name: &str) -> Result<(), JsValue> {
    let data_url = canvas.to_data_url_with_type("image/png")?;
    click_link(&data_url, file_name)
}
