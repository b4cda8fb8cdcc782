//! Recipe `pid-step` (`pid_step_response.py`): a discrete PID loop closed around a first-order
//! plant, driven by a unit step.
//!
//! ```text
//! dt = 0.05 s,  a = dt / (tau + dt),  r = 1
//! e = r - y;  integ += e dt;  deriv = (e - e_prev) / dt
//! u = Kp e + Ki integ + Kd deriv;  y += a (u - y)          (row: t = round(k dt, 4), r, y, u, e)
//! ```
//!
//! `round(k*dt, 4)` is Python's: round half to even on the exact binary value, which Rust's
//! `{:.4}` formatting also does (see [`crate::pyfmt::py_round`]).
//!
//! Decisions where the Python recipe is silent or crashes:
//! - `steps` must be a whole number in `[0, MAX_STEPS]` (a negative count gives an empty table
//!   in Python; we reject it; 0 is allowed: header only, `final_y=0.0000`);
//! - `tau` must lie in `[0, TAU_MAX_S]` (`tau = -dt` divides by zero; a negative time constant
//!   has no physical meaning);
//! - the gains may be any finite numbers. An unstable loop grows until it overflows to `inf` and
//!   then `nan`, and the table shows that exactly as Python prints it.

use super::info::RecipeInfo;
use super::kernel::{float_csv_with, plan_of, Kernel, Progress, RunResult};
use super::output::RecipeOutput;
use super::picture::{
    lines,
    series::{BLUE, ORANGE},
    Picture, Table,
};
use crate::args::{check_count, finite, in_range, parse_count, ArgKind, ArgSpec, Args, Bound};
use crate::error::RecipeError;
use crate::error::RecipeWarning;
use crate::pyfmt::{fixed, py_round};

/// Controller and plant sample period, s (fixed in the recipe).
pub const DT_S: f64 = 0.05;
/// Setpoint of the step.
pub const SETPOINT: f64 = 1.0;
/// Most simulation steps: a CSV of about 80 MB is the most a browser tab should build.
pub const MAX_STEPS: i64 = 1_000_000;
/// Largest plant time constant, s (about 11.6 days of plant lag; the loop is 0.05 s).
pub const TAU_MAX_S: f64 = 1e6;

/// The CSV this recipe writes.
pub const FILE_NAME: &str = "pid_step.csv";
const HEADER: [&str; 5] = ["t", "r", "y", "u", "e"];

const ARGS: [ArgSpec; 5] = [
    ArgSpec::number("Kp", "1.2", "proportional gain").hint("recipe-pid-step-hint-Kp"),
    ArgSpec::number("Ki", "0.4", "integral gain, 1/s")
        .unit("1/s")
        .hint("recipe-pid-step-hint-Ki"),
    ArgSpec::number("Kd", "0.05", "derivative gain, s")
        .unit("s")
        .hint("recipe-pid-step-hint-Kd"),
    ArgSpec::number("tau", "0.8", "plant time constant, s")
        .unit("s")
        .limits(Bound::Incl(0.0), Bound::Incl(TAU_MAX_S))
        .hint("recipe-pid-step-hint-tau"),
    ArgSpec::number("steps", "80", "number of 0.05 s steps")
        .kind(ArgKind::Integer)
        .limits(Bound::Incl(0.0), Bound::Incl(MAX_STEPS as f64))
        .hint("recipe-pid-step-hint-steps"),
];

/// A final output this far from the unit setpoint means the loop diverged (a stable loop ends
/// near 1; the default ends at 0.7967).
pub const DIVERGED_ABS: f64 = 1e3;

/// `pid-step`: id, Python file, arguments with the recipe's defaults, output file.
pub const INFO: RecipeInfo = RecipeInfo {
    id: "pid-step",
    python: "pid_step_response.py",
    args: &ARGS,
    flags: &[],
    writes: &[FILE_NAME],
    quirks_id: "recipe-pid-step-quirks",
    plan: plan_of::<Entry>,
    page: Some("pid-step"),
};

/// Controller gains, plant time constant and run length (the recipe's defaults: 1.2, 0.4, 0.05,
/// 0.8 s, 80 steps).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PidParams {
    pub kp: f64,
    pub ki: f64,
    pub kd: f64,
    /// Plant time constant, s.
    pub tau: f64,
    /// Number of steps of [`DT_S`].
    pub steps: i64,
}

