use super::*;
use crate::view::exercises;
#[cfg(target_family = "wasm")]
use wasm_bindgen_test::wasm_bindgen_test as test;

fn sample() -> LearnerProgress {
    let mut p = LearnerProgress::new("2026.12-abc123");
    p.set_learner("  Aiko  ").unwrap();
    p.record_answer("pendulum-euler-dt", false);
    p.record_answer("pendulum-euler-dt", true);
    p.record_answer("trap-accel-end", true);
    p.record_goal_met("pid-tune");
    p.record_answer("ik-w-pose", false);
    p
}

fn entry(attempts: u32, first_try_right: bool, done: bool) -> ExerciseProgress {
    ExerciseProgress {
        attempts,
        first_try_right,
        done,
    }
}

#[test]
fn recording_counts_attempts_first_tries_and_done() {
    let p = sample();
    assert_eq!(p.learner.as_deref(), Some("Aiko"));
    assert_eq!(p.get("pendulum-euler-dt"), entry(2, false, true));
    assert_eq!(p.get("trap-accel-end"), entry(1, true, true));
    assert_eq!(p.get("pid-tune"), entry(1, true, true));
    assert_eq!(p.get("ik-w-pose"), entry(1, false, false));
    assert_eq!(p.get("rrt-300"), ExerciseProgress::default());
    let standings: Vec<_> = [
        "trap-accel-end",
        "pendulum-euler-dt",
        "ik-w-pose",
        "rrt-300",
    ]
    .map(|id| p.get(id).standing())
    .into();
    assert_eq!(
        standings,
        [
            Standing::FirstTry,
            Standing::Later,
            Standing::NotYet,
            Standing::NotYet
        ]
    );
    // Done stays done; a goal met again changes nothing.
    let mut q = p.clone();
    q.record_answer("trap-accel-end", false);
    assert_eq!(q.get("trap-accel-end"), entry(2, true, true));
    q.record_goal_met("pid-tune");
    assert_eq!(q.get("pid-tune"), entry(1, true, true));
    // An empty name is none; a long one is refused.
    q.set_learner("   ").unwrap();
    assert_eq!(q.learner, None);
    assert_eq!(
        q.set_learner(&"x".repeat(MAX_NAME_CHARS + 1)),
        Err(ProgressError::NameTooLong)
    );
}

#[test]
fn json_round_trips_with_its_format_and_sorted_ids() {
    let p = sample();
    let text = to_json(&p);
    assert_eq!(
        text,
        r#"{
  "format": "bsv-progress",
  "version": 1,
  "learner": "Aiko",
  "build": "2026.12-abc123",
  "exercises": [
    {
      "id": "ik-w-pose",
      "attempts": 1,
      "firstTryRight": false,
      "done": false
    },
    {
      "id": "pendulum-euler-dt",
      "attempts": 2,
      "firstTryRight": false,
      "done": true
    },
    {
      "id": "pid-tune",
      "attempts": 1,
      "firstTryRight": true,
      "done": true
    },
    {
      "id": "trap-accel-end",
      "attempts": 1,
      "firstTryRight": true,
      "done": true
    }
  ]
}
"#
    );
    assert_eq!(from_json(&text), Ok(p));
    // Without a name, no `learner` field; an empty record reads back.
    let empty = LearnerProgress::new("b");
    let text = to_json(&empty);
    assert!(!text.contains("learner"));
    assert_eq!(from_json(&text), Ok(empty));
    // A byte-order mark is skipped.
    assert!(from_json(&format!("\u{feff}{text}")).is_ok());
}

#[test]
fn merging_keeps_the_most_and_is_idempotent() {
    let a = sample();
    let mut b = LearnerProgress::new("older-build");
    b.record_answer("pendulum-euler-dt", true);
    b.record_answer("ik-w-pose", false);
    b.record_answer("ik-w-pose", false);
    b.record_answer("ik-w-pose", true);
    b.record_goal_met("rrt-300");
    b.exercises
        .insert("from-a-newer-build".into(), entry(3, false, false));

    let mut merged = a.clone();
    merged.merge(&b);
    assert_eq!(merged.learner.as_deref(), Some("Aiko"));
    assert_eq!(merged.build, "2026.12-abc123");
    // Attempts: the larger; first try right and done: either.
    assert_eq!(merged.get("pendulum-euler-dt"), entry(2, true, true));
    assert_eq!(merged.get("ik-w-pose"), entry(3, false, true));
    assert_eq!(merged.get("rrt-300"), entry(1, true, true));
    assert_eq!(merged.get("trap-accel-end"), entry(1, true, true));
    // Unknown ids are kept and named.
    assert_eq!(merged.get("from-a-newer-build"), entry(3, false, false));
    assert_eq!(
        merged.unknown_ids(|id| exercises::find(id).is_some()),
        ["from-a-newer-build"]
    );
    // Either order gives the same exercises; importing twice changes nothing.
    let mut other_way = b.clone();
    other_way.merge(&a);
    assert_eq!(other_way.exercises, merged.exercises);
    let mut twice = merged.clone();
    twice.merge(&b);
    twice.merge(&a);
    assert_eq!(twice, merged);
    // A record without a name takes the imported one.
    assert_eq!(other_way.learner.as_deref(), Some("Aiko"));
    assert_eq!(other_way.build, "older-build");
}

