//! The class summary (`#/class`): many learners' progress files
//! ([`crate::view::learner_progress`]) as a table of learners by exercises (right at the first
//! try, right later, not yet), each exercise's success rate with the hardest first, and the
//! `class_summary.csv` text. Nothing leaves the browser: the page hands the files' names and
//! texts in.
//!
//! - A file that does not read is named with its error, as a lesson import names one; the
//!   others are kept.
//! - A learner is known by the name in the file (trimmed, letter case ignored). A second file
//!   with the same name is named as a duplicate of the first (the first given is kept), saying
//!   whether its record is the same. A file without a name is shown by its file name, and is
//!   a duplicate only when an earlier nameless file has the same file name and the same record
//!   (the same file given twice): every student's export is `bsv_progress.json`.
//! - Columns are the exercises the page passes in (the app's catalog); ids a file has beyond
//!   them are listed on its row and counted nowhere.
//! - Success rate: the share of the kept learners who have done the exercise (first try or
//!   later); hardest first is the lowest success rate first, then the lowest share right at
//!   the first try, then the catalog's order.
//! - Rows are sorted by learner (letter case ignored), then file name.
//!
//! CSV (Python `csv.writer` quoting, `\r\n`): `row,learner,file,<id>...` with the ids hardest
//! first; a `learner` row per learner with each exercise's standing (`first-try`, `later`,
//! `not-yet`), then one `success_rate` row with each rate in % to one decimal (empty without
//! learners). A learner or file name that a spreadsheet would read as a formula (starting
//! with `=`, `+`, `-`, `@`, a tab or a carriage return) is written after a `'`.

use crate::pyfmt::{fixed, CsvText};
use crate::view::learner_progress::{from_json, LearnerProgress, ProgressError, Standing};

/// The file the summary downloads as.
pub const CSV_NAME: &str = "class_summary.csv";

/// One exercise's column: how many learners stand where.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ExerciseColumn {
    pub id: String,
    pub first_try: usize,
    pub later: usize,
    pub not_yet: usize,
}

impl ExerciseColumn {
    fn learners(&self) -> usize {
        self.first_try + self.later + self.not_yet
    }

    /// Share of the learners who have done it, 0 to 1 (`None` without learners).
    pub fn success_rate(&self) -> Option<f64> {
        let n = self.learners();
        (n > 0).then(|| (self.first_try + self.later) as f64 / n as f64)
    }

    /// Share of the learners right at the first try, 0 to 1 (`None` without learners).
    pub fn first_try_rate(&self) -> Option<f64> {
        let n = self.learners();
        (n > 0).then(|| self.first_try as f64 / n as f64)
    }
}

/// One learner's row.
#[derive(Debug, Clone, PartialEq)]
pub struct LearnerRow {
    /// The learner's name, or the file name when the file has none.
    pub learner: String,
    /// Whether the file named the learner.
    pub named: bool,
    pub file: String,
    /// A standing per column of [`ClassSummary::exercises`], in its order.
    pub standings: Vec<Standing>,
    /// Ids of the file that are not columns (a newer build's exercises).
    pub unknown_ids: Vec<String>,
    pub progress: LearnerProgress,
}

/// Why a file is not in the table.
#[derive(Debug, Clone, PartialEq)]
pub enum FileProblem {
    /// It does not read as a progress file.
    Unreadable(ProgressError),
    /// A second file of a learner already in the table (`first_file`); `same_record` when
    /// both hold the same progress.
    Duplicate {
        learner: String,
        first_file: String,
        same_record: bool,
    },
}

impl FileProblem {
    /// The Fluent id of the message (the page puts the file's name before it).
    pub fn message_id(&self) -> &'static str {
        match self {
            FileProblem::Unreadable(e) => e.message_id(),
            FileProblem::Duplicate { .. } => "class-duplicate",
        }
    }

    /// The message's arguments (name, value).
    pub fn args(&self) -> Vec<(&'static str, String)> {
        match self {
            FileProblem::Unreadable(e) => e.args(),
            FileProblem::Duplicate {
                learner,
                first_file,
                same_record,
            } => vec![
                ("learner", learner.clone()),
                ("first", first_file.clone()),
                (
                    "same",
                    if *same_record { "same" } else { "different" }.to_owned(),
                ),
            ],
        }
    }
}

