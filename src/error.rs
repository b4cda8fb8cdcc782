//! The one error type of the kernels: what went wrong, and with which parameter.
//!
//! `Display` gives the English one-liner the CLI prints; [`RecipeError::message_id`] and
//! [`RecipeError::message_args`] give the Fluent message (`locales/*/errors.ftl`) the UI shows.

use std::fmt;

/// Everything a kernel, the argument parser or the CSV reader can reject.
#[non_exhaustive]
#[derive(Debug, Clone, PartialEq)]
pub enum RecipeError {
    /// No recipe has this id.
    UnknownRecipe { id: String },
    /// A `--flag` the recipe does not take.
    UnknownFlag { flag: String },
    /// A `--flag` given without its value.
    MissingFlagValue { flag: String },
    /// More positional arguments than the recipe takes.
    TooManyArgs { max: usize, got: usize },
    /// A value that is not a number.
    NotANumber { param: String, value: String },
    /// A value that must be a whole number.
    NotAnInteger { param: String, value: String },
    /// NaN or infinite.
    NotFinite { param: String },
    /// Zero or negative where a positive value is required (a step, a duration).
    NotPositive { param: String, value: f64 },
    /// Outside the allowed closed range.
    OutOfRange {
        param: String,
        value: f64,
        min: f64,
        max: f64,
    },
    /// The parameter would make `count` rows (or cells, iterations) — more than the tab allows.
    TooLarge {
        param: String,
        count: u64,
        limit: u64,
    },
    /// A list parameter with the wrong number of items (e.g. DH joint angles).
    WrongCount {
        param: String,
        expected: usize,
        got: usize,
    },
    /// A value not among the allowed choices (e.g. `--integrator`).
    BadChoice {
        param: String,
        value: String,
        choices: String,
    },
    /// Input text larger than the limit, in bytes.
    InputTooLarge { bytes: u64, limit: u64 },
    /// A CSV without a required column.
    CsvMissingColumn { column: String },
    /// A CSV with no joint columns besides time.
    CsvNoJointColumns,
    /// A CSV with fewer data rows than needed.
    CsvTooFewRows { rows: usize, min: usize },
    /// A CSV row whose cell count differs from the header's. Rows count from 1 = header.
    CsvRagged {
        row: usize,
        expected: usize,
        got: usize,
    },
    /// A cell that is not a finite number.
    CsvBadCell {
        row: usize,
        column: String,
        value: String,
    },
    /// Time not strictly increasing at this row.
    CsvTimeNotIncreasing { row: usize },
    /// A quoted field that never closes.
    CsvUnterminatedQuote { row: usize },
    /// A path argument naming an input file that was not attached (opened) with the run.
    InputMissing { name: String },
}

