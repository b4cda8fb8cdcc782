//! The class page's two tables: learners by exercises (`data-testid="class-table"`, a row per
//! learner with `data-learner`, each cell a mark with its standing in words for screen
//! readers) and the exercises hardest first with their success rates. Text from the files
//! (learner and file names) is escaped: a file is the teacher's learners', not the app's.

use wasm_bindgen::prelude::*;
use web_sys::Element;

use crate::i18n::fluent_args;
use crate::numtext::fixed;
use crate::ui::ctx;
use crate::ui::kit::form::escape;
use crate::ui::page::ShellLink;
use crate::view::class_summary::ClassSummary;
use crate::view::exercises::PAGE_IDS;
use crate::view::learner_progress::Standing;

/// The mark of a standing in a cell.
fn mark(standing: Standing) -> &'static str {
    match standing {
        Standing::FirstTry => "✓",
        Standing::Later => "◐",
        Standing::NotYet => "·",
    }
}

/// A rate, 0 to 1, as `63 %` (`—` without learners).
fn rate_text(rate: Option<f64>) -> String {
    rate.map_or_else(
        || "—".to_owned(),
        |r| {
            ctx::t_args(
                "class-rate-value",
                &fluent_args(vec![("rate", fixed(100.0 * r, 0))]),
            )
        },
    )
}

/// The table of learners by exercises (hardest first), with each exercise's success rate in
/// its foot, into `container`.
pub fn draw_learners(container: &Element, summary: &ClassSummary) -> Result<(), JsValue> {
    let standing_words = [Standing::FirstTry, Standing::Later, Standing::NotYet]
        .map(|s| (s, escape(&ctx::t(&format!("class-standing-{}", s.key())))));
    let words = |s: Standing| {
        standing_words
            .iter()
            .find(|(k, _)| *k == s)
            .map_or("", |(_, w)| w.as_str())
    };
    let mut html = format!(
        "<table class=\"class-table\" data-testid=\"class-table\"><thead><tr>\
<th scope=\"col\">{}</th><th scope=\"col\">{}</th>",
        escape(&ctx::t("class-learner")),
        escape(&ctx::t("class-file"))
    );
    for column in &summary.exercises {
        html.push_str(&format!(
            "<th scope=\"col\" class=\"class-ex\" data-exercise=\"{id}\"><span>{id}</span></th>",
            id = escape(&column.id)
        ));
    }
    html.push_str("</tr></thead><tbody>");
    for row in &summary.learners {
        let learner = escape(&row.learner);
        html.push_str(&format!(
            "<tr data-learner=\"{learner}\"><th scope=\"row\">{learner}</th><td class=\"class-file\">{}</td>",
            escape(&row.file)
        ));
        for (standing, column) in row.standings.iter().zip(&summary.exercises) {
            let word = words(*standing);
            html.push_str(&format!(
                "<td data-standing=\"{}\" data-exercise=\"{}\" title=\"{word}\"><span aria-hidden=\"true\">{}</span>\
<span class=\"visually-hidden\">{word}</span></td>",
                standing.key(),
                escape(&column.id),
                mark(*standing)
            ));
        }
        html.push_str("</tr>");
    }
    html.push_str(&format!(
        "</tbody><tfoot><tr><th scope=\"row\" colspan=\"2\">{}</th>",
        escape(&ctx::t("class-rate-success"))
    ));
    for column in &summary.exercises {
        html.push_str(&format!(
            "<td data-exercise=\"{}\">{}</td>",
            escape(&column.id),
            rate_text(column.success_rate())
        ));
    }
    html.push_str("</tr></tfoot></table>");
    container.set_inner_html(&html);
    Ok(())
}

/// The exercises, hardest first: id, page, success rate and the share right at the first
/// try, into `container`.
pub fn draw_rates(
    container: &Element,
    summary: &ClassSummary,
    shell: ShellLink,
) -> Result<(), JsValue> {
    let mut html = format!(
        "<table class=\"class-rates\" data-testid=\"class-rates\"><thead><tr><th scope=\"col\">{}</th>\
<th scope=\"col\">{}</th><th scope=\"col\">{}</th><th scope=\"col\">{}</th></tr></thead><tbody>",
        escape(&ctx::t("class-rate-exercise")),
        escape(&ctx::t("class-rate-page")),
        escape(&ctx::t("class-rate-success")),
        escape(&ctx::t("class-rate-first-try"))
    );
    for column in &summary.exercises {
        let page = PAGE_IDS
            .iter()
            .find(|(_, ids)| ids.contains(&column.id.as_str()))
            .and_then(|(page, _)| shell.find(page))
            .map_or_else(String::new, |def| ctx::t(def.title_id));
        html.push_str(&format!(
            "<tr data-exercise=\"{id}\"><th scope=\"row\"><code>{id}</code></th><td>{}</td><td>{}</td><td>{}</td></tr>",
            escape(&page),
            rate_text(column.success_rate()),
            rate_text(column.first_try_rate()),
            id = escape(&column.id)
        ));
    }
    html.push_str("</tbody></table>");
    container.set_inner_html(&html);
    Ok(())
}
