//! Differential IK in relative mode, as Isaac Lab's `DifferentialIKController`
//! (`isaaclab.controllers.differential_ik`, `DifferentialIKControllerCfg`) computes the joint
//! step `Δq` for a task-space step `Δx = (Δx, Δz, Δφ)`:
//!
//! ```text
//! dls           Δq = Jᵀ (J Jᵀ + λ² I)⁻¹ Δx           λ = lambda (Isaac Lab's "lambda_val", 0.01)
//! pinv          Δq = k J⁺ Δx = k Jᵀ (J Jᵀ)⁻¹ Δx      k = pinv_gain (Isaac Lab's "k_val", 1.0)
//! trans         Δq = k α Jᵀ Δx                        k = trans_gain (Isaac Lab's "k_val", 1.0)
//!               α = ⟨Δx, J Jᵀ Δx⟩ / |J Jᵀ Δx|²
//! adaptive-dls  Δq = Jᵀ (J Jᵀ + λ(σ)² I)⁻¹ Δx
//!               λ(σ)² = λmin²                                   σ_min ≥ σ_thresh
//!               λ(σ)² = λmin² + (1 − (σ_min / σ_thresh)²) λmax²  σ_min < σ_thresh
//! ```
//! `σ_min` is the smallest singular value of J. The 3×3 solves use Gaussian elimination with
//! partial pivoting and `σ_min` comes from cyclic Jacobi rotations of `J Jᵀ` (a fixed number
//! of sweeps): arithmetic and `sqrt` only, so the same bits natively and in wasm.

#![warn(missing_docs)]

use serde::{Deserialize, Serialize};

/// The IK method of [`ControlParams`], with the ids Isaac Lab uses (`adaptive-dls` for its
/// `adaptive_dls`, kebab-case like every id of the site).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
pub enum IkMethod {
    /// Damped least squares, the default.
    #[default]
    Dls,
    /// Moore–Penrose pseudo-inverse (no damping). J is square here, so `pinv` is `J⁻¹`: it
    /// grows without bound near a singularity, which is what the page lets a class see; at an
    /// exactly singular J (a zero pivot) it gives no step and the arm does not move.
    Pinv,
    /// Jacobian transpose with a gain, scaled by Buss's step size α ("Introduction to inverse
    /// kinematics with Jacobian transpose, pseudoinverse and damped least squares methods",
    /// 2004, eq. 7): the step along `Jᵀ Δx` whose task-space image `J Jᵀ Δx` comes closest to
    /// `Δx`. Isaac Lab's plain `k Jᵀ Δx` has no α; with our task vector mixing metres (links
    /// of about 0.1 m, so `J Jᵀ` ≈ 0.04 m² for position) and radians (≈ 3 for the angle row),
    /// a fixed k either barely moves the tip or makes the angle overshoot many times over.
    /// With α the transpose moves at the commanded size along the best transpose direction,
    /// and still shows its weakness: the direction is not the commanded one.
    Trans,
    /// Damped least squares whose damping grows as the smallest singular value falls (Isaac
    /// Lab's `adaptive_dls` takes the same three parameters, `lambda_min`, `lambda_max`,
    /// `sigma_thresh`; the blend is the classic one of Nakamura–Hanafusa and Chiaverini).
    AdaptiveDls,
}

impl IkMethod {
    /// Every method, in the page's order.
    pub const ALL: [IkMethod; 4] = [
        IkMethod::Dls,
        IkMethod::Pinv,
        IkMethod::Trans,
        IkMethod::AdaptiveDls,
    ];

    /// `dls`, `pinv`, `trans`, `adaptive-dls`.
    pub fn id(self) -> &'static str {
        match self {
            IkMethod::Dls => "dls",
            IkMethod::Pinv => "pinv",
            IkMethod::Trans => "trans",
            IkMethod::AdaptiveDls => "adaptive-dls",
        }
    }

    /// The method with this id (`adaptive_dls` is accepted too, as Isaac Lab spells it).
    pub fn from_id(id: &str) -> Option<IkMethod> {
        match id {
            "dls" => Some(IkMethod::Dls),
            "pinv" => Some(IkMethod::Pinv),
            "trans" => Some(IkMethod::Trans),
            "adaptive-dls" | "adaptive_dls" => Some(IkMethod::AdaptiveDls),
            _ => None,
        }
    }
}

