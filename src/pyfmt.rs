//! Numbers and CSV text exactly as the Python recipes write them.
//!
//! Python's `repr(float)` is the shortest string that round-trips, in fixed notation when the
//! decimal exponent is in `[-4, 16)` and scientific otherwise (`5e-05`, `1e+16`); integral values
//! keep `.0`. Rust's `{}` and `{:e}` give the same shortest digits, so only the layout differs.

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
    if x.is_nan() {
        return "nan".to_string();
    }
    if x.is_infinite() {
        return if x > 0.0 { "inf" } else { "-inf" }.to_string();
    }
    if x == 0.0 {
        return if x.is_sign_negative() { "-0.0" } else { "0.0" }.to_string();
    }
    let (digits, exp) = shortest_digits(x.abs());
    layout(x < 0.0, &digits, exp)
}

/// Shortest round-trip significant digits of `x > 0` and its decimal exponent, with ties
/// between two equally short candidates broken to the even last digit as Python's `repr`
/// (David Gay's dtoa) does; Rust's formatter breaks such exact ties upwards.
fn shortest_digits(x: f64) -> (String, i32) {
    let sci = format!("{x:e}");
    let (mantissa, exp) = split_sci(&sci);
    let digits: String = mantissa.chars().filter(char::is_ascii_digit).collect();
    let n = digits.len();
    // A tie: the exact value has exactly n + 1 significant digits, the last a 5. Cheap
    // filter first (n + 3 digits end in "500"), exact confirmation second.
    let probe = format!("{x:.prec$e}", prec = n + 2);
    let (probe_mantissa, probe_exp) = split_sci(&probe);
    let probe_digits: String = probe_mantissa
        .chars()
        .filter(char::is_ascii_digit)
        .collect();
    if !probe_digits.ends_with("500") {
        return (digits, exp);
    }
    let exact = format!("{x:.800e}");
    let (exact_mantissa, _) = split_sci(&exact);
    let exact_digits: String = exact_mantissa
        .chars()
        .filter(char::is_ascii_digit)
        .collect();
    let is_tie = exact_digits.as_bytes().get(n) == Some(&b'5')
        && exact_digits.bytes().skip(n + 1).all(|b| b == b'0');
    let low = &probe_digits[..n];
    let low_is_even = low.bytes().last().is_some_and(|d| (d - b'0') % 2 == 0);
    if is_tie && low_is_even {
        let trimmed = low.trim_end_matches('0');
        let trimmed = if trimmed.is_empty() { "0" } else { trimmed };
        return (trimmed.to_string(), probe_exp);
    }
    (digits, exp)
}

fn split_sci(s: &str) -> (&str, i32) {
    match s.split_once('e') {
        Some((m, e)) => (m, e.parse::<i32>().unwrap_or(0)),
        None => (s, 0),
    }
}

/// Python's layout of significant `digits` with decimal exponent `exp`: fixed notation for
/// `-4 <= exp < 16`, else `d.ddde±XX`.
fn layout(negative: bool, digits: &str, exp: i32) -> String {
    let mut out = String::with_capacity(digits.len() + 8);
    if negative {
        out.push('-');
    }
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
        if exp.unsigned_abs() < 10 {
            out.push('0');
        }
        out.push_str(&exp.unsigned_abs().to_string());
    }
    out
}

/// Python's `f"{x:.{digits}f}"`.
pub fn fixed(x: f64, digits: usize) -> String {
    if x.is_nan() {
        return "nan".to_string();
    }
    if x.is_infinite() {
        return if x > 0.0 { "inf" } else { "-inf" }.to_string();
    }
    format!("{x:.digits$}")
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
                Cell::Float(v) => self.text.push_str(&py_float(*v)),
                Cell::Int(v) => self.text.push_str(&v.to_string()),
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
            self.text.push_str(&py_float(*v));
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
            (577343969884.53125, "577343969884.5312"),
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
    }

    #[test]
    fn csv_quotes_only_when_needed() {
        let mut t = CsvText::with_header(&["a", "b"]);
        t.raw_row(["x,y", "say \"hi\""]);
        t.row(&[Cell::Int(3), Cell::Empty]);
        assert_eq!(t.finish(), "a,b\r\n\"x,y\",\"say \"\"hi\"\"\"\r\n3,\r\n");
    }
}
