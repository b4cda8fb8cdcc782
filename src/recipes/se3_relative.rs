//! Recipe `se3-relative` (`se3_relative_pose.py`): the pose of frame B seen from frame A,
//! `T_rel = T_A⁻¹ T_B`, from two `x y z roll pitch yaw` poses; also the numpy-order matrix
//! product the kinematics recipes share.
//!
//! ```text
//! R(roll, pitch, yaw) = Rz(yaw) · Ry(pitch) · Rx(roll)          (Z·Y·X, "yaw-pitch-roll")
//! T = [ R  p ]        T⁻¹ = [ Rᵀ  −Rᵀ p ]        T_rel = T_A⁻¹ · T_B
//!     [ 0  1 ]              [ 0     1   ]
//! pitch = asin(clip(−R₂₀, −1, 1))
//! |cos pitch| ≥ 1e-8:  roll = atan2(R₂₁, R₂₂),  yaw = atan2(R₁₀, R₀₀)
//! otherwise (gimbal):  roll = 0,                yaw = atan2(−R₀₁, R₁₁)
//! ```
//!
//! Angles are in **radians**. The recipe's docstring says "Degrees for RPY input", but its
//! code feeds the numbers straight to `cos`/`sin`: the defaults (`0.2 0.1 -0.3`) are radians,
//! and so are ours.
//!
//! The recipe inverts `T_A` with `np.linalg.inv` (LU); we use the exact rigid inverse above,
//! which agrees to rounding (about 1e-16). Products are summed as numpy's `matmul` does
//! (`acc = 0; acc = fma(a, b, acc)` in index order, see [`crate::numpy::matmul`]), so an exactly zero entry is
//! `+0.0` as in numpy, and `-0.0` appears only where the recipe negates (`pitch = asin(−0.0)`).

use glam::{DVec2, DVec3};
use nalgebra::{Matrix3, Matrix4, SMatrix, Vector3};

use super::info::RecipeInfo;
use super::kernel::{plan_of, Kernel, Progress, RunResult};
use super::output::RecipeOutput;
use super::picture::{series, Mark, Picture, UnitFrame};
use crate::args::{finite, ArgSpec, Args};
use crate::camera3d::{Camera, Preset};
use crate::error::RecipeError;
use crate::numpy::matmul;
use crate::pyfmt::{fixed, CsvText};

/// The CSV file the recipe writes.
pub const CSV_NAME: &str = "se3_relative.csv";

const CSV_HEADER: [&str; 6] = ["x_m", "y_m", "z_m", "roll_rad", "pitch_rad", "yaw_rad"];

/// `|cos pitch|` below which the recipe treats the rotation as gimbal-locked.
pub const GIMBAL_COS_EPS: f64 = 1e-8;

const ARGS: [ArgSpec; 12] = [
    ArgSpec::number("ax", "0", "pose A x, metres")
        .unit("m")
        .hint("recipe-se3-relative-hint-position"),
    ArgSpec::number("ay", "0", "pose A y, metres")
        .unit("m")
        .hint("recipe-se3-relative-hint-position"),
    ArgSpec::number("az", "0", "pose A z, metres")
        .unit("m")
        .hint("recipe-se3-relative-hint-position"),
    ArgSpec::number("ar", "0", "pose A roll (about x), radians")
        .unit("rad")
        .hint("recipe-se3-relative-hint-angle"),
    ArgSpec::number("ap", "0", "pose A pitch (about y), radians")
        .unit("rad")
        .hint("recipe-se3-relative-hint-angle"),
    ArgSpec::number("aw", "0", "pose A yaw (about z), radians")
        .unit("rad")
        .hint("recipe-se3-relative-hint-angle"),
    ArgSpec::number("bx", "0.1", "pose B x, metres")
        .unit("m")
        .hint("recipe-se3-relative-hint-position"),
    ArgSpec::number("by", "0.05", "pose B y, metres")
        .unit("m")
        .hint("recipe-se3-relative-hint-position"),
    ArgSpec::number("bz", "0.02", "pose B z, metres")
        .unit("m")
        .hint("recipe-se3-relative-hint-position"),
    ArgSpec::number("br", "0.2", "pose B roll (about x), radians")
        .unit("rad")
        .hint("recipe-se3-relative-hint-angle"),
    ArgSpec::number("bp", "0.1", "pose B pitch (about y), radians")
        .unit("rad")
        .hint("recipe-se3-relative-hint-angle"),
    ArgSpec::number("bw", "-0.3", "pose B yaw (about z), radians")
        .unit("rad")
        .hint("recipe-se3-relative-hint-angle"),
];

