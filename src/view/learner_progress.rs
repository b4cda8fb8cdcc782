//! A learner's progress on the exercises ([`crate::view::exercises`]): for each exercise the
//! attempts, whether the first try was right, and whether it is done; kept in the browser
//! (`bsv.progress`) and exported as `bsv_progress.json`, both as the JSON file below.
//!
//! ```text
//! {"format": "bsv-progress", "version": 1, "learner": "Aiko", "build": "<the app's build>",
//!  "exercises": [{"id": "pid-tune", "attempts": 2, "firstTryRight": false, "done": true}]}
//! ```
//! `learner` is optional; exercises are written in id order, those never tried are left out.
//!
//! Recording: an answer (a prediction or a choice) counts one attempt; the first attempt
//! being right sets `firstTryRight`; any right attempt sets `done`, which stays set. A goal has
//! no tries: met, it counts one attempt, right at the first, and is done (a goal met again
//! changes nothing).
//!
//! Reading checks, in order (as the lesson file is read): the size ([`MAX_FILE_BYTES`]; the
//! page refuses a bigger file from its size alone), text at all, nesting ([`MAX_DEPTH`],
//! before parsing), JSON (its line and column when it is not), an object, its `format` (a file
//! without one, or with another, is another program's) and `version`, then every field by
//! name (unknown, missing, wrong type) and the limits below. An exercise is consistent: done
//! needs an attempt, right at the first try needs done. An id may appear once.
//!
//! Ids this build does not know (a file from a newer build) are kept, so that importing and
//! exporting again loses nothing, and named ([`LearnerProgress::unknown_ids`]) for the page to
//! say so; they count in no page's progress.
//!
//! Merging (an import into the current record, [`LearnerProgress::merge`]) takes, for each
//! exercise, the larger number of attempts, and `done` and `firstTryRight` if either record
//! has them. It is the same whichever record comes first and importing the same file twice
//! changes nothing (a record exported from this browser and imported back is a no-op), at
//! the cost of undercounting attempts made on two devices. The current record keeps its
//! learner name and build; a record without a name takes the imported one.

use std::collections::BTreeMap;

use serde::Serialize;
use serde_json::{Map, Value};

use crate::error::RecipeError;
use crate::pyfmt::{group_u64, size_text};
use crate::view::json_file::{kind_of, quoted, too_deep_at, unknown_field};

/// The file of the progress file's messages (its problems, the panel that exports and imports
/// it, the home page's progress and the class page): `locales/<lang>/progress.ftl`.
pub const MESSAGE_FILE: &str = "progress.ftl";

/// [`MESSAGE_FILE`] of both languages, for the tests.
#[cfg(test)]
pub(crate) const MESSAGE_SOURCES: [(crate::i18n::Lang, &str, &str); 2] = [
    (
        crate::i18n::Lang::En,
        MESSAGE_FILE,
        include_str!("../../locales/en/progress.ftl"),
    ),
    (
        crate::i18n::Lang::Ja,
        MESSAGE_FILE,
        include_str!("../../locales/ja/progress.ftl"),
    ),
];

/// The `format` field of a progress file.
pub const FORMAT: &str = "bsv-progress";
/// The version this build writes and reads.
pub const VERSION: u32 = 1;
/// A progress file larger than this is refused unread (all exercises at full length are
/// under 40 KiB).
pub const MAX_FILE_BYTES: u64 = 256 * 1024;
/// Deepest nesting read (a progress file has 3: file, exercises, exercise).
pub const MAX_DEPTH: usize = 8;
/// Most exercises in one file (known and unknown).
pub const MAX_EXERCISES: usize = 1000;
/// Longest exercise id (kebab-case: lower-case ASCII letters, digits, single hyphens).
pub const MAX_ID_CHARS: usize = 64;
/// Longest learner name and build.
pub const MAX_NAME_CHARS: usize = 80;
pub const MAX_BUILD_CHARS: usize = 80;
/// Most attempts recorded for one exercise.
pub const MAX_ATTEMPTS: u32 = 1_000_000;
/// Longest text from a file quoted in a message.
pub const MAX_QUOTED_CHARS: usize = 40;

/// The fields of the file, then of an exercise.
const FILE_FIELDS: [&str; 5] = ["format", "version", "learner", "build", "exercises"];
const EXERCISE_FIELDS: [&str; 4] = ["id", "attempts", "firstTryRight", "done"];

