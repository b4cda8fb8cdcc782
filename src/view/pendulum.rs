//! The pendulum page (`#/pendulum-energy`): its run (the recipe's rows kept as they are
//! stepped, for exact step-back), the period estimate from zero crossings, the energy error
//! and drift, the separatrix of the phase portrait and the URL state. Plain Rust, tested
//! natively.
//!
//! ```text
//! energy error   e(t) = (E(t) + W(t) − E(0)) / E(0),   W(t) = Σ b ω² h  (work of the damping)
//! drift          100 · e(t) / t   (% of E(0) per simulated second)
//! separatrix     ω(θ) = ± cos(θ/2) · sqrt(2 m g L / I)   (E = m g L: the top, at rest)
//! period         the time between every other zero crossing of θ
//! ```
//!
//! `E` is the capsule's true energy ([`PendulumRow::true_energy`]). With damping, `E` falls
//! because the damper takes energy out; adding back its work `W` (trapezoid rule over the
//! steps) leaves only what the integrator itself gains or loses.

use crate::error::RecipeError;
use crate::pyfmt::py_float;
use crate::recipes::pendulum_energy::{
    Integrator, Pendulum, PendulumParams, PendulumRow, GRAVITY, INFO,
};
use crate::view::url::IgnoredKey;

/// One integrator's run: the rows taken so far, the work of the damping after each row and
/// the zero crossings of θ.
#[derive(Debug, Clone)]
pub struct Track {
    pendulum: Pendulum,
    start: Pendulum,
    rows: Vec<PendulumRow>,
    /// `W` after each row.
    damping_work: Vec<f64>,
    /// Zero-crossing times of θ (state times, `k h`), in order.
    crossings: Vec<f64>,
}

impl Track {
    /// A track at the start of `params` (already valid).
    pub fn new(params: &PendulumParams) -> Result<Track, RecipeError> {
        let pendulum = Pendulum::new(params)?;
        Ok(Track {
            start: pendulum.clone(),
            pendulum,
            rows: Vec::new(),
            damping_work: Vec::new(),
            crossings: Vec::new(),
        })
    }

    /// Steps until `n` rows exist (never undoes a step).
    pub fn extend_to(&mut self, n: usize) {
        let p = *self.pendulum.params();
        let h = p.timestep_s;
        while self.rows.len() < n {
            let (theta0, omega0) = (self.pendulum.theta(), self.pendulum.omega());
            let row = self.pendulum.step();
            let work = self.damping_work.last().copied().unwrap_or(0.0)
                + p.damping * h * 0.5 * (omega0 * omega0 + row.omega * row.omega);
            if theta0 != 0.0 && theta0 * row.theta <= 0.0 {
                let k = self.rows.len() as f64;
                let frac = theta0 / (theta0 - row.theta);
                self.crossings.push((k + frac) * h);
            }
            self.rows.push(row);
            self.damping_work.push(work);
        }
    }

    /// Rows taken.
    pub fn rows(&self) -> &[PendulumRow] {
        &self.rows
    }

    /// The starting state.
    pub fn start(&self) -> &Pendulum {
        &self.start
    }

    /// `(θ, ω, true energy)` after `index` steps (`index ≤ rows().len()`).
    pub fn state(&self, index: usize) -> (f64, f64, f64) {
        match index.checked_sub(1).and_then(|i| self.rows.get(i)) {
            Some(r) => (r.theta, r.omega, r.true_energy),
            None => (
                self.start.theta(),
                self.start.omega(),
                self.start.true_energy(),
            ),
        }
    }

    /// The energy error `e` after `index` steps (0 at the start, or with no energy).
    pub fn energy_error(&self, index: usize) -> f64 {
        let e0 = self.start.true_energy();
        let Some(i) = index.checked_sub(1) else {
            return 0.0;
        };
        match (self.rows.get(i), self.damping_work.get(i)) {
            (Some(r), Some(w)) => energy_error(e0, r.true_energy, *w),
            _ => 0.0,
        }
    }

