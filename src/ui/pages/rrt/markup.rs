//! The page's markup: heading, the world view under its stepper, the editor toolbar, the
//! sub-step panel with the pseudocode, the counters, the parameters, the exports and the
//! explanation. Every text is a Fluent id (`data-i18n`), filled by the shell.

use crate::ui::kit::exports;
use crate::ui::kit::readouts;
use crate::view::rrt::CODE_LINES;

/// `(data-readout key, Fluent id of its label)`, in order.
pub const READOUTS: [(&str, &str); 8] = [
    ("iteration", "rrt-ro-iteration"),
    ("nodes", "rrt-ro-nodes"),
    ("rejected_out", "rrt-ro-rejected-out"),
    ("rejected_collision", "rrt-ro-rejected-collision"),
    ("rejected_zero", "rrt-ro-rejected-zero"),
    ("path_points", "rrt-ro-path-points"),
    ("length", "rrt-ro-length"),
    ("nodes_per_s", "rrt-ro-rate"),
];

/// The pseudocode lines, each `data-code-line="<n>"`.
fn code() -> String {
    let mut html = String::from("<ol class=\"rrt-code\" data-rrt=\"code\">");
    for n in 1..=CODE_LINES {
        html.push_str(&format!(
            "<li data-code-line=\"{n}\"><code data-i18n=\"rrt-code-{n}\"></code></li>"
        ));
    }
    html.push_str("</ol>");
    html
}

/// The page's HTML.
pub fn page() -> String {
    format!(
        "<div class=\"kit-page rrt\">\
         <header class=\"rrt-head\"><h1 data-i18n=\"rrt-title\"></h1>\
         <p class=\"rrt-lede\" data-i18n=\"rrt-lede\"></p>\
         <p class=\"rrt-notice\" data-rrt=\"url-notice\" hidden></p></header>\
         <div class=\"rrt-top\">\
         <section class=\"rrt-card rrt-world\"><h2 data-i18n=\"rrt-world-title\"></h2>\
         <div data-rrt=\"stepper\" data-section=\"stepper\"></div>\
         <p class=\"rrt-note rrt-finishing\" data-rrt=\"finishing\" data-testid=\"rrt-2d-finishing\" role=\"status\" hidden></p>\
         <div class=\"rrt-stage\" data-rrt=\"stage\" data-section=\"world\">\
         <canvas class=\"rrt-layer\" aria-hidden=\"true\"></canvas>\
         <canvas class=\"rrt-layer\" aria-hidden=\"true\"></canvas>\
         <canvas class=\"rrt-layer\" data-testid=\"rrt-2d-canvas\" tabindex=\"0\" role=\"img\" \
         data-i18n-attr=\"aria-label=rrt-canvas-label\" aria-describedby=\"rrt-readouts\"></canvas></div>\
         <div class=\"rrt-tools\">\
         <button type=\"button\" class=\"button\" data-action=\"add-box\" data-i18n=\"rrt-add-box\"></button>\
         <button type=\"button\" class=\"button\" data-action=\"delete-box\" data-i18n=\"rrt-delete-box\"></button>\
         <button type=\"button\" class=\"button\" data-action=\"recipe-world\" data-i18n=\"rrt-recipe-world\"></button>\
         <label class=\"rrt-switch\"><input type=\"checkbox\" data-rrt=\"substep-mode\">\
         <span data-i18n=\"rrt-substep-mode\"></span></label></div>\
         <p class=\"rrt-refusal\" data-rrt=\"world-message\" data-testid=\"rrt-2d-world-message\" role=\"alert\" hidden></p>\
         <p class=\"rrt-note\" data-rrt=\"key-target\" data-testid=\"rrt-2d-key-target\" role=\"status\" hidden></p>\
         <p class=\"rrt-note\" data-i18n=\"rrt-world-note\"></p></section>\
         <div class=\"rrt-side\">\
         <section class=\"rrt-card\" data-section=\"substeps\"><h2 data-i18n=\"rrt-sub-title\"></h2>\
         <ol class=\"rrt-subs\" data-rrt=\"subs\" data-testid=\"rrt-2d-substeps\"></ol>\
         <p class=\"rrt-note\" data-rrt=\"sub-none\" data-i18n=\"rrt-sub-none\"></p>\
         <p class=\"rrt-note\" data-testid=\"rrt-2d-sub-help\" data-i18n=\"rrt-sub-help\"></p>\
         <h3 data-i18n=\"rrt-code-title\"></h3>{code}</section>\
         <section class=\"rrt-card\" data-section=\"readouts\"><h2 data-i18n=\"rrt-counters-title\"></h2>{readouts}{live}</section>\
         </div></div>\
         <div class=\"rrt-mid\">\
         <section class=\"rrt-card\" data-section=\"form\"><h2 data-i18n=\"rrt-params-title\"></h2>\
         <form data-rrt=\"form\" novalidate></form></section>\
         <section class=\"rrt-card\" data-section=\"exports\"><h2 data-i18n=\"rrt-exports-title\"></h2>\
         <p class=\"rrt-note\" data-i18n=\"rrt-exports-note\"></p>\
         <div class=\"rrt-buttons\">\
         <button type=\"button\" class=\"button primary\" data-download=\"rrt_nodes.csv\" data-i18n=\"rrt-download-nodes\"></button>\
         <button type=\"button\" class=\"button primary\" data-download=\"rrt_path.csv\" data-i18n=\"rrt-download-path\"></button>\
         <button type=\"button\" class=\"button\" data-download=\"rrt_2d.png\" data-i18n=\"rrt-download-png\"></button></div>\
         <p class=\"rrt-note\" data-rrt=\"csv-progress\" data-testid=\"rrt-2d-csv-progress\" role=\"status\" hidden></p>\
         {commands}\
         <p class=\"rrt-note\" data-rrt=\"python-none\" data-i18n=\"rrt-python-none\" hidden></p>\
         </section></div>\
         <section class=\"rrt-card rrt-explain\" data-section=\"explain\"><h2 data-i18n=\"rrt-explain-title\"></h2>\
         <h3 data-i18n=\"rrt-explain-what-title\"></h3><p data-i18n=\"rrt-explain-what\"></p>\
         <h3 data-i18n=\"rrt-explain-bias-title\"></h3><p data-i18n=\"rrt-explain-bias\"></p>\
         <h3 data-i18n=\"rrt-explain-corner-title\"></h3><p data-i18n=\"rrt-explain-corner\"></p>\
         <h3 data-i18n=\"rrt-explain-numbers-title\"></h3><p data-i18n=\"rrt-explain-numbers\"></p>\
         <h3 data-i18n=\"rrt-explain-back-title\"></h3><p data-i18n=\"rrt-explain-back\"></p>\
         <h3 data-i18n=\"rrt-explain-recipe-title\"></h3><p data-i18n=\"recipe-rrt-2d-blurb\"></p>\
         <p data-i18n=\"drills-about-rrt-2d\"></p><p data-i18n=\"rrt-explain-expected\"></p>\
         <p data-i18n=\"recipe-rrt-2d-quirks\"></p></section>\
         </div>",
        code = code(),
        readouts = readouts::markup("rrt", &READOUTS),
        live = readouts::live_markup("rrt"),
        commands = exports::markup("rrt"),
    )
}
