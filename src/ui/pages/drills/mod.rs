//! All drills (`#/drills?recipe=<id>&<arg>=<value>...`): run any of the twelve recipes in the
//! browser with the user's arguments and download its CSV file(s), byte for byte what
//! `bsv <id> <args>` writes (and, through the kernels' parity, what the Python recipe writes).
//!
//! How a run happens:
//! - every keystroke validates the form with the recipe's own parser and checks
//!   ([`plan::check`], no run), and puts the localized message beside the offending field;
//! - a valid form whose run is small ([`plan::AUTO_RUN_MAX_WORK`] rows) runs 250 ms after the
//!   last keystroke; a bigger one waits for Run / Enter / `r`, which first paints a "Running…"
//!   state and then runs ([`after_paint`]), so the tab never freezes without saying so;
//! - the last result (summary, files, command lines) stays on screen until a new run succeeds;
//!   a note says when the form has moved on from it.
//!
//! Files: [`fields`] (the form and its hints), [`plan`] (checks and run sizes), [`command`]
//! (run arguments and command lines), [`query`] (URL state), [`output`] (result panel),
//! [`preview`] (CSV tables), [`file`] (traj-resample's input file), [`keys`], [`texts`]
//! (explanations, number formats), [`markup`]. Timers and the clipboard are the shared
//! [`crate::ui::schedule`] and [`crate::ui::clipboard`].

mod command;
mod fields;
mod file;
mod keys;
mod markup;
mod output;
mod plan;
mod preview;
mod query;
mod texts;

use std::cell::RefCell;
use std::rc::{Rc, Weak};

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::{Element, Event, HtmlSelectElement, KeyboardEvent};

use self::command::RunArgs;
use self::fields::{Form, Kind, Message};
use self::file::InputFile;
use self::output::Shown;
use self::plan::{InputCheck, Plan};
use self::query::UrlState;
use crate::args::Args;
use crate::error::RecipeError;
use crate::recipes::{self, traj_resample, Recipe, RecipeOutput, RECIPES};
use crate::ui::ctx::{self, t_strings};
use crate::ui::dom::{self, show, Listener};
use crate::ui::page::{MountCtx, PageDef, PageHandle, Shortcut};
use crate::ui::schedule::{after_paint, now_ms, Timer};
use crate::ui::{clipboard, router};

/// The page, as the shell's page table lists it.
pub const PAGE: PageDef = PageDef {
    id: "drills",
    title_id: "drills-title",
    blurb_id: "drills-blurb",
    mount,
};

/// The link to one drill: `#/drills?recipe=<id>`.
pub fn link(recipe_id: &str) -> String {
    router::build_hash(
        PAGE.id,
        &[(query::RECIPE_KEY.to_string(), recipe_id.to_string())],
    )
}

/// Milliseconds between the last keystroke and a small drill's run.
const AUTO_RUN_DELAY_MS: i32 = 250;
/// Milliseconds between the last keystroke and the URL update.
const URL_DELAY_MS: i32 = 300;

fn mount(ctx: MountCtx) -> Result<Box<dyn PageHandle>, JsValue> {
    let page = Page::build(ctx)?;
    Ok(Box::new(Handle(page)))
}

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
    url_notice: Element,
    about: Element,
    quirk_box: Element,
    quirk: Element,
    output: Element,
    stale: Element,
    empty: Element,
    result: Element,
    summary: Element,
    files: Element,
    cmd_python: Element,
    cmd_bsv: Element,
    python_note: Element,
    file_note: Element,
    copy_status: Element,
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

/// What the URL asked for that the page could not do as asked.
#[derive(Debug, Clone, Default)]
struct UrlNotes {
    unknown_recipe: Option<String>,
    ignored: Vec<String>,
    invalid: Vec<String>,
    missing_file: Option<String>,
}

impl UrlNotes {
    fn is_empty(&self) -> bool {
        self.unknown_recipe.is_none()
            && self.ignored.is_empty()
            && self.invalid.is_empty()
            && self.missing_file.is_none()
    }
}

