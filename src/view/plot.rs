//! The pure part of the kit's plot (`ui::kit::plot`): linear scales between data and pixels,
//! "nice" 1-2-5 ticks and their labels, log₁₀ axes (range and decade labels), y ranges
//! that fit the data, the sample nearest a cursor, and min/max decimation per pixel column (a series of a million samples draws as at
//! most four points per column and looks the same).

/// A linear map from a data interval to a pixel interval (either may be reversed: y pixels
/// grow downwards).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinearScale {
    pub domain: (f64, f64),
    pub range: (f64, f64),
}

impl LinearScale {
    /// A scale; an empty or non-finite domain is widened to ±0.5 around its value (or 0..1).
    pub fn new(domain: (f64, f64), range: (f64, f64)) -> LinearScale {
        let (mut a, mut b) = domain;
        if !a.is_finite() || !b.is_finite() {
            (a, b) = (0.0, 1.0);
        }
        if (b - a).abs() < f64::EPSILON * a.abs().max(1e-300) || a == b {
            (a, b) = (a - 0.5, b + 0.5);
        }
        LinearScale {
            domain: (a, b),
            range,
        }
    }

    /// Pixel of data value `v`.
    pub fn map(&self, v: f64) -> f64 {
        let (d0, d1) = self.domain;
        let (r0, r1) = self.range;
        r0 + (v - d0) / (d1 - d0) * (r1 - r0)
    }

    /// Data value at pixel `px`.
    pub fn invert(&self, px: f64) -> f64 {
        let (d0, d1) = self.domain;
        let (r0, r1) = self.range;
        if r1 == r0 {
            return d0;
        }
        d0 + (px - r0) / (r1 - r0) * (d1 - d0)
    }
}

/// A tick step of the 1-2-5 series giving about `target` intervals over `lo..hi`.
pub fn nice_step(lo: f64, hi: f64, target: usize) -> f64 {
    let span = (hi - lo).abs();
    if !span.is_finite() || span == 0.0 {
        return 1.0;
    }
    let raw = span / target.max(1) as f64;
    let mag = 10f64.powf(raw.log10().floor());
    for m in [1.0, 2.0, 5.0, 10.0] {
        if m * mag >= raw * (1.0 - 1e-9) {
            return m * mag;
        }
    }
    10.0 * mag
}

/// Tick values: multiples of [`nice_step`] inside `lo..=hi` (exact zero where it falls).
pub fn nice_ticks(lo: f64, hi: f64, target: usize) -> Vec<f64> {
    let (lo, hi) = (lo.min(hi), lo.max(hi));
    let step = nice_step(lo, hi, target);
    let first = (lo / step - 1e-9).ceil() as i64;
    let last = (hi / step + 1e-9).floor() as i64;
    if last < first || last - first > 1000 {
        return Vec::new();
    }
    (first..=last)
        .map(|k| if k == 0 { 0.0 } else { k as f64 * step })
        .collect()
}

/// A tick label with as many decimals as the step needs (`0.25`, `1.5`, `200`), and
/// exponent form for very large or small values.
pub fn tick_label(v: f64, step: f64) -> String {
    if v == 0.0 {
        return "0".to_string();
    }
    let a = v.abs();
    if !(1e-4..1e6).contains(&a) {
        return format!("{v:.1e}");
    }
    let decimals = if step > 0.0 && step < 1.0 {
        (-step.log10().floor()) as usize + usize::from(is_half_step(step))
    } else {
        0
    };
    crate::numtext::fixed(v, decimals)
}

/// 0.25, 0.025 … need one decimal more than their magnitude.
fn is_half_step(step: f64) -> bool {
    let m = step / 10f64.powf(step.log10().floor());
    (m - 2.5).abs() < 1e-9
}

/// The axis range of a log₁₀ axis over the data range `range`: `(log₁₀ lo, log₁₀ hi)`; a
/// range that is not positive becomes `1e-12..1` (its positive end kept when it has one).
pub fn log_axis_range(range: (f64, f64)) -> (f64, f64) {
    let (lo, hi) = (range.0.min(range.1), range.0.max(range.1));
    let usable = |v: f64| v > 0.0 && v.is_finite();
    let (lo, hi) = match (usable(lo), usable(hi)) {
        (true, true) => (lo, hi),
        (false, true) => (hi.min(1.0) * 1e-12, hi),
        _ => (1e-12, 1.0),
    };
    let (a, b) = (lo.log10(), hi.log10());
    if range.0 <= range.1 {
        (a, b)
    } else {
        (b, a)
    }
}

