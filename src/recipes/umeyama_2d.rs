//! Recipe `umeyama-2d` (`umeyama_align_2d.py`): recover the similarity `Y ≈ s R X + t` of two
//! corresponded 2-D point sets with Umeyama's method.
//!
//! With means `mu_x`, `mu_y`, centred sets `Xc`, `Yc` and `n` points:
//! - `var_x = sum |Xc_i|^2 / n`, `C = Yc^T Xc / n` (2x2), `C = U diag(S) V^T` (in closed form,
//!   see [`umeyama`]);
//! - `R = U V^T`; if `det R < 0`, negate the last column of `U` and recompute `R`;
//! - `s = (S_1 + S_2) / var_x` (1 when `var_x <= 1e-12`); the recipe keeps the plain sum even
//!   after the reflection fix, where Umeyama would use `S_1 - S_2`;
//! - `t = mu_y - s R mu_x`, `rmse = sqrt(sum |s R X_i + t - Y_i|^2 / n)`,
//!   `angle = atan2(R_21, R_11)` in degrees.
//!
//! The recipe draws `X = normal(size=(n, 2))` (row-major: x0, y0, x1, ...) from
//! `default_rng(seed)`, then `Y = 1.3 R(35°) X + (0.4, -0.2) + normal(0, sigma, (n, 2))`.
//!
//! Options of this port (not the Python recipe's; without them the run is the recipe's, byte
//! for byte): `--scale`, `--angle` (degrees), `--tx`, `--ty` replace the true similarity,
//! `--mirror yes` mirrors X (`y -> -y`) before it (the fit then meets the reflection case),
//! and `--x "x,y;x,y;..."` gives the source points instead of the random ones (n is then their
//! count; the n argument is not used). The random
//! draws stay in the recipe's order (X's 2n normals are drawn and, with `--x`, set aside), so
//! point `i` gets the recipe's noise for point `i`. With any option set the run also writes
//! `umeyama_points.csv`: X, Y and the aligned points `s R X + t`, one row per point.

use super::info::RecipeInfo;
use super::kernel::{plan_of, Kernel, Progress, RunResult};
use super::output::{CsvFile, RecipeOutput};
use super::picture::{series, Mark, Picture, UnitFrame};
use crate::args::{finite, in_range, parse_i64, parse_seed, ArgKind, ArgSpec, Args, Bound};
use crate::error::{RecipeError, RecipeWarning};
use crate::pyfmt::{fixed, CsvText};
use crate::rng::NumpyRng;
use glam::DVec2;
use nalgebra::{Matrix2, Vector2};

/// The true scale of the recipe's transform.
pub const SCALE_TRUE: f64 = 1.3;
/// The true rotation of the recipe's transform, in degrees.
pub const ROTATION_TRUE_DEG: f64 = 35.0;
/// The true translation of the recipe's transform.
pub const TRANSLATION_TRUE: [f64; 2] = [0.4, -0.2];
/// Below this point variance the scale is taken as 1.
pub const MIN_VARIANCE: f64 = 1e-12;
/// Fewest points: two are the least that fix a similarity.
pub const MIN_POINTS: usize = 2;
/// Most points accepted (each costs four normal draws).
pub const MAX_POINTS: usize = 100_000;

/// Positional arguments of `umeyama_align_2d.py`.
pub const ARGS: [ArgSpec; 3] = [
    ArgSpec::number(
        "sigma",
        "0.02",
        "standard deviation of the noise added to Y (>= 0)",
    )
    .limits(Bound::Incl(0.0), Bound::None)
    .hint("recipe-umeyama-2d-hint-sigma"),
    ArgSpec::seed(
        "seed",
        "3",
        "RNG seed of np.random.default_rng, an integer in [0, 2^63)",
    )
    .hint("recipe-hint-seed"),
    ArgSpec::integer(
        "n",
        "12",
        "number of point pairs, 2 to 100000",
        MIN_POINTS as i64,
        MAX_POINTS as i64,
    )
    .hint("recipe-umeyama-2d-hint-n"),
];

/// `--scale S`: the true scale.
pub const FLAG_SCALE: ArgSpec =
    ArgSpec::number("scale", "1.3", "the true scale s of Y = s R X + t")
        .limits(Bound::Excl(0.0), Bound::Incl(1000.0))
        .hint("recipe-umeyama-2d-hint-scale");
/// `--angle DEG`: the true rotation, degrees.
pub const FLAG_ANGLE: ArgSpec = ArgSpec::number("angle", "35", "the true rotation angle")
    .unit("deg")
    .limits(Bound::Incl(-360.0), Bound::Incl(360.0))
    .hint("recipe-umeyama-2d-hint-angle");
/// `--tx X`: the true translation's x.
pub const FLAG_TX: ArgSpec = ArgSpec::number("tx", "0.4", "the true translation's x")
    .limits(Bound::Incl(-1000.0), Bound::Incl(1000.0))
    .hint("recipe-umeyama-2d-hint-t");
