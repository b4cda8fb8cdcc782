//! The page's HTML skeleton (its stylesheet, `style.css` beside this file, is bundled into
//! `www/app.css` by `scripts/build-dist.sh`). Every visible word is a `data-i18n` id that the
//! shell (and `dom::relocalize`) fills from `locales/*/ik2r.ftl`; elements the code drives carry
//! `data-ik2r="<role>"`, and the ones tests drive carry `data-testid` / `data-readout` /
//! `data-download`.

use super::{explain, params, readouts};
use crate::view::ik2r::{ARM_PNG, EXPORTS};

fn readout_row(label: &str, rows: &[(&str, &str)]) -> String {
    let mut html = format!("<div class=\"ik2r-ro\"><dt data-i18n=\"{label}\"></dt><dd>");
    for (name, unit) in rows {
        html.push_str(&format!(
            "<span class=\"ik2r-num\"><span class=\"ik2r-val\" data-readout=\"{name}\"></span>\
             <span class=\"ik2r-unit\" data-i18n=\"{unit}\"></span></span>"
        ));
    }
    html.push_str("</dd></div>");
    html
}

fn readouts() -> String {
    let mut html = String::from(
        "<section class=\"ik2r-card ik2r-readouts\" aria-live=\"off\">\
         <h2 data-i18n=\"ik2r-readouts-title\"></h2><dl>",
    );
    html.push_str(&readout_row(
        "ik2r-ro-q1",
        &[("q1", "ik2r-unit-rad"), ("q1_deg", "ik2r-unit-deg")],
    ));
    html.push_str(&readout_row(
        "ik2r-ro-q2",
        &[("q2", "ik2r-unit-rad"), ("q2_deg", "ik2r-unit-deg")],
    ));
    html.push_str(&readout_row(
        "ik2r-ro-tip",
        &[("x_mm", "ik2r-unit-mm"), ("y_mm", "ik2r-unit-mm")],
    ));
    html.push_str(&readout_row("ik2r-ro-det", &[("det_j", "ik2r-unit-m2")]));
    html.push_str(&readout_row(
        "ik2r-ro-w",
        &[("manipulability", "ik2r-unit-m2")],
    ));
    html.push_str(&readout_row(
        "ik2r-ro-sigma",
        &[("sigma_min", "ik2r-unit-m"), ("sigma_max", "ik2r-unit-m")],
    ));
    html.push_str(
        "</dl><div class=\"ik2r-jac\"><span class=\"ik2r-jac-label\" data-i18n=\"ik2r-ro-jac\"></span>\
         <div class=\"ik2r-matrix\" role=\"table\">\
         <span data-readout=\"j11\" role=\"cell\"></span><span data-readout=\"j12\" role=\"cell\"></span>\
         <span data-readout=\"j21\" role=\"cell\"></span><span data-readout=\"j22\" role=\"cell\"></span>\
         </div><span class=\"ik2r-unit\" data-i18n=\"ik2r-unit-m-per-rad\"></span></div>\
         <p class=\"ik2r-hint\" data-i18n=\"ik2r-ro-hint\"></p></section>",
    );
    html
}

fn downloads_panel() -> String {
    let mut html = String::from(
        "<section class=\"ik2r-card ik2r-downloads\"><h2 data-i18n=\"ik2r-downloads-title\"></h2>\
         <p class=\"ik2r-hint\" data-i18n=\"ik2r-downloads-hint\"></p><div class=\"ik2r-dl-grid\">",
    );
    for export in EXPORTS {
        let (file, label) = (export.file, export.label_id);
        html.push_str(&format!(
            "<div class=\"ik2r-dl\">\
             <button type=\"button\" class=\"ik2r-btn ik2r-btn-primary\" data-download=\"{file}\" \
             data-i18n=\"{label}\"></button>\
             <p class=\"ik2r-error\" data-dl-error=\"{file}\" role=\"alert\" hidden></p>\
             <div class=\"ik2r-cmd\"><span class=\"ik2r-cmd-label\" data-i18n=\"ik2r-dl-cmd-python\"></span>\
             <code data-cmd=\"{file}:python\"></code>\
             <button type=\"button\" class=\"ik2r-btn ik2r-copy\" data-copy=\"{file}:python\" \
             data-i18n=\"ik2r-copy\"></button></div>\
             <div class=\"ik2r-cmd\"><span class=\"ik2r-cmd-label\" data-i18n=\"ik2r-dl-cmd-bsv\"></span>\
             <code data-cmd=\"{file}:bsv\"></code>\
             <button type=\"button\" class=\"ik2r-btn ik2r-copy\" data-copy=\"{file}:bsv\" \
             data-i18n=\"ik2r-copy\"></button></div>\
             </div>"
        ));
    }
    html.push_str(&format!(
        "<div class=\"ik2r-dl\"><button type=\"button\" class=\"ik2r-btn\" data-download=\"{}\" \
         data-i18n=\"ik2r-dl-png\"></button><p class=\"ik2r-hint\" data-i18n=\"ik2r-dl-png-hint\"></p></div>\
         </div><p class=\"ik2r-status\" data-ik2r=\"copy-status\" role=\"status\"></p></section>",
        ARM_PNG
    ));
    html
}

