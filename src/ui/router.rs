//! The hash router: `#/<page-id>?k=v&...` picks a page from the page table and hands it the
//! decoded query. `#`, `#/` and an empty hash are the home page; an unknown page id shows a
//! localized "page not found" with a link home.
//!
//! - `hashchange` (links, back/forward, an edited address) unmounts the current page and mounts
//!   the new one. [`replace_query`] rewrites the query of the current URL with
//!   `history.replaceState` (no reload, no new history entry, no re-mount): pages call it with
//!   their whole state whenever it changes, so the address is always a link to what is on screen.
//! - Percent-encoding: keys and values are encoded as in `encodeURIComponent` (except that `,`
//!   stays readable); decoding also accepts `+` for a space, and invalid escapes stay as typed.
//! - `lang`: the shell's, not the page's. It is removed from the query a page sees. It is
//!   written into the URL only when the language came from the URL or the user switched it
//!   (then a copied link opens in the language on screen); otherwise the address stays free of
//!   it, so a shared link opens in each visitor's own language.

use std::cell::{Cell, RefCell};

use wasm_bindgen::prelude::*;

use crate::i18n::Lang;
use crate::ui::dom;
use crate::ui::page::{MountCtx, PageDef, PageHandle};
use crate::ui::{ctx, pages, shell};

/// The query key the shell uses for the language.
pub const LANG_KEY: &str = "lang";

/// A parsed hash route.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Route {
    /// The page id (`"home"` for an empty route).
    pub page: String,
    /// The decoded query, in order, `lang` included.
    pub query: Vec<(String, String)>,
}

impl Route {
    /// The language named by `?lang=`, if any and known.
    pub fn lang(&self) -> Option<Lang> {
        self.query
            .iter()
            .find(|(k, _)| k == LANG_KEY)
            .and_then(|(_, v)| Lang::parse(v))
    }

    /// The query without `lang`.
    pub fn page_query(&self) -> Vec<(String, String)> {
        self.query
            .iter()
            .filter(|(k, _)| k != LANG_KEY)
            .cloned()
            .collect()
    }
}

/// Parses a location hash (`"#/ik-2r?L1=0.12&lang=ja"`, `"#/"`, `""`).
pub fn parse_hash(hash: &str) -> Route {
    let body = hash.strip_prefix('#').unwrap_or(hash);
    let body = body.strip_prefix('/').unwrap_or(body);
    let (path, query) = body.split_once('?').unwrap_or((body, ""));
    let page = percent_decode(path.trim_end_matches('/'));
    let page = if page.is_empty() {
        pages::HOME_ID.to_string()
    } else {
        page
    };
    let query = query
        .split('&')
        .filter(|pair| !pair.is_empty())
        .map(|pair| {
            let (k, v) = pair.split_once('=').unwrap_or((pair, ""));
            (percent_decode(k), percent_decode(v))
        })
        .collect();
    Route { page, query }
}

/// The hash for a page and query (`"#/ik-2r?L1=0.12"`; `"#/"` for home without a query).
pub fn build_hash(page: &str, query: &[(String, String)]) -> String {
    let path = if page == pages::HOME_ID {
        String::new()
    } else {
        percent_encode(page)
    };
    let mut hash = format!("#/{path}");
    for (index, (key, value)) in query.iter().enumerate() {
        hash.push(if index == 0 { '?' } else { '&' });
        hash.push_str(&percent_encode(key));
        hash.push('=');
        hash.push_str(&percent_encode(value));
    }
    hash
}

/// Percent-encodes everything but `A–Z a–z 0–9 - _ . ~ ,` (UTF-8 bytes for other text).
pub fn percent_encode(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for byte in text.bytes() {
        if byte.is_ascii_alphanumeric() || matches!(byte, b'-' | b'_' | b'.' | b'~' | b',') {
            out.push(byte as char);
        } else {
            out.push_str(&format!("%{byte:02X}"));
        }
    }
    out
}

/// Decodes `%XX` escapes (as UTF-8, invalid sequences replaced) and `+` as a space; a `%` not
/// followed by two hex digits stays as it is.
pub fn percent_decode(text: &str) -> String {
    let bytes = text.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut index = 0;
    while index < bytes.len() {
        let byte = bytes[index];
        let escaped = if byte == b'%' {
            bytes
                .get(index + 1..index + 3)
                .and_then(|hex| std::str::from_utf8(hex).ok())
                .and_then(|hex| u8::from_str_radix(hex, 16).ok())
        } else {
            None
        };
        match (byte, escaped) {
            (_, Some(decoded)) => {
                out.push(decoded);
                index += 3;
            }
            (b'+', None) => {
                out.push(b' ');
                index += 1;
            }
            (_, None) => {
                out.push(byte);
                index += 1;
            }
        }
    }
    String::from_utf8_lossy(&out).into_owned()
}

