//! The drill's form: the kit form of the recipe's arguments, checked as it is typed with the
//! recipe's own parse + validate + plan ([`crate::view::form::validate`]), every message put
//! where it belongs (beside its field, beside the file picker, or under the form).

use super::file::PRECHECK_MAX_BYTES;
use super::markup::PREFIX;
use super::state::{Page, Plan, Slot};
use crate::args::Args;
use crate::error::RecipeError;
use crate::recipes::RecipeInfo;
use crate::ui::dom::show;
use crate::ui::kit::form::{Form, Message, RECIPE_GROUPS};
use crate::view::command_line::RunArgs;
use crate::view::form::{recipe_fields, validate};

/// Builds the form of `info` into `container`, filled with `texts` (`None` = default).
pub(super) fn build(
    container: &web_sys::Element,
    info: &'static RecipeInfo,
    texts: &[Option<String>],
) -> Result<Form, wasm_bindgen::JsValue> {
    let fields = recipe_fields(info);
    let values: Vec<String> = fields
        .iter()
        .enumerate()
        .map(|(i, f)| {
            texts
                .get(i)
                .and_then(|t| t.clone())
                .unwrap_or_else(|| f.default().to_string())
        })
        .collect();
    Form::build(container, PREFIX, &RECIPE_GROUPS, fields, &values)
}

impl Page {
    /// The texts of every field now: the form's, with the file picker's value being the
    /// opened (or URL-named) file.
    pub(super) fn current_texts(&self) -> Vec<Option<String>> {
        let form = self.form.borrow();
        let st = self.st.borrow();
        let file_name = st
            .input
            .as_ref()
            .map(|f| f.name.clone())
            .or_else(|| st.missing_file.clone());
        form.fields
            .iter()
            .zip(form.texts())
            .map(|(field, text)| {
                if field.is_file() {
                    file_name.clone()
                } else {
                    text
                }
            })
            .collect()
    }

    /// The run the form describes now.
    pub(super) fn current_args(&self) -> RunArgs {
        let texts = self.current_texts();
        let form = self.form.borrow();
        RunArgs::new(self.st.borrow().recipe.id, &form.fields, &texts)
    }

    /// Where a run's error goes: beside the field it names first, an error about no argument
    /// (an input file's) beside the file picker, else under the form.
    pub(super) fn slot_for(&self, error: &RecipeError) -> Slot {
        let form = self.form.borrow();
        error
            .param()
            .and_then(|p| form.index_of(p))
            .or_else(|| form.file_index())
            .map_or(Slot::General, Slot::Field)
    }

    /// Checks the form without running and shows the messages beside their fields.
    pub(super) fn validate(&self) {
        let texts = self.current_texts();
        let form = self.form.borrow();
        let st = self.st.borrow();
        let info = st.recipe;
        // The opened file is attached to the check when it is small enough to look at on every
        // keystroke; a bigger one is sized by the run.
        let input = st.input.as_ref();
        let check = |texts: &[Option<String>]| -> Result<Plan, RecipeError> {
            let args = RunArgs::new(info.id, &form.fields, texts);
            let mut parsed = Args::parse(&args.raw(), info.args, info.flags)?;
            let named = |name: &str| args.positional.iter().any(|p| p == name);
            if let Some(file) = input.filter(|f| named(&f.name)) {
                if file.bytes > PRECHECK_MAX_BYTES {
                    // What its shape showed on opening (the header, the first and last
                    // lines) is an error of the run already: said at once.
                    if let Err(error) = &file.shape {
                        return Err(error.clone());
                    }
                    return match (info.plan)(&parsed) {
                        Err(RecipeError::InputMissing { name }) if name == file.name => {
                            Ok(Plan { rows: None })
                        }
                        other => other.map(|p| Plan { rows: Some(p.rows) }),
                    };
                }
                parsed = parsed.with_inputs(vec![(file.name.clone(), file.text.clone())]);
            }
            (info.plan)(&parsed).map(|p| Plan { rows: Some(p.rows) })
        };
        let checked = validate(&form.fields, &texts, form.changed(), check, |_| {
            form.file_index()
        });
        let mut errors: Vec<(Slot, Message)> = checked
            .messages
            .iter()
            .map(|(i, e)| (Slot::Field(*i), Message::Recipe(e.clone())))
            .collect();
        if let Some(error) = &checked.general {
            errors.push((Slot::General, Message::Recipe(error.clone())));
        }
        let mut marked = checked.marked.clone();
        if let (Some(problem), Some(i)) = (&st.file_problem, form.file_index()) {
            errors.retain(|(s, _)| *s != Slot::Field(i));
            errors.push((Slot::Field(i), problem.clone()));
            marked.push(i);
        }
        let args = RunArgs::new(info.id, &form.fields, &texts);
        if let Some((failed_args, slot, message)) = &st.failed {
            if *failed_args == args && !errors.iter().any(|(s, _)| s == slot) {
                errors.push((*slot, message.clone()));
            }
        }
        let plan = if errors.is_empty() {
            checked.value
        } else {
            None
        };
        drop(st);
        drop(form);
        {
            let mut st = self.st.borrow_mut();
            st.errors = errors;
            st.marked = marked;
            st.plan = plan;
            st.texts = texts;
        }
        self.render_errors();
    }

    /// Shows the current messages (also on a language switch).
    pub(super) fn render_errors(&self) {
        let st = self.st.borrow();
        let by_field: Vec<(usize, Message)> = st
            .errors
            .iter()
            .filter_map(|(slot, m)| match slot {
                Slot::Field(i) => Some((*i, m.clone())),
                Slot::General => None,
            })
            .collect();
        let mut form = self.form.borrow_mut();
        form.show(&by_field, &st.marked);
        match st.errors.iter().find(|(s, _)| *s == Slot::General) {
            Some((_, message)) => {
                self.els
                    .error
                    .set_text_content(Some(&form.message_text(message)));
                show(&self.els.error, true);
            }
            None => {
                self.els.error.set_text_content(None);
                show(&self.els.error, false);
            }
        }
        drop(form);
        drop(st);
        self.render_stale();
    }
}
