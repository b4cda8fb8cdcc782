//! Planar two-link (2R) arm kinematics: FK, IK with both elbow branches, the Jacobian, its
//! determinant, Yoshikawa manipulability, singular values and the manipulability ellipse.
//!
//! With link lengths `L1`, `L2` and joint angles `q1`, `q2`:
//!
//! ```text
//! x = L1 cos q1 + L2 cos(q1 + q2)        J = [ -L1 s1 - L2 s12   -L2 s12 ]
//! y = L1 sin q1 + L2 sin(q1 + q2)            [  L1 c1 + L2 c12    L2 c12 ]
//! det J = L1 L2 sin q2                   w = sqrt(det(J Jᵀ)) = |det J|
//! ```
//!
//! IK: `c2 = (x² + y² − L1² − L2²) / (2 L1 L2)`, reachable when `|c2| ≤ 1`;
//! `q2 = ±acos(c2)`, `q1 = atan2(y, x) − atan2(L2 sin q2, L1 + L2 cos q2)`. The recipes' branch is
//! `q2 = +acos(c2)` ("elbow-down"); `q2 = −acos(c2)` is elbow-up.
//!
//! Determinants, `J Jᵀ` and singular values are computed as numpy does (LU with partial
//! pivoting and `exp(log|det|)`, OpenBLAS's fused product, LAPACK's Householder + `dlas2`), so
//! that recipe CSVs agree with `np.linalg.det` / `np.linalg.svd` to the last digits.

/// The elementary functions of the arm's geometry: [`Exact`] for everything a recipe, a
/// readout or an export computes; [`Fast`] for a drawing that needs no parity.
pub trait Trig {
    fn sin(x: f64) -> f64;
    fn cos(x: f64) -> f64;
    fn sincos(x: f64) -> (f64, f64);
    fn atan2(y: f64, x: f64) -> f64;
    fn acos(x: f64) -> f64;
    fn hypot(x: f64, y: f64) -> f64;
    fn ln(x: f64) -> f64;
    fn exp(x: f64) -> f64;
}

/// Correctly rounded ([`crate::math`]): the numbers of the recipes and numpy.
pub enum Exact {}

/// The platform's `f64` functions, within an ulp or two of [`Exact`] and much smaller in the
/// wasm: for the home page's arm, whose angles are shown to a tenth of a degree and exported
/// nowhere.
pub enum Fast {}

impl Trig for Exact {
    fn sin(x: f64) -> f64 {
        crate::math::sin(x)
    }
    fn cos(x: f64) -> f64 {
        crate::math::cos(x)
    }
    fn sincos(x: f64) -> (f64, f64) {
        crate::math::sincos(x)
    }
    fn atan2(y: f64, x: f64) -> f64 {
        crate::math::atan2(y, x)
    }
    fn acos(x: f64) -> f64 {
        crate::math::acos(x)
    }
    fn hypot(x: f64, y: f64) -> f64 {
        crate::math::hypot(x, y)
    }
    fn ln(x: f64) -> f64 {
        crate::math::log(x)
    }
    fn exp(x: f64) -> f64 {
        crate::math::exp(x)
    }
}

impl Trig for Fast {
    fn sin(x: f64) -> f64 {
        x.sin()
    }
    fn cos(x: f64) -> f64 {
        x.cos()
    }
    fn sincos(x: f64) -> (f64, f64) {
        x.sin_cos()
    }
    fn atan2(y: f64, x: f64) -> f64 {
        y.atan2(x)
    }
    fn acos(x: f64) -> f64 {
        x.acos()
    }
    fn hypot(x: f64, y: f64) -> f64 {
        x.hypot(y)
    }
    fn ln(x: f64) -> f64 {
        x.ln()
    }
    fn exp(x: f64) -> f64 {
        x.exp()
    }
}

/// Where the joints of an arm are: what drawing and hit-testing the arm need.
pub trait ArmShape {
    /// Elbow (joint 2) position.
    fn elbow(&self, q1: f64) -> (f64, f64);
    /// Tip position.
    fn fk(&self, q1: f64, q2: f64) -> (f64, f64);
}

