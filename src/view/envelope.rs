//! The plot envelope of a CSV table: every numeric column against the first, min/max
//! decimated into a fixed number of x buckets (first, lowest, highest and last point of each
//! bucket, in x order), so a million-row file becomes a few thousand points per column that
//! draw in one frame with the same pixels as all of them. Computed where the file is (in the
//! Web Worker for a big run, `crate::ui::kit::worker`), so the page never parses the whole file
//! on its main thread.
//!
//! The reader is for plotting only (the numbers written and downloaded are the kernel's): a
//! UTF-8 byte-order mark is dropped, `\r\n`, `\n` and `\r` end lines, blank lines are skipped,
//! quoted cells may hold commas, and a cell that is not a finite number is left out of its
//! column (a `note` column gives no points).

use crate::view::plot::{decimate, LinearScale};
use crate::view::table::{split_cells, Quotes};

/// Buckets of an envelope: enough for a 4K-wide plot at one bucket per device pixel column.
pub const BUCKETS: usize = 4096;

/// The envelope of a table.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Envelope {
    /// The header (the x column first).
    pub header: Vec<String>,
    /// Data rows (non-blank lines after the header).
    pub rows: u64,
    /// The first and the last x of the data rows that have one.
    pub x_span: Option<(f64, f64)>,
    /// `series[c]`: the decimated points of column `c + 1` against column 0.
    pub series: Vec<Vec<(f64, f64)>>,
}

impl Envelope {
    /// The points of the column called `name` (empty when there is none).
    pub fn column(&self, name: &str) -> &[(f64, f64)] {
        self.header
            .iter()
            .skip(1)
            .position(|h| h == name)
            .and_then(|i| self.series.get(i))
            .map_or(&[], Vec::as_slice)
    }

    /// The lowest and highest y of column `name`.
    pub fn y_range(&self, name: &str) -> Option<(f64, f64)> {
        let pts = self.column(name);
        let lo = pts.iter().map(|p| p.1).fold(f64::INFINITY, f64::min);
        let hi = pts.iter().map(|p| p.1).fold(f64::NEG_INFINITY, f64::max);
        (lo <= hi).then_some((lo, hi))
    }
}

/// A cell as a finite number.
fn number(cell: &str) -> Option<f64> {
    cell.trim().parse::<f64>().ok().filter(|v| v.is_finite())
}

/// The envelope of CSV `text` in `buckets` x buckets.
pub fn csv_envelope(text: &str, buckets: usize) -> Envelope {
    let body = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut lines = body
        .split(['\n', '\r'])
        .filter(|line| !line.trim().is_empty());
    let mut row = Vec::new();
    let Some(header) = lines.next() else {
        return Envelope::default();
    };
    split_cells(header, Quotes::Anywhere, &mut row);
    let header: Vec<String> = row.iter().map(|c| c.trim().to_string()).collect();
    let width = header.len();
    let mut columns: Vec<Vec<(f64, f64)>> = vec![Vec::new(); width.saturating_sub(1)];
    let mut rows = 0u64;
    let mut x_span: Option<(f64, f64)> = None;
    for line in lines {
        rows += 1;
        let x = if !line.contains('"') {
            let mut parts = line.split(',');
            let Some(x) = parts.next().and_then(number) else {
                continue;
            };
            for (c, part) in parts.enumerate().take(columns.len()) {
                if let (Some(y), Some(col)) = (number(part), columns.get_mut(c)) {
                    col.push((x, y));
                }
            }
            x
        } else {
            split_cells(line, Quotes::Anywhere, &mut row);
            let Some(x) = row.first().and_then(|c| number(c)) else {
                continue;
            };
            for (c, part) in row.iter().skip(1).enumerate().take(columns.len()) {
                if let (Some(y), Some(col)) = (number(part), columns.get_mut(c)) {
                    col.push((x, y));
                }
            }
            x
        };
        x_span = Some(match x_span {
            None => (x, x),
            Some((first, _)) => (first, x),
        });
    }
    let series = match x_span {
        Some((a, b)) if b > a && buckets > 0 => {
            let scale = LinearScale::new((a, b), (0.0, buckets as f64 - 1e-9));
            columns.iter().map(|c| decimate(c, &scale)).collect()
        }
        _ => columns,
    };
    Envelope {
        header,
        rows,
        x_span,
        series,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_small_table_keeps_every_point_and_skips_text_cells() {
        let text = "\u{feff}t_s,q1,q2,note\r\n0.0,0.0,1.0,a\r\n\r\n0.5,\"0.25\",2.0,\"x, y\"\r\n1.0,1.0,nan,z\r\n";
        let env = csv_envelope(text, BUCKETS);
        assert_eq!(env.header, ["t_s", "q1", "q2", "note"]);
        assert_eq!(env.rows, 3);
        assert_eq!(env.x_span, Some((0.0, 1.0)));
        assert_eq!(env.column("q1"), [(0.0, 0.0), (0.5, 0.25), (1.0, 1.0)]);
        assert_eq!(env.column("q2"), [(0.0, 1.0), (0.5, 2.0)]);
        assert!(env.column("note").is_empty());
        assert!(env.column("q9").is_empty());
        assert_eq!(env.y_range("q2"), Some((1.0, 2.0)));
    }

    #[test]
    fn a_million_rows_become_at_most_four_points_a_bucket_with_the_extremes_kept() {
        let mut text = String::from("t_s,q1\n");
        let n = 1_000_000;
        for i in 0..n {
            let t = i as f64 * 1e-3;
            let q = if i == 777_777 { 9.0 } else { (t * 3.0).sin() };
            text.push_str(&format!("{t},{q}\n"));
        }
        let env = csv_envelope(&text, 1000);
        assert_eq!(env.rows, n);
        let pts = env.column("q1");
        assert!(pts.len() <= 4 * 1000 + 4, "{}", pts.len());
        assert!(pts.len() >= 1000);
        // The spike and the true extremes survive; x stays in order.
        assert!(pts.iter().any(|p| p.1 == 9.0));
        let lo = pts.iter().map(|p| p.1).fold(f64::INFINITY, f64::min);
        assert!(lo < -0.99999, "{lo}");
        assert!(pts.windows(2).all(|w| w[0].0 <= w[1].0));
        assert_eq!(pts.first().map(|p| p.0), Some(0.0));
        assert_eq!(env.x_span, Some((0.0, (n - 1) as f64 * 1e-3)));
    }

    #[test]
    fn empty_and_header_only_tables() {
        assert_eq!(csv_envelope("", BUCKETS), Envelope::default());
        let env = csv_envelope("t_s,q1\n", BUCKETS);
        assert_eq!(env.rows, 0);
        assert_eq!(env.x_span, None);
        assert!(env.column("q1").is_empty());
    }
}
