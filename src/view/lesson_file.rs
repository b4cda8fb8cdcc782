//! The lesson `.json` file (format `bsv-lesson`), written as version 3 and read as version 3, 2
//! or 1 (version 2 adds a step's `focus`, the section of its page it brings into view, version
//! 3 a step's `exercise`, one of its page's exercises, and `goals`, the teacher's own goal
//! ([`crate::view::lesson_goal`]); an older file reads as it always did,
//! its steps without those fields); what can be wrong with one is a
//! [`LessonError`] naming the place (step n, field f). A focus its page does not have is no
//! error: the page names it ([`Lesson::take_unknown_focuses`]).
//!
//! Reading checks, in order: the size ([`MAX_FILE_BYTES`]; the page refuses a bigger file
//! from its size alone, before reading it), text at all, nesting (at most [`MAX_DEPTH`] levels,
//! checked before parsing: a lesson nests 3 deep, and serde_json's own limit of 128 would make
//! a plain "syntax error"), JSON, an object, its `format` and `version`, then every field of
//! the lesson and of each step by name (an unknown field, a missing one, a wrong type), at least
//! one step (a file; the stored lesson may have none), and the limits of [`Lesson::validate`].
//! Text fields are kept as text: the pages put them in inputs and text nodes only, so
//! `<script>` or `javascript:` in a title or a note is shown, never run; a route must name a
//! page of the app and is rebuilt by the URL codec, so a link is always `#/<page>?...`.

use serde::Serialize;
use serde_json::{Map, Value};

use crate::view::json_file::{kind_of, too_deep_at, unknown_field};
use crate::view::lesson::{
    without_lang, Expected, Lesson, LessonError, LessonStep, FIRST_VERSION, FORMAT, MAX_DEPTH,
    MAX_FILE_BYTES, MAX_PAGE_STEPS, MAX_STEPS, VERSION,
};
use crate::view::lesson_goal::{GoalCondition, GoalOp, MAX_GOALS};

/// The fields of the file, then of a step (version 2 has no `exercise`, version 1 no `focus`
/// either).
const FILE_FIELDS: [&str; 4] = ["format", "version", "title", "steps"];
const STEP_FIELDS: [&str; 7] = [
    "route",
    "title",
    "note",
    "pageSteps",
    "focus",
    "exercise",
    "goals",
];
/// The fields of a goal's condition.
const GOAL_FIELDS: [&str; 4] = ["readout", "op", "value", "tolerance"];
const STEP_FIELDS_V2: [&str; 5] = ["route", "title", "note", "pageSteps", "focus"];
const STEP_FIELDS_V1: [&str; 4] = ["route", "title", "note", "pageSteps"];
/// The version that added `focus`.
const FOCUS_VERSION: u64 = 2;

/// The file form: the lesson with its format and version (field order as written).
#[derive(Serialize)]
struct LessonFile<'a> {
    format: &'a str,
    version: u32,
    title: &'a str,
    steps: &'a [LessonStep],
}

/// The `.json` file text of `lesson` (pretty, stable key order).
pub fn to_json(lesson: &Lesson) -> String {
    let file = LessonFile {
        format: FORMAT,
        version: VERSION,
        title: &lesson.title,
        steps: &lesson.steps,
    };
    // Serializing plain strings and numbers cannot fail.
    serde_json::to_string_pretty(&file).unwrap_or_default() + "\n"
}

/// Reads a lesson file to import (see the module docs for the checks, in order); a lesson
/// without steps is refused.
pub fn from_json(text: &str, is_page: impl Fn(&str) -> bool) -> Result<Lesson, LessonError> {
    read(text, is_page, false)
}

/// Reads the lesson kept in the browser's storage: [`from_json`], except that a lesson
/// without steps (the user removed them all) is fine.
pub fn from_stored(text: &str, is_page: impl Fn(&str) -> bool) -> Result<Lesson, LessonError> {
    read(text, is_page, true)
}

