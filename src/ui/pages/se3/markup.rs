//! The page's markup: heading, the slot of the 3D view (the kit's orbit view), the readouts and the rad/deg
//! switch, the two poses' form, the matrices with the result row and the composition check,
//! the intrinsic/extrinsic panel, the exports and the explanation. Every text is a Fluent id
//! (`data-i18n`), filled by the shell.

use crate::recipes::se3_relative::CSV_NAME;
use crate::ui::kit::{exports, readouts};

/// Class and role prefix.
pub const P: &str = "se3";
/// The PNG of the 3D view.
pub const PNG: &str = "se3_relative.png";

/// `(data-readout key, Fluent id of its label in radians)`: the relative pose.
pub const READOUTS: [(&str, &str); 6] = [
    ("x", "se3-ro-x"),
    ("y", "se3-ro-y"),
    ("z", "se3-ro-z"),
    ("roll", "se3-ro-roll"),
    ("pitch", "se3-ro-pitch"),
    ("yaw", "se3-ro-yaw"),
];

/// A 4×4 matrix table `data-matrix="<key>"` (cells filled by the page).
fn matrix(key: &str, caption_id: &str, n: usize) -> String {
    let mut html = format!(
        "<figure class=\"se3-matrix\"><figcaption data-i18n=\"{caption_id}\"></figcaption>\
         <table data-matrix=\"{key}\"><tbody>"
    );
    for _ in 0..n {
        html.push_str("<tr>");
        for _ in 0..n {
            html.push_str("<td></td>");
        }
        html.push_str("</tr>");
    }
    html.push_str("</tbody></table></figure>");
    html
}

/// The page's HTML.
pub fn page() -> String {
    let explain: String = [
        "what",
        "input",
        "steps",
        "expected",
        "convention",
        "inverse",
    ]
    .iter()
    .map(|k| {
        format!(
            "<h3 data-i18n=\"se3-explain-{k}-title\"></h3><p data-i18n=\"se3-explain-{k}\"></p>"
        )
    })
    .collect();
    format!(
        "<div class=\"kit-page se3\">\
         <header class=\"se3-head\"><h1 data-i18n=\"se3-title\"></h1>\
         <p class=\"se3-lede\" data-i18n=\"se3-lede\"></p>\
         <p class=\"se3-notice\" data-{P}=\"url-notice\" hidden></p></header>\
         <div class=\"se3-top\">\
         <section class=\"se3-card\"><h2 data-i18n=\"se3-view-title\"></h2>\
         <div class=\"se3-view\" data-{P}=\"view\" data-section=\"frames\"></div>\
         <p class=\"se3-note\" data-i18n=\"se3-view-note\"></p></section>\
         <div class=\"se3-side\">\
         <section class=\"se3-card\" data-section=\"readouts\"><h2 data-i18n=\"se3-result-title\"></h2>{readouts}{live}\
         <p class=\"se3-check\"><span data-i18n=\"se3-check-label\"></span> \
         <strong data-readout=\"check-error\"></strong></p></section>\
         <section class=\"se3-card\" data-section=\"poses\"><h2 data-i18n=\"se3-poses-title\"></h2>\
         <fieldset class=\"se3-unit\" data-{P}=\"unit\"><legend data-i18n=\"se3-unit-legend\"></legend>\
         <label class=\"se3-radio\"><input type=\"radio\" name=\"se3-unit\" value=\"rad\" data-angle-unit=\"rad\">\
         <span data-i18n=\"se3-unit-rad\"></span></label>\
         <label class=\"se3-radio\"><input type=\"radio\" name=\"se3-unit\" value=\"deg\" data-angle-unit=\"deg\">\
         <span data-i18n=\"se3-unit-deg\"></span></label>\
         <p class=\"se3-note\" data-i18n=\"se3-unit-note\"></p></fieldset>\
         <form class=\"se3-form\" data-{P}=\"form\" novalidate></form></section>\
         </div></div>\
         <section class=\"se3-card\" data-section=\"matrices\"><h2 data-i18n=\"se3-matrices-title\"></h2>\
         <div class=\"se3-matrices\">{ma}{mb}{mrel}</div>\
         <h3 data-i18n=\"se3-row-title\"></h3>\
         <pre class=\"se3-row\" data-{P}=\"csv-row\" data-testid=\"se3-relative-row\"></pre>\
         <p class=\"se3-note\" data-i18n=\"se3-check-note\"></p></section>\
         <section class=\"se3-card\" data-section=\"rotations\"><h2 data-i18n=\"se3-rot-title\"></h2>\
         <p class=\"se3-note\" id=\"se3-rot-lede\" data-i18n=\"se3-rot-lede\"></p>\
         <label class=\"se3-select\"><span data-i18n=\"se3-rot-source\"></span> \
         <select data-{P}=\"rot-source\"><option value=\"b\" data-i18n=\"se3-rot-source-b\"></option>\
         <option value=\"a\" data-i18n=\"se3-rot-source-a\"></option>\
         <option value=\"rel\" data-i18n=\"se3-rot-source-rel\"></option></select></label>\
         <div class=\"se3-rot-stage\" data-{P}=\"rot-stage\">\
         <canvas class=\"se3-layer\" data-testid=\"se3-relative-rotations\" role=\"img\" \
         data-i18n-attr=\"aria-label=se3-rot-canvas-label\" aria-describedby=\"se3-rot-lede se3-rot-matrices\"></canvas></div>\
         <div class=\"se3-matrices\" id=\"se3-rot-matrices\">{rrec}{rint}</div>\
         <p class=\"se3-check\"><span data-i18n=\"se3-rot-diff\"></span> \
         <strong data-readout=\"rot-diff\"></strong></p></section>\
         <section class=\"se3-card\" data-section=\"exports\"><h2 data-i18n=\"se3-exports-title\"></h2>\
         <div class=\"se3-buttons\">{csv}\
         <button type=\"button\" class=\"button\" data-download=\"{PNG}\" data-i18n=\"se3-download-png\"></button></div>\
         {commands}</section>\
         <section class=\"se3-card se3-explain\" data-section=\"explain\"><h2 data-i18n=\"se3-explain-title\"></h2>\
         <p data-i18n=\"recipe-se3-relative-blurb\"></p>{explain}\
         <h3 data-i18n=\"se3-explain-quirks-title\"></h3><p data-i18n=\"recipe-se3-relative-quirks\"></p></section>\
         </div>",
        readouts = readouts::markup(P, &READOUTS),
        live = readouts::live_markup(P),
        ma = matrix("a", "se3-matrix-a", 4),
        mb = matrix("b", "se3-matrix-b", 4),
        mrel = matrix("rel", "se3-matrix-rel", 4),
        rrec = matrix("rot-recipe", "se3-rot-recipe", 3),
        rint = matrix("rot-intrinsic", "se3-rot-intrinsic", 3),
        csv = exports::download_button(P, CSV_NAME),
        commands = exports::markup(P),
    )
}
