//! The page's markup: heading, the 3D view slot with its axis legend, the tip readouts, the
//! joints (sliders and the kit form of `angles`), the modified-DH table, the "show one row"
//! panel, the frame poses, the exports and the explanation. Every text is a Fluent id
//! (`data-i18n`), filled by the shell; numbers are written by the components.

use crate::recipes::dh_fk::INFO;
use crate::ui::kit::readouts;
use crate::ui::kit::recipe_controls;
use crate::view::dh_fk::Elementary;

/// Class and `data-` prefix of the page.
pub const P: &str = "dh";
/// The PNG of the 3D view.
pub const PNG: &str = "dh_fk_view.png";
/// `(data-readout, label id)`: the tip (frame 3).
pub const READOUTS: [(&str, &str); 6] = [
    ("x", "dh-ro-x"),
    ("y", "dh-ro-y"),
    ("z", "dh-ro-z"),
    ("roll", "dh-ro-roll"),
    ("pitch", "dh-ro-pitch"),
    ("yaw", "dh-ro-yaw"),
];

fn dh_table() -> String {
    let head: String = ["i", "alpha", "a", "d", "theta", "show"]
        .iter()
        .map(|c| format!("<th scope=\"col\" data-i18n=\"dh-col-{c}\"></th>"))
        .collect();
    let rows: String = (1..=3)
        .map(|i| {
            format!(
                "<tr data-dh-row=\"{i}\"><th scope=\"row\">{i}</th><td data-cell=\"alpha\"></td>\
                 <td data-cell=\"a\"></td><td data-cell=\"d\"></td><td data-cell=\"theta\"></td>\
                 <td><button type=\"button\" class=\"tool-button dh-row-button\" data-row=\"{i}\" \
                 aria-pressed=\"false\" data-i18n=\"dh-show-row-{i}\"></button></td></tr>"
            )
        })
        .collect();
    format!(
        "<div class=\"dh-scroll\"><table class=\"dh-table\" data-testid=\"dh-fk-dh-table\">\
         <thead><tr>{head}</tr></thead><tbody>{rows}</tbody></table></div>"
    )
}

fn pose_table() -> String {
    let head: String = ["frame", "x", "y", "z", "roll", "pitch", "yaw"]
        .iter()
        .map(|c| format!("<th scope=\"col\" data-i18n=\"dh-pose-{c}\"></th>"))
        .collect();
    let rows: String = (0..=3)
        .map(|i| {
            let cells: String = (0..7).map(|_| "<td></td>").collect::<Vec<_>>().join("");
            format!("<tr data-pose-row=\"{i}\">{cells}</tr>")
        })
        .collect();
    format!(
        "<div class=\"dh-scroll\"><table class=\"dh-table dh-pose\" data-testid=\"dh-fk-pose-table\">\
         <thead><tr>{head}</tr></thead><tbody>{rows}</tbody></table></div>"
    )
}

/// A 4×4 matrix of empty cells, `data-testid="dh-fk-<name>"`.
fn matrix(name: &str) -> String {
    let rows: String = (0..4)
        .map(|r| {
            let cells: String = (0..4)
                .map(|c| format!("<td data-rc=\"{r}{c}\"></td>"))
                .collect();
            format!("<tr>{cells}</tr>")
        })
        .collect();
    format!(
        "<figure class=\"dh-matrix-box\"><figcaption data-dh=\"{name}-caption\"></figcaption>\
         <table class=\"dh-matrix\" data-testid=\"dh-fk-{name}\"><tbody>{rows}</tbody></table></figure>"
    )
}

fn walk_panel() -> String {
    let steps: String = Elementary::ALL
        .iter()
        .enumerate()
        .map(|(k, e)| {
            format!(
                "<li data-step=\"{n}\" data-kind=\"{id}\"><span class=\"dh-step-symbol\"></span> \
                 <span class=\"dh-step-text\"></span></li>",
                n = k + 1,
                id = e.id()
            )
        })
        .collect();
    format!(
        "<p class=\"dh-note\" data-i18n=\"dh-walk-intro\"></p>\
         <p class=\"dh-walk-where\" data-dh=\"walk-where\" aria-live=\"polite\"></p>\
         <div data-dh=\"stepper\"></div>\
         <ol class=\"dh-steps\" data-testid=\"dh-fk-steps\">{steps}</ol>\
         <div class=\"dh-matrices\">{e}{m}</div>",
        e = matrix("elementary"),
        m = matrix("product"),
    )
}

