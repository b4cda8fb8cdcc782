//! SO-101 episodes: recording, the episode CSV (`so101_episode_<n>.csv`), exact replay, the
//! figures and the label the page proposes.
//!
//! The CSV: the marker row [`MARKER`]; `# config,<json>` and `# start,<json>` (the
//! [`SceneConfig`] and start [`State`] as JSON, whose numbers read back to the same bits);
//! the column header [`COLUMNS`]; one row per step, numbers as Python's `repr` writes them,
//! booleans `0`/`1`, `event` the step's events as [`Event::text`] joined by `;`.

use serde::{Deserialize, Serialize};

use super::kinematics::{fk, jacobian, manipulability, norm, sub};
use super::scene::SceneConfig;
use super::sim::{Command, Sim, State, StepRecord};
use crate::pyfmt::push_py_float;
use crate::teleop::episode::{
    bad, check_size, mismatch, propose, replay_steps, row_cells, same_bool, same_events, same_f64,
    FailureCategory, Label, ReplayMismatch,
};
use crate::teleop::metrics::EpisodeMetrics;
use crate::teleop::recording::{arm_sim, EpisodeOf, Recorder};
use crate::teleop::session::{control_summary, each_event, run_length, run_steps, PracticeEpisode};
use crate::teleop::sim::{Event, Outcome};
use crate::teleop::TeleopError;

/// The first row of an SO-101 episode CSV.
pub const MARKER: &str = "# bsv so101 episode,1";

/// The column header of the step rows.
pub const COLUMNS: [&str; 35] = [
    "t_s",
    "dx",
    "dy",
    "dz",
    "droll",
    "dpitch",
    "dyaw",
    "gripper_cmd",
    "applied_dx",
    "applied_dy",
    "applied_dz",
    "applied_droll",
    "applied_dpitch",
    "applied_dyaw",
    "applied_gripper",
    "q1",
    "q2",
    "q3",
    "q4",
    "q5",
    "x",
    "y",
    "z",
    "roll",
    "pitch",
    "yaw",
    "gripper",
    "held",
    "cube_x",
    "cube_y",
    "cube_z",
    "manipulability",
    "orientation_error",
    "event",
    "step",
];

/// The largest episode file read, bytes.
pub const MAX_EPISODE_BYTES: u64 = 96 * 1024 * 1024;

/// One SO-101 attempt: its configuration, start state, commands and records
/// ([`EpisodeOf`] the arm's [`Sim`]).
pub type Episode = EpisodeOf<Sim>;

/// Records an episode step by step (the page's live run).
pub type EpisodeRecorder = Recorder<Sim>;

arm_sim!(Sim, SceneConfig, State, Command, StepRecord, true);

impl EpisodeOf<Sim> {
    /// The episode's figures (see [`mod@crate::teleop::metrics`]; `fitts` is `None`, the ideal
    /// path is start tool → cube start, then cube start → where it rests, when done).
    pub fn metrics(&self) -> EpisodeMetrics {
        let start_tool = fk(&self.start.q).pos;
        let mut path = 0.0;
        let mut last = start_tool;
        let mut min_m = manipulability(&jacobian(&self.start.q));
        let mut m = EpisodeMetrics::empty(
            self.records.last().map_or(0.0, |r| r.t_s),
            0.0,
            self.outcome(),
        );
        for r in &self.records {
            path += norm(&sub(&r.tool, &last));
            last = r.tool;
            min_m = min_m.min(r.manipulability);
            for e in &r.events {
                m.count(r.step, e);
            }
        }
        let cube0 = self.start.cube.pos;
        let mut ideal = 0.0;
        if m.grasps > 0 {
            ideal += norm(&sub(&cube0, &start_tool));
        }
        if m.outcome == Some(Outcome::Success) {
            if let Some(r) = self.records.last() {
                ideal += norm(&sub(&r.cube, &cube0));
            }
        }
        m.path_m = path;
        m.efficiency = if path > 0.0 {
            (ideal / path).min(1.0)
        } else {
            0.0
        };
        m.min_manipulability = min_m;
        m
    }

    /// The label and category the page proposes (the planar arm's rules,
    /// [`crate::teleop::episode::proposed_label`]).
    pub fn proposed_label(&self) -> (Label, Option<FailureCategory>) {
        let released = self.records.last().is_some_and(|r| !r.held);
        propose(
            &self.metrics(),
            released,
            self.config.noise_sigma,
            self.config.latency_steps,
        )
    }
}

