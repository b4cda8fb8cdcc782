//! The page's markup: heading, the pendulum view with its stepper and compare switch, the
//! readouts, the plots, the parameters, the exports and the explanation. Every text is a
//! Fluent id (`data-i18n`), filled by the shell.

use super::params;
use super::readouts;

/// The page's HTML.
pub fn page() -> String {
    format!(
        "<div class=\"pend\">\
         <header class=\"pend-head\"><h1 data-i18n=\"pendulum-title\"></h1>\
         <p class=\"pend-lede\" data-i18n=\"pendulum-lede\"></p>\
         <p class=\"pend-notice\" data-pend=\"url-notice\" hidden></p></header>\
         <div class=\"pend-top\">\
         <section class=\"pend-card\"><h2 data-i18n=\"pendulum-view-title\"></h2>\
         <div class=\"pend-stage pend-stage-view\" data-pend=\"view-stage\">\
         <canvas class=\"pend-layer\" data-testid=\"pendulum-energy-canvas\" tabindex=\"0\" \
         data-i18n-attr=\"aria-label=pendulum-canvas-label\"></canvas></div>\
         <div data-pend=\"stepper\"></div>\
         <label class=\"pend-switch\"><input type=\"checkbox\" data-field=\"compare\">\
         <span data-i18n=\"pendulum-compare\"></span></label>\
         <p class=\"pend-note\" data-i18n=\"pendulum-compare-note\"></p></section>\
         <section class=\"pend-card\"><h2 data-i18n=\"pendulum-readouts-title\"></h2>{readouts}</section>\
         </div>\
         <section class=\"pend-card\"><h2 data-i18n=\"pendulum-plots-title\"></h2>\
         <div class=\"pend-plots\">\
         <div class=\"pend-stage pend-stage-time\" data-pend=\"time-stage\">\
         <canvas class=\"pend-layer\" aria-hidden=\"true\"></canvas><canvas class=\"pend-layer\" aria-hidden=\"true\"></canvas>\
         <canvas class=\"pend-layer\" role=\"img\" data-i18n-attr=\"aria-label=pendulum-plot-label\"></canvas></div>\
         <div class=\"pend-stage pend-stage-phase\" data-pend=\"phase-stage\">\
         <canvas class=\"pend-layer\" aria-hidden=\"true\"></canvas><canvas class=\"pend-layer\" aria-hidden=\"true\"></canvas>\
         <canvas class=\"pend-layer\" role=\"img\" data-i18n-attr=\"aria-label=pendulum-phase-label\"></canvas></div>\
         </div><p class=\"pend-note\" data-i18n=\"pendulum-plots-note\"></p></section>\
         <div class=\"pend-mid\">\
         <section class=\"pend-card\"><h2 data-i18n=\"pendulum-params-title\"></h2>\
         <form data-pend=\"form\" novalidate>{fields}</form></section>\
         <section class=\"pend-card\"><h2 data-i18n=\"pendulum-exports-title\"></h2>\
         <div class=\"pend-buttons\">\
         <button type=\"button\" class=\"tool-button\" data-download=\"pendulum_energy.csv\" data-i18n=\"pendulum-download-csv\"></button>\
         <button type=\"button\" class=\"tool-button\" data-download=\"pendulum_energy_plots.png\" data-i18n=\"pendulum-download-png\"></button></div>\
         <h3 data-i18n=\"pendulum-cli-title\"></h3>\
         <pre class=\"pend-cmd\"><code data-command=\"bsv\"></code></pre>\
         <button type=\"button\" class=\"tool-button\" data-action=\"copy-bsv\" data-i18n=\"pendulum-copy\"></button>\
         <h3 data-i18n=\"pendulum-python-title\"></h3>\
         <pre class=\"pend-cmd\"><code data-command=\"python\"></code></pre>\
         <p class=\"pend-note\" data-pend=\"python-note\" data-i18n=\"pendulum-python-none\" hidden></p>\
         <button type=\"button\" class=\"tool-button\" data-action=\"copy-python\" data-i18n=\"pendulum-copy\"></button>\
         <p class=\"pend-note\" data-pend=\"copy-status\" role=\"status\" aria-live=\"polite\"></p>\
         </section></div>\
         <section class=\"pend-card pend-explain\"><h2 data-i18n=\"pendulum-explain-title\"></h2>\
         <h3 data-i18n=\"pendulum-explain-int-title\"></h3><p data-i18n=\"pendulum-explain-int\"></p>\
         <h3 data-i18n=\"pendulum-explain-energy-title\"></h3><p data-i18n=\"pendulum-explain-energy\"></p>\
         <h3 data-i18n=\"pendulum-explain-lag-title\"></h3><p data-i18n=\"pendulum-explain-lag\"></p>\
         <h3 data-i18n=\"pendulum-explain-sep-title\"></h3><p data-i18n=\"pendulum-explain-sep\"></p>\
         <h3 data-i18n=\"pendulum-explain-drift-title\"></h3><p data-i18n=\"pendulum-explain-drift\"></p>\
         <h3 data-i18n=\"pendulum-explain-recipe-title\"></h3><p data-i18n=\"recipe-pendulum-energy-blurb\"></p>\
         <p data-i18n=\"recipe-pendulum-energy-quirks\"></p></section>\
         </div>",
        readouts = readouts::markup(),
        fields = params::markup(),
    )
}