impl RecipeError {
    /// The Fluent message id for this error (in `locales/*/errors.ftl`).
    pub fn message_id(&self) -> &'static str {
        use RecipeError::*;
        match self {
            UnknownRecipe { .. } => "err-unknown-recipe",
            UnknownFlag { .. } => "err-unknown-flag",
            MissingFlagValue { .. } => "err-missing-flag-value",
            TooManyArgs { .. } => "err-too-many-args",
            NotANumber { .. } => "err-not-a-number",
            NotAnInteger { .. } => "err-not-an-integer",
            NotFinite { .. } => "err-not-finite",
            NotPositive { .. } => "err-not-positive",
            OutOfRange { .. } => "err-out-of-range",
            TooLarge { .. } => "err-too-large",
            WrongCount { .. } => "err-wrong-count",
            BadChoice { .. } => "err-bad-choice",
            InputTooLarge { .. } => "err-input-too-large",
            CsvMissingColumn { .. } => "err-csv-missing-column",
            CsvNoJointColumns => "err-csv-no-joint-columns",
            CsvTooFewRows { .. } => "err-csv-too-few-rows",
            CsvRagged { .. } => "err-csv-ragged",
            CsvBadCell { .. } => "err-csv-bad-cell",
            CsvTimeNotIncreasing { .. } => "err-csv-time-not-increasing",
            CsvUnterminatedQuote { .. } => "err-csv-unterminated-quote",
            InputMissing { .. } => "err-input-missing",
        }
    }

    /// The Fluent arguments of [`Self::message_id`], as strings (numbers already formatted).
    pub fn message_args(&self) -> Vec<(&'static str, String)> {
        use RecipeError::*;
        let n = |v: &f64| crate::pyfmt::py_float(*v);
        match self {
            UnknownRecipe { id } => vec![("id", id.clone())],
            UnknownFlag { flag } | MissingFlagValue { flag } => vec![("flag", flag.clone())],
            TooManyArgs { max, got } => vec![("max", max.to_string()), ("got", got.to_string())],
            NotANumber { param, value } | NotAnInteger { param, value } => {
                vec![("param", param.clone()), ("value", value.clone())]
            }
            NotFinite { param } => vec![("param", param.clone())],
            NotPositive { param, value } => vec![("param", param.clone()), ("value", n(value))],
            OutOfRange {
                param,
                value,
                min,
                max,
            } => vec![
                ("param", param.clone()),
                ("value", n(value)),
                ("min", n(min)),
                ("max", n(max)),
            ],
            TooLarge {
                param,
                count,
                limit,
            } => vec![
                ("param", param.clone()),
                ("count", count.to_string()),
                ("limit", limit.to_string()),
            ],
            WrongCount {
                param,
                expected,
                got,
            } => vec![
                ("param", param.clone()),
                ("expected", expected.to_string()),
                ("got", got.to_string()),
            ],
            BadChoice {
                param,
                value,
                choices,
            } => vec![
                ("param", param.clone()),
                ("value", value.clone()),
                ("choices", choices.clone()),
            ],
            InputTooLarge { bytes, limit } => {
                vec![("bytes", bytes.to_string()), ("limit", limit.to_string())]
            }
            CsvMissingColumn { column } => vec![("column", column.clone())],
            CsvNoJointColumns => vec![],
            CsvTooFewRows { rows, min } => {
                vec![("rows", rows.to_string()), ("min", min.to_string())]
            }
            CsvRagged { row, expected, got } => vec![
                ("row", row.to_string()),
                ("expected", expected.to_string()),
                ("got", got.to_string()),
            ],
            CsvBadCell { row, column, value } => vec![
                ("row", row.to_string()),
                ("column", column.clone()),
                ("value", value.clone()),
            ],
            CsvTimeNotIncreasing { row } | CsvUnterminatedQuote { row } => {
                vec![("row", row.to_string())]
            }
            InputMissing { name } => vec![("name", name.clone())],
        }
    }

    /// The parameter this error is about, if any (the UI puts the message beside that field).
    pub fn param(&self) -> Option<&str> {
        use RecipeError::*;
        match self {
            NotANumber { param, .. }
            | NotAnInteger { param, .. }
            | NotFinite { param }
            | NotPositive { param, .. }
            | OutOfRange { param, .. }
            | TooLarge { param, .. }
            | WrongCount { param, .. }
            | BadChoice { param, .. } => Some(param),
            _ => None,
        }
    }
}

impl fmt::Display for RecipeError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use RecipeError::*;
        let n = crate::pyfmt::py_float;
        match self {
            UnknownRecipe { id } => write!(f, "unknown recipe '{id}' (try bsv --help)"),
            UnknownFlag { flag } => write!(f, "unknown option '{flag}'"),
            MissingFlagValue { flag } => write!(f, "option '{flag}' needs a value"),
            TooManyArgs { max, got } => {
                write!(f, "too many arguments: takes at most {max}, got {got}")
            }
            NotANumber { param, value } => write!(f, "{param}: '{value}' is not a number"),
            NotAnInteger { param, value } => {
                write!(f, "{param}: '{value}' is not a whole number")
            }
            NotFinite { param } => {
                write!(f, "{param}: must be a finite number (not NaN or infinity)")
            }
            NotPositive { param, value } => {
                write!(f, "{param}: must be greater than zero (got {})", n(*value))
            }
            OutOfRange {
                param,
                value,
                min,
                max,
            } => write!(
                f,
                "{param}: {} is out of range [{}, {}]",
                n(*value),
                n(*min),
                n(*max)
            ),
            TooLarge {
                param,
                count,
                limit,
            } => write!(
                f,
                "{param}: would need {count} rows/cells/iterations; the limit is {limit}"
            ),
            WrongCount {
                param,
                expected,
                got,
            } => {
                write!(f, "{param}: need {expected} values, got {got}")
            }
            BadChoice {
                param,
                value,
                choices,
            } => {
                write!(f, "{param}: '{value}' is not one of {choices}")
            }
            InputTooLarge { bytes, limit } => {
                write!(f, "input is {bytes} bytes; the limit is {limit} bytes")
            }
            CsvMissingColumn { column } => write!(f, "CSV must include a '{column}' column"),
            CsvNoJointColumns => write!(f, "CSV has no joint columns besides t_s"),
            CsvTooFewRows { rows, min } => {
                write!(f, "CSV has {rows} data rows; need at least {min}")
            }
            CsvRagged { row, expected, got } => {
                write!(f, "CSV row {row}: {got} cells, header has {expected}")
            }
            CsvBadCell { row, column, value } => {
                write!(
                    f,
                    "CSV row {row}, column {column}: '{value}' is not a number"
                )
            }
            CsvTimeNotIncreasing { row } => {
                write!(f, "CSV row {row}: t_s must be strictly increasing")
            }
            CsvUnterminatedQuote { row } => {
                write!(f, "CSV row {row}: a quoted field is never closed")
            }
            InputMissing { name } => {
                write!(f, "input file '{name}' not found (open it first)")
            }
        }
    }
}

impl std::error::Error for RecipeError {}
