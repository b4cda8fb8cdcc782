//! The parameter form's model, read from a recipe's facts
//! ([`ArgSpec`](crate::args::ArgSpec)): one field per argument (label id, hint id, unit,
//! keypad, default) and the validation that puts each message beside the right field.
//!
//! Validation runs the kernel's own parse + validate (the page passes it as a `check`
//! closure), so the messages are the recipe's. Each field the user typed in is first checked
//! alone (the others at their defaults), so that every bad field is named; then all together.
//! A cross-field limit ([`RecipeError::params`] lists more than one argument) marks every
//! field involved and puts its message on the one the user changed last, if it is among them,
//! else on the first (the main) one.
//!
//! `kit::form` (wasm) draws this model; this file is plain Rust, tested natively.

pub use super::field::{recipe_fields, typed, FieldDef};
use crate::error::RecipeError;
pub use crate::i18n::fluent_args;
use crate::i18n::FluentArg;

/// Runs whose plan (the recipe's rows of work) is at most this many rows run while the user
/// types; bigger ones wait for Run (they may take from a fraction of a second to a few
/// seconds).
pub const AUTO_RUN_MAX_ROWS: u64 = 50_000;

/// Whether a run of `rows` (`None`: only the run can size it) may start while the user types.
pub fn runs_while_typing(rows: Option<u64>) -> bool {
    rows.is_some_and(|r| r <= AUTO_RUN_MAX_ROWS)
}

/// What validation found.
#[derive(Debug, Clone, PartialEq)]
pub struct Checked<T> {
    /// Messages beside fields: `(field index, error)`, at most one per field.
    pub messages: Vec<(usize, RecipeError)>,
    /// Every field an error involves (`aria-invalid`), the ones with a message included.
    pub marked: Vec<usize>,
    /// An error about no field of the form (shown under it).
    pub general: Option<RecipeError>,
    /// The check's result, when everything passed.
    pub value: Option<T>,
}

impl<T> Checked<T> {
    /// Nothing to complain about.
    pub fn is_valid(&self) -> bool {
        self.messages.is_empty() && self.general.is_none()
    }

    /// The field the user should look at first (the first with a message, in form order).
    pub fn first_field(&self) -> Option<usize> {
        self.messages.iter().map(|(i, _)| *i).min()
    }
}

/// Checks `texts` (one per field of `fields`; `None` or blank = default) with `check`, the
/// recipe's parse + validate on a full set of texts. `changed` is the field the user edited
/// last; `place` gives the field of an error that names no argument (an input file's error
/// goes beside the file picker), or `None` for under the form.
pub fn validate<T>(
    fields: &[FieldDef],
    texts: &[Option<String>],
    changed: Option<usize>,
    check: impl Fn(&[Option<String>]) -> Result<T, RecipeError>,
    place: impl Fn(&RecipeError) -> Option<usize>,
) -> Checked<T> {
    validate_fields(fields, texts, changed, |_| true, check, place)
}

/// [`validate`] after an edit of the fields `edited` alone, when the texts before the edit
/// passed [`validate`] with nothing to say (no message, no field marked): the same result for
/// fewer runs of `check`. Only the edited fields are checked alone (a field's check alone
/// depends on its own text only, so the others would pass again), then all together. A live
/// page's drag or slider, which changes one or two fields per frame, calls this instead of
/// checking every typed field again.
pub fn validate_changed<T>(
    fields: &[FieldDef],
    texts: &[Option<String>],
    changed: Option<usize>,
    edited: &[usize],
    check: impl Fn(&[Option<String>]) -> Result<T, RecipeError>,
    place: impl Fn(&RecipeError) -> Option<usize>,
) -> Checked<T> {
    validate_fields(
        fields,
        texts,
        changed,
        |i| edited.contains(&i),
        check,
        place,
    )
}

