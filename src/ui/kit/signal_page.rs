//! The shell of a signal page: a page that runs one recipe live and plots its table
//! (`#/cubic-path`, `#/pid-step`, `#/trapezoid-profile`). One skeleton for all of them: the
//! head (title, the recipe's blurb, the URL notice), the plot card (a stage of layered
//! canvases, whatever the page puts under it), the readouts card, the parameters card (the
//! kit's [`RecipeControls`]: form, sliders, URL, exports), the exports card and the
//! explanation (the page's sections, then the recipe's quirks); one mount (markup, language,
//! controls, the stage, the readouts, the URL writer and the scope); the same answers to a
//! language or projector switch and to a resize (everything redrawn).
//!
//! A page says what differs in a [`SignalPage`]: its [`SignalSpec`] (prefix, recipe, sliders,
//! readouts, explanation sections), its extra markup, what it builds before it exists
//! ([`SignalPage::prepare`]), its listeners, its kernel (rows one at a time: the shell computes
//! a big run a slice per frame, [`LIVE_ROWS`]), its `show_run` and `redraw_all`; it registers
//! as `PageDef::of::<Signal<MyPage>>(…)`. Its plot is a [`SignalPlot`]: the kit plot with the
//! drag handles, the hover cursor and the PNG every signal page has.
//!
//! Fluent ids it reads: `<prefix>-title`, `<prefix>-plots-title`, `<prefix>-canvas-label`,
//! `<prefix>-explain-<section>` and `<prefix>-explain-<section>-title`,
//! `recipe-<recipe id>-blurb`, the recipe's quirks id and the `signals-*` card titles.
//! Hooks: `data-testid="<recipe id>-canvas"` on the top canvas, `data-<prefix>="stage"`.

use std::any::Any;
use std::cell::RefCell;
use std::rc::{Rc, Weak};

use glam::DVec2;
use wasm_bindgen::JsValue;
use web_sys::{CanvasRenderingContext2d, Element, KeyboardEvent};

use super::canvas::Ink;
use super::drag::{Drag, DragEvent, PointerKind};
use super::frame::FrameLoop;
use super::plot::{AxisSpec, Mark, Plot, SeriesSpec};
use super::readouts::{self, Readouts};
use super::recipe_controls::{self, record_frame_ms, Parse, RecipeControls};
use super::scope::Scope;
use super::url_state::UrlWriter;
use crate::pyfmt::py_float;
use crate::recipes::RecipeInfo;
use crate::ui::page::{MountCtx, Page, Shortcut};
use crate::ui::schedule::now_ms;
use crate::ui::{ctx, dom};
use crate::view::drag::HandleShape;
use crate::view::progress::group_digits;
use crate::view::signal::{nearest_row, sig, Slider};

/// What a signal page is, as the shell needs it.
pub struct SignalSpec {
    /// Prefix of its Fluent ids, classes and `data-<prefix>` roles (`cubic`).
    pub prefix: &'static str,
    /// The recipe it runs.
    pub info: &'static RecipeInfo,
    /// The file the PNG button saves.
    pub png: &'static str,
    /// Canvases in the stage: 3 (axes, data, cursor) or 4 (axes, data, marks, cursor).
    pub layers: usize,
    pub sliders: &'static [Slider],
    /// `(data-readout, label id)`.
    pub readouts: &'static [(&'static str, &'static str)],
    /// The explanation's sections (`<prefix>-explain-<section>`), before the quirks.
    pub explain: &'static [&'static str],
    /// URL keys of the page's own (not arguments, not reported as ignored).
    pub own_keys: &'static [&'static str],
    /// The page's keys, for the `?` overlay (exactly those [`SignalPage::on_key`] takes).
    pub keys: &'static [Shortcut],
}

/// What a signal page's axes do on a redraw.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Fit {
    /// Keep their ranges (a drag of a plot handle: the point stays under the pointer).
    Keep,
    /// Grow to hold the data, never shrink (a slider being moved:
    /// [`crate::view::signal::held_range`]); refitted when it is let go.
    Hold,
    /// Fit the data.
    Refit,
}

