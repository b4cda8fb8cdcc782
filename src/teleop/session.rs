//! The practice session of the Robot Pilot page (`#/teleop`): the Academy's five modules
//! (preflight → basic control → record ten → failure review → repeatability), the recorded
//! episodes with the pilot's labels, and the session's files: `teleop_episodes.csv` (one row
//! per episode), `teleop_episode_<n>.csv` (the kernel's [`episode_csv`]) and
//! `teleop_session_evidence.json` in the Academy's teleop-session-evidence v0.1 format. Saved
//! files open again ([`Session::from_files`]): a bad file gives a [`SessionError`] naming the
//! file and what is wrong in it. Plain Rust, no web-sys, no clock (the page passes the
//! ISO 8601 times in).
//!
//! Rules the issue left to us, stated once here:
//! - Failures are never deleted: an episode, once ended, stays in the session; an episode cut
//!   off by a reload or a crash of the tab comes back `interrupted`, proposed as a FAILURE of
//!   category `operator-abort`, for the pilot to confirm.
//! - `episodes.attempted` counts every recorded episode; `successful` those labelled SUCCESS;
//!   `failed` the rest (FAILURE, PARTIAL, interrupted, unlabelled): a session's evidence never
//!   hides an attempt. `recoveryEpisodes` counts SUCCESS episodes in which a failure event
//!   (grasp miss, drop, collision) happened before the success: the pilot recovered.
//! - `safetyEvents` lists every collision of a recorded episode (episode, step, time, link):
//!   on a real arm those are the contacts a reviewer must see.
//! - `dataArtifacts` lists `teleop_episodes.csv` and every `teleop_episode_<n>.csv` with the
//!   SHA-256 of its exact bytes (computed here; [`sha256_hex`]).
//! - Sessions are stored (localStorage) as their episodes' configurations, start states and
//!   command streams, run-length coded ([`StoredEpisode`]); the records are simulated again on
//!   load, bit for bit (the kernel is deterministic), which keeps ten minute-long episodes
//!   well under the browser's storage quota.

use std::rc::Rc;

use serde::{Deserialize, Serialize};
use serde_json::{json, Map, Value};

use crate::pyfmt::push_py_float;
use crate::teleop::{
    episode_csv, metrics, parse_episode_csv, proposed_label, Command, Episode, EpisodeMetrics,
    Event, FailureCategory, Label, SceneConfig, Sim, State, StepRecord,
};

/// The evidence file's name.
pub const EVIDENCE_NAME: &str = "teleop_session_evidence.json";
/// The per-episode summary file's name.
pub const EPISODES_NAME: &str = "teleop_episodes.csv";
/// Episodes the record module asks for.
pub const RECORD_TARGET: usize = 10;
/// `runtime` of the evidence.
pub const RUNTIME: &str = "bsv-playground";
/// `embodiment` of the evidence: our simulated arm, not an SO-101.
pub const EMBODIMENT: &str = "bsv-planar-3r-gripper-sim";
/// Longest pilot id kept.
pub const PILOT_ID_MAX: usize = 64;

/// The name of episode `n`'s time series (n from 1).
pub fn episode_file_name(n: usize) -> String {
    format!("teleop_episode_{n}.csv")
}

/// The Academy's five modules, in order.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum Module {
    Preflight,
    BasicControl,
    RecordTen,
    FailureReview,
    Repeatability,
}

impl Module {
    /// All modules, in order.
    pub const ALL: [Module; 5] = [
        Module::Preflight,
        Module::BasicControl,
        Module::RecordTen,
        Module::FailureReview,
        Module::Repeatability,
    ];

    /// `preflight`, `basic-control`, `record-ten`, `failure-review`, `repeatability`.
    pub fn id(self) -> &'static str {
        match self {
            Module::Preflight => "preflight",
            Module::BasicControl => "basic-control",
            Module::RecordTen => "record-ten",
            Module::FailureReview => "failure-review",
            Module::Repeatability => "repeatability",
        }
    }

    /// The module with id `id`.
    pub fn from_id(id: &str) -> Option<Module> {
        Module::ALL.into_iter().find(|m| m.id() == id)
    }

    /// Position, 0 to 4.
    pub fn index(self) -> usize {
        Module::ALL.iter().position(|m| *m == self).unwrap_or(0)
    }

    /// The module after this one (the last stays).
    pub fn next(self) -> Module {
        Module::ALL[(self.index() + 1).min(Module::ALL.len() - 1)]
    }

    /// Whether the simulation's episodes are recorded in this module.
    pub fn records(self) -> bool {
        self == Module::RecordTen
    }
}

/// The input device the pilot chose in preflight.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum InputDevice {
    Keyboard,
    Gamepad,
    Pointer,
}

impl InputDevice {
    pub const ALL: [InputDevice; 3] = [
        InputDevice::Keyboard,
        InputDevice::Gamepad,
        InputDevice::Pointer,
    ];

    /// `keyboard`, `gamepad`, `pointer` (the evidence's `inputDevice`).
    pub fn id(self) -> &'static str {
        match self {
            InputDevice::Keyboard => "keyboard",
            InputDevice::Gamepad => "gamepad",
            InputDevice::Pointer => "pointer",
        }
    }

    /// The device with id `id`.
    pub fn from_id(id: &str) -> Option<InputDevice> {
        InputDevice::ALL.into_iter().find(|d| d.id() == id)
    }
}

/// `SUCCESS`, `FAILURE`, `PARTIAL` (the page's `data-label` values and the CSV's).
pub fn label_id(label: Label) -> &'static str {
    label.id()
}

/// The label with id `id`.
pub fn label_from_id(id: &str) -> Option<Label> {
    Label::from_id(id)
}

/// The Academy's ten failure categories, in its order.
pub const CATEGORIES: [FailureCategory; 10] = FailureCategory::ALL;

/// The category with id `id` (`grasp-miss`, ...).
pub fn category_from_id(id: &str) -> Option<FailureCategory> {
    FailureCategory::from_id(id)
}

/// An episode as stored: configuration, start state and the run-length coded commands.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StoredEpisode {
    pub config: SceneConfig,
    pub start: State,
    /// `(count, command)`: `count` steps of the same command.
    pub runs: Vec<(u32, Command)>,
}

impl StoredEpisode {
    /// The commands of `episode`, run-length coded.
    pub fn of(episode: &Episode) -> StoredEpisode {
        StoredEpisode {
            config: episode.config.clone(),
            start: episode.start.clone(),
            runs: run_length(&episode.commands),
        }
    }

    /// The command stream.
    pub fn commands(&self) -> Vec<Command> {
        let mut out = Vec::new();
        for (n, c) in &self.runs {
            for _ in 0..*n {
                out.push(*c);
            }
        }
        out
    }
}

/// A stored session simulated again in slices of steps ([`SessionLoader::run`]), so that a
/// page opening ten minute-long episodes (60,000 steps) never blocks its tab for long; the
/// session it gives ([`SessionLoader::finish`]) is [`Session::from_json`]'s, bit for bit.
#[derive(Debug, Clone)]
pub struct SessionLoader {
    /// The session so far (the episodes simulated again, in order).
    session: Session,
    /// Episodes still to simulate, in order (the one in progress last, interrupted).
    pending: std::collections::VecDeque<StoredEntry>,
    /// The episode being simulated: its entry, simulation, commands and records so far.
    current: Option<(StoredEntry, Sim, Vec<Command>, Vec<StepRecord>)>,
    steps_total: usize,
    steps_done: usize,
}