struct Mounted {
    page_id: &'static str,
    handle: Box<dyn PageHandle>,
}

thread_local! {
    static MOUNTED: RefCell<Option<Mounted>> = const { RefCell::new(None) };
    static LANG_IN_URL: Cell<bool> = const { Cell::new(false) };
}

/// Whether the URL carries `lang=` (it came from the URL, or the user switched language).
pub fn lang_in_url() -> bool {
    LANG_IN_URL.with(Cell::get)
}

/// Marks that the URL should carry `lang=` from now on.
pub(crate) fn set_lang_in_url(on: bool) {
    LANG_IN_URL.with(|cell| cell.set(on));
}

/// The route of the current location.
pub fn current_route() -> Route {
    let hash = web_sys::window()
        .and_then(|w| w.location().hash().ok())
        .unwrap_or_default();
    parse_hash(&hash)
}

/// Replaces the query of the current URL with `pairs` (plus `lang` when the URL carries it),
/// with `history.replaceState`: no reload, no history entry, no re-mount.
pub fn replace_query(pairs: &[(&str, String)]) {
    let query: Vec<(String, String)> = pairs
        .iter()
        .filter(|(k, _)| *k != LANG_KEY)
        .map(|(k, v)| (k.to_string(), v.clone()))
        .collect();
    replace_url(&current_route().page, query);
}

/// Rewrites the current URL to `page` with `query` (and `lang` when the URL carries it).
fn replace_url(page: &str, mut query: Vec<(String, String)>) {
    if lang_in_url() {
        query.push((LANG_KEY.to_string(), ctx::lang().code().to_string()));
    }
    let hash = build_hash(page, &query);
    let Some(window) = web_sys::window() else {
        return;
    };
    let location = window.location();
    let base = format!(
        "{}{}",
        location.pathname().unwrap_or_default(),
        location.search().unwrap_or_default()
    );
    if let Ok(history) = window.history() {
        let _ = history.replace_state_with_url(&JsValue::NULL, "", Some(&format!("{base}{hash}")));
    }
}

/// Rewrites the current URL so that its `lang` matches the shell (after a language switch).
pub(crate) fn sync_lang_in_url() {
    let route = current_route();
    replace_url(&route.page, route.page_query());
}

/// Starts routing: mounts the current route and re-mounts on every `hashchange`.
pub(crate) fn start() -> Result<(), JsValue> {
    let window = dom::window()?;
    dom::Listener::new(&window, "hashchange", |_| {
        if let Err(error) = mount_current() {
            web_sys::console::error_2(&"BSV Playground: routing failed".into(), &error);
        }
        if let Some(window) = web_sys::window() {
            window.scroll_to_with_x_and_y(0.0, 0.0);
        }
    })?
    .forever();
    mount_current()
}

/// Calls `f` with the mounted page, if any (`None` also while the page is being swapped).
pub(crate) fn with_page<R>(f: impl FnOnce(&dyn PageHandle) -> R) -> Option<R> {
    MOUNTED
        .try_with(|cell| {
            let mounted = cell.try_borrow().ok()?;
            mounted.as_ref().map(|m| f(m.handle.as_ref()))
        })
        .ok()
        .flatten()
}

/// The id of the mounted page (`None` on the not-found page).
pub fn current_page_id() -> Option<&'static str> {
    MOUNTED
        .try_with(|cell| cell.try_borrow().ok()?.as_ref().map(|m| m.page_id))
        .ok()
        .flatten()
}

/// Unmounts the current page and mounts the one the URL names.
pub(crate) fn mount_current() -> Result<(), JsValue> {
    let route = current_route();
    if let Some(lang) = route.lang() {
        set_lang_in_url(true);
        if lang != ctx::lang() {
            shell::apply_lang(lang)?;
        }
    }
    let old = MOUNTED.with(|cell| cell.try_borrow_mut().ok().and_then(|mut m| m.take()));
    if let Some(old) = old {
        old.handle.unmount();
    }
    let main = shell::main_element()?;
    dom::clear(&main);
    let def = pages::find(&route.page);
    match def {
        Some(def) => mount_page(def, &main, route.page_query())?,
        None => render_not_found(&main)?,
    }
    shell::route_changed(def)?;
    if lang_in_url() && route.lang() != Some(ctx::lang()) {
        sync_lang_in_url();
    }
    Ok(())
}

