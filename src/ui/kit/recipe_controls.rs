//! The controls of a page that runs one recipe live: the kit [`Form`] of the recipe's
//! arguments with a slider beside each number field, checked on every input with the recipe's
//! own parse + validate ([`crate::view::form::validate`]); the URL state of the arguments (keys
//! = the command line's argument names, see [`crate::view::signal`]); and the exports panel
//! (the recipe's CSV download, a PNG button the page fills, the `bsv` and `python` lines).
//!
//! The last valid arguments stay in use while a field holds a bad value: the page keeps its
//! plot, the download and the command lines are those of the last valid run.
//!
//! The exports panel is reached through [`RecipeExports`], a trait object: a page that loads
//! in two stages mounts the controls without it ([`RecipeControls::mount_later`]) and hands it
//! over once its second stage is in ([`RecipeControls::set_exports`]), so the command lines,
//! the downloads (the kernel's run, the CSV writing) and the clipboard are not in its first
//! stage.
//!
//! Hooks: text fields `data-field="<name>"`, messages `data-field-error="<name>"` (the kit
//! form's), sliders `data-slider="<name>"`, downloads `data-download="<file>"`.

use std::cell::{Cell, RefCell};
use std::rc::{Rc, Weak};

use wasm_bindgen::{JsCast, JsValue};
use web_sys::{Element, Event, HtmlInputElement};

use super::exports::{self, Exports};
use super::form::{escape, Form, Message, RECIPE_GROUPS};
use super::scope::Scope;
use super::url_state::UrlNotice;
use crate::args::Args;
use crate::error::RecipeError;
use crate::recipes::{PageRecipe, RecipeInfo, RunRaw};
use crate::ui::dom;
use crate::view::command_line::RunArgs;
use crate::view::form::{recipe_fields, validate, validate_changed, FieldDef};
use crate::view::signal::{read_texts, write_texts, Slider};

/// The kernel's parse + validate of a recipe's arguments.
pub type Parse<T> = fn(&Args) -> Result<T, RecipeError>;

/// The form slot, the URL notice and the exports panel's markup (the page places them); the
/// PNG button saves `png` and says `png_label_id`.
pub fn markup(
    prefix: &str,
    info: &RecipeInfo,
    png: &str,
    png_label_id: &str,
) -> (String, String, String) {
    let p = escape(prefix);
    let form =
        format!("<form class=\"kit-live-form {p}-form\" data-{p}=\"form\" novalidate></form>");
    let notice = format!("<p class=\"kit-notice {p}-notice\" data-{p}=\"url-notice\" hidden></p>");
    let mut buttons = String::from("<div class=\"kit-downloads\">");
    for file in info.writes {
        buttons.push_str(&exports::download_button(prefix, file));
    }
    buttons.push_str(&format!(
        "<button type=\"button\" class=\"button kit-download {p}-download\" data-download=\"{f}\" \
         data-i18n=\"{label}\"></button></div>",
        f = escape(png),
        label = escape(png_label_id),
    ));
    (form, notice, buttons + &exports::markup(prefix))
}

/// Messages shown beside fields (field index, message) and the fields marked invalid.
type Shown = (Vec<(usize, Message)>, Vec<usize>);

/// What the controls ask of their exports panel.
pub trait RecipeExports {
    /// Shows the command lines of `args` (recipe script `python`).
    fn show_run(&self, args: &RunArgs, python: &'static str);
    /// Clears the status line (the form changed).
    fn clear_status(&self);
    /// A copy button (`data-copy`): its command line to the clipboard.
    fn copy(&self, kind: &str);
    /// Saves `file` of the recipe's run on the arguments `raw` (the `bsv` bytes).
    fn download(&self, file: &str, raw: &[String]);
    /// The notes and the status line in the current language.
    fn relocalize(&self);
}

/// The kit's exports panel of one recipe run: the [`Exports`] of [`markup`] and the recipe's
/// kernel, which the downloads run.
pub struct RunExports {
    exports: Exports,
    run: RunRaw,
}

impl RunExports {
    /// Finds the panel of [`markup`] under `root`; `run` is the recipe's kernel.
    pub fn find(root: &Element, prefix: &str, run: RunRaw) -> Result<RunExports, JsValue> {
        Ok(RunExports {
            exports: Exports::find(root, prefix)?,
            run,
        })
    }
}

impl RecipeExports for RunExports {
    fn show_run(&self, args: &RunArgs, python: &'static str) {
        self.exports.show_run(args, python, None);
    }

