//! The dataset's JSON files as LeRobot writes them (`json.dump(…, indent=4,
//! ensure_ascii=False)`, floats as Python's `repr`): `meta/info.json`, `meta/stats.json`, and
//! our `meta/bsv_labels.json`; and the features they describe.

use super::frames::{ENVIRONMENT_NAMES, FPS, JOINT_NAMES};
use super::stats::{FeatureStats, StatValues};
use crate::pyfmt::push_py_float;

/// `codebase_version` of `meta/info.json`: the dataset format LeRobot reads since 0.4.
pub const CODEBASE_VERSION: &str = "v3.0";
/// `robot_type`: LeRobot's SO-100/SO-101 follower (`SOFollower.name`).
pub const ROBOT_TYPE: &str = "so_follower";
/// `chunks_size`, `data_files_size_in_mb`, `video_files_size_in_mb`: LeRobot's defaults
/// (`DEFAULT_CHUNK_SIZE` files per chunk, the MB per file before it starts a new one).
pub const CHUNKS_SIZE: u64 = 1000;
/// See [`CHUNKS_SIZE`].
pub const DATA_FILES_SIZE_IN_MB: u64 = 100;
/// See [`CHUNKS_SIZE`].
pub const VIDEO_FILES_SIZE_IN_MB: u64 = 200;
/// `data_path`: the template of the data files (`DEFAULT_DATA_PATH`).
pub const DATA_PATH: &str = "data/chunk-{chunk_index:03d}/file-{file_index:03d}.parquet";

/// A feature's element type.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Dtype {
    /// `float32`.
    Float32,
    /// `int64`.
    Int64,
    /// `bool`.
    Bool,
}

impl Dtype {
    /// The name in `info.json`.
    pub fn name(self) -> &'static str {
        match self {
            Dtype::Float32 => "float32",
            Dtype::Int64 => "int64",
            Dtype::Bool => "bool",
        }
    }
}

/// One feature of `info.json`: a data column.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Feature {
    /// The key (column name).
    pub key: &'static str,
    /// Element type.
    pub dtype: Dtype,
    /// Values per frame (`shape` is `[width]`).
    pub width: usize,
    /// The dimensions' names (`None`: `null`, as LeRobot's default features).
    pub names: Option<&'static [&'static str]>,
}

const fn feature(
    key: &'static str,
    dtype: Dtype,
    width: usize,
    names: Option<&'static [&'static str]>,
) -> Feature {
    Feature {
        key,
        dtype,
        width,
        names,
    }
}

/// The features, in column order: the robot's, the scene's, the outcome flags
/// (`lerobot_eval`'s), then LeRobot's default features (`DEFAULT_FEATURES`).
pub const FEATURES: [Feature; 10] = [
    feature("action", Dtype::Float32, 6, Some(&JOINT_NAMES)),
    feature("observation.state", Dtype::Float32, 6, Some(&JOINT_NAMES)),
    feature(
        "observation.environment_state",
        Dtype::Float32,
        6,
        Some(&ENVIRONMENT_NAMES),
    ),
    feature("next.success", Dtype::Bool, 1, None),
    feature("next.done", Dtype::Bool, 1, None),
    feature("timestamp", Dtype::Float32, 1, None),
    feature("frame_index", Dtype::Int64, 1, None),
    feature("episode_index", Dtype::Int64, 1, None),
    feature("index", Dtype::Int64, 1, None),
    feature("task_index", Dtype::Int64, 1, None),
];

/// A JSON value, written as Python's `json.dump(indent=4)` does.
#[derive(Debug, Clone, PartialEq)]
pub enum Json {
    /// `null`.
    Null,
    /// An integer.
    Int(i64),
    /// A float (Python's `repr`).
    Float(f64),
    /// A string.
    Str(String),
    /// An array.
    Array(Vec<Json>),
    /// An object, keys in order.
    Object(Vec<(String, Json)>),
}

impl Json {
    /// The object of `(key, value)` pairs.
    pub fn object<const N: usize>(pairs: [(&str, Json); N]) -> Json {
        Json::Object(pairs.into_iter().map(|(k, v)| (k.to_string(), v)).collect())
    }

    /// A string.
    pub fn str(s: &str) -> Json {
        Json::Str(s.to_string())
    }

