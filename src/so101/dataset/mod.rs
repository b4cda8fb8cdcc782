//! The labelled SO-101 practice episodes as a LeRobot dataset, format v3.0 (the only one
//! LeRobot reads since 0.4), so that `LeRobotDataset(repo_id, root=<folder>)` loads it frame
//! by frame. Plain Rust, no web-sys: the `#/so101` page builds it episode by episode
//! ([`DatasetBuilder`]) and zips it ([`zip()`]); `bsv so101-dataset` writes the same files.
//!
//! # Files (paths from the dataset's root)
//! - `meta/info.json`: `codebase_version` `v3.0`, `robot_type` `so_follower`, `fps`, the
//!   [`FEATURES`] (dtype, shape, names), the totals, LeRobot's default chunk and file sizes,
//!   `data_path`, `video_path` null (no camera), `splits` `{"train": "0:N"}`;
//! - `meta/stats.json`: every feature's `min max mean std count q01 q10 q50 q90 q99`,
//!   aggregated over the episodes as LeRobot does ([`stats`]);
//! - `meta/tasks.parquet`: `task_index` and the task, the task the (pandas) index;
//! - `meta/episodes/chunk-000/file-000.parquet`: one row per episode: `episode_index`,
//!   `tasks`, `length`, `data/chunk_index`, `data/file_index`, `dataset_from_index`,
//!   `dataset_to_index`, `stats/<feature>/<stat>`, `meta/episodes/chunk_index`,
//!   `meta/episodes/file_index`;
//! - `data/chunk-000/file-000.parquet`: one row per frame, one row group per episode (a
//!   session stays far below the 100 MB at which LeRobot starts a second file: about 120
//!   bytes a frame);
//! - `meta/bsv_labels.json`: the pilot's label, failure category and note per episode
//!   (LeRobot ignores the file).
//!
//! # Frames
//! 25 frames per second: every 4th step of the 100 Hz simulation. LeRobot records SO-101
//! datasets at 30 fps, which does not divide 100 Hz; 25 is the nearest divisor, and LeRobot
//! only needs `timestamp = frame_index / fps` to hold (its `delta_timestamps` are multiples of
//! `1 / fps`). Frame `k` of an episode is taken before step `4k + 1`: `ceil(steps / 4)`
//! frames.
//!
//! - `observation.state`: the joints measured before the frame's step, in the SO follower's
//!   units with `use_degrees` (LeRobot's default): `shoulder_pan.pos` … `wrist_roll.pos` in
//!   degrees from the middle of the calibrated range, which is the MJCF's zero
//!   (`so101_new_calib`), `gripper.pos` 0–100 over the jaw joint's range (`RANGE_0_100`:
//!   the jaw at −10° reads 0, at 100° reads 100; open 55.97, closed on the cube 24.70,
//!   closed on nothing 9.09);
//! - `action`: what that step commanded, same units: the joints before it plus the IK's
//!   joint step after the speed and position limits, before contact could stop the move
//!   ([`crate::so101::Sim::target_q`]), and the gripper's command (open, or closed on
//!   nothing: a closed leader's jaw);
//! - `observation.environment_state`: the cube's centre (x, y, z in metres), its yaw about
//!   the vertical (radians) and the goal square's centre (x, y in metres), world frame (x
//!   forward from the base, y to the arm's left, z up from the table), before the step;
//! - `next.success`: on the last frame of an episode labelled SUCCESS; `next.done`: on
//!   every episode's last frame;
//! - `timestamp` (`frame_index / 25`, float32), `frame_index`, `episode_index` (the order
//!   episodes are added in), `index` (over the dataset), `task_index`.
//!
//! One task per scene, the goal as a sentence: [`TASK`], or [`TASK_OBSTACLE`] with the wall
//! between cube and goal; task indices in order of first use.

mod archive;
mod arrow_schema;
mod error;
mod frames;
mod meta;
mod parquet_file;
pub mod stats;