/// The controller's method and parameters.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct ControlParams {
    /// How a task step becomes a joint step.
    pub method: IkMethod,
    /// `dls` damping λ (Isaac Lab's `lambda_val`, default 0.01).
    pub lambda: f64,
    /// `pinv` scale k (Isaac Lab's `k_val`, default 1.0).
    pub pinv_gain: f64,
    /// `trans` scale k on top of Buss's α (Isaac Lab's `k_val`, default 1.0).
    pub trans_gain: f64,
    /// `adaptive-dls` smallest damping λmin (default 0.01).
    pub lambda_min: f64,
    /// `adaptive-dls` largest added damping λmax (default 0.1).
    pub lambda_max: f64,
    /// `adaptive-dls` σ threshold below which damping grows (default 0.02).
    pub sigma_threshold: f64,
}

impl ControlParams {
    /// Isaac Lab's defaults where it has them (λ = 0.01, k = 1), ours otherwise.
    pub const DEFAULT: ControlParams = ControlParams {
        method: IkMethod::Dls,
        lambda: 0.01,
        pinv_gain: 1.0,
        trans_gain: 1.0,
        lambda_min: 0.01,
        lambda_max: 0.1,
        sigma_threshold: 0.02,
    };
}

impl Default for ControlParams {
    fn default() -> Self {
        ControlParams::DEFAULT
    }
}

/// A 3×3 matrix, row-major.
pub type Mat3 = [[f64; 3]; 3];

/// The joint step `Δq` for the task step `dx` with Jacobian `j` (see the module docs), or
/// `None` when the method's matrix is exactly singular or the result is not finite.
///
/// # Example
/// ```
/// use bsv_playground::teleop::{ik_step, ControlParams, IkMethod};
/// let j = [[1.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, 4.0]];
/// let pinv = ControlParams { method: IkMethod::Pinv, ..ControlParams::DEFAULT };
/// assert_eq!(ik_step(&pinv, &j, &[1.0, 1.0, 1.0]), Some([1.0, 0.5, 0.25]));
/// ```
pub fn ik_step(params: &ControlParams, j: &Mat3, dx: &[f64; 3]) -> Option<[f64; 3]> {
    let dq = match params.method {
        IkMethod::Dls => damped(j, dx, params.lambda * params.lambda)?,
        IkMethod::Pinv => scale(damped(j, dx, 0.0)?, params.pinv_gain),
        IkMethod::Trans => scale(transpose_step(j, dx), params.trans_gain),
        IkMethod::AdaptiveDls => damped(j, dx, adaptive_damping_sq(params, j))?,
    };
    dq.iter().all(|v| v.is_finite()).then_some(dq)
}

/// `α Jᵀ dx` with Buss's α (zero when `J Jᵀ dx` is zero).
fn transpose_step(j: &Mat3, dx: &[f64; 3]) -> [f64; 3] {
    let jt_dx = mul_t(j, dx);
    let mut j_jt_dx = [0.0; 3];
    for (row, out) in j_jt_dx.iter_mut().enumerate() {
        *out = j[row][0] * jt_dx[0] + j[row][1] * jt_dx[1] + j[row][2] * jt_dx[2];
    }
    let num = dx[0] * j_jt_dx[0] + dx[1] * j_jt_dx[1] + dx[2] * j_jt_dx[2];
    let den = j_jt_dx[0] * j_jt_dx[0] + j_jt_dx[1] * j_jt_dx[1] + j_jt_dx[2] * j_jt_dx[2];
    buss_step(jt_dx, num, den)
}

