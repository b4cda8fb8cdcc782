//! Recipe `manip-grid` (`manip_ellipse_2r.py`): |det J| of a planar 2R arm over an n × n grid
//! of joint angles (the recipe is called "ellipse" but writes |det J| only).
//!
//! ```text
//! q_i = -pi + 2 pi i / max(n - 1, 1),   i = 0 .. n-1   (same angles for q1 and q2)
//! det J = (-L1 s1 - L2 s12)(L2 c12) - (-L2 s12)(L1 c1 + L2 c12)   (= L1 L2 sin q2)
//! ```
//!
//! Rows run `i` over q1 (outer) and `j` over q2 (inner). The summary's maximum is the first
//! maximum in row order, as Python's `max()`. The CSV path evaluates the recipe's formula
//! operation for operation ([`Arm::det_explicit`]); [`fill_abs_det`] is a table-driven fast path
//! for heatmaps that agrees to ~1e-17.
//!
//! Decisions where the Python recipe is silent or crashes:
//! - `n` must be a whole number in `[1, MAX_N]` (n <= 0 makes Python's `max()` of no rows crash);
//! - link lengths must lie in [`LINK_MIN_M`](super::ik_workspace::LINK_MIN_M),
//!   [`LINK_MAX_M`](super::ik_workspace::LINK_MAX_M).

use super::ik_workspace::{check_link_m, LINK_ARGS};
use super::info::RecipeInfo;
use super::kernel::{plan_of, Kernel, Progress, RunResult};
use super::output::RecipeOutput;
use super::picture::{Mark, Picture, Table};
use crate::args::{check_count, parse_count, ArgKind, ArgSpec, Args, Bound};
use crate::error::RecipeError;
use crate::planar2r::Arm;
use crate::pyfmt::{fixed, CsvText};
use std::f64::consts::PI;

/// Largest grid side: 1024² ≈ 1M rows (a CSV of ~80 MB), the most a browser tab should build;
/// also the size of the fast path's stack tables.
pub const MAX_N: i64 = 1024;

/// The CSV this recipe writes.
pub const FILE_NAME: &str = "manip_ellipse.csv";
const HEADER: [&str; 4] = ["q1", "q2", "detJ", "manip"];

const ARGS: [ArgSpec; 3] = [
    LINK_ARGS[0],
    LINK_ARGS[1],
    ArgSpec::number("n", "24", "grid side: n × n joint configurations")
        .kind(ArgKind::Integer)
        .limits(Bound::Incl(1.0), Bound::Incl(MAX_N as f64))
        .hint("recipe-manip-grid-hint-n"),
];

/// `manip-grid`: id, Python file, arguments with the recipe's defaults, output file.
pub const INFO: RecipeInfo = RecipeInfo {
    id: "manip-grid",
    python: "manip_ellipse_2r.py",
    args: &ARGS,
    flags: &[],
    writes: &[FILE_NAME],
    quirks_id: "recipe-manip-grid-quirks",
    plan: plan_of::<Entry>,
    page: Some("ik-2r"),
};

/// Parameters of the grid (the recipe's defaults: 0.12 m, 0.10 m, n = 24).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GridParams {
    /// Upper link length, m.
    pub l1: f64,
    /// Forearm link length, m.
    pub l2: f64,
    /// Grid side (whole number in `[1, MAX_N]`).
    pub n: i64,
}

impl Default for GridParams {
    fn default() -> Self {
        GridParams {
            l1: 0.12,
            l2: 0.10,
            n: 24,
        }
    }
}

impl GridParams {
    /// Checks every parameter; the error names the first bad one.
    pub fn validate(&self) -> Result<(), RecipeError> {
        self.side().map(|_| ())
    }

    fn side(&self) -> Result<usize, RecipeError> {
        check_link_m("L1", self.l1)?;
        check_link_m("L2", self.l2)?;
        let n = check_count("n", self.n, 1, MAX_N)?;
        Ok(usize::try_from(n).unwrap_or(1))
    }
}

/// `q_i = -pi + 2 pi i / max(n - 1, 1)`, evaluated as the recipe does.
fn grid_angle(i: usize, n: usize) -> f64 {
    -PI + 2.0 * PI * i as f64 / n.saturating_sub(1).max(1) as f64
}

