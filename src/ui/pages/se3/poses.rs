//! The two poses' form: the kit form of the recipe's twelve arguments (`data-field` = the
//! argument names), in two fieldsets (frame A, frame B), with the rad/deg switch. The page
//! keeps each field's text in the recipe's radians ([`PoseFields`]); in degree mode the angle
//! fields show and take degrees, with labels, hints and defaults saying so. Each edit is
//! checked by the recipe's own parse + validate with a localized message beside the field;
//! only a valid set reaches the view, the URL, the command lines and the download.

use wasm_bindgen::{JsCast, JsValue};
use web_sys::{Element, HtmlInputElement};

use crate::args::Args;
use crate::error::RecipeError;
use crate::recipes::se3_relative::{params_from_args, Se3Params, INFO};
use crate::ui::dom;
use crate::ui::kit::form::{Form, Group, Message};
use crate::view::command_line::RunArgs;
use crate::view::form::{recipe_fields, validate, FieldDef};
use crate::view::se3_relative::{
    field_name, is_angle, rad_to_deg_text, AngleUnit, PoseFields, FIELDS,
};

use super::markup::P;

/// Frame A's six fields, then frame B's.
const GROUPS: [Group; 2] = [
    Group {
        legend_id: "se3-form-a",
        note_id: None,
    },
    Group {
        legend_id: "se3-form-b",
        note_id: None,
    },
];

/// The form component.
pub struct Poses {
    pub element: Element,
    pub form: Form,
    /// What the fields hold, in the recipe's units.
    pub fields: PoseFields,
    /// The texts of the last valid set (recipe units) and its value.
    valid: (Vec<Option<String>>, Se3Params),
    /// Messages shown (re-rendered on a language switch).
    shown: (Vec<(usize, Message)>, Vec<usize>),
}

fn form_fields() -> Vec<FieldDef> {
    recipe_fields(&INFO)
        .into_iter()
        .enumerate()
        .map(|(i, mut f)| {
            f.group = usize::from(i >= 6);
            f
        })
        .collect()
}

fn parse(fields: &[FieldDef], texts: &[Option<String>]) -> Result<Se3Params, RecipeError> {
    let args = RunArgs::new(INFO.id, fields, texts);
    params_from_args(&Args::parse(&args.raw(), INFO.args, INFO.flags)?)
}

/// The Fluent id of field `index`'s label in `unit`.
fn label_id(index: usize, unit: AngleUnit) -> String {
    let name = field_name(index);
    if is_angle(index) && unit == AngleUnit::Deg {
        format!("se3-arg-{name}-deg")
    } else {
        format!("recipe-se3-relative-arg-{name}")
    }
}

impl Poses {
    /// Builds the form into `element` with `fields` (from the URL).
    pub fn build(element: Element, fields: PoseFields) -> Result<Poses, JsValue> {
        let form = Form::build(&element, P, &GROUPS, form_fields(), &fields.shown_all())?;
        let defaults = vec![None; FIELDS];
        let default_params =
            parse(&form.fields, &defaults).map_err(|e| JsValue::from_str(&e.to_string()))?;
        let mut poses = Poses {
            element,
            form,
            fields,
            valid: (defaults, default_params),
            shown: (Vec::new(), Vec::new()),
        };
        poses.show_unit();
        poses.check();
        Ok(poses)
    }

    /// The last valid poses.
    pub fn params(&self) -> Se3Params {
        self.valid.1
    }

    /// The arguments of the last valid set, as the command line spells them.
    pub fn run_args(&self) -> RunArgs {
        RunArgs::new(INFO.id, &self.form.fields, &self.valid.0)
    }

    /// The URL pairs of the last valid set and the unit.
    pub fn url_pairs(&self) -> Vec<(String, String)> {
        PoseFields {
            recipe: self.valid.0.clone(),
            unit: self.fields.unit,
        }
        .write()
    }

    /// An input event: the field's text (in the current unit) is taken, then the form is
    /// checked. The new poses when they are valid and differ from the last.
    pub fn edited(&mut self, target: &Element) -> Option<Se3Params> {
        let name = target.get_attribute("data-field")?;
        let index = (0..FIELDS).find(|&i| field_name(i) == name)?;
        let text = target.dyn_ref::<HtmlInputElement>()?.value();
        self.form.note_edit(target);
        self.fields.set_shown(index, &text);
        self.check_changed()
    }

