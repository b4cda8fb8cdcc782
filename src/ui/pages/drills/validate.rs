//! Checking the form as it is typed, without running: the texts and run arguments the form
//! holds now, each changed field checked alone and then all together ([`super::plan::check`]),
//! and every message put where it belongs (beside its field, beside the file picker, or under
//! the form).

use super::command::RunArgs;
use super::fields::{Form, Kind, Message};
use super::plan::{self, InputCheck, Plan};
use super::{Page, Slot};
use crate::args::Args;
use crate::error::RecipeError;
use crate::ui::dom::show;

/// Whether a traj-resample error is about its input file (shown beside the file picker).
fn is_input_error(error: &RecipeError) -> bool {
    use RecipeError::*;
    matches!(
        error,
        InputTooLarge { .. }
            | CsvMissingColumn { .. }
            | CsvNoJointColumns
            | CsvTooFewRows { .. }
            | CsvRagged { .. }
            | CsvBadCell { .. }
            | CsvTimeNotIncreasing { .. }
            | CsvUnterminatedQuote { .. }
            | InputMissing { .. }
    )
}

/// Where the message of `error` goes: beside the field it names, beside the file picker when
/// it is about the input file, else under the form.
pub(super) fn slot_for(form: &Form, error: &RecipeError) -> Slot {
    let file_field = || form.fields.iter().position(|f| f.kind == Kind::File);
    error
        .param()
        .and_then(|p| form.index_of(p))
        .or_else(|| is_input_error(error).then(file_field).flatten())
        .map_or(Slot::General, Slot::Field)
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
            .map(|(field, text)| match field.kind {
                Kind::File => file_name.clone(),
                _ => text,
            })
            .collect()
    }

    /// The run the form describes now.
    pub(super) fn current_args(&self) -> RunArgs {
        let texts = self.current_texts();
        let form = self.form.borrow();
        RunArgs::new(form.recipe, &form.fields, &texts)
    }

    /// Checks the form (each changed field alone, then all together) without running, and
    /// shows the messages beside their fields.
    pub(super) fn validate(&self) {
        let texts = self.current_texts();
        let form = self.form.borrow();
        let recipe = form.recipe;
        let info = self.st.borrow().recipe.info;
        let check = |args: &RunArgs, input: InputCheck<'_>| -> Result<Plan, RecipeError> {
            let parsed = Args::parse(&args.raw(), info.args, info.flags)?;
            plan::check(recipe, &parsed, input)
        };
        let mut errors: Vec<(Slot, Message)> = Vec::new();
        // Each changed field alone (the others at their defaults): every bad field is named.
        for (index, field) in form.fields.iter().enumerate() {
            let typed = texts
                .get(index)
                .and_then(|t| t.as_deref())
                .map(str::trim)
                .filter(|t| !t.is_empty() && *t != field.spec.default);
            if typed.is_none() || field.kind == Kind::File {
                continue;
            }
            let mut alone: Vec<Option<String>> = vec![None; form.fields.len()];
            if let Some(slot) = alone.get_mut(index) {
                *slot = typed.map(str::to_string);
            }
            let args = RunArgs::new(recipe, &form.fields, &alone);
            if let Err(error) = check(&args, InputCheck::None) {
                if error.param() == Some(field.spec.name) {
                    errors.push((Slot::Field(index), Message::Recipe(error)));
                }
            }
        }
        // Everything together.
        let st = self.st.borrow();
        let args = RunArgs::new(recipe, &form.fields, &texts);
        let input = match &st.input {
            Some(file) => match &file.shape {
                Some(shape) => InputCheck::Parsed(shape),
                None => InputCheck::Unchecked,
            },
            None => InputCheck::None,
        };
        let plan = match check(&args, input) {
            Ok(plan) => Some(plan),
            Err(error) => {
                let slot = slot_for(&form, &error);
                if !errors.iter().any(|(s, _)| *s == slot) {
                    errors.push((slot, Message::Recipe(error)));
                }
                None
            }
        };
        if let Some(problem) = &st.file_problem {
            if let Some(i) = form.fields.iter().position(|f| f.kind == Kind::File) {
                errors.retain(|(s, _)| *s != Slot::Field(i));
                errors.push((Slot::Field(i), problem.clone()));
            }
        }
        if let Some((failed_args, slot, message)) = &st.failed {
            if *failed_args == args && !errors.iter().any(|(s, _)| s == slot) {
                errors.push((*slot, message.clone()));
            }
        }
        drop(st);
        drop(form);
        let plan = if errors.is_empty() { plan } else { None };
        {
            let mut st = self.st.borrow_mut();
            st.errors = errors;
            st.plan = plan;
            st.texts = texts;
        }
        self.render_errors();
    }

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
        self.form.borrow_mut().show_errors(&by_field);
        match st.errors.iter().find(|(s, _)| *s == Slot::General) {
            Some((_, message)) => {
                self.els.error.set_text_content(Some(&message.text()));
                show(&self.els.error, true);
            }
            None => {
                self.els.error.set_text_content(None);
                show(&self.els.error, false);
            }
        }
        drop(st);
        self.render_stale();
    }
}