impl ArmShape for Arm {
    fn elbow(&self, q1: f64) -> (f64, f64) {
        Arm::elbow(self, q1)
    }
    fn fk(&self, q1: f64, q2: f64) -> (f64, f64) {
        Arm::fk(self, q1, q2)
    }
}

/// An arm computed with [`Fast`] functions (the home page's drawing).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sketch(pub Arm);

impl ArmShape for Sketch {
    fn elbow(&self, q1: f64) -> (f64, f64) {
        self.0.elbow_in::<Fast>(q1)
    }
    fn fk(&self, q1: f64, q2: f64) -> (f64, f64) {
        self.0.fk_in::<Fast>(q1, q2)
    }
}

impl Sketch {
    /// [`Arm::ik`] with [`Fast`] functions.
    pub fn ik(&self, x: f64, y: f64, elbow: Elbow) -> Option<(f64, f64)> {
        self.0.ik_in::<Fast>(x, y, elbow)
    }

    /// [`Arm::clamp_to_reach`] with [`Fast`] functions.
    pub fn clamp_to_reach(&self, x: f64, y: f64) -> (f64, f64, bool) {
        self.0.clamp_to_reach_in::<Fast>(x, y)
    }
}

/// The numbers a page computes for one arm, with the functions of one [`Trig`], as a trait
/// object: a page can start on [`FAST`] and switch to [`EXACT`] once the code of the correctly
/// rounded functions is loaded, without holding that code itself.
pub trait Kinematics {
    /// [`Arm::fk`].
    fn fk(&self, arm: &Arm, q1: f64, q2: f64) -> (f64, f64);
    /// [`Arm::elbow`].
    fn elbow(&self, arm: &Arm, q1: f64) -> (f64, f64);
    /// [`Arm::ik`].
    fn ik(&self, arm: &Arm, x: f64, y: f64, elbow: Elbow) -> Option<(f64, f64)>;
    /// [`Arm::clamp_to_reach`].
    fn clamp_to_reach(&self, arm: &Arm, x: f64, y: f64) -> (f64, f64, bool);
    /// [`Arm::report`].
    fn report(&self, arm: &Arm, q1: f64, q2: f64) -> PoseReport;
    /// Whether these are the [`Exact`] functions.
    fn exact(&self) -> bool;
}

/// [`Kinematics`] with the functions of `T`.
pub struct KinematicsIn<T>(std::marker::PhantomData<T>);

impl<T: Trig + 'static> Kinematics for KinematicsIn<T> {
    fn fk(&self, arm: &Arm, q1: f64, q2: f64) -> (f64, f64) {
        arm.fk_in::<T>(q1, q2)
    }
    fn elbow(&self, arm: &Arm, q1: f64) -> (f64, f64) {
        arm.elbow_in::<T>(q1)
    }
    fn ik(&self, arm: &Arm, x: f64, y: f64, elbow: Elbow) -> Option<(f64, f64)> {
        arm.ik_in::<T>(x, y, elbow)
    }
    fn clamp_to_reach(&self, arm: &Arm, x: f64, y: f64) -> (f64, f64, bool) {
        arm.clamp_to_reach_in::<T>(x, y)
    }
    fn report(&self, arm: &Arm, q1: f64, q2: f64) -> PoseReport {
        arm.report_in::<T>(q1, q2)
    }
    fn exact(&self) -> bool {
        std::any::TypeId::of::<T>() == std::any::TypeId::of::<Exact>()
    }
}

/// The platform's functions: within an ulp or two of [`EXACT`].
pub const FAST: &dyn Kinematics = &KinematicsIn::<Fast>(std::marker::PhantomData);
/// The correctly rounded functions: the numbers of the recipes and numpy.
pub const EXACT: &dyn Kinematics = &KinematicsIn::<Exact>(std::marker::PhantomData);

/// Which of the two IK solutions to take.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Elbow {
    /// `q2 = +acos(c2)`: the recipes' branch.
    #[default]
    Down,
    /// `q2 = -acos(c2)`.
    Up,
}

