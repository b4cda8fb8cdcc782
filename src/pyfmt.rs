//! Numbers and CSV text exactly as the Python recipes write them.
//!
//! Python's `repr(float)` is the shortest string that round-trips, in fixed notation when the
//! decimal exponent is in `[-4, 16)` and scientific otherwise (`5e-05`, `1e+16`); integral values
//! keep `.0`. Rust's `{}` and `{:e}` give the same shortest digits, so only the layout differs.

/// A number as a person writes it, for messages and hints (not for CSV): whole numbers with
/// thousands separators (`1,000,000`), others in plain decimals without an exponent
/// (`0.000001`, `0.12`), `-` for negatives. 2^63 (i64's bound as f64) reads as i64::MAX.
///
/// # Example
/// ```
/// use bsv_playground::pyfmt::human;
/// assert_eq!(human(1e6), "1,000,000");
/// assert_eq!(human(1e-6), "0.000001");
/// assert_eq!(human(-0.05), "-0.05");
/// assert_eq!(human(1000000.0), "1,000,000");
/// assert_eq!(human(9.223372036854776e18), "9,223,372,036,854,775,807");
/// assert_eq!(human(1e-300), "1 × 10⁻³⁰⁰");
/// assert_eq!(human(-1.5e30), "-1.5 × 10³⁰");
/// ```
pub fn human(x: f64) -> String {
    if !x.is_finite() {
        return py_float(x);
    }
    let sign = if x < 0.0 { "-" } else { "" };
    let a = x.abs();
    if a == 9_223_372_036_854_775_808.0 {
        return format!("{sign}{}", group_digits(&i64::MAX.to_string()));
    }
    if a.fract() == 0.0 && a < 1e21 {
        return format!("{sign}{}", group_digits(&format!("{a:.0}")));
    }
    if !(1e-9..1e21).contains(&a) {
        // Tiny or huge: plain digits would be unreadable; "1.5 × 10⁻¹²" reads as written.
        return format!("{sign}{}", power_of_ten(a));
    }
    let text = format!("{a}");
    let (int, frac) = text.split_once('.').unwrap_or((&text, ""));
    let int = group_digits(int);
    if frac.is_empty() {
        format!("{sign}{int}")
    } else {
        format!("{sign}{int}.{frac}")
    }
}

/// `a` (positive, finite) as `m × 10ⁿ` with the shortest round-trip mantissa.
fn power_of_ten(a: f64) -> String {
    let text = format!("{a:e}");
    let (mantissa, exp) = text.split_once('e').unwrap_or((&text, "0"));
    let sup: String = exp
        .chars()
        .map(|c| match c {
            '-' => '⁻',
            '0' => '⁰',
            '1' => '¹',
            '2' => '²',
            '3' => '³',
            '4' => '⁴',
            '5' => '⁵',
            '6' => '⁶',
            '7' => '⁷',
            '8' => '⁸',
            '9' => '⁹',
            other => other,
        })
        .collect();
    format!("{mantissa} × 10{sup}")
}

/// A whole number with its digits in groups of three (`1048576` → `"1,048,576"`), as people
/// write counts in English and Japanese alike.
pub fn group_u64(n: u64) -> String {
    group_digits(&n.to_string())
}

/// A size in bytes for reading: counts stay exact below 1 KiB, then one decimal in KiB / MiB /
/// GiB, a trailing `.0` dropped.
///
/// ```
/// use bsv_playground::pyfmt::size_text;
/// assert_eq!(size_text(100), "100 B");
/// assert_eq!(size_text(1536), "1.5 KiB");
/// assert_eq!(size_text(50 << 20), "50 MiB");
/// ```
pub fn size_text(bytes: u64) -> String {
    const UNITS: [&str; 3] = ["KiB", "MiB", "GiB"];
    if bytes < 1024 {
        return format!("{bytes} B");
    }
    let mut value = bytes as f64 / 1024.0;
    let mut unit = 0;
    while value >= 1024.0 && unit + 1 < UNITS.len() {
        value /= 1024.0;
        unit += 1;
    }
    let text = format!("{value:.1}");
    let text = text.strip_suffix(".0").unwrap_or(&text);
    format!("{text} {}", UNITS[unit])
}

