//! `teleop_episodes.csv`, one row per episode under [`EPISODES_HEADER`]: written from a
//! session, and read back (RFC 4180 quotes) when saved files are opened again; and the name
//! of each episode's own time series file.

use super::kind::PracticeEpisode;
use super::practice::{category_from_id, label_from_id, label_id, Session};
use crate::pyfmt::push_py_float;
use crate::teleop::episode::{FailureCategory, Label};
use crate::teleop::metrics::EpisodeMetrics;
use crate::teleop::sim::Outcome;

/// The per-episode summary file's name.
pub const EPISODES_NAME: &str = "teleop_episodes.csv";

/// The header of `teleop_episodes.csv`.
pub const EPISODES_HEADER: &str = "id,task,label,category,note,interrupted,outcome,duration_s,path_m,efficiency,collisions,joint_limit_stops,singularity_stops,min_manipulability,fitts_id_bits,throughput_bits_per_s,first_failure_step,first_failure_event,steps";

/// The name of episode `n`'s time series (n from 1).
pub fn episode_file_name(n: usize) -> String {
    format!("teleop_episode_{n}.csv")
}

impl<E: PracticeEpisode> Session<E> {
    /// `teleop_episodes.csv` (`so101_episodes.csv`): one row per episode.
    pub fn episodes_csv(&self) -> String {
        let mut out = String::from(EPISODES_HEADER);
        out.push('\n');
        for e in &self.episodes {
            let m = &e.metrics;
            let mut cells: Vec<String> = vec![
                e.number.to_string(),
                e.episode.task_id().to_string(),
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
            cells.push(e.episode.steps().to_string());
            out.push_str(&cells.join(","));
            out.push('\n');
        }
        out
    }
}

fn outcome_id(m: &EpisodeMetrics) -> &'static str {
    match m.outcome {
        Some(Outcome::Success) => "success",
        Some(Outcome::Timeout) => "timeout",
        None => "ended",
    }
}

fn float(x: f64) -> String {
    let mut s = String::new();
    push_py_float(&mut s, x);
    s
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

/// One row of `teleop_episodes.csv` as read back: what the pilot said about episode `number`.
#[derive(Debug, Clone, PartialEq)]
pub struct TableRow {
    /// The episode's number (from 1): its file is `<prefix>_episode_<number>.csv`.
    pub number: usize,
    /// The pilot's label, if any.
    pub label: Option<Label>,
    /// The failure category, if any.
    pub category: Option<FailureCategory>,
    /// The pilot's note.
    pub note: String,
    /// Cut off by a reload or a crash of the tab.
    pub interrupted: bool,
}

/// A cell of `teleop_episodes.csv` that cannot be read: its row (the header is row 1) and
/// column.
#[derive(Debug, Clone, PartialEq)]
pub struct BadCell {
    /// The row, the header row 1.
    pub row: usize,
    /// The column's name.
    pub column: String,
}

/// The rows of `teleop_episodes.csv` (a byte order mark and CRLF line ends are read too).
pub fn parse_episodes_table(text: &str) -> Result<Vec<TableRow>, BadCell> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let bad = |row: usize, column: &str| BadCell {
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