impl Elbow {
    /// The other branch.
    pub fn flipped(self) -> Elbow {
        match self {
            Elbow::Down => Elbow::Up,
            Elbow::Up => Elbow::Down,
        }
    }
}

/// Link lengths in metres.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Arm {
    pub l1: f64,
    pub l2: f64,
}

/// A 2×2 matrix, row-major: `m[row][col]`.
pub type Mat2 = [[f64; 2]; 2];

/// The manipulability (velocity) ellipse at the tip: semi-axes are the singular values of J,
/// the major axis points along the first left singular vector.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ellipse {
    pub sigma_max: f64,
    pub sigma_min: f64,
    /// Angle of the major axis from +x, radians, in (-pi/2, pi/2].
    pub angle_rad: f64,
}

/// Everything the IK page shows for one pose.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PoseReport {
    pub q1: f64,
    pub q2: f64,
    pub x: f64,
    pub y: f64,
    pub jacobian: Mat2,
    pub det_j: f64,
    pub manipulability: f64,
    pub ellipse: Ellipse,
}

impl Arm {
    /// The arm of the recipes' defaults (0.12 m, 0.10 m).
    pub const DEFAULT: Arm = Arm { l1: 0.12, l2: 0.10 };

    /// Tip position.
    pub fn fk(&self, q1: f64, q2: f64) -> (f64, f64) {
        self.fk_in::<Exact>(q1, q2)
    }

    /// [`Arm::fk`] with the functions of `T`.
    pub fn fk_in<T: Trig>(&self, q1: f64, q2: f64) -> (f64, f64) {
        let (s1, c1) = T::sincos(q1);
        let (s12, c12) = T::sincos(q1 + q2);
        let x = self.l1 * c1 + self.l2 * c12;
        let y = self.l1 * s1 + self.l2 * s12;
        (x, y)
    }

    /// Elbow (joint 2) position.
    pub fn elbow(&self, q1: f64) -> (f64, f64) {
        self.elbow_in::<Exact>(q1)
    }

    /// [`Arm::elbow`] with the functions of `T`.
    pub fn elbow_in<T: Trig>(&self, q1: f64) -> (f64, f64) {
        (self.l1 * T::cos(q1), self.l1 * T::sin(q1))
    }

    /// Inner and outer radius of the reachable annulus.
    pub fn reach(&self) -> (f64, f64) {
        ((self.l1 - self.l2).abs(), self.l1 + self.l2)
    }

    /// IK for one branch, exactly as the recipe computes it; `None` outside the annulus
    /// (`|c2| > 1`).
    pub fn ik(&self, x: f64, y: f64, elbow: Elbow) -> Option<(f64, f64)> {
        self.ik_in::<Exact>(x, y, elbow)
    }

    /// [`Arm::ik`] with the functions of `T`.
    pub fn ik_in<T: Trig>(&self, x: f64, y: f64, elbow: Elbow) -> Option<(f64, f64)> {
        let (q2, beta) = self.ik_radial_in::<T>(x * x + y * y, elbow)?;
        Some((T::atan2(y, x) - beta, q2))
    }

    /// The part of [`Arm::ik`] that depends only on `r2 = x² + y²`: `(q2, beta)` with
    /// `q1 = atan2(y, x) - beta`, bit for bit as `ik` computes them (grids reuse it for cells
    /// with the same `r2`).
    pub fn ik_radial(&self, r2: f64, elbow: Elbow) -> Option<(f64, f64)> {
        self.ik_radial_in::<Exact>(r2, elbow)
    }

    fn ik_radial_in<T: Trig>(&self, r2: f64, elbow: Elbow) -> Option<(f64, f64)> {
        let (l1, l2) = (self.l1, self.l2);
        let c2 = (r2 - l1 * l1 - l2 * l2) / (2.0 * l1 * l2);
        if c2.abs() > 1.0 || c2.is_nan() {
            return None;
        }
        let mut q2 = T::acos(c2.clamp(-1.0, 1.0));
        if elbow == Elbow::Up {
            q2 = -q2;
        }
        let (sin_q2, cos_q2) = T::sincos(q2);
        Some((q2, T::atan2(l2 * sin_q2, l1 + l2 * cos_q2)))
    }

