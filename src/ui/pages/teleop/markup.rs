//! The page's markup: heading, notices and the storage warning, introduction and disclaimer,
//! the module bar, the arm view (the episode's outcome and the gamepad offer over it) with its
//! buttons and the review stepper, the readouts, the preflight checks, the label panel, the
//! episodes with the downloads and the file opener, the repeatability table, the settings and
//! the key map.
//! Every text is a Fluent id (`data-i18n`), filled by the shell. [`role`] and [`find`] find
//! its parts; [`KEYS`] is the key map, shown on the page and in the `?` overlay.

use wasm_bindgen::{JsCast, JsValue};
use web_sys::Element;

use crate::teleop::session::{label_id, Module, CATEGORIES, EPISODES_NAME, EVIDENCE_NAME};
use crate::teleop::Label;
use crate::ui::dom;
use crate::ui::kit::readouts::{self, ReadoutRow};
use crate::ui::kit::review::ReviewIds;
use crate::ui::page::Shortcut;
use crate::view::teleop::IK_IDS;

/// The page's keys.
pub const KEYS: &[Shortcut] = &[
    Shortcut {
        keys: "W / S",
        message_id: "teleop-key-x",
    },
    Shortcut {
        keys: "Q / E",
        message_id: "teleop-key-z",
    },
    Shortcut {
        keys: "→ ← / ↑ ↓",
        message_id: "teleop-key-arrows",
    },
    Shortcut {
        keys: "T / G",
        message_id: "teleop-key-phi",
    },
    Shortcut {
        keys: "K",
        message_id: "teleop-key-gripper",
    },
    Shortcut {
        keys: "R",
        message_id: "teleop-key-reset",
    },
    Shortcut {
        keys: "L",
        message_id: "teleop-key-clear",
    },
    Shortcut {
        keys: "Space",
        message_id: "teleop-key-engage",
    },
];

/// Where the failure review lives.
pub const REVIEW: ReviewIds = ReviewIds {
    attr: "tele",
    stepper: "teleop-stepper",
    timeline: "teleop-timeline",
};

/// An ARIA state's text (`aria-pressed`, `aria-disabled`, ...).
pub fn bool_text(b: bool) -> &'static str {
    if b {
        "true"
    } else {
        "false"
    }
}

/// The element `sel` under `root`.
pub fn find<T: JsCast>(root: &Element, sel: &str) -> Result<T, JsValue> {
    dom::find(root, sel, "teleop")
}

/// The element `[data-tele="name"]` under `root`.
pub fn role<T: JsCast>(root: &Element, name: &str) -> Result<T, JsValue> {
    find(root, &format!("[data-tele=\"{name}\"]"))
}

fn modules() -> String {
    let mut html = String::from(
        "<nav class=\"tele-modules\" data-tele=\"modules\" data-i18n-attr=\"aria-label=teleop-modules-label\"><ol>",
    );
    for (i, m) in Module::ALL.iter().enumerate() {
        html.push_str(&format!(
            "<li><button type=\"button\" class=\"tele-module\" data-module=\"{id}\">\
             <span class=\"tele-module-n\">{n}</span> <span data-i18n=\"teleop-module-{id}\"></span></button>\
             <span class=\"tele-module-why\" id=\"tele-why-{id}\" data-testid=\"module-unlock-{id}\" hidden></span></li>",
            id = m.id(),
            n = i + 1,
        ));
    }
    html.push_str("</ol></nav>");
    html
}

fn readouts_markup() -> String {
    readouts::markup_rows(
        "tele",
        &[
            ReadoutRow {
                label_id: "teleop-ro-tip",
                values: &[
                    ("x", "teleop-unit-m-x"),
                    ("z", "teleop-unit-m-z"),
                    ("phi", "teleop-unit-rad-phi"),
                ],
            },
            ReadoutRow {
                label_id: "teleop-ro-joints",
                values: &[
                    ("q1", "teleop-unit-rad"),
                    ("q2", "teleop-unit-rad"),
                    ("q3", "teleop-unit-rad"),
                ],
            },
            ReadoutRow {
                label_id: "teleop-ro-manipulability",
                values: &[("manipulability", "teleop-unit-m2")],
            },
            ReadoutRow {
                label_id: "teleop-ro-time",
                values: &[("time", "teleop-unit-s")],
            },
        ],
    ) + &readouts::markup(
        "tele",
        &[
            ("episode", "teleop-ro-episode"),
            ("state", "teleop-ro-state"),
            ("gripper", "teleop-ro-gripper"),
        ],
    )
}