/// The page's state.
struct State {
    recipe: &'static Recipe,
    /// The text of each field of the recipe (`None` for the file picker).
    texts: Vec<Option<String>>,
    /// Texts of drills visited before in this visit, restored when the user comes back.
    remembered: Vec<(&'static str, Vec<Option<String>>)>,
    /// traj-resample's opened input file.
    input: Option<InputFile>,
    /// A file named by the URL that is not open.
    missing_file: Option<String>,
    /// A problem with the chosen file (too large, unreadable).
    file_problem: Option<Message>,
    /// The file being read, and a counter that drops stale reads.
    reading: Option<String>,
    read_generation: u32,
    /// Messages now shown.
    errors: Vec<(Slot, Message)>,
    /// The plan of the current (valid) form.
    plan: Option<Plan>,
    /// A run that failed, with its arguments (its message stays while they do not change).
    failed: Option<(RunArgs, Slot, Message)>,
    shown: Option<Shown>,
    /// Successful runs so far (`data-run` of the result panel).
    runs: u32,
    status: Status,
    url: UrlNotes,
    copy_status: Option<&'static str>,
}

/// The mounted page.
pub(crate) struct Page {
    els: Els,
    st: RefCell<State>,
    form: RefCell<Form>,
    listeners: RefCell<Vec<Listener>>,
    auto_timer: Timer,
    url_timer: Timer,
    weak: RefCell<Weak<Page>>,
}

fn find<T: JsCast>(root: &Element, selector: &str) -> Result<T, JsValue> {
    dom::find(root, selector, "drills")
}

fn role<T: JsCast>(root: &Element, name: &str) -> Result<T, JsValue> {
    find(root, &format!("[data-drills=\"{name}\"]"))
}

/// Runs `args`; traj-resample with an opened file reads the file's text in place (the same
/// kernel path as `run_with_inputs`, without copying a large input).
fn compute(args: &RunArgs, input: Option<&InputFile>) -> Result<RecipeOutput, RecipeError> {
    let raw = args.raw();
    if args.recipe == traj_resample::INFO.id {
        if let Some(file) = input.filter(|f| args.positional.first() == Some(&f.name)) {
            let info = &traj_resample::INFO;
            let parsed = Args::parse(&raw, info.args, info.flags)?;
            let params = traj_resample::ResampleParams::from_args(&parsed)?;
            return traj_resample::run_text(&params, &file.text);
        }
    }
    recipes::run(args.recipe, &raw)
}

/// Whether a traj-resample error is about its input file (shown beside the file picker).
fn is_input_error(error: &RecipeError) -> bool {
    use RecipeError::*;
    matches!(
        error,
        InputTooLarge { .. }
            | CsvMissingColumn { .. }
            | CsvNoJointColumns
            | CsvTooFewRows { .. }
            | CsvRagged { .. }
            | CsvBadCell { .. }
            | CsvTimeNotIncreasing { .. }
            | CsvUnterminatedQuote { .. }
            | InputMissing { .. }
    )
}

/// Where the message of `error` goes: beside the field it names, beside the file picker when
/// it is about the input file, else under the form.
fn slot_for(form: &Form, error: &RecipeError) -> Slot {
    let file_field = || form.fields.iter().position(|f| f.kind == Kind::File);
    error
        .param()
        .and_then(|p| form.index_of(p))
        .or_else(|| is_input_error(error).then(file_field).flatten())
        .map_or(Slot::General, Slot::Field)
}

/// A file name usable as a positional argument (one starting with `-` gets `./`).
fn path_word(name: &str) -> String {
    match name {
        "" => "input.csv".to_string(),
        n if n.starts_with('-') => format!("./{n}"),
        n => n.to_string(),
    }
}

impl Page {
    fn build(mount: MountCtx) -> Result<Rc<Page>, JsValue> {
        let root = mount.root.clone();
        root.set_inner_html(&markup::page());
        let els = Els {
            page: find(&root, ".drills")?,
            recipe: role(&root, "recipe")?,
            recipe_title: role(&root, "recipe-title")?,
            recipe_blurb: role(&root, "recipe-blurb")?,
            form: role(&root, "form")?,
            run: role(&root, "run")?,
            status: role(&root, "status")?,
            error: role(&root, "error")?,
            url_notice: role(&root, "url-notice")?,
            about: role(&root, "about")?,
            quirk_box: role(&root, "quirk-box")?,
            quirk: role(&root, "quirk")?,
            output: role(&root, "output")?,
            stale: role(&root, "stale")?,
            empty: role(&root, "empty")?,
            result: role(&root, "result")?,
            summary: role(&root, "summary")?,
            files: role(&root, "files")?,
            cmd_python: find(&root, "[data-cmd=\"python\"]")?,
            cmd_bsv: find(&root, "[data-cmd=\"bsv\"]")?,
            python_note: role(&root, "python-note")?,
            file_note: role(&root, "file-note")?,
            copy_status: role(&root, "copy-status")?,
        };
        dom::relocalize(&root)?;

        let url = UrlState::parse(&mount.query);
        let recipe = url.recipe;
        let field_list = fields::fields(recipe.info);
        let mut texts = url.texts(&field_list);
        let mut missing_file = None;
        for (field, text) in field_list.iter().zip(texts.iter_mut()) {
            if field.kind == Kind::File {
                missing_file = text.take().filter(|t| !t.trim().is_empty());
            }
        }
        let form = Form::build(&els.form, recipe.info, &fill_values(&field_list, &texts))?;
        let state = State {
            recipe,
            texts,
            remembered: Vec::new(),
            input: None,
            missing_file: missing_file.clone(),
            file_problem: None,
            reading: None,
            read_generation: 0,
            errors: Vec::new(),
            plan: None,
            failed: None,
            shown: None,
            runs: 0,
            status: Status::Idle,
            url: UrlNotes {
                unknown_recipe: url.unknown_recipe.clone(),
                ignored: url.ignored.clone(),
                invalid: Vec::new(),
                missing_file,
            },
            copy_status: None,
        };
        let page = Rc::new(Page {
            els,
            st: RefCell::new(state),
            form: RefCell::new(form),
            listeners: RefCell::new(Vec::new()),
            auto_timer: Timer::default(),
            url_timer: Timer::default(),
            weak: RefCell::new(Weak::new()),
        });
        *page.weak.borrow_mut() = Rc::downgrade(&page);
        page.install()?;
        page.els.recipe.set_value(recipe.info.id);
        page.render_recipe_texts()?;
        page.validate();
        {
            // Values from the URL that do not pass: name them in the notice.
            let form = page.form.borrow();
            let mut st = page.st.borrow_mut();
            let invalid: Vec<String> = st
                .errors
                .iter()
                .filter_map(|(slot, _)| match slot {
                    Slot::Field(i) => form.fields.get(*i).map(|f| f.spec.name.to_string()),
                    Slot::General => None,
                })
                .filter(|name| url.values.iter().any(|(k, _)| k == name))
                .collect();
            st.url.invalid = invalid;
        }
        page.render_notice();
        page.render_file_status();
        page.auto_run();
        page.render_output()?;
        page.render_status();
        Ok(page)
    }