impl Fit {
    /// For a change of the arguments: `Keep` while a plot handle is dragged, `Hold` while a
    /// slider is moved, else `Refit`.
    pub fn for_change<T: Clone + 'static>(dragging: bool, controls: &RecipeControls<T>) -> Fit {
        if dragging {
            Fit::Keep
        } else if controls.sliding() {
            Fit::Hold
        } else {
            Fit::Refit
        }
    }
}

/// Runs of more rows than this are computed a slice per animation frame (at most
/// [`SLICE_MS`] of kernel work each), the last run staying on the plot and in the readouts
/// meanwhile, a line under the plot saying how far it is (a newer big change is computed
/// after it, only the latest kept; a newer small one replaces it). Smaller runs are
/// recomputed within the input's frame (about 15 ms at this size: kernel, readouts and plot).
/// A million rows (every page's limit) in one task was 100-300 ms.
pub const LIVE_ROWS: u64 = 150_000;
/// The kernel work of one slice, ms.
pub const SLICE_MS: f64 = 8.0;
/// Rows pulled between two looks at the clock.
const CLOCK_EVERY: usize = 2048;

/// Where a run shown by [`SignalPage::show_run`] comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RunFrom {
    /// The page's first run (the URL's arguments).
    Mount,
    /// A change, computed within its input's frame.
    Input,
    /// A change computed in slices, shown once finished (the input may be over).
    Slices,
}

/// A run being computed in slices.
struct Sliced<P, R> {
    params: P,
    source: Box<dyn Iterator<Item = R>>,
    rows: Vec<R>,
    total: u64,
    from: RunFrom,
    /// The latest big change that came meanwhile: computed once this run is shown.
    next: Option<P>,
}

/// The parts every signal page has once it is mounted.
pub struct Shell<T> {
    pub root: Element,
    pub controls: RecipeControls<T>,
    /// The element holding the plot's canvases.
    pub stage: Element,
    pub readouts: Readouts,
    pub url: UrlWriter,
    scope: RefCell<Scope>,
    /// A run over [`LIVE_ROWS`] being computed a slice per frame (a [`Sliced`] of the page's
    /// params and rows), the loop that computes it, and the line that says so.
    pending: RefCell<Option<Box<dyn Any>>>,
    slices: FrameLoop,
    computing: Element,
}

impl<T: Clone + 'static> Shell<T> {
    /// Shows number `x` under readout `key`: `digits` significant digits, the exact value in
    /// `data-value`.
    pub fn show_number(&self, key: &str, x: f64, digits: usize) {
        self.readouts
            .set_with_value(key, &sig(x, digits), &py_float(x));
    }

    /// [`Shell::show_number`] of each `(key, x)`, 4 significant digits.
    pub fn show_numbers(&self, values: &[(&str, f64)]) {
        for (key, x) in values {
            self.show_number(key, *x, 4);
        }
    }

    /// The element of role `data-<prefix>="<role>"` (markup the page added).
    pub fn role(&self, prefix: &str, role: &str) -> Result<Element, JsValue> {
        dom::find(&self.root, &format!("[data-{prefix}=\"{role}\"]"), prefix)
    }

    /// Runs `f` with the page's scope (to add listeners).
    pub fn with_scope<R>(&self, f: impl FnOnce(&mut Scope) -> R) -> R {
        f(&mut self.scope.borrow_mut())
    }
}

