//! The Umeyama page (`#/umeyama-2d`) without the browser: the scene of one run (X, the noisy
//! targets Y, the fit's intermediates from the kernel's own [`umeyama_steps`]), the teaching
//! steps (centroids → centred sets → covariance → SVD → reflection fix → scale → translation →
//! rmse) with the small matrix each one shows, the point editor (add, move, remove, the text
//! `--x` takes), the handles of the true similarity, and the view's world ↔ pixel frame with
//! its hit tests.
//!
//! Every number the page shows comes from [`umeyama_steps`], the function the recipe's run
//! calls: the readouts equal the CSV's to the bit. Only the SVD's factors `U`, `Vᵀ` are
//! derived here (the kernel needs just the singular values and `R`), from the same closed
//! form: `C = Q rot(α) + R refl(β)` gives `U = rot((α+β)/2)`, `Vᵀ = rot((α−β)/2)`,
//! `S = (Q + R, |Q − R|)`.

use glam::DVec2;

use crate::recipes::umeyama_2d::{
    sample_setup, umeyama_steps, Alignment, Similarity, UmeyamaSetup, UmeyamaSteps, FLAG_ANGLE,
    FLAG_SCALE, FLAG_TX, FLAG_TY, MIN_POINTS,
};

/// Most points the page's editor holds (the CLI takes up to 100,000).
pub const MAX_EDIT_POINTS: usize = 40;
/// Grid of edited points: coordinates are rounded to it (short URLs and command lines; the
/// CLI reads the same numbers).
pub const GRID: f64 = 0.001;
/// Grid of a dragged point, of the dragged translation and scale.
pub const DRAG_GRID: f64 = 0.01;
/// Grid of a dragged angle, degrees.
pub const ANGLE_GRID: f64 = 0.5;

/// One run as the page shows it.
#[derive(Debug, Clone, PartialEq)]
pub struct Scene {
    pub setup: UmeyamaSetup,
    /// The source points X and the noisy targets Y.
    pub x: Vec<[f64; 2]>,
    pub y: Vec<[f64; 2]>,
    /// The fit and its intermediates, as the recipe's run computes them.
    pub steps: UmeyamaSteps,
}

impl Scene {
    /// The run of `setup` (validated by the caller; `None` without points).
    pub fn new(setup: &UmeyamaSetup) -> Option<Scene> {
        let (x, y) = sample_setup(setup);
        let steps = umeyama_steps(&x, &y)?;
        Some(Scene {
            setup: setup.clone(),
            x,
            y,
            steps,
        })
    }

    /// The estimate (the CSV's numbers).
    pub fn fit(&self) -> Alignment {
        self.steps.alignment()
    }

    /// The true similarity.
    pub fn truth(&self) -> Similarity {
        self.setup.truth
    }

    /// Everything the view should show: X, Y, the aligned points, the centroids, the origin
    /// and the truth's handles, as (min, max) corners.
    pub fn bounds(&self) -> ([f64; 2], [f64; 2]) {
        let truth = self.truth();
        let extra = [
            [0.0, 0.0],
            truth.t,
            rotation_handle(&truth),
            self.steps.mu_x,
            self.steps.mu_y,
        ];
        let mut lo = [f64::INFINITY; 2];
        let mut hi = [f64::NEG_INFINITY; 2];
        for p in self
            .x
            .iter()
            .chain(&self.y)
            .chain(&self.steps.aligned)
            .chain(&extra)
        {
            for k in 0..2 {
                if p[k].is_finite() {
                    lo[k] = lo[k].min(p[k]);
                    hi[k] = hi[k].max(p[k]);
                }
            }
        }
        (lo, hi)
    }
}

/// The grid lines of spacing `step` over `lo..=hi`: the multiples k with k·step from the one at
/// or below `lo` to the last at or below `hi`; `None` when they are not finite or more than
/// 1,000 (points near ±1e308, from a huge sigma, make the span infinite).
pub fn grid_multiples(lo: f64, hi: f64, step: f64) -> Option<std::ops::RangeInclusive<i64>> {
    let (first, last) = ((lo / step).floor(), (hi / step).floor());
    (first.is_finite() && last.is_finite() && (0.0..=1000.0).contains(&(last - first)))
        .then_some(first as i64..=last as i64)
}

/// A 2×2 matrix, row-major.
pub type Mat2 = [[f64; 2]; 2];

fn rot(angle: f64) -> Mat2 {
    let (s, c) = crate::math::sincos(angle);
    [[c, -s], [s, c]]
}

/// `a b`.
pub fn mat_mul(a: &Mat2, b: &Mat2) -> Mat2 {
    let mut out = [[0.0; 2]; 2];
    for (i, row) in out.iter_mut().enumerate() {
        for (j, cell) in row.iter_mut().enumerate() {
            *cell = a[i][0] * b[0][j] + a[i][1] * b[1][j];
        }
    }
    out
}

/// `det a`.
pub fn det(a: &Mat2) -> f64 {
    a[0][0] * a[1][1] - a[0][1] * a[1][0]
}

