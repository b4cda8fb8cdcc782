//! Recipe `ik-workspace` (`planar_ik_workspace.py`): grid the plane around a planar 2R arm,
//! mark the reachable cells and record the elbow-down IK plus the FK round-trip error.
//!
//! ```text
//! xs = ys = np.arange(-half, half + 1e-9, step)        half = half_mm/1000, step = step_mm/1000
//! c2 = (x² + y² − L1² − L2²) / (2 L1 L2)              reachable when |c2| ≤ 1
//! q2 = acos(c2),  q1 = atan2(y, x) − atan2(L2 sin q2, L1 + L2 cos q2)
//! fk_err_mm = ((x_fk − x)**2 + (y_fk − y)**2)**0.5 · 1000     (C pow, as numpy)
//! ```
//!
//! Cells are visited x-major (`for x in xs: for y in ys`), so cell `k = ix * ys.len() + iy`.
//! An unreachable cell prints `x_mm,y_mm,0,,,`.
//!
//! Decisions where the Python recipe is silent or crashes:
//! - link lengths must lie in [`LINK_MIN_M`, `LINK_MAX_M`] (zero gives a division by zero in
//!   Python; tiny links make `c2` NaN and print `nan` rows);
//! - `half_mm` must lie in `[0, HALF_MAX_MM]` (a negative half-extent gives an empty grid);
//! - `step_mm` must be > 0 (Python divides by zero or builds an empty grid) and the grid may
//!   hold at most [`MAX_AXIS_SAMPLES`] × [`MAX_AXIS_SAMPLES`] cells.

use super::info::RecipeInfo;
use super::kernel::{plan_of, Kernel, Progress, RunResult};
use super::output::RecipeOutput;
use super::picture::{
    pairs,
    series::{BLUE, GREY},
    Mark, Picture, Table, UnitFrame,
};
use crate::args::{finite, in_range, positive, within_limit, ArgSpec, Args, Bound};
use crate::error::RecipeError;
use crate::numpy;
use crate::planar2r::{Arm, Elbow};
use crate::pyfmt::{Cell, CsvText};

/// Shortest link accepted by the 2R recipes, metres: keeps `2 L1 L2` far from underflow.
pub const LINK_MIN_M: f64 = 1e-6;
/// Longest link accepted by the 2R recipes, metres. A classroom or industrial arm is far
/// below 10 m; the IK playground and the drills page state this one limit (it also keeps
/// `J Jᵀ` and `x²` far from overflow).
pub const LINK_MAX_M: f64 = 10.0;
/// Largest grid half-extent, mm (1 km): beyond it nothing about a tabletop arm is left to see.
pub const HALF_MAX_MM: f64 = 1e6;
/// Most samples per axis: 1001 (e.g. half 500 mm at 1 mm steps).
pub const MAX_AXIS_SAMPLES: u64 = 1001;
/// Most grid cells, `MAX_AXIS_SAMPLES²` = 1 002 001: one CSV of about 60 MB, the most a browser
/// tab builds and offers for download without stalling.
pub const MAX_CELLS: u64 = MAX_AXIS_SAMPLES * MAX_AXIS_SAMPLES;

/// The CSV this recipe writes.
pub const FILE_NAME: &str = "ik_workspace.csv";
const HEADER: [&str; 6] = ["x_mm", "y_mm", "reachable", "q1_rad", "q2_rad", "fk_err_mm"];

/// `L1` and `L2` as all three 2R recipes take them (positional arguments 0 and 1).
pub(crate) const LINK_ARGS: [ArgSpec; 2] = [
    ArgSpec::number("L1", "0.12", "upper link length, m")
        .unit("m")
        .limits(Bound::Incl(LINK_MIN_M), Bound::Incl(LINK_MAX_M))
        .hint("recipe-2r-hint-L1"),
    ArgSpec::number("L2", "0.10", "forearm link length, m")
        .unit("m")
        .limits(Bound::Incl(LINK_MIN_M), Bound::Incl(LINK_MAX_M))
        .hint("recipe-2r-hint-L2"),
];

const ARGS: [ArgSpec; 4] = [
    LINK_ARGS[0],
    LINK_ARGS[1],
    ArgSpec::number("half_mm", "200", "grid half-extent, mm")
        .unit("mm")
        .limits(Bound::Incl(0.0), Bound::Incl(HALF_MAX_MM))
        .hint("recipe-ik-workspace-hint-half_mm"),
    ArgSpec::number("step_mm", "10", "grid step, mm")
        .unit("mm")
        .limits(Bound::Excl(0.0), Bound::None)
        .hint("recipe-ik-workspace-hint-step_mm"),
];