    /// The drift after `index` steps, % of `E(0)` per simulated second.
    pub fn drift(&self, index: usize) -> f64 {
        drift_percent_per_s(
            self.energy_error(index),
            index as f64 * self.pendulum.params().timestep_s,
        )
    }

    /// The period estimate from the crossings before the state after `index` steps.
    pub fn period(&self, index: usize) -> Option<f64> {
        let t = index as f64 * self.pendulum.params().timestep_s;
        let n = self.crossings.partition_point(|&c| c <= t + 1e-12);
        period_from_crossings(&self.crossings[..n])
    }
}

/// `(E + W − E0) / E0`; 0 when `E0` is 0 (hanging at rest).
pub fn energy_error(e0: f64, e: f64, damping_work: f64) -> f64 {
    if e0 > 0.0 {
        (e + damping_work - e0) / e0
    } else {
        0.0
    }
}

/// `100 e / t`, % per second (0 at `t = 0`).
pub fn drift_percent_per_s(error: f64, t_s: f64) -> f64 {
    if t_s > 0.0 {
        100.0 * error / t_s
    } else {
        0.0
    }
}

/// The period from zero-crossing times: the time between the last crossing and the one two
/// before it (same direction), or twice the last gap with only two crossings.
pub fn period_from_crossings(crossings: &[f64]) -> Option<f64> {
    match crossings {
        [.., a, _, c] => Some(c - a),
        [a, b] => Some(2.0 * (b - a)),
        _ => None,
    }
}

/// The undamped separatrix's `|ω|` at `θ`: `|cos(θ/2)| sqrt(2 m g L / I)`.
pub fn separatrix_omega(params: &PendulumParams, inertia: f64, theta: f64) -> f64 {
    (theta / 2.0).cos().abs() * (2.0 * params.mass_kg * GRAVITY * params.length_m / inertia).sqrt()
}

/// The separatrix as `n + 1` points over `θ ∈ [−π, π]`, upper branch (`ω ≥ 0`).
pub fn separatrix(params: &PendulumParams, inertia: f64, n: usize) -> Vec<(f64, f64)> {
    let pi = std::f64::consts::PI;
    (0..=n)
        .map(|k| {
            let theta = -pi + 2.0 * pi * k as f64 / n.max(1) as f64;
            (theta, separatrix_omega(params, inertia, theta))
        })
        .collect()
}

/// The page's state in the URL: the recipe's arguments as texts (CLI names), the state time
/// `t` and `compare`.
#[derive(Debug, Clone, PartialEq)]
pub struct PageQuery {
    /// Text of each argument, in [`arg_names`] order (the recipe's defaults where absent).
    pub texts: Vec<String>,
    /// Time of the state to show, seconds.
    pub t: Option<f64>,
    pub compare: bool,
}

/// The recipe's argument names in form order: `duration_s` then every flag.
pub fn arg_names() -> Vec<&'static str> {
    INFO.args
        .iter()
        .chain(INFO.flags.iter())
        .map(|s| s.name)
        .collect()
}

/// The recipe's defaults, in [`arg_names`] order.
pub fn default_texts() -> Vec<String> {
    INFO.args
        .iter()
        .chain(INFO.flags.iter())
        .map(|s| s.default.to_string())
        .collect()
}

