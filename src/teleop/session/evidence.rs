//! `teleop_session_evidence.json` in the Academy's teleop-session-evidence v0.1 format, and
//! [`check_evidence`], its rules as a reader checks them.
//!
//! - `episodes.attempted` counts every recorded episode; `successful` those labelled SUCCESS;
//!   `failed` the rest (FAILURE, PARTIAL, interrupted, unlabelled): a session's evidence never
//!   hides an attempt. `recoveryEpisodes` counts SUCCESS episodes in which a failure event
//!   (grasp miss, drop, collision) happened before the success: the pilot recovered.
//! - `safetyEvents` lists every collision of a recorded episode as one line of text (the
//!   schema's items are strings): `collision: episode 3, step 120, t 1.2 s, link forearm`.
//! - `dataArtifacts` lists `teleop_episodes.csv` and every `teleop_episode_<n>.csv`: `type`
//!   ([`TABLE_TYPE`], [`EPISODE_TYPE`]), `uriOrRef` (the file's name), the SHA-256 of its
//!   exact bytes ([`sha256_hex`]), and `mediaType` and `bytes`, which the schema allows.
//! - `startedAt` and `endedAt` are RFC 3339 date-times (the schema's `format: date-time`).

use serde_json::{json, Map, Value};
use sha2::Digest;

use super::kind::PracticeEpisode;
use super::practice::Session;
use crate::teleop::sim::Event;

/// The evidence file's name.
pub const EVIDENCE_NAME: &str = "teleop_session_evidence.json";

/// `runtime` of the evidence.
pub const RUNTIME: &str = "bsv-playground";

/// `embodiment` of the planar arm's evidence: our simulated arm, not an SO-101 (the SO-101's
/// is [`crate::so101::EMBODIMENT`]).
pub const EMBODIMENT: &str = "bsv-planar-3r-gripper-sim";

/// `type` of the per-episode summary table among the `dataArtifacts`.
pub const TABLE_TYPE: &str = "episode-table";

/// `type` of an episode's time series among the `dataArtifacts`.
pub const EPISODE_TYPE: &str = "episode-timeseries";

/// `type` of a dataset written from the labelled episodes among the `dataArtifacts` (the
/// SO-101's LeRobot dataset v3.0, `so101_lerobot_v3.zip`).
pub const DATASET_TYPE: &str = "lerobot-dataset";

/// One file of the evidence's `dataArtifacts`: its name, size and SHA-256.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Artifact {
    /// The file's name.
    pub path: String,
    /// Its size, bytes.
    pub bytes: u64,
    /// The SHA-256 of its bytes, lowercase hex.
    pub sha256: String,
}

impl Artifact {
    /// The artifact of the file `path` holding `text`.
    pub fn of(path: &str, text: &str) -> Artifact {
        Artifact::of_bytes(path, text.as_bytes())
    }

    /// The artifact of the file `path` holding `bytes`.
    pub fn of_bytes(path: &str, bytes: &[u8]) -> Artifact {
        Artifact {
            path: path.to_string(),
            bytes: bytes.len() as u64,
            sha256: sha256_hex(bytes),
        }
    }
}

/// A file listed among the `dataArtifacts` after the episodes' (a dataset written from them):
/// its `type`, `mediaType` and artifact.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ExtraArtifact {
    /// `type`, e.g. [`DATASET_TYPE`].
    pub kind: &'static str,
    /// `mediaType`, e.g. `application/zip`.
    pub media_type: &'static str,
    /// The file.
    pub artifact: Artifact,
}

impl<E: PracticeEpisode> Session<E> {
    /// `teleop_session_evidence.json` (pretty-printed, keys in the schema's order), with
    /// `ended_at` as the end time when the session has none yet.
    pub fn evidence(&self, ended_at: &str) -> String {
        self.evidence_with(ended_at, &self.episode_artifacts())
    }

    /// The evidence given the artifacts of the episodes' CSVs (one per episode, in order),
    /// hashed beforehand (a page hashes long episodes in slices): the same text as
    /// [`Session::evidence`] when they are the episodes' [`Artifact::of`].
    pub fn evidence_with(&self, ended_at: &str, episode_artifacts: &[Artifact]) -> String {
        self.evidence_with_extra(ended_at, episode_artifacts, &[])
    }