impl SessionLoader {
    /// Parses a stored session (no simulation yet); `None` if the text is not a stored
    /// session of this version.
    pub fn new(text: &str) -> Option<SessionLoader> {
        let stored: StoredSession = serde_json::from_str(text).ok()?;
        if stored.version != STORED_VERSION {
            return None;
        }
        let mut pending: std::collections::VecDeque<StoredEntry> =
            stored.episodes.into_iter().collect();
        if let Some(p) = stored.in_progress {
            pending.push_back(StoredEntry {
                episode: p,
                label: None,
                category: None,
                note: String::new(),
                interrupted: true,
            });
        }
        let steps_total = pending
            .iter()
            .map(|e| {
                e.episode
                    .runs
                    .iter()
                    .map(|(n, _)| *n as usize)
                    .sum::<usize>()
            })
            .sum();
        Some(SessionLoader {
            session: Session {
                pilot_id: stored.pilot_id,
                input_device: stored.input_device,
                module: stored.module,
                preflight: stored.preflight,
                started_at: stored.started_at,
                ended_at: stored.ended_at,
                episodes: Vec::new(),
            },
            pending,
            current: None,
            steps_total,
            steps_done: 0,
        })
    }

    /// Simulates up to `max_steps` more steps. `Some(true)` when every episode is done, `Some(false)` when
    /// there is more, `None` if an episode does not simulate again (refused configuration, or
    /// a start state that is not the configuration's).
    pub fn run(&mut self, max_steps: usize) -> Option<bool> {
        let mut budget = max_steps;
        loop {
            if self.current.is_none() {
                let Some(entry) = self.pending.pop_front() else {
                    return Some(true);
                };
                let sim = Sim::new(entry.episode.config.clone()).ok()?;
                if *sim.start_state() != entry.episode.start {
                    return None;
                }
                let commands = entry.episode.commands();
                let records = Vec::with_capacity(commands.len());
                self.current = Some((entry, sim, commands, records));
            }
            let (_, sim, commands, records) = self.current.as_mut()?;
            let from = records.len();
            let to = commands.len().min(from.saturating_add(budget));
            for c in &commands[from..to] {
                records.push(sim.step(c));
            }
            budget -= to - from;
            self.steps_done += to - from;
            if records.len() < commands.len() {
                return Some(false);
            }
            let (entry, _, commands, records) = self.current.take()?;
            let episode = Episode {
                config: entry.episode.config,
                start: entry.episode.start,
                commands,
                records,
            };
            let n = self.session.record(episode, entry.interrupted);
            let e = self.session.episodes.get_mut(n - 1)?;
            e.label = entry.label.as_deref().and_then(label_from_id);
            e.category = entry.category.as_deref().and_then(category_from_id);
            e.note = entry.note;
            if budget == 0 && !self.pending.is_empty() {
                return Some(false);
            }
        }
    }

    /// The session so far: its pilot, device, module and preflight as stored, and the
    /// episodes simulated again until now.
    pub fn session(&self) -> &Session {
        &self.session
    }

    /// Steps simulated so far and in all.
    pub fn progress(&self) -> (usize, usize) {
        (self.steps_done, self.steps_total)
    }

    /// The session, once [`SessionLoader::run`] said `Some(true)` (`None` before).
    pub fn finish(self) -> Option<Session> {
        (self.current.is_none() && self.pending.is_empty()).then_some(self.session)
    }
}

/// Run-length coding of a command stream.
pub fn run_length(commands: &[Command]) -> Vec<(u32, Command)> {
    let mut runs: Vec<(u32, Command)> = Vec::new();
    for c in commands {
        match runs.last_mut() {
            Some((n, last)) if last == c && *n < u32::MAX => *n += 1,
            _ => runs.push((1, *c)),
        }
    }
    runs
}

/// One recorded episode and what the pilot said about it.
#[derive(Debug, Clone, PartialEq)]
pub struct EpisodeEntry {
    /// 1, 2, ... in recording order.
    pub number: usize,
    /// The episode (shared: a copy of the session, as an export takes, copies no steps).
    pub episode: Rc<Episode>,
    pub metrics: EpisodeMetrics,
    /// `None` until the pilot labels it.
    pub label: Option<Label>,
    pub category: Option<FailureCategory>,
    pub note: String,
    /// Cut off by a reload or a crash of the tab.
    pub interrupted: bool,
}

impl EpisodeEntry {
    /// A just-ended episode, unlabelled.
    pub fn new(number: usize, episode: Episode, interrupted: bool) -> EpisodeEntry {
        let metrics = metrics(&episode);
        EpisodeEntry {
            number,
            episode: Rc::new(episode),
            metrics,
            label: None,
            category: None,
            note: String::new(),
            interrupted,
        }
    }

    /// The label and category the page preselects: the kernel's proposal (its first event),
    /// or FAILURE / operator-abort for an interrupted episode.
    pub fn proposal(&self) -> (Label, Option<FailureCategory>) {
        if self.interrupted {
            return (Label::Failure, Some(FailureCategory::OperatorAbort));
        }
        proposed_label(&self.episode)
    }

    /// Sets the pilot's label (a SUCCESS has no category).
    pub fn set_label(&mut self, label: Label, category: Option<FailureCategory>, note: &str) {
        self.label = Some(label);
        self.category = if label == Label::Success {
            None
        } else {
            category
        };
        self.note = note.to_string();
    }

    /// A SUCCESS with a failure event before it.
    pub fn is_recovery(&self) -> bool {
        self.label == Some(Label::Success)
            && self.episode.records.iter().any(|r| {
                r.events
                    .iter()
                    .any(|e| matches!(e, Event::GraspMiss | Event::Drop | Event::Collision { .. }))
            })
    }

    /// The episode's time series file (the kernel's CSV).
    pub fn csv(&self) -> String {
        episode_csv(&self.episode)
    }
}

/// The preflight module's checks.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct Preflight {
    /// The chosen device moved the arm.
    pub moved: bool,
    /// A reset was asked for and returned the scene to its start state bit for bit
    /// (`Some(false)`: it did not).
    pub reset_verified: Option<bool>,
}

impl Preflight {
    /// Both checks passed.
    pub fn passed(&self) -> bool {
        self.moved && self.reset_verified == Some(true)
    }
}

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
        Artifact {
            path: path.to_string(),
            bytes: text.len() as u64,
            sha256: sha256_hex(text.as_bytes()),
        }
    }
}

/// A practice session.
#[derive(Debug, Clone, PartialEq)]
pub struct Session {
    pub pilot_id: String,
    pub input_device: InputDevice,
    pub module: Module,
    pub preflight: Preflight,
    /// ISO 8601, from the page's clock.
    pub started_at: String,
    pub ended_at: Option<String>,
    pub episodes: Vec<EpisodeEntry>,
}

/// The stored form of a session (localStorage): episodes as [`StoredEpisode`]s.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StoredSession {
    pub version: u32,
    pub pilot_id: String,
    pub input_device: InputDevice,
    pub module: Module,
    pub preflight: Preflight,
    pub started_at: String,
    pub ended_at: Option<String>,
    pub episodes: Vec<StoredEntry>,
    /// The episode being recorded when the page last saved (comes back interrupted).
    pub in_progress: Option<StoredEpisode>,
}

