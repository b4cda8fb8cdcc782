//! Numbers as the app shows them to people (readouts, tables, labels, messages): fixed
//! decimals where a value that rounds to zero reads `0`, `0.0`, `0.000`, never `-0.0`.
//! Rust's `{:.N}` keeps the sign of a negative number however small (`-0.04` → `-0.0`), as
//! Python's `%.Nf` does; the files the app writes keep that (`crate::pyfmt`, which must match
//! the Python recipes byte for byte), what it shows does not.
//!
//! ```
//! use bsv_playground::numtext::{fixed, fixed_minus};
//! assert_eq!(fixed(-0.04, 1), "0.0");
//! assert_eq!(fixed(-0.06, 1), "-0.1");
//! assert_eq!(fixed_minus(-12.34, 1), "−12.3");
//! ```

/// The typeset minus sign (U+2212) some readouts write.
pub const MINUS: char = '\u{2212}';

/// `x` with `decimals` decimals, `-` for negatives; a value that rounds to zero has no sign.
pub fn fixed(x: f64, decimals: usize) -> String {
    unsigned_zero(format!("{x:.decimals$}"))
}

/// [`fixed`] with the typeset minus sign (U+2212) for negatives.
pub fn fixed_minus(x: f64, decimals: usize) -> String {
    typeset_minus(&fixed(x, decimals))
}

/// `text` (a number however written: `-0.000`, `−0`, `-0.0e0`) without its sign when all its
/// digits are zeros; any other text as it is.
pub fn unsigned_zero(text: String) -> String {
    let rest = text.strip_prefix('-').or_else(|| text.strip_prefix(MINUS));
    match rest {
        Some(rest) if is_zero(rest) => rest.to_string(),
        _ => text,
    }
}

/// Whether a number's text (no sign) is zero: only zeros and a point before any exponent.
fn is_zero(unsigned: &str) -> bool {
    let mantissa = unsigned.split(['e', 'E']).next().unwrap_or(unsigned);
    mantissa.bytes().any(|b| b == b'0') && mantissa.bytes().all(|b| b == b'0' || b == b'.')
}

/// Every `-` of `text` written as the typeset minus sign (U+2212).
pub fn typeset_minus(text: &str) -> String {
    text.replace('-', "\u{2212}")
}

#[cfg(test)]
mod tests {
    #[cfg(target_arch = "wasm32")]
    use wasm_bindgen_test::wasm_bindgen_test as test;

    use super::*;

    #[test]
    fn a_value_that_rounds_to_zero_has_no_sign() {
        assert_eq!(fixed(-0.04, 1), "0.0");
        assert_eq!(fixed(-0.0, 0), "0");
        assert_eq!(fixed(-0.0, 3), "0.000");
        assert_eq!(fixed(-0.0004, 3), "0.000");
        assert_eq!(fixed(-1e-300, 2), "0.00");
        assert_eq!(fixed_minus(-0.04, 1), "0.0");
        assert_eq!(fixed_minus(-0.0, 0), "0");
    }

    #[test]
    fn a_negative_value_keeps_its_sign() {
        assert_eq!(fixed(-0.06, 1), "-0.1");
        assert_eq!(fixed(-0.05, 1), "-0.1");
        assert_eq!(fixed(-100.0, 0), "-100");
        assert_eq!(fixed(0.04, 1), "0.0");
        assert_eq!(fixed_minus(-0.06, 1), "−0.1");
        assert_eq!(fixed_minus(-110.0, 1), "−110.0");
    }

    #[test]
    fn other_texts_lose_only_a_zero_sign() {
        assert_eq!(unsigned_zero("-0".into()), "0");
        assert_eq!(unsigned_zero("−0.00".into()), "0.00");
        assert_eq!(unsigned_zero("-0.0e0".into()), "0.0e0");
        assert_eq!(unsigned_zero("-1.0e-7".into()), "-1.0e-7");
        assert_eq!(unsigned_zero("-0.001".into()), "-0.001");
        assert_eq!(unsigned_zero("-".into()), "-");
        assert_eq!(unsigned_zero("-inf".into()), "-inf");
        assert_eq!(unsigned_zero("−".into()), "−");
    }

    #[test]
    fn the_files_keep_pythons_negative_zero() {
        // The CSV writer is Python's `%.Nf`, not this module's.
        assert_eq!(crate::pyfmt::fixed(-0.04, 1), "-0.0");
    }
}
