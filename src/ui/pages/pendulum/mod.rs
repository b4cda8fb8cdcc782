//! The pendulum (`#/pendulum-energy`): the recipe's capsule pendulum swinging, stepped by the
//! MuJoCo-exact kernel in whole timesteps (never the frame clock), so after `k` steps from the
//! start the readouts show the CSV's data row `k`. Energy, angle, rate and energy-error plots
//! fill in as it swings, with the phase portrait and its separatrix; a compare switch runs
//! Euler and RK4 side by side from the same state.
//!
//! The page is a struct of components, one file each: `view` (the pendulum drawn to
//! scale), `plots`, `params` (the validated form), `readouts`, `exports` (CSV, PNG,
//! command lines) and `markup` (with the explanation). This file holds the run ([`Sim`],
//! the stepper's model, from the pure `crate::view::pendulum`) and wires them.

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
use crate::ui::kit::keymap;
use crate::ui::kit::scope::Scope;
use crate::ui::kit::stepper::{Command, Length, Speed, StepModel, StepperOptions, StepperWidget};
use crate::ui::kit::url_state::{UrlNotice, UrlWriter};
use crate::ui::page::{MountCtx, Page, PageDef, Shortcut};
use crate::ui::{ctx, dom};
use crate::view::pendulum::{cli_args, other, PageQuery, Track};

/// The page, as the shell's page table lists it.
pub const PAGE: PageDef =
    PageDef::of::<PendulumPage>("pendulum-energy", "pendulum-title", "pendulum-blurb");

/// Speeds, multiples of real time.
const SPEEDS: [f64; 7] = [0.1, 0.25, 0.5, 1.0, 2.0, 5.0, 10.0];
/// Shortest time between two URL writes while playing, ms.
const URL_EVERY_MS: f64 = 500.0;
/// 1× real time.
const DEFAULT_SPEED: usize = 3;

/// The run: one track per integrator shown (the page's first), stepped to the index asked.
pub struct Sim {
    pub params: PendulumParams,
    pub steps: u64,
    pub tracks: Vec<Track>,
    pub index: u64,
    /// Time the last `go_to` took, ms (frame work).
    pub advance_ms: f64,
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
            advance_ms: 0.0,
        })
    }
}

impl StepModel for Sim {
    fn length(&self) -> Length {
        Length::Finite(self.steps)
    }
    fn go_to(&mut self, index: u64) {
        let started = crate::ui::schedule::now_ms();
        for t in &mut self.tracks {
            t.extend_to(index as usize);
        }
        self.index = index;
        self.advance_ms = crate::ui::schedule::now_ms() - started;
    }
}

/// The mounted page.
pub struct PendulumPage(Rc<Inner>);

struct Inner {
    me: Weak<Inner>,
    root: Element,
    sim: Rc<RefCell<Sim>>,
    /// The texts of the last valid run (the URL's and the command lines').
    texts: RefCell<Vec<String>>,
    compare: Cell<bool>,
    compare_box: HtmlInputElement,
    stepper_slot: Element,
    stepper: RefCell<Option<StepperWidget<Sim>>>,
    view: RefCell<view::PendulumView>,
    plots: RefCell<plots::Plots>,
    params: RefCell<params::Params>,
    readouts: readouts::Readouts,
    exports: exports::Exports,
    url_notice: UrlNotice,
    url: Option<UrlWriter>,
    /// When the URL was last written, ms.
    url_written: Cell<f64>,
    scope: RefCell<Scope>,
}

fn role<T: JsCast>(root: &Element, name: &str) -> Result<T, JsValue> {
    dom::find(root, &format!("[data-pend=\"{name}\"]"), "pendulum")
}

/// Whether the user asked for reduced motion (no autoplay).
fn reduced_motion() -> bool {
    let Some(window) = web_sys::window() else {
        return false;
    };
    let media = js_sys::Reflect::get(&window, &"matchMedia".into())
        .ok()
        .and_then(|f| f.dyn_into::<js_sys::Function>().ok())
        .and_then(|f| {
            f.call1(&window, &"(prefers-reduced-motion: reduce)".into())
                .ok()
        });
    media
        .and_then(|m| js_sys::Reflect::get(&m, &"matches".into()).ok())
        .and_then(|v| v.as_bool())
        .unwrap_or(false)
}