/// A page built on the shell.
pub trait SignalPage: Sized + 'static {
    /// The recipe's parameters.
    type Params: Clone + 'static;
    /// One row of the kernel's table.
    type Row: 'static;
    /// What the page builds before it exists ([`SignalPage::prepare`]).
    type Parts;
    const SPEC: SignalSpec;
    /// The recipe's parse + validate.
    const PARSE: Parse<Self::Params>;

    /// Markup under the stage, in the plot card (notes, warnings, checkboxes).
    fn stage_markup() -> String;
    /// Markup under the readouts.
    fn readouts_markup() -> String {
        String::new()
    }
    /// The plot and whatever else the page needs, from the mounted markup and controls, and
    /// the first run's rows (none when the run is bigger than [`LIVE_ROWS`]: the shell computes
    /// it in slices once the page is mounted).
    fn prepare(
        ctx: &MountCtx,
        root: &Element,
        controls: &RecipeControls<Self::Params>,
        stage: &Element,
        rows: Vec<Self::Row>,
    ) -> Result<Self::Parts, JsValue>;
    /// The page, from the shell and its parts.
    fn new(shell: Shell<Self::Params>, parts: Self::Parts) -> Self;
    fn shell(&self) -> &Shell<Self::Params>;
    /// Listeners of the page's own (the plot's drags, checkboxes), once it exists.
    fn install(&self, me: &Weak<Self>) -> Result<(), JsValue>;
    /// The kernel's rows of `params`, yielded one at a time, and how many there are (about:
    /// the recipe's own estimate); `None` when the kernel refuses `params`.
    #[allow(clippy::type_complexity)]
    fn kernel(params: &Self::Params) -> Option<(Box<dyn Iterator<Item = Self::Row>>, u64)>;
    /// Shows the finished run of `params`: readouts and plots; a change's run is also
    /// announced (not the page's first). The shell writes the URL.
    fn show_run(&self, params: Self::Params, rows: Vec<Self::Row>, from: RunFrom);
    /// Everything again (mount, size, language, mode).
    fn redraw_all(&self);
    /// A slider was let go (its `change`): a page that held its axes while it moved
    /// ([`Fit::Hold`]) refits them here. By default nothing (the last change drew it all).
    fn slider_released(&self) {}
    /// Saves the plot as [`SignalSpec::png`].
    fn png(&self);
    /// The URL pairs (the arguments that differ from the defaults, by default).
    fn query(&self) -> Vec<(String, String)> {
        self.shell().controls.url_pairs()
    }
    fn on_key(&self, event: &KeyboardEvent) -> bool;
}

/// The markup of page `S`.
fn markup<S: SignalPage>() -> String {
    let spec = &S::SPEC;
    let (p, id) = (spec.prefix, spec.info.id);
    let (form, notice, exports) = recipe_controls::markup(p, spec.info, spec.png, "signals-png");
    let explain: String = spec
        .explain
        .iter()
        .map(|k| {
            format!(
                "<h3 data-i18n=\"{p}-explain-{k}-title\"></h3><p data-i18n=\"{p}-explain-{k}\"></p>"
            )
        })
        .collect();
    let under = "<canvas class=\"sig-layer\" aria-hidden=\"true\"></canvas>"
        .repeat(spec.layers.saturating_sub(1));
    format!(
        "<div class=\"sig\"><header class=\"sig-head\"><h1 data-i18n=\"{p}-title\"></h1>\
         <p class=\"sig-lede\" data-i18n=\"recipe-{id}-blurb\"></p>{notice}</header>\
         <div class=\"sig-top\"><section class=\"sig-card\"><h2 data-i18n=\"{p}-plots-title\"></h2>\
         <div class=\"sig-stage\" data-{p}=\"stage\">{under}<canvas class=\"sig-layer\" \
         data-testid=\"{id}-canvas\" role=\"img\" tabindex=\"0\" data-i18n-attr=\"aria-label={p}-canvas-label\" \
         aria-describedby=\"{p}-readouts\"></canvas></div>\
         <p class=\"sig-computing\" data-{p}=\"computing\" data-testid=\"{id}-computing\" hidden></p>\
         {stage_extra}</section>\
         <div class=\"sig-side\"><section class=\"sig-card\"><h2 data-i18n=\"signals-readouts-title\"></h2>{ro}{live}{ro_extra}</section>\
         <section class=\"sig-card\"><h2 data-i18n=\"signals-params-title\"></h2>{form}</section></div></div>\
         <section class=\"sig-card\"><h2 data-i18n=\"signals-exports-title\"></h2>{exports}</section>\
         <section class=\"sig-card sig-explain\"><h2 data-i18n=\"signals-explain-title\"></h2>{explain}\
         <h3 data-i18n=\"signals-quirks-title\"></h3><p data-i18n=\"{quirks}\"></p></section></div>",
        stage_extra = S::stage_markup(),
        ro = readouts::markup(p, spec.readouts),
        live = readouts::live_markup(p),
        ro_extra = S::readouts_markup(),
        quirks = spec.info.quirks_id,
    )
}

fn controls_of<S: SignalPage>(page: &S) -> &RecipeControls<S::Params> {
    &page.shell().controls
}

/// A change of the arguments, timed (bench builds keep the time: recompute + redraw).
fn timed_change<S: SignalPage>(page: &S, params: S::Params) {
    let t0 = now_ms();
    change(page, params);
    record_frame_ms(now_ms() - t0);
}

