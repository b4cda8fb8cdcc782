//! The Fluent files of a language, loaded as they are needed: the files every page needs
//! ([`i18n::FIRST_FILES`]) and the page's own (its `page!` line) before the page is shown,
//! and, once it is, the page's files in the other language (parsed in idle time). The app fetches them beside itself,
//! `locales/<lang>/<file>`: the files of `locales/`, byte for byte (`scripts/build-dist.sh`
//! copies them; `www/boot.js` preloads the visitor's). A build without the `split` feature
//! (tests, Node) has every file of both languages in its wasm.

use wasm_bindgen::JsValue;

use crate::i18n::{self, Lang};
use crate::ui::ctx;

/// The files every page needs, and `page_files` (a page's own), of `lang`: loaded at once if
/// they are in, else fetched together.
pub async fn load(lang: Lang, page_files: &[&str]) -> Result<(), JsValue> {
    let wanted: Vec<&str> = i18n::FIRST_FILES
        .iter()
        .chain(page_files)
        .copied()
        .filter(|file| !ctx::has_file(lang, file))
        .collect();
    if wanted.is_empty() {
        return Ok(());
    }
    add(lang, &wanted).await
}

/// Parses `lang`'s loaded files that are not parsed yet, a piece (a few KB) per task, so that
/// no task parses much and the page that follows builds with its strings ready. A message asked
/// for meanwhile parses what is left at once (the bundle never misses a file).
pub async fn parse_in_tasks(lang: Lang) {
    while ctx::build_next_piece(lang) {
        crate::ui::schedule::yield_now().await;
    }
}

/// Without the `split` feature every file is in the wasm.
#[cfg(not(feature = "split"))]
async fn add(lang: Lang, _files: &[&str]) -> Result<(), JsValue> {
    ctx::add_files(lang, i18n::locale_files(lang));
    Ok(())
}

/// Fetches `files` of `lang` together and adds them once all have come. A file `www/boot.js`
/// asked for already (its response's promise in `window.bsvTexts`, by URL) is taken from
/// there, once.
#[cfg(feature = "split")]
async fn add(lang: Lang, files: &[&str]) -> Result<(), JsValue> {
    use wasm_bindgen::JsCast;
    use wasm_bindgen_futures::JsFuture;

    let window = web_sys::window().ok_or_else(|| JsValue::from_str("no window"))?;
    let requests: Vec<(&str, js_sys::Promise)> = files
        .iter()
        .map(|file| {
            let url = format!("locales/{}/{file}", lang.code());
            let asked = js_sys::Reflect::get(&window, &"bsvTexts".into())
                .ok()
                .filter(JsValue::is_object)
                .and_then(|texts| {
                    let key = JsValue::from_str(&url);
                    let asked = js_sys::Reflect::get(&texts, &key).ok()?.dyn_into().ok()?;
                    js_sys::Reflect::delete_property(texts.unchecked_ref::<js_sys::Object>(), &key)
                        .ok()?;
                    Some(asked)
                });
            (*file, asked.unwrap_or_else(|| window.fetch_with_str(&url)))
        })
        .collect();
    let mut texts = Vec::with_capacity(requests.len());
    for (file, request) in requests {
        let response: web_sys::Response = JsFuture::from(request).await?.dyn_into()?;
        if !response.ok() {
            return Err(JsValue::from_str(&format!(
                "locales/{}/{file}: HTTP {}",
                lang.code(),
                response.status()
            )));
        }
        let text = JsFuture::from(response.text()?).await?;
        texts.push((file, text.as_string().unwrap_or_default()));
    }
    let files: Vec<(&str, &str)> = texts.iter().map(|(f, t)| (*f, t.as_str())).collect();
    ctx::add_files(lang, &files);
    Ok(())
}
