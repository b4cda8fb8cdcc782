//! Recipe `traj-resample` (`joint_traj_resample.py`): reads a joint trajectory CSV
//! (`t_s,q1,q2,...`) and linearly interpolates every joint onto a uniform time grid.
//!
//! ```text
//! t_new = np.arange(t[0], t[-1] + 1e-12, dt)           (crate::numpy::arange)
//! q_j(x) = np.interp(x, t, q_j):  j = max{k : t[k] <= x}
//!          x == t[j] or j is the last sample  ->  q[j]
//!          otherwise  ->  slope (x - t[j]) + q[j],  slope = (q[j+1] - q[j]) / (t[j+1] - t[j])
//!          (below t[0] -> q[0], above t[-1] -> q[-1])
//! ```
//!
//! Without a path (or with an empty one, Python's `if not path:`) the recipe writes its labeled
//! synthetic sample `traj_sample_labeled.csv` and resamples that. A path names an input file
//! attached to the run ([`Args::input`]): the CLI reads it from disk, the browser passes what the
//! user opened.
//!
//! The CSV reader follows Python's `csv.DictReader` (RFC 4180 quoting with `""` escapes, `\r\n`,
//! `\n` or `\r` line ends, blank lines skipped), plus: a UTF-8 byte-order mark is dropped, blank
//! lines before the header are skipped too, and the checks the reference leaves to Python
//! tracebacks are errors naming the row and column: ragged rows, cells that are not finite
//! numbers, fewer than 2 rows, no joint columns, a header of more than [`MAX_COLUMNS`] columns,
//! and time that is not strictly increasing (the reference does not check that; np.interp
//! silently gives nonsense). What is not text (UTF-16, NUL bytes, bytes that are not UTF-8) is
//! refused before this reader by [`crate::recipes::decode_input`]. The `note` column is
//! dropped, as in the recipe. Rows are the 1-based line of the file a record starts on (the
//! header is row 1).

use glam::DVec2;
use std::borrow::Cow;
use std::collections::{HashMap, HashSet};

use super::info::RecipeInfo;
use super::kernel::{plan_of, Kernel, Progress, RunResult};
use super::output::{CsvFile, RecipeOutput};
use super::picture::{
    pairs,
    series::{BLUE, ORANGE},
    Mark, Picture, Table, UnitFrame,
};
use crate::args::{finite, positive, rows_within, ArgKind, ArgSpec, Args, Bound};
use crate::error::RecipeError;
use crate::numpy::{arange, arange_len};
use crate::pyfmt::{push_fixed, py_float, CsvText};

/// Largest input CSV accepted, in bytes (128 MiB): a million rows of six joints is about 60 MB.
pub const MAX_INPUT_BYTES: u64 = 128 * 1024 * 1024;

/// Largest output, in cells (output rows × joints): 20 million, about 300 MB of CSV text.
pub const MAX_OUTPUT_CELLS: u64 = 20_000_000;

/// Largest input, in numeric cells (data rows × (1 + joints)): 20 million, 160 MB of `f64`.
/// Keeps a 128 MiB file of tiny cells from exhausting a browser tab's memory; a million rows of
/// six joints is 7 million.
pub const MAX_INPUT_CELLS: u64 = 20_000_000;

/// Most columns a header may have (time, joints, `note`): a thousand joints is far beyond any
/// arm; a file with a million columns is refused after reading its header line, before any
/// plot or table of that width is made.
pub const MAX_COLUMNS: usize = 1000;

/// The output CSV.
pub const RESAMPLED_NAME: &str = "traj_resampled.csv";

/// The labeled sample the recipe writes when no path is given.
pub const SAMPLE_NAME: &str = "traj_sample_labeled.csv";

/// The recipe's synthetic sample, byte for byte (`\n` line ends, as Python writes it on Linux).
pub const SAMPLE: &str = "t_s,q1,q2,note
0.00,0.0,0.0,example-row
0.10,0.2,0.1,example-row
0.25,0.5,0.4,example-row
0.40,0.7,0.6,example-row
0.55,0.6,0.5,example-row
";

/// Name of the time column.
pub const TIME_COLUMN: &str = "t_s";

/// A column the recipe drops.
pub const NOTE_COLUMN: &str = "note";

/// Fewest data rows that can be interpolated.
pub const MIN_ROWS: usize = 2;

