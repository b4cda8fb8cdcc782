//! The pendulum (`#/pendulum-energy`): the recipe's capsule pendulum swinging, stepped by the
//! MuJoCo-exact kernel in whole timesteps (never the frame clock), so after `k` steps from the
//! start the readouts show the CSV's data row `k`. Energy, angle, rate and energy-error plots
//! fill in as it swings, with the phase portrait and its separatrix; a compare switch runs
//! Euler and RK4 side by side from the same state.
//!
//! The page is a struct of components, one file each: `view` (the pendulum drawn to
//! scale), `plots`, `params` (the kit's validated form), `readouts` (the kit's panel),
//! `exports` (the kit's panel: CSV, PNG, command lines), `markup` (with the explanation) and
//! `bench` (timing hooks, bench builds only). This file holds the run ([`Sim`], the
//! stepper's model, from the pure `crate::view::pendulum`) and wires them.

mod bench;
mod exports;
mod markup;
mod params;
mod plots;
mod readouts;
mod view;

use std::cell::{Cell, RefCell};
use std::rc::{Rc, Weak};

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::{Element, HtmlCanvasElement, HtmlInputElement, KeyboardEvent};

use crate::recipes::pendulum_energy::{Integrator, PendulumParams};
use crate::ui::kit::canvas::{focus_without_scroll, Ink};
use crate::ui::kit::exercise_slot::ExerciseSlot;
use crate::ui::kit::frame::reduced_motion;
use crate::ui::kit::keymap;
use crate::ui::kit::page_root::PageRoot;
use crate::ui::kit::scope::Scope;
use crate::ui::kit::stepper::{Command, Length, Speed, StepModel, StepperOptions, StepperWidget};
use crate::ui::kit::url_state::{UrlNotice, UrlWriter};
use crate::ui::page::{MountCtx, Page, Shortcut};
use crate::ui::schedule::{now_ms, Timer};
use crate::ui::{ctx, dom};
use crate::view::exercises::pendulum::EXERCISES;
use crate::view::exercises::PageModel;
use crate::view::pendulum::{cli_args, other, PageQuery, Track};

/// Speeds, multiples of real time.
const SPEEDS: [f64; 7] = [0.1, 0.25, 0.5, 1.0, 2.0, 5.0, 10.0];
/// Shortest time between two URL writes while playing, ms.
const URL_EVERY_MS: f64 = 500.0;
/// 1× real time.
const DEFAULT_SPEED: usize = 3;
/// The timestep control's choices, s (undamped from the default 120°, semi-implicit Euler
/// gains enough energy to go over the top from about h = 0.2 s; near the bottom it is
/// unstable above h = 2/ω₀ ≈ 0.29 s).
const TIMESTEPS: [f64; 10] = [0.0005, 0.001, 0.002, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.3];
/// At the end of a damped run, below this fraction of E(0) left the pendulum counts as at rest.
const AT_REST: f64 = 0.02;
/// The pause at the end of a looping run before it plays again from the start, ms.
const LOOP_PAUSE_MS: i32 = 1200;

/// The run: one track per integrator shown (the page's first), stepped to the index asked.
pub struct Sim {
    pub params: PendulumParams,
    pub steps: u64,
    pub tracks: Vec<Track>,
    pub index: u64,
    /// When the frame's work began (the first `go_to` since the last draw), ms.
    pub work_started: Cell<Option<f64>>,
}

impl Sim {
    fn new(params: PendulumParams, compare: bool) -> Result<Sim, JsValue> {
        let steps = params
            .validate()
            .map_err(|e| JsValue::from_str(&e.to_string()))?;
        let mut tracks = vec![Track::new(&params).map_err(|e| JsValue::from_str(&e.to_string()))?];
        if compare {
            let p = PendulumParams {
                integrator: other(params.integrator),
                ..params
            };
            tracks.push(Track::new(&p).map_err(|e| JsValue::from_str(&e.to_string()))?);
        }
        Ok(Sim {
            params,
            steps,
            tracks,
            index: 0,
            work_started: Cell::new(None),
        })
    }
}

impl StepModel for Sim {
    fn length(&self) -> Length {
        Length::Finite(self.steps)
    }
    fn go_to(&mut self, index: u64) {
        if self.work_started.get().is_none() {
            self.work_started.set(Some(now_ms()));
        }
        for t in &mut self.tracks {
            t.extend_to(index as usize);
        }
        self.index = index;
    }
}

