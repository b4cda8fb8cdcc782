//! The parameters: one field per recipe argument (label, unit and limits hint from the
//! recipe's facts), validated on every edit with a localized message beside the field (and
//! beside every field a cross-field limit involves). Only a valid set reaches the page: a bad
//! value keeps the last valid run.

use wasm_bindgen::{JsCast, JsValue};
use web_sys::{Element, HtmlInputElement, HtmlSelectElement};

use crate::args::ArgSpec;
use crate::error::RecipeError;
use crate::recipes::parse_args;
use crate::recipes::pendulum_energy::{PendulumParams, INFO};
use crate::ui::{ctx, dom};
use crate::view::pendulum::{arg_names, cli_args};

fn specs() -> Vec<(&'static ArgSpec, bool)> {
    INFO.args
        .iter()
        .map(|s| (s, false))
        .chain(INFO.flags.iter().map(|s| (s, true)))
        .collect()
}

/// The form's markup: `data-field="<name>"`, messages in `data-field-error="<name>"`.
pub fn markup() -> String {
    let mut html = String::new();
    for (spec, flag) in specs() {
        let name = spec.name;
        let label = spec.label_id(INFO.id, flag);
        let input = if name == "integrator" {
            format!(
                "<select id=\"pend-f-{name}\" data-field=\"{name}\" aria-describedby=\"pend-h-{name} pend-e-{name}\">\
                 <option value=\"euler\" data-i18n=\"pendulum-int-euler\"></option>\
                 <option value=\"rk4\" data-i18n=\"pendulum-int-rk4\"></option></select>"
            )
        } else {
            let mode = if name == "angle-deg" {
                "text"
            } else {
                "decimal"
            };
            format!(
                "<input id=\"pend-f-{name}\" type=\"text\" inputmode=\"{mode}\" autocomplete=\"off\" \
                 spellcheck=\"false\" data-field=\"{name}\" aria-describedby=\"pend-h-{name} pend-e-{name}\">"
            )
        };
        html.push_str(&format!(
            "<div class=\"pend-field\"><label for=\"pend-f-{name}\" data-i18n=\"{label}\"></label>\
             {input}<small class=\"pend-hint\" id=\"pend-h-{name}\" data-i18n=\"{hint}\"></small>\
             <p class=\"pend-error\" id=\"pend-e-{name}\" data-field-error=\"{name}\" role=\"alert\" hidden></p></div>",
            hint = spec.hint_id,
        ));
    }
    html
}

/// A field: a text input or the integrator select.
enum Input {
    Text(HtmlInputElement),
    Select(HtmlSelectElement),
}

impl Input {
    fn value(&self) -> String {
        match self {
            Input::Text(i) => i.value(),
            Input::Select(s) => s.value(),
        }
    }
    fn set_value(&self, v: &str) {
        match self {
            Input::Text(i) => i.set_value(v),
            Input::Select(s) => s.set_value(v),
        }
    }
    fn element(&self) -> &Element {
        match self {
            Input::Text(i) => i.unchecked_ref(),
            Input::Select(s) => s.unchecked_ref(),
        }
    }
}

/// The form component.
pub struct Params {
    pub form: Element,
    inputs: Vec<Input>,
    errors: Vec<Element>,
    /// The errors shown, by field index (re-rendered on a language switch).
    shown: Vec<(usize, RecipeError)>,
}

/// A field's label in the current language.
fn label(name: &str) -> String {
    specs()
        .into_iter()
        .find(|(s, _)| s.name == name)
        .map_or_else(
            || name.to_string(),
            |(s, flag)| ctx::t(&s.label_id(INFO.id, flag)),
        )
}

fn message(e: &RecipeError) -> String {
    ctx::t_strings(e.message_id(), &e.message_args_labelled(&label))
}

/// Checks the texts (in `arg_names` order): each field on its own, then the whole run.
pub fn check(texts: &[String]) -> Result<PendulumParams, Vec<(usize, RecipeError)>> {
    let names = arg_names();
    let mut errors = Vec::new();
    for (k, ((spec, _), text)) in specs().into_iter().zip(texts).enumerate() {
        if let Err(e) = spec.check_text(text) {
            errors.push((k, e));
        }
    }
    if !errors.is_empty() {
        return Err(errors);
    }
    let params = parse_args(INFO.id, &cli_args(texts))
        .and_then(|a| PendulumParams::from_args(&a))
        .and_then(|p| p.validate().map(|_| p));
    params.map_err(|e| {
        let involved: Vec<usize> = e
            .params()
            .iter()
            .filter_map(|p| names.iter().position(|n| n == p))
            .collect();
        let involved = if involved.is_empty() {
            vec![0]
        } else {
            involved
        };
        involved.into_iter().map(|k| (k, e.clone())).collect()
    })
}

impl Params {
    /// Finds the fields under `root`.
    pub fn find(root: &Element, form: Element) -> Result<Params, JsValue> {
        let mut inputs = Vec::new();
        let mut errors = Vec::new();
        for name in arg_names() {
            let el: Element = dom::find(root, &format!("[data-field=\"{name}\"]"), "pendulum")?;
            inputs.push(if name == "integrator" {
                Input::Select(el.dyn_into()?)
            } else {
                Input::Text(el.dyn_into()?)
            });
            errors.push(dom::find(
                root,
                &format!("[data-field-error=\"{name}\"]"),
                "pendulum",
            )?);
        }
        Ok(Params {
            form,
            inputs,
            errors,
            shown: Vec::new(),
        })
    }

    /// Puts `texts` in the fields.
    pub fn fill(&self, texts: &[String]) {
        for (input, text) in self.inputs.iter().zip(texts) {
            input.set_value(text);
        }
    }

    /// The texts of the fields.
    pub fn texts(&self) -> Vec<String> {
        self.inputs.iter().map(Input::value).collect()
    }

    /// Shows `errors` (or clears them all).
    pub fn show(&mut self, errors: Vec<(usize, RecipeError)>) {
        self.shown = errors;
        self.render();
    }

    fn render(&self) {
        for (k, (slot, input)) in self.errors.iter().zip(&self.inputs).enumerate() {
            let mine: Vec<String> = self
                .shown
                .iter()
                .filter(|(i, _)| *i == k)
                .map(|(_, e)| message(e))
                .collect();
            slot.set_text_content(Some(&mine.join(" ")));
            dom::show(slot, !mine.is_empty());
            let _ = if mine.is_empty() {
                input.element().remove_attribute("aria-invalid")
            } else {
                input.element().set_attribute("aria-invalid", "true")
            };
        }
    }

    /// Re-renders the messages in the current language.
    pub fn relocalize(&self) {
        self.render();
    }
}
