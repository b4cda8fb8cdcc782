//! Recipe `trapezoid-profile` (`trapezoid_velocity_profile.py`): accelerate at `amax`, cruise at
//! `vmax`, decelerate at `amax` over a scalar distance `D`, sampled every `dt`.
//!
//! ```text
//! D, vmax, amax = |distance|, |vmax|, |amax|
//! t_acc = vmax / amax,  d_acc = amax t_acc² / 2
//! if 2 d_acc >= D:  t_acc = sqrt(D / amax), t_flat = 0, vmax = amax t_acc   (triangle)
//! else:             t_flat = (D - 2 d_acc) / vmax
//! t_total = 2 t_acc + t_flat
//! accel:  s = amax t² / 2                v = amax t           a = amax
//! cruise: s = d_acc + vmax (t - t_acc)    v = vmax             a = 0
//! decel:  s = d_acc + vmax t_flat + vmax tau - amax tau² / 2,  v = vmax - amax tau,  a = -amax
//! ```
//!
//! Time advances by repeated `t += dt` while `t <= t_total + 1e-12`, so accumulated rounding
//! decides the row count; each row prints `round(t, 5)`. In the triangle branch `d_acc` keeps the
//! value from the untruncated `vmax`, so the decel positions are offset; the table reproduces
//! that quirk.
//!
//! Decisions where the Python recipe is silent or crashes:
//! - `dt` must be > 0 (Python loops forever on `dt <= 0`), and the run may hold at most
//!   [`MAX_ROWS`] rows;
//! - `|vmax|` and `|amax|` must be > 0 (Python divides by zero) and, like `|distance|`, at most
//!   [`MAGNITUDE_MAX`]; `|vmax|`, `|amax|` at least [`MAGNITUDE_MIN`]. These keep `t_acc²` and
//!   `d_acc` finite (Python raises OverflowError on `t_acc ** 2`). Signs are dropped as in the
//!   recipe (`abs()`), so the range applies to the magnitude.

use super::info::RecipeInfo;
use super::kernel::{float_csv_with, plan_of, Kernel, Progress, RunResult};
use super::output::RecipeOutput;
use super::picture::{lines, series::BLUE, Picture, Table};
use crate::args::{finite, positive, ArgSpec, Args, Bound};
use crate::error::RecipeError;
use crate::pyfmt::{fixed, py_round};

/// Smallest accepted `|vmax|`, `|amax|` (non-zero).
pub const MAGNITUDE_MIN: f64 = 1e-9;
/// Largest accepted `|distance|`, `|vmax|`, `|amax|`.
pub const MAGNITUDE_MAX: f64 = 1e9;
/// Most samples: a CSV of about 80 MB is the most a browser tab should build.
pub const MAX_ROWS: u64 = 1_000_000;

/// The CSV this recipe writes.
pub const FILE_NAME: &str = "trap_profile.csv";
const HEADER: [&str; 4] = ["t", "s", "v", "a"];

const ARGS: [ArgSpec; 4] = [
    ArgSpec::number("distance", "1.0", "move distance (sign ignored)")
        .limits(Bound::Incl(-MAGNITUDE_MAX), Bound::Incl(MAGNITUDE_MAX))
        .hint("recipe-trapezoid-profile-hint-distance"),
    ArgSpec::number("vmax", "0.5", "speed limit (sign ignored)")
        .limits(Bound::Incl(-MAGNITUDE_MAX), Bound::Incl(MAGNITUDE_MAX))
        .hint("recipe-trapezoid-profile-hint-vmax"),
    ArgSpec::number("amax", "1.0", "acceleration limit (sign ignored)")
        .limits(Bound::Incl(-MAGNITUDE_MAX), Bound::Incl(MAGNITUDE_MAX))
        .hint("recipe-trapezoid-profile-hint-amax"),
    ArgSpec::number("dt", "0.01", "sample period, s")
        .unit("s")
        .limits(Bound::Excl(0.0), Bound::None)
        .hint("recipe-trapezoid-profile-hint-dt"),
];