/// The sampled grid.
#[derive(Debug, Clone, PartialEq)]
pub struct ManipGrid {
    /// Grid side.
    pub n: usize,
    /// The n joint angles (shared by q1 and q2), rad.
    pub q: Vec<f64>,
    /// det J, row-major: index `i * n + j`, `i` over q1, `j` over q2.
    pub det_j: Vec<f64>,
}

/// Runs the recipe's grid.
///
/// # Example
/// ```
/// use bsv_playground::recipes::manip_grid::{grid, GridParams};
/// let g = grid(&GridParams::default()).unwrap();
/// assert_eq!(g.det_j.len(), 576);
/// assert!(g.summary().starts_with("wrote 576 configs max|detJ|=0.01197"));
/// ```
pub fn grid(params: &GridParams) -> Result<ManipGrid, RecipeError> {
    grid_with(params, &mut Progress::silent())
}

/// [`grid`] reporting its rows as the first half of `progress`.
pub fn grid_with(params: &GridParams, progress: &mut Progress) -> Result<ManipGrid, RecipeError> {
    let n = params.side()?;
    let arm = Arm {
        l1: params.l1,
        l2: params.l2,
    };
    let q: Vec<f64> = (0..n).map(|i| grid_angle(i, n)).collect();
    let mut det_j = Vec::with_capacity(n * n);
    for (i, &q1) in q.iter().enumerate() {
        progress.phase_at(0, 2, i as u64, n as u64);
        for &q2 in &q {
            det_j.push(arm.det_explicit(q1, q2));
        }
    }
    Ok(ManipGrid { n, q, det_j })
}

impl ManipGrid {
    /// `manip_ellipse.csv` exactly as the recipe writes it.
    pub fn to_csv(&self) -> String {
        self.to_csv_with(&mut Progress::silent())
    }

    /// [`Self::to_csv`] reporting its rows as the second half of `progress`.
    pub fn to_csv_with(&self, progress: &mut Progress) -> String {
        let mut csv = CsvText::with_header(&HEADER);
        let rows = self.det_j.len() as u64;
        for (k, det) in self.det_j.iter().enumerate() {
            progress.phase_at(1, 2, k as u64, rows);
            let (i, j) = (k / self.n.max(1), k % self.n.max(1));
            let q1 = self.q.get(i).copied().unwrap_or(f64::NAN);
            let q2 = self.q.get(j).copied().unwrap_or(f64::NAN);
            csv.floats(&[q1, q2, *det, det.abs()]);
        }
        csv.finish()
    }

    /// Index of the first largest |det J| in row order (Python's `max()`), if any.
    pub fn argmax(&self) -> Option<usize> {
        let mut best: Option<(usize, f64)> = None;
        for (k, det) in self.det_j.iter().enumerate() {
            let m = det.abs();
            match best {
                // Python's max(): only a strictly greater key replaces (NaN never does).
                Some((_, b)) if m.partial_cmp(&b) != Some(std::cmp::Ordering::Greater) => {}
                _ => best = Some((k, m)),
            }
        }
        best.map(|(k, _)| k)
    }

    /// The line the recipe prints.
    pub fn summary(&self) -> String {
        let rows = self.det_j.len();
        match self.argmax() {
            Some(k) => {
                let n = self.n.max(1);
                let q1 = self.q.get(k / n).copied().unwrap_or(f64::NAN);
                let q2 = self.q.get(k % n).copied().unwrap_or(f64::NAN);
                let manip = self.det_j.get(k).map_or(f64::NAN, |d| d.abs());
                format!(
                    "wrote {rows} configs max|detJ|={} at q=({},{}) -> {FILE_NAME}",
                    fixed(manip, 5),
                    fixed(q1, 3),
                    fixed(q2, 3)
                )
            }
            None => format!("wrote {rows} configs -> {FILE_NAME}"),
        }
    }
}

