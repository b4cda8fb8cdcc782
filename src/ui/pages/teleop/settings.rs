//! The settings form: task, IK method, λ, latency, noise, time box, the active device's
//! sensitivities, the gamepad's dead zone and the pilot id. Every edit is checked by
//! `crate::view::teleop::check`; each problem is shown beside its field in the current
//! language (`data-field-error`), and only a valid set reaches the page (the last valid one
//! stays in force). The valid set's texts, but the pilot id, are the page's URL query.

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::{Element, HtmlInputElement, HtmlSelectElement};

use crate::teleop::session::InputDevice;
use crate::ui::{ctx, dom};
use crate::view::teleop::{
    check, sensitivity_defaults, FieldProblem, Settings, SettingsTexts, FIELDS,
};

use super::markup::role;

/// The form.
pub struct SettingsForm {
    pub element: Element,
    controls: Vec<(&'static str, Element)>,
    errors: Vec<(&'static str, Element)>,
    /// The problems shown (kept to redraw them in another language).
    problems: Vec<FieldProblem>,
    /// The texts of the settings in force.
    valid: SettingsTexts,
}

impl SettingsForm {
    /// Finds the form under `root` and fills it: the URL's `query` over the defaults of
    /// `device`, with `pilot`; the defaults (pilot "pilot") if those are refused. The form
    /// and its settings.
    pub fn mount(
        root: &Element,
        query: &[(String, String)],
        device: InputDevice,
        pilot: &str,
    ) -> Result<(SettingsForm, Settings), JsValue> {
        let mut texts = SettingsTexts::defaults(device);
        texts.pilot = pilot.to_string();
        for (k, v) in query {
            if FIELDS.contains(&k.as_str()) && k != "pilot" {
                texts.set(k, v);
            }
        }
        let mut form = SettingsForm::find(role(root, "settings")?)?;
        form.show(&texts);
        let settings = match form.check() {
            Some(s) => s,
            None => {
                texts = SettingsTexts::defaults(device);
                texts.pilot = "pilot".into();
                form.show(&texts);
                form.check()
                    .ok_or_else(|| JsValue::from_str("teleop: default settings refused"))?
            }
        };
        form.valid = texts;
        Ok((form, settings))
    }

    /// Finds the form's fields under `form`.
    fn find(form: Element) -> Result<SettingsForm, JsValue> {
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
            valid: SettingsTexts::defaults(InputDevice::Keyboard),
        })
    }

    /// An edit: the settings if all fields are valid (then in force).
    pub fn edited(&mut self) -> Option<Settings> {
        let settings = self.check()?;
        self.valid = self.texts();
        Some(settings)
    }

    /// The sensitivities follow the device from `old` to `new` while they are `old`'s
    /// defaults.
    pub fn follow_device(&self, old: InputDevice, new: InputDevice) {
        let (op, or) = sensitivity_defaults(old);
        let (np, nr) = sensitivity_defaults(new);
        let mut t = self.texts();
        if t.pos_sensitivity.trim().parse::<f64>().ok() == Some(op) {
            t.pos_sensitivity = np.to_string();
        }
        if t.rot_sensitivity.trim().parse::<f64>().ok() == Some(or) {
            t.rot_sensitivity = nr.to_string();
        }
        self.show(&t);
    }

    /// The settings in force as the page's URL query (all fields but the pilot id).
    pub fn write_url(&self) {
        let pairs: Vec<(&str, String)> = FIELDS
            .iter()
            .filter(|f| **f != "pilot")
            .map(|f| (*f, self.valid.get(f).to_string()))
            .collect();
        crate::ui::router::replace_query(&pairs);
    }

    /// Writes `texts` into the fields.
    fn show(&self, texts: &SettingsTexts) {
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
    fn texts(&self) -> SettingsTexts {
        let mut t = SettingsTexts::defaults(InputDevice::Keyboard);
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
    fn check(&mut self) -> Option<Settings> {
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