/// What the recipe is, takes and writes.
pub const INFO: RecipeInfo = RecipeInfo {
    id: "se3-relative",
    python: "se3_relative_pose.py",
    args: &ARGS,
    flags: &[],
    writes: &[CSV_NAME],
    quirks_id: "recipe-se3-relative-quirks",
    plan: plan_of::<Entry>,
    page: Some("se3-relative"),
};

/// A pose as the recipe takes it: position in metres, roll/pitch/yaw in radians (Z·Y·X).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Pose {
    pub x: f64,
    pub y: f64,
    pub z: f64,
    pub roll: f64,
    pub pitch: f64,
    pub yaw: f64,
}

impl Pose {
    /// From `[x, y, z, roll, pitch, yaw]`.
    pub fn from_array(v: [f64; 6]) -> Pose {
        let [x, y, z, roll, pitch, yaw] = v;
        Pose {
            x,
            y,
            z,
            roll,
            pitch,
            yaw,
        }
    }

    /// `[x, y, z, roll, pitch, yaw]`.
    pub fn to_array(&self) -> [f64; 6] {
        [self.x, self.y, self.z, self.roll, self.pitch, self.yaw]
    }

    /// The homogeneous transform `[R p; 0 1]` (the recipe's `pose_to_T`).
    pub fn to_matrix(&self) -> Matrix4<f64> {
        let r = rpy_to_rotation(self.roll, self.pitch, self.yaw);
        let mut t = Matrix4::identity();
        t.fixed_view_mut::<3, 3>(0, 0).copy_from(&r);
        t.fixed_view_mut::<3, 1>(0, 3)
            .copy_from(&Vector3::new(self.x, self.y, self.z));
        t
    }

    /// The pose of a transform: its translation and [`rotation_to_rpy`] of its rotation.
    pub fn from_matrix(t: &Matrix4<f64>) -> Pose {
        let r: Matrix3<f64> = t.fixed_view::<3, 3>(0, 0).into_owned();
        let (roll, pitch, yaw) = rotation_to_rpy(&r);
        Pose {
            x: t[(0, 3)],
            y: t[(1, 3)],
            z: t[(2, 3)],
            roll,
            pitch,
            yaw,
        }
    }
}

/// `Rz(yaw) · Ry(pitch) · Rx(roll)`, multiplied left to right as the recipe does.
pub fn rpy_to_rotation(roll: f64, pitch: f64, yaw: f64) -> Matrix3<f64> {
    let (sr, cr) = crate::math::sincos(roll);
    let (sp, cp) = crate::math::sincos(pitch);
    let (sy, cy) = crate::math::sincos(yaw);
    #[rustfmt::skip]
    let rz = Matrix3::new(
        cy, -sy, 0.0,
        sy, cy, 0.0,
        0.0, 0.0, 1.0,
    );
    #[rustfmt::skip]
    let ry = Matrix3::new(
        cp, 0.0, sp,
        0.0, 1.0, 0.0,
        -sp, 0.0, cp,
    );
    #[rustfmt::skip]
    let rx = Matrix3::new(
        1.0, 0.0, 0.0,
        0.0, cr, -sr,
        0.0, sr, cr,
    );
    matmul(&matmul(&rz, &ry), &rx)
}

