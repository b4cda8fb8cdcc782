//! Loading the second stage ([`super::more`]: the exports panel and the PNG), a wasm chunk of
//! its own (`umeyama_more`) fetched as soon as the page is live, and the line that stands in
//! for it: "loading" (`role="status"`) while the chunk comes, a message with Retry
//! (`role="alert"`) if it cannot be fetched.

use std::rc::Rc;

use wasm_bindgen::JsValue;
use web_sys::Element;

use super::more::{self, BuildFn, More};
use crate::ui::page::SplitLoaderError;
use crate::ui::page_frame;

/// The second stage's builder, once its chunk is in.
#[cfg(feature = "split")]
#[wasm_split_helpers::wasm_split(umeyama_more, fallible)]
fn second_stage() -> Result<BuildFn, SplitLoaderError> {
    Ok(more::build)
}

/// Without the `split` feature the second stage is in the one wasm.
#[cfg(not(feature = "split"))]
async fn second_stage() -> Result<BuildFn, SplitLoaderError> {
    Ok(more::build)
}

/// What the page does with the built second stage.
pub(super) type Arrived = Rc<dyn Fn(Rc<dyn More>)>;

/// Loads the second stage, builds it under `root` and hands it to `arrived`, removing
/// `status`; if the chunk cannot be fetched, `status` says so with a Retry button.
pub(super) fn load(root: Element, status: Element, arrived: Arrived) {
    wasm_bindgen_futures::spawn_local(async move {
        let loaded = second_stage().await;
        // The page may have been left meanwhile.
        if !root.contains(Some(&status)) {
            return;
        }
        let done = match loaded {
            Ok(build) => build(&root).map(|more| {
                status.remove();
                arrived(more);
            }),
            Err(_) => show_failed(root, &status, arrived),
        };
        if let Err(error) = done {
            web_sys::console::error_1(&error);
        }
    });
}

/// `status` as the line that stands in for the second stage while its chunk loads.
pub(super) fn show_loading(status: &Element) -> Result<(), JsValue> {
    page_frame::show_part_loading(status, "umeyama-more-loading")
}

fn show_failed(root: Element, status: &Element, arrived: Arrived) -> Result<(), JsValue> {
    let again = status.clone();
    page_frame::show_part_failed(
        status,
        "umeyama-more-failed",
        "umeyama-more-loading",
        move || load(root.clone(), again.clone(), arrived.clone()),
    )
}
