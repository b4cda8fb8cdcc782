//! The app shell: a "Skip to content" link, the header (product name and subtitle, navigation
//! of the page table with the drill pages in a grouped menu ([`nav_menu`]), language switch,
//! projector toggle, "Share" ([`share`]), `?` button), the `<main>` that hosts the page the router names, the
//! footer with the safety disclaimer, and the keys.
//!
//! - Hosting: on every route the shell drops the mounted page and mounts the one the route
//!   names (else a localized "page not found"). Only the shell imports the page table; what
//!   lies below it gets the table from the shell ([`ShellLink`]) and asks it for what it needs.
//! - Language: `?lang=`, else the saved choice (`bsv.lang`), else `navigator.languages`, else
//!   English; a switch re-renders every localized string and calls the page's `relocalize()`.
//! - Projector mode: class `projector` on `<html>`, saved in `bsv.projector`, passed to the
//!   page's `set_projector()`.
//! - Keys follow [`keymap`]: `?`, `p`, `l` are the shell's; other keys go to the page's `on_key`
//!   only while the page body or a canvas has focus. Keys the page does not take keep their
//!   default, so presenter remotes keep working.

use std::cell::{Cell, RefCell};
use std::rc::Rc;
use std::task::{Context, Poll, Waker};

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::{Element, KeyboardEvent};

use crate::i18n::{self, Lang};
use crate::ui::drill_chain;
use crate::ui::embed;
use crate::ui::embed_api::ShellFns;
use crate::ui::kit::keymap::{self, ShellKey};
use crate::ui::kit::late_style;
use crate::ui::lang_files;
use crate::ui::lesson_bar;
use crate::ui::nav_cue;
use crate::ui::nav_menu::{self, NavMenu};
use crate::ui::page::{self, MountCtx, Nav, Page, PageDef, ShellLink, ShellRequest};
use crate::ui::pages::PAGES;
use crate::ui::router::{Route, HOME_ID};
use crate::ui::schedule;
use crate::ui::section_keys;
use crate::ui::share;
use crate::ui::update_banner;
use crate::ui::{ctx, dom, overlay, page_frame, router};

/// localStorage key of the language the user chose.
pub const LANG_STORAGE_KEY: &str = "bsv.lang";
/// localStorage key of projector mode (`"1"` on, `"0"` off).
pub const PROJECTOR_STORAGE_KEY: &str = "bsv.projector";

/// The page table and the shell's requests, lent to pages and the lesson bar.
const SHELL: ShellLink = ShellLink {
    pages: PAGES,
    request: perform,
};

/// What the shell lends the embedding API.
const EMBED_SHELL: ShellFns = ShellFns {
    main: main_element,
    settled: page_settled,
    remount,
};

const APP_ID: &str = "app";
const MAIN_ID: &str = "app-main";
/// The status line under "?" (the shortcuts overlay could not be loaded).
const HELP_STATUS_ID: &str = "help-status";

/// Builds the shell into `#app` (or `<body>`), applies the initial language and projector
/// mode, installs the keys and starts the router; the first route is mounted by
/// [`mount_first_route`], in a task of its own. Calling it twice does nothing: whether it built
/// the shell.
pub(crate) fn start(lang: Lang) -> Result<bool, JsValue> {
    let document = dom::document()?;
    if document.get_element_by_id(MAIN_ID).is_some() {
        return Ok(false);
    }
    ctx::set_lang(lang);
    ctx::set_projector(dom::storage_get(PROJECTOR_STORAGE_KEY).as_deref() == Some("1"));
    embed::install(EMBED_SHELL)?;

    let app = match document.get_element_by_id(APP_ID) {
        Some(app) => app,
        None => {
            let app = dom::el("div")?;
            app.set_id(APP_ID);
            let body = document
                .body()
                .ok_or_else(|| JsValue::from_str("no body"))?;
            body.append_child(&app)?;
            app
        }
    };
    dom::clear(&app);
    dom::append(&app, &build_skip_link()?)?;
    dom::append(&app, &build_header()?)?;
    let main = dom::el_class("main", "site-main")?;
    main.set_id(MAIN_ID);
    main.set_attribute("tabindex", "-1")?;
    dom::append(&app, &main)?;
    dom::append(&app, &drill_chain::build()?)?;
    dom::append(&app, &build_footer()?)?;
    dom::append(&app, &update_banner::build()?)?;
    let bar = lesson_bar::build_bar()?;
    dom::Listener::new(&bar, "click", |event| {
        report(lesson_bar::on_bar_click(&event).and_then(perform_all));
    })?
    .forever();
    dom::append(&app, &bar)?;
    if let Some(status) = document.get_element_by_id("boot-status") {
        status.remove();
    }

    apply_projector_class(ctx::projector())?;
    apply_lang_chrome()?;
    install_keys()?;
    router::on_hashchange(|route| {
        report(mount_route(&route));
        if let Some(window) = web_sys::window() {
            window.scroll_to_with_x_and_y(0.0, 0.0);
        }
    })?;
    install_load_progress()?;
    lesson_bar::join_if_audience(SHELL);
    Ok(true)
}