impl PageQuery {
    /// Reads the query: known keys are taken as they are (the form validates them), `t` must
    /// be a finite number ≥ 0, `compare` `0`/`1`; anything else is reported.
    pub fn read(query: &[(String, String)]) -> (PageQuery, Vec<IgnoredKey>) {
        let names = arg_names();
        let mut q = PageQuery {
            texts: default_texts(),
            t: None,
            compare: false,
        };
        let mut ignored = Vec::new();
        for (key, value) in query {
            if let Some(i) = names.iter().position(|n| n == key) {
                q.texts[i] = value.clone();
            } else if key == "t" {
                match value.trim().parse::<f64>() {
                    Ok(t) if t.is_finite() && t >= 0.0 => q.t = Some(t),
                    _ => ignored.push(IgnoredKey::invalid(key.clone())),
                }
            } else if key == "compare" {
                match value.as_str() {
                    "1" | "true" => q.compare = true,
                    "0" | "false" => q.compare = false,
                    _ => ignored.push(IgnoredKey::invalid(key.clone())),
                }
            } else {
                ignored.push(IgnoredKey::unknown(key.clone()));
            }
        }
        (q, ignored)
    }

    /// The query: arguments that differ from the defaults, then `t` and `compare` when set.
    pub fn write(&self) -> Vec<(String, String)> {
        let mut out: Vec<(String, String)> = arg_names()
            .into_iter()
            .zip(self.texts.iter().zip(default_texts()))
            .filter(|(_, (text, default))| *text != default)
            .map(|(name, (text, _))| (name.to_string(), text.clone()))
            .collect();
        if let Some(t) = self.t.filter(|t| *t > 0.0) {
            out.push(("t".to_string(), py_float(t)));
        }
        if self.compare {
            out.push(("compare".to_string(), "1".to_string()));
        }
        out
    }
}

/// The recipe's argument list for valid texts (in [`arg_names`] order): the duration, then
/// every flag with its value, as `bsv pendulum-energy` takes them.
pub fn cli_args(texts: &[String]) -> Vec<String> {
    let mut out = Vec::new();
    for (k, (name, text)) in arg_names().into_iter().zip(texts).enumerate() {
        if k == 0 {
            out.push(text.trim().to_string());
        } else {
            out.push(format!("--{name}"));
            out.push(text.trim().to_string());
        }
    }
    out
}

/// Whether only `duration_s` differs from the defaults (then the Python recipe, which takes
/// only the duration, makes the same CSV).
pub fn python_equivalent(params: &PendulumParams) -> bool {
    let d = PendulumParams::default();
    PendulumParams {
        duration_s: d.duration_s,
        ..*params
    } == d
}

