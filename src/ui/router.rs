//! The router: the URL of the tab and nothing else. The codec (`#/<page-id>?k=v&...`,
//! percent-encoding, the `lang` rules) is [`crate::view::url`], re-exported here; this file
//! adds the browser side: the current route, [`replace_query`] and the `hashchange` hook the
//! shell hosts pages from. It knows no page and no shell (no import of either).
//!
//! - [`replace_query`] rewrites the query of the current URL with `history.replaceState` (no
//!   reload, no new history entry, no re-mount): pages call it with their whole state whenever
//!   it changes, so the address is always a link to what is on screen.
//! - `embed=1`: the shell's too; kept in the address of an embedded tab.
//! - `lang`: the shell's, not the page's. It is written into the URL only when the language
//!   came from the URL or the user switched it (then a copied link opens in the language on
//!   screen); otherwise the address stays free of it, so a shared link opens in each visitor's
//!   own language.

use std::cell::Cell;

use wasm_bindgen::prelude::*;

use crate::ui::{ctx, dom};
use crate::view::drills::RECIPE_KEY;
pub use crate::view::url::{
    build_hash, parse_hash, percent_decode, percent_encode, with_shell_keys, Route, HOME_ID,
    LANG_KEY,
};

/// Route id of the drills page, where every recipe runs (`#/drills?recipe=<id>`).
pub const DRILLS_ID: &str = "drills";

/// The link to one drill: `#/drills?recipe=<id>`.
pub fn drill_hash(recipe_id: &str) -> String {
    build_hash(
        DRILLS_ID,
        &[(RECIPE_KEY.to_string(), recipe_id.to_string())],
    )
}

thread_local! {
    static LANG_IN_URL: Cell<bool> = const { Cell::new(false) };
    static EMBEDDED: Cell<bool> = const { Cell::new(false) };
    static ON_WRITE: Cell<Option<fn()>> = const { Cell::new(None) };
}

/// Whether the tab is embedded: the address keeps `embed=1`.
pub fn embedded() -> bool {
    EMBEDDED.get()
}

/// Marks the tab embedded (its first route had `embed=1`).
pub(crate) fn set_embedded() {
    EMBEDDED.set(true);
}

/// Calls `hook` after every write of the address ([`replace_query`], the language).
pub(crate) fn on_write(hook: fn()) {
    ON_WRITE.set(Some(hook));
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

thread_local! {
    /// The page the shell shows (its route's page id), whose state the URL holds.
    static SHOWN: std::cell::RefCell<String> = const { std::cell::RefCell::new(String::new()) };
}

/// Says which page the shell shows (`mount_route`): only its state is written to the URL.
pub(crate) fn set_shown_page(page: &str) {
    SHOWN.with_borrow_mut(|shown| {
        shown.clear();
        shown.push_str(page);
    });
}

/// Replaces the query of the current URL with `pairs` (plus `lang` when the URL carries it),
/// with `history.replaceState`: no reload, no history entry, no re-mount. Nothing is written
/// when the URL already names another page than the one shown (a link was followed and the
/// shell has not shown its page yet): a leaving page's state never lands on the next route.
pub fn replace_query<K: AsRef<str>>(pairs: &[(K, String)]) {
    let page = current_route().page;
    if SHOWN.with_borrow(|shown| *shown != page) {
        return;
    }
    replace_url(&page, pairs);
}

/// Rewrites the current URL to `page` with `pairs` (and `lang` when the URL carries it).
fn replace_url<K: AsRef<str>>(page: &str, pairs: &[(K, String)]) {
    let lang = lang_in_url().then(ctx::lang);
    let hash = build_hash(page, &with_shell_keys(pairs, embedded(), lang));
    let Some(window) = web_sys::window() else {
        return;
    };
    let location = window.location();
    // The same address is not written again (a page writes its settings as it opens).
    if location.hash().ok().as_deref() != Some(hash.as_str()) {
        let base = format!(
            "{}{}",
            location.pathname().unwrap_or_default(),
            location.search().unwrap_or_default()
        );
        if let Ok(history) = window.history() {
            let _ =
                history.replace_state_with_url(&JsValue::NULL, "", Some(&format!("{base}{hash}")));
        }
    }
    if let Some(hook) = ON_WRITE.get() {
        hook();
    }
}

/// Rewrites the current URL so that its `lang` matches the shell (after a language switch).
pub(crate) fn sync_lang_in_url() {
    let route = current_route();
    replace_url(&route.page, &route.page_query());
}

/// Calls `on_route` with the new route on every `hashchange` (links, back/forward, an edited
/// address), for the life of the tab.
pub(crate) fn on_hashchange(on_route: impl Fn(Route) + 'static) -> Result<(), JsValue> {
    let window = dom::window()?;
    dom::Listener::new(&window, "hashchange", move |_| on_route(current_route()))?.forever();
    Ok(())
}
