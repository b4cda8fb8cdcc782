//! The PID step page (`#/pid-step`), plain Rust: the step-response figures computed from the
//! exact samples the CSV holds (no interpolation), against the recipe's unit setpoint r.
//!
//! - rise time (10–90 %): the `t` of the first row with `y ≥ 0.9 r` minus that of the first
//!   row with `y ≥ 0.1 r` (none when y never gets there);
//! - overshoot: `(max y − r) / r`, in %, 0 when y stays below r;
//! - settling time (2 % band): the `t` of the row after the last one with `|y − r| > 0.02 |r|`
//!   (none when the last row is still outside: not settled within the run);
//! - steady-state error: `r − y` of the last row;
//! - peak u: the row with the largest `|u|` (its `t` and signed value).
//!
//! Times are the CSV's `t` column (row k: `t = round(k·0.05, 4)` s, y after that step). A
//! response that is not finite has no figures but the peak u where one exists.
//!
//! [`rows`] is the kernel's loop ([`pid_step::response`]: r, y, u and e are the CSV's to
//! the last bit), with `t = k·dt` left unrounded: the CSV rounds every row's time through a
//! decimal formatting (Python's `round`), which costs more than the loop itself; the figures
//! round only the few times they report.

use crate::pyfmt::py_round;
use crate::recipes::pid_step::{self, PidParams, PidSample};
use crate::view::plot::auto_range;
use crate::view::signal::{nice_range, y_extent, SignalRow};

/// The kernel's response of valid `p` ([`pid_step::response`]), with unrounded times `k·dt`,
/// one row at a time, and how many rows (what the page computes, in slices when there are
/// many); none for invalid `p`.
pub fn rows(p: &PidParams) -> Option<(pid_step::Response, u64)> {
    let rows = pid_step::response(p).ok()?;
    Some((rows, u64::try_from(p.steps).unwrap_or(0)))
}

/// A row's time as the CSV writes it (`round(t, 4)`; unchanged for the kernel's rows).
fn csv_t(s: &PidSample) -> f64 {
    py_round(s.t, 4)
}

/// The step-response figures of one run.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct StepFigures {
    pub rise_time: Option<f64>,
    pub overshoot_pct: Option<f64>,
    pub settling_time: Option<f64>,
    pub steady_state_error: Option<f64>,
    /// `(t, u)` of the largest `|u|`.
    pub peak_u: Option<(f64, f64)>,
    pub final_y: Option<f64>,
}

/// Fraction of r the rise starts at and ends at.
const RISE_FROM: f64 = 0.1;
const RISE_TO: f64 = 0.9;
/// Half-width of the settling band, as a fraction of r.
const SETTLE_BAND: f64 = 0.02;

/// The figures of `samples`, in one pass over them (a million rows are 40 MB: six passes,
/// one a figure, were most of a live page's frame).
pub fn figures(samples: &[PidSample]) -> StepFigures {
    let mut out = StepFigures::default();
    let Some(last) = samples.last() else {
        return out;
    };
    let r = last.r;
    let (rise_from, rise_to, band) = (RISE_FROM * r, RISE_TO * r, SETTLE_BAND * r.abs());
    let mut peak_u = None::<(f64, f64)>;
    let mut finite = true;
    let (mut first_from, mut first_to) = (None, None);
    let mut max_y = f64::NEG_INFINITY;
    let mut outside = None;
    for (i, s) in samples.iter().enumerate() {
        // The first of the largest |u| (a later tie does not replace it).
        if s.u.is_finite() && peak_u.is_none_or(|(_, u)| u.abs() < s.u.abs()) {
            peak_u = Some((s.t, s.u));
        }
        if !s.y.is_finite() {
            finite = false;
            continue;
        }
        if first_from.is_none() && s.y >= rise_from {
            first_from = Some(i);
        }
        if first_to.is_none() && s.y >= rise_to {
            first_to = Some(i);
        }
        max_y = max_y.max(s.y);
        if (s.y - r).abs() > band {
            outside = Some(i);
        }
    }
    out.peak_u = peak_u.map(|(t, u)| (py_round(t, 4), u));
    if !finite {
        return out;
    }
    let t_of = |i: usize| csv_t(&samples[i]);
    out.rise_time = first_from.zip(first_to).map(|(a, b)| t_of(b) - t_of(a));
    out.overshoot_pct = Some(((max_y - r) / r * 100.0).max(0.0));
    out.settling_time = match outside {
        None => Some(t_of(0)),
        Some(i) => samples.get(i + 1).map(csv_t),
    };
    out.steady_state_error = Some(r - last.y);
    out.final_y = Some(last.y);
    out
}

