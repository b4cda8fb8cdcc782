//! The table preview of a CSV file: its header and first rows (at most [`PREVIEW_ROWS`] rows
//! and [`PREVIEW_COLUMNS`] columns, so that a million-row file costs one scan for the row
//! count and nothing more), cells split as `csv.reader` does (quotes with `""` escapes).

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

/// Splits one CSV line into cells (quoted cells may hold commas and `""`).
fn cells(line: &str) -> Vec<String> {
    let mut out = Vec::new();
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
            ('"', false) if cell.is_empty() => quoted = true,
            (',', false) => out.push(std::mem::take(&mut cell)),
            (c, _) => cell.push(c),
        }
    }
    out.push(cell);
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

#[cfg(test)]
mod tests {
    use super::*;
    use wasm_bindgen_test::wasm_bindgen_test as test;

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
}