/// The label of tick `v` on a log₁₀ axis: a whole decade as `10⁻⁶`, `1`, `10`, `10³`;
/// anything else as the value it stands for (`2.0e-5`, `0.5`).
pub fn log_tick_label(v: f64) -> String {
    if !v.is_finite() {
        return String::new();
    }
    let k = v.round();
    if (v - k).abs() > 1e-9 {
        let x = 10f64.powf(v);
        return tick_label(x, x);
    }
    match k as i64 {
        0 => "1".to_string(),
        1 => "10".to_string(),
        e => {
            const SUP: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
            let mut s = String::from("10");
            if e < 0 {
                s.push('⁻');
            }
            for d in e.unsigned_abs().to_string().bytes() {
                s.push(SUP[usize::from(d - b'0')]);
            }
            s
        }
    }
}

/// A y range holding every finite value with `pad` (a fraction of the span) on both sides;
/// `None` when there is no finite value.
pub fn auto_range(values: impl IntoIterator<Item = f64>, pad: f64) -> Option<(f64, f64)> {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for v in values.into_iter().filter(|v| v.is_finite()) {
        lo = lo.min(v);
        hi = hi.max(v);
    }
    if lo > hi {
        return None;
    }
    let span = if hi > lo { hi - lo } else { lo.abs().max(1.0) };
    Some((lo - pad * span, hi + pad * span))
}

/// The index of the sample whose x is nearest to `x` (`xs` ascending); `None` if empty.
pub fn nearest_index(xs: &[f64], x: f64) -> Option<usize> {
    if xs.is_empty() {
        return None;
    }
    let i = xs.partition_point(|&v| v < x);
    if i == 0 {
        return Some(0);
    }
    if i >= xs.len() {
        return Some(xs.len() - 1);
    }
    Some(if (xs[i] - x).abs() < (x - xs[i - 1]).abs() {
        i
    } else {
        i - 1
    })
}

/// Min/max decimation: the points of `pts` reduced to at most four per run of consecutive
/// points in one pixel column of `x` (first, min, max, last, in order), so a polyline through
/// the result has the same pixels as one through all points. For x ascending (a time series)
/// that is at most four per column; a curve that turns back in x (a phase portrait) works
/// too, run by run. Non-finite points break nothing: they are kept
/// (they split the line where the plot draws it).
pub fn decimate(pts: &[(f64, f64)], x: &LinearScale) -> Vec<(f64, f64)> {
    let mut out = Vec::with_capacity(pts.len().min(4096));
    let mut i = 0;
    while i < pts.len() {
        let (px, py) = pts[i];
        if !px.is_finite() || !py.is_finite() {
            out.push(pts[i]);
            i += 1;
            continue;
        }
        let col = x.map(px).floor();
        let start = i;
        let (mut lo, mut hi) = (i, i);
        let mut j = i + 1;
        while j < pts.len() {
            let (qx, qy) = pts[j];
            if !qx.is_finite() || !qy.is_finite() || x.map(qx).floor() != col {
                break;
            }
            if qy < pts[lo].1 {
                lo = j;
            }
            if qy > pts[hi].1 {
                hi = j;
            }
            j += 1;
        }
        let end = j - 1;
        let mut keep = [start, lo, hi, end];
        keep.sort_unstable();
        let mut last = usize::MAX;
        for k in keep {
            if k != last {
                out.push(pts[k]);
                last = k;
            }
        }
        i = j;
    }
    out
}

/// Packs legend entries `(series, text width)`, in order, into rows at most `width` wide
/// (each entry is its swatch `lead` plus its text, `gap` between entries); an entry wider
/// than a row gets a row of its own. No entries: no rows.
pub fn legend_layout(
    entries: &[(usize, f64)],
    lead: f64,
    gap: f64,
    width: f64,
) -> Vec<Vec<(usize, f64)>> {
    let mut rows: Vec<Vec<(usize, f64)>> = Vec::new();
    let mut used = 0.0;
    for &(i, w) in entries {
        let need = lead + w;
        match rows.last_mut() {
            Some(row) if used + gap + need <= width => {
                row.push((i, w));
                used += gap + need;
            }
            _ => {
                rows.push(vec![(i, w)]);
                used = need;
            }
        }
    }
    rows
}

/// An axis title as one line: `title [unit]`, or the title alone without a unit.
pub fn axis_desc(title: &str, unit: &str) -> String {
    if unit.is_empty() {
        title.to_string()
    } else {
        format!("{title} [{unit}]")
    }
}

