//! The signal kit: a page that runs one recipe live and plots its table (`#/cubic-path`,
//! `#/pid-step`, `#/trapezoid-profile`). A page is a [`SignalPage`]: its [`SignalSpec`] (the
//! recipe, kernel, sliders, readouts, keys, overlays, explanation), a `build` of its own parts
//! and a `show` of the run; it registers as `PageDef::of::<Signal<MyPage>>(…)`.
//!
//! The kit does the rest: the markup, the controls ([`RecipeControls`]: form, sliders, URL,
//! exports), the plot ([`SignalPlot`]: drags, hover cursor, PNG), the first run, every change
//! (a run over [`LIVE_ROWS`] rows computed a slice per frame, thinned to the plot as its rows
//! come, summarized and shown each in a frame of its own), the URL, the arrow keys and `r`,
//! a slider let go, a drag ended, an overlay toggled, and a language, projector or size change
//! (everything shown again).

mod plot;
mod sliced;
mod spec;
mod thinned;

use std::cell::{Cell, Ref, RefCell};
use std::rc::{Rc, Weak};

use glam::DVec2;
use wasm_bindgen::{JsCast, JsValue};
use web_sys::{Element, HtmlInputElement, KeyboardEvent};

pub use self::plot::{axis, draw_handle, series, time_axis, Fit, SignalPlot};
use self::sliced::Sliced;
pub use self::sliced::{boxed, Rows, RunFrom, LIVE_ROWS};
pub use self::spec::{Arrows, Nudge, SignalSpec};
pub use self::thinned::ThinRow;
use self::thinned::{Kept, ThinCache, ThinKey};
use crate::pyfmt::py_float;
use crate::recipes::PageRecipe;
use crate::ui::dom;
use crate::ui::kit::canvas::{focus_without_scroll, Ink};
use crate::ui::kit::drag::{DragEvent, PointerKind};
use crate::ui::kit::exercise_slot::ExerciseSlot;
use crate::ui::kit::frame::FrameLoop;
use crate::ui::kit::plot::Plot;
use crate::ui::kit::readouts::Readouts;
use crate::ui::kit::recipe_controls::{record_frame_ms, RecipeControls};
use crate::ui::kit::scope::Scope;
use crate::ui::kit::url_state::UrlWriter;
use crate::ui::page::{MountCtx, Page, ShellLink, ShellRequest, Shortcut};
use crate::ui::page_frame;
use crate::ui::schedule::now_ms;
use crate::view::exercises::{Exercise, PageModel};
use crate::view::signal::sig;
pub use crate::view::signal::ColumnsThin;
pub use crate::view::signal::SignalRow;

/// A run computed in slices is shown in the slice that finds it complete if that slice has
/// worked less than this, ms; else in the next frame's.
const SHOW_AFTER_MS: f64 = 1.0;

/// Why a page shows its run again.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Draw {
    /// What the axes do.
    pub fit: Fit,
    /// The canvases are refitted and everything formatted again (mount, size, language,
    /// projector mode).
    pub resized: bool,
    /// A new run (`None`: the same run again: a slider let go, a drag ended, an overlay).
    pub run: Option<RunFrom>,
}

impl Draw {
    /// Whether this is a change's new run (announced; the page's first is not).
    pub fn changed(&self) -> bool {
        matches!(self.run, Some(RunFrom::Input | RunFrom::Slices))
    }
}

