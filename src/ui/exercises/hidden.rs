//! The readouts that give a prediction's answer away (`data-readout` keys of its page), blurred
//! while the learner predicts: from the moment they go to the field until the answer shows
//! (right, revealed) or they leave the field empty. A readout stays in its place (the page does
//! not move) and out of the accessibility tree while blurred.

use wasm_bindgen::JsValue;
use web_sys::Element;

use crate::ui::dom;

/// Exercise id → the readouts that show its answer.
const ANSWER_READOUTS: &[(&str, &[&str])] = &[
    ("ik-w-pose", &["manipulability"]),
    ("dh-tip-height", &["z"]),
    ("umeyama-angle", &["angle"]),
    ("pendulum-euler-dt", &["drift", "drift-euler"]),
    ("pendulum-period", &["period"]),
    ("pid-final-y", &["final-y"]),
    ("pid-overshoot", &["overshoot"]),
    ("cubic-peak-velocity", &["peak-velocity"]),
    ("trap-accel-end", &["t-acc"]),
    ("trap-total-time", &["t-total"]),
    ("rrt-path-length", &["length"]),
];

/// The readouts that show exercise `id`'s answer.
pub fn answer_readouts(id: &str) -> &'static [&'static str] {
    ANSWER_READOUTS
        .iter()
        .find(|(e, _)| *e == id)
        .map_or(&[], |(_, keys)| keys)
}

/// Blurs the readouts `keys` under `root` (outside `section`) and shows every other one.
pub fn hide_only(root: &Element, section: &Element, keys: &[&str]) -> Result<(), JsValue> {
    for readout in dom::matching(root, "[data-readout]")? {
        if section.contains(Some(&readout)) {
            continue;
        }
        let hide = readout
            .get_attribute("data-readout")
            .is_some_and(|k| keys.contains(&k.as_str()));
        if hide != readout.has_attribute("data-ex-hidden") {
            if hide {
                readout.set_attribute("data-ex-hidden", "")?;
                readout.set_attribute("aria-hidden", "true")?;
            } else {
                readout.remove_attribute("data-ex-hidden")?;
                readout.remove_attribute("aria-hidden")?;
            }
        }
    }
    Ok(())
}
