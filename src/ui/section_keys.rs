//! Presenter remotes on pages that do not step: PageDown / PageUp (what a remote's buttons
//! send) go to the next / previous section of the page (its cards and headings) instead of
//! scrolling a screenful; past the last section PageDown opens the next drill of the seed's
//! chain, and PageUp at the top the previous one. A page that takes PageDown / PageUp itself
//! (a stepper) keeps them; nothing happens while the user types in a field. PageUp above the
//! first section goes back to the top of the page first.

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::{HtmlElement, KeyboardEvent};

use crate::ui::kit::keymap;
use crate::ui::{dom, drill_chain};

/// What counts as a section: the home page's cards, headings outside them, the drill chain.
const SECTIONS: &str =
    "#app-main .featured-card, #app-main .recipe-card, #app-main h2, #drill-chain:not([hidden])";

/// Pixels of slack: a section whose top is within this of the viewport's top is "here".
const SLACK_PX: f64 = 12.0;

/// Handles PageDown / PageUp the page did not take; true when it did something. `exists` says
/// which pages the drill chain may link to.
pub(crate) fn on_key(
    event: &KeyboardEvent,
    current_page: Option<&str>,
    exists: impl Fn(&str) -> bool,
) -> Result<bool, JsValue> {
    let forward = match event.key().as_str() {
        "PageDown" => true,
        "PageUp" => false,
        _ => return Ok(false),
    };
    if keymap::has_command_modifier(event) || event.shift_key() {
        return Ok(false);
    }
    if keymap::is_typing(event.target()) {
        return Ok(false);
    }
    let document = dom::document()?;
    let Some(root) = document.document_element() else {
        return Ok(false);
    };
    let mut sections: Vec<(f64, HtmlElement)> = dom::matching(&root, SECTIONS)?
        .into_iter()
        .filter_map(|e| e.dyn_into::<HtmlElement>().ok())
        .filter(|e| e.offset_parent().is_some())
        .map(|e| (e.get_bounding_client_rect().top(), e))
        .collect();
    sections.sort_by(|a, b| a.0.total_cmp(&b.0));
    // From the focused section (a press already landed there) in document order, else from
    // where the viewport stands.
    let active = document.active_element();
    let here = sections.iter().position(|(_, e)| {
        active
            .as_ref()
            .is_some_and(|a| a == e.as_ref() as &web_sys::Element)
    });
    // Sections side by side (the home page's tiles) are one row: a press goes to the first
    // section of the next or previous row.
    let from = here.map_or(0.0, |i| sections[i].0);
    let target = if forward {
        sections.into_iter().find(|(top, _)| *top > from + SLACK_PX)
    } else {
        let row = sections
            .iter()
            .map(|(top, _)| *top)
            .filter(|top| *top < from - SLACK_PX)
            .fold(f64::NEG_INFINITY, f64::max);
        sections
            .into_iter()
            .find(|(top, _)| (*top - row).abs() <= SLACK_PX)
    };
    if let Some((_, element)) = target {
        if element.get_attribute("tabindex").is_none() && element.tab_index() < 0 {
            element.set_attribute("tabindex", "-1")?;
        }
        element.scroll_into_view_with_bool(true);
        dom::focus(&element);
        return Ok(true);
    }
    let window = dom::window()?;
    if !forward && window.scroll_y()? > 1.0 {
        window.scroll_to_with_x_and_y(0.0, 0.0);
        if let Some(main) = document.get_element_by_id("app-main") {
            dom::focus(&main);
        }
        return Ok(true);
    }
    let neighbour = current_page
        .and_then(|page| drill_chain::neighbour_href(page, if forward { 1 } else { -1 }, exists));
    if let Some(href) = neighbour {
        // Start the next page from its top, not from the (persistent) chain at the foot.
        if let Some(main) = document.get_element_by_id("app-main") {
            dom::focus(&main);
        }
        window.location().set_hash(&href)?;
        return Ok(true);
    }
    Ok(false)
}
