//! The session's episodes, one row each (number, label, category, duration, path, efficiency,
//! collisions, first failure) with Replay, Label and the episode's CSV download
//! (`data-download="teleop_episode_<n>.csv"`); the repeatability table (first session beside
//! the second); the session line and the texts of the two session downloads. Rebuilt when the
//! session changes and on a language switch.

use wasm_bindgen::prelude::*;
use web_sys::Element;

use crate::teleop::session::{
    episode_file_name, Session, EPISODES_NAME, EVIDENCE_NAME, RECORD_TARGET,
};
use crate::ui::{ctx, dom};
use crate::view::teleop::fixed_clean;

use super::label_panel::label_message;
use super::markup::{find, role};

/// The two tables, the session line and the session downloads.
pub struct EpisodeTables {
    episodes_body: Element,
    compare_body: Element,
    session_line: Element,
    downloads: Vec<(&'static str, Element)>,
}

impl EpisodeTables {
    /// Finds the tables under `root`.
    pub fn find(root: &Element) -> Result<EpisodeTables, JsValue> {
        let downloads = [EPISODES_NAME, EVIDENCE_NAME]
            .into_iter()
            .map(|name| {
                let el = find(root, &format!("button[data-download=\"{name}\"]"))?;
                Ok((name, el))
            })
            .collect::<Result<Vec<_>, JsValue>>()?;
        Ok(EpisodeTables {
            episodes_body: find(root, "[data-tele=\"episodes\"] tbody")?,
            compare_body: find(root, "[data-tele=\"compare\"] tbody")?,
            session_line: role(root, "session-line")?,
            downloads,
        })
    }

    /// Rebuilds them for `session` (and `first`, the first session, if any).
    pub fn render(&self, session: &Session, first: Option<&Session>) {
        if let Err(e) = render_episodes(&self.episodes_body, session) {
            web_sys::console::warn_1(&e);
        }
        let sum = session.summary();
        let first = first.map(Session::summary);
        if let Err(e) = crate::ui::kit::pilot_session::render_comparison(
            &self.compare_body,
            first.as_ref(),
            &sum,
        ) {
            web_sys::console::warn_1(&e);
        }
        let line = ctx::t_args(
            "teleop-session-line",
            &[
                ("pilot", session.pilot_id.clone().into()),
                ("attempted", sum.attempted.into()),
                ("successful", sum.successful.into()),
                ("target", RECORD_TARGET.into()),
            ],
        );
        self.session_line.set_text_content(Some(&line));
        for (name, button) in &self.downloads {
            button.set_text_content(Some(&ctx::t_strings(
                "teleop-download-file",
                &[("file", name.to_string())],
            )));
        }
    }
}

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
fn render_episodes(tbody: &Element, session: &Session) -> Result<(), JsValue> {
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
