//! The settings form: task, IK method, λ, latency, noise, time box, the active device's
//! sensitivities, the gamepad's dead zone and the pilot id. Every edit is checked by
//! `crate::view::teleop::check`; each problem is shown beside its field in the current
//! language (`data-field-error`), and only a valid set reaches the page (the last valid one
//! stays in force).

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::{Element, HtmlInputElement, HtmlSelectElement};

use crate::ui::{ctx, dom};
use crate::view::teleop::{check, FieldProblem, Settings, SettingsTexts, FIELDS};

/// The form.
pub struct SettingsForm {
    pub element: Element,
    controls: Vec<(&'static str, Element)>,
    errors: Vec<(&'static str, Element)>,
    /// The problems shown (kept to redraw them in another language).
    problems: Vec<FieldProblem>,
}

impl SettingsForm {
    /// Finds the form's fields under `form`.
    pub fn find(form: Element) -> Result<SettingsForm, JsValue> {
        let mut controls = Vec::new();
        let mut errors = Vec::new();
        for name in FIELDS {
            controls.push((
                name,
                dom::find(&form, &format!("[data-field=\"{name}\"]"), "teleop")?,
            ));
            errors.push((
                name,
                dom::find(&form, &format!("[data-field-error=\"{name}\"]"), "teleop")?,
            ));
        }
        Ok(SettingsForm {
            element: form,
            controls,
            errors,
            problems: Vec::new(),
        })
    }

    /// Writes `texts` into the fields.
    pub fn show(&self, texts: &SettingsTexts) {
        for (name, el) in &self.controls {
            let v = texts.get(name);
            if let Some(i) = el.dyn_ref::<HtmlInputElement>() {
                i.set_value(v);
            } else if let Some(s) = el.dyn_ref::<HtmlSelectElement>() {
                s.set_value(v);
            }
        }
    }

    /// The fields' texts.
    pub fn texts(&self) -> SettingsTexts {
        let mut t = SettingsTexts::defaults(crate::teleop::session::InputDevice::Keyboard);
        for (name, el) in &self.controls {
            let v = if let Some(i) = el.dyn_ref::<HtmlInputElement>() {
                i.value()
            } else if let Some(s) = el.dyn_ref::<HtmlSelectElement>() {
                s.value()
            } else {
                String::new()
            };
            t.set(name, &v);
        }
        t
    }

    /// Checks the fields; shows each problem beside its field; the settings if all are valid.
    pub fn check(&mut self) -> Option<Settings> {
        let result = check(&self.texts());
        self.problems = match &result {
            Ok(_) => Vec::new(),
            Err(p) => p.clone(),
        };
        self.render();
        result.ok()
    }

    /// The problems in the current language.
    pub fn render(&self) {
        for (name, el) in &self.errors {
            let problem = self.problems.iter().find(|p| p.field == *name);
            match problem {
                Some(p) => {
                    let args: Vec<(&str, String)> =
                        p.args.iter().map(|(k, v)| (*k, v.clone())).collect();
                    el.set_text_content(Some(&ctx::t_strings(p.message_id, &args)));
                    dom::show(el, true);
                }
                None => dom::show(el, false),
            }
            if let Some((_, control)) = self.controls.iter().find(|(n, _)| n == name) {
                let _ = control.set_attribute(
                    "aria-invalid",
                    if problem.is_some() { "true" } else { "false" },
                );
            }
        }
    }
}
