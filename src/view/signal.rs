//! What the three signal pages (`#/cubic-path`, `#/pid-step`, `#/trapezoid-profile`) share,
//! plain Rust: their arguments in the URL (keys = the command line's argument names, values
//! as typed; only values that differ from the recipe's defaults are written), the sliders
//! beside their fields, rounding of dragged values, and readout number formatting.

use crate::recipes::RecipeInfo;
use crate::view::plot::{nice_step, LinearScale};
use crate::view::url::IgnoredKey;

/// A slider beside the field of argument `name`: its range and step (the field itself takes
/// any value the recipe accepts).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Slider {
    pub name: &'static str,
    pub min: f64,
    pub max: f64,
    pub step: f64,
}

impl Slider {
    /// The slider of argument `name` from `min` to `max` by `step`.
    pub const fn new(name: &'static str, min: f64, max: f64, step: f64) -> Slider {
        Slider {
            name,
            min,
            max,
            step,
        }
    }
}

/// A row of a signal page's table, as the plot's cursor reads it.
pub trait SignalRow: 'static {
    /// The cursor's readouts (`data-readout` keys): the time, then the row's three columns.
    const CURSOR: [&'static str; 4];
    /// Its time, s (the plots' shared axis).
    fn t(&self) -> f64;
    /// The values of [`SignalRow::CURSOR`]: the time as the CSV writes it, then the columns.
    fn cursor_values(&self) -> [f64; 4];
}

/// The texts of the recipe's arguments the URL sets (`None`: the default), in argument
/// order, and the keys it has that are neither arguments nor in `own_keys` (the page's).
pub fn read_texts(
    info: &RecipeInfo,
    query: &[(String, String)],
    own_keys: &[&str],
) -> (Vec<Option<String>>, Vec<IgnoredKey>) {
    let names: Vec<&str> = info.all_args().map(|(a, _)| a.name).collect();
    let mut texts = vec![None; names.len()];
    let mut ignored = Vec::new();
    for (key, value) in query {
        match names.iter().position(|n| n == key) {
            Some(i) => texts[i] = Some(value.clone()),
            None if own_keys.contains(&key.as_str()) => {}
            None => ignored.push(IgnoredKey::unknown(key.clone())),
        }
    }
    (texts, ignored)
}

/// The URL pairs of `texts` (argument order; `None` or the default is left out).
pub fn write_texts(info: &RecipeInfo, texts: &[Option<String>]) -> Vec<(String, String)> {
    info.all_args()
        .zip(texts)
        .filter_map(|((arg, _), text)| {
            let text = text.as_deref()?.trim();
            (!text.is_empty() && text != arg.default)
                .then(|| (arg.name.to_string(), text.to_string()))
        })
        .collect()
}

/// `value` rounded to a multiple of `step` and written without float noise (`0.35`, not
/// `0.35000000000000003`): what a drag puts in a field.
pub fn snap(value: f64, step: f64) -> String {
    if !value.is_finite() || step <= 0.0 {
        return "0".to_string();
    }
    let decimals = (-step.log10().floor()).max(0.0) as usize;
    let snapped = (value / step).round() * step;
    crate::numtext::fixed(snapped, decimals)
}

/// The axis range to show while a slider is held: `shown` as long as it holds `fitted`, else
/// grown to hold both (never shrunk: the axes stay put while the curve moves inside them and
/// are refitted when the slider is let go).
pub fn held_range(shown: (f64, f64), fitted: (f64, f64)) -> (f64, f64) {
    if !(shown.0.is_finite() && shown.1.is_finite() && shown.0 < shown.1) {
        return fitted;
    }
    (shown.0.min(fitted.0), shown.1.max(fitted.1))
}

/// [`held_range`] of each panel's range.
pub fn held_ranges<const N: usize>(
    shown: [(f64, f64); N],
    fitted: [(f64, f64); N],
) -> [(f64, f64); N] {
    std::array::from_fn(|k| held_range(shown[k], fitted[k]))
}

/// `range` widened to multiples of a 1-2-5 step (about 8 intervals), so that small changes of
/// the data often keep the same axes (and the plot redraws only its series).
pub fn nice_range(range: (f64, f64)) -> (f64, f64) {
    let step = nice_step(range.0, range.1, 8);
    (
        (range.0 / step).floor() * step,
        (range.1 / step).ceil() * step,
    )
}

