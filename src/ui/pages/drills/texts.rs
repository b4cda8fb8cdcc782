//! Text helpers of the drills page: the explanation of a recipe (`drills-about-<id>`) and
//! numbers formatted for reading (`1,000,000`, `128 MiB`).

/// Fluent id of "what it computes" for a recipe.
pub fn about_id(recipe: &str) -> String {
    format!("drills-about-{recipe}")
}

/// `1234567` → `"1,234,567"` (the grouping reads the same in English and Japanese).
pub fn group(n: u64) -> String {
    crate::pyfmt::group_u64(n)
}

pub use crate::pyfmt::size_text;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::i18n::{I18n, Lang};
    use crate::recipes::INFOS;
    use wasm_bindgen_test::wasm_bindgen_test as test;

    #[test]
    fn numbers_read_plainly() {
        assert_eq!(group(0), "0");
        assert_eq!(group(999), "999");
        assert_eq!(group(1000), "1,000");
        assert_eq!(group(1_048_576), "1,048,576");
        assert_eq!(size_text(100), "100 B");
        assert_eq!(size_text(1536), "1.5 KiB");
        assert_eq!(size_text(128 * 1024 * 1024), "128 MiB");
    }

    #[test]
    fn every_recipe_has_an_explanation_in_both_languages() {
        let i18n = I18n::new();
        for recipe in INFOS {
            let id = recipe.id;
            for msg in [about_id(id), recipe.quirks_id.to_string()] {
                for lang in Lang::ALL {
                    assert!(i18n.has_message(lang, &msg), "{lang:?}: {msg}");
                }
            }
        }
    }
}
