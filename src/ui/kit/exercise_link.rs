//! What a page and its exercises list share ([`crate::ui::kit::exercise_slot`] builds the
//! page's side, the exercises' chunk [`crate::ui::exercises`] the list's): the page's route
//! id, its section, a loan of its model, and the list's answer to the page's changes.
//!
//! The checks are the list's (its chunk holds the catalog), not the page's: a page's first
//! load carries none of them (the IK page's would bring the accurate `sin` and `atan2` its
//! first stage does without).

use web_sys::Element;

use crate::view::exercises::PageModel;

/// Lends the page's model to `use_model` (nothing once the page is gone).
pub type WithModel = Box<dyn Fn(&mut dyn FnMut(&PageModel))>;

/// A page's side of its exercises list.
pub struct PageLink {
    /// The page's route id (its exercises are [`crate::view::exercises::of_page`]).
    pub page: &'static str,
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