impl Default for PidParams {
    fn default() -> Self {
        PidParams {
            kp: 1.2,
            ki: 0.4,
            kd: 0.05,
            tau: 0.8,
            steps: 80,
        }
    }
}

impl PidParams {
    /// Checks every parameter; the error names the first bad one.
    pub fn validate(&self) -> Result<(), RecipeError> {
        finite("Kp", self.kp)?;
        finite("Ki", self.ki)?;
        finite("Kd", self.kd)?;
        finite("tau", self.tau)?;
        in_range("tau", self.tau, 0.0, TAU_MAX_S)?;
        check_count("steps", self.steps, 0, MAX_STEPS)?;
        Ok(())
    }
}

/// One row of the response.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PidSample {
    /// `round(k dt, 4)`, s.
    pub t: f64,
    /// Setpoint.
    pub r: f64,
    /// Plant output after the step.
    pub y: f64,
    /// Controller output.
    pub u: f64,
    /// Error before the step.
    pub e: f64,
}

/// Runs the loop, operation for operation as the recipe.
///
/// # Example
/// ```
/// use bsv_playground::recipes::pid_step::{simulate, summary, PidParams};
/// let rows = simulate(&PidParams::default()).unwrap();
/// assert_eq!(summary(&rows), "wrote 80 PID samples final_y=0.7967 -> pid_step.csv");
/// ```
pub fn simulate(params: &PidParams) -> Result<Vec<PidSample>, RecipeError> {
    simulate_with(params, &mut Progress::silent())
}

/// [`simulate`] reporting its rows as the first half of `progress`.
pub fn simulate_with(
    params: &PidParams,
    progress: &mut Progress,
) -> Result<Vec<PidSample>, RecipeError> {
    let steps = response(params)?;
    let n = steps.len();
    let mut rows = Vec::with_capacity(n);
    for (k, s) in steps.enumerate() {
        progress.phase_at(0, 2, k as u64, n as u64);
        rows.push(PidSample {
            t: py_round(s.t, 4),
            ..s
        });
    }
    Ok(rows)
}

/// The rows of the loop in order, operation for operation as the recipe, with the time
/// `t = k·dt` left unrounded: the CSV prints `round(k dt, 4)` ([`simulate`] rounds), a live
/// plot needs no decimal rounding of every row. The one loop of the recipe.
///
/// # Example
/// ```
/// use bsv_playground::recipes::pid_step::{response, PidParams};
/// let rows: Vec<_> = response(&PidParams::default()).unwrap().collect();
/// assert_eq!(rows.len(), 80);
/// assert_eq!((rows[0].u, rows[7].t), (2.2199999999999998, 7.0 * 0.05));
/// ```
pub fn response(params: &PidParams) -> Result<Response, RecipeError> {
    params.validate()?;
    Ok(Response {
        kp: params.kp,
        ki: params.ki,
        kd: params.kd,
        a: DT_S / (params.tau + DT_S),
        y: 0.0,
        integ: 0.0,
        prev_e: 0.0,
        k: 0,
        steps: usize::try_from(params.steps).unwrap_or(0),
    })
}

/// The iterator of [`response`]: the loop's state between two steps.
#[derive(Debug, Clone)]
pub struct Response {
    kp: f64,
    ki: f64,
    kd: f64,
    /// `dt / (tau + dt)`.
    a: f64,
    y: f64,
    integ: f64,
    prev_e: f64,
    /// The next step, and how many there are.
    k: usize,
    steps: usize,
}

impl Iterator for Response {
    type Item = PidSample;

    fn next(&mut self) -> Option<PidSample> {
        if self.k >= self.steps {
            return None;
        }
        let (dt, r) = (DT_S, SETPOINT);
        let e = r - self.y;
        self.integ += e * dt;
        let deriv = (e - self.prev_e) / dt;
        let u = self.kp * e + self.ki * self.integ + self.kd * deriv;
        self.y = self.y + self.a * (u - self.y);
        self.prev_e = e;
        let t = self.k as f64 * dt;
        self.k += 1;
        Some(PidSample {
            t,
            r,
            y: self.y,
            u,
            e,
        })
    }

    fn size_hint(&self) -> (usize, Option<usize>) {
        let left = self.steps - self.k;
        (left, Some(left))
    }
}

impl ExactSizeIterator for Response {}

