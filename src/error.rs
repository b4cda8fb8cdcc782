//! The one error type of the kernels: what went wrong, and with which parameter.
//!
//! `Display` gives the English one-liner the CLI prints; [`RecipeError::message_id`] and
//! [`RecipeError::message_args`] give the Fluent message (`locales/*/errors.ftl`) the UI shows.

use std::fmt;

use crate::pyfmt::{human, py_float};

/// Everything a kernel, the argument parser or the CSV reader can reject. Serializable, so a
/// run in a Web Worker hands the page the error itself (the kit's worker runs), which the
/// page then shows exactly as an error of a run of its own.
#[non_exhaustive]
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
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
    /// `also` lists the other arguments of a cross-field limit (rows = span ÷ step: the step
    /// is `param`, the span's arguments are `also`); `square` marks a square grid, whose
    /// message speaks of `√count × √count` cells against `√limit × √limit`.
    TooLarge {
        param: String,
        count: u64,
        limit: u64,
        also: Vec<String>,
        square: bool,
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
    /// An input file that is not UTF-8 text: the first byte that is not valid UTF-8, counted
    /// from 0 at the file's start (a byte-order mark included). The CLI and the pages decode
    /// input files the same way ([`crate::recipes::decode_input`]).
    InputNotUtf8 { name: String, offset: u64 },
    /// An input file that starts with a UTF-16 byte-order mark (`FF FE` or `FE FF`).
    InputUtf16 { name: String },
    /// An input file holding a NUL byte (a binary file): its line (from 1) and its byte in
    /// that line (from 1).
    InputBinary {
        name: String,
        line: u64,
        column: u64,
    },
    /// A CSV header with more columns than the limit.
    CsvTooManyColumns { count: u64, limit: u64 },
    /// A point (rrt-2d's `start` or `goal`) inside obstacle box `index` (1-based, edges
    /// included).
    PointInObstacle {
        param: String,
        x: f64,
        y: f64,
        index: usize,
    },
    /// A box `x0,y0,x1,y1` (1-based `index` among the given ones) with `x0 > x1` or `y0 > y1`.
    BoxInverted {
        param: String,
        index: usize,
        corners: [f64; 4],
    },
    /// A repeatable flag given more often than allowed.
    TooManyValues {
        param: String,
        count: usize,
        limit: usize,
    },
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
            OutOfRange { min, .. } if min.is_infinite() => "err-too-big",
            OutOfRange { max, .. } if max.is_infinite() => "err-too-small",
            OutOfRange { .. } => "err-out-of-range",
            TooLarge { square: true, .. } => "err-grid-too-large",
            TooLarge { also, .. } if !also.is_empty() => "err-too-many-rows",
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
            InputNotUtf8 { .. } => "err-input-not-utf8",
            InputUtf16 { .. } => "err-input-utf16",
            InputBinary { .. } => "err-input-binary",
            CsvTooManyColumns { .. } => "err-csv-too-many-columns",
            PointInObstacle { .. } => "err-point-in-obstacle",
            BoxInverted { .. } => "err-box-inverted",
            TooManyValues { .. } => "err-too-many-values",
        }
    }

    /// The Fluent arguments of [`Self::message_id`], as strings (numbers already formatted as
    /// a person writes them, see [`crate::pyfmt::human`]). Errors about an argument carry
    /// `label`: here the argument's name; the UI replaces it with the field's localized label
    /// ([`Self::message_args_labelled`]).
    pub fn message_args(&self) -> Vec<(&'static str, String)> {
        self.message_args_labelled(&|name| name.to_string())
    }

    /// [`Self::message_args`] with `label` given by `label(argument name)`.
    pub fn message_args_labelled(
        &self,
        label: &dyn Fn(&str) -> String,
    ) -> Vec<(&'static str, String)> {
        use RecipeError::*;
        let n = |v: &f64| human(*v);
        let c = |v: &u64| human(*v as f64);
        let l = |p: &str| ("label", label(p));
        match self {
            UnknownRecipe { id } => vec![("id", id.clone())],
            UnknownFlag { flag } | MissingFlagValue { flag } => vec![("flag", flag.clone())],
            TooManyArgs { max, got } => vec![("max", max.to_string()), ("got", got.to_string())],
            NotANumber { param, value } | NotAnInteger { param, value } => {
                vec![l(param), ("value", value.clone())]
            }
            NotFinite { param } => vec![l(param)],
            NotPositive { param, value } => vec![l(param), ("value", n(value))],
            OutOfRange {
                param,
                value,
                min,
                max,
            } => {
                let mut args = vec![l(param), ("value", n(value))];
                if min.is_finite() {
                    args.push(("min", n(min)));
                }
                if max.is_finite() {
                    args.push(("max", n(max)));
                }
                args
            }
            TooLarge {
                param,
                count,
                limit,
                square: true,
                ..
            } => vec![
                l(param),
                ("side", side_text(*count)),
                ("limit", side_text(*limit)),
            ],
            TooLarge {
                param,
                count,
                limit,
                ..
            } => vec![l(param), ("count", c(count)), ("limit", c(limit))],
            WrongCount {
                param,
                expected,
                got,
            } => vec![
                l(param),
                ("expected", expected.to_string()),
                ("got", got.to_string()),
            ],
            BadChoice {
                param,
                value,
                choices,
            } => vec![
                l(param),
                ("value", value.clone()),
                ("choices", choices.clone()),
            ],
            InputTooLarge { bytes, limit } => vec![("bytes", c(bytes)), ("limit", c(limit))],
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
            InputNotUtf8 { name, offset } => vec![("name", name.clone()), ("offset", c(offset))],
            InputUtf16 { name } => vec![("name", name.clone())],
            InputBinary { name, line, column } => vec![
                ("name", name.clone()),
                ("line", c(line)),
                ("column", c(column)),
            ],
            CsvTooManyColumns { count, limit } => vec![("count", c(count)), ("limit", c(limit))],
            PointInObstacle { param, x, y, index } => vec![
                l(param),
                ("x", n(x)),
                ("y", n(y)),
                ("index", index.to_string()),
            ],
            BoxInverted {
                param,
                index,
                corners,
            } => vec![
                l(param),
                ("index", index.to_string()),
                ("box", box_text(corners)),
            ],
            TooManyValues {
                param,
                count,
                limit,
            } => vec![
                l(param),
                ("count", count.to_string()),
                ("limit", limit.to_string()),
            ],
        }
    }

    /// The parameter this error is about, if any (the UI puts the message beside that field):
    /// the first of [`Self::params`].
    pub fn param(&self) -> Option<&str> {
        self.params().into_iter().next()
    }

    /// Every argument this error involves, the main one (the one to change) first: one for a
    /// single-field limit, all of them for a cross-field limit (mark every field involved).
    pub fn params(&self) -> Vec<&str> {
        use RecipeError::*;
        match self {
            NotANumber { param, .. }
            | NotAnInteger { param, .. }
            | NotFinite { param }
            | NotPositive { param, .. }
            | OutOfRange { param, .. }
            | WrongCount { param, .. }
            | BadChoice { param, .. }
            | PointInObstacle { param, .. }
            | BoxInverted { param, .. }
            | TooManyValues { param, .. } => vec![param.as_str()],
            TooLarge { param, also, .. } => std::iter::once(param.as_str())
                .chain(also.iter().map(String::as_str))
                .collect(),
            _ => Vec::new(),
        }
    }
}

