//! What can stop an episode from going into the dataset.

use std::fmt;

/// Why an episode, or the dataset, could not be written.
#[non_exhaustive]
#[derive(Debug, Clone, PartialEq)]
pub enum DatasetError {
    /// The episode has no step, so no frame.
    EmptyEpisode,
    /// No episode was added (LeRobot reads no empty dataset).
    NoEpisodes,
    /// Replayed from its start state, the episode does not give its recorded step `step`
    /// (0: its config or start state, or a commands/records length mismatch).
    NotReplayed { step: u64 },
    /// The parquet writer refused a file (its message).
    Parquet { file: String, detail: String },
    /// The zip writer refused a file (its message).
    Zip { detail: String },
}

impl fmt::Display for DatasetError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            DatasetError::EmptyEpisode => write!(f, "the episode has no step"),
            DatasetError::NoEpisodes => write!(f, "no labelled episode to put in the dataset"),
            DatasetError::NotReplayed { step: 0 } => {
                write!(
                    f,
                    "the episode's start state is not its config's, or its rows are uneven"
                )
            }
            DatasetError::NotReplayed { step } => write!(
                f,
                "step {step} is not what the episode's commands give when replayed"
            ),
            DatasetError::Parquet { file, detail } => write!(f, "{file}: {detail}"),
            DatasetError::Zip { detail } => write!(f, "zip: {detail}"),
        }
    }
}

impl std::error::Error for DatasetError {}