/// The other integrator (compare mode).
pub fn other(integrator: Integrator) -> Integrator {
    match integrator {
        Integrator::Euler => Integrator::Rk4,
        Integrator::Rk4 => Integrator::Euler,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn undamped(integrator: Integrator, h: f64) -> PendulumParams {
        PendulumParams {
            damping: 0.0,
            timestep_s: h,
            integrator,
            ..PendulumParams::default()
        }
    }

    #[test]
    fn period_from_crossings_of_a_small_swing() {
        // Small angle: the compound pendulum's period 2π sqrt(I / (m g L/2)).
        let params = PendulumParams {
            angle_deg: 2.0,
            damping: 0.0,
            timestep_s: 0.0005,
            integrator: Integrator::Rk4,
            ..PendulumParams::default()
        };
        let mut track = Track::new(&params).unwrap();
        track.extend_to(10_000);
        let inertia = track.start().joint_inertia();
        let small = 2.0 * std::f64::consts::PI * (inertia / (0.2 * GRAVITY * 0.15)).sqrt();
        let period = track.period(10_000).unwrap();
        assert!((period - small).abs() < 1e-4 * small, "{period} vs {small}");
        // Before the first crossing there is no estimate.
        assert_eq!(track.period(10), None);
    }

    #[test]
    fn period_from_crossing_times() {
        assert_eq!(period_from_crossings(&[]), None);
        assert_eq!(period_from_crossings(&[0.5]), None);
        assert_eq!(period_from_crossings(&[0.5, 1.0]), Some(1.0));
        assert_eq!(period_from_crossings(&[0.5, 1.1, 1.6, 2.2]), Some(1.1));
    }

    #[test]
    fn rk4_drifts_far_less_than_euler() {
        for damping in [0.0, 0.05] {
            let mut euler = Track::new(&PendulumParams {
                damping,
                ..undamped(Integrator::Euler, 0.002)
            })
            .unwrap();
            let mut rk4 = Track::new(&PendulumParams {
                damping,
                ..undamped(Integrator::Rk4, 0.002)
            })
            .unwrap();
            euler.extend_to(2500);
            rk4.extend_to(2500);
            let (de, dr) = (euler.drift(2500).abs(), rk4.drift(2500).abs());
            assert!(de > 1e-4, "euler drift {de}");
            assert!(dr < de / 100.0, "damping {damping}: rk4 {dr} vs euler {de}");
        }
    }

    #[test]
    fn drift_of_undamped_rk4_is_its_energy_error() {
        let mut track = Track::new(&undamped(Integrator::Rk4, 0.01)).unwrap();
        track.extend_to(100);
        let e0 = track.start().true_energy();
        let e = track.rows()[99].true_energy;
        let want = 100.0 * (e - e0) / e0 / 1.0;
        assert!((track.drift(100) - want).abs() < 1e-12);
        assert_eq!(track.drift(0), 0.0);
    }

    #[test]
    fn separatrix_meets_the_top_at_rest() {
        let p = PendulumParams::default();
        let inertia = crate::recipes::pendulum_energy::capsule_joint_inertia(0.3, 0.2, 0.01);
        let pi = std::f64::consts::PI;
        assert!(separatrix_omega(&p, inertia, pi) < 1e-12);
        // At the bottom its kinetic energy is m g L: the energy of resting at the top.
        let w = separatrix_omega(&p, inertia, 0.0);
        assert!((0.5 * inertia * w * w - 0.2 * GRAVITY * 0.3).abs() < 1e-12);
        let pts = separatrix(&p, inertia, 100);
        assert_eq!(pts.len(), 101);
        assert!((pts[50].1 - w).abs() < 1e-12);
    }

    #[test]
    fn step_back_shows_the_kept_rows() {
        let mut track = Track::new(&PendulumParams::default()).unwrap();
        track.extend_to(5);
        let rows = crate::recipes::pendulum_energy::simulate(&PendulumParams {
            duration_s: 0.01,
            ..PendulumParams::default()
        })
        .unwrap();
        assert_eq!(track.rows(), &rows[..]);
        assert_eq!(track.state(3).0, rows[2].theta);
        assert_eq!(track.state(0).0, 120f64.to_radians());
    }

    #[test]
    fn query_round_trip_and_args() {
        let raw = |pairs: &[(&str, &str)]| {
            pairs
                .iter()
                .map(|(k, v)| (k.to_string(), v.to_string()))
                .collect::<Vec<_>>()
        };
        let (q, ignored) = PageQuery::read(&raw(&[
            ("duration_s", "2"),
            ("timestep", "0.001"),
            ("integrator", "rk4"),
            ("t", "0.5"),
            ("compare", "1"),
            ("zoom", "3"),
            ("t", "-1"),
        ]));
        assert_eq!(ignored.len(), 2);
        assert_eq!(q.t, Some(0.5));
        assert!(q.compare);
        let w = q.write();
        assert_eq!(
            w,
            raw(&[
                ("duration_s", "2"),
                ("timestep", "0.001"),
                ("integrator", "rk4"),
                ("t", "0.5"),
                ("compare", "1")
            ])
        );
        assert_eq!(PageQuery::read(&w).0, q);
        let args = cli_args(&q.texts);
        assert_eq!(&args[..3], &["2", "--damping", "0.05"]);
        assert_eq!(args.len(), 15);
        let p = PendulumParams {
            duration_s: 9.0,
            ..PendulumParams::default()
        };
        assert!(python_equivalent(&p));
        assert!(!python_equivalent(&PendulumParams { mass_kg: 1.0, ..p }));
    }
}