/// Mounts the route of the address, unless a route was mounted already (a `hashchange` since
/// [`start`]).
pub(crate) fn mount_first_route() -> Result<(), JsValue> {
    if ROUTING.with(|routing| routing.generation.get()) == 0 {
        mount_route(&router::current_route())?;
    }
    Ok(())
}

/// Once a page is shown and painted: its strings in the other language, fetched and then
/// parsed a piece (a few KB) per idle slice, so that a switch of language is immediate.
/// Nothing else is loaded ahead: a page's code and strings come when it is opened (its chunk
/// compiled as its bytes land), and the service worker caches the rest of the build on its
/// own thread, so the main thread does no work the visitor did not ask for. A part that fails
/// to load is loaded again when it is needed.
async fn warm_other_lang(def: Option<&'static PageDef>) {
    let other = ctx::lang().other();
    schedule::idle().await;
    if lang_files::load(other, page_strings(def)).await.is_err() {
        return;
    }
    loop {
        schedule::idle().await;
        if !ctx::build_next_piece(other) {
            break;
        }
    }
}

/// [`warm_other_lang`] once what is on the page now is painted.
fn warm_after_paint(def: Option<&'static PageDef>) -> Result<(), JsValue> {
    schedule::after_paint(move || wasm_bindgen_futures::spawn_local(warm_other_lang(def)))
}

/// `?lang=`, else the saved choice, else the browser's languages, else English.
pub(crate) fn initial_lang() -> Lang {
    if let Some(lang) = router::current_route().lang() {
        return lang;
    }
    if let Some(lang) = dom::storage_get(LANG_STORAGE_KEY).and_then(|code| Lang::parse(&code)) {
        return lang;
    }
    let preferred: Vec<String> = web_sys::window()
        .map(|w| w.navigator().languages())
        .map(|list| list.iter().filter_map(|v| v.as_string()).collect())
        .unwrap_or_default();
    i18n::negotiate(&preferred)
}

/// The `<main>` element pages mount into.
pub(crate) fn main_element() -> Result<Element, JsValue> {
    dom::document()?
        .get_element_by_id(MAIN_ID)
        .ok_or_else(|| JsValue::from_str("the shell is not built"))
}

/// "Skip to content": the first focusable element, visible when focused; it moves the focus to
/// `<main>` without touching the route (the hash is the router's).
fn build_skip_link() -> Result<Element, JsValue> {
    let link = dom::el_i18n("a", "skip-link", "skip-to-content")?;
    link.set_attribute("href", &format!("#{MAIN_ID}"))?;
    link.set_attribute("data-testid", "skip-link")?;
    dom::Listener::new(&link, "click", |event| {
        event.prevent_default();
        if let Ok(main) = main_element() {
            dom::focus(&main);
            main.scroll_into_view();
        }
    })?
    .forever();
    Ok(link)
}

