//! The parameters form: one text field per [`Field`] with its label, unit and hint (all
//! Fluent ids), validated on every keystroke; an invalid value shows a localized message
//! beside the field and the last valid value stays in use.

use wasm_bindgen::{JsCast, JsValue};
use web_sys::{Element, HtmlInputElement};

use super::state::{Field, Params};
use crate::error::RecipeError;
use crate::ui::ctx;

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

/// The form's inputs and error slots.
pub struct Form {
    pub inputs: Vec<(Field, HtmlInputElement)>,
    errors: Vec<(Field, Element)>,
    /// The error shown beside each field (re-rendered on a language switch).
    shown: Vec<(Field, RecipeError)>,
}

impl Form {
    /// Finds the fields under `root`.
    pub fn find(root: &Element) -> Result<Form, JsValue> {
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
        Ok(Form {
            inputs,
            errors,
            shown: Vec::new(),
        })
    }

    /// Writes every field from `p` and clears the errors.
    pub fn fill(&mut self, p: &Params) {
        for (field, input) in &self.inputs {
            input.set_value(&field.text(p));
        }
        for field in Field::ALL {
            self.set_error(field, None);
        }
    }

    /// The text now in `field`.
    pub fn text(&self, field: Field) -> Option<String> {
        self.inputs
            .iter()
            .find(|(f, _)| *f == field)
            .map(|(_, i)| i.value())
    }

    /// Shows (or with `None` clears) the error beside `field`.
    pub fn set_error(&mut self, field: Field, error: Option<RecipeError>) {
        self.shown.retain(|(f, _)| *f != field);
        if let Some((_, slot)) = self.errors.iter().find(|(f, _)| *f == field) {
            match &error {
                Some(e) => {
                    slot.set_text_content(Some(&ctx::error_text(e)));
                    let _ = slot.remove_attribute("hidden");
                }
                None => {
                    slot.set_text_content(None);
                    let _ = slot.set_attribute("hidden", "");
                }
            }
        }
        if let Some((_, input)) = self.inputs.iter().find(|(f, _)| *f == field) {
            let _ = input.set_attribute(
                "aria-invalid",
                if error.is_some() { "true" } else { "false" },
            );
        }
        if let Some(e) = error {
            self.shown.push((field, e));
        }
    }

    /// Re-renders the shown errors in the current language.
    pub fn relocalize(&self) {
        for (field, error) in &self.shown {
            if let Some((_, slot)) = self.errors.iter().find(|(f, _)| f == field) {
                slot.set_text_content(Some(&ctx::error_text(error)));
            }
        }
    }
}
