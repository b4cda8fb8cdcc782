//! The browser UI (wasm32 only): the app shell and its pages, started by `startApp()` from
//! `www/bootstrap.js`; `pageTable()` tells the browser tests the page table. `startApp` is an
//! ordinary export, not `#[wasm_bindgen(start)]`, because the same wasm also runs under Node
//! (kernel tests, `runRecipe`) where there is no DOM to build.
//!
//! - [`shell`] hosts the page the [`router`] names, with the header ([`nav_menu`]), the
//!   [`lesson_bar`] (presenting in [`lesson_present`], with [`lesson_focus`]), the
//!   [`drill_chain`], [`section_keys`], the [`overlay`] and the [`update_banner`]; it alone
//!   imports the page table, [`pages`].
//! - [`page`] is the contract between the shell and a page; pages are built from the [`kit`],
//!   [`dom`], [`ctx`] (language, projector mode) and [`schedule`] (timers, after paint).
//! - [`embed`] and [`embed_api`]: a page embedded in another site (`embed=1`) and its
//!   postMessage API.
//! - [`exercises`]: a page's exercises list, the chunk its section fetches
//!   ([`kit::exercise_slot`]).
//! - [`download`], [`clipboard`], [`command_line`]: files, copies and shell quoting.
//! - [`modal`]: the modal dialog of the `?` overlay and the share dialog; [`split_point`]: the
//!   shell's parts cut into wasm chunks of their own, fetched on first use.

use wasm_bindgen::prelude::*;

pub mod clipboard;
pub mod command_line;
pub mod ctx;
pub mod dom;
pub mod download;
pub mod drill_chain;
pub mod embed;
pub mod embed_api;
pub mod exercises;
pub mod kit;
pub mod lang_files;
pub mod lesson_bar;
pub mod lesson_focus;
pub mod lesson_present;
pub mod modal;
pub mod nav_cue;
pub mod nav_menu;
pub mod overlay;
pub mod page;
pub mod page_frame;
pub mod pages;
pub mod present_two;
pub mod router;
pub mod schedule;
pub mod section_keys;
pub mod share;
pub mod share_dialog;
pub mod shell;
pub mod split_point;
pub mod update_banner;

/// Builds the app into `#app` and routes to the page the URL names. Installs a panic hook
/// first: a panic is logged with `console.error` and a localized banner says that the work is
/// kept in the URL and offers a reload.
/// Resolves once the first page is mounted (or its chunk is on its way); rejects if the
/// strings of the visitor's language that the page needs could not be loaded.
#[wasm_bindgen(js_name = startApp)]
pub async fn start_app() -> Result<(), JsValue> {
    install_panic_hook();
    let lang = shell::initial_lang();
    lang_files::load(lang, shell::first_page_strings())
        .await
        .map_err(|error| {
            let reason = error.as_string().unwrap_or_default();
            JsValue::from_str(&format!("{} strings: {reason}", lang.code()))
        })?;
    lang_files::parse_in_tasks(lang).await;
    // The shell and the first route's frame in two tasks, each short on a slow phone.
    if shell::start(lang)? {
        schedule::next_task().await;
        shell::mount_first_route()?;
    }
    Ok(())
}

/// The page table, in navigation order: `[{ id, group, tool }]`, `group` being the Drills
/// menu's group (`"kinematics"`, `"dynamics"`, `"trajectories"`, `"planning"`) or `null` for a
/// top-level link, `tool` whether it is a tool page with no link in the header. The browser
/// tests check the navigation and the drill chain against it.
#[wasm_bindgen(js_name = pageTable)]
pub fn page_table() -> Result<js_sys::Array, JsValue> {
    let table = js_sys::Array::new();
    for def in pages::PAGES {
        let entry = js_sys::Object::new();
        js_sys::Reflect::set(&entry, &"id".into(), &def.id.into())?;
        let group = def.nav.group().map_or(JsValue::NULL, JsValue::from);
        js_sys::Reflect::set(&entry, &"group".into(), &group)?;
        let tool = def.nav == page::Nav::Tool;
        js_sys::Reflect::set(&entry, &"tool".into(), &tool.into())?;
        table.push(&entry);
    }
    Ok(table)
}

fn install_panic_hook() {
    std::panic::set_hook(Box::new(|info| {
        web_sys::console::error_1(&JsValue::from_str(&format!(
            "BSV Playground stopped: {info}"
        )));
        let _ = show_crash_banner();
    }));
}

/// The visible "something went wrong" banner at the top of the page. Its reload button is
/// the browser's own `location.reload` bound to `location` (no wasm closure, so it works even
/// though the wasm instance is no longer usable; no `Function("...")`, which the strict CSP
/// blocks as eval).
fn show_crash_banner() -> Result<(), JsValue> {
    let document = dom::document()?;
    if document.get_element_by_id("crash-banner").is_some() {
        return Ok(());
    }
    let body = document
        .body()
        .ok_or_else(|| JsValue::from_str("no body"))?;
    let banner = dom::el_class("div", "crash-banner")?;
    banner.set_id("crash-banner");
    banner.set_attribute("role", "alert")?;
    banner.set_attribute("data-testid", "crash-banner")?;
    let title = dom::el_text("strong", "", &ctx::t("crash-title"))?;
    dom::append(&banner, &title)?;
    dom::append(&banner, &dom::el_text("span", "", &ctx::t("crash-body"))?)?;
    let reload = dom::el_text("button", "tool-button", &ctx::t("crash-reload"))?;
    reload.set_attribute("type", "button")?;
    let location = dom::window()?.location();
    let action = js_sys::Reflect::get(&location, &JsValue::from_str("reload"))?
        .dyn_into::<js_sys::Function>()?
        .bind0(&location);
    reload.add_event_listener_with_callback("click", &action)?;
    dom::append(&banner, &reload)?;
    body.prepend_with_node_1(&banner)
}