/// Added to the last time so that it lands on the grid despite rounding (the recipe's `1e-12`).
const END_PAD_S: f64 = 1e-12;

const ARGS: [ArgSpec; 2] = [
    ArgSpec::number(
        "csv_path",
        "",
        "trajectory CSV with t_s,q1,q2,... (empty: the labeled sample)",
    )
    .kind(ArgKind::File)
    .hint("recipe-traj-resample-hint-csv_path"),
    ArgSpec::number("dt", "0.02", "time step of the uniform grid, seconds")
        .unit("s")
        .limits(Bound::Excl(0.0), Bound::None)
        .hint("recipe-traj-resample-hint-dt"),
];

/// What the recipe is, takes and writes.
pub const INFO: RecipeInfo = RecipeInfo {
    id: "traj-resample",
    python: "joint_traj_resample.py",
    args: &ARGS,
    flags: &[],
    writes: &[RESAMPLED_NAME, SAMPLE_NAME],
    quirks_id: "recipe-traj-resample-quirks",
    plan: plan_of::<Entry>,
    page: Some("traj-resample"),
};

/// The recipe's arguments; `Default` is the recipe's (the sample, 0.02 s).
#[derive(Debug, Clone, PartialEq)]
pub struct ResampleParams {
    /// Name of the attached input CSV; empty means the labeled sample.
    pub csv_path: String,
    /// Grid step, seconds.
    pub dt: f64,
}

impl Default for ResampleParams {
    fn default() -> Self {
        ResampleParams {
            csv_path: String::new(),
            dt: 0.02,
        }
    }
}

impl ResampleParams {
    /// Checks `dt > 0` (the output size is checked by [`resample`], which knows the span).
    pub fn validate(&self) -> Result<(), RecipeError> {
        finite(ARGS[1].name, self.dt)?;
        positive(ARGS[1].name, self.dt)?;
        Ok(())
    }

    /// Whether the run uses the labeled sample (Python's `not path`).
    pub fn uses_sample(&self) -> bool {
        self.csv_path.is_empty()
    }

    /// Reads the recipe's positional arguments.
    pub fn from_args(args: &Args) -> Result<ResampleParams, RecipeError> {
        Ok(ResampleParams {
            csv_path: args.text(0, &ARGS[0]).to_string(),
            dt: args.f64(1, &ARGS[1])?,
        })
    }
}

/// A parsed trajectory: time and one series per joint column.
#[derive(Debug, Clone, PartialEq)]
pub struct Trajectory {
    /// Joint column names in file order (without `t_s` and `note`).
    pub columns: Vec<String>,
    /// Sample times, seconds, strictly increasing.
    pub t: Vec<f64>,
    /// `q[j][i]`: joint `columns[j]` at `t[i]`.
    pub q: Vec<Vec<f64>>,
}

impl Trajectory {
    /// Number of samples (data rows).
    pub fn len(&self) -> usize {
        self.t.len()
    }

    /// Whether it has no samples.
    pub fn is_empty(&self) -> bool {
        self.t.is_empty()
    }

    /// Checks the invariants a hand-built trajectory may break: at least [`MIN_ROWS`] samples,
    /// one series per column, each as long as `t`, finite and strictly increasing time.
    pub fn validate(&self) -> Result<(), RecipeError> {
        if self.columns.is_empty() || self.q.is_empty() {
            return Err(RecipeError::CsvNoJointColumns);
        }
        if self.t.len() < MIN_ROWS {
            return Err(RecipeError::CsvTooFewRows {
                rows: self.t.len(),
                min: MIN_ROWS,
            });
        }
        if self.q.len() != self.columns.len() {
            return Err(RecipeError::WrongCount {
                param: "columns".to_string(),
                expected: self.columns.len(),
                got: self.q.len(),
            });
        }
        for (name, series) in self.columns.iter().zip(&self.q) {
            if series.len() != self.t.len() {
                return Err(RecipeError::WrongCount {
                    param: name.clone(),
                    expected: self.t.len(),
                    got: series.len(),
                });
            }
        }
        for (i, t) in self.t.iter().enumerate() {
            if !t.is_finite() {
                return Err(RecipeError::CsvBadCell {
                    row: i + 2,
                    column: TIME_COLUMN.to_string(),
                    value: py_float(*t),
                });
            }
        }
        if let Some(i) = self.t.windows(2).position(|w| w[1] <= w[0]) {
            return Err(RecipeError::CsvTimeNotIncreasing { row: i + 3 });
        }
        Ok(())
    }
}

