//! The statistics LeRobot keeps of every numeric feature (`compute_stats.py`): per episode
//! ([`FeatureStats::of_episode`], the `stats/<feature>/<stat>` columns of the episodes
//! table) and for the dataset ([`FeatureStats::aggregate`], `meta/stats.json`).
//!
//! Per episode and per dimension, over the episode's `n` frames (`get_feature_stats` with
//! `RunningQuantileStats`): `min`, `max`, `mean`, `std = √max(0, mean(x²) − mean²)`,
//! `count = n`, and the quantiles `q01 q10 q50 q90 q99` read from a 5000-bin histogram
//! between `min − 1e-10` and `max + 1e-10`: the first bin whose cumulative count reaches
//! `q·n`, interpolated linearly inside it. The bin edges are computed in the feature's
//! precision as numpy does (`float32` for `float32` and `bool` features, where `1e-10`
//! vanishes, `float64` for `int64`), so values fall into the same bins; sums are taken in
//! `f64` (LeRobot sums `float32` features in `float32`: means agree to about 1e-7 relative).
//! With fewer than 2 frames every quantile is the mean and `std` numpy's.
//!
//! Over episodes (`aggregate_stats` of LeRobot 0.6.1): the min of the minima, the max of the
//! maxima, the count-weighted mean, the pooled variance `Σ nᵢ (σᵢ² + (μᵢ − μ)²) / Σ nᵢ`, and
//! each quantile the count-weighted mean of the episodes' (an estimate: exact quantiles cannot
//! be recovered from the episodes' summaries).

/// The quantiles LeRobot keeps, with their keys.
pub const QUANTILES: [(f64, &str); 5] = [
    (0.01, "q01"),
    (0.10, "q10"),
    (0.50, "q50"),
    (0.90, "q90"),
    (0.99, "q99"),
];

/// Bins of the quantile histogram (`num_quantile_bins`).
const QUANTILE_BINS: usize = 5000;

/// The padding of the histogram's range (`1e-10` in `RunningQuantileStats`).
const EDGE_PAD: f64 = 1e-10;

/// The precision numpy computes a feature's histogram edges in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Precision {
    /// `float32` and `bool` features.
    Single,
    /// `int64` features.
    Double,
}

/// One feature's statistics, one value per dimension (`count` once).
#[derive(Debug, Clone, PartialEq)]
pub struct FeatureStats {
    /// Smallest value.
    pub min: Vec<f64>,
    /// Largest value.
    pub max: Vec<f64>,
    /// Mean.
    pub mean: Vec<f64>,
    /// Standard deviation (population).
    pub std: Vec<f64>,
    /// Frames counted.
    pub count: u64,
    /// The [`QUANTILES`], in order.
    pub quantiles: [Vec<f64>; 5],
}

impl FeatureStats {
    /// The statistics of one episode's values: `rows[i]` is frame `i`'s vector.
    pub fn of_episode<const D: usize>(rows: &[[f64; D]], precision: Precision) -> FeatureStats {
        let n = rows.len();
        let mut s = FeatureStats {
            min: vec![f64::INFINITY; D],
            max: vec![f64::NEG_INFINITY; D],
            mean: vec![0.0; D],
            std: vec![0.0; D],
            count: n as u64,
            quantiles: Default::default(),
        };
        for q in s.quantiles.iter_mut() {
            *q = vec![0.0; D];
        }
        if n == 0 {
            return s;
        }
        let column = |d: usize| rows.iter().map(move |r| r[d]);
        for d in 0..D {
            let (mut sum, mut sum_sq) = (0.0, 0.0);
            for v in column(d) {
                s.min[d] = s.min[d].min(v);
                s.max[d] = s.max[d].max(v);
                sum += v;
                sum_sq += v * v;
            }
            let mean = sum / n as f64;
            s.mean[d] = mean;
            if n < 2 {
                for q in s.quantiles.iter_mut() {
                    q[d] = mean;
                }
                continue;
            }
            s.std[d] = (sum_sq / n as f64 - mean * mean).max(0.0).sqrt();
            let edges = bin_edges(s.min[d], s.max[d], precision);
            let counts = histogram(column(d), &edges);
            for (q, (level, _)) in s.quantiles.iter_mut().zip(QUANTILES) {
                q[d] = quantile(&counts, &edges, level * n as f64);
            }
        }
        s
    }