/// The SVD `C = U diag(S) Vᵀ` of the cross-covariance, as numpy orders it (`S_1 >= S_2 >= 0`),
/// and the recipe's reflection fix.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Svd {
    pub u: Mat2,
    pub s: [f64; 2],
    pub vt: Mat2,
    /// `det(U Vᵀ)`: −1 when `U Vᵀ` is a reflection.
    pub det_uvt: f64,
    /// `U` after the fix (its last column negated when `det(U Vᵀ) < 0`; else `U`).
    pub u_fixed: Mat2,
}

/// The SVD of `steps`' covariance from its closed form.
pub fn svd(steps: &UmeyamaSteps) -> Svd {
    let [e, f, g, h] = steps.efgh;
    let alpha = crate::math::atan2(h, e);
    let beta = crate::math::atan2(g, f);
    let theta = (alpha + beta) / 2.0;
    let phi = (beta - alpha) / 2.0;
    let rotation_u = rot(theta);
    let vt = rot(-phi);
    let (q, r) = (steps.q, steps.r);
    let reflection = steps.reflection_fixed();
    // Q < R: the second singular value R − Q is positive with U's second column negated.
    let u = if reflection {
        [
            [rotation_u[0][0], -rotation_u[0][1]],
            [rotation_u[1][0], -rotation_u[1][1]],
        ]
    } else {
        rotation_u
    };
    Svd {
        u,
        s: [q + r, (q - r).abs()],
        vt,
        det_uvt: if reflection { -1.0 } else { 1.0 },
        u_fixed: rotation_u,
    }
}

/// The teaching steps, in the order the recipe computes them; `Overview` is the whole fit.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Step {
    Overview,
    Centroids,
    Centred,
    Covariance,
    Svd,
    Reflection,
    Scale,
    Translation,
    Rmse,
}

/// Every step, stepper index 0 to 8.
pub const STEPS: [Step; 9] = [
    Step::Overview,
    Step::Centroids,
    Step::Centred,
    Step::Covariance,
    Step::Svd,
    Step::Reflection,
    Step::Scale,
    Step::Translation,
    Step::Rmse,
];

impl Step {
    /// The step at stepper index `i` (past the end: the last).
    pub fn at(i: u64) -> Step {
        STEPS[(i as usize).min(STEPS.len() - 1)]
    }

    /// The key of its Fluent ids (`umeyama-step-<key>-title`, `-text`).
    pub fn key(self) -> &'static str {
        match self {
            Step::Overview => "overview",
            Step::Centroids => "centroids",
            Step::Centred => "centred",
            Step::Covariance => "covariance",
            Step::Svd => "svd",
            Step::Reflection => "reflection",
            Step::Scale => "scale",
            Step::Translation => "translation",
            Step::Rmse => "rmse",
        }
    }
}

/// A small matrix (or vector, or number) a step shows: its symbol and its rows.
#[derive(Debug, Clone, PartialEq)]
pub struct Shown {
    pub symbol: &'static str,
    pub rows: Vec<Vec<f64>>,
}

fn shown(symbol: &'static str, rows: Vec<Vec<f64>>) -> Shown {
    Shown { symbol, rows }
}

fn column(v: [f64; 2]) -> Vec<Vec<f64>> {
    vec![vec![v[0]], vec![v[1]]]
}

fn matrix(m: &Mat2) -> Vec<Vec<f64>> {
    m.iter().map(|r| r.to_vec()).collect()
}

/// The matrices `step` shows for `scene` (the fit's own numbers).
pub fn shown_for(scene: &Scene, step: Step) -> Vec<Shown> {
    let s = &scene.steps;
    match step {
        Step::Overview => vec![
            shown("s", vec![vec![s.scale]]),
            shown("R", matrix(&s.rotation)),
            shown("t", column(s.t)),
        ],
        Step::Centroids => vec![shown("μx", column(s.mu_x)), shown("μy", column(s.mu_y))],
        Step::Centred => {
            let first = |v: &[[f64; 2]]| v.first().copied().unwrap_or([f64::NAN; 2]);
            vec![
                shown("Xc₁", column(first(&s.centred_x))),
                shown("Yc₁", column(first(&s.centred_y))),
                shown("var_x", vec![vec![s.var_x]]),
            ]
        }
        Step::Covariance => vec![
            shown("C", matrix(&s.cov)),
            shown("det C", vec![vec![det(&s.cov)]]),
        ],
        Step::Svd => {
            let d = svd(s);
            vec![
                shown("U", matrix(&d.u)),
                shown("S", vec![vec![d.s[0], d.s[1]]]),
                shown("Vᵀ", matrix(&d.vt)),
            ]
        }
        Step::Reflection => {
            let d = svd(s);
            vec![
                shown("det(UVᵀ)", vec![vec![d.det_uvt]]),
                shown("U′", matrix(&d.u_fixed)),
                shown("R", matrix(&s.rotation)),
            ]
        }
        Step::Scale => vec![
            shown("S₁+S₂", vec![vec![s.singular_sum]]),
            shown("var_x", vec![vec![s.var_x]]),
            shown("s", vec![vec![s.scale]]),
        ],
        Step::Translation => vec![shown("t", column(s.t))],
        Step::Rmse => vec![shown("rmse", vec![vec![s.rmse]])],
    }
}