fn labels() -> String {
    let mut html = String::from(
        "<section class=\"tele-card tele-label\" data-tele=\"label-panel\" hidden>\
         <h2 data-tele=\"label-title\"></h2><p data-tele=\"label-summary\"></p>\
         <p class=\"tele-note\" data-tele=\"label-proposal\"></p>\
         <div class=\"tele-choice\" role=\"group\" data-i18n-attr=\"aria-label=teleop-label-group\">",
    );
    for l in [Label::Success, Label::Failure, Label::Partial] {
        let id = label_id(l);
        html.push_str(&format!(
            "<button type=\"button\" class=\"button tele-pick\" data-label=\"{id}\" aria-pressed=\"false\" \
             data-i18n=\"teleop-label-{lower}\"></button>",
            lower = id.to_ascii_lowercase(),
        ));
    }
    html.push_str(
        "</div><p class=\"tele-sub\" data-i18n=\"teleop-category-title\"></p>\
         <div class=\"tele-choice tele-categories\" role=\"group\" data-i18n-attr=\"aria-label=teleop-category-title\">",
    );
    for c in CATEGORIES {
        html.push_str(&format!(
            "<button type=\"button\" class=\"button tele-pick\" data-category=\"{id}\" aria-pressed=\"false\" \
             data-i18n=\"teleop-cat-{id}\"></button>",
            id = c.id(),
        ));
    }
    html.push_str(
        "</div><label class=\"tele-field\"><span data-i18n=\"teleop-note-label\"></span>\
         <textarea rows=\"2\" maxlength=\"500\" data-field=\"note\"></textarea></label>\
         <div class=\"tele-buttons\"><button type=\"button\" class=\"button primary\" data-action=\"confirm-label\" \
         data-i18n=\"teleop-label-confirm\"></button></div></section>",
    );
    html
}

fn field(name: &str, input: &str) -> String {
    format!(
        "<div class=\"tele-field\" data-field-wrap=\"{name}\">\
         <label for=\"tele-f-{name}\" data-i18n=\"teleop-field-{name}\"></label>{input}\
         <p class=\"tele-hint\" data-i18n=\"teleop-hint-{name}\"></p>\
         <p class=\"tele-error\" data-field-error=\"{name}\" role=\"alert\" hidden></p></div>"
    )
}

fn text_input(name: &str, mode: &str) -> String {
    field(
        name,
        &format!(
            "<input id=\"tele-f-{name}\" type=\"text\" inputmode=\"{mode}\" autocomplete=\"off\" \
             spellcheck=\"false\" data-field=\"{name}\" aria-describedby=\"tele-e-{name}\">"
        ),
    )
}

fn select(name: &str, options: &[(&str, String)]) -> String {
    let mut s = format!("<select id=\"tele-f-{name}\" data-field=\"{name}\">");
    for (value, label_id) in options {
        s.push_str(&format!(
            "<option value=\"{value}\" data-i18n=\"{label_id}\"></option>"
        ));
    }
    s.push_str("</select>");
    field(name, &s)
}

fn settings() -> String {
    let tasks: Vec<(&str, String)> = crate::teleop::Task::IDS
        .iter()
        .map(|t| (*t, format!("teleop-task-{t}")))
        .collect();
    let iks: Vec<(&str, String)> = IK_IDS
        .iter()
        .map(|m| (*m, format!("teleop-ik-{m}")))
        .collect();
    format!(
        "<form class=\"tele-form\" data-tele=\"settings\" novalidate>{}{}{}{}{}{}{}{}{}{}</form>\
         <p class=\"tele-note\" data-tele=\"settings-note\" data-i18n=\"teleop-settings-note\"></p>",
        text_input("pilot", "text"),
        select("task", &tasks),
        select("ik", &iks),
        text_input("lambda", "decimal"),
        text_input("latency_ms", "numeric"),
        text_input("noise", "decimal"),
        text_input("time_box_s", "decimal"),
        text_input("pos_sensitivity", "decimal"),
        text_input("rot_sensitivity", "decimal"),
        text_input("dead_zone", "decimal"),
    )
}