    fn clear_status(&self) {
        self.exports.clear_status();
    }

    fn copy(&self, kind: &str) {
        self.exports.copy(kind);
    }

    fn download(&self, file: &str, raw: &[String]) {
        // The arguments passed the recipe's own check, so the run succeeds.
        if let Ok(out) = (self.run)(raw, Vec::new()) {
            self.exports
                .download(file, out.file(file).unwrap_or_default());
        }
    }

    fn relocalize(&self) {
        self.exports.relocalize();
    }
}

/// The form, sliders, URL notice and exports of one recipe.
pub struct RecipeControls<T> {
    pub info: &'static RecipeInfo,
    /// The page root (the exports' buttons) and the `<form>`.
    root: Element,
    container: Element,
    pub form: RefCell<Form>,
    sliders: Vec<(usize, HtmlInputElement)>,
    /// The exports panel, once the page has it.
    exports: RefCell<Option<Rc<dyn RecipeExports>>>,
    notice: UrlNotice,
    parse: Parse<T>,
    /// The texts and value of the last valid arguments.
    valid: RefCell<(Vec<Option<String>>, T)>,
    /// Messages shown beside fields and the fields marked invalid.
    shown: RefCell<Shown>,
    /// The texts of the last check when it passed with nothing shown (`None` otherwise).
    clean: RefCell<Option<Vec<Option<String>>>>,
    /// [`RecipeControls::check_only_edits`] was called.
    only_edits: Cell<bool>,
    /// A slider is being moved: its `input` came, its `change` (released, or a key's step
    /// done) not yet.
    sliding: Cell<bool>,
}

/// The texts of a valid set as the last valid arguments keep them: trimmed, `None` where
/// blank or the default.
fn canonical(texts: &[Option<String>], fields: &[FieldDef]) -> Vec<Option<String>> {
    texts
        .iter()
        .zip(fields)
        .map(|(t, f)| {
            t.as_deref()
                .map(str::trim)
                .filter(|t| !t.is_empty() && *t != f.default())
                .map(str::to_string)
        })
        .collect()
}

fn parse_texts<T>(
    info: &'static RecipeInfo,
    form: &Form,
    texts: &[Option<String>],
    parse: Parse<T>,
) -> Result<T, RecipeError> {
    let args = RunArgs::new(info.id, &form.fields, texts);
    parse(&Args::parse(&args.raw(), info.args, info.flags)?)
}

impl<T: Clone + 'static> RecipeControls<T> {
    /// Builds the form under `root` (after [`markup`] is in place) from the URL's `query`
    /// (keys in `own_keys` are the page's and not reported), with a slider per [`Slider`].
    /// A URL value the recipe refuses shows its message; the run is then the defaults'.
    pub fn mount(
        root: &Element,
        prefix: &str,
        recipe: PageRecipe,
        sliders: &[Slider],
        query: &[(String, String)],
        own_keys: &[&str],
        parse: Parse<T>,
    ) -> Result<RecipeControls<T>, JsValue> {
        let PageRecipe { info, run } = recipe;
        let controls = Self::mount_later(root, prefix, info, sliders, query, own_keys, parse)?;
        controls.set_exports(Rc::new(RunExports::find(root, prefix, run)?));
        Ok(controls)
    }

