//! The page's markup: heading, the view with its legend, point tools, stepper and step panel,
//! the estimate-against-truth readouts, the kit's form and exports, and the explanation (the
//! recipe's text and code). Every text is a Fluent id (`data-i18n`), filled by the shell.
//! The exports (`data-ume="later"`) are hidden until the second stage (`super::more`) is in;
//! the line `data-ume="more"` stands in for them meanwhile.

use crate::recipes::umeyama_2d::INFO;
use crate::ui::kit::{readouts, recipe_controls};

/// Class and role prefix.
pub const P: &str = "ume";
/// The PNG of the view.
pub const PNG: &str = "umeyama_2d.png";

/// `(data-readout of the estimate, of the truth, label id)`.
pub const READOUT_ROWS: [(&str, &str, &str); 5] = [
    ("scale", "scale-true", "umeyama-ro-scale"),
    ("angle", "angle-true", "umeyama-ro-angle"),
    ("tx", "tx-true", "umeyama-ro-tx"),
    ("ty", "ty-true", "umeyama-ro-ty"),
    ("rmse", "rmse-noise", "umeyama-ro-rmse"),
];

fn readout_table() -> String {
    let mut rows = String::new();
    for (estimate, truth, label) in READOUT_ROWS {
        rows.push_str(&format!(
            "<tr><th scope=\"row\" data-i18n=\"{label}\"></th>\
             <td data-readout=\"{estimate}\"></td><td data-readout=\"{truth}\"></td></tr>"
        ));
    }
    format!(
        "<table class=\"ume-table\" id=\"ume-readouts\" data-testid=\"umeyama-2d-readouts\"><thead><tr><th></th>\
         <th scope=\"col\" data-i18n=\"umeyama-ro-estimate\"></th>\
         <th scope=\"col\" data-i18n=\"umeyama-ro-truth\"></th></tr></thead><tbody>{rows}</tbody></table>"
    )
}

fn legend() -> String {
    let item = |class: &str, id: &str| {
        format!("<li><span class=\"ume-key {class}\" aria-hidden=\"true\"></span><span data-i18n=\"{id}\"></span></li>")
    };
    format!(
        "<ul class=\"ume-legend\">{}{}{}{}{}</ul>",
        item("ume-key-x", "umeyama-legend-x"),
        item("ume-key-y", "umeyama-legend-y"),
        item("ume-key-aligned", "umeyama-legend-aligned"),
        item("ume-key-residual", "umeyama-legend-residual"),
        item("ume-key-truth", "umeyama-legend-truth"),
    )
}

/// The explanation's sections: `umeyama-explain-<key>-title` and `umeyama-explain-<key>`.
const EXPLAIN: [&str; 5] = ["what", "steps", "reflection", "edit", "recipe"];

/// The page's HTML.
pub fn page() -> String {
    let (form, notice, exports) = recipe_controls::markup(P, &INFO, PNG, "umeyama-png");
    let explain: String = EXPLAIN
        .iter()
        .map(|k| {
            format!(
                "<h3 data-i18n=\"umeyama-explain-{k}-title\"></h3><p data-i18n=\"umeyama-explain-{k}\"></p>"
            )
        })
        .collect();
    let action = |name: &str, class: &str| {
        format!(
            "<button type=\"button\" class=\"button{class}\" data-action=\"{name}\" \
             data-testid=\"umeyama-{name}\" data-i18n=\"umeyama-action-{name}\"></button>"
        )
    };
    format!(
        "<div class=\"sig ume\"><header class=\"sig-head\"><h1 data-i18n=\"umeyama-title\"></h1>\
         <p class=\"sig-lede\" data-i18n=\"umeyama-lede\"></p>{notice}\
         <p class=\"sig-notice ume-edited\" data-{P}=\"edited\" data-testid=\"umeyama-2d-edited\" \
         data-i18n=\"umeyama-edited\" hidden></p></header>\
         <div class=\"sig-top\"><section class=\"sig-card\"><h2 data-i18n=\"umeyama-view-title\"></h2>\
         <div class=\"sig-stage ume-stage\" data-{P}=\"stage\" data-section=\"points\">\
         <canvas class=\"sig-layer\" aria-hidden=\"true\"></canvas>\
         <canvas class=\"sig-layer\" data-testid=\"umeyama-2d-canvas\" role=\"img\" tabindex=\"0\" \
         data-i18n-attr=\"aria-label=umeyama-canvas-label\" aria-describedby=\"ume-readouts\"></canvas></div>{legend}\
         <div class=\"ume-tools\">{add}{remove}{mirror}{recipe}</div>\
         <p class=\"sig-note ume-selection\" data-{P}=\"selection\" data-testid=\"umeyama-2d-selection\" \
         role=\"status\" aria-live=\"polite\"></p>\
         <p class=\"ume-message\" data-{P}=\"message\" data-testid=\"umeyama-2d-message\" role=\"status\" hidden></p>\
         <p class=\"sig-note\" data-i18n=\"umeyama-view-note\"></p>\
         <div data-{P}=\"stepper\" data-section=\"stepper\"></div>\
         <div class=\"ume-step\" data-testid=\"umeyama-2d-step\">\
         <h3 data-{P}=\"step-title\" aria-live=\"polite\"></h3><p data-{P}=\"step-text\"></p>\
         <div class=\"ume-mats\" data-{P}=\"step-mats\"></div></div></section>\
         <div class=\"sig-side\"><section class=\"sig-card\" data-section=\"readouts\"><h2 data-i18n=\"umeyama-ro-title\"></h2>{table}{live}\
         <p class=\"sig-note\" data-i18n=\"umeyama-ro-note\"></p></section>\
         <section class=\"sig-card\" data-section=\"form\"><h2 data-i18n=\"signals-params-title\"></h2>{form}</section></div></div>\
         <section class=\"sig-card\" data-section=\"exports\"><h2 data-i18n=\"signals-exports-title\"></h2>\
         <p class=\"ume-more\" data-{P}=\"more\" data-testid=\"umeyama-2d-more\"></p>\
         <div data-{P}=\"later\" hidden>{exports}</div></section>\
         <section class=\"sig-card sig-explain\" data-section=\"explain\"><h2 data-i18n=\"signals-explain-title\"></h2>{explain}\
         <pre class=\"ume-code\"><code data-i18n=\"umeyama-code\"></code></pre>\
         <h3 data-i18n=\"signals-quirks-title\"></h3><p data-i18n=\"recipe-umeyama-2d-quirks\"></p></section></div>",
        legend = legend(),
        add = action("add", ""),
        remove = action("remove", ""),
        mirror = action("mirror", ""),
        recipe = action("recipe", ""),
        table = readout_table(),
        live = readouts::live_markup(P),
    )
}