/// `ik-workspace`: id, Python file, arguments with the recipe's defaults, output file.
pub const INFO: RecipeInfo = RecipeInfo {
    id: "ik-workspace",
    python: "planar_ik_workspace.py",
    args: &ARGS,
    flags: &[],
    writes: &[FILE_NAME],
    quirks_id: "recipe-ik-workspace-quirks",
    plan: plan_of::<Entry>,
    page: Some("ik-2r"),
};

/// Parameters of the workspace grid (the recipe's defaults: 0.12 m, 0.10 m, 200 mm, 10 mm).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WorkspaceParams {
    /// Upper link length, m.
    pub l1: f64,
    /// Forearm link length, m.
    pub l2: f64,
    /// Grid half-extent, mm: x and y run from `-half_mm` to `+half_mm`.
    pub half_mm: f64,
    /// Grid step, mm.
    pub step_mm: f64,
}

impl Default for WorkspaceParams {
    fn default() -> Self {
        WorkspaceParams {
            l1: 0.12,
            l2: 0.10,
            half_mm: 200.0,
            step_mm: 10.0,
        }
    }
}

/// Checks a link length: finite, > 0 and within [`LINK_MIN_M`, `LINK_MAX_M`].
pub(crate) fn check_link_m(param: &str, value: f64) -> Result<(), RecipeError> {
    finite(param, value)?;
    positive(param, value)?;
    in_range(param, value, LINK_MIN_M, LINK_MAX_M)?;
    Ok(())
}

impl WorkspaceParams {
    /// Checks every parameter; the error names the first bad one.
    pub fn validate(&self) -> Result<(), RecipeError> {
        self.axis().map(|_| ())
    }

    /// Validates and returns the axis in metres (`np.arange(-half, half + 1e-9, step)`).
    fn axis(&self) -> Result<Vec<f64>, RecipeError> {
        check_link_m("L1", self.l1)?;
        check_link_m("L2", self.l2)?;
        finite("half_mm", self.half_mm)?;
        in_range("half_mm", self.half_mm, 0.0, HALF_MAX_MM)?;
        finite("step_mm", self.step_mm)?;
        positive("step_mm", self.step_mm)?;
        let half = self.half_mm / 1000.0;
        let step = self.step_mm / 1000.0;
        let (start, stop) = (-half, half + 1e-9);
        let per_axis = numpy::arange_len(start, stop, step);
        if let Err(RecipeError::TooLarge { count, limit, .. }) =
            within_limit("step_mm", per_axis * per_axis, MAX_CELLS)
        {
            return Err(RecipeError::TooLarge {
                param: "step_mm".to_string(),
                count,
                limit,
                also: vec!["half_mm".to_string()],
                square: true,
            });
        }
        numpy::arange(start, stop, step, "step_mm", MAX_AXIS_SAMPLES)
    }

    /// Cells of the grid (validating first).
    pub fn cells(&self) -> Result<u64, RecipeError> {
        let n = self.axis()?.len() as u64;
        Ok(n * n)
    }
}

/// The sampled grid. Cell `k = ix * ys_mm.len() + iy`; `q1`, `q2`, `err_mm` are NaN where the
/// cell is unreachable.
#[derive(Debug, Clone, PartialEq)]
pub struct Workspace {
    /// Grid x values, mm (`x * 1000` as the recipe prints them).
    pub xs_mm: Vec<f64>,
    /// Grid y values, mm.
    pub ys_mm: Vec<f64>,
    /// Whether `|c2| <= 1` in each cell.
    pub reachable: Vec<bool>,
    /// Elbow-down shoulder angle, rad.
    pub q1: Vec<f64>,
    /// Elbow-down elbow angle (`+acos c2`), rad.
    pub q2: Vec<f64>,
    /// FK(IK(x)) distance from the cell centre, mm.
    pub err_mm: Vec<f64>,
}

/// Runs the recipe's grid: validation, then IK and the FK check in every cell.
///
/// # Example
/// ```
/// use bsv_playground::recipes::ik_workspace::{compute, WorkspaceParams};
/// let ws = compute(&WorkspaceParams::default()).unwrap();
/// assert_eq!((ws.xs_mm.len(), ws.reachable_count()), (41, 1450));
/// ```
pub fn compute(params: &WorkspaceParams) -> Result<Workspace, RecipeError> {
    compute_with(params, &mut Progress::silent())
}