/// `trapezoid-profile`: id, Python file, arguments with the recipe's defaults, output file.
pub const INFO: RecipeInfo = RecipeInfo {
    id: "trapezoid-profile",
    python: "trapezoid_velocity_profile.py",
    args: &ARGS,
    flags: &[],
    writes: &[FILE_NAME],
    quirks_id: "recipe-trapezoid-profile-quirks",
    plan: plan_of::<Entry>,
    page: Some("trapezoid-profile"),
};

/// Move and sampling parameters (the recipe's defaults: 1.0, 0.5, 1.0, dt 0.01 s).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TrapParams {
    /// Distance; the recipe uses its magnitude.
    pub distance: f64,
    /// Speed limit; the recipe uses its magnitude.
    pub vmax: f64,
    /// Acceleration limit; the recipe uses its magnitude.
    pub amax: f64,
    /// Sample period, s.
    pub dt: f64,
}

impl Default for TrapParams {
    fn default() -> Self {
        TrapParams {
            distance: 1.0,
            vmax: 0.5,
            amax: 1.0,
            dt: 0.01,
        }
    }
}

fn magnitude(param: &str, value: f64, min: f64) -> Result<f64, RecipeError> {
    let m = finite(param, value)?.abs();
    if (min..=MAGNITUDE_MAX).contains(&m) {
        Ok(m)
    } else {
        Err(RecipeError::OutOfRange {
            param: param.to_string(),
            value: m,
            min,
            max: MAGNITUDE_MAX,
        })
    }
}

/// The phase timing of one profile.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Plan {
    triangle: bool,
    amax: f64,
    vmax_used: f64,
    t_acc: f64,
    d_acc: f64,
    t_flat: f64,
    t_total: f64,
}

impl TrapParams {
    /// Checks every parameter and the row count; the error names the first bad one.
    pub fn validate(&self) -> Result<(), RecipeError> {
        self.plan().map(|_| ())
    }

    /// About how many rows the run writes (`(t_total + 1e-12) / dt + 1`; 0 when invalid).
    pub fn rows_estimate(&self) -> u64 {
        match self.plan() {
            Ok(plan) => ((plan.t_total + 1e-12) / self.dt + 1.0) as u64,
            Err(_) => 0,
        }
    }

    fn plan(&self) -> Result<Plan, RecipeError> {
        let distance = magnitude("distance", self.distance, 0.0)?;
        for (param, value) in [("vmax", self.vmax), ("amax", self.amax)] {
            if value == 0.0 {
                positive(param, value)?;
            }
        }
        let mut vmax = magnitude("vmax", self.vmax, MAGNITUDE_MIN)?;
        let amax = magnitude("amax", self.amax, MAGNITUDE_MIN)?;
        finite("dt", self.dt)?;
        positive("dt", self.dt)?;
        let mut t_acc = vmax / amax;
        // `t_acc ** 2`: pow(x, 2) is the correctly rounded square, one product (`math::pow`).
        let d_acc = 0.5 * amax * (t_acc * t_acc);
        let t_flat;
        let triangle = 2.0 * d_acc >= distance;
        if triangle {
            t_acc = (distance / amax).sqrt();
            t_flat = 0.0;
            vmax = amax * t_acc;
        } else {
            t_flat = (distance - 2.0 * d_acc) / vmax;
        }
        let t_total = 2.0 * t_acc + t_flat;
        // Rows are about (t_total + 1e-12) / dt + 1; the loop re-checks the exact count.
        let estimate = (t_total + 1e-12) / self.dt;
        if estimate.is_nan() || estimate >= MAX_ROWS as f64 {
            return Err(too_many_rows(estimate + 1.0));
        }
        Ok(Plan {
            triangle,
            amax,
            vmax_used: vmax,
            t_acc,
            d_acc,
            t_flat,
            t_total,
        })
    }
}