fn build_header() -> Result<Element, JsValue> {
    let header = dom::el_class("header", "site-header")?;
    header.set_attribute("data-testid", "site-header")?;

    let brand = dom::el_class("div", "brand")?;
    // The full name, and a short one that phones show instead (screen readers always hear
    // the full name: the short one is aria-hidden, the full one only visually hidden there).
    let name = dom::el_class("a", "brand-name")?;
    name.set_attribute("href", "#/")?;
    name.set_attribute("data-testid", "brand")?;
    dom::append(&name, &dom::el_i18n("span", "brand-full", "app-name")?)?;
    let short = dom::el_i18n("span", "brand-short", "app-name-short")?;
    short.set_attribute("aria-hidden", "true")?;
    dom::append(&name, &short)?;
    dom::append(&brand, &name)?;
    let subtitle = dom::el_i18n("span", "brand-subtitle", "app-subtitle")?;
    subtitle.set_attribute("data-testid", "brand-subtitle")?;
    dom::append(&brand, &subtitle)?;
    dom::append(&header, &brand)?;

    let nav = dom::el_class("nav", "site-nav")?;
    nav.set_attribute("data-testid", "site-nav")?;
    dom::set_i18n_attrs(&nav, &[("aria-label", "nav-label")])?;
    let list = dom::el("ul")?;
    let menu = nav_menu::build(PAGES, nav_link)?;
    for def in PAGES.iter().filter(|def| def.nav == Nav::Top) {
        let item = dom::el("li")?;
        dom::append(&item, &nav_link(def)?)?;
        dom::append(&list, &item)?;
        if def.id == HOME_ID {
            dom::append(&list, menu.item())?;
        }
    }
    NAV_MENU.with(|slot| *slot.borrow_mut() = Some(menu));
    dom::append(&nav, &list)?;
    dom::append(&header, &nav)?;
    nav_cue::install(&nav, &list)?;

    let tools = dom::el_class("div", "header-tools")?;
    dom::append(&tools, &lesson_bar::build_add_button(SHELL)?)?;
    let lang = dom::el_class("button", "tool-button lang-switch")?;
    lang.set_attribute("type", "button")?;
    lang.set_attribute("data-testid", "lang-switch")?;
    lang.set_id("lang-switch");
    dom::set_i18n_attrs(&lang, &[("title", "lang-switch-title")])?;
    on_click(&lang, || switch_lang(ctx::lang().other()))?;
    dom::append(&tools, &lang)?;

    let projector = dom::el_i18n("button", "tool-button projector-toggle", "projector-toggle")?;
    projector.set_attribute("type", "button")?;
    projector.set_attribute("data-testid", "projector-toggle")?;
    projector.set_id("projector-toggle");
    dom::set_i18n_attrs(&projector, &[("title", "projector-toggle-title")])?;
    on_click(&projector, || set_projector(!ctx::projector()))?;
    dom::append(&tools, &projector)?;
    dom::append(&tools, &share::build_button()?)?;

    let help = dom::el_text("button", "tool-button help-button", "?")?;
    help.set_attribute("type", "button")?;
    help.set_attribute("data-testid", "help-button")?;
    dom::set_i18n_attrs(
        &help,
        &[
            ("aria-label", "help-button-label"),
            ("title", "help-button-label"),
        ],
    )?;
    on_click(&help, toggle_overlay)?;
    // Says so under "?" when the overlay's code cannot be fetched.
    let help_wrap = dom::el_class("span", "tool-wrap")?;
    let help_status = dom::el_class("span", "tool-status visually-hidden")?;
    help_status.set_id(HELP_STATUS_ID);
    help_status.set_attribute("role", "status")?;
    help_status.set_attribute("data-testid", "help-status")?;
    dom::append(&help_wrap, &help)?;
    dom::append(&help_wrap, &help_status)?;
    dom::append(&tools, &help_wrap)?;
    dom::append(&header, &tools)?;
    Ok(header)
}

/// One navigation link (top level or in the drills menu).
fn nav_link(def: &'static PageDef) -> Result<Element, JsValue> {
    let link = dom::el_i18n("a", "nav-link", nav_title_id(def))?;
    link.set_attribute("href", &nav_menu::href(def))?;
    link.set_attribute("data-page", def.id)?;
    link.set_attribute("data-testid", &format!("nav-{}", def.id))?;
    Ok(link)
}

/// The home page is "Home" in the navigation; other pages use their title.
fn nav_title_id(def: &PageDef) -> &'static str {
    if def.id == HOME_ID {
        "nav-home"
    } else {
        def.title_id
    }
}

fn build_footer() -> Result<Element, JsValue> {
    let footer = dom::el_class("footer", "site-footer")?;
    footer.set_attribute("data-testid", "site-footer")?;
    let disclaimer = dom::el_i18n("p", "disclaimer", "footer-disclaimer")?;
    disclaimer.set_attribute("data-testid", "disclaimer")?;
    dom::append(&footer, &disclaimer)?;
    let offline = dom::el_i18n("p", "offline-note", "footer-offline")?;
    dom::append(&footer, &offline)?;
    Ok(footer)
}

fn on_click(
    element: &Element,
    mut action: impl FnMut() -> Result<(), JsValue> + 'static,
) -> Result<(), JsValue> {
    dom::Listener::new(element, "click", move |_| report(action()))?.forever();
    Ok(())
}

/// Logs a failed shell action (the UI stays usable).
fn report(result: Result<(), JsValue>) {
    if let Err(error) = result {
        web_sys::console::error_2(&"BSV Playground:".into(), &error);
    }
}

