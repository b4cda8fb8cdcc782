//! Recipe `dh-fk` (`dh_fk_chain.py`): forward kinematics of the recipe's 3R demo chain with
//! modified (Craig) Denavit–Hartenberg parameters; every frame's origin and XYZ roll/pitch/yaw.
//!
//! ```text
//! link i: (α_{i-1}, a_{i-1}, d_i, θ_i = q_i + offset_i)
//!            [ cθ      −sθ      0     a    ]
//! T_mdh  =   [ sθ cα    cθ cα   −sα   −sα d ]          T_0 = I,  T_i = T_{i-1} · T_mdh(link i)
//!            [ sθ sα    cθ sα    cα    cα d ]
//!            [ 0        0       0     1    ]
//! rpy (XYZ fixed angles): sy = −R₂₀, cy = sqrt(max(0, 1 − sy²)), pitch = atan2(sy, cy)
//!   cy > 1e-8:  roll = atan2(R₂₁, R₂₂),  yaw = atan2(R₁₀, R₀₀)
//!   otherwise:  roll = atan2(−R₁₂, R₁₁), yaw = 0
//! ```
//!
//! The chain: `(0, 0, 0.10, 0)`, `(−π/2, 0, 0, 0)`, `(0, 0.25, 0, 0)` (metres, radians).
//! The CSV's first row is the base frame written as literal zeros `0,0.0,...`; frame numbers
//! are integers. Products are accumulated as numpy's `matmul` does, from `+0.0` with fused
//! multiply-adds ([`crate::numpy::matmul`]), so the last digits match the reference and
//! negative zeros appear exactly where the recipe makes them: `pitch = atan2(−(+0.0), 1) = −0.0`
//! for a joint frame whose `R₂₀` is zero.

use glam::{DVec2, DVec3};
use nalgebra::{Matrix3, Matrix4};

use super::info::RecipeInfo;
use super::kernel::{plan_of, Kernel, Progress, RunResult};
use super::output::RecipeOutput;
use super::picture::{
    series::{BLUE, GREY, ORANGE},
    Mark, Picture, Table, UnitFrame,
};
use crate::args::{finite, parse_f64, ArgKind, ArgSpec, Args};
use crate::camera3d::{ground_grid, Camera, Preset};
use crate::error::RecipeError;
use crate::numpy::matmul;
use crate::pyfmt::{fixed, Cell, CsvText};

/// The CSV file the recipe writes.
pub const CSV_NAME: &str = "dh_fk.csv";

const CSV_HEADER: [&str; 7] = [
    "frame",
    "x_m",
    "y_m",
    "z_m",
    "roll_rad",
    "pitch_rad",
    "yaw_rad",
];

/// `cos pitch` at or below which [`rpy_xyz`] takes the gimbal branch.
pub const GIMBAL_COS_EPS: f64 = 1e-8;

/// Number of joints of the demo chain.
pub const JOINTS: usize = 3;

/// One link in modified DH form.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MdhLink {
    /// `α_{i-1}`, radians.
    pub alpha: f64,
    /// `a_{i-1}`, metres.
    pub a: f64,
    /// `d_i`, metres.
    pub d: f64,
    /// Added to the joint angle, radians.
    pub theta_offset: f64,
}

/// The recipe's demo 3R chain ("anthropomorphic-ish" lengths).
pub const DEMO_CHAIN: [MdhLink; JOINTS] = [
    MdhLink {
        alpha: 0.0,
        a: 0.0,
        d: 0.10,
        theta_offset: 0.0,
    },
    MdhLink {
        alpha: -std::f64::consts::FRAC_PI_2,
        a: 0.0,
        d: 0.0,
        theta_offset: 0.0,
    },
    MdhLink {
        alpha: 0.0,
        a: 0.25,
        d: 0.0,
        theta_offset: 0.0,
    },
];

const ARGS: [ArgSpec; 1] = [ArgSpec::number(
    "angles",
    "0.2,0.4,-0.3",
    "joint angles q1,q2,q3 in radians, comma-separated",
)
.kind(ArgKind::List { len: JOINTS })
.unit("rad")
.hint("recipe-dh-fk-hint-angles")];