    /// The evidence with `extra` listed after the episodes among the `dataArtifacts` (a
    /// dataset written from them, its SHA-256 that of the bytes downloaded).
    pub fn evidence_with_extra(
        &self,
        ended_at: &str,
        episode_artifacts: &[Artifact],
        extra: &[ExtraArtifact],
    ) -> String {
        let value = self.evidence_value_with(ended_at, episode_artifacts, extra);
        let mut text = serde_json::to_string_pretty(&value).unwrap_or_default();
        text.push('\n');
        text
    }

    /// The evidence as a JSON value.
    pub fn evidence_value(&self, ended_at: &str) -> Value {
        self.evidence_value_with(ended_at, &self.episode_artifacts(), &[])
    }

    /// The artifacts of the episodes' time series, in order.
    pub fn episode_artifacts(&self) -> Vec<Artifact> {
        self.episodes
            .iter()
            .map(|e| Artifact::of(&E::episode_file_name(e.number), &e.csv()))
            .collect()
    }

    /// The evidence as a JSON value, given the episodes' artifacts (see
    /// [`Session::evidence_with`]).
    fn evidence_value_with(
        &self,
        ended_at: &str,
        episode_artifacts: &[Artifact],
        extra: &[ExtraArtifact],
    ) -> Value {
        let s = self.summary();
        let episodes_csv = self.episodes_csv();
        let table = Artifact::of(&E::episodes_name(), &episodes_csv);
        let csv = "text/csv";
        let artifacts: Vec<Value> = std::iter::once((TABLE_TYPE, csv, &table))
            .chain(episode_artifacts.iter().map(|a| (EPISODE_TYPE, csv, a)))
            .chain(extra.iter().map(|x| (x.kind, x.media_type, &x.artifact)))
            .map(|(kind, media_type, a)| {
                json!({
                    "type": kind,
                    "uriOrRef": a.path,
                    "sha256": a.sha256,
                    "mediaType": media_type,
                    "bytes": a.bytes,
                })
            })
            .collect();
        let mut safety = Vec::new();
        for e in &self.episodes {
            e.episode.for_each_event(&mut |step, t_s, ev| {
                if let Event::Collision { link } = ev {
                    safety.push(Value::String(format!(
                        "{}: episode {}, step {step}, t {t_s:.2} s, link {link}",
                        ev.id(),
                        e.number,
                    )));
                }
            });
        }
        let mut metrics = Map::new();
        for (category, n) in &s.by_category {
            metrics.insert(format!("failures.{}", category.id()), json!(n));
        }
        let mut put = |k: &str, v: Value| {
            metrics.insert(k.to_string(), v);
        };
        put("successRate", num(s.success_rate));
        put("partial", json!(s.partial));
        put("interrupted", json!(s.interrupted));
        put("unlabelled", json!(s.unlabelled));
        put("meanDurationS", num(s.mean_duration_s));
        put("meanPathM", num(s.mean_path_m));
        put("meanEfficiency", num(s.mean_efficiency));
        put("collisions", json!(s.collisions));
        put("jointLimitStops", json!(s.joint_limit_stops));
        put("singularityStops", json!(s.singularity_stops));
        put("minManipulability", num(s.min_manipulability));
        put("meanThroughputBitsPerS", num(s.mean_throughput));
        put("preflightDeviceMoved", json!(self.preflight.moved));
        put(
            "preflightResetVerified",
            self.preflight
                .reset_verified
                .map_or(Value::Null, Value::Bool),
        );
        if let Some(first) = self.episodes.first() {
            let (method, lambda, latency_steps, noise_sigma) = first.episode.control_summary();
            put("ikMethod", json!(method));
            put("lambda", num(Some(lambda)));
            put("latencyMs", json!(u64::from(latency_steps) * 10));
            put("noiseSigma", num(Some(noise_sigma)));
        }
        json!({
            "schemaVersion": "0.1",
            "evidenceId": self.evidence_id(),
            "pilotId": self.pilot_id,
            "taskId": self.task_id().unwrap_or("none"),
            "environment": "SIMULATION",
            "runtime": RUNTIME,
            "runtimeVersion": env!("CARGO_PKG_VERSION"),
            "embodiment": E::EMBODIMENT,
            "inputDevice": self.input_device.id(),
            "startedAt": self.started_at,
            "endedAt": self.ended_at.as_deref().unwrap_or(ended_at),
            "episodes": {
                "attempted": s.attempted,
                "successful": s.successful,
                "failed": s.attempted - s.successful,
                "recoveryEpisodes": s.recovery,
            },
            "safetyEvents": safety,
            "dataArtifacts": artifacts,
            "metrics": Value::Object(metrics),
            "review": { "status": "UNREVIEWED" },
        })
    }