/// The episode as `so101_episode_<n>.csv` (see the module docs).
pub fn episode_csv(episode: &Episode) -> String {
    let mut out = String::with_capacity(2048 + episode.records.len() * 420);
    out.push_str(MARKER);
    out.push('\n');
    out.push_str("# config,");
    out.push_str(&serde_json::to_string(&episode.config).unwrap_or_default());
    out.push_str("\n# start,");
    out.push_str(&serde_json::to_string(&episode.start).unwrap_or_default());
    out.push('\n');
    out.push_str(&COLUMNS.join(","));
    out.push('\n');
    let bit = |b: bool| if b { "1" } else { "0" };
    for (cmd, r) in episode.commands.iter().zip(&episode.records) {
        push_py_float(&mut out, r.t_s);
        let nums = |out: &mut String, vs: &[f64]| {
            for v in vs {
                out.push(',');
                push_py_float(out, *v);
            }
        };
        nums(&mut out, &cmd.axes());
        out.push(',');
        out.push_str(bit(cmd.gripper_closed));
        nums(&mut out, &r.applied.axes());
        out.push(',');
        out.push_str(bit(r.applied.gripper_closed));
        nums(&mut out, &r.q);
        nums(&mut out, &r.tool);
        nums(&mut out, &r.rpy);
        out.push(',');
        out.push_str(bit(r.gripper_closed));
        out.push(',');
        out.push_str(bit(r.held));
        nums(&mut out, &r.cube);
        nums(&mut out, &[r.manipulability, r.orientation_error]);
        out.push(',');
        let events: Vec<String> = r.events.iter().map(Event::text).collect();
        out.push_str(&events.join(";"));
        out.push_str(&format!(",{}\n", r.step));
    }
    out
}

/// Reads an episode CSV back; errors name the row (1-based) and column.
pub fn parse_episode_csv(text: &str) -> Result<Episode, TeleopError> {
    check_size(text, MAX_EPISODE_BYTES)?;
    let mut lines = text.lines();
    if lines.next().map(str::trim_end) != Some(MARKER) {
        return Err(TeleopError::NotAnEpisode);
    }
    let mut json_row = |row: usize, key: &str| -> Result<&str, TeleopError> {
        let line = lines.next().unwrap_or("");
        line.strip_prefix("# ")
            .and_then(|l| l.split_once(','))
            .filter(|(k, _)| *k == key)
            .map(|(_, v)| v)
            .ok_or_else(|| TeleopError::MissingHeader {
                key: key.to_string(),
            })
            .map_err(|e| {
                if line.is_empty() {
                    e
                } else {
                    bad(row, key, line)
                }
            })
    };
    let config: SceneConfig =
        serde_json::from_str(json_row(2, "config")?).map_err(|_| bad(2, "config", "json"))?;
    let start: State =
        serde_json::from_str(json_row(3, "start")?).map_err(|_| bad(3, "start", "json"))?;
    config.validate()?;
    if lines.next().map(str::trim_end) != Some(COLUMNS.join(",").as_str()) {
        return Err(TeleopError::MissingHeader {
            key: "columns".to_string(),
        });
    }
    let mut commands = Vec::new();
    let mut records = Vec::new();
    for (i, line) in lines.enumerate() {
        let row = i + 5;
        if line.trim().is_empty() {
            continue;
        }
        let cells = row_cells(row, line, COLUMNS.len())?;
        let (cmd, r) = parse_row(row, &cells)?;
        commands.push(cmd);
        records.push(r);
    }
    Ok(Episode {
        config,
        start,
        commands,
        records,
    })
}

fn parse_row(row: usize, cells: &[&str]) -> Result<(Command, StepRecord), TeleopError> {
    let f = |k: usize| -> Result<f64, TeleopError> {
        cells[k]
            .trim()
            .parse::<f64>()
            .map_err(|_| bad(row, COLUMNS[k], cells[k]))
    };
    let b = |k: usize| -> Result<bool, TeleopError> {
        match cells[k].trim() {
            "0" => Ok(false),
            "1" => Ok(true),
            _ => Err(bad(row, COLUMNS[k], cells[k])),
        }
    };
    let arr = |from: usize| -> Result<[f64; 6], TeleopError> {
        let mut a = [0.0; 6];
        for (i, o) in a.iter_mut().enumerate() {
            *o = f(from + i)?;
        }
        Ok(a)
    };
    let cmd = Command::with_axes(arr(1)?, b(7)?);
    let applied = Command::with_axes(arr(8)?, b(14)?);
    let mut events = Vec::new();
    for t in cells[33].split(';').filter(|t| !t.is_empty()) {
        events.push(Event::from_text(t).ok_or_else(|| bad(row, "event", t))?);
    }
    let step = cells[34]
        .trim()
        .parse::<u64>()
        .map_err(|_| bad(row, "step", cells[34]))?;
    let r = StepRecord {
        step,
        t_s: f(0)?,
        cmd,
        applied,
        q: [f(15)?, f(16)?, f(17)?, f(18)?, f(19)?],
        tool: [f(20)?, f(21)?, f(22)?],
        rpy: [f(23)?, f(24)?, f(25)?],
        gripper_closed: b(26)?,
        held: b(27)?,
        cube: [f(28)?, f(29)?, f(30)?],
        manipulability: f(31)?,
        orientation_error: f(32)?,
        events,
    };
    Ok((cmd, r))
}

