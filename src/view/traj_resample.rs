//! The trajectory-resampling page (`#/traj-resample?csv_path=walk.csv&dt=0.05`): its URL state
//! (the keys are the CLI's argument names; the file itself never leaves the computer, so a
//! link with `csv_path` asks for the file again) and its readouts (rows, joints, time span),
//! computed from the plot envelopes of the input and the output ([`crate::view::envelope`]).

use crate::pyfmt::{group_u64, human};
use crate::recipes::traj_resample::{MAX_INPUT_BYTES, NOTE_COLUMN, TIME_COLUMN};
use crate::view::envelope::Envelope;
use crate::view::url::{IgnoredKey, UrlState};

/// The URL key of the input file's name.
pub const CSV_PATH_KEY: &str = "csv_path";
/// The URL key of the time step.
pub const DT_KEY: &str = "dt";
/// The recipe's default time step, as typed.
pub const DEFAULT_DT: &str = "0.02";

/// What the page's URL holds.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PageQuery {
    /// The opened file's name (`None`: the labeled sample).
    pub csv_path: Option<String>,
    /// The dt field's text, as typed.
    pub dt: String,
}

impl Default for PageQuery {
    fn default() -> PageQuery {
        PageQuery {
            csv_path: None,
            dt: DEFAULT_DT.to_string(),
        }
    }
}

impl UrlState for PageQuery {
    /// Unknown keys are reported; a file name is reported as a file to open again (the page
    /// validates `dt` in its field).
    fn read(query: &[(String, String)]) -> (PageQuery, Vec<IgnoredKey>) {
        let mut out = PageQuery::default();
        let mut ignored = Vec::new();
        for (key, value) in query {
            match key.as_str() {
                CSV_PATH_KEY => {
                    let name = value.trim();
                    out.csv_path = (!name.is_empty()).then(|| name.to_string());
                }
                DT_KEY => out.dt = value.trim().to_string(),
                _ if !ignored.iter().any(|k: &IgnoredKey| &k.key == key) => {
                    ignored.push(IgnoredKey::unknown(key.clone()))
                }
                _ => {}
            }
        }
        if let Some(name) = &out.csv_path {
            ignored.push(IgnoredKey::file(name.clone()));
        }
        (out, ignored)
    }

    /// `csv_path` (a file), then `dt` unless it is the default.
    fn write(&self) -> Vec<(String, String)> {
        let mut pairs = Vec::new();
        if let Some(name) = &self.csv_path {
            pairs.push((CSV_PATH_KEY.to_string(), name.clone()));
        }
        if !self.dt.is_empty() && self.dt != DEFAULT_DT {
            pairs.push((DT_KEY.to_string(), self.dt.clone()));
        }
        pairs
    }
}

/// The joint columns of a trajectory header (without `t_s` and `note`), in order.
pub fn joint_columns(header: &[String]) -> Vec<String> {
    header
        .iter()
        .filter(|h| h.as_str() != TIME_COLUMN && h.as_str() != NOTE_COLUMN)
        .cloned()
        .collect()
}

/// The readouts of a resampling, as shown.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Readings {
    /// Data rows of the input.
    pub rows_in: String,
    /// Rows of the resampled output.
    pub rows_out: String,
    pub joints: String,
    /// First and last time of the input, seconds.
    pub t_first: String,
    pub t_last: String,
    /// `t_last − t_first`, seconds.
    pub duration: String,
}

/// Seconds for reading: nanosecond rounding hides the float noise of a difference
/// (`0.55 − 0.1` reads `0.45`, not `0.45000000000000007`).
fn seconds(s: f64) -> String {
    human((s * 1e9).round() / 1e9)
}

/// The readouts of an input and its resampled output.
pub fn readings(input: &Envelope, output: &Envelope) -> Readings {
    let (first, last) = input.x_span.unwrap_or((0.0, 0.0));
    Readings {
        rows_in: group_u64(input.rows),
        rows_out: group_u64(output.rows),
        joints: joint_columns(&output.header).len().to_string(),
        t_first: seconds(first),
        t_last: seconds(last),
        duration: seconds(last - first),
    }
}

/// Bytes in a MiB.
const MIB: f64 = 1024.0 * 1024.0;

