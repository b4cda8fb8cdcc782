//! The one error type of the teleop kernel: a configuration field out of range or an episode
//! file that cannot be read, each naming the field, or the row and column.

#![warn(missing_docs)]

use std::fmt;

use crate::pyfmt::human;

/// The first row of an episode CSV, the row whose absence is [`TeleopError::NotAnEpisode`].
pub const EPISODE_MARKER: &str = "# bsv teleop episode,1";

/// What [`crate::teleop::SceneConfig::validate`] or [`crate::teleop::parse_episode_csv`]
/// rejects. `field` is the [`crate::teleop::SceneConfig`] field name (`latency_steps`,
/// `pos_sensitivity`, `targets` …), which is also the key of the episode CSV's header row.
// The fields are what each variant's doc names.
#[allow(missing_docs)]
#[non_exhaustive]
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub enum TeleopError {
    /// NaN or infinite.
    NotFinite { field: String },
    /// Outside the closed range `[min, max]`.
    OutOfRange {
        field: String,
        value: f64,
        min: f64,
        max: f64,
    },
    /// `q_min[joint] > q_max[joint]` (joint 1-based).
    LimitsInverted { joint: usize },
    /// The start pose puts a link (1-3) into the table or an obstacle.
    StartInCollision { link: u8 },
    /// A reach task without targets, or with more than [`crate::teleop::scene::MAX_TARGETS`].
    TargetCount { count: usize, max: usize },
    /// A value not among the allowed choices (task id, IK method id).
    BadChoice {
        field: String,
        value: String,
        choices: String,
    },
    /// An episode file that does not start with the teleop episode marker row.
    NotAnEpisode,
    /// An episode file without this header row (`# key,...`).
    MissingHeader { key: String },
    /// An episode file row (1-based, the first line is row 1) whose cell count differs from
    /// the column header's.
    Ragged {
        row: usize,
        expected: usize,
        got: usize,
    },
    /// A cell that cannot be read: `column` is the column (or header key) name.
    BadCell {
        row: usize,
        column: String,
        value: String,
    },
    /// Larger than the kernel accepts (bytes).
    TooLarge { bytes: u64, limit: u64 },
}

impl TeleopError {
    /// The config field (or CSV column/header key) this error is about, if any: the page puts
    /// its message beside that field.
    pub fn field(&self) -> Option<&str> {
        match self {
            TeleopError::NotFinite { field }
            | TeleopError::OutOfRange { field, .. }
            | TeleopError::BadChoice { field, .. } => Some(field),
            TeleopError::LimitsInverted { .. } => Some("q_min"),
            TeleopError::StartInCollision { .. } => Some("start_q"),
            TeleopError::TargetCount { .. } => Some("targets"),
            TeleopError::BadCell { column, .. } => Some(column),
            TeleopError::MissingHeader { key } => Some(key),
            _ => None,
        }
    }

    /// The row of an episode file this error is about (1-based), if any.
    pub fn row(&self) -> Option<usize> {
        match self {
            TeleopError::Ragged { row, .. } | TeleopError::BadCell { row, .. } => Some(*row),
            _ => None,
        }
    }
}

impl fmt::Display for TeleopError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            TeleopError::NotFinite { field } => {
                write!(f, "{field}: must be a finite number (not NaN or infinity)")
            }
            TeleopError::OutOfRange {
                field,
                value,
                min,
                max,
            } => write!(
                f,
                "{field}: must be between {} and {} (it is {})",
                human(*min),
                human(*max),
                human(*value)
            ),
            TeleopError::LimitsInverted { joint } => {
                write!(
                    f,
                    "q_min: joint {joint}'s lower limit is above its upper limit"
                )
            }
            TeleopError::StartInCollision { link } => write!(
                f,
                "start_q: link {link} starts inside the table or an obstacle"
            ),
            TeleopError::TargetCount { count, max } => {
                write!(
                    f,
                    "targets: a reach task needs 1 to {max} targets (got {count})"
                )
            }
            TeleopError::BadChoice {
                field,
                value,
                choices,
            } => write!(f, "{field}: '{value}' is not one of {choices}"),
            TeleopError::NotAnEpisode => write!(
                f,
                "not a teleop episode file (the first row must be '{}')",
                EPISODE_MARKER
            ),
            TeleopError::MissingHeader { key } => {
                write!(f, "the episode file has no '# {key},...' header row")
            }
            TeleopError::Ragged { row, expected, got } => {
                write!(
                    f,
                    "row {row}: {got} cells, the column header has {expected}"
                )
            }
            TeleopError::BadCell { row, column, value } => {
                write!(f, "row {row}, column {column}: '{value}' cannot be read")
            }
            TeleopError::TooLarge { bytes, limit } => write!(
                f,
                "the episode file is {} bytes; the limit is {} bytes",
                human(*bytes as f64),
                human(*limit as f64)
            ),
        }
    }
}

impl std::error::Error for TeleopError {}