/// The trajectory on the uniform grid.
#[derive(Debug, Clone, PartialEq)]
pub struct Resampled {
    /// Joint column names, as in the input.
    pub columns: Vec<String>,
    /// Grid times `np.arange(t[0], t[-1] + 1e-12, dt)`.
    pub t: Vec<f64>,
    /// `q[j][i]`: joint `columns[j]` at `t[i]`.
    pub q: Vec<Vec<f64>>,
}

impl Resampled {
    /// The recipe's `traj_resampled.csv`: `t_s` with 6 decimals, joints with 8, `\r\n` ends.
    pub fn to_csv(&self) -> String {
        self.to_csv_with(&mut Progress::silent(), (0, 1))
    }

    /// [`Self::to_csv`] reporting its rows as phase `phase.0` of `phase.1` of `progress`.
    pub fn to_csv_with(&self, progress: &mut Progress, phase: (u64, u64)) -> String {
        let n = self.t.len() as u64;
        let mut header = vec![TIME_COLUMN];
        header.extend(self.columns.iter().map(String::as_str));
        let mut out = CsvText::with_header(&header).finish();
        out.reserve(self.t.len() * (10 + 12 * self.q.len()));
        for (i, ti) in self.t.iter().enumerate() {
            progress.phase_at(phase.0, phase.1, i as u64, n);
            push_fixed(&mut out, *ti, 6);
            for series in &self.q {
                out.push(',');
                push_fixed(&mut out, series.get(i).copied().unwrap_or(f64::NAN), 8);
            }
            out.push_str("\r\n");
        }
        out
    }
}

/// Where one query point falls in the sample times (numpy's `binary_search_with_guess` result
/// already reduced to the two cases `arr_interp` distinguishes).
#[derive(Debug, Clone, Copy, PartialEq)]
enum Bracket {
    /// Take sample `j` as is: `x == t[j]`, `j` is the last sample, or `x` is outside the range.
    Sample(usize),
    /// Interpolate between samples `j` and `j + 1`.
    Between(usize),
}

/// Brackets every `x` in `xp` (strictly increasing, at least one value): `j` is the largest
/// index with `xp[j] <= x`. A moving guess makes sorted queries linear time.
fn brackets(x: &[f64], xp: &[f64]) -> Vec<Bracket> {
    let last = xp.len().saturating_sub(1);
    let (Some(&first_t), Some(&last_t)) = (xp.first(), xp.last()) else {
        return Vec::new();
    };
    let mut j = 0usize;
    x.iter()
        .map(|&xv| {
            if xv.is_nan() || xv < first_t {
                return Bracket::Sample(0);
            }
            if xv > last_t {
                return Bracket::Sample(last);
            }
            if xp.get(j).is_some_and(|&v| v > xv) {
                // Unsorted query: search from scratch.
                j = xp.partition_point(|&v| v <= xv).saturating_sub(1);
            }
            while xp.get(j + 1).is_some_and(|&v| v <= xv) {
                j += 1;
            }
            if j >= last || xp.get(j) == Some(&xv) {
                Bracket::Sample(j)
            } else {
                Bracket::Between(j)
            }
        })
        .collect()
}

/// `np.interp(x, xp, fp)` with numpy's defaults (`left = fp[0]`, `right = fp[-1]`), operation for
/// operation, for strictly increasing `xp` and `fp` as long as `xp`. NaN queries give NaN.
///
/// # Example
/// ```
/// use bsv_playground::recipes::traj_resample::interp;
/// assert_eq!(interp(&[0.5, 2.0, -1.0], &[0.0, 1.0], &[10.0, 20.0]), vec![15.0, 20.0, 10.0]);
/// ```
pub fn interp(x: &[f64], xp: &[f64], fp: &[f64]) -> Vec<f64> {
    let b = brackets(x, xp);
    x.iter()
        .zip(&b)
        .map(|(&xv, &br)| interp_at(xv, br, xp, fp))
        .collect()
}

