//! The page's markup: heading and link notice, the plot with its readouts, the input and dt
//! (the kit's form, filled by the code), the result's downloads and command lines, and the
//! explanation with the seed's recipe text. Every fixed word is a `data-i18n` id.

use crate::ui::kit::{exports, readouts};

/// Class and test-id prefix of the kit widgets.
pub const PREFIX: &str = "traj";

/// The readouts: `(data-readout key, label id)`.
const READOUTS: [(&str, &str); 6] = [
    ("rows_in", "traj-ro-rows-in"),
    ("joints", "traj-ro-joints"),
    ("span", "traj-ro-span"),
    ("duration", "traj-ro-duration"),
    ("dt", "traj-ro-dt"),
    ("rows_out", "traj-ro-rows-out"),
];

/// The page's HTML.
pub fn page() -> String {
    format!(
        "<div class=\"kit-page traj\" data-testid=\"traj-resample-page\" data-state=\"ready\">\
         <header class=\"traj-head\"><h1 data-i18n=\"traj-title\"></h1>\
         <p class=\"traj-lede\" data-i18n=\"traj-lede\"></p>\
         <p class=\"traj-notice\" data-traj=\"url-notice\" data-testid=\"traj-url-notice\" hidden></p></header>\
         <div class=\"traj-top\">\
         <section class=\"traj-card traj-plot-card\"><h2 data-i18n=\"traj-plot-title\"></h2>\
         <div class=\"traj-stage\" data-traj=\"stage\" data-section=\"plot\">\
         <canvas class=\"traj-layer\" aria-hidden=\"true\"></canvas><canvas class=\"traj-layer\" aria-hidden=\"true\"></canvas>\
         <canvas class=\"traj-layer\" role=\"img\" tabindex=\"0\" data-testid=\"traj-resample-canvas\" \
         data-i18n-attr=\"aria-label=traj-canvas-label\" aria-describedby=\"traj-readouts\"></canvas></div>\
         <p class=\"traj-note\" data-i18n=\"traj-plot-note\"></p></section>\
         <section class=\"traj-card\" data-section=\"readouts\"><h2 data-i18n=\"traj-readouts-title\"></h2>{readouts}\
         <p class=\"traj-note\" data-i18n=\"traj-drop-note\"></p></section>\
         </div>\
         <div class=\"traj-mid\">\
         <section class=\"traj-card\" data-section=\"form\"><h2 data-i18n=\"traj-input-title\"></h2>\
         <form class=\"traj-form\" data-traj=\"form\" novalidate></form>\
         <p class=\"traj-status\" data-traj=\"status\" data-testid=\"traj-status\" role=\"status\" aria-live=\"polite\"></p>\
         </section>\
         <section class=\"traj-card\" data-section=\"exports\" data-traj=\"output\" data-testid=\"traj-output\"><h2 data-i18n=\"traj-exports-title\"></h2>\
         <div class=\"traj-files\" data-traj=\"files\"></div>{exports}</section>\
         </div>\
         <section class=\"traj-card traj-explain\" data-section=\"explain\"><h2 data-i18n=\"traj-explain-title\"></h2>\
         <h3 data-i18n=\"recipe-traj-resample-title\"></h3>\
         <p data-i18n=\"recipe-traj-resample-blurb\"></p>\
         <dl class=\"traj-recipe\">\
         <dt data-i18n=\"traj-explain-input-label\"></dt><dd data-i18n=\"traj-explain-input\"></dd>\
         <dt data-i18n=\"traj-explain-output-label\"></dt><dd data-i18n=\"traj-explain-output\"></dd>\
         <dt data-i18n=\"traj-explain-steps-label\"></dt><dd data-i18n=\"traj-explain-steps\"></dd>\
         <dt data-i18n=\"traj-explain-expected-label\"></dt><dd data-i18n=\"traj-explain-expected\"></dd>\
         </dl>\
         <h3 data-i18n=\"traj-explain-interp-title\"></h3><p data-i18n=\"traj-explain-interp\"></p>\
         <h3 data-i18n=\"traj-explain-quirks-title\"></h3><p data-i18n=\"recipe-traj-resample-quirks\"></p>\
         <h3 data-i18n=\"traj-explain-decoding-title\"></h3><p data-i18n=\"traj-explain-decoding\"></p>\
         </section>{live}</div>",
        readouts = readouts::markup(PREFIX, &READOUTS),
        exports = exports::markup(PREFIX),
        live = readouts::live_markup(PREFIX),
    )
}