    /// The reachable point nearest to `(x, y)` and whether it had to move.
    pub fn clamp_to_reach(&self, x: f64, y: f64) -> (f64, f64, bool) {
        self.clamp_to_reach_in::<Exact>(x, y)
    }

    fn clamp_to_reach_in<T: Trig>(&self, x: f64, y: f64) -> (f64, f64, bool) {
        let (inner, outer) = self.reach();
        let r = T::hypot(x, y);
        // A hair inside the boundary, so that IK of the pinned point succeeds.
        let eps = 1e-12 * outer.max(1e-300);
        let target = if r > outer - eps {
            outer - eps
        } else if r < inner + eps {
            inner + eps
        } else {
            return (x, y, false);
        };
        let moved = r > outer || r < inner;
        if r < 1e-300 {
            return (target, 0.0, moved);
        }
        (x / r * target, y / r * target, moved)
    }

    /// Geometric Jacobian d(x, y)/d(q1, q2).
    pub fn jacobian(&self, q1: f64, q2: f64) -> Mat2 {
        self.jacobian_in::<Exact>(q1, q2)
    }

    /// [`Arm::jacobian`] with the functions of `T`.
    pub fn jacobian_in<T: Trig>(&self, q1: f64, q2: f64) -> Mat2 {
        let (s1, c1) = T::sincos(q1);
        let (s12, c12) = T::sincos(q1 + q2);
        [
            [-self.l1 * s1 - self.l2 * s12, -self.l2 * s12],
            [self.l1 * c1 + self.l2 * c12, self.l2 * c12],
        ]
    }

    /// All the numbers of one pose.
    pub fn report(&self, q1: f64, q2: f64) -> PoseReport {
        self.report_in::<Exact>(q1, q2)
    }

    /// [`Arm::report`] with the functions of `T`.
    pub fn report_in<T: Trig>(&self, q1: f64, q2: f64) -> PoseReport {
        let (x, y) = self.fk_in::<T>(q1, q2);
        let j = self.jacobian_in::<T>(q1, q2);
        PoseReport {
            q1,
            q2,
            x,
            y,
            jacobian: j,
            det_j: det_in::<T>(&j),
            manipulability: manipulability_in::<T>(&j),
            ellipse: ellipse_in::<T>(&j),
        }
    }

    /// `det J` as the manip-grid recipe writes it out by hand (not via LU).
    pub fn det_explicit(&self, q1: f64, q2: f64) -> f64 {
        let (l1, l2) = (self.l1, self.l2);
        let (s1, c1) = crate::math::sincos(q1);
        let (s12, c12) = crate::math::sincos(q1 + q2);
        (-l1 * s1 - l2 * s12) * (l2 * c12) - (-l2 * s12) * (l1 * c1 + l2 * c12)
    }
}

/// Determinant the way `np.linalg.det` gets it: LU with partial pivoting (LAPACK `getrf`,
/// row swap when `|m10| > |m00|`, the multiplier formed with the reciprocal of the pivot), then
/// numpy's `det = sign * exp(sum(log|u_ii|))` (numpy computes `det` from `slogdet`). A zero
/// pivot (singular matrix) gives `0.0`, as numpy does.
pub fn det(m: &Mat2) -> f64 {
    det_in::<Exact>(m)
}

/// [`det`] with the functions of `T`.
pub fn det_in<T: Trig>(m: &Mat2) -> f64 {
    let [[a, b], [c, d]] = *m;
    let (p, q, r, s, mut sign) = if c.abs() > a.abs() {
        (c, d, a, b, -1.0)
    } else {
        (a, b, c, d, 1.0)
    };
    if p == 0.0 {
        return 0.0;
    }
    // getf2 scales by the reciprocal unless the pivot is subnormal (then it divides).
    let l = if p.abs() >= f64::MIN_POSITIVE {
        r * (1.0 / p)
    } else {
        r / p
    };
    let u22 = s - l * q;
    if u22 == 0.0 {
        return 0.0;
    }
    let mut log_det = 0.0;
    for u in [p, u22] {
        if u < 0.0 {
            sign = -sign;
        }
        log_det += T::ln(u.abs());
    }
    sign * T::exp(log_det)
}