/// Re-runs the commands from the config's start state and checks the start state and every
/// recorded number, flag and event bit for bit; on success the episode's figures.
pub fn replay(episode: &Episode) -> Result<EpisodeMetrics, ReplayMismatch> {
    let mut sim = Sim::new(episode.config.clone())
        .map_err(|e| mismatch(0, "config", "a valid config".to_string(), e.to_string()))?;
    if *sim.start_state() != episode.start {
        return Err(mismatch(
            0,
            "start",
            "the recorded start state".to_string(),
            "a different start state".to_string(),
        ));
    }
    if episode.commands.len() != episode.records.len() {
        return Err(mismatch(
            0,
            "rows",
            episode.records.len().to_string(),
            episode.commands.len().to_string(),
        ));
    }
    replay_steps(&mut sim, &episode.commands, &episode.records, compare)?;
    Ok(episode.metrics())
}

fn compare(step: u64, e: &StepRecord, g: &StepRecord) -> Result<(), ReplayMismatch> {
    same_f64(step, "t_s", e.t_s, g.t_s)?;
    let (ec, gc) = (e.cmd.axes(), g.cmd.axes());
    let (ea, ga) = (e.applied.axes(), g.applied.axes());
    for i in 0..6 {
        same_f64(step, COLUMNS[1 + i], ec[i], gc[i])?;
        same_f64(step, COLUMNS[8 + i], ea[i], ga[i])?;
    }
    same_bool(
        step,
        "gripper_cmd",
        e.cmd.gripper_closed,
        g.cmd.gripper_closed,
    )?;
    let nums = [
        (&e.q[..], &g.q[..], 15),
        (&e.tool[..], &g.tool[..], 20),
        (&e.rpy[..], &g.rpy[..], 23),
        (&e.cube[..], &g.cube[..], 28),
    ];
    for (a, b, col) in nums {
        for i in 0..a.len() {
            same_f64(step, COLUMNS[col + i], a[i], b[i])?;
        }
    }
    same_bool(step, "gripper", e.gripper_closed, g.gripper_closed)?;
    same_bool(step, "held", e.held, g.held)?;
    same_f64(step, "manipulability", e.manipulability, g.manipulability)?;
    same_f64(
        step,
        "orientation_error",
        e.orientation_error,
        g.orientation_error,
    )?;
    same_events(step, &e.events, &g.events)
}

/// An SO-101 episode as stored (localStorage): configuration, start state and the
/// run-length coded commands.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StoredEpisode {
    /// The config.
    pub config: SceneConfig,
    /// The start state.
    pub start: State,
    /// `(count, command)` runs.
    pub runs: Vec<(u32, Command)>,
}

/// A stored SO-101 episode being simulated again.
#[derive(Debug, Clone)]
pub struct Loading {
    recorder: EpisodeRecorder,
    runs: Vec<(u32, Command)>,
    /// Index of the current run and steps done of it.
    at: (usize, u32),
}

impl PracticeEpisode for Episode {
    type Stored = StoredEpisode;
    type Loading = Loading;
    const EMBODIMENT: &'static str = super::scene::EMBODIMENT;
    const FILE_PREFIX: &'static str = "so101";

    fn metrics(&self) -> EpisodeMetrics {
        Episode::metrics(self)
    }

    fn task_id(&self) -> &'static str {
        self.config.task_id()
    }

    fn csv(&self) -> String {
        episode_csv(self)
    }

    fn parse_csv(text: &str) -> Result<Self, String> {
        parse_episode_csv(text).map_err(|e| e.to_string())
    }

    fn replays(&self) -> bool {
        replay(self).is_ok()
    }

    fn proposed_label(&self) -> (Label, Option<FailureCategory>) {
        Episode::proposed_label(self)
    }

    fn for_each_event(&self, f: &mut dyn FnMut(usize, f64, &Event)) {
        each_event(self.records.iter().map(|r| (r.t_s, &r.events[..])), f);
    }

    fn steps(&self) -> usize {
        self.commands.len()
    }

    fn control_summary(&self) -> (&'static str, f64, u32, f64) {
        let c = &self.config;
        control_summary(&c.control, c.latency_steps, c.noise_sigma)
    }

    fn stored(&self) -> StoredEpisode {
        StoredEpisode {
            config: self.config.clone(),
            start: self.start.clone(),
            runs: run_length(&self.commands),
        }
    }

    fn stored_steps(stored: &StoredEpisode) -> usize {
        run_steps(&stored.runs)
    }

    fn load(stored: StoredEpisode) -> Option<Loading> {
        let recorder = EpisodeRecorder::new(stored.config).ok()?;
        if *recorder.sim().start_state() != stored.start {
            return None;
        }
        Some(Loading {
            recorder,
            runs: stored.runs,
            at: (0, 0),
        })
    }

    fn load_run(l: &mut Loading, max_steps: usize) -> usize {
        let mut done = 0;
        while done < max_steps {
            let Some((n, c)) = l.runs.get(l.at.0).copied() else {
                break;
            };
            if l.at.1 >= n {
                l.at = (l.at.0 + 1, 0);
                continue;
            }
            l.recorder.step(&c);
            l.at.1 += 1;
            done += 1;
        }
        done
    }

    fn load_done(l: &Loading) -> bool {
        l.runs[l.at.0.min(l.runs.len())..]
            .iter()
            .enumerate()
            .all(|(i, (n, _))| if i == 0 { l.at.1 >= *n } else { *n == 0 })
    }

    fn loaded(l: Loading) -> Self {
        l.recorder.into_episode()
    }
}