/// The user switched language: apply it, save it, and put it in the URL once it is shown (its
/// strings may have to come first: until then the URL keeps the language shown).
pub(crate) fn switch_lang(lang: Lang) -> Result<(), JsValue> {
    dom::storage_set(LANG_STORAGE_KEY, lang.code());
    router::set_lang_in_url(true);
    show_lang_then(lang, router::sync_lang_in_url)
}

/// Makes `lang` current and re-renders every visible string, once its strings are loaded.
pub(crate) fn apply_lang(lang: Lang) -> Result<(), JsValue> {
    show_lang_then(lang, || {})
}

/// [`apply_lang`], then `then` once `lang` is shown.
fn show_lang_then(lang: Lang, then: fn()) -> Result<(), JsValue> {
    if has_strings(lang, routed_def()) {
        show_lang(lang)?;
        then();
        return Ok(());
    }
    wasm_bindgen_futures::spawn_local(async move {
        match lang_files::load(lang, page_strings(routed_def())).await {
            Ok(()) => {
                report(show_lang(lang));
                then();
            }
            Err(_) => report(Err(JsValue::from_str(&format!(
                "the {} strings could not be loaded",
                lang.code()
            )))),
        }
    });
    Ok(())
}

fn show_lang(lang: Lang) -> Result<(), JsValue> {
    ctx::set_lang(lang);
    apply_lang_chrome()?;
    if let Some(body) = dom::document()?.body() {
        dom::relocalize(&body)?;
    }
    update_title(routed_def())?;
    with_page(|page| page.relocalize());
    lesson_bar::render()?;
    Ok(())
}

/// `<html lang>` and the language button (it shows the other language, in that language).
fn apply_lang_chrome() -> Result<(), JsValue> {
    let document = dom::document()?;
    let lang = ctx::lang();
    if let Some(html) = document.document_element() {
        html.set_attribute("lang", lang.code())?;
    }
    if let Some(button) = document.get_element_by_id("lang-switch") {
        let other = lang.other();
        button.set_text_content(Some(other.native_name()));
        button.set_attribute("lang", other.code())?;
        button.set_attribute("title", &ctx::t("lang-switch-title"))?;
    }
    Ok(())
}

/// Turns projector mode on or off, saves it and tells the page.
pub(crate) fn set_projector(on: bool) -> Result<(), JsValue> {
    dom::storage_set(PROJECTOR_STORAGE_KEY, if on { "1" } else { "0" });
    show_projector(on)
}

/// Projector mode on or off in this window, not remembered.
fn show_projector(on: bool) -> Result<(), JsValue> {
    ctx::set_projector(on);
    apply_projector_class(on)?;
    with_page(|page| page.set_projector(on));
    Ok(())
}

fn apply_projector_class(on: bool) -> Result<(), JsValue> {
    let document = dom::document()?;
    if let Some(html) = document.document_element() {
        html.class_list().toggle_with_force("projector", on)?;
    }
    if let Some(button) = document.get_element_by_id("projector-toggle") {
        button.set_attribute("aria-pressed", if on { "true" } else { "false" })?;
    }
    Ok(())
}

/// The page the route names (mounted, or its chunk on its way).
fn routed_def() -> Option<&'static PageDef> {
    ROUTING.with(|routing| routing.def.get())
}

/// The Fluent files page `def` needs beyond the ones every page needs.
fn page_strings(def: Option<&'static PageDef>) -> &'static [&'static str] {
    def.map_or(&[], |def| def.strings)
}

/// The Fluent files the page the address names needs beyond the ones every page needs (what
/// the app loads before its first page).
pub(crate) fn first_page_strings() -> &'static [&'static str] {
    page_strings(page::find(PAGES, &router::current_route().page))
}

/// Whether every string `def` shows in `lang` is loaded.
fn has_strings(lang: Lang, def: Option<&'static PageDef>) -> bool {
    i18n::FIRST_FILES
        .iter()
        .chain(page_strings(def))
        .all(|file| ctx::has_file(lang, file))
}