/// A box's corners as they are typed: `0.35,0.25,0.65,0.75`.
fn box_text(corners: &[f64; 4]) -> String {
    corners
        .iter()
        .map(|v| human(*v))
        .collect::<Vec<_>>()
        .join(",")
}

/// The side of a square grid of `cells` cells, as a person writes it (`u64::MAX` stands for
/// "too many to count").
fn side_text(cells: u64) -> String {
    if cells == u64::MAX {
        return "∞".to_string();
    }
    let side = (cells as f64).sqrt().round();
    human(side)
}

impl RecipeError {
    /// The English line of an input file that is not UTF-8 text.
    fn fmt_not_text(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use RecipeError::*;
        let c = |v: u64| human(v as f64);
        match self {
            InputNotUtf8 { name, offset } => write!(
                f,
                "'{name}' is not UTF-8 text: byte {} (counted from 0) is not valid UTF-8; save it as UTF-8",
                c(*offset)
            ),
            InputUtf16 { name } => write!(
                f,
                "'{name}' is UTF-16 text (it starts with a UTF-16 byte-order mark); save it as UTF-8"
            ),
            InputBinary { name, line, column } => write!(
                f,
                "'{name}' holds a NUL byte (line {}, byte {} of the line): a binary file, not CSV text",
                c(*line),
                c(*column)
            ),
            _ => Ok(()),
        }
    }
}

impl fmt::Display for RecipeError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use RecipeError::*;
        let n = human;
        let c = |v: u64| human(v as f64);
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
            } => {
                let value = n(*value);
                match (min.is_finite(), max.is_finite()) {
                    (true, false) => {
                        write!(f, "{param}: must be at least {} (it is {value})", n(*min))
                    }
                    (false, true) => {
                        write!(f, "{param}: must be at most {} (it is {value})", n(*max))
                    }
                    _ => write!(
                        f,
                        "{param}: must be between {} and {} (it is {value})",
                        n(*min),
                        n(*max)
                    ),
                }
            }
            TooLarge {
                param,
                count,
                limit,
                also,
                square,
            } => {
                let names = std::iter::once(param.as_str())
                    .chain(also.iter().map(String::as_str))
                    .collect::<Vec<_>>()
                    .join(", ");
                if *square {
                    let side = side_text(*count);
                    let max = side_text(*limit);
                    write!(
                        f,
                        "{names}: the grid would be {side} × {side} cells; the limit is {max} × {max}"
                    )
                } else {
                    let count = if *count == u64::MAX {
                        "too many".to_string()
                    } else {
                        c(*count)
                    };
                    write!(
                        f,
                        "{names}: would need {count} rows/cells/iterations; the limit is {}",
                        c(*limit)
                    )
                }
            }
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
                write!(
                    f,
                    "input is {} bytes; the limit is {} bytes",
                    c(*bytes),
                    c(*limit)
                )
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
            InputNotUtf8 { .. } | InputUtf16 { .. } | InputBinary { .. } => self.fmt_not_text(f),
            CsvTooManyColumns { count, limit } => write!(
                f,
                "CSV header has {} columns; the limit is {}",
                c(*count),
                c(*limit)
            ),
            PointInObstacle { param, x, y, index } => write!(
                f,
                "{param}: ({}, {}) lies inside obstacle {index} (edges included); move it out of the box",
                n(*x),
                n(*y)
            ),
            BoxInverted {
                param,
                index,
                corners,
            } => write!(
                f,
                "{param} {index} ({}): needs x0 <= x1 and y0 <= y1 (x0,y0,x1,y1)",
                box_text(corners)
            ),
            TooManyValues {
                param,
                count,
                limit,
            } => write!(f, "{param}: given {count} times; at most {limit}"),
        }
    }
}