fn group_digits(digits: &str) -> String {
    let mut out = String::with_capacity(digits.len() + digits.len() / 3);
    for (i, c) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i) % 3 == 0 {
            out.push(',');
        }
        out.push(c);
    }
    out
}

/// `repr(x)` for a Python float.
///
/// # Example
/// ```
/// use bsv_playground::pyfmt::py_float;
/// assert_eq!(py_float(0.1), "0.1");
/// assert_eq!(py_float(5e-5), "5e-05");
/// assert_eq!(py_float(1.0), "1.0");
/// assert_eq!(py_float(-0.0), "-0.0");
/// assert_eq!(py_float(1e16), "1e+16");
/// assert_eq!(py_float(1.469576158976824e-18), "1.469576158976824e-18");
/// assert_eq!(py_float(f64::NAN), "nan");
/// ```
pub fn py_float(x: f64) -> String {
    let mut out = String::with_capacity(24);
    push_py_float(&mut out, x);
    out
}

/// Appends `nan`, `inf` or `-inf` (as Python writes them) when `x` is not finite; whether it
/// did.
fn push_non_finite(out: &mut String, x: f64) -> bool {
    if x.is_nan() {
        out.push_str("nan");
    } else if x.is_infinite() {
        out.push_str(if x > 0.0 { "inf" } else { "-inf" });
    }
    !x.is_finite()
}

/// Appends `repr(x)` to `out` without allocating (the CSV writers' hot path).
pub fn push_py_float(out: &mut String, x: f64) {
    if push_non_finite(out, x) {
        return;
    }
    if x == 0.0 {
        out.push_str(if x.is_sign_negative() { "-0.0" } else { "0.0" });
        return;
    }
    if x < 0.0 {
        out.push('-');
    }
    let mut buffer = ryu::Buffer::new();
    let (digits, exp) = shortest_digits(buffer.format_finite(x.abs()));
    layout(out, digits, exp);
}

/// Shortest round-trip significant digits and the decimal exponent, from Ryu's text of a
/// positive finite number (`d.ddd`, `d.ddde±X` or `0.000ddd`).
///
/// Ryu, like Python's `repr` (David Gay's dtoa), breaks an exact tie between two equally
/// short candidates to the even digit; Rust's own formatter breaks such ties upwards
/// (`577343969884.53125` → `…5313`, Python `…5312`), so it is not used here.
fn shortest_digits(text: &str) -> (Digits, i32) {
    let (mantissa, exp10) = match text.split_once('e') {
        Some((m, e)) => (m, e.parse::<i32>().unwrap_or(0)),
        None => (text, 0),
    };
    let mut digits = Digits::default();
    let mut int_len = 0i32;
    let mut seen_point = false;
    let mut leading_zeros = 0i32;
    for b in mantissa.bytes() {
        match b {
            b'.' => seen_point = true,
            b'0'..=b'9' => {
                if !seen_point {
                    int_len += 1;
                }
                if digits.len == 0 && b == b'0' {
                    leading_zeros += 1;
                } else {
                    digits.push(b);
                }
            }
            _ => {}
        }
    }
    while digits.len > 1 && digits.bytes[digits.len - 1] == b'0' {
        digits.len -= 1;
    }
    if digits.len == 0 {
        digits.push(b'0');
    }
    (digits, int_len - 1 - leading_zeros + exp10)
}

/// Up to 32 ASCII digits on the stack.
#[derive(Default)]
struct Digits {
    bytes: [u8; 32],
    len: usize,
}

impl Digits {
    fn push(&mut self, b: u8) {
        if self.len < self.bytes.len() {
            self.bytes[self.len] = b;
            self.len += 1;
        }
    }

    fn as_str(&self) -> &str {
        std::str::from_utf8(&self.bytes[..self.len]).unwrap_or("0")
    }
}

