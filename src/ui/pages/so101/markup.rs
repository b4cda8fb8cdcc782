//! The page's markup: heading and introduction, the storage warning, the world view's slot
//! (the gamepad offer and the episode's outcome over it) beside the wrist camera, the arm's
//! buttons, the failure review, the disclaimer, the module bar and the device choice, the
//! readouts and the orientation sentence, the label panel, the episodes with their downloads,
//! the file opener and the summary, the repeatability table, the settings and the key map.
//! Every text is a Fluent id (`data-i18n`), filled by the shell.

use crate::so101::episode::Episode;
use crate::teleop::session::{InputDevice, Module, PracticeEpisode, CATEGORIES, EVIDENCE_NAME};
use crate::teleop::Label;
use crate::ui::kit::keymap::key;
use crate::ui::kit::readouts;
use crate::ui::kit::review::ReviewIds;
use crate::ui::page::Shortcut;
use crate::view::teleop::IK_IDS;

/// Class and `data-` prefix of the page.
pub const P: &str = "so101";

/// Where the failure review lives.
pub const REVIEW: ReviewIds = ReviewIds {
    attr: "so101",
    stepper: "so101-stepper",
    timeline: "so101-timeline",
};

/// The page's keys (Isaac Lab's Se3Keyboard).
pub const KEYS: &[Shortcut] = &[
    key("W / S", "so101-key-x"),
    key("A / D", "so101-key-y"),
    key("Q / E", "so101-key-z"),
    key("Z / X", "so101-key-roll"),
    key("T / G", "so101-key-pitch"),
    key("C / V", "so101-key-yaw"),
    key("K", "teleop-key-gripper"),
    key("R", "teleop-key-reset"),
    key("Space", "teleop-key-engage"),
];