/// `--ty Y`: the true translation's y.
pub const FLAG_TY: ArgSpec = ArgSpec::number("ty", "-0.2", "the true translation's y")
    .limits(Bound::Incl(-1000.0), Bound::Incl(1000.0))
    .hint("recipe-umeyama-2d-hint-t");
/// `--mirror yes`: X mirrored (`y -> -y`) before the similarity.
pub const FLAG_MIRROR: ArgSpec = ArgSpec::number(
    "mirror",
    "no",
    "yes: mirror X (y -> -y) before the similarity, the reflection case of the fit",
)
.kind(ArgKind::Choice(&["no", "yes"]))
.hint("recipe-umeyama-2d-hint-mirror");
/// `--x "x,y;x,y;..."`: the source points.
pub const FLAG_X: ArgSpec = ArgSpec::number(
    "x",
    "",
    "the n source points x,y;x,y;... instead of the recipe's random ones",
)
.kind(ArgKind::Points)
.limits(Bound::Incl(-1000.0), Bound::Incl(1000.0))
.hint("recipe-umeyama-2d-hint-x");

/// Every option, in `bsv --help` and form order.
pub const OPTIONS: [ArgSpec; 6] = [
    FLAG_SCALE,
    FLAG_ANGLE,
    FLAG_TX,
    FLAG_TY,
    FLAG_MIRROR,
    FLAG_X,
];

pub const INFO: RecipeInfo = RecipeInfo {
    id: "umeyama-2d",
    python: "umeyama_align_2d.py",
    args: &ARGS,
    flags: &OPTIONS,
    writes: &[CSV, POINTS_CSV],
    quirks_id: "recipe-umeyama-2d-quirks",
    plan: plan_of::<Entry>,
    page: Some("umeyama-2d"),
};

const CSV: &str = "umeyama_2d.csv";
/// The points file a run with options writes too.
pub const POINTS_CSV: &str = "umeyama_points.csv";

/// A similarity estimate `Y ≈ s R(angle) X + t` and its fit error.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Alignment {
    /// `s`.
    pub scale: f64,
    /// Angle of `R`, `atan2(R_21, R_11)` in degrees, in (-180, 180].
    pub rotation_deg: f64,
    /// `t_x`.
    pub tx: f64,
    /// `t_y`.
    pub ty: f64,
    /// Root mean squared residual `sqrt(sum |s R X_i + t - Y_i|^2 / n)`.
    pub rmse: f64,
}

/// Umeyama's similarity alignment of corresponding points `x[i] -> y[i]`, as the recipe
/// computes it (see the module docs). Only the first `min(x.len(), y.len())` pairs are used;
/// with no pairs every field is NaN.
pub fn umeyama(x: &[[f64; 2]], y: &[[f64; 2]]) -> Alignment {
    umeyama_steps(x, y).map_or_else(Alignment::nan, |s| s.alignment())
}

/// Every intermediate of [`umeyama`], in the order it computes them (the page's stepper shows
/// them); [`UmeyamaSteps::alignment`] is [`umeyama`]'s result, bit for bit.
#[derive(Debug, Clone, PartialEq)]
pub struct UmeyamaSteps {
    /// The centroids `mu_x`, `mu_y`.
    pub mu_x: [f64; 2],
    pub mu_y: [f64; 2],
    /// The centred sets `Xc = X - mu_x`, `Yc = Y - mu_y`.
    pub centred_x: Vec<[f64; 2]>,
    pub centred_y: Vec<[f64; 2]>,
    /// `var_x = sum |Xc_i|^2 / n`.
    pub var_x: f64,
    /// `C = Yc^T Xc / n`, row-major.
    pub cov: [[f64; 2]; 2],
    /// `C = [[E+F, G-H], [G+H, E-F]]`: `(E, F, G, H)`.
    pub efgh: [f64; 4],
    /// `Q = |(E, H)|`, `R = |(F, G)|`: the singular values are `Q + R` and `|Q - R|`.
    pub q: f64,
    pub r: f64,
    /// `S_1 + S_2`, the recipe's numerator of the scale.
    pub singular_sum: f64,
    /// `R`, row-major: a rotation (after the reflection fix when `Q < R`).
    pub rotation: [[f64; 2]; 2],
    /// `s`.
    pub scale: f64,
    /// `t = mu_y - s R mu_x`.
    pub t: [f64; 2],
    /// `s R X_i + t`.
    pub aligned: Vec<[f64; 2]>,
    /// `sqrt(sum |s R X_i + t - Y_i|^2 / n)`.
    pub rmse: f64,
    /// `atan2(R_21, R_11)` in degrees.
    pub rotation_deg: f64,
}

impl UmeyamaSteps {
    /// Whether `U Vᵀ` of the SVD was a reflection (`det C < 0`, i.e. `Q < R`), which the
    /// recipe fixes by negating the last column of `U`.
    pub fn reflection_fixed(&self) -> bool {
        self.q < self.r
    }

    /// The estimate.
    pub fn alignment(&self) -> Alignment {
        Alignment {
            scale: self.scale,
            rotation_deg: self.rotation_deg,
            tx: self.t[0],
            ty: self.t[1],
            rmse: self.rmse,
        }
    }
}