pub use archive::zip;
pub use error::DatasetError;
pub use frames::{
    episode_frames, gripper_percent, Frame, FrameReplay, ENVIRONMENT_NAMES, FPS, JOINT_NAMES,
    STEPS_PER_FRAME,
};
pub use meta::{
    Dtype, Feature, CHUNKS_SIZE, CODEBASE_VERSION, DATA_FILES_SIZE_IN_MB, DATA_PATH, FEATURES,
    ROBOT_TYPE, VIDEO_FILES_SIZE_IN_MB,
};
pub use stats::{FeatureStats, Precision, QUANTILES};

use meta::{info_json, stats_json, Json};
use parquet_file::{parquet_file, Column, Values};

use super::episode::Episode;
use crate::teleop::episode::{FailureCategory, Label};

/// The task of the open table.
pub const TASK: &str = "Pick up the blue cube and place it in the green square";
/// The task with the wall (`pick-place-obstacle`).
pub const TASK_OBSTACLE: &str =
    "Pick up the blue cube and place it in the green square, past the wall between them";

/// `meta/info.json`.
pub const INFO_PATH: &str = "meta/info.json";
/// `meta/stats.json`.
pub const STATS_PATH: &str = "meta/stats.json";
/// `meta/tasks.parquet`.
pub const TASKS_PATH: &str = "meta/tasks.parquet";
/// The episodes table (one file: a session has far fewer than LeRobot's 1000 per file).
pub const EPISODES_PATH: &str = "meta/episodes/chunk-000/file-000.parquet";
/// The frames (one file).
pub const DATA_FILE_PATH: &str = "data/chunk-000/file-000.parquet";
/// Our labels, categories and notes.
pub const LABELS_PATH: &str = "meta/bsv_labels.json";

/// A parquet file's bytes, or the writer's refusal naming `file`.
fn parquet_result(
    file: &str,
    bytes: Result<Vec<u8>, ::parquet::errors::ParquetError>,
) -> Result<Vec<u8>, DatasetError> {
    bytes.map_err(|e| DatasetError::Parquet {
        file: file.to_string(),
        detail: e.to_string(),
    })
}

/// An episode added: where its frames are and what the pilot said of it.
#[derive(Debug, Clone, PartialEq)]
struct Added {
    from: usize,
    length: usize,
    task_index: usize,
    label: Label,
    category: Option<FailureCategory>,
    note: String,
    task_id: &'static str,
    stats: Vec<FeatureStats>,
}

/// A dataset built one episode at a time (the page runs it in slices between frames).
///
/// # Example
/// ```
/// use bsv_playground::so101::dataset::{DatasetBuilder, INFO_PATH};
/// use bsv_playground::so101::{Command, Episode, SceneConfig};
/// use bsv_playground::teleop::{FailureCategory, Label};
///
/// let commands = vec![Command::with_axes([0.5, 0.0, -0.2, 0.0, 0.0, 0.0], false); 10];
/// let episode = Episode::record(SceneConfig::default_for(false), &commands).unwrap();
/// let mut builder = DatasetBuilder::new();
/// builder.add_episode(&episode, Label::Failure, Some(FailureCategory::OperatorAbort), "").unwrap();
/// assert_eq!((builder.episodes(), builder.frames()), (1, 3)); // 10 steps: frames at 0, 4, 8
/// let files = builder.finish().unwrap();
/// assert_eq!(files[0].0, INFO_PATH);
/// ```
#[derive(Debug, Clone, Default)]
pub struct DatasetBuilder {
    frames: Vec<Frame>,
    added: Vec<Added>,
    tasks: Vec<&'static str>,
}

impl DatasetBuilder {
    /// An empty dataset.
    pub fn new() -> DatasetBuilder {
        DatasetBuilder::default()
    }

    /// Episodes added.
    pub fn episodes(&self) -> usize {
        self.added.len()
    }

    /// Frames added.
    pub fn frames(&self) -> usize {
        self.frames.len()
    }

    /// Adds an episode as the next `episode_index` (replayed from its start: one pass of the
    /// simulation over its steps, and its statistics).
    pub fn add_episode(
        &mut self,
        episode: &Episode,
        label: Label,
        category: Option<FailureCategory>,
        note: &str,
    ) -> Result<(), DatasetError> {
        let frames = episode_frames(episode)?;
        self.add_frames(episode, frames, label, category, note);
        Ok(())
    }

