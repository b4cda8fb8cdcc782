//! The contract between the app shell and its pages.
//!
//! The shell owns the header (product name, navigation, language switch, projector toggle),
//! the footer (safety disclaimer), the `?` shortcut overlay and the hash router. A page is a
//! [`PageDef`] listed in the shell's page table; when its route `#/<id>` opens, the shell
//! empties the `<main>` element and calls `mount`, keeping the returned [`PageHandle`] until
//! the route changes (then `unmount`).
//!
//! Localized text: any element with `data-i18n="msg-id"` has its text set by the shell from
//! the current bundle, now and on every language switch; `data-i18n-attr="title=msg-id;
//! aria-label=msg-id"` does the same for attributes. Strings a page formats itself (canvas
//! labels, validation messages with arguments) are redrawn in `PageHandle::relocalize`, with
//! `crate::ui::ctx::t` / `t_args` (the current language's bundle).
//!
//! Page state lives in the URL query after the route (`#/ik-2r?L1=0.12&q1=0.3&lang=ja`):
//! `MountCtx::query` has it on mount, and the page calls `crate::ui::router::replace_query`
//! with its whole state whenever it changes (history.replaceState, no reload, no new history
//! entry). `lang` is the shell's and is added by the router.

use wasm_bindgen::JsValue;
use web_sys::{Element, KeyboardEvent};

/// One key of a page, for the `?` overlay: the key as shown (`"e"`, `"← ↑ → ↓"`,
/// `"Shift + ←"`) and the Fluent id of what it does.
#[derive(Debug, Clone, Copy)]
pub struct Shortcut {
    pub keys: &'static str,
    pub message_id: &'static str,
}

/// What a page gets when it mounts.
pub struct MountCtx {
    /// The empty `<main>` element the page fills.
    pub root: Element,
    /// The query of the route, decoded, in order (`lang` removed).
    pub query: Vec<(String, String)>,
}

impl MountCtx {
    /// The value of query key `key`, if present.
    pub fn get(&self, key: &str) -> Option<&str> {
        self.query
            .iter()
            .find(|(k, _)| k == key)
            .map(|(_, v)| v.as_str())
    }
}

/// A mounted page.
pub trait PageHandle {
    /// The language changed: redraw whatever the page formats itself.
    fn relocalize(&self) {}
    /// Projector mode turned on or off: redraw canvases with larger type and lines.
    fn set_projector(&self, _on: bool) {}
    /// The page's keys, listed in the `?` overlay after the shell's own.
    fn shortcuts(&self) -> Vec<Shortcut> {
        Vec::new()
    }
    /// A key pressed while no text field has focus and no overlay is open; return `true` if
    /// the page handled it (the shell then calls `preventDefault`).
    fn on_key(&self, _event: &KeyboardEvent) -> bool {
        false
    }
    /// The route is leaving this page: drop listeners, cancel animation frames.
    fn unmount(&self) {}
}

/// A page the shell can route to.
#[derive(Clone, Copy)]
pub struct PageDef {
    /// Route id: `#/<id>`; also the prefix of its `data-testid`s and Fluent ids.
    pub id: &'static str,
    /// Fluent id of its name in the navigation and on its home-page card.
    pub title_id: &'static str,
    /// Fluent id of its one-line description on the home-page card.
    pub blurb_id: &'static str,
    /// Builds the page under `ctx.root`.
    pub mount: fn(MountCtx) -> Result<Box<dyn PageHandle>, JsValue>,
}
