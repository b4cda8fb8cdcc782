//! Episodes: recording, the episode CSV (`teleop_episode_<n>.csv`), exact replay and the
//! label the page proposes.
//!
//! An [`Episode`] is its [`SceneConfig`], its start [`State`] and the operator's command
//! stream; the [`StepRecord`]s are what the simulation made of them. Because [`Sim`] is
//! deterministic, [`replay`] re-runs the commands from the start state and checks that every
//! recorded number comes back bit for bit.
//!
//! The CSV: a marker row [`MARKER`], then one `# key,value…` row per config field (the keys
//! are the field names; `targets` is flat `x,z,radius` triples; `start_block` the block's
//! start centre), then the column header [`COLUMNS`] and one row per step. Numbers are written
//! as Python's `repr` writes them ([`crate::pyfmt`], as the recipes' CSVs), which reads back to
//! the same bits; booleans are `0`/`1`; `event` is the step's events as
//! [`Event::text`] joined by `;` (empty when none).

#![warn(missing_docs)]

use serde::{Deserialize, Serialize};

use super::arm::ArmParams;
use super::control::{ControlParams, IkMethod};
use super::error::TeleopError;
use super::metrics::EpisodeMetrics;
use super::recording::{arm_sim, ArmSim, EpisodeOf, Recorder};
use super::scene::{SceneConfig, Target, Task};
use super::sim::{Command, Event, Outcome, Sim, State, StepRecord};
use crate::pyfmt::{push_py_float, py_float};

/// The first row of an episode CSV.
pub use super::error::EPISODE_MARKER as MARKER;

/// The column header of the step rows.
pub const COLUMNS: [&str; 21] = [
    "t_s",
    "dx",
    "dz",
    "dphi",
    "gripper_cmd",
    "applied_dx",
    "applied_dz",
    "applied_dphi",
    "applied_gripper",
    "q1",
    "q2",
    "q3",
    "x",
    "z",
    "phi",
    "gripper",
    "held",
    "block_x",
    "block_z",
    "manipulability",
    "event",
];

/// The largest episode file [`parse_episode_csv`] reads, bytes (a 600 s episode is about
/// 15 MB).
pub const MAX_EPISODE_BYTES: u64 = 64 * 1024 * 1024;

/// One attempt of the planar arm: its scene and controller, start state, commands and
/// records ([`EpisodeOf`] the arm's [`Sim`]).
pub type Episode = EpisodeOf<Sim>;

/// A [`Sim`] that records every step into an [`Episode`] (nothing once the episode ended).
pub type EpisodeRecorder = Recorder<Sim>;

arm_sim!(Sim, SceneConfig, State, Command, StepRecord, false);

/// The figures of `episode`, from its records (no re-simulation; see [`EpisodeMetrics`]).
pub fn metrics(episode: &Episode) -> EpisodeMetrics {
    EpisodeMetrics::of(&episode.config, &episode.start, &episode.records)
}

/// The episode as `teleop_episode_<n>.csv` (see the module docs): [`episode_csv_head`] then
/// [`push_episode_csv_rows`] of every step.
pub fn episode_csv(episode: &Episode) -> String {
    let mut out = episode_csv_head(episode);
    out.reserve(episode.records.len() * 260);
    push_episode_csv_rows(&mut out, episode, 0..episode.records.len());
    out
}

