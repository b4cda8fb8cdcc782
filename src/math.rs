//! Elementary functions for the kernels: correctly rounded (pxfm, pure Rust ports of
//! CORE-MATH / LLVM libc), so that the CLI (native), Node and the browser (wasm) compute the
//! very same bits, and the same bits as Python's `math` / numpy on glibc in practically every
//! case (glibc's results are the correctly rounded ones but for rare exceptions).
//!
//! Rust's `f64::sin` & co. call the platform's libm: glibc natively but a port of musl's in
//! wasm, whose last bits differ (`0.2` in Python becomes `0.19999999999999998` in a browser).
//! Kernels therefore call these functions, never the `f64` methods. `sqrt` is exact in IEEE
//! arithmetic everywhere and stays `f64::sqrt`.

/// tan x, as sin x / cos x (within an ulp or two; for views, not for kernels' output).
#[inline]
pub fn tan(x: f64) -> f64 {
    let (s, c) = sincos(x);
    s / c
}

/// atan x, as atan2(x, 1).
#[inline]
pub fn atan(x: f64) -> f64 {
    atan2(x, 1.0)
}

/// sin x.
#[inline]
pub fn sin(x: f64) -> f64 {
    pxfm::f_sin(x)
}

/// cos x.
#[inline]
pub fn cos(x: f64) -> f64 {
    pxfm::f_cos(x)
}

/// (sin x, cos x).
#[inline]
pub fn sincos(x: f64) -> (f64, f64) {
    pxfm::f_sincos(x)
}

/// atan2(y, x).
#[inline]
pub fn atan2(y: f64, x: f64) -> f64 {
    pxfm::f_atan2(y, x)
}

/// acos x.
#[inline]
pub fn acos(x: f64) -> f64 {
    pxfm::f_acos(x)
}

/// asin x.
#[inline]
pub fn asin(x: f64) -> f64 {
    pxfm::f_asin(x)
}

/// e^x.
#[inline]
pub fn exp(x: f64) -> f64 {
    pxfm::f_exp(x)
}

/// Natural logarithm.
#[inline]
pub fn log(x: f64) -> f64 {
    pxfm::f_log(x)
}

/// ln(1 + x).
#[inline]
pub fn log1p(x: f64) -> f64 {
    pxfm::f_log1p(x)
}

/// sqrt(x² + y²) without overflow.
#[inline]
pub fn hypot(x: f64, y: f64) -> f64 {
    pxfm::f_hypot(x, y)
}

/// x^y (Python's `x ** y` for floats, which calls C `pow`). glibc's `pow(x, 2)` is off by one
/// ulp in rare cases; those values then differ from Python's in the last digit (well inside
/// the 1e-9 parity tolerance).
#[inline]
pub fn pow(x: f64, y: f64) -> f64 {
    pxfm::f_pow(x, y)
}

#[cfg(test)]
mod tests {
    // The same tests run natively and, under `wasm-pack test --node`, as wasm.
    #[cfg(target_arch = "wasm32")]
    use wasm_bindgen_test::wasm_bindgen_test as test;

    use super::*;

    #[test]
    fn correctly_rounded_where_musl_is_not() {
        // Values glibc (and so Python) prints; musl's port gets the last bit of some wrong.
        assert_eq!(atan2(0.19866933079506122, 0.9800665778412416), 0.2);
        assert_eq!(sin(0.5), 0.479425538604203);
        assert_eq!(cos(1.0), 0.5403023058681398);
        assert_eq!(sincos(0.3), (sin(0.3), cos(0.3)));
        assert_eq!(exp(1.0), std::f64::consts::E);
        assert_eq!(log(std::f64::consts::E), 1.0);
        assert_eq!(acos(-1.0), std::f64::consts::PI);
        assert_eq!(hypot(3.0, 4.0), 5.0);
        assert_eq!(pow(2.0, 0.5), std::f64::consts::SQRT_2);
    }
    #[test]
    fn pow_two_is_the_correctly_rounded_square() {
        // `pow(x, 2.0)` is correctly rounded, and so is one product: the two are the same
        // double (kernels may write `x * x` for `x ** 2`, bit for bit). Values of every
        // magnitude, subnormal to near overflow, from a fixed xorshift sequence.
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
        for _ in 0..2_000_000 {
            let bits = next();
            let x = f64::from_bits(bits & !(0x7ff << 52) | ((bits >> 52) % 1400 + 324) << 52);
            assert_eq!(pow(x, 2.0).to_bits(), (x * x).to_bits(), "x = {x:e}");
        }
        for k in 0..1_000_000u32 {
            let t = f64::from(k) * 2.5e-5;
            assert_eq!(pow(t, 2.0).to_bits(), (t * t).to_bits(), "t = {t}");
        }
        for x in [
            0.0,
            -0.0,
            5e-324,
            1e154,
            1.3407807929942596e154,
            f64::INFINITY,
        ] {
            assert_eq!(pow(x, 2.0).to_bits(), (x * x).to_bits(), "x = {x:e}");
        }
    }
}