fn read(
    text: &str,
    is_page: impl Fn(&str) -> bool,
    allow_empty: bool,
) -> Result<Lesson, LessonError> {
    let bytes = text.len() as u64;
    if bytes > MAX_FILE_BYTES {
        return Err(LessonError::TooBig { bytes });
    }
    let body = text.strip_prefix('\u{feff}').unwrap_or(text);
    if body.trim().is_empty() {
        return Err(LessonError::EmptyFile);
    }
    if let Some((line, column)) = too_deep_at(body, MAX_DEPTH) {
        return Err(LessonError::TooDeep { line, column });
    }
    let value: Value = serde_json::from_str(body).map_err(|e| LessonError::NotJson {
        line: e.line(),
        column: e.column(),
    })?;
    let Value::Object(file) = &value else {
        return Err(LessonError::NotAnObject {
            kind: kind_of(&value),
        });
    };
    match file.get("format") {
        None => return Err(LessonError::NoFormat),
        Some(Value::String(f)) if f == FORMAT => {}
        Some(Value::String(f)) => return Err(LessonError::WrongFormat { found: f.clone() }),
        Some(_) => return Err(wrong_type(None, "format", Expected::Text)),
    }
    let version = match file.get("version") {
        None => return Err(missing(None, "version")),
        Some(Value::Number(n)) => match n.as_u64() {
            Some(v) if (u64::from(FIRST_VERSION)..=u64::from(VERSION)).contains(&v) => v,
            Some(v) => return Err(LessonError::WrongVersion { found: v }),
            None => return Err(wrong_type(None, "version", Expected::WholeNumber)),
        },
        Some(_) => return Err(wrong_type(None, "version", Expected::WholeNumber)),
    };
    let step_fields: &[&str] = match version {
        v if v == u64::from(FIRST_VERSION) => &STEP_FIELDS_V1,
        FOCUS_VERSION => &STEP_FIELDS_V2,
        _ => &STEP_FIELDS,
    };
    known_fields(file, &FILE_FIELDS, None)?;
    let title = text_field(file, "title", None)?.ok_or(missing(None, "title"))?;
    let steps = match file.get("steps") {
        None => return Err(missing(None, "steps")),
        Some(Value::Array(steps)) => steps,
        Some(_) => return Err(wrong_type(None, "steps", Expected::List)),
    };
    if steps.is_empty() && !allow_empty {
        return Err(LessonError::NoSteps);
    }
    if steps.len() > MAX_STEPS {
        return Err(LessonError::TooManySteps { count: steps.len() });
    }
    let steps = steps
        .iter()
        .enumerate()
        .map(|(i, step)| read_step(step, i + 1, step_fields))
        .collect::<Result<Vec<_>, _>>()?;
    let lesson = Lesson { title, steps };
    lesson.validate(is_page)?;
    Ok(lesson)
}

/// Step `n` of a file whose steps may hold `fields`.
fn read_step(value: &Value, n: usize, fields: &[&str]) -> Result<LessonStep, LessonError> {
    let Value::Object(step) = value else {
        return Err(LessonError::StepNotAnObject { step: n });
    };
    let at = Some(n);
    known_fields(step, fields, at)?;
    let route = text_field(step, "route", at)?.ok_or(missing(at, "route"))?;
    let title = text_field(step, "title", at)?.ok_or(missing(at, "title"))?;
    let note = text_field(step, "note", at)?.unwrap_or_default();
    let focus = text_field(step, "focus", at)?;
    let exercise = text_field(step, "exercise", at)?;
    let goals = match step.get("goals") {
        None => Vec::new(),
        Some(Value::Array(goals)) if goals.len() <= MAX_GOALS => goals
            .iter()
            .enumerate()
            .map(|(j, goal)| {
                read_goal(goal).ok_or(LessonError::BadGoal {
                    step: n,
                    goal: j + 1,
                })
            })
            .collect::<Result<Vec<_>, _>>()?,
        Some(Value::Array(_)) => {
            return Err(LessonError::BadGoal {
                step: n,
                goal: MAX_GOALS + 1,
            })
        }
        Some(_) => return Err(wrong_type(at, "goals", Expected::List)),
    };
    let page_steps = match step.get("pageSteps") {
        None => 0,
        Some(Value::Number(k)) => match k.as_u64() {
            Some(k) => u32::try_from(k)
                .ok()
                .filter(|k| *k <= MAX_PAGE_STEPS)
                .ok_or(LessonError::TooManyPageSteps { step: n })?,
            None => return Err(wrong_type(at, "pageSteps", Expected::WholeNumber)),
        },
        Some(_) => return Err(wrong_type(at, "pageSteps", Expected::WholeNumber)),
    };
    Ok(LessonStep {
        route: without_lang(&route),
        title,
        note,
        page_steps,
        focus,
        exercise,
        goals,
    })
}