/// Fluent arguments as texts.
type FluentTexts = Vec<(&'static str, String)>;

/// What the notice under the pendulum says. At the recipe's default damping the pendulum is
/// at rest after about a second of its five, so the default view (playing from the start)
/// ends still. The page keeps the recipe's defaults (the CSV is `bsv pendulum-energy 5`'s)
/// and says so at the end of the run, with a Replay button and one that sets the damping to
/// 0 (a swing that lasts, and Euler's drift alone).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum EndNotice {
    /// The damper has left the pendulum at rest.
    Rest,
    /// The run is over.
    End,
}

/// The mounted page.
pub struct PendulumPage {
    inner: Rc<Inner>,
    _exercises: ExerciseSlot,
}

struct Inner {
    me: Weak<Inner>,
    root: PageRoot,
    sim: Rc<RefCell<Sim>>,
    /// The texts of the last valid run (the URL's and the command lines').
    texts: RefCell<Vec<String>>,
    compare: Cell<bool>,
    compare_box: HtmlInputElement,
    /// The timestep control (a slider over [`TIMESTEPS`]) and its value.
    h_slider: HtmlInputElement,
    h_value: Element,
    /// The end-of-run notice, its text and its damping-0 button.
    end_notice: Element,
    end_text: Element,
    undamped: Element,
    /// What the notice says (kind and Fluent arguments), if shown.
    end_shown: RefCell<Option<(EndNotice, FluentTexts)>>,
    stepper_slot: Element,
    stepper: RefCell<Option<StepperWidget<Sim>>>,
    /// Whether the run plays again from the start at its end: on an opening that plays by
    /// itself, until the visitor acts (a key, a click in the page, an edit; a touch that
    /// scrolls the page is no act).
    looping: Cell<bool>,
    /// Waits out the pause before a looping run starts again.
    loop_timer: Rc<Timer>,
    view: RefCell<view::PendulumView>,
    plots: RefCell<plots::Plots>,
    /// Set while the page opens: the plots are first drawn once the pendulum is painted
    /// (their axes and grids cost more than the pendulum and its readouts).
    plots_after_paint: Cell<bool>,
    params: RefCell<params::Params>,
    readouts: RefCell<readouts::Readouts>,
    exports: exports::Exports,
    url_notice: UrlNotice,
    url: Option<UrlWriter>,
    scope: RefCell<Scope>,
}

impl Page for PendulumPage {
    fn mount(ctx: MountCtx) -> Result<PendulumPage, JsValue> {
        let exercises_root = ctx.root.clone();
        let root = PageRoot::fill(&ctx.root, &markup::page(), "pend", "pendulum")?;
        let (query, ignored) = PageQuery::read(&ctx.query);
        let url_notice = UrlNotice::new(root.role("url-notice")?, ignored)?;
        let mut form = params::Params::build(root.role("form")?, &query.texts)?;
        // The URL's values if valid, else the recipe's defaults (the fields keep the text
        // and show why).
        let (params, texts) = match form.check() {
            Some(p) => (p, query.texts.clone()),
            None => (
                PendulumParams::default(),
                crate::view::pendulum::default_texts(),
            ),
        };
        let compare_box: HtmlInputElement = root.find("[data-field=\"compare\"]")?;
        compare_box.set_checked(query.compare);
        let sim = Rc::new(RefCell::new(Sim::new(params, query.compare)?));
        let stepper_slot = root.role("stepper")?;
        let view = view::PendulumView::find(&root.role("view-stage")?)?;
        let plots = plots::Plots::find(&root.role("time-stage")?, &root.role("phase-stage")?)?;
        let readouts = readouts::Readouts::find(&root)?;
        let exports = exports::Exports::find(&root)?;
        let h_slider: HtmlInputElement = root.role("h-slider")?;
        h_slider.set_max(&(TIMESTEPS.len() - 1).to_string());
        let h_value = root.role("h-value")?;
        let end_notice = root.role("end")?;
        let end_text = root.role("end-text")?;
        let undamped = root.find("[data-action=\"undamped\"]")?;
        let inner = Rc::new_cyclic(|me: &Weak<Inner>| {
            let mut scope = Scope::new();
            let url = Some(UrlWriter::new(&mut scope, me, Inner::query));
            let loop_timer = scope.timer(me, Inner::loop_again);
            Inner {
                me: me.clone(),
                sim,
                texts: RefCell::new(texts),
                compare: Cell::new(query.compare),
                compare_box,
                h_slider,
                h_value,
                end_notice,
                end_text,
                undamped,
                end_shown: RefCell::new(None),
                stepper_slot,
                stepper: RefCell::new(None),
                looping: Cell::new(false),
                loop_timer,
                view: RefCell::new(view),
                plots: RefCell::new(plots),
                plots_after_paint: Cell::new(true),
                params: RefCell::new(form),
                readouts: RefCell::new(readouts),
                exports,
                url_notice,
                url,
                scope: RefCell::new(scope),
                root,
            }
        });
        inner.install()?;
        #[cfg(feature = "bench")]
        {
            let weak = Rc::downgrade(&inner);
            bench::install_hooks(move |steps| {
                weak.upgrade().map_or(f64::NAN, |p| p.bench_frame(steps))
            });
        }
        inner.rebuild(DEFAULT_SPEED)?;
        let first_frame = inner
            .scope
            .borrow_mut()
            .frame_loop(&inner.me, |p: &Inner, _| p.relayout_once());
        first_frame.request();
        crate::ui::schedule::after_paint_for(&inner.me, |p| {
            p.plots_after_paint.set(false);
            p.update();
        })?;
        let h = inner.sim.borrow().params.timestep_s;
        match query.t {
            Some(t) => inner.command(Command::Seek((t / h).round() as u64)),
            None if !reduced_motion() => {
                inner.looping.set(true);
                inner.command(Command::Play);
            }
            None => {}
        }
        let exercises = ExerciseSlot::lending(&exercises_root, &EXERCISES, &inner, lend_model)?;
        Ok(PendulumPage {
            inner,
            _exercises: exercises,
        })
    }