/// Where a learner stands on one exercise (the class summary's cells).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Standing {
    /// Done, right at the first try.
    FirstTry,
    /// Done after a wrong try.
    Later,
    /// Not done (tried or not).
    NotYet,
}

impl Standing {
    /// The word of the CSV and of the page's `data-` attributes.
    pub fn key(self) -> &'static str {
        match self {
            Standing::FirstTry => "first-try",
            Standing::Later => "later",
            Standing::NotYet => "not-yet",
        }
    }
}

/// One exercise's record.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct ExerciseProgress {
    pub attempts: u32,
    pub first_try_right: bool,
    pub done: bool,
}

impl ExerciseProgress {
    /// Where it stands.
    pub fn standing(&self) -> Standing {
        match (self.done, self.first_try_right) {
            (true, true) => Standing::FirstTry,
            (true, false) => Standing::Later,
            (false, _) => Standing::NotYet,
        }
    }

    /// The merge of two records of the same exercise (see the module docs).
    pub fn merged(self, other: ExerciseProgress) -> ExerciseProgress {
        ExerciseProgress {
            attempts: self.attempts.max(other.attempts),
            first_try_right: self.first_try_right || other.first_try_right,
            done: self.done || other.done,
        }
    }

    /// Done needs an attempt, right at the first try needs done.
    fn is_consistent(&self) -> bool {
        (!self.done || self.attempts > 0) && (!self.first_try_right || self.done)
    }
}

/// A learner's record.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct LearnerProgress {
    /// The learner's name, trimmed, never empty.
    pub learner: Option<String>,
    /// The build of the app that wrote the record (the current one's once merged into it).
    pub build: String,
    /// By exercise id (ids this build does not know included).
    pub exercises: BTreeMap<String, ExerciseProgress>,
}

/// The file form (field order as written).
#[derive(Serialize)]
struct ProgressFile<'a> {
    format: &'a str,
    version: u32,
    #[serde(skip_serializing_if = "Option::is_none")]
    learner: Option<&'a str>,
    build: &'a str,
    exercises: Vec<ExerciseEntry<'a>>,
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct ExerciseEntry<'a> {
    id: &'a str,
    #[serde(flatten)]
    progress: ExerciseProgress,
}

impl LearnerProgress {
    /// An empty record of the app's `build`.
    pub fn new(build: &str) -> LearnerProgress {
        LearnerProgress {
            learner: None,
            build: build.to_owned(),
            exercises: BTreeMap::new(),
        }
    }

    /// The record of exercise `id` (all zero when never tried).
    pub fn get(&self, id: &str) -> ExerciseProgress {
        self.exercises.get(id).copied().unwrap_or_default()
    }

    /// Records an answer to `id`, right or not.
    pub fn record_answer(&mut self, id: &str, right: bool) {
        let e = self.exercises.entry(id.to_owned()).or_default();
        e.attempts = e.attempts.saturating_add(1).min(MAX_ATTEMPTS);
        if e.attempts == 1 && right {
            e.first_try_right = true;
        }
        e.done |= right;
    }

    /// Records goal `id` met (once; again changes nothing).
    pub fn record_goal_met(&mut self, id: &str) {
        let e = self.exercises.entry(id.to_owned()).or_default();
        if !e.done {
            e.attempts = e.attempts.saturating_add(1).min(MAX_ATTEMPTS);
            e.first_try_right = e.attempts == 1;
            e.done = true;
        }
    }

    /// Sets the learner's name (trimmed; empty removes it).
    pub fn set_learner(&mut self, name: &str) -> Result<(), ProgressError> {
        self.learner = learner_name(name)?;
        Ok(())
    }

    /// Merges `imported` into this record (see the module docs).
    pub fn merge(&mut self, imported: &LearnerProgress) {
        for (id, theirs) in &imported.exercises {
            let ours = self.exercises.entry(id.clone()).or_default();
            *ours = ours.merged(*theirs);
        }
        if self.learner.is_none() {
            self.learner.clone_from(&imported.learner);
        }
    }

    /// The ids of the record that `is_known` does not know, in order.
    pub fn unknown_ids(&self, is_known: impl Fn(&str) -> bool) -> Vec<&str> {
        self.exercises
            .keys()
            .map(String::as_str)
            .filter(|id| !is_known(id))
            .collect()
    }
}

