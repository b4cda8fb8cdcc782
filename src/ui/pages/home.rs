//! The home page: the headline and introduction beside a live 2R arm a visitor drags
//! (`home_arm`), then the tiles, recipe cards and tools table (`home_cards`), a wasm chunk of
//! their own fetched once the arm is live (their pictures run every recipe's kernel); a line
//! stands in their place while they load, and says so with Retry if they cannot be fetched.
//! Every text is a `data-i18n` message, so a language switch needs nothing from the page
//! itself.

use std::rc::Rc;

use wasm_bindgen::prelude::*;
use web_sys::{Element, KeyboardEvent};

use super::home_arm::{self, HomeArm};
use super::home_cards;
use super::home_progress::Keep;
use crate::ui::dom::{append, el_class, el_i18n};
use crate::ui::page::{MountCtx, Page, ShellLink, Shortcut, SplitLoaderError};
use crate::ui::page_frame;

/// The home page (`#/`): markup, every text a `data-i18n` message, the live arm, and what
/// the chunk of its tiles keeps while the page is shown (the progress' listeners).
pub struct HomePage {
    arm: Rc<HomeArm>,
    _keep: Keep,
}

impl Page for HomePage {
    fn mount(ctx: MountCtx) -> Result<HomePage, JsValue> {
        let keep = Keep::default();
        let arm = build(&ctx.root, ctx.shell, &keep)?;
        Ok(HomePage { arm, _keep: keep })
    }

    fn set_projector(&self, _on: bool) {
        self.arm.request();
    }

    fn shortcuts(&self) -> Vec<Shortcut> {
        home_arm::KEYS.to_vec()
    }

    fn on_key(&self, event: &KeyboardEvent) -> bool {
        self.arm.on_key(event)
    }
}

fn build(root: &Element, shell: ShellLink, keep: &Keep) -> Result<Rc<HomeArm>, JsValue> {
    let hero = el_class("section", "hero")?;
    crate::ui::dom::mark_section(&hero, "arm")?;
    let text = el_class("div", "hero-text")?;
    let headline = el_i18n("h1", "headline", "home-headline")?;
    headline.set_attribute("data-testid", "home-headline")?;
    append(&text, &headline)?;
    append(&text, &el_i18n("p", "intro", "home-intro")?)?;
    append(&hero, &text)?;
    let arm = home_arm::mount(&hero)?;
    let content = crate::ui::dom::document()?.create_document_fragment();
    content.append_child(&hero)?;
    page_frame::fill_with(root, &content)?;

    let status = el_class("p", "home-more")?;
    status.set_attribute("data-testid", "home-more")?;
    show_loading(&status)?;
    append(root, &status)?;
    // Fetched once the arm is painted, so that the first frame does not wait on its requests.
    let (root, keep) = (root.clone(), keep.clone());
    crate::ui::schedule::after_paint(move || load_cards(root, status, shell, keep))?;
    Ok(arm)
}

/// Builds the tiles, recipe cards and tools table (`home_cards`).
type CardsFn = fn(&Element, &Element, ShellLink, &Keep) -> Result<(), JsValue>;

/// The tiles, recipe cards and tools table: a wasm chunk of their own (drawing the pictures
/// runs every recipe's kernel), fetched once the arm is live.
#[cfg(feature = "split")]
#[wasm_split_helpers::wasm_split(home_cards, fallible)]
fn cards() -> Result<CardsFn, SplitLoaderError> {
    Ok(home_cards::build)
}

/// Without the `split` feature the cards are in the one wasm.
#[cfg(not(feature = "split"))]
async fn cards() -> Result<CardsFn, SplitLoaderError> {
    Ok(home_cards::build)
}

/// Loads the cards' chunk and builds them into `root` in place of `status`; if the chunk
/// cannot be fetched, `status` says so with a Retry button.
fn load_cards(root: Element, status: Element, shell: ShellLink, keep: Keep) {
    wasm_bindgen_futures::spawn_local(async move {
        let built = match cards().await {
            Ok(build) => {
                // The page may have been left meanwhile.
                if !root.contains(Some(&status)) {
                    return;
                }
                build(&root, &status, shell, &keep)
            }
            Err(_) => show_failed(&root, &status, shell, keep),
        };
        if let Err(error) = built {
            web_sys::console::error_1(&error);
        }
    });
}

fn show_failed(
    root: &Element,
    status: &Element,
    shell: ShellLink,
    keep: Keep,
) -> Result<(), JsValue> {
    let (root, again) = (root.clone(), status.clone());
    page_frame::show_part_failed(status, "home-more-failed", "home-more-loading", move || {
        load_cards(root.clone(), again.clone(), shell, keep.clone())
    })
}

/// `status` as the line that stands in for the cards while their chunk loads.
fn show_loading(status: &Element) -> Result<(), JsValue> {
    page_frame::show_part_loading(status, "home-more-loading")
}