/// Buss's `α Jᵀ dx` from `Jᵀ dx` and α's numerator `dx · J Jᵀ dx` and denominator
/// `|J Jᵀ dx|²`: zero when the denominator is (any arm's).
pub fn buss_step<const N: usize>(jt_dx: [f64; N], num: f64, den: f64) -> [f64; N] {
    if den > 0.0 {
        let alpha = num / den;
        jt_dx.map(|v| v * alpha)
    } else {
        [0.0; N]
    }
}

/// `λ(σ)²` of `adaptive-dls` for Jacobian `j`.
pub fn adaptive_damping_sq(params: &ControlParams, j: &Mat3) -> f64 {
    damping_sq_for_sigma(params, sigma_min(j))
}

/// `λ(σ)²` of `adaptive-dls` for a Jacobian whose smallest singular value is `sigma` (any
/// arm's).
pub fn damping_sq_for_sigma(params: &ControlParams, sigma: f64) -> f64 {
    let base = params.lambda_min * params.lambda_min;
    if sigma >= params.sigma_threshold || params.sigma_threshold <= 0.0 {
        return base;
    }
    let ratio = sigma / params.sigma_threshold;
    base + (1.0 - ratio * ratio) * params.lambda_max * params.lambda_max
}

/// `Jᵀ (J Jᵀ + damping_sq I)⁻¹ dx`.
fn damped(j: &Mat3, dx: &[f64; 3], damping_sq: f64) -> Option<[f64; 3]> {
    let mut a = j_jt(j);
    for (i, row) in a.iter_mut().enumerate() {
        row[i] += damping_sq;
    }
    let y = solve3(a, *dx)?;
    Some(mul_t(j, &y))
}

fn scale(v: [f64; 3], k: f64) -> [f64; 3] {
    [v[0] * k, v[1] * k, v[2] * k]
}

/// `Jᵀ v`.
fn mul_t(j: &Mat3, v: &[f64; 3]) -> [f64; 3] {
    let mut out = [0.0; 3];
    for (col, o) in out.iter_mut().enumerate() {
        *o = j[0][col] * v[0] + j[1][col] * v[1] + j[2][col] * v[2];
    }
    out
}

/// `J Jᵀ`.
pub fn j_jt(j: &Mat3) -> Mat3 {
    let mut out = [[0.0; 3]; 3];
    for r in 0..3 {
        for c in 0..3 {
            out[r][c] = j[r][0] * j[c][0] + j[r][1] * j[c][1] + j[r][2] * j[c][2];
        }
    }
    out
}

/// `A x = b` by Gaussian elimination with partial pivoting; `None` at a zero pivot.
pub fn solve3(a: Mat3, b: [f64; 3]) -> Option<[f64; 3]> {
    solve(a, b)
}

/// `A x = b` for any size N by Gaussian elimination with partial pivoting; `None` at a zero
/// pivot.
// Matrix code reads as the textbook writes it, with indices.
#[allow(clippy::needless_range_loop)]
pub fn solve<const N: usize>(mut a: [[f64; N]; N], mut b: [f64; N]) -> Option<[f64; N]> {
    for k in 0..N {
        let mut pivot = k;
        for r in k + 1..N {
            if a[r][k].abs() > a[pivot][k].abs() {
                pivot = r;
            }
        }
        if a[pivot][k] == 0.0 || !a[pivot][k].is_finite() {
            return None;
        }
        a.swap(k, pivot);
        b.swap(k, pivot);
        for r in k + 1..N {
            let m = a[r][k] / a[k][k];
            for c in k..N {
                a[r][c] -= m * a[k][c];
            }
            b[r] -= m * b[k];
        }
    }
    let mut x = [0.0; N];
    for k in (0..N).rev() {
        let mut s = b[k];
        for c in k + 1..N {
            s -= a[k][c] * x[c];
        }
        x[k] = s / a[k][k];
    }
    Some(x)
}