/// Umeyama's own scale `(S_1 − S_2) / var_x` when the reflection fix was needed (the recipe
/// keeps `S_1 + S_2`); `None` otherwise.
pub fn umeyama_scale(steps: &UmeyamaSteps) -> Option<f64> {
    if !steps.reflection_fixed() || steps.var_x <= crate::recipes::umeyama_2d::MIN_VARIANCE {
        return None;
    }
    let d = svd(steps);
    Some((d.s[0] - d.s[1]) / steps.var_x)
}

// ---------- The point editor ----------

/// Why an edit of the points was refused.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Refusal {
    /// Already [`MAX_EDIT_POINTS`].
    TooMany,
    /// Only [`MIN_POINTS`] left.
    TooFew,
}

impl Refusal {
    /// Its Fluent id (with `$count`).
    pub fn message_id(self) -> &'static str {
        match self {
            Refusal::TooMany => "umeyama-refused-too-many",
            Refusal::TooFew => "umeyama-refused-too-few",
        }
    }

    /// The limit it names.
    pub fn count(self) -> usize {
        match self {
            Refusal::TooMany => MAX_EDIT_POINTS,
            Refusal::TooFew => MIN_POINTS,
        }
    }
}

/// `v` on the grid `step`, through its decimal text (0.35, not 0.35000000000000003).
pub fn snap_to(v: f64, step: f64) -> f64 {
    let digits = (-step.log10().floor()).max(0.0) as usize;
    let s = (v / step).round() * step;
    let text = format!("{s:.digits$}");
    let parsed: f64 = text.parse().unwrap_or(s);
    // No "-0" in URLs and command lines.
    if parsed == 0.0 {
        0.0
    } else {
        parsed
    }
}

/// A number as `--x` and the other options write it (`0.35`, `-1`, `12.5`).
pub fn num(v: f64) -> String {
    format!("{v}")
}

/// The text `--x` takes: `x,y;x,y;...`.
pub fn points_text(points: &[[f64; 2]]) -> String {
    points
        .iter()
        .map(|p| format!("{},{}", num(p[0]), num(p[1])))
        .collect::<Vec<_>>()
        .join(";")
}

/// The points as the editor holds them: X on the editor's grid (the recipe's random points
/// become editable this way, each moved by less than half a thousandth).
pub fn editable(points: &[[f64; 2]]) -> Vec<[f64; 2]> {
    points
        .iter()
        .map(|p| [snap_to(p[0], GRID), snap_to(p[1], GRID)])
        .collect()
}

/// `points` with point `i` moved to `to` (on the drag grid).
pub fn move_point(points: &[[f64; 2]], i: usize, to: [f64; 2]) -> Vec<[f64; 2]> {
    let mut out = editable(points);
    if let Some(p) = out.get_mut(i) {
        *p = [snap_to(to[0], DRAG_GRID), snap_to(to[1], DRAG_GRID)];
    }
    out
}

/// `points` with a new point at `at` (on the drag grid), refused past [`MAX_EDIT_POINTS`].
pub fn add_point(points: &[[f64; 2]], at: [f64; 2]) -> Result<Vec<[f64; 2]>, Refusal> {
    if points.len() >= MAX_EDIT_POINTS {
        return Err(Refusal::TooMany);
    }
    let mut out = editable(points);
    out.push([snap_to(at[0], DRAG_GRID), snap_to(at[1], DRAG_GRID)]);
    Ok(out)
}

/// `points` without point `i` (the last when `i` is out of range), refused at
/// [`MIN_POINTS`].
pub fn remove_point(points: &[[f64; 2]], i: usize) -> Result<Vec<[f64; 2]>, Refusal> {
    if points.len() <= MIN_POINTS {
        return Err(Refusal::TooFew);
    }
    let mut out = editable(points);
    let i = i.min(out.len() - 1);
    out.remove(i);
    Ok(out)
}

/// What `n` selects after `selected` (`forward`), or Shift + `n` (not `forward`): the points
/// in the list order, then the truth's translation handle, then its rotation handle, round
/// again; from none, the first point or the rotation handle. A point out of range counts as
/// none.
pub fn next_selection(selected: Option<Grab>, count: usize, forward: bool) -> Option<Grab> {
    // Position k in the round: points 0..count, then t, then s·R.
    let n = count + 2;
    let at = |k: usize| match k {
        k if k < count => Grab::Point(k),
        k if k == count => Grab::Translation,
        _ => Grab::Rotation,
    };
    let k = match selected {
        Some(Grab::Point(i)) if i < count => Some(i),
        Some(Grab::Translation) => Some(count),
        Some(Grab::Rotation) => Some(count + 1),
        _ => None,
    };
    Some(at(match (k, forward) {
        (None, true) => 0,
        (None, false) => n - 1,
        (Some(k), true) => (k + 1) % n,
        (Some(k), false) => (k + n - 1) % n,
    }))
}

