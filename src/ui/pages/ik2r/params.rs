//! The parameters form: one text field per [`Field`] with its label, unit and hint (all
//! Fluent ids), validated on every keystroke; a refused value shows a localized message
//! beside the field the user changed, and a limit over several values (grid cells, sweep
//! rows, start ≤ stop) also marks the other fields it involves; the last valid value stays in
//! use. Valid values go to the page at once.

use std::rc::Weak;

use wasm_bindgen::{JsCast, JsValue};
use web_sys::{Element, HtmlInputElement};

use super::{role, Page};
use crate::error::RecipeError;
use crate::ui::ctx::{self, t_strings};
use crate::ui::dom::Listener;
use crate::view::ik2r::{check, Field, Params, Refusal};

/// How a field is presented.
#[derive(Debug, Clone, Copy)]
pub struct FieldMeta {
    pub field: Field,
    /// Fluent ids of the label, the unit and the hint (limits, default).
    pub label: &'static str,
    pub unit: &'static str,
    pub hint: &'static str,
    /// `inputmode`: `decimal` where the value is never negative, `text` where it may be
    /// (phone decimal keypads often have no minus key), `numeric` for whole numbers.
    pub inputmode: &'static str,
    /// The fieldset it belongs to.
    pub group: Group,
}

/// The fieldsets of the form.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Group {
    Arm,
    Workspace,
    Sweep,
    Maps,
}

impl Group {
    /// All groups, in order, with their legend's Fluent id.
    pub const ALL: [(Group, &'static str); 4] = [
        (Group::Arm, "ik2r-group-arm"),
        (Group::Workspace, "ik2r-group-ws"),
        (Group::Sweep, "ik2r-group-sweep"),
        (Group::Maps, "ik2r-group-maps"),
    ];
}

/// The form's fields.
pub const FIELDS: [FieldMeta; 9] = [
    FieldMeta {
        field: Field::L1,
        label: "ik2r-field-L1",
        unit: "ik2r-unit-m",
        hint: "ik2r-hint-L1",
        inputmode: "decimal",
        group: Group::Arm,
    },
    FieldMeta {
        field: Field::L2,
        label: "ik2r-field-L2",
        unit: "ik2r-unit-m",
        hint: "ik2r-hint-L2",
        inputmode: "decimal",
        group: Group::Arm,
    },
    FieldMeta {
        field: Field::HalfMm,
        label: "ik2r-field-half_mm",
        unit: "ik2r-unit-mm",
        hint: "ik2r-hint-half_mm",
        inputmode: "decimal",
        group: Group::Workspace,
    },
    FieldMeta {
        field: Field::StepMm,
        label: "ik2r-field-step_mm",
        unit: "ik2r-unit-mm",
        hint: "ik2r-hint-step_mm",
        inputmode: "decimal",
        group: Group::Workspace,
    },
    FieldMeta {
        field: Field::Q1Start,
        label: "ik2r-field-q1_start",
        unit: "ik2r-unit-rad",
        hint: "ik2r-hint-q1_start",
        inputmode: "text",
        group: Group::Sweep,
    },
    FieldMeta {
        field: Field::Q1Stop,
        label: "ik2r-field-q1_stop",
        unit: "ik2r-unit-rad",
        hint: "ik2r-hint-q1_stop",
        inputmode: "text",
        group: Group::Sweep,
    },
    FieldMeta {
        field: Field::Q1Step,
        label: "ik2r-field-q1_step",
        unit: "ik2r-unit-rad",
        hint: "ik2r-hint-q1_step",
        inputmode: "decimal",
        group: Group::Sweep,
    },
    FieldMeta {
        field: Field::HeatmapN,
        label: "ik2r-field-res",
        unit: "ik2r-unit-cells",
        hint: "ik2r-hint-res",
        inputmode: "numeric",
        group: Group::Maps,
    },
    FieldMeta {
        field: Field::ManipN,
        label: "ik2r-field-n",
        unit: "ik2r-unit-points",
        hint: "ik2r-hint-n",
        inputmode: "numeric",
        group: Group::Maps,
    },
];

/// The form's markup (fields carry `data-field="<key>"`; errors `data-field-error="<key>"`).
pub fn markup() -> String {
    let mut html = String::new();
    for (group, legend) in Group::ALL {
        html.push_str(&format!(
            "<fieldset class=\"ik2r-fieldset\"><legend data-i18n=\"{legend}\"></legend>"
        ));
        for meta in FIELDS.iter().filter(|m| m.group == group) {
            let key = meta.field.key();
            html.push_str(&format!(
                "<div class=\"ik2r-field\">\
                 <label for=\"ik2r-f-{key}\" data-i18n=\"{label}\"></label>\
                 <div class=\"ik2r-input-row\">\
                 <input id=\"ik2r-f-{key}\" type=\"text\" inputmode=\"{mode}\" autocomplete=\"off\" \
                 spellcheck=\"false\" data-field=\"{key}\" aria-describedby=\"ik2r-h-{key} ik2r-e-{key}\">\
                 <span class=\"ik2r-unit\" data-i18n=\"{unit}\"></span></div>\
                 <small class=\"ik2r-hint\" id=\"ik2r-h-{key}\" data-i18n=\"{hint}\"></small>\
                 <p class=\"ik2r-error\" id=\"ik2r-e-{key}\" data-field-error=\"{key}\" role=\"alert\" hidden></p>\
                 </div>",
                label = meta.label,
                mode = meta.inputmode,
                unit = meta.unit,
                hint = meta.hint,
            ));
        }
        html.push_str("</fieldset>");
    }
    html
}

/// The form component: its inputs, error slots and the refusals shown.
pub(super) struct ParamsForm {
    form: Element,
    inputs: Vec<(Field, HtmlInputElement)>,
    errors: Vec<(Field, Element)>,
    /// The refusal shown for each field the user changed (re-rendered on a language switch).
    shown: Vec<(Field, Refusal)>,
}

fn label_of(field: Field) -> String {
    FIELDS
        .iter()
        .find(|m| m.field == field)
        .map_or_else(|| field.key().to_string(), |m| ctx::t(m.label))
}

/// A refusal's message, naming the fields by their labels.
fn error_text(e: &RecipeError) -> String {
    let label = |name: &str| Field::from_key(name).map_or_else(|| name.to_string(), label_of);
    t_strings(e.message_id(), &e.message_args_labelled(&label))
}

impl ParamsForm {
    /// Finds the fields under `root`.
    pub fn find(root: &Element) -> Result<ParamsForm, JsValue> {
        let mut inputs = Vec::new();
        let mut errors = Vec::new();
        for meta in FIELDS {
            let key = meta.field.key();
            if let Some(input) = root.query_selector(&format!("[data-field=\"{key}\"]"))? {
                inputs.push((meta.field, input.dyn_into::<HtmlInputElement>()?));
            }
            if let Some(e) = root.query_selector(&format!("[data-field-error=\"{key}\"]"))? {
                errors.push((meta.field, e));
            }
        }
        Ok(ParamsForm {
            form: role(root, "form")?,
            inputs,
            errors,
            shown: Vec::new(),
        })
    }

