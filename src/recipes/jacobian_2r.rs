//! Recipe `jacobian-2r` (`jacobian_planar_2r.py`): sweep q1 at fixed q2 and write the planar 2R
//! Jacobian's determinant, Yoshikawa manipulability and singular values.
//!
//! ```text
//! q1 = np.arange(q1_start, q1_stop + 1e-12, q1_step)
//! J = [ -L1 s1 - L2 s12   -L2 s12 ]     det_j = np.linalg.det(J)
//!     [  L1 c1 + L2 c12    L2 c12 ]     w = sqrt(max(0, det(J Jᵀ)))
//! sigma_min, sigma_max = min/max of np.linalg.svd(J, compute_uv=False)
//! ```
//!
//! The numpy routines are reproduced in [`crate::planar2r`] (`det`, `manipulability`,
//! `singular_values`) so the CSV matches numpy's digits.
//!
//! Decisions where the Python recipe is silent or crashes:
//! - link lengths must lie in [`LINK_MIN_M`](super::ik_workspace::LINK_MIN_M),
//!   [`LINK_MAX_M`](super::ik_workspace::LINK_MAX_M);
//! - angles must lie in `[-ANGLE_MAX_RAD, ANGLE_MAX_RAD]` (beyond ~16000 rad `stop + 1e-12`
//!   rounds back to `stop` and a one-point sweep comes out empty);
//! - `q1_step` must be > 0 and `q1_stop >= q1_start`: Python divides by zero, or crashes with an
//!   IndexError on the empty sweep (`rows[0]`); we reject both with an error naming the value;
//! - at most [`MAX_SAMPLES`] samples.

use super::ik_workspace::{check_link_m, LINK_ARGS};
use super::info::RecipeInfo;
use super::kernel::{float_csv_with, plan_of, Kernel, Progress, RunResult};
use super::output::RecipeOutput;
use super::picture::{
    pairs,
    series::{BLUE, GREY, ORANGE},
    Mark, Picture, Table, UnitFrame,
};
use crate::args::{finite, in_range, positive, rows_within, ArgSpec, Args, Bound};
use crate::error::RecipeError;
use crate::numpy;
use crate::planar2r::{self, Arm};
use crate::pyfmt::fixed;
use glam::DVec2;

/// Largest joint angle magnitude accepted, rad (about 160 turns): keeps `q1_stop + 1e-12`
/// distinct from `q1_stop`, so a sweep of one point is never empty.
pub const ANGLE_MAX_RAD: f64 = 1000.0;
/// Most samples in one sweep: a CSV of about 150 MB is the most a browser tab should build.
pub const MAX_SAMPLES: u64 = 1_000_000;

/// The CSV this recipe writes.
pub const FILE_NAME: &str = "jacobian_2r.csv";
const HEADER: [&str; 8] = [
    "q1_rad",
    "q2_rad",
    "x_m",
    "y_m",
    "det_j",
    "manipulability",
    "sigma_min",
    "sigma_max",
];

const ANGLE: ArgSpec = ArgSpec::number("", "", "")
    .unit("rad")
    .limits(Bound::Incl(-ANGLE_MAX_RAD), Bound::Incl(ANGLE_MAX_RAD));

const ARGS: [ArgSpec; 6] = [
    LINK_ARGS[0],
    LINK_ARGS[1],
    ArgSpec {
        name: "q1_start",
        default: "0",
        help: "first shoulder angle of the sweep, rad",
        hint_id: "recipe-jacobian-2r-hint-q1_start",
        ..ANGLE
    },
    ArgSpec {
        name: "q1_stop",
        default: "1.57",
        help: "last shoulder angle of the sweep (included), rad",
        hint_id: "recipe-jacobian-2r-hint-q1_stop",
        ..ANGLE
    },
    ArgSpec::number("q1_step", "0.1", "shoulder angle step, rad")
        .unit("rad")
        .limits(Bound::Excl(0.0), Bound::None)
        .hint("recipe-jacobian-2r-hint-q1_step"),
    ArgSpec {
        name: "q2",
        default: "0.8",
        help: "fixed elbow angle, rad",
        hint_id: "recipe-jacobian-2r-hint-q2",
        ..ANGLE
    },
];