fn interp_at(x: f64, bracket: Bracket, xp: &[f64], fp: &[f64]) -> f64 {
    if x.is_nan() {
        return x;
    }
    let at = |v: &[f64], k: usize| v.get(k).copied().unwrap_or(f64::NAN);
    match bracket {
        Bracket::Sample(j) => at(fp, j),
        Bracket::Between(j) => {
            let (x0, x1, y0, y1) = (at(xp, j), at(xp, j + 1), at(fp, j), at(fp, j + 1));
            let slope = (y1 - y0) / (x1 - x0);
            let value = slope * (x - x0) + y0;
            if !value.is_nan() {
                return value;
            }
            // numpy: if we get nan in one direction, try the other.
            let value = slope * (x - x1) + y1;
            if value.is_nan() && y0 == y1 {
                y0
            } else {
                value
            }
        }
    }
}

/// Resamples every joint onto `np.arange(t[0], t[-1] + 1e-12, dt)`. Rejects `dt <= 0` and
/// outputs of more than [`MAX_OUTPUT_CELLS`] cells.
pub fn resample(traj: &Trajectory, dt: f64) -> Result<Resampled, RecipeError> {
    resample_with(traj, dt, &mut Progress::silent(), (0, 1))
}

/// [`resample`] reporting its rows as phase `phase.0` of `phase.1` of `progress`.
pub fn resample_with(
    traj: &Trajectory,
    dt: f64,
    progress: &mut Progress,
    phase: (u64, u64),
) -> Result<Resampled, RecipeError> {
    positive(ARGS[1].name, dt)?;
    finite(ARGS[1].name, dt)?;
    traj.validate()?;
    let (start, stop) = match (traj.t.first(), traj.t.last()) {
        (Some(a), Some(b)) => (*a, *b + END_PAD_S),
        _ => {
            return Err(RecipeError::CsvTooFewRows {
                rows: 0,
                min: MIN_ROWS,
            })
        }
    };
    let joints = traj.q.len() as f64;
    rows_within(
        ARGS[1].name,
        &[ARGS[0].name],
        arange_len(start, stop, dt) * joints,
        MAX_OUTPUT_CELLS,
    )?;
    let t = arange(start, stop, dt, ARGS[1].name, MAX_OUTPUT_CELLS)?;
    let b = brackets(&t, &traj.t);
    let cells = (t.len() * traj.q.len()) as u64;
    let mut q = Vec::with_capacity(traj.q.len());
    for (j, fp) in traj.q.iter().enumerate() {
        let mut series = Vec::with_capacity(t.len());
        for (i, (&x, &br)) in t.iter().zip(&b).enumerate() {
            progress.phase_at(phase.0, phase.1, (j * t.len() + i) as u64, cells);
            series.push(interp_at(x, br, &traj.t, fp));
        }
        q.push(series);
    }
    Ok(Resampled {
        columns: traj.columns.clone(),
        t,
        q,
    })
}

/// Parses a trajectory CSV (see the module docs for the dialect and the checks).
pub fn parse_trajectory(text: &str) -> Result<Trajectory, RecipeError> {
    parse_with_limits(text, MAX_INPUT_BYTES, MAX_INPUT_CELLS)
}

/// The shape of a trajectory CSV, enough to size its resampling, read cheaply (the header,
/// the first and the last data line, and a count of line ends; no cell is parsed beyond
/// those). A file whose last line the quick look cannot read (quotes) is parsed in full.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Shape {
    /// Data rows (lines after the header, blank lines included in a quick look).
    pub rows: u64,
    /// Joint columns (without `t_s` and `note`).
    pub joints: usize,
    pub t_first: f64,
    pub t_last: f64,
}

impl Shape {
    /// Rows of the resampled output at step `dt`.
    pub fn out_rows(&self, dt: f64) -> f64 {
        arange_len(self.t_first, self.t_last + END_PAD_S, dt)
    }
}

