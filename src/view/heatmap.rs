//! The pure part of the kit's heatmap (`ui::kit::heatmap`): the colour map (a viridis-like
//! 256-entry table), the RGBA fill of a grid of values, and the layout of the plot square and
//! its colour legend with the maps between grid nodes, values and canvas pixels.
//!
//! Grids are sampled on nodes, like the manip-grid recipe: node `i` of `n` along an axis
//! `min..=max` is `min + (max − min) i / (n − 1)`; values are stored column by column,
//! `values[i * ny + j]` for x node `i` and y node `j` (y up). The painted image has one pixel
//! per node and its top row is the largest y.

/// One RGB colour.
pub type Rgb = [u8; 3];

/// A viridis-like colour map: 256 RGB entries from dark purple (0) to yellow (1).
pub fn viridis() -> Vec<Rgb> {
    const STOPS: [[f64; 3]; 5] = [
        [68.0, 1.0, 84.0],
        [59.0, 82.0, 139.0],
        [33.0, 145.0, 140.0],
        [94.0, 201.0, 98.0],
        [253.0, 231.0, 37.0],
    ];
    (0..256)
        .map(|k| {
            let t = k as f64 / 255.0 * 4.0;
            let i = (t.floor() as usize).min(3);
            let f = t - i as f64;
            let (a, b) = (STOPS[i], STOPS[i + 1]);
            [0, 1, 2].map(|c| (a[c] + (b[c] - a[c]) * f).round().clamp(0.0, 255.0) as u8)
        })
        .collect()
}

/// The colour of `t ∈ [0, 1]` (clamped; NaN is the bottom colour).
pub fn colour_at(lut: &[Rgb], t: f64) -> Rgb {
    let t = if t.is_nan() { 0.0 } else { t.clamp(0.0, 1.0) };
    let k = (t * (lut.len().max(1) - 1) as f64).round() as usize;
    lut.get(k).copied().unwrap_or([0, 0, 0])
}

/// The RGBA bytes (`nx × ny` pixels, opaque, top row = largest y) of `values` coloured over
/// `scale = (min, max)`. Missing values (a short slice) and NaN are black.
///
/// Walked in bands of [`FILL_BAND`] columns, row by row inside a band, so that both the
/// values (column-major) and the pixels (row-major) are read and written in short runs; the
/// colour index is `f32` arithmetic, as precise as the values.
pub fn fill_rgba(values: &[f32], nx: usize, ny: usize, scale: (f64, f64), lut: &[Rgb]) -> Vec<u8> {
    let mut rgba = vec![255u8; nx * ny * 4];
    let (lo, hi) = scale;
    let span = if hi > lo { hi - lo } else { 1.0 };
    let top = lut.len().max(1) - 1;
    let inv = (top as f64 / span) as f32;
    let (lo, top_f) = (lo as f32, top as f32);
    let black: Rgb = [0, 0, 0];
    let colour = |v: f32| -> Rgb {
        let k = (v - lo) * inv;
        if k >= 0.0 {
            lut.get(k.min(top_f).round() as usize)
                .copied()
                .unwrap_or(black)
        } else if k < 0.0 {
            lut.first().copied().unwrap_or(black)
        } else {
            black // NaN
        }
    };
    let mut i0 = 0;
    while i0 < nx {
        let i1 = (i0 + FILL_BAND).min(nx);
        for j in 0..ny {
            let row = (ny - 1 - j) * nx;
            for i in i0..i1 {
                let rgb = values.get(i * ny + j).map_or(black, |&v| colour(v));
                let px = (row + i) * 4;
                if let Some(p) = rgba.get_mut(px..px + 3) {
                    p.copy_from_slice(&rgb);
                }
            }
        }
        i0 = i1;
    }
    rgba
}

/// Columns per band of [`fill_rgba`].
pub const FILL_BAND: usize = 16;

/// One axis of a node grid: `n` nodes from `min` to `max`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GridAxis {
    pub min: f64,
    pub max: f64,
    pub n: usize,
}

impl GridAxis {
    /// The value of node `i`.
    pub fn node(&self, i: usize) -> f64 {
        let d = (self.n.max(2) - 1) as f64;
        self.min + (self.max - self.min) * i as f64 / d
    }

    /// The node nearest to `v` when `v` lies within half a node of the axis.
    pub fn nearest(&self, v: f64) -> Option<usize> {
        let d = (self.n.max(2) - 1) as f64;
        let u = (v - self.min) / (self.max - self.min) * d;
        if !(-0.5..=d + 0.5).contains(&u) {
            return None;
        }
        Some(u.round().clamp(0.0, d) as usize)
    }
}

/// Where the plot square and the colour legend sit on the canvas, CSS px.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HeatLayout {
    pub x: f64,
    pub y: f64,
    pub size: f64,
    pub legend_x: f64,
    pub legend_w: f64,
    /// The axis ranges the square shows (x left → right, y bottom → top).
    pub x_range: (f64, f64),
    pub y_range: (f64, f64),
}

impl HeatLayout {
    /// Lays out a `w × h` canvas with type scale `scale` (1 normally, larger on a projector)
    /// for the given axis ranges.
    pub fn new(w: f64, h: f64, scale: f64, x_range: (f64, f64), y_range: (f64, f64)) -> HeatLayout {
        let left = 46.0 * scale;
        let bottom = 38.0 * scale;
        let top = 10.0 * scale;
        let legend_w = 14.0 * scale;
        let legend_room = legend_w + 80.0 * scale;
        let size = (w - left - legend_room - 8.0)
            .min(h - top - bottom)
            .max(10.0);
        HeatLayout {
            x: left,
            y: top,
            size,
            legend_x: left + size + 12.0 * scale,
            legend_w,
            x_range,
            y_range,
        }
    }

