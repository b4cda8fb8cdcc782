//! What the app's JSON files (the lesson, the learner's progress) share when they are read:
//! the nesting check made before parsing, a value's kind for a message, the first field an
//! object should not have, and text from a file made short and printable for a message.

use serde_json::{Map, Value};

/// The line and column (from 1) of the first `[` or `{` nested deeper than `max_depth`
/// (brackets inside strings skipped); `None` when the text nests no deeper. Run before
/// parsing: serde_json's own limit of 128 levels would only say "syntax error".
pub fn too_deep_at(text: &str, max_depth: usize) -> Option<(usize, usize)> {
    let (mut depth, mut line, mut column) = (0usize, 1usize, 0usize);
    let (mut in_string, mut escaped) = (false, false);
    for c in text.chars() {
        if c == '\n' {
            line += 1;
            column = 0;
        } else {
            column += 1;
        }
        if in_string {
            match c {
                _ if escaped => escaped = false,
                '\\' => escaped = true,
                '"' => in_string = false,
                _ => {}
            }
            continue;
        }
        match c {
            '"' => in_string = true,
            '[' | '{' => {
                depth += 1;
                if depth > max_depth {
                    return Some((line, column));
                }
            }
            ']' | '}' => depth = depth.saturating_sub(1),
            _ => {}
        }
    }
    None
}

/// What a JSON value is, for a message's `kind` argument.
pub fn kind_of(value: &Value) -> &'static str {
    match value {
        Value::Array(_) => "array",
        Value::String(_) => "text",
        Value::Number(_) => "number",
        Value::Bool(_) => "boolean",
        Value::Null => "null",
        Value::Object(_) => "object",
    }
}

/// The first field of `object` (in key order) that is not among `known`.
pub fn unknown_field<'a>(object: &'a Map<String, Value>, known: &[&str]) -> Option<&'a String> {
    object.keys().find(|k| !known.contains(&k.as_str()))
}

/// Text from a file for a message: at most `max_chars` characters (then `…`), control
/// characters shown as `�`.
pub fn quoted(text: &str, max_chars: usize) -> String {
    let mut out: String = text
        .chars()
        .take(max_chars)
        .map(|c| if c.is_control() { '\u{fffd}' } else { c })
        .collect();
    if text.chars().nth(max_chars).is_some() {
        out.push('…');
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    #[cfg(target_family = "wasm")]
    use wasm_bindgen_test::wasm_bindgen_test as test;

    #[test]
    fn nesting_is_measured_outside_strings() {
        assert_eq!(too_deep_at("[[[]]]", 3), None);
        assert_eq!(too_deep_at("[\n [[[]]]]", 3), Some((2, 4)));
        assert_eq!(too_deep_at(r#"["[[[[\"[["]"#, 1), None);
    }

    #[test]
    fn quoted_text_is_short_and_printable() {
        assert_eq!(quoted("ab\u{0}c", 10), "ab\u{fffd}c");
        assert_eq!(quoted("abcdef", 3), "abc…");
        assert_eq!(quoted("abc", 3), "abc");
    }
}
