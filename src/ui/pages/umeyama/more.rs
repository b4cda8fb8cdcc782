//! The page's second stage, a wasm chunk of its own (`umeyama_more`, loaded by `more_status`)
//! that arrives after the points, the fit and the steps are live: the exports panel (the
//! `bsv` and `python` command lines, the CSV downloads, which run the recipe's kernel and
//! write its files, the copy buttons) and the PNG of the view. The page reaches them only
//! through [`More`] (a trait object made here), so none of their code is in the first stage.

use std::rc::Rc;

use wasm_bindgen::JsValue;
use web_sys::Element;

use super::markup::{P, PNG};
use crate::recipes::{run_raw_of, umeyama_2d};
use crate::ui::kit::canvas::LayeredCanvas;
use crate::ui::kit::recipe_controls::{RecipeExports, RunExports};

/// What the page asks of its second stage.
pub(super) trait More {
    /// The exports panel, for the page's [`crate::ui::kit::recipe_controls::RecipeControls`].
    fn exports(&self) -> Rc<dyn RecipeExports>;
    /// Saves the view as the page's PNG.
    fn save_png(&self, canvas: &LayeredCanvas);
}

/// Builds the second stage on the page's markup under `root` (what the `umeyama_more` chunk
/// hands the page).
pub(super) type BuildFn = fn(&Element) -> Result<Rc<dyn More>, JsValue>;

/// The second stage.
struct Loaded {
    exports: Rc<RunExports>,
}

/// Finds the exports panel under `root`.
pub(super) fn build(root: &Element) -> Result<Rc<dyn More>, JsValue> {
    let exports = RunExports::find(root, P, run_raw_of::<umeyama_2d::Entry>)?;
    Ok(Rc::new(Loaded {
        exports: Rc::new(exports),
    }))
}

impl More for Loaded {
    fn exports(&self) -> Rc<dyn RecipeExports> {
        self.exports.clone()
    }

    fn save_png(&self, canvas: &LayeredCanvas) {
        if let Ok(flat) = canvas.flatten("#ffffff") {
            let _ = crate::ui::kit::png::download(&flat, PNG);
        }
    }
}