    fn relocalize(&self) {
        self.inner.relocalize();
    }

    fn set_projector(&self, _on: bool) {
        self.inner.relayout();
    }

    fn shortcuts(&self) -> Vec<Shortcut> {
        keymap::STEPPER.to_vec()
    }

    fn on_key(&self, event: &KeyboardEvent) -> bool {
        self.inner.stop_looping();
        self.inner
            .stepper
            .borrow()
            .as_ref()
            .is_some_and(|s| s.on_key(event))
    }
}

impl Drop for PendulumPage {
    fn drop(&mut self) {
        bench::remove_hooks();
    }
}

impl Inner {
    /// The URL query of the page.
    fn query(&self) -> Vec<(String, String)> {
        let sim = self.sim.borrow();
        PageQuery {
            texts: self.texts.borrow().clone(),
            t: Some(sim.index as f64 * sim.params.timestep_s),
            compare: self.compare.get(),
        }
        .write()
    }

    /// Listeners: form edits, the compare switch, exports, resizes, canvas focus.
    fn install(&self) -> Result<(), JsValue> {
        let mut scope = self.scope.borrow_mut();
        let me = &self.me;
        for kind in ["click", "keydown"] {
            scope.listen_for(&self.root, kind, me, |p, _| p.stop_looping())?;
        }
        let form = self.params.borrow().element.clone();
        let note_edit = |p: &Inner, e: &web_sys::Event| {
            if let Some(el) = e.target().and_then(|t| t.dyn_into::<Element>().ok()) {
                p.params.borrow().form.note_edit(&el);
            }
            p.edited();
        };
        scope.listen_for(&form, "input", me, note_edit)?;
        scope.listen_for(&form, "change", me, note_edit)?;
        scope.listen_for(&form, "submit", me, |_, e| e.prevent_default())?;
        scope.listen_for(&self.h_slider, "input", me, |p, _| {
            let k = p.h_slider.value().parse::<usize>().unwrap_or(0);
            let h = TIMESTEPS[k.min(TIMESTEPS.len() - 1)];
            p.params
                .borrow_mut()
                .set_text("timestep", &crate::pyfmt::py_float(h));
            p.edited();
        })?;
        let replay: Element = self.root.find("[data-action=\"replay\"]")?;
        scope.listen_for(&replay, "click", me, |p, _| p.command(Command::Play))?;
        scope.listen_for(&self.undamped, "click", me, |p, _| {
            p.params.borrow_mut().set_text("damping", "0");
            p.edited();
            p.command(Command::Play);
        })?;
        scope.listen_for(&self.compare_box, "change", me, |p, _| {
            p.compare.set(p.compare_box.checked());
            let params = p.sim.borrow().params;
            p.restart(params);
        })?;
        scope.listen_for(&self.exports.csv, "click", me, |p, _| {
            let params = p.sim.borrow().params;
            p.exports.download_csv(&params);
        })?;
        scope.listen_for(&self.exports.png, "click", me, |p, _| p.download_png())?;
        for kind in ["bsv", "python"] {
            let button: Element = self.root.find(&format!("[data-copy=\"{kind}\"]"))?;
            scope.listen_for(&button, "click", me, move |p, _| p.exports.kit.copy(kind))?;
        }
        let canvas = self.view.borrow().canvas.top().canvas.clone();
        scope.listen_for(&canvas, "pointerdown", me, |p, _| {
            focus_without_scroll(&p.view.borrow().canvas.top().canvas);
        })?;
        let stages: Vec<Element> = ["view-stage", "time-stage", "phase-stage"]
            .iter()
            .filter_map(|n| self.root.role::<Element>(n).ok())
            .collect();
        scope.observe_resize(&stages.iter().collect::<Vec<_>>(), me, |p| p.relayout())?;
        Ok(())
    }

