//! Recipe `cubic-path` (`cubic_joint_path.py`): the interpolating cubic from q0 to q1 in time T
//! with zero velocity at both ends, sampled every dt.
//!
//! ```text
//! q(t) = a0 + a1 t + a2 t² + a3 t³,   a0 = q0, a1 = 0,
//! a2 = 3 (q1 - q0) / T²,   a3 = -2 (q1 - q0) / T³
//! qd = a1 + 2 a2 t + 3 a3 t²,   qdd = 2 a2 + 6 a3 t
//! t = np.arange(0.0, T + 1e-12, dt)
//! ```
//!
//! Decisions where the Python recipe is silent or crashes:
//! - `T` and `dt` must be > 0 (the recipe's own check: "T and dt must be positive");
//! - `T` must lie in `[DURATION_MIN_S, DURATION_MAX_S]` (below ~1e-108 s `T*T*T` underflows and
//!   Python divides by zero) and `q0`, `q1` in `[-ANGLE_MAX_RAD, ANGLE_MAX_RAD]`, which keeps
//!   every coefficient finite;
//! - at most [`MAX_ROWS`] samples.

use super::info::RecipeInfo;
use super::kernel::{float_csv_with, plan_of, Kernel, Progress, RunResult};
use super::output::RecipeOutput;
use super::picture::{
    lines,
    series::{BLUE, ORANGE},
    Picture, Table,
};
use crate::args::{finite, in_range, positive, rows_within, ArgSpec, Args, Bound};
use crate::error::RecipeError;
use crate::numpy;
use crate::pyfmt::py_float;

/// Largest waypoint magnitude, rad (or whatever unit the user means): keeps `q1 - q0` and the
/// coefficients finite.
pub const ANGLE_MAX_RAD: f64 = 1e9;
/// Shortest move duration, s: keeps `T³` far from underflow.
pub const DURATION_MIN_S: f64 = 1e-9;
/// Longest move duration, s.
pub const DURATION_MAX_S: f64 = 1e9;
/// Most samples: a CSV of about 80 MB is the most a browser tab should build.
pub const MAX_ROWS: u64 = 1_000_000;

/// The CSV this recipe writes.
pub const FILE_NAME: &str = "cubic_path.csv";
const HEADER: [&str; 4] = ["t_s", "q", "qd", "qdd"];

const ARGS: [ArgSpec; 4] = [
    ArgSpec::number("q0", "0.0", "start joint angle, rad")
        .unit("rad")
        .limits(Bound::Incl(-ANGLE_MAX_RAD), Bound::Incl(ANGLE_MAX_RAD))
        .hint("recipe-cubic-path-hint-q0"),
    ArgSpec::number("q1", "1.2", "end joint angle, rad")
        .unit("rad")
        .limits(Bound::Incl(-ANGLE_MAX_RAD), Bound::Incl(ANGLE_MAX_RAD))
        .hint("recipe-cubic-path-hint-q1"),
    ArgSpec::number("T", "1.0", "move duration, s")
        .unit("s")
        .limits(Bound::Incl(DURATION_MIN_S), Bound::Incl(DURATION_MAX_S))
        .hint("recipe-cubic-path-hint-T"),
    ArgSpec::number("dt", "0.02", "sample period, s")
        .unit("s")
        .limits(Bound::Excl(0.0), Bound::None)
        .hint("recipe-cubic-path-hint-dt"),
];

/// `cubic-path`: id, Python file, arguments with the recipe's defaults, output file.
pub const INFO: RecipeInfo = RecipeInfo {
    id: "cubic-path",
    python: "cubic_joint_path.py",
    args: &ARGS,
    flags: &[],
    writes: &[FILE_NAME],
    quirks_id: "recipe-cubic-path-quirks",
    plan: plan_of::<Entry>,
    page: Some("cubic-path"),
};

/// Parameters of the path (the recipe's defaults: 0.0 → 1.2 rad in 1.0 s, dt 0.02 s).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CubicParams {
    /// Start angle, rad.
    pub q0: f64,
    /// End angle, rad.
    pub q1: f64,
    /// Move duration T, s.
    pub duration_s: f64,
    /// Sample period, s.
    pub dt_s: f64,
}

impl Default for CubicParams {
    fn default() -> Self {
        CubicParams {
            q0: 0.0,
            q1: 1.2,
            duration_s: 1.0,
            dt_s: 0.02,
        }
    }
}

impl CubicParams {
    /// Checks every parameter; the error names the first bad one.
    pub fn validate(&self) -> Result<(), RecipeError> {
        self.times().map(|_| ())
    }