/// The rows of an episode CSV before its step rows: the marker, the config rows and the
/// column header (a page writing a long episode in slices starts with these).
pub fn episode_csv_head(episode: &Episode) -> String {
    let c = &episode.config;
    let mut out = String::with_capacity(1024);
    out.push_str(MARKER);
    out.push('\n');
    let mut row = |key: &str, values: &[f64]| {
        out.push_str("# ");
        out.push_str(key);
        for v in values {
            out.push(',');
            push_py_float(&mut out, *v);
        }
        out.push('\n');
    };
    row("links", &c.arm.links);
    row("q_min", &c.arm.q_min);
    row("q_max", &c.arm.q_max);
    row("qd_max", &c.arm.qd_max);
    row("link_radius", &[c.arm.link_radius]);
    row("lambda", &[c.control.lambda]);
    row("pinv_gain", &[c.control.pinv_gain]);
    row("trans_gain", &[c.control.trans_gain]);
    row("lambda_min", &[c.control.lambda_min]);
    row("lambda_max", &[c.control.lambda_max]);
    row("sigma_threshold", &[c.control.sigma_threshold]);
    row("start_q", &c.start_q);
    row("noise_sigma", &[c.noise_sigma]);
    row("time_box_s", &[c.time_box_s]);
    row("pos_sensitivity", &[c.pos_sensitivity]);
    row("rot_sensitivity", &[c.rot_sensitivity]);
    let targets: Vec<f64> = c
        .task
        .targets()
        .iter()
        .flat_map(|t| [t.x, t.z, t.radius])
        .collect();
    row("targets", &targets);
    row(
        "start_block",
        &[episode.start.block.x, episode.start.block.z],
    );
    out.push_str(&format!(
        "# task,{}\n# method,{}\n# latency_steps,{}\n# noise_seed,{}\n# success_steps,{}\n",
        c.task.id(),
        c.control.method.id(),
        c.latency_steps,
        c.noise_seed,
        c.success_steps
    ));
    out.push_str(&COLUMNS.join(","));
    out.push('\n');
    out
}

/// Appends the step rows `steps` (0-based, clamped to the episode) of the episode CSV to
/// `out`: [`episode_csv`] is the head and every step's row, so slices written one after the
/// other give the same bytes.
pub fn push_episode_csv_rows(out: &mut String, episode: &Episode, steps: std::ops::Range<usize>) {
    let n = episode.commands.len().min(episode.records.len());
    let start = steps.start.min(n);
    let end = steps.end.min(n).max(start);
    let bit = |b: bool| if b { "1" } else { "0" };
    let rows = episode.commands[start..end]
        .iter()
        .zip(&episode.records[start..end]);
    for (cmd, r) in rows {
        let mut first = true;
        let mut num = |out: &mut String, v: f64| {
            if !first {
                out.push(',');
            }
            first = false;
            push_py_float(out, v);
        };
        num(out, r.t_s);
        num(out, cmd.dx);
        num(out, cmd.dz);
        num(out, cmd.dphi);
        out.push(',');
        out.push_str(bit(cmd.gripper_closed));
        for v in [r.applied.dx, r.applied.dz, r.applied.dphi] {
            out.push(',');
            push_py_float(out, v);
        }
        out.push(',');
        out.push_str(bit(r.applied.gripper_closed));
        for v in [r.q[0], r.q[1], r.q[2], r.x, r.z, r.phi] {
            out.push(',');
            push_py_float(out, v);
        }
        out.push(',');
        out.push_str(bit(r.gripper_closed));
        out.push(',');
        out.push_str(bit(r.held));
        for v in [r.block_x, r.block_z, r.manipulability] {
            out.push(',');
            push_py_float(out, v);
        }
        out.push(',');
        for (i, e) in r.events.iter().enumerate() {
            if i > 0 {
                out.push(';');
            }
            out.push_str(&e.text());
        }
        out.push('\n');
    }
}

/// A header row: its cells after the key, and its row number.
struct HeaderRow<'a> {
    row: usize,
    key: &'a str,
    cells: Vec<&'a str>,
}

fn header<'a, 'b>(rows: &'b [HeaderRow<'a>], key: &str) -> Result<&'b HeaderRow<'a>, TeleopError> {
    rows.iter()
        .find(|r| r.key == key)
        .ok_or_else(|| TeleopError::MissingHeader {
            key: key.to_string(),
        })
}

/// A cell that does not read: its row (1-based), column and text.
pub fn bad(row: usize, column: &str, value: &str) -> TeleopError {
    TeleopError::BadCell {
        row,
        column: column.to_string(),
        value: value.to_string(),
    }
}

/// Refuses an episode file longer than `limit` bytes.
pub fn check_size(text: &str, limit: u64) -> Result<(), TeleopError> {
    if text.len() as u64 > limit {
        return Err(TeleopError::TooLarge {
            bytes: text.len() as u64,
            limit,
        });
    }
    Ok(())
}