/// Reads the [`Shape`] of a trajectory CSV (see there); errors are those the header and the
/// first and last lines show (the run checks every line).
pub fn shape_of(text: &str) -> Result<Shape, RecipeError> {
    let (mut reader, header, layout) = open_csv(text, MAX_INPUT_BYTES)?;
    let mut fields: Vec<Cow<'_, str>> = Vec::new();
    let time_index = layout.slots.iter().position(|s| matches!(s, Slot::Time));
    let time_of = |fields: &[Cow<'_, str>]| -> Option<f64> {
        time_index
            .and_then(|i| fields.get(i))
            .and_then(|f| parse_cell(f))
    };
    let first = match reader.next_record(&mut fields)? {
        Some(_) => time_of(&fields),
        None => None,
    };
    let rest = reader.rest();
    let last_line = rest
        .trim_end_matches(['\r', '\n'])
        .rsplit(['\n', '\r'])
        .next()
        .unwrap_or("");
    let quick_last = if last_line.contains('"') {
        None
    } else {
        let cells: Vec<Cow<'_, str>> = last_line.split(',').map(Cow::Borrowed).collect();
        if cells.len() == header.len() {
            time_of(&cells)
        } else {
            None
        }
    };
    let lines_after_first = rest.bytes().filter(|&c| c == b'\n').count() as u64;
    match (first, quick_last) {
        (Some(t_first), Some(t_last)) if lines_after_first > 0 && t_last > t_first => Ok(Shape {
            rows: 1 + lines_after_first,
            joints: layout.joint_names.len(),
            t_first,
            t_last,
        }),
        _ => {
            // Too odd for a quick look: read it all (the errors are then the run's).
            let traj = parse_trajectory(text)?;
            Ok(Shape {
                rows: traj.len() as u64,
                joints: traj.columns.len(),
                t_first: traj.t.first().copied().unwrap_or(0.0),
                t_last: traj.t.last().copied().unwrap_or(0.0),
            })
        }
    }
}

fn parse_with_limits(
    text: &str,
    max_bytes: u64,
    max_cells: u64,
) -> Result<Trajectory, RecipeError> {
    parse_limited(text, max_bytes, max_cells, &mut Progress::silent())
}

/// A trajectory CSV of at most `max_bytes` opened past its header (a byte-order mark
/// dropped): the reader, the header and its column layout.
fn open_csv(
    text: &str,
    max_bytes: u64,
) -> Result<(CsvReader<'_>, Vec<String>, ColumnLayout), RecipeError> {
    let bytes = text.len() as u64;
    if bytes > max_bytes {
        return Err(RecipeError::InputTooLarge {
            bytes,
            limit: max_bytes,
        });
    }
    let body = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut reader = CsvReader::new(body);
    let mut fields: Vec<Cow<'_, str>> = Vec::new();
    let Some(_) = reader.next_record(&mut fields)? else {
        return Err(RecipeError::CsvTooFewRows {
            rows: 0,
            min: MIN_ROWS,
        });
    };
    if fields.len() > MAX_COLUMNS {
        return Err(RecipeError::CsvTooManyColumns {
            count: fields.len() as u64,
            limit: MAX_COLUMNS as u64,
        });
    }
    let header: Vec<String> = fields.iter().map(|f| f.to_string()).collect();
    let layout = ColumnLayout::new(&header)?;
    Ok((reader, header, layout))
}

/// [`parse_with_limits`] reporting bytes read as the first third of `progress`.
fn parse_limited(
    text: &str,
    max_bytes: u64,
    max_cells: u64,
    progress: &mut Progress,
) -> Result<Trajectory, RecipeError> {
    let (mut reader, header, layout) = open_csv(text, max_bytes)?;
    let mut fields: Vec<Cow<'_, str>> = Vec::new();

    let mut t: Vec<f64> = Vec::new();
    let mut q: Vec<Vec<f64>> = vec![Vec::new(); layout.joint_names.len()];
    let mut row_values = vec![0.0; layout.joint_names.len()];
    let cells_per_row = 1 + layout.joint_names.len() as u64;
    let total_bytes = reader.text.len() as u64;
    while let Some(row) = reader.next_record(&mut fields)? {
        progress.phase_at(0, 3, reader.pos as u64, total_bytes);
        if fields.len() != header.len() {
            return Err(RecipeError::CsvRagged {
                row,
                expected: header.len(),
                got: fields.len(),
            });
        }
        let mut time = 0.0;
        for ((field, slot), name) in fields.iter().zip(&layout.slots).zip(&header) {
            let target = match slot {
                Slot::Ignored => continue,
                Slot::Time => &mut time,
                Slot::Joint(j) => match row_values.get_mut(*j) {
                    Some(v) => v,
                    None => continue,
                },
            };
            *target = parse_cell(field).ok_or_else(|| RecipeError::CsvBadCell {
                row,
                column: name.clone(),
                value: shorten(field),
            })?;
        }
        if t.last().is_some_and(|&prev| time <= prev) {
            return Err(RecipeError::CsvTimeNotIncreasing { row });
        }
        if (t.len() as u64 + 1) * cells_per_row > max_cells {
            // Estimate the file's total from the line ends left, for the message.
            let rows_left = reader.rest().bytes().filter(|&c| c == b'\n').count() as u64;
            return Err(RecipeError::TooLarge {
                param: ARGS[0].name.to_string(),
                count: (t.len() as u64 + 1 + rows_left) * cells_per_row,
                limit: max_cells,
                also: Vec::new(),
                square: false,
            });
        }
        t.push(time);
        for (series, v) in q.iter_mut().zip(&row_values) {
            series.push(*v);
        }
    }
    if t.len() < MIN_ROWS {
        return Err(RecipeError::CsvTooFewRows {
            rows: t.len(),
            min: MIN_ROWS,
        });
    }
    Ok(Trajectory {
        columns: layout.joint_names,
        t,
        q,
    })
}

