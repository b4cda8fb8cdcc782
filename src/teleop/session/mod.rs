//! The practice session of the Robot Pilot page (`#/teleop`): the Academy's five modules
//! (preflight → basic control → record ten → failure review → repeatability), the recorded
//! episodes with the pilot's labels, and the session's files: `teleop_episodes.csv` (one row
//! per episode), `teleop_episode_<n>.csv` (the kernel's episode CSV) and
//! `teleop_session_evidence.json`. Plain Rust, no web-sys, no clock (the page passes the
//! RFC 3339 times in).
//!
//! - `practice`: the [`Session`], its modules, preflight and labelled [`EpisodeEntry`]s, its
//!   figures ([`Summary`]) and the repeatability comparison;
//! - `stored`: the stored form (localStorage) and the sliced [`SessionLoader`];
//! - `table`: `teleop_episodes.csv`, written and read back;
//! - `evidence`: the evidence JSON, its SHA-256 artifacts and [`check_evidence`];
//! - `files`: the session's files, and a session opened again from them.

mod evidence;
mod files;
mod kind;
mod practice;
mod stored;
mod table;

pub use evidence::{
    check_evidence, is_iso8601, sha256_hex, Artifact, EvidenceProblem, ExtraArtifact, Sha256,
    DATASET_TYPE, EMBODIMENT, EPISODE_TYPE, EVIDENCE_KEYS, EVIDENCE_NAME, RUNTIME, TABLE_TYPE,
};
pub use files::SessionError;
pub use kind::{control_summary, each_event, run_steps, PracticeEpisode, Replayable};
pub use practice::{
    category_from_id, clean_pilot_id, compare, label_from_id, label_id, ComparisonRow,
    EpisodeEntry, InputDevice, Module, Preflight, Session, Summary, CATEGORIES, PILOT_ID_MAX,
    RECORD_TARGET,
};
pub use stored::{
    run_length, PlanarLoading, SessionLoader, StoredEntry, StoredEpisode, StoredSession,
    STORED_VERSION,
};
pub use table::{
    csv_text, episode_file_name, parse_episodes_table, BadCell, TableRow, EPISODES_HEADER,
    EPISODES_NAME,
};

#[cfg(test)]
mod tests;