/// [`compute`] reporting its cells as the first half of `progress`.
pub fn compute_with(
    params: &WorkspaceParams,
    progress: &mut Progress,
) -> Result<Workspace, RecipeError> {
    let axis = params.axis()?;
    let arm = Arm {
        l1: params.l1,
        l2: params.l2,
    };
    let cells = axis.len() * axis.len();
    let mut ws = Workspace {
        xs_mm: axis.iter().map(|x| x * 1000.0).collect(),
        ys_mm: axis.iter().map(|y| y * 1000.0).collect(),
        reachable: Vec::with_capacity(cells),
        q1: Vec::with_capacity(cells),
        q2: Vec::with_capacity(cells),
        err_mm: Vec::with_capacity(cells),
    };
    // x and y run over the same array, and x*x + y*y == y*y + x*x exactly, so the transposed
    // cell (iy, ix) has the very same q2 and beta: compute them once per pair (the second
    // time they are read back from the row already done). Bit-for-bit what `Arm::ik` gives.
    let n = axis.len();
    let mut beta = vec![f64::NAN; cells];
    for (ix, &x) in axis.iter().enumerate() {
        progress.phase_at(0, 2, ix as u64, n as u64);
        for (iy, &y) in axis.iter().enumerate() {
            let radial = if iy < ix {
                let k = iy * n + ix;
                ws.reachable[k].then(|| (ws.q2[k], beta[k]))
            } else {
                arm.ik_radial(x * x + y * y, Elbow::Down)
            };
            match radial {
                Some((q2, b)) => {
                    let q1 = crate::math::atan2(y, x) - b;
                    let (xr, yr) = arm.fk(q1, q2);
                    let (dx, dy) = (xr - x, yr - y);
                    ws.reachable.push(true);
                    ws.q1.push(q1);
                    ws.q2.push(q2);
                    // The recipe writes `((xr - x) ** 2 + (yr - y) ** 2) ** 0.5`; this is
                    // round-off noise (~1e-14 mm), so plain products and sqrt are as faithful.
                    ws.err_mm.push((dx * dx + dy * dy).sqrt() * 1000.0);
                    if let Some(slot) = beta.get_mut(ix * n + iy) {
                        *slot = b;
                    }
                }
                None => {
                    ws.reachable.push(false);
                    ws.q1.push(f64::NAN);
                    ws.q2.push(f64::NAN);
                    ws.err_mm.push(f64::NAN);
                }
            }
        }
    }
    Ok(ws)
}

impl Workspace {
    /// Number of reachable cells.
    pub fn reachable_count(&self) -> usize {
        self.reachable.iter().filter(|&&r| r).count()
    }

    /// `ik_workspace.csv` exactly as the recipe writes it.
    pub fn to_csv(&self) -> String {
        self.to_csv_with(&mut Progress::silent())
    }

    /// [`Self::to_csv`] reporting its rows as the second half of `progress`.
    pub fn to_csv_with(&self, progress: &mut Progress) -> String {
        let mut csv = CsvText::with_header(&HEADER);
        let ny = self.ys_mm.len();
        let nx = self.xs_mm.len() as u64;
        for (ix, &x_mm) in self.xs_mm.iter().enumerate() {
            progress.phase_at(1, 2, ix as u64, nx);
            for (iy, &y_mm) in self.ys_mm.iter().enumerate() {
                let k = ix * ny + iy;
                let (x, y) = (Cell::Float(x_mm), Cell::Float(y_mm));
                if self.reachable.get(k).copied().unwrap_or(false) {
                    let cell = |v: &[f64]| Cell::Float(v.get(k).copied().unwrap_or(f64::NAN));
                    csv.row(&[
                        x,
                        y,
                        Cell::Int(1),
                        cell(&self.q1),
                        cell(&self.q2),
                        cell(&self.err_mm),
                    ]);
                } else {
                    csv.row(&[x, y, Cell::Int(0), Cell::Empty, Cell::Empty, Cell::Empty]);
                }
            }
        }
        csv.finish()
    }

    /// The line the recipe prints.
    pub fn summary(&self) -> String {
        let (nx, ny) = (self.xs_mm.len(), self.ys_mm.len());
        format!(
            "grid {nx}×{ny} = {} cells, reachable {} -> {FILE_NAME}",
            nx * ny,
            self.reachable_count()
        )
    }
}

