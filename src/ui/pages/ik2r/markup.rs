//! The page's HTML skeleton (its stylesheet, `style.css` beside this file, is bundled into
//! `www/app.css` by `scripts/build-dist.sh`). Every visible word is a `data-i18n` id that the
//! shell (and `dom::relocalize`) fills from `locales/*/ik2r.ftl`; elements the code drives carry
//! `data-ik2r="<role>"`, and the ones tests drive carry `data-testid` / `data-readout` /
//! `data-download`.

use wasm_bindgen::{JsCast, JsValue};
use web_sys::Element;

use super::explain;
use crate::ui::dom;
use crate::ui::kit::readouts::live_markup;

/// The parts of the page the second stage (`super::panels`) fills: hidden until it has.
pub const LATER_SELECTOR: &str = ".ik2r-later";

/// The element `[data-ik2r="name"]` of the page.
pub fn role<T: JsCast>(root: &Element, name: &str) -> Result<T, JsValue> {
    dom::find(root, &format!("[data-ik2r=\"{name}\"]"), "ik-2r")
}

/// The whole page, with the components' own markup: the readouts card and the phone strip
/// (`readouts`, `strip`). The heatmap, the sweep plot and the form are hidden
/// ([`LATER_SELECTOR`]) until the second stage fills them, and the downloads panel is its
/// (`[data-ik2r="downloads"]` is where it goes: its markup names the recipes' kernels); the
/// line `[data-ik2r="more"]` stands in for them meanwhile.
pub fn page(readouts: &str, strip: &str) -> String {
    format!(
        "<div class=\"ik2r\" data-testid=\"ik-2r-page\">\
<header class=\"ik2r-head\"><h1 data-i18n=\"ik2r-title\"></h1><p class=\"ik2r-lede\" data-i18n=\"ik2r-lede\"></p>\
<p class=\"ik2r-notice\" data-ik2r=\"url-notice\" data-testid=\"ik-2r-url-notice\" role=\"status\" hidden></p></header>\
<div class=\"ik2r-top\">\
<section class=\"ik2r-card ik2r-armcard\">\
<div class=\"ik2r-toolbar\">\
<div class=\"ik2r-seg\" role=\"radiogroup\" data-i18n-attr=\"aria-label=ik2r-elbow-legend\">\
<label><input type=\"radio\" name=\"ik2r-elbow\" value=\"down\" data-ik2r=\"elbow-down\" data-testid=\"ik-2r-elbow-down\"><span data-i18n=\"ik2r-elbow-down\"></span></label>\
<label><input type=\"radio\" name=\"ik2r-elbow\" value=\"up\" data-ik2r=\"elbow-up\" data-testid=\"ik-2r-elbow-up\"><span data-i18n=\"ik2r-elbow-up\"></span></label>\
</div>\
<label class=\"ik2r-check\"><input type=\"checkbox\" data-ik2r=\"ws-toggle\" data-testid=\"ik-2r-ws-toggle\"><span data-i18n=\"ik2r-ws-show\"></span></label>\
<label class=\"ik2r-select\"><span data-i18n=\"ik2r-ws-color\"></span>\
<select data-ik2r=\"ws-color\" data-testid=\"ik-2r-ws-color\">\
<option value=\"reach\" data-i18n=\"ik2r-ws-color-reach\"></option>\
<option value=\"manip\" data-i18n=\"ik2r-ws-color-manip\"></option>\
<option value=\"err\" data-i18n=\"ik2r-ws-color-err\"></option></select></label>\
<button type=\"button\" class=\"ik2r-btn\" data-ik2r=\"reset\" data-i18n=\"ik2r-reset\"></button>\
</div>\
{strip}<div class=\"ik2r-stage ik2r-stage-arm\" data-ik2r=\"arm-stage\" data-section=\"arm\">\
<canvas class=\"ik2r-layer\" data-ik2r=\"arm-bg\" aria-hidden=\"true\"></canvas>\
<canvas class=\"ik2r-layer ik2r-interactive\" data-ik2r=\"arm-fg\" data-testid=\"ik-2r-canvas\" role=\"img\" tabindex=\"0\" \
data-i18n-attr=\"aria-label=ik2r-canvas-label\" aria-describedby=\"ik2r-readouts-list\"></canvas>\
<p class=\"ik2r-clamp\" data-ik2r=\"clamp-note\" data-testid=\"ik-2r-clamp-note\" role=\"status\" data-i18n=\"ik2r-clamped\" hidden></p>\
</div>\
{live}\
<p class=\"ik2r-hint\" data-i18n=\"ik2r-drag-hint\"></p>\
<p class=\"ik2r-hint\" data-ik2r=\"view-notes\"></p>\
<p class=\"ik2r-hint\" data-ik2r=\"ws-summary\" hidden></p>\
</section>\
<div class=\"ik2r-side\">{readouts}\
<section class=\"ik2r-card ik2r-heat ik2r-later\" hidden><h2 data-i18n=\"ik2r-heatmap-title\"></h2>\
<div class=\"ik2r-stage ik2r-stage-heat\" data-ik2r=\"heat-stage\" data-section=\"heatmap\">\
<canvas class=\"ik2r-layer\" data-ik2r=\"heat-bg\" aria-hidden=\"true\"></canvas>\
<canvas class=\"ik2r-layer ik2r-interactive\" data-ik2r=\"heat-fg\" data-testid=\"ik-2r-heatmap\" role=\"img\" tabindex=\"0\" \
data-i18n-attr=\"aria-label=ik2r-heatmap-label\" aria-describedby=\"ik2r-heat-hint ik2r-readouts-list\"></canvas></div>\
<p class=\"ik2r-hover\" data-ik2r=\"heat-hover\" data-testid=\"ik-2r-heatmap-hover\"></p>\
<p class=\"ik2r-hint\" id=\"ik2r-heat-hint\" data-i18n=\"ik2r-heatmap-hint\"></p></section>\
<p class=\"ik2r-more\" data-ik2r=\"more\" data-testid=\"ik-2r-more\"></p>\
</div></div>\
<div class=\"ik2r-mid ik2r-later\" hidden>\
<section class=\"ik2r-card ik2r-plots\"><h2 data-i18n=\"ik2r-plot-title\"></h2>\
<p class=\"ik2r-hint\" id=\"ik2r-plot-hint\" data-i18n=\"ik2r-plot-hint\"></p>\
<div class=\"ik2r-stage ik2r-stage-plot\" data-ik2r=\"plot-stage\" data-section=\"sweep\">\
<canvas class=\"ik2r-layer\" data-ik2r=\"plot-bg\" aria-hidden=\"true\"></canvas>\
<canvas class=\"ik2r-layer\" data-ik2r=\"plot-fg\" data-testid=\"ik-2r-plot\" role=\"img\" \
data-i18n-attr=\"aria-label=ik2r-plot-label\" aria-describedby=\"ik2r-plot-hint ik2r-readouts-list\"></canvas>\
<canvas class=\"ik2r-layer\" data-ik2r=\"plot-cursor\" aria-hidden=\"true\"></canvas></div></section>\
<section class=\"ik2r-card ik2r-params\" data-section=\"form\"><h2 data-i18n=\"ik2r-params-title\"></h2>\
<p class=\"ik2r-hint\" data-i18n=\"ik2r-params-hint\"></p>\
<form class=\"ik2r-form\" data-ik2r=\"form\" novalidate></form></section>\
</div>\
<div class=\"ik2r-later\" data-ik2r=\"downloads\" hidden></div>\
{explain}\
</div>",
        live = live_markup("ik-2r"),
        explain = explain::markup(),
    )
}