/// Fast path for heatmaps: writes |det J| of the recipe's n × n grid into `out` (row-major,
/// `i * n + j`, `i` over q1) as f32, without allocating, and returns the largest value.
///
/// Uses one sin/cos table for the n angles and the angle-addition formulas for `q1 + q2`, so
/// values differ from the CSV path by rounding only (~1e-17 for the default arm). `out` must
/// hold exactly `n * n` values.
pub fn fill_abs_det(l1: f64, l2: f64, n: i64, out: &mut [f32]) -> Result<f32, RecipeError> {
    let n = GridParams { l1, l2, n }.side()?;
    if out.len() != n * n {
        return Err(RecipeError::WrongCount {
            param: "out".to_string(),
            expected: n * n,
            got: out.len(),
        });
    }
    const TABLE: usize = MAX_N as usize;
    let mut sin_q = [0.0f64; TABLE];
    let mut cos_q = [0.0f64; TABLE];
    for (i, (s, c)) in sin_q.iter_mut().zip(cos_q.iter_mut()).take(n).enumerate() {
        let q = grid_angle(i, n);
        (*s, *c) = crate::math::sincos(q);
    }
    let mut max = 0.0f32;
    for (row, (&s1, &c1)) in out.chunks_exact_mut(n).zip(sin_q.iter().zip(&cos_q)) {
        for (cell, (&s2, &c2)) in row.iter_mut().zip(sin_q.iter().zip(&cos_q)) {
            let s12 = s1 * c2 + c1 * s2;
            let c12 = c1 * c2 - s1 * s2;
            let det = (-l1 * s1 - l2 * s12) * (l2 * c12) - (-l2 * s12) * (l1 * c1 + l2 * c12);
            let v = det.abs() as f32;
            *cell = v;
            max = max.max(v);
        }
    }
    Ok(max)
}

/// Parses the recipe's arguments (any whole-number notation for `n`) and validates them.
pub fn params_from_args(args: &Args) -> Result<GridParams, RecipeError> {
    let params = GridParams {
        l1: args.f64(0, &ARGS[0])?,
        l2: args.f64(1, &ARGS[1])?,
        n: parse_count(ARGS[2].name, args.text(2, &ARGS[2]), 1, MAX_N)?,
    };
    params.validate()?;
    Ok(params)
}

/// The recipe's uniform entry ([`Kernel`]).
pub struct Entry;

impl Kernel for Entry {
    type Params = GridParams;
    const INFO: &'static RecipeInfo = &INFO;

    fn params(args: &Args) -> Result<GridParams, RecipeError> {
        params_from_args(args)
    }

    fn rows(params: &GridParams, _args: &Args) -> Result<u64, RecipeError> {
        let n = params.side()? as u64;
        Ok(n * n)
    }

    fn run(params: &GridParams, _args: &Args, progress: &mut Progress) -> RunResult {
        let g = grid_with(params, progress)?;
        let csv = g.to_csv_with(progress);
        Ok(RecipeOutput::single(FILE_NAME, csv, g.summary()))
    }
}

/// The home card's picture: the manipulability over the (q1, q2) grid, scaled to its peak.
pub fn picture(output: &RecipeOutput, _aspect: f64) -> Option<Picture> {
    let t = Table::parse(output.file(FILE_NAME)?)?;
    let (q1, q2, m) = (t.col("q1")?, t.col("q2")?, t.col("manip")?);
    let distinct = |v: &[f64]| {
        let mut s: Vec<f64> = v.to_vec();
        s.sort_by(f64::total_cmp);
        s.dedup();
        s
    };
    let (xs, ys) = (distinct(&q1), distinct(&q2));
    let top = m
        .iter()
        .copied()
        .filter(|v| v.is_finite())
        .fold(0.0, f64::max);
    let mut values = vec![0.0; xs.len() * ys.len()];
    for i in 0..m.len() {
        let cx = xs.binary_search_by(|v| v.total_cmp(&q1[i])).ok()?;
        let cy = ys.binary_search_by(|v| v.total_cmp(&q2[i])).ok()?;
        values[cy * xs.len() + cx] = if top > 0.0 { m[i] / top } else { 0.0 };
    }
    Some(Picture {
        marks: vec![Mark::Cells {
            cols: xs.len(),
            rows: ys.len(),
            values,
        }],
    })
}

#[cfg(test)]
mod tests {
    #[cfg(target_arch = "wasm32")]
    use wasm_bindgen_test::wasm_bindgen_test as test;

    use super::*;
    use crate::recipes::testkit::{assert_rejects, run_strs};