    /// Canvas x of value `v` on the x axis.
    pub fn x_of(&self, v: f64) -> f64 {
        let (a, b) = self.x_range;
        self.x + (v - a) / (b - a) * self.size
    }

    /// Canvas y of value `v` on the y axis (the largest at the top).
    pub fn y_of(&self, v: f64) -> f64 {
        let (a, b) = self.y_range;
        self.y + (b - v) / (b - a) * self.size
    }

    /// The grid node `(i, j)` under canvas point `(px, py)`, if it is inside the square (or
    /// within half a node of its edge).
    pub fn node_at(&self, px: f64, py: f64, nx: usize, ny: usize) -> Option<(usize, usize)> {
        let (xa, xb) = self.x_range;
        let (ya, yb) = self.y_range;
        let vx = xa + (px - self.x) / self.size * (xb - xa);
        let vy = yb - (py - self.y) / self.size * (yb - ya);
        let i = GridAxis {
            min: xa,
            max: xb,
            n: nx,
        }
        .nearest(vx)?;
        let j = GridAxis {
            min: ya,
            max: yb,
            n: ny,
        }
        .nearest(vy)?;
        Some((i, j))
    }

    /// The drawn image's rectangle (x, y, w, h): node centres sit on their values, so the
    /// image reaches half a node beyond the square on every side.
    pub fn image_rect(&self, nx: usize, ny: usize) -> (f64, f64, f64, f64) {
        let cx = self.size / (nx.max(2) - 1) as f64;
        let cy = self.size / (ny.max(2) - 1) as f64;
        (
            self.x - cx / 2.0,
            self.y - cy / 2.0,
            self.size + cx,
            self.size + cy,
        )
    }
}

/// A legend or axis number: three significant digits, no exponent for everyday sizes.
pub fn legend_value(v: f64) -> String {
    if v == 0.0 {
        "0".to_string()
    } else if v.abs() >= 1e-4 && v.abs() < 1e4 {
        let digits = (2 - v.abs().log10().floor() as i32).clamp(0, 8) as usize;
        crate::numtext::fixed(v, digits)
    } else {
        format!("{v:.2e}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    #[test]
    fn viridis_runs_from_purple_to_yellow() {
        let lut = viridis();
        assert_eq!(lut.len(), 256);
        assert_eq!(lut[0], [68, 1, 84]);
        assert_eq!(lut[255], [253, 231, 37]);
        assert_eq!(colour_at(&lut, 2.0), [253, 231, 37]);
        assert_eq!(colour_at(&lut, f64::NAN), [68, 1, 84]);
    }

    #[test]
    fn rgba_fill_puts_the_largest_y_on_top() {
        let lut = viridis();
        // 2 × 3 grid: x node 1, y node 2 is the maximum, everything else 0.
        let mut v = vec![0.0f32; 6];
        v[3 + 2] = 1.0; // i = 1, j = 2: i * ny + j
        let rgba = fill_rgba(&v, 2, 3, (0.0, 1.0), &lut);
        assert_eq!(rgba.len(), 24);
        // Top row (y node 2), second pixel (x node 1): yellow; alpha opaque everywhere.
        assert_eq!(&rgba[4..8], &[253, 231, 37, 255]);
        assert_eq!(&rgba[0..4], &[68, 1, 84, 255]);
        assert_eq!(&rgba[20..24], &[68, 1, 84, 255]);
        // A short slice leaves black, never panics.
        let short = fill_rgba(&[0.5], 2, 2, (0.0, 1.0), &lut);
        assert_eq!(&short[4..8], &[0, 0, 0, 255]);
    }

    #[test]
    fn nodes_and_pixels_round_trip() {
        let lay = HeatLayout::new(520.0, 400.0, 1.0, (-PI, PI), (-PI, PI));
        let n = 256;
        let axis = GridAxis {
            min: -PI,
            max: PI,
            n,
        };
        for (i, j) in [(0, 0), (64, 200), (255, 255), (128, 3)] {
            let (px, py) = (lay.x_of(axis.node(i)), lay.y_of(axis.node(j)));
            assert_eq!(lay.node_at(px, py, n, n), Some((i, j)));
        }
        assert_eq!(lay.y_of(PI), lay.y);
        assert_eq!(lay.x_of(-PI), lay.x);
        // Outside the square by more than half a node: nothing.
        assert_eq!(lay.node_at(lay.x - 5.0, lay.y + 10.0, n, n), None);
        assert_eq!(
            lay.node_at(lay.x + 10.0, lay.y + lay.size + 5.0, n, n),
            None
        );
        assert_eq!(axis.node(0), -PI);
        assert_eq!(axis.node(255), PI);
    }

    #[test]
    fn legend_values_read_like_numbers() {
        for (value, shown) in [
            (0.012, "0.0120"),
            (0.006, "0.00600"),
            (150.0, "150"),
            (0.0, "0"),
            (2.5e-6, "2.50e-6"),
        ] {
            assert_eq!(legend_value(value), shown);
        }
    }
}