fn keymap() -> String {
    let mut html = String::from("<dl class=\"tele-keys\">");
    for key in KEYS {
        html.push_str(&format!(
            "<div><dt><kbd>{}</kbd></dt><dd data-i18n=\"{}\"></dd></div>",
            key.keys, key.message_id
        ));
    }
    html.push_str("</dl>");
    html
}

/// The warning that the session is not saved, with its downloads.
fn storage_warning() -> String {
    crate::ui::kit::pilot_session::storage_warning_markup(
        EPISODES_NAME,
        "tele-notice tele-warning",
        "tele-buttons",
        "button",
    )
}

/// The offer to use a gamepad that sends input while another device is chosen.
fn gamepad_offer() -> String {
    "<div class=\"tele-offer\" data-testid=\"gamepad-offer\" role=\"status\" hidden>\
     <p data-tele=\"offer-text\"></p><div class=\"tele-buttons\">\
     <button type=\"button\" class=\"button primary\" data-action=\"use-gamepad\" \
     data-i18n=\"teleop-pad-offer-use\"></button>\
     <button type=\"button\" class=\"button\" data-action=\"dismiss-gamepad\" \
     data-i18n=\"teleop-pad-offer-dismiss\"></button></div></div>"
        .to_string()
}

/// The page's HTML.
pub fn page() -> String {
    format!(
        "<div class=\"tele\">\
         <header class=\"tele-head\"><h1 data-i18n=\"teleop-title\"></h1><p class=\"tele-task\" data-i18n=\"teleop-head-lede\"></p>\
         <p class=\"tele-notice\" data-tele=\"loading\" role=\"status\" hidden></p>\
         <p class=\"tele-notice\" data-tele=\"restored\" role=\"status\" hidden></p>{storage}</header>\
         {modules}\
         <p class=\"tele-module-help\" data-tele=\"module-help\"></p>\
         <div class=\"tele-top\">\
         <section class=\"tele-card tele-view\">\
         <div class=\"tele-stage\" data-tele=\"stage\" data-section=\"world\">\
         <canvas class=\"tele-canvas\" data-testid=\"teleop-canvas\" tabindex=\"0\" role=\"img\" aria-describedby=\"tele-readouts-list tele-readouts\" \
         data-i18n-attr=\"aria-label=teleop-canvas-label\"></canvas>\
         <div class=\"tele-overlay\">{control}\
         <p class=\"tele-ended\" data-tele=\"ended\" data-testid=\"episode-outcome\" role=\"status\" hidden></p>\
         {offer}</div></div>\
         <p class=\"tele-stop\" data-tele=\"stop\" role=\"status\"></p>\
         <div class=\"tele-buttons\" data-tele=\"live-buttons\">\
         <button type=\"button\" class=\"button primary\" data-action=\"engage\" aria-pressed=\"true\"></button>\
         <button type=\"button\" class=\"button\" data-action=\"gripper\" aria-pressed=\"false\"></button>\
         <button type=\"button\" class=\"button\" data-action=\"reset\" data-i18n=\"teleop-reset\"></button>\
         <button type=\"button\" class=\"button\" data-action=\"end-episode\" data-i18n=\"teleop-end-episode\"></button>\
         <button type=\"button\" class=\"button\" data-action=\"next-module\" data-i18n=\"teleop-next-module\"></button></div>\
         <p class=\"tele-device\" data-tele=\"device-status\" role=\"status\"></p>\
         {review}\
         </section>\
         <section class=\"tele-card\" data-section=\"readouts\"><h2 data-i18n=\"teleop-readouts-title\"></h2>{readouts}{live}\
         <section class=\"tele-preflight\" data-tele=\"preflight\" data-section=\"device\"><h3 data-i18n=\"teleop-preflight-title\"></h3>\
         <div class=\"tele-choice\" role=\"radiogroup\" data-i18n-attr=\"aria-label=teleop-device-label\">\
         <button type=\"button\" class=\"button tele-pick\" role=\"radio\" data-device=\"keyboard\" aria-checked=\"true\" data-i18n=\"teleop-device-keyboard\"></button>\
         <button type=\"button\" class=\"button tele-pick\" role=\"radio\" data-device=\"gamepad\" aria-checked=\"false\" data-i18n=\"teleop-device-gamepad\"></button>\
         <button type=\"button\" class=\"button tele-pick\" role=\"radio\" data-device=\"pointer\" aria-checked=\"false\" data-i18n=\"teleop-device-pointer\"></button></div>\
         <ul class=\"tele-checks\"><li data-check=\"moved\" data-i18n=\"teleop-check-moved\"></li>\
         <li data-check=\"reset\" data-i18n=\"teleop-check-reset\"></li></ul></section>\
         <h3 data-i18n=\"teleop-keys-title\"></h3>{keys}\
         <p class=\"tele-note\" data-i18n=\"teleop-pad-map\"></p>\
         <p class=\"tele-note\" data-i18n=\"teleop-pointer-map\"></p>\
         <p class=\"tele-note\" data-i18n=\"teleop-limits\"></p></section>\
         </div>\
         <div class=\"tele-intro\"><p class=\"tele-lede\" data-i18n=\"teleop-lede\"></p>\
         <p class=\"tele-disclaimer\" data-testid=\"teleop-disclaimer\" data-i18n=\"teleop-disclaimer\"></p></div>\
         {labels}\
         <section class=\"tele-card\" data-section=\"session\"><h2 data-i18n=\"teleop-episodes-title\"></h2>\
         <p class=\"tele-note\" data-tele=\"session-line\"></p>\
         <div class=\"tele-table-wrap\"><table class=\"tele-table\" data-tele=\"episodes\"><thead><tr>\
         <th data-i18n=\"teleop-col-n\"></th><th data-i18n=\"teleop-col-label\"></th><th data-i18n=\"teleop-col-category\"></th>\
         <th data-i18n=\"teleop-col-duration\"></th><th data-i18n=\"teleop-col-path\"></th><th data-i18n=\"teleop-col-efficiency\"></th>\
         <th data-i18n=\"teleop-col-collisions\"></th><th data-i18n=\"teleop-col-first\"></th><th data-i18n=\"teleop-col-actions\"></th>\
         </tr></thead><tbody></tbody></table></div>\
         <div class=\"tele-buttons\">\
         <button type=\"button\" class=\"button\" data-download=\"{EPISODES_NAME}\"></button>\
         <button type=\"button\" class=\"button\" data-download=\"{EVIDENCE_NAME}\"></button>\
         <label class=\"button tele-open\"><span data-i18n=\"teleop-open\"></span>\
         <input type=\"file\" multiple accept=\".json,.csv,application/json,text/csv\" data-tele=\"open\" class=\"kit-visually-hidden\"></label>\
         <button type=\"button\" class=\"button\" data-action=\"new-session\" data-i18n=\"teleop-new-session\"></button></div>\
         <p class=\"tele-note\" data-tele=\"export-progress\" data-state=\"idle\" role=\"status\" hidden></p>\
         <p class=\"tele-note\" data-i18n=\"teleop-open-note\"></p>\
         <p class=\"tele-error\" data-tele=\"open-error\" role=\"alert\" hidden></p>\
         <p class=\"tele-note\" data-tele=\"status\" role=\"status\"></p></section>\
         <section class=\"tele-card\" data-tele=\"repeat\"><h2 data-i18n=\"teleop-repeat-title\"></h2>\
         <p class=\"tele-note\" data-i18n=\"teleop-repeat-note\"></p>\
         <div class=\"tele-buttons\"><button type=\"button\" class=\"button\" data-action=\"second-session\" \
         data-i18n=\"teleop-second-session\"></button></div>\
         <div class=\"tele-table-wrap\"><table class=\"tele-table\" data-tele=\"compare\"><thead><tr>\
         <th data-i18n=\"teleop-col-figure\"></th><th data-i18n=\"teleop-col-first-session\"></th>\
         <th data-i18n=\"teleop-col-second-session\"></th></tr></thead><tbody></tbody></table></div></section>\
         <section class=\"tele-card\" data-section=\"form\"><h2 data-i18n=\"teleop-settings-title\"></h2>{settings}</section>\
         <section class=\"tele-card\" data-section=\"explain\"><h2 data-i18n=\"teleop-about-title\"></h2>\
         <p data-i18n=\"teleop-about-control\"></p><p data-i18n=\"teleop-about-session\"></p>\
         <p data-i18n=\"teleop-about-not\"></p></section>\
         </div>",
        modules = modules(),
        storage = storage_warning(),
        control = crate::ui::kit::pilot_control::markup("tele"),
        offer = gamepad_offer(),
        readouts = readouts_markup(),
        live = readouts::live_markup("tele"),
        keys = keymap(),
        labels = labels(),
        settings = settings(),
        review = crate::ui::kit::review::markup(REVIEW),
    )
}