    /// [`RecipeControls::mount`] without the exports panel: the command lines stay empty and
    /// the download and copy buttons do nothing until [`RecipeControls::set_exports`].
    pub fn mount_later(
        root: &Element,
        prefix: &str,
        info: &'static RecipeInfo,
        sliders: &[Slider],
        query: &[(String, String)],
        own_keys: &[&str],
        parse: Parse<T>,
    ) -> Result<RecipeControls<T>, JsValue> {
        let fields = recipe_fields(info);
        let (texts, ignored) = read_texts(info, query, own_keys);
        let values: Vec<String> = texts
            .iter()
            .zip(&fields)
            .map(|(t, f)| t.clone().unwrap_or_else(|| f.default().to_string()))
            .collect();
        let container: Element = dom::find(root, &format!("[data-{prefix}=\"form\"]"), prefix)?;
        let form = Form::build(&container, prefix, &RECIPE_GROUPS, fields, &values)?;
        let mut slider_els = Vec::new();
        for s in sliders {
            let Some(index) = form.index_of(s.name) else {
                continue;
            };
            let text: Element =
                dom::find(&container, &format!("[data-field=\"{}\"]", s.name), prefix)?;
            text.insert_adjacent_html(
                "afterend",
                &format!(
                    "<input type=\"range\" class=\"kit-slider {prefix}-slider\" data-slider=\"{n}\" \
                     min=\"{min}\" max=\"{max}\" step=\"{step}\" data-i18n-attr=\"aria-label={label}\">",
                    n = s.name,
                    min = s.min,
                    max = s.max,
                    step = s.step,
                    label = escape(&form.fields[index].label_id),
                ),
            )?;
            slider_els.push((
                index,
                dom::find(&container, &format!("[data-slider=\"{}\"]", s.name), prefix)?,
            ));
        }
        dom::relocalize(&container)?;
        let defaults = vec![None; form.fields.len()];
        // The recipe's defaults always pass its check: its message id is enough.
        let default_value = parse_texts(info, &form, &defaults, parse)
            .map_err(|e| JsValue::from_str(e.message_id()))?;
        let notice = UrlNotice::new(
            dom::find(root, &format!("[data-{prefix}=\"url-notice\"]"), prefix)?,
            ignored,
        )?;
        let controls = RecipeControls {
            info,
            root: root.clone(),
            container,
            form: RefCell::new(form),
            sliders: slider_els,
            exports: RefCell::new(None),
            notice,
            parse,
            valid: RefCell::new((defaults, default_value)),
            shown: RefCell::new((Vec::new(), Vec::new())),
            clean: RefCell::new(None),
            only_edits: Cell::new(false),
            sliding: Cell::new(false),
        };
        controls.check(None);
        controls.sync_sliders(None);
        Ok(controls)
    }

    /// The exports panel is in: it shows the command lines of the last valid arguments, in
    /// the current language, and the download and copy buttons work.
    pub fn set_exports(&self, exports: Rc<dyn RecipeExports>) {
        *self.exports.borrow_mut() = Some(exports.clone());
        self.show_commands();
        exports.relocalize();
    }

    fn exports(&self) -> Option<Rc<dyn RecipeExports>> {
        self.exports.borrow().clone()
    }

    fn clear_status(&self) {
        if let Some(exports) = self.exports.borrow().as_ref() {
            exports.clear_status();
        }
    }