/// `jacobian-2r`: id, Python file, arguments with the recipe's defaults, output file.
pub const INFO: RecipeInfo = RecipeInfo {
    id: "jacobian-2r",
    python: "jacobian_planar_2r.py",
    args: &ARGS,
    flags: &[],
    writes: &[FILE_NAME],
    quirks_id: "recipe-jacobian-2r-quirks",
    plan: plan_of::<Entry>,
    page: Some("ik-2r"),
};

/// Parameters of the sweep (the recipe's defaults: 0.12 m, 0.10 m, 0 to 1.57 by 0.1, q2 0.8).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SweepParams {
    /// Upper link length, m.
    pub l1: f64,
    /// Forearm link length, m.
    pub l2: f64,
    /// First shoulder angle, rad.
    pub q1_start: f64,
    /// Last shoulder angle (included up to 1e-12), rad.
    pub q1_stop: f64,
    /// Shoulder angle step, rad.
    pub q1_step: f64,
    /// Fixed elbow angle, rad.
    pub q2: f64,
}

impl Default for SweepParams {
    fn default() -> Self {
        SweepParams {
            l1: 0.12,
            l2: 0.10,
            q1_start: 0.0,
            q1_stop: 1.57,
            q1_step: 0.1,
            q2: 0.8,
        }
    }
}

fn check_angle(param: &str, value: f64) -> Result<(), RecipeError> {
    finite(param, value)?;
    in_range(param, value, -ANGLE_MAX_RAD, ANGLE_MAX_RAD)?;
    Ok(())
}

impl SweepParams {
    /// Checks every parameter; the error names the first bad one.
    pub fn validate(&self) -> Result<(), RecipeError> {
        self.q1_values().map(|_| ())
    }

    /// Validates and returns the q1 values of the sweep.
    fn q1_values(&self) -> Result<Vec<f64>, RecipeError> {
        check_link_m("L1", self.l1)?;
        check_link_m("L2", self.l2)?;
        check_angle("q1_start", self.q1_start)?;
        check_angle("q1_stop", self.q1_stop)?;
        in_range("q1_stop", self.q1_stop, self.q1_start, ANGLE_MAX_RAD)?;
        finite("q1_step", self.q1_step)?;
        positive("q1_step", self.q1_step)?;
        check_angle("q2", self.q2)?;
        rows_within(
            "q1_step",
            &["q1_stop", "q1_start"],
            numpy::arange_len(self.q1_start, self.q1_stop + 1e-12, self.q1_step),
            MAX_SAMPLES,
        )?;
        let q1 = numpy::arange(
            self.q1_start,
            self.q1_stop + 1e-12,
            self.q1_step,
            "q1_step",
            MAX_SAMPLES,
        )?;
        if q1.is_empty() {
            // Unreachable with the bounds above; kept so that no input reaches Python's crash.
            return Err(RecipeError::OutOfRange {
                param: "q1_stop".to_string(),
                value: self.q1_stop,
                min: self.q1_start,
                max: ANGLE_MAX_RAD,
            });
        }
        Ok(q1)
    }
}

/// One row of the sweep.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JacobianSample {
    /// Shoulder angle, rad.
    pub q1: f64,
    /// Elbow angle, rad.
    pub q2: f64,
    /// Tip x, m.
    pub x: f64,
    /// Tip y, m.
    pub y: f64,
    /// `np.linalg.det(J)`.
    pub det_j: f64,
    /// Yoshikawa manipulability `sqrt(max(0, det(J Jᵀ)))`.
    pub manipulability: f64,
    /// Smaller singular value of J.
    pub sigma_min: f64,
    /// Larger singular value of J.
    pub sigma_max: f64,
}

/// Runs the sweep.
///
/// # Example
/// ```
/// use bsv_playground::recipes::jacobian_2r::{summary, sweep, SweepParams};
/// let rows = sweep(&SweepParams::default()).unwrap();
/// assert_eq!(
///     summary(&rows),
///     "wrote 16 Jacobian samples -> jacobian_2r.csv (min manip=0.0086)"
/// );
/// ```
pub fn sweep(params: &SweepParams) -> Result<Vec<JacobianSample>, RecipeError> {
    sweep_with(params, &mut Progress::silent())
}

