//! The foot of every drill page: the seed's "next step" sentence with a link to the next
//! drill, and the whole chain (pendulum → … → Robot Pilot practice) as a strip of links with
//! the page's own steps marked ([`crate::view::drill_chain`]). Hidden on pages off the chain.
//! Which pages exist (a step links to its recipe's page when there is one) comes from the
//! shell's page table, as `exists`.

use wasm_bindgen::prelude::*;
use web_sys::Element;

use crate::recipes;
use crate::ui::{dom, router};
use crate::view::drill_chain::{self, CHAIN};

const CHAIN_ID: &str = "drill-chain";

fn page_of(recipe: &str) -> Option<&'static str> {
    recipes::page_of(recipe)
}

fn href(step: &str, exists: impl Fn(&str) -> bool) -> Option<String> {
    drill_chain::link(step, page_of, exists).map(|l| router::build_hash(l.page, &l.query))
}

/// The (empty, hidden) element the shell places between `<main>` and the footer.
pub(crate) fn build() -> Result<Element, JsValue> {
    dom::hidden_landmark("nav", CHAIN_ID, "chain-label")
}

/// Fills the chain for page `current` (or hides it off the chain).
pub(crate) fn route_changed(current: &str, exists: impl Fn(&str) -> bool) -> Result<(), JsValue> {
    let Some(nav) = dom::document()?.get_element_by_id(CHAIN_ID) else {
        return Ok(());
    };
    dom::clear(&nav);
    let mine = drill_chain::positions_of_page(current, page_of);
    let Some(&primary) = mine.first() else {
        dom::show(&nav, false);
        return Ok(());
    };
    dom::show(&nav, true);

    let heading = dom::el_i18n("h2", "chain-title", "chain-title")?;
    dom::append(&nav, &heading)?;
    if let Some(next) = CHAIN
        .get(primary + 1)
        .and_then(|step| href(step, &exists).map(|h| (step, h)))
    {
        let line = dom::el_class("p", "chain-next")?;
        line.set_attribute("data-testid", "chain-next")?;
        let sentence = dom::el_i18n("span", "", &drill_chain::next_sentence_id(CHAIN[primary]))?;
        dom::append(&line, &sentence)?;
        let open = dom::el_i18n("a", "chain-next-link", &drill_chain::label_id(next.0))?;
        open.set_attribute("href", &next.1)?;
        open.set_attribute("data-testid", "chain-next-link")?;
        dom::append(&line, &open)?;
        dom::append(&nav, &line)?;
    }

    let list = dom::el_class("ol", "chain-steps")?;
    for (i, step) in CHAIN.iter().enumerate() {
        let Some(target) = href(step, &exists) else {
            continue;
        };
        let item = dom::el("li")?;
        let link = dom::el_i18n("a", "chain-step", &drill_chain::label_id(step))?;
        link.set_attribute("href", &target)?;
        link.set_attribute("data-step", step)?;
        if mine.contains(&i) {
            link.set_attribute("aria-current", "step")?;
        }
        dom::append(&item, &link)?;
        dom::append(&list, &item)?;
    }
    dom::append(&nav, &list)?;
    Ok(())
}

/// The href of the drill before (`delta` = -1) or after (+1) page `current` in the chain, for
/// presenter remotes at the top or the end of a page.
pub(crate) fn neighbour_href(
    current: &str,
    delta: isize,
    exists: impl Fn(&str) -> bool,
) -> Option<String> {
    // From the step whose "next step" sentence the page shows (the IK page: the workspace).
    let from = drill_chain::primary_position(current, page_of)?;
    let to = from.checked_add_signed(delta)?;
    CHAIN.get(to).and_then(|step| href(step, exists))
}