    /// Adds an episode whose frames were replayed beforehand ([`FrameReplay`], a piece at a
    /// time) as the next `episode_index`.
    pub fn add_frames(
        &mut self,
        episode: &Episode,
        frames: Vec<Frame>,
        label: Label,
        category: Option<FailureCategory>,
        note: &str,
    ) {
        let task = if episode.config.obstacle {
            TASK_OBSTACLE
        } else {
            TASK
        };
        let task_index = match self.tasks.iter().position(|t| *t == task) {
            Some(i) => i,
            None => {
                self.tasks.push(task);
                self.tasks.len() - 1
            }
        };
        let mut added = Added {
            from: self.frames.len(),
            length: frames.len(),
            task_index,
            label,
            category,
            note: note.to_string(),
            task_id: episode.config.task_id(),
            stats: Vec::new(),
        };
        added.stats = episode_stats(&frames, &added, self.added.len());
        self.frames.extend(frames);
        self.added.push(added);
    }

    /// Every file of the dataset, `(path from the root, bytes)`: [`INFO_PATH`],
    /// [`STATS_PATH`], [`TASKS_PATH`], [`EPISODES_PATH`], [`DATA_FILE_PATH`],
    /// [`LABELS_PATH`].
    pub fn finish(self) -> Result<Vec<(String, Vec<u8>)>, DatasetError> {
        let data = self.data_file()?;
        self.finish_with(data)
    }

    /// The data file, [`DATA_FILE_PATH`] (the largest: one row per frame), written apart
    /// from the others so that a page can write it in a task of its own.
    pub fn data_file(&self) -> Result<Vec<u8>, DatasetError> {
        if self.added.is_empty() {
            return Err(DatasetError::NoEpisodes);
        }
        let lengths: Vec<usize> = self.added.iter().map(|a| a.length).collect();
        parquet_result(
            DATA_FILE_PATH,
            parquet_file(&self.data_columns(), &lengths, &[]),
        )
    }

    /// [`DatasetBuilder::finish`] given the data file ([`DatasetBuilder::data_file`]).
    pub fn finish_with(self, data: Vec<u8>) -> Result<Vec<(String, Vec<u8>)>, DatasetError> {
        if self.added.is_empty() {
            return Err(DatasetError::NoEpisodes);
        }
        let dataset_stats: Vec<FeatureStats> = (0..FEATURES.len())
            .filter_map(|k| {
                let each: Vec<&FeatureStats> = self.added.iter().map(|a| &a.stats[k]).collect();
                FeatureStats::aggregate(&each)
            })
            .collect();
        let episodes = parquet_result(
            EPISODES_PATH,
            parquet_file(&self.episode_columns(), &[self.added.len()], &[]),
        )?;
        let tasks = parquet_result(TASKS_PATH, self.tasks_file())?;
        let info = info_json(self.added.len(), self.frames.len(), self.tasks.len());
        Ok(vec![
            (INFO_PATH.to_string(), info.into_bytes()),
            (
                STATS_PATH.to_string(),
                stats_json(&dataset_stats).into_bytes(),
            ),
            (TASKS_PATH.to_string(), tasks),
            (EPISODES_PATH.to_string(), episodes),
            (DATA_FILE_PATH.to_string(), data),
            (LABELS_PATH.to_string(), self.labels_json().into_bytes()),
        ])
    }