/// What the recipe is, takes and writes.
pub const INFO: RecipeInfo = RecipeInfo {
    id: "dh-fk",
    python: "dh_fk_chain.py",
    args: &ARGS,
    flags: &[],
    writes: &[CSV_NAME],
    quirks_id: "recipe-dh-fk-quirks",
    plan: plan_of::<Entry>,
    page: Some("dh-fk"),
};

/// The link transform `T_mdh(α, a, d, θ)`, entry for entry as the recipe builds it.
pub fn mdh_transform(alpha: f64, a: f64, d: f64, theta: f64) -> Matrix4<f64> {
    let (sa, ca) = crate::math::sincos(alpha);
    let (st, ct) = crate::math::sincos(theta);
    #[rustfmt::skip]
    let t = Matrix4::new(
        ct, -st, 0.0, a,
        st * ca, ct * ca, -sa, -sa * d,
        st * sa, ct * sa, ca, ca * d,
        0.0, 0.0, 0.0, 1.0,
    );
    t
}

/// The recipe's `rpy_xyz`: `(roll, pitch, yaw)` of a rotation (see module docs).
pub fn rpy_xyz(r: &Matrix3<f64>) -> (f64, f64, f64) {
    let sy = -r[(2, 0)];
    let cy = (1.0 - sy * sy).max(0.0).sqrt();
    let (rx, rz) = if cy > GIMBAL_COS_EPS {
        (
            crate::math::atan2(r[(2, 1)], r[(2, 2)]),
            crate::math::atan2(r[(1, 0)], r[(0, 0)]),
        )
    } else {
        (crate::math::atan2(-r[(1, 2)], r[(1, 1)]), 0.0)
    };
    (rx, crate::math::atan2(sy, cy), rz)
}

/// One frame of the chain.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Frame {
    /// 0 for the base, `i` after joint `i`.
    pub index: usize,
    /// Base-to-frame transform.
    pub transform: Matrix4<f64>,
    /// Origin `(x, y, z)`, metres.
    pub origin: [f64; 3],
    /// `(roll, pitch, yaw)` from [`rpy_xyz`], radians.
    pub rpy: (f64, f64, f64),
}

impl Frame {
    fn new(index: usize, transform: Matrix4<f64>) -> Frame {
        let r: Matrix3<f64> = transform.fixed_view::<3, 3>(0, 0).into_owned();
        Frame {
            index,
            transform,
            origin: [transform[(0, 3)], transform[(1, 3)], transform[(2, 3)]],
            rpy: rpy_xyz(&r),
        }
    }
}

/// Base frame plus one frame per joint: `T_i = T_{i-1} · T_mdh(α, a, d, q_i + offset)`.
///
/// # Example
/// ```
/// use bsv_playground::recipes::dh_fk::{forward_kinematics, DEMO_CHAIN};
/// let frames = forward_kinematics(&DEMO_CHAIN, &[0.2, 0.4, -0.3]);
/// assert_eq!(frames.len(), 4);
/// let [x, y, z] = frames[3].origin;
/// assert_eq!((x, y, z), (0.225675274093865, 0.045746642824996776, 0.002645414422837375));
/// ```
pub fn forward_kinematics(chain: &[MdhLink], q: &[f64]) -> Vec<Frame> {
    // The recipe writes the base row as literal zeros (its rpy is not computed: pitch +0.0).
    let mut frames = vec![Frame {
        index: 0,
        transform: Matrix4::identity(),
        origin: [0.0; 3],
        rpy: (0.0, 0.0, 0.0),
    }];
    let mut t = Matrix4::identity();
    for (i, (link, qi)) in chain.iter().zip(q).enumerate() {
        let theta = qi + link.theta_offset;
        t = matmul(&t, &mdh_transform(link.alpha, link.a, link.d, theta));
        frames.push(Frame::new(i + 1, t));
    }
    frames
}

/// The recipe's argument: the demo chain's joint angles.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DhParams {
    /// `q1, q2, q3`, radians.
    pub q: [f64; JOINTS],
}

impl Default for DhParams {
    fn default() -> Self {
        DhParams {
            q: [0.2, 0.4, -0.3],
        }
    }
}

impl DhParams {
    /// The angles must be finite.
    pub fn validate(&self) -> Result<(), RecipeError> {
        for &q in &self.q {
            finite(ARGS[0].name, q)?;
        }
        Ok(())
    }