/// What one header position feeds.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Slot {
    Time,
    Joint(usize),
    Ignored,
}

/// How header positions map to time and joints, with `csv.DictReader`'s dict semantics: a
/// repeated name keeps its first position in the column order and takes the last cell's value.
struct ColumnLayout {
    joint_names: Vec<String>,
    slots: Vec<Slot>,
}

impl ColumnLayout {
    /// Linear in the header width (a one-line file can have millions of columns).
    fn new(header: &[String]) -> Result<ColumnLayout, RecipeError> {
        // Last position of each name; the column order follows first appearances.
        let mut last_index: HashMap<&str, usize> = HashMap::with_capacity(header.len());
        for (i, name) in header.iter().enumerate() {
            last_index.insert(name, i);
        }
        if !last_index.contains_key(TIME_COLUMN) {
            return Err(RecipeError::CsvMissingColumn {
                column: TIME_COLUMN.to_string(),
            });
        }
        let mut slots = vec![Slot::Ignored; header.len()];
        let mut joint_names = Vec::new();
        let mut seen: HashSet<&str> = HashSet::with_capacity(header.len());
        for name in header {
            let Some(&last) = last_index.get(name.as_str()) else {
                continue;
            };
            let first_appearance = seen.insert(name);
            if name == TIME_COLUMN {
                if let Some(slot) = slots.get_mut(last) {
                    *slot = Slot::Time;
                }
            } else if name != NOTE_COLUMN && first_appearance {
                if let Some(slot) = slots.get_mut(last) {
                    *slot = Slot::Joint(joint_names.len());
                }
                joint_names.push(name.clone());
            }
        }
        if joint_names.is_empty() {
            return Err(RecipeError::CsvNoJointColumns);
        }
        Ok(ColumnLayout { joint_names, slots })
    }
}

/// A cell as Python's `float()` reads it (surrounding whitespace, `_` between digits), but
/// only finite values.
fn parse_cell(cell: &str) -> Option<f64> {
    let s = cell.trim();
    let value = match s.parse::<f64>() {
        Ok(v) => v,
        Err(_) if s.contains('_') && underscores_between_digits(s) => {
            s.replace('_', "").parse::<f64>().ok()?
        }
        Err(_) => return None,
    };
    value.is_finite().then_some(value)
}

fn underscores_between_digits(s: &str) -> bool {
    let b = s.as_bytes();
    b.iter().enumerate().all(|(i, &c)| {
        c != b'_'
            || (i > 0
                && b.get(i - 1).is_some_and(u8::is_ascii_digit)
                && b.get(i + 1).is_some_and(u8::is_ascii_digit))
    })
}

/// A cell for an error message: at most 40 characters.
fn shorten(cell: &str) -> String {
    const MAX_CHARS: usize = 40;
    match cell.char_indices().nth(MAX_CHARS) {
        Some((cut, _)) => format!("{}…", &cell[..cut]),
        None => cell.to_string(),
    }
}

/// A minimal reader for Python's `excel` CSV dialect over borrowed text: unquoted fields and
/// quoted fields without `""` are slices of the input, so a large file costs no allocation per
/// cell.
struct CsvReader<'a> {
    text: &'a str,
    pos: usize,
    /// 1-based line at `pos`.
    line: usize,
}

