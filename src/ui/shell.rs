//! The app shell: header (product name and subtitle, navigation of the pages that exist,
//! language switch, projector toggle, `?` button), the `<main>` the router fills, the footer
//! with the safety disclaimer, and the shell's keys.
//!
//! - Language: `?lang=` in the URL, else the saved choice (localStorage `bsv.lang`), else
//!   `navigator.languages`, else English. Only an explicit switch (button or `l`) is saved.
//!   A switch re-renders every `[data-i18n]` / `[data-i18n-attr]`, `<html lang>` and
//!   `document.title`, then calls the page's `relocalize()`; nothing reloads.
//! - Projector mode: class `projector` on `<html>` (CSS does type, lines and contrast), saved
//!   in localStorage `bsv.projector`, and passed to the page's `set_projector()`.
//! - Keys (ignored with Ctrl/Alt/Meta and while typing in a field): `?` shortcut list, `p`
//!   projector, `l` language. Everything else goes to the page's `on_key`, so presenter
//!   remotes (PageUp/PageDown, arrows, `b`, `.`) keep working as the page and the
//!   presentation software expect.

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::{Element, KeyboardEvent};

use crate::i18n::{self, Lang};
use crate::ui::page::PageDef;
use crate::ui::{ctx, dom, overlay, pages, router};

/// localStorage key of the language the user chose.
pub const LANG_STORAGE_KEY: &str = "bsv.lang";
/// localStorage key of projector mode (`"1"` on, `"0"` off).
pub const PROJECTOR_STORAGE_KEY: &str = "bsv.projector";

const APP_ID: &str = "app";
const MAIN_ID: &str = "app-main";

/// Builds the shell into `#app` (or `<body>`), applies the initial language and projector
/// mode, installs the keys and starts the router. Calling it twice does nothing.
pub(crate) fn start() -> Result<(), JsValue> {
    let document = dom::document()?;
    if document.get_element_by_id(MAIN_ID).is_some() {
        return Ok(());
    }
    ctx::set_lang(initial_lang());
    ctx::set_projector(dom::storage_get(PROJECTOR_STORAGE_KEY).as_deref() == Some("1"));

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
    dom::append(&app, &build_header()?)?;
    let main = dom::el_class("main", "site-main")?;
    main.set_id(MAIN_ID);
    main.set_attribute("tabindex", "-1")?;
    dom::append(&app, &main)?;
    dom::append(&app, &build_footer()?)?;
    if let Some(status) = document.get_element_by_id("boot-status") {
        status.remove();
    }

    apply_projector_class(ctx::projector())?;
    apply_lang_chrome()?;
    install_keys()?;
    router::start()?;
    if let Some(html) = document.document_element() {
        html.set_attribute("data-app-ready", "1")?;
    }
    Ok(())
}