/// Number of cyclic Jacobi sweeps for the 3×3 eigenvalues (converged long before).
const JACOBI_SWEEPS: usize = 12;

/// The smallest singular value of `j`: the square root of the smallest eigenvalue of `J Jᵀ`
/// (cyclic Jacobi rotations, arithmetic and `sqrt` only).
pub fn sigma_min(j: &Mat3) -> f64 {
    smallest_eigenvalue(j_jt(j), JACOBI_SWEEPS).max(0.0).sqrt()
}

/// The smallest eigenvalue of the symmetric matrix `a` after `sweeps` cyclic Jacobi sweeps
/// (pairs (p, q), p < q, in order).
#[allow(clippy::needless_range_loop)]
pub fn smallest_eigenvalue<const N: usize>(mut a: [[f64; N]; N], sweeps: usize) -> f64 {
    for _ in 0..sweeps {
        for p in 0..N {
            for q in p + 1..N {
                if a[p][q] == 0.0 {
                    continue;
                }
                let theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
                let t = theta.signum() / (theta.abs() + (theta * theta + 1.0).sqrt());
                let t = if theta.is_finite() { t } else { 0.0 };
                let c = 1.0 / (t * t + 1.0).sqrt();
                let s = t * c;
                // A' = Rᵀ A R with the rotation in the (p, q) plane.
                for k in 0..N {
                    let (akp, akq) = (a[k][p], a[k][q]);
                    a[k][p] = c * akp - s * akq;
                    a[k][q] = s * akp + c * akq;
                }
                for k in 0..N {
                    let (apk, aqk) = (a[p][k], a[q][k]);
                    a[p][k] = c * apk - s * aqk;
                    a[q][k] = s * apk + c * aqk;
                }
            }
        }
    }
    (1..N).fold(a[0][0], |m, i| m.min(a[i][i]))
}

#[cfg(test)]
mod tests {
    #[cfg(target_arch = "wasm32")]
    use wasm_bindgen_test::wasm_bindgen_test as test;

    use super::*;
    use crate::teleop::arm::{jacobian, ArmParams};
    use nalgebra::{Matrix3, Vector3};

