//! The few numpy routines the recipes lean on, reproduced operation for operation so that
//! row counts and values match: `np.arange` for floats.

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

#[cfg(test)]
mod tests {
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