/// A goal's condition (`None` unless it is an object of [`GOAL_FIELDS`] that makes a
/// well-formed condition).
fn read_goal(value: &Value) -> Option<GoalCondition> {
    let Value::Object(goal) = value else {
        return None;
    };
    if goal.keys().any(|k| !GOAL_FIELDS.contains(&k.as_str())) {
        return None;
    }
    let condition = GoalCondition {
        readout: goal.get("readout")?.as_str()?.to_owned(),
        op: GoalOp::of_word(goal.get("op")?.as_str()?)?,
        value: goal.get("value")?.as_f64()?,
        tolerance: match goal.get("tolerance") {
            None => None,
            Some(t) => Some(t.as_f64()?),
        },
    };
    condition.is_valid().then_some(condition)
}

fn missing(step: Option<usize>, field: &'static str) -> LessonError {
    LessonError::MissingField { step, field }
}

fn wrong_type(step: Option<usize>, field: &'static str, expected: Expected) -> LessonError {
    LessonError::WrongType {
        step,
        field,
        expected,
    }
}

/// The first field of `object` not among `known`, as an error.
fn known_fields(
    object: &Map<String, Value>,
    known: &[&str],
    step: Option<usize>,
) -> Result<(), LessonError> {
    match unknown_field(object, known) {
        Some(field) => Err(LessonError::UnknownField {
            step,
            field: field.clone(),
        }),
        None => Ok(()),
    }
}