    /// Listens to the form (inputs, sliders, submit) and the exports' buttons: `changed` gets
    /// each new valid value, `png` is the PNG button.
    pub fn attach<P: 'static>(
        &self,
        scope: &mut Scope,
        page: &Weak<P>,
        get: fn(&P) -> &RecipeControls<T>,
        changed: fn(&P, T),
        png: fn(&P),
    ) -> Result<(), JsValue> {
        let form = self.container.clone();
        // What the user types changes a field before any listener hears of it: the texts last
        // checked are no longer the fields' (a page's own listener on the field runs first).
        scope.keep(crate::ui::dom::Listener::capture_for_page(
            &form,
            "input",
            page,
            move |p, e| {
                let typed = e
                    .target()
                    .and_then(|t| t.dyn_into::<Element>().ok())
                    .is_some_and(|t| t.has_attribute("data-field"));
                if typed {
                    *get(p).clean.borrow_mut() = None;
                }
            },
        )?);
        scope.listen_for(&form, "input", page, move |p, e| {
            if let Some(value) = get(p).edit(e) {
                changed(p, value);
            }
        })?;
        scope.listen_for(&form, "submit", page, |_, e| e.prevent_default())?;
        for button in dom::matching(&self.root, "[data-download]")? {
            let file = button.get_attribute("data-download").unwrap_or_default();
            scope.listen_for(&button, "click", page, move |p, _| {
                if file.ends_with(".png") {
                    png(p);
                } else {
                    get(p).download(&file);
                }
            })?;
        }
        for button in dom::matching(&self.root, "[data-copy]")? {
            let kind = button.get_attribute("data-copy").unwrap_or_default();
            scope.listen_for(&button, "click", page, move |p, _| {
                if let Some(exports) = get(p).exports() {
                    exports.copy(&kind);
                }
            })?;
        }
        Ok(())
    }

    /// An input event in the form: a slider writes its value into its text field; then the
    /// form is checked. The new value when it is valid and differs from the last.
    pub fn edit(&self, event: &Event) -> Option<T> {
        let target = event.target()?.dyn_into::<Element>().ok()?;
        let from_slider = target.get_attribute("data-slider");
        if let Some(name) = &from_slider {
            let value = target.dyn_ref::<HtmlInputElement>()?.value();
            return self.set_text(name, &value, true);
        }
        self.form.borrow().note_edit(&target);
        self.sliding.set(false);
        self.check_changed(None)
    }

    /// Whether a slider is being moved (its `change` has not come yet): a live page keeps
    /// its axes steady meanwhile and refits them when [`RecipeControls::end_slide`] says the
    /// slider was let go.
    pub fn sliding(&self) -> bool {
        self.sliding.get()
    }

    /// A slider's `change` (let go, or a key's step done): whether one was being moved.
    pub fn end_slide(&self) -> bool {
        self.sliding.replace(false)
    }

    /// Sets field `name` to `text` (a drag, a key, a slider) and checks the form.
    pub fn set_text(&self, name: &str, text: &str, from_slider: bool) -> Option<T> {
        // Any other edit ends a slide whose `change` never came.
        self.sliding.set(from_slider);
        let slider = if from_slider {
            self.form.borrow().index_of(name)
        } else {
            None
        };
        self.set_texts(&[(name, text)], slider)
    }

    /// Sets several fields at once (a drag of a point that is two arguments) and checks the
    /// form once; `slider` is the field whose slider is being dragged (left alone).
    pub fn set_texts(&self, values: &[(&str, &str)], slider: Option<usize>) -> Option<T> {
        if self.only_edits.get() {
            if let Some(result) = self.set_edited_texts(values, slider) {
                return result;
            }
        }
        {
            let form = self.form.borrow();
            let mut texts: Vec<String> = form
                .texts()
                .into_iter()
                .map(Option::unwrap_or_default)
                .collect();
            for (name, text) in values {
                if let Some(index) = form.index_of(name) {
                    texts[index] = text.to_string();
                }
            }
            form.fill(&texts);
            if let Some(el) = values.first().and_then(|(name, _)| self.field(name)) {
                form.note_edit(&el);
            }
        }
        self.check_changed(slider)
    }

    /// The text now in field `name`.
    pub fn text(&self, name: &str) -> String {
        self.field(name)
            .and_then(|el| el.dyn_into::<HtmlInputElement>().ok())
            .map(|i| i.value())
            .unwrap_or_default()
    }

    fn field(&self, name: &str) -> Option<Element> {
        self.container
            .query_selector(&format!("[data-field=\"{name}\"]"))
            .ok()
            .flatten()
    }

    /// Adds `keys` to the URL notice (a page's own keys whose values it could not use).
    pub fn note_ignored(&self, keys: Vec<crate::view::url::IgnoredKey>) {
        if keys.is_empty() {
            return;
        }
        let mut all = self.notice.keys();
        all.extend(keys);
        self.notice.set(all);
    }

    /// Back to the recipe's defaults.
    pub fn reset(&self) -> Option<T> {
        self.sliding.set(false);
        self.form.borrow().reset();
        self.notice.set(Vec::new());
        self.check_changed(None)
    }

    /// From now on a drag, a key or a slider ([`RecipeControls::set_texts`],
    /// [`RecipeControls::set_text`], a slider's input) writes only the fields whose text it
    /// changes and, while the form shows no message, checks only those alone before the whole
    /// set ([`validate_changed`]): the same messages, value, sliders and command lines as
    /// before for a fraction of a live page's frame. The page then changes the fields only
    /// through these methods and [`RecipeControls::reset`] (not with [`Form::fill`]); what the
    /// user types is checked in full as before.
    pub fn check_only_edits(&self) {
        self.only_edits.set(true);
    }

    /// [`RecipeControls::set_texts`] after a check that passed with nothing shown: the new
    /// value, if any (`None`: the form showed something, so all of it is checked as before).
    fn set_edited_texts(
        &self,
        values: &[(&str, &str)],
        slider: Option<usize>,
    ) -> Option<Option<T>> {
        let mut texts = self.clean.borrow().clone()?;
        let mut edited = Vec::new();
        let mut form = self.form.borrow_mut();
        for (name, text) in values {
            let Some(index) = form.index_of(name) else {
                continue;
            };
            if texts[index].as_deref() == Some(*text) {
                continue;
            }
            let now = form.set_value(index, text);
            if texts[index] != now {
                texts[index] = now;
                edited.push(index);
            }
        }
        if let Some(index) = values.first().and_then(|(name, _)| form.index_of(name)) {
            form.note_changed(index);
        }
        if edited.is_empty() {
            drop(form);
            self.clear_status();
            return Some(None);
        }
        let (info, parse) = (self.info, self.parse);
        let checked = validate_changed(
            &form.fields,
            &texts,
            form.changed(),
            &edited,
            |t| parse_texts(info, &form, t, parse),
            |_| None,
        );
        // Nothing was shown: only a new message needs the form's fields written.
        if !(checked.messages.is_empty() && checked.marked.is_empty()) {
            self.show_messages(&mut form, &checked.messages, &checked.marked);
        }
        let ok = checked.is_valid() && checked.marked.is_empty();
        let value = checked.value.filter(|_| ok);
        let Some(value) = value else {
            drop(form);
            *self.clean.borrow_mut() = None;
            self.clear_status();
            return Some(None);
        };
        let canonical = canonical(&texts, &form.fields);
        drop(form);
        for (index, el) in &self.sliders {
            if edited.contains(index) && Some(*index) != slider {
                if let Some(Some(text)) = texts.get(*index) {
                    if text.trim().parse::<f64>().is_ok() {
                        el.set_value(text.trim());
                    }
                }
            }
        }
        *self.clean.borrow_mut() = Some(texts);
        let new = self.valid.borrow().0 != canonical;
        *self.valid.borrow_mut() = (canonical, value);
        self.clear_status();
        if !new {
            return Some(None);
        }
        self.show_commands();
        Some(Some(self.value()))
    }

    fn check_changed(&self, slider: Option<usize>) -> Option<T> {
        let before = self.valid.borrow().0.clone();
        let valid = self.check(slider);
        self.clear_status();
        if !valid || self.valid.borrow().0 == before {
            return None;
        }
        self.show_commands();
        Some(self.value())
    }

    /// Checks the form, shows the messages; a valid set becomes the last valid one. Sliders
    /// follow the fields (all but the one being dragged).
    fn check(&self, slider: Option<usize>) -> bool {
        let mut form = self.form.borrow_mut();
        let texts = form.texts();
        let (info, parse) = (self.info, self.parse);
        let checked = validate(
            &form.fields,
            &texts,
            form.changed(),
            |t| parse_texts(info, &form, t, parse),
            |_| None,
        );
        self.show_messages(&mut form, &checked.messages, &checked.marked);
        let ok = checked.value.is_some() && checked.is_valid();
        let clean = ok && checked.messages.is_empty() && checked.marked.is_empty();
        if let Some(value) = checked.value.filter(|_| ok) {
            *self.valid.borrow_mut() = (canonical(&texts, &form.fields), value);
        }
        *self.clean.borrow_mut() = clean.then_some(texts);
        drop(form);
        if ok {
            self.sync_sliders(slider);
        }
        ok
    }

    /// Shows the recipe's `messages` beside their fields and marks fields `marked`.
    fn show_messages(&self, form: &mut Form, messages: &[(usize, RecipeError)], marked: &[usize]) {
        let messages: Vec<(usize, Message)> = messages
            .iter()
            .map(|(i, e)| (*i, Message::Recipe(e.clone())))
            .collect();
        form.show(&messages, marked);
        *self.shown.borrow_mut() = (messages, marked.to_vec());
    }

    fn sync_sliders(&self, skip: Option<usize>) {
        let form = self.form.borrow();
        let texts = form.texts();
        for (index, slider) in &self.sliders {
            if Some(*index) == skip {
                continue;
            }
            if let Some(Some(text)) = texts.get(*index) {
                if text.trim().parse::<f64>().is_ok() {
                    slider.set_value(text.trim());
                }
            }
        }
    }

    fn run_args(&self) -> RunArgs {
        let form = self.form.borrow();
        RunArgs::new(self.info.id, &form.fields, &self.valid.borrow().0)
    }

    fn show_commands(&self) {
        if let Some(exports) = self.exports() {
            exports.show_run(&self.run_args(), self.info.python);
        }
    }

    /// The value of the last valid arguments.
    pub fn value(&self) -> T {
        self.valid.borrow().1.clone()
    }

    /// The arguments of the last valid run, as the kernel parses them.
    pub fn raw_args(&self) -> Vec<String> {
        self.run_args().raw()
    }

    /// The URL pairs of the last valid arguments (those that differ from the defaults).
    pub fn url_pairs(&self) -> Vec<(String, String)> {
        write_texts(self.info, &self.valid.borrow().0)
    }

    /// Saves `file` of the recipe's run with the last valid arguments (the `bsv` bytes).
    /// Nothing before the exports panel is in.
    pub fn download(&self, file: &str) {
        if let Some(exports) = self.exports() {
            exports.download(file, &self.raw_args());
        }
    }

    /// The messages, notes, notice and download labels in the current language.
    pub fn relocalize(&self) {
        for file in self.info.writes {
            if let Ok(Some(button)) = self
                .root
                .query_selector(&format!("[data-download=\"{file}\"]"))
            {
                let label = crate::ui::ctx::t_strings(
                    "kit-exports-download",
                    &[("file", file.to_string())],
                );
                button.set_text_content(Some(&label));
            }
        }
        let (messages, marked) = self.shown.borrow().clone();
        self.form.borrow_mut().show(&messages, &marked);
        if let Some(exports) = self.exports() {
            exports.relocalize();
        }
        self.notice.relocalize();
    }
}

