//! The page's markup: heading, the pendulum view with its stepper and compare switch, the
//! readouts, the plots, the parameters, the exports and the explanation. Every text is a
//! Fluent id (`data-i18n`), filled by the shell.

use super::exports;
use super::readouts;

/// The page's HTML.
pub fn page() -> String {
    format!(
        "<div class=\"kit-page pend\">\
         <header class=\"pend-head\"><h1 data-i18n=\"pendulum-title\"></h1>\
         <p class=\"pend-lede\" data-i18n=\"pendulum-lede\"></p>\
         <p class=\"pend-notice\" data-pend=\"url-notice\" hidden></p></header>\
         <div class=\"pend-top\">\
         <section class=\"pend-card\"><h2 data-i18n=\"pendulum-view-title\"></h2>\
         <div class=\"pend-stage pend-stage-view\" data-pend=\"view-stage\" data-section=\"pendulum\">\
         <canvas class=\"pend-layer\" data-testid=\"pendulum-energy-canvas\" role=\"img\" tabindex=\"0\" \
         data-i18n-attr=\"aria-label=pendulum-canvas-label\" aria-describedby=\"pend-readouts\"></canvas></div>\
         <div class=\"pend-end\" data-pend=\"end\" role=\"status\" hidden>\
         <p data-pend=\"end-text\"></p><div class=\"pend-buttons\">\
         <button type=\"button\" class=\"button primary\" data-action=\"replay\" data-i18n=\"pendulum-replay\"></button>\
         <button type=\"button\" class=\"button\" data-action=\"undamped\" data-i18n=\"pendulum-undamped\"></button></div></div>\
         <div data-pend=\"stepper\" data-section=\"stepper\"></div>\
         <div class=\"pend-h\"><label for=\"pend-h-slider\" data-i18n=\"pendulum-h-label\"></label>\
         <input id=\"pend-h-slider\" type=\"range\" min=\"0\" max=\"9\" step=\"1\" data-pend=\"h-slider\" \
         aria-describedby=\"pend-h-note\"><output data-pend=\"h-value\" for=\"pend-h-slider\"></output></div>\
         <p class=\"pend-note\" id=\"pend-h-note\" data-i18n=\"pendulum-h-note\"></p>\
         <label class=\"pend-switch\"><input type=\"checkbox\" data-field=\"compare\">\
         <span data-i18n=\"pendulum-compare\"></span></label>\
         <p class=\"pend-note\" data-i18n=\"pendulum-compare-note\"></p></section>\
         <section class=\"pend-card\" data-section=\"readouts\"><h2 data-i18n=\"pendulum-readouts-title\"></h2>{readouts}\
         <p class=\"pend-note\" data-pend=\"energy-note\" data-i18n=\"pendulum-energy-note\"></p></section>\
         </div>\
         <section class=\"pend-card\"><h2 data-i18n=\"pendulum-plots-title\"></h2>\
         <div class=\"pend-plots\" data-section=\"plot\">\
         <div class=\"pend-stage pend-stage-time\" data-pend=\"time-stage\">\
         <canvas class=\"pend-layer\" aria-hidden=\"true\"></canvas><canvas class=\"pend-layer\" aria-hidden=\"true\"></canvas>\
         <canvas class=\"pend-layer\" role=\"img\" data-i18n-attr=\"aria-label=pendulum-plot-label\" \
         aria-describedby=\"pend-readouts pend-plots-note\"></canvas></div>\
         <div class=\"pend-stage pend-stage-phase\" data-pend=\"phase-stage\">\
         <canvas class=\"pend-layer\" aria-hidden=\"true\"></canvas><canvas class=\"pend-layer\" aria-hidden=\"true\"></canvas>\
         <canvas class=\"pend-layer\" role=\"img\" data-i18n-attr=\"aria-label=pendulum-phase-label\" \
         aria-describedby=\"pend-readouts pend-plots-note\"></canvas></div>\
         </div><p class=\"pend-note\" id=\"pend-plots-note\" data-i18n=\"pendulum-plots-note\"></p></section>\
         <div class=\"pend-mid\">\
         <section class=\"pend-card\" data-section=\"form\"><h2 data-i18n=\"pendulum-params-title\"></h2>\
         <form class=\"pend-form\" data-pend=\"form\" novalidate></form></section>\
         <section class=\"pend-card\" data-section=\"exports\"><h2 data-i18n=\"pendulum-exports-title\"></h2>{exports}\
         </section></div>\
         <section class=\"pend-card pend-explain\" data-section=\"explain\"><h2 data-i18n=\"pendulum-explain-title\"></h2>\
         <h3 data-i18n=\"pendulum-explain-int-title\"></h3><p data-i18n=\"pendulum-explain-int\"></p>\
         <h3 data-i18n=\"pendulum-explain-energy-title\"></h3><p data-i18n=\"pendulum-explain-energy\"></p>\
         <h3 data-i18n=\"pendulum-explain-lag-title\"></h3><p data-i18n=\"pendulum-explain-lag\"></p>\
         <h3 data-i18n=\"pendulum-explain-sep-title\"></h3><p data-i18n=\"pendulum-explain-sep\"></p>\
         <h3 data-i18n=\"pendulum-explain-drift-title\"></h3><p data-i18n=\"pendulum-explain-drift\"></p>\
         <h3 data-i18n=\"pendulum-explain-recipe-title\"></h3><p data-i18n=\"recipe-pendulum-energy-blurb\"></p>\
         <p data-i18n=\"recipe-pendulum-energy-quirks\"></p></section>\
         </div>",
        readouts = readouts::markup(),
        exports = exports::markup(),
    )
}