/// After a route change: mark the current page in the navigation, set the document title.
pub(crate) fn route_changed(def: Option<&'static PageDef>) -> Result<(), JsValue> {
    let document = dom::document()?;
    let current = def.map(|d| d.id).unwrap_or("");
    if let Some(nav) = document.query_selector(".site-nav").ok().flatten() {
        for link in dom::matching(&nav, "a[data-page]")? {
            if link.get_attribute("data-page").as_deref() == Some(current) {
                link.set_attribute("aria-current", "page")?;
                // Measured after the page's first paint: measuring now would force the whole
                // new page's first layout inside the task that mounts it.
                let link = link.clone();
                schedule::after_paint(move || reveal_in_nav(&link))?;
            } else {
                link.remove_attribute("aria-current")?;
            }
        }
    }
    NAV_MENU.with(|slot| {
        if let Some(menu) = slot.borrow().as_ref() {
            menu.route_changed(current);
        }
    });
    drill_chain::route_changed(current, |id| SHELL.is_page(id))?;
    lesson_bar::render()?;
    update_title(def)
}

/// At phone width the navigation is one row that scrolls sideways: keep the current page's
/// link in view.
fn reveal_in_nav(link: &Element) {
    let Some(list) = link.closest("ul").ok().flatten() else {
        return;
    };
    let (Some(link), Some(list_el)) = (
        link.dyn_ref::<web_sys::HtmlElement>(),
        list.dyn_ref::<web_sys::HtmlElement>(),
    ) else {
        return;
    };
    let left = f64::from(link.offset_left() - list_el.offset_left());
    let right = left + f64::from(link.offset_width());
    let view = f64::from(list.client_width());
    let scrolled = f64::from(list.scroll_left());
    if right > scrolled + view {
        list.set_scroll_left((right - view) as i32);
    } else if left < scrolled {
        list.set_scroll_left(left as i32);
    }
}

/// `document.title`: "BSV Playground" at home, "<page> — BSV Playground" elsewhere.
fn update_title(def: Option<&'static PageDef>) -> Result<(), JsValue> {
    let app = ctx::t("app-name");
    let title = match def {
        Some(def) if def.id == HOME_ID => format!("{app} — {}", ctx::t("app-subtitle")),
        Some(def) => format!("{} — {app}", ctx::t(def.title_id)),
        None => format!("{} — {app}", ctx::t("notfound-title")),
    };
    dom::document()?.set_title(&title);
    Ok(())
}

fn install_keys() -> Result<(), JsValue> {
    let window = dom::window()?;
    // A presenter's keys first, before any page or control sees them: a remote always works.
    dom::Listener::capture(&window, "keydown", |event| {
        if let Some(key) = event.dyn_ref::<KeyboardEvent>() {
            report(on_presenter_key(key));
        }
    })?
    .forever();
    dom::Listener::new(&window, "keydown", |event| {
        if let Some(key) = event.dyn_ref::<KeyboardEvent>() {
            report(on_keydown(key));
        }
    })?
    .forever();
    Ok(())
}

/// A key while a lesson is presented ([`lesson_bar::on_key`]): taken before the page and the
/// focused control see it, unless the `?` overlay or a dialog (Share) is open.
fn on_presenter_key(event: &KeyboardEvent) -> Result<(), JsValue> {
    if overlay::is_open() || keymap::dialog_open() {
        return Ok(());
    }
    if let Some(requests) = lesson_bar::on_key(event)? {
        event.prevent_default();
        event.stop_propagation();
        return perform_all(requests);
    }
    Ok(())
}

fn on_keydown(event: &KeyboardEvent) -> Result<(), JsValue> {
    if overlay::is_open() {
        return overlay::on_key(event);
    }
    if let Some(action) = keymap::shell_key(event) {
        event.prevent_default();
        if event.repeat() {
            return Ok(());
        }
        return match action {
            ShellKey::Help => open_overlay(),
            ShellKey::Projector => set_projector(!ctx::projector()),
            ShellKey::Lang => switch_lang(ctx::lang().other()),
        };
    }
    if keymap::page_may_take(event) && with_page(|page| page.on_key(event)) == Some(true) {
        event.prevent_default();
        return Ok(());
    }
    if keymap::page_may_take_over_control(event)
        && with_page(|page| page.on_key_over_control(event)) == Some(true)
    {
        event.prevent_default();
        return Ok(());
    }
    let exists = |id: &str| SHELL.is_page(id);
    if section_keys::on_key(event, current_page_id(), exists)? {
        event.prevent_default();
    }
    Ok(())
}

/// The overlay with the shell's keys and the mounted page's.
/// What "?" opens ([`overlay::open`]).
type OpenOverlay = fn(&[page::Shortcut], &[page::Shortcut]) -> Result<(), JsValue>;