/// A file left out, by name.
#[derive(Debug, Clone, PartialEq)]
pub struct RejectedFile {
    pub file: String,
    pub problem: FileProblem,
}

/// The whole summary.
#[derive(Debug, Clone, PartialEq)]
pub struct ClassSummary {
    /// The columns, hardest first.
    pub exercises: Vec<ExerciseColumn>,
    pub learners: Vec<LearnerRow>,
    /// Files left out, in the order given.
    pub rejected: Vec<RejectedFile>,
}

/// How a learner is recognized across files.
fn learner_key(progress: &LearnerProgress, file: &str) -> (bool, String) {
    match &progress.learner {
        Some(name) => (true, name.to_lowercase()),
        None => (false, file.to_owned()),
    }
}

/// The summary of `files` (`(file name, text)`, in the order given) over the exercises
/// `exercise_ids` (catalog order).
pub fn summarize(files: &[(String, String)], exercise_ids: &[&str]) -> ClassSummary {
    let mut kept: Vec<LearnerRow> = Vec::new();
    let mut rejected = Vec::new();
    for (file, text) in files {
        let progress = match from_json(text) {
            Ok(p) => p,
            Err(e) => {
                rejected.push(RejectedFile {
                    file: file.clone(),
                    problem: FileProblem::Unreadable(e),
                });
                continue;
            }
        };
        let (named, key) = learner_key(&progress, file);
        let first = kept.iter().find(|row| {
            learner_key(&row.progress, &row.file) == (named, key.clone())
                && (named || row.progress == progress)
        });
        if let Some(first) = first {
            rejected.push(RejectedFile {
                file: file.clone(),
                problem: FileProblem::Duplicate {
                    learner: first.learner.clone(),
                    first_file: first.file.clone(),
                    same_record: first.progress.exercises == progress.exercises,
                },
            });
            continue;
        }
        kept.push(LearnerRow {
            learner: progress.learner.clone().unwrap_or_else(|| file.clone()),
            named,
            file: file.clone(),
            standings: Vec::new(),
            unknown_ids: progress
                .unknown_ids(|id| exercise_ids.contains(&id))
                .into_iter()
                .map(str::to_owned)
                .collect(),
            progress,
        });
    }
    let mut exercises: Vec<ExerciseColumn> = exercise_ids
        .iter()
        .map(|id| {
            let mut column = ExerciseColumn {
                id: (*id).to_owned(),
                first_try: 0,
                later: 0,
                not_yet: 0,
            };
            for row in &kept {
                match row.progress.get(id).standing() {
                    Standing::FirstTry => column.first_try += 1,
                    Standing::Later => column.later += 1,
                    Standing::NotYet => column.not_yet += 1,
                }
            }
            column
        })
        .collect();
    // Stable: equal columns keep the catalog's order.
    exercises.sort_by(|a, b| {
        let rates = |c: &ExerciseColumn| (c.success_rate(), c.first_try_rate());
        rates(a)
            .partial_cmp(&rates(b))
            .unwrap_or(std::cmp::Ordering::Equal)
    });
    for row in &mut kept {
        row.standings = exercises
            .iter()
            .map(|c| row.progress.get(&c.id).standing())
            .collect();
    }
    kept.sort_by(|a, b| {
        (a.learner.to_lowercase(), &a.file).cmp(&(b.learner.to_lowercase(), &b.file))
    });
    ClassSummary {
        exercises,
        learners: kept,
        rejected,
    }
}

/// Text a spreadsheet would read as a formula, made plain with a leading `'`.
fn spreadsheet_text(text: &str) -> String {
    if text.starts_with(['=', '+', '-', '@', '\t', '\r']) {
        format!("'{text}")
    } else {
        text.to_owned()
    }
}