/// [`umeyama`] with its intermediates (`None` without pairs).
pub fn umeyama_steps(x: &[[f64; 2]], y: &[[f64; 2]]) -> Option<UmeyamaSteps> {
    let n = x.len().min(y.len());
    if n == 0 {
        return None;
    }
    let (x, y) = (&x[..n], &y[..n]);
    let count = n as f64;
    let mean = |points: &[[f64; 2]]| {
        let sum = points
            .iter()
            .fold(Vector2::zeros(), |acc: Vector2<f64>, p| {
                acc + Vector2::new(p[0], p[1])
            });
        sum / count
    };
    let (mu_x, mu_y) = (mean(x), mean(y));
    let mut sum_sq_x = 0.0;
    let mut cov = Matrix2::zeros();
    let mut centred_x = Vec::with_capacity(n);
    let mut centred_y = Vec::with_capacity(n);
    for (p, q) in x.iter().zip(y) {
        let xc = Vector2::new(p[0], p[1]) - mu_x;
        let yc = Vector2::new(q[0], q[1]) - mu_y;
        sum_sq_x += xc[0] * xc[0] + xc[1] * xc[1];
        cov += yc * xc.transpose();
        centred_x.push([xc[0], xc[1]]);
        centred_y.push([yc[0], yc[1]]);
    }
    let var_x = sum_sq_x / count;
    cov /= count;

    // The 2×2 SVD in closed form, with crate::math so the browser and the CLI agree to the
    // bit: cov = [[E+F, G-H], [G+H, E-F]] = Q rot(atan2(H, E)) + R refl(atan2(G, F)) with
    // Q = |(E, H)|, R = |(F, G)|; its singular values are Q + R and |Q - R|. U Vᵀ is
    // rot(atan2(H, E)) when Q >= R; when Q < R it is a reflection, and the recipe's fix
    // (negate U's last column) turns it into the same rotation, the proper rotation nearest
    // to cov. The recipe's quirk stays: the scale uses the sum of both singular values.
    let (a, b, c, d) = (cov[(0, 0)], cov[(0, 1)], cov[(1, 0)], cov[(1, 1)]);
    let (e, f, g, h) = ((a + d) / 2.0, (a - d) / 2.0, (c + b) / 2.0, (c - b) / 2.0);
    let (q, r) = (crate::math::hypot(e, h), crate::math::hypot(f, g));
    let singular_sum = (q + r) + (q - r).abs();
    let (sin_a, cos_a) = crate::math::sincos(crate::math::atan2(h, e));
    let rotation = Matrix2::new(cos_a, -sin_a, sin_a, cos_a);
    let scale = if var_x > MIN_VARIANCE {
        singular_sum / var_x
    } else {
        1.0
    };
    let t = mu_y - (rotation * scale) * mu_x;
    let aligned: Vec<[f64; 2]> = x
        .iter()
        .map(|p| {
            let v = rotation * Vector2::new(p[0], p[1]) * scale + t;
            [v[0], v[1]]
        })
        .collect();
    let sum_sq_residual: f64 = aligned
        .iter()
        .zip(y)
        .map(|(v, q)| {
            let r = Vector2::new(v[0], v[1]) - Vector2::new(q[0], q[1]);
            r[0] * r[0] + r[1] * r[1]
        })
        .sum();
    Some(UmeyamaSteps {
        mu_x: [mu_x[0], mu_x[1]],
        mu_y: [mu_y[0], mu_y[1]],
        centred_x,
        centred_y,
        var_x,
        cov: [[a, b], [c, d]],
        efgh: [e, f, g, h],
        q,
        r,
        singular_sum,
        rotation: [
            [rotation[(0, 0)], rotation[(0, 1)]],
            [rotation[(1, 0)], rotation[(1, 1)]],
        ],
        scale,
        t: [t[0], t[1]],
        aligned,
        rmse: (sum_sq_residual / count).sqrt(),
        rotation_deg: crate::math::atan2(rotation[(1, 0)], rotation[(0, 0)]).to_degrees(),
    })
}

impl Alignment {
    fn nan() -> Alignment {
        Alignment {
            scale: f64::NAN,
            rotation_deg: f64::NAN,
            tx: f64::NAN,
            ty: f64::NAN,
            rmse: f64::NAN,
        }
    }
}

/// Parameters of the recipe run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct UmeyamaParams {
    /// Noise standard deviation, >= 0.
    pub sigma: f64,
    /// Seed of `np.random.default_rng`, in `[0, 2^63)`.
    pub seed: u64,
    /// Number of point pairs, in `[2, 100_000]`.
    pub n: usize,
}

impl Default for UmeyamaParams {
    fn default() -> Self {
        UmeyamaParams {
            sigma: 0.02,
            seed: 3,
            n: 12,
        }
    }
}