    /// The dataset's statistics from its episodes' (see the module docs); `None` without
    /// episodes.
    pub fn aggregate(episodes: &[&FeatureStats]) -> Option<FeatureStats> {
        let first = episodes.first()?;
        let dims = first.mean.len();
        let total: u64 = episodes.iter().map(|e| e.count).sum();
        let mut out = FeatureStats {
            min: first.min.clone(),
            max: first.max.clone(),
            mean: vec![0.0; dims],
            std: vec![0.0; dims],
            count: total,
            quantiles: first.quantiles.clone(),
        };
        for d in 0..dims {
            let weighted: f64 = episodes.iter().map(|e| e.mean[d] * e.count as f64).sum();
            let mean = weighted / total as f64;
            let pooled: f64 = episodes
                .iter()
                .map(|e| (e.std[d].powi(2) + (e.mean[d] - mean).powi(2)) * e.count as f64)
                .sum();
            out.mean[d] = mean;
            out.std[d] = (pooled / total as f64).sqrt();
            for e in &episodes[1..] {
                out.min[d] = out.min[d].min(e.min[d]);
                out.max[d] = out.max[d].max(e.max[d]);
            }
            for k in 0..QUANTILES.len() {
                let weighted: f64 = episodes
                    .iter()
                    .map(|e| e.quantiles[k][d] * e.count as f64)
                    .sum();
                out.quantiles[k][d] = weighted / total as f64;
            }
        }
        Some(out)
    }

    /// The statistics as `(key, values)` in LeRobot's order: `min max mean std count` and
    /// the quantiles (`count` as one value).
    pub fn entries(&self) -> [(&'static str, StatValues<'_>); 10] {
        let q = &self.quantiles;
        [
            ("min", StatValues::Float(&self.min)),
            ("max", StatValues::Float(&self.max)),
            ("mean", StatValues::Float(&self.mean)),
            ("std", StatValues::Float(&self.std)),
            ("count", StatValues::Count(self.count)),
            (QUANTILES[0].1, StatValues::Float(&q[0])),
            (QUANTILES[1].1, StatValues::Float(&q[1])),
            (QUANTILES[2].1, StatValues::Float(&q[2])),
            (QUANTILES[3].1, StatValues::Float(&q[3])),
            (QUANTILES[4].1, StatValues::Float(&q[4])),
        ]
    }
}

/// One statistic's values: a float per dimension, or the count.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum StatValues<'a> {
    /// `min`, `max`, `mean`, `std`, a quantile.
    Float(&'a [f64]),
    /// `count`.
    Count(u64),
}

/// `np.linspace(min − 1e-10, max + 1e-10, 5001)` in the feature's precision.
fn bin_edges(min: f64, max: f64, precision: Precision) -> Vec<f64> {
    let n = QUANTILE_BINS;
    match precision {
        Precision::Single => {
            // float32 − 1e-10 stays float32 in numpy (NEP 50): 1e-10 is made a float32
            // first, and vanishes next to all but tiny values.
            let start = min as f32 - EDGE_PAD as f32;
            let stop = max as f32 + EDGE_PAD as f32;
            let step = (stop - start) / n as f32;
            let mut edges: Vec<f64> = (0..=n)
                .map(|i| f64::from(i as f32 * step + start))
                .collect();
            edges[n] = f64::from(stop);
            edges
        }
        Precision::Double => {
            let (start, stop) = (min - EDGE_PAD, max + EDGE_PAD);
            let step = (stop - start) / n as f64;
            let mut edges: Vec<f64> = (0..=n).map(|i| i as f64 * step + start).collect();
            edges[n] = stop;
            edges
        }
    }
}

/// `np.histogram(values, bins=edges)`: bins closed on the left, the last also on the right.
fn histogram(values: impl Iterator<Item = f64>, edges: &[f64]) -> Vec<f64> {
    let bins = edges.len() - 1;
    let mut counts = vec![0.0; bins];
    for v in values {
        if v < edges[0] || v > edges[bins] {
            continue;
        }
        let at = edges.partition_point(|e| *e <= v);
        counts[at.saturating_sub(1).min(bins - 1)] += 1.0;
    }
    counts
}

/// `_compute_single_quantile`: the first bin whose cumulative count reaches `target`,
/// interpolated inside it.
fn quantile(counts: &[f64], edges: &[f64], target: f64) -> f64 {
    let mut cumsum = Vec::with_capacity(counts.len());
    let mut total = 0.0;
    for c in counts {
        total += c;
        cumsum.push(total);
    }
    let idx = cumsum.partition_point(|c| *c < target);
    if idx == 0 {
        return edges[0];
    }
    if idx >= cumsum.len() {
        return edges[edges.len() - 1];
    }
    let before = cumsum[idx - 1];
    let in_bin = cumsum[idx] - before;
    if in_bin == 0.0 {
        return edges[idx];
    }
    let fraction = (target - before) / in_bin;
    edges[idx] + fraction * (edges[idx + 1] - edges[idx])
}