/// The page's refusal of a file over the recipe's limit (the CLI's, [`MAX_INPUT_BYTES`]),
/// before reading any of it: the Fluent id and arguments of the message beside the file
/// picker, sizes in MiB (the file's rounded up to a tenth, so it never reads as the limit).
/// `None` when the file is within the limit.
pub fn file_too_large(
    name: &str,
    bytes: u64,
) -> Option<(&'static str, Vec<(&'static str, String)>)> {
    if bytes <= MAX_INPUT_BYTES {
        return None;
    }
    let size = (bytes as f64 / MIB * 10.0).ceil() / 10.0;
    Some((
        "traj-file-too-large",
        vec![
            ("name", name.to_string()),
            ("size", format!("{size:.1}")),
            ("limit", human(MAX_INPUT_BYTES as f64 / MIB)),
        ],
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::view::envelope::{csv_envelope, BUCKETS};
    use crate::view::url::{build_hash, parse_hash, IgnoredReason};

    fn q(hash: &str) -> Vec<(String, String)> {
        parse_hash(hash).page_query()
    }

    #[test]
    fn the_url_round_trips_and_asks_for_a_named_file_again() {
        let (query, ignored) = PageQuery::read(&q("#/traj-resample"));
        assert_eq!(query, PageQuery::default());
        assert!(ignored.is_empty());
        assert!(query.write().is_empty());
        let state = PageQuery {
            csv_path: Some("walk 1.csv".into()),
            dt: "0.05".into(),
        };
        let hash = build_hash("traj-resample", &state.write());
        assert_eq!(hash, "#/traj-resample?csv_path=walk%201.csv&dt=0.05");
        let (back, ignored) = PageQuery::read(&q(&hash));
        assert_eq!(back, state);
        assert_eq!(ignored, vec![IgnoredKey::file("walk 1.csv")]);
        assert_eq!(ignored[0].reason, IgnoredReason::File);
        let (bad, ignored) = PageQuery::read(&q("#/traj-resample?dt=abc&zoom=2&zoom=3"));
        assert_eq!(bad.dt, "abc", "kept for the field to flag");
        assert_eq!(ignored, vec![IgnoredKey::unknown("zoom")]);
    }

    #[test]
    fn readings_count_rows_joints_and_the_span() {
        let input = csv_envelope(crate::recipes::traj_resample::SAMPLE, BUCKETS);
        let output = csv_envelope("t_s,q1,q2\n0.000000,0.0,0.0\n0.020000,0.04,0.02\n", BUCKETS);
        let r = readings(&input, &output);
        assert_eq!(r.rows_in, "5");
        assert_eq!(r.rows_out, "2");
        assert_eq!(r.joints, "2");
        assert_eq!((r.t_first.as_str(), r.t_last.as_str()), ("0", "0.55"));
        assert_eq!(r.duration, "0.55");
        let late = csv_envelope("t_s,q1\n0.1,0\n0.55,1\n", BUCKETS);
        assert_eq!(readings(&late, &output).duration, "0.45");
        assert_eq!(
            joint_columns(&input.header),
            vec!["q1".to_string(), "q2".to_string()]
        );
    }

    #[test]
    fn a_file_over_128_mib_is_refused_in_mib() {
        assert_eq!(MAX_INPUT_BYTES, 128 * 1024 * 1024);
        assert_eq!(file_too_large("a.csv", MAX_INPUT_BYTES), None);
        let (id, args) = file_too_large("big.csv", MAX_INPUT_BYTES + 1).unwrap();
        assert_eq!(id, "traj-file-too-large");
        let value = |k: &str| args.iter().find(|(n, _)| *n == k).unwrap().1.clone();
        assert_eq!(value("name"), "big.csv");
        assert_eq!(
            value("size"),
            "128.1",
            "rounded up: never reads as the limit"
        );
        assert_eq!(value("limit"), "128");
        let (_, args) = file_too_large("huge.csv", 200 * 1024 * 1024).unwrap();
        assert_eq!(args[1].1, "200.0");
        // Both languages have the message, with every argument.
        let i18n = crate::i18n::I18n::new();
        for lang in [crate::i18n::Lang::En, crate::i18n::Lang::Ja] {
            let args: Vec<(&str, crate::i18n::FluentArg)> =
                args.iter().map(|(k, v)| (*k, v.clone().into())).collect();
            let text = i18n.t_args(lang, id, &args);
            assert!(
                text.contains("huge.csv") && text.contains("200.0") && text.contains("128"),
                "{text}"
            );
        }
    }
}