impl UmeyamaParams {
    /// Checks `sigma >= 0` (finite), the seed range and `2 <= n <= 100_000`.
    pub fn validate(&self) -> Result<(), RecipeError> {
        finite("sigma", self.sigma)?;
        in_range("sigma", self.sigma, 0.0, f64::INFINITY)?;
        crate::rng::check_seed("seed", self.seed)?;
        if self.n > MAX_POINTS {
            return Err(RecipeError::TooLarge {
                param: "n".to_string(),
                count: self.n as u64,
                limit: MAX_POINTS as u64,
                also: Vec::new(),
                square: false,
            });
        }
        if self.n < MIN_POINTS {
            return Err(n_out_of_range(self.n as f64));
        }
        Ok(())
    }
}

fn n_out_of_range(value: f64) -> RecipeError {
    RecipeError::OutOfRange {
        param: "n".to_string(),
        value,
        min: MIN_POINTS as f64,
        max: MAX_POINTS as f64,
    }
}

/// The true similarity `Y = s R(angle) M X + t` (`M` mirrors `y -> -y` when `mirror`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Similarity {
    pub scale: f64,
    pub angle_deg: f64,
    pub t: [f64; 2],
    pub mirror: bool,
}

impl Similarity {
    /// The recipe's: 1.3, 35°, (0.4, -0.2), no mirror.
    pub const RECIPE: Similarity = Similarity {
        scale: SCALE_TRUE,
        angle_deg: ROTATION_TRUE_DEG,
        t: TRANSLATION_TRUE,
        mirror: false,
    };

    /// Checks each value against its option's facts.
    pub fn validate(&self) -> Result<(), RecipeError> {
        FLAG_SCALE.check(self.scale)?;
        FLAG_ANGLE.check(self.angle_deg)?;
        FLAG_TX.check(self.t[0])?;
        FLAG_TY.check(self.t[1])?;
        Ok(())
    }
}

/// A run: the recipe's arguments, the true similarity and, when given, the source points.
#[derive(Debug, Clone, PartialEq)]
pub struct UmeyamaSetup {
    /// `sigma seed n` (`n` is the number of points when they are given).
    pub params: UmeyamaParams,
    pub truth: Similarity,
    /// The source points X (`--x`), or `None` for the recipe's random ones.
    pub points: Option<Vec<[f64; 2]>>,
}

impl Default for UmeyamaSetup {
    fn default() -> Self {
        UmeyamaSetup::recipe(UmeyamaParams::default())
    }
}

impl UmeyamaSetup {
    /// The recipe's run of `params`.
    pub fn recipe(params: UmeyamaParams) -> UmeyamaSetup {
        UmeyamaSetup {
            params,
            truth: Similarity::RECIPE,
            points: None,
        }
    }

    /// Whether this is the Python recipe's run (no option changes anything).
    pub fn is_recipe(&self) -> bool {
        self.points.is_none() && self.truth == Similarity::RECIPE
    }

    /// Checks the arguments, the similarity and that the points number `n`.
    pub fn validate(&self) -> Result<(), RecipeError> {
        self.params.validate()?;
        self.truth.validate()?;
        if let Some(points) = &self.points {
            check_point_count(points.len(), self.params.n)?;
            for p in points {
                for v in p {
                    FLAG_X.check(*v)?;
                }
            }
        }
        Ok(())
    }
}

fn check_point_count(count: usize, n: usize) -> Result<(), RecipeError> {
    if count != n {
        return Err(RecipeError::WrongCount {
            param: FLAG_X.name.to_string(),
            expected: 2 * n,
            got: 2 * count,
        });
    }
    Ok(())
}

/// The recipe's data: `X` and the noisy transformed `Y`, drawn in the recipe's order
/// (`params` is not validated here; [`run`] does that).
pub fn sample_points(params: &UmeyamaParams) -> (Vec<[f64; 2]>, Vec<[f64; 2]>) {
    sample_setup(&UmeyamaSetup::recipe(*params))
}

/// The data of a run: X (the given points, else the recipe's) and `Y = s R M X + t` plus the
/// recipe's noise, drawn in the recipe's order (not validated here).
pub fn sample_setup(setup: &UmeyamaSetup) -> (Vec<[f64; 2]>, Vec<[f64; 2]>) {
    let params = &setup.params;
    let mut rng = NumpyRng::new(params.seed);
    let drawn: Vec<[f64; 2]> = (0..params.n)
        .map(|_| {
            let px = rng.normal(0.0, 1.0);
            let py = rng.normal(0.0, 1.0);
            [px, py]
        })
        .collect();
    let x = match &setup.points {
        Some(points) => points.clone(),
        None => drawn,
    };
    let truth = &setup.truth;
    let th = truth.angle_deg.to_radians();
    let (sin, cos) = crate::math::sincos(th);
    let y = x
        .iter()
        .map(|p| {
            let p = if truth.mirror { [p[0], -p[1]] } else { *p };
            let rotated = [cos * p[0] - sin * p[1], sin * p[0] + cos * p[1]];
            let noise_x = rng.normal(0.0, params.sigma);
            let noise_y = rng.normal(0.0, params.sigma);
            [
                truth.scale * rotated[0] + truth.t[0] + noise_x,
                truth.scale * rotated[1] + truth.t[1] + noise_y,
            ]
        })
        .collect();
    (x, y)
}