/// [`validate`], checking alone only the typed fields that `alone` names.
fn validate_fields<T>(
    fields: &[FieldDef],
    texts: &[Option<String>],
    changed: Option<usize>,
    alone: impl Fn(usize) -> bool,
    check: impl Fn(&[Option<String>]) -> Result<T, RecipeError>,
    place: impl Fn(&RecipeError) -> Option<usize>,
) -> Checked<T> {
    let index_of = |name: &str| fields.iter().position(|f| f.name() == name);
    let mut out = Checked {
        messages: Vec::new(),
        marked: Vec::new(),
        general: None,
        value: None,
    };
    // Each typed field alone: every bad field is named, each beside itself.
    for (index, field) in fields.iter().enumerate() {
        if !alone(index) {
            continue;
        }
        let Some(text) = typed(texts, index) else {
            continue;
        };
        if field.is_file() || text == field.default() {
            continue;
        }
        let mut alone: Vec<Option<String>> = vec![None; fields.len()];
        alone[index] = Some(text.to_string());
        if let Err(error) = check(&alone) {
            if error.params().len() == 1 && error.param() == Some(field.name()) {
                out.messages.push((index, error));
                out.marked.push(index);
            }
        }
    }
    // Everything together.
    match check(texts) {
        Ok(value) if out.messages.is_empty() => out.value = Some(value),
        Ok(_) => {}
        Err(error) => {
            let involved: Vec<usize> = error.params().into_iter().filter_map(index_of).collect();
            let target = match changed {
                Some(c) if involved.contains(&c) => Some(c),
                _ => involved.first().copied().or_else(|| place(&error)),
            };
            for i in &involved {
                if !out.marked.contains(i) {
                    out.marked.push(*i);
                }
            }
            match target {
                Some(t) => {
                    if !out.messages.iter().any(|(i, _)| *i == t) {
                        out.messages.push((t, error));
                    }
                    if !out.marked.contains(&t) {
                        out.marked.push(t);
                    }
                }
                None => out.general = Some(error),
            }
        }
    }
    out.marked.sort_unstable();
    out
}

/// Whose label names argument `name` in `error`'s message shown beside field `at`: a
/// cross-field limit shown beside another field it involves (the one the user changed) speaks
/// in that field's name, so "Move distance: the table would have … rows" sits under distance
/// although the rows limit is dt's.
pub fn speaker<'a>(error: &RecipeError, at: Option<&'a str>, name: &'a str) -> &'a str {
    match at {
        Some(here) if error.param() == Some(name) && error.params().contains(&here) => here,
        _ => name,
    }
}

