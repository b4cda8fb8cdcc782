//! All drills (`#/drills?recipe=<id>&<arg>=<value>...`): run any of the twelve recipes in the
//! browser with the user's arguments and download its CSV file(s), byte for byte what
//! `bsv <id> <args>` writes. The page knows nothing about any recipe: form, hints, limits,
//! quirks and run sizes come from the recipe's facts (`RecipeInfo`, `ArgSpec`, `plan`).
//!
//! Every keystroke validates the form with the recipe's own checks; a small run
//! ([`crate::view::form::AUTO_RUN_MAX_ROWS`]) runs 250 ms after the last keystroke, a bigger
//! one waits for Run / Enter / `r` (in the Web Worker); the last result stays until a new run
//! succeeds.
//!
//! `state` holds the page and its state; the components add to it, one file each: `picker`,
//! `form`, `input` (read by `file`), `run` (when and how a drill runs, the worker run of
//! `background`), `result` (of `shown`), `url`, `keys`; `mount` builds and wires them from
//! `markup`; `texts` formats sizes.

mod background;
mod file;
mod form;
mod input;
mod keys;
mod markup;
mod mount;
mod picker;
mod result;
mod run;
mod shown;
mod state;
mod texts;
mod url;

use std::rc::Rc;

use wasm_bindgen::JsValue;
use web_sys::KeyboardEvent;

use self::state::Page;
use crate::ui::page::{self, MountCtx, Shortcut};

/// The drills page.
pub struct DrillsPage(Rc<Page>);

impl page::Page for DrillsPage {
    fn mount(ctx: MountCtx) -> Result<DrillsPage, JsValue> {
        mount::mount(ctx).map(DrillsPage)
    }

    fn relocalize(&self) {
        self.0.relocalize();
    }

    fn shortcuts(&self) -> Vec<Shortcut> {
        keys::shortcuts()
    }

    fn on_key(&self, event: &KeyboardEvent) -> bool {
        keys::on_key(&self.0, event)
    }
}

impl Drop for DrillsPage {
    fn drop(&mut self) {
        self.0.unmount();
    }
}