/// The file text of `progress` (pretty, stable order; exercises never tried left out).
pub fn to_json(progress: &LearnerProgress) -> String {
    let file = ProgressFile {
        format: FORMAT,
        version: VERSION,
        learner: progress.learner.as_deref(),
        build: &progress.build,
        exercises: progress
            .exercises
            .iter()
            .filter(|(_, p)| **p != ExerciseProgress::default())
            .map(|(id, p)| ExerciseEntry { id, progress: *p })
            .collect(),
    };
    // Serializing plain strings, numbers and booleans cannot fail.
    serde_json::to_string_pretty(&file).unwrap_or_default() + "\n"
}

/// What a field should hold (the `expected` argument of a message).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Expected {
    Text,
    WholeNumber,
    TrueFalse,
    List,
}

impl Expected {
    fn word(self) -> &'static str {
        match self {
            Expected::Text => "text",
            Expected::WholeNumber => "number",
            Expected::TrueFalse => "boolean",
            Expected::List => "list",
        }
    }
}

/// What is wrong with a progress file, for a localized message (`progress-error-<id>` with
/// the details as arguments). `exercise` counts the file's exercises from 1; `None` is the
/// file itself.
#[derive(Debug, Clone, PartialEq)]
pub enum ProgressError {
    /// The browser could not read the file (its reason).
    NotText { detail: String },
    /// Not UTF-8 text ([`crate::recipes::decode_input`]'s error).
    Decode(RecipeError),
    /// Bigger than [`MAX_FILE_BYTES`].
    TooBig { bytes: u64 },
    /// Nothing in it (or only spaces).
    EmptyFile,
    /// Nested deeper than [`MAX_DEPTH`]; where the limit is passed.
    TooDeep { line: usize, column: usize },
    /// Not JSON: where the parser stopped.
    NotJson { line: usize, column: usize },
    /// JSON, but not an object.
    NotAnObject { kind: &'static str },
    /// An object without `format` (another program's JSON).
    NoFormat,
    /// `format` is not `bsv-progress` (another program's file, a lesson...).
    WrongFormat { found: String },
    /// A newer (or unknown) version.
    WrongVersion { found: u64 },
    /// A field this version does not know.
    UnknownField {
        exercise: Option<usize>,
        field: String,
    },
    /// A required field is absent.
    MissingField {
        exercise: Option<usize>,
        field: &'static str,
    },
    /// A field holds the wrong kind of value.
    WrongType {
        exercise: Option<usize>,
        field: &'static str,
        expected: Expected,
    },
    /// Exercise `exercise` is not an object.
    ExerciseNotAnObject { exercise: usize },
    /// More than [`MAX_EXERCISES`].
    TooManyExercises { count: usize },
    /// An id that is not kebab-case or is longer than [`MAX_ID_CHARS`].
    BadId { exercise: usize, id: String },
    /// The same id twice.
    DuplicateId { id: String },
    /// More attempts than [`MAX_ATTEMPTS`].
    TooManyAttempts { exercise: usize },
    /// Done without an attempt, or right at the first try without done.
    Inconsistent { id: String },
    /// A learner name longer than [`MAX_NAME_CHARS`].
    NameTooLong,
    /// A build longer than [`MAX_BUILD_CHARS`].
    BuildTooLong,
}

impl ProgressError {
    /// The Fluent id of the message.
    pub fn message_id(&self) -> &'static str {
        use ProgressError::*;
        match self {
            NotText { .. } | Decode(_) => "progress-error-not-text",
            TooBig { .. } => "progress-error-too-big",
            EmptyFile => "progress-error-empty-file",
            TooDeep { .. } => "progress-error-too-deep",
            NotJson { .. } => "progress-error-not-json",
            NotAnObject { .. } => "progress-error-not-an-object",
            NoFormat => "progress-error-no-format",
            WrongFormat { .. } => "progress-error-format",
            WrongVersion { .. } => "progress-error-version",
            UnknownField {
                exercise: Some(_), ..
            } => "progress-error-exercise-unknown-field",
            UnknownField { .. } => "progress-error-unknown-field",
            MissingField {
                exercise: Some(_), ..
            } => "progress-error-exercise-missing-field",
            MissingField { .. } => "progress-error-missing-field",
            WrongType {
                exercise: Some(_), ..
            } => "progress-error-exercise-wrong-type",
            WrongType { .. } => "progress-error-wrong-type",
            ExerciseNotAnObject { .. } => "progress-error-exercise-not-an-object",
            TooManyExercises { .. } => "progress-error-too-many-exercises",
            BadId { .. } => "progress-error-bad-id",
            DuplicateId { .. } => "progress-error-duplicate-id",
            TooManyAttempts { .. } => "progress-error-attempts",
            Inconsistent { .. } => "progress-error-inconsistent",
            NameTooLong => "progress-error-name-too-long",
            BuildTooLong => "progress-error-build-too-long",
        }
    }