/// Text field `field` of `object` (`None` when absent).
fn text_field(
    object: &Map<String, Value>,
    field: &'static str,
    step: Option<usize>,
) -> Result<Option<String>, LessonError> {
    match object.get(field) {
        None => Ok(None),
        Some(Value::String(s)) => Ok(Some(s.clone())),
        Some(_) => Err(wrong_type(step, field, Expected::Text)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::RecipeError;
    use crate::i18n::{I18n, Lang};
    use crate::view::lesson::tests::{is_page, sample};
    use crate::view::lesson::{UnknownFocus, MAX_NOTE_CHARS, MAX_QUOTED_CHARS};

    fn import(text: &str) -> Result<Lesson, LessonError> {
        from_json(text, is_page)
    }

    /// A lesson file of the current version with `steps` (JSON text of the array).
    fn with_steps(steps: &str) -> String {
        format!(r#"{{"format":"bsv-lesson","version":2,"title":"T","steps":{steps}}}"#)
    }

    #[test]
    fn json_round_trips_and_states_its_format() {
        let lesson = sample();
        let text = to_json(&lesson);
        assert!(text.contains("\"format\": \"bsv-lesson\"") && text.contains("\"pageSteps\": 5"));
        assert!(text.contains("\"version\": 3") && text.contains("\"focus\": \"world\""));
        // A step without a focus writes none.
        assert_eq!(text.matches("\"focus\"").count(), 1);
        assert_eq!(from_json(&text, is_page), Ok(lesson));
    }

    #[test]
    fn a_step_exercise_round_trips_and_must_be_its_pages() {
        let mut lesson = sample();
        lesson.steps[0].exercise = Some("rrt-300".into());
        let text = to_json(&lesson);
        assert_eq!(text.matches("\"exercise\": \"rrt-300\"").count(), 1);
        assert_eq!(from_json(&text, is_page), Ok(lesson.clone()));
        // Another page's exercise, or none of the app's, is named with its step.
        let other = text.replace("rrt-300", "ik-singular");
        assert_eq!(
            from_json(&other, is_page),
            Err(LessonError::UnknownExercise {
                step: 1,
                page: "rrt-2d".into(),
                exercise: "ik-singular".into()
            })
        );
        let err = from_json(&text.replace("rrt-300", "no-such"), is_page).unwrap_err();
        assert_eq!(err.message_id(), "lesson-error-unknown-exercise");
        // Version 2 has no exercise: a step with one is a field it does not know.
        let v2 = text.replace("\"version\": 3", "\"version\": 2");
        assert_eq!(
            from_json(&v2, is_page),
            Err(LessonError::UnknownField {
                step: Some(1),
                field: "exercise".into()
            })
        );
        // Version 4 is not read.
        let v4 = text.replace("\"version\": 3", "\"version\": 4");
        assert_eq!(
            from_json(&v4, is_page),
            Err(LessonError::WrongVersion { found: 4 })
        );
    }

    #[test]
    fn a_steps_goal_round_trips_and_is_checked() {
        let mut lesson = sample();
        lesson.steps[1].goals = vec![
            GoalCondition {
                readout: "overshoot".into(),
                op: GoalOp::Below,
                value: 5.0,
                tolerance: None,
            },
            GoalCondition {
                readout: "settling-time".into(),
                op: GoalOp::Within,
                value: 1.0,
                tolerance: Some(0.5),
            },
        ];
        let text = to_json(&lesson);
        assert!(text.contains("\"op\": \"within\"") && text.contains("\"tolerance\": 0.5"));
        assert_eq!(from_json(&text, is_page), Ok(lesson.clone()));
        let bad_goal = |text: &str| from_json(text, is_page).unwrap_err();
        let err = LessonError::BadGoal { step: 2, goal: 2 };
        assert_eq!(bad_goal(&text.replace("\"within\"", "\"about\"")), err);
        assert_eq!(
            bad_goal(&text.replace("\"tolerance\": 0.5", "\"tolerance\": -1")),
            err
        );
        assert_eq!(
            bad_goal(&text.replace("\"tolerance\": 0.5", "\"tol\": 0.5")),
            err
        );
        let err = LessonError::BadGoal { step: 2, goal: 1 };
        assert_eq!(
            bad_goal(&text.replace("\"value\": 5.0", "\"value\": \"5\"")),
            err
        );
        assert_eq!(
            bad_goal(&text.replace("\"overshoot\"", "\"Over shoot\"")),
            err
        );
        assert_eq!(err.message_id(), "lesson-error-goal");
        // More than three: the fourth is named.
        lesson.steps[1].goals = vec![lesson.steps[1].goals[0].clone(); 4];
        assert_eq!(
            bad_goal(&to_json(&lesson)),
            LessonError::BadGoal { step: 2, goal: 4 }
        );
        // Version 2 has no goals.
        lesson.steps[1].goals.truncate(1);
        let v2 = to_json(&lesson).replace("\"version\": 3", "\"version\": 2");
        assert_eq!(
            bad_goal(&v2),
            LessonError::UnknownField {
                step: Some(2),
                field: "goals".into()
            }
        );
    }

    #[test]
    fn a_version_1_file_reads_as_before() {
        let v1 = r##"{"format":"bsv-lesson","version":1,"title":"T","steps":[{"route":"#/ik-2r?q2=0.05","title":"a","note":"n","pageSteps":2}]}"##;
        let lesson = import(v1).unwrap_or_default();
        assert_eq!(lesson.steps.len(), 1);
        assert_eq!(lesson.steps[0].route, "#/ik-2r?q2=0.05");
        assert_eq!(
            (lesson.steps[0].page_steps, &lesson.steps[0].focus),
            (2, &None)
        );
        // Version 1 has no focus: a step with one is a field it does not know.
        let v1_focus = v1.replace("\"pageSteps\":2", "\"focus\":\"heatmap\"");
        assert_eq!(
            import(&v1_focus),
            Err(LessonError::UnknownField {
                step: Some(1),
                field: "focus".into()
            })
        );
        // Version 2 without focus reads too.
        let v2 = v1.replace("\"version\":1", "\"version\":2");
        assert_eq!(import(&v2), Ok(lesson));
    }

    #[test]
    fn a_focus_the_page_does_not_have_is_named_and_dropped() {
        let text = r##"{"format":"bsv-lesson","version":2,"title":"T","steps":[
            {"route":"#/ik-2r","title":"a","focus":"heatmap"},
            {"route":"#/rrt-2d","title":"b","focus":"heatmap"},
            {"route":"#/pid-step","title":"c","focus":"<b>plot\u0000</b>"}]}"##;
        let mut lesson = import(text).unwrap_or_default();
        assert_eq!(lesson.steps.len(), 3);
        let unknown = lesson.take_unknown_focuses();
        assert_eq!(
            unknown,
            vec![
                UnknownFocus {
                    step: 2,
                    page: "rrt-2d".into(),
                    focus: "heatmap".into()
                },
                UnknownFocus {
                    step: 3,
                    page: "pid-step".into(),
                    focus: "<b>plot\u{fffd}</b>".into()
                },
            ]
        );
        assert_eq!(lesson.steps[0].focus.as_deref(), Some("heatmap"));
        assert!(lesson.steps[1].focus.is_none() && lesson.steps[2].focus.is_none());
        assert!(lesson.take_unknown_focuses().is_empty());
        assert_eq!(unknown[0].args()[2], ("focus", "heatmap".to_owned()));
        // A focus that is not text is a wrong type.
        assert_eq!(
            import(&with_steps(
                r##"[{"route":"#/ik-2r","title":"a","focus":3}]"##
            )),
            Err(wrong_type(Some(1), "focus", Expected::Text))
        );
    }

    #[test]
    fn bad_files_name_what_is_wrong() {
        let bad = |text: &str| from_json(text, is_page).unwrap_err();
        assert_eq!(
            bad(
                r##"{"format":"bsv-lesson","version":1,"title":"","steps":[{"route":"#/nope","title":"a"}]}"##
            ),
            LessonError::UnknownPage {
                step: 1,
                page: "nope".into()
            }
        );
        // A lesson cannot contain the lesson page itself.
        assert!(matches!(
            bad(
                r##"{"format":"bsv-lesson","version":1,"title":"","steps":[{"route":"#/lesson","title":"a"}]}"##
            ),
            LessonError::UnknownPage { .. }
        ));
        let long = "x".repeat(MAX_NOTE_CHARS + 1);
        let text = format!(
            r##"{{"format":"bsv-lesson","version":1,"title":"","steps":[{{"route":"#/ik-2r","title":"a","note":"{long}"}}]}}"##
        );
        assert_eq!(
            bad(&text),
            LessonError::TooLong {
                step: 1,
                field: "note"
            }
        );
        for e in [
            LessonError::TitleTooLong,
            LessonError::TooManyPageSteps { step: 2 },
        ] {
            assert!(e.message_id().starts_with("lesson-error-") && !e.args().is_empty());
        }
    }

    #[test]
    fn not_json_names_the_line_and_column() {
        assert_eq!(
            import("{\n  \"format\": bsv\n}"),
            Err(LessonError::NotJson {
                line: 2,
                column: 13
            })
        );
        assert_eq!(import(""), Err(LessonError::EmptyFile));
        assert_eq!(import("\u{feff} \n\t"), Err(LessonError::EmptyFile));
    }

    #[test]
    fn other_json_is_named_for_what_it_is() {
        for (text, kind) in [
            ("[1, 2]", "array"),
            ("42", "number"),
            ("\"lesson\"", "text"),
            ("true", "boolean"),
            ("null", "null"),
        ] {
            assert_eq!(
                import(text),
                Err(LessonError::NotAnObject { kind }),
                "{text}"
            );
        }
        // A teleop evidence file: an object without "format".
        let evidence = r#"{"schemaVersion":"0.1","sessionId":"s","dataArtifacts":[]}"#;
        assert_eq!(import(evidence), Err(LessonError::NoFormat));
        assert_eq!(
            import(r#"{"format":"slides","version":1}"#),
            Err(LessonError::WrongFormat {
                found: "slides".into()
            })
        );
        assert_eq!(
            import(r#"{"format":"bsv-lesson","version":4,"title":"","steps":[]}"#),
            Err(LessonError::WrongVersion { found: 4 })
        );
        assert_eq!(
            import(r#"{"format":"bsv-lesson","version":"1"}"#),
            Err(wrong_type(None, "version", Expected::WholeNumber))
        );
    }

    #[test]
    fn deep_nesting_is_refused_before_parsing() {
        let deep = "[".repeat(10_000) + &"]".repeat(10_000);
        assert_eq!(
            import(&deep),
            Err(LessonError::TooDeep {
                line: 1,
                column: MAX_DEPTH + 1
            })
        );
        let objects = "{\"a\":".repeat(10_000) + "1" + &"}".repeat(10_000);
        assert!(matches!(import(&objects), Err(LessonError::TooDeep { .. })));
        // Brackets inside text do not count.
        let title = "[{".repeat(40) + "\\\"";
        let text = format!(
            r##"{{"format":"bsv-lesson","version":1,"title":"{title}","steps":[{{"route":"#/ik-2r","title":"a"}}]}}"##
        );
        assert_eq!(import(&text).map(|l| l.title), Ok("[{".repeat(40) + "\""));
    }

    #[test]
    fn a_file_over_the_limit_is_refused_with_its_size() {
        let big = " ".repeat(MAX_FILE_BYTES as usize + 1);
        let error = import(&big).unwrap_err();
        assert_eq!(
            error,
            LessonError::TooBig {
                bytes: MAX_FILE_BYTES + 1
            }
        );
        assert_eq!(
            error.args(),
            vec![
                ("size", "512 KiB".to_owned()),
                ("bytes", "524,289".to_owned()),
                ("limit", "512 KiB".to_owned())
            ]
        );
        let fifty_mb = LessonError::TooBig { bytes: 50 << 20 };
        assert_eq!(fifty_mb.args()[0], ("size", "50 MiB".to_owned()));
    }

    #[test]
    fn fields_are_checked_by_name_with_their_step() {
        let step = r##"{"route":"#/ik-2r","title":"a"}"##;
        assert_eq!(
            import(&with_steps(&format!(
                r##"[{step},{{"route":"#/ik-2r","title":"b","evil":1}}]"##
            ))),
            Err(LessonError::UnknownField {
                step: Some(2),
                field: "evil".into()
            })
        );
        assert_eq!(
            import(&with_steps(r##"[{"route":"#/ik-2r"}]"##)),
            Err(missing(Some(1), "title"))
        );
        assert_eq!(
            import(&with_steps(
                r##"[{"route":"#/ik-2r","title":"a","pageSteps":"3"}]"##
            )),
            Err(wrong_type(Some(1), "pageSteps", Expected::WholeNumber))
        );
        assert_eq!(
            import(&with_steps(
                r##"[{"route":"#/ik-2r","title":"a","pageSteps":5000}]"##
            )),
            Err(LessonError::TooManyPageSteps { step: 1 })
        );
        assert_eq!(
            import(&with_steps(r#"[{"route":7,"title":"a"}]"#)),
            Err(wrong_type(Some(1), "route", Expected::Text))
        );
        assert_eq!(
            import(&with_steps(r##"["#/ik-2r"]"##)),
            Err(LessonError::StepNotAnObject { step: 1 })
        );
        assert_eq!(
            import(&with_steps("{}")),
            Err(wrong_type(None, "steps", Expected::List))
        );
        assert_eq!(
            import(r#"{"format":"bsv-lesson","version":1,"steps":[],"extra":0}"#),
            Err(LessonError::UnknownField {
                step: None,
                field: "extra".into()
            })
        );
        assert_eq!(
            import(r#"{"format":"bsv-lesson","version":1,"steps":[]}"#),
            Err(missing(None, "title"))
        );
    }

    #[test]
    fn an_empty_lesson_is_refused_as_a_file_but_read_from_storage() {
        let empty = with_steps("[]");
        assert_eq!(import(&empty), Err(LessonError::NoSteps));
        assert_eq!(
            from_stored(&empty, is_page),
            Ok(Lesson {
                title: "T".into(),
                steps: vec![]
            })
        );
    }

    #[test]
    fn script_like_text_stays_text_and_a_route_must_name_a_page() {
        let text = with_steps(
            r##"[{"route":"#/ik-2r?q1=0.3","title":"<script>alert(1)</script>","note":"javascript:alert(1) <img src=x onerror=alert(1)>"}]"##,
        );
        let lesson = import(&text).unwrap_or_default();
        assert_eq!(lesson.steps[0].title, "<script>alert(1)</script>");
        assert!(lesson.steps[0].note.starts_with("javascript:alert(1) <img"));
        for route in [
            "javascript:alert(1)",
            "https://example.com/#/ik-2r",
            "#/lesson",
        ] {
            let text = with_steps(&format!(r#"[{{"route":"{route}","title":"a"}}]"#));
            assert!(
                matches!(import(&text), Err(LessonError::UnknownPage { step: 1, .. })),
                "{route}"
            );
        }
        // A route is rebuilt by the URL codec: a link on the page is always `#/<page>?...`.
        let text = with_steps(r##"[{"route":"#/ik%2D2r?q1=<b>","title":"a"}]"##);
        assert_eq!(
            import(&text).map(|l| l.steps[0].route.clone()),
            Ok("#/ik-2r?q1=%3Cb%3E".into())
        );
    }

    #[test]
    fn quoted_file_text_is_short_and_printable() {
        let e = LessonError::UnknownField {
            step: None,
            field: format!("a\u{0}{}", "x".repeat(100)),
        };
        let field = &e.args()[0].1;
        assert!(field.starts_with("a\u{fffd}x") && field.ends_with('…'));
        assert_eq!(field.chars().count(), MAX_QUOTED_CHARS + 1);
    }

    #[test]
    fn every_error_has_a_message_in_both_languages() {
        let i18n = I18n::new();
        let errors = [
            LessonError::NotText { detail: "x".into() },
            LessonError::Decode(RecipeError::InputUtf16 { name: "x".into() }),
            LessonError::TooBig { bytes: 1 },
            LessonError::EmptyFile,
            LessonError::TooDeep {
                line: 1,
                column: 17,
            },
            LessonError::NotJson { line: 1, column: 1 },
            LessonError::NotAnObject { kind: "array" },
            LessonError::StepNotAnObject { step: 1 },
            LessonError::NoFormat,
            LessonError::WrongFormat { found: "x".into() },
            LessonError::WrongVersion { found: 2 },
            LessonError::UnknownField {
                step: None,
                field: "x".into(),
            },
            LessonError::UnknownField {
                step: Some(1),
                field: "x".into(),
            },
            missing(None, "title"),
            missing(Some(1), "title"),
            wrong_type(None, "steps", Expected::List),
            wrong_type(Some(1), "route", Expected::Text),
            LessonError::NoSteps,
            LessonError::TooManySteps { count: 61 },
            LessonError::UnknownPage {
                step: 1,
                page: "x".into(),
            },
            LessonError::TooLong {
                step: 1,
                field: "note",
            },
            LessonError::TooManyPageSteps { step: 1 },
            LessonError::TitleTooLong,
        ];
        for e in &errors {
            for lang in Lang::ALL {
                assert!(i18n.has_message(lang, e.message_id()), "{lang:?} {e:?}");
                assert!(i18n.has_message(lang, UnknownFocus::MESSAGE_ID));
            }
            assert!(e.message_id().starts_with("lesson-error-"));
        }
    }
}
