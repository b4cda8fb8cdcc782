//! Loading the second stage ([`super::panels`]: heatmap, sweep plot, parameters form,
//! downloads), a wasm chunk of its own (`ik2r_more`) fetched as soon as the arm is live, and
//! the line that stands in for it: "loading" (`role="status"`) while the chunk comes, a
//! message with Retry (`role="alert"`) if it cannot be fetched.

use std::rc::Weak;

use wasm_bindgen::JsValue;
use web_sys::Element;

use super::panels::{self, BuildFn, PanelsHost};
use crate::ui::page::SplitLoaderError;
use crate::ui::page_frame;

/// The second stage's builder, once its chunk is in.
#[cfg(feature = "split")]
#[wasm_split_helpers::wasm_split(ik2r_more, fallible)]
fn second_stage() -> Result<BuildFn, SplitLoaderError> {
    Ok(panels::build)
}

/// Without the `split` feature the second stage is in the one wasm.
#[cfg(not(feature = "split"))]
async fn second_stage() -> Result<BuildFn, SplitLoaderError> {
    Ok(panels::build)
}

/// Loads the second stage and hands it to the page, removing `status`; if the chunk cannot
/// be fetched, `status` says so with a Retry button.
pub(super) fn load(page: Weak<dyn PanelsHost>, status: Element) {
    wasm_bindgen_futures::spawn_local(async move {
        let loaded = second_stage().await;
        // The page may have been left meanwhile.
        let Some(live) = page.upgrade() else {
            return;
        };
        let done = match loaded {
            Ok(build) => build(&live).map(|panels| {
                status.remove();
                live.panels_arrived(panels);
            }),
            Err(_) => show_failed(page, &status),
        };
        if let Err(error) = done {
            web_sys::console::error_1(&error);
        }
    });
}

/// `status` as the line that stands in for the second stage while its chunk loads.
pub(super) fn show_loading(status: &Element) -> Result<(), JsValue> {
    page_frame::show_part_loading(status, "ik2r-more-loading")
}

fn show_failed(page: Weak<dyn PanelsHost>, status: &Element) -> Result<(), JsValue> {
    let again = status.clone();
    page_frame::show_part_failed(status, "ik2r-more-failed", "ik2r-more-loading", move || {
        load(page.clone(), again.clone())
    })
}