/// A row of the readout tables: `data-readout` key, label id, unit.
struct Row(&'static str, &'static str, &'static str);

/// The control, the episode and the tool's pose.
const TOOL_ROWS: [Row; 10] = [
    Row("state", "teleop-ro-state", ""),
    Row("episode", "teleop-ro-episode", ""),
    Row("gripper", "teleop-ro-gripper", ""),
    Row("x", "so101-ro-x", "mm"),
    Row("y", "so101-ro-y", "mm"),
    Row("z", "so101-ro-z", "mm"),
    Row("roll", "so101-ro-roll", "°"),
    Row("pitch", "so101-ro-pitch", "°"),
    Row("yaw", "so101-ro-yaw", "°"),
    Row("time", "teleop-ro-time", "s"),
];

/// The joints (their limits beside them), the manipulability and the orientation error.
const JOINT_ROWS: [Row; 7] = [
    Row("q1", "so101-ro-q1", "°"),
    Row("q2", "so101-ro-q2", "°"),
    Row("q3", "so101-ro-q3", "°"),
    Row("q4", "so101-ro-q4", "°"),
    Row("q5", "so101-ro-q5", "°"),
    Row("manipulability", "so101-ro-manipulability", "m³"),
    Row("orientation-error", "so101-ro-orientation-error", "°"),
];

/// The readouts as two tables (name, value, unit, limit; the value alone in its cell, in
/// tabular digits), `id="so101-readouts"`: the views' text alternative.
fn readout_tables() -> String {
    let table = |caption: &str, rows: &[Row]| -> String {
        let mut html = format!(
            "<table class=\"so101-ro\"><caption data-i18n=\"{caption}\"></caption><thead><tr>\
             <th scope=\"col\" data-i18n=\"so101-col-readout\"></th><th scope=\"col\" data-i18n=\"so101-col-value\"></th>\
             <th scope=\"col\" data-i18n=\"so101-col-unit\"></th><th scope=\"col\" data-i18n=\"so101-col-limit\"></th>\
             </tr></thead><tbody>"
        );
        for Row(key, label, unit) in rows {
            let limit = key
                .strip_prefix('q')
                .and_then(|n| n.parse::<usize>().ok())
                .filter(|n| (1..=5).contains(n))
                .map_or(String::new(), |n| {
                    crate::view::so101::joint_limits_text(n - 1)
                });
            html.push_str(&format!(
                "<tr><th scope=\"row\" data-i18n=\"{label}\"></th>\
                 <td class=\"so101-ro-value\" data-readout=\"{key}\"></td>\
                 <td class=\"so101-ro-unit\">{unit}</td><td class=\"so101-ro-limit\">{limit}</td></tr>"
            ));
        }
        html.push_str("</tbody></table>");
        html
    };
    format!(
        "<div class=\"so101-ro-tables\" id=\"so101-readouts\">{}{}</div>",
        table("so101-ro-tool-caption", &TOOL_ROWS),
        table("so101-ro-joints-caption", &JOINT_ROWS)
    )
}

fn button(action: &str, label: &str) -> String {
    format!(
        "<button type=\"button\" class=\"tool-button so101-button\" data-action=\"{action}\" \
         data-i18n=\"{label}\"></button>"
    )
}

/// A row of toggle buttons `data-<attr>="<id>"` labelled `<prefix><id>`.
fn toggles(attr: &str, class: &str, prefix: &str, ids: &[&str]) -> String {
    ids.iter()
        .map(|id| {
            format!(
                "<button type=\"button\" class=\"tool-button {class}\" data-{attr}=\"{id}\" \
                 aria-pressed=\"false\" data-i18n=\"{prefix}{id}\"></button>"
            )
        })
        .collect()
}

fn modules() -> String {
    let modules: Vec<&str> = Module::ALL.iter().map(|m| m.id()).collect();
    let devices: Vec<&str> = InputDevice::ALL.iter().map(|d| d.id()).collect();
    format!(
        "<div class=\"so101-modules\" role=\"group\" data-i18n-attr=\"aria-label=teleop-modules-label\">\
         {modules}</div><p class=\"so101-help\" data-so101=\"module-help\"></p>\
         <div class=\"so101-devices\" role=\"group\" data-so101=\"devices\" data-section=\"device\" data-i18n-attr=\"aria-label=teleop-device-label\">\
         <span data-i18n=\"teleop-device-label\"></span>{devices}</div>\
         <ul class=\"so101-checks\" data-so101=\"preflight\">\
         <li data-check=\"moved\" data-state=\"todo\"><span data-i18n=\"teleop-check-moved\"></span></li>\
         <li data-check=\"reset\" data-state=\"todo\"><span data-i18n=\"teleop-check-reset\"></span></li></ul>",
        modules = toggles("module", "so101-module", "teleop-module-", &modules),
        devices = toggles("device", "so101-device", "teleop-device-", &devices),
    )
}

fn views() -> String {
    format!(
        "<div class=\"so101-views\">\
         <div class=\"so101-world\" data-so101=\"world\" data-section=\"arm\">{control}\
         <div class=\"so101-offer\" data-testid=\"gamepad-offer\" hidden>\
         <p data-so101=\"offer-text\"></p>{use_pad}{dismiss}</div>\
         <p class=\"so101-ended\" data-testid=\"episode-outcome\" data-so101=\"ended\" hidden></p>\
         </div>\
         <div class=\"so101-side\"><figure class=\"so101-wrist\" data-section=\"wrist\"><div class=\"so101-wrist-stage\" data-so101=\"wrist-stage\">\
         <canvas data-testid=\"so101-wrist\" role=\"img\" aria-describedby=\"so101-readouts\" data-i18n-attr=\"aria-label=so101-wrist-label\"></canvas>\
         </div><figcaption data-i18n=\"so101-wrist-caption\"></figcaption></figure>\
         <p class=\"so101-lede\" data-i18n=\"so101-lede\"></p></div>\
         </div>\
         <div class=\"so101-buttons\" data-so101=\"live-buttons\">{engage}{gripper}{reset}{end}</div>{review}",
        control = crate::ui::kit::pilot_control::markup(P),
        use_pad = button("use-gamepad", "teleop-pad-offer-use"),
        dismiss = button("dismiss-gamepad", "teleop-pad-offer-dismiss"),
        engage = button("engage", "teleop-engage"),
        gripper = button("gripper", "teleop-gripper-close-button"),
        reset = button("reset", "teleop-reset"),
        end = button("end-episode", "teleop-end-episode"),
        review = crate::ui::kit::review::markup(REVIEW),
    )
}

fn label_panel() -> String {
    let mut html = String::from(
        "<section class=\"so101-labels\" data-so101=\"label-panel\" hidden>\
         <h2 data-so101=\"label-title\"></h2><p data-so101=\"label-proposal\"></p>\
         <div role=\"group\" class=\"so101-label-row\" data-i18n-attr=\"aria-label=teleop-label-group\">",
    );
    for l in Label::ALL {
        html.push_str(&format!(
            "<button type=\"button\" class=\"tool-button\" data-label=\"{id}\" aria-pressed=\"false\" \
             data-i18n=\"teleop-label-{low}\"></button>",
            id = l.id(),
            low = l.id().to_ascii_lowercase()
        ));
    }
    html.push_str(
        "</div><p data-i18n=\"teleop-category-title\"></p><div role=\"group\" class=\"so101-label-row\">",
    );
    let categories: Vec<&str> = CATEGORIES.iter().map(|c| c.id()).collect();
    html.push_str(&toggles("category", "", "teleop-cat-", &categories));
    html.push_str(&format!(
        "</div><label class=\"so101-note\"><span data-i18n=\"teleop-note-label\"></span>\
         <input type=\"text\" data-field=\"note\" maxlength=\"200\"></label>{}</section>",
        button("confirm-label", "teleop-label-confirm")
    ));
    html
}

fn episodes() -> String {
    let cols: String = [
        "n",
        "label",
        "category",
        "duration",
        "collisions",
        "actions",
    ]
    .iter()
    .map(|c| format!("<th scope=\"col\" data-i18n=\"teleop-col-{c}\"></th>"))
    .collect();
    let table = Episode::episodes_name();
    format!(
        "<section class=\"so101-episodes\" data-section=\"session\"><h2 data-i18n=\"teleop-episodes-title\"></h2>\
         <p data-so101=\"session-line\"></p>\
         <div class=\"so101-scroll\"><table class=\"so101-table\"><thead><tr>{cols}</tr></thead>\
         <tbody data-so101=\"episodes\"></tbody></table></div>\
         <p class=\"so101-downloads\">\
         <button type=\"button\" class=\"tool-button\" data-download=\"{table}\">{table}</button>\
         <button type=\"button\" class=\"tool-button\" data-download=\"{EVIDENCE_NAME}\">{EVIDENCE_NAME}</button>\
         <button type=\"button\" class=\"tool-button\" data-download=\"{zip}\" data-i18n=\"so101-dataset-button\"></button>\
         <label class=\"tool-button so101-open\"><span data-i18n=\"teleop-open\"></span>\
         <input type=\"file\" multiple accept=\".json,.csv,application/json,text/csv\" data-so101=\"open\" class=\"kit-visually-hidden\"></label>\
         </p><p class=\"so101-help\" data-so101=\"dataset-progress\" data-state=\"idle\" role=\"status\" hidden></p>\
         <p class=\"so101-help\" data-i18n=\"so101-dataset-note\"></p>\
         <p class=\"so101-help\" data-i18n=\"so101-open-note\"></p>\
         <p class=\"so101-error\" data-so101=\"open-error\" role=\"alert\" hidden></p>\
         <p class=\"so101-help\" data-so101=\"status\" role=\"status\"></p>\
         <div data-so101=\"summary-block\"><h3 data-i18n=\"so101-summary-title\"></h3>\
         <dl class=\"so101-summary\" data-so101=\"summary\"></dl></div></section>\
         <section class=\"so101-repeat\" data-so101=\"repeat\"><h2 data-i18n=\"teleop-repeat-title\"></h2>\
         <p class=\"so101-help\" data-i18n=\"teleop-repeat-note\"></p>\
         <p class=\"so101-downloads\">{second}</p>\
         <div class=\"so101-scroll\"><table class=\"so101-table\" data-so101=\"compare\"><thead><tr>\
         <th scope=\"col\" data-i18n=\"teleop-col-figure\"></th><th scope=\"col\" data-i18n=\"teleop-col-first-session\"></th>\
         <th scope=\"col\" data-i18n=\"teleop-col-second-session\"></th></tr></thead><tbody></tbody></table></div></section>",
        second = button("second-session", "teleop-second-session"),
        zip = crate::so101::dataset::ZIP_NAME,
    )
}

fn settings() -> String {
    let methods: String = IK_IDS
        .iter()
        .map(|id| format!("<option value=\"{id}\" data-i18n=\"teleop-ik-{id}\"></option>"))
        .collect();
    format!(
        "<details class=\"so101-settings\" data-section=\"form\"><summary data-i18n=\"teleop-settings-title\"></summary>\
         <form data-so101=\"settings\" novalidate>\
         <label><span data-i18n=\"teleop-field-pilot\"></span><input type=\"text\" data-field=\"pilot\" maxlength=\"64\"></label>\
         <label><span data-i18n=\"teleop-field-ik\"></span><select data-field=\"ik\">{methods}</select></label>\
         <label><span data-i18n=\"teleop-field-latency_ms\"></span><input type=\"number\" data-field=\"latency_ms\" min=\"0\" max=\"500\" step=\"10\" value=\"0\"></label>\
         <label><span data-i18n=\"teleop-field-noise\"></span><input type=\"number\" data-field=\"noise\" min=\"0\" max=\"1\" step=\"0.05\" value=\"0\"></label>\
         <label><span data-i18n=\"teleop-field-pos_sensitivity\"></span><input type=\"number\" data-field=\"pos_sensitivity\" min=\"0.05\" max=\"4\" step=\"0.05\"></label>\
         <label><span data-i18n=\"teleop-field-rot_sensitivity\"></span><input type=\"number\" data-field=\"rot_sensitivity\" min=\"0.05\" max=\"4\" step=\"0.05\"></label>\
         <label class=\"so101-check-label\"><input type=\"checkbox\" data-field=\"obstacle\"><span data-i18n=\"so101-field-obstacle\"></span></label>\
         <p class=\"so101-help\" data-i18n=\"so101-settings-note\"></p>\
         </form></details>"
    )
}

fn keys() -> String {
    let items: String = KEYS
        .iter()
        .map(|k| {
            format!(
                "<li><kbd>{}</kbd> <span data-i18n=\"{}\"></span></li>",
                k.keys, k.message_id
            )
        })
        .collect();
    format!(
        "<section class=\"so101-keys\" data-section=\"keys\"><h2 data-i18n=\"teleop-keys-title\"></h2><ul>{items}</ul>\
         <p data-i18n=\"so101-pad-map\"></p><p data-i18n=\"so101-pointer-map\"></p>\
         <p data-i18n=\"so101-source\"></p></section>"
    )
}

/// The whole page.
pub fn page() -> String {
    format!(
        "<div class=\"so101-page\"><h1 data-i18n=\"so101-title\"></h1><p class=\"so101-task\" data-i18n=\"so101-head-lede\"></p>\
         <p class=\"so101-notice\" data-so101=\"restored\" data-i18n=\"teleop-restored\" hidden></p>\
         {storage}{views}\
         <p class=\"so101-disclaimer\" data-i18n=\"teleop-disclaimer\"></p>{modules}\
         <section class=\"so101-readouts\" data-section=\"readouts\"><h2 data-i18n=\"teleop-readouts-title\"></h2>{ro}\
         <p class=\"so101-why\" data-so101=\"orientation-why\" data-i18n=\"so101-orientation-why\"></p>\
         <p class=\"so101-why\" data-so101=\"grasp-rule\" data-i18n=\"so101-grasp-rule\"></p></section>\
         {labels}{episodes}{settings}{keys}{live}</div>",
        storage = crate::ui::kit::pilot_session::storage_warning_markup(
            &Episode::episodes_name(),
            "so101-notice so101-warning",
            "so101-downloads",
            "tool-button",
        ),
        modules = modules(),
        views = views(),
        ro = readout_tables(),
        labels = label_panel(),
        episodes = episodes(),
        settings = settings(),
        keys = keys(),
        live = readouts::live_markup(P),
    )
}
