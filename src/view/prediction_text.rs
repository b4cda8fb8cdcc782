//! The learner's typed prediction read as a number in the exercise's unit, and a value written
//! back with its unit, as an exercise shows them.
//!
//! Reading is forgiving about how a number is typed and strict about what it is: spaces
//! around it, full-width digits and signs (an IME's `０．５`), the typeset minus `−`, a
//! trailing unit (the exercise's own, or its ASCII spelling: `m2` for `m²`, `°` or `deg` for
//! degrees, `％` for `%`) and e-notation (`1e-3`) are taken; a comma is refused (a decimal
//! comma and a thousands separator read alike), as is anything that is not a finite number.

use crate::view::signal::sig;

/// The longest prediction read, in characters (a number with its unit is far shorter).
pub const MAX_CHARS: usize = 40;

/// Significant digits of a value shown beside a prediction.
pub const SHOWN_DIGITS: usize = 3;

/// Why a typed prediction is not a number.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PredictionError {
    /// Nothing typed.
    Empty,
    /// A comma in it.
    Comma,
    /// Not a finite number (letters, two points, `inf`, longer than [`MAX_CHARS`]).
    NotANumber,
}

impl PredictionError {
    /// The Fluent id of the message shown beside the field.
    pub fn message_id(self) -> &'static str {
        match self {
            PredictionError::Empty => "exercise-prediction-empty",
            PredictionError::Comma => "exercise-prediction-comma",
            PredictionError::NotANumber => "exercise-prediction-not-a-number",
        }
    }
}

/// A full-width or typeset character as its ASCII counterpart.
fn ascii(c: char) -> char {
    match c {
        '０'..='９' => char::from_digit(u32::from(c) - u32::from('０'), 10).unwrap_or(c),
        '．' | '。' => '.',
        '，' | '、' => ',',
        '－' | '−' | '–' => '-',
        '＋' => '+',
        'ｅ' | 'Ｅ' => 'e',
        '％' => '%',
        '\u{3000}' => ' ',
        _ => c,
    }
}

/// The spellings of `unit` a learner may type after the number.
fn unit_spellings(unit: &str) -> &'static [&'static str] {
    match unit {
        "m²" => &["m²", "m2", "m^2"],
        "deg" => &["°", "deg", "degrees", "度"],
        "%" => &["%"],
        "s" => &["s", "sec", "秒"],
        "m" => &["m"],
        "rad/s" => &["rad/s"],
        _ => &[],
    }
}

/// The prediction typed as `text`, in `unit` (see the module docs).
pub fn parse_prediction(text: &str, unit: &str) -> Result<f64, PredictionError> {
    if text.chars().count() > MAX_CHARS {
        return Err(PredictionError::NotANumber);
    }
    let normal: String = text.chars().map(ascii).collect();
    let mut body = normal.trim();
    if body.is_empty() {
        return Err(PredictionError::Empty);
    }
    for spelling in unit_spellings(unit) {
        if let Some(number) = body.strip_suffix(spelling) {
            body = number.trim_end();
            break;
        }
    }
    if body.contains(',') {
        return Err(PredictionError::Comma);
    }
    // Rust also reads `inf`, `NaN` and `infinity`: only digits, a point, signs and an
    // exponent make a prediction.
    let plain = body
        .chars()
        .all(|c| c.is_ascii_digit() || matches!(c, '.' | '+' | '-' | 'e' | 'E'));
    match body.parse::<f64>() {
        Ok(x) if plain && x.is_finite() => Ok(x),
        _ => Err(PredictionError::NotANumber),
    }
}

/// How `unit` is written after a number (`°` for degrees; nothing for a pure number).
pub fn unit_text(unit: &str) -> &str {
    match unit {
        "deg" => "°",
        other => other,
    }
}

/// `x` with [`SHOWN_DIGITS`] significant digits and its unit (`0.00151 %`, `90°`, `0.797`).
pub fn value_text(x: f64, unit: &str) -> String {
    let number = sig(x, SHOWN_DIGITS);
    match unit_text(unit) {
        "" => number,
        "°" => format!("{number}°"),
        shown => format!("{number} {shown}"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    #[cfg(target_family = "wasm")]
    use wasm_bindgen_test::wasm_bindgen_test as test;

    #[test]
    fn numbers_are_read_however_they_are_typed() {
        assert_eq!(parse_prediction("0.5", "%"), Ok(0.5));
        assert_eq!(parse_prediction("  1e-3 ", "m²"), Ok(0.001));
        assert_eq!(parse_prediction("０．００２", "%"), Ok(0.002));
        assert_eq!(parse_prediction("−12", "deg"), Ok(-12.0));
        assert_eq!(parse_prediction("90°", "deg"), Ok(90.0));
        assert_eq!(parse_prediction("90 deg", "deg"), Ok(90.0));
        assert_eq!(parse_prediction("0.0086 m2", "m²"), Ok(0.0086));
        assert_eq!(parse_prediction("5 ％", "%"), Ok(5.0));
        assert_eq!(parse_prediction("1.2秒", "s"), Ok(1.2));
        assert_eq!(parse_prediction(".5", ""), Ok(0.5));
        assert_eq!(parse_prediction("+2", ""), Ok(2.0));
    }

    #[test]
    fn what_is_not_a_finite_number_is_refused_without_a_panic() {
        assert_eq!(parse_prediction("", "s"), Err(PredictionError::Empty));
        assert_eq!(
            parse_prediction(" \u{3000}", "s"),
            Err(PredictionError::Empty)
        );
        assert_eq!(parse_prediction("0,5", "s"), Err(PredictionError::Comma));
        assert_eq!(parse_prediction("1,000", ""), Err(PredictionError::Comma));
        for bad in [
            "abc",
            "1.2.3",
            "inf",
            "-infinity",
            "NaN",
            "1e999",
            "--1",
            "e",
            "5 m",
            "0x10",
            "½",
            "1 2",
        ] {
            assert_eq!(
                parse_prediction(bad, "s"),
                Err(PredictionError::NotANumber),
                "{bad}"
            );
        }
        assert_eq!(
            parse_prediction(&"1".repeat(MAX_CHARS + 1), ""),
            Err(PredictionError::NotANumber)
        );
        // A unit is taken only as the exercise's.
        assert_eq!(
            parse_prediction("3 %", "s"),
            Err(PredictionError::NotANumber)
        );
    }

    #[test]
    fn values_are_written_with_three_digits_and_their_unit() {
        assert_eq!(value_text(0.0015066, "%"), "0.00151 %");
        assert_eq!(value_text(90.0, "deg"), "90.0°");
        assert_eq!(value_text(0.7967, ""), "0.797");
        assert_eq!(value_text(0.0086, "m²"), "0.00860 m²");
        assert_eq!(value_text(f64::NAN, "s"), "— s");
    }
}