/// The cells of step row `row`, which must have `columns` of them.
pub fn row_cells(row: usize, line: &str, columns: usize) -> Result<Vec<&str>, TeleopError> {
    let cells: Vec<&str> = line.split(',').collect();
    if cells.len() != columns {
        return Err(TeleopError::Ragged {
            row,
            expected: columns,
            got: cells.len(),
        });
    }
    Ok(cells)
}

fn parse_f64(row: usize, column: &str, text: &str) -> Result<f64, TeleopError> {
    text.trim()
        .parse::<f64>()
        .map_err(|_| bad(row, column, text))
}

fn parse_bool(row: usize, column: &str, text: &str) -> Result<bool, TeleopError> {
    match text.trim() {
        "0" => Ok(false),
        "1" => Ok(true),
        _ => Err(bad(row, column, text)),
    }
}

/// `n` numbers from header row `key`.
fn numbers<const N: usize>(rows: &[HeaderRow], key: &str) -> Result<[f64; N], TeleopError> {
    let h = header(rows, key)?;
    if h.cells.len() != N {
        return Err(TeleopError::Ragged {
            row: h.row,
            expected: N + 1,
            got: h.cells.len() + 1,
        });
    }
    let mut out = [0.0; N];
    for (o, cell) in out.iter_mut().zip(&h.cells) {
        *o = parse_f64(h.row, key, cell)?;
    }
    Ok(out)
}

fn one_text<'a>(rows: &[HeaderRow<'a>], key: &str) -> Result<(usize, &'a str), TeleopError> {
    let h = header(rows, key)?;
    match h.cells.as_slice() {
        [v] => Ok((h.row, v.trim())),
        _ => Err(TeleopError::Ragged {
            row: h.row,
            expected: 2,
            got: h.cells.len() + 1,
        }),
    }
}

fn one_int<T: std::str::FromStr>(rows: &[HeaderRow], key: &str) -> Result<T, TeleopError> {
    let (row, text) = one_text(rows, key)?;
    text.parse::<T>().map_err(|_| bad(row, key, text))
}

/// Reads an episode CSV back (see the module docs). The config is validated; errors name the
/// row (1-based, the marker row is 1) and the column or header key.
pub fn parse_episode_csv(text: &str) -> Result<Episode, TeleopError> {
    check_size(text, MAX_EPISODE_BYTES)?;
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut lines = text
        .lines()
        .map(|l| l.strip_suffix('\r').unwrap_or(l))
        .enumerate()
        .map(|(i, l)| (i + 1, l));
    match lines.next() {
        Some((_, first)) if first.trim_end_matches(',') == MARKER => {}
        _ => return Err(TeleopError::NotAnEpisode),
    }
    let mut headers = Vec::new();
    let mut columns_row = None;
    for (row, line) in lines.by_ref() {
        if let Some(rest) = line.strip_prefix('#') {
            let mut cells = rest.split(',');
            let key = cells.next().unwrap_or("").trim();
            headers.push(HeaderRow {
                row,
                key,
                cells: cells.filter(|c| !c.is_empty()).collect(),
            });
        } else if line.trim().is_empty() {
            continue;
        } else {
            columns_row = Some((row, line));
            break;
        }
    }
    let Some((columns_row, columns_line)) = columns_row else {
        return Err(TeleopError::MissingHeader {
            key: "t_s".to_string(),
        });
    };
    let got: Vec<&str> = columns_line.split(',').map(str::trim).collect();
    if got != COLUMNS {
        if got.len() != COLUMNS.len() {
            return Err(TeleopError::Ragged {
                row: columns_row,
                expected: COLUMNS.len(),
                got: got.len(),
            });
        }
        let (i, cell) = got
            .iter()
            .enumerate()
            .find(|(i, c)| **c != COLUMNS[*i])
            .unwrap_or((0, &""));
        return Err(bad(columns_row, COLUMNS[i], cell));
    }

    let config = config_from_headers(&headers)?;
    let mut start = Sim::new(config.clone())?.start_state().clone();
    let [bx, bz] = numbers::<2>(&headers, "start_block")?;
    start.block.x = bx;
    start.block.z = bz;

    let mut commands = Vec::new();
    let mut records = Vec::new();
    for (row, line) in lines {
        if line.trim().is_empty() {
            continue;
        }
        let cells = row_cells(row, line, COLUMNS.len())?;
        let f = |i: usize| parse_f64(row, COLUMNS[i], cells[i]);
        let b = |i: usize| parse_bool(row, COLUMNS[i], cells[i]);
        let cmd = Command {
            dx: f(1)?,
            dz: f(2)?,
            dphi: f(3)?,
            gripper_closed: b(4)?,
        };
        let applied = Command {
            dx: f(5)?,
            dz: f(6)?,
            dphi: f(7)?,
            gripper_closed: b(8)?,
        };
        let events = cells[20]
            .split(';')
            .map(str::trim)
            .filter(|e| !e.is_empty())
            .map(|e| Event::from_text(e).ok_or_else(|| bad(row, "event", e)))
            .collect::<Result<Vec<_>, _>>()?;
        records.push(StepRecord {
            step: records.len() as u64 + 1,
            t_s: f(0)?,
            cmd,
            applied,
            q: [f(9)?, f(10)?, f(11)?],
            x: f(12)?,
            z: f(13)?,
            phi: f(14)?,
            gripper_closed: b(15)?,
            held: b(16)?,
            block_x: f(17)?,
            block_z: f(18)?,
            manipulability: f(19)?,
            events,
        });
        commands.push(cmd);
    }
    Ok(Episode {
        config,
        start,
        commands,
        records,
    })
}