/// The Fluent arguments of `error`'s message, each argument named by `label(name)` (the
/// field's label in the current language) and whole numbers passed as numbers (for plural
/// variants).
pub fn error_args(
    error: &RecipeError,
    label: &dyn Fn(&str) -> String,
) -> Vec<(&'static str, FluentArg)> {
    fluent_args(error.message_args_labelled(label))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::args::Args;
    use crate::i18n::{I18n, Lang};
    use crate::recipes::{self, RECIPES};
    use crate::view::field::{missing_messages, texts_by_name};

    /// The recipe's own plan (parse + validate) on the form's texts, as the drills page runs it.
    fn checker(id: &'static str) -> impl Fn(&[Option<String>]) -> Result<u64, RecipeError> {
        let info = recipes::find(id).unwrap().info;
        move |texts| {
            let fields = recipe_fields(info);
            let args = crate::view::command_line::RunArgs::new(id, &fields, texts);
            let parsed = Args::parse(&args.raw(), info.args, info.flags)?;
            (info.plan)(&parsed).map(|p| p.rows)
        }
    }

    fn texts(id: &str, values: &[(&str, &str)]) -> Vec<Option<String>> {
        texts_by_name(&recipe_fields(recipes::find(id).unwrap().info), values)
    }

    fn check(id: &'static str, values: &[(&str, &str)], changed: Option<&str>) -> Checked<u64> {
        let fields = recipe_fields(recipes::find(id).unwrap().info);
        let changed = changed.and_then(|c| fields.iter().position(|f| f.name() == c));
        validate(&fields, &texts(id, values), changed, checker(id), |_| None)
    }

    fn names(id: &str, indices: &[usize]) -> Vec<&'static str> {
        let fields = recipe_fields(recipes::find(id).unwrap().info);
        indices.iter().map(|i| fields[*i].name()).collect()
    }

    #[test]
    fn fields_follow_the_command_line_with_labels_keypads_and_hints() {
        let pendulum = recipe_fields(&recipes::pendulum_energy::INFO);
        assert_eq!(pendulum[0].name(), "duration_s");
        assert_eq!(
            pendulum[0].label_id,
            "recipe-pendulum-energy-arg-duration_s"
        );
        assert!(!pendulum[0].flag && pendulum[1].flag && pendulum[1].group == 1);
        assert_eq!(pendulum[0].inputmode(), "decimal");
        let angle = pendulum.iter().find(|f| f.name() == "angle-deg").unwrap();
        assert_eq!(
            angle.inputmode(),
            "text",
            "a negative angle needs a minus key"
        );
        let rrt = recipe_fields(&recipes::rrt_2d::INFO);
        assert_eq!(rrt[0].inputmode(), "numeric");
        assert!(recipe_fields(&recipes::traj_resample::INFO)[0].is_file());
        assert!(recipe_fields(&recipes::dh_fk::INFO)[0].is_wide());
        for recipe in RECIPES {
            let fields = recipe_fields(recipe.info);
            assert_eq!(missing_messages(&fields), Vec::<String>::new());
        }
    }

    #[test]
    fn defaults_pass_and_give_the_plan() {
        for recipe in RECIPES {
            let id = recipe.info.id;
            let checked = check(id, &[], None);
            assert!(checked.is_valid(), "{id}: {checked:?}");
            assert!(checked.value.is_some(), "{id}");
        }
        assert_eq!(
            check("pid-step", &[("steps", "120")], None).value,
            Some(120)
        );
        assert_eq!(
            check("manip-grid", &[("n", "1e3")], None).value,
            Some(1_000_000)
        );
    }

    #[test]
    fn small_runs_run_while_typing_and_big_ones_wait() {
        for recipe in RECIPES {
            let rows = check(recipe.info.id, &[], None).value;
            assert!(runs_while_typing(rows), "{}: {rows:?}", recipe.info.id);
        }
        let rows = |id: &'static str, values: &[(&str, &str)]| check(id, values, None).value;
        assert_eq!(rows("pid-step", &[("steps", "120")]), Some(120));
        assert_eq!(rows("manip-grid", &[("n", "1024")]), Some(1024 * 1024));
        assert_eq!(rows("ik-workspace", &[]), Some(41 * 41));
        assert_eq!(
            rows("pendulum-energy", &[("duration_s", "2000")]),
            Some(1_000_000)
        );
        assert_eq!(rows("cubic-path", &[]), Some(51));
        assert_eq!(rows("jacobian-2r", &[]), Some(16));
        assert_eq!(
            rows("traj-resample", &[]),
            Some(28),
            "the sample at dt = 0.02"
        );
        assert!(!runs_while_typing(rows("rrt-2d", &[("max_iter", "50000")])));
        assert!(!runs_while_typing(rows("manip-grid", &[("n", "300")])));
        assert!(
            !runs_while_typing(None),
            "an input too big to size waits for Run"
        );
    }

    #[test]
    fn an_attached_file_sizes_the_run_and_reports_its_errors() {
        let info = &recipes::traj_resample::INFO;
        let fields = recipe_fields(info);
        let with_file = |csv: &'static str| {
            move |texts: &[Option<String>]| -> Result<u64, RecipeError> {
                let fields = recipe_fields(info);
                let args = crate::view::command_line::RunArgs::new(info.id, &fields, texts);
                let parsed = Args::parse(&args.raw(), info.args, info.flags)?
                    .with_inputs(vec![("mine.csv".into(), csv.into())]);
                (info.plan)(&parsed).map(|p| p.rows)
            }
        };
        let values = texts("traj-resample", &[("csv_path", "mine.csv"), ("dt", "0.01")]);
        let file = |_: &RecipeError| Some(0);
        let c = validate(
            &fields,
            &values,
            None,
            with_file("t_s,q1\n0,0\n1,1\n"),
            file,
        );
        assert_eq!(c.value, Some(101));
        let tiny = texts("traj-resample", &[("csv_path", "mine.csv"), ("dt", "1e-9")]);
        let c = validate(
            &fields,
            &tiny,
            Some(1),
            with_file("t_s,q1\n0,0\n1,1\n"),
            file,
        );
        assert_eq!(
            c.messages[0].0, 1,
            "too many cells: the message is on dt, changed"
        );
        let c = validate(&fields, &values, None, with_file("t_s\n0\n1\n"), file);
        assert_eq!(
            c.messages,
            vec![(0, RecipeError::CsvNoJointColumns)],
            "a file's error sits beside the picker"
        );
    }

    #[test]
    fn every_bad_field_gets_its_own_message() {
        let c = check("pid-step", &[("steps", "abc"), ("tau", "-1")], Some("tau"));
        assert_eq!(names("pid-step", &c.marked), vec!["tau", "steps"]);
        assert_eq!(c.messages.len(), 2);
        assert!(matches!(
            c.messages
                .iter()
                .find(|(i, _)| names("pid-step", &[*i]) == ["steps"]),
            Some((_, RecipeError::NotAnInteger { .. }))
        ));
        assert_eq!(names("pid-step", &[c.first_field().unwrap()]), vec!["tau"]);
        assert!(c.value.is_none() && !c.is_valid());
    }

    #[test]
    fn a_cross_field_limit_marks_every_field_and_speaks_on_the_changed_one() {
        // trapezoid-profile distance=1e9: the rows limit involves distance, dt (and the
        // limits); the message goes on distance, the field the user changed.
        let c = check(
            "trapezoid-profile",
            &[("distance", "1e9")],
            Some("distance"),
        );
        assert!(!c.is_valid());
        let with_message = names("trapezoid-profile", &[c.messages[0].0]);
        assert_eq!(with_message, vec!["distance"], "{c:?}");
        let marked = names("trapezoid-profile", &c.marked);
        assert!(
            marked.contains(&"distance") && marked.contains(&"dt"),
            "{marked:?}"
        );
        // The same limit reached by changing dt speaks on dt.
        let c = check(
            "trapezoid-profile",
            &[("distance", "1e6"), ("dt", "1e-9")],
            Some("dt"),
        );
        assert_eq!(
            names("trapezoid-profile", &[c.messages[0].0]),
            vec!["dt"],
            "{c:?}"
        );
    }

    #[test]
    fn errors_of_no_field_go_where_the_page_places_them() {
        let fields = recipe_fields(&recipes::traj_resample::INFO);
        let c = validate(
            &fields,
            &texts("traj-resample", &[("csv_path", "mine.csv")]),
            None,
            checker("traj-resample"),
            |e| matches!(e, RecipeError::InputMissing { .. }).then_some(0),
        );
        assert_eq!(c.messages.len(), 1);
        assert_eq!(c.messages[0].0, 0);
        let c = validate(
            &fields,
            &texts("traj-resample", &[("csv_path", "mine.csv")]),
            None,
            checker("traj-resample"),
            |_| None,
        );
        assert!(matches!(c.general, Some(RecipeError::InputMissing { .. })));
    }

    #[test]
    fn checking_only_the_edited_fields_after_a_clean_check_finds_the_same() {
        // (recipe, texts that pass, edits of one or two fields: good, bad, cross-field)
        let points = "0.1,0.2;1,-1;2.5,0.3;-1,-1";
        /// Field texts by argument name.
        type Texts<'a> = &'a [(&'a str, &'a str)];
        let cases: [(&'static str, Texts, &[Texts]); 4] = [
            (
                "pid-step",
                &[("steps", "120"), ("Kp", "1.5")],
                &[
                    &[("tau", "-1")],
                    &[("steps", "abc")],
                    &[("Kp", "2")],
                    &[("Kp", "2"), ("steps", "1e12")],
                    &[("steps", "120")],
                ],
            ),
            (
                "trapezoid-profile",
                &[("distance", "100")],
                &[&[("dt", "1e-9")], &[("distance", "1e9")], &[("dt", "0.02")]],
            ),
            (
                "umeyama-2d",
                &[("n", "40"), ("x", points), ("angle", "-20")],
                &[
                    &[("x", "1,2;3")],
                    &[("x", "0,0;1,1"), ("n", "2")],
                    &[("sigma", "-1")],
                    &[("angle", "abc")],
                    &[("tx", "0.5"), ("ty", "-0.25")],
                    &[("x", ""), ("n", "1")],
                    &[("scale", "0")],
                ],
            ),
            (
                "manip-grid",
                &[("n", "64")],
                &[&[("n", "5000")], &[("n", "32")]],
            ),
        ];
        for (id, base, edits) in cases {
            let fields = recipe_fields(recipes::find(id).unwrap().info);
            let before = texts(id, base);
            let clean = validate(&fields, &before, None, checker(id), |_| None);
            assert!(
                clean.is_valid() && clean.marked.is_empty(),
                "{id}: {clean:?}"
            );
            let mut refused = 0;
            for edit in edits {
                let mut after = before.clone();
                let mut edited = Vec::new();
                for (name, text) in *edit {
                    let i = fields.iter().position(|f| f.name() == *name).unwrap();
                    after[i] = Some(text.to_string());
                    edited.push(i);
                }
                let changed = edited.first().copied();
                let full = validate(&fields, &after, changed, checker(id), |_| None);
                let quick =
                    validate_changed(&fields, &after, changed, &edited, checker(id), |_| None);
                assert_eq!(quick, full, "{id} {edit:?}");
                refused += usize::from(!full.is_valid());
            }
            assert!(refused > 0 && refused < edits.len(), "{id}: {refused}");
        }
        // Fewer runs of the check: the edited field alone, then all together.
        let fields = recipe_fields(&recipes::umeyama_2d::INFO);
        let mut after = texts(
            "umeyama-2d",
            &[("n", "40"), ("x", points), ("angle", "-20")],
        );
        after[0] = Some("0.1".into());
        let runs = std::cell::Cell::new(0);
        let counting = |t: &[Option<String>]| {
            runs.set(runs.get() + 1);
            checker("umeyama-2d")(t)
        };
        let quick = validate_changed(&fields, &after, Some(0), &[0], counting, |_| None);
        assert!(quick.is_valid() && quick.value.is_some());
        assert_eq!(runs.get(), 2);
    }

    #[test]
    fn messages_use_the_label_and_human_numbers() {
        let i18n = I18n::new();
        let c = check("pid-step", &[("steps", "abc")], Some("steps"));
        let label = |name: &str| i18n.t(Lang::En, &format!("recipe-pid-step-arg-{name}"));
        let (_, error) = &c.messages[0];
        let text = i18n.t_args(Lang::En, error.message_id(), &error_args(error, &label));
        let steps_label = label("steps");
        assert!(text.starts_with(&steps_label), "{text}");
        assert!(!text.starts_with("steps:"), "{text}");
        // A cross-field limit shown under the changed field speaks in its name.
        let c = check(
            "trapezoid-profile",
            &[("distance", "1e9")],
            Some("distance"),
        );
        let (_, error) = &c.messages[0];
        let main = error.param().unwrap();
        assert_eq!(speaker(error, Some("distance"), main), "distance");
        assert_eq!(speaker(error, Some("Kp"), main), main, "Kp is not involved");
        let tlabel = |n: &str| n.to_string();
        let here = |n: &str| tlabel(speaker(error, Some("distance"), n));
        let text = i18n.t_args(Lang::En, error.message_id(), &error_args(error, &here));
        assert!(text.starts_with("distance:"), "{text}");
        let c = check("manip-grid", &[("n", "5000")], Some("n"));
        let (_, error) = &c.messages[0];
        let text = i18n.t_args(
            Lang::En,
            error.message_id(),
            &error_args(error, &|n| n.into()),
        );
        assert!(text.contains("1,024") && text.contains("5,000"), "{text}");
        assert!(!text.contains(".0"), "{text}");
        assert_eq!(i18n.take_warnings(), Vec::<String>::new());
    }
}