    /// Parses `"q1,q2,q3"` like the recipe (`float()` of each comma-separated item), then
    /// checks there are exactly three.
    pub fn parse(text: &str) -> Result<DhParams, RecipeError> {
        let values = text
            .split(',')
            .map(|item| parse_f64(ARGS[0].name, item))
            .collect::<Result<Vec<f64>, _>>()?;
        let q: [f64; JOINTS] =
            values
                .as_slice()
                .try_into()
                .map_err(|_| RecipeError::WrongCount {
                    param: ARGS[0].name.to_string(),
                    expected: JOINTS,
                    got: values.len(),
                })?;
        Ok(DhParams { q })
    }

    /// Reads the positional argument.
    pub fn from_args(args: &Args) -> Result<DhParams, RecipeError> {
        DhParams::parse(args.text(0, &ARGS[0]))
    }

    /// The base frame and the three joint frames of the demo chain.
    pub fn frames(&self) -> Result<Vec<Frame>, RecipeError> {
        self.validate()?;
        Ok(forward_kinematics(&DEMO_CHAIN, &self.q))
    }
}

/// Runs the recipe: the frame table and the line the Python recipe prints.
pub fn run(params: &DhParams) -> Result<RecipeOutput, RecipeError> {
    let frames = params.frames()?;
    let mut csv = CsvText::with_header(&CSV_HEADER);
    for f in &frames {
        let [x, y, z] = f.origin;
        let (roll, pitch, yaw) = f.rpy;
        csv.row(&[
            Cell::Int(f.index as i64),
            Cell::Float(x),
            Cell::Float(y),
            Cell::Float(z),
            Cell::Float(roll),
            Cell::Float(pitch),
            Cell::Float(yaw),
        ]);
    }
    let tip = frames.last().map_or([0.0; 3], |f| f.origin);
    let summary = format!(
        "frames {} -> {CSV_NAME}; tip xyz=({},{},{})",
        frames.len(),
        fixed(tip[0], 4),
        fixed(tip[1], 4),
        fixed(tip[2], 4)
    );
    Ok(RecipeOutput::single(CSV_NAME, csv.finish(), summary))
}

/// Reads the positional argument and validates it.
pub fn params_from_args(args: &Args) -> Result<DhParams, RecipeError> {
    let params = DhParams::from_args(args)?;
    params.validate()?;
    Ok(params)
}

/// The recipe's uniform entry ([`Kernel`]).
pub struct Entry;

impl Kernel for Entry {
    type Params = DhParams;
    const INFO: &'static RecipeInfo = &INFO;

    fn params(args: &Args) -> Result<DhParams, RecipeError> {
        params_from_args(args)
    }

    fn rows(_params: &DhParams, _args: &Args) -> Result<u64, RecipeError> {
        Ok(JOINTS as u64 + 1)
    }

    fn run(params: &DhParams, _args: &Args, _progress: &mut Progress) -> RunResult {
        run(params)
    }
}

/// The home card's picture: the chain's joints in an iso view over a ground grid.
pub fn picture(output: &RecipeOutput, aspect: f64) -> Option<Picture> {
    let t = Table::parse(output.file(CSV_NAME)?)?;
    let (x, y, z) = (t.col("x_m")?, t.col("y_m")?, t.col("z_m")?);
    let chain: Vec<DVec3> = (0..x.len()).map(|i| DVec3::new(x[i], y[i], z[i])).collect();
    let cam = Camera::framing(DVec3::new(0.0, 0.0, 0.15), 0.3, Preset::Iso, 1.0, 1.0);
    let grid: Vec<(DVec3, DVec3)> = ground_grid(4, 0.1);
    let project = |p: DVec3| cam.project(p).map(|q| DVec2::new(q.at.x, 1.0 - q.at.y));
    let grid2: Vec<(DVec2, DVec2)> = grid
        .into_iter()
        .filter_map(|(a, b)| Some((project(a)?, project(b)?)))
        .collect();
    let chain2: Vec<DVec2> = chain.into_iter().filter_map(project).collect();
    let frame = UnitFrame::fit(
        chain2
            .iter()
            .copied()
            .chain(grid2.iter().flat_map(|(a, b)| [*a, *b])),
        Some(aspect),
    );
    let grid = Mark::Segments {
        series: GREY,
        pairs: grid2
            .iter()
            .map(|(a, b)| (frame.map(*a), frame.map(*b)))
            .collect(),
    };
    let chain = chain2.iter().map(|p| frame.map(*p)).collect();
    let [line, dots] = Mark::joined_dots(chain, BLUE, ORANGE);
    Some(Picture {
        marks: vec![grid, line, dots],
    })
}

