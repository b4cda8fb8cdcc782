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

use super::{plan_of, CsvFile, Kernel, Plan, Progress, RecipeInfo, RecipeOutput};
use crate::args::{finite, in_range, parse_i64, parse_seed, ArgSpec, Args, Bound};
use crate::error::{RecipeError, RecipeWarning};
use crate::pyfmt::{fixed, CsvText};
use crate::rng::NumpyRng;
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

pub const INFO: RecipeInfo = RecipeInfo {
    id: "umeyama-2d",
    python: "umeyama_align_2d.py",
    args: &ARGS,
    flags: &[],
    writes: &[CSV],
    quirks_id: "recipe-umeyama-2d-quirks",
    plan: plan_of::<Entry>,
    page: None,
};

const CSV: &str = "umeyama_2d.csv";

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
    let n = x.len().min(y.len());
    if n == 0 {
        return Alignment::nan();
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
    for (p, q) in x.iter().zip(y) {
        let xc = Vector2::new(p[0], p[1]) - mu_x;
        let yc = Vector2::new(q[0], q[1]) - mu_y;
        sum_sq_x += xc[0] * xc[0] + xc[1] * xc[1];
        cov += yc * xc.transpose();
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
    let sum_sq_residual: f64 = x
        .iter()
        .zip(y)
        .map(|(p, q)| {
            let aligned = rotation * Vector2::new(p[0], p[1]) * scale + t;
            let r = aligned - Vector2::new(q[0], q[1]);
            r[0] * r[0] + r[1] * r[1]
        })
        .sum();
    Alignment {
        scale,
        rotation_deg: crate::math::atan2(rotation[(1, 0)], rotation[(0, 0)]).to_degrees(),
        tx: t[0],
        ty: t[1],
        rmse: (sum_sq_residual / count).sqrt(),
    }
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

/// The recipe's data: `X` and the noisy transformed `Y`, drawn in the recipe's order
/// (`params` is not validated here; [`run`] does that).
pub fn sample_points(params: &UmeyamaParams) -> (Vec<[f64; 2]>, Vec<[f64; 2]>) {
    let mut rng = NumpyRng::new(params.seed);
    let x: Vec<[f64; 2]> = (0..params.n)
        .map(|_| {
            let px = rng.normal(0.0, 1.0);
            let py = rng.normal(0.0, 1.0);
            [px, py]
        })
        .collect();
    let th = ROTATION_TRUE_DEG.to_radians();
    let (sin, cos) = crate::math::sincos(th);
    let y = x
        .iter()
        .map(|p| {
            let rotated = [cos * p[0] - sin * p[1], sin * p[0] + cos * p[1]];
            let noise_x = rng.normal(0.0, params.sigma);
            let noise_y = rng.normal(0.0, params.sigma);
            [
                SCALE_TRUE * rotated[0] + TRANSLATION_TRUE[0] + noise_x,
                SCALE_TRUE * rotated[1] + TRANSLATION_TRUE[1] + noise_y,
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
        SCALE_TRUE,
        ROTATION_TRUE_DEG.to_radians().to_degrees(),
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
    type Params = UmeyamaParams;

    fn params(args: &Args) -> Result<UmeyamaParams, RecipeError> {
        params_from_args(args)
    }

    fn plan(params: &UmeyamaParams, _args: &Args) -> Result<Plan, RecipeError> {
        Ok(Plan {
            rows: params.n as u64,
        })
    }

    fn run(
        params: &UmeyamaParams,
        _args: &Args,
        _progress: &mut Progress,
    ) -> Result<RecipeOutput, RecipeError> {
        let fit = run(params)?;
        Ok(output(&fit).with_warnings(warnings(params)))
    }
}

/// Parses `sigma seed n`, runs, and writes the recipe's output.
pub fn run_args(args: &Args) -> Result<RecipeOutput, RecipeError> {
    super::run_of::<Entry>(args)
}

#[cfg(test)]
mod tests {
    // The same tests run natively and, under `wasm-pack test --node`, as wasm.
    #[cfg(target_arch = "wasm32")]
    use wasm_bindgen_test::wasm_bindgen_test as test;

    use super::*;
    use crate::recipes::run_strs;

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
            assert!((fit.scale - SCALE_TRUE).abs() < 1e-12, "{fit:?}");
            assert!(
                (fit.rotation_deg - ROTATION_TRUE_DEG).abs() < 1e-12,
                "{fit:?}"
            );
            assert!((fit.tx - TRANSLATION_TRUE[0]).abs() < 1e-12, "{fit:?}");
            assert!((fit.ty - TRANSLATION_TRUE[1]).abs() < 1e-12, "{fit:?}");
            assert!(fit.rmse < 1e-12, "{fit:?}");
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
        let err = |v: &[&str]| run_strs(INFO.id, v).unwrap_err();
        assert!(matches!(err(&["-0.1"]), RecipeError::OutOfRange { .. }));
        assert!(matches!(err(&["inf"]), RecipeError::NotFinite { .. }));
        assert!(matches!(
            err(&["0.02", "-1"]),
            RecipeError::OutOfRange { .. }
        ));
        assert!(matches!(
            err(&["0.02", "3", "1"]),
            RecipeError::OutOfRange { .. }
        ));
        assert!(matches!(
            err(&["0.02", "3", "-5"]),
            RecipeError::OutOfRange { .. }
        ));
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