/// A live drill on the signal kit.
pub trait SignalPage: Sized + 'static {
    /// The recipe's arguments.
    type Params: Clone + 'static;
    /// One row of the kernel's table.
    type Row: SignalRow;
    /// What the page reads off every row of a run (its readouts).
    type Summary: 'static;
    /// What a press on the plot can grab (`()`: nothing).
    type Handle: Copy + PartialEq + 'static;
    const SPEC: SignalSpec<Self::Params, Self::Row>;

    /// The summary of the run of `params`, once a run: for a run computed in slices in a frame
    /// of its own before the one that shows it (showing a run then passes over none of its
    /// rows).
    fn summarize(params: &Self::Params, rows: &[Self::Row]) -> Self::Summary;

    /// The page's own parts, once the kit is mounted (markup, controls, plot, first run).
    fn build(kit: &Kit<Self>) -> Result<Self, JsValue>;
    /// Shows the kit's run ([`Kit::run`]): readouts, notes and plot (with
    /// [`Kit::draw_plot`]; the rows plotted thinned with [`Run::thinned`]); a change's run is
    /// also announced.
    fn show(&self, kit: &Kit<Self>, draw: Draw);
    /// The time axis the run of `params` is plotted over when `draw` shows it: a run computed
    /// in slices is thinned to it (and to the refitted one) as its rows come, so that showing
    /// it thins nothing.
    fn time_axis(&self, kit: &Kit<Self>, params: &Self::Params, draw: Draw) -> (f64, f64);

    /// Handle `handle` dragged to CSS px `at`: the new arguments, if any.
    fn drag(&self, _kit: &Kit<Self>, _handle: Self::Handle, _at: DVec2) -> Option<Self::Params> {
        None
    }
    /// A change ended: a field or slider committed (`change`), a key, or a run computed in
    /// slices that came after its input.
    fn change_ended(&self, _kit: &Kit<Self>) {}
    /// A click on a `[data-action]` button of the page's markup: the new arguments, if any
    /// (shown, written to the URL and committed as an edit's are).
    fn action(&self, _kit: &Kit<Self>, _action: &str) -> Option<Self::Params> {
        None
    }
    /// The page's exercises ([`crate::view::exercises`]) and the model they check.
    const EXERCISES: &'static [Exercise];
    fn exercise_model(params: &Self::Params) -> PageModel<'_>;
    /// Where the cursor stands before any hover: mid-run.
    fn cursor_start(_params: &Self::Params, rows: &[Self::Row]) -> f64 {
        rows.last().map_or(0.0, |r| r.t() / 2.0)
    }
}

/// A run shown: its arguments, rows, summary ([`SignalPage::summarize`]) and the rows'
/// thinnings (shared, never copied: a million rows are 40 MB).
pub struct Run<P, R, M> {
    pub params: P,
    pub rows: Rc<Vec<R>>,
    pub summary: Rc<M>,
    thinned: Rc<ThinCache<R>>,
}

impl<P: Clone, R, M> Clone for Run<P, R, M> {
    fn clone(&self) -> Run<P, R, M> {
        Run {
            params: self.params.clone(),
            rows: self.rows.clone(),
            summary: self.summary.clone(),
            thinned: self.thinned.clone(),
        }
    }
}

impl<P, R, M> Run<P, R, M> {
    fn new((params, rows, summary): (P, Vec<R>, M), thin: ThinRow<R>, kept: Kept) -> Run<P, R, M> {
        Run {
            params,
            rows: Rc::new(rows),
            summary: Rc::new(summary),
            thinned: Rc::new(ThinCache::new(thin, kept)),
        }
    }

    /// The plotted columns of the rows ([`SignalSpec::thin`]) thinned to time axis `x` on
    /// `plot` (each pixel column keeps its first, lowest, highest and last point; every point
    /// before the plot has a plotting area); a column the rows lack is empty.
    pub fn thinned<const N: usize>(&self, plot: &Plot, x: (f64, f64)) -> [Vec<(f64, f64)>; N] {
        let columns = self.thinned.columns(plot, x, &self.rows);
        std::array::from_fn(|k| columns.get(k).cloned().unwrap_or_default())
    }
}

/// What the kit gives a page: its elements, controls, plot and run.
pub struct Kit<S: SignalPage> {
    pub root: Element,
    pub controls: RecipeControls<S::Params>,
    /// The element holding the plot's canvases.
    pub stage: Element,
    pub readouts: Readouts,
    pub plot: RefCell<SignalPlot<S::Handle>>,
    run: RefCell<Run<S::Params, S::Row, S::Summary>>,
    /// Which [`SignalSpec::overlays`] are on.
    overlays: RefCell<Vec<bool>>,
}

