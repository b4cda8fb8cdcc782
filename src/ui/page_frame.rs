//! What `<main>` shows while a page's chunk is on its way: the page's frame (its title and
//! one-line description, from the page table) with a "Loading this drill…" line and its
//! progress; and, if the chunk cannot be fetched (offline before it was cached, a missing
//! file), a message with a Retry button. Both are localized like the rest of the shell.

use wasm_bindgen::JsValue;
use web_sys::Element;

use crate::ui::dom;
use crate::ui::page::PageDef;

/// The frame of page `def` with its loading line, built into `main` (emptied first).
pub fn show_loading(main: &Element, def: &PageDef) -> Result<(), JsValue> {
    dom::clear(main);
    let section = frame(def)?;
    let line = dom::el_class("p", "page-loading-line")?;
    line.set_attribute("role", "status")?;
    line.set_attribute("data-testid", "page-loading")?;
    dom::append(&line, &dom::el_i18n("span", "", "page-loading")?)?;
    let progress = dom::el_class("progress", "page-loading-progress")?;
    progress.set_attribute("data-testid", "page-loading-progress")?;
    progress.set_attribute("aria-hidden", "true")?;
    dom::append(&line, &progress)?;
    dom::append(&section, &line)?;
    dom::append(main, &section)
}

/// Shows how much of the page's chunk has arrived (`loaded` of `total` bytes) on the loading
/// line, if it is shown.
pub fn show_progress(main: &Element, loaded: f64, total: f64) -> Result<(), JsValue> {
    if let Some(progress) = main.query_selector(".page-loading-progress")? {
        if total > 0.0 {
            progress.set_attribute("max", &format!("{total}"))?;
            progress.set_attribute("value", &format!("{}", loaded.min(total)))?;
        }
    }
    Ok(())
}

/// The frame of page `def` with the "could not be loaded" message and its Retry button
/// (`data-action="retry"`), built into `main`; returns the button.
pub fn show_failed(main: &Element, def: &PageDef) -> Result<Element, JsValue> {
    dom::clear(main);
    let section = frame(def)?;
    let alert = dom::el_class("div", "page-load-failed")?;
    alert.set_attribute("role", "alert")?;
    alert.set_attribute("data-testid", "page-load-failed")?;
    dom::append(&alert, &dom::el_i18n("p", "", "page-load-failed")?)?;
    let retry = retry_button()?;
    dom::append(&alert, &retry)?;
    dom::append(&section, &alert)?;
    dom::append(main, &section)?;
    Ok(retry)
}

/// The Retry button of a part that could not be fetched (`data-action="retry"`).
pub fn retry_button() -> Result<Element, JsValue> {
    let retry = dom::el_i18n("button", "tool-button", "page-load-retry")?;
    retry.set_attribute("type", "button")?;
    retry.set_attribute("data-action", "retry")?;
    Ok(retry)
}

/// `status` as the line that stands in for a part of the page while its chunk loads
/// (`role="status"`, `data-state="loading"`, the message `loading_id`).
pub fn show_part_loading(status: &Element, loading_id: &str) -> Result<(), JsValue> {
    dom::clear(status);
    status.set_attribute("data-state", "loading")?;
    status.set_attribute("role", "status")?;
    dom::set_i18n(status, loading_id)
}

/// `status` says that the part could not be fetched (`role="alert"`, `data-state="failed"`,
/// the message `failed_id`) with a Retry button, which shows the loading line
/// (`loading_id`) again and calls `retry`.
pub fn show_part_failed(
    status: &Element,
    failed_id: &str,
    loading_id: &'static str,
    retry: impl Fn() + 'static,
) -> Result<(), JsValue> {
    dom::clear(status);
    status.remove_attribute("data-i18n")?;
    status.set_attribute("data-state", "failed")?;
    status.set_attribute("role", "alert")?;
    dom::append(status, &dom::el_i18n("span", "", failed_id)?)?;
    dom::append(status, &dom::el_text("span", "", " ")?)?;
    let button = retry_button()?;
    dom::append(status, &button)?;
    let again = status.clone();
    dom::Listener::new(&button, "click", move |_| {
        if show_part_loading(&again, loading_id).is_ok() {
            retry();
        }
    })?
    .forever();
    Ok(())
}

fn frame(def: &PageDef) -> Result<Element, JsValue> {
    let section = dom::el_class("section", "page-frame")?;
    section.set_attribute("data-testid", "page-frame")?;
    section.set_attribute("data-page", def.id)?;
    dom::append(&section, &dom::el_i18n("h1", "", def.title_id)?)?;
    dom::append(
        &section,
        &dom::el_i18n("p", "page-frame-blurb", def.blurb_id)?,
    )?;
    Ok(section)
}
