//! What a page and its exercises list share ([`crate::ui::kit::exercise_slot`] builds the
//! page's side, the exercises' chunk [`crate::ui::exercises`] the list's): the page's
//! exercises, its section, a loan of its model, and the list's answer to the page's changes.
//!
//! The page hands over its own exercises (`crate::view::exercises::<page>::EXERCISES`), not
//! the catalog: their checks, and the kernels they run, are the page's, in its chunk beside
//! its own use of those kernels, and the list's chunk holds no kernel (with the catalog, a
//! list on one page would fetch every page's kernels).

use web_sys::Element;

use crate::view::exercises::{Exercise, PageModel};

/// The `data-section` of a page's exercises.
pub const EXERCISES_SECTION: &str = "exercises";
/// The attribute of the document element naming the exercise a presented lesson step is about:
/// its answer stays hidden until the presenter reveals it.
pub const PRESENT_EXERCISE_ATTR: &str = "data-present-exercise";
/// The window event told when that attribute changes.
pub const PRESENT_EXERCISE_EVENT: &str = "bsv-present-exercise";

/// Lends the page's model to `use_model` (nothing once the page is gone).
pub type WithModel = Box<dyn Fn(&mut dyn FnMut(&PageModel))>;

/// A page's side of its exercises list.
pub struct PageLink {
    /// The page's exercises, in the order it lists them.
    pub exercises: &'static [Exercise],
    /// The page's element the list listens to for the learner's input (`<main>`).
    pub root: Element,
    /// The section (`data-section="exercises"`); the list fills it after its heading.
    pub section: Element,
    /// The page's model now.
    pub with_model: WithModel,
    /// The address's hash as the page opened: a changed page query is a learner's change
    /// made before the list came.
    pub opened_hash: String,
}

/// A mounted exercises list, held by the page's slot and dropped with it.
pub trait ExerciseList {
    /// The page's state changed other than through an input on the page (a pilot's frame
    /// moved the arm): the goals are checked again, soon.
    fn changed(&self);
}

/// Mounts the list of a page's exercises in its section.
pub type MountList =
    fn(std::rc::Rc<PageLink>) -> Result<Box<dyn ExerciseList>, wasm_bindgen::JsValue>;

/// What the list's chunk hands the page.
#[derive(Clone, Copy)]
pub struct ListChunk {
    pub mount: MountList,
}