    /// Samples of the path, `len(np.arange(0, T + 1e-12, dt))` (before validation).
    pub fn rows(&self) -> f64 {
        numpy::arange_len(0.0, self.duration_s + 1e-12, self.dt_s)
    }

    /// Validates and returns the sample times.
    fn times(&self) -> Result<Vec<f64>, RecipeError> {
        for (param, q) in [("q0", self.q0), ("q1", self.q1)] {
            finite(param, q)?;
            in_range(param, q, -ANGLE_MAX_RAD, ANGLE_MAX_RAD)?;
        }
        finite("T", self.duration_s)?;
        positive("T", self.duration_s)?;
        in_range("T", self.duration_s, DURATION_MIN_S, DURATION_MAX_S)?;
        finite("dt", self.dt_s)?;
        positive("dt", self.dt_s)?;
        rows_within("dt", &["T"], self.rows(), MAX_ROWS)?;
        numpy::arange(0.0, self.duration_s + 1e-12, self.dt_s, "dt", MAX_ROWS)
    }
}

/// One row: time, angle, velocity, acceleration.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CubicSample {
    pub t: f64,
    pub q: f64,
    pub qd: f64,
    pub qdd: f64,
}

/// The sampled path and what the summary line repeats.
#[derive(Debug, Clone, PartialEq)]
pub struct CubicPath {
    pub q0: f64,
    pub q1: f64,
    pub duration_s: f64,
    pub samples: Vec<CubicSample>,
}

/// Samples the cubic, operation for operation as the recipe.
///
/// # Example
/// ```
/// use bsv_playground::recipes::cubic_path::{compute, CubicParams};
/// let path = compute(&CubicParams::default()).unwrap();
/// assert_eq!(path.samples.len(), 51);
/// assert_eq!(path.summary(), "wrote 51 cubic samples q0=0.0→q1=1.2 T=1.0s -> cubic_path.csv");
/// ```
pub fn compute(params: &CubicParams) -> Result<CubicPath, RecipeError> {
    compute_with(params, &mut Progress::silent())
}

/// [`compute`] reporting its rows as the first half of `progress`.
pub fn compute_with(
    params: &CubicParams,
    progress: &mut Progress,
) -> Result<CubicPath, RecipeError> {
    let rows = samples(params)?;
    let n = rows.len() as u64;
    let samples = rows
        .enumerate()
        .map(|(k, s)| {
            progress.phase_at(0, 2, k as u64, n);
            s
        })
        .collect();
    Ok(CubicPath {
        q0: params.q0,
        q1: params.q1,
        duration_s: params.duration_s,
        samples,
    })
}

/// The samples of [`compute`], one at a time (a live page computes a million in slices).
pub fn samples(
    params: &CubicParams,
) -> Result<impl ExactSizeIterator<Item = CubicSample>, RecipeError> {
    let ts = params.times()?;
    let (q0, q1, big_t) = (params.q0, params.q1, params.duration_s);
    let (a0, a1) = (q0, 0.0);
    let a2 = 3.0 * (q1 - q0) / (big_t * big_t);
    let a3 = -2.0 * (q1 - q0) / (big_t * big_t * big_t);
    Ok(ts.into_iter().map(move |t| CubicSample {
        t,
        q: a0 + a1 * t + a2 * t * t + a3 * t * t * t,
        qd: a1 + 2.0 * a2 * t + 3.0 * a3 * t * t,
        qdd: 2.0 * a2 + 6.0 * a3 * t,
    }))
}

impl CubicPath {
    /// `cubic_path.csv` exactly as the recipe writes it.
    pub fn to_csv(&self) -> String {
        self.to_csv_with(&mut Progress::silent())
    }

    /// [`Self::to_csv`] reporting its rows as the second half of `progress`.
    pub fn to_csv_with(&self, progress: &mut Progress) -> String {
        let rows = self.samples.iter().map(|s| [s.t, s.q, s.qd, s.qdd]);
        float_csv_with(&HEADER, rows, progress)
    }

    /// The line the recipe prints (numbers as Python's `repr`).
    pub fn summary(&self) -> String {
        format!(
            "wrote {} cubic samples q0={}→q1={} T={}s -> {FILE_NAME}",
            self.samples.len(),
            py_float(self.q0),
            py_float(self.q1),
            py_float(self.duration_s)
        )
    }
}