impl<S: SignalPage> Kit<S> {
    /// The run shown.
    pub fn run(&self) -> Ref<'_, Run<S::Params, S::Row, S::Summary>> {
        self.run.borrow()
    }

    /// Whether overlay `k` of [`SignalSpec::overlays`] is on.
    pub fn overlay(&self, k: usize) -> bool {
        self.overlays.borrow().get(k).copied().unwrap_or(false)
    }

    /// The element of role `data-<prefix>="<role>"` (markup the page added).
    pub fn role(&self, role: &str) -> Result<Element, JsValue> {
        let p = S::SPEC.prefix;
        dom::find(&self.root, &format!("[data-{p}=\"{role}\"]"), p)
    }

    /// Shows number `x` under readout `key`: `digits` significant digits, the exact value in
    /// `data-value`.
    pub fn show_number(&self, key: &str, x: f64, digits: usize) {
        self.readouts
            .set_with_value(key, &sig(x, digits), &py_float(x));
    }

    /// [`Kit::show_number`] of each `(key, x)`, 4 significant digits.
    pub fn show_numbers(&self, values: &[(&str, f64)]) {
        for (key, x) in values {
            self.show_number(key, *x, 4);
        }
    }

    /// Draws the plot, the cursor on the row at the hovered time, and that row's readouts.
    pub fn draw_plot(&self) {
        let run = self.run.borrow();
        let start = S::cursor_start(&run.params, &run.rows);
        let readouts = {
            let mut plot = self.plot.borrow_mut();
            let row = plot.cursor_row(&run.rows, start, <S::Row as SignalRow>::t);
            let readouts = row.map(SignalRow::cursor_values);
            let _ = plot.plot.draw(Ink::current());
            readouts
        };
        if let Some(values) = readouts {
            for (key, x) in <S::Row as SignalRow>::CURSOR.into_iter().zip(values) {
                self.show_number(key, x, 4);
            }
        }
    }
}

/// A run of page `S` being computed in slices.
type Job<S> = Sliced<<S as SignalPage>::Params, <S as SignalPage>::Row, <S as SignalPage>::Summary>;

/// A mounted signal page: the page, its kit, and what computes and writes its runs.
struct Live<S: SignalPage> {
    kit: Kit<S>,
    page: S,
    url: UrlWriter,
    scope: RefCell<Scope>,
    /// A run over [`LIVE_ROWS`] being computed a slice per frame, the loop that computes it,
    /// and the line that says so.
    pending: RefCell<Option<Job<S>>>,
    slices: FrameLoop,
    computing: Element,
    /// The first drawing, in an animation frame after the mount's task (which builds the
    /// page) and the page's first layout: three shorter tasks on a phone instead of one long
    /// one. The page is settled once it has drawn.
    first: FrameLoop,
    drawn: Cell<bool>,
    shell: ShellLink,
}

impl<S: SignalPage> Live<S> {
    /// The first drawing (see [`Live::first`]); the shell is told the page is settled.
    fn first_draw(&self) {
        if self.drawn.replace(true) {
            return;
        }
        let t0 = now_ms();
        self.redraw_all();
        record_frame_ms(now_ms() - t0);
        if let Err(error) = (self.shell.request)(ShellRequest::Settled) {
            web_sys::console::error_1(&error);
        }
    }

    fn show(&self, fit: Fit, resized: bool, run: Option<RunFrom>) {
        self.page.show(&self.kit, Draw { fit, resized, run });
    }

    /// Everything again (mount, size, language, mode).
    fn redraw_all(&self) {
        self.show(Fit::Refit, true, None);
    }

    /// A change of the arguments, timed (bench builds keep the time: recompute + redraw).
    fn timed_change(&self, params: S::Params) {
        let t0 = now_ms();
        self.change(params);
        record_frame_ms(now_ms() - t0);
    }

    /// New valid arguments: a run of at most [`LIVE_ROWS`] rows is computed and shown now
    /// (within the input's frame), replacing a run still being computed; a bigger one is
    /// computed a slice per frame, then shown, or, while another big run is being computed,
    /// once that one is shown (only the latest such change is kept). The URL follows.
    fn change(&self, params: S::Params) {
        self.start(params, RunFrom::Input);
        self.url.schedule();
    }

    fn start(&self, params: S::Params, from: RunFrom) {
        match (S::SPEC.kernel)(&params) {
            Some(rows) => self.run(params, rows, from),
            None => self.stop_slices(),
        }
    }

    /// Drops the run being computed in slices, if any, and its line.
    fn stop_slices(&self) {
        self.pending.replace(None);
        self.slices.cancel();
        dom::show(&self.computing, false);
    }