/// `pid_step.csv` exactly as the recipe writes it.
pub fn to_csv(samples: &[PidSample]) -> String {
    to_csv_with(samples, &mut Progress::silent())
}

/// [`to_csv`] reporting its rows as the second half of `progress`.
pub fn to_csv_with(samples: &[PidSample], progress: &mut Progress) -> String {
    let rows = samples.iter().map(|s| [s.t, s.r, s.y, s.u, s.e]);
    float_csv_with(&HEADER, rows, progress)
}

/// What looks wrong with a response: an output that overflowed (not finite from some step
/// on) or that ends far from the setpoint (an unstable loop).
pub fn warnings(samples: &[PidSample]) -> Vec<RecipeWarning> {
    if let Some(step) = samples.iter().position(|s| !s.y.is_finite()) {
        return vec![RecipeWarning::NotFinite { step: step as u64 }];
    }
    let final_y = samples.last().map_or(0.0, |s| s.y);
    if (final_y - SETPOINT).abs() > DIVERGED_ABS {
        let peak = samples.iter().fold(0.0f64, |m, s| m.max(s.y.abs()));
        return vec![RecipeWarning::Diverged {
            peak,
            final_value: final_y,
        }];
    }
    Vec::new()
}

/// The line the recipe prints: the final plant output (0 before any step) with 4 decimals.
pub fn summary(samples: &[PidSample]) -> String {
    let final_y = samples.last().map_or(0.0, |s| s.y);
    format!(
        "wrote {} PID samples final_y={} -> {FILE_NAME}",
        samples.len(),
        fixed(final_y, 4)
    )
}

/// Parses the recipe's arguments (any whole-number notation for `steps`) and validates them.
pub fn params_from_args(args: &Args) -> Result<PidParams, RecipeError> {
    let params = PidParams {
        kp: args.f64(0, &ARGS[0])?,
        ki: args.f64(1, &ARGS[1])?,
        kd: args.f64(2, &ARGS[2])?,
        tau: args.f64(3, &ARGS[3])?,
        steps: parse_count(ARGS[4].name, args.text(4, &ARGS[4]), 0, MAX_STEPS)?,
    };
    params.validate()?;
    Ok(params)
}

/// The recipe's uniform entry ([`Kernel`]).
pub struct Entry;

impl Kernel for Entry {
    type Params = PidParams;
    const INFO: &'static RecipeInfo = &INFO;

    fn params(args: &Args) -> Result<PidParams, RecipeError> {
        params_from_args(args)
    }

    fn rows(params: &PidParams, _args: &Args) -> Result<u64, RecipeError> {
        Ok(params.steps.unsigned_abs())
    }

    fn run(params: &PidParams, _args: &Args, progress: &mut Progress) -> RunResult {
        let rows = simulate_with(params, progress)?;
        let csv = to_csv_with(&rows, progress);
        Ok(RecipeOutput::single(FILE_NAME, csv, summary(&rows)).with_warnings(warnings(&rows)))
    }
}

/// The home card's picture: the setpoint and the plant's response over time.
pub fn picture(output: &RecipeOutput, _aspect: f64) -> Option<Picture> {
    let t = Table::parse(output.file(FILE_NAME)?)?;
    Some(lines(
        &t.col("t")?,
        &[(&t.col("r")?, ORANGE), (&t.col("y")?, BLUE)],
    ))
}

#[cfg(test)]
mod tests {
    #[cfg(target_arch = "wasm32")]
    use wasm_bindgen_test::wasm_bindgen_test as test;

    use super::*;
    use crate::recipes::testkit::{assert_rejects, run_strs};

    #[test]
    fn round_is_pythons() {
        // Values checked against CPython 3.11 `round(k * 0.05, 4)` / `round(x, n)`.
        assert_eq!(py_round(3.0 * 0.05, 4), 0.15);
        assert_eq!(py_round(0.15000000000000002, 4), 0.15);
        assert_eq!(py_round(1e-5 * 0.5, 5), 1e-05);
        assert_eq!(py_round(0.000015, 5), 2e-05);
        assert_eq!(py_round(0.0625, 3), 0.062);
        assert_eq!(py_round(-0.00001, 4), -0.0);
        assert!(py_round(-0.00001, 4).is_sign_negative());
        assert_eq!(py_round(49999.950000000004, 4), 49999.95);
        assert_eq!(py_round(1e300, 4), 1e300);
        // Every t of a long run is the nearest double to k/20 (what round(k*dt, 4) yields).
        for k in 0..20_000u32 {
            let t = py_round(f64::from(k) * DT_S, 4);
            assert_eq!(t, f64::from(k) / 20.0, "k={k}");
        }
    }

