//! The table preview of a CSV file: its header and first rows (at most [`PREVIEW_ROWS`] rows
//! and [`PREVIEW_COLUMNS`] columns, so that a million-row file costs one scan for the row
//! count and nothing more), cells split as `csv.reader` does (quotes with `""` escapes); and
//! the rounded text of a cell ([`rounded`]) that tables show by default (downloads and the
//! "exact" view keep the CSV's text).

/// Data rows shown under the header.
pub const PREVIEW_ROWS: usize = 50;

/// Columns shown (a resampled trajectory may have many joints).
pub const PREVIEW_COLUMNS: usize = 12;

/// The first rows of a CSV and its size.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Preview {
    pub header: Vec<String>,
    pub rows: Vec<Vec<String>>,
    /// Data rows in the whole file.
    pub total_rows: usize,
    /// Columns of the header.
    pub total_columns: usize,
}

/// Where a `"` opens a quoted part of a cell.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Quotes {
    /// Only at the start of a cell, as `csv.reader` reads it (elsewhere it is text).
    AtCellStart,
    /// Anywhere (the plot's reader, which only needs the numbers).
    Anywhere,
}

/// Splits one CSV line into `out`'s cells: quoted parts may hold commas and `""` (one quote);
/// the quotes themselves are dropped.
pub fn split_cells(line: &str, quotes: Quotes, out: &mut Vec<String>) {
    out.clear();
    let mut cell = String::new();
    let mut quoted = false;
    let mut chars = line.chars().peekable();
    while let Some(c) = chars.next() {
        match (c, quoted) {
            ('"', true) if chars.peek() == Some(&'"') => {
                cell.push('"');
                chars.next();
            }
            ('"', true) => quoted = false,
            ('"', false) if cell.is_empty() || quotes == Quotes::Anywhere => quoted = true,
            (',', false) => out.push(std::mem::take(&mut cell)),
            (c, _) => cell.push(c),
        }
    }
    out.push(cell);
}

/// The cells of one CSV line, as `csv.reader` splits it.
fn cells(line: &str) -> Vec<String> {
    let mut out = Vec::new();
    split_cells(line, Quotes::AtCellStart, &mut out);
    out
}

/// The preview of CSV `text` (`\r\n` or `\n` line ends; the recipes' files have no line
/// breaks inside cells).
pub fn preview(text: &str) -> Preview {
    let mut lines = text.split('\n').map(|l| l.strip_suffix('\r').unwrap_or(l));
    let header = lines.next().map(cells).unwrap_or_default();
    let total_columns = header.len();
    let rows: Vec<Vec<String>> = lines
        .clone()
        .filter(|l| !l.is_empty())
        .take(PREVIEW_ROWS)
        .map(|l| {
            let mut row = cells(l);
            row.truncate(PREVIEW_COLUMNS);
            row
        })
        .collect();
    let total_rows = if rows.len() < PREVIEW_ROWS {
        rows.len()
    } else {
        count_rows(text)
    };
    let mut header = header;
    header.truncate(PREVIEW_COLUMNS);
    Preview {
        header,
        rows,
        total_rows,
        total_columns,
    }
}

/// Data rows of a CSV: non-empty lines after the header.
pub fn count_rows(text: &str) -> usize {
    text.split('\n')
        .filter(|l| !l.is_empty() && *l != "\r")
        .count()
        .saturating_sub(1)
}

/// Significant digits of a rounded cell.
pub const ROUNDED_DIGITS: usize = 6;

/// A cell as a table shows it by default: a number with more than [`ROUNDED_DIGITS`]
/// significant digits rounded to that many (trailing zeros dropped, the CSV's own notation
/// kept otherwise: `0.018000000000000002` → `0.018`, `1.0` stays `1.0`, `-3.1415926535` →
/// `-3.14159`, `1.23456789e-10` → `1.23457e-10`); anything else (words, `nan`, whole
/// numbers, short decimals) as it is, but a negative zero (`-0.0`, as Python writes it)
/// shown as `0.0`.
pub fn rounded(cell: &str) -> String {
    let text = cell.trim();
    let Ok(value) = text.parse::<f64>() else {
        return cell.to_string();
    };
    if !value.is_finite() || significant_digits(text) <= ROUNDED_DIGITS {
        return crate::numtext::unsigned_zero(cell.to_string());
    }
    let exponent = if value == 0.0 {
        0
    } else {
        value.abs().log10().floor() as i32
    };
    let exp_form = text.contains(['e', 'E']) || !(-5..15).contains(&exponent);
    if exp_form {
        let s = format!("{:.*e}", ROUNDED_DIGITS - 1, value);
        let (mantissa, exp) = s.split_once('e').unwrap_or((&s, "0"));
        return format!("{}e{exp}", trim_zeros(mantissa));
    }
    let decimals = (ROUNDED_DIGITS as i32 - 1 - exponent).max(0) as usize;
    let s = format!("{value:.decimals$}");
    let trimmed = trim_zeros(&s);
    if trimmed.contains('.') || !text.contains('.') {
        trimmed
    } else {
        // A decimal that rounds to a whole number keeps one decimal, as the CSV writes floats.
        format!("{trimmed}.0")
    }
}