/// [`crate::view::plot::decimate`] of the points `points` (x ascending) streamed: the same
/// points (first, min, max, last of each pixel column of `x`, in order; non-finite points
/// kept), without first collecting them all. A live page hands the plot a few thousand
/// points instead of copying every sample of a 100,000-row run.
pub fn thin(points: impl IntoIterator<Item = (f64, f64)>, x: &LinearScale) -> Vec<(f64, f64)> {
    let mut column = ColumnThin::default();
    for (i, p) in points.into_iter().enumerate() {
        if p.0.is_finite() && p.1.is_finite() {
            column.push(i, p, x.map(p.0).floor());
        } else {
            column.gap(p);
        }
    }
    column.finish()
}

/// [`thin`] of `N` columns sharing their x, in one pass over the rows `(x, [y; N])`: the
/// pixel column of each x is found once, and no row is copied. Column `k` of the result is
/// `thin` of the points `(x, y[k])`.
pub fn thin_columns<const N: usize>(
    rows: impl IntoIterator<Item = (f64, [f64; N])>,
    x: &LinearScale,
) -> [Vec<(f64, f64)>; N] {
    let mut thin = ColumnsThin::new(Some(*x));
    for (t, ys) in rows {
        thin.push(t, &ys);
    }
    let mut columns = thin.finish().into_iter();
    std::array::from_fn(|_| columns.next().unwrap_or_default())
}

/// [`thin_columns`] fed one row at a time (a run computed a slice per frame is thinned as
/// its rows come): columns sharing their x, as many as the first row has values. Without a
/// scale (no plotting area yet) every point is kept.
pub struct ColumnsThin {
    x: Option<LinearScale>,
    columns: Vec<ColumnThin>,
    /// Rows pushed so far.
    rows: usize,
}

impl ColumnsThin {
    /// Thins to the pixel columns of `x` (`None`: keeps every point).
    pub fn new(x: Option<LinearScale>) -> ColumnsThin {
        ColumnsThin {
            x,
            columns: Vec::new(),
            rows: 0,
        }
    }

    /// The next row: its x and its values, one a column.
    pub fn push(&mut self, t: f64, ys: &[f64]) {
        if self.columns.len() < ys.len() {
            self.columns.resize_with(ys.len(), ColumnThin::default);
        }
        let i = self.rows;
        self.rows += 1;
        let Some(x) = &self.x else {
            for (column, y) in self.columns.iter_mut().zip(ys) {
                column.out.push((t, *y));
            }
            return;
        };
        let px = t.is_finite().then(|| x.map(t).floor());
        for (column, &y) in self.columns.iter_mut().zip(ys) {
            match px {
                Some(px) if y.is_finite() => column.push(i, (t, y), px),
                _ => column.gap((t, y)),
            }
        }
    }

    /// The rows pushed so far.
    pub fn rows(&self) -> usize {
        self.rows
    }

    /// The thinned points of each column.
    pub fn finish(self) -> Vec<Vec<(f64, f64)>> {
        self.columns.into_iter().map(ColumnThin::finish).collect()
    }
}

/// The (lo, hi) of the finite values of each of `N` columns, in one pass over `rows`;
/// `(inf, -inf)` for a column without any.
pub fn extents<const N: usize>(rows: impl IntoIterator<Item = [f64; N]>) -> [(f64, f64); N] {
    let mut out = [(f64::INFINITY, f64::NEG_INFINITY); N];
    for row in rows {
        for (e, v) in out.iter_mut().zip(row) {
            if v.is_finite() {
                *e = (e.0.min(v), e.1.max(v));
            }
        }
    }
    out
}

/// The (lo, hi) of the finite y of `points` (a thinned series: each pixel column keeps its
/// lowest and highest point, so this is the extent of every sample it was thinned from);
/// `(inf, -inf)` when there is none.
pub fn y_extent<'a>(points: impl IntoIterator<Item = &'a (f64, f64)>) -> (f64, f64) {
    let [e] = extents(points.into_iter().map(|p| [p.1]));
    e
}

/// The (index, point) of the first, min, max and last points of one pixel column.
type Kept = [(usize, (f64, f64)); 4];

/// One series being thinned: the points kept so far and the pixel column under way.
#[derive(Default)]
struct ColumnThin {
    out: Vec<(f64, f64)>,
    kept: Option<(f64, Kept)>,
}

impl ColumnThin {
    /// Point `i`, finite, in pixel column `px`.
    fn push(&mut self, i: usize, p: (f64, f64), px: f64) {
        match &mut self.kept {
            Some((c, k)) if *c == px => {
                if p.1 < k[1].1 .1 {
                    k[1] = (i, p);
                }
                if p.1 > k[2].1 .1 {
                    k[2] = (i, p);
                }
                k[3] = (i, p);
            }
            _ => {
                self.flush();
                self.kept = Some((px, [(i, p); 4]));
            }
        }
    }

