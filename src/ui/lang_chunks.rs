//! Each language's strings as a wasm chunk of its own: the app loads the visitor's language
//! before its first frame and the other one when the visitor switches (or in the background
//! once the first page is shown), so a first visit carries one language's text, not both.

#[cfg(feature = "split")]
use wasm_split_helpers::wasm_split;
use wasm_split_helpers::SplitLoaderError;

use crate::i18n::{self, Lang};
use crate::ui::ctx;

#[cfg(feature = "split")]
type Files = &'static [(&'static str, &'static str)];

/// The Fluent files of English (file name, text): what the `strings_en` chunk holds.
#[cfg(feature = "split")]
#[wasm_split(strings_en, fallible)]
fn strings_en() -> Result<Files, SplitLoaderError> {
    Ok(i18n::EN_FILES)
}

/// The Fluent files of Japanese: what the `strings_ja` chunk holds.
#[cfg(feature = "split")]
#[wasm_split(strings_ja, fallible)]
fn strings_ja() -> Result<Files, SplitLoaderError> {
    Ok(i18n::JA_FILES)
}

/// Loads `lang`'s strings into the app's bundles (at once if they are in).
pub async fn load(lang: Lang) -> Result<(), SplitLoaderError> {
    if ctx::has_lang(lang) {
        return Ok(());
    }
    #[cfg(feature = "split")]
    let files = match lang {
        Lang::En => strings_en().await?,
        Lang::Ja => strings_ja().await?,
    };
    // Without the `split` feature both languages are in the one wasm.
    #[cfg(not(feature = "split"))]
    let files = i18n::locale_files(lang);
    ctx::add_lang(lang, files);
    Ok(())
}