/// Parses the recipe's arguments and validates them.
pub fn params_from_args(args: &Args) -> Result<CubicParams, RecipeError> {
    let params = CubicParams {
        q0: args.f64(0, &ARGS[0])?,
        q1: args.f64(1, &ARGS[1])?,
        duration_s: args.f64(2, &ARGS[2])?,
        dt_s: args.f64(3, &ARGS[3])?,
    };
    params.validate()?;
    Ok(params)
}

/// The recipe's uniform entry ([`Kernel`]).
pub struct Entry;

impl Kernel for Entry {
    type Params = CubicParams;
    const INFO: &'static RecipeInfo = &INFO;

    fn params(args: &Args) -> Result<CubicParams, RecipeError> {
        params_from_args(args)
    }

    fn rows(params: &CubicParams, _args: &Args) -> Result<u64, RecipeError> {
        Ok(params.rows() as u64)
    }

    fn run(params: &CubicParams, _args: &Args, progress: &mut Progress) -> RunResult {
        let path = compute_with(params, progress)?;
        let csv = path.to_csv_with(progress);
        Ok(RecipeOutput::single(FILE_NAME, csv, path.summary()))
    }
}

/// The home card's picture: position and velocity over time.
pub fn picture(output: &RecipeOutput, _aspect: f64) -> Option<Picture> {
    let t = Table::parse(output.file(FILE_NAME)?)?;
    Some(lines(
        &t.col("t_s")?,
        &[(&t.col("q")?, BLUE), (&t.col("qd")?, ORANGE)],
    ))
}

#[cfg(test)]
mod tests {
    #[cfg(target_arch = "wasm32")]
    use wasm_bindgen_test::wasm_bindgen_test as test;

    use super::*;
    use crate::recipes::testkit::{assert_rejects, run_strs};

    #[test]
    fn reference_rows_and_boundary_conditions() {
        let path = compute(&CubicParams::default()).unwrap();
        // golden/cubic_default rows 1 and 2, exact.
        assert_eq!(
            path.samples[0],
            CubicSample {
                t: 0.0,
                q: 0.0,
                qd: 0.0,
                qdd: 7.199999999999999
            }
        );
        assert_eq!(path.samples[1].q, 0.0014207999999999998);
        let last = path.samples[path.samples.len() - 1];
        assert!((last.t - 1.0).abs() < 1e-12);
        assert!((last.q - 1.2).abs() < 1e-12 && last.qd.abs() < 1e-12);
    }

    #[test]
    fn typed_api_agrees_with_csv_path() {
        let path = compute(&CubicParams {
            q0: -0.5,
            q1: 2.0,
            duration_s: 0.3,
            dt_s: 0.1,
        })
        .unwrap();
        let out = run_strs::<Entry>(&["-0.5", "2", "0.3", "0.1"]).unwrap();
        assert_eq!(out.file(FILE_NAME), Some(path.to_csv().as_str()));
        // np.arange(0, 0.3 + 1e-12, 0.1) has 4 values: 0.30000000000000004 is the last.
        assert_eq!(
            out.summary,
            "wrote 4 cubic samples q0=-0.5→q1=2.0 T=0.3s -> cubic_path.csv"
        );
        assert_eq!(path.samples[3].t, 0.30000000000000004);
    }

    #[test]
    fn rejections_name_the_parameter() {
        let check = |raw: &[&str], param: &str, ok: fn(&RecipeError) -> bool| {
            assert_rejects::<Entry>(raw, param, ok)
        };
        use RecipeError as E;
        check(&["0", "1", "0"], "T", |e| {
            matches!(e, E::NotPositive { .. })
        });
        check(&["0", "1", "-1"], "T", |e| {
            matches!(e, E::NotPositive { .. })
        });
        check(&["0", "1", "1e-12"], "T", |e| {
            matches!(e, E::OutOfRange { .. })
        });
        check(&["0", "1", "1", "0"], "dt", |e| {
            matches!(e, E::NotPositive { .. })
        });
        check(
            &["0", "1", "1", "1e-7"],
            "dt",
            |e| matches!(e, E::TooLarge { limit, .. } if *limit == MAX_ROWS),
        );
        check(&["1e10"], "q0", |e| matches!(e, E::OutOfRange { .. }));
        check(&["0", "zero"], "q1", |e| matches!(e, E::NotANumber { .. }));
        let nan = CubicParams {
            dt_s: f64::NAN,
            ..CubicParams::default()
        };
        assert!(matches!(nan.validate(), Err(E::NotFinite { .. })));
        // A dt longer than T gives the start sample only.
        assert_eq!(
            run_strs::<Entry>(&["0", "1", "1", "5"])
                .unwrap()
                .summary
                .split(' ')
                .nth(1),
            Some("1")
        );
    }
}