/// Where Shift + an arrow sends the rotation handle of `truth`: ← → turn it by
/// [`ANGLE_GRID`]° (counter-clockwise for →), ↑ ↓ grow or shrink the scale by [`DRAG_GRID`]
/// (`(dx, dy)`, each −1, 0 or 1). A drag to there ([`rotation_texts`]) snaps it: the angle and
/// the scale move by exactly one step.
pub fn rotation_key_target(truth: &Similarity, (dx, dy): (f64, f64)) -> [f64; 2] {
    let angle = (truth.angle_deg + dx * ANGLE_GRID).to_radians();
    let scale = (truth.scale + dy * DRAG_GRID).max(DRAG_GRID);
    [
        truth.t[0] + scale * angle.cos(),
        truth.t[1] + scale * angle.sin(),
    ]
}

/// Where Shift + an arrow sends point `p`: one [`DRAG_GRID`] step along `(dx, dy)` (each −1,
/// 0 or 1). A drag to there (`move_point`) puts it on the drag grid: a point already on it
/// moves by exactly one step.
pub fn key_step_target(p: [f64; 2], (dx, dy): (f64, f64)) -> [f64; 2] {
    [p[0] + dx * DRAG_GRID, p[1] + dy * DRAG_GRID]
}

/// The selected point of `scene` (its index, when in range) and where it is as the editor
/// holds it (on [`GRID`], as `--x` writes it).
pub fn selected_point(scene: &Scene, selected: Option<usize>) -> Option<(usize, [f64; 2])> {
    let i = selected?;
    let p = scene.x.get(i)?;
    Some((i, [snap_to(p[0], GRID), snap_to(p[1], GRID)]))
}

/// Where a new point goes when added by the button: beyond the points' extent on a slow
/// spiral, so successive ones do not pile up.
pub fn new_point_spot(points: &[[f64; 2]]) -> [f64; 2] {
    let k = points.len() as f64;
    let radius = points
        .iter()
        .map(|p| p[0].hypot(p[1]))
        .fold(0.5_f64, f64::max)
        .min(5.0);
    let angle = k * 2.399_963; // the golden angle, radians
    [radius * angle.cos(), radius * angle.sin()]
}

// ---------- Labels ----------

/// Where a label box of `size` (CSS px) beside a mark at `p` goes: its top-left corner, `gap`
/// px from `p` up-right, else up-left, down-right, down-left, the first whose box keeps
/// `clear` px from every circle of `avoid` (centre, radius); up-right when none does. A circle
/// centred on `p` (the labelled mark itself) is not avoided.
pub fn label_corner(p: DVec2, size: DVec2, gap: f64, avoid: &[(DVec2, f64)], clear: f64) -> DVec2 {
    let corners = [
        p + DVec2::new(gap, -gap - size.y),
        p + DVec2::new(-gap - size.x, -gap - size.y),
        p + DVec2::new(gap, gap),
        p + DVec2::new(-gap - size.x, gap),
    ];
    let free = |c: &DVec2| {
        avoid
            .iter()
            .all(|(q, r)| q.distance(p) < 0.5 || q.clamp(*c, *c + size).distance(*q) > r + clear)
    };
    corners.iter().copied().find(free).unwrap_or(corners[0])
}

// ---------- The true similarity's handles ----------

/// The rotation handle: `t + s (cos θ, sin θ)`, the image of `(1, 0)` under the truth.
pub fn rotation_handle(truth: &Similarity) -> [f64; 2] {
    let (sin, cos) = crate::math::sincos(truth.angle_deg.to_radians());
    [
        truth.t[0] + truth.scale * cos,
        truth.t[1] + truth.scale * sin,
    ]
}