/// Rows = t_total ÷ dt: dt and every argument that sets t_total are involved.
fn too_many_rows(count: f64) -> RecipeError {
    RecipeError::TooLarge {
        param: "dt".to_string(),
        count: if count.is_finite() {
            count as u64
        } else {
            u64::MAX
        },
        limit: MAX_ROWS,
        also: vec!["distance".into(), "vmax".into(), "amax".into()],
        square: false,
    }
}

/// One row: time (rounded to 5 decimals), position, velocity, acceleration.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TrapSample {
    pub t: f64,
    pub s: f64,
    pub v: f64,
    pub a: f64,
}

/// The sampled profile and what the summary line reports.
#[derive(Debug, Clone, PartialEq)]
pub struct Profile {
    /// `2 t_acc + t_flat`, s.
    pub t_total: f64,
    /// The cruise speed actually reached (lower than `vmax` for a triangle).
    pub vmax_used: f64,
    /// Whether the move never reaches `vmax` (no cruise phase).
    pub triangle: bool,
    pub samples: Vec<TrapSample>,
}

/// Samples the profile, operation for operation as the recipe.
///
/// # Example
/// ```
/// use bsv_playground::recipes::trapezoid_profile::{compute, TrapParams};
/// let p = compute(&TrapParams::default()).unwrap();
/// assert_eq!(p.summary(), "wrote 251 samples t_total=2.5000s vmax_used=0.5000 -> trap_profile.csv");
/// ```
pub fn compute(params: &TrapParams) -> Result<Profile, RecipeError> {
    compute_with(params, &mut Progress::silent())
}

/// [`compute`] reporting its rows as the first half of `progress` (of the estimated rows).
pub fn compute_with(params: &TrapParams, progress: &mut Progress) -> Result<Profile, RecipeError> {
    let rows = samples(params)?;
    let Plan {
        triangle,
        vmax_used,
        t_total,
        ..
    } = rows.plan;
    let estimate = params.rows_estimate();
    let mut samples = Vec::new();
    for sample in rows {
        if samples.len() as u64 >= MAX_ROWS {
            return Err(too_many_rows(MAX_ROWS as f64 + 1.0));
        }
        progress.phase_at(0, 2, samples.len() as u64, estimate);
        samples.push(TrapSample {
            t: py_round(sample.t, 5),
            ..sample
        });
    }
    Ok(Profile {
        t_total,
        vmax_used,
        triangle,
        samples,
    })
}

/// The samples of the profile in order, operation for operation as the recipe, with the
/// accumulated time `t` left unrounded: the CSV prints `round(t, 5)` ([`compute`] rounds),
/// a live plot needs no decimal rounding of every row. The one loop of the recipe.
///
/// # Example
/// ```
/// use bsv_playground::recipes::trapezoid_profile::{samples, TrapParams};
/// let rows: Vec<_> = samples(&TrapParams::default()).unwrap().collect();
/// assert_eq!(rows.len(), 251);
/// assert_eq!(rows[1].s, 5e-05);
/// assert!(rows[250].v.abs() < 1e-9, "at rest at the end");
/// ```
pub fn samples(params: &TrapParams) -> Result<Samples, RecipeError> {
    Ok(Samples {
        plan: params.plan()?,
        dt: params.dt,
        t: 0.0,
    })
}

/// The iterator of [`samples`]: `t` advances by repeated `+= dt` while `t <= t_total + 1e-12`.
/// It does not stop at [`MAX_ROWS`] (valid parameters stay within it, but for the rounding
/// of the accumulated time: [`compute`] refuses one row more).
#[derive(Debug, Clone)]
pub struct Samples {
    plan: Plan,
    dt: f64,
    t: f64,
}

impl Iterator for Samples {
    type Item = TrapSample;

