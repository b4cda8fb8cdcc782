//! The session's episodes, one row each (number, label, category, duration, path, efficiency,
//! collisions, first failure) with Replay, Label and the episode's CSV download
//! (`data-download="teleop_episode_<n>.csv"`); the repeatability table (first session beside
//! the second). Rebuilt when the session changes and on a language switch.

use wasm_bindgen::prelude::*;
use web_sys::Element;

use crate::teleop::session::{compare, episode_file_name, Session, Summary};
use crate::ui::{ctx, dom};
use crate::view::teleop::{comparison_cell, fixed_clean};

use super::label_panel::label_message;

fn cell(row: &Element, text: &str) -> Result<Element, JsValue> {
    let td = dom::el_text("td", "", text)?;
    dom::append(row, &td)?;
    Ok(td)
}

fn cell_i18n(row: &Element, id: &str) -> Result<(), JsValue> {
    let td = dom::el_i18n("td", "", id)?;
    dom::append(row, &td)
}

fn button(
    parent: &Element,
    attr: &str,
    value: &str,
    text: &str,
    i18n: bool,
) -> Result<(), JsValue> {
    let b = if i18n {
        dom::el_i18n("button", "button tele-small", text)?
    } else {
        dom::el_text("button", "button tele-small", text)?
    };
    b.set_attribute("type", "button")?;
    b.set_attribute(attr, value)?;
    dom::append(parent, &b)
}

/// Rebuilds the episodes table's body from `session`.
pub fn render_episodes(tbody: &Element, session: &Session) -> Result<(), JsValue> {
    dom::clear(tbody);
    for e in &session.episodes {
        let tr = dom::el("tr")?;
        tr.set_attribute("data-episode", &e.number.to_string())?;
        cell(&tr, &e.number.to_string())?;
        match e.label {
            Some(l) => cell_i18n(&tr, &label_message(l))?,
            None => cell_i18n(&tr, "teleop-unlabelled")?,
        }
        match e.category {
            Some(c) => cell_i18n(&tr, &format!("teleop-cat-{}", c.id()))?,
            None => {
                cell(&tr, "—")?;
            }
        }
        let m = &e.metrics;
        cell(&tr, &format!("{} s", fixed_clean(m.duration_s, 2)))?;
        cell(&tr, &format!("{} m", fixed_clean(m.path_m, 3)))?;
        cell(&tr, &fixed_clean(m.efficiency, 3))?;
        cell(&tr, &m.collisions.to_string())?;
        match &m.first_failure {
            Some((step, event)) => {
                let td = cell(&tr, "")?;
                td.set_text_content(Some(&ctx::t_strings(
                    "teleop-first-failure",
                    &[
                        ("event", ctx::t(&format!("teleop-ev-{}", event.id()))),
                        ("step", step.to_string()),
                    ],
                )));
            }
            None => {
                cell(&tr, "—")?;
            }
        }
        let actions = dom::el_class("td", "tele-actions")?;
        let n = e.number.to_string();
        button(&actions, "data-replay", &n, "teleop-replay", true)?;
        button(&actions, "data-relabel", &n, "teleop-relabel", true)?;
        let file = episode_file_name(e.number);
        button(
            &actions,
            "data-download",
            &file,
            &ctx::t_strings("teleop-download-file", &[("file", file.clone())]),
            false,
        )?;
        dom::append(&tr, &actions)?;
        dom::append(tbody, &tr)?;
    }
    Ok(())
}

/// Rebuilds the comparison table's body: `first` (if any) beside `second`.
pub fn render_comparison(
    tbody: &Element,
    first: Option<&Summary>,
    second: &Summary,
) -> Result<(), JsValue> {
    dom::clear(tbody);
    let empty = Summary::of(&[]);
    let (a, b) = match first {
        Some(f) => (f, second),
        None => (second, &empty),
    };
    for row in compare(a, b) {
        let tr = dom::el("tr")?;
        tr.set_attribute("data-compare", &row.id)?;
        let name = if crate::teleop::session::category_from_id(&row.id).is_some() {
            format!("teleop-cat-{}", row.id)
        } else {
            format!("teleop-cmp-{}", row.id)
        };
        cell_i18n(&tr, &name)?;
        cell(&tr, &comparison_cell(&row.id, row.first))?;
        let second = if first.is_some() { row.second } else { None };
        cell(&tr, &comparison_cell(&row.id, second))?;
        dom::append(tbody, &tr)?;
    }
    Ok(())
}