/// `J Jᵀ` as numpy's `J @ J.T` gets it (OpenBLAS `dgemm`: the first product, then the second
/// fused-multiply-added onto it), so the recipe CSV matches numpy digit for digit.
pub fn j_jt_numpy(j: &Mat2) -> Mat2 {
    let [[a, b], [c, d]] = *j;
    [
        [b.mul_add(b, a * a), b.mul_add(d, a * c)],
        [d.mul_add(b, c * a), d.mul_add(d, c * c)],
    ]
}

/// Yoshikawa manipulability `sqrt(max(0, det(J Jᵀ)))`, as the jacobian-2r recipe computes it
/// (numpy product and determinant; Python's `max(0.0, nan)` is `0.0`, as here).
pub fn manipulability(j: &Mat2) -> f64 {
    manipulability_in::<Exact>(j)
}

/// [`manipulability`] with the functions of `T`.
pub fn manipulability_in<T: Trig>(j: &Mat2) -> f64 {
    let d = det_in::<T>(&j_jt_numpy(j));
    if d > 0.0 {
        d.sqrt()
    } else {
        0.0
    }
}

/// Singular values `(sigma_min, sigma_max)` of a 2×2 matrix, as `np.linalg.svd(m,
/// compute_uv=False)` gets them: LAPACK `dgesdd` reduces `m` to upper bidiagonal form with one
/// Householder reflection (`dgebd2`), and the 2×2 bidiagonal's singular values come from `dlas2`.
/// (dgesdd's rescaling of matrices whose largest entry is below ~1e-138 or above ~1e138 is not
/// reproduced; no kinematic Jacobian of sane link lengths gets there.)
pub fn singular_values(m: &Mat2) -> (f64, f64) {
    let [[a11, a12], [a21, a22]] = *m;
    let (d1, e1, d2) = if a21 == 0.0 {
        (a11, a12, a22)
    } else {
        // dlarfg(2, a11, a21): H = I - tau v vᵀ with v = (1, v2) maps (a11, a21) to (beta, 0).
        let (beta, tau, v2) = householder(a11, a21);
        // dlarf: apply H to the second column, w = Cᵀ v, C -= tau v wᵀ.
        let w = a12 + a22 * v2;
        let t = -tau * w;
        (beta, a12 + t, a22 + v2 * t)
    };
    dlas2(d1, e1, d2)
}

/// LAPACK `dlarfg` for a 2-vector `(alpha, x)` with `x != 0`: `(beta, tau, v2)`.
fn householder(alpha: f64, x: f64) -> (f64, f64, f64) {
    // dlamch('S') / dlamch('E'): 2^-1022 / 2^-53.
    let safmin = f64::MIN_POSITIVE / (f64::EPSILON / 2.0);
    let (mut alpha, mut x) = (alpha, x);
    let mut beta = -lapy2(alpha, x.abs()).copysign(alpha);
    let mut rescaled = 0;
    if beta.abs() < safmin {
        // Scale up tiny vectors (at most 20 times), as dlarfg does.
        while beta.abs() < safmin && rescaled < 20 {
            rescaled += 1;
            x /= safmin;
            beta /= safmin;
            alpha /= safmin;
        }
        beta = -lapy2(alpha, x.abs()).copysign(alpha);
    }
    let tau = (beta - alpha) / beta;
    let v2 = x * (1.0 / (alpha - beta));
    for _ in 0..rescaled {
        beta *= safmin;
    }
    (beta, tau, v2)
}

/// LAPACK `dlapy2`: `sqrt(x² + y²)` as `w sqrt(1 + (z/w)²)`.
fn lapy2(x: f64, y: f64) -> f64 {
    let (xa, ya) = (x.abs(), y.abs());
    let w = xa.max(ya);
    let z = xa.min(ya);
    if z == 0.0 || w > f64::MAX {
        w
    } else {
        w * (1.0 + (z / w) * (z / w)).sqrt()
    }
}