impl<'a> CsvReader<'a> {
    fn new(text: &'a str) -> Self {
        CsvReader {
            text,
            pos: 0,
            line: 1,
        }
    }

    /// The text not read yet.
    fn rest(&self) -> &'a str {
        self.text.get(self.pos..).unwrap_or_default()
    }

    fn byte(&self, at: usize) -> Option<u8> {
        self.text.as_bytes().get(at).copied()
    }

    /// Consumes a line end at `pos` if there is one (`\r\n`, `\n` or `\r`).
    fn eat_line_end(&mut self) -> bool {
        match self.byte(self.pos) {
            Some(b'\n') => {
                self.pos += 1;
                self.line += 1;
                true
            }
            Some(b'\r') => {
                self.pos += 1;
                if self.byte(self.pos) == Some(b'\n') {
                    self.pos += 1;
                }
                self.line += 1;
                true
            }
            _ => false,
        }
    }

    /// Advances to the next `,`, line end or the end; returns the slice passed over.
    fn take_unquoted(&mut self) -> &'a str {
        let start = self.pos;
        let rest = self.text.as_bytes().get(start..).unwrap_or_default();
        let len = rest
            .iter()
            .position(|&c| c == b',' || c == b'\n' || c == b'\r')
            .unwrap_or(rest.len());
        self.pos = start + len;
        self.text.get(start..self.pos).unwrap_or_default()
    }

    /// Reads a quoted field whose opening quote is at `pos`.
    fn take_quoted(&mut self, record_row: usize) -> Result<Cow<'a, str>, RecipeError> {
        self.pos += 1;
        let mut owned: Option<String> = None;
        let mut segment_start = self.pos;
        loop {
            let Some(c) = self.byte(self.pos) else {
                return Err(RecipeError::CsvUnterminatedQuote { row: record_row });
            };
            match c {
                b'"' if self.byte(self.pos + 1) == Some(b'"') => {
                    // An escaped quote: keep one.
                    let piece = self.text.get(segment_start..=self.pos).unwrap_or_default();
                    owned.get_or_insert_with(String::new).push_str(piece);
                    self.pos += 2;
                    segment_start = self.pos;
                }
                b'"' => break,
                b'\n' => {
                    self.line += 1;
                    self.pos += 1;
                }
                b'\r' => {
                    if self.byte(self.pos + 1) != Some(b'\n') {
                        self.line += 1;
                    }
                    self.pos += 1;
                }
                _ => self.pos += 1,
            }
        }
        let last_piece = self.text.get(segment_start..self.pos).unwrap_or_default();
        // Skip the closing quote; like csv's non-strict mode, text after it joins the field.
        self.pos += 1;
        let tail = self.take_unquoted();
        Ok(match owned {
            None if tail.is_empty() => Cow::Borrowed(last_piece),
            owned => {
                let mut field = owned.unwrap_or_default();
                field.push_str(last_piece);
                field.push_str(tail);
                Cow::Owned(field)
            }
        })
    }

    /// Reads the next non-blank record into `fields`; returns the line it starts on, or `None`
    /// at the end of the text.
    fn next_record(
        &mut self,
        fields: &mut Vec<Cow<'a, str>>,
    ) -> Result<Option<usize>, RecipeError> {
        fields.clear();
        while self.eat_line_end() {}
        if self.pos >= self.text.len() {
            return Ok(None);
        }
        let row = self.line;
        loop {
            let field = if self.byte(self.pos) == Some(b'"') {
                self.take_quoted(row)?
            } else {
                Cow::Borrowed(self.take_unquoted())
            };
            fields.push(field);
            if self.byte(self.pos) == Some(b',') {
                self.pos += 1;
                continue;
            }
            self.eat_line_end();
            return Ok(Some(row));
        }
    }
}

/// The text of the CSV `params` resamples: the sample, or the attached input it names.
fn input_text<'a>(params: &ResampleParams, args: &'a Args) -> Result<&'a str, RecipeError> {
    if params.uses_sample() {
        return Ok(SAMPLE);
    }
    args.input(&params.csv_path)
        .ok_or_else(|| RecipeError::InputMissing {
            name: params.csv_path.clone(),
        })
}

