//! Pure helpers of the worker runs (`crate::ui::kit::worker`): the head of a file that comes
//! back as text for a preview while the whole file stays a `Blob`.

/// The first `lines` lines of `text`, with their line ends (all of a shorter text).
pub fn head(text: &str, lines: usize) -> &str {
    let mut end = 0;
    for _ in 0..lines {
        match text[end..].find('\n') {
            Some(i) => end += i + 1,
            None => return text,
        }
    }
    &text[..end]
}

/// Data rows of a CSV: non-empty lines after the header (the drills preview's count).
pub fn data_rows(text: &str) -> usize {
    text.split('\n')
        .filter(|l| !l.is_empty() && *l != "\r")
        .count()
        .saturating_sub(1)
}

#[cfg(test)]
mod tests {
    use super::{data_rows, head};

    #[test]
    fn data_rows_skip_the_header_and_blank_lines() {
        assert_eq!(data_rows("t,q\n0,1\n1,2\n"), 2);
        assert_eq!(data_rows("t,q\r\n0,1\r\n\r\n"), 1);
        assert_eq!(data_rows("t,q\n"), 0);
        assert_eq!(data_rows(""), 0);
    }

    #[test]
    fn head_keeps_the_first_lines_with_their_ends() {
        assert_eq!(head("a\nb\nc\n", 2), "a\nb\n");
        assert_eq!(head("a\nb\nc\n", 3), "a\nb\nc\n");
        assert_eq!(head("a\nb\nc", 5), "a\nb\nc");
        assert_eq!(head("", 5), "");
        assert_eq!(head("x\r\ny\r\n", 1), "x\r\n");
        assert_eq!(head("é,ü\n1,2\n", 1), "é,ü\n");
    }
}