    /// Both plots (time panels above, phase portrait below) in one PNG.
    fn download_png(&self) {
        let plots = self.plots.borrow();
        let time: Vec<&HtmlCanvasElement> =
            plots.time.canvas.layers.iter().map(|l| &l.canvas).collect();
        let phase: Vec<&HtmlCanvasElement> = plots
            .phase
            .canvas
            .layers
            .iter()
            .map(|l| &l.canvas)
            .collect();
        if let Err(e) =
            crate::ui::kit::png::download_stacked(&[&time, &phase], "#ffffff", exports::PNG_NAME)
        {
            web_sys::console::warn_1(&e);
        }
    }

    /// The visitor acted: the run stops at its end from now on.
    fn stop_looping(&self) {
        self.looping.set(false);
        self.loop_timer.cancel();
    }

    /// A looping run at its end: from the start again once it has stopped (the timer waits
    /// out [`LOOP_PAUSE_MS`] first).
    fn loop_again(&self) {
        if !self.looping.get() {
            return;
        }
        let at_end = self
            .sim
            .try_borrow()
            .is_ok_and(|sim| sim.index >= sim.steps);
        if !at_end {
            return;
        }
        if self.stepper.borrow().as_ref().is_some_and(|s| s.playing()) {
            self.loop_timer.schedule(LOOP_PAUSE_MS);
            return;
        }
        self.command(Command::Start);
        self.command(Command::Play);
    }

    /// A field changed: a valid set restarts the run, a refused one keeps the last run.
    fn edited(&self) {
        self.stop_looping();
        let texts = self.params.borrow().texts();
        let checked = self.params.borrow_mut().check();
        self.exports.kit.clear_status();
        if let Some(params) = checked {
            let changed = *self.texts.borrow() != texts;
            if changed {
                *self.texts.borrow_mut() = texts;
                self.restart(params);
            }
        }
    }

    /// A new run of `params` from the start (keeps playing if it was).
    fn restart(&self, params: PendulumParams) {
        let playing = self.stepper.borrow().as_ref().is_some_and(|s| s.playing());
        let speed = self.speed_index();
        match Sim::new(params, self.compare.get()) {
            Ok(sim) => *self.sim.borrow_mut() = sim,
            Err(e) => {
                web_sys::console::warn_1(&e);
                return;
            }
        }
        if self.rebuild(speed).is_ok() && playing {
            self.command(Command::Play);
        }
        if let Some(url) = self.url.as_ref() {
            url.schedule();
        }
    }

    /// The index of the speed selected.
    fn speed_index(&self) -> usize {
        self.stepper_slot
            .query_selector("[data-stepper=\"speed\"]")
            .ok()
            .flatten()
            .and_then(|s| s.dyn_into::<web_sys::HtmlSelectElement>().ok())
            .and_then(|s| usize::try_from(s.selected_index()).ok())
            .unwrap_or(DEFAULT_SPEED)
    }