fn config_from_headers(h: &[HeaderRow]) -> Result<SceneConfig, TeleopError> {
    let (row, task_id) = one_text(h, "task")?;
    let task = match Task::from_id(task_id) {
        Some(Task::Reach { .. }) => {
            let t = header(h, "targets")?;
            if t.cells.len() % 3 != 0 {
                return Err(bad(t.row, "targets", &t.cells.join(",")));
            }
            let values = t
                .cells
                .iter()
                .map(|c| parse_f64(t.row, "targets", c))
                .collect::<Result<Vec<_>, _>>()?;
            Task::Reach {
                targets: values
                    .chunks_exact(3)
                    .map(|v| Target {
                        x: v[0],
                        z: v[1],
                        radius: v[2],
                    })
                    .collect(),
            }
        }
        Some(task) => task,
        None => {
            return Err(TeleopError::BadChoice {
                field: "task".to_string(),
                value: format!("{task_id} (row {row})"),
                choices: Task::IDS.join(", "),
            })
        }
    };
    let (row, method_id) = one_text(h, "method")?;
    let method = IkMethod::from_id(method_id).ok_or_else(|| TeleopError::BadChoice {
        field: "method".to_string(),
        value: format!("{method_id} (row {row})"),
        choices: IkMethod::ALL.map(IkMethod::id).join(", "),
    })?;
    let [link_radius] = numbers::<1>(h, "link_radius")?;
    let arm = ArmParams {
        links: numbers(h, "links")?,
        q_min: numbers(h, "q_min")?,
        q_max: numbers(h, "q_max")?,
        qd_max: numbers(h, "qd_max")?,
        link_radius,
    };
    let [lambda] = numbers::<1>(h, "lambda")?;
    let [pinv_gain] = numbers::<1>(h, "pinv_gain")?;
    let [trans_gain] = numbers::<1>(h, "trans_gain")?;
    let [lambda_min] = numbers::<1>(h, "lambda_min")?;
    let [lambda_max] = numbers::<1>(h, "lambda_max")?;
    let [sigma_threshold] = numbers::<1>(h, "sigma_threshold")?;
    let [noise_sigma] = numbers::<1>(h, "noise_sigma")?;
    let [time_box_s] = numbers::<1>(h, "time_box_s")?;
    let [pos_sensitivity] = numbers::<1>(h, "pos_sensitivity")?;
    let [rot_sensitivity] = numbers::<1>(h, "rot_sensitivity")?;
    let config = SceneConfig {
        arm,
        control: ControlParams {
            method,
            lambda,
            pinv_gain,
            trans_gain,
            lambda_min,
            lambda_max,
            sigma_threshold,
        },
        task,
        start_q: numbers(h, "start_q")?,
        latency_steps: one_int(h, "latency_steps")?,
        noise_sigma,
        noise_seed: one_int(h, "noise_seed")?,
        time_box_s,
        success_steps: one_int(h, "success_steps")?,
        pos_sensitivity,
        rot_sensitivity,
    };
    config.validate()?;
    Ok(config)
}