    #[test]
    fn reference_rows() {
        let rows = simulate(&PidParams::default()).unwrap();
        // golden/pid_default rows 1 and 3, exact.
        assert_eq!(
            rows[0],
            PidSample {
                t: 0.0,
                r: 1.0,
                y: 0.13058823529411764,
                u: 2.2199999999999998,
                e: 1.0
            }
        );
        assert_eq!(rows[2].u, 0.9910527612456748);
        assert_eq!(rows[7].t, 0.35);
    }

    #[test]
    fn typed_api_agrees_with_csv_path() {
        let params = PidParams {
            kp: 2.0,
            ki: 0.0,
            kd: 0.1,
            tau: 0.0,
            steps: 5,
        };
        let rows = simulate(&params).unwrap();
        let out = run_strs::<Entry>(&["2", "0", "0.1", "0", "5"]).unwrap();
        assert_eq!(out.file(FILE_NAME), Some(to_csv(&rows).as_str()));
        assert_eq!(out.summary, summary(&rows));
        // tau = 0: the plant follows u at once (a = 1).
        assert!(rows.iter().all(|s| s.y == s.u));
    }

    #[test]
    fn zero_steps_is_header_only() {
        let out = run_strs::<Entry>(&["1", "1", "1", "1", "0"]).unwrap();
        assert_eq!(out.file(FILE_NAME), Some("t,r,y,u,e\r\n"));
        assert_eq!(
            out.summary,
            "wrote 0 PID samples final_y=0.0000 -> pid_step.csv"
        );
    }

    #[test]
    fn unstable_gains_overflow_like_python() {
        // y_{k+1} = y (1 - a (Kp + 1)) + a Kp grows by ~|1 - 101 a| ≈ 4.9 per step.
        let rows = simulate(&PidParams {
            kp: 100.0,
            ki: 0.0,
            kd: 0.0,
            tau: 0.8,
            steps: 600,
        })
        .unwrap();
        let first_inf = rows.iter().position(|s| s.y.is_infinite()).unwrap();
        assert!(rows[..first_inf].iter().all(|s| s.y.is_finite()));
        assert!(rows[first_inf + 1].y.is_nan());
    }

    #[test]
    fn rejections_name_the_parameter() {
        let check = |raw: &[&str], param: &str, ok: fn(&RecipeError) -> bool| {
            assert_rejects::<Entry>(raw, param, ok)
        };
        use RecipeError as E;
        check(&["1", "1", "1", "1", "-1"], "steps", |e| {
            matches!(e, E::OutOfRange { .. })
        });
        check(
            &["1", "1", "1", "1", "1000001"],
            "steps",
            |e| matches!(e, E::OutOfRange { max, .. } if *max == 1e6),
        );
        check(&["1", "1", "1", "1", "80.5"], "steps", |e| {
            matches!(e, E::NotAnInteger { .. })
        });
        // Whole numbers in any notation: "80.0" and "8e1" are 80 steps.
        for whole in ["80.0", "8e1"] {
            let out = run_strs::<Entry>(&["1.2", "0.4", "0.05", "0.8", whole]).unwrap();
            assert_eq!(
                out.summary,
                "wrote 80 PID samples final_y=0.7967 -> pid_step.csv"
            );
        }
        check(
            &["1", "1", "1", "1", "1e9"],
            "steps",
            |e| matches!(e, E::OutOfRange { max, .. } if *max == 1e6),
        );
        check(&["1", "1", "1", "-0.05"], "tau", |e| {
            matches!(e, E::OutOfRange { .. })
        });
        check(&["1", "1", "x"], "Kd", |e| {
            matches!(e, E::NotANumber { .. })
        });
        check(&["inf"], "Kp", |e| matches!(e, E::NotFinite { .. }));
        let nan = PidParams {
            ki: f64::NAN,
            ..PidParams::default()
        };
        assert!(matches!(nan.validate(), Err(E::NotFinite { .. })));
        let long = PidParams {
            steps: MAX_STEPS,
            ..PidParams::default()
        };
        assert_eq!(long.validate(), Ok(()));
    }
}
