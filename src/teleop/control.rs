//! Differential IK in relative mode, as Isaac Lab's `DifferentialIKController`
//! (`isaaclab.controllers.differential_ik`, `DifferentialIKControllerCfg`) computes the joint
//! step `Δq` for a task-space step `Δx = (Δx, Δz, Δφ)`:
//!
//! ```text
//! dls           Δq = Jᵀ (J Jᵀ + λ² I)⁻¹ Δx           λ = lambda (Isaac Lab's "lambda_val", 0.01)
//! pinv          Δq = k J⁺ Δx = k Jᵀ (J Jᵀ)⁻¹ Δx      k = pinv_gain (Isaac Lab's "k_val", 1.0)
//! trans         Δq = k Jᵀ Δx                          k = trans_gain (see below)
//! adaptive-dls  Δq = Jᵀ (J Jᵀ + λ(σ)² I)⁻¹ Δx
//!               λ(σ)² = λmin²                                   σ_min ≥ σ_thresh
//!               λ(σ)² = λmin² + (1 − (σ_min / σ_thresh)²) λmax²  σ_min < σ_thresh
//! ```
//! `σ_min` is the smallest singular value of J (Isaac Lab's `adaptive_dls` takes the same three
//! parameters, `lambda_min`, `lambda_max`, `sigma_thresh`; the blend is the classic one of
//! Nakamura–Hanafusa and Chiaverini). J is square here, so `pinv` is `J⁻¹`: it grows without
//! bound near a singularity, which is what the page lets a class see; at an exactly singular J
//! (a zero pivot) it returns `None` and the arm does not move.
//!
//! Isaac Lab's transpose default `k_val = 1.0` suits its metre-sized arms; `Jᵀ` has units of
//! metres here (links of about 0.1 m), so `k` has units 1/m² and the default
//! [`ControlParams::DEFAULT`] `trans_gain = 25` (≈ 1 / (0.2 m)²) makes a tip step roughly the
//! commanded size near the start pose.
//!
//! The 3×3 solves use Gaussian elimination with partial pivoting and `σ_min` comes from cyclic
//! Jacobi rotations of `J Jᵀ` (a fixed number of sweeps): arithmetic and `sqrt` only, so the
//! same bits natively and in wasm.

use serde::{Deserialize, Serialize};

/// The IK method of [`ControlParams`], with the ids Isaac Lab uses (`adaptive-dls` for its
/// `adaptive_dls`, kebab-case like every id of the site).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
pub enum IkMethod {
    /// Damped least squares, the default.
    #[default]
    Dls,
    /// Moore–Penrose pseudo-inverse (no damping).
    Pinv,
    /// Jacobian transpose with a gain.
    Trans,
    /// Damped least squares whose damping grows as the smallest singular value falls.
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
    pub method: IkMethod,
    /// `dls` damping λ (Isaac Lab's `lambda_val`, default 0.01).
    pub lambda: f64,
    /// `pinv` scale k (Isaac Lab's `k_val`, default 1.0).
    pub pinv_gain: f64,
    /// `trans` gain k, 1/m² (default 25, see the module docs).
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
        trans_gain: 25.0,
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
        IkMethod::Trans => scale(mul_t(j, dx), params.trans_gain),
        IkMethod::AdaptiveDls => damped(j, dx, adaptive_damping_sq(params, j))?,
    };
    dq.iter().all(|v| v.is_finite()).then_some(dq)
}

/// `λ(σ)²` of `adaptive-dls` for Jacobian `j`.
pub fn adaptive_damping_sq(params: &ControlParams, j: &Mat3) -> f64 {
    let sigma = sigma_min(j);
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
// Matrix code reads as the textbook writes it, with indices.
#[allow(clippy::needless_range_loop)]
pub fn solve3(mut a: Mat3, mut b: [f64; 3]) -> Option<[f64; 3]> {
    for k in 0..3 {
        let mut pivot = k;
        for r in k + 1..3 {
            if a[r][k].abs() > a[pivot][k].abs() {
                pivot = r;
            }
        }
        if a[pivot][k] == 0.0 || !a[pivot][k].is_finite() {
            return None;
        }
        a.swap(k, pivot);
        b.swap(k, pivot);
        for r in k + 1..3 {
            let m = a[r][k] / a[k][k];
            for c in k..3 {
                a[r][c] -= m * a[k][c];
            }
            b[r] -= m * b[k];
        }
    }
    let mut x = [0.0; 3];
    for k in (0..3).rev() {
        let mut s = b[k];
        for c in k + 1..3 {
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
#[allow(clippy::needless_range_loop)]
pub fn sigma_min(j: &Mat3) -> f64 {
    let mut a = j_jt(j);
    for _ in 0..JACOBI_SWEEPS {
        for (p, q) in [(0, 1), (0, 2), (1, 2)] {
            if a[p][q] == 0.0 {
                continue;
            }
            let theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
            let t = theta.signum() / (theta.abs() + (theta * theta + 1.0).sqrt());
            let t = if theta.is_finite() { t } else { 0.0 };
            let c = 1.0 / (t * t + 1.0).sqrt();
            let s = t * c;
            // A' = Rᵀ A R with the rotation in the (p, q) plane.
            for k in 0..3 {
                let akp = a[k][p];
                let akq = a[k][q];
                a[k][p] = c * akp - s * akq;
                a[k][q] = s * akp + c * akq;
            }
            for k in 0..3 {
                let apk = a[p][k];
                let aqk = a[q][k];
                a[p][k] = c * apk - s * aqk;
                a[q][k] = s * apk + c * aqk;
            }
        }
    }
    let smallest = a[0][0].min(a[1][1]).min(a[2][2]);
    smallest.max(0.0).sqrt()
}
