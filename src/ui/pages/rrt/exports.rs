//! Exports: `rrt_nodes.csv` and `rrt_path.csv` of the run at its end (the kernel's own output
//! for the page's arguments, so byte for byte what `bsv rrt-2d` writes), a PNG of the world
//! view, and the command lines: `bsv` always, `python rrt_2d_grid.py` only when the world
//! and the planner's constants are the recipe's (the Python recipe has no options).

use wasm_bindgen::JsValue;
use web_sys::Element;

use crate::recipes::rrt_2d::{output, INFO};
use crate::ui::dom;
use crate::ui::kit::exports::Exports as Commands;
use crate::view::rrt::PageState;

use super::Run;

/// The exports component.
pub struct Exports {
    pub commands: Commands,
    pub nodes: Element,
    pub path: Element,
    pub png: Element,
    python_row: Option<Element>,
    python_note: Element,
    python_none: Element,
    recipe_world: std::cell::Cell<bool>,
}

impl Exports {
    /// Finds the elements under `root`.
    pub fn find(root: &Element) -> Result<Exports, JsValue> {
        let f = |sel: &str| -> Result<Element, JsValue> { dom::find(root, sel, "rrt") };
        let python = f("[data-cmd=\"python\"]")?;
        Ok(Exports {
            commands: Commands::find(root, "rrt")?,
            nodes: f("[data-download=\"rrt_nodes.csv\"]")?,
            path: f("[data-download=\"rrt_path.csv\"]")?,
            png: f("[data-download=\"rrt_2d.png\"]")?,
            python_row: python.parent_element(),
            python_note: f("[data-rrt=\"python-note\"]")?,
            python_none: f("[data-rrt=\"python-none\"]")?,
            recipe_world: std::cell::Cell::new(true),
        })
    }

    /// Shows the command lines of `state`.
    pub fn update(&self, state: &PageState) {
        self.commands.show_run(&state.run_args(), INFO.python, None);
        self.recipe_world.set(state.is_recipe_world());
        self.python_visibility();
    }

    fn python_visibility(&self) {
        let recipe = self.recipe_world.get();
        if let Some(row) = &self.python_row {
            dom::show(row, recipe);
        }
        if !recipe {
            dom::show(&self.python_note, false);
        }
        dom::show(&self.python_none, !recipe);
    }

    /// Re-renders in the current language.
    pub fn relocalize(&self) {
        self.commands.relocalize();
        self.python_visibility();
    }

    /// Downloads `file` of the finished run.
    pub fn download(&self, run: &Run, file: &str) {
        let out = output(&run.finished);
        if let Some(text) = out.file(file) {
            self.commands.download(file, text);
        }
    }
}
