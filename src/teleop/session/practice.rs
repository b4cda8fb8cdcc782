//! A practice session: the pilot, the input device, the Academy module reached, the preflight
//! checks and the recorded episodes ([`EpisodeEntry`]) with the pilot's labels; its figures
//! ([`Summary`]) and the repeatability comparison of two sessions ([`compare`]).
//!
//! Failures are never deleted: an episode, once ended, stays in the session; an episode cut
//! off by a reload or a crash of the tab comes back `interrupted`, proposed as a FAILURE of
//! category `operator-abort`, for the pilot to confirm.

use std::rc::Rc;

use serde::{Deserialize, Serialize};

use super::kind::PracticeEpisode;
use crate::teleop::episode::{Episode, FailureCategory, Label};
use crate::teleop::metrics::EpisodeMetrics;
use crate::teleop::sim::Event;

/// Episodes the record module asks for.
pub const RECORD_TARGET: usize = 10;

/// Longest pilot id kept.
pub const PILOT_ID_MAX: usize = 64;

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

/// One recorded episode and what the pilot said about it.
#[derive(Debug, Clone, PartialEq)]
pub struct EpisodeEntry<E = Episode> {
    /// 1, 2, ... in recording order.
    pub number: usize,
    /// The episode (shared: a copy of the session, as an export takes, copies no steps).
    pub episode: Rc<E>,
    pub metrics: EpisodeMetrics,
    /// `None` until the pilot labels it.
    pub label: Option<Label>,
    pub category: Option<FailureCategory>,
    pub note: String,
    /// Cut off by a reload or a crash of the tab.
    pub interrupted: bool,
}

impl<E: PracticeEpisode> EpisodeEntry<E> {
    /// A just-ended episode, unlabelled.
    pub fn new(number: usize, episode: E, interrupted: bool) -> EpisodeEntry<E> {
        let metrics = episode.metrics();
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
        self.episode.proposed_label()
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
        if self.label != Some(Label::Success) {
            return false;
        }
        let mut failed = false;
        self.episode.for_each_event(&mut |_, _, e| {
            failed |= matches!(e, Event::GraspMiss | Event::Drop | Event::Collision { .. });
        });
        failed
    }

    /// The episode's time series file (the kernel's CSV).
    pub fn csv(&self) -> String {
        self.episode.csv()
    }
}

/// A practice session.
#[derive(Debug, Clone, PartialEq)]
pub struct Session<E = Episode> {
    pub pilot_id: String,
    pub input_device: InputDevice,
    pub module: Module,
    pub preflight: Preflight,
    /// ISO 8601, from the page's clock.
    pub started_at: String,
    pub ended_at: Option<String>,
    pub episodes: Vec<EpisodeEntry<E>>,
}

impl<E: PracticeEpisode> Session<E> {
    /// A new session started at `started_at`.
    pub fn new(pilot_id: &str, input_device: InputDevice, started_at: &str) -> Session<E> {
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
        self.episodes.first().map(|e| e.episode.task_id())
    }

    /// Adds a finished (or interrupted) episode; returns its number.
    pub fn record(&mut self, episode: E, interrupted: bool) -> usize {
        let n = self.episodes.len() + 1;
        self.episodes
            .push(EpisodeEntry::new(n, episode, interrupted));
        n
    }

    /// Repeatability: this session gives way to a second one for the same pilot and device,
    /// started at `now` with the preflight carried over (its module is the page's to enter);
    /// the first is returned, ended at `now` unless it had ended. `None` (nothing changes)
    /// when it has no episodes.
    pub fn start_second(&mut self, now: &str) -> Option<Session<E>> {
        if self.episodes.is_empty() {
            return None;
        }
        let mut second = Session::new(&self.pilot_id, self.input_device, now);
        second.preflight = self.preflight;
        let mut first = std::mem::replace(self, second);
        first.ended_at.get_or_insert_with(|| now.to_string());
        Some(first)
    }

    /// The first episode the pilot has not labelled yet.
    pub fn unlabelled(&self) -> Option<usize> {
        self.episodes
            .iter()
            .position(|e| e.label.is_none())
            .map(|i| i + 1)
    }

    /// The session's figures (success rate, means, counts by category).
    pub fn summary(&self) -> Summary {
        Summary::of(&self.episodes)
    }
}

/// The pilot id as kept: trimmed, at most [`PILOT_ID_MAX`] characters.
pub fn clean_pilot_id(id: &str) -> String {
    id.trim().chars().take(PILOT_ID_MAX).collect()
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
    /// The figures of no episode (every category counted 0).
    pub fn empty() -> Summary {
        Summary {
            by_category: CATEGORIES.iter().map(|c| (*c, 0)).collect(),
            ..Summary::default()
        }
    }

    /// The figures of `episodes`.
    pub fn of<E: PracticeEpisode>(episodes: &[EpisodeEntry<E>]) -> Summary {
        let count = |f: &dyn Fn(&EpisodeEntry<E>) -> bool| episodes.iter().filter(|e| f(e)).count();
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