    /// Wires the controls (delegated on stable containers, so rebuilding the form or the
    /// result needs no new listeners) and the timers.
    fn install(&self) -> Result<(), JsValue> {
        let weak = self.weak.borrow().clone();
        self.auto_timer.set_callback(&weak, Page::auto_run);
        self.url_timer.set_callback(&weak, Page::write_url);

        let reset: Element = find(&self.els.page, "[data-drills=\"reset\"]")?;
        *self.listeners.borrow_mut() = vec![
            Listener::for_page(&self.els.recipe, "change", &weak, |p, _| {
                let id = p.els.recipe.value();
                if let Some(recipe) = recipes::find(&id) {
                    p.switch_recipe(recipe);
                }
            })?,
            Listener::for_page(&self.els.form, "input", &weak, |p, e| {
                let is_field = target_element(e).is_some_and(|el| el.has_attribute("data-field"));
                if is_field {
                    p.on_edit();
                }
            })?,
            Listener::for_page(&self.els.form, "change", &weak, |p, e| {
                let Some(el) = target_element(e) else {
                    return;
                };
                // Text fields and selects report through "input"; the file picker here.
                if el.has_attribute("data-file-input") {
                    p.on_file_chosen();
                }
            })?,
            Listener::for_page(&self.els.form, "keydown", &weak, |p, e| {
                let Some(key) = e.dyn_ref::<KeyboardEvent>() else {
                    return;
                };
                let in_field = target_element(e).is_some_and(|el| el.has_attribute("data-field"));
                if key.key() == "Enter" && in_field && !key.is_composing() {
                    e.prevent_default();
                    p.request_run();
                }
            })?,
            Listener::for_page(&self.els.form, "submit", &weak, |_, e| e.prevent_default())?,
            Listener::for_page(&self.els.form, "click", &weak, |p, e| {
                if target_element(e)
                    .is_some_and(|el| el.closest("[data-use-sample]").ok().flatten().is_some())
                {
                    p.use_sample();
                }
            })?,
            Listener::for_page(&self.els.run, "click", &weak, |p, _| p.request_run())?,
            Listener::for_page(&reset, "click", &weak, |p, _| p.reset())?,
            Listener::for_page(&self.els.output, "click", &weak, |p, e| {
                let Some(el) = target_element(e) else {
                    return;
                };
                if let Some(button) = el.closest("[data-download]").ok().flatten() {
                    let file = button.get_attribute("data-download").unwrap_or_default();
                    p.download(&file);
                } else if let Some(button) = el.closest("[data-copy]").ok().flatten() {
                    let kind = button.get_attribute("data-copy").unwrap_or_default();
                    p.copy_command(&kind);
                }
            })?,
        ];
        Ok(())
    }

