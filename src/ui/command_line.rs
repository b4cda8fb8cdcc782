//! POSIX shell quoting for the command lines the pages show (`bsv …`, `python …`), so that a
//! copied line runs as written.

/// `text` as one POSIX shell word: as it is when it holds only plain characters, else in
/// single quotes (`''` for an empty word).
pub fn shell_word(text: &str) -> String {
    let plain = !text.is_empty()
        && text
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || "-_.,+/:=@%".contains(c));
    if plain {
        text.to_string()
    } else {
        format!("'{}'", text.replace('\'', r"'\''"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use wasm_bindgen_test::wasm_bindgen_test as test;

    #[test]
    fn quotes_only_what_needs_it() {
        assert_eq!(shell_word("0.12"), "0.12");
        assert_eq!(shell_word("0.2,0.4,-0.3"), "0.2,0.4,-0.3");
        assert_eq!(shell_word(""), "''");
        assert_eq!(shell_word("my traj.csv"), "'my traj.csv'");
        assert_eq!(shell_word("it's"), r"'it'\''s'");
    }
}