/// New valid arguments: a run of at most [`LIVE_ROWS`] rows is computed and shown now
/// (within the input's frame), replacing a run still being computed; a bigger one is computed
/// a slice per frame, then shown, or, while another big run is being computed, once that one
/// is shown (only the latest such change is kept).
/// The URL follows the arguments at once.
pub fn change<S: SignalPage>(page: &S, params: S::Params) {
    start(page, params, RunFrom::Input);
    page.shell().url.schedule();
}

fn start<S: SignalPage>(page: &S, params: S::Params, from: RunFrom) {
    match S::kernel(&params) {
        Some((source, total)) => run(page, params, source, total, from),
        None => stop_slices(page.shell()),
    }
}

/// Drops the run being computed in slices, if any, and its line.
fn stop_slices<T: Clone + 'static>(shell: &Shell<T>) {
    shell.pending.replace(None);
    shell.slices.cancel();
    dom::show(&shell.computing, false);
}

/// Shows the run of `params` whose rows `source` yields (`total` of them): now, or computed
/// in slices when there are more than [`LIVE_ROWS`].
fn run<S: SignalPage>(
    page: &S,
    params: S::Params,
    source: Box<dyn Iterator<Item = S::Row>>,
    total: u64,
    from: RunFrom,
) {
    let shell = page.shell();
    if total <= LIVE_ROWS {
        stop_slices(shell);
        page.show_run(params, source.collect(), from);
        return;
    }
    // A big run under way: it goes on and is shown, then the latest change is computed (a
    // slider dragged over a million rows shows a run every few frames, not none).
    if let Some(job) = shell
        .pending
        .borrow_mut()
        .as_mut()
        .and_then(|b| b.downcast_mut::<Sliced<S::Params, S::Row>>())
    {
        job.next = Some(params);
        return;
    }
    let from = if from == RunFrom::Mount {
        from
    } else {
        RunFrom::Slices
    };
    let rows = Vec::with_capacity(total as usize);
    shell.pending.replace(Some(Box::new(Sliced {
        params,
        source,
        rows,
        total,
        from,
        next: None,
    })));
    show_computing(shell, 0, total);
    shell.slices.request();
}

/// One slice of the pending run; shows it when it is complete, else asks for the next frame.
fn compute_slice<S: SignalPage>(page: &S) {
    let shell = page.shell();
    let t0 = now_ms();
    let finished = {
        let mut pending = shell.pending.borrow_mut();
        let Some(job) = pending
            .as_mut()
            .and_then(|b| b.downcast_mut::<Sliced<S::Params, S::Row>>())
        else {
            return;
        };
        let mut done = false;
        while !done && now_ms() - t0 < SLICE_MS {
            for _ in 0..CLOCK_EVERY {
                match job.source.next() {
                    Some(row) => job.rows.push(row),
                    None => {
                        done = true;
                        break;
                    }
                }
            }
        }
        if done {
            pending.take()
        } else {
            show_computing(shell, job.rows.len() as u64, job.total);
            None
        }
    };
    match finished.and_then(|b| b.downcast::<Sliced<S::Params, S::Row>>().ok()) {
        Some(job) => {
            dom::show(&shell.computing, false);
            let job = *job;
            page.show_run(job.params, job.rows, job.from);
            if let Some(next) = job.next {
                start(page, next, RunFrom::Input);
            }
        }
        None => shell.slices.request(),
    }
    record_frame_ms(now_ms() - t0);
}

/// The line under the plot: `done` of `total` rows computed.
fn show_computing<T: Clone + 'static>(shell: &Shell<T>, done: u64, total: u64) {
    let pct = (done as f64 / total.max(1) as f64 * 100.0)
        .floor()
        .min(99.0);
    shell.computing.set_text_content(Some(&ctx::t_strings(
        "signals-computing",
        &[
            ("rows", group_digits(total)),
            ("percent", format!("{pct:.0}")),
        ],
    )));
    dom::show(&shell.computing, true);
}

/// A mounted signal page.
pub struct Signal<S>(Rc<S>);

impl<S: SignalPage> Signal<S> {
    /// The page (for keys that change the arguments: call [`change`]).
    pub fn page(&self) -> &S {
        &self.0
    }
}

