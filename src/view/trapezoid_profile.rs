//! The trapezoid-profile page (`#/trapezoid-profile`), plain Rust: the three phases of a
//! profile (accelerate, cruise, brake) with their times, whether it is a triangle (the
//! distance is too short to reach vmax), the peak velocity actually reached, and the values a
//! drag on the velocity plot gives.
//!
//! ```text
//! t_acc = vmax / amax;  triangle when amax · t_acc² ≥ D:  t_acc = √(D / amax), t_flat = 0
//! otherwise t_flat = (D − amax · t_acc²) / vmax;   t_total = 2 t_acc + t_flat
//! ```
//! (the kernel's own operations, so `t_total` is the kernel's to the last bit).

use std::iter::Take;

use crate::pyfmt::py_round;
use crate::recipes::trapezoid_profile::{self, TrapParams, TrapSample, MAX_ROWS};
use crate::view::signal::SignalRow;

/// The phases of one profile, s; the velocity reached.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Phases {
    pub triangle: bool,
    pub t_acc: f64,
    pub t_flat: f64,
    pub t_total: f64,
    /// The cruise speed reached (below |vmax| for a triangle).
    pub v_peak: f64,
    /// |vmax|, |amax|, |distance| as the recipe uses them.
    pub vmax: f64,
    pub amax: f64,
    pub distance: f64,
    /// The distance of the ramp at the asked vmax (kept for the brake phase, as the recipe
    /// does, also for a triangle).
    pub d_acc: f64,
}

/// The phases of `p` (valid parameters), computed as the kernel computes them.
pub fn phases(p: &TrapParams) -> Phases {
    let (distance, vmax, amax) = (p.distance.abs(), p.vmax.abs(), p.amax.abs());
    let mut t_acc = vmax / amax;
    // `t_acc ** 2`: pow(x, 2) is the correctly rounded square, one product (`math::pow`).
    let d_acc = 0.5 * amax * (t_acc * t_acc);
    let triangle = 2.0 * d_acc >= distance;
    let (t_flat, v_peak) = if triangle {
        t_acc = (distance / amax).sqrt();
        (0.0, amax * t_acc)
    } else {
        ((distance - 2.0 * d_acc) / vmax, vmax)
    };
    Phases {
        triangle,
        t_acc,
        t_flat,
        t_total: 2.0 * t_acc + t_flat,
        v_peak,
        vmax,
        amax,
        distance,
        d_acc,
    }
}

/// The kernel's samples of valid `p` ([`trapezoid_profile::samples`]: s, v, a and the row
/// count are the CSV's to the last bit), with the accumulated time left unrounded (the kernel
/// prints `round(t, 5)` through a decimal formatting on every row, which costs more than the
/// loop), one row at a time, at most [`MAX_ROWS`], and about how many
/// ([`TrapParams::rows_estimate`]): what the page computes, in slices when there are many;
/// none for invalid `p`.
pub fn rows(p: &TrapParams) -> Option<(Take<trapezoid_profile::Samples>, u64)> {
    let rows = trapezoid_profile::samples(p).ok()?;
    Some((rows.take(MAX_ROWS as usize), p.rows_estimate()))
}

/// The three phases as time bands `(start, end)`: accelerate, cruise (empty for a triangle),
/// brake.
pub fn bands(ph: &Phases) -> [(f64, f64); 3] {
    let cruise_end = ph.t_acc + ph.t_flat;
    [
        (0.0, ph.t_acc),
        (ph.t_acc, cruise_end),
        (cruise_end, ph.t_total),
    ]
}

/// The amax of a drag of the ramp's corner to `(t, v)` on the velocity plot: the slope from
/// the origin (`None` when the point is not up and to the right).
pub fn amax_from_corner(t: f64, v: f64) -> Option<f64> {
    (t > 0.0 && v > 0.0).then(|| v / t)
}

