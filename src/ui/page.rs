//! The contract between the app shell and its pages.
//!
//! A page is one struct holding its state and a [`Scope`](crate::ui::kit::scope::Scope),
//! implementing [`Page`]; the page table (`crate::ui::pages::PAGES`) registers it with one
//! line that also places it in the navigation:
//!
//! ```ignore
//! page!(ik2r_page, ik2r::Ik2rPage, "ik-2r", "ik2r-title", "ik2r-blurb", Nav::Kinematics, ["ik2r.ftl"]),
//! ```
//!
//! Each page's code is a wasm chunk of its own, fetched when the page is first opened (the
//! `page!` line splits it off). On its route `#/<id>` the shell empties `<main>`, shows the
//! page's frame while its chunk loads ([`PageDef::load`]), then calls [`Page::mount`] and keeps
//! the page until the route changes; then it drops it (the scope removes what the page
//! installed).
//! Text in `data-i18n` / `data-i18n-attr` elements is the shell's; what a page formats itself
//! is redrawn in [`Page::relocalize`]. Page state lives in the URL query after the route:
//! [`MountCtx::query`] on mount, `crate::ui::router::replace_query` on every change.

use std::future::Future;
use std::pin::Pin;

use wasm_bindgen::JsValue;
use web_sys::{Element, KeyboardEvent};

pub use wasm_split_helpers::SplitLoaderError;

/// One key of a page, for the `?` overlay: the key as shown (`"e"`, `"← ↑ → ↓"`,
/// `"Shift + ←"`) and the Fluent id of what it does.
#[derive(Debug, Clone, Copy)]
pub struct Shortcut {
    pub keys: &'static str,
    pub message_id: &'static str,
}

/// What a page or the lesson presenter asks the shell to do.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ShellRequest {
    /// Send the mounted page one PageDown, as a presenter remote would (a lesson step that
    /// steps the page's stepper).
    StepPage,
    /// Mount the current route again (a lesson step shown a second time starts afresh).
    Remount,
    /// Projector mode on or off (a lesson being presented turns it on).
    Projector(bool),
    /// Projector mode on in this window only, not remembered (the room's window of a
    /// two-screen presentation).
    ProjectorHere,
    /// Switch to this language, as the language button does.
    Lang(crate::i18n::Lang),
    /// The mounted page, which waited for a chunk before it was built, is built (or says that
    /// the chunk could not be fetched): the route is settled.
    Settled,
}

/// What the shell lends a page: the page table and a way to ask the shell for something.
#[derive(Clone, Copy)]
pub struct ShellLink {
    /// Every page, in navigation order.
    pub pages: &'static [PageDef],
    /// Carries out a request.
    pub request: fn(ShellRequest) -> Result<(), JsValue>,
}

impl ShellLink {
    /// The page with route id `id`.
    pub fn find(&self, id: &str) -> Option<&'static PageDef> {
        find(self.pages, id)
    }

    /// Whether page `id` exists.
    pub fn is_page(&self, id: &str) -> bool {
        self.find(id).is_some()
    }
}

/// The page with route id `id` in `pages`.
pub fn find(pages: &'static [PageDef], id: &str) -> Option<&'static PageDef> {
    pages.iter().find(|def| def.id == id)
}

/// What a page gets when it mounts.
pub struct MountCtx {
    /// The empty `<main>` element the page fills.
    pub root: Element,
    /// The query of the route, decoded, in order (`lang` removed).
    pub query: Vec<(String, String)>,
    /// The page table and the shell's requests.
    pub shell: ShellLink,
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

/// A page: one struct holding its state and its scope, built by `mount` and dropped when the
/// route changes.
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
    /// A key pressed while a control that is not a text entry has focus (a button, tab, check
    /// box, slider or select, anywhere in the document), no dialog is open and no
    /// Ctrl/Alt/Meta is held: a page whose held keys drive something (the pilot pages) takes
    /// its driving keys here, so a click on a control never stops them; `true` if taken.
    fn on_key_over_control(&self, _event: &KeyboardEvent) -> bool {
        false
    }
    /// Whether the page is built and answering input (`false` while it waits for a chunk;
    /// it then asks for [`ShellRequest::Settled`] once it is built).
    fn settled(&self) -> bool {
        true
    }
}

/// Builds page `P`: what a page's chunk hands the shell.
pub type MountFn = fn(MountCtx) -> Result<Box<dyn Page>, JsValue>;

/// Loading a page's chunk: its mount function once the chunk is in, or why it could not load
/// (offline before the chunk was fetched, a missing file).
pub type PageLoad = Pin<Box<dyn Future<Output = Result<MountFn, SplitLoaderError>>>>;

/// The mount function of page `P`.
pub fn mount_boxed<P: Page>(ctx: MountCtx) -> Result<Box<dyn Page>, JsValue> {
    Ok(Box::new(P::mount(ctx)?))
}

/// Where a page's link sits in the header's navigation.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Nav {
    /// A top-level link of the header.
    Top,
    /// A teacher's tool with no link in the header (one more would wrap the header to a
    /// second row at 1366 px): reached from its home-page tile and from the pages that use
    /// it (the home page's progress links the class page).
    Tool,
    /// The groups of the Drills menu (in the order the page table first names them).
    Kinematics,
    Dynamics,
    Trajectories,
    Planning,
}

