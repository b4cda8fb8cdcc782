//! The cubic-path page (`#/cubic-path`), plain Rust: the coefficients (the kernel's own
//! operations), the peaks of the sampled path (what the CSV holds), the comparison overlays a
//! teacher may ask for (the quintic with zero end accelerations, and the trapezoid with the
//! same end time, run through the trapezoid-profile kernel) and the plot's ranges.
//!
//! ```text
//! cubic:    q = q0 + Δ (3 s² − 2 s³),            s = t / T,  Δ = q1 − q0
//! quintic:  q = q0 + Δ (10 s³ − 15 s⁴ + 6 s⁵)    (zero end velocity and acceleration)
//! trapezoid: t_acc = T / 3,  vmax = 1.5 |Δ| / T,  amax = 4.5 |Δ| / T²   (ends at T)
//! ```

use crate::recipes::cubic_path::{self, CubicParams, CubicSample};
use crate::recipes::trapezoid_profile::{self, TrapParams};
use crate::view::plot::auto_range;
use crate::view::signal::SignalRow;

/// The kernel's samples of valid `p` ([`cubic_path::samples`]), one at a time, and how many;
/// none for invalid `p`.
pub fn rows(p: &CubicParams) -> Option<(impl Iterator<Item = CubicSample>, u64)> {
    let rows = cubic_path::samples(p).ok()?;
    let n = rows.len() as u64;
    Some((rows, n))
}

/// `q(t) = a0 + a1 t + a2 t² + a3 t³`, computed as the kernel computes it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Coefficients {
    pub a0: f64,
    pub a1: f64,
    pub a2: f64,
    pub a3: f64,
}

/// The coefficients of `p` (same operations as `cubic_path::compute`).
pub fn coefficients(p: &CubicParams) -> Coefficients {
    let (q0, q1, big_t) = (p.q0, p.q1, p.duration_s);
    Coefficients {
        a0: q0,
        a1: 0.0,
        a2: 3.0 * (q1 - q0) / (big_t * big_t),
        a3: -2.0 * (q1 - q0) / (big_t * big_t * big_t),
    }
}

/// The sample with the largest magnitude of a column: its time and signed value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Peak {
    pub t: f64,
    pub value: f64,
}

/// For each of `fs`, the first sample where `|f|` is largest (`None` for no samples), in one
/// pass over `samples`.
pub fn peaks<const N: usize>(
    samples: &[CubicSample],
    fs: [fn(&CubicSample) -> f64; N],
) -> [Option<Peak>; N] {
    let mut best = [None::<Peak>; N];
    for s in samples {
        for (b, f) in best.iter_mut().zip(fs) {
            let v = f(s);
            if b.is_none_or(|b| v.abs() > b.value.abs()) {
                *b = Some(Peak { t: s.t, value: v });
            }
        }
    }
    best
}

/// The page's readouts of one path.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Readouts {
    pub peak_velocity: Option<Peak>,
    pub peak_acceleration: Option<Peak>,
    pub coefficients: Coefficients,
    pub rows: usize,
}

/// The readouts of the path of `p` from its `samples` (as the CSV has them).
pub fn readouts(p: &CubicParams, samples: &[CubicSample]) -> Readouts {
    let [peak_velocity, peak_acceleration] = peaks(samples, [|s| s.qd, |s| s.qdd]);
    Readouts {
        peak_velocity,
        peak_acceleration,
        coefficients: coefficients(p),
        rows: samples.len(),
    }
}

/// The quintic from q0 to q1 in T with zero end velocities and accelerations, `n + 1` samples.
pub fn quintic(p: &CubicParams, n: usize) -> Vec<CubicSample> {
    let (d, big_t) = (p.q1 - p.q0, p.duration_s);
    (0..=n)
        .map(|k| {
            let s = k as f64 / n.max(1) as f64;
            let (s2, s3) = (s * s, s * s * s);
            CubicSample {
                t: s * big_t,
                q: p.q0 + d * (10.0 * s3 - 15.0 * s3 * s + 6.0 * s3 * s2),
                qd: d * (30.0 * s2 - 60.0 * s3 + 30.0 * s2 * s2) / big_t,
                qdd: d * (60.0 * s - 180.0 * s2 + 120.0 * s3) / (big_t * big_t),
            }
        })
        .collect()
}