/// The recipe's `R_to_rpy`: `(roll, pitch, yaw)` with `pitch = asin(clip(−R₂₀))` in
/// `[−π/2, π/2]`; at gimbal lock (`|cos pitch| < 1e-8`) roll is 0 and yaw takes it all.
pub fn rotation_to_rpy(r: &Matrix3<f64>) -> (f64, f64, f64) {
    let pitch = crate::math::asin((-r[(2, 0)]).clamp(-1.0, 1.0));
    if crate::math::cos(pitch).abs() < GIMBAL_COS_EPS {
        (0.0, pitch, crate::math::atan2(-r[(0, 1)], r[(1, 1)]))
    } else {
        (
            crate::math::atan2(r[(2, 1)], r[(2, 2)]),
            pitch,
            crate::math::atan2(r[(1, 0)], r[(0, 0)]),
        )
    }
}

/// The inverse of a rigid transform `[R p; 0 1]`: `[Rᵀ −Rᵀp; 0 1]`.
pub fn rigid_inverse(t: &Matrix4<f64>) -> Matrix4<f64> {
    let rt: Matrix3<f64> = t.fixed_view::<3, 3>(0, 0).transpose();
    let p: SMatrix<f64, 3, 1> = t.fixed_view::<3, 1>(0, 3).into_owned();
    let rt_p = matmul(&rt, &p);
    let mut inv = Matrix4::identity();
    inv.fixed_view_mut::<3, 3>(0, 0).copy_from(&rt);
    inv.fixed_view_mut::<3, 1>(0, 3).copy_from(&(-rt_p));
    inv
}

/// `T_A⁻¹ · T_B`: frame B expressed in frame A.
pub fn relative_transform(a: &Pose, b: &Pose) -> Matrix4<f64> {
    matmul(&rigid_inverse(&a.to_matrix()), &b.to_matrix())
}

/// The recipe's arguments; `Default` is the recipe's (A at the origin, B a small offset).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Se3Params {
    pub a: Pose,
    pub b: Pose,
}

impl Default for Se3Params {
    fn default() -> Self {
        Se3Params {
            a: Pose::default(),
            b: Pose::from_array([0.1, 0.05, 0.02, 0.2, 0.1, -0.3]),
        }
    }
}

impl Se3Params {
    /// All twelve numbers must be finite.
    pub fn validate(&self) -> Result<(), RecipeError> {
        let values = self.a.to_array().into_iter().chain(self.b.to_array());
        for (value, spec) in values.zip(&ARGS) {
            finite(spec.name, value)?;
        }
        Ok(())
    }

    /// Reads the twelve positional numbers.
    pub fn from_args(args: &Args) -> Result<Se3Params, RecipeError> {
        let mut v = [0.0; 12];
        for (i, (slot, spec)) in v.iter_mut().zip(&ARGS).enumerate() {
            *slot = args.f64(i, spec)?;
        }
        let [ax, ay, az, ar, ap, aw, bx, by, bz, br, bp, bw] = v;
        Ok(Se3Params {
            a: Pose::from_array([ax, ay, az, ar, ap, aw]),
            b: Pose::from_array([bx, by, bz, br, bp, bw]),
        })
    }

    /// The relative pose `T_A⁻¹ T_B` as the recipe reports it.
    pub fn relative(&self) -> Result<Pose, RecipeError> {
        self.validate()?;
        Ok(Pose::from_matrix(&relative_transform(&self.a, &self.b)))
    }
}

/// Runs the recipe: one CSV row and the line the Python recipe prints.
pub fn run(params: &Se3Params) -> Result<RecipeOutput, RecipeError> {
    let rel = params.relative()?;
    let mut csv = CsvText::with_header(&CSV_HEADER);
    csv.floats(&rel.to_array());
    let f = |v: f64| fixed(v, 4);
    let summary = format!(
        "T_A^-1 T_B xyz=({},{},{}) rpy=({},{},{}) -> {CSV_NAME}",
        f(rel.x),
        f(rel.y),
        f(rel.z),
        f(rel.roll),
        f(rel.pitch),
        f(rel.yaw)
    );
    Ok(RecipeOutput::single(CSV_NAME, csv.finish(), summary))
}