impl<S: SignalPage> Page for Signal<S> {
    fn mount(ctx: MountCtx) -> Result<Signal<S>, JsValue> {
        let spec = &S::SPEC;
        let p = spec.prefix;
        let root = ctx.root.clone();
        root.set_inner_html(&markup::<S>());
        dom::relocalize(&root)?;
        let controls = RecipeControls::mount(
            &root,
            p,
            spec.info,
            spec.sliders,
            &ctx.query,
            spec.own_keys,
            S::PARSE,
        )?;
        // A slider's or a handle's frame checks only the field it changed.
        controls.check_only_edits();
        let stage: Element = dom::find(&root, &format!("[data-{p}=\"stage\"]"), p)?;
        let readouts = Readouts::find(&root)?;
        let computing: Element = dom::find(&root, &format!("[data-{p}=\"computing\"]"), p)?;
        // The first run: its rows now, or (too big for the mount's task) in slices once the
        // page is mounted.
        let params = controls.value();
        let (first, big) = match S::kernel(&params) {
            Some((source, total)) if total <= LIVE_ROWS => (source.collect(), None),
            big => (Vec::new(), big),
        };
        let parts = S::prepare(&ctx, &root, &controls, &stage, first)?;
        let page = Rc::new_cyclic(|me: &Weak<S>| {
            let mut scope = Scope::new();
            let url = UrlWriter::new(&mut scope, me, S::query);
            let slices = scope.frame_loop(me, |p: &S, _| compute_slice(p));
            let shell = Shell {
                root,
                controls,
                stage,
                readouts,
                url,
                scope: RefCell::new(scope),
                pending: RefCell::new(None),
                slices,
                computing,
            };
            S::new(shell, parts)
        });
        let me = Rc::downgrade(&page);
        {
            let shell = page.shell();
            let mut scope = shell.scope.borrow_mut();
            shell
                .controls
                .attach(&mut scope, &me, controls_of::<S>, timed_change::<S>, S::png)?;
            scope.observe_resize(&[&shell.stage], &me, S::redraw_all)?;
            for slider in dom::matching(&shell.root, "[data-slider]")? {
                scope.listen_for(&slider, "change", &me, |p: &S, _| {
                    if p.shell().controls.end_slide() {
                        let t0 = now_ms();
                        p.slider_released();
                        record_frame_ms(now_ms() - t0);
                    }
                })?;
            }
        }
        page.install(&me)?;
        let t0 = now_ms();
        page.redraw_all();
        record_frame_ms(now_ms() - t0);
        if let Some((source, total)) = big {
            run(&*page, params, source, total, RunFrom::Mount);
        }
        Ok(Signal(page))
    }

    fn relocalize(&self) {
        self.0.shell().controls.relocalize();
        self.0.redraw_all();
    }

    fn set_projector(&self, _on: bool) {
        self.0.redraw_all();
    }

    fn shortcuts(&self) -> Vec<Shortcut> {
        S::SPEC.keys.to_vec()
    }

    fn on_key(&self, event: &KeyboardEvent) -> bool {
        let t0 = now_ms();
        let took = self.0.on_key(event);
        if took {
            record_frame_ms(now_ms() - t0);
        }
        took
    }
}

/// An axis: title and unit from Fluent (an empty unit id: no unit).
pub fn axis(title_id: &str, unit_id: &str, range: (f64, f64)) -> AxisSpec {
    AxisSpec {
        title: ctx::t(title_id),
        unit: if unit_id.is_empty() {
            String::new()
        } else {
            ctx::t(unit_id)
        },
        range,
    }
}

/// A series named by Fluent id `name_id`.
pub fn series(name_id: &str, rgb: (u8, u8, u8), mark: Mark, width: f64, alpha: f64) -> SeriesSpec {
    SeriesSpec {
        name: ctx::t(name_id),
        rgb,
        mark,
        width,
        alpha,
    }
}

/// Radius of a handle's hit area, CSS px (a finger's width).
const HANDLE_REACH_PX: f64 = 22.0;