    #[test]
    fn default_grid_matches_reference() {
        let g = grid(&GridParams::default()).unwrap();
        assert_eq!(
            g.summary(),
            "wrote 576 configs max|detJ|=0.01197 at q=(-1.229,1.503) -> manip_ellipse.csv"
        );
        // golden/manip_default first row, exact.
        assert_eq!(g.q[0], -PI);
        assert_eq!(g.det_j[0], -1.469576158976824e-18);
        assert_eq!(g.q[1], -2.86841068371242);
    }

    #[test]
    fn typed_api_agrees_with_csv_path() {
        let g = grid(&GridParams {
            l1: 0.3,
            l2: 0.2,
            n: 5,
        })
        .unwrap();
        let out = run_strs::<Entry>(&["0.3", "0.2", "5"]).unwrap();
        assert_eq!(out.file(FILE_NAME), Some(g.to_csv().as_str()));
        assert_eq!(out.summary, g.summary());
        // n = 5: q = -pi, -pi/2, 0, pi/2, pi; the maximum |det| = L1 L2 is first reached at
        // (q1, q2) = (-pi, -pi/2).
        assert_eq!(
            out.summary,
            "wrote 25 configs max|detJ|=0.06000 at q=(-3.142,-1.571) -> manip_ellipse.csv"
        );
    }

    #[test]
    fn n_one_is_a_single_config() {
        let out = run_strs::<Entry>(&["0.12", "0.10", "1"]).unwrap();
        assert_eq!(
            out.file(FILE_NAME),
            Some("q1,q2,detJ,manip\r\n-3.141592653589793,-3.141592653589793,-1.469576158976824e-18,1.469576158976824e-18\r\n")
        );
    }

    #[test]
    fn fast_path_agrees_with_recipe_formula() {
        for (l1, l2, n) in [(0.12, 0.10, 24), (0.5, 0.05, 37), (1.0, 1.0, 1)] {
            let g = grid(&GridParams { l1, l2, n }).unwrap();
            let mut out = vec![0.0f32; g.det_j.len()];
            let max = fill_abs_det(l1, l2, n, &mut out).unwrap();
            for (fast, exact) in out.iter().zip(&g.det_j) {
                assert!((f64::from(*fast) - exact.abs()).abs() <= 1e-6 * l1 * l2 + 1e-15);
            }
            let exact_max = g.argmax().map(|k| g.det_j[k].abs()).unwrap();
            assert!((f64::from(max) - exact_max).abs() <= 1e-6 * exact_max);
        }
        let mut wrong = [0.0f32; 3];
        assert!(matches!(
            fill_abs_det(0.1, 0.1, 2, &mut wrong),
            Err(RecipeError::WrongCount {
                expected: 4,
                got: 3,
                ..
            })
        ));
        assert!(matches!(
            fill_abs_det(0.1, 0.1, 0, &mut []),
            Err(RecipeError::OutOfRange { .. })
        ));
    }

    #[test]
    fn rejections_name_the_parameter() {
        for (raw, param) in [
            (&["0.12", "0.10", "0"][..], "n"),
            (&["0.12", "0.10", "-3"][..], "n"),
            (&["0.12", "0.10", "1025"][..], "n"),
            (&["0.12", "0.10", "99999999999999999999999"][..], "n"),
        ] {
            assert_rejects::<Entry>(raw, param, |e| matches!(e, RecipeError::OutOfRange { .. }));
        }
        // Whole numbers in any notation are accepted; a fraction is not.
        let e = run_strs::<Entry>(&["0.12", "0.10", "24.5"]).unwrap_err();
        assert!(matches!(e, RecipeError::NotAnInteger { .. }) && e.param() == Some("n"));
        for whole in ["24.0", "2.4e1", "24"] {
            let out = run_strs::<Entry>(&["0.12", "0.10", whole]).unwrap();
            assert!(out.summary.starts_with("wrote 576 configs"), "{whole}");
        }
        let e = run_strs::<Entry>(&["0.12", "0"]).unwrap_err();
        assert!(matches!(e, RecipeError::NotPositive { .. }) && e.param() == Some("L2"));
        let e = run_strs::<Entry>(&["1e7"]).unwrap_err();
        assert!(matches!(e, RecipeError::OutOfRange { .. }) && e.param() == Some("L1"));
        assert_eq!(
            GridParams {
                n: 1024,
                ..GridParams::default()
            }
            .validate(),
            Ok(())
        );
    }
}
