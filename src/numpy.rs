//! The few numpy routines the recipes lean on, reproduced operation for operation so that
//! row counts and values match: `np.arange` for floats and the `@` matrix product.

use nalgebra::SMatrix;

use crate::error::RecipeError;

/// Length of `np.arange(start, stop, step)`: `ceil((stop - start) / step)`, at least 0.
pub fn arange_len(start: f64, stop: f64, step: f64) -> f64 {
    let delta = stop - start;
    let len = delta / step;
    let len = if len == 0.0 && delta != 0.0 {
        if len.is_sign_negative() {
            0.0
        } else {
            1.0
        }
    } else {
        len.ceil()
    };
    if len.is_nan() {
        0.0
    } else {
        len.max(0.0)
    }
}

/// `np.arange(start, stop, step)` for floats: `start + i * d` where `d = (start + step) - start`,
/// as numpy's fill does. `param` names the argument that sets the size, for the error when the
/// array would hold more than `limit` values.
pub fn arange(
    start: f64,
    stop: f64,
    step: f64,
    param: &str,
    limit: u64,
) -> Result<Vec<f64>, RecipeError> {
    let len = crate::args::within_limit(param, arange_len(start, stop, step), limit)? as usize;
    let mut out = Vec::with_capacity(len);
    if len == 0 {
        return Ok(out);
    }
    out.push(start);
    let d = (start + step) - start;
    for i in 1..len {
        out.push(start + i as f64 * d);
    }
    Ok(out)
}

/// `a · b` summed as numpy's `matmul` does it through OpenBLAS `dgemm`: each entry starts at
/// `0.0` and accumulates `a[i,k] b[k,j]` for `k` in order with a fused multiply-add. So an
/// exactly zero sum is `+0.0`, and the last bits match the reference (the DH golden runs differ
/// in the last digit with separate multiply and add).
///
/// # Example
/// ```
/// use bsv_playground::numpy::matmul;
/// use nalgebra::Matrix2;
/// let a = Matrix2::new(1.0, 2.0, 3.0, 4.0);
/// assert_eq!(matmul(&a, &Matrix2::identity()), a);
/// ```
pub fn matmul<const R: usize, const K: usize, const C: usize>(
    a: &SMatrix<f64, R, K>,
    b: &SMatrix<f64, K, C>,
) -> SMatrix<f64, R, C> {
    SMatrix::from_fn(|i, j| (0..K).fold(0.0, |acc, k| a[(i, k)].mul_add(b[(k, j)], acc)))
}

#[cfg(test)]
mod tests {
    // The same tests run natively and, under `wasm-pack test --node`, as wasm.
    #[cfg(target_arch = "wasm32")]
    use wasm_bindgen_test::wasm_bindgen_test as test;

    use super::*;

    #[test]
    fn arange_matches_numpy_counts() {
        // np.arange(-0.2, 0.2 + 1e-9, 0.01) has 41 values; np.arange(0, 1.57 + 1e-12, 0.1) 16.
        assert_eq!(
            arange(-0.2, 0.2 + 1e-9, 0.01, "step", 100).unwrap().len(),
            41
        );
        assert_eq!(
            arange(0.0, 1.57 + 1e-12, 0.1, "step", 100).unwrap().len(),
            16
        );
        assert_eq!(arange(0.0, 1.0 + 1e-12, 0.02, "dt", 100).unwrap().len(), 51);
        assert!(arange(1.0, 0.0, 0.1, "step", 100).unwrap().is_empty());
        assert!(arange(0.0, 1.0, 1e-9, "step", 100).is_err());
    }
}