impl Page for PendulumPage {
    fn mount(ctx: MountCtx) -> Result<PendulumPage, JsValue> {
        let root = ctx.root.clone();
        root.set_inner_html(&markup::page());
        dom::relocalize(&root)?;
        let (query, ignored) = PageQuery::read(&ctx.query);
        let url_notice = UrlNotice::new(role(&root, "url-notice")?, ignored)?;
        let mut form = params::Params::find(&root, role(&root, "form")?)?;
        form.fill(&query.texts);
        // The URL's values if valid, else the recipe's defaults (the fields keep the text
        // and show why).
        let (params, texts) = match params::check(&query.texts) {
            Ok(p) => (p, query.texts.clone()),
            Err(errors) => {
                form.show(errors);
                (
                    PendulumParams::default(),
                    crate::view::pendulum::default_texts(),
                )
            }
        };
        let compare_box: HtmlInputElement =
            dom::find(&root, "[data-field=\"compare\"]", "pendulum")?;
        compare_box.set_checked(query.compare);
        let sim = Rc::new(RefCell::new(Sim::new(params, query.compare)?));
        let stepper_slot = role(&root, "stepper")?;
        let view = view::PendulumView::find(&role(&root, "view-stage")?)?;
        let plots = plots::Plots::find(&role(&root, "time-stage")?, &role(&root, "phase-stage")?)?;
        let readouts = readouts::Readouts::find(&root)?;
        let exports = exports::Exports::find(&root)?;
        let inner = Rc::new_cyclic(|me: &Weak<Inner>| {
            let mut scope = Scope::new();
            let url = Some(UrlWriter::new(&mut scope, me, Inner::query));
            Inner {
                me: me.clone(),
                sim,
                texts: RefCell::new(texts),
                compare: Cell::new(query.compare),
                compare_box,
                stepper_slot,
                stepper: RefCell::new(None),
                view: RefCell::new(view),
                plots: RefCell::new(plots),
                params: RefCell::new(form),
                readouts,
                exports,
                url_notice,
                url,
                url_written: Cell::new(0.0),
                scope: RefCell::new(scope),
                root,
            }
        });
        inner.install()?;
        inner.view.borrow_mut().canvas.fit();
        inner.rebuild(DEFAULT_SPEED)?;
        let h = inner.sim.borrow().params.timestep_s;
        match query.t {
            Some(t) => inner.command(Command::Seek((t / h).round() as u64)),
            None if !reduced_motion() => inner.command(Command::Play),
            None => {}
        }
        Ok(PendulumPage(inner))
    }

    fn relocalize(&self) {
        self.0.relocalize();
    }

    fn set_projector(&self, _on: bool) {
        self.0.relayout();
    }

    fn shortcuts(&self) -> Vec<Shortcut> {
        keymap::STEPPER.to_vec()
    }