/// The shortcuts overlay: a wasm chunk of its own, fetched on the first "?".
#[cfg(feature = "split")]
#[wasm_split_helpers::wasm_split(shortcuts_overlay, fallible)]
fn overlay_opener() -> Result<OpenOverlay, page::SplitLoaderError> {
    Ok(overlay::open)
}

/// Without the `split` feature the overlay is in the one wasm.
#[cfg(not(feature = "split"))]
async fn overlay_opener() -> Result<OpenOverlay, page::SplitLoaderError> {
    Ok(overlay::open)
}

/// Opens the shortcuts overlay once its code is here (at once after the first time); if it
/// cannot be fetched, says so under "?" (the next press tries again).
fn open_overlay() -> Result<(), JsValue> {
    wasm_bindgen_futures::spawn_local(async {
        let loaded = overlay_opener().await;
        let status = dom::document()
            .ok()
            .and_then(|d| d.get_element_by_id(HELP_STATUS_ID));
        if let Some(status) = &status {
            dom::clear(status);
            let failed = loaded.is_err();
            let classes = status.class_list();
            let _ = classes.toggle_with_force("visually-hidden", !failed);
            let _ = classes.toggle_with_force("tool-failed", failed);
            let _ = status.set_attribute("role", if failed { "alert" } else { "status" });
            if failed {
                status.set_text_content(Some(&ctx::t("help-failed")));
            }
        }
        if let Ok(open) = loaded {
            if !overlay::is_open() {
                let page_keys = with_page(|page| page.shortcuts()).unwrap_or_default();
                report(open(keymap::SHELL, &page_keys));
            }
        }
    });
    Ok(())
}

fn toggle_overlay() -> Result<(), JsValue> {
    if overlay::is_open() {
        overlay::close();
        Ok(())
    } else {
        open_overlay()
    }
}

// ---------- Hosting the page ----------

struct Mounted {
    page_id: &'static str,
    page: Box<dyn Page>,
}

thread_local! {
    static NAV_MENU: RefCell<Option<Rc<NavMenu>>> = const { RefCell::new(None) };
    static MOUNTED: RefCell<Option<Mounted>> = const { RefCell::new(None) };
}

/// Calls `f` with the mounted page, if any (`None` also while the page is being swapped).
fn with_page<R>(f: impl FnOnce(&dyn Page) -> R) -> Option<R> {
    MOUNTED
        .try_with(|cell| {
            let mounted = cell.try_borrow().ok()?;
            mounted.as_ref().map(|m| f(m.page.as_ref()))
        })
        .ok()
        .flatten()
}

/// Carries out what a page or the lesson presenter asked for.
fn perform(request: ShellRequest) -> Result<(), JsValue> {
    match request {
        ShellRequest::StepPage if current_page_id().is_none() && routed_def().is_some() => {
            ROUTING.with(|routing| routing.pending.borrow_mut().push(request));
            Ok(())
        }
        ShellRequest::StepPage => step_page(),
        ShellRequest::Remount => mount_route(&router::current_route()),
        ShellRequest::Projector(on) if ctx::projector() != on => set_projector(on),
        ShellRequest::Projector(_) => Ok(()),
        ShellRequest::ProjectorHere => show_projector(true),
        ShellRequest::Lang(lang) if lang != ctx::lang() => switch_lang(lang),
        ShellRequest::Lang(_) => Ok(()),
        ShellRequest::Settled => {
            embed::mounted();
            mark_ready()
        }
    }
}

fn perform_all(requests: Vec<ShellRequest>) -> Result<(), JsValue> {
    requests.into_iter().try_for_each(perform)
}

/// Sends the mounted page one PageDown, as a presenter remote would.
fn step_page() -> Result<(), JsValue> {
    let init = web_sys::KeyboardEventInit::new();
    init.set_key("PageDown");
    init.set_bubbles(true);
    init.set_cancelable(true);
    let event = KeyboardEvent::new_with_keyboard_event_init_dict("keydown", &init)?;
    with_page(|page| page.on_key(&event));
    Ok(())
}

/// Mounts the route of the address again (its state read afresh from the address).
fn remount() -> Result<(), JsValue> {
    mount_route(&router::current_route())
}

/// Whether the route is settled: its page built and answering input, or no page (not
/// found).
fn page_settled() -> bool {
    routed_def().is_none() || with_page(|page| page.settled()).unwrap_or(false)
}

/// The id of the mounted page (`None` on the not-found page).
pub fn current_page_id() -> Option<&'static str> {
    MOUNTED
        .try_with(|cell| cell.try_borrow().ok()?.as_ref().map(|m| m.page_id))
        .ok()
        .flatten()
}