    /// The message's arguments (name, value).
    pub fn args(&self) -> Vec<(&'static str, String)> {
        use ProgressError::*;
        let at = |exercise: &Option<usize>| exercise.map(|n| ("exercise", n.to_string()));
        match self {
            NotText { detail } => vec![("detail", detail.clone())],
            Decode(error) => vec![("detail", error.to_string())],
            TooBig { bytes } => vec![
                ("size", size_text(*bytes)),
                ("bytes", group_u64(*bytes)),
                ("limit", size_text(MAX_FILE_BYTES)),
            ],
            EmptyFile | NoFormat => vec![],
            TooDeep { line, column } => vec![
                ("line", line.to_string()),
                ("column", column.to_string()),
                ("max", MAX_DEPTH.to_string()),
            ],
            NotJson { line, column } => {
                vec![("line", line.to_string()), ("column", column.to_string())]
            }
            NotAnObject { kind } => vec![("kind", (*kind).to_owned())],
            WrongFormat { found } => vec![("found", quote(found))],
            WrongVersion { found } => vec![
                ("found", found.to_string()),
                ("version", VERSION.to_string()),
            ],
            UnknownField { exercise, field } => {
                let mut args = vec![("field", quote(field))];
                args.extend(at(exercise));
                args
            }
            MissingField { exercise, field } => {
                let mut args = vec![("field", (*field).to_owned())];
                args.extend(at(exercise));
                args
            }
            WrongType {
                exercise,
                field,
                expected,
            } => {
                let mut args = vec![
                    ("field", (*field).to_owned()),
                    ("expected", expected.word().to_owned()),
                ];
                args.extend(at(exercise));
                args
            }
            ExerciseNotAnObject { exercise } | TooManyAttempts { exercise } => {
                vec![("exercise", exercise.to_string())]
            }
            TooManyExercises { count } => vec![
                ("count", count.to_string()),
                ("max", MAX_EXERCISES.to_string()),
            ],
            BadId { exercise, id } => {
                vec![("exercise", exercise.to_string()), ("id", quote(id))]
            }
            DuplicateId { id } | Inconsistent { id } => vec![("id", quote(id))],
            NameTooLong => vec![("max", MAX_NAME_CHARS.to_string())],
            BuildTooLong => vec![("max", MAX_BUILD_CHARS.to_string())],
        }
    }
}

fn quote(text: &str) -> String {
    quoted(text, MAX_QUOTED_CHARS)
}

/// A learner name as kept: trimmed, `None` when empty.
fn learner_name(name: &str) -> Result<Option<String>, ProgressError> {
    let name = name.trim();
    if name.chars().count() > MAX_NAME_CHARS {
        return Err(ProgressError::NameTooLong);
    }
    Ok((!name.is_empty()).then(|| name.to_owned()))
}

/// Whether `id` is kebab-case within [`MAX_ID_CHARS`].
fn is_exercise_id(id: &str) -> bool {
    id.len() <= MAX_ID_CHARS
        && id.split('-').all(|word| {
            !word.is_empty()
                && word
                    .chars()
                    .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit())
        })
}