    fn next(&mut self) -> Option<TrapSample> {
        let p = self.plan;
        let (amax, vmax, t_acc, d_acc, t_flat) = (p.amax, p.vmax_used, p.t_acc, p.d_acc, p.t_flat);
        let t = self.t;
        // `while t <= t_total + 1e-12` (a NaN stops it, as in Python).
        let within = t <= p.t_total + 1e-12;
        if !within {
            return None;
        }
        // `t ** 2` as one product: the same double as the correctly rounded `pow(t, 2.0)`
        // (`math::tests::pow_two_is_the_correctly_rounded_square`), at a fraction of its cost.
        let (s, v, a);
        if t < t_acc {
            a = amax;
            v = amax * t;
            s = 0.5 * amax * (t * t);
        } else if t < t_acc + t_flat {
            a = 0.0;
            v = vmax;
            s = d_acc + vmax * (t - t_acc);
        } else {
            let tau = t - (t_acc + t_flat);
            a = -amax;
            v = vmax - amax * tau;
            s = d_acc + vmax * t_flat + vmax * tau - 0.5 * amax * (tau * tau);
        }
        self.t += self.dt;
        Some(TrapSample { t, s, v, a })
    }
}

impl Profile {
    /// `trap_profile.csv` exactly as the recipe writes it.
    pub fn to_csv(&self) -> String {
        self.to_csv_with(&mut Progress::silent())
    }

    /// [`Self::to_csv`] reporting its rows as the second half of `progress`.
    pub fn to_csv_with(&self, progress: &mut Progress) -> String {
        let rows = self.samples.iter().map(|s| [s.t, s.s, s.v, s.a]);
        float_csv_with(&HEADER, rows, progress)
    }

    /// The line the recipe prints.
    pub fn summary(&self) -> String {
        format!(
            "wrote {} samples t_total={}s vmax_used={} -> {FILE_NAME}",
            self.samples.len(),
            fixed(self.t_total, 4),
            fixed(self.vmax_used, 4)
        )
    }
}

/// Parses the recipe's arguments and validates them.
pub fn params_from_args(args: &Args) -> Result<TrapParams, RecipeError> {
    let params = TrapParams {
        distance: args.f64(0, &ARGS[0])?,
        vmax: args.f64(1, &ARGS[1])?,
        amax: args.f64(2, &ARGS[2])?,
        dt: args.f64(3, &ARGS[3])?,
    };
    params.validate()?;
    Ok(params)
}

/// The recipe's uniform entry ([`Kernel`]).
pub struct Entry;

impl Kernel for Entry {
    type Params = TrapParams;
    const INFO: &'static RecipeInfo = &INFO;

    fn params(args: &Args) -> Result<TrapParams, RecipeError> {
        params_from_args(args)
    }

    fn rows(params: &TrapParams, _args: &Args) -> Result<u64, RecipeError> {
        Ok(params.rows_estimate())
    }

    fn run(params: &TrapParams, _args: &Args, progress: &mut Progress) -> RunResult {
        let profile = compute_with(params, progress)?;
        let csv = profile.to_csv_with(progress);
        Ok(RecipeOutput::single(FILE_NAME, csv, profile.summary()))
    }
}

/// The home card's picture: the velocity over time.
pub fn picture(output: &RecipeOutput, _aspect: f64) -> Option<Picture> {
    let t = Table::parse(output.file(FILE_NAME)?)?;
    Some(lines(&t.col("t")?, &[(&t.col("v")?, BLUE)]))
}

#[cfg(test)]
mod tests {
    #[cfg(target_arch = "wasm32")]
    use wasm_bindgen_test::wasm_bindgen_test as test;

    use super::*;
    use crate::recipes::testkit::{assert_rejects, run_strs};

    #[test]
    fn trapezoid_and_triangle_reference_summaries() {
        let p = compute(&TrapParams::default()).unwrap();
        assert!(!p.triangle);
        assert_eq!(p.samples[1].s, 5e-05);
        let tri = run_strs::<Entry>(&["0.2", "1.0", "2.0", "0.005"]).unwrap();
        assert_eq!(
            tri.summary,
            "wrote 127 samples t_total=0.6325s vmax_used=0.6325 -> trap_profile.csv"
        );
    }