    /// The data file's columns, in [`FEATURES`] order.
    fn data_columns(&self) -> Vec<Column> {
        let n = self.frames.len();
        let flat = |pick: fn(&Frame) -> &[f32; 6]| -> Values {
            Values::Float32Fixed {
                width: 6,
                values: self.frames.iter().flat_map(|f| *pick(f)).collect(),
            }
        };
        let (mut success, mut done) = (Vec::with_capacity(n), Vec::with_capacity(n));
        let (mut timestamp, mut frame_index) = (Vec::with_capacity(n), Vec::with_capacity(n));
        let (mut episode_index, mut task_index) = (Vec::with_capacity(n), Vec::with_capacity(n));
        for (e, a) in self.added.iter().enumerate() {
            for k in 0..a.length {
                let last = k + 1 == a.length;
                success.push(last && a.label == Label::Success);
                done.push(last);
                timestamp.push(frame_time(k));
                frame_index.push(k as i64);
                episode_index.push(e as i64);
                task_index.push(a.task_index as i64);
            }
        }
        let values = [
            flat(|f| &f.action),
            flat(|f| &f.state),
            flat(|f| &f.environment),
            Values::Bool(success),
            Values::Bool(done),
            Values::Float32(timestamp),
            Values::Int64(frame_index),
            Values::Int64(episode_index),
            Values::Int64((0..n as i64).collect()),
            Values::Int64(task_index),
        ];
        FEATURES
            .iter()
            .zip(values)
            .map(|(f, v)| (f.key.to_string(), v))
            .collect()
    }

    /// The episodes table's columns, in the order LeRobot writes them.
    fn episode_columns(&self) -> Vec<Column> {
        let ints = |f: &dyn Fn(usize, &Added) -> usize| -> Values {
            Values::Int64(
                self.added
                    .iter()
                    .enumerate()
                    .map(|(e, a)| f(e, a) as i64)
                    .collect(),
            )
        };
        let mut columns: Vec<Column> = vec![
            ("episode_index".into(), ints(&|e, _| e)),
            (
                "tasks".into(),
                Values::Utf8List(
                    self.added
                        .iter()
                        .map(|a| vec![self.tasks[a.task_index].to_string()])
                        .collect(),
                ),
            ),
            ("length".into(), ints(&|_, a| a.length)),
            ("data/chunk_index".into(), ints(&|_, _| 0)),
            ("data/file_index".into(), ints(&|_, _| 0)),
            ("dataset_from_index".into(), ints(&|_, a| a.from)),
            ("dataset_to_index".into(), ints(&|_, a| a.from + a.length)),
        ];
        for (k, feature) in FEATURES.iter().enumerate() {
            let count = self.added.first().map_or(0, |a| a.stats[k].entries().len());
            for s in 0..count {
                let mut floats = Vec::new();
                let mut counts = Vec::new();
                let mut name = "";
                for a in &self.added {
                    let (key, values) = a.stats[k].entries()[s];
                    name = key;
                    match values {
                        stats::StatValues::Float(v) => floats.push(v.to_vec()),
                        stats::StatValues::Count(c) => counts.push(vec![c as i64]),
                    }
                }
                let values = if counts.is_empty() {
                    Values::Float64List(floats)
                } else {
                    Values::Int64List(counts)
                };
                columns.push((format!("stats/{}/{name}", feature.key), values));
            }
        }
        columns.push(("meta/episodes/chunk_index".into(), ints(&|_, _| 0)));
        columns.push(("meta/episodes/file_index".into(), ints(&|_, _| 0)));
        columns
    }

    /// `meta/tasks.parquet`: `task_index` and `task`, with pandas' metadata making `task`
    /// the index (LeRobot reads it with `pd.read_parquet` and looks tasks up by index).
    fn tasks_file(&self) -> Result<Vec<u8>, ::parquet::errors::ParquetError> {
        let columns: Vec<Column> = vec![
            (
                "task_index".into(),
                Values::Int64((0..self.tasks.len() as i64).collect()),
            ),
            (
                "task".into(),
                Values::Utf8(self.tasks.iter().map(|t| t.to_string()).collect()),
            ),
        ];
        parquet_file(
            &columns,
            &[self.tasks.len()],
            &[("pandas", PANDAS_TASKS_METADATA.to_string())],
        )
    }

