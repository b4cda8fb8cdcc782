//! A session's figures ([`Summary`]: success rate, means, counts by failure category) and the
//! repeatability comparison of two sessions side by side ([`compare`]).

use super::practice::{EpisodeEntry, Session, CATEGORIES};
use crate::teleop::episode::{FailureCategory, Label};

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

impl Session {
    /// The session's figures (success rate, means, counts by category).
    pub fn summary(&self) -> Summary {
        Summary::of(&self.episodes)
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
