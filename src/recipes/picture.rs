//! The drawing model of the home page's recipe-card and tile pictures: marks in unit
//! coordinates (x right, y up, both in [0, 1]) so the page only scales them to its canvas,
//! series as slots of the page's palette; and the helpers each recipe's `picture` draws with
//! (CSV columns by header, a frame that fits data onto the unit square).

use glam::DVec2;

/// One mark of a picture.
#[derive(Debug, Clone, PartialEq)]
pub enum Mark {
    /// A polyline.
    Line { series: u8, points: Vec<DVec2> },
    /// Dots.
    Dots { series: u8, points: Vec<DVec2> },
    /// Separate segments (tree edges, frame axes).
    Segments {
        series: u8,
        pairs: Vec<(DVec2, DVec2)>,
    },
    /// A solid polygon (a link, a block), closed.
    Fill { series: u8, points: Vec<DVec2> },
    /// A region (a goal): a closed polygon lightly filled, its outline drawn.
    Region { series: u8, points: Vec<DVec2> },
    /// A grid of cells, row-major from the bottom-left, values in [0, 1].
    Cells {
        cols: usize,
        rows: usize,
        values: Vec<f64>,
    },
}

impl Mark {
    /// A polyline through `points` in series `line`, and a dot at each point in series `dots`.
    pub fn joined_dots(points: Vec<DVec2>, line: u8, dots: u8) -> [Mark; 2] {
        [
            Mark::Line {
                series: line,
                points: points.clone(),
            },
            Mark::Dots {
                series: dots,
                points,
            },
        ]
    }
}

/// A recipe card's picture.
#[derive(Debug, Clone, PartialEq)]
pub struct Picture {
    pub marks: Vec<Mark>,
}

impl Picture {
    /// Every point its marks place (a grid of cells places none).
    pub fn points(&self) -> Vec<DVec2> {
        self.marks
            .iter()
            .flat_map(|m| match m {
                Mark::Line { points, .. }
                | Mark::Dots { points, .. }
                | Mark::Fill { points, .. }
                | Mark::Region { points, .. } => points.clone(),
                Mark::Segments { pairs, .. } => pairs.iter().flat_map(|(a, b)| [*a, *b]).collect(),
                Mark::Cells { .. } => Vec::new(),
            })
            .collect()
    }
}

/// Palette slots the page maps to colours (Okabe–Ito, safe for colour-blind readers).
pub mod series {
    pub const BLUE: u8 = 0;
    pub const ORANGE: u8 = 1;
    pub const GREEN: u8 = 2;
    pub const GREY: u8 = 3;
    pub const RED: u8 = 4;
}

/// A CSV text as columns by header name (cells that are not numbers read as NaN).
pub struct Table<'a> {
    header: Vec<&'a str>,
    rows: Vec<Vec<f64>>,
}

impl<'a> Table<'a> {
    /// The table of a CSV text with a header line (`None` for an empty text).
    pub fn parse(text: &'a str) -> Option<Table<'a>> {
        let mut lines = text.lines();
        let header: Vec<&str> = lines.next()?.split(',').collect();
        let rows = lines
            .map(|line| {
                line.split(',')
                    .map(|cell| cell.trim().parse::<f64>().unwrap_or(f64::NAN))
                    .collect()
            })
            .collect();
        Some(Table { header, rows })
    }

    /// The column called `name`, if the header has it.
    pub fn col(&self, name: &str) -> Option<Vec<f64>> {
        let i = self.header.iter().position(|h| *h == name)?;
        Some(
            self.rows
                .iter()
                .map(|r| r.get(i).copied().unwrap_or(f64::NAN))
                .collect(),
        )
    }
}

/// Maps data boxes onto the unit square with a margin.
#[derive(Debug, Clone, Copy)]
pub struct UnitFrame {
    min: DVec2,
    scale: DVec2,
    offset: DVec2,
}

impl UnitFrame {
    const MARGIN: f64 = 0.06;

    /// Fits the points' box; with `aspect` (canvas width / height) set, one data unit is as
    /// long across as up on the canvas (a square stays square), else each axis fills.
    pub fn fit(points: impl Iterator<Item = DVec2>, aspect: Option<f64>) -> UnitFrame {
        let (mut lo, mut hi) = (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY));
        for p in points.filter(|p| p.is_finite()) {
            lo = lo.min(p);
            hi = hi.max(p);
        }
        if !lo.is_finite() || !hi.is_finite() {
            lo = DVec2::ZERO;
            hi = DVec2::ONE;
        }
        let span = (hi - lo).max(DVec2::splat(1e-12));
        let inner = 1.0 - 2.0 * Self::MARGIN;
        match aspect.filter(|a| a.is_finite() && *a > 0.0) {
            None => UnitFrame {
                min: lo,
                scale: DVec2::splat(inner) / span,
                offset: DVec2::splat(Self::MARGIN),
            },
            Some(aspect) => {
                // Pixels of a canvas `aspect` wide and 1 high.
                let s = (inner * aspect / span.x).min(inner / span.y);
                let scale = DVec2::new(s / aspect, s);
                let used = span * scale;
                UnitFrame {
                    min: lo,
                    scale,
                    offset: (DVec2::ONE - used) / 2.0,
                }
            }
        }
    }

    /// The point `p` of the data on the unit square.
    pub fn map(&self, p: DVec2) -> DVec2 {
        self.offset + (p - self.min) * self.scale
    }
}

/// The points `(x[i], y[i])`.
pub fn pairs(x: &[f64], y: &[f64]) -> Vec<DVec2> {
    x.iter().zip(y).map(|(a, b)| DVec2::new(*a, *b)).collect()
}

/// Lines of `ys` over `x`, one frame for all.
pub fn lines(x: &[f64], ys: &[(&[f64], u8)]) -> Picture {
    let all: Vec<Vec<DVec2>> = ys.iter().map(|(y, _)| pairs(x, y)).collect();
    let frame = UnitFrame::fit(all.iter().flatten().copied(), None);
    Picture {
        marks: all
            .into_iter()
            .zip(ys)
            .map(|(pts, (_, series))| Mark::Line {
                series: *series,
                points: pts.into_iter().map(|p| frame.map(p)).collect(),
            })
            .collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn equal_aspect_keeps_squares_square_on_a_wide_canvas() {
        let aspect = 3.0;
        let frame = UnitFrame::fit([DVec2::ZERO, DVec2::ONE].into_iter(), Some(aspect));
        let (a, b) = (frame.map(DVec2::ZERO), frame.map(DVec2::ONE));
        // Canvas pixels: x scaled by the aspect.
        let w = (b.x - a.x) * aspect;
        let h = b.y - a.y;
        assert!((w - h).abs() < 1e-12 && h > 0.8 && a.x > 0.0 && b.x < 1.0);
    }
}