    /// The texts of every field now: the form's, with the file picker's value being the
    /// opened (or URL-named) file.
    fn current_texts(&self) -> Vec<Option<String>> {
        let form = self.form.borrow();
        let st = self.st.borrow();
        let file_name = st
            .input
            .as_ref()
            .map(|f| f.name.clone())
            .or_else(|| st.missing_file.clone());
        form.fields
            .iter()
            .zip(form.texts())
            .map(|(field, text)| match field.kind {
                Kind::File => file_name.clone(),
                _ => text,
            })
            .collect()
    }

    /// The run the form describes now.
    fn current_args(&self) -> RunArgs {
        let texts = self.current_texts();
        let form = self.form.borrow();
        RunArgs::new(form.recipe, &form.fields, &texts)
    }

    /// Checks the form (each changed field alone, then all together) without running, and
    /// shows the messages beside their fields.
    fn validate(&self) {
        let texts = self.current_texts();
        let form = self.form.borrow();
        let recipe = form.recipe;
        let info = self.st.borrow().recipe.info;
        let check = |args: &RunArgs, input: InputCheck<'_>| -> Result<Plan, RecipeError> {
            let parsed = Args::parse(&args.raw(), info.args, info.flags)?;
            plan::check(recipe, &parsed, input)
        };
        let mut errors: Vec<(Slot, Message)> = Vec::new();
        // Each changed field alone (the others at their defaults): every bad field is named.
        for (index, field) in form.fields.iter().enumerate() {
            let typed = texts
                .get(index)
                .and_then(|t| t.as_deref())
                .map(str::trim)
                .filter(|t| !t.is_empty() && *t != field.spec.default);
            if typed.is_none() || field.kind == Kind::File {
                continue;
            }
            let mut alone: Vec<Option<String>> = vec![None; form.fields.len()];
            if let Some(slot) = alone.get_mut(index) {
                *slot = typed.map(str::to_string);
            }
            let args = RunArgs::new(recipe, &form.fields, &alone);
            if let Err(error) = check(&args, InputCheck::None) {
                if error.param() == Some(field.spec.name) {
                    errors.push((Slot::Field(index), Message::Recipe(error)));
                }
            }
        }
        // Everything together.
        let st = self.st.borrow();
        let args = RunArgs::new(recipe, &form.fields, &texts);
        let input = match &st.input {
            Some(file) => match &file.shape {
                Some(shape) => InputCheck::Parsed(shape),
                None => InputCheck::Unchecked,
            },
            None => InputCheck::None,
        };
        let plan = match check(&args, input) {
            Ok(plan) => Some(plan),
            Err(error) => {
                let slot = slot_for(&form, &error);
                if !errors.iter().any(|(s, _)| *s == slot) {
                    errors.push((slot, Message::Recipe(error)));
                }
                None
            }
        };
        if let Some(problem) = &st.file_problem {
            if let Some(i) = form.fields.iter().position(|f| f.kind == Kind::File) {
                errors.retain(|(s, _)| *s != Slot::Field(i));
                errors.push((Slot::Field(i), problem.clone()));
            }
        }
        if let Some((failed_args, slot, message)) = &st.failed {
            if *failed_args == args && !errors.iter().any(|(s, _)| s == slot) {
                errors.push((*slot, message.clone()));
            }
        }
        drop(st);
        drop(form);
        let plan = if errors.is_empty() { plan } else { None };
        {
            let mut st = self.st.borrow_mut();
            st.errors = errors;
            st.plan = plan;
            st.texts = texts;
        }
        self.render_errors();
    }

    fn render_errors(&self) {
        let st = self.st.borrow();
        let by_field: Vec<(usize, Message)> = st
            .errors
            .iter()
            .filter_map(|(slot, m)| match slot {
                Slot::Field(i) => Some((*i, m.clone())),
                Slot::General => None,
            })
            .collect();
        self.form.borrow_mut().show_errors(&by_field);
        match st.errors.iter().find(|(s, _)| *s == Slot::General) {
            Some((_, message)) => {
                self.els.error.set_text_content(Some(&message.text()));
                show(&self.els.error, true);
            }
            None => {
                self.els.error.set_text_content(None);
                show(&self.els.error, false);
            }
        }
        drop(st);
        self.render_stale();
    }