    /// `meta/bsv_labels.json`.
    fn labels_json(&self) -> String {
        let episodes = self
            .added
            .iter()
            .enumerate()
            .map(|(e, a)| {
                Json::object([
                    ("episode_index", Json::Int(e as i64)),
                    ("task_id", Json::str(a.task_id)),
                    ("label", Json::str(a.label.id())),
                    (
                        "category",
                        a.category.map_or(Json::Null, |c| Json::str(c.id())),
                    ),
                    ("note", Json::str(&a.note)),
                ])
            })
            .collect();
        Json::object([
            ("format", Json::str("bsv-so101-labels")),
            ("version", Json::Int(1)),
            ("episodes", Json::Array(episodes)),
        ])
        .text()
    }
}

/// pandas' metadata of a frame indexed by the string column `task` with the int64 column
/// `task_index` (pandas 2's layout, which pandas 2 and 3 read back with that index).
const PANDAS_TASKS_METADATA: &str = r#"{"index_columns": ["task"], "column_indexes": [{"name": null, "field_name": null, "pandas_type": "unicode", "numpy_type": "object", "metadata": {"encoding": "UTF-8"}}], "columns": [{"name": "task_index", "field_name": "task_index", "pandas_type": "int64", "numpy_type": "int64", "metadata": null}, {"name": "task", "field_name": "task", "pandas_type": "unicode", "numpy_type": "object", "metadata": null}], "creator": {"library": "bsv-playground", "version": "0.1.0"}, "pandas_version": "2.2.3"}"#;

/// Frame `k`'s `timestamp`, s: `k / fps` in float32.
fn frame_time(k: usize) -> f32 {
    (k as f64 / f64::from(FPS)) as f32
}

/// The statistics of episode `episode_index` (frames `frames`, placed as `added` says), one
/// per feature in [`FEATURES`] order.
fn episode_stats(frames: &[Frame], added: &Added, episode_index: usize) -> Vec<FeatureStats> {
    let vector = |pick: fn(&Frame) -> [f32; 6]| -> FeatureStats {
        let rows: Vec<[f64; 6]> = frames.iter().map(|f| pick(f).map(f64::from)).collect();
        FeatureStats::of_episode(&rows, Precision::Single)
    };
    let n = frames.len();
    let scalar = |precision: Precision, value: &dyn Fn(usize) -> f64| -> FeatureStats {
        let rows: Vec<[f64; 1]> = (0..n).map(|k| [value(k)]).collect();
        FeatureStats::of_episode(&rows, precision)
    };
    let last = |k: usize| f64::from(u8::from(k + 1 == n));
    let success = added.label == Label::Success;
    vec![
        vector(|f| f.action),
        vector(|f| f.state),
        vector(|f| f.environment),
        scalar(Precision::Single, &|k| {
            if success {
                last(k)
            } else {
                0.0
            }
        }),
        scalar(Precision::Single, &last),
        scalar(Precision::Single, &|k| f64::from(frame_time(k))),
        scalar(Precision::Double, &|k| k as f64),
        scalar(Precision::Double, &|_| episode_index as f64),
        scalar(Precision::Double, &|k| (added.from + k) as f64),
        scalar(Precision::Double, &|_| added.task_index as f64),
    ]
}

/// The dataset of `episodes` (each with its label, failure category and note), in order: the
/// files of [`DatasetBuilder::finish`].
pub fn dataset_files(
    episodes: &[(&Episode, Label, Option<FailureCategory>, &str)],
) -> Result<Vec<(String, Vec<u8>)>, DatasetError> {
    let mut builder = DatasetBuilder::new();
    for (episode, label, category, note) in episodes {
        builder.add_episode(episode, *label, *category, note)?;
    }
    builder.finish()
}

// The dataset zip written in pieces, so that a page keeps every task short: each labelled
// episode replayed a bounded number of steps at a time (`FrameReplay`) and added; then the
// data file written in one piece, the other files in the next, the zip in the last
// (`ExportJob::writing_next` says when the next piece is one of those, the longest, for a page
// to start a task with it).

/// The zip's name on the page (`data-download`).
pub const ZIP_NAME: &str = "so101_lerobot_v3.zip";

/// An episode with what the pilot said of it: label, failure category, note.
#[derive(Debug, Clone, PartialEq)]
pub struct LabelledEpisode {
    /// The episode.
    pub episode: Episode,
    /// Its label.
    pub label: Label,
    /// Its failure category, if any.
    pub category: Option<FailureCategory>,
    /// The pilot's note.
    pub note: String,
}

