//! The parameters: seed, max_iter, step, goal bias and goal tolerance in the kit form (labels,
//! defaults and limits from the kernel's facts), each edit validated by the CLI's own parse
//! with the page's world, with a localized message beside the field. Only a valid set reaches
//! the run; a refused one keeps the last valid run.

use wasm_bindgen::JsValue;
use web_sys::Element;

use crate::ui::kit::form::{Form, RECIPE_GROUPS};
use crate::view::form::validate;
use crate::view::rrt::{form_fields, PageState};

/// The form component.
pub struct Params {
    pub form: Form,
    pub element: Element,
}

impl Params {
    /// Builds the form into `element` with the texts of `state`.
    pub fn build(element: Element, state: &PageState) -> Result<Params, JsValue> {
        let form = Form::build(&element, "rrt", &RECIPE_GROUPS, form_fields(), &state.texts)?;
        Ok(Params { form, element })
    }

    /// The texts typed (blank = the default).
    pub fn texts(&self) -> Vec<String> {
        self.form
            .texts()
            .into_iter()
            .zip(&self.form.fields)
            .map(|(t, f)| {
                let t = t.unwrap_or_default();
                if t.trim().is_empty() {
                    f.default().to_string()
                } else {
                    t.trim().to_string()
                }
            })
            .collect()
    }

    /// Validates the fields against the world of `current`: the new state if every field
    /// is valid (messages cleared), else `None` with the messages shown.
    pub fn check(&mut self, current: &PageState) -> Option<PageState> {
        let texts = self.form.texts();
        let checked = validate(
            &self.form.fields,
            &texts,
            self.form.changed(),
            |t| {
                let texts: Vec<String> = t
                    .iter()
                    .zip(&current.texts)
                    .zip(&self.form.fields)
                    .map(|((typed, _), f)| {
                        typed
                            .as_deref()
                            .map(str::trim)
                            .filter(|s| !s.is_empty())
                            .unwrap_or(f.default())
                            .to_string()
                    })
                    .collect();
                current.with_texts(texts).setup()
            },
            |_| Some(0),
        );
        self.form.show_checked(&checked);
        checked
            .value
            .is_some()
            .then(|| current.with_texts(self.texts()))
    }
}