impl Nav {
    /// The group's key (`None` for a top-level link).
    pub fn group(self) -> Option<&'static str> {
        match self {
            Nav::Top | Nav::Tool => None,
            Nav::Kinematics => Some("kinematics"),
            Nav::Dynamics => Some("dynamics"),
            Nav::Trajectories => Some("trajectories"),
            Nav::Planning => Some("planning"),
        }
    }
}

/// A page the shell can route to: one line of the page table.
#[derive(Clone, Copy)]
pub struct PageDef {
    /// Route id: `#/<id>`; also the prefix of its `data-testid`s and Fluent ids.
    pub id: &'static str,
    /// Fluent id of its name in the navigation and on its home-page card.
    pub title_id: &'static str,
    /// The page's head as its markup opens it: its outer element, the elements down to its
    /// `<h1>` and the paragraph after it (the lede), in the page's own classes and with their
    /// `data-i18n` ids, closed. The frame shows it while the page's code loads, laid out as the
    /// page will be; the page keeps those nodes ([`crate::ui::page_frame::fill`]).
    pub head: &'static str,
    /// Where its link sits in the navigation.
    pub nav: Nav,
    /// The Fluent files it needs beyond [`crate::i18n::FIRST_FILES`] (fetched with its code).
    pub strings: &'static [&'static str],
    /// Its own stylesheet, if its body's rules are not in `app.css`: `<name>.late.css` beside
    /// its Rust, `www/<name>.css` in dist/, fetched with its code and loaded before it mounts.
    /// The rules of its head (which the frame shows first) stay in its `style.css`.
    pub sheet: Option<&'static str>,
    /// Loads the page's chunk (at once if it is in) and gives its mount function.
    pub load: fn() -> PageLoad,
}

/// One line of the page table: `page!(chunk, PageType, id, title_id, head, nav, [files])`
/// registers `PageType` under route `#/<id>` with its code split off into the wasm chunk
/// `chunk` and the Fluent files it needs beyond the first ones, both fetched when the page is
/// first opened; `page!(..., [files], "sheet")` also names its own stylesheet
/// ([`PageDef::sheet`]).
macro_rules! page {
    ($chunk:ident, $page:ty, $id:expr, $title_id:expr, $head:expr, $nav:expr, [$($file:expr),* $(,)?] $(, $sheet:literal)?) => {
        $crate::ui::page::PageDef {
            id: $id,
            title_id: $title_id,
            head: $head,
            nav: $nav,
            strings: &[$($file),*],
            sheet: $crate::ui::page::page_sheet!($($sheet)?),
            load: $crate::ui::page::page_load!($chunk, $page),
        }
    };
}

/// The `sheet` of a page: `None`, or `Some` of the name given.
macro_rules! page_sheet {
    () => {
        None
    };
    ($sheet:literal) => {
        Some($sheet)
    };
}

/// The `load` of a page: its code split off into the chunk `$chunk`.
#[cfg(feature = "split")]
macro_rules! page_load {
    ($chunk:ident, $page:ty) => {{
        #[wasm_split_helpers::wasm_split($chunk, fallible)]
        fn $chunk() -> Result<$crate::ui::page::MountFn, $crate::ui::page::SplitLoaderError> {
            Ok($crate::ui::page::mount_boxed::<$page>)
        }
        || -> $crate::ui::page::PageLoad { Box::pin($chunk()) }
    }};
}

/// Without the `split` feature (tests, benches) every page is in the one wasm.
#[cfg(not(feature = "split"))]
macro_rules! page_load {
    ($chunk:ident, $page:ty) => {
        || -> $crate::ui::page::PageLoad {
            Box::pin(std::future::ready(Ok(
                $crate::ui::page::mount_boxed::<$page> as $crate::ui::page::MountFn,
            )))
        }
    };
}
pub(crate) use page;
pub(crate) use page_load;
pub(crate) use page_sheet;