/// The dataset of some labelled episodes, written a piece at a time ([`ExportJob::advance`]).
///
/// # Example
/// ```
/// use bsv_playground::so101::dataset::{dataset_files, zip, ExportJob, LabelledEpisode};
/// use bsv_playground::so101::{Command, Episode, SceneConfig};
/// use bsv_playground::teleop::Label;
///
/// let commands = vec![Command::with_axes([0.5, 0.0, -0.2, 0.0, 0.0, 0.0], false); 30];
/// let episode = Episode::record(SceneConfig::default_for(false), &commands).unwrap();
/// let labelled = LabelledEpisode { episode: episode.clone(), label: Label::Success, category: None, note: String::new() };
/// let mut job = ExportJob::new(vec![labelled]);
/// let bytes = loop {
///     if let Some(done) = job.advance(7) {
///         break done.unwrap();
///     }
/// };
/// let whole = zip(&dataset_files(&[(&episode, Label::Success, None, "")]).unwrap()).unwrap();
/// assert_eq!(bytes, whole);
/// ```
#[derive(Debug, Clone)]
pub struct ExportJob {
    episodes: Vec<LabelledEpisode>,
    builder: Option<DatasetBuilder>,
    replay: Option<FrameReplay>,
    next: usize,
    /// The data file, once written (the piece after writes the others).
    data: Option<Vec<u8>>,
    /// The dataset's files, once written (the last piece zips them).
    files: Option<Vec<(String, Vec<u8>)>>,
}

impl ExportJob {
    /// The job for `episodes`, in their order.
    pub fn new(episodes: Vec<LabelledEpisode>) -> ExportJob {
        ExportJob {
            episodes,
            builder: Some(DatasetBuilder::new()),
            replay: None,
            next: 0,
            data: None,
            files: None,
        }
    }

    /// Whether the next piece writes the files or zips them (every episode is in).
    pub fn writing_next(&self) -> bool {
        self.next >= self.episodes.len()
    }

    /// Episodes in the dataset.
    pub fn total(&self) -> usize {
        self.episodes.len()
    }

    /// Episodes added so far.
    pub fn done(&self) -> usize {
        self.next
    }

    /// Replays up to `max_steps` steps (at least one piece of work), or, once every episode is
    /// in, writes the data file, then the others, then zips them: `Some` with the zip's bytes (or why it could not
    /// be written) when the job is over, `None` while there is more to do.
    pub fn advance(&mut self, max_steps: usize) -> Option<Result<Vec<u8>, DatasetError>> {
        match self.step(max_steps.max(1)) {
            Ok(None) => None,
            Ok(Some(bytes)) => Some(Ok(bytes)),
            Err(e) => {
                self.next = self.episodes.len();
                self.builder = None;
                Some(Err(e))
            }
        }
    }

    fn step(&mut self, max_steps: usize) -> Result<Option<Vec<u8>>, DatasetError> {
        let Some(item) = self.episodes.get(self.next) else {
            if let Some(files) = self.files.take() {
                return zip(&files).map(Some);
            }
            if let Some(data) = self.data.take() {
                let builder = self.builder.take().ok_or(DatasetError::NoEpisodes)?;
                self.files = Some(builder.finish_with(data)?);
                return Ok(None);
            }
            let builder = self.builder.as_ref().ok_or(DatasetError::NoEpisodes)?;
            self.data = Some(builder.data_file()?);
            return Ok(None);
        };
        let replay = match self.replay.as_mut() {
            Some(r) => r,
            None => self.replay.insert(FrameReplay::new(&item.episode)?),
        };
        if replay.advance(&item.episode, max_steps)? {
            let frames = self.replay.take().map(FrameReplay::into_frames);
            if let (Some(frames), Some(builder)) = (frames, self.builder.as_mut()) {
                builder.add_frames(&item.episode, frames, item.label, item.category, &item.note);
            }
            self.next += 1;
        }
        Ok(None)
    }
}

#[cfg(test)]
mod tests;