    /// A field changed: validate, rewrite the URL soon, run soon if small.
    fn on_edit(&self) {
        self.validate();
        let (valid, small, large) = {
            let st = self.st.borrow();
            let valid = st.errors.is_empty();
            let small = st.plan.is_some_and(|p| p.is_small());
            (valid, small, valid && !small)
        };
        {
            let mut st = self.st.borrow_mut();
            if st.status != Status::Running {
                st.status = if large { Status::Large } else { Status::Idle };
            }
            st.copy_status = None;
        }
        self.els.copy_status.set_text_content(None);
        self.render_status();
        self.url_timer.schedule(URL_DELAY_MS);
        if valid && small {
            self.auto_timer.schedule(AUTO_RUN_DELAY_MS);
        } else {
            self.auto_timer.cancel();
        }
    }

    /// Runs now if the form is valid, small and not already shown; otherwise says what is
    /// needed.
    fn auto_run(&self) {
        let (valid, plan, busy) = {
            let st = self.st.borrow();
            (
                st.errors.is_empty(),
                st.plan,
                st.status == Status::Running || st.reading.is_some(),
            )
        };
        if busy || !valid {
            return;
        }
        match plan {
            Some(plan) if plan.is_small() => {
                let args = self.current_args();
                let already = self
                    .st
                    .borrow()
                    .shown
                    .as_ref()
                    .is_some_and(|s| s.args == args);
                if !already {
                    self.run_now();
                }
            }
            Some(_) => {
                self.st.borrow_mut().status = Status::Large;
                self.render_status();
            }
            None => {}
        }
    }

    /// Run / Enter / `r`: shows "Running…", lets the browser paint it, then runs.
    pub(crate) fn request_run(&self) {
        self.auto_timer.cancel();
        if self.st.borrow().status == Status::Running {
            return;
        }
        if self.st.borrow().reading.is_some() {
            return;
        }
        self.validate();
        if !self.st.borrow().errors.is_empty() {
            self.st.borrow_mut().status = Status::Invalid;
            self.render_status();
            self.form.borrow().focus_first_error();
            return;
        }
        self.st.borrow_mut().status = Status::Running;
        self.render_status();
        let weak = self.weak.borrow().clone();
        let started = after_paint(move || {
            if let Some(page) = weak.upgrade() {
                page.run_now();
            }
        });
        if started.is_err() {
            self.run_now();
        }
    }

    /// Runs the form's arguments now and shows the result (or the error).
    fn run_now(&self) {
        let args = self.current_args();
        let t0 = now_ms();
        let result = {
            let st = self.st.borrow();
            compute(&args, st.input.as_ref())
        };
        let ms = now_ms() - t0;
        match result {
            Ok(out) => {
                let input_name = {
                    let st = self.st.borrow();
                    st.input
                        .as_ref()
                        .filter(|f| args.positional.first() == Some(&f.name))
                        .map(|f| f.name.clone())
                };
                let mut st = self.st.borrow_mut();
                st.shown = Some(Shown::new(args, input_name, out));
                st.runs += 1;
                st.status = Status::Done(ms);
                st.failed = None;
                st.copy_status = None;
            }
            Err(error) => {
                let slot = slot_for(&self.form.borrow(), &error);
                let mut st = self.st.borrow_mut();
                st.failed = Some((args, slot, Message::Recipe(error)));
                st.status = Status::Failed;
            }
        }
        self.validate();
        if let Err(e) = self.render_output() {
            web_sys::console::error_2(&"drills: result".into(), &e);
        }
        self.render_status();
        self.write_url();
    }