impl ClassSummary {
    /// The `class_summary.csv` text (see the module docs).
    pub fn to_csv(&self) -> String {
        let mut header = vec!["row", "learner", "file"];
        header.extend(self.exercises.iter().map(|c| c.id.as_str()));
        let mut csv = CsvText::with_header(&header);
        for row in &self.learners {
            let (learner, file) = (spreadsheet_text(&row.learner), spreadsheet_text(&row.file));
            let mut cells = vec!["learner", learner.as_str(), file.as_str()];
            cells.extend(row.standings.iter().map(|s| s.key()));
            csv.raw_row(cells);
        }
        let rates: Vec<String> = self
            .exercises
            .iter()
            .map(|c| {
                c.success_rate()
                    .map_or(String::new(), |r| fixed(100.0 * r, 1))
            })
            .collect();
        let mut cells = vec!["success_rate", "", ""];
        cells.extend(rates.iter().map(String::as_str));
        csv.raw_row(cells);
        csv.finish()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::view::learner_progress::to_json;
    #[cfg(target_family = "wasm")]
    use wasm_bindgen_test::wasm_bindgen_test as test;

    const IDS: [&str; 4] = ["ik-singular", "pid-tune", "trap-triangle", "rrt-300"];

    /// A progress file of `name` with `(id, answers)`: each answer right or not.
    fn file_of(name: Option<&str>, answers: &[(&str, &[bool])]) -> String {
        let mut p = LearnerProgress::new("build-1");
        if let Some(name) = name {
            p.set_learner(name).unwrap();
        }
        for (id, tries) in answers {
            for right in *tries {
                p.record_answer(id, *right);
            }
        }
        to_json(&p)
    }

    fn files(list: &[(&str, String)]) -> Vec<(String, String)> {
        list.iter()
            .map(|(n, t)| ((*n).to_owned(), t.clone()))
            .collect()
    }

    fn class() -> Vec<(String, String)> {
        files(&[
            (
                "ken.json",
                file_of(
                    Some("Ken"),
                    &[("ik-singular", &[true]), ("pid-tune", &[false, true])],
                ),
            ),
            (
                "aiko.json",
                file_of(
                    Some("Aiko"),
                    &[
                        ("ik-singular", &[true]),
                        ("trap-triangle", &[false]),
                        ("future-exercise", &[true]),
                    ],
                ),
            ),
            ("broken.json", "{\"format\": \"bsv-progress\",".to_owned()),
            (
                "bsv_progress.json",
                file_of(None, &[("ik-singular", &[false, false, true])]),
            ),
        ])
    }

    #[test]
    fn the_table_has_a_row_per_learner_and_names_the_broken_file() {
        let s = summarize(&class(), &IDS);
        let rows: Vec<(&str, &str)> = s
            .learners
            .iter()
            .map(|r| (r.learner.as_str(), r.file.as_str()))
            .collect();
        assert_eq!(
            rows,
            [
                ("Aiko", "aiko.json"),
                ("bsv_progress.json", "bsv_progress.json"),
                ("Ken", "ken.json")
            ]
        );
        assert_eq!(s.rejected.len(), 1);
        assert_eq!(s.rejected[0].file, "broken.json");
        assert!(matches!(
            s.rejected[0].problem,
            FileProblem::Unreadable(ProgressError::NotJson { line: 1, .. })
        ));
        assert_eq!(s.learners[0].unknown_ids, ["future-exercise"]);
        assert!(!s.learners[1].named);
    }

    #[test]
    fn exercises_are_sorted_hardest_first() {
        let s = summarize(&class(), &IDS);
        let order: Vec<(&str, Option<f64>)> = s
            .exercises
            .iter()
            .map(|c| (c.id.as_str(), c.success_rate()))
            .collect();
        // trap-triangle and rrt-300: nobody (trap-triangle before rrt-300, the catalog's
        // order); pid-tune: 1 of 3; ik-singular: all 3.
        assert_eq!(
            order,
            [
                ("trap-triangle", Some(0.0)),
                ("rrt-300", Some(0.0)),
                ("pid-tune", Some(1.0 / 3.0)),
                ("ik-singular", Some(1.0)),
            ]
        );
        let ik = &s.exercises[3];
        assert_eq!((ik.first_try, ik.later, ik.not_yet), (2, 1, 0));
        // Equal success rates: the fewer right at the first try is harder.
        let two = files(&[
            (
                "a.json",
                file_of(
                    Some("A"),
                    &[("pid-tune", &[true]), ("ik-singular", &[false, true])],
                ),
            ),
            ("b.json", file_of(Some("B"), &[])),
        ]);
        let s = summarize(&two, &["pid-tune", "ik-singular"]);
        assert_eq!(s.exercises[0].id, "ik-singular");
        // Without learners the catalog's order stays and there are no rates.
        let none = summarize(&[], &IDS);
        assert_eq!(
            none.exercises
                .iter()
                .map(|c| c.id.as_str())
                .collect::<Vec<_>>(),
            IDS
        );
        assert!(none.exercises.iter().all(|c| c.success_rate().is_none()));
    }

    #[test]
    fn a_learners_second_file_is_a_duplicate() {
        let ken = file_of(Some("Ken"), &[("ik-singular", &[true])]);
        let ken_later = file_of(
            Some(" ken "),
            &[("ik-singular", &[true]), ("pid-tune", &[true])],
        );
        let nameless = file_of(None, &[("pid-tune", &[true])]);
        let other_nameless = file_of(None, &[("rrt-300", &[true])]);
        let s = summarize(
            &files(&[
                ("ken.json", ken.clone()),
                ("ken (1).json", ken),
                ("ken-later.json", ken_later),
                ("bsv_progress.json", nameless.clone()),
                ("bsv_progress.json", nameless),
                ("bsv_progress.json", other_nameless),
            ]),
            &IDS,
        );
        assert_eq!(s.learners.len(), 3);
        let problems: Vec<(&str, &FileProblem)> = s
            .rejected
            .iter()
            .map(|r| (r.file.as_str(), &r.problem))
            .collect();
        assert_eq!(
            problems,
            [
                (
                    "ken (1).json",
                    &FileProblem::Duplicate {
                        learner: "Ken".into(),
                        first_file: "ken.json".into(),
                        same_record: true
                    }
                ),
                (
                    "ken-later.json",
                    &FileProblem::Duplicate {
                        learner: "Ken".into(),
                        first_file: "ken.json".into(),
                        same_record: false
                    }
                ),
                (
                    "bsv_progress.json",
                    &FileProblem::Duplicate {
                        learner: "bsv_progress.json".into(),
                        first_file: "bsv_progress.json".into(),
                        same_record: true
                    }
                ),
            ]
        );
    }

    #[test]
    fn problems_have_messages_in_both_languages() {
        use crate::i18n::{fluent_args, I18n, Lang};
        let i18n = I18n::from_sources(&crate::view::learner_progress::MESSAGE_SOURCES);
        let s = summarize(
            &files(&[
                ("a.json", file_of(Some("A"), &[])),
                ("a2.json", file_of(Some("A"), &[("pid-tune", &[true])])),
                ("b.json", "[]".to_owned()),
            ]),
            &IDS,
        );
        assert_eq!(s.rejected.len(), 2);
        for r in &s.rejected {
            for lang in Lang::ALL {
                let text =
                    i18n.t_args(lang, r.problem.message_id(), &fluent_args(r.problem.args()));
                assert!(!text.contains('{'), "{text}");
            }
        }
        let en = i18n.t_args(
            Lang::En,
            s.rejected[0].problem.message_id(),
            &fluent_args(s.rejected[0].problem.args()),
        );
        assert_eq!(
            en,
            "A second file of A (the first is a.json) with different progress: left out; the first file's progress is shown."
        );
        assert_eq!(i18n.take_warnings(), Vec::<String>::new());
    }

    #[test]
    fn the_csv_is_exact_and_keeps_formulas_out() {
        let s = summarize(&class(), &IDS);
        assert_eq!(
            s.to_csv(),
            "row,learner,file,trap-triangle,rrt-300,pid-tune,ik-singular\r\n\
             learner,Aiko,aiko.json,not-yet,not-yet,not-yet,first-try\r\n\
             learner,bsv_progress.json,bsv_progress.json,not-yet,not-yet,not-yet,later\r\n\
             learner,Ken,ken.json,not-yet,not-yet,later,first-try\r\n\
             success_rate,,,0.0,0.0,33.3,100.0\r\n"
        );
        let odd = files(&[(
            "=cmd.json",
            file_of(
                Some("=HYPERLINK(\"x\"), \"Sato\""),
                &[("pid-tune", &[true])],
            ),
        )]);
        let csv = summarize(&odd, &["pid-tune"]).to_csv();
        assert_eq!(
            csv,
            "row,learner,file,pid-tune\r\n\
             learner,\"'=HYPERLINK(\"\"x\"\"), \"\"Sato\"\"\",'=cmd.json,first-try\r\n\
             success_rate,,,100.0\r\n"
        );
        assert_eq!(
            summarize(&[], &["pid-tune"]).to_csv(),
            "row,learner,file,pid-tune\r\nsuccess_rate,,,\r\n"
        );
    }
}