/// Draws the recipe's points and aligns them.
pub fn run(params: &UmeyamaParams) -> Result<Alignment, RecipeError> {
    params.validate()?;
    let (x, y) = sample_points(params);
    Ok(umeyama(&x, &y))
}

/// The CSV and the summary line, exactly as the recipe writes them.
pub fn output(fit: &Alignment) -> RecipeOutput {
    output_of(fit, &Similarity::RECIPE)
}

fn output_of(fit: &Alignment, truth: &Similarity) -> RecipeOutput {
    let mut csv = CsvText::with_header(&[
        "scale",
        "rotation_deg",
        "tx",
        "ty",
        "rmse",
        "scale_true",
        "rotation_true_deg",
    ]);
    csv.floats(&[
        fit.scale,
        fit.rotation_deg,
        fit.tx,
        fit.ty,
        fit.rmse,
        truth.scale,
        truth.angle_deg.to_radians().to_degrees(),
    ]);
    RecipeOutput {
        files: vec![CsvFile {
            name: CSV.to_string(),
            text: csv.finish(),
        }],
        summary: format!(
            "Umeyama s={} ang={}deg rmse={} -> {CSV}",
            fixed(fit.scale, 4),
            fixed(fit.rotation_deg, 2),
            fixed(fit.rmse, 4)
        ),
        warnings: Vec::new(),
    }
}

/// `umeyama_points.csv`: per point X, Y and the aligned `s R X + t`.
pub fn points_csv(x: &[[f64; 2]], y: &[[f64; 2]], aligned: &[[f64; 2]]) -> String {
    let mut csv =
        CsvText::with_header(&["x", "y", "target_x", "target_y", "aligned_x", "aligned_y"]);
    for ((p, q), a) in x.iter().zip(y).zip(aligned) {
        csv.floats(&[p[0], p[1], q[0], q[1], a[0], a[1]]);
    }
    csv.finish()
}

/// The run of `setup`: the recipe's CSV and summary (its estimate, the true values), and with
/// any option `umeyama_points.csv` too.
pub fn run_setup(setup: &UmeyamaSetup) -> Result<RecipeOutput, RecipeError> {
    setup.validate()?;
    let (x, y) = sample_setup(setup);
    let steps = umeyama_steps(&x, &y);
    let fit = steps
        .as_ref()
        .map_or_else(Alignment::nan, UmeyamaSteps::alignment);
    let mut out = output_of(&fit, &setup.truth);
    if !setup.is_recipe() {
        let aligned = steps.map(|s| s.aligned).unwrap_or_default();
        out.files.push(CsvFile {
            name: POINTS_CSV.to_string(),
            text: points_csv(&x, &y, &aligned),
        });
    }
    Ok(out.with_warnings(warnings(&setup.params)))
}

/// Parses `sigma seed n` (any whole-number notation for the seed and n) and validates them.
pub fn params_from_args(args: &Args) -> Result<UmeyamaParams, RecipeError> {
    let [sigma_spec, seed_spec, n_spec] = &ARGS;
    let sigma = args.f64(0, sigma_spec)?;
    let seed = parse_seed(seed_spec.name, args.text(1, seed_spec))?;
    let n = match parse_i64(n_spec.name, args.text(2, n_spec)) {
        Ok(n) => n,
        Err(RecipeError::OutOfRange { value, .. }) => return Err(n_out_of_range(value)),
        Err(e) => return Err(e),
    };
    let n = usize::try_from(n).map_err(|_| n_out_of_range(n as f64))?;
    let params = UmeyamaParams { sigma, seed, n };
    params.validate()?;
    Ok(params)
}

/// Parses the arguments and the options and validates them: with `--x`, n is the number of
/// points given (the n argument is then not used, so a form can edit both one at a time).
pub fn setup_from_args(args: &Args) -> Result<UmeyamaSetup, RecipeError> {
    let points = FLAG_X.points(args.flag_text(&FLAG_X))?;
    let mut params = params_from_args(args)?;
    if !points.is_empty() {
        // n is the number of points given (the n argument is not used).
        if !(MIN_POINTS..=MAX_POINTS).contains(&points.len()) {
            return Err(RecipeError::OutOfRange {
                param: FLAG_X.name.to_string(),
                value: points.len() as f64,
                min: MIN_POINTS as f64,
                max: MAX_POINTS as f64,
            });
        }
        params.n = points.len();
    }
    let number = |spec: &ArgSpec| args.flag_f64(spec).and_then(|v| spec.check(v));
    let truth = Similarity {
        scale: number(&FLAG_SCALE)?,
        angle_deg: number(&FLAG_ANGLE)?,
        t: [number(&FLAG_TX)?, number(&FLAG_TY)?],
        mirror: {
            let text = args.flag_text(&FLAG_MIRROR);
            FLAG_MIRROR.check_text(text)?;
            text.trim().eq_ignore_ascii_case("yes")
        },
    };
    let points = (!points.is_empty()).then_some(points);
    let setup = UmeyamaSetup {
        params,
        truth,
        points,
    };
    setup.validate()?;
    Ok(setup)
}