    /// A stepper for the current run (speeds depend on the timestep), plots reset, redraw.
    fn rebuild(&self, speed: usize) -> Result<(), JsValue> {
        self.stepper.borrow_mut().take();
        dom::clear(&self.stepper_slot);
        let h = self.sim.borrow().params.timestep_s;
        let me = self.me.clone();
        let widget = StepperWidget::new(
            &self.stepper_slot,
            self.sim.clone(),
            StepperOptions {
                speeds: SPEEDS
                    .iter()
                    .map(|&m| Speed::times_real_time(m, 1.0 / h))
                    .collect(),
                initial_speed: speed,
                speed_label: Box::new(move |s| match s {
                    Speed::PerSecond(rate) => {
                        ctx::t_args("pendulum-speed", &[("m", (rate * h).into())])
                    }
                    Speed::Max => ctx::t("kit-stepper-speed-max"),
                }),
                testid: "pendulum-stepper",
            },
            move |_| {
                if let Some(p) = me.upgrade() {
                    p.update();
                }
            },
        )?;
        *self.stepper.borrow_mut() = Some(widget);
        {
            let sim = self.sim.borrow();
            self.plots.borrow_mut().reset(&sim.tracks, sim.steps);
        }
        let args = cli_args(&self.texts.borrow());
        self.exports.update(&self.sim.borrow().params, &args);
        self.show_timestep();
        self.update();
        Ok(())
    }

    /// The timestep control at the run's timestep (the nearest choice).
    fn show_timestep(&self) {
        let h = self.sim.borrow().params.timestep_s;
        let k = TIMESTEPS
            .iter()
            .enumerate()
            .min_by(|a, b| {
                let d = |x: f64| (x.ln() - h.ln()).abs();
                d(*a.1).total_cmp(&d(*b.1))
            })
            .map_or(0, |(k, _)| k);
        self.h_slider.set_value(&k.to_string());
        self.h_value.set_text_content(Some(&ctx::t_strings(
            "pendulum-h-value",
            &[("h", crate::pyfmt::py_float(h))],
        )));
    }

    /// Bench builds: one frame's work, `steps` timesteps further (from the start again once
    /// the run is over), and its duration, ms.
    #[cfg(feature = "bench")]
    fn bench_frame(&self, steps: u64) -> f64 {
        self.stop_looping();
        let over = self
            .sim
            .try_borrow()
            .map_or(true, |sim| sim.index + steps > sim.steps);
        if over {
            // Over the end: the same run from the start, as a replay (not timed).
            let params = self.sim.borrow().params;
            self.restart(params);
        }
        let t0 = now_ms();
        {
            let Ok(mut sim) = self.sim.try_borrow_mut() else {
                return f64::NAN;
            };
            let next = (sim.index + steps).min(sim.steps);
            sim.go_to(next);
        }
        self.update();
        now_ms() - t0
    }

    fn command(&self, command: Command) {
        if let Some(s) = self.stepper.borrow().as_ref() {
            s.apply(command);
        }
    }

    /// The page's first frame: the pendulum sized and drawn (unless a resize did it).
    fn relayout_once(&self) {
        if !self.view.borrow().canvas.is_fitted() {
            self.relayout();
        }
    }

    /// Sizes changed: refit and redraw everything.
    fn relayout(&self) {
        self.view.borrow_mut().canvas.fit();
        {
            let mut plots = self.plots.borrow_mut();
            plots.time.invalidate_all();
            plots.phase.invalidate_all();
        }
        self.update();
    }

    /// The language changed.
    fn relocalize(&self) {
        let _ = dom::relocalize(&self.root);
        self.params.borrow_mut().check();
        self.exports.relocalize();
        self.readouts.borrow_mut().relocalize();
        self.show_timestep();
        self.render_end();
        self.url_notice.relocalize();
        if let Some(s) = self.stepper.borrow().as_ref() {
            s.relocalize();
        }
        let sim = self.sim.borrow();
        let mut plots = self.plots.borrow_mut();
        plots.reset(&sim.tracks, sim.steps);
        plots.update(&sim.tracks, sim.index as usize);
        plots.draw(Ink::current());
    }

