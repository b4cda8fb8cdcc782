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

#[cfg(test)]
mod tests {
    use super::head;

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