    /// Another drill: remember this one's values, restore the other's (or its defaults).
    fn switch_recipe(&self, recipe: &'static Recipe) {
        if self.st.borrow().recipe.info.id == recipe.info.id {
            return;
        }
        self.auto_timer.cancel();
        let texts = {
            let mut st = self.st.borrow_mut();
            let current = (st.recipe.info.id, st.texts.clone());
            st.remembered.retain(|(id, _)| *id != current.0);
            st.remembered.push(current);
            st.recipe = recipe;
            st.shown = None;
            st.failed = None;
            st.status = Status::Idle;
            st.url = UrlNotes::default();
            st.copy_status = None;
            st.remembered
                .iter()
                .find(|(id, _)| *id == recipe.info.id)
                .map(|(_, t)| t.clone())
                .unwrap_or_default()
        };
        let field_list = fields::fields(recipe.info);
        let values = fill_values(&field_list, &texts);
        match Form::build(&self.els.form, recipe.info, &values) {
            Ok(form) => *self.form.borrow_mut() = form,
            Err(e) => web_sys::console::error_2(&"drills: form".into(), &e),
        }
        self.els.recipe.set_value(recipe.info.id);
        if let Err(e) = self.render_recipe_texts() {
            web_sys::console::error_2(&"drills: texts".into(), &e);
        }
        self.validate();
        self.render_notice();
        self.render_file_status();
        self.write_url();
        self.auto_run();
        if let Err(e) = self.render_output() {
            web_sys::console::error_2(&"drills: result".into(), &e);
        }
        self.render_status();
    }

    /// `[` / `]`: the previous / next drill.
    pub(crate) fn switch_by(&self, delta: i32) {
        let id = self.st.borrow().recipe.info.id;
        let n = RECIPES.len() as i32;
        let index = RECIPES.iter().position(|r| r.info.id == id).unwrap_or(0) as i32;
        let next = (index + delta).rem_euclid(n) as usize;
        if let Some(recipe) = RECIPES.get(next) {
            self.switch_recipe(recipe);
        }
    }

    /// Back to the recipe's defaults (the labeled sample for traj-resample).
    fn reset(&self) {
        self.auto_timer.cancel();
        {
            let mut st = self.st.borrow_mut();
            st.input = None;
            st.missing_file = None;
            st.file_problem = None;
            st.failed = None;
            st.url = UrlNotes::default();
            st.status = Status::Idle;
        }
        let form = self.form.borrow();
        let defaults: Vec<String> = form
            .fields
            .iter()
            .map(|f| f.spec.default.to_string())
            .collect();
        form.fill(&defaults);
        if let Some(input) = form.file_input() {
            input.set_value("");
        }
        drop(form);
        self.validate();
        self.render_notice();
        self.render_file_status();
        self.write_url();
        self.auto_run();
        self.render_status();
    }

    /// "Use the built-in labeled sample": forget the opened file.
    fn use_sample(&self) {
        {
            let mut st = self.st.borrow_mut();
            st.input = None;
            st.missing_file = None;
            st.file_problem = None;
            st.url.missing_file = None;
            st.read_generation += 1;
            st.reading = None;
        }
        if let Some(input) = self.form.borrow().file_input() {
            input.set_value("");
        }
        self.after_input_change();
    }

    /// A file was chosen: refuse it above the kernel's limit, else read it.
    fn on_file_chosen(&self) {
        let chosen = self.form.borrow().file_input().and_then(file::chosen);
        let Some((name, bytes, blob)) = chosen else {
            return;
        };
        let name = path_word(&name);
        let limit = traj_resample::MAX_INPUT_BYTES;
        if bytes > limit {
            {
                let mut st = self.st.borrow_mut();
                st.file_problem = Some(Message::FileTooLarge { name, bytes, limit });
                st.read_generation += 1;
                st.reading = None;
            }
            if let Some(input) = self.form.borrow().file_input() {
                input.set_value("");
            }
            self.after_input_change();
            return;
        }
        let generation = {
            let mut st = self.st.borrow_mut();
            st.read_generation += 1;
            st.reading = Some(name.clone());
            st.file_problem = None;
            st.status = Status::Reading(name.clone());
            st.read_generation
        };
        self.render_status();
        self.render_file_status();
        let weak = self.weak.borrow().clone();
        file::read_text(&blob, move |result| {
            let Some(page) = weak.upgrade() else {
                return;
            };
            page.file_read(generation, name, bytes, result);
        });
    }

    /// The chosen file's text arrived (or reading failed).
    fn file_read(&self, generation: u32, name: String, bytes: u64, result: Result<String, String>) {
        {
            let mut st = self.st.borrow_mut();
            if st.read_generation != generation {
                return;
            }
            st.reading = None;
            st.status = Status::Idle;
            match result {
                Ok(text) => {
                    let shape = (bytes <= plan::PRECHECK_MAX_BYTES).then(|| plan::shape_of(&text));
                    st.input = Some(InputFile {
                        name,
                        bytes,
                        text,
                        shape,
                    });
                    st.missing_file = None;
                    st.url.missing_file = None;
                    st.file_problem = None;
                }
                Err(reason) => {
                    st.file_problem = Some(Message::FileUnreadable { name, reason });
                }
            }
        }
        if let Some(input) = self.form.borrow().file_input() {
            input.set_value("");
        }
        self.after_input_change();
    }