    /// Shows the run of `params`: now, or computed in slices when there are more than
    /// [`LIVE_ROWS`] rows.
    fn run(&self, params: S::Params, rows: Rows<S::Row>, from: RunFrom) {
        if rows.1 <= LIVE_ROWS {
            self.stop_slices();
            let rows: Vec<S::Row> = rows.0.collect();
            let summary = S::summarize(&params, &rows);
            self.show_run((params, rows, summary), Vec::new(), from);
            return;
        }
        // A big run under way: it goes on and is shown, then the latest change is computed (a
        // slider dragged over a million rows shows a run every few frames, not none).
        if let Some(job) = self.pending.borrow_mut().as_mut() {
            job.next = Some(params);
            return;
        }
        let mut job = Sliced::new(params, rows, from, S::SPEC.thin);
        // Thinned to the axes it is shown on and to those it is refitted to when the slider or
        // the handle is let go.
        for fit in [self.fit_now(), Fit::Refit] {
            if let Some(key) = self.thin_key(&job.params, job.from, fit) {
                job.thin_to(key);
            }
        }
        self.show_progress(&job);
        self.pending.replace(Some(job));
        self.slices.request();
    }

    /// One slice of the pending run; shows it when it is complete, else asks for the next
    /// frame.
    fn compute_slice(&self) {
        let t0 = now_ms();
        let finished = {
            let mut pending = self.pending.borrow_mut();
            let Some(job) = pending.as_mut() else {
                return;
            };
            // Complete and thinned to the axes of this moment (else thinned to them over the
            // next slices: the plot was sized or refitted meanwhile): summarized, then shown,
            // each in a task of its own, not after a slice's work.
            let complete = job.pull(t0) && {
                let key = self.thin_key(&job.params, job.from, self.fit_now());
                !key.is_some_and(|key| job.thin_to(key))
            };
            let idle = now_ms() - t0 < SHOW_AFTER_MS;
            if complete && idle && job.summary.is_none() {
                job.summary = Some(S::summarize(&job.params, &job.rows));
                None
            } else if complete && idle {
                pending.take()
            } else {
                self.show_progress(job);
                None
            }
        };
        match finished {
            Some(mut job) => {
                dom::show(&self.computing, false);
                let (next, from) = (job.next.take(), job.from);
                let (params, rows, summary, kept) = job.finish();
                let summary = summary.unwrap_or_else(|| S::summarize(&params, &rows));
                self.show_run((params, rows, summary), kept, from);
                if let Some(next) = next {
                    self.start(next, RunFrom::Input);
                }
            }
            None => self.slices.request(),
        }
        record_frame_ms(now_ms() - t0);
    }

    /// How the axes fit a new run at this moment ([`Fit::for_change`]).
    fn fit_now(&self) -> Fit {
        let dragging = self.kit.plot.borrow().dragging;
        Fit::for_change(dragging, self.kit.controls.sliding())
    }

    /// What the run of `params` from `from` is thinned to when shown with `fit` now.
    fn thin_key(&self, params: &S::Params, from: RunFrom, fit: Fit) -> Option<ThinKey> {
        let draw = Draw {
            fit,
            resized: false,
            run: Some(from),
        };
        let x = self.page.time_axis(&self.kit, params, draw);
        ThinKey::of(&self.kit.plot.borrow().plot, x)
    }

    fn show_progress(&self, job: &Job<S>) {
        self.computing.set_text_content(Some(&job.progress()));
        dom::show(&self.computing, true);
    }

    /// Shows a finished run (`kept`: its rows already thinned); one computed in slices after
    /// its input ended ends the change.
    fn show_run(&self, run: (S::Params, Vec<S::Row>, S::Summary), kept: Kept, from: RunFrom) {
        *self.kit.run.borrow_mut() = Run::new(run, S::SPEC.thin, kept);
        self.show(self.fit_now(), false, Some(from));
        if from == RunFrom::Slices && !self.kit.controls.sliding() {
            self.page.change_ended(&self.kit);
        }
    }

    /// The URL pairs: the arguments that differ from the defaults, then the overlays on.
    fn query(&self) -> Vec<(String, String)> {
        let mut pairs = self.kit.controls.url_pairs();
        for (o, on) in S::SPEC
            .overlays
            .iter()
            .zip(self.kit.overlays.borrow().iter())
        {
            if *on {
                pairs.push((o.to_string(), "1".into()));
            }
        }
        pairs
    }

