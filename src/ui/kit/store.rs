//! A page's work kept in the browser's storage (localStorage) under one key, read and saved so
//! that nothing is lost: text the page cannot read (edited by hand, cut short, from another
//! version) is moved aside under `<key>.unreadable` ([`aside_key`]) before the page starts
//! clean, and a save the browser refuses (`QuotaExceededError`: storage full; storage turned
//! off) is reported, so the page keeps its work in memory and says it is not saved.

use js_sys::Reflect;
use wasm_bindgen::JsValue;
use web_sys::Storage;

use crate::ui::dom;

/// What a read of a key found.
#[derive(Debug, Clone, PartialEq)]
pub enum Stored<T> {
    /// Nothing stored (or no storage).
    Nothing,
    /// The stored value.
    Read(T),
    /// Text the page could not read, now kept under [`aside_key`] (the key itself cleared).
    SetAside,
}

/// Why a save did not happen.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Refused {
    /// The browser's storage is full (`QuotaExceededError`).
    Full,
    /// No storage (turned off, private mode) or another refusal.
    Unavailable,
}

/// Where unreadable text of `key` is kept.
pub fn aside_key(key: &str) -> String {
    format!("{key}.unreadable")
}

fn storage() -> Option<Storage> {
    web_sys::window()?.local_storage().ok()?
}

/// Reads `key` with `parse`. Text `parse` refuses is moved to [`aside_key`] (replacing what
/// was kept there) and `key` cleared, so that the page's next save cannot overwrite the
/// user's only copy; if the browser refuses that move, the text stays under `key`.
pub fn read<T, E>(key: &str, parse: impl FnOnce(&str) -> Result<T, E>) -> Stored<T> {
    let Some(text) = dom::storage_get(key) else {
        return Stored::Nothing;
    };
    match parse(&text) {
        Ok(value) => Stored::Read(value),
        Err(_) => {
            set_aside(key, &text);
            Stored::SetAside
        }
    }
}

/// Keeps `text`, unreadable as `key`, under [`aside_key`] and clears `key`.
pub fn set_aside(key: &str, text: &str) {
    let Some(storage) = storage() else {
        return;
    };
    // Removing first frees the room the copy needs when storage is full.
    let _ = storage.remove_item(key);
    if storage.set_item(&aside_key(key), text).is_err() {
        let _ = storage.set_item(key, text);
    }
}

/// Whether anything is stored under one of `keys` (asked of the storage without copying the
/// stored text into the wasm).
pub fn holds_any(keys: &[&str]) -> bool {
    storage().is_some_and(|s| {
        keys.iter()
            .any(|k| Reflect::has(&s, &JsValue::from_str(k)).unwrap_or(false))
    })
}

/// The text kept aside for `key`, if any.
pub fn aside(key: &str) -> Option<String> {
    dom::storage_get(&aside_key(key))
}

/// Forgets the text kept aside for `key`.
pub fn forget_aside(key: &str) {
    if let Some(storage) = storage() {
        let _ = storage.remove_item(&aside_key(key));
    }
}

/// Saves `value` under `key`; `Err` says why the browser refused.
pub fn save(key: &str, value: &str) -> Result<(), Refused> {
    let storage = storage().ok_or(Refused::Unavailable)?;
    storage.set_item(key, value).map_err(|e| refusal(&e))
}

fn refusal(error: &JsValue) -> Refused {
    let name = Reflect::get(error, &JsValue::from_str("name"))
        .ok()
        .and_then(|n| n.as_string());
    match name.as_deref() {
        Some("QuotaExceededError") => Refused::Full,
        _ => Refused::Unavailable,
    }
}