/// The plot of a signal page: the kit [`Plot`] of the stage, its drags (handles `H`; `()`
/// for a plot with none), whether one is under way (the axes keep their ranges meanwhile),
/// and the hovered time of the cursor.
pub struct SignalPlot<H: Copy + PartialEq + 'static> {
    pub plot: Plot,
    drag: Option<Drag<H>>,
    /// Whether a handle is being dragged.
    pub dragging: bool,
    /// The hovered time (`None`: none yet, the cursor stands mid-run).
    pub cursor_t: Option<f64>,
}

impl<H: Copy + PartialEq + 'static> SignalPlot<H> {
    /// The plot of `stage`'s canvases.
    pub fn new(stage: &Element) -> Result<SignalPlot<H>, JsValue> {
        Ok(SignalPlot {
            plot: Plot::new(stage)?,
            drag: None,
            dragging: false,
            cursor_t: None,
        })
    }

    /// Listens for drags, hovers and taps on `stage`: `hit(page, at, kind)` says which handle
    /// a press grabs (positions in CSS px of the top canvas), `on(page, event)` hears them.
    pub fn attach<P: 'static>(
        &mut self,
        stage: &Element,
        me: &Weak<P>,
        hit: fn(&P, DVec2, PointerKind) -> Option<H>,
        on: fn(&P, DragEvent<H>),
    ) -> Result<(), JsValue> {
        let surface = self.plot.canvas.top().canvas.clone();
        let (hit_me, on_me) = (me.clone(), me.clone());
        self.drag = Some(Drag::attach(
            stage,
            &surface,
            move |at, kind| hit(&*hit_me.upgrade()?, at, kind),
            move |ev| {
                if let Some(page) = on_me.upgrade() {
                    on(&page, ev);
                }
            },
        )?);
        Ok(())
    }

    /// The hovered time at CSS px `at` (on the shared time axis), remembered for the cursor.
    pub fn hover(&mut self, at: DVec2) -> bool {
        let t = self.plot.from_px(0, at).map(|(t, _)| t);
        if t.is_some() {
            self.cursor_t = t;
        }
        t.is_some()
    }

    /// The row of `rows` under the cursor (mid-run, `mid`, before any hover); the cursor is
    /// drawn there.
    pub fn cursor_row<'a, T>(
        &mut self,
        rows: &'a [T],
        mid: f64,
        t_of: impl Fn(&T) -> f64,
    ) -> Option<&'a T> {
        let row = nearest_row(rows, self.cursor_t.unwrap_or(mid), &t_of);
        self.plot.set_cursor(row.map(&t_of));
        row
    }

    /// The handles at `centres` (CSS px), for the drags: a finger-wide circle each; their
    /// places are also written as `data-<name>-x` / `-y` on the top canvas (for tests and
    /// assistive tools), `names` in the order of `centres`.
    pub fn set_handles(&self, names: &[&str], centres: &[DVec2]) {
        if let Some(drag) = &self.drag {
            let shapes: Vec<HandleShape> = centres
                .iter()
                .map(|&centre| HandleShape::Circle {
                    centre,
                    radius: HANDLE_REACH_PX,
                })
                .collect();
            drag.set_handles(&shapes);
        }
        let top = &self.plot.canvas.top().canvas;
        for (name, at) in names.iter().zip(centres) {
            let _ = top.set_attribute(&format!("data-{name}-x"), &format!("{:.1}", at.x));
            let _ = top.set_attribute(&format!("data-{name}-y"), &format!("{:.1}", at.y));
        }
    }

    /// Saves the plot's layers, on white, as `file`.
    pub fn png(&self, file: &str) {
        if let Ok(canvas) = self.plot.canvas.flatten("#ffffff") {
            let _ = super::png::download(&canvas, file);
        }
    }
}

/// Draws a drag handle (an orange ring) at `at` on `c`.
pub fn draw_handle(c: &CanvasRenderingContext2d, at: DVec2, ink: Ink) {
    c.set_fill_style_str("rgba(194, 65, 12, 0.18)");
    c.set_stroke_style_str("#c2410c");
    c.set_line_width(2.0 * ink.line);
    c.begin_path();
    let _ = c.arc(at.x, at.y, 9.0 * ink.line, 0.0, std::f64::consts::TAU);
    c.fill();
    c.stroke();
}

/// How far from a handle a press still grabs it, CSS px (wider for touch and pen).
pub fn reach(kind: PointerKind) -> f64 {
    if kind.is_coarse() {
        24.0
    } else {
        12.0
    }
}