/// The smallest type a y-axis title is shrunk to, as a fraction of the tick labels' size.
pub const MIN_TITLE_SCALE: f64 = 0.75;

/// A y-axis title laid out along a panel's height: its lines (drawn rotated, side by side)
/// and the type size as a fraction of the tick labels'.
#[derive(Clone, Debug, PartialEq)]
pub struct AxisTitle {
    pub lines: Vec<String>,
    pub scale: f64,
}

/// Lays out a y-axis title along `room` px (the panel's height; projector type on a short
/// panel is what makes it tight): `title [unit]` on one line when it fits; else, when
/// `two_lines` allows (the label area is wide enough), the title and `[unit]` on two lines;
/// the type shrunk (to no less than [`MIN_TITLE_SCALE`]) until the longest line fits; a line
/// still too long is cut and ends in "…". `measure` is a text's width at full size; titles
/// never run into the next panel's.
pub fn axis_title(
    title: &str,
    unit: &str,
    room: f64,
    two_lines: bool,
    measure: impl Fn(&str) -> f64,
) -> AxisTitle {
    let one = axis_desc(title, unit);
    let fits = |lines: &[String], scale: f64| lines.iter().all(|l| measure(l) * scale <= room);
    let mut candidates = vec![vec![one]];
    if two_lines && !unit.is_empty() {
        candidates.push(vec![title.to_string(), format!("[{unit}]")]);
    }
    for lines in &candidates {
        if fits(lines, 1.0) {
            return AxisTitle {
                lines: lines.clone(),
                scale: 1.0,
            };
        }
    }
    let lines = candidates.pop().unwrap_or_default();
    let longest = lines.iter().map(|l| measure(l)).fold(0.0, f64::max);
    let scale = if longest > 0.0 {
        (room / longest).clamp(MIN_TITLE_SCALE, 1.0)
    } else {
        1.0
    };
    let lines = lines
        .into_iter()
        .map(|line| {
            if measure(&line) * scale <= room {
                return line;
            }
            let chars: Vec<char> = line.chars().collect();
            (0..chars.len())
                .rev()
                .map(|n| format!("{}…", chars[..n].iter().collect::<String>().trim_end()))
                .find(|cut| measure(cut) * scale <= room)
                .unwrap_or_default()
        })
        .collect();
    AxisTitle { lines, scale }
}