/// The option texts a drag of the translation handle to `to` sets: `(tx, ty)`.
pub fn translation_texts(to: [f64; 2]) -> [(&'static str, String); 2] {
    let clamp = |v: f64, spec: &crate::args::ArgSpec| {
        let lo = spec.min.value().unwrap_or(f64::NEG_INFINITY);
        let hi = spec.max.value().unwrap_or(f64::INFINITY);
        num(snap_to(v.clamp(lo, hi), DRAG_GRID))
    };
    [
        (FLAG_TX.name, clamp(to[0], &FLAG_TX)),
        (FLAG_TY.name, clamp(to[1], &FLAG_TY)),
    ]
}

/// The option texts a drag of the rotation handle to `to` sets, the translation `t` held:
/// `(angle, scale)` (the angle in (−180, 180], the scale at least [`DRAG_GRID`]).
pub fn rotation_texts(t: [f64; 2], to: [f64; 2]) -> [(&'static str, String); 2] {
    let d = [to[0] - t[0], to[1] - t[1]];
    let angle = snap_to(crate::math::atan2(d[1], d[0]).to_degrees(), ANGLE_GRID);
    let angle = if angle <= -180.0 {
        angle + 360.0
    } else {
        angle
    };
    let hi = FLAG_SCALE.max.value().unwrap_or(1000.0);
    let scale = snap_to(d[0].hypot(d[1]), DRAG_GRID).clamp(DRAG_GRID, hi);
    [
        (FLAG_ANGLE.name, num(angle)),
        (FLAG_SCALE.name, num(snap_to(scale, DRAG_GRID))),
    ]
}

// ---------- The view's frame and hit tests ----------

/// World ↔ CSS pixels: x right, y up, one scale for both axes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Frame {
    /// Pixels per world unit.
    pub scale: f64,
    /// The pixel of the world origin.
    pub origin: DVec2,
}

impl Frame {
    /// The frame showing `bounds` (min, max corners) in a `size` px canvas with `margin` px on
    /// every side, centred.
    pub fn fit(bounds: ([f64; 2], [f64; 2]), size: (f64, f64), margin: f64) -> Frame {
        let (lo, hi) = bounds;
        let (lo, hi) = if lo[0].is_finite() && hi[0].is_finite() {
            (lo, hi)
        } else {
            ([-1.0, -1.0], [1.0, 1.0])
        };
        let span = [(hi[0] - lo[0]).max(1e-3), (hi[1] - lo[1]).max(1e-3)];
        let w = (size.0 - 2.0 * margin).max(10.0);
        let h = (size.1 - 2.0 * margin).max(10.0);
        let scale = (w / span[0]).min(h / span[1]);
        let centre = [(lo[0] + hi[0]) / 2.0, (lo[1] + hi[1]) / 2.0];
        Frame {
            scale,
            origin: DVec2::new(
                size.0 / 2.0 - centre[0] * scale,
                size.1 / 2.0 + centre[1] * scale,
            ),
        }
    }

    /// The pixel of world point `p`.
    pub fn px(&self, p: [f64; 2]) -> DVec2 {
        DVec2::new(
            self.origin.x + p[0] * self.scale,
            self.origin.y - p[1] * self.scale,
        )
    }

    /// The world point at pixel `at`.
    pub fn world(&self, at: DVec2) -> [f64; 2] {
        [
            (at.x - self.origin.x) / self.scale,
            (self.origin.y - at.y) / self.scale,
        ]
    }

    /// Whether every point of `bounds` is inside the `size` px canvas.
    pub fn shows(&self, bounds: ([f64; 2], [f64; 2]), size: (f64, f64)) -> bool {
        let a = self.px(bounds.0);
        let b = self.px(bounds.1);
        let inside = |p: DVec2| p.x >= 0.0 && p.y >= 0.0 && p.x <= size.0 && p.y <= size.1;
        inside(a) && inside(b)
    }

    /// Whether the view should be fitted again to show `bounds`: something lies outside, or
    /// everything has shrunk below a third of the canvas. Between those the frame stays put,
    /// so a slider or a field moves the points in a still view (and costs no re-layout of
    /// the touch handles).
    pub fn needs_refit(&self, bounds: ([f64; 2], [f64; 2]), size: (f64, f64)) -> bool {
        if !self.shows(bounds, size) {
            return true;
        }
        let w = (bounds.1[0] - bounds.0[0]) * self.scale;
        let h = (bounds.1[1] - bounds.0[1]) * self.scale;
        w < size.0 / 3.0 && h < size.1 / 3.0
    }
}

/// What a press grabs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Grab {
    /// Source point `i`.
    Point(usize),
    /// The true translation.
    Translation,
    /// The true rotation (and scale).
    Rotation,
}

