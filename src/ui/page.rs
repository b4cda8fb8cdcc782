//! The contract between the app shell and its pages.
//!
//! The shell owns the header (product name, navigation, language switch, projector toggle),
//! the footer (safety disclaimer), the `?` shortcut overlay and hosts the page the router
//! names. A page is one struct holding its state and a [`Scope`](crate::ui::kit::scope::Scope)
//! (its listeners, timers, frame loop, observers), implementing [`Page`]; it registers itself
//! with one line in `crate::ui::pages::PAGES`:
//!
//! ```ignore
//! pub const PAGE: PageDef = PageDef::of::<Pendulum>("pendulum", "pendulum-title", "pendulum-blurb");
//! ```
//!
//! When its route `#/<id>` opens, the shell empties the `<main>` element and calls
//! [`Page::mount`], keeping the page until the route changes; then it drops it (unmount =
//! drop: the scope removes everything). Pages written before the kit implement
//! [`PageHandle`] directly and fill in [`PageDef`] by hand (`unmount` is then called before
//! the drop).
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
    /// A key pressed while the page (its body or canvas, not a control) has focus and no
    /// overlay is open; return `true` if the page handled it (the shell then calls
    /// `preventDefault`).
    fn on_key(&self, _event: &KeyboardEvent) -> bool {
        false
    }
    /// The route is leaving this page (called just before it is dropped): drop listeners,
    /// cancel animation frames. A [`Page`] needs none: its scope does it on drop.
    fn unmount(&self) {}
}

/// A page: one struct holding its state and its scope, built by `mount` and dropped when the
/// route changes. Every [`Page`] is a [`PageHandle`].
pub trait Page: 'static {
    /// Builds the page under `ctx.root` from the URL's query.
    fn mount(ctx: MountCtx) -> Result<Self, JsValue>
    where
        Self: Sized;
    /// The language changed: redraw whatever the page formats itself.
    fn relocalize(&self) {}
    /// Projector mode turned on or off: redraw canvases with larger type and lines.
    fn set_projector(&self, _on: bool) {}
    /// The page's keys for the `?` overlay (with [`crate::ui::kit::keymap::STEPPER`] if the
    /// page has a stepper): exactly the keys `on_key` takes.
    fn shortcuts(&self) -> Vec<Shortcut> {
        Vec::new()
    }
    /// A key pressed while the page (its body or canvas, not a control) has focus, no
    /// overlay is open and no Ctrl/Alt/Meta is held; `true` if the page took it (the shell
    /// then calls `preventDefault`).
    fn on_key(&self, _event: &KeyboardEvent) -> bool {
        false
    }
}

impl<P: Page> PageHandle for P {
    fn relocalize(&self) {
        Page::relocalize(self);
    }
    fn set_projector(&self, on: bool) {
        Page::set_projector(self, on);
    }
    fn shortcuts(&self) -> Vec<Shortcut> {
        Page::shortcuts(self)
    }
    fn on_key(&self, event: &KeyboardEvent) -> bool {
        Page::on_key(self, event)
    }
}

fn mount_boxed<P: Page>(ctx: MountCtx) -> Result<Box<dyn PageHandle>, JsValue> {
    Ok(Box::new(P::mount(ctx)?))
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

impl PageDef {
    /// The registration of page `P` under route `#/<id>`.
    pub const fn of<P: Page>(
        id: &'static str,
        title_id: &'static str,
        blurb_id: &'static str,
    ) -> PageDef {
        PageDef {
            id,
            title_id,
            blurb_id,
            mount: mount_boxed::<P>,
        }
    }
}