/// What looks wrong with a fit: with two point pairs the similarity fits exactly whatever the
/// noise, so the rmse says nothing.
pub fn warnings(params: &UmeyamaParams) -> Vec<RecipeWarning> {
    if params.n <= MIN_POINTS && params.sigma > 0.0 {
        vec![RecipeWarning::FewPoints { n: params.n as u64 }]
    } else {
        Vec::new()
    }
}

/// The recipe's uniform entry ([`Kernel`]).
pub struct Entry;

impl Kernel for Entry {
    type Params = UmeyamaSetup;
    const INFO: &'static RecipeInfo = &INFO;

    fn params(args: &Args) -> Result<UmeyamaSetup, RecipeError> {
        setup_from_args(args)
    }

    fn rows(setup: &UmeyamaSetup, _args: &Args) -> Result<u64, RecipeError> {
        Ok(setup.params.n as u64)
    }

    fn run(setup: &UmeyamaSetup, _args: &Args, _progress: &mut Progress) -> RunResult {
        run_setup(setup)
    }
}

/// The home card's picture: the recipe's noisy targets Y and the aligned source points
/// s R X + t (its defaults), with residuals.
pub fn picture(_output: &RecipeOutput, aspect: f64) -> Option<Picture> {
    let params = UmeyamaParams::default();
    let (x, y) = sample_points(&params);
    let fit = umeyama(&x, &y);
    let (s, c) = fit.rotation_deg.to_radians().sin_cos();
    let aligned: Vec<DVec2> = x
        .iter()
        .map(|p| {
            DVec2::new(
                fit.scale * (c * p[0] - s * p[1]) + fit.tx,
                fit.scale * (s * p[0] + c * p[1]) + fit.ty,
            )
        })
        .collect();
    let source: Vec<DVec2> = x.iter().map(|p| DVec2::new(p[0], p[1])).collect();
    let target: Vec<DVec2> = y.iter().map(|p| DVec2::new(p[0], p[1])).collect();
    let frame = UnitFrame::fit(
        source.iter().chain(&target).chain(&aligned).copied(),
        Some(aspect),
    );
    let m = |v: &[DVec2]| v.iter().map(|p| frame.map(*p)).collect::<Vec<_>>();
    Some(Picture {
        marks: vec![
            Mark::Segments {
                series: series::GREY,
                pairs: target
                    .iter()
                    .zip(&aligned)
                    .map(|(a, b)| (frame.map(*a), frame.map(*b)))
                    .collect(),
            },
            Mark::Dots {
                series: series::GREY,
                points: m(&source),
            },
            Mark::Dots {
                series: series::ORANGE,
                points: m(&target),
            },
            Mark::Dots {
                series: series::BLUE,
                points: m(&aligned),
            },
        ],
    })
}

#[cfg(test)]
mod tests {
    #[cfg(target_arch = "wasm32")]
    use wasm_bindgen_test::wasm_bindgen_test as test;

    use super::*;
    use crate::recipes::testkit::run_strs;

    fn transform(x: &[[f64; 2]], scale: f64, angle_deg: f64, t: [f64; 2]) -> Vec<[f64; 2]> {
        let (sin, cos) = crate::math::sincos(angle_deg.to_radians());
        x.iter()
            .map(|p| {
                [
                    scale * (cos * p[0] - sin * p[1]) + t[0],
                    scale * (sin * p[0] + cos * p[1]) + t[1],
                ]
            })
            .collect()
    }

    /// Angle difference wrapped into (-180, 180].
    fn angle_error(a: f64, b: f64) -> f64 {
        let d = (a - b).rem_euclid(360.0);
        if d > 180.0 {
            d - 360.0
        } else {
            d
        }
    }

    fn assert_recovers(x: &[[f64; 2]], scale: f64, angle_deg: f64, t: [f64; 2]) {
        let y = transform(x, scale, angle_deg, t);
        let fit = umeyama(x, &y);
        let what = format!("s={scale} angle={angle_deg} t={t:?} n={}", x.len());
        assert_fit(&fit, scale, angle_deg, t, &what);
    }

    /// `fit` is the similarity (`scale`, `angle_deg`, `t`) with no residual, to 1e-12.
    fn assert_fit(fit: &Alignment, scale: f64, angle_deg: f64, t: [f64; 2], what: &str) {
        assert!((fit.scale - scale).abs() < 1e-12, "{what}: {fit:?}");
        assert!(
            angle_error(fit.rotation_deg, angle_deg).abs() < 1e-12,
            "{what}: {fit:?}"
        );
        assert!((fit.tx - t[0]).abs() < 1e-12, "{what}: {fit:?}");
        assert!((fit.ty - t[1]).abs() < 1e-12, "{what}: {fit:?}");
        assert!(fit.rmse < 1e-12, "{what}: {fit:?}");
    }

    #[test]
    fn default_run_matches_the_reference() {
        // tests/golden/umeyama_default: the Python recipe's output for 0.02 3 12.
        let fit = run(&UmeyamaParams::default()).unwrap();
        let want = [
            1.3012006103240168,
            34.89537285376068,
            0.3985602249870085,
            -0.19661898717730925,
            0.02822138270044215,
        ];
        let got = [fit.scale, fit.rotation_deg, fit.tx, fit.ty, fit.rmse];
        for (g, w) in got.iter().zip(want) {
            assert!((g - w).abs() <= 1e-13 * w.abs(), "{got:?}");
        }
        assert_eq!(
            output(&fit).summary,
            "Umeyama s=1.3012 ang=34.90deg rmse=0.0282 -> umeyama_2d.csv"
        );
    }