    /// The input file changed: check, show, write the URL, run if small.
    fn after_input_change(&self) {
        self.validate();
        self.render_notice();
        self.render_file_status();
        self.write_url();
        {
            let mut st = self.st.borrow_mut();
            if st.status != Status::Running {
                st.status = Status::Idle;
            }
        }
        self.auto_run();
        self.render_status();
    }

    /// Writes the form into the URL now.
    fn write_url(&self) {
        self.url_timer.cancel();
        let texts = self.current_texts();
        let form = self.form.borrow();
        let pairs = query::pairs(form.recipe, &form.fields, &texts);
        router::replace_query(&pairs);
    }

    /// A download button: the last run's file, exactly its bytes.
    fn download(&self, file: &str) {
        let result = {
            let st = self.st.borrow();
            match st.shown.as_ref().and_then(|s| s.output.file(file)) {
                Some(text) => crate::ui::download::download_text(file, text, "text/csv"),
                None => Ok(()),
            }
        };
        if let Err(e) = result {
            let reason = e.as_string().unwrap_or_else(|| format!("{e:?}"));
            self.els.error.set_text_content(Some(&t_strings(
                "drills-download-failed",
                &[("file", file.to_string()), ("error", reason)],
            )));
            show(&self.els.error, true);
        }
    }

    /// `d`: the first file of the last run.
    pub(crate) fn download_first(&self) {
        let first = self
            .st
            .borrow()
            .shown
            .as_ref()
            .and_then(|s| s.output.files.first())
            .map(|f| f.name.clone());
        if let Some(name) = first {
            self.download(&name);
        }
    }

    /// A copy button: its command line to the clipboard.
    fn copy_command(&self, kind: &str) {
        let code = if kind == "python" {
            &self.els.cmd_python
        } else {
            &self.els.cmd_bsv
        };
        let text = code.text_content().unwrap_or_default();
        let weak = self.weak.borrow().clone();
        clipboard::copy_text(&text, move |ok| {
            let Some(page) = weak.upgrade() else {
                return;
            };
            let id = if ok {
                "drills-copied"
            } else {
                "drills-copy-failed"
            };
            page.st.borrow_mut().copy_status = Some(id);
            page.els.copy_status.set_text_content(Some(&ctx::t(id)));
        });
    }

    /// Title, blurb, explanation and quirks of the current recipe (kept localized by the
    /// shell through `data-i18n`).
    fn render_recipe_texts(&self) -> Result<(), JsValue> {
        let id = self.st.borrow().recipe.info.id;
        dom::set_i18n(&self.els.recipe_title, &format!("recipe-{id}-title"))?;
        dom::set_i18n(&self.els.recipe_blurb, &format!("recipe-{id}-blurb"))?;
        dom::set_i18n(&self.els.about, &texts::about_id(id))?;
        match texts::quirk_id(id) {
            Some(quirk) => {
                dom::set_i18n(&self.els.quirk, &quirk)?;
                show(&self.els.quirk_box, true);
            }
            None => show(&self.els.quirk_box, false),
        }
        self.els.page.set_attribute("data-recipe", id)
    }

    /// The status line beside Run and the page's `data-state`.
    fn render_status(&self) {
        let st = self.st.borrow();
        let (text, bad) = match &st.status {
            Status::Idle => (String::new(), false),
            Status::Running => (ctx::t("drills-running"), false),
            Status::Large => (ctx::t("drills-large"), false),
            Status::Invalid => (ctx::t("drills-invalid"), true),
            Status::Reading(name) => (
                t_strings("drills-reading", &[("name", name.clone())]),
                false,
            ),
            Status::Done(ms) => (
                t_strings("drills-done", &[("ms", format!("{}", ms.max(0.0).round()))]),
                false,
            ),
            Status::Failed => (ctx::t("drills-failed"), true),
        };
        self.els.status.set_text_content(Some(&text));
        let _ = self
            .els
            .status
            .class_list()
            .toggle_with_force("drills-status-bad", bad);
        let running = st.status == Status::Running;
        let _ = self
            .els
            .page
            .set_attribute("data-state", if running { "running" } else { "ready" });
        let _ = self
            .els
            .run
            .set_attribute("aria-busy", if running { "true" } else { "false" });
        drop(st);
        self.render_stale();
    }

