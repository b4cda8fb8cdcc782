//! The parameters: the kit's form of the recipe's arguments (label, unit, default and the
//! limits explained, from the recipe's facts), checked on every edit with the recipe's own
//! parse + validate ([`crate::view::form::validate`]), each message beside its field (and a
//! cross-field limit marks every field it involves). Only a valid set reaches the page: a
//! bad value keeps the last valid run.

use wasm_bindgen::JsValue;
use web_sys::Element;

use crate::error::RecipeError;
use crate::recipes::pendulum_energy::{PendulumParams, INFO};
use crate::ui::kit::form::{Form, RECIPE_GROUPS};
use crate::view::command_line::RunArgs;
use crate::view::form::{recipe_fields, validate};
use crate::view::pendulum::default_texts;

/// The form's class prefix (`pend-field`, `pend-hint`, …).
const PREFIX: &str = "pend";

/// The form component.
pub struct Params {
    pub form: Form,
    /// The `<form>` element (its input events).
    pub element: Element,
}

/// The recipe's parse + validate of one set of texts (blank = default).
fn check_texts(form: &Form, texts: &[Option<String>]) -> Result<PendulumParams, RecipeError> {
    let args = RunArgs::new(INFO.id, &form.fields, texts);
    let params = PendulumParams::from_args(&INFO.parse(&args.raw())?)?;
    params.validate()?;
    Ok(params)
}

impl Params {
    /// Builds the form into `element`, filled with `texts` (one per argument, CLI order).
    pub fn build(element: Element, texts: &[String]) -> Result<Params, JsValue> {
        let form = Form::build(
            &element,
            PREFIX,
            &RECIPE_GROUPS,
            recipe_fields(&INFO),
            texts,
        )?;
        Ok(Params { form, element })
    }

    /// The texts of the fields, a blank one being the default (CLI order).
    pub fn texts(&self) -> Vec<String> {
        self.form
            .texts()
            .into_iter()
            .zip(default_texts())
            .map(|(text, default)| match text {
                Some(t) if !t.trim().is_empty() => t.trim().to_string(),
                _ => default,
            })
            .collect()
    }

    /// Checks the fields now: the parameters when valid (messages cleared), else the
    /// messages shown beside their fields.
    pub fn check(&mut self) -> Option<PendulumParams> {
        let texts = self.form.texts();
        let checked = validate(
            &self.form.fields,
            &texts,
            self.form.changed(),
            |t| check_texts(&self.form, t),
            |_| Some(0),
        );
        self.form.show_checked(&checked);
        checked.value
    }

    /// Writes `text` into the field `name` as if typed (the timestep control).
    pub fn set_text(&mut self, name: &str, text: &str) {
        let Some(index) = self.form.index_of(name) else {
            return;
        };
        let mut values = self.texts();
        if let Some(v) = values.get_mut(index) {
            *v = text.to_string();
        }
        self.form.fill(&values);
        if let Ok(Some(control)) = self
            .element
            .query_selector(&format!("[data-field=\"{name}\"]"))
        {
            self.form.note_edit(&control);
        }
    }
}