/// The first place a replay differs from the recording: the step (1-based; 0 for the start
/// state), the field (a CSV column name, `start_*` or `rows`), the recorded value and the
/// replayed one, as the CSV writes them.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct ReplayMismatch {
    /// The step (1-based; 0 = the start state).
    pub step: u64,
    /// The CSV column (or `start_*`, `rows`, `config`).
    pub field: String,
    /// What the file recorded.
    pub expected: String,
    /// What the replay produced.
    pub got: String,
}

impl std::fmt::Display for ReplayMismatch {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "step {}: {} differs: recorded {}, replayed {}",
            self.step, self.field, self.expected, self.got
        )
    }
}

pub(crate) fn mismatch(step: u64, field: &str, expected: String, got: String) -> ReplayMismatch {
    ReplayMismatch {
        step,
        field: field.to_string(),
        expected,
        got,
    }
}

/// Checks one number bit for bit.
pub(crate) fn same_f64(
    step: u64,
    field: &str,
    expected: f64,
    got: f64,
) -> Result<(), ReplayMismatch> {
    if expected.to_bits() == got.to_bits() {
        Ok(())
    } else {
        Err(mismatch(step, field, py_float(expected), py_float(got)))
    }
}

pub(crate) fn same_bool(
    step: u64,
    field: &str,
    expected: bool,
    got: bool,
) -> Result<(), ReplayMismatch> {
    if expected == got {
        Ok(())
    } else {
        Err(mismatch(
            step,
            field,
            u8::from(expected).to_string(),
            u8::from(got).to_string(),
        ))
    }
}

/// Re-runs the episode's commands from its config's start state and checks the start state
/// and every recorded number, flag and event against the simulation, bit for bit; on success
/// the episode's [`metrics`].
pub fn replay(episode: &Episode) -> Result<EpisodeMetrics, ReplayMismatch> {
    let mut sim = Sim::new(episode.config.clone())
        .map_err(|e| mismatch(0, "config", "a valid config".to_string(), e.to_string()))?;
    let s0 = sim.start_state();
    let e0 = &episode.start;
    for (i, name) in ["start_q1", "start_q2", "start_q3"].iter().enumerate() {
        same_f64(0, name, e0.q[i], s0.q[i])?;
    }
    same_f64(0, "start_block_x", e0.block.x, s0.block.x)?;
    same_f64(0, "start_block_z", e0.block.z, s0.block.z)?;
    if e0 != s0 {
        return Err(mismatch(
            0,
            "start",
            "the recorded start state".to_string(),
            "a different start state".to_string(),
        ));
    }
    if episode.commands.len() != episode.records.len() {
        return Err(mismatch(
            episode.commands.len().min(episode.records.len()) as u64 + 1,
            "rows",
            episode.records.len().to_string(),
            episode.commands.len().to_string(),
        ));
    }
    replay_steps(&mut sim, &episode.commands, &episode.records, compare)?;
    Ok(metrics(episode))
}

/// Steps `sim` with each of `commands` and checks what each step made against the one of
/// `records` beside it with `compare` (the step's number, recorded, made); a command left
/// after the episode ended is a mismatch of the `rows`.
// Each arm's `replay` is its one caller: inlined there.
#[inline(always)]
pub fn replay_steps<S: ArmSim>(
    sim: &mut S,
    commands: &[S::Command],
    records: &[S::Record],
    compare: impl Fn(u64, &S::Record, &S::Record) -> Result<(), ReplayMismatch>,
) -> Result<(), ReplayMismatch> {
    for (cmd, rec) in commands.iter().zip(records) {
        let step = sim.steps_taken() + 1;
        if sim.done().is_some() {
            return Err(mismatch(
                step,
                "rows",
                "a step".to_string(),
                "the episode had already ended".to_string(),
            ));
        }
        let got = sim.advance(cmd);
        compare(step, rec, &got)?;
    }
    Ok(())
}