/// The points of a series for `plot`, whose x axis will span `x_range`: thinned to the plot's
/// own min/max decimation per pixel column ([`crate::view::signal::thin`]) once the plot has
/// laid out its panels, all of them before.
pub fn thinned(
    plot: &super::plot::Plot,
    x_range: (f64, f64),
    points: impl Iterator<Item = (f64, f64)>,
) -> Vec<(f64, f64)> {
    match plot.panel_px(0) {
        Some((x0, x1, _, _)) => {
            let x = crate::view::plot::LinearScale::new(x_range, (x0, x1));
            crate::view::signal::thin(points, &x)
        }
        None => points.collect(),
    }
}

/// [`thinned`] of `N` columns sharing their x, in one pass over `rows` (`(x, [y; N])`):
/// column `k` is the thinned `(x, y[k])` of the plot's first panel
/// ([`crate::view::signal::thin_columns`]).
pub fn thinned_columns<const N: usize>(
    plot: &super::plot::Plot,
    x_range: (f64, f64),
    rows: impl Iterator<Item = (f64, [f64; N])>,
) -> [Vec<(f64, f64)>; N] {
    match plot.panel_px(0) {
        Some((x0, x1, _, _)) => {
            let x = crate::view::plot::LinearScale::new(x_range, (x0, x1));
            crate::view::signal::thin_columns(rows, &x)
        }
        None => {
            let mut out: [Vec<(f64, f64)>; N] = std::array::from_fn(|_| Vec::new());
            for (t, ys) in rows {
                for (column, y) in out.iter_mut().zip(ys) {
                    column.push((t, y));
                }
            }
            out
        }
    }
}

/// Bench builds keep the duration of every recompute + redraw of a live page, ms, in
/// `window.__signalFrameMs` (`tests/bench/signals.bench.mjs` reads it).
pub fn record_frame_ms(ms: f64) {
    crate::ui::kit::bench_log::push_ms("__signalFrameMs", ms, crate::ui::kit::bench_log::KEEP_ALL);
}