/// The trapezoid-profile parameters of the move from q0 to q1 that ends at T (a third of the
/// time accelerating, a third cruising, a third braking), sampled `n` times.
pub fn trapezoid_params(p: &CubicParams, n: usize) -> TrapParams {
    let (d, big_t) = ((p.q1 - p.q0).abs(), p.duration_s);
    TrapParams {
        distance: d,
        vmax: 1.5 * d / big_t,
        amax: 4.5 * d / (big_t * big_t),
        dt: big_t / n.max(1) as f64,
    }
}

/// The trapezoid with the same end time, from the trapezoid-profile kernel, shifted to start
/// at q0 and signed like q1 − q0 (`None` when q1 = q0 or the kernel refuses the sizes).
pub fn trapezoid(p: &CubicParams, n: usize) -> Option<Vec<CubicSample>> {
    let profile = trapezoid_profile::compute(&trapezoid_params(p, n)).ok()?;
    let sign = if p.q1 >= p.q0 { 1.0 } else { -1.0 };
    Some(
        profile
            .samples
            .iter()
            .map(|s| CubicSample {
                t: s.t,
                q: p.q0 + sign * s.s,
                qd: sign * s.v,
                qdd: sign * s.a,
            })
            .collect(),
    )
}

/// The range of one panel holding `values` (the finite ones) and zero, padded by 8 %. A page
/// passes its thinned points: each pixel column keeps its lowest and highest value, so the
/// range is the same as the samples'.
pub fn panel_range(values: impl IntoIterator<Item = f64>) -> (f64, f64) {
    let [(lo, hi)] = crate::view::signal::extents(values.into_iter().map(|v| [v]));
    auto_range([lo, hi, 0.0], 0.08).unwrap_or((-1.0, 1.0))
}

/// The time axis: 0 to T with room for dragging T further (a quarter more).
pub fn time_range(p: &CubicParams) -> (f64, f64) {
    (0.0, p.duration_s * 1.25)
}