/// Gains that reach the recipe's setpoint on its plant (τ = 0.8 s) within its 80 steps:
/// rise time 0.75 s, overshoot 1.5 %, settled (2 % band) at 1.1 s.
pub const TUNED_GAINS: [(&str, &str); 3] = [("Kp", "2"), ("Ki", "3"), ("Kd", "0.05")];

/// Whether the run of gains `p` (figures `f`) stops short of the setpoint: finite, never
/// above r, and still outside the settling band at the end, with an integral gain that is not
/// negative: the proportional action alone leaves that error, the integral term too weak to
/// remove it within the run.
pub fn stops_short(p: &PidParams, f: &StepFigures) -> bool {
    let band = SETTLE_BAND * pid_step::SETPOINT.abs();
    p.ki >= 0.0 && f.overshoot_pct == Some(0.0) && f.steady_state_error.is_some_and(|e| e > band)
}

/// The (lo, hi) of the finite values of a thinned series, clamped to ±1e12 (an overflowed
/// run plots up to where it broke); an empty range (`lo > hi`) when there is none.
pub fn plot_extent(points: &[(f64, f64)]) -> (f64, f64) {
    let clamp = |v: f64| v.clamp(-1e12, 1e12);
    let (lo, hi) = y_extent(points);
    (clamp(lo), clamp(hi))
}

/// The axis range of extents `a` and `b` and the value `with`, padded by 6 % and snapped to
/// 1-2-5 steps.
pub fn plot_range(a: (f64, f64), b: (f64, f64), with: f64) -> (f64, f64) {
    let r = auto_range([a.0, a.1, b.0, b.1, with], 0.06).unwrap_or((-1.0, 1.0));
    nice_range(r)
}