    pub fn attach(&self, weak: &Weak<Page>, out: &mut Vec<Listener>) -> Result<(), JsValue> {
        out.push(Listener::for_page(&self.form, "input", weak, |p, e| {
            let key = e
                .target()
                .and_then(|t| t.dyn_into::<Element>().ok())
                .and_then(|el| el.get_attribute("data-field"));
            if let Some(field) = key.as_deref().and_then(Field::from_key) {
                let old = p.state.borrow().params;
                let next = p.params.borrow_mut().on_input(field, old);
                p.apply_params(old, next);
            }
        })?);
        out.push(Listener::for_page(&self.form, "submit", weak, |_, e| {
            e.prevent_default()
        })?);
        Ok(())
    }

    /// The text now in `field`.
    fn text(&self, field: Field) -> String {
        self.inputs
            .iter()
            .find(|(f, _)| *f == field)
            .map(|(_, i)| i.value())
            .unwrap_or_default()
    }

    /// `field` changed: validates it and, as values depend on each other (q1_start after
    /// q1_stop grew), retries the fields still refused. Returns the parameters to use.
    pub fn on_input(&mut self, field: Field, params: Params) -> Params {
        let mut p = params;
        self.shown.retain(|(f, _)| *f != field);
        match check(&p, field, &self.text(field)) {
            Ok(next) => p = next,
            Err(refusal) => self.shown.push((field, refusal)),
        }
        for other in Field::ALL {
            if other == field || !self.shown.iter().any(|(f, _)| *f == other) {
                continue;
            }
            let text = self.text(other);
            if other.text(&p) == text {
                self.shown.retain(|(f, _)| *f != other);
                continue;
            }
            if let Ok(next) = check(&p, other, &text) {
                self.shown.retain(|(f, _)| *f != other);
                p = next;
            }
        }
        self.render();
        p
    }

    /// Writes every field from `p` and clears the errors.
    pub fn fill(&mut self, p: &Params) {
        for (field, input) in &self.inputs {
            input.set_value(&field.text(p));
        }
        self.shown.clear();
        self.render();
    }

    /// Shows each refusal beside its field, marks the fields it involves, clears the rest.
    fn render(&self) {
        for (field, slot) in &self.errors {
            let own = self.shown.iter().find(|(f, _)| f == field);
            let involved = self
                .shown
                .iter()
                .find(|(f, r)| f != field && r.involved.contains(field));
            let text = match (own, involved) {
                (Some((_, r)), _) => Some(error_text(&r.error)),
                (None, Some((by, _))) => Some(t_strings(
                    "ik2r-field-involved",
                    &[("field", label_of(*by))],
                )),
                (None, None) => None,
            };
            match &text {
                Some(t) => {
                    if slot.text_content().as_deref() != Some(t) {
                        slot.set_text_content(Some(t));
                    }
                    let _ = slot.remove_attribute("hidden");
                }
                None => {
                    slot.set_text_content(None);
                    let _ = slot.set_attribute("hidden", "");
                }
            }
            if let Some((_, input)) = self.inputs.iter().find(|(f, _)| f == field) {
                let _ = input.set_attribute(
                    "aria-invalid",
                    if text.is_some() { "true" } else { "false" },
                );
            }
        }
    }

    /// Re-renders the shown messages in the current language.
    pub fn relocalize(&self) {
        self.render();
    }
}