/// Places labels of `(centre, width)` along x, in order, inside `[x0, x1]` with at least
/// `gap` between them: each as near its centre as it can be; one that cannot fit after the
/// label before it is left out (`None`). Returns the centres.
pub fn place_labels(labels: &[(f64, f64)], x0: f64, x1: f64, gap: f64) -> Vec<Option<f64>> {
    let mut next = x0;
    labels
        .iter()
        .map(|&(centre, w)| {
            let left = (centre - w / 2.0).min(x1 - w).max(next);
            if left + w > x1 + 1e-9 {
                return None;
            }
            next = left + w + gap;
            Some(left + w / 2.0)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn labels_stay_inside_and_apart() {
        // Room enough: each on its centre.
        let at = place_labels(&[(50.0, 20.0), (150.0, 20.0)], 0.0, 200.0, 4.0);
        assert_eq!(at, [Some(50.0), Some(150.0)]);
        // A label wider than its band at the left edge moves right, inside the area (it ran
        // over the y tick labels); the next one moves right after it.
        let at = place_labels(
            &[(20.0, 80.0), (70.0, 40.0), (180.0, 40.0)],
            0.0,
            200.0,
            6.0,
        );
        assert_eq!(at, [Some(40.0), Some(106.0), Some(180.0)]);
        // At the right edge: moved left; one that cannot fit any more is left out.
        let at = place_labels(
            &[(100.0, 90.0), (190.0, 40.0), (199.0, 60.0)],
            0.0,
            200.0,
            6.0,
        );
        assert_eq!(at, [Some(100.0), Some(180.0), None]);
    }

    /// A fixed-pitch stand-in for the canvas: 10 px a character.
    fn pitch(s: &str) -> f64 {
        10.0 * s.chars().count() as f64
    }

    #[test]
    fn axis_titles_fit_their_panel() {
        // Room enough: one line, full size.
        let t = axis_title("angle q", "rad", 200.0, true, pitch);
        assert_eq!(t.lines, ["angle q [rad]"]);
        assert_eq!(t.scale, 1.0);
        // Too long for one line (25 chars = 250 px in 200): title and unit on two lines.
        let t = axis_title("acceleration qdd", "rad/s²", 200.0, true, pitch);
        assert_eq!(t.lines, ["acceleration qdd", "[rad/s²]"]);
        assert_eq!(t.scale, 1.0);
        // No room for a second line: one line, shrunk.
        let t = axis_title("acceleration qdd", "rad/s²", 200.0, false, pitch);
        assert_eq!(t.lines, ["acceleration qdd [rad/s²]"]);
        assert!((t.scale - 0.8).abs() < 1e-12);
        // Shorter still: shrunk to the least size, then cut.
        let t = axis_title("acceleration qdd", "rad/s²", 90.0, true, pitch);
        assert_eq!(t.scale, MIN_TITLE_SCALE);
        for line in &t.lines {
            assert!(pitch(line) * t.scale <= 90.0, "{line} fits");
        }
        assert_eq!(t.lines, ["acceleratio…", "[rad/s²]"]);
        // No unit: one line whatever the room; Japanese is measured the same way.
        let t = axis_title("位置 s", "", 30.0, true, pitch);
        assert_eq!(t.lines.len(), 1);
        assert!(pitch(&t.lines[0]) * t.scale <= 30.0);
        // Every line of every layout fits, at any room.
        for room in [0.0, 5.0, 40.0, 75.0, 120.0, 160.0, 260.0] {
            for two in [false, true] {
                let t = axis_title("velocity qd", "rad/s", room, two, pitch);
                assert!(
                    t.lines.iter().all(|l| pitch(l) * t.scale <= room),
                    "{room} {two}: {t:?}"
                );
            }
        }
    }

    #[test]
    fn scales_map_and_invert() {
        let y = LinearScale::new((-1.0, 1.0), (200.0, 0.0));
        assert_eq!(y.map(-1.0), 200.0);
        assert_eq!(y.map(0.5), 50.0);
        assert_eq!(y.invert(50.0), 0.5);
        // A flat domain is widened, not divided by zero.
        let flat = LinearScale::new((3.0, 3.0), (0.0, 100.0));
        assert_eq!(flat.domain, (2.5, 3.5));
        assert_eq!(flat.map(3.0), 50.0);
    }

    #[test]
    fn ticks_are_one_two_five_multiples_inside_the_range() {
        assert_eq!(nice_ticks(0.0, 1.57, 6), vec![0.0, 0.5, 1.0, 1.5]);
        assert_eq!(nice_ticks(-0.0132, 0.0132, 4), vec![-0.01, 0.0, 0.01]);
        assert_eq!(nice_ticks(-1.0, 1.0, 8), vec![-1.0, -0.5, 0.0, 0.5, 1.0]);
        assert_eq!(nice_step(0.0, 1000.0, 5), 200.0);
        assert_eq!(nice_step(0.0, 10.0, 4), 5.0);
        assert!(nice_ticks(0.0, f64::INFINITY, 5).is_empty());
    }

    #[test]
    fn tick_labels_have_the_step_s_decimals() {
        for (value, step, shown) in [
            (0.6000000000000001, 0.2, "0.6"),
            (-0.005, 0.005, "-0.005"),
            (0.25, 0.25, "0.25"),
            (200.0, 200.0, "200"),
            (0.0, 0.1, "0"),
            (2.0e7, 1.0e7, "2.0e7"),
        ] {
            assert_eq!(tick_label(value, step), shown, "{value} by {step}");
        }
    }

    #[test]
    fn log_axes_in_decades() {
        assert_eq!(log_axis_range((1e-12, 100.0)), (-12.0, 2.0));
        assert_eq!(log_axis_range((10.0, 0.001)), (1.0, -3.0));
        assert_eq!(log_axis_range((0.0, 100.0)), (-12.0, 2.0));
        assert_eq!(log_axis_range((-1.0, 0.0)), (-12.0, 0.0));
        assert_eq!(log_tick_label(-12.0), "10⁻¹²");
        assert_eq!(log_tick_label(-6.000000000001), "10⁻⁶");
        assert_eq!(log_tick_label(0.0), "1");
        assert_eq!(log_tick_label(1.0), "10");
        assert_eq!(log_tick_label(3.0), "10³");
        assert_eq!(log_tick_label(2f64.log10()), "2");
        assert_eq!(log_tick_label(f64::NAN), "");
    }

    #[test]
    fn auto_range_pads_and_skips_nan() {
        assert_eq!(auto_range([1.0, f64::NAN, 3.0], 0.1), Some((0.8, 3.2)));
        assert_eq!(auto_range([2.0], 0.0), Some((2.0, 2.0)));
        assert_eq!(auto_range([f64::NAN], 0.1), None);
    }

    #[test]
    fn nearest_sample_to_a_cursor() {
        let xs = [0.0, 1.0, 2.0, 4.0];
        assert_eq!(nearest_index(&xs, -3.0), Some(0));
        assert_eq!(nearest_index(&xs, 1.4), Some(1));
        assert_eq!(nearest_index(&xs, 3.1), Some(3));
        assert_eq!(nearest_index(&xs, 9.0), Some(3));
        assert_eq!(nearest_index(&[], 1.0), None);
    }

    #[test]
    fn decimation_keeps_each_column_s_extremes_in_order() {
        // 1000 samples of a sine over 10 pixel columns.
        let pts: Vec<(f64, f64)> = (0..1000)
            .map(|i| {
                let x = i as f64 / 1000.0;
                (x, (x * 40.0).sin())
            })
            .collect();
        let x = LinearScale::new((0.0, 1.0), (0.0, 10.0));
        let d = decimate(&pts, &x);
        assert!(d.len() <= 40, "{} points", d.len());
        assert_eq!(d.first(), pts.first());
        assert_eq!(d.last(), pts.last());
        assert!(d.windows(2).all(|w| w[0].0 <= w[1].0));
        // The highest and lowest y of `points` in pixel column `col`.
        let extremes = |points: &[(f64, f64)], col: usize| {
            let ys = points
                .iter()
                .filter(|p| x.map(p.0).floor() == col as f64)
                .map(|p| p.1);
            let max = ys.clone().fold(f64::MIN, f64::max);
            (max, ys.fold(f64::MAX, f64::min))
        };
        for col in 0..10 {
            assert_eq!(extremes(&pts, col), extremes(&d, col), "column {col}");
        }
        // Few points: unchanged.
        let few = [(0.0, 1.0), (0.5, 2.0), (1.0, 0.0)];
        assert_eq!(decimate(&few, &x), few.to_vec());
    }

    #[test]
    fn decimation_of_a_curve_that_turns_back_keeps_its_extent() {
        // A phase-portrait ellipse traced finely: runs within a column shrink to ≤ 4 points,
        // and the turning points stay (in y exactly, in x to the pixel column).
        let pts: Vec<(f64, f64)> = (0..=20_000)
            .map(|i| {
                let a = i as f64 / 20_000.0 * std::f64::consts::TAU;
                (2.0 * a.cos(), 10.0 * a.sin())
            })
            .collect();
        let x = LinearScale::new((-2.0, 2.0), (0.0, 400.0));
        let d = decimate(&pts, &x);
        assert!(d.len() < pts.len() / 4, "{} points", d.len());
        let extent = |p: &[(f64, f64)]| {
            p.iter()
                .fold((f64::MAX, f64::MIN, f64::MAX, f64::MIN), |e, q| {
                    (e.0.min(q.0), e.1.max(q.0), e.2.min(q.1), e.3.max(q.1))
                })
        };
        // Same y extremes; x extremes in the same pixel columns (x within a column is one
        // pixel).
        let (a, b) = (extent(&d), extent(&pts));
        assert_eq!((a.2, a.3), (b.2, b.3));
        assert_eq!(x.map(a.0).floor(), x.map(b.0).floor());
        assert_eq!(x.map(a.1).floor(), x.map(b.1).floor());
        assert_eq!((d.first(), d.last()), (pts.first(), pts.last()));
    }

    #[test]
    fn legend_rows_pack_in_order_and_wrap() {
        let e = [(0, 20.0), (1, 20.0), (2, 20.0), (3, 100.0)];
        // lead 10 + text: 30, 30, 30 with gaps of 5: 100 fits one row; 110 does not.
        assert_eq!(legend_layout(&e[..3], 10.0, 5.0, 100.0).len(), 1);
        let rows = legend_layout(&e, 10.0, 5.0, 70.0);
        let ids: Vec<Vec<usize>> = rows
            .iter()
            .map(|r| r.iter().map(|x| x.0).collect())
            .collect();
        assert_eq!(ids, vec![vec![0, 1], vec![2], vec![3]]);
        assert!(legend_layout(&[], 10.0, 5.0, 70.0).is_empty());
    }
}