/// Drops the current page and mounts the one `route` names: at once if its chunk is in, else
/// after showing the page's frame while the chunk loads. The frame www/boot.js painted goes in
/// the same task.
fn mount_route(route: &Route) -> Result<(), JsValue> {
    let result = mount_route_in_main(route);
    if let Some(frame) = dom::document()?.get_element_by_id("boot-frame") {
        frame.remove();
    }
    result
}

fn mount_route_in_main(route: &Route) -> Result<(), JsValue> {
    router::set_shown_page(&route.page);
    if let Some(lang) = route.lang() {
        router::set_lang_in_url(true);
        if lang != ctx::lang() {
            apply_lang(lang)?;
        }
    }
    let old = MOUNTED.with(|cell| cell.try_borrow_mut().ok().and_then(|mut m| m.take()));
    drop(old);
    let main = main_element()?;
    dom::clear(&main);
    let generation = ROUTING.with(|routing| {
        routing.generation.set(routing.generation.get() + 1);
        routing.generation.get()
    });
    let def = page::find(PAGES, &route.page);
    ROUTING.with(|routing| routing.def.set(def));
    match def {
        Some(def) => load_page(def, generation, route.page_query())?,
        None => {
            set_pending(false)?;
            render_not_found(&main)?;
            warm_after_paint(None)?;
            mark_ready()?;
        }
    }
    route_changed(def)?;
    if router::lang_in_url() && route.lang() != Some(ctx::lang()) {
        router::sync_lang_in_url();
    }
    Ok(())
}

/// Which page the route names and how many routings there were: a chunk that lands after the
/// route changed again is not mounted.
struct Routing {
    def: Cell<Option<&'static PageDef>>,
    generation: Cell<u64>,
    /// Requests for the page (a presenter's step) made while its chunk loads.
    pending: RefCell<Vec<ShellRequest>>,
}

thread_local! {
    static ROUTING: Routing = const {
        Routing {
            def: Cell::new(None),
            generation: Cell::new(0),
            pending: RefCell::new(Vec::new()),
        }
    };
}

fn is_current(generation: u64) -> bool {
    ROUTING.with(|routing| routing.generation.get()) == generation
}

/// Mounts page `def` from its chunk: in this task if the chunk and its strings are in; else
/// shows the page's frame and its loading line (once the page's strings are in, so that the
/// frame's heading and lede are the page's own), and mounts when the chunk lands (if the route
/// is still this one), or shows the failure with a Retry button.
fn load_page(
    def: &'static PageDef,
    generation: u64,
    query: Vec<(String, String)>,
) -> Result<(), JsValue> {
    let mut load = (def.load)();
    // The page's stylesheet is asked for with its code, and the page mounts once it is in.
    let styled = def.sheet.is_none_or(|sheet| {
        late_style::link(sheet).is_some_and(|link| late_style::has_sheet(&link))
    });
    // The chunk's request is made on the loader's first poll.
    let mut poll = Context::from_waker(Waker::noop());
    let landed = match load.as_mut().poll(&mut poll) {
        Poll::Ready(result) => Some(result),
        Poll::Pending => None,
    };
    let lang = ctx::lang();
    let framed = has_strings(lang, Some(def));
    // The tab's first page is shown as its frame first, even when its code is in: the frame (the
    // page's head) is painted in the task that builds the shell, and the page is built in a
    // task of its own after that paint.
    let first = generation == 1;
    let landed = match landed {
        Some(result) if framed && styled && !first => {
            return loaded(def, generation, query, result.map_err(|e| e.to_string()));
        }
        other => other,
    };
    // Whether the frame has been painted (set once it is).
    let painted = Rc::new(Cell::new(false));
    let show_frame = {
        let painted = Rc::clone(&painted);
        move || -> Result<(), JsValue> {
            page_frame::show_loading(&main_element()?, def)?;
            let painted = Rc::clone(&painted);
            schedule::after_paint(move || painted.set(true))
        }
    };
    if framed {
        show_frame()?;
    }
    set_pending(true)?;
    wasm_bindgen_futures::spawn_local(async move {
        let strings = lang_files::load(lang, def.strings).await;
        if !framed && strings.is_ok() && is_current(generation) {
            report(show_frame());
        }
        lang_files::parse_in_tasks(lang).await;
        let chunk = match landed {
            Some(result) => result,
            None => load.await,
        };
        // The frame is on screen before the page replaces it (a phone sees the page's head at
        // once, and its largest paint is the frame's): if its code came first, the page waits
        // for that paint.
        if !painted.get() {
            schedule::painted().await;
        }
        if let Some(sheet) = def.sheet {
            late_style::linked(sheet).await;
        }
        let result = match (chunk, strings) {
            (Ok(mount), Ok(())) => Ok(mount),
            (Err(error), _) => Err(error.to_string()),
            (_, Err(error)) => Err(error.as_string().unwrap_or_default()),
        };
        if is_current(generation) {
            report(loaded(def, generation, query, result));
        }
    });
    Ok(())
}