    /// The text, with a final newline-free layout as `json.dump` leaves it.
    pub fn text(&self) -> String {
        let mut out = String::new();
        self.write(&mut out, 0);
        out
    }

    fn write(&self, out: &mut String, depth: usize) {
        let indent = |out: &mut String, depth: usize| {
            out.push('\n');
            out.push_str(&"    ".repeat(depth));
        };
        match self {
            Json::Null => out.push_str("null"),
            Json::Int(i) => out.push_str(&i.to_string()),
            Json::Float(x) => push_py_float(out, *x),
            Json::Str(s) => push_string(out, s),
            Json::Array(items) if items.is_empty() => out.push_str("[]"),
            Json::Object(items) if items.is_empty() => out.push_str("{}"),
            Json::Array(items) => {
                out.push('[');
                for (i, item) in items.iter().enumerate() {
                    if i > 0 {
                        out.push(',');
                    }
                    indent(out, depth + 1);
                    item.write(out, depth + 1);
                }
                indent(out, depth);
                out.push(']');
            }
            Json::Object(items) => {
                out.push('{');
                for (i, (key, value)) in items.iter().enumerate() {
                    if i > 0 {
                        out.push(',');
                    }
                    indent(out, depth + 1);
                    push_string(out, key);
                    out.push_str(": ");
                    value.write(out, depth + 1);
                }
                indent(out, depth);
                out.push('}');
            }
        }
    }
}

/// A JSON string as `json.dumps(ensure_ascii=False)` writes it.
fn push_string(out: &mut String, s: &str) {
    out.push('"');
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            '\t' => out.push_str("\\t"),
            '\u{8}' => out.push_str("\\b"),
            '\u{c}' => out.push_str("\\f"),
            c if u32::from(c) < 0x20 => out.push_str(&format!("\\u{:04x}", u32::from(c))),
            c => out.push(c),
        }
    }
    out.push('"');
}

/// `meta/info.json` for `episodes` episodes of `frames` frames in all and `tasks` tasks.
pub fn info_json(episodes: usize, frames: usize, tasks: usize) -> String {
    let features = FEATURES
        .iter()
        .map(|f| {
            let names = match f.names {
                Some(names) => Json::Array(names.iter().map(|n| Json::str(n)).collect()),
                None => Json::Null,
            };
            let value = Json::object([
                ("dtype", Json::str(f.dtype.name())),
                ("shape", Json::Array(vec![Json::Int(f.width as i64)])),
                ("names", names),
            ]);
            (f.key.to_string(), value)
        })
        .collect();
    let info = Json::object([
        ("codebase_version", Json::str(CODEBASE_VERSION)),
        ("robot_type", Json::str(ROBOT_TYPE)),
        ("total_episodes", Json::Int(episodes as i64)),
        ("total_frames", Json::Int(frames as i64)),
        ("total_tasks", Json::Int(tasks as i64)),
        ("chunks_size", Json::Int(CHUNKS_SIZE as i64)),
        (
            "data_files_size_in_mb",
            Json::Int(DATA_FILES_SIZE_IN_MB as i64),
        ),
        (
            "video_files_size_in_mb",
            Json::Int(VIDEO_FILES_SIZE_IN_MB as i64),
        ),
        ("fps", Json::Int(i64::from(FPS))),
        (
            "splits",
            Json::object([("train", Json::Str(format!("0:{episodes}")))]),
        ),
        ("data_path", Json::str(DATA_PATH)),
        ("video_path", Json::Null),
        ("features", Json::Object(features)),
    ]);
    info.text()
}

/// One feature's statistics as a JSON object (`count` a one-element array).
fn stats_object(stats: &FeatureStats) -> Json {
    Json::Object(
        stats
            .entries()
            .iter()
            .map(|(key, values)| {
                let array = match values {
                    StatValues::Float(v) => v.iter().map(|x| Json::Float(*x)).collect(),
                    StatValues::Count(n) => vec![Json::Int(*n as i64)],
                };
                (key.to_string(), Json::Array(array))
            })
            .collect(),
    )
}

/// `meta/stats.json`: each feature's dataset statistics, in [`FEATURES`] order.
pub fn stats_json(stats: &[FeatureStats]) -> String {
    Json::Object(
        FEATURES
            .iter()
            .zip(stats)
            .map(|(f, s)| (f.key.to_string(), stats_object(s)))
            .collect(),
    )
    .text()
}