/// Parses the recipe's arguments and validates them.
pub fn params_from_args(args: &Args) -> Result<WorkspaceParams, RecipeError> {
    let params = WorkspaceParams {
        l1: args.f64(0, &ARGS[0])?,
        l2: args.f64(1, &ARGS[1])?,
        half_mm: args.f64(2, &ARGS[2])?,
        step_mm: args.f64(3, &ARGS[3])?,
    };
    params.validate()?;
    Ok(params)
}

/// The recipe's uniform entry ([`Kernel`]).
pub struct Entry;

impl Kernel for Entry {
    type Params = WorkspaceParams;
    const INFO: &'static RecipeInfo = &INFO;

    fn params(args: &Args) -> Result<WorkspaceParams, RecipeError> {
        params_from_args(args)
    }

    fn rows(params: &WorkspaceParams, _args: &Args) -> Result<u64, RecipeError> {
        params.cells()
    }

    fn run(params: &WorkspaceParams, _args: &Args, progress: &mut Progress) -> RunResult {
        let ws = compute_with(params, progress)?;
        let csv = ws.to_csv_with(progress);
        Ok(RecipeOutput::single(FILE_NAME, csv, ws.summary()))
    }
}

/// The home card's picture: the grid's reachable points over the unreachable ones.
pub fn picture(output: &RecipeOutput, aspect: f64) -> Option<Picture> {
    let t = Table::parse(output.file(FILE_NAME)?)?;
    let pts = pairs(&t.col("x_mm")?, &t.col("y_mm")?);
    let reach = t.col("reachable")?;
    let frame = UnitFrame::fit(pts.iter().copied(), Some(aspect));
    let (mut yes, mut no) = (Vec::new(), Vec::new());
    for (p, r) in pts.iter().zip(&reach) {
        if *r > 0.5 { &mut yes } else { &mut no }.push(frame.map(*p));
    }
    Some(Picture {
        marks: vec![
            Mark::Dots {
                series: GREY,
                points: no,
            },
            Mark::Dots {
                series: BLUE,
                points: yes,
            },
        ],
    })
}

#[cfg(test)]
mod tests {
    #[cfg(target_arch = "wasm32")]
    use wasm_bindgen_test::wasm_bindgen_test as test;

    use super::*;
    use crate::recipes::testkit::run_strs;

    fn param_of(err: RecipeError) -> String {
        err.param().unwrap_or("").to_string()
    }

    #[test]
    fn grid_equals_per_cell_ik_bit_for_bit() {
        // The transpose reuse in `compute` must give exactly what `Arm::ik` gives per cell.
        for params in [
            WorkspaceParams::default(),
            WorkspaceParams {
                l1: 0.2,
                l2: 0.15,
                half_mm: 400.0,
                step_mm: 7.0,
            },
            WorkspaceParams {
                l1: 0.1,
                l2: 0.1,
                half_mm: 210.0,
                step_mm: 3.0,
            },
        ] {
            let ws = compute(&params).unwrap();
            let arm = Arm {
                l1: params.l1,
                l2: params.l2,
            };
            let axis = params.axis().unwrap();
            for (ix, &x) in axis.iter().enumerate() {
                for (iy, &y) in axis.iter().enumerate() {
                    let k = ix * axis.len() + iy;
                    match arm.ik(x, y, Elbow::Down) {
                        Some((q1, q2)) => {
                            assert!(ws.reachable[k]);
                            assert_eq!(
                                (ws.q1[k].to_bits(), ws.q2[k].to_bits()),
                                (q1.to_bits(), q2.to_bits())
                            );
                        }
                        None => assert!(!ws.reachable[k]),
                    }
                }
            }
        }
    }

    #[test]
    fn default_grid_counts_and_cells() {
        let ws = compute(&WorkspaceParams::default()).unwrap();
        assert_eq!(
            ws.summary(),
            "grid 41×41 = 1681 cells, reachable 1450 -> ik_workspace.csv"
        );
        assert_eq!(ws.xs_mm.first(), Some(&-200.0));
        assert_eq!(ws.reachable.len(), 1681);
        // golden/ik_default line 1257: cell (ix, iy) = (30, 25), exact.
        let k = 30 * 41 + 25;
        assert_eq!(
            (ws.xs_mm[30], ws.ys_mm[25]),
            (100.00000000000026, 50.00000000000021)
        );
        assert!(ws.reachable[k]);
        assert_eq!(
            (ws.q1[k], ws.q2[k], ws.err_mm[k]),
            (
                -0.42581978074352284,
                2.089590495500249,
                1.3877787807814457e-14
            )
        );
        // The cell nearest the origin (x = 1.7e-13 mm) is inside the inner hole
        // (|L1 - L2| = 20 mm).
        let origin = 20 * 41 + 20;
        assert!(!ws.reachable[origin] && ws.q1[origin].is_nan());
    }