/// [`sweep`] reporting its rows as the first half of `progress`.
pub fn sweep_with(
    params: &SweepParams,
    progress: &mut Progress,
) -> Result<Vec<JacobianSample>, RecipeError> {
    let q1s = params.q1_values()?;
    let n = q1s.len() as u64;
    let arm = Arm {
        l1: params.l1,
        l2: params.l2,
    };
    let q2 = params.q2;
    Ok(q1s
        .into_iter()
        .enumerate()
        .map(|(k, q1)| {
            progress.phase_at(0, 2, k as u64, n);
            let j = arm.jacobian(q1, q2);
            let (x, y) = arm.fk(q1, q2);
            let (sigma_min, sigma_max) = planar2r::singular_values(&j);
            JacobianSample {
                q1,
                q2,
                x,
                y,
                det_j: planar2r::det(&j),
                manipulability: planar2r::manipulability(&j),
                sigma_min,
                sigma_max,
            }
        })
        .collect())
}

/// `jacobian_2r.csv` exactly as the recipe writes it.
pub fn to_csv(samples: &[JacobianSample]) -> String {
    to_csv_with(samples, &mut Progress::silent())
}

/// [`to_csv`] reporting its rows as the second half of `progress`.
pub fn to_csv_with(samples: &[JacobianSample], progress: &mut Progress) -> String {
    let rows = samples.iter().map(|s| {
        [
            s.q1,
            s.q2,
            s.x,
            s.y,
            s.det_j,
            s.manipulability,
            s.sigma_min,
            s.sigma_max,
        ]
    });
    float_csv_with(&HEADER, rows, progress)
}

/// The line the recipe prints (`min manip` with 4 decimals). An empty slice, which
/// [`sweep`] never returns, prints without the minimum.
pub fn summary(samples: &[JacobianSample]) -> String {
    let min = samples
        .iter()
        .map(|s| s.manipulability)
        .reduce(|a, b| if b < a { b } else { a });
    match min {
        Some(min) => format!(
            "wrote {} Jacobian samples -> {FILE_NAME} (min manip={})",
            samples.len(),
            fixed(min, 4)
        ),
        None => format!("wrote 0 Jacobian samples -> {FILE_NAME}"),
    }
}

/// Parses the recipe's arguments and validates them.
pub fn params_from_args(args: &Args) -> Result<SweepParams, RecipeError> {
    let params = SweepParams {
        l1: args.f64(0, &ARGS[0])?,
        l2: args.f64(1, &ARGS[1])?,
        q1_start: args.f64(2, &ARGS[2])?,
        q1_stop: args.f64(3, &ARGS[3])?,
        q1_step: args.f64(4, &ARGS[4])?,
        q2: args.f64(5, &ARGS[5])?,
    };
    params.validate()?;
    Ok(params)
}

/// The recipe's uniform entry ([`Kernel`]).
pub struct Entry;

impl Kernel for Entry {
    type Params = SweepParams;
    const INFO: &'static RecipeInfo = &INFO;

    fn params(args: &Args) -> Result<SweepParams, RecipeError> {
        params_from_args(args)
    }

    fn rows(params: &SweepParams, _args: &Args) -> Result<u64, RecipeError> {
        let rows = numpy::arange_len(params.q1_start, params.q1_stop + 1e-12, params.q1_step);
        Ok(rows as u64)
    }

    fn run(params: &SweepParams, _args: &Args, progress: &mut Progress) -> RunResult {
        let samples = sweep_with(params, progress)?;
        let csv = to_csv_with(&samples, progress);
        Ok(RecipeOutput::single(FILE_NAME, csv, summary(&samples)))
    }
}

/// The home card's picture: the sweep turns q1 at a fixed q2, so the tip's arc, with the
/// arm's reach to each tip.
pub fn picture(output: &RecipeOutput, aspect: f64) -> Option<Picture> {
    let t = Table::parse(output.file(FILE_NAME)?)?;
    let tips = pairs(&t.col("x_m")?, &t.col("y_m")?);
    let frame = UnitFrame::fit(tips.iter().copied().chain([DVec2::ZERO]), Some(aspect));
    let reach = Mark::Segments {
        series: GREY,
        pairs: tips
            .iter()
            .map(|p| (frame.map(DVec2::ZERO), frame.map(*p)))
            .collect(),
    };
    let arc = tips.iter().map(|p| frame.map(*p)).collect();
    let [line, dots] = Mark::joined_dots(arc, BLUE, ORANGE);
    Some(Picture {
        marks: vec![reach, line, dots],
    })
}

#[cfg(test)]
mod tests {
    #[cfg(target_arch = "wasm32")]
    use wasm_bindgen_test::wasm_bindgen_test as test;

    use super::*;
    use crate::recipes::testkit::{self, run_strs};