#[cfg(test)]
mod tests {
    #[cfg(target_arch = "wasm32")]
    use wasm_bindgen_test::wasm_bindgen_test as test;

    use super::*;
    use crate::recipes::kernel::run_of;
    use crate::recipes::testkit::run_strs;

    #[test]
    fn reference_runs_are_byte_identical() {
        let out = run_of::<Entry>(&Args::default()).unwrap();
        assert_eq!(
            out.file(CSV_NAME),
            Some(include_str!("../../tests/golden/dh_default/dh_fk.csv"))
        );
        assert_eq!(
            out.summary,
            "frames 4 -> dh_fk.csv; tip xyz=(0.2257,0.0457,0.0026)"
        );
        let out = run_strs::<Entry>(&["1.0,-0.5,2.0"]).unwrap();
        assert_eq!(
            out.file(CSV_NAME),
            Some(include_str!("../../tests/golden/dh_other/dh_fk.csv"))
        );
    }

    #[test]
    fn zero_angles_reach_straight_out() {
        // q = 0: link 3 lies along x at height d1. The base row's pitch is +0.0 (literal), a
        // computed frame's is −0.0 (atan2(−(+0.0), 1)), as in the recipe.
        let frames = DhParams { q: [0.0; 3] }.frames().unwrap();
        let tip = frames[3].origin;
        assert!((tip[0] - 0.25).abs() < 1e-15 && tip[1].abs() < 1e-15);
        assert!((tip[2] - 0.10).abs() < 1e-15);
        assert!(frames[0].rpy.1 == 0.0 && frames[0].rpy.1.is_sign_positive());
        assert!(frames[1].rpy.1 == 0.0 && frames[1].rpy.1.is_sign_negative());
    }

    #[test]
    fn gimbal_branch_of_rpy() {
        // Pitch exactly +90°: R₂₀ = −1; roll from −R₁₂, R₁₁; yaw 0.
        #[rustfmt::skip]
        let r = Matrix3::new(
            0.0, 0.0, 1.0,
            0.0, 1.0, 0.0,
            -1.0, 0.0, 0.0,
        );
        let (roll, pitch, yaw) = rpy_xyz(&r);
        assert_eq!((pitch, yaw), (std::f64::consts::FRAC_PI_2, 0.0));
        assert_eq!(roll, 0.0);
    }

    #[test]
    fn angle_list_errors() {
        assert_eq!(
            run_strs::<Entry>(&["0.1,0.2"]).unwrap_err(),
            RecipeError::WrongCount {
                param: "angles".into(),
                expected: 3,
                got: 2
            }
        );
        assert!(matches!(
            run_strs::<Entry>(&["0.1,0.2,0.3,0.4"]),
            Err(RecipeError::WrongCount { got: 4, .. })
        ));
        assert!(matches!(
            run_strs::<Entry>(&["0.1,,0.3"]),
            Err(RecipeError::NotANumber { .. })
        ));
        assert!(matches!(
            run_strs::<Entry>(&["0.1,nan,0.3"]),
            Err(RecipeError::NotFinite { .. })
        ));
        // Spaces around items are fine, as with Python's float().
        assert!(run_strs::<Entry>(&[" 0.1, 0.2 ,0.3"]).is_ok());
    }

    #[cfg(not(target_arch = "wasm32"))]
    mod properties {
        use super::*;
        use proptest::prelude::*;

        proptest! {
            #[test]
            fn frame_rotations_are_orthonormal(
                q1 in -10.0..10.0f64,
                q2 in -10.0..10.0f64,
                q3 in -10.0..10.0f64,
            ) {
                for f in forward_kinematics(&DEMO_CHAIN, &[q1, q2, q3]) {
                    let r: Matrix3<f64> = f.transform.fixed_view::<3, 3>(0, 0).into_owned();
                    let err = (r * r.transpose() - Matrix3::identity()).abs().max();
                    prop_assert!(err < 1e-12, "frame {}: R Rᵀ - I = {err}", f.index);
                }
            }
        }
    }
}