    #[test]
    fn signs_are_dropped_like_abs() {
        let a = run_strs::<Entry>(&["-1.0", "-0.5", "-1.0", "0.01"]).unwrap();
        let b = run_strs::<Entry>(&[]).unwrap();
        assert_eq!(a, b);
    }

    #[test]
    fn zero_distance_is_one_row_with_the_triangle_quirk() {
        // Python: t_total = 0, one decel row whose s is the untruncated d_acc = 0.125.
        let out = run_strs::<Entry>(&["0", "0.5", "1.0", "0.01"]).unwrap();
        assert_eq!(
            out.file(FILE_NAME),
            Some("t,s,v,a\r\n0.0,0.125,0.0,-1.0\r\n")
        );
        assert_eq!(
            out.summary,
            "wrote 1 samples t_total=0.0000s vmax_used=0.0000 -> trap_profile.csv"
        );
    }

    #[test]
    fn typed_api_agrees_with_csv_path() {
        let params = TrapParams {
            distance: 3.0,
            vmax: 2.0,
            amax: 4.0,
            dt: 0.07,
        };
        let p = compute(&params).unwrap();
        let out = run_strs::<Entry>(&["3", "2", "4", "0.07"]).unwrap();
        assert_eq!(out.file(FILE_NAME), Some(p.to_csv().as_str()));
        assert_eq!(out.summary, p.summary());
        // Cruise phase present; ends at rest at the full distance.
        assert!(p.samples.iter().any(|s| s.a == 0.0));
        let t_total = 2.0 * 0.5 + 1.0;
        assert_eq!(p.t_total, t_total);
    }

    #[test]
    fn rejections_name_the_parameter() {
        let check = |raw: &[&str], param: &str, ok: fn(&RecipeError) -> bool| {
            assert_rejects::<Entry>(raw, param, ok)
        };
        use RecipeError as E;
        check(&["1", "0.5", "1", "0"], "dt", |e| {
            matches!(e, E::NotPositive { .. })
        });
        check(&["1", "0.5", "1", "-0.01"], "dt", |e| {
            matches!(e, E::NotPositive { .. })
        });
        check(
            &["1", "0.5", "1", "1e-7"],
            "dt",
            |e| matches!(e, E::TooLarge { limit, .. } if *limit == MAX_ROWS),
        );
        check(&["1", "0", "1"], "vmax", |e| {
            matches!(e, E::NotPositive { .. })
        });
        check(&["1", "0.5", "0"], "amax", |e| {
            matches!(e, E::NotPositive { .. })
        });
        check(&["1", "0.5", "1e-300"], "amax", |e| {
            matches!(e, E::OutOfRange { .. })
        });
        check(
            &["-2e9"],
            "distance",
            |e| matches!(e, E::OutOfRange { value, .. } if *value == 2e9),
        );
        check(&["1", "x"], "vmax", |e| matches!(e, E::NotANumber { .. }));
        // Extremes within the ranges stay finite or are rejected by the row count.
        for raw in [
            ["1e9", "1e-9", "1e9", "1e12"],
            ["1e9", "1e9", "1e-9", "1e30"],
            ["1e-300", "1e9", "1e-9", "1"],
        ] {
            match run_strs::<Entry>(&raw) {
                Ok(out) => assert!(!out.file(FILE_NAME).unwrap().contains("inf")),
                Err(e) => assert!(matches!(e, E::TooLarge { .. }), "{raw:?} {e:?}"),
            }
        }
    }

    #[test]
    fn row_count_limit() {
        // t_total = 2.5 s: dt = 2.5e-6 makes ~1e6 + 1 rows, over the limit.
        let e = compute(&TrapParams {
            dt: 2.5e-6,
            ..TrapParams::default()
        })
        .unwrap_err();
        assert!(matches!(e, RecipeError::TooLarge { .. }));
        let ok = compute(&TrapParams {
            dt: 2.6e-6,
            ..TrapParams::default()
        })
        .unwrap();
        assert!(ok.samples.len() as u64 <= MAX_ROWS);
    }
}