/// `?lang=`, else the saved choice, else the browser's languages, else English.
fn initial_lang() -> Lang {
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

fn build_header() -> Result<Element, JsValue> {
    let header = dom::el_class("header", "site-header")?;
    header.set_attribute("data-testid", "site-header")?;

    let brand = dom::el_class("div", "brand")?;
    let name = dom::el_i18n("a", "brand-name", "app-name")?;
    name.set_attribute("href", "#/")?;
    name.set_attribute("data-testid", "brand")?;
    dom::append(&brand, &name)?;
    let subtitle = dom::el_i18n("span", "brand-subtitle", "app-subtitle")?;
    subtitle.set_attribute("data-testid", "brand-subtitle")?;
    dom::append(&brand, &subtitle)?;
    dom::append(&header, &brand)?;

    let nav = dom::el_class("nav", "site-nav")?;
    nav.set_attribute("data-testid", "site-nav")?;
    dom::set_i18n_attrs(&nav, &[("aria-label", "nav-label")])?;
    let list = dom::el("ul")?;
    for def in pages::PAGES {
        let item = dom::el("li")?;
        let link = dom::el_i18n("a", "nav-link", nav_title_id(def))?;
        link.set_attribute("href", &router::build_hash(def.id, &[]))?;
        link.set_attribute("data-page", def.id)?;
        link.set_attribute("data-testid", &format!("nav-{}", def.id))?;
        dom::append(&item, &link)?;
        dom::append(&list, &item)?;
    }
    dom::append(&nav, &list)?;
    dom::append(&header, &nav)?;

    let tools = dom::el_class("div", "header-tools")?;
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
    on_click(&help, overlay::toggle)?;
    dom::append(&tools, &help)?;
    dom::append(&header, &tools)?;
    Ok(header)
}

/// The home page is "Home" in the navigation; other pages use their title.
fn nav_title_id(def: &PageDef) -> &'static str {
    if def.id == pages::HOME_ID {
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

/// The user switched language: apply it, save it, and put it in the URL.
pub(crate) fn switch_lang(lang: Lang) -> Result<(), JsValue> {
    dom::storage_set(LANG_STORAGE_KEY, lang.code());
    router::set_lang_in_url(true);
    apply_lang(lang)?;
    router::sync_lang_in_url();
    Ok(())
}

/// Makes `lang` current and re-renders every visible string.
pub(crate) fn apply_lang(lang: Lang) -> Result<(), JsValue> {
    ctx::set_lang(lang);
    apply_lang_chrome()?;
    if let Some(body) = dom::document()?.body() {
        dom::relocalize(&body)?;
    }
    update_title(current_def())?;
    router::with_page(|page| page.relocalize());
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
    ctx::set_projector(on);
    dom::storage_set(PROJECTOR_STORAGE_KEY, if on { "1" } else { "0" });
    apply_projector_class(on)?;
    router::with_page(|page| page.set_projector(on));
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

fn current_def() -> Option<&'static PageDef> {
    router::current_page_id().and_then(pages::find)
}

/// After a route change: mark the current page in the navigation, set the document title.
pub(crate) fn route_changed(def: Option<&'static PageDef>) -> Result<(), JsValue> {
    let document = dom::document()?;
    let current = def.map(|d| d.id).unwrap_or("");
    if let Some(nav) = document.query_selector(".site-nav").ok().flatten() {
        for link in dom::matching(&nav, "a[data-page]")? {
            if link.get_attribute("data-page").as_deref() == Some(current) {
                link.set_attribute("aria-current", "page")?;
            } else {
                link.remove_attribute("aria-current")?;
            }
        }
    }
    update_title(def)
}

/// `document.title`: "BSV Playground" at home, "<page> — BSV Playground" elsewhere.
fn update_title(def: Option<&'static PageDef>) -> Result<(), JsValue> {
    let app = ctx::t("app-name");
    let title = match def {
        Some(def) if def.id == pages::HOME_ID => format!("{app} — {}", ctx::t("app-subtitle")),
        Some(def) => format!("{} — {app}", ctx::t(def.title_id)),
        None => format!("{} — {app}", ctx::t("notfound-title")),
    };
    dom::document()?.set_title(&title);
    Ok(())
}

fn install_keys() -> Result<(), JsValue> {
    let window = dom::window()?;
    dom::Listener::new(&window, "keydown", |event| {
        if let Some(key) = event.dyn_ref::<KeyboardEvent>() {
            report(on_keydown(key));
        }
    })?
    .forever();
    Ok(())
}

fn on_keydown(event: &KeyboardEvent) -> Result<(), JsValue> {
    if overlay::is_open() {
        return overlay::on_key(event);
    }
    if event.ctrl_key() || event.meta_key() || event.alt_key() || event.default_prevented() {
        return Ok(());
    }
    if dom::is_typing_target(event.target()) {
        return Ok(());
    }
    let key = event.key();
    let plain = !event.shift_key();
    let shell_key = match key.as_str() {
        "?" => Some(ShellKey::Help),
        "p" | "P" if plain => Some(ShellKey::Projector),
        "l" | "L" if plain => Some(ShellKey::Lang),
        _ => None,
    };
    match shell_key {
        Some(action) => {
            event.prevent_default();
            if event.repeat() {
                return Ok(());
            }
            match action {
                ShellKey::Help => overlay::open(),
                ShellKey::Projector => set_projector(!ctx::projector()),
                ShellKey::Lang => switch_lang(ctx::lang().other()),
            }
        }
        None => {
            if router::with_page(|page| page.on_key(event)) == Some(true) {
                event.prevent_default();
            }
            Ok(())
        }
    }
}

enum ShellKey {
    Help,
    Projector,
    Lang,
}

/// The shell's own keys for the `?` overlay: keys as shown and the Fluent id of the action.
pub(crate) const SHELL_SHORTCUTS: &[(&str, &str)] = &[
    ("?", "key-help"),
    ("P", "key-projector"),
    ("L", "key-lang"),
    ("Esc", "key-escape"),
];
