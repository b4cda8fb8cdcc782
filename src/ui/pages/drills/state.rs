//! The page's state and the mounted page: the elements it drives, what the form and the last
//! run hold, what the URL asked for, and the widgets (form, exports, readouts, URL writer,
//! worker run). The components add their behaviour to [`Page`] in their own files.

use std::cell::RefCell;
use std::rc::{Rc, Weak};

use web_sys::{Element, HtmlSelectElement};

use super::background::Background;
use super::file::InputFile;
use super::shown::Shown;
use crate::recipes::RecipeInfo;
use crate::ui::dom::Listener;
use crate::ui::kit::exports::Exports;
use crate::ui::kit::form::{Form, Message};
use crate::ui::kit::readouts::Readouts;
use crate::ui::kit::scope::Scope;
use crate::ui::kit::url_state::{IgnoredKey, IgnoredReason, UrlNotice, UrlWriter};
use crate::ui::schedule::Timer;
use crate::view::command_line::RunArgs;

/// The elements the page drives.
pub(super) struct Els {
    pub(super) page: Element,
    pub(super) recipe: HtmlSelectElement,
    pub(super) recipe_title: Element,
    pub(super) recipe_blurb: Element,
    pub(super) form: Element,
    pub(super) run: Element,
    pub(super) status: Element,
    pub(super) error: Element,
    pub(super) about: Element,
    pub(super) quirk: Element,
    pub(super) output: Element,
    pub(super) stale: Element,
    pub(super) empty: Element,
    pub(super) result: Element,
    pub(super) summary: Element,
    pub(super) warnings: Element,
    pub(super) files: Element,
}

/// What the status line beside Run says.
#[derive(Debug, Clone, PartialEq)]
pub(super) enum Status {
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
pub(super) enum Slot {
    Field(usize),
    /// Under the form (errors about no particular field).
    General,
}

/// What the URL asked for that the page could not do as asked (shown by the kit's
/// [`UrlNotice`] until the user moves on: another drill, Reset, the named file opened).
#[derive(Debug, Clone, Default)]
pub(super) struct UrlNotes {
    /// The recipe id of the link, when no recipe has it.
    pub(super) unknown_recipe: Option<String>,
    /// Keys the drill does not take, values flagged in their field, the file to open again.
    pub(super) keys: Vec<IgnoredKey>,
}

impl UrlNotes {
    /// The file the link named is open now (or the sample is used instead).
    pub(super) fn file_settled(&mut self) {
        self.keys.retain(|k| k.reason != IgnoredReason::File);
    }
}

/// The page's state.
pub(super) struct State {
    pub(super) recipe: &'static RecipeInfo,
    /// The text of each field of the recipe (`None` for the file picker).
    pub(super) texts: Vec<Option<String>>,
    /// Texts of drills visited before in this visit, restored when the user comes back.
    pub(super) remembered: Vec<(&'static str, Vec<Option<String>>)>,
    /// The opened input file.
    pub(super) input: Option<InputFile>,
    /// A file named by the URL that is not open.
    pub(super) missing_file: Option<String>,
    /// A problem with the chosen file (too large, unreadable).
    pub(super) file_problem: Option<Message>,
    /// The file being read, and a counter that drops stale reads.
    pub(super) reading: Option<String>,
    pub(super) read_generation: u32,
    /// Messages now shown, and every field an error involves.
    pub(super) errors: Vec<(Slot, Message)>,
    pub(super) marked: Vec<usize>,
    /// The plan of the current (valid) form.
    pub(super) plan: Option<Plan>,
    /// A run that failed, with its arguments (its message stays while they do not change).
    pub(super) failed: Option<(RunArgs, Slot, Message)>,
    pub(super) shown: Option<Shown>,
    /// Successful runs so far (`data-run` of the result panel).
    pub(super) runs: u32,
    pub(super) status: Status,
    pub(super) url: UrlNotes,
    /// Tables show the CSV's exact text instead of rounded numbers.
    pub(super) exact: bool,
}

impl State {
    /// A run succeeded in `ms` milliseconds: its result is shown, a failure before it is gone.
    pub(super) fn succeeded(&mut self, shown: Shown, ms: f64) {
        self.shown = Some(shown);
        self.runs += 1;
        self.status = Status::Done(ms);
        self.failed = None;
    }
}

/// The mounted page.
pub(super) struct Page {
    pub(super) els: Els,
    pub(super) st: RefCell<State>,
    pub(super) form: RefCell<Form>,
    pub(super) exports: Exports,
    pub(super) readouts: Readouts,
    pub(super) listeners: RefCell<Vec<Listener>>,
    pub(super) auto_timer: Timer,
    /// Owns the URL writer's timer (dropped on unmount).
    pub(super) scope: RefCell<Scope>,
    pub(super) url: UrlWriter,
    pub(super) url_notice: UrlNotice,
    pub(super) weak: RefCell<Weak<Page>>,
    /// Big runs in the Web Worker, with their progress panel.
    pub(super) background: RefCell<Option<Rc<Background>>>,
}

/// What a valid form will cost.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct Plan {
    /// Rows of work (the recipe's `plan`); `None` when only the run can size it (a large
    /// input file).
    pub rows: Option<u64>,
}

impl Plan {
    /// Whether the page may run it while the user types.
    pub fn is_small(&self) -> bool {
        crate::view::form::runs_while_typing(self.rows)
    }
}