    fn png(&self) {
        self.kit.plot.borrow().png(S::SPEC.png);
    }

    fn grab(&self, at: DVec2, kind: PointerKind) -> Option<S::Handle> {
        self.kit.plot.borrow().grab(at, kind)
    }

    fn on_drag(&self, ev: DragEvent<S::Handle>) {
        let plot = &self.kit.plot;
        match ev {
            DragEvent::Start { handle, at, .. } | DragEvent::Move { handle, at } => {
                if matches!(ev, DragEvent::Start { .. }) {
                    plot.borrow_mut().dragging = true;
                    focus_without_scroll(&plot.borrow().plot.canvas.top().canvas);
                }
                if let Some(p) = self.page.drag(&self.kit, handle, at) {
                    self.change(p);
                }
            }
            DragEvent::End { .. } => {
                plot.borrow_mut().dragging = false;
                self.show(Fit::Refit, false, None);
                self.url.write_now();
            }
            DragEvent::Hover(at) | DragEvent::Tap { at } => {
                if plot.borrow_mut().hover(at) {
                    self.kit.draw_plot();
                }
            }
            DragEvent::Leave => {}
        }
    }

    /// `r` resets, the [`SignalSpec::nudges`] step their argument; a key taken ends the change.
    fn on_key(&self, event: &KeyboardEvent) -> bool {
        let controls = &self.kit.controls;
        let next = if matches!(event.key().as_str(), "r" | "R") {
            controls.reset()
        } else {
            let params = controls.value();
            let Some((field, text)) = S::SPEC
                .nudges
                .iter()
                .find_map(|n| Some((n.field, n.text(event, &params)?)))
            else {
                return false;
            };
            controls.set_text(field, &text, false)
        };
        if let Some(p) = next {
            self.change(p);
        }
        self.page.change_ended(&self.kit);
        true
    }

    /// The listeners: the controls and exports, the stage's size, the sliders let go, the
    /// form's committed changes, the overlays and the plot's drags.
    fn listen(&self, me: &Weak<Live<S>>) -> Result<(), JsValue> {
        let kit = &self.kit;
        let mut scope = self.scope.borrow_mut();
        kit.controls.attach(
            &mut scope,
            me,
            |l: &Live<S>| &l.kit.controls,
            Live::timed_change,
            Live::png,
        )?;
        scope.observe_resize(&[&kit.stage], me, Live::redraw_all)?;
        for slider in dom::matching(&kit.root, "[data-slider]")? {
            scope.listen_for(&slider, "change", me, |l: &Live<S>, _| {
                if l.kit.controls.end_slide() {
                    let t0 = now_ms();
                    l.show(Fit::Refit, false, None);
                    record_frame_ms(now_ms() - t0);
                }
            })?;
        }
        for button in dom::matching(&kit.root, "[data-action]")? {
            let action = button.get_attribute("data-action").unwrap_or_default();
            scope.listen_for(&button, "click", me, move |l: &Live<S>, _| {
                if let Some(p) = l.page.action(&l.kit, &action) {
                    l.timed_change(p);
                    l.page.change_ended(&l.kit);
                }
            })?;
        }
        let form = kit.role("form")?;
        scope.listen_for(&form, "change", me, |l: &Live<S>, _| {
            l.page.change_ended(&l.kit);
        })?;
        for (k, o) in S::SPEC.overlays.iter().enumerate() {
            let input = overlay_input(&kit.root, o)?;
            scope.listen_for(&input, "change", me, move |l: &Live<S>, e| {
                let checked = e
                    .target()
                    .and_then(|t| t.dyn_into::<HtmlInputElement>().ok());
                if let Some(on) = l.kit.overlays.borrow_mut().get_mut(k) {
                    *on = checked.is_some_and(|i| i.checked());
                }
                l.show(Fit::Refit, false, None);
                l.url.schedule();
            })?;
        }
        drop(scope);
        kit.plot
            .borrow_mut()
            .attach(&kit.stage, me, Live::grab, Live::on_drag)
    }
}

fn overlay_input(root: &Element, name: &str) -> Result<HtmlInputElement, JsValue> {
    dom::find(root, &format!("[data-overlay=\"{name}\"]"), name)
}