/// Reads the twelve positional numbers and validates them.
pub fn params_from_args(args: &Args) -> Result<Se3Params, RecipeError> {
    let params = Se3Params::from_args(args)?;
    params.validate()?;
    Ok(params)
}

/// The recipe's uniform entry ([`Kernel`]).
pub struct Entry;

impl Kernel for Entry {
    type Params = Se3Params;
    const INFO: &'static RecipeInfo = &INFO;

    fn params(args: &Args) -> Result<Se3Params, RecipeError> {
        params_from_args(args)
    }

    fn rows(_params: &Se3Params, _args: &Args) -> Result<u64, RecipeError> {
        Ok(1)
    }

    fn run(params: &Se3Params, _args: &Args, _progress: &mut Progress) -> RunResult {
        run(params)
    }
}

/// The home card's picture: frames A and B (the recipe's defaults) as triads in an iso view,
/// with the arrow A → B.
pub fn picture(_output: &RecipeOutput, aspect: f64) -> Option<Picture> {
    let params = Se3Params::default();
    let cam = Camera::framing(DVec3::new(0.05, 0.025, 0.01), 0.12, Preset::Iso, 1.0, 1.0);
    let project = |p: DVec3| cam.project(p).map(|q| DVec2::new(q.at.x, 1.0 - q.at.y));
    let triad = |t: Matrix4<f64>, len: f64| -> Vec<(u8, DVec2, DVec2)> {
        let o = DVec3::new(t[(0, 3)], t[(1, 3)], t[(2, 3)]);
        (0..3)
            .filter_map(|k| {
                let axis = DVec3::new(t[(0, k)], t[(1, k)], t[(2, k)]);
                Some((k as u8, project(o)?, project(o + axis * len)?))
            })
            .collect()
    };
    let mut axes = triad(params.a.to_matrix(), 0.05);
    axes.extend(triad(params.b.to_matrix(), 0.05));
    let arrow: Vec<DVec2> = [params.a, params.b]
        .iter()
        .filter_map(|p| project(DVec3::new(p.x, p.y, p.z)))
        .collect();
    let frame = UnitFrame::fit(
        axes.iter()
            .flat_map(|(_, a, b)| [*a, *b])
            .chain(arrow.iter().copied()),
        Some(aspect),
    );
    let colour = |k: u8| match k {
        0 => series::RED,
        1 => series::GREEN,
        _ => series::BLUE,
    };
    let mut marks: Vec<Mark> = (0..3u8)
        .map(|k| Mark::Segments {
            series: colour(k),
            pairs: axes
                .iter()
                .filter(|(axis, _, _)| *axis == k)
                .map(|(_, a, b)| (frame.map(*a), frame.map(*b)))
                .collect(),
        })
        .collect();
    marks.push(Mark::Line {
        series: series::ORANGE,
        points: arrow.iter().map(|p| frame.map(*p)).collect(),
    });
    Some(Picture { marks })
}

#[cfg(test)]
mod tests {
    #[cfg(target_arch = "wasm32")]
    use wasm_bindgen_test::wasm_bindgen_test as test;

    use super::*;
    use crate::recipes::kernel::run_of;
    use crate::recipes::testkit::args_strs;

    #[test]
    fn default_run_is_byte_identical_to_the_reference() {
        let out = run_of::<Entry>(&Args::default()).unwrap();
        assert_eq!(
            out.file(CSV_NAME),
            Some(include_str!(
                "../../tests/golden/se3_default/se3_relative.csv"
            ))
        );
        assert_eq!(
            out.summary,
            "T_A^-1 T_B xyz=(0.1000,0.0500,0.0200) rpy=(0.2000,0.1000,-0.3000) -> se3_relative.csv"
        );
    }

