//! Text helpers of the drills page: which explanation a recipe has (`drills-about-<id>`, and
//! `drills-quirk-<id>` for the quirks of the reference that the output reproduces on purpose),
//! numbers formatted for reading (`1,000,000`, `128 MiB`), and HTML escaping for markup built
//! from strings.

/// Recipes with a quirk note (`drills-quirk-<id>`): REFERENCE.md's "Quirks the reference has",
/// plus the two the kernels document (trapezoid's triangle branch, Umeyama's scale).
pub const QUIRKS: &[&str] = &[
    "pendulum-energy",
    "traj-resample",
    "dh-fk",
    "se3-relative",
    "rrt-2d",
    "manip-grid",
    "trapezoid-profile",
    "umeyama-2d",
];

/// Fluent id of "what it computes" for a recipe.
pub fn about_id(recipe: &str) -> String {
    format!("drills-about-{recipe}")
}

/// Fluent id of the quirk note of a recipe, if it has one.
pub fn quirk_id(recipe: &str) -> Option<String> {
    QUIRKS
        .contains(&recipe)
        .then(|| format!("drills-quirk-{recipe}"))
}

/// `1234567` → `"1,234,567"` (the grouping reads the same in English and Japanese).
pub fn group(n: u64) -> String {
    let digits = n.to_string();
    let mut out = String::with_capacity(digits.len() + digits.len() / 3);
    for (i, c) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i) % 3 == 0 {
            out.push(',');
        }
        out.push(c);
    }
    out
}

/// A limit for reading: whole numbers grouped (`1,000,000`), others in plain decimals
/// (`0.000001`), never in exponent form.
pub fn plain_number(x: f64) -> String {
    if x.fract() == 0.0 && x.abs() < 1e15 {
        let sign = if x < 0.0 { "-" } else { "" };
        format!("{sign}{}", group(x.abs() as u64))
    } else {
        format!("{x}")
    }
}

/// A size in bytes for reading: `512 bytes`-style counts stay exact below 1 KiB, then one
/// decimal in KiB / MiB / GiB (`1.5 KiB`, `128 MiB`).
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

/// Escapes `& < > " '` for HTML text and attribute values.
pub fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            c => out.push(c),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::i18n::{I18n, Lang};
    use crate::recipes::RECIPES;
    use wasm_bindgen_test::wasm_bindgen_test as test;

    #[test]
    fn numbers_read_plainly() {
        assert_eq!(group(0), "0");
        assert_eq!(group(999), "999");
        assert_eq!(group(1000), "1,000");
        assert_eq!(group(1_048_576), "1,048,576");
        assert_eq!(plain_number(1e6), "1,000,000");
        assert_eq!(plain_number(1e-6), "0.000001");
        assert_eq!(plain_number(-1000.0), "-1,000");
        assert_eq!(plain_number(0.5), "0.5");
        assert_eq!(size_text(100), "100 B");
        assert_eq!(size_text(1536), "1.5 KiB");
        assert_eq!(size_text(128 * 1024 * 1024), "128 MiB");
        assert_eq!(
            escape("<a href=\"x\">&'"),
            "&lt;a href=&quot;x&quot;&gt;&amp;&#39;"
        );
    }

    #[test]
    fn every_recipe_has_an_explanation_in_both_languages() {
        let i18n = I18n::new();
        for recipe in RECIPES {
            let id = recipe.info.id;
            let ids = std::iter::once(about_id(id)).chain(quirk_id(id));
            for msg in ids {
                for lang in Lang::ALL {
                    assert!(i18n.has_message(lang, &msg), "{lang:?}: {msg}");
                }
            }
        }
        for id in QUIRKS {
            assert!(crate::recipes::find(id).is_some(), "{id}");
        }
    }
}