    /// `teleop_<pilot>_<start time digits>`, matching `^teleop_[a-z0-9_-]+$`.
    pub fn evidence_id(&self) -> String {
        let pilot: String = self
            .pilot_id
            .chars()
            .map(|c| c.to_ascii_lowercase())
            .map(|c| {
                if c.is_ascii_alphanumeric() || c == '-' || c == '_' {
                    c
                } else {
                    '-'
                }
            })
            .collect();
        let stamp: String = self
            .started_at
            .chars()
            .filter(|c| c.is_ascii_digit())
            .take(14)
            .collect();
        let pilot = if pilot.is_empty() {
            "pilot".to_string()
        } else {
            pilot
        };
        if stamp.is_empty() {
            format!("teleop_{pilot}")
        } else {
            format!("teleop_{pilot}_{stamp}")
        }
    }
}

fn num(x: Option<f64>) -> Value {
    match x {
        Some(v) if v.is_finite() => json!(v),
        _ => Value::Null,
    }
}

/// A rule of teleop-session-evidence v0.1 that a document breaks.
#[derive(Debug, Clone, PartialEq)]
pub enum EvidenceProblem {
    /// The top level is not an object.
    NotObject,
    /// A required key is missing (`episodes.failed`).
    Missing { field: String },
    /// A top-level key the schema does not have.
    Unexpected { field: String },
    /// The value has the wrong type.
    Type { field: String },
    /// The value is not allowed (a pattern, a constant, a date, a count).
    Value { field: String },
}

impl std::fmt::Display for EvidenceProblem {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            EvidenceProblem::NotObject => write!(f, "not a JSON object"),
            EvidenceProblem::Missing { field } => write!(f, "{field} is missing"),
            EvidenceProblem::Unexpected { field } => write!(f, "{field} is not allowed"),
            EvidenceProblem::Type { field } => write!(f, "{field} has the wrong type"),
            EvidenceProblem::Value { field } => write!(f, "{field} has a value not allowed"),
        }
    }
}

impl EvidenceProblem {
    /// The field named.
    pub fn field(&self) -> &str {
        match self {
            EvidenceProblem::NotObject => "",
            EvidenceProblem::Missing { field }
            | EvidenceProblem::Unexpected { field }
            | EvidenceProblem::Type { field }
            | EvidenceProblem::Value { field } => field,
        }
    }
}

/// The top-level keys of teleop-session-evidence v0.1, in order.
pub const EVIDENCE_KEYS: [&str; 16] = [
    "schemaVersion",
    "evidenceId",
    "pilotId",
    "taskId",
    "environment",
    "runtime",
    "runtimeVersion",
    "embodiment",
    "inputDevice",
    "startedAt",
    "endedAt",
    "episodes",
    "safetyEvents",
    "dataArtifacts",
    "metrics",
    "review",
];