/// The compact strip of key numbers over the arm view (shown at phone width).
fn strip() -> String {
    let mut html = String::from("<div class=\"ik2r-strip\" aria-hidden=\"true\">");
    for (name, label, unit) in readouts::STRIP {
        html.push_str(&format!(
            "<span class=\"ik2r-strip-item\"><span class=\"ik2r-strip-label\" data-i18n=\"{label}\"></span> \
             <span class=\"ik2r-val\" data-strip=\"{name}\"></span>\
             <span class=\"ik2r-unit\" data-i18n=\"{unit}\"></span></span>"
        ));
    }
    html.push_str("</div>");
    html
}

/// The whole page.
pub fn page() -> String {
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
{strip}<div class=\"ik2r-stage ik2r-stage-arm\" data-ik2r=\"arm-stage\">\
<canvas class=\"ik2r-layer\" data-ik2r=\"arm-bg\" aria-hidden=\"true\"></canvas>\
<canvas class=\"ik2r-layer ik2r-interactive\" data-ik2r=\"arm-fg\" data-testid=\"ik-2r-canvas\" role=\"img\" tabindex=\"0\" \
data-i18n-attr=\"aria-label=ik2r-canvas-label\"></canvas>\
<p class=\"ik2r-clamp\" data-ik2r=\"clamp-note\" data-testid=\"ik-2r-clamp-note\" role=\"status\" data-i18n=\"ik2r-clamped\" hidden></p>\
</div>\
<p class=\"ik2r-sr-only\" data-ik2r=\"live\" data-testid=\"ik-2r-live\" role=\"status\" aria-live=\"polite\"></p>\
<p class=\"ik2r-hint\" data-i18n=\"ik2r-drag-hint\"></p>\
<p class=\"ik2r-hint\" data-ik2r=\"view-notes\"></p>\
<p class=\"ik2r-hint\" data-ik2r=\"ws-summary\" hidden></p>\
</section>\
<div class=\"ik2r-side\">{readouts}\
<section class=\"ik2r-card ik2r-heat\"><h2 data-i18n=\"ik2r-heatmap-title\"></h2>\
<div class=\"ik2r-stage ik2r-stage-heat\" data-ik2r=\"heat-stage\">\
<canvas class=\"ik2r-layer\" data-ik2r=\"heat-bg\" aria-hidden=\"true\"></canvas>\
<canvas class=\"ik2r-layer ik2r-interactive\" data-ik2r=\"heat-fg\" data-testid=\"ik-2r-heatmap\" role=\"img\" \
data-i18n-attr=\"aria-label=ik2r-heatmap-label\"></canvas></div>\
<p class=\"ik2r-hover\" data-ik2r=\"heat-hover\" data-testid=\"ik-2r-heatmap-hover\"></p>\
<p class=\"ik2r-hint\" data-i18n=\"ik2r-heatmap-hint\"></p></section>\
</div></div>\
<div class=\"ik2r-mid\">\
<section class=\"ik2r-card ik2r-plots\"><h2 data-i18n=\"ik2r-plot-title\"></h2>\
<p class=\"ik2r-hint\" data-i18n=\"ik2r-plot-hint\"></p>\
<div class=\"ik2r-stage ik2r-stage-plot\" data-ik2r=\"plot-stage\">\
<canvas class=\"ik2r-layer\" data-ik2r=\"plot-bg\" aria-hidden=\"true\"></canvas>\
<canvas class=\"ik2r-layer\" data-ik2r=\"plot-fg\" data-testid=\"ik-2r-plot\" role=\"img\" \
data-i18n-attr=\"aria-label=ik2r-plot-label\"></canvas>\
<canvas class=\"ik2r-layer\" data-ik2r=\"plot-cursor\" aria-hidden=\"true\"></canvas></div></section>\
<section class=\"ik2r-card ik2r-params\"><h2 data-i18n=\"ik2r-params-title\"></h2>\
<p class=\"ik2r-hint\" data-i18n=\"ik2r-params-hint\"></p>\
<form class=\"ik2r-form\" data-ik2r=\"form\" novalidate>{form}</form></section>\
</div>\
{downloads}\
{explain}\
</div>",
        readouts = readouts(),
        strip = strip(),
        form = params::markup(),
        downloads = downloads_panel(),
        explain = explain::markup(),
    )
}