fn mount_page(
    def: &'static PageDef,
    main: &web_sys::Element,
    query: Vec<(String, String)>,
) -> Result<(), JsValue> {
    let mount_ctx = MountCtx {
        root: main.clone(),
        query,
    };
    match (def.mount)(mount_ctx) {
        Ok(handle) => {
            if ctx::projector() {
                handle.set_projector(true);
            }
            MOUNTED.with(|cell| {
                if let Ok(mut mounted) = cell.try_borrow_mut() {
                    *mounted = Some(Mounted {
                        page_id: def.id,
                        handle,
                    });
                }
            });
        }
        Err(error) => {
            web_sys::console::error_2(
                &format!("BSV Playground: page '{}' failed to mount", def.id).into(),
                &error,
            );
            dom::clear(main);
            let message = dom::el_i18n("p", "page-error", "page-mount-failed")?;
            message.set_attribute("role", "alert")?;
            dom::append(main, &message)?;
        }
    }
    Ok(())
}

/// The localized "page not found" with a link home.
fn render_not_found(main: &web_sys::Element) -> Result<(), JsValue> {
    let section = dom::el_class("section", "not-found")?;
    section.set_attribute("data-testid", "not-found")?;
    dom::append(&section, &dom::el_i18n("h1", "", "notfound-title")?)?;
    dom::append(&section, &dom::el_i18n("p", "", "notfound-body")?)?;
    let home = dom::el_i18n("a", "button-link", "notfound-home")?;
    home.set_attribute("href", "#/")?;
    home.set_attribute("data-testid", "not-found-home")?;
    dom::append(&section, &home)?;
    dom::append(main, &section)
}

#[cfg(test)]
mod tests {
    use super::*;
    use wasm_bindgen_test::wasm_bindgen_test as test;

    fn q(pairs: &[(&str, &str)]) -> Vec<(String, String)> {
        pairs
            .iter()
            .map(|(k, v)| (k.to_string(), v.to_string()))
            .collect()
    }

    #[test]
    fn empty_and_root_hashes_are_home() {
        for hash in ["", "#", "#/", "/", "#/?"] {
            let route = parse_hash(hash);
            assert_eq!(route.page, pages::HOME_ID, "{hash:?}");
            assert!(route.query.is_empty(), "{hash:?}");
        }
    }

    #[test]
    fn page_and_query_are_split_and_decoded_in_order() {
        let route = parse_hash("#/ik-2r?L1=0.12&note=a%20b+c&lang=ja&flag");
        assert_eq!(route.page, "ik-2r");
        assert_eq!(
            route.query,
            q(&[
                ("L1", "0.12"),
                ("note", "a b c"),
                ("lang", "ja"),
                ("flag", "")
            ])
        );
        assert_eq!(route.lang(), Some(Lang::Ja));
        assert_eq!(
            route.page_query(),
            q(&[("L1", "0.12"), ("note", "a b c"), ("flag", "")])
        );
        assert_eq!(parse_hash("#/ik-2r/").page, "ik-2r");
        assert_eq!(parse_hash("#/x?lang=fr").lang(), None);
    }

    #[test]
    fn encoding_round_trips_any_text() {
        for text in [
            "0.2,0.4,-0.3",
            "a b&c=d?e#f/g",
            "日本語",
            "100%",
            "+1e-3",
            "",
        ] {
            assert_eq!(percent_decode(&percent_encode(text)), text);
        }
        assert_eq!(percent_encode("a b&c"), "a%20b%26c");
        assert_eq!(percent_encode("日"), "%E6%97%A5");
        assert_eq!(percent_encode("+1"), "%2B1");
    }

    #[test]
    fn broken_escapes_do_not_panic_and_stay_as_typed() {
        assert_eq!(percent_decode("100%"), "100%");
        assert_eq!(percent_decode("%zz%4"), "%zz%4");
        assert_eq!(percent_decode("%E6%97"), "\u{FFFD}");
        assert_eq!(percent_decode("%"), "%");
    }

    #[test]
    fn built_hashes_parse_back() {
        let query = q(&[("L1", "0.12"), ("q", "a&b"), ("lang", "ja")]);
        let hash = build_hash("ik-2r", &query);
        assert_eq!(hash, "#/ik-2r?L1=0.12&q=a%26b&lang=ja");
        assert_eq!(
            parse_hash(&hash),
            Route {
                page: "ik-2r".into(),
                query
            }
        );
        assert_eq!(build_hash(pages::HOME_ID, &[]), "#/");
    }
}
