//! All drills (`#/drills?recipe=<id>&<arg>=<value>...`): run any of the twelve recipes in the
//! browser with the user's arguments and download its CSV file(s), byte for byte what
//! `bsv <id> <args>` writes (and, through the kernels' parity, what the Python recipe writes).
//!
//! The page knows nothing about any recipe: the form, hints, limits, quirks and run sizes come
//! from the recipe's facts (`RecipeInfo`, `ArgSpec`, `RecipeInfo::plan`), and the fields, the
//! exports panel and the readouts are the kit's (`crate::ui::kit`).
//!
//! How a run happens:
//! - every keystroke validates the form with the recipe's own parse + validate (its `plan`, no
//!   run) and puts the localized message beside the field ([`crate::view::form::validate`]);
//! - a valid form whose run is small ([`crate::view::form::AUTO_RUN_MAX_ROWS`]) runs 250 ms after the last
//!   keystroke; a bigger one waits for Run / Enter / `r`, which first paints a "Running…"
//!   state and then runs, and brings the result (or the first error) into view;
//! - the last result (summary, warnings, files, command lines) stays on screen until a new run
//!   succeeds; a note says when the form has moved on from it.
//!
//! Components, one file each: `picker` (the drill select, its texts, switching, defaults),
//! `form` (the kit form and its validation), `input` (an input file on the page, read by
//! `file`), `run` (when and how a drill runs, the status line), `result` (summary, warnings,
//! previews, downloads and the kit's exports panel), `url` (the kit's URL writer and notice;
//! the codec is [`crate::view::drills`]), `keys`; `mount` builds and wires them from `markup`; `texts` formats sizes.

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
mod texts;
mod url;

use std::cell::RefCell;
use std::rc::{Rc, Weak};

use wasm_bindgen::JsValue;
use web_sys::{Element, HtmlSelectElement, KeyboardEvent};

use self::file::InputFile;
use self::result::Shown;
use self::run::Plan;
use crate::recipes::Recipe;
use crate::ui::dom::Listener;
use crate::ui::kit::exports::Exports;
use crate::ui::kit::form::{Form, Message};
use crate::ui::kit::readouts::Readouts;
use crate::ui::kit::scope::Scope;
use crate::ui::kit::url_state::{IgnoredKey, IgnoredReason, UrlNotice, UrlWriter};
use crate::ui::page::{self, MountCtx, Shortcut};
use crate::ui::schedule::Timer;
use crate::view::command_line::RunArgs;

/// The class and test-id prefix of the page's kit widgets.
const PREFIX: &str = "drills";

/// The elements the page drives.
struct Els {
    page: Element,
    recipe: HtmlSelectElement,
    recipe_title: Element,
    recipe_blurb: Element,
    form: Element,
    run: Element,
    status: Element,
    error: Element,
    about: Element,
    quirk: Element,
    output: Element,
    stale: Element,
    empty: Element,
    result: Element,
    summary: Element,
    warnings: Element,
    files: Element,
}

/// What the status line beside Run says.
#[derive(Debug, Clone, PartialEq)]
enum Status {
    /// Nothing to say.
    Idle,
    /// A run is about to start or running.
    Running,
    /// Valid, but too big to run while typing.
    Large,
    /// Run was asked for while a field is invalid.
    Invalid,
    /// The input file is being read.
    Reading(String),
    /// The last run succeeded, in this many milliseconds.
    Done(f64),
    /// The last run failed (the message is beside the field or under the form).
    Failed,
}

/// Where a message goes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Slot {
    Field(usize),
    /// Under the form (errors about no particular field).
    General,
}

/// What the URL asked for that the page could not do as asked (shown by the kit's
/// [`UrlNotice`] until the user moves on: another drill, Reset, the named file opened).
#[derive(Debug, Clone, Default)]
struct UrlNotes {
    /// The recipe id of the link, when no recipe has it.
    unknown_recipe: Option<String>,
    /// Keys the drill does not take, values flagged in their field, the file to open again.
    keys: Vec<IgnoredKey>,
}

impl UrlNotes {
    /// The file the link named is open now (or the sample is used instead).
    fn file_settled(&mut self) {
        self.keys.retain(|k| k.reason != IgnoredReason::File);
    }
}

/// The page's state.
struct State {
    recipe: &'static Recipe,
    /// The text of each field of the recipe (`None` for the file picker).
    texts: Vec<Option<String>>,
    /// Texts of drills visited before in this visit, restored when the user comes back.
    remembered: Vec<(&'static str, Vec<Option<String>>)>,
    /// The opened input file.
    input: Option<InputFile>,
    /// A file named by the URL that is not open.
    missing_file: Option<String>,
    /// A problem with the chosen file (too large, unreadable).
    file_problem: Option<Message>,
    /// The file being read, and a counter that drops stale reads.
    reading: Option<String>,
    read_generation: u32,
    /// Messages now shown, and every field an error involves.
    errors: Vec<(Slot, Message)>,
    marked: Vec<usize>,
    /// The plan of the current (valid) form.
    plan: Option<Plan>,
    /// A run that failed, with its arguments (its message stays while they do not change).
    failed: Option<(RunArgs, Slot, Message)>,
    shown: Option<Shown>,
    /// Successful runs so far (`data-run` of the result panel).
    runs: u32,
    status: Status,
    url: UrlNotes,
    /// Tables show the CSV's exact text instead of rounded numbers.
    exact: bool,
}

/// The mounted page.
pub(crate) struct Page {
    els: Els,
    st: RefCell<State>,
    form: RefCell<Form>,
    exports: Exports,
    readouts: Readouts,
    listeners: RefCell<Vec<Listener>>,
    auto_timer: Timer,
    /// Owns the URL writer's timer (dropped on unmount).
    scope: RefCell<Scope>,
    url: UrlWriter,
    url_notice: UrlNotice,
    weak: RefCell<Weak<Page>>,
    /// Big runs in the Web Worker, with their progress panel (background.rs).
    background: RefCell<Option<Rc<background::Background>>>,
}

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
