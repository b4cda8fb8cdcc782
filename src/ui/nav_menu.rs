//! The navigation's "Drills" menu: a disclosure button in the header and a panel of the drill
//! pages in groups (kinematics, dynamics and control, trajectories, planning), so the header
//! stays one row however many drill pages there are. A page's group is its [`Nav`] in the page
//! table; groups and pages follow the table's order. Pages in no group are top-level links.
//!
//! The panel opens and closes with the button (`aria-expanded`), closes on `Escape` (focus back
//! on the button), on a click outside it and on every route change. The button is marked
//! current when the page shown is in the menu.

use std::rc::Rc;

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::{Element, Event, KeyboardEvent, Node};

use crate::ui::page::{Nav, PageDef};
use crate::ui::{dom, router};

const MENU_ID: &str = "nav-menu";

/// The menu's button and panel (both in the header; the shell holds them for its life).
pub(crate) struct NavMenu {
    item: Element,
    button: Element,
    panel: Element,
    /// The ids of the pages in the menu.
    ids: Vec<&'static str>,
}

/// Builds `<li>` with the button and the panel of `pages`' groups; `link` makes one page link
/// exactly as the shell makes its top-level ones.
pub(crate) fn build(
    pages: &'static [PageDef],
    link: impl Fn(&'static PageDef) -> Result<Element, JsValue>,
) -> Result<Rc<NavMenu>, JsValue> {
    let item = dom::el_class("li", "nav-menu-item")?;
    let button = dom::el_class("button", "nav-link nav-menu-button")?;
    button.set_attribute("type", "button")?;
    button.set_attribute("aria-expanded", "false")?;
    button.set_attribute("aria-controls", MENU_ID)?;
    button.set_attribute("data-testid", "nav-menu-button")?;
    let label = dom::el_i18n("span", "", "nav-drills-menu")?;
    dom::append(&button, &label)?;
    let caret = dom::el_text("span", "nav-menu-caret", "▾")?;
    caret.set_attribute("aria-hidden", "true")?;
    dom::append(&button, &caret)?;
    dom::append(&item, &button)?;

    let panel = dom::el_class("div", "nav-menu")?;
    panel.set_id(MENU_ID);
    panel.set_attribute("data-testid", "nav-menu")?;
    panel.set_attribute("hidden", "")?;
    // The groups in the order the table first names them, each with its pages in table order.
    let mut groups: Vec<(Nav, &'static str)> = Vec::new();
    for def in pages {
        if let Some(key) = def.nav.group() {
            if !groups.iter().any(|(nav, _)| *nav == def.nav) {
                groups.push((def.nav, key));
            }
        }
    }
    let mut ids = Vec::new();
    for (nav, key) in groups {
        let defs = pages.iter().filter(|def| def.nav == nav);
        let title_id = format!("nav-group-{key}");
        let group = dom::el_class("div", "nav-group")?;
        let heading = dom::el_i18n("p", "nav-group-title", &title_id)?;
        let heading_id = format!("{title_id}-heading");
        heading.set_id(&heading_id);
        dom::append(&group, &heading)?;
        let list = dom::el("ul")?;
        list.set_attribute("aria-labelledby", &heading_id)?;
        for def in defs {
            ids.push(def.id);
            let li = dom::el("li")?;
            dom::append(&li, &link(def)?)?;
            dom::append(&list, &li)?;
        }
        dom::append(&group, &list)?;
        dom::append(&panel, &group)?;
    }
    dom::append(&item, &panel)?;

    let menu = Rc::new(NavMenu {
        item,
        button,
        panel,
        ids,
    });
    menu.listen()?;
    Ok(menu)
}

impl NavMenu {
    pub(crate) fn item(&self) -> &Element {
        &self.item
    }

    fn is_open(&self) -> bool {
        self.button.get_attribute("aria-expanded").as_deref() == Some("true")
    }

    /// Opens or closes the panel.
    pub(crate) fn set_open(&self, open: bool) {
        let _ = self
            .button
            .set_attribute("aria-expanded", if open { "true" } else { "false" });
        dom::show(&self.panel, open);
    }

    /// After a route change: closed, and the button marked when the page is one of the menu's.
    pub(crate) fn route_changed(&self, current: &str) {
        self.set_open(false);
        let inside = self.ids.contains(&current);
        let _ = self
            .button
            .class_list()
            .toggle_with_force("has-current", inside);
    }

    fn listen(self: &Rc<Self>) -> Result<(), JsValue> {
        let menu = Rc::clone(self);
        dom::Listener::new(&self.button, "click", move |_| {
            menu.set_open(!menu.is_open());
        })?
        .forever();

        let menu = Rc::clone(self);
        dom::Listener::new(&self.item, "keydown", move |event: Event| {
            let Some(key) = event.dyn_ref::<KeyboardEvent>() else {
                return;
            };
            if matches!(key.key().as_str(), "Escape" | "Esc") && menu.is_open() {
                key.prevent_default();
                key.stop_propagation();
                menu.set_open(false);
                dom::focus(&menu.button);
            }
        })?
        .forever();

        // A press anywhere outside the menu closes it (a link inside closes it through the
        // route change).
        let menu = Rc::clone(self);
        let document = dom::document()?;
        dom::Listener::new(&document, "pointerdown", move |event: Event| {
            if !menu.is_open() {
                return;
            }
            let inside = event
                .target()
                .and_then(|t| t.dyn_into::<Node>().ok())
                .is_some_and(|node| menu.item.contains(Some(&node)));
            if !inside {
                menu.set_open(false);
            }
        })?
        .forever();

        // Focus leaving the menu by Tab closes it too.
        let menu = Rc::clone(self);
        dom::Listener::new(&self.item, "focusout", move |event: Event| {
            let next = event
                .dyn_ref::<web_sys::FocusEvent>()
                .and_then(|f| f.related_target())
                .and_then(|t| t.dyn_into::<Node>().ok());
            if let Some(next) = next {
                if !menu.item.contains(Some(&next)) {
                    menu.set_open(false);
                }
            }
        })?
        .forever();
        Ok(())
    }
}

/// The href of a page's link (the same for top-level links and menu links).
pub(crate) fn href(def: &PageDef) -> String {
    router::build_hash(def.id, &[])
}