    fn norm(v: &[f64; 3]) -> f64 {
        (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
    }

    /// `Jᵀ (J Jᵀ + λ² I)⁻¹ dx` with nalgebra's own product and LU inverse.
    fn dls_by_nalgebra(j: &Mat3, dx: &[f64; 3], lambda: f64) -> [f64; 3] {
        let jm = Matrix3::from_fn(|r, c| j[r][c]);
        let inner = jm * jm.transpose() + Matrix3::identity() * (lambda * lambda);
        let dq = jm.transpose() * inner.try_inverse().unwrap() * Vector3::from_column_slice(dx);
        [dq[0], dq[1], dq[2]]
    }

    #[test]
    fn one_dls_step_equals_the_formula() {
        let arm = ArmParams::DEFAULT;
        let params = ControlParams::DEFAULT;
        for (q, dx) in [
            ([1.2, -1.3, -1.4], [0.001, -0.0005, 0.008]),
            ([0.4, 0.9, -2.0], [-0.001, 0.0, 0.0]),
            ([2.0, 0.05, 0.3], [0.0, 0.001, -0.004]),
        ] {
            let j = jacobian(&arm, &q);
            let got = ik_step(&params, &j, &dx).unwrap();
            let want = dls_by_nalgebra(&j, &dx, 0.01);
            for i in 0..3 {
                let tol = 1e-12 * want[i].abs().max(1e-9);
                assert!(
                    (got[i] - want[i]).abs() <= tol,
                    "{q:?}: {got:?} vs {want:?}"
                );
            }
        }
    }

    #[test]
    fn dls_stays_bounded_at_the_stretched_out_singularity_where_pinv_does_not() {
        let arm = ArmParams::DEFAULT;
        let dls = ControlParams::DEFAULT;
        let pinv = ControlParams {
            method: IkMethod::Pinv,
            ..dls
        };
        let adaptive = ControlParams {
            method: IkMethod::AdaptiveDls,
            ..dls
        };
        // Stretched out along x, asked to move further out by 1 mm (the direction J lost).
        let dx = [0.001, 0.0, 0.0];
        for q2 in [1e-3, 1e-5, 1e-7] {
            let j = jacobian(&arm, &[0.0, q2, 0.0]);
            let dq_dls = ik_step(&dls, &j, &dx).unwrap();
            // DLS gain is at most 1 / (2 λ) per unit of task motion.
            assert!(norm(&dq_dls) <= 0.001 / (2.0 * 0.01) + 1e-12, "dls {q2}");
            let dq_adaptive = ik_step(&adaptive, &j, &dx).unwrap();
            assert!(norm(&dq_adaptive) <= norm(&dq_dls), "adaptive {q2}");
            let dq_pinv = ik_step(&pinv, &j, &dx).unwrap();
            assert!(
                norm(&dq_pinv) > 1e3 * norm(&dq_dls),
                "pinv {q2}: {}",
                norm(&dq_pinv)
            );
        }
        // Away from it, all three agree closely.
        let j = jacobian(&arm, &[1.2, -1.3, -1.4]);
        let a = ik_step(&dls, &j, &dx).unwrap();
        let b = ik_step(&pinv, &j, &dx).unwrap();
        assert!((norm(&a) - norm(&b)).abs() < 0.05 * norm(&b));
    }

    #[test]
    fn pinv_at_an_exactly_singular_jacobian_gives_none() {
        let j = [[0.0, 0.0, 0.0], [0.28, 0.16, 0.06], [1.0, 1.0, 1.0]];
        let pinv = ControlParams {
            method: IkMethod::Pinv,
            ..ControlParams::DEFAULT
        };
        assert_eq!(ik_step(&pinv, &j, &[0.001, 0.0, 0.0]), None);
        assert!(ik_step(&ControlParams::DEFAULT, &j, &[0.001, 0.0, 0.0]).is_some());
    }

    #[test]
    fn transpose_moves_along_its_best_step() {
        let arm = ArmParams::DEFAULT;
        let trans = ControlParams {
            method: IkMethod::Trans,
            ..ControlParams::DEFAULT
        };
        let j = jacobian(&arm, &[1.2, -1.3, -1.4]);
        let dx = [0.001, 0.0, 0.0];
        let dq = ik_step(&trans, &j, &dx).unwrap();
        // The task-space image J dq is the projection of dx on J Jᵀ dx: no longer than dx,
        // and its residual is orthogonal to it.
        let img: Vec<f64> = (0..3)
            .map(|r| j[r][0] * dq[0] + j[r][1] * dq[1] + j[r][2] * dq[2])
            .collect();
        let dot = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(x, y)| x * y).sum::<f64>();
        let residual: Vec<f64> = (0..3).map(|i| dx[i] - img[i]).collect();
        assert!(dot(&residual, &img).abs() < 1e-18);
        assert!(dot(&img, &img) <= dot(&dx, &dx));
        assert!(img[0] > 0.0);
    }

    #[test]
    fn sigma_min_matches_nalgebra() {
        let arm = ArmParams::DEFAULT;
        for q in [[1.2, -1.3, -1.4], [0.0, 1e-4, 0.0], [2.0, 2.5, -1.0]] {
            let j = jacobian(&arm, &q);
            let svd = Matrix3::from_fn(|r, c| j[r][c]).singular_values();
            let want = svd.min();
            assert!((sigma_min(&j) - want).abs() < 1e-12, "{q:?}");
        }
    }

    #[test]
    fn ids_round_trip() {
        for m in IkMethod::ALL {
            assert_eq!(IkMethod::from_id(m.id()), Some(m));
        }
        assert_eq!(
            IkMethod::from_id("adaptive_dls"),
            Some(IkMethod::AdaptiveDls)
        );
        assert_eq!(IkMethod::from_id("svd"), None);
    }
}