/// The loader's `bsv-chunk-progress` events (bytes of a chunk arrived) move the loading line's
/// progress bar, while it is shown.
fn install_load_progress() -> Result<(), JsValue> {
    let window = dom::window()?;
    dom::Listener::new(&window, "bsv-chunk-progress", |event| {
        let detail = event
            .dyn_ref::<web_sys::CustomEvent>()
            .map(|e| e.detail())
            .unwrap_or(JsValue::UNDEFINED);
        let number = |key: &str| {
            js_sys::Reflect::get(&detail, &JsValue::from_str(key))
                .ok()
                .and_then(|v| v.as_f64())
                .unwrap_or(0.0)
        };
        if let Ok(main) = main_element() {
            report(page_frame::show_progress(
                &main,
                number("loaded"),
                number("total"),
            ));
        }
    })?
    .forever();
    Ok(())
}

/// `html[data-app-ready]`: the first route is settled (its page mounted, or the message that
/// it could not be loaded, or "not found"); tests and the first-frame bench wait for it.
fn mark_ready() -> Result<(), JsValue> {
    if let Some(html) = dom::document()?.document_element() {
        if !html.has_attribute("data-app-ready") {
            html.set_attribute("data-app-ready", "1")?;
        }
    }
    Ok(())
}

/// While a page's frame stands in for it (`#app[data-page-pending]`), what stands below the
/// page (the drill chain, the footer) is not shown: shown under the short frame, it would jump
/// down when the page comes.
fn set_pending(pending: bool) -> Result<(), JsValue> {
    if let Some(app) = dom::document()?.get_element_by_id(APP_ID) {
        if pending {
            app.set_attribute("data-page-pending", "")?;
        } else {
            app.remove_attribute("data-page-pending")?;
        }
    }
    Ok(())
}

/// The chunk of page `def` landed (or failed to).
fn loaded(
    def: &'static PageDef,
    generation: u64,
    query: Vec<(String, String)>,
    result: Result<page::MountFn, String>,
) -> Result<(), JsValue> {
    let main = main_element()?;
    set_pending(false)?;
    match result {
        Ok(mount) => {
            // The page fills `<main>` around its frame's heading (`page_frame::fill`); a frame
            // left over from a page that builds otherwise goes.
            mount_page(def, mount, &main, query)?;
            page_frame::remove_leftover(&main)?;
            embed::mounted();
            warm_after_paint(Some(def))?;
            if with_page(|page| page.settled()).unwrap_or(true) {
                mark_ready()?;
            }
            let pending: Vec<ShellRequest> = ROUTING.with(|routing| routing.pending.take());
            perform_all(pending)
        }
        Err(error) => {
            web_sys::console::warn_1(
                &format!(
                    "BSV Playground: the code or strings of page '{}' could not be loaded: {error}",
                    def.id
                )
                .into(),
            );
            let retry = page_frame::show_failed(&main, def, has_strings(ctx::lang(), Some(def)))?;
            mark_ready()?;
            let query = RefCell::new(Some(query));
            dom::Listener::new(&retry, "click", move |_| {
                if let Some(query) = query.borrow_mut().take() {
                    if is_current(generation) {
                        report(load_page(def, generation, query));
                    }
                }
            })?
            .forever();
            Ok(())
        }
    }
}

fn mount_page(
    def: &'static PageDef,
    mount: page::MountFn,
    main: &Element,
    query: Vec<(String, String)>,
) -> Result<(), JsValue> {
    let mount_ctx = MountCtx {
        root: main.clone(),
        query,
        shell: SHELL,
    };
    match mount(mount_ctx) {
        Ok(page) => {
            if ctx::projector() {
                page.set_projector(true);
            }
            MOUNTED.with(|cell| {
                if let Ok(mut mounted) = cell.try_borrow_mut() {
                    *mounted = Some(Mounted {
                        page_id: def.id,
                        page,
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
fn render_not_found(main: &Element) -> Result<(), JsValue> {
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
