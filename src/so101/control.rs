//! Differential IK in relative pose mode, as Isaac Lab's `DifferentialIKController`
//! (`isaaclab.controllers.differential_ik`) computes the joint step `Δq` of the SO-101 for a
//! task step `Δx = (dx, dy, dz, droll, dpitch, dyaw)` (world frame, m and rad) with the 6×5
//! geometric Jacobian J of [`super::kinematics`]:
//!
//! ```text
//! dls           Δq = Jᵀ (J Jᵀ + λ² I₆)⁻¹ Δx         λ = lambda_val, 0.01
//! pinv          Δq = k J⁺ Δx = k (JᵀJ)⁻¹ Jᵀ Δx      k = k_val, 1.0
//! trans         Δq = k α Jᵀ Δx                     α = ⟨Δx, J Jᵀ Δx⟩ / |J Jᵀ Δx|²
//! adaptive-dls  Δq = Jᵀ (J Jᵀ + λ(σ)² I₆)⁻¹ Δx      λ(σ) as crate::teleop::control
//! ```
//! The methods, their parameters and ids are [`crate::teleop::control`]'s (the planar arm's
//! page has the same four). With five joints `J Jᵀ` is singular at every pose, so `dls` keeps
//! Isaac Lab's 6×6 form (λ² makes it invertible) and `pinv` solves the 5×5 `JᵀJ`, giving no
//! step at an exactly singular one; `σ_min` is the square root of the smallest eigenvalue of
//! `JᵀJ` by cyclic Jacobi rotations. Arithmetic and `sqrt` only.

use super::kinematics::{jt_j, Jacobian};
use crate::teleop::control::{
    buss_step, damping_sq_for_sigma, smallest_eigenvalue, solve, ControlParams, IkMethod,
};

/// The joint step for the task step `dx` (see the module docs), or `None` when the method's
/// matrix is exactly singular or the step is not finite.
pub fn ik_step(params: &ControlParams, j: &Jacobian, dx: &[f64; 6]) -> Option<[f64; 5]> {
    let dq = match params.method {
        IkMethod::Dls => damped(j, dx, params.lambda * params.lambda)?,
        IkMethod::Pinv => scale(pinv_step(j, dx)?, params.pinv_gain),
        IkMethod::Trans => scale(transpose_step(j, dx), params.trans_gain),
        IkMethod::AdaptiveDls => damped(j, dx, adaptive_damping_sq(params, j))?,
    };
    dq.iter().all(|v| v.is_finite()).then_some(dq)
}

/// `J v` (6 rows).
pub fn apply(j: &Jacobian, v: &[f64; 5]) -> [f64; 6] {
    let mut out = [0.0; 6];
    for (o, row) in out.iter_mut().zip(j) {
        *o = (0..5).map(|k| row[k] * v[k]).sum();
    }
    out
}

/// `Jᵀ v` (5 rows).
fn apply_t(j: &Jacobian, v: &[f64; 6]) -> [f64; 5] {
    let mut out = [0.0; 5];
    for (c, o) in out.iter_mut().enumerate() {
        *o = (0..6).map(|k| j[k][c] * v[k]).sum();
    }
    out
}

fn scale(v: [f64; 5], k: f64) -> [f64; 5] {
    v.map(|x| x * k)
}

/// `Jᵀ (J Jᵀ + damping_sq I)⁻¹ dx`.
fn damped(j: &Jacobian, dx: &[f64; 6], damping_sq: f64) -> Option<[f64; 5]> {
    let mut a = [[0.0; 6]; 6];
    for (r, row) in a.iter_mut().enumerate() {
        for (c, o) in row.iter_mut().enumerate() {
            *o = (0..5).map(|k| j[r][k] * j[c][k]).sum();
        }
        row[r] += damping_sq;
    }
    Some(apply_t(j, &solve(a, *dx)?))
}

/// `(JᵀJ)⁻¹ Jᵀ dx`.
fn pinv_step(j: &Jacobian, dx: &[f64; 6]) -> Option<[f64; 5]> {
    solve(jt_j(j), apply_t(j, dx))
}

/// `α Jᵀ dx` with Buss's α (zero when `J Jᵀ dx` is zero).
fn transpose_step(j: &Jacobian, dx: &[f64; 6]) -> [f64; 5] {
    let jt_dx = apply_t(j, dx);
    let img = apply(j, &jt_dx);
    let num: f64 = dx.iter().zip(&img).map(|(a, b)| a * b).sum();
    let den: f64 = img.iter().map(|v| v * v).sum();
    buss_step(jt_dx, num, den)
}

/// `λ(σ)²` of `adaptive-dls` for Jacobian `j`.
pub fn adaptive_damping_sq(params: &ControlParams, j: &Jacobian) -> f64 {
    damping_sq_for_sigma(params, sigma_min(j))
}

/// Cyclic Jacobi sweeps for the 5×5 eigenvalues (converged long before).
const JACOBI_SWEEPS: usize = 16;

/// The smallest singular value of `j` (cyclic Jacobi rotations of `JᵀJ`).
pub fn sigma_min(j: &Jacobian) -> f64 {
    smallest_eigenvalue(jt_j(j), JACOBI_SWEEPS).max(0.0).sqrt()
}