/// Python's layout of significant `digits` with decimal exponent `exp`: fixed notation for
/// `-4 <= exp < 16`, else `d.ddde±XX`.
fn layout(out: &mut String, digits: Digits, exp: i32) {
    let digits = digits.as_str();
    if (-4..16).contains(&exp) {
        if exp >= 0 {
            let int_len = exp as usize + 1;
            if digits.len() <= int_len {
                out.push_str(digits);
                out.extend(std::iter::repeat_n('0', int_len - digits.len()));
                out.push_str(".0");
            } else {
                out.push_str(&digits[..int_len]);
                out.push('.');
                out.push_str(&digits[int_len..]);
            }
        } else {
            out.push_str("0.");
            out.extend(std::iter::repeat_n('0', (-exp - 1) as usize));
            out.push_str(digits);
        }
    } else {
        out.push_str(&digits[..1]);
        if digits.len() > 1 {
            out.push('.');
            out.push_str(&digits[1..]);
        }
        out.push('e');
        out.push(if exp < 0 { '-' } else { '+' });
        let abs = exp.unsigned_abs();
        if abs < 10 {
            out.push('0');
        }
        let mut itoa = [0u8; 4];
        let mut n = 0;
        let mut v = abs;
        while v > 0 || n == 0 {
            itoa[n] = b'0' + (v % 10) as u8;
            v /= 10;
            n += 1;
        }
        for i in (0..n).rev() {
            out.push(itoa[i] as char);
        }
    }
}

/// Python's `f"{x:.{digits}f}"`.
pub fn fixed(x: f64, digits: usize) -> String {
    let mut out = String::with_capacity(24);
    push_fixed(&mut out, x, digits);
    out
}

/// Appends Python's `f"{x:.{digits}f}"`: correctly rounded (half to even on the exact binary
/// value), sign kept on negative values that round to zero.
///
/// Fast path, exact: for `|x * 10^digits| < 2^33` the product is within 1e-6 of the exact
/// scaled value, so rounding it to an integer is exact unless its fraction is within 2e-6 of
/// one half; those rare cases, and everything else, go through Rust's exact formatter.
pub fn push_fixed(out: &mut String, x: f64, digits: usize) {
    use std::fmt::Write;
    const POW10: [f64; 10] = [1.0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9];
    if push_non_finite(out, x) {
        return;
    }
    if let Some(&scale) = POW10.get(digits) {
        let scaled = (x * scale).abs();
        if scaled < 8_589_934_592.0 {
            let floor = scaled.floor();
            let frac = scaled - floor;
            if (frac - 0.5).abs() > 2e-6 {
                let n = (if frac > 0.5 { floor + 1.0 } else { floor }) as u64;
                if x.is_sign_negative() {
                    out.push('-');
                }
                let mut buf = [b'0'; 24];
                let mut len = 0;
                let mut v = n;
                while v > 0 || len <= digits {
                    buf[len] = b'0' + (v % 10) as u8;
                    v /= 10;
                    len += 1;
                }
                for i in (0..len).rev() {
                    out.push(buf[i] as char);
                    if i == digits && digits > 0 {
                        out.push('.');
                    }
                }
                return;
            }
        }
    }
    let _ = write!(out, "{x:.digits$}");
}

/// Python's `round(x, ndigits)` for a float: the exact binary value rounded half to even to
/// `ndigits` decimals, read back as the nearest double. Rust's fixed-precision formatting is
/// exact and rounds half to even, so formatting and parsing back is Python's algorithm.
///
/// ```
/// use bsv_playground::pyfmt::py_round;
/// assert_eq!(py_round(7.0 * 0.05, 4), 0.35); // 0.35000000000000003
/// assert_eq!(py_round(0.125, 2), 0.12); // an exact tie goes to even
/// assert_eq!(py_round(2.675, 2), 2.67); // 2.67499999...
/// ```
pub fn py_round(x: f64, ndigits: usize) -> f64 {
    if !x.is_finite() {
        return x;
    }
    fixed(x, ndigits).parse().unwrap_or(x)
}

/// One CSV cell: a float (`repr`), an integer, or empty.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Cell {
    Float(f64),
    Int(i64),
    Empty,
}

