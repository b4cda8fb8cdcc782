//! "Share" in the shell: the header button, and `open` (also `S` while presenting), which
//! fetches the share dialog's chunk ([`crate::ui::share_dialog`]: the QR encoder and its
//! drawing, in no page's first load) on first use and opens it on the address of the press.

use wasm_bindgen::prelude::*;
use web_sys::Element;

use crate::ui::split_point::split_point;
use crate::ui::{ctx, dom, share_dialog};

const STATUS_ID: &str = "share-status";
/// The button (an icon named by its label: the header has no room for a word at 1366 px; the
/// icon is a QR code's three finder squares and two modules) and the line under it that says
/// when the dialog's code could not be fetched, empty and so silent until then. Markup, the
/// cheapest way to build them in the shell: no style attribute, so the CSP allows it.
const MARKUP: &str = "<button type=button class=tool-button data-action=share \
data-i18n-attr='aria-label=share-button;title=share-button-title'>\
<svg class=share-icon viewBox='0 0 10 10' aria-hidden=true><path fill=currentColor \
fill-rule=evenodd d='M0 0h4v4H0zm1 1v2h2V1zm5-1h4v4H6zm1 1v2h2V1zM0 6h4v4H0zm1 1v2h2V7zm5-1h2v2H6zm2 2h2v2H8z'/>\
</svg></button><span id=share-status class=tool-status role=alert></span>";

/// The header's "Share" button and its status line.
pub(crate) fn build_button() -> Result<Element, JsValue> {
    let wrap = dom::el_class("span", "tool-wrap")?;
    wrap.set_inner_html(MARKUP);
    dom::relocalize(&wrap)?;
    dom::Listener::new(&wrap, "click", |_| open())?.forever();
    Ok(wrap)
}

/// What opens the dialog on an address ([`share_dialog::open`]).
type OpenDialog = fn(&str) -> Result<(), JsValue>;

// The share dialog: a wasm chunk of its own, fetched on the first "Share".
split_point!(share_dialog, fn dialog_opener() -> OpenDialog = share_dialog::open);

/// Opens the share dialog on the address as it is now, once the dialog's code is here; if it
/// cannot be fetched, says so under the button (the next press tries again).
pub(crate) fn open() {
    let Ok(link) = dom::window().and_then(|w| w.location().href()) else {
        return;
    };
    wasm_bindgen_futures::spawn_local(async move {
        let loaded = dialog_opener().await;
        if let Some(status) = dom::document()
            .ok()
            .and_then(|d| d.get_element_by_id(STATUS_ID))
        {
            let failed = loaded.is_err();
            status.set_class_name(if failed {
                "tool-status tool-failed"
            } else {
                "tool-status"
            });
            status.set_text_content(failed.then(|| ctx::t("share-failed")).as_deref());
        }
        if let Ok(Err(error)) = loaded.map(|open| open(&link)) {
            web_sys::console::error_2(&"BSV Playground:".into(), &error);
        }
    });
}