fn joints() -> String {
    let sliders: String = (1..=3)
        .map(|i| {
            format!(
                "<div class=\"dh-joint\"><label for=\"dh-q{i}\" data-i18n=\"dh-q{i}\"></label>\
                 <input id=\"dh-q{i}\" type=\"range\" class=\"kit-slider dh-slider\" min=\"-3.14\" max=\"3.14\" \
                 step=\"0.01\" data-slider=\"q{i}\"><output for=\"dh-q{i}\" data-dh=\"q{i}-value\"></output></div>"
            )
        })
        .collect();
    format!("<div class=\"dh-joints\">{sliders}</div>")
}

/// The page's HTML.
pub fn page() -> String {
    let (form, notice, exports) = recipe_controls::markup(P, &INFO, PNG, "dh-png");
    let explain: String = ["what", "input", "steps", "expected"]
        .iter()
        .map(|k| {
            format!(
                "<h3 data-i18n=\"dh-explain-{k}-title\"></h3><p data-i18n=\"dh-explain-{k}\"></p>"
            )
        })
        .collect();
    format!(
        "<div class=\"kit-page dh\" data-testid=\"dh-fk-page\">\
         <header class=\"dh-head\"><h1 data-i18n=\"dh-title\"></h1>\
         <p class=\"dh-lede\" data-i18n=\"recipe-dh-fk-blurb\"></p>{notice}</header>\
         <div class=\"dh-top\">\
         <section class=\"dh-card\"><h2 data-i18n=\"dh-view-title\"></h2>\
         <div data-dh=\"view\" data-section=\"arm\"></div>\
         <div class=\"dh-legend\" data-dh=\"legend\" data-palette=\"classic\">\
         <span class=\"dh-key\"><span class=\"dh-swatch dh-swatch-x\"></span><span data-i18n=\"dh-legend-x\"></span></span>\
         <span class=\"dh-key\"><span class=\"dh-swatch dh-swatch-y\"></span><span data-i18n=\"dh-legend-y\"></span></span>\
         <span class=\"dh-key\"><span class=\"dh-swatch dh-swatch-z\"></span><span data-i18n=\"dh-legend-z\"></span></span>\
         <span class=\"dh-key\"><span class=\"dh-swatch dh-swatch-axis\"></span><span data-i18n=\"dh-legend-axis\"></span></span>\
         <label class=\"dh-check\"><input type=\"checkbox\" data-option=\"cb-axes\">\
         <span data-i18n=\"dh-cb-axes\"></span></label></div></section>\
         <div class=\"dh-side\">\
         <section class=\"dh-card\" data-section=\"readouts\"><h2 data-i18n=\"dh-readouts-title\"></h2>{ro}{live}</section>\
         <section class=\"dh-card\" data-section=\"joints\"><h2 data-i18n=\"dh-joints-title\"></h2>{joints}{form}</section>\
         </div></div>\
         <div class=\"dh-mid\">\
         <section class=\"dh-card\" data-section=\"table\"><h2 data-i18n=\"dh-table-title\"></h2>{dh}\
         <p class=\"dh-note\" data-i18n=\"dh-table-note\"></p></section>\
         <section class=\"dh-card\" data-section=\"row\"><h2 data-i18n=\"dh-walk-title\"></h2>{walk}</section>\
         </div>\
         <section class=\"dh-card\" data-section=\"poses\"><h2 data-i18n=\"dh-pose-title\"></h2>{pose}\
         <p class=\"dh-note\" data-i18n=\"dh-pose-note\"></p></section>\
         <section class=\"dh-card\" data-section=\"exports\"><h2 data-i18n=\"dh-exports-title\"></h2>{exports}</section>\
         <section class=\"dh-card dh-explain\" data-section=\"explain\"><h2 data-i18n=\"dh-explain-title\"></h2>\
         <h3 data-i18n=\"dh-convention-title\"></h3><p data-i18n=\"dh-convention\"></p>\
         <p data-i18n=\"dh-convention-standard\"></p>{explain}\
         <h3 data-i18n=\"dh-quirks-title\"></h3><p data-i18n=\"recipe-dh-fk-quirks\"></p></section>\
         </div>",
        ro = readouts::markup(P, &READOUTS),
        live = readouts::live_markup(P),
        joints = joints(),
        dh = dh_table(),
        walk = walk_panel(),
        pose = pose_table(),
    )
}