    #[test]
    fn typed_api_agrees_with_csv_path() {
        let params = WorkspaceParams {
            l1: 0.2,
            l2: 0.15,
            half_mm: 60.0,
            step_mm: 7.5,
        };
        let ws = compute(&params).unwrap();
        let out = run_strs::<Entry>(&["0.2", "0.15", "60", "7.5"]).unwrap();
        assert_eq!(out.file(FILE_NAME), Some(ws.to_csv().as_str()));
        assert_eq!(out.summary, ws.summary());
        let text = ws.to_csv();
        let lines: Vec<&str> = text.split("\r\n").collect();
        assert_eq!(lines[0], "x_mm,y_mm,reachable,q1_rad,q2_rad,fk_err_mm");
        assert_eq!(lines.len(), ws.reachable.len() + 2);
        assert!(!text.contains("nan"));
    }

    #[test]
    fn half_zero_is_one_cell() {
        let out = run_strs::<Entry>(&["0.12", "0.10", "0", "10"]).unwrap();
        assert_eq!(
            out.summary,
            "grid 1×1 = 1 cells, reachable 0 -> ik_workspace.csv"
        );
        assert_eq!(
            out.file(FILE_NAME),
            Some("x_mm,y_mm,reachable,q1_rad,q2_rad,fk_err_mm\r\n-0.0,-0.0,0,,,\r\n")
        );
    }

    #[test]
    fn rejections_name_the_parameter() {
        let e = run_strs::<Entry>(&["0"]).unwrap_err();
        assert!(matches!(e, RecipeError::NotPositive { .. }) && param_of(e) == "L1");
        let e = run_strs::<Entry>(&["0.12", "2e6"]).unwrap_err();
        assert!(matches!(e, RecipeError::OutOfRange { .. }) && param_of(e) == "L2");
        let e = run_strs::<Entry>(&["0.12", "0.1", "-5"]).unwrap_err();
        assert!(matches!(e, RecipeError::OutOfRange { .. }) && param_of(e) == "half_mm");
        let e = run_strs::<Entry>(&["0.12", "0.1", "200", "0"]).unwrap_err();
        assert!(matches!(e, RecipeError::NotPositive { .. }) && param_of(e) == "step_mm");
        let e = run_strs::<Entry>(&["0.12", "0.1", "200", "abc"]).unwrap_err();
        assert!(matches!(e, RecipeError::NotANumber { .. }) && param_of(e) == "step_mm");
        let e = run_strs::<Entry>(&["0.12", "0.1", "nan"]).unwrap_err();
        assert!(matches!(e, RecipeError::NotFinite { .. }) && param_of(e) == "half_mm");
        let e = run_strs::<Entry>(&["0.12", "0.1", "1", "2", "3"]).unwrap_err();
        assert!(matches!(e, RecipeError::TooManyArgs { max: 4, got: 5 }));
        // The typed API rejects what the parser cannot produce.
        let nan = WorkspaceParams {
            l2: f64::NAN,
            ..WorkspaceParams::default()
        };
        assert!(matches!(nan.validate(), Err(RecipeError::NotFinite { .. })));
    }

    #[test]
    fn grid_size_limit() {
        // 1001 per axis is the most: half 500 mm at 1 mm.
        let ok = WorkspaceParams {
            half_mm: 500.0,
            step_mm: 1.0,
            ..WorkspaceParams::default()
        };
        assert_eq!(ok.validate(), Ok(()));
        let too_fine = WorkspaceParams {
            half_mm: 500.0,
            step_mm: 0.999,
            ..WorkspaceParams::default()
        };
        match too_fine.validate() {
            Err(RecipeError::TooLarge { param, limit, .. }) => {
                assert_eq!((param.as_str(), limit), ("step_mm", MAX_CELLS));
            }
            other => panic!("{other:?}"),
        }
        let e = run_strs::<Entry>(&["0.12", "0.1", "1e6", "1e-300"]).unwrap_err();
        assert!(matches!(e, RecipeError::TooLarge { .. }) && param_of(e) == "step_mm");
    }
}