#[test]
fn merged_records_stay_consistent() {
    let all = [
        entry(0, false, false),
        entry(1, false, false),
        entry(1, true, true),
        entry(4, false, true),
    ];
    for a in all {
        for b in all {
            let m = a.merged(b);
            assert!(m.is_consistent(), "{a:?} {b:?}");
            assert_eq!(m, b.merged(a));
            assert_eq!(m.merged(b), m);
        }
    }
}

fn with_exercises(exercises: &str) -> String {
    format!(r#"{{"format":"bsv-progress","version":1,"build":"b","exercises":{exercises}}}"#)
}

#[test]
fn bad_files_name_what_is_wrong() {
    let bad = |text: &str| from_json(text).unwrap_err();
    assert_eq!(
        bad("{\n  \"format\": bsv\n}"),
        ProgressError::NotJson {
            line: 2,
            column: 13
        }
    );
    assert_eq!(bad(" \n"), ProgressError::EmptyFile);
    assert_eq!(bad("[1]"), ProgressError::NotAnObject { kind: "array" });
    // Another program's JSON, a lesson file.
    assert_eq!(bad(r#"{"schemaVersion":"0.1"}"#), ProgressError::NoFormat);
    assert_eq!(
        bad(r#"{"format":"bsv-lesson","version":2,"title":"T","steps":[]}"#),
        ProgressError::WrongFormat {
            found: "bsv-lesson".into()
        }
    );
    assert_eq!(
        bad(r#"{"format":"bsv-progress","version":2,"build":"b","exercises":[]}"#),
        ProgressError::WrongVersion { found: 2 }
    );
    assert_eq!(
        bad(r#"{"format":"bsv-progress","version":1,"build":"b","exercises":[],"score":9}"#),
        ProgressError::UnknownField {
            exercise: None,
            field: "score".into()
        }
    );
    assert_eq!(
        bad(r#"{"format":"bsv-progress","version":1,"exercises":[]}"#),
        missing(None, "build")
    );
    assert_eq!(
        bad(r#"{"format":"bsv-progress","version":1,"build":"b","learner":7,"exercises":[]}"#),
        wrong_type(None, "learner", Expected::Text)
    );
    assert_eq!(
        bad(&with_exercises("{}")),
        wrong_type(None, "exercises", Expected::List)
    );
    let ok = r#"{"id":"pid-tune","attempts":1,"firstTryRight":true,"done":true}"#;
    assert_eq!(
        bad(&with_exercises(&format!(
            r#"[{ok},{{"id":"x","attempts":1,"firstTryRight":true,"done":true,"when":0}}]"#
        ))),
        ProgressError::UnknownField {
            exercise: Some(2),
            field: "when".into()
        }
    );
    assert_eq!(
        bad(&with_exercises(&format!("[{ok},{ok}]"))),
        ProgressError::DuplicateId {
            id: "pid-tune".into()
        }
    );
    assert_eq!(
        bad(&with_exercises(
            r#"[{"id":"pid-tune","attempts":0,"firstTryRight":false,"done":true}]"#
        )),
        ProgressError::Inconsistent {
            id: "pid-tune".into()
        }
    );
    assert_eq!(
        bad(&with_exercises(
            r#"[{"id":"pid-tune","attempts":2,"firstTryRight":true,"done":false}]"#
        )),
        ProgressError::Inconsistent {
            id: "pid-tune".into()
        }
    );
    assert_eq!(
        bad(&with_exercises(
            r#"[{"id":"pid-tune","attempts":-1,"firstTryRight":false,"done":false}]"#
        )),
        wrong_type(Some(1), "attempts", Expected::WholeNumber)
    );
    assert_eq!(
        bad(&with_exercises(
            r#"[{"id":"pid-tune","attempts":4294967296,"firstTryRight":false,"done":false}]"#
        )),
        ProgressError::TooManyAttempts { exercise: 1 }
    );
    assert_eq!(
        bad(&with_exercises(
            r#"[{"id":"pid-tune","attempts":1,"firstTryRight":"yes","done":true}]"#
        )),
        wrong_type(Some(1), "firstTryRight", Expected::TrueFalse)
    );
    assert_eq!(
        bad(&with_exercises(
            r#"[{"id":"pid-tune","attempts":1,"done":true}]"#
        )),
        missing(Some(1), "firstTryRight")
    );
    assert_eq!(
        bad(&with_exercises(
            r#"[{"id":"<b>Pid</b>","attempts":1,"firstTryRight":true,"done":true}]"#
        )),
        ProgressError::BadId {
            exercise: 1,
            id: "<b>Pid</b>".into()
        }
    );
    assert_eq!(
        bad(&with_exercises(r#"["pid-tune"]"#)),
        ProgressError::ExerciseNotAnObject { exercise: 1 }
    );
}

#[test]
fn size_and_nesting_are_checked_before_parsing() {
    let big = " ".repeat(MAX_FILE_BYTES as usize + 1);
    assert_eq!(
        from_json(&big),
        Err(ProgressError::TooBig {
            bytes: MAX_FILE_BYTES + 1
        })
    );
    let deep = "[".repeat(10_000) + &"]".repeat(10_000);
    assert_eq!(
        from_json(&deep),
        Err(ProgressError::TooDeep {
            line: 1,
            column: MAX_DEPTH + 1
        })
    );
    let many: Vec<String> = (0..=MAX_EXERCISES)
        .map(|i| format!(r#"{{"id":"e{i}","attempts":0,"firstTryRight":false,"done":false}}"#))
        .collect();
    let text = with_exercises(&format!("[{}]", many.join(",")));
    assert!(text.len() as u64 <= MAX_FILE_BYTES);
    assert_eq!(
        from_json(&text),
        Err(ProgressError::TooManyExercises {
            count: MAX_EXERCISES + 1
        })
    );
    // Every exercise of the catalog at its most fits well within the limit.
    let mut full = LearnerProgress::new(&"b".repeat(MAX_BUILD_CHARS));
    full.set_learner(&"名".repeat(MAX_NAME_CHARS)).unwrap();
    for e in exercises::catalog() {
        full.exercises
            .insert(e.id.to_owned(), entry(MAX_ATTEMPTS, false, true));
    }
    assert!(to_json(&full).len() < 40 * 1024);
    assert_eq!(from_json(&to_json(&full)), Ok(full));
}

#[test]
fn errors_have_message_ids_and_quoted_arguments() {
    let e = ProgressError::WrongFormat {
        found: format!("a\u{7}{}", "x".repeat(100)),
    };
    assert_eq!(e.message_id(), "progress-error-format");
    let found = &e.args()[0].1;
    assert!(found.starts_with("a\u{fffd}x") && found.ends_with('…'));
    assert_eq!(
        ProgressError::TooBig { bytes: 300_000 }.args(),
        vec![
            ("size", "293 KiB".to_owned()),
            ("bytes", "300,000".to_owned()),
            ("limit", "256 KiB".to_owned())
        ]
    );
    assert_eq!(
        missing(Some(3), "done").message_id(),
        "progress-error-exercise-missing-field"
    );
    assert_eq!(
        missing(Some(3), "done").args(),
        vec![("field", "done".to_owned()), ("exercise", "3".to_owned())]
    );
}

#[test]
fn every_error_has_a_message_in_both_languages() {
    use crate::i18n::{fluent_args, I18n, Lang};
    let i18n = I18n::from_sources(&super::MESSAGE_SOURCES);
    let errors = [
        ProgressError::NotText { detail: "x".into() },
        ProgressError::Decode(RecipeError::InputUtf16 { name: "x".into() }),
        ProgressError::TooBig { bytes: 1 },
        ProgressError::EmptyFile,
        ProgressError::TooDeep { line: 1, column: 9 },
        ProgressError::NotJson { line: 1, column: 1 },
        ProgressError::NotAnObject { kind: "array" },
        ProgressError::NoFormat,
        ProgressError::WrongFormat { found: "x".into() },
        ProgressError::WrongVersion { found: 2 },
        ProgressError::UnknownField {
            exercise: None,
            field: "x".into(),
        },
        ProgressError::UnknownField {
            exercise: Some(1),
            field: "x".into(),
        },
        missing(None, "build"),
        missing(Some(1), "done"),
        wrong_type(None, "exercises", Expected::List),
        wrong_type(Some(1), "done", Expected::TrueFalse),
        ProgressError::ExerciseNotAnObject { exercise: 1 },
        ProgressError::TooManyExercises { count: 1001 },
        ProgressError::BadId {
            exercise: 1,
            id: "X".into(),
        },
        ProgressError::DuplicateId { id: "x".into() },
        ProgressError::TooManyAttempts { exercise: 1 },
        ProgressError::Inconsistent { id: "x".into() },
        ProgressError::NameTooLong,
        ProgressError::BuildTooLong,
    ];
    for e in &errors {
        assert!(e.message_id().starts_with("progress-error-"));
        for lang in Lang::ALL {
            assert!(i18n.has_message(lang, e.message_id()), "{lang:?} {e:?}");
            let text = i18n.t_args(lang, e.message_id(), &fluent_args(e.args()));
            assert!(!text.contains('{'), "{text}");
        }
    }
    assert_eq!(i18n.take_warnings(), Vec::<String>::new());
}