/// LAPACK `dlas2`: singular values `(ssmin, ssmax)` of the upper triangular `[[f, g], [0, h]]`.
fn dlas2(f: f64, g: f64, h: f64) -> (f64, f64) {
    let (fa, ga, ha) = (f.abs(), g.abs(), h.abs());
    let fhmn = fa.min(ha);
    let fhmx = fa.max(ha);
    if fhmn == 0.0 {
        let ssmax = if fhmx == 0.0 {
            ga
        } else {
            let (big, small) = (fhmx.max(ga), fhmx.min(ga));
            big * (1.0 + (small / big) * (small / big)).sqrt()
        };
        (0.0, ssmax)
    } else if ga < fhmx {
        let at_s = 1.0 + fhmn / fhmx;
        let at_d = (fhmx - fhmn) / fhmx;
        let au = (ga / fhmx) * (ga / fhmx);
        let c = 2.0 / ((at_s * at_s + au).sqrt() + (at_d * at_d + au).sqrt());
        (fhmn * c, fhmx / c)
    } else {
        let au = fhmx / ga;
        if au == 0.0 {
            ((fhmn * fhmx) / ga, ga)
        } else {
            let at_s = 1.0 + fhmn / fhmx;
            let at_d = (fhmx - fhmn) / fhmx;
            let c = 1.0
                / ((1.0 + (at_s * au) * (at_s * au)).sqrt()
                    + (1.0 + (at_d * au) * (at_d * au)).sqrt());
            let ssmin = (fhmn * c) * au;
            (ssmin + ssmin, ga / (c + c))
        }
    }
}

/// The manipulability ellipse of `J`: singular values (as [`singular_values`]) and the major
/// axis direction.
pub fn ellipse(m: &Mat2) -> Ellipse {
    ellipse_in::<Exact>(m)
}

/// [`ellipse`] with the functions of `T`.
pub fn ellipse_in<T: Trig>(m: &Mat2) -> Ellipse {
    let (sigma_min, sigma_max) = singular_values(m);
    // Major axis: eigenvector of J Jᵀ for the larger eigenvalue.
    let [[p, pq], [_, s]] = j_jt_numpy(m);
    let angle_rad = 0.5 * T::atan2(2.0 * pq, p - s);
    Ellipse {
        sigma_max,
        sigma_min,
        angle_rad,
    }
}

/// Wraps an angle to (-pi, pi].
pub fn wrap_angle(q: f64) -> f64 {
    use std::f64::consts::PI;
    let w = (q + PI).rem_euclid(2.0 * PI) - PI;
    if w <= -PI {
        w + 2.0 * PI
    } else {
        w
    }
}

#[cfg(test)]
mod tests {
    // The same tests run natively and, under `wasm-pack test --node`, as wasm.
    #[cfg(target_arch = "wasm32")]
    use wasm_bindgen_test::wasm_bindgen_test as test;

    use super::*;

    #[test]
    fn the_sketch_follows_the_exact_arm_to_within_a_few_ulps() {
        let sketch = Sketch(Arm::DEFAULT);
        for i in 0..400 {
            let q1 = -3.1 + 0.0157 * i as f64;
            let q2 = 2.9 - 0.0141 * i as f64;
            let (x, y) = Arm::DEFAULT.fk(q1, q2);
            let (sx, sy) = sketch.fk(q1, q2);
            assert!(
                (x - sx).abs() < 1e-15 && (y - sy).abs() < 1e-15,
                "fk at {q1}, {q2}"
            );
            let (ex, ey) = ArmShape::elbow(&sketch, q1);
            assert!((ex - Arm::DEFAULT.elbow(q1).0).abs() < 1e-15);
            assert!((ey - Arm::DEFAULT.elbow(q1).1).abs() < 1e-15);
            for elbow in [Elbow::Down, Elbow::Up] {
                let exact = Arm::DEFAULT.ik(x, y, elbow);
                let fast = sketch.ik(x, y, elbow);
                match (exact, fast) {
                    (Some((a1, a2)), Some((b1, b2))) => {
                        assert!(
                            (a1 - b1).abs() < 1e-12 && (a2 - b2).abs() < 1e-12,
                            "ik at {x}, {y}"
                        );
                    }
                    (a, b) => assert_eq!(a.is_some(), b.is_some(), "ik at {x}, {y}"),
                }
            }
            let far = (3.0 * x, 3.0 * y);
            let (cx, cy, moved) = sketch.clamp_to_reach(far.0, far.1);
            let (ex2, ey2, exact_moved) = Arm::DEFAULT.clamp_to_reach(far.0, far.1);
            assert_eq!(moved, exact_moved);
            assert!((cx - ex2).abs() < 1e-15 && (cy - ey2).abs() < 1e-15);
        }
    }