impl SignalRow for TrapSample {
    const CURSOR: [&'static str; 4] = ["cursor-t", "cursor-s", "cursor-v", "cursor-a"];

    fn t(&self) -> f64 {
        self.t
    }

    /// The CSV's row: its time as the CSV writes it (`round(t, 5)`).
    fn cursor_values(&self) -> [f64; 4] {
        [py_round(self.t, 5), self.s, self.v, self.a]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::recipes::trapezoid_profile::compute;

    #[test]
    fn phases_match_the_kernel_s_profile() {
        for (raw, triangle) in [
            (TrapParams::default(), false),
            (
                TrapParams {
                    distance: 0.2,
                    vmax: 1.0,
                    amax: 2.0,
                    dt: 0.005,
                },
                true,
            ),
            (
                TrapParams {
                    distance: -3.0,
                    vmax: 2.0,
                    amax: -4.0,
                    dt: 0.07,
                },
                false,
            ),
        ] {
            let ph = phases(&raw);
            let profile = compute(&raw).unwrap();
            assert_eq!(ph.triangle, triangle);
            assert_eq!(ph.triangle, profile.triangle);
            assert_eq!(ph.t_total, profile.t_total);
            assert_eq!(ph.v_peak, profile.vmax_used);
            // Every sample's acceleration says which band it is in.
            let [acc, cruise, brake] = bands(&ph);
            for s in &profile.samples {
                let t = s.t;
                if t < acc.1 - 1e-9 {
                    assert_eq!(s.a, ph.amax, "t = {t}");
                } else if t > cruise.0 + 1e-9 && t < cruise.1 - 1e-9 {
                    assert_eq!(s.a, 0.0, "t = {t}");
                } else if t > brake.0 + 1e-9 {
                    assert_eq!(s.a, -ph.amax, "t = {t}");
                }
            }
        }
        let d = phases(&TrapParams::default());
        assert_eq!(
            (d.t_acc, d.t_flat, d.t_total, d.v_peak),
            (0.5, 1.5, 2.5, 0.5)
        );
    }

    #[test]
    fn the_fast_samples_are_the_kernel_s() {
        for p in [
            TrapParams::default(),
            TrapParams {
                distance: 0.2,
                vmax: 1.0,
                amax: 2.0,
                dt: 0.005,
            },
            TrapParams {
                distance: 0.0,
                vmax: 0.5,
                amax: 1.0,
                dt: 0.01,
            },
            TrapParams {
                distance: -3.0,
                vmax: 2.0,
                amax: -4.0,
                dt: 0.00007,
            },
        ] {
            let fast: Vec<TrapSample> = rows(&p).unwrap().0.collect();
            let kernel = compute(&p).unwrap().samples;
            assert_eq!(fast.len(), kernel.len(), "{p:?}");
            for (f, k) in fast.iter().zip(&kernel) {
                let bits = |x: &TrapSample| [x.s, x.v, x.a].map(f64::to_bits);
                assert_eq!(bits(f), bits(k));
                assert_eq!(crate::pyfmt::py_round(f.t, 5), k.t);
            }
        }
    }

    #[test]
    fn a_short_move_is_a_triangle_below_vmax() {
        let ph = phases(&TrapParams {
            distance: 0.2,
            vmax: 1.0,
            amax: 2.0,
            dt: 0.005,
        });
        assert!(ph.triangle && ph.t_flat == 0.0);
        assert!((ph.v_peak - (0.2f64 * 2.0).sqrt()).abs() < 1e-15);
        assert!(ph.v_peak < ph.vmax);
        assert_eq!(bands(&ph)[1].0, bands(&ph)[1].1, "no cruise");
    }

    #[test]
    fn a_corner_drag_gives_the_slope() {
        assert_eq!(amax_from_corner(0.5, 0.5), Some(1.0));
        assert_eq!(amax_from_corner(0.0, 0.5), None);
        assert_eq!(amax_from_corner(0.5, -0.1), None);
    }

    #[test]
    fn the_cursor_reads_the_csv_row() {
        let row = TrapSample {
            t: 0.123456789,
            s: 1.0,
            v: 2.0,
            a: 3.0,
        };
        assert_eq!(row.t(), 0.123456789);
        let values = row.cursor_values();
        assert_eq!(values, [0.12346, 1.0, 2.0, 3.0]);
    }
}