impl std::error::Error for RecipeError {}

/// A run that finished and wrote its CSV, but whose result is probably not what was meant
/// (the page shows it beside the result, the CLI on stderr; the CSV stays the recipe's).
#[non_exhaustive]
#[derive(Debug, Clone, PartialEq)]
pub enum RecipeWarning {
    /// A loop whose output grows without bound (finite, but far beyond the setpoint).
    Diverged { peak: f64, final_value: f64 },
    /// A loop whose output overflowed: not finite from step `step` (0-based row) on.
    NotFinite { step: u64 },
    /// The RRT did not reach the goal within its iteration budget.
    GoalNotReached { iterations: u64 },
    /// The RRT goal lies inside the obstacle: unreachable whatever the budget.
    GoalInObstacle { x: f64, y: f64 },
    /// The total energy of a damped pendulum grew (by `percent` %): the step is too large.
    EnergyGrows { percent: f64 },
    /// Too few point pairs for the fit error to mean anything.
    FewPoints { n: u64 },
}

impl RecipeWarning {
    /// The Fluent message id (in `locales/*/errors.ftl`).
    pub fn message_id(&self) -> &'static str {
        use RecipeWarning::*;
        match self {
            Diverged { .. } => "warn-diverged",
            NotFinite { .. } => "warn-not-finite",
            GoalNotReached { .. } => "warn-goal-not-reached",
            GoalInObstacle { .. } => "warn-goal-in-obstacle",
            EnergyGrows { .. } => "warn-energy-grows",
            FewPoints { .. } => "warn-few-points",
        }
    }

    /// The Fluent arguments of [`Self::message_id`], numbers as a person writes them.
    pub fn message_args(&self) -> Vec<(&'static str, String)> {
        use RecipeWarning::*;
        let g = |v: f64| significant(v);
        match self {
            Diverged { peak, final_value } => vec![("peak", g(*peak)), ("final", g(*final_value))],
            NotFinite { step } => vec![("step", human(*step as f64))],
            GoalNotReached { iterations } => vec![("iterations", human(*iterations as f64))],
            GoalInObstacle { x, y } => vec![("x", human(*x)), ("y", human(*y))],
            EnergyGrows { percent } => vec![("percent", significant(*percent))],
            FewPoints { n } => vec![("n", n.to_string())],
        }
    }
}

/// A measured value for a message: 4 significant digits, grouped, no exponent below 1e21.
fn significant(x: f64) -> String {
    if !x.is_finite() {
        return py_float(x);
    }
    let a = x.abs();
    if a >= 1e4 {
        return human(x.round());
    }
    if a == 0.0 {
        return "0".to_string();
    }
    let decimals = (3 - a.log10().floor() as i32).clamp(0, 12) as usize;
    let text = format!("{x:.decimals$}");
    let text = if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        text
    };
    text
}

impl fmt::Display for RecipeWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use RecipeWarning::*;
        match self {
            Diverged { peak, final_value } => write!(
                f,
                "warning: the loop is unstable: the output grows without bound (largest size {}, final value {})",
                significant(*peak),
                significant(*final_value)
            ),
            NotFinite { step } => write!(
                f,
                "warning: the loop blew up: the output is not finite from step {} on",
                human(*step as f64)
            ),
            GoalNotReached { iterations } => write!(
                f,
                "warning: the goal was not reached within {} iterations (the path file is empty)",
                human(*iterations as f64)
            ),
            GoalInObstacle { x, y } => write!(
                f,
                "warning: the goal ({}, {}) is inside the obstacle and can never be reached",
                human(*x),
                human(*y)
            ),
            EnergyGrows { percent } => write!(
                f,
                "warning: the total energy grew by {} % although damping never adds energy (time step too large?)",
                significant(*percent)
            ),
            FewPoints { n } => write!(
                f,
                "warning: only {n} point pairs: the fit is exact for any noise"
            ),
        }
    }
}