/// Runs the recipe on CSV `text` (the sample when `params.uses_sample()`).
pub fn run_text(params: &ResampleParams, text: &str) -> Result<RecipeOutput, RecipeError> {
    run_text_with(params, text, &mut Progress::silent())
}

/// [`run_text`] reporting parsing, resampling and CSV writing (a third each) to `progress`.
pub fn run_text_with(
    params: &ResampleParams,
    text: &str,
    progress: &mut Progress,
) -> Result<RecipeOutput, RecipeError> {
    params.validate()?;
    let traj = parse_limited(text, MAX_INPUT_BYTES, MAX_INPUT_CELLS, progress)?;
    let out = resample_with(&traj, params.dt, progress, (1, 3))?;
    let resampled_line = format!(
        "resampled {} -> {} rows at dt={}s -> {RESAMPLED_NAME}",
        traj.len(),
        out.t.len(),
        py_float(params.dt)
    );
    let mut files = vec![CsvFile {
        name: RESAMPLED_NAME.to_string(),
        text: out.to_csv_with(progress, (2, 3)),
    }];
    let summary = if params.uses_sample() {
        files.push(CsvFile {
            name: SAMPLE_NAME.to_string(),
            text: SAMPLE.to_string(),
        });
        format!("wrote labeled synthetic sample: {SAMPLE_NAME}\n{resampled_line}")
    } else {
        resampled_line
    };
    Ok(RecipeOutput {
        files,
        summary,
        warnings: Vec::new(),
    })
}

/// Reads the positional arguments and validates them (the input is read by the run).
pub fn params_from_args(args: &Args) -> Result<ResampleParams, RecipeError> {
    let params = ResampleParams::from_args(args)?;
    params.validate()?;
    Ok(params)
}

/// The recipe's uniform entry ([`Kernel`]).
pub struct Entry;

impl Kernel for Entry {
    type Params = ResampleParams;
    const INFO: &'static RecipeInfo = &INFO;

    fn params(args: &Args) -> Result<ResampleParams, RecipeError> {
        params_from_args(args)
    }

    /// From the attached input's [`Shape`] (read cheaply): the larger of the input and output
    /// rows; too many output cells is an error naming `dt` and `csv_path`.
    fn rows(params: &ResampleParams, args: &Args) -> Result<u64, RecipeError> {
        let shape = shape_of(input_text(params, args)?)?;
        let out_rows = shape.out_rows(params.dt);
        rows_within(
            ARGS[1].name,
            &[ARGS[0].name],
            out_rows * shape.joints as f64,
            MAX_OUTPUT_CELLS,
        )?;
        Ok((out_rows as u64).max(shape.rows))
    }

    fn run(params: &ResampleParams, args: &Args, progress: &mut Progress) -> RunResult {
        run_text_with(params, input_text(params, args)?, progress)
    }
}

/// The home card's picture: the resampled joints as lines over the labelled samples as dots.
pub fn picture(output: &RecipeOutput, _aspect: f64) -> Option<Picture> {
    let t = Table::parse(output.file(RESAMPLED_NAME)?)?;
    let raw = Table::parse(output.file(SAMPLE_NAME)?)?;
    let x = t.col("t_s")?;
    let (q1, q2) = (t.col("q1")?, t.col("q2")?);
    let (rx, r1, r2) = (raw.col("t_s")?, raw.col("q1")?, raw.col("q2")?);
    let frame = UnitFrame::fit(
        pairs(&x, &q1)
            .into_iter()
            .chain(pairs(&x, &q2))
            .chain(pairs(&rx, &r1))
            .chain(pairs(&rx, &r2)),
        None,
    );
    let m = |v: Vec<DVec2>| v.into_iter().map(|p| frame.map(p)).collect::<Vec<_>>();
    // The resampled joints as lines first, the labelled samples as dots over them.
    let joints = [(&q1, &r1, BLUE), (&q2, &r2, ORANGE)];
    let lines = joints.iter().map(|(q, _, series)| Mark::Line {
        series: *series,
        points: m(pairs(&x, q)),
    });
    let dots = joints.iter().map(|(_, r, series)| Mark::Dots {
        series: *series,
        points: m(pairs(&rx, r)),
    });
    Some(Picture {
        marks: lines.chain(dots).collect(),
    })
}

#[cfg(test)]
mod tests;