fn compare(step: u64, e: &StepRecord, g: &StepRecord) -> Result<(), ReplayMismatch> {
    same_f64(step, "t_s", e.t_s, g.t_s)?;
    let commanded = ["dx", "dz", "dphi", "gripper_cmd"];
    same_command(step, commanded, &e.cmd, &g.cmd)?;
    let applied = [
        "applied_dx",
        "applied_dz",
        "applied_dphi",
        "applied_gripper",
    ];
    same_command(step, applied, &e.applied, &g.applied)?;
    for (i, name) in ["q1", "q2", "q3"].iter().enumerate() {
        same_f64(step, name, e.q[i], g.q[i])?;
    }
    same_f64(step, "x", e.x, g.x)?;
    same_f64(step, "z", e.z, g.z)?;
    same_f64(step, "phi", e.phi, g.phi)?;
    same_bool(step, "gripper", e.gripper_closed, g.gripper_closed)?;
    same_bool(step, "held", e.held, g.held)?;
    same_f64(step, "block_x", e.block_x, g.block_x)?;
    same_f64(step, "block_z", e.block_z, g.block_z)?;
    same_f64(step, "manipulability", e.manipulability, g.manipulability)?;
    same_events(step, &e.events, &g.events)
}

/// Checks a command of step `step`, its columns named `[dx, dz, dphi, gripper]`.
fn same_command(
    step: u64,
    [dx, dz, dphi, gripper]: [&'static str; 4],
    e: &Command,
    g: &Command,
) -> Result<(), ReplayMismatch> {
    same_f64(step, dx, e.dx, g.dx)?;
    same_f64(step, dz, e.dz, g.dz)?;
    same_f64(step, dphi, e.dphi, g.dphi)?;
    same_bool(step, gripper, e.gripper_closed, g.gripper_closed)
}

/// Checks that step `step` made the recorded events, in order.
pub fn same_events(step: u64, expected: &[Event], got: &[Event]) -> Result<(), ReplayMismatch> {
    if expected != got {
        let text = |events: &[Event]| events.iter().map(Event::text).collect::<Vec<_>>().join(";");
        return Err(mismatch(step, "event", text(expected), text(got)));
    }
    Ok(())
}

/// The pilot's label of an episode (the Academy's SUCCESS / FAILURE / PARTIAL).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum Label {
    /// The task was done cleanly.
    Success,
    /// The task was not done.
    Failure,
    /// Done with a failure on the way, or not done but with progress.
    Partial,
}

impl Label {
    /// Every label, in the page's order.
    pub const ALL: [Label; 3] = [Label::Success, Label::Failure, Label::Partial];

    /// `SUCCESS`, `FAILURE`, `PARTIAL` (as the evidence file and `data-label` write them).
    pub fn id(self) -> &'static str {
        match self {
            Label::Success => "SUCCESS",
            Label::Failure => "FAILURE",
            Label::Partial => "PARTIAL",
        }
    }

    /// The label with this id.
    pub fn from_id(id: &str) -> Option<Label> {
        Label::ALL.into_iter().find(|l| l.id() == id)
    }
}

/// The Academy's ten failure categories.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum FailureCategory {
    /// The gripper closed without the block.
    GraspMiss,
    /// The block fell from the gripper outside the goal.
    Drop,
    /// A link or the carried block hit the table or an obstacle.
    Collision,
    /// The block was set down, or the tip stopped, outside the goal.
    GoalMiss,
    /// The time box ran out.
    Timeout,
    /// The input device's tracking failed (noise, dropouts).
    TrackingLoss,
    /// The delay between input and motion made the pilot fail.
    InputLag,
    /// A reset did not return the scene to its start state.
    ResetFailure,
    /// The simulation misbehaved.
    SimInstability,
    /// The pilot gave the attempt up.
    OperatorAbort,
}

impl FailureCategory {
    /// All ten, in the Academy's order.
    pub const ALL: [FailureCategory; 10] = [
        FailureCategory::GraspMiss,
        FailureCategory::Drop,
        FailureCategory::Collision,
        FailureCategory::GoalMiss,
        FailureCategory::Timeout,
        FailureCategory::TrackingLoss,
        FailureCategory::InputLag,
        FailureCategory::ResetFailure,
        FailureCategory::SimInstability,
        FailureCategory::OperatorAbort,
    ];