impl SignalRow for PidSample {
    const CURSOR: [&'static str; 4] = ["cursor-t", "cursor-r", "cursor-y", "cursor-u"];

    fn t(&self) -> f64 {
        self.t
    }

    /// The CSV's row: its time as the CSV writes it (`round(t, 4)`).
    fn cursor_values(&self) -> [f64; 4] {
        [csv_t(self), self.r, self.y, self.u]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::recipes::pid_step::{simulate, Entry, PidParams};
    use crate::recipes::testkit::run_strs;

    /// The CSV of `bsv pid-step <raw>` as rows of numbers (t, r, y, u, e).
    fn csv(raw: &[&str]) -> Vec<[f64; 5]> {
        let out = run_strs::<Entry>(raw).unwrap();
        out.files[0]
            .text
            .lines()
            .skip(1)
            .map(|l| {
                let v: Vec<f64> = l.split(',').map(|x| x.parse().unwrap()).collect();
                [v[0], v[1], v[2], v[3], v[4]]
            })
            .collect()
    }

    #[test]
    fn figures_of_a_settling_response_read_the_csv() {
        let raw = ["2", "4", "0.05", "0.8", "300"];
        let p = PidParams {
            kp: 2.0,
            ki: 4.0,
            kd: 0.05,
            tau: 0.8,
            steps: 300,
        };
        let f = figures(&simulate(&p).unwrap());
        let rows = csv(&raw);
        let t_first = |level: f64| rows.iter().find(|r| r[2] >= level).unwrap()[0];
        assert_eq!(f.rise_time, Some(t_first(0.9) - t_first(0.1)));
        let max_y = rows.iter().map(|r| r[2]).fold(f64::MIN, f64::max);
        assert_eq!(f.overshoot_pct, Some(((max_y - 1.0) * 100.0).max(0.0)));
        let last_out = rows
            .iter()
            .rposition(|r| (r[2] - 1.0).abs() > 0.02)
            .unwrap();
        assert_eq!(f.settling_time, Some(rows[last_out + 1][0]));
        assert_eq!(f.steady_state_error, Some(1.0 - rows[299][2]));
        let peak = rows
            .iter()
            .max_by(|a, b| a[3].abs().total_cmp(&b[3].abs()))
            .unwrap();
        assert_eq!(f.peak_u, Some((peak[0], peak[3])));
        assert!(f.overshoot_pct.unwrap() > 0.0, "{f:?}");
        assert!(f.settling_time.unwrap() < 15.0, "{f:?}");
    }

    #[test]
    fn the_fast_response_is_the_kernel_s() {
        for p in [
            PidParams::default(),
            PidParams {
                kp: 2.0,
                ki: 4.0,
                kd: 0.05,
                tau: 0.8,
                steps: 5000,
            },
            PidParams {
                kp: 100.0,
                ki: 0.0,
                kd: 0.0,
                tau: 0.8,
                steps: 600,
            },
            PidParams {
                kp: 2.0,
                ki: 0.0,
                kd: 0.1,
                tau: 0.0,
                steps: 0,
            },
        ] {
            let fast: Vec<PidSample> = rows(&p).unwrap().0.collect();
            let kernel = simulate(&p).unwrap();
            assert_eq!(fast.len(), kernel.len());
            for (f, k) in fast.iter().zip(&kernel) {
                let bits = |s: &PidSample| [s.r, s.y, s.u, s.e].map(f64::to_bits);
                assert_eq!(bits(f), bits(k));
                assert_eq!(py_round(f.t, 4), k.t);
            }
            assert_eq!(figures(&fast), figures(&kernel), "{p:?}");
        }
    }

    #[test]
    fn the_default_run_has_not_risen_to_90_percent() {
        // final_y = 0.7967 after 80 steps: no rise time, no settling, error 0.2033.
        let f = figures(&simulate(&PidParams::default()).unwrap());
        assert_eq!(f.rise_time, None);
        assert_eq!(f.settling_time, None);
        assert_eq!(f.overshoot_pct, Some(0.0));
        assert!((f.steady_state_error.unwrap() - 0.2033).abs() < 1e-4);
        // The first u is the largest: 2.22 (the derivative kick of the step).
        assert_eq!(f.peak_u, Some((0.0, 2.2199999999999998)));
    }

    #[test]
    fn diverged_and_empty_runs_have_no_response_figures() {
        // A proportional gain so high that the response overflows.
        let gains = PidParams {
            kp: 100.0,
            ki: 0.0,
            kd: 0.0,
            steps: 600,
            ..PidParams::default()
        };
        let wild = simulate(&gains).unwrap();
        let f = figures(&wild);
        assert_eq!(
            (f.rise_time, f.overshoot_pct, f.final_y),
            (None, None, None)
        );
        assert!(f.peak_u.unwrap().1.is_finite());
        assert_eq!(figures(&[]), StepFigures::default());
    }

    #[test]
    fn the_default_run_stops_short_and_the_tuned_gains_settle() {
        let default = PidParams::default();
        assert!(stops_short(
            &default,
            &figures(&simulate(&default).unwrap())
        ));
        let [kp, ki, kd] = TUNED_GAINS.map(|(_, v)| v.parse::<f64>().unwrap());
        let tuned = PidParams {
            kp,
            ki,
            kd,
            ..default
        };
        let f = figures(&simulate(&tuned).unwrap());
        assert!(!stops_short(&tuned, &f));
        assert!(f.rise_time.is_some(), "{f:?}");
        assert!(f.overshoot_pct.unwrap() < 2.0, "{f:?}");
        assert!(f.settling_time.unwrap() < 1.5, "{f:?}");
        assert!(f.steady_state_error.unwrap().abs() < 0.01, "{f:?}");
        // A loop that overshoots or diverges does not stop short.
        let wild = PidParams {
            kp: 100.0,
            ki: 0.0,
            ..default
        };
        assert!(!stops_short(&wild, &figures(&simulate(&wild).unwrap())));
    }

    #[test]
    fn the_cursor_reads_the_csv_row() {
        let row = PidSample {
            t: 0.15000000000000002,
            r: 1.0,
            y: 0.5,
            u: 2.0,
            e: 0.5,
        };
        let values = row.cursor_values();
        assert_eq!(values, [0.15, 1.0, 0.5, 2.0]);
    }

    #[test]
    fn an_overflowed_run_plots_up_to_where_it_broke() {
        let points = [(0.0, 1.0), (0.05, f64::INFINITY), (0.1, -1e300)];
        assert_eq!(plot_extent(&points), (-1e12, 1.0));
        assert_eq!(plot_extent(&[]), (1e12, -1e12));
        let none = (f64::INFINITY, f64::NEG_INFINITY);
        let (lo, hi) = plot_range((0.0, 1.0), none, 1.0);
        assert!(lo < 0.0 && hi > 1.0, "padded: {lo} {hi}");
    }
}