/// Significant digits of a number's text (mantissa digits without leading zeros).
fn significant_digits(text: &str) -> usize {
    let mantissa = text.split(['e', 'E']).next().unwrap_or(text);
    let digits: String = mantissa.chars().filter(char::is_ascii_digit).collect();
    let digits = digits.trim_start_matches('0');
    let digits = if mantissa.contains('.') {
        digits
    } else {
        digits.trim_end_matches('0')
    };
    digits.len()
}

/// `"0.018000"` → `"0.018"`, `"2.000"` → `"2"`.
fn trim_zeros(s: &str) -> String {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s.to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn header_rows_and_counts() {
        let p = preview("t,r,y\r\n0.0,1.0,0.1\r\n0.05,1.0,0.2\r\n");
        assert_eq!(p.header, vec!["t", "r", "y"]);
        assert_eq!(p.rows.len(), 2);
        assert_eq!(p.rows[1], vec!["0.05", "1.0", "0.2"]);
        assert_eq!((p.total_rows, p.total_columns), (2, 3));
        let header_only = preview("x,y\r\n");
        assert_eq!((header_only.total_rows, header_only.rows.len()), (0, 0));
        let sample = preview(crate::recipes::traj_resample::SAMPLE);
        assert_eq!(sample.total_rows, 5);
        assert_eq!(sample.rows[0][3], "example-row");
        assert_eq!(
            cells(r#"a,"b,c","d""e",,"#),
            vec!["a", "b,c", "d\"e", "", ""]
        );
    }

    #[test]
    fn long_files_show_the_first_rows_and_count_all() {
        let mut text = String::from("i\r\n");
        for i in 0..1234 {
            text.push_str(&format!("{i}\r\n"));
        }
        let p = preview(&text);
        assert_eq!(p.rows.len(), PREVIEW_ROWS);
        assert_eq!(p.total_rows, 1234);
        assert_eq!(count_rows("a\nb\nc"), 2);
        assert_eq!(count_rows(""), 0);
        let wide = format!(
            "{}\r\n",
            (0..40)
                .map(|i| format!("q{i}"))
                .collect::<Vec<_>>()
                .join(",")
        );
        let p = preview(&wide);
        assert_eq!((p.header.len(), p.total_columns), (PREVIEW_COLUMNS, 40));
    }

    #[test]
    fn rounded_cells_read_like_a_person_writes_them() {
        for (cell, shown) in [
            ("0.018000000000000002", "0.018"),
            ("0.30000000000000004", "0.3"),
            ("-3.141592653589793", "-3.14159"),
            ("1.0", "1.0"),
            ("-0.0", "0.0"),
            ("-0.05", "-0.05"),
            ("0.05", "0.05"),
            ("800", "800"),
            ("123456789012", "123456789012"),
            ("1234.56789012", "1234.57"),
            ("0.9999999999999999", "1.0"),
            ("1.2345678901e-10", "1.23457e-10"),
            ("0.0000012345678901", "1.23457e-6"),
            ("nan", "nan"),
            ("example-row", "example-row"),
            ("", ""),
        ] {
            assert_eq!(rounded(cell), shown, "{cell}");
        }
        // Rounding never changes a value by more than half a unit of its sixth digit.
        for text in [
            "0.018000000000000002",
            "-3.141592653589793",
            "1234.56789012",
            "7.77777777e5",
        ] {
            let exact: f64 = text.parse().unwrap();
            let shown: f64 = rounded(text).parse().unwrap();
            assert!(
                (exact - shown).abs() <= exact.abs() * 5e-6,
                "{text} -> {shown}"
            );
        }
    }
}