/// Checks `doc` against the rules of teleop-session-evidence v0.1; the first rule broken,
/// in key order.
pub fn check_evidence(doc: &Value) -> Result<(), EvidenceProblem> {
    let Some(top) = doc.as_object() else {
        return Err(EvidenceProblem::NotObject);
    };
    for key in top.keys() {
        if !EVIDENCE_KEYS.contains(&key.as_str()) {
            return Err(EvidenceProblem::Unexpected { field: key.clone() });
        }
    }
    let field = |name: &str| -> Result<&Value, EvidenceProblem> {
        top.get(name).ok_or_else(|| EvidenceProblem::Missing {
            field: name.to_string(),
        })
    };
    let type_err = |name: &str| EvidenceProblem::Type {
        field: name.to_string(),
    };
    let string = |name: &str| field(name)?.as_str().ok_or_else(|| type_err(name));
    let array = |name: &str| field(name)?.as_array().ok_or_else(|| type_err(name));
    let object = |name: &str| field(name)?.as_object().ok_or_else(|| type_err(name));
    let value_err = |name: &str| EvidenceProblem::Value {
        field: name.to_string(),
    };
    if string("schemaVersion")? != "0.1" {
        return Err(value_err("schemaVersion"));
    }
    let id = string("evidenceId")?;
    let tail = id.strip_prefix("teleop_").unwrap_or("");
    if tail.is_empty()
        || !tail
            .chars()
            .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_' || c == '-')
    {
        return Err(value_err("evidenceId"));
    }
    for name in [
        "pilotId",
        "taskId",
        "runtime",
        "runtimeVersion",
        "embodiment",
        "inputDevice",
    ] {
        if string(name)?.is_empty() {
            return Err(value_err(name));
        }
    }
    if string("environment")? != "SIMULATION" {
        return Err(value_err("environment"));
    }
    for name in ["startedAt", "endedAt"] {
        if !is_iso8601(string(name)?) {
            return Err(value_err(name));
        }
    }
    let episodes = object("episodes")?;
    let mut counts = [0u64; 4];
    for (i, name) in ["attempted", "successful", "failed", "recoveryEpisodes"]
        .iter()
        .enumerate()
    {
        let full = format!("episodes.{name}");
        let v = episodes
            .get(*name)
            .ok_or_else(|| EvidenceProblem::Missing {
                field: full.clone(),
            })?;
        counts[i] = v.as_u64().ok_or_else(|| type_err(&full))?;
    }
    if counts[1] + counts[2] != counts[0] || counts[3] > counts[1] {
        return Err(value_err("episodes"));
    }
    let events = array("safetyEvents")?;
    if let Some(i) = events.iter().position(|e| !e.is_string()) {
        return Err(type_err(&format!("safetyEvents[{i}]")));
    }
    let artifacts = array("dataArtifacts")?;
    for (i, a) in artifacts.iter().enumerate() {
        for key in ["type", "uriOrRef"] {
            if a[key].as_str().is_none_or(str::is_empty) {
                return Err(EvidenceProblem::Missing {
                    field: format!("dataArtifacts[{i}].{key}"),
                });
            }
        }
        let sha_ok = a["sha256"].as_str().is_some_and(|s| {
            s.len() == 64
                && s.chars()
                    .all(|c| c.is_ascii_digit() || ('a'..='f').contains(&c))
        });
        if !sha_ok {
            return Err(value_err(&format!("dataArtifacts[{i}].sha256")));
        }
    }
    let metrics = object("metrics")?;
    for (k, v) in metrics {
        if v.is_array() || v.is_object() {
            return Err(type_err(&format!("metrics.{k}")));
        }
    }
    let review = object("review")?;
    if review.get("status").and_then(Value::as_str) != Some("UNREVIEWED") {
        return Err(value_err("review.status"));
    }
    Ok(())
}

/// Whether `text` is an RFC 3339 date-time (the schema's `format: date-time`) in the ISO 8601
/// shape browsers write, `YYYY-MM-DDTHH:MM:SS[.fff](Z|±HH:MM)`: a date and a time of day that
/// exist, and `T` (or `t`) between them, where RFC 3339 would also let a space or any other
/// character stand.
pub fn is_iso8601(text: &str) -> bool {
    matches!(text.as_bytes().get(10), Some(b'T' | b't'))
        && time::OffsetDateTime::parse(text, &time::format_description::well_known::Rfc3339).is_ok()
}

/// The SHA-256 of `bytes`, lowercase hex.
pub fn sha256_hex(bytes: &[u8]) -> String {
    hex(&sha2::Sha256::digest(bytes))
}

fn hex(digest: &[u8]) -> String {
    digest.iter().map(|b| format!("{b:02x}")).collect()
}

/// A SHA-256 fed in pieces that counts the bytes fed: the hash of the pieces one after the
/// other is the hash of their concatenation, so a page can hash a file while it writes it in
/// slices.
#[derive(Debug, Clone, Default)]
pub struct Sha256 {
    hasher: sha2::Sha256,
    /// Bytes fed so far.
    len: u64,
}

impl Sha256 {
    /// A hasher of nothing yet.
    pub fn new() -> Sha256 {
        Sha256::default()
    }

    /// Bytes fed so far.
    pub fn len(&self) -> u64 {
        self.len
    }

    /// Whether nothing was fed yet.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Feeds `bytes`.
    pub fn update(&mut self, bytes: &[u8]) {
        self.len = self.len.wrapping_add(bytes.len() as u64);
        self.hasher.update(bytes);
    }

    /// The hash of everything fed, lowercase hex.
    pub fn finish_hex(self) -> String {
        hex(&self.hasher.finalize())
    }
}