    fn on_key(&self, event: &KeyboardEvent) -> bool {
        self.0
            .stepper
            .borrow()
            .as_ref()
            .is_some_and(|s| s.on_key(event))
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
        let form = self.params.borrow().form.clone();
        scope.listen_for(&form, "input", me, |p, _| p.edited())?;
        scope.listen_for(&form, "change", me, |p, _| p.edited())?;
        scope.listen_for(&form, "submit", me, |_, e| e.prevent_default())?;
        scope.listen_for(&self.compare_box, "change", me, |p, _| {
            p.compare.set(p.compare_box.checked());
            let params = p.sim.borrow().params;
            p.restart(params);
        })?;
        scope.listen_for(&self.exports.csv, "click", me, |p, _| {
            let params = p.sim.borrow().params;
            if let Err(e) = p.exports.download_csv(&params) {
                web_sys::console::warn_1(&e);
            }
        })?;
        scope.listen_for(&self.exports.png, "click", me, |p, _| {
            let plots = p.plots.borrow();
            let layers: Vec<&HtmlCanvasElement> =
                plots.time.canvas.layers.iter().map(|l| &l.canvas).collect();
            let _ = crate::ui::kit::png::download_layers(
                &layers,
                "#ffffff",
                "pendulum_energy_plots.png",
            );
        })?;
        scope.listen_for(&self.exports.copy_bsv, "click", me, |p, _| {
            p.copy(p.exports.bsv_text());
        })?;
        scope.listen_for(&self.exports.copy_python, "click", me, |p, _| {
            if let Some(line) = p.exports.python_line() {
                p.copy(line);
            }
        })?;
        let canvas = self.view.borrow().canvas.top().canvas.clone();
        scope.listen_for(&canvas, "pointerdown", me, |p, _| {
            focus_without_scroll(&p.view.borrow().canvas.top().canvas);
        })?;
        let stages: Vec<Element> = ["view-stage", "time-stage", "phase-stage"]
            .iter()
            .filter_map(|n| role::<Element>(&self.root, n).ok())
            .collect();
        scope.observe_resize(&stages.iter().collect::<Vec<_>>(), me, |p| p.relayout())?;
        Ok(())
    }

    fn copy(&self, text: String) {
        let status = self.exports.status.clone();
        crate::ui::clipboard::copy_text(&text, move |ok| {
            status.set_text_content(Some(&ctx::t(if ok {
                "pendulum-copied"
            } else {
                "pendulum-copy-failed"
            })));
        });
    }

    /// A field changed: a valid set restarts the run, a refused one keeps the last run.
    fn edited(&self) {
        let texts = self.params.borrow().texts();
        match params::check(&texts) {
            Ok(params) => {
                self.params.borrow_mut().show(Vec::new());
                let changed = *self.texts.borrow() != texts;
                if changed {
                    *self.texts.borrow_mut() = texts;
                    self.restart(params);
                }
            }
            Err(errors) => self.params.borrow_mut().show(errors),
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
        self.update();
        Ok(())
    }

    fn command(&self, command: Command) {
        if let Some(s) = self.stepper.borrow().as_ref() {
            s.apply(command);
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
        self.params.borrow().relocalize();
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

    /// The state changed: the pendulum, the plots, the readouts, the URL.
    fn update(&self) {
        let started = crate::ui::schedule::now_ms();
        let Ok(sim) = self.sim.try_borrow() else {
            return;
        };
        let index = sim.index as usize;
        let ink = Ink::current();
        {
            // Sized on mount and on resizes only (a layout read per frame costs milliseconds).
            self.view.borrow_mut().draw(&sim.tracks, index, ink);
        }
        {
            let mut plots = self.plots.borrow_mut();
            plots.update(&sim.tracks, index);
            plots.draw(ink);
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
            self.readouts.show(&v);
        }
        let work = sim.advance_ms + crate::ui::schedule::now_ms() - started;
        drop(sim);
        bench_record(work);
        // While playing, the debounced write would never fire: write at most twice a second.
        if let Some(url) = self.url.as_ref() {
            let now = crate::ui::schedule::now_ms();
            if now - self.url_written.get() > URL_EVERY_MS {
                self.url_written.set(now);
                url.write_now();
            } else {
                url.schedule();
            }
        }
    }
}

/// Bench builds keep every frame's work (advance + draw), ms, in `window.__pendulumFrameMs`.
#[cfg(feature = "bench")]
fn bench_record(ms: f64) {
    let Some(window) = web_sys::window() else {
        return;
    };
    let key = JsValue::from_str("__pendulumFrameMs");
    let list = js_sys::Reflect::get(&window, &key)
        .ok()
        .and_then(|v| v.dyn_into::<js_sys::Array>().ok())
        .unwrap_or_else(|| {
            let a = js_sys::Array::new();
            let _ = js_sys::Reflect::set(&window, &key, &a);
            a
        });
    list.push(&JsValue::from_f64(ms));
}

#[cfg(not(feature = "bench"))]
fn bench_record(_ms: f64) {}