    fn assert_rejects(raw: &[&str], param: &str, check: fn(&RecipeError) -> bool) {
        testkit::assert_rejects::<Entry>(raw, param, check)
    }

    #[test]
    fn default_sweep_numbers() {
        let rows = sweep(&SweepParams::default()).unwrap();
        assert_eq!(rows.len(), 16);
        // golden/jacobian_default first row, exact.
        let first = rows[0];
        assert_eq!(first.x, 0.18967067093471654);
        assert_eq!(first.det_j, 0.008608273090794276);
        assert_eq!(first.sigma_min, 0.03864146032693336);
        // det J = L1 L2 sin q2 all along the sweep.
        for r in &rows {
            assert!((r.det_j - 0.012 * crate::math::sin(0.8f64)).abs() < 1e-15);
            assert!(r.sigma_min <= r.sigma_max);
            assert!((r.sigma_min * r.sigma_max - r.det_j).abs() < 1e-15);
        }
    }

    #[test]
    fn typed_api_agrees_with_csv_path() {
        let params = SweepParams {
            l1: 0.3,
            l2: 0.25,
            q1_start: -1.0,
            q1_stop: 1.0,
            q1_step: 0.25,
            q2: 0.0,
        };
        let rows = sweep(&params).unwrap();
        let out = run_strs::<Entry>(&["0.3", "0.25", "-1", "1", "0.25", "0"]).unwrap();
        assert_eq!(out.file(FILE_NAME), Some(to_csv(&rows).as_str()));
        assert_eq!(out.summary, summary(&rows));
        // q2 = 0 is the stretched-out singularity.
        assert_eq!(
            out.summary,
            "wrote 9 Jacobian samples -> jacobian_2r.csv (min manip=0.0000)"
        );
        for r in &rows {
            assert!(r.det_j.abs() < 1e-16 && r.sigma_min < 1e-15, "{r:?}");
            // Rank one: both columns along (-s1, c1), lengths L1 + L2 and L2.
            assert!(
                (r.sigma_max - crate::math::hypot(0.55f64, 0.25)).abs() < 1e-15,
                "{r:?}"
            );
        }
    }

    #[test]
    fn one_point_sweep() {
        let out = run_strs::<Entry>(&["0.12", "0.10", "0.5", "0.5", "0.1"]).unwrap();
        assert!(out.summary.starts_with("wrote 1 Jacobian samples"));
        let out = run_strs::<Entry>(&["0.12", "0.10", "-1000", "-1000", "0.1"]).unwrap();
        assert!(out.summary.starts_with("wrote 1 Jacobian samples"));
    }

    #[test]
    fn rejections_name_the_parameter() {
        use RecipeError as E;
        assert_rejects(&["-0.1"], "L1", |e| matches!(e, E::NotPositive { .. }));
        assert_rejects(&["0.1", "1e-7"], "L2", |e| {
            matches!(e, E::OutOfRange { .. })
        });
        assert_rejects(&["0.1", "0.1", "x"], "q1_start", |e| {
            matches!(e, E::NotANumber { .. })
        });
        assert_rejects(
            &["0.1", "0.1", "1", "0.5"],
            "q1_stop",
            |e| matches!(e, E::OutOfRange { min, .. } if *min == 1.0),
        );
        assert_rejects(&["0.1", "0.1", "0", "1", "0"], "q1_step", |e| {
            matches!(e, E::NotPositive { .. })
        });
        assert_rejects(&["0.1", "0.1", "0", "1", "-0.1"], "q1_step", |e| {
            matches!(e, E::NotPositive { .. })
        });
        assert_rejects(
            &["0.1", "0.1", "0", "1", "1e-7"],
            "q1_step",
            |e| matches!(e, E::TooLarge { limit, .. } if *limit == MAX_SAMPLES),
        );
        assert_rejects(&["0.1", "0.1", "0", "1", "0.1", "inf"], "q2", |e| {
            matches!(e, E::NotFinite { .. })
        });
        assert_rejects(&["0.1", "0.1", "0", "1e4"], "q1_stop", |e| {
            matches!(e, E::OutOfRange { .. })
        });
        // 1e6 samples is allowed.
        let many = SweepParams {
            q1_start: 0.0,
            q1_stop: 999_999.0 * 1e-4,
            q1_step: 1e-4,
            ..SweepParams::default()
        };
        assert_eq!(many.validate(), Ok(()));
    }
}