/// What lies within `radius` px of `at`: the nearest source point, else a truth handle.
pub fn hit_test(frame: &Frame, scene: &Scene, at: DVec2, radius: f64) -> Option<Grab> {
    let nearest = scene
        .x
        .iter()
        .enumerate()
        .map(|(i, p)| (i, frame.px(*p).distance(at)))
        .filter(|(_, d)| *d <= radius)
        .min_by(|a, b| a.1.total_cmp(&b.1));
    if let Some((i, _)) = nearest {
        return Some(Grab::Point(i));
    }
    let truth = scene.truth();
    if frame.px(rotation_handle(&truth)).distance(at) <= radius {
        return Some(Grab::Rotation);
    }
    if frame.px(truth.t).distance(at) <= radius {
        return Some(Grab::Translation);
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::args::Args;
    use crate::recipes::umeyama_2d::{
        self, setup_from_args, UmeyamaParams, ARGS, INFO, OPTIONS, POINTS_CSV,
    };
    use crate::view::signal::{read_texts, write_texts};

    fn setup_of(raw: &[&str]) -> UmeyamaSetup {
        let raw: Vec<String> = raw.iter().map(|s| s.to_string()).collect();
        setup_from_args(&Args::parse(&raw, &ARGS, &OPTIONS).unwrap()).unwrap()
    }

    fn default_scene() -> Scene {
        Scene::new(&UmeyamaSetup::default()).unwrap()
    }

    /// The largest difference of two matrices' entries.
    fn max_diff(a: &Mat2, b: &Mat2) -> f64 {
        a.iter()
            .flatten()
            .zip(b.iter().flatten())
            .map(|(x, y)| (x - y).abs())
            .fold(0.0, f64::max)
    }

    /// `U diag(S) Vᵀ`.
    fn product(d: &Svd) -> Mat2 {
        let us = [
            [d.u[0][0] * d.s[0], d.u[0][1] * d.s[1]],
            [d.u[1][0] * d.s[0], d.u[1][1] * d.s[1]],
        ];
        mat_mul(&us, &d.vt)
    }

    #[test]
    fn the_scene_is_the_recipes_run_to_the_bit() {
        let scene = default_scene();
        let fit = umeyama_2d::run(&UmeyamaParams::default()).unwrap();
        assert_eq!(scene.fit(), fit);
        // The CSV row is made of the same numbers.
        let out = crate::recipes::testkit::run_strs::<umeyama_2d::Entry>(&[]).unwrap();
        let row = out.files[0].text.lines().nth(1).unwrap().to_string();
        let want: Vec<String> = [fit.scale, fit.rotation_deg, fit.tx, fit.ty, fit.rmse]
            .iter()
            .map(|v| crate::pyfmt::py_float(*v))
            .collect();
        assert!(row.starts_with(&want.join(",")), "{row}");
    }

    #[test]
    fn intermediates_agree_with_their_definitions() {
        let scene = default_scene();
        let s = &scene.steps;
        let n = scene.x.len() as f64;
        let mean = |v: &[[f64; 2]], k: usize| v.iter().map(|p| p[k]).sum::<f64>() / n;
        for k in 0..2 {
            assert!((s.mu_x[k] - mean(&scene.x, k)).abs() < 1e-15);
            assert!((s.mu_y[k] - mean(&scene.y, k)).abs() < 1e-15);
            // Centred sets have zero mean.
            assert!(mean(&s.centred_x, k).abs() < 1e-15);
            assert!(mean(&s.centred_y, k).abs() < 1e-15);
        }
        // C = Yc^T Xc / n.
        let entry = |i: usize, j: usize| {
            s.centred_y
                .iter()
                .zip(&s.centred_x)
                .map(|(yc, xc)| yc[i] * xc[j])
                .sum::<f64>()
                / n
        };
        let c = [[entry(0, 0), entry(0, 1)], [entry(1, 0), entry(1, 1)]];
        assert!(max_diff(&c, &s.cov) < 1e-14);
        // U diag(S) Vᵀ = C; U, V orthogonal; R = U′Vᵀ.
        let d = svd(s);
        assert!(max_diff(&product(&d), &s.cov) < 1e-14);
        assert!(max_diff(&mat_mul(&d.u_fixed, &d.vt), &s.rotation) < 1e-14);
        assert!((det(&d.u) - 1.0).abs() < 1e-14 && (det(&d.vt) - 1.0).abs() < 1e-14);
        assert!(d.s[0] >= d.s[1] && d.s[1] >= 0.0);
        assert_eq!(d.det_uvt, 1.0);
        assert!((d.s[0] + d.s[1] - s.singular_sum).abs() < 1e-15);
        // s = (S1 + S2) / var_x; t = mu_y - s R mu_x: the kernel's numbers.
        assert_eq!(s.scale, s.singular_sum / s.var_x);
        assert_eq!(umeyama_scale(s), None);
        // Every step shows something, the overview the fit.
        for step in STEPS {
            assert!(!shown_for(&scene, step).is_empty(), "{step:?}");
        }
        assert_eq!(Step::at(0), Step::Overview);
        assert_eq!(Step::at(99), Step::Rmse);
        assert_eq!(shown_for(&scene, Step::Rmse)[0].rows, vec![vec![s.rmse]]);
    }

    #[test]
    fn the_mirror_preset_shows_the_reflection_fix() {
        let scene = Scene::new(&setup_of(&["0", "3", "12", "--mirror", "yes"])).unwrap();
        let s = &scene.steps;
        assert!(s.reflection_fixed());
        let d = svd(s);
        assert_eq!(d.det_uvt, -1.0);
        assert!((det(&mat_mul(&d.u, &d.vt)) + 1.0).abs() < 1e-14);
        // U diag(S) Vᵀ is still C, with U a reflection; the fixed U gives a rotation.
        assert!(max_diff(&product(&d), &s.cov) < 1e-14);
        assert!((det(&d.u_fixed) - 1.0).abs() < 1e-14);
        // The recipe keeps S1 + S2; Umeyama would use S1 − S2: smaller.
        let umeyama = umeyama_scale(s).unwrap();
        assert!(umeyama < s.scale, "{umeyama} {}", s.scale);
        let shown = shown_for(&scene, Step::Reflection);
        assert_eq!(shown[0].rows, vec![vec![-1.0]]);
    }

    #[test]
    fn edits_keep_the_points_on_the_grid_within_limits() {
        let scene = default_scene();
        let moved = move_point(&scene.x, 3, [0.123_456, -1.987_6]);
        assert_eq!(moved.len(), 12);
        assert_eq!(moved[3], [0.12, -1.99]);
        for (a, b) in moved
            .iter()
            .zip(&scene.x)
            .filter(|(a, _)| **a != [0.12, -1.99])
        {
            assert!((a[0] - b[0]).abs() <= 0.0005 && (a[1] - b[1]).abs() <= 0.0005);
        }
        let text = points_text(&moved);
        assert!(text.contains("0.12,-1.99"), "{text}");
        // The text is what --x reads back.
        let setup = setup_of(&["0.02", "3", "12", "--x", &text]);
        assert_eq!(setup.points.as_deref(), Some(&moved[..]));
        let added = add_point(&moved, [1.0, 1.0]).unwrap();
        assert_eq!(added.len(), 13);
        assert_eq!(remove_point(&added, 0).unwrap().len(), 12);
        assert_eq!(remove_point(&added, 99).unwrap()[..12], added[..12]);
        let two = vec![[0.0, 0.0], [1.0, 0.0]];
        assert_eq!(remove_point(&two, 0), Err(Refusal::TooFew));
        let full = vec![[0.0, 0.0]; MAX_EDIT_POINTS];
        assert_eq!(add_point(&full, [0.0, 0.0]), Err(Refusal::TooMany));
        assert_eq!(snap_to(-0.0001, GRID), 0.0);
        assert_eq!(num(snap_to(-0.0001, GRID)), "0");
        let spot = new_point_spot(&scene.x);
        assert!(spot[0].is_finite() && spot[1].is_finite());
    }

    #[test]
    fn rotation_keys_turn_and_scale_by_one_step() {
        let scene = default_scene();
        let truth = scene.truth();
        let texts = |to: [f64; 2]| rotation_texts(truth.t, to);
        let [(_, angle), (_, scale)] = texts(rotation_handle(&truth));
        let (angle, scale): (f64, f64) = (angle.parse().unwrap(), scale.parse().unwrap());
        let step = |d| {
            let [(_, a), (_, s)] = texts(rotation_key_target(&truth, d));
            (a.parse::<f64>().unwrap(), s.parse::<f64>().unwrap())
        };
        let close = |a: f64, b: f64| (a - b).abs() < 1e-9;
        let (a, s) = step((1.0, 0.0));
        assert!(close(a, angle + ANGLE_GRID) && close(s, scale), "{a} {s}");
        let (a, s) = step((-1.0, 0.0));
        assert!(close(a, angle - ANGLE_GRID) && close(s, scale), "{a} {s}");
        let (a, s) = step((0.0, 1.0));
        assert!(close(a, angle) && close(s, scale + DRAG_GRID), "{a} {s}");
        let (a, s) = step((0.0, -1.0));
        assert!(close(a, angle) && close(s, scale - DRAG_GRID), "{a} {s}");
    }

    #[test]
    fn keys_select_in_turn_and_step_on_the_drag_grid() {
        use Grab::{Point, Rotation, Translation};
        assert_eq!(next_selection(None, 12, true), Some(Point(0)));
        assert_eq!(next_selection(None, 12, false), Some(Rotation));
        assert_eq!(next_selection(Some(Point(2)), 12, true), Some(Point(3)));
        // After the last point: the translation handle, then the rotation handle, then round.
        assert_eq!(next_selection(Some(Point(11)), 12, true), Some(Translation));
        assert_eq!(next_selection(Some(Translation), 12, true), Some(Rotation));
        assert_eq!(next_selection(Some(Rotation), 12, true), Some(Point(0)));
        assert_eq!(next_selection(Some(Point(0)), 12, false), Some(Rotation));
        assert_eq!(
            next_selection(Some(Translation), 12, false),
            Some(Point(11))
        );
        assert_eq!(
            next_selection(Some(Point(20)), 12, true),
            Some(Point(0)),
            "out of range: none"
        );
        assert_eq!(next_selection(None, 0, true), Some(Translation));
        let scene = default_scene();
        let (i, at) = selected_point(&scene, Some(2)).unwrap();
        assert_eq!(i, 2);
        assert_eq!(at, editable(&scene.x)[2]);
        assert_eq!(selected_point(&scene, Some(12)), None);
        assert_eq!(selected_point(&scene, None), None);
        // The first step lands on the drag grid; from there each step is exactly 0.01, and
        // the text --x takes says so.
        let mut points = editable(&scene.x);
        points = move_point(&points, 2, key_step_target(points[2], (1.0, 0.0)));
        let on_grid = points[2];
        assert_eq!(
            on_grid,
            [snap_to(at[0] + 0.01, DRAG_GRID), snap_to(at[1], DRAG_GRID)]
        );
        for _ in 0..3 {
            points = move_point(&points, 2, key_step_target(points[2], (1.0, 0.0)));
        }
        points = move_point(&points, 2, key_step_target(points[2], (0.0, -1.0)));
        assert_eq!(
            points[2],
            [
                snap_to(on_grid[0] + 0.03, DRAG_GRID),
                snap_to(on_grid[1] - 0.01, DRAG_GRID)
            ]
        );
        let others = |v: &[[f64; 2]]| {
            let mut v = v.to_vec();
            v.remove(2);
            v
        };
        assert_eq!(others(&points), others(&editable(&scene.x)));
    }

    #[test]
    fn handles_set_the_truth_as_the_options_write_it() {
        let truth = Similarity::RECIPE;
        let h = rotation_handle(&truth);
        let back = rotation_texts(truth.t, h);
        assert_eq!(back[0], ("angle", "35".to_string()));
        assert_eq!(back[1], ("scale", "1.3".to_string()));
        assert_eq!(
            rotation_texts([0.0, 0.0], [-1.0, -0.0001])[0].1,
            "180",
            "angles stay in (-180, 180]"
        );
        assert_eq!(
            translation_texts([1.234, -5000.0]),
            [("tx", "1.23".to_string()), ("ty", "-1000".to_string())]
        );
    }

    #[test]
    fn frame_round_trips_and_hit_tests_find_points_then_handles() {
        let scene = default_scene();
        let size = (600.0, 400.0);
        let frame = Frame::fit(scene.bounds(), size, 30.0);
        assert!(frame.shows(scene.bounds(), size));
        let p = scene.x[5];
        let px = frame.px(p);
        let back = frame.world(px);
        assert!((back[0] - p[0]).abs() < 1e-12 && (back[1] - p[1]).abs() < 1e-12);
        assert_eq!(
            hit_test(&frame, &scene, px + DVec2::new(3.0, 0.0), 12.0),
            Some(Grab::Point(5))
        );
        let t = frame.px(scene.truth().t);
        let r = frame.px(rotation_handle(&scene.truth()));
        // The handles are hit where no point is nearer.
        if scene.x.iter().all(|q| frame.px(*q).distance(t) > 12.0) {
            assert_eq!(hit_test(&frame, &scene, t, 12.0), Some(Grab::Translation));
        }
        if scene.x.iter().all(|q| frame.px(*q).distance(r) > 12.0) {
            assert_eq!(hit_test(&frame, &scene, r, 12.0), Some(Grab::Rotation));
        }
        assert_eq!(
            hit_test(&frame, &scene, DVec2::new(-50.0, -50.0), 12.0),
            None
        );
        // y grows up.
        assert!(frame.px([0.0, 1.0]).y < frame.px([0.0, 0.0]).y);
        // The fitted frame stays; a point outside or a much smaller scene refits it.
        assert!(!frame.needs_refit(scene.bounds(), size));
        let (lo, hi) = scene.bounds();
        assert!(frame.needs_refit((lo, [hi[0] * 10.0, hi[1]]), size));
        let mid = [(lo[0] + hi[0]) / 2.0, (lo[1] + hi[1]) / 2.0];
        assert!(frame.needs_refit((mid, [mid[0] + 0.01, mid[1] + 0.01]), size));
    }

    #[test]
    fn the_url_keys_are_the_cli_arguments_and_restore_the_run() {
        let moved = move_point(&default_scene().x, 0, [2.0, 2.0]);
        let query: Vec<(String, String)> = vec![
            ("sigma".into(), "0.1".into()),
            ("angle".into(), "-20".into()),
            ("x".into(), points_text(&moved)),
            ("n".into(), "12".into()),
            ("step".into(), "3".into()),
            ("bogus".into(), "1".into()),
        ];
        let (texts, ignored) = read_texts(&INFO, &query, &["step"]);
        assert_eq!(ignored.len(), 1);
        let pairs = write_texts(&INFO, &texts);
        let keys: Vec<&str> = pairs.iter().map(|(k, _)| k.as_str()).collect();
        // n = 12 is the default: left out (the CLI then counts the points).
        assert_eq!(keys, ["sigma", "angle", "x"]);
        let fields = crate::view::form::recipe_fields(&INFO);
        let run = crate::view::command_line::RunArgs::new(INFO.id, &fields, &texts);
        let setup = setup_from_args(&Args::parse(&run.raw(), &ARGS, &OPTIONS).unwrap()).unwrap();
        assert_eq!(setup.points.as_deref(), Some(&moved[..]));
        assert_eq!(setup.truth.angle_deg, -20.0);
        let line = run.bsv_command();
        assert!(
            line.starts_with("bsv umeyama-2d 0.1 3 12 --angle -20 --x '"),
            "{line}"
        );
        let out = crate::recipes::run(INFO.id, &run.raw()).unwrap();
        assert!(out.file(POINTS_CSV).is_some());
    }

    #[test]
    fn labels_keep_clear_of_other_handles() {
        let p = DVec2::new(100.0, 100.0);
        let size = DVec2::new(20.0, 12.0);
        // Nothing near: up-right.
        assert_eq!(
            label_corner(p, size, 6.0, &[(p, 8.0)], 3.0),
            DVec2::new(106.0, 82.0)
        );
        // A handle up-right: up-left.
        let handle = (DVec2::new(115.0, 88.0), 6.0);
        let c = label_corner(p, size, 6.0, &[handle], 3.0);
        assert_eq!(c, DVec2::new(74.0, 82.0));
        // Handles above on both sides: down-right.
        let left = (DVec2::new(85.0, 88.0), 6.0);
        assert_eq!(
            label_corner(p, size, 6.0, &[handle, left], 3.0),
            DVec2::new(106.0, 106.0)
        );
    }

    #[test]
    fn grid_lines_are_counted_and_bounded() {
        assert_eq!(grid_multiples(-0.25, 1.0, 0.5), Some(-1..=2));
        assert_eq!(grid_multiples(0.0, 0.0, 0.5), Some(0..=0));
        // A huge sigma puts targets near ±1e308: no endless grid.
        assert_eq!(grid_multiples(-1e308, 1e308, 1.0), None);
        assert_eq!(grid_multiples(f64::NEG_INFINITY, 1.0, 0.5), None);
        assert_eq!(grid_multiples(0.0, 1.0, f64::NAN), None);
        assert_eq!(grid_multiples(0.0, 2000.0, 1.0), None);
    }
}