    /// Sets fields from the page (a drag: a frame's x, y, z), rewrites the form and checks.
    pub fn set(&mut self, values: &[(usize, String)]) -> Option<Se3Params> {
        for (index, text) in values {
            if let Some(slot) = self.fields.recipe.get_mut(*index) {
                *slot = Some(text.clone());
            }
        }
        self.form.fill(&self.fields.shown_all());
        self.check_changed()
    }

    /// Back to the recipe's defaults (the unit stays).
    pub fn reset(&mut self) -> Option<Se3Params> {
        self.fields = PoseFields::new(self.fields.unit);
        self.form.fill(&self.fields.shown_all());
        self.check_changed()
    }

    /// Shows the angle fields in `unit`: their texts, labels, hints and defaults.
    pub fn set_unit(&mut self, unit: AngleUnit) {
        if unit == self.fields.unit {
            return;
        }
        self.fields.unit = unit;
        self.form.fill(&self.fields.shown_all());
        self.show_unit();
        self.relocalize();
    }

    /// Labels, hints and defaults of the angle fields in the current unit.
    fn show_unit(&mut self) {
        let unit = self.fields.unit;
        for index in (0..FIELDS).filter(|&i| is_angle(i)) {
            let name = field_name(index);
            let label = label_id(index, unit);
            if let Some(field) = self.form.fields.get_mut(index) {
                field.label_id = label.clone();
            }
            let Ok(Some(wrap)) = self
                .element
                .query_selector(&format!("[data-field-wrap=\"{name}\"]"))
            else {
                continue;
            };
            if let Ok(Some(span)) = wrap.query_selector(".kit-label > span[data-i18n]") {
                let _ = span.set_attribute("data-i18n", &label);
            }
            if let Ok(Some(hint)) = wrap.query_selector("[data-hint]") {
                let id = match unit {
                    AngleUnit::Rad => "recipe-se3-relative-hint-angle",
                    AngleUnit::Deg => "se3-hint-angle-deg",
                };
                let _ = hint.set_attribute("data-i18n", id);
            }
            let default = INFO.args.get(index).map_or("", |a| a.default);
            let shown = match unit {
                AngleUnit::Rad => default.to_string(),
                AngleUnit::Deg => rad_to_deg_text(default),
            };
            if let Ok(Some(code)) = wrap.query_selector(".kit-default code") {
                code.set_text_content(Some(&shown));
            }
            if let Ok(Some(input)) = wrap.query_selector("[data-field]") {
                let _ = input.set_attribute("placeholder", &shown);
                let _ = input.set_attribute("data-unit", unit.id());
            }
        }
        let _ = dom::relocalize(&self.element);
    }

    fn check_changed(&mut self) -> Option<Se3Params> {
        let before = self.valid.0.clone();
        let ok = self.check();
        (ok && self.valid.0 != before).then_some(self.valid.1)
    }

    /// Checks the fields with the recipe's parse; a valid set becomes the last valid one.
    fn check(&mut self) -> bool {
        let texts = self.fields.recipe.clone();
        let fields = self.form.fields.clone();
        let checked = validate(
            &fields,
            &texts,
            self.form.changed(),
            |t| parse(&fields, t),
            |_| Some(0),
        );
        let messages = self.form.show_checked(&checked);
        self.shown = (messages, checked.marked.clone());
        let ok = checked.is_valid();
        if let Some(value) = checked.value.filter(|_| ok) {
            let canonical = (0..FIELDS)
                .map(|i| {
                    let text = self.fields.recipe_text(i);
                    let default = INFO.args.get(i).map_or("", |a| a.default);
                    (text != default).then_some(text)
                })
                .collect();
            self.valid = (canonical, value);
        }
        ok
    }

    /// Messages in the current language.
    pub fn relocalize(&mut self) {
        let (messages, marked) = self.shown.clone();
        self.form.show(&messages, &marked);
    }
}