/// A stored episode entry.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StoredEntry {
    pub episode: StoredEpisode,
    pub label: Option<String>,
    pub category: Option<String>,
    pub note: String,
    pub interrupted: bool,
}

/// Version of [`StoredSession`].
pub const STORED_VERSION: u32 = 1;

impl Session {
    /// A new session started at `started_at`.
    pub fn new(pilot_id: &str, input_device: InputDevice, started_at: &str) -> Session {
        Session {
            pilot_id: clean_pilot_id(pilot_id),
            input_device,
            module: Module::Preflight,
            preflight: Preflight::default(),
            started_at: started_at.to_string(),
            ended_at: None,
            episodes: Vec::new(),
        }
    }

    /// The task of the session (its first episode's, else `None`).
    pub fn task_id(&self) -> Option<&'static str> {
        self.episodes.first().map(|e| e.episode.config.task.id())
    }

    /// Adds a finished (or interrupted) episode; returns its number.
    pub fn record(&mut self, episode: Episode, interrupted: bool) -> usize {
        let n = self.episodes.len() + 1;
        self.episodes
            .push(EpisodeEntry::new(n, episode, interrupted));
        n
    }

    /// The first episode the pilot has not labelled yet.
    pub fn unlabelled(&self) -> Option<usize> {
        self.episodes
            .iter()
            .position(|e| e.label.is_none())
            .map(|i| i + 1)
    }

    /// The stored form, with the episode in progress (if any).
    pub fn stored(&self, in_progress: Option<&Episode>) -> StoredSession {
        StoredSession {
            version: STORED_VERSION,
            pilot_id: self.pilot_id.clone(),
            input_device: self.input_device,
            module: self.module,
            preflight: self.preflight,
            started_at: self.started_at.clone(),
            ended_at: self.ended_at.clone(),
            episodes: self
                .episodes
                .iter()
                .map(|e| StoredEntry {
                    episode: StoredEpisode::of(&e.episode),
                    label: e.label.map(|l| label_id(l).to_string()),
                    category: e.category.map(|c| c.id().to_string()),
                    note: e.note.clone(),
                    interrupted: e.interrupted,
                })
                .collect(),
            in_progress: in_progress
                .filter(|e| !e.commands.is_empty())
                .map(StoredEpisode::of),
        }
    }

    /// The stored session as JSON.
    pub fn to_json(&self, in_progress: Option<&Episode>) -> String {
        serde_json::to_string(&self.stored(in_progress)).unwrap_or_default()
    }

    /// A session from its stored JSON; an episode in progress comes back as an interrupted
    /// episode at the end. `None` if the text is not a stored session of this version or an
    /// episode does not simulate again. All at once: [`SessionLoader`] does the same in slices.
    pub fn from_json(text: &str) -> Option<Session> {
        let mut loader = SessionLoader::new(text)?;
        while !loader.run(usize::MAX)? {}
        loader.finish()
    }

    /// `teleop_episodes.csv`: one row per episode.
    pub fn episodes_csv(&self) -> String {
        let mut out = String::from(EPISODES_HEADER);
        out.push('\n');
        for e in &self.episodes {
            let m = &e.metrics;
            let mut cells: Vec<String> = vec![
                e.number.to_string(),
                e.episode.config.task.id().to_string(),
                e.label.map(label_id).unwrap_or("").to_string(),
                e.category.map(|c| c.id()).unwrap_or("").to_string(),
                csv_text(&e.note),
                u8::from(e.interrupted).to_string(),
                outcome_id(m).to_string(),
            ];
            for x in [m.duration_s, m.path_m, m.efficiency] {
                cells.push(float(x));
            }
            cells.push(m.collisions.to_string());
            cells.push(m.joint_limit_stops.to_string());
            cells.push(m.singularity_stops.to_string());
            cells.push(float(m.min_manipulability));
            match &m.fitts {
                Some(f) => {
                    cells.push(float(f.id_bits));
                    cells.push(float(f.throughput_bits_per_s));
                }
                None => {
                    cells.push(String::new());
                    cells.push(String::new());
                }
            }
            match &m.first_failure {
                Some((step, event)) => {
                    cells.push(step.to_string());
                    cells.push(event.id().to_string());
                }
                None => {
                    cells.push(String::new());
                    cells.push(String::new());
                }
            }
            cells.push(e.episode.commands.len().to_string());
            out.push_str(&cells.join(","));
            out.push('\n');
        }
        out
    }

    /// The session's figures (success rate, means, counts by category).
    pub fn summary(&self) -> Summary {
        Summary::of(&self.episodes)
    }

    /// `teleop_session_evidence.json` (pretty-printed, keys in the schema's order), with
    /// `ended_at` as the end time when the session has none yet.
    pub fn evidence(&self, ended_at: &str) -> String {
        let artifacts: Vec<Artifact> = self
            .episodes
            .iter()
            .map(|e| Artifact::of(&episode_file_name(e.number), &e.csv()))
            .collect();
        self.evidence_with(ended_at, &artifacts)
    }

    /// The evidence given the artifacts of the episodes' CSVs (one per episode, in order),
    /// hashed beforehand (a page hashes long episodes in slices): the same text as
    /// [`Session::evidence`] when they are the episodes' [`Artifact::of`].
    pub fn evidence_with(&self, ended_at: &str, episode_artifacts: &[Artifact]) -> String {
        let value = self.evidence_value_with(ended_at, episode_artifacts);
        let mut text = serde_json::to_string_pretty(&value).unwrap_or_default();
        text.push('\n');
        text
    }

    /// The evidence as a JSON value.
    pub fn evidence_value(&self, ended_at: &str) -> Value {
        let artifacts: Vec<Artifact> = self
            .episodes
            .iter()
            .map(|e| Artifact::of(&episode_file_name(e.number), &e.csv()))
            .collect();
        self.evidence_value_with(ended_at, &artifacts)
    }

    /// The evidence as a JSON value, given the episodes' artifacts (see
    /// [`Session::evidence_with`]).
    fn evidence_value_with(&self, ended_at: &str, episode_artifacts: &[Artifact]) -> Value {
        let s = self.summary();
        let episodes_csv = self.episodes_csv();
        let table = Artifact::of(EPISODES_NAME, &episodes_csv);
        let artifacts: Vec<Value> = std::iter::once(&table)
            .chain(episode_artifacts)
            .map(|a| {
                json!({
                    "path": a.path,
                    "mediaType": "text/csv",
                    "bytes": a.bytes,
                    "sha256": a.sha256,
                })
            })
            .collect();
        let mut safety = Vec::new();
        for e in &self.episodes {
            for (step, r) in e.episode.records.iter().enumerate() {
                for ev in &r.events {
                    if let Event::Collision { link } = ev {
                        safety.push(json!({
                            "episode": e.number,
                            "step": step + 1,
                            "tS": r.t_s,
                            "type": ev.id(),
                            "link": link,
                        }));
                    }
                }
            }
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
            let c = &first.episode.config;
            put("ikMethod", json!(c.control.method.id()));
            put("lambda", num(Some(c.control.lambda)));
            put("latencyMs", json!(u64::from(c.latency_steps) * 10));
            put("noiseSigma", num(Some(c.noise_sigma)));
        }
        json!({
            "schemaVersion": "0.1",
            "evidenceId": self.evidence_id(),
            "pilotId": self.pilot_id,
            "taskId": self.task_id().unwrap_or("none"),
            "environment": "SIMULATION",
            "runtime": RUNTIME,
            "runtimeVersion": env!("CARGO_PKG_VERSION"),
            "embodiment": EMBODIMENT,
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

    /// Every file of the session, `(name, text)`: the evidence, the episodes table and each
    /// episode's time series.
    pub fn files(&self, ended_at: &str) -> Vec<(String, String)> {
        let mut out = vec![
            (EVIDENCE_NAME.to_string(), self.evidence(ended_at)),
            (EPISODES_NAME.to_string(), self.episodes_csv()),
        ];
        for e in &self.episodes {
            out.push((episode_file_name(e.number), e.csv()));
        }
        out
    }

    /// A session from its saved files (the evidence, the episodes table and every episode's
    /// time series; other files are ignored). Every rule of the evidence is checked, every
    /// CSV's SHA-256 must be the one the evidence lists, and every episode is replayed.
    pub fn from_files(files: &[(String, String)]) -> Result<Session, SessionError> {
        let get = |name: &str| -> Result<&str, SessionError> {
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
                    .find(|x| x["path"].as_str() == Some(name))
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
        let table = get(EPISODES_NAME)?;
        check_sha(EPISODES_NAME, table)?;
        let device = evidence["inputDevice"]
            .as_str()
            .and_then(InputDevice::from_id)
            .ok_or(SessionError::Evidence {
                problem: EvidenceProblem::Value {
                    field: "inputDevice".into(),
                },
            })?;
        let mut session = Session::new(
            evidence["pilotId"].as_str().unwrap_or(""),
            device,
            evidence["startedAt"].as_str().unwrap_or(""),
        );
        session.module = Module::FailureReview;
        session.preflight = Preflight {
            moved: evidence["metrics"]["preflightDeviceMoved"]
                .as_bool()
                .unwrap_or(false),
            reset_verified: evidence["metrics"]["preflightResetVerified"].as_bool(),
        };
        session.ended_at = evidence["endedAt"].as_str().map(str::to_string);
        let rows = parse_episodes_table(table)?;
        for row in rows {
            let name = episode_file_name(row.number);
            let text = get(&name)?;
            check_sha(&name, text)?;
            let episode = parse_episode_csv(text).map_err(|e| SessionError::Episode {
                file: name.clone(),
                detail: e.to_string(),
            })?;
            if crate::teleop::replay(&episode).is_err() {
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

/// The pilot id as kept: trimmed, at most [`PILOT_ID_MAX`] characters.
pub fn clean_pilot_id(id: &str) -> String {
    id.trim().chars().take(PILOT_ID_MAX).collect()
}

/// The header of `teleop_episodes.csv`.
pub const EPISODES_HEADER: &str = "id,task,label,category,note,interrupted,outcome,duration_s,path_m,efficiency,collisions,joint_limit_stops,singularity_stops,min_manipulability,fitts_id_bits,throughput_bits_per_s,first_failure_step,first_failure_event,steps";

fn outcome_id(m: &EpisodeMetrics) -> &'static str {
    match m.outcome {
        Some(crate::teleop::Outcome::Success) => "success",
        Some(crate::teleop::Outcome::Timeout) => "timeout",
        None => "ended",
    }
}

fn float(x: f64) -> String {
    let mut s = String::new();
    push_py_float(&mut s, x);
    s
}

fn num(x: Option<f64>) -> Value {
    match x {
        Some(v) if v.is_finite() => json!(v),
        _ => Value::Null,
    }
}

/// A CSV cell: quoted (RFC 4180) when it holds a comma, a quote or a line break.
pub fn csv_text(text: &str) -> String {
    if text.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_string()
    }
}

/// The cells of one CSV record starting at `text` (RFC 4180 quotes), and the rest.
fn csv_record(text: &str) -> Option<(Vec<String>, &str)> {
    if text.is_empty() {
        return None;
    }
    let mut cells = Vec::new();
    let mut cell = String::new();
    let mut chars = text.char_indices().peekable();
    let mut quoted = false;
    while let Some((i, c)) = chars.next() {
        if quoted {
            if c == '"' {
                if chars.peek().map(|p| p.1) == Some('"') {
                    cell.push('"');
                    chars.next();
                } else {
                    quoted = false;
                }
            } else {
                cell.push(c);
            }
            continue;
        }
        match c {
            '"' if cell.is_empty() => quoted = true,
            ',' => cells.push(std::mem::take(&mut cell)),
            '\r' => {}
            '\n' => {
                cells.push(cell);
                return Some((cells, &text[i + 1..]));
            }
            _ => cell.push(c),
        }
    }
    cells.push(cell);
    Some((cells, ""))
}

struct TableRow {
    number: usize,
    label: Option<Label>,
    category: Option<FailureCategory>,
    note: String,
    interrupted: bool,
}

fn parse_episodes_table(text: &str) -> Result<Vec<TableRow>, SessionError> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let bad = |row: usize, column: &str| SessionError::Table {
        row,
        column: column.to_string(),
    };
    let Some((header, mut rest)) = csv_record(text) else {
        return Err(bad(1, "id"));
    };
    let want: Vec<&str> = EPISODES_HEADER.split(',').collect();
    for (i, name) in want.iter().enumerate() {
        if header.get(i).map(String::as_str) != Some(*name) {
            return Err(bad(1, name));
        }
    }
    let mut rows = Vec::new();
    let mut row = 1;
    while let Some((cells, next)) = csv_record(rest) {
        rest = next;
        row += 1;
        if cells.len() == 1 && cells[0].is_empty() {
            continue;
        }
        if cells.len() != want.len() {
            return Err(bad(row, "id"));
        }
        let number: usize = cells[0].parse().map_err(|_| bad(row, "id"))?;
        if number != rows.len() + 1 {
            return Err(bad(row, "id"));
        }
        let label = match cells[2].as_str() {
            "" => None,
            id => Some(label_from_id(id).ok_or_else(|| bad(row, "label"))?),
        };
        let category = match cells[3].as_str() {
            "" => None,
            id => Some(category_from_id(id).ok_or_else(|| bad(row, "category"))?),
        };
        let interrupted = match cells[5].as_str() {
            "0" => false,
            "1" => true,
            _ => return Err(bad(row, "interrupted")),
        };
        rows.push(TableRow {
            number,
            label,
            category,
            note: cells[4].clone(),
            interrupted,
        });
    }
    Ok(rows)
}

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

/// Checks `doc` against the rules of teleop-session-evidence v0.1 as the issue lists them;
/// the first rule broken, in key order.
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
    let string = |name: &str| -> Result<&str, EvidenceProblem> {
        field(name)?.as_str().ok_or_else(|| EvidenceProblem::Type {
            field: name.to_string(),
        })
    };
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
    let episodes = field("episodes")?
        .as_object()
        .ok_or_else(|| EvidenceProblem::Type {
            field: "episodes".into(),
        })?;
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
        counts[i] = v.as_u64().ok_or(EvidenceProblem::Type {
            field: full.clone(),
        })?;
    }
    if counts[1] + counts[2] != counts[0] || counts[3] > counts[1] {
        return Err(value_err("episodes"));
    }
    if !field("safetyEvents")?.is_array() {
        return Err(EvidenceProblem::Type {
            field: "safetyEvents".into(),
        });
    }
    let artifacts = field("dataArtifacts")?
        .as_array()
        .ok_or_else(|| EvidenceProblem::Type {
            field: "dataArtifacts".into(),
        })?;
    for (i, a) in artifacts.iter().enumerate() {
        let path_ok = a["path"].as_str().is_some_and(|p| !p.is_empty());
        if !path_ok {
            return Err(EvidenceProblem::Missing {
                field: format!("dataArtifacts[{i}].path"),
            });
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
    let metrics = field("metrics")?
        .as_object()
        .ok_or_else(|| EvidenceProblem::Type {
            field: "metrics".into(),
        })?;
    for (k, v) in metrics {
        if v.is_array() || v.is_object() {
            return Err(EvidenceProblem::Type {
                field: format!("metrics.{k}"),
            });
        }
    }
    let review = field("review")?
        .as_object()
        .ok_or_else(|| EvidenceProblem::Type {
            field: "review".into(),
        })?;
    if review.get("status").and_then(Value::as_str) != Some("UNREVIEWED") {
        return Err(value_err("review.status"));
    }
    Ok(())
}

/// Whether `text` is an ISO 8601 date-time as browsers write it:
/// `YYYY-MM-DDTHH:MM:SS[.fff](Z|±HH:MM)`.
pub fn is_iso8601(text: &str) -> bool {
    let b = text.as_bytes();
    let digits = |r: std::ops::Range<usize>| {
        b.get(r.clone())
            .is_some_and(|s| s.len() == r.len() && s.iter().all(u8::is_ascii_digit))
    };
    if !(digits(0..4)
        && b.get(4) == Some(&b'-')
        && digits(5..7)
        && b.get(7) == Some(&b'-')
        && digits(8..10)
        && b.get(10) == Some(&b'T')
        && digits(11..13)
        && b.get(13) == Some(&b':')
        && digits(14..16)
        && b.get(16) == Some(&b':')
        && digits(17..19))
    {
        return false;
    }
    let mut i = 19;
    if b.get(i) == Some(&b'.') {
        i += 1;
        let start = i;
        while b.get(i).is_some_and(u8::is_ascii_digit) {
            i += 1;
        }
        if i == start {
            return false;
        }
    }
    match &b[i..] {
        b"Z" => true,
        [s, ..] if *s == b'+' || *s == b'-' => {
            let rest = &text[i + 1..];
            rest.len() == 5
                && rest.as_bytes()[2] == b':'
                && rest[..2].bytes().all(|c| c.is_ascii_digit())
                && rest[3..].bytes().all(|c| c.is_ascii_digit())
        }
        _ => false,
    }
}

/// A session's figures, for the evidence and the repeatability comparison.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Summary {
    pub attempted: usize,
    pub successful: usize,
    pub partial: usize,
    pub interrupted: usize,
    pub unlabelled: usize,
    pub recovery: usize,
    /// Successful / attempted (`None` with no episode).
    pub success_rate: Option<f64>,
    /// Means over all episodes.
    pub mean_duration_s: Option<f64>,
    pub mean_path_m: Option<f64>,
    pub mean_efficiency: Option<f64>,
    pub collisions: u64,
    pub joint_limit_stops: u64,
    pub singularity_stops: u64,
    pub min_manipulability: Option<f64>,
    /// Mean Fitts throughput of reach episodes.
    pub mean_throughput: Option<f64>,
    /// Labelled failure categories, every one of the ten, in the Academy's order.
    pub by_category: Vec<(FailureCategory, usize)>,
}

fn mean(values: impl Iterator<Item = f64>) -> Option<f64> {
    let (mut sum, mut n) = (0.0, 0usize);
    for v in values.filter(|v| v.is_finite()) {
        sum += v;
        n += 1;
    }
    (n > 0).then(|| sum / n as f64)
}

impl Summary {
    /// The figures of `episodes`.
    pub fn of(episodes: &[EpisodeEntry]) -> Summary {
        let count = |f: &dyn Fn(&EpisodeEntry) -> bool| episodes.iter().filter(|e| f(e)).count();
        let attempted = episodes.len();
        let successful = count(&|e| e.label == Some(Label::Success));
        Summary {
            attempted,
            successful,
            partial: count(&|e| e.label == Some(Label::Partial)),
            interrupted: count(&|e| e.interrupted),
            unlabelled: count(&|e| e.label.is_none()),
            recovery: count(&|e| e.is_recovery()),
            success_rate: (attempted > 0).then(|| successful as f64 / attempted as f64),
            mean_duration_s: mean(episodes.iter().map(|e| e.metrics.duration_s)),
            mean_path_m: mean(episodes.iter().map(|e| e.metrics.path_m)),
            mean_efficiency: mean(episodes.iter().map(|e| e.metrics.efficiency)),
            collisions: episodes.iter().map(|e| e.metrics.collisions as u64).sum(),
            joint_limit_stops: episodes
                .iter()
                .map(|e| e.metrics.joint_limit_stops as u64)
                .sum(),
            singularity_stops: episodes
                .iter()
                .map(|e| e.metrics.singularity_stops as u64)
                .sum(),
            min_manipulability: episodes
                .iter()
                .map(|e| e.metrics.min_manipulability)
                .filter(|v| v.is_finite())
                .reduce(f64::min),
            mean_throughput: mean(
                episodes
                    .iter()
                    .filter_map(|e| e.metrics.fitts.as_ref())
                    .map(|f| f.throughput_bits_per_s),
            ),
            by_category: CATEGORIES
                .iter()
                .map(|c| (*c, count(&|e| e.category == Some(*c))))
                .collect(),
        }
    }
}

/// One row of the repeatability comparison: what, first session, second session.
#[derive(Debug, Clone, PartialEq)]
pub struct ComparisonRow {
    /// `success-rate`, `mean-time`, `efficiency`, `collisions`, or a category id.
    pub id: String,
    pub first: Option<f64>,
    pub second: Option<f64>,
}

/// The repeatability comparison of two sessions, side by side: success rate, mean time,
/// path efficiency, collisions, then the counts by failure category.
pub fn compare(first: &Summary, second: &Summary) -> Vec<ComparisonRow> {
    let row = |id: &str, a: Option<f64>, b: Option<f64>| ComparisonRow {
        id: id.to_string(),
        first: a,
        second: b,
    };
    let mut rows = vec![
        row(
            "attempted",
            Some(first.attempted as f64),
            Some(second.attempted as f64),
        ),
        row("success-rate", first.success_rate, second.success_rate),
        row("mean-time", first.mean_duration_s, second.mean_duration_s),
        row("efficiency", first.mean_efficiency, second.mean_efficiency),
        row(
            "collisions",
            Some(first.collisions as f64),
            Some(second.collisions as f64),
        ),
    ];
    for ((c, a), (_, b)) in first.by_category.iter().zip(&second.by_category) {
        rows.push(row(c.id(), Some(*a as f64), Some(*b as f64)));
    }
    rows
}

/// The SHA-256 of `bytes`, lowercase hex (FIPS 180-4).
pub fn sha256_hex(bytes: &[u8]) -> String {
    let mut hasher = Sha256::new();
    hasher.update(bytes);
    hasher.finish_hex()
}

/// SHA-256 round constants.
const SHA256_K: [u32; 64] = [
    0x428a2f98, 0x71374491, 0xb5c0fbcf, 0xe9b5dba5, 0x3956c25b, 0x59f111f1, 0x923f82a4, 0xab1c5ed5,
    0xd807aa98, 0x12835b01, 0x243185be, 0x550c7dc3, 0x72be5d74, 0x80deb1fe, 0x9bdc06a7, 0xc19bf174,
    0xe49b69c1, 0xefbe4786, 0x0fc19dc6, 0x240ca1cc, 0x2de92c6f, 0x4a7484aa, 0x5cb0a9dc, 0x76f988da,
    0x983e5152, 0xa831c66d, 0xb00327c8, 0xbf597fc7, 0xc6e00bf3, 0xd5a79147, 0x06ca6351, 0x14292967,
    0x27b70a85, 0x2e1b2138, 0x4d2c6dfc, 0x53380d13, 0x650a7354, 0x766a0abb, 0x81c2c92e, 0x92722c85,
    0xa2bfe8a1, 0xa81a664b, 0xc24b8b70, 0xc76c51a3, 0xd192e819, 0xd6990624, 0xf40e3585, 0x106aa070,
    0x19a4c116, 0x1e376c08, 0x2748774c, 0x34b0bcb5, 0x391c0cb3, 0x4ed8aa4a, 0x5b9cca4f, 0x682e6ff3,
    0x748f82ee, 0x78a5636f, 0x84c87814, 0x8cc70208, 0x90befffa, 0xa4506ceb, 0xbef9a3f7, 0xc67178f2,
];

/// A SHA-256 fed in pieces (FIPS 180-4): the hash of the pieces one after the other is the
/// hash of their concatenation, so a page can hash a file while it writes it in slices.
#[derive(Debug, Clone)]
pub struct Sha256 {
    h: [u32; 8],
    /// Bytes of the block not yet compressed.
    block: [u8; 64],
    filled: usize,
    /// Bytes fed so far.
    len: u64,
}

impl Default for Sha256 {
    fn default() -> Self {
        Sha256::new()
    }
}

impl Sha256 {
    /// A hasher of nothing yet.
    pub fn new() -> Sha256 {
        Sha256 {
            h: [
                0x6a09e667, 0xbb67ae85, 0x3c6ef372, 0xa54ff53a, 0x510e527f, 0x9b05688c, 0x1f83d9ab,
                0x5be0cd19,
            ],
            block: [0; 64],
            filled: 0,
            len: 0,
        }
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
    pub fn update(&mut self, mut bytes: &[u8]) {
        self.len = self.len.wrapping_add(bytes.len() as u64);
        if self.filled > 0 {
            let take = (64 - self.filled).min(bytes.len());
            self.block[self.filled..self.filled + take].copy_from_slice(&bytes[..take]);
            self.filled += take;
            bytes = &bytes[take..];
            if self.filled < 64 {
                return;
            }
            let block = self.block;
            self.compress(&block);
            self.filled = 0;
        }
        let mut blocks = bytes.chunks_exact(64);
        for block in &mut blocks {
            self.compress(block);
        }
        let rest = blocks.remainder();
        self.block[..rest.len()].copy_from_slice(rest);
        self.filled = rest.len();
    }

    /// The hash of everything fed, lowercase hex.
    pub fn finish_hex(mut self) -> String {
        let bit_len = self.len.wrapping_mul(8);
        let mut tail = [0u8; 128];
        tail[..self.filled].copy_from_slice(&self.block[..self.filled]);
        tail[self.filled] = 0x80;
        let total = if self.filled < 56 { 64 } else { 128 };
        tail[total - 8..total].copy_from_slice(&bit_len.to_be_bytes());
        for block in tail[..total].chunks_exact(64) {
            self.compress(block);
        }
        self.h.iter().map(|x| format!("{x:08x}")).collect()
    }

    /// One 64-byte block.
    fn compress(&mut self, block: &[u8]) {
        let mut w = [0u32; 64];
        for (i, word) in block.chunks_exact(4).enumerate() {
            w[i] = u32::from_be_bytes([word[0], word[1], word[2], word[3]]);
        }
        for i in 16..64 {
            let s0 = w[i - 15].rotate_right(7) ^ w[i - 15].rotate_right(18) ^ (w[i - 15] >> 3);
            let s1 = w[i - 2].rotate_right(17) ^ w[i - 2].rotate_right(19) ^ (w[i - 2] >> 10);
            w[i] = w[i - 16]
                .wrapping_add(s0)
                .wrapping_add(w[i - 7])
                .wrapping_add(s1);
        }
        let [mut a, mut b, mut c, mut d, mut e, mut f, mut g, mut hh] = self.h;
        for i in 0..64 {
            let s1 = e.rotate_right(6) ^ e.rotate_right(11) ^ e.rotate_right(25);
            let ch = (e & f) ^ (!e & g);
            let t1 = hh
                .wrapping_add(s1)
                .wrapping_add(ch)
                .wrapping_add(SHA256_K[i])
                .wrapping_add(w[i]);
            let s0 = a.rotate_right(2) ^ a.rotate_right(13) ^ a.rotate_right(22);
            let maj = (a & b) ^ (a & c) ^ (b & c);
            let t2 = s0.wrapping_add(maj);
            hh = g;
            g = f;
            f = e;
            e = d.wrapping_add(t1);
            d = c;
            c = b;
            b = a;
            a = t1.wrapping_add(t2);
        }
        for (x, y) in self.h.iter_mut().zip([a, b, c, d, e, f, g, hh]) {
            *x = x.wrapping_add(y);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const START: &str = "2026-12-02T05:00:00.000Z";
    const END: &str = "2026-12-02T05:30:00.000Z";

    fn push(n: usize, dx: f64, dz: f64, closed: bool) -> Vec<Command> {
        vec![
            Command {
                dx,
                dz,
                dphi: 0.0,
                gripper_closed: closed,
            };
            n
        ]
    }

    fn episode(commands: &[Command]) -> Episode {
        Episode::record(SceneConfig::default(), commands).expect("default config")
    }

    /// A session of three labelled episodes (a success-less move, a grasp miss, a dive into
    /// the table).
    fn session() -> Session {
        let mut s = Session::new("Pilot 7", InputDevice::Keyboard, START);
        s.module = Module::RecordTen;
        s.preflight = Preflight {
            moved: true,
            reset_verified: Some(true),
        };
        let mut moves = push(40, 1.0, 0.0, false);
        moves.extend(push(20, 0.0, 1.0, false));
        s.record(episode(&moves), false);
        s.record(episode(&push(30, 0.0, 0.0, true)), false);
        s.record(episode(&push(150, 0.0, -1.0, false)), false);
        s.episodes[0].set_label(
            Label::Partial,
            Some(FailureCategory::GoalMiss),
            "went, \"almost\"",
        );
        s.episodes[1].set_label(Label::Failure, Some(FailureCategory::GraspMiss), "");
        s.episodes[2].set_label(Label::Failure, Some(FailureCategory::Collision), "");
        s
    }

    #[test]
    fn sha256_of_known_text() {
        assert_eq!(
            sha256_hex(b""),
            "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855"
        );
        assert_eq!(
            sha256_hex(b"abc"),
            "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad"
        );
        assert_eq!(
            sha256_hex(b"abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1"
        );
        let million = vec![b'a'; 1_000_000];
        assert_eq!(
            sha256_hex(&million),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0"
        );
    }

    #[test]
    fn sha256_fed_in_pieces_is_the_hash_of_the_whole() {
        let million = vec![b'a'; 1_000_000];
        let mut h = Sha256::new();
        for piece in million.chunks(7) {
            h.update(piece);
        }
        assert_eq!(h.len(), 1_000_000);
        assert_eq!(
            h.finish_hex(),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0"
        );
        // Every length around the padding's edges (55, 56, 63, 64, 119, 120 …), cut anywhere.
        let bytes: Vec<u8> = (0u32..300).map(|i| (i * 37 % 251) as u8).collect();
        for len in [0, 1, 55, 56, 57, 63, 64, 65, 119, 120, 127, 128, 129, 300] {
            let whole = &bytes[..len];
            let want = sha256_hex(whole);
            for cut in [1, 3, 63, 64, 65, 200] {
                let mut h = Sha256::new();
                h.update(&[]);
                for piece in whole.chunks(cut) {
                    h.update(piece);
                }
                assert_eq!(h.finish_hex(), want, "{len} bytes in pieces of {cut}");
            }
        }
        assert_eq!(
            sha256_hex(&bytes[..56]),
            "928e47b7ec93b2357b1dedf2f5f4fa86151cdf7b05f5d0a73cef7a2de1ee02c0"
        );
    }

    #[test]
    fn evidence_follows_the_schema_field_by_field() {
        let s = session();
        let doc: Value = serde_json::from_str(&s.evidence(END)).expect("json");
        assert_eq!(check_evidence(&doc), Ok(()));
        let keys: Vec<&str> = doc
            .as_object()
            .expect("object")
            .keys()
            .map(String::as_str)
            .collect();
        let mut want = EVIDENCE_KEYS.to_vec();
        want.sort_unstable();
        let mut got = keys.clone();
        got.sort_unstable();
        assert_eq!(got, want, "exactly the schema's top-level keys");
        assert_eq!(doc["schemaVersion"], "0.1");
        assert_eq!(doc["evidenceId"], "teleop_pilot-7_20261202050000");
        assert_eq!(doc["pilotId"], "Pilot 7");
        assert_eq!(doc["taskId"], "pick-place");
        assert_eq!(doc["environment"], "SIMULATION");
        assert_eq!(doc["runtime"], RUNTIME);
        assert_eq!(doc["embodiment"], EMBODIMENT);
        assert_eq!(doc["inputDevice"], "keyboard");
        assert_eq!(doc["startedAt"], START);
        assert_eq!(doc["endedAt"], END);
        assert_eq!(doc["episodes"]["attempted"], 3);
        assert_eq!(doc["episodes"]["successful"], 0);
        assert_eq!(doc["episodes"]["failed"], 3);
        assert_eq!(doc["episodes"]["recoveryEpisodes"], 0);
        assert_eq!(doc["review"]["status"], "UNREVIEWED");
        // Every CSV listed with the SHA-256 of its bytes.
        let artifacts = doc["dataArtifacts"].as_array().expect("array");
        assert_eq!(artifacts.len(), 4);
        for (name, text) in s.files(END).iter().skip(1) {
            let a = artifacts
                .iter()
                .find(|a| a["path"] == name.as_str())
                .expect("listed");
            assert_eq!(a["sha256"], sha256_hex(text.as_bytes()));
            assert_eq!(a["bytes"], text.len());
        }
        // Metrics: flat values only; counts by category.
        let m = doc["metrics"].as_object().expect("metrics");
        assert!(m.values().all(|v| !v.is_array() && !v.is_object()));
        assert_eq!(m["failures.grasp-miss"], 1);
        assert_eq!(m["failures.collision"], 1);
        assert_eq!(m["failures.goal-miss"], 1);
        assert_eq!(m["failures.drop"], 0);
        assert_eq!(m["failures.operator-abort"], 0);
        assert_eq!(m["successRate"], 0.0);
        assert_eq!(m["preflightResetVerified"], true);
        assert_eq!(m["ikMethod"], "dls");
        // The dive into the table is a safety event.
        let safety = doc["safetyEvents"].as_array().expect("array");
        assert!(safety
            .iter()
            .any(|e| e["episode"] == 3 && e["type"] == "collision"));
    }

    #[test]
    fn each_schema_rule_names_its_field() {
        let good: Value = serde_json::from_str(&session().evidence(END)).expect("json");
        let broken = |f: &dyn Fn(&mut Map<String, Value>)| {
            let mut doc = good.clone();
            f(doc.as_object_mut().expect("object"));
            check_evidence(&doc).expect_err("refused")
        };
        let field = |name: &str| name.to_string();
        assert_eq!(
            broken(&|d| {
                d.remove("pilotId");
            }),
            EvidenceProblem::Missing {
                field: field("pilotId")
            }
        );
        assert_eq!(
            broken(&|d| {
                d.insert("extra".into(), json!(1));
            }),
            EvidenceProblem::Unexpected {
                field: field("extra")
            }
        );
        assert_eq!(
            broken(&|d| {
                d.insert("schemaVersion".into(), json!("0.2"));
            }),
            EvidenceProblem::Value {
                field: field("schemaVersion")
            }
        );
        for bad in ["teleop_", "Teleop_x", "teleop_A", "teleop_a b", "x_teleop"] {
            assert_eq!(
                broken(&|d| {
                    d.insert("evidenceId".into(), json!(bad));
                }),
                EvidenceProblem::Value {
                    field: field("evidenceId")
                },
                "{bad}"
            );
        }
        assert_eq!(
            broken(&|d| {
                d.insert("environment".into(), json!("REAL"));
            }),
            EvidenceProblem::Value {
                field: field("environment")
            }
        );
        assert_eq!(
            broken(&|d| {
                d.insert("endedAt".into(), json!("yesterday"));
            }),
            EvidenceProblem::Value {
                field: field("endedAt")
            }
        );
        assert_eq!(
            broken(&|d| {
                d.insert("runtimeVersion".into(), json!(1));
            }),
            EvidenceProblem::Type {
                field: field("runtimeVersion")
            }
        );
        assert_eq!(
            broken(&|d| {
                d["episodes"]["failed"] = json!(0);
            }),
            EvidenceProblem::Value {
                field: field("episodes")
            }
        );
        assert_eq!(
            broken(&|d| {
                d["episodes"]
                    .as_object_mut()
                    .map(|e| e.remove("recoveryEpisodes"));
            }),
            EvidenceProblem::Missing {
                field: field("episodes.recoveryEpisodes")
            }
        );
        assert_eq!(
            broken(&|d| {
                d["dataArtifacts"][0]["sha256"] = json!("abc");
            }),
            EvidenceProblem::Value {
                field: field("dataArtifacts[0].sha256")
            }
        );
        assert_eq!(
            broken(&|d| {
                d["metrics"]["nested"] = json!({"a": 1});
            }),
            EvidenceProblem::Type {
                field: field("metrics.nested")
            }
        );
        assert_eq!(
            broken(&|d| {
                d["review"]["status"] = json!("APPROVED");
            }),
            EvidenceProblem::Value {
                field: field("review.status")
            }
        );
        assert_eq!(
            broken(&|d| {
                d.insert("safetyEvents".into(), json!(3));
            }),
            EvidenceProblem::Type {
                field: field("safetyEvents")
            }
        );
        assert_eq!(check_evidence(&json!([1])), Err(EvidenceProblem::NotObject));
    }

    #[test]
    fn iso_dates() {
        for ok in [START, "2026-12-02T05:00:00Z", "2026-12-02T14:00:00+09:00"] {
            assert!(is_iso8601(ok), "{ok}");
        }
        for bad in [
            "",
            "2026-12-02",
            "2026-12-02 05:00:00Z",
            "2026-12-02T05:00:00",
            "2026-12-02T05:00:00.Z",
            "2026-12-02T05:00:00+0900",
        ] {
            assert!(!is_iso8601(bad), "{bad}");
        }
    }

    #[test]
    fn episodes_table_rows_and_category_counts() {
        let s = session();
        let csv = s.episodes_csv();
        let mut lines = csv.lines();
        assert_eq!(lines.next(), Some(EPISODES_HEADER));
        let first = lines.next().expect("row 1");
        assert!(
            first.starts_with(
                "1,pick-place,PARTIAL,goal-miss,\"went, \"\"almost\"\"\",0,ended,0.6,"
            ),
            "{first}"
        );
        assert!(lines
            .next()
            .expect("row 2")
            .starts_with("2,pick-place,FAILURE,grasp-miss,,0,"));
        assert_eq!(csv.lines().count(), 4);
        let sum = s.summary();
        assert_eq!(sum.attempted, 3);
        assert_eq!(sum.partial, 1);
        let counts: Vec<(&str, usize)> =
            sum.by_category.iter().map(|(c, n)| (c.id(), *n)).collect();
        assert_eq!(counts[0], ("grasp-miss", 1));
        assert_eq!(counts[2], ("collision", 1));
        assert_eq!(counts[3], ("goal-miss", 1));
        assert_eq!(counts.iter().map(|(_, n)| n).sum::<usize>(), 3);
    }

    #[test]
    fn stored_session_round_trips_and_keeps_an_interrupted_episode() {
        let s = session();
        let in_progress = episode(&push(25, 0.5, 0.5, false));
        let json = s.to_json(Some(&in_progress));
        let back = Session::from_json(&json).expect("back");
        assert_eq!(back.episodes.len(), 4, "the interrupted episode is kept");
        assert_eq!(back.episodes[..3], s.episodes[..]);
        let last = &back.episodes[3];
        assert!(last.interrupted);
        assert_eq!(last.label, None);
        assert_eq!(*last.episode, in_progress, "simulated again bit for bit");
        assert_eq!(
            last.proposal(),
            (Label::Failure, Some(FailureCategory::OperatorAbort))
        );
        assert_eq!(back.unlabelled(), Some(4));
        assert!(
            json.len() < 20_000,
            "run-length coded: {} bytes",
            json.len()
        );
        assert_eq!(Session::from_json("{}"), None);
    }

    #[test]
    fn a_session_loaded_in_slices_is_the_one_loaded_at_once() {
        let s = session();
        let in_progress = episode(&push(25, 0.5, 0.5, false));
        let json = s.to_json(Some(&in_progress));
        let whole = Session::from_json(&json).expect("whole");
        for slice in [0, 1, 7, 1000] {
            let mut loader = SessionLoader::new(&json).expect("loader");
            let (_, total) = loader.progress();
            let steps: usize = whole.episodes.iter().map(|e| e.episode.records.len()).sum();
            assert_eq!(total, steps);
            let mut calls = 0;
            while !loader.run(slice.max(1)).expect("simulates") {
                calls += 1;
                assert!(calls <= steps, "slice {slice}: ends");
                let (done, _) = loader.progress();
                assert!(
                    done <= calls * slice.max(1),
                    "slice {slice}: at most {slice} a call"
                );
            }
            assert_eq!(loader.progress(), (total, total));
            assert_eq!(loader.finish(), Some(whole.clone()), "slice {slice}");
        }
        // Not finished: no session yet.
        let mut loader = SessionLoader::new(&json).expect("loader");
        assert_eq!(loader.run(3), Some(false));
        assert_eq!(loader.finish(), None);
        // A start state that is not the configuration's: refused, as at once.
        let mut stored: StoredSession = serde_json::from_str(&json).expect("stored");
        stored.episodes[1].episode.start.q[0] += 0.1;
        let bad = serde_json::to_string(&stored).expect("json");
        assert_eq!(Session::from_json(&bad), None);
        let mut loader = SessionLoader::new(&bad).expect("parses");
        let mut result = Some(false);
        while result == Some(false) {
            result = loader.run(5);
        }
        assert_eq!(result, None);
        assert!(SessionLoader::new("{}").is_none());
    }

    #[test]
    fn saved_files_open_again_and_bad_ones_are_named() {
        let s = session();
        let files = s.files(END);
        let back = Session::from_files(&files).expect("opens");
        assert_eq!(back.episodes, s.episodes);
        assert_eq!(back.pilot_id, s.pilot_id);
        assert_eq!(back.evidence(END), s.evidence(END));

        let without = |name: &str| -> Vec<(String, String)> {
            files.iter().filter(|(n, _)| n != name).cloned().collect()
        };
        assert_eq!(
            Session::from_files(&without("teleop_episode_2.csv")),
            Err(SessionError::MissingFile {
                name: "teleop_episode_2.csv".into()
            })
        );
        let mut tampered = files.clone();
        tampered[3].1 = tampered[3].1.replacen("0.0", "0.1", 1);
        assert_eq!(
            Session::from_files(&tampered),
            Err(SessionError::Sha256Mismatch {
                name: "teleop_episode_2.csv".into()
            })
        );
        let mut bad_json = files.clone();
        bad_json[0].1 = "{ \"schemaVersion\": ".into();
        assert!(matches!(
            Session::from_files(&bad_json),
            Err(SessionError::NotJson { line: 1, .. })
        ));
        let mut extra_key = files.clone();
        extra_key[0].1 = extra_key[0].1.replacen('{', "{\"x\": 1,", 1);
        assert_eq!(
            Session::from_files(&extra_key),
            Err(SessionError::Evidence {
                problem: EvidenceProblem::Unexpected { field: "x".into() }
            })
        );
    }

    #[test]
    fn repeatability_compares_side_by_side() {
        let first = session();
        let mut second = Session::new("Pilot 7", InputDevice::Keyboard, END);
        second.record(episode(&push(30, 0.0, 0.0, true)), false);
        second.episodes[0].set_label(Label::Success, Some(FailureCategory::Drop), "");
        assert_eq!(
            second.episodes[0].category, None,
            "a success has no category"
        );
        let rows = compare(&first.summary(), &second.summary());
        let ids: Vec<&str> = rows.iter().map(|r| r.id.as_str()).collect();
        assert_eq!(
            &ids[..5],
            &[
                "attempted",
                "success-rate",
                "mean-time",
                "efficiency",
                "collisions"
            ]
        );
        assert_eq!(ids.len(), 15);
        assert_eq!(rows[0].first, Some(3.0));
        assert_eq!(rows[1].first, Some(0.0));
        assert_eq!(rows[1].second, Some(1.0));
        assert_eq!(rows[5].id, "grasp-miss");
        assert_eq!((rows[5].first, rows[5].second), (Some(1.0), Some(0.0)));
    }

    #[test]
    fn modules_in_order() {
        let ids: Vec<&str> = Module::ALL.iter().map(|m| m.id()).collect();
        assert_eq!(
            ids,
            [
                "preflight",
                "basic-control",
                "record-ten",
                "failure-review",
                "repeatability"
            ]
        );
        assert_eq!(Module::Repeatability.next(), Module::Repeatability);
        assert_eq!(Module::from_id("record-ten"), Some(Module::RecordTen));
        assert!(Module::RecordTen.records() && !Module::BasicControl.records());
        assert_eq!(clean_pilot_id(&"x".repeat(100)).len(), PILOT_ID_MAX);
    }
}
