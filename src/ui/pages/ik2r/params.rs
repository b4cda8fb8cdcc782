//! The parameters form: the kit's ArgSpec-driven form ([`crate::ui::kit::form`]) over the
//! arguments of the page's three recipes (L1 and L2 of all three, ik-workspace's grid,
//! jacobian-2r's sweep, manip-grid's n, each with its recipe's limits, hint and default) and the
//! page's own heatmap resolution, in four fieldsets, with the unit beside each box.
//!
//! Validated on every keystroke by the kit's validation with the kernels' own checks
//! ([`Params::from_texts`]): a refused value shows a localized message beside the field the
//! user changed, and a limit over several values (grid cells, start ≤ stop) also marks the
//! other fields it involves, each saying so. A refused field keeps its last valid value in use
//! while the other fields' new values apply at once.

use std::rc::Weak;

use wasm_bindgen::{JsCast, JsValue};
use web_sys::Element;

use super::markup::role;
use crate::ui::kit::form::{Form, FormOptions, Group, Message};
use crate::ui::kit::scope::Scope;
use crate::view::form::validate;
use crate::view::ik2r::{form_fields, Field, Params};

/// The fieldsets, in [`Field::group`] order.
const GROUPS: [Group; 4] = [
    Group {
        legend_id: "ik2r-group-arm",
        note_id: None,
    },
    Group {
        legend_id: "ik2r-group-ws",
        note_id: None,
    },
    Group {
        legend_id: "ik2r-group-sweep",
        note_id: Some("ik2r-group-sweep-note"),
    },
    Group {
        legend_id: "ik2r-group-maps",
        note_id: None,
    },
];

/// The unit beside each box.
const UNITS: [(&str, &str); 8] = [
    ("L1", "ik2r-unit-m"),
    ("L2", "ik2r-unit-m"),
    ("half_mm", "ik2r-unit-mm"),
    ("step_mm", "ik2r-unit-mm"),
    ("q1_start", "ik2r-unit-rad"),
    ("q1_stop", "ik2r-unit-rad"),
    ("q1_step", "ik2r-unit-rad"),
    ("res", "ik2r-unit-cells"),
];

/// The form component.
pub(super) struct ParamsForm {
    element: Element,
    form: Form,
}

impl ParamsForm {
    /// Builds the form into `[data-ik2r="form"]`, filled with `p`.
    pub fn build(root: &Element, p: &Params) -> Result<ParamsForm, JsValue> {
        let element: Element = role(root, "form")?;
        let options = FormOptions {
            units: &UNITS,
            involved_note: true,
        };
        let form = Form::build_with(
            &element,
            "ik2r",
            &GROUPS,
            form_fields(),
            &p.texts(),
            &options,
        )?;
        Ok(ParamsForm { element, form })
    }

    /// The form's listeners: an edit goes to `on_input` with the edited element.
    pub fn attach<H: 'static>(
        &self,
        host: &Weak<H>,
        scope: &mut Scope,
        on_input: impl Fn(&H, &Element) + 'static,
    ) -> Result<(), JsValue> {
        scope.listen_for(&self.element, "input", host, move |h, e| {
            if let Some(target) = e.target().and_then(|t| t.dyn_into::<Element>().ok()) {
                on_input(h, &target);
            }
        })?;
        scope.listen_for(&self.element, "submit", host, |_, e| e.prevent_default())
    }

    /// The user edited the field holding `target`: validates every field and returns the
    /// parameters to use (`current` with the refused fields' values kept).
    pub fn on_input(&mut self, target: &Element, current: Params) -> Params {
        self.form.note_edit(target);
        let texts = self.form.texts();
        let checked = validate(
            &self.form.fields,
            &texts,
            self.form.changed(),
            Params::from_texts,
            |_| None,
        );
        let messages: Vec<(usize, Message)> = checked
            .messages
            .iter()
            .map(|(i, e)| (*i, Message::Recipe(e.clone())))
            .collect();
        self.form.show(&messages, &checked.marked);
        if let Some(next) = checked.value {
            return next;
        }
        // The refused fields keep their last valid values; the others apply.
        let kept: Vec<Option<String>> = Field::ALL
            .iter()
            .zip(texts)
            .enumerate()
            .map(|(i, (field, text))| {
                if checked.marked.contains(&i) {
                    Some(field.text(&current))
                } else {
                    text
                }
            })
            .collect();
        Params::from_texts(&kept).unwrap_or(current)
    }

    /// Writes every field from `p` and clears the messages.
    pub fn fill(&mut self, p: &Params) {
        self.form.fill(&p.texts());
        self.form.show(&[], &[]);
    }

    /// The messages in the current language.
    pub fn relocalize(&self) {
        self.form.relocalize();
    }
}