    #[test]
    fn kinematics_objects_compute_the_arm_with_their_functions() {
        assert!(EXACT.exact() && !FAST.exact());
        let arm = Arm { l1: 0.3, l2: 0.17 };
        for i in 0..300 {
            let (q1, q2) = (-3.0 + 0.02 * i as f64, 2.8 - 0.019 * i as f64);
            // The exact object is the arm's own functions, bit for bit.
            assert_eq!(EXACT.report(&arm, q1, q2), arm.report(q1, q2));
            assert_eq!(EXACT.fk(&arm, q1, q2), arm.fk(q1, q2));
            assert_eq!(EXACT.elbow(&arm, q1), arm.elbow(q1));
            let (x, y) = arm.fk(q1, q2);
            for elbow in [Elbow::Down, Elbow::Up] {
                assert_eq!(EXACT.ik(&arm, x, y, elbow), arm.ik(x, y, elbow));
            }
            assert_eq!(
                EXACT.clamp_to_reach(&arm, 2.0 * x, 2.0 * y),
                arm.clamp_to_reach(2.0 * x, 2.0 * y)
            );
            // The platform's agree to well below what the readouts show (six digits).
            let (e, f) = (arm.report(q1, q2), FAST.report(&arm, q1, q2));
            let near = |a: f64, b: f64| (a - b).abs() <= 1e-12 * (1.0 + a.abs());
            assert!(near(e.x, f.x) && near(e.y, f.y), "fk at {q1}, {q2}");
            assert!(near(e.det_j, f.det_j), "det at {q1}, {q2}");
            assert!(near(e.manipulability, f.manipulability), "w at {q1}, {q2}");
            assert!(near(e.ellipse.sigma_max, f.ellipse.sigma_max));
            assert!(near(e.ellipse.sigma_min, f.ellipse.sigma_min));
            assert!((e.ellipse.angle_rad - f.ellipse.angle_rad).abs() < 1e-9);
            for r in 0..2 {
                for c in 0..2 {
                    assert!(near(e.jacobian[r][c], f.jacobian[r][c]));
                }
            }
        }
    }

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() <= 1e-12 + 1e-9 * b.abs()
    }

    #[test]
    fn ik_round_trips_both_branches() {
        let arm = Arm::DEFAULT;
        for &(x, y) in &[(0.15, 0.05), (-0.1, 0.12), (0.03, -0.2), (0.21, 0.0)] {
            for elbow in [Elbow::Down, Elbow::Up] {
                let (q1, q2) = arm.ik(x, y, elbow).unwrap();
                let (fx, fy) = arm.fk(q1, q2);
                assert!(close(fx, x) && close(fy, y), "{x} {y} {elbow:?}");
                assert_eq!(q2 >= 0.0, elbow == Elbow::Down);
            }
        }
        assert!(arm.ik(0.3, 0.0, Elbow::Down).is_none());
        assert!(arm.ik(0.0, 0.01, Elbow::Down).is_none());
    }

    #[test]
    fn jacobian_numbers() {
        let arm = Arm::DEFAULT;
        let rep = arm.report(0.0, 0.8);
        // golden/jacobian_default first row
        assert!(close(rep.det_j, 0.008608273090794276));
        assert!(close(rep.manipulability, 0.008608273090794276));
        assert!(close(rep.ellipse.sigma_min, 0.03864146032693336));
        assert!(close(rep.ellipse.sigma_max, 0.22277297539902366));
        assert!(close(rep.det_j, arm.l1 * arm.l2 * crate::math::sin(0.8f64)));
    }

    #[test]
    fn det_manipulability_and_svd_match_numpy_bit_for_bit() {
        // golden/jacobian_default rows q1 = 0.2 and 1.5 (q2 = 0.8): det_j, manipulability,
        // sigma_min, sigma_max exactly as numpy printed them.
        let arm = Arm::DEFAULT;
        let rows = [
            (
                0.2,
                [
                    0.008608273090794276,
                    0.008608273090794283,
                    0.038641460326933365,
                    0.22277297539902366,
                ],
            ),
            (
                1.5,
                [
                    0.008608273090794268,
                    0.008608273090794276,
                    0.038641460326933344,
                    0.2227729753990237,
                ],
            ),
        ];
        for (q1, want) in rows {
            let j = arm.jacobian(q1, 0.8);
            let (sigma_min, sigma_max) = singular_values(&j);
            assert_eq!(
                [det(&j), manipulability(&j), sigma_min, sigma_max],
                want,
                "q1={q1}"
            );
        }
    }

    #[test]
    fn det_and_svd_edge_cases() {
        assert_eq!(det(&[[0.0, 1.0], [0.0, 2.0]]), 0.0);
        assert_eq!(det(&[[1.0, 2.0], [2.0, 4.0]]), 0.0);
        assert_eq!(det(&[[0.0, 1.0], [1.0, 0.0]]), -1.0);
        assert!(close(det(&[[3.0, -1.0], [4.0, 2.0]]), 10.0));
        assert_eq!(singular_values(&[[0.0, 0.0], [0.0, 0.0]]), (0.0, 0.0));
        let (lo, hi) = singular_values(&[[0.0, -2.0], [3.0, 0.0]]);
        assert!(close(lo, 2.0) && close(hi, 3.0));
        // Tiny entries go through dlarfg's rescaling without under/overflow.
        // [[1, 0], [1, 1]] has singular values phi - 1 and phi.
        let phi = (1.0 + 5f64.sqrt()) / 2.0;
        let (lo, hi) = singular_values(&[[1e-300, 0.0], [1e-300, 1e-300]]);
        assert!(((lo / 1e-300) / (phi - 1.0) - 1.0).abs() < 1e-12, "{lo:e}");
        assert!(((hi / 1e-300) / phi - 1.0).abs() < 1e-12, "{hi:e}");
        assert_eq!(manipulability(&[[1.0, 2.0], [2.0, 4.0]]), 0.0);
    }

    #[test]
    fn ellipse_axis_is_the_stretched_direction() {
        let arm = Arm::DEFAULT;
        let j = arm.jacobian(0.4, 1.1);
        let e = ellipse(&j);
        // |Jᵀ u| = sigma_max for the unit vector u along the major axis.
        let (u0, u1) = (crate::math::cos(e.angle_rad), crate::math::sin(e.angle_rad));
        let jt_u = (j[0][0] * u0 + j[1][0] * u1, j[0][1] * u0 + j[1][1] * u1);
        assert!(close(crate::math::hypot(jt_u.0, jt_u.1), e.sigma_max));
    }

    #[test]
    fn clamp_pins_to_annulus() {
        let arm = Arm::DEFAULT;
        let (x, y, moved) = arm.clamp_to_reach(1.0, 0.0);
        assert!(moved && arm.ik(x, y, Elbow::Down).is_some());
        let (x, y, moved) = arm.clamp_to_reach(0.0, 0.001);
        assert!(moved && arm.ik(x, y, Elbow::Up).is_some());
        assert_eq!(arm.clamp_to_reach(0.1, 0.1), (0.1, 0.1, false));
        let (x, y, _) = arm.clamp_to_reach(0.0, 0.0);
        assert!(arm.ik(x, y, Elbow::Down).is_some());
    }

    #[test]
    fn wraps() {
        use std::f64::consts::PI;
        assert!(close(wrap_angle(3.0 * PI / 2.0), -PI / 2.0));
        assert!(close(wrap_angle(-PI), PI));
    }
}