    /// A non-finite point: kept as it is (the line breaks there).
    fn gap(&mut self, p: (f64, f64)) {
        self.flush();
        self.out.push(p);
    }

    fn flush(&mut self) {
        if let Some((_, mut k)) = self.kept.take() {
            k.sort_by_key(|(i, _)| *i);
            let mut last = usize::MAX;
            for (i, p) in k {
                if i != last {
                    self.out.push(p);
                    last = i;
                }
            }
        }
    }

    fn finish(mut self) -> Vec<(f64, f64)> {
        self.flush();
        self.out
    }
}

/// `x` with `digits` significant digits for a readout (plain notation between 1e-4 and 1e6,
/// "—" when not finite).
pub fn sig(x: f64, digits: usize) -> String {
    if !x.is_finite() {
        return "—".to_string();
    }
    if x == 0.0 {
        return "0".to_string();
    }
    let mag = x.abs().log10().floor() as i32;
    if !(-4..6).contains(&mag) {
        return format!("{:.*e}", digits.saturating_sub(1), x);
    }
    let decimals = (digits as i32 - 1 - mag).max(0) as usize;
    crate::numtext::fixed(x, decimals)
}

/// The row of `rows` (times ascending, `t_of`) whose time is nearest `t`: what a cursor at
/// `t` reads. `None` when there are no rows.
pub fn nearest_row<T>(rows: &[T], t: f64, t_of: impl Fn(&T) -> f64) -> Option<&T> {
    let i = rows.partition_point(|r| t_of(r) < t);
    let before = i.checked_sub(1).and_then(|k| rows.get(k));
    match (before, rows.get(i)) {
        (Some(a), Some(b)) if (t_of(b) - t).abs() < (t - t_of(a)).abs() => Some(b),
        (Some(a), _) => Some(a),
        (None, b) => b,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::recipes::{cubic_path, pid_step};
    use crate::view::url::query as q;

    #[test]
    fn a_held_range_grows_and_never_shrinks() {
        assert_eq!(held_range((0.0, 2.0), (0.0, 1.0)), (0.0, 2.0));
        assert_eq!(held_range((0.0, 2.0), (-0.5, 3.0)), (-0.5, 3.0));
        assert_eq!(held_range((0.0, 2.0), (1.0, 2.5)), (0.0, 2.5));
        // Nothing shown yet (or nothing usable): the fitted range.
        assert_eq!(held_range((f64::NAN, 1.0), (0.0, 1.0)), (0.0, 1.0));
        assert_eq!(held_range((1.0, 1.0), (0.0, 3.0)), (0.0, 3.0));
        assert_eq!(
            held_ranges([(0.0, 2.0), (-1.0, 1.0)], [(0.0, 1.0), (-2.0, 0.5)]),
            [(0.0, 2.0), (-2.0, 1.0)]
        );
    }

    #[test]
    fn url_keys_are_the_argument_names() {
        let (texts, ignored) = read_texts(
            &cubic_path::INFO,
            &q(&[("T", "2"), ("quintic", "1"), ("bogus", "x"), ("q1", "0.5")]),
            &["quintic"],
        );
        assert_eq!(
            texts,
            vec![None, Some("0.5".into()), Some("2".into()), None]
        );
        assert_eq!(ignored, vec![IgnoredKey::unknown("bogus")]);
        // Round trip; defaults are not written.
        assert_eq!(
            write_texts(&cubic_path::INFO, &texts),
            q(&[("q1", "0.5"), ("T", "2")])
        );
        let defaults = vec![Some("1.2".into()), None, None, None, Some("80".into())];
        assert_eq!(write_texts(&pid_step::INFO, &defaults), vec![]);
    }

    #[test]
    fn thinning_streams_the_plot_s_decimation() {
        use crate::view::plot::decimate;
        let x = LinearScale::new((0.0, 3.0), (40.0, 340.0));
        let mut pts: Vec<(f64, f64)> = (0..30_000)
            .map(|i| {
                let t = i as f64 * 1e-4;
                (t, (t * 37.0).sin() + 0.3 * (t * 1234.5).cos())
            })
            .collect();
        pts[777].1 = f64::NAN;
        pts[20_000].1 = f64::INFINITY;
        let thin_pts = thin(pts.iter().copied(), &x);
        let want = decimate(&pts, &x);
        assert_eq!(thin_pts.len(), want.len());
        for (a, b) in thin_pts.iter().zip(&want) {
            assert_eq!(
                (a.0.to_bits(), a.1.to_bits()),
                (b.0.to_bits(), b.1.to_bits())
            );
        }
        assert!(thin_pts.len() < 4 * 302);
        assert_eq!(thin(Vec::new(), &x), Vec::<(f64, f64)>::new());
    }

    #[test]
    fn thinning_columns_at_once_equals_thinning_each() {
        let x = LinearScale::new((0.0, 2.0), (10.0, 250.0));
        let mut rows: Vec<(f64, [f64; 3])> = (0..20_000)
            .map(|i| {
                let t = i as f64 * 1e-4;
                (t, [(t * 50.0).sin(), t * t, (t * 900.0).cos() * t])
            })
            .collect();
        rows[100].1[1] = f64::NAN;
        rows[5000].0 = f64::NAN;
        rows[9000].1[2] = f64::NEG_INFINITY;
        let all = thin_columns(rows.iter().copied(), &x);
        for (k, got) in all.iter().enumerate() {
            let want = thin(rows.iter().map(|(t, ys)| (*t, ys[k])), &x);
            let bits = |v: &[(f64, f64)]| -> Vec<(u64, u64)> {
                v.iter().map(|p| (p.0.to_bits(), p.1.to_bits())).collect()
            };
            assert_eq!(bits(got), bits(&want), "column {k}");
            assert!(got.len() < 4 * 242 + 4, "column {k}: {}", got.len());
        }
    }

    #[test]
    fn thinning_row_by_row_equals_thinning_at_once() {
        let x = LinearScale::new((0.0, 2.0), (10.0, 250.0));
        let rows: Vec<(f64, [f64; 2])> = (0..20_000)
            .map(|i| {
                let t = i as f64 * 1e-4;
                let y = if i == 700 { f64::NAN } else { (t * 50.0).sin() };
                (t, [y, (t * 900.0).cos() * t])
            })
            .collect();
        let mut streamed = ColumnsThin::new(Some(x));
        for (t, ys) in &rows {
            streamed.push(*t, ys);
        }
        assert_eq!(streamed.rows(), 20_000);
        let streamed = streamed.finish();
        let at_once = thin_columns(rows.iter().copied(), &x);
        let bits = |v: &[(f64, f64)]| -> Vec<(u64, u64)> {
            v.iter().map(|p| (p.0.to_bits(), p.1.to_bits())).collect()
        };
        assert_eq!(streamed.len(), 2);
        for (got, want) in streamed.iter().zip(&at_once) {
            assert_eq!(bits(got), bits(want));
            assert!(got.len() < 4 * 242 + 4, "{}", got.len());
        }
        // Without a scale every point is kept.
        let mut all = ColumnsThin::new(None);
        for (t, ys) in &rows[..10] {
            all.push(*t, ys);
        }
        let all = all.finish();
        assert_eq!(all[1].len(), 10);
        assert_eq!(all[1][3], (rows[3].0, rows[3].1[1]));
        assert!(ColumnsThin::new(Some(x)).finish().is_empty());
    }

    #[test]
    fn snapped_values_read_as_typed() {
        assert_eq!(snap(0.35000000000000003, 0.01), "0.35");
        assert_eq!(snap(1.23456, 0.05), "1.25");
        assert_eq!(snap(-0.001, 0.01), "0.00");
        assert_eq!(snap(12.0, 1.0), "12");
        assert_eq!(sig(0.7967, 3), "0.797");
        let (lo, hi) = nice_range((-0.096, 1.296));
        assert!(
            (lo + 0.2).abs() < 1e-12 && (hi - 1.4).abs() < 1e-12,
            "{lo} {hi}"
        );
        assert_eq!(sig(f64::NAN, 3), "—");
        assert_eq!(sig(2.5e7, 3), "2.50e7");
    }

    #[test]
    fn nearest_row_picks_the_closer_time() {
        let ts = [0.0, 0.05, 0.1, 0.15];
        let at = |t: f64| nearest_row(&ts, t, |x| *x).copied();
        assert_eq!(at(-1.0), Some(0.0));
        assert_eq!(at(0.0), Some(0.0));
        assert_eq!(at(0.024), Some(0.0));
        assert_eq!(at(0.026), Some(0.05));
        assert_eq!(at(0.1), Some(0.1));
        assert_eq!(at(9.0), Some(0.15));
        assert_eq!(nearest_row(&[] as &[f64], 1.0, |x| *x), None);
    }
}