    /// The notice under the pendulum: once the damper has left it at rest (less than
    /// [`AT_REST`] of `E(0)`), or at the end of the run (not while playing), with a Replay
    /// button (and one for no damping). Written only when what it says changes.
    fn show_end(&self, sim: &Sim, track: &Track, playing: bool, t: f64) {
        let e0 = track.start().true_energy();
        let (_, _, e) = track.state(sim.index as usize);
        let damped = sim.params.damping > 0.0;
        let at_rest = damped && e0 > 0.0 && e < AT_REST * e0;
        let at_end = !playing && sim.index >= sim.steps;
        let now = if at_rest {
            Some(EndNotice::Rest)
        } else if at_end {
            Some(EndNotice::End)
        } else {
            None
        };
        let shown = self.end_shown.borrow().as_ref().map(|(kind, _)| *kind);
        if shown == now {
            return;
        }
        match now {
            None => {
                dom::show(&self.end_notice, false);
                *self.end_shown.borrow_mut() = None;
            }
            Some(kind) => {
                let args = vec![
                    ("t", crate::pyfmt::py_float(t)),
                    (
                        "percent",
                        format!("{:.0}", 100.0 * (1.0 - e / e0.max(f64::MIN_POSITIVE))),
                    ),
                ];
                *self.end_shown.borrow_mut() = Some((kind, args));
                self.render_end();
                dom::show(&self.undamped, damped);
                dom::show(&self.end_notice, true);
            }
        }
    }

    /// The notice's text in the current language.
    fn render_end(&self) {
        if let Some((kind, args)) = self.end_shown.borrow().as_ref() {
            let id = match kind {
                EndNotice::Rest => "pendulum-end-rest",
                EndNotice::End => "pendulum-end-done",
            };
            self.end_text
                .set_text_content(Some(&ctx::t_strings(id, args)));
        }
    }

    /// The state changed: the pendulum, the plots, the readouts, the URL.
    fn update(&self) {
        let Ok(sim) = self.sim.try_borrow() else {
            return;
        };
        let started = sim.work_started.take().unwrap_or_else(now_ms);
        let index = sim.index as usize;
        let ink = Ink::current();
        {
            // Sized in the page's first frame (its loop lays the page out first) and on
            // resizes only (a layout read per frame costs milliseconds): not drawn before.
            let mut view = self.view.borrow_mut();
            if view.canvas.is_fitted() {
                view.draw(&sim.tracks, index, ink);
            }
        }
        if !self.plots_after_paint.get() {
            let mut plots = self.plots.borrow_mut();
            plots.update(&sim.tracks, index);
            plots.draw(ink);
            if !self.stepper.borrow().as_ref().is_some_and(|s| s.playing()) {
                plots.describe();
            }
        }
        if let Some(track) = sim.tracks.first() {
            let p = &sim.params;
            let (theta, omega, true_energy) = track.state(index);
            let mut v = readouts::Values {
                theta,
                omega,
                true_energy,
                drift: track.drift(index),
                period: track.period(index),
                ..Default::default()
            };
            match index.checked_sub(1).and_then(|i| track.rows().get(i)) {
                Some(r) => {
                    v.t = r.t_s;
                    v.ke = r.ke;
                    v.pe = r.pe;
                    v.total = r.total;
                }
                None => {
                    v.pe = p.mass_kg
                        * crate::recipes::pendulum_energy::GRAVITY
                        * p.length_m
                        * (1.0 - theta.cos());
                    v.total = v.pe;
                }
            }
            if let Some(second) = sim.tracks.get(1) {
                let (a, b) = (track.drift(index), second.drift(index));
                v.drifts = Some(match p.integrator {
                    Integrator::Euler => (a, b),
                    Integrator::Rk4 => (b, a),
                });
            }
            let mut readouts = self.readouts.borrow_mut();
            readouts.show(&v);
            let playing = self.stepper.borrow().as_ref().is_some_and(|s| s.playing());
            if !playing {
                readouts.announce(&v);
            }
            self.show_end(&sim, track, playing, v.t);
            if self.looping.get() && sim.index >= sim.steps {
                self.loop_timer.schedule(LOOP_PAUSE_MS);
            }
        }
        let work = now_ms() - started;
        drop(sim);
        bench::record(work);
        // While playing, the debounced write would never fire: write at most twice a second.
        if let Some(url) = self.url.as_ref() {
            url.write_at_most_every(URL_EVERY_MS);
        }
    }
}

/// The page's model for its exercises.
fn lend_model(inner: &Inner, lend: &mut dyn FnMut(&PageModel)) {
    lend(&PageModel::Pendulum(&inner.sim.borrow().params))
}