    /// The "values changed since this result" note.
    fn render_stale(&self) {
        let st = self.st.borrow();
        let stale = match &st.shown {
            Some(shown) => {
                let texts = &st.texts;
                let form = self.form.try_borrow();
                match form {
                    Ok(form) => shown.args != RunArgs::new(form.recipe, &form.fields, texts),
                    Err(_) => false,
                }
            }
            None => false,
        };
        show(&self.els.stale, stale && st.status != Status::Running);
    }

    /// The notice about the URL the page was opened with.
    fn render_notice(&self) {
        let st = self.st.borrow();
        let url = &st.url;
        if url.is_empty() {
            show(&self.els.url_notice, false);
            return;
        }
        let mut parts = Vec::new();
        if let Some(id) = &url.unknown_recipe {
            let title = ctx::t(&format!("recipe-{}-title", st.recipe.info.id));
            parts.push(t_strings(
                "drills-url-unknown-recipe",
                &[("id", id.clone()), ("title", title)],
            ));
        }
        if !url.ignored.is_empty() {
            parts.push(t_strings(
                "drills-url-ignored",
                &[("keys", url.ignored.join(", "))],
            ));
        }
        if !url.invalid.is_empty() {
            parts.push(t_strings(
                "drills-url-invalid",
                &[("keys", url.invalid.join(", "))],
            ));
        }
        if let Some(name) = &url.missing_file {
            parts.push(t_strings("drills-url-file", &[("name", name.clone())]));
        }
        self.els.url_notice.set_text_content(Some(&parts.join(" ")));
        show(&self.els.url_notice, true);
    }

    /// traj-resample's line under the file picker: which input the run uses.
    fn render_file_status(&self) {
        let form = self.form.borrow();
        let Some(status) = form.file_status.as_ref() else {
            return;
        };
        let st = self.st.borrow();
        let text = if let Some(name) = &st.reading {
            t_strings("drills-reading", &[("name", name.clone())])
        } else if let Some(file) = &st.input {
            let mut args = vec![
                ("name", file.name.clone()),
                ("size", texts::size_text(file.bytes)),
            ];
            match &file.shape {
                Some(Ok(shape)) => {
                    args.push(("rows", texts::group(shape.rows as u64)));
                    args.push(("joints", shape.joints.to_string()));
                    t_strings("drills-file-using-rows", &args)
                }
                _ => t_strings("drills-file-using", &args),
            }
        } else if let Some(name) = &st.missing_file {
            t_strings("drills-file-missing", &[("name", name.clone())])
        } else {
            let rows = plan::shape_of(traj_resample::SAMPLE).map_or(0, |s| s.rows);
            t_strings(
                "drills-file-using-sample",
                &[
                    ("name", traj_resample::SAMPLE_NAME.to_string()),
                    ("rows", rows.to_string()),
                ],
            )
        };
        status.set_text_content(Some(&text));
    }

    fn relocalize(&self) {
        self.form.borrow().relocalize();
        self.render_errors();
        self.render_status();
        self.render_notice();
        self.render_file_status();
        if let Err(e) = self.render_output() {
            web_sys::console::error_2(&"drills: result".into(), &e);
        }
    }

    fn unmount(&self) {
        self.auto_timer.cancel();
        self.url_timer.cancel();
        self.listeners.borrow_mut().clear();
        let mut st = self.st.borrow_mut();
        st.read_generation += 1;
        st.shown = None;
        st.input = None;
    }
}

/// The element an event happened on.
fn target_element(event: &Event) -> Option<Element> {
    event.target().and_then(|t| t.dyn_into::<Element>().ok())
}

/// The values to put in the fields: the text, or the default where there is none.
fn fill_values(fields: &[fields::Field], texts: &[Option<String>]) -> Vec<String> {
    fields
        .iter()
        .enumerate()
        .map(|(i, f)| {
            texts
                .get(i)
                .and_then(|t| t.clone())
                .unwrap_or_else(|| f.spec.default.to_string())
        })
        .collect()
}

/// The shell's handle on the page.
struct Handle(Rc<Page>);

impl PageHandle for Handle {
    fn relocalize(&self) {
        self.0.relocalize();
    }

    fn shortcuts(&self) -> Vec<Shortcut> {
        keys::shortcuts()
    }

    fn on_key(&self, event: &KeyboardEvent) -> bool {
        keys::on_key(&self.0, event)
    }

    fn unmount(&self) {
        self.0.unmount();
    }
}