    #[test]
    fn noise_free_recipe_recovers_the_true_transform() {
        for (seed, n) in [(3, 12), (0, 2), (99, 1000)] {
            let fit = run(&UmeyamaParams {
                sigma: 0.0,
                seed,
                n,
            })
            .unwrap();
            let what = format!("seed {seed}, n {n}");
            assert_fit(&fit, SCALE_TRUE, ROTATION_TRUE_DEG, TRANSLATION_TRUE, &what);
        }
    }

    #[test]
    fn reflected_data_keeps_the_plain_singular_value_sum() {
        // Y = mirror image of X: the best rotation is forced (det R = +1) and the recipe's
        // scale is (S1 + S2) / var_x, not Umeyama's (S1 - S2) / var_x.
        let x = [[1.0, 0.0], [-1.0, 0.0], [0.0, 0.5], [0.0, -0.5]];
        let y: Vec<[f64; 2]> = x.iter().map(|p| [p[0], -p[1]]).collect();
        let fit = umeyama(&x, &y);
        // var_x = (1 + 1 + 0.25 + 0.25) / 4 = 0.625; C = diag(0.5, -0.125), S = (0.5, 0.125):
        // the recipe's s = 0.625 / 0.625 = 1 (Umeyama's would be 0.375 / 0.625 = 0.6).
        assert!((fit.scale - 1.0).abs() < 1e-15, "{fit:?}");
        assert!(fit.rotation_deg.abs() < 1e-12, "{fit:?}");
    }

    #[test]
    fn empty_input_gives_nan() {
        assert!(umeyama(&[], &[]).scale.is_nan());
    }

    #[test]
    fn rejects_bad_arguments() {
        let err = |v: &[&str]| run_strs::<Entry>(v).unwrap_err();
        let out_of_range = |v: &[&str]| matches!(err(v), RecipeError::OutOfRange { .. });
        assert!(out_of_range(&["-0.1"]));
        assert!(matches!(err(&["inf"]), RecipeError::NotFinite { .. }));
        assert!(out_of_range(&["0.02", "-1"]), "a negative seed");
        assert!(out_of_range(&["0.02", "3", "1"]), "one point");
        assert!(out_of_range(&["0.02", "3", "-5"]), "fewer than none");
        assert!(matches!(
            err(&["0.02", "3", "100001"]),
            RecipeError::TooLarge { .. }
        ));
        assert!(matches!(
            err(&["0.02", "3", "12.5"]),
            RecipeError::NotAnInteger { .. }
        ));
    }

    #[test]
    fn noise_free_similarity_grid_is_recovered() {
        // The same invariant as the proptest below, on a fixed grid that also runs in wasm.
        for seed in [0, 5, 1234] {
            for n in [2, 3, 40] {
                let x = sample_points(&UmeyamaParams {
                    sigma: 0.0,
                    seed,
                    n,
                })
                .0;
                for scale in [0.05, 1.0, 17.5] {
                    for angle_deg in [-179.0, -90.0, 0.0, 35.0, 135.0, 180.0] {
                        assert_recovers(&x, scale, angle_deg, [-3.5, 2.25]);
                    }
                }
            }
        }
    }

    #[test]
    fn options_at_their_defaults_are_the_recipe_byte_for_byte() {
        let recipe = run_strs::<Entry>(&["0.05", "9", "20"]).unwrap();
        let same = run_strs::<Entry>(&[
            "0.05", "9", "20", "--scale", "1.3", "--angle", "35.0", "--tx", "0.4", "--ty", "-0.2",
            "--mirror", "no",
        ])
        .unwrap();
        assert_eq!(recipe, same);
        assert_eq!(recipe.files.len(), 1);
    }