    #[test]
    fn same_pose_gives_identity_with_numpy_zero_signs() {
        // T_A⁻¹ T_A = I: translation +0.0 (matmul sums), pitch = asin(-(+0.0)) = -0.0.
        let p = ["0.3", "-0.2", "0.1", "0.5", "-0.4", "1.2"];
        let raw: Vec<&str> = p.iter().chain(p.iter()).copied().collect();
        let rel = Se3Params::from_args(&args_strs::<Entry>(&raw).unwrap())
            .unwrap()
            .relative()
            .unwrap();
        for v in rel.to_array() {
            assert!(v.abs() < 1e-15, "{rel:?}");
        }
        let out = run_of::<Entry>(&args_strs::<Entry>(&["0"; 12]).unwrap()).unwrap();
        assert_eq!(
            out.file(CSV_NAME).unwrap(),
            "x_m,y_m,z_m,roll_rad,pitch_rad,yaw_rad\r\n0.0,0.0,0.0,0.0,-0.0,0.0\r\n"
        );
    }

    #[test]
    fn relative_pose_composes_back() {
        // T_A · T_rel = T_B for a rotated, translated A.
        let a = Pose::from_array([0.4, -0.1, 0.25, -0.7, 0.3, 2.0]);
        let b = Pose::from_array([-0.2, 0.5, 0.05, 0.1, -1.1, -2.5]);
        let back = a.to_matrix() * relative_transform(&a, &b);
        assert!((back - b.to_matrix()).abs().max() < 1e-14);
    }

    #[test]
    fn gimbal_lock_branch() {
        let r = rpy_to_rotation(0.3, std::f64::consts::FRAC_PI_2, 0.5);
        let (roll, pitch, yaw) = rotation_to_rpy(&r);
        assert_eq!(roll, 0.0);
        assert!((pitch - std::f64::consts::FRAC_PI_2).abs() < 1e-7);
        // Only yaw - roll is observable at pitch = +90°.
        assert!((yaw - (0.5 - 0.3)).abs() < 1e-7, "{yaw}");
    }

    #[test]
    fn rejects_non_numbers() {
        assert!(matches!(
            run_of::<Entry>(&args_strs::<Entry>(&["0", "x"]).unwrap()),
            Err(RecipeError::NotANumber { param, .. }) if param == "ay"
        ));
        let p = Se3Params {
            b: Pose::from_array([0.0, 0.0, f64::NAN, 0.0, 0.0, 0.0]),
            ..Se3Params::default()
        };
        assert!(matches!(
            run(&p),
            Err(RecipeError::NotFinite { param }) if param == "bz"
        ));
    }

    #[cfg(not(target_arch = "wasm32"))]
    mod properties {
        use super::*;
        use proptest::prelude::*;

        const PI: f64 = std::f64::consts::PI;

        proptest! {
            #[test]
            fn rpy_round_trips_away_from_gimbal_lock(
                roll in -PI + 1e-6..PI - 1e-6,
                pitch in -1.5..1.5f64,
                yaw in -PI + 1e-6..PI - 1e-6,
            ) {
                let r = rpy_to_rotation(roll, pitch, yaw);
                let (r2, p2, y2) = rotation_to_rpy(&r);
                prop_assert!((r2 - roll).abs() < 1e-9, "roll {roll} -> {r2}");
                prop_assert!((p2 - pitch).abs() < 1e-9, "pitch {pitch} -> {p2}");
                prop_assert!((y2 - yaw).abs() < 1e-9, "yaw {yaw} -> {y2}");
            }

            #[test]
            fn rotation_is_orthonormal(
                roll in -10.0..10.0f64,
                pitch in -10.0..10.0f64,
                yaw in -10.0..10.0f64,
            ) {
                let r = rpy_to_rotation(roll, pitch, yaw);
                let err = (r * r.transpose() - Matrix3::identity()).abs().max();
                prop_assert!(err < 1e-12, "R Rᵀ - I = {err}");
                prop_assert!((r.determinant() - 1.0).abs() < 1e-12);
            }
        }
    }
}