/// Reads a progress file, exported or stored (see the module docs for the checks, in order).
pub fn from_json(text: &str) -> Result<LearnerProgress, ProgressError> {
    let bytes = text.len() as u64;
    if bytes > MAX_FILE_BYTES {
        return Err(ProgressError::TooBig { bytes });
    }
    let body = text.strip_prefix('\u{feff}').unwrap_or(text);
    if body.trim().is_empty() {
        return Err(ProgressError::EmptyFile);
    }
    if let Some((line, column)) = too_deep_at(body, MAX_DEPTH) {
        return Err(ProgressError::TooDeep { line, column });
    }
    let value: Value = serde_json::from_str(body).map_err(|e| ProgressError::NotJson {
        line: e.line(),
        column: e.column(),
    })?;
    let Value::Object(file) = &value else {
        return Err(ProgressError::NotAnObject {
            kind: kind_of(&value),
        });
    };
    match file.get("format") {
        None => return Err(ProgressError::NoFormat),
        Some(Value::String(f)) if f == FORMAT => {}
        Some(Value::String(f)) => return Err(ProgressError::WrongFormat { found: f.clone() }),
        Some(_) => return Err(wrong_type(None, "format", Expected::Text)),
    }
    match file.get("version") {
        None => return Err(missing(None, "version")),
        Some(Value::Number(n)) => match n.as_u64() {
            Some(v) if v == u64::from(VERSION) => {}
            Some(v) => return Err(ProgressError::WrongVersion { found: v }),
            None => return Err(wrong_type(None, "version", Expected::WholeNumber)),
        },
        Some(_) => return Err(wrong_type(None, "version", Expected::WholeNumber)),
    }
    known_fields(file, &FILE_FIELDS, None)?;
    let learner = match text_field(file, "learner", None)? {
        Some(name) => learner_name(&name)?,
        None => None,
    };
    let build = text_field(file, "build", None)?.ok_or(missing(None, "build"))?;
    if build.chars().count() > MAX_BUILD_CHARS {
        return Err(ProgressError::BuildTooLong);
    }
    let entries = match file.get("exercises") {
        None => return Err(missing(None, "exercises")),
        Some(Value::Array(entries)) => entries,
        Some(_) => return Err(wrong_type(None, "exercises", Expected::List)),
    };
    if entries.len() > MAX_EXERCISES {
        return Err(ProgressError::TooManyExercises {
            count: entries.len(),
        });
    }
    let mut exercises = BTreeMap::new();
    for (i, entry) in entries.iter().enumerate() {
        let (id, progress) = read_exercise(entry, i + 1)?;
        if exercises.contains_key(&id) {
            return Err(ProgressError::DuplicateId { id });
        }
        exercises.insert(id, progress);
    }
    Ok(LearnerProgress {
        learner,
        build,
        exercises,
    })
}

/// Exercise `n` of the file.
fn read_exercise(value: &Value, n: usize) -> Result<(String, ExerciseProgress), ProgressError> {
    let Value::Object(entry) = value else {
        return Err(ProgressError::ExerciseNotAnObject { exercise: n });
    };
    let at = Some(n);
    known_fields(entry, &EXERCISE_FIELDS, at)?;
    let id = text_field(entry, "id", at)?.ok_or(missing(at, "id"))?;
    if !is_exercise_id(&id) {
        return Err(ProgressError::BadId { exercise: n, id });
    }
    let attempts = match entry.get("attempts") {
        None => return Err(missing(at, "attempts")),
        Some(Value::Number(k)) => match k.as_u64() {
            Some(k) => u32::try_from(k)
                .ok()
                .filter(|k| *k <= MAX_ATTEMPTS)
                .ok_or(ProgressError::TooManyAttempts { exercise: n })?,
            None => return Err(wrong_type(at, "attempts", Expected::WholeNumber)),
        },
        Some(_) => return Err(wrong_type(at, "attempts", Expected::WholeNumber)),
    };
    let progress = ExerciseProgress {
        attempts,
        first_try_right: bool_field(entry, "firstTryRight", at)?,
        done: bool_field(entry, "done", at)?,
    };
    if !progress.is_consistent() {
        return Err(ProgressError::Inconsistent { id });
    }
    Ok((id, progress))
}

fn missing(exercise: Option<usize>, field: &'static str) -> ProgressError {
    ProgressError::MissingField { exercise, field }
}

fn wrong_type(exercise: Option<usize>, field: &'static str, expected: Expected) -> ProgressError {
    ProgressError::WrongType {
        exercise,
        field,
        expected,
    }
}

fn known_fields(
    object: &Map<String, Value>,
    known: &[&str],
    exercise: Option<usize>,
) -> Result<(), ProgressError> {
    match unknown_field(object, known) {
        Some(field) => Err(ProgressError::UnknownField {
            exercise,
            field: field.clone(),
        }),
        None => Ok(()),
    }
}

fn text_field(
    object: &Map<String, Value>,
    field: &'static str,
    exercise: Option<usize>,
) -> Result<Option<String>, ProgressError> {
    match object.get(field) {
        None => Ok(None),
        Some(Value::String(s)) => Ok(Some(s.clone())),
        Some(_) => Err(wrong_type(exercise, field, Expected::Text)),
    }
}

fn bool_field(
    object: &Map<String, Value>,
    field: &'static str,
    exercise: Option<usize>,
) -> Result<bool, ProgressError> {
    match object.get(field) {
        None => Err(missing(exercise, field)),
        Some(Value::Bool(b)) => Ok(*b),
        Some(_) => Err(wrong_type(exercise, field, Expected::TrueFalse)),
    }
}

#[cfg(test)]
mod tests;