/// A mounted signal page and its exercises.
pub struct Signal<S: SignalPage> {
    live: Rc<Live<S>>,
    _exercises: ExerciseSlot,
}

impl<S: SignalPage> Page for Signal<S> {
    fn mount(ctx: MountCtx) -> Result<Signal<S>, JsValue> {
        let spec = &S::SPEC;
        let p = spec.prefix;
        let root = ctx.root.clone();
        page_frame::fill(&root, &spec::markup(spec, <S::Row as SignalRow>::CURSOR))?;
        dom::relocalize(&root)?;
        let controls = RecipeControls::mount(
            &root,
            p,
            PageRecipe {
                info: spec.info,
                run: spec.run,
            },
            spec.sliders,
            &ctx.query,
            spec.overlays,
            spec.parse,
        )?;
        // A slider's or a handle's frame checks only the field it changed.
        controls.check_only_edits();
        let overlays: Vec<bool> = spec
            .overlays
            .iter()
            .map(|o| ctx.get(o) == Some("1"))
            .collect();
        for (o, on) in spec.overlays.iter().zip(&overlays) {
            overlay_input(&root, o)?.set_checked(*on);
        }
        let stage: Element = dom::find(&root, &format!("[data-{p}=\"stage\"]"), p)?;
        let computing: Element = dom::find(&root, &format!("[data-{p}=\"computing\"]"), p)?;
        // The first run: its rows now, or (too big for the mount's task) in slices once the
        // page is mounted.
        let params = controls.value();
        let (first, big) = match (spec.kernel)(&params) {
            Some((source, total)) if total <= LIVE_ROWS => (source.collect(), None),
            big => (Vec::new(), big),
        };
        let summary = S::summarize(&params, &first);
        let kit = Kit {
            readouts: Readouts::find(&root)?,
            plot: RefCell::new(SignalPlot::new(&stage)?),
            run: RefCell::new(Run::new(
                (params.clone(), first, summary),
                spec.thin,
                Vec::new(),
            )),
            overlays: RefCell::new(overlays),
            root,
            controls,
            stage,
        };
        let page = S::build(&kit)?;
        let live = Rc::new_cyclic(|me: &Weak<Live<S>>| {
            let mut scope = Scope::new();
            let url = UrlWriter::new(&mut scope, me, Live::query);
            let slices = scope.frame_loop(me, |l: &Live<S>, _| l.compute_slice());
            let first = scope.frame_loop(me, |l: &Live<S>, _| l.first_draw());
            Live {
                kit,
                page,
                url,
                scope: RefCell::new(scope),
                pending: RefCell::new(None),
                slices,
                computing,
                first,
                drawn: Cell::new(false),
                shell: ctx.shell,
            }
        });
        live.listen(&Rc::downgrade(&live))?;
        // The page's first layout (a fresh tab's costliest: its fonts, its styles) in a task of
        // its own, then the first drawing in the next animation frame.
        let weak = Rc::downgrade(&live);
        wasm_bindgen_futures::spawn_local(async move {
            crate::ui::schedule::next_task().await;
            if let Some(live) = weak.upgrade() {
                live.kit.root.get_bounding_client_rect();
                live.first.request();
            }
        });
        if let Some(rows) = big {
            live.run(params, rows, RunFrom::Mount);
        }
        let exercises =
            ExerciseSlot::lending(&live.kit.root, S::EXERCISES, &live, |live, lend| {
                lend(&S::exercise_model(&live.kit.run().params))
            })?;
        Ok(Signal {
            live,
            _exercises: exercises,
        })
    }

    fn settled(&self) -> bool {
        self.live.drawn.get()
    }

    fn relocalize(&self) {
        self.live.kit.controls.relocalize();
        self.live.redraw_all();
    }

    fn set_projector(&self, _on: bool) {
        self.live.redraw_all();
    }

    fn shortcuts(&self) -> Vec<Shortcut> {
        spec::shortcuts(&S::SPEC)
    }

    fn on_key(&self, event: &KeyboardEvent) -> bool {
        let t0 = now_ms();
        let took = self.live.on_key(event);
        if took {
            record_frame_ms(now_ms() - t0);
        }
        took
    }
}
