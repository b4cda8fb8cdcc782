//! The recipe's geometry: its distance (`np.linalg.norm` of the difference), the nearest node
//! by a linear scan, the 12 check points of a segment, and the length of a path.
//!
//! A segment `a -> b` is clear when none of the 12 points `a (1 - t) + b t`,
//! `t = np.linspace(0, 1, 12)`, lies in a (closed) box, so a thin corner can be cut.
//! `|v|` is `sqrt(vx * vx + vy * vy)`.

use super::world::{OBSTACLE, SEGMENT_CHECKS};

/// `np.linalg.norm` of a 2-vector.
pub(super) fn norm(v: [f64; 2]) -> f64 {
    (v[0] * v[0] + v[1] * v[1]).sqrt()
}

/// The recipe's distance from node `p` to the sample `q`: `norm(p - q)`.
#[inline]
pub(super) fn distance(p: [f64; 2], q: [f64; 2]) -> f64 {
    norm([p[0] - q[0], p[1] - q[1]])
}

/// The recipe's nearest node by a linear scan: `np.argmin` of the distances (the first index
/// among equal ones). The reference [`NearestIndex`](super::NearestIndex) is tested
/// against.
pub fn nearest_linear(nodes: &[[f64; 2]], q: [f64; 2]) -> usize {
    let mut best = (0, f64::INFINITY);
    for (i, node) in nodes.iter().enumerate() {
        let d = distance(*node, q);
        if d < best.1 {
            best = (i, d);
        }
    }
    best.0
}

/// The 12 points `a (1 - t) + b t`, `t = np.linspace(0, 1, 12)`.
pub fn check_points(a: [f64; 2], b: [f64; 2]) -> [[f64; 2]; SEGMENT_CHECKS] {
    let last = SEGMENT_CHECKS - 1;
    let spacing = 1.0 / last as f64;
    std::array::from_fn(|k| {
        // np.linspace: k * step (+ 0.0), with the end point set to exactly 1.
        let t = if k == last { 1.0 } else { k as f64 * spacing };
        [a[0] * (1.0 - t) + b[0] * t, a[1] * (1.0 - t) + b[1] * t]
    })
}

/// The recipe's `segment_clear(a, b)`: no point `a (1 - t) + b t`, `t = np.linspace(0, 1, 12)`,
/// in the recipe's obstacle.
pub fn segment_clear(a: [f64; 2], b: [f64; 2]) -> bool {
    check_points(a, b).iter().all(|p| !OBSTACLE.contains(*p))
}

/// Sum of segment lengths in order; NaN for an empty path (the recipe prints `length=nan`).
pub fn path_length(path: &[[f64; 2]]) -> f64 {
    if path.is_empty() {
        return f64::NAN;
    }
    path.windows(2)
        .map(|w| norm([w[1][0] - w[0][0], w[1][1] - w[0][1]]))
        .fold(0.0, |sum, d| sum + d)
}