    /// `grasp-miss`, `drop`, `collision`, `goal-miss`, `timeout`, `tracking-loss`,
    /// `input-lag`, `reset-failure`, `sim-instability`, `operator-abort`.
    pub fn id(self) -> &'static str {
        match self {
            FailureCategory::GraspMiss => "grasp-miss",
            FailureCategory::Drop => "drop",
            FailureCategory::Collision => "collision",
            FailureCategory::GoalMiss => "goal-miss",
            FailureCategory::Timeout => "timeout",
            FailureCategory::TrackingLoss => "tracking-loss",
            FailureCategory::InputLag => "input-lag",
            FailureCategory::ResetFailure => "reset-failure",
            FailureCategory::SimInstability => "sim-instability",
            FailureCategory::OperatorAbort => "operator-abort",
        }
    }

    /// The category with this id.
    pub fn from_id(id: &str) -> Option<FailureCategory> {
        FailureCategory::ALL.into_iter().find(|c| c.id() == id)
    }

    /// The category of a failure event (`None` for events that are not failures).
    pub fn of_event(event: &Event) -> Option<FailureCategory> {
        match event {
            Event::GraspMiss => Some(FailureCategory::GraspMiss),
            Event::Drop => Some(FailureCategory::Drop),
            Event::Collision { .. } => Some(FailureCategory::Collision),
            Event::Timeout => Some(FailureCategory::Timeout),
            _ => None,
        }
    }
}

/// Latency from which an otherwise unexplained failure is proposed as `input-lag`, steps
/// (100 ms).
pub const INPUT_LAG_STEPS: u32 = 10;

/// The label and category the page proposes (the pilot confirms or changes them):
///
/// - success without a failure event: SUCCESS;
/// - success after a failure event (a grasp miss, drop or collision on the way): PARTIAL,
///   with that event's category;
/// - a timeout or an episode the pilot ended: PARTIAL if it made progress (a target reached,
///   the block grasped), FAILURE otherwise; the category is that of the first failure event
///   (grasp-miss, drop, collision). Without one: `goal-miss` when the block was set down
///   outside the goal; else `tracking-loss` with input noise on, `input-lag` with a latency
///   of [`INPUT_LAG_STEPS`] or more; else `timeout` (timed out) or `operator-abort` (ended by
///   the pilot).
///
/// `reset-failure` and `sim-instability` are never proposed: the page's preflight detects the
/// first, and the pilot names the second.
pub fn proposed_label(episode: &Episode) -> (Label, Option<FailureCategory>) {
    let config = &episode.config;
    let pick = matches!(config.task, Task::PickPlace | Task::PickPlaceObstacle);
    let last_held = episode.records.last().is_some_and(|r| r.held);
    propose(
        &metrics(episode),
        pick && !last_held,
        config.noise_sigma,
        config.latency_steps,
    )
}

/// [`proposed_label`] from an episode's figures: `released` says the episode is a pick task
/// whose object was not held at its end, `noise_sigma` and `latency_steps` are its config's.
pub fn propose(
    m: &EpisodeMetrics,
    released: bool,
    noise_sigma: f64,
    latency_steps: u32,
) -> (Label, Option<FailureCategory>) {
    let first = m
        .first_failure
        .and_then(|(_, e)| FailureCategory::of_event(&e))
        .filter(|c| *c != FailureCategory::Timeout);
    if m.outcome == Some(Outcome::Success) {
        return match first {
            None => (Label::Success, None),
            Some(c) => (Label::Partial, Some(c)),
        };
    }
    let label = if m.targets_reached > 0 || m.grasps > 0 {
        Label::Partial
    } else {
        Label::Failure
    };
    let set_down_outside = released && m.grasps > 0;
    let category = first.unwrap_or(if set_down_outside {
        FailureCategory::GoalMiss
    } else if noise_sigma > 0.0 {
        FailureCategory::TrackingLoss
    } else if latency_steps >= INPUT_LAG_STEPS {
        FailureCategory::InputLag
    } else if m.outcome == Some(Outcome::Timeout) {
        FailureCategory::Timeout
    } else {
        FailureCategory::OperatorAbort
    });
    (label, Some(category))
}

#[cfg(test)]
mod tests;
