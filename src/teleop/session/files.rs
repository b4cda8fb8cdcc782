//! A session's files, `(name, text)`: the evidence, the episodes table and each episode's
//! time series; and a session opened again from them ([`Session::from_files`]), a bad file
//! giving a [`SessionError`] that names the file and what is wrong in it.

use serde_json::Value;

use super::evidence::{check_evidence, sha256_hex, EvidenceProblem, EVIDENCE_NAME};
use super::kind::PracticeEpisode;
use super::practice::{InputDevice, Module, Preflight, Session};
use super::table::{parse_episodes_table, TableRow, EPISODES_NAME};

/// What is wrong with a saved session's files.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum SessionError {
    /// A file the session needs was not among those opened.
    MissingFile { name: String },
    /// Not JSON (where the parser stopped).
    NotJson {
        file: String,
        line: usize,
        column: usize,
    },
    /// The evidence breaks a rule of teleop-session-evidence v0.1.
    Evidence { problem: EvidenceProblem },
    /// A CSV's bytes are not those the evidence lists (edited after export).
    Sha256Mismatch { name: String },
    /// A CSV the evidence does not list.
    NotListed { name: String },
    /// `teleop_episodes.csv`: a bad cell (row 1 is the header).
    Table { row: usize, column: String },
    /// An episode's time series does not parse (the kernel's message).
    Episode { file: String, detail: String },
    /// An episode's recorded states are not what its commands give.
    Replay { file: String },
}

impl std::fmt::Display for SessionError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            SessionError::MissingFile { name } => write!(f, "{name}: missing"),
            SessionError::NotJson { file, line, column } => {
                write!(f, "{file}: not JSON (line {line}, column {column})")
            }
            SessionError::Evidence { problem } => write!(f, "{EVIDENCE_NAME}: {problem}"),
            SessionError::Sha256Mismatch { name } => {
                write!(f, "{name}: its SHA-256 is not the one the evidence lists")
            }
            SessionError::NotListed { name } => {
                write!(f, "{name}: not listed in the evidence's dataArtifacts")
            }
            SessionError::Table { row, column } => {
                write!(f, "{EPISODES_NAME}: row {row}, column {column}")
            }
            SessionError::Episode { file, detail } => write!(f, "{file}: {detail}"),
            SessionError::Replay { file } => {
                write!(
                    f,
                    "{file}: the commands do not reproduce the recorded states"
                )
            }
        }
    }
}

impl std::error::Error for SessionError {}

impl<E: PracticeEpisode> Session<E> {
    /// Every file of the session, `(name, text)`: the evidence, the episodes table and each
    /// episode's time series.
    pub fn files(&self, ended_at: &str) -> Vec<(String, String)> {
        let mut out = vec![
            (EVIDENCE_NAME.to_string(), self.evidence(ended_at)),
            (E::episodes_name(), self.episodes_csv()),
        ];
        for e in &self.episodes {
            out.push((E::episode_file_name(e.number), e.csv()));
        }
        out
    }

    /// A session from its saved files (the evidence, the episodes table and every episode's
    /// time series; other files are ignored). Every rule of the evidence is checked, every
    /// CSV's SHA-256 must be the one the evidence lists, and every episode is replayed.
    pub fn from_files(files: &[(String, String)]) -> Result<Session<E>, SessionError> {
        let opened = open_checked(files, &E::episodes_name(), &E::episode_file_name)?;
        let mut session = Session::new(&opened.pilot_id, opened.device, &opened.started_at);
        session.module = Module::FailureReview;
        session.preflight = opened.preflight;
        session.ended_at = opened.ended_at;
        for (row, (name, text)) in opened.rows.into_iter().zip(opened.episodes) {
            let episode = E::parse_csv(text).map_err(|detail| SessionError::Episode {
                file: name.clone(),
                detail,
            })?;
            if !episode.replays() {
                return Err(SessionError::Replay { file: name });
            }
            let n = session.record(episode, row.interrupted);
            if let Some(entry) = session.episodes.get_mut(n - 1) {
                entry.label = row.label;
                entry.category = row.category;
                entry.note = row.note;
            }
        }
        Ok(session)
    }
}

/// What a session's files say once checked, whatever the arm (one copy of this code): the
/// session's fields from the evidence, the episodes table's rows and each row's episode file
/// (name and text), its SHA-256 the one the evidence lists.
struct Opened<'a> {
    pilot_id: String,
    device: InputDevice,
    started_at: String,
    ended_at: Option<String>,
    preflight: Preflight,
    rows: Vec<TableRow>,
    episodes: Vec<(String, &'a str)>,
}

/// Checks the evidence, the table `table_name` and the presence and SHA-256 of every episode
/// file (named by `episode_name`).
fn open_checked<'a>(
    files: &'a [(String, String)],
    table_name: &str,
    episode_name: &dyn Fn(usize) -> String,
) -> Result<Opened<'a>, SessionError> {
    let get = |name: &str| -> Result<&'a str, SessionError> {
        files
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, t)| t.as_str())
            .ok_or_else(|| SessionError::MissingFile {
                name: name.to_string(),
            })
    };
    let evidence_text = get(EVIDENCE_NAME)?;
    let evidence: Value =
        serde_json::from_str(evidence_text).map_err(|e| SessionError::NotJson {
            file: EVIDENCE_NAME.to_string(),
            line: e.line(),
            column: e.column(),
        })?;
    check_evidence(&evidence).map_err(|problem| SessionError::Evidence { problem })?;
    let listed = |name: &str| -> Option<String> {
        evidence["dataArtifacts"].as_array().and_then(|a| {
            a.iter()
                .find(|x| x["uriOrRef"].as_str() == Some(name))
                .and_then(|x| x["sha256"].as_str())
                .map(str::to_string)
        })
    };
    let check_sha = |name: &str, text: &str| -> Result<(), SessionError> {
        match listed(name) {
            Some(sha) if sha == sha256_hex(text.as_bytes()) => Ok(()),
            Some(_) => Err(SessionError::Sha256Mismatch {
                name: name.to_string(),
            }),
            None => Err(SessionError::NotListed {
                name: name.to_string(),
            }),
        }
    };
    let table = get(table_name)?;
    check_sha(table_name, table)?;
    let device = evidence["inputDevice"]
        .as_str()
        .and_then(InputDevice::from_id)
        .ok_or(SessionError::Evidence {
            problem: EvidenceProblem::Value {
                field: "inputDevice".into(),
            },
        })?;
    let rows = parse_episodes_table(table).map_err(|cell| SessionError::Table {
        row: cell.row,
        column: cell.column,
    })?;
    let mut episodes = Vec::with_capacity(rows.len());
    for row in &rows {
        let name = episode_name(row.number);
        let text = get(&name)?;
        check_sha(&name, text)?;
        episodes.push((name, text));
    }
    Ok(Opened {
        pilot_id: evidence["pilotId"].as_str().unwrap_or("").to_string(),
        device,
        started_at: evidence["startedAt"].as_str().unwrap_or("").to_string(),
        ended_at: evidence["endedAt"].as_str().map(str::to_string),
        preflight: Preflight {
            moved: evidence["metrics"]["preflightDeviceMoved"]
                .as_bool()
                .unwrap_or(false),
            reset_verified: evidence["metrics"]["preflightResetVerified"].as_bool(),
        },
        rows,
        episodes,
    })
}