    #[test]
    fn given_points_get_the_recipes_noise_for_their_index() {
        let params = UmeyamaParams {
            sigma: 0.1,
            seed: 11,
            n: 5,
        };
        let (x, y) = sample_points(&params);
        // The recipe's own X given back with --x: the same Y, the same fit, bit for bit.
        let text: Vec<String> = x
            .iter()
            .map(|p| {
                format!(
                    "{},{}",
                    crate::pyfmt::py_float(p[0]),
                    crate::pyfmt::py_float(p[1])
                )
            })
            .collect();
        let args = Args::parse(
            &["0.1".into(), "11".into(), "--x".into(), text.join(";")],
            &ARGS,
            &OPTIONS,
        )
        .unwrap();
        let setup = setup_from_args(&args).unwrap();
        assert_eq!(setup.params, params);
        assert_eq!(setup.points.as_deref(), Some(&x[..]));
        assert!(!setup.is_recipe());
        let (x2, y2) = sample_setup(&setup);
        assert_eq!((&x2, &y2), (&x, &y));
        // Moving one point keeps every other point's noise.
        let mut moved = setup.clone();
        if let Some(points) = moved.points.as_mut() {
            points[2] = [3.0, -1.0];
        }
        let (_, y3) = sample_setup(&moved);
        for i in [0, 1, 3, 4] {
            assert_eq!(y3[i], y[i]);
        }
        let out = run_setup(&setup).unwrap();
        let recipe = run_strs::<Entry>(&["0.1", "11", "5"]).unwrap();
        assert_eq!(out.files[0], recipe.files[0]);
        let points = out.file(POINTS_CSV).unwrap();
        assert_eq!(points.lines().count(), 6);
        let steps = umeyama_steps(&x, &y).unwrap();
        let first = format!(
            "{},{},{},{},{},{}\r\n",
            crate::pyfmt::py_float(x[0][0]),
            crate::pyfmt::py_float(x[0][1]),
            crate::pyfmt::py_float(y[0][0]),
            crate::pyfmt::py_float(y[0][1]),
            crate::pyfmt::py_float(steps.aligned[0][0]),
            crate::pyfmt::py_float(steps.aligned[0][1]),
        );
        assert!(points.contains(&first), "{points}");
    }

    #[test]
    fn the_truth_options_move_y_and_the_csv_states_them() {
        let out = run_strs::<Entry>(&[
            "0", "3", "12", "--scale", "2", "--angle", "-90", "--tx", "1", "--ty", "2",
        ])
        .unwrap();
        let csv = out.file(CSV).unwrap();
        let row: Vec<f64> = csv
            .lines()
            .nth(1)
            .unwrap()
            .split(',')
            .map(|v| v.parse().unwrap())
            .collect();
        assert!((row[0] - 2.0).abs() < 1e-12, "{csv}");
        assert!((row[1] + 90.0).abs() < 1e-12, "{csv}");
        assert!(
            (row[2] - 1.0).abs() < 1e-12 && (row[3] - 2.0).abs() < 1e-12,
            "{csv}"
        );
        assert_eq!(&row[5..], &[2.0, -90.0]);
        assert!(out.file(POINTS_CSV).is_some());
    }

    #[test]
    fn a_mirrored_set_needs_the_reflection_fix() {
        let setup = UmeyamaSetup {
            truth: Similarity {
                mirror: true,
                ..Similarity::RECIPE
            },
            ..UmeyamaSetup::recipe(UmeyamaParams {
                sigma: 0.0,
                ..UmeyamaParams::default()
            })
        };
        let (x, y) = sample_setup(&setup);
        let steps = umeyama_steps(&x, &y).unwrap();
        assert!(steps.reflection_fixed(), "{steps:?}");
        let det = steps.cov[0][0] * steps.cov[1][1] - steps.cov[0][1] * steps.cov[1][0];
        assert!(det < 0.0);
        // R stays a rotation; the fit cannot undo a mirror, so the residual is large.
        let r = steps.rotation;
        assert!((r[0][0] * r[1][1] - r[0][1] * r[1][0] - 1.0).abs() < 1e-12);
        assert!(steps.rmse > 0.5, "{}", steps.rmse);
        // The recipe's run has no reflection.
        let (x, y) = sample_points(&UmeyamaParams::default());
        assert!(!umeyama_steps(&x, &y).unwrap().reflection_fixed());
    }

    #[test]
    fn bad_options_are_refused_naming_them() {
        let err = |v: &[&str]| run_strs::<Entry>(v).unwrap_err();
        assert!(matches!(
            err(&["--x", "0,0"]),
            RecipeError::OutOfRange { ref param, .. } if param == "x"
        ));
        assert!(matches!(
            err(&["--x", "0,0;1"]),
            RecipeError::WrongCount { ref param, expected: 2, got: 1 } if param == "x"
        ));
        assert!(matches!(
            err(&["--scale", "0"]),
            RecipeError::OutOfRange { ref param, .. } if param == "scale"
        ));
        assert!(matches!(
            err(&["--mirror", "maybe"]),
            RecipeError::BadChoice { .. }
        ));
        // n follows the points, given or not.
        for raw in [
            &["0.02", "3", "--x", "0,0;1,0;0,1"][..],
            &["0.02", "3", "7", "--x", "0,0;1,0;0,1"][..],
        ] {
            let out = run_strs::<Entry>(raw).unwrap();
            assert_eq!(out.file(POINTS_CSV).unwrap().lines().count(), 4);
        }
    }

    #[cfg(not(target_arch = "wasm32"))]
    mod properties {
        use super::*;
        use proptest::prelude::*;

        proptest! {
            #[test]
            fn noise_free_similarity_is_recovered(
                seed in 0u64..10_000,
                n in 2usize..60,
                scale in 0.05f64..20.0,
                angle_deg in -179.9f64..179.9,
                tx in -5.0f64..5.0,
                ty in -5.0f64..5.0,
            ) {
                let x = sample_points(&UmeyamaParams { sigma: 0.0, seed, n }).0;
                assert_recovers(&x, scale, angle_deg, [tx, ty]);
            }
        }
    }
}