/// Builds CSV text the way Python's `csv.writer` does (`\r\n` line ends, quoting only when a
/// field needs it).
#[derive(Debug, Default, Clone)]
pub struct CsvText {
    text: String,
}

impl CsvText {
    /// Starts a table with its header row.
    pub fn with_header(header: &[&str]) -> Self {
        let mut out = CsvText::default();
        out.raw_row(header.iter().copied());
        out
    }

    /// Appends a row of already formatted fields.
    pub fn raw_row<'a>(&mut self, fields: impl IntoIterator<Item = &'a str>) {
        for (i, field) in fields.into_iter().enumerate() {
            if i > 0 {
                self.text.push(',');
            }
            push_field(&mut self.text, field);
        }
        self.text.push_str("\r\n");
    }

    /// Appends a row of cells.
    pub fn row(&mut self, cells: &[Cell]) {
        for (i, cell) in cells.iter().enumerate() {
            if i > 0 {
                self.text.push(',');
            }
            match cell {
                Cell::Float(v) => push_py_float(&mut self.text, *v),
                Cell::Int(v) => {
                    use std::fmt::Write;
                    let _ = write!(self.text, "{v}");
                }
                Cell::Empty => {}
            }
        }
        self.text.push_str("\r\n");
    }

    /// Appends a row of floats.
    pub fn floats(&mut self, values: &[f64]) {
        for (i, v) in values.iter().enumerate() {
            if i > 0 {
                self.text.push(',');
            }
            push_py_float(&mut self.text, *v);
        }
        self.text.push_str("\r\n");
    }

    /// The finished text.
    pub fn finish(self) -> String {
        self.text
    }
}

fn push_field(out: &mut String, field: &str) {
    if field.contains([',', '"', '\r', '\n']) {
        out.push('"');
        out.push_str(&field.replace('"', "\"\""));
        out.push('"');
    } else {
        out.push_str(field);
    }
}

#[cfg(test)]
mod tests {
    // The same tests run natively and, under `wasm-pack test --node`, as wasm.
    #[cfg(target_arch = "wasm32")]
    use wasm_bindgen_test::wasm_bindgen_test as test;

    use super::*;

    #[test]
    fn repr_layout_matches_python() {
        let cases = [
            (0.0001, "0.0001"),
            (0.00012, "0.00012"),
            (0.000012, "1.2e-05"),
            (123456789012345.6, "123456789012345.6"),
            (1e15, "1000000000000000.0"),
            (1.5e16, "1.5e+16"),
            (1e100, "1e+100"),
            (-2.5e-7, "-2.5e-07"),
            // An exact tie between two 16-digit candidates: Python picks the even one.
            (577343969884.0 + 17.0 / 32.0, "577343969884.5312"),
            (7.199999999999999, "7.199999999999999"),
            (-200.0, "-200.0"),
            (f64::INFINITY, "inf"),
        ];
        for (x, want) in cases {
            assert_eq!(py_float(x), want, "{x:e}");
        }
    }

    #[test]
    fn fixed_rounds_like_python() {
        assert_eq!(fixed(0.886669, 6), "0.886669");
        assert_eq!(fixed(-0.0, 4), "-0.0000");
        assert_eq!(fixed(2.675, 2), "2.67");
        assert_eq!(fixed(0.02, 6), "0.020000");
        assert_eq!(fixed(-1e-9, 6), "-0.000000");
        assert_eq!(fixed(0.125, 2), "0.12");
        assert_eq!(fixed(1.0000005, 6), "1.000001");
        assert_eq!(fixed(123.456, 0), "123");
        assert_eq!(fixed(-7.5, 0), "-8");
        assert_eq!(fixed(1e300, 2).len(), 304);
    }

    #[test]
    fn csv_quotes_only_when_needed() {
        let mut t = CsvText::with_header(&["a", "b"]);
        t.raw_row(["x,y", "say \"hi\""]);
        t.row(&[Cell::Int(3), Cell::Empty]);
        assert_eq!(t.finish(), "a,b\r\n\"x,y\",\"say \"\"hi\"\"\"\r\n3,\r\n");
    }
}