impl SignalRow for CubicSample {
    const CURSOR: [&'static str; 4] = ["cursor-t", "cursor-q", "cursor-qd", "cursor-qdd"];

    fn t(&self) -> f64 {
        self.t
    }

    fn cursor_values(&self) -> [f64; 4] {
        [self.t, self.q, self.qd, self.qdd]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::recipes::cubic_path::{compute, Entry};
    use crate::recipes::testkit::run_strs;

    fn csv_column(raw: &[&str], col: usize) -> Vec<f64> {
        let out = run_strs::<Entry>(raw).unwrap();
        let text = out.files[0].text.clone();
        text.lines()
            .skip(1)
            .map(|l| l.split(',').nth(col).unwrap().parse().unwrap())
            .collect()
    }

    #[test]
    fn coefficients_give_the_kernel_s_samples_exactly() {
        let p = CubicParams {
            q0: -0.3,
            q1: 2.1,
            duration_s: 1.7,
            dt_s: 0.03,
        };
        let c = coefficients(&p);
        let path = compute(&p).unwrap();
        for s in &path.samples {
            let t = s.t;
            assert_eq!(c.a0 + c.a1 * t + c.a2 * t * t + c.a3 * t * t * t, s.q);
        }
        assert_eq!(
            (c.a2, c.a3),
            (3.0 * 2.4 / (1.7 * 1.7), -2.0 * 2.4 / (1.7 * 1.7 * 1.7))
        );
    }

    #[test]
    fn peaks_are_the_csv_s() {
        let p = CubicParams::default();
        let r = readouts(&p, &compute(&p).unwrap().samples);
        let qd = csv_column(&[], 2);
        let qdd = csv_column(&[], 3);
        let max_abs = |v: &[f64]| v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        assert_eq!(r.peak_velocity.unwrap().value, max_abs(&qd));
        assert_eq!(r.peak_acceleration.unwrap().value.abs(), max_abs(&qdd));
        // Peak velocity 1.5 Δ / T at mid-move; peak acceleration 6 Δ / T² at the start.
        assert!((r.peak_velocity.unwrap().value - 1.8).abs() < 1e-12);
        assert!((r.peak_velocity.unwrap().t - 0.5).abs() < 1e-12);
        assert_eq!(r.peak_acceleration.unwrap().t, 0.0);
        assert_eq!(r.rows, 51);
        // A move down has negative peaks.
        let down = CubicParams { q1: -1.0, ..p };
        let r = readouts(&down, &compute(&down).unwrap().samples);
        assert!(r.peak_velocity.unwrap().value < 0.0);
    }

    #[test]
    fn the_quintic_meets_the_ends_with_zero_rates() {
        let p = CubicParams::default();
        let q = quintic(&p, 200);
        let (first, last) = (q[0], q[200]);
        assert_eq!(
            (first.t, first.q, first.qd, first.qdd),
            (0.0, 0.0, 0.0, 0.0)
        );
        assert!((last.t - 1.0).abs() < 1e-15 && (last.q - 1.2).abs() < 1e-12);
        assert!(last.qd.abs() < 1e-12 && last.qdd.abs() < 1e-9);
        // Peak velocity 15 Δ / (8 T) at mid-move.
        assert!((q[100].qd - 15.0 * 1.2 / 8.0).abs() < 1e-12);
    }

    #[test]
    fn the_trapezoid_ends_at_t_on_q1_as_the_kernel_runs_it() {
        let p = CubicParams {
            q0: 0.5,
            q1: -0.7,
            duration_s: 2.0,
            dt_s: 0.02,
        };
        let tp = trapezoid_params(&p, 300);
        let kernel = trapezoid_profile::compute(&tp).unwrap();
        assert!(!kernel.triangle);
        assert!((kernel.t_total - 2.0).abs() < 1e-12);
        let over = trapezoid(&p, 300).unwrap();
        assert_eq!(over.len(), kernel.samples.len());
        for (o, k) in over.iter().zip(&kernel.samples) {
            assert_eq!((o.t, o.q, o.qd, o.qdd), (k.t, 0.5 - k.s, -k.v, -k.a));
        }
        let last = over.last().unwrap();
        assert!((last.q - -0.7).abs() < 1e-9, "{last:?}");
        assert!(trapezoid(
            &CubicParams {
                q1: 0.0,
                q0: 0.0,
                ..p
            },
            300
        )
        .is_none());
    }

    #[test]
    fn peaks_in_one_pass_are_each_columns_peak() {
        // The plain search of one column, as a reference.
        let peak = |samples: &[CubicSample], f: fn(&CubicSample) -> f64| {
            let mut best: Option<Peak> = None;
            for s in samples {
                let v = f(s);
                if best.is_none_or(|b| v.abs() > b.value.abs()) {
                    best = Some(Peak { t: s.t, value: v });
                }
            }
            best
        };
        for p in [
            CubicParams::default(),
            CubicParams {
                q0: 0.5,
                q1: -2.0,
                duration_s: 3.0,
                dt_s: 0.07,
            },
        ] {
            let path = compute(&p).unwrap();
            let [v, a] = peaks(&path.samples, [|s| s.qd, |s| s.qdd]);
            assert_eq!(v, peak(&path.samples, |s| s.qd));
            assert_eq!(a, peak(&path.samples, |s| s.qdd));
            assert!(v.is_some() && a.is_some());
        }
        assert_eq!(peaks(&[], [|s| s.q]), [None]);
    }

    #[test]
    fn ranges_hold_every_series_and_zero() {
        let p = CubicParams::default();
        let path = compute(&p).unwrap();
        let quint = quintic(&p, 100);
        let all = || path.samples.iter().chain(&quint);
        let [q, qd, qdd] = [
            panel_range(all().map(|s| s.q)),
            panel_range(all().map(|s| s.qd)),
            panel_range(all().map(|s| s.qdd)),
        ];
        assert!(q.0 < 0.0 && q.1 > 1.2);
        assert!(qd.1 > 15.0 * 1.2 / 8.0);
        assert!(qdd.0 < -7.2 && qdd.1 > 7.2);
        assert_eq!(time_range(&p), (0.0, 1.25));
    }
}
