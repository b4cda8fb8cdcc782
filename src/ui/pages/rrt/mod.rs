//! The RRT stepper (`#/rrt-2d`): the recipe's tree grown one iteration at a time in a world
//! the user draws, backwards too (the kernel's exact `seek`: an RNG checkpoint every 64
//! iterations and a replay), each iteration's sub-steps drawn and written out with the
//! pseudocode line that decided it, and the run's CSVs byte for byte those of `bsv rrt-2d`
//! with the page's arguments.
//!
//! Components, one file each: `run` (the run and the stepper's model), `world` (the
//! three-layer view), `substeps` (the sub-step panel and pseudocode), `key_target` (the world
//! editor by keyboard), `counters`, `params` (the validated form), `exports` (CSVs, PNG,
//! command lines) and `markup`. This file wires them: the world editor's drags (move a box,
//! resize it by a corner, move the start or the goal) go through `crate::view::rrt::drag`,
//! which refuses a start or goal inside a box or outside the square with a message; every
//! edit restarts the run at iteration 0.

mod counters;
mod exports;
mod key_target;
mod markup;
mod params;
mod run;
mod substeps;
mod world;

use std::cell::{Cell, RefCell};
use std::rc::{Rc, Weak};

use wasm_bindgen::prelude::*;
use web_sys::{Element, HtmlInputElement, KeyboardEvent};

use crate::error::RecipeError;
use crate::i18n::FluentArg;
use crate::recipes::rrt_2d::RrtOutcome;
use crate::ui::kit::canvas::{focus_without_scroll, Ink};
use crate::ui::kit::drag::{Drag, DragEvent, PointerKind};
use crate::ui::kit::exercise_slot::ExerciseSlot;
use crate::ui::kit::keymap;
use crate::ui::kit::message_line::MessageLine;
use crate::ui::kit::page_root::PageRoot;
use crate::ui::kit::scope::Scope;
use crate::ui::kit::stepper::{Command, StepperWidget};
use crate::ui::kit::url_state::{UrlNotice, UrlState, UrlWriter};
use crate::ui::page::{MountCtx, Page, Shortcut};
use crate::ui::schedule::{now_ms, Timer};
use crate::ui::{ctx, dom};
use crate::view::exercises::rrt::EXERCISES;
use crate::view::exercises::PageModel;
use crate::view::rrt::{
    add_box, delete_box, drag, hit_test, phases, Grab, PageState, Phase, Refusal, IT_KEY,
};
use run::Run;

/// The page's keys besides the stepper's.
const KEYS: [Shortcut; 4] = [
    keymap::key("n", "rrt-key-select"),
    keymap::key("c", "rrt-key-corner"),
    keymap::key("Shift + ← ↑ → ↓", "rrt-key-move"),
    keymap::key("Delete", "rrt-key-delete"),
];
/// The iteration a URL without `it` opens at: a small tree and one iteration written out in
/// the sub-step panel, rather than a lone start.
const OPENING_IT: u64 = 5;
/// Shortest time between two URL writes while playing, ms.
const URL_EVERY_MS: f64 = 500.0;
/// Runs up to this budget restart on every move of a drag; bigger ones when it ends.
const LIVE_RESTART_MAX_ITER: usize = 20_000;

/// Longest slice of the run to its end per main-thread task, ms (the page stays responsive:
/// no task near 100 ms whatever `max_iter`).
const FINISH_SLICE_MS: f64 = 20.0;
/// The first slice of the run to its end, in the mount's task, ms (a run of a few thousand
/// iterations is complete in it).
const MOUNT_SLICE_MS: f64 = 4.0;

/// A drag under way: what, where it began (world), the state before it.
type DragStart = (Grab, [f64; 2], PageState);

/// The mounted page.
pub struct RrtPage {
    inner: Rc<Inner>,
    _exercises: ExerciseSlot,
}

struct Inner {
    me: Weak<Inner>,
    root: PageRoot,
    /// The last valid state (the form's texts and the world; `it` is the run's).
    state: RefCell<PageState>,
    /// The state the run was made from (a drag of a big run restarts at its end).
    run_state: RefCell<PageState>,
    run: Rc<RefCell<Run>>,
    stepper_slot: Element,
    stepper: RefCell<Option<StepperWidget<Run>>>,
    world: RefCell<world::WorldView>,
    drag: RefCell<Option<Drag<Grab>>>,
    dragging: RefCell<Option<DragStart>>,
    hover: Cell<Option<Grab>>,
    selected: Cell<Option<usize>>,
    /// What Shift + arrows move (chosen with `n`), said in its line.
    key_target: MessageLine<Grab>,
    /// Why the last edit of the world was refused.
    refusal: MessageLine<Refusal>,
    substeps: substeps::SubSteps,
    substep_mode: HtmlInputElement,
    /// In sub-step mode: the sub-step shown (index into the iteration's phases).
    phase: Cell<Option<usize>>,
    /// The sub-step keys are moving the stepper (keep `phase`).
    substep_driving: Cell<bool>,
    params: RefCell<params::Params>,
    counters: counters::Counters,
    exports: exports::Exports,
    url_notice: UrlNotice,
    url: Option<UrlWriter>,
    /// Grows the run to its end, one slice per task.
    finisher: Rc<Timer>,
    /// Draws the rest of a big tree over the next tasks.
    tree_more: Rc<Timer>,
    /// Writes the rest of a big tree's `rrt_nodes.csv` over the next tasks.
    csv_more: Rc<Timer>,
    /// The URL's `it`, waiting for the run to its end to reach it.
    pending_it: Cell<Option<u64>>,
    /// "Running to the end: 12,345 of 1,000,000 iterations", while it is.
    finishing: Element,
    scope: RefCell<Scope>,
}

/// Why an edit of the world was refused, in the current language.
fn refusal_text(r: Refusal) -> String {
    let (id, point, index) = r.message();
    let mut args = vec![("index", FluentArg::Number(index as f64))];
    if let Some(p) = point {
        args.push(("point", FluentArg::Text(ctx::t(p.name_id()))));
    }
    ctx::t_args(id, &args)
}

fn js_error(e: &RecipeError) -> JsValue {
    JsValue::from_str(&ctx::error_text(e))
}

impl Page for RrtPage {
    fn mount(ctx: MountCtx) -> Result<RrtPage, JsValue> {
        let exercises_root = ctx.root.clone();
        let root = PageRoot::fill(&ctx.root, &markup::page(), "rrt", "rrt")?;
        let (state, ignored) = PageState::read(&ctx.query);
        let url_notice = UrlNotice::new(root.role("url-notice")?, ignored)?;
        let params = params::Params::build(root.role("form")?, &state)?;
        let setup = state.setup().map_err(|e| js_error(&e))?;
        let run = Rc::new(RefCell::new(Run::new(&setup, 0).map_err(|e| js_error(&e))?));
        let world = world::WorldView::find(&root.role("stage")?)?;
        let substeps = substeps::SubSteps::find(&root)?;
        let counters = counters::Counters::find(&root)?;
        let exports = exports::Exports::find(&root)?;
        let start_it = if ctx.query.iter().any(|(k, _)| k == IT_KEY) {
            state.it
        } else {
            OPENING_IT
        };
        let stepper_slot: Element = root.role("stepper")?;
        let refusal = MessageLine::new(root.role("world-message")?, refusal_text);
        let key_target = MessageLine::new(root.role("key-target")?, key_target::text);
        let substep_mode: HtmlInputElement = root.role("substep-mode")?;
        let finishing: Element = root.role("finishing")?;
        let inner = Rc::new_cyclic(|me: &Weak<Inner>| {
            let mut scope = Scope::new();
            let url = Some(UrlWriter::new(&mut scope, me, Inner::query));
            let finisher = scope.timer(me, Inner::finish_slice);
            let tree_more = scope.timer(me, |p: &Inner| p.draw_tree_now());
            let csv_more = scope.timer(me, Inner::csv_slice);
            Inner {
                csv_more,
                finisher,
                tree_more,
                pending_it: Cell::new(None),
                finishing,
                me: me.clone(),
                run_state: RefCell::new(state.clone()),
                state: RefCell::new(state),
                run,
                stepper_slot,
                stepper: RefCell::new(None),
                world: RefCell::new(world),
                drag: RefCell::new(None),
                dragging: RefCell::new(None),
                hover: Cell::new(None),
                selected: Cell::new(None),
                key_target,
                refusal,
                substeps,
                substep_mode,
                phase: Cell::new(None),
                substep_driving: Cell::new(false),
                params: RefCell::new(params),
                counters,
                exports,
                url_notice,
                url,
                scope: RefCell::new(scope),
                root,
            }
        });
        inner.install()?;
        inner.build_stepper()?;
        inner.exports.update(&inner.state.borrow());
        if start_it > 0 {
            inner.pending_it.set(Some(start_it));
        }
        inner.finish_slice_for(MOUNT_SLICE_MS);
        // The URL is written after the first frame (it only tidies it), not in the mount's
        // task.
        if let Some(url) = inner.url.as_ref() {
            url.hold_from_now();
        }
        inner.update();
        // The canvases are sized and drawn by the stage's first ResizeObserver callback, in
        // the first frame after its layout and before its paint: measuring them here would
        // force the whole page's first layout inside the mount's task.
        let exercises = ExerciseSlot::lending(&exercises_root, &EXERCISES, &inner, lend_model)?;
        Ok(RrtPage {
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
        keymap::with_stepper(&KEYS)
    }

    fn on_key(&self, event: &KeyboardEvent) -> bool {
        self.inner.on_key(event)
    }
}

impl Inner {
    /// The URL query of the page.
    fn query(&self) -> Vec<(String, String)> {
        let mut state = self.state.borrow().clone();
        state.it = self
            .run
            .try_borrow()
            .map_or(state.it, |r| r.shown().iterations() as u64);
        state.write()
    }

    /// Listeners: the form, the editor's buttons, the downloads, the drag, resizes.
    fn install(&self) -> Result<(), JsValue> {
        let mut scope = self.scope.borrow_mut();
        let me = &self.me;
        let form = self.params.borrow().element.clone();
        scope.listen_for(&form, "input", me, |p, e| {
            if let Some(el) = e.target().and_then(|t| t.dyn_into::<Element>().ok()) {
                p.params.borrow().form.note_edit(&el);
            }
            p.edited();
        })?;
        scope.listen_for(&form, "change", me, |p, _| p.edited())?;
        scope.listen_for(&form, "submit", me, |_, e| e.prevent_default())?;
        for (action, f) in [
            ("add-box", Inner::add_box as fn(&Inner)),
            ("delete-box", Inner::delete_box),
            ("recipe-world", Inner::recipe_world),
        ] {
            let button: Element = self.root.find(&format!("[data-action=\"{action}\"]"))?;
            scope.listen_for(&button, "click", me, move |p, _| f(p))?;
        }
        // In sub-step mode the step and back buttons walk the sub-steps, as the keys do:
        // their clicks are taken on the way down, before the stepper's own listeners.
        scope.keep(dom::Listener::capture_for_page(
            &self.stepper_slot,
            "click",
            me,
            |p, e| {
                if !p.substep_mode.checked() {
                    return;
                }
                let action = e
                    .target()
                    .and_then(|t| t.dyn_into::<Element>().ok())
                    .and_then(|el| el.closest("[data-action]").ok().flatten())
                    .and_then(|el| el.get_attribute("data-action"));
                let forward = match action.as_deref() {
                    Some("step") => true,
                    Some("back") => false,
                    _ => return,
                };
                e.stop_propagation();
                p.substep(forward);
            },
        )?);
        scope.listen_for(&self.substep_mode, "change", me, |p, _| {
            p.phase.set(None);
            p.update();
        })?;
        for (el, file) in [
            (&self.exports.nodes, "rrt_nodes.csv"),
            (&self.exports.path, "rrt_path.csv"),
        ] {
            scope.listen_for(el, "click", me, move |p, _| {
                let more = {
                    let run = p.run.borrow();
                    run.is_finished() && p.exports.download(&run, file)
                };
                if more {
                    p.csv_more.schedule(0);
                }
                p.show_finishing();
            })?;
        }
        scope.listen_for(&self.exports.png, "click", me, |p, _| {
            let world = p.world.borrow();
            if let Ok(canvas) = world.canvas.flatten("#ffffff") {
                let _ = crate::ui::kit::png::download(&canvas, "rrt_2d.png");
            }
        })?;
        for kind in ["python", "bsv"] {
            let button: Element = self.root.find(&format!("[data-copy=\"{kind}\"]"))?;
            scope.listen_for(&button, "click", me, move |p, _| {
                p.exports.commands.copy(kind)
            })?;
        }
        let (stage, top) = {
            let w = self.world.borrow();
            (w.canvas.stage.clone(), w.canvas.top().canvas.clone())
        };
        scope.listen_for(&top, "pointerdown", me, |p, _| {
            focus_without_scroll(&p.world.borrow().canvas.top().canvas);
        })?;
        scope.observe_resize(&[&stage], me, |p| p.relayout())?;
        drop(scope);
        let (w_hit, w_on) = (self.me.clone(), self.me.clone());
        *self.drag.borrow_mut() = Some(Drag::attach(
            &stage,
            &top,
            move |at, kind| {
                let p = w_hit.upgrade()?;
                let world = p.world.borrow();
                let state = p.state.borrow();
                if kind == PointerKind::Touch
                    && !world.handles(&state).iter().any(|h| h.contains(at))
                {
                    // A finger grabs only a handle; anywhere else it scrolls the page.
                    return None;
                }
                hit_test(
                    &world.frame,
                    &state,
                    at,
                    world::WorldView::hit_radius(kind.is_coarse()),
                )
            },
            move |ev| {
                if let Some(p) = w_on.upgrade() {
                    p.on_drag(ev);
                }
            },
        )?);
        Ok(())
    }

    /// A new stepper over the run (at its start).
    fn build_stepper(&self) -> Result<(), JsValue> {
        self.stepper.borrow_mut().take();
        dom::clear(&self.stepper_slot);
        let me = self.me.clone();
        let widget = StepperWidget::new(
            &self.stepper_slot,
            self.run.clone(),
            run::stepper_options(),
            move |_| {
                if let Some(p) = me.upgrade() {
                    p.update();
                }
            },
        )?;
        // As fast as possible, yet whole frames (the tree appended, the panel) stay short.
        widget.set_frame_budget(run::FRAME_BUDGET_MS, true);
        *self.stepper.borrow_mut() = Some(widget);
        Ok(())
    }

    fn command(&self, command: Command) {
        if let Some(s) = self.stepper.borrow().as_ref() {
            s.apply(command);
        }
    }

    fn playing(&self) -> bool {
        self.stepper.borrow().as_ref().is_some_and(|s| s.playing())
    }

    /// Keys: in sub-step mode the step keys walk the sub-steps (as the step buttons do); the
    /// stepper's otherwise.
    fn on_key(&self, event: &KeyboardEvent) -> bool {
        if !keymap::has_command_modifier(event) {
            let step = |dx: f64, dy: f64| {
                self.nudge_world([dx * key_target::KEY_STEP, dy * key_target::KEY_STEP])
            };
            match (event.key().as_str(), event.shift_key()) {
                ("n" | "N", _) => self.choose_key_target(),
                ("c" | "C", _) => self.choose_corner(),
                ("ArrowLeft", true) => step(-1.0, 0.0),
                ("ArrowRight", true) => step(1.0, 0.0),
                ("ArrowUp", true) => step(0.0, 1.0),
                ("ArrowDown", true) => step(0.0, -1.0),
                ("Delete", _) if self.selected.get().is_some() => self.delete_box(),
                _ => {
                    return self.on_stepper_key(event);
                }
            }
            return true;
        }
        self.on_stepper_key(event)
    }

    /// `n`: the next thing Shift + arrows move (the start, the goal, each box, round again).
    fn choose_key_target(&self) {
        let boxes = self.state.borrow().obstacles.len();
        let next = key_target::next_target(self.key_target.get(), boxes);
        self.key_target.set(Some(next));
        self.selected.set(match next {
            Grab::Box(i) => Some(i),
            _ => None,
        });
        self.hover.set(Some(next));
        self.update_marks();
    }

    /// `c`: a corner of the chosen box for Shift + arrows to resize it, or the whole box
    /// again ([`key_target::next_corner`]). Nothing without a box.
    fn choose_corner(&self) {
        let boxes = self.state.borrow().obstacles.len();
        let next = key_target::next_corner(self.key_target.get(), self.selected.get(), boxes);
        let Some(next @ (Grab::Box(i) | Grab::Corner(i, _))) = next else {
            return;
        };
        self.key_target.set(Some(next));
        self.selected.set(Some(i));
        self.hover.set(Some(next));
        self.update_marks();
    }

    /// Shift + an arrow: moves the chosen start, goal, box or corner (resizing its box) by
    /// `delta` (world units) as a drag would, refused with the same messages; the run starts
    /// again.
    fn nudge_world(&self, delta: [f64; 2]) {
        let Some(grab) = self.key_target.get() else {
            self.choose_key_target();
            return;
        };
        let before = self.state.borrow().clone();
        let from = key_target::start_point(&before, grab);
        self.command(Command::Pause);
        match drag(
            &before,
            grab,
            from,
            [from[0] + delta[0], from[1] + delta[1]],
        ) {
            Ok(next) => {
                self.show_refusal(None);
                if next != before {
                    self.set_state(next, true);
                    if let Some(url) = self.url.as_ref() {
                        url.schedule();
                    }
                }
            }
            Err(r) => self.show_refusal(Some(r)),
        }
    }

    fn on_stepper_key(&self, event: &KeyboardEvent) -> bool {
        if self.substep_mode.checked() && !keymap::has_command_modifier(event) {
            match event.key().as_str() {
                "ArrowRight" | "PageDown" => {
                    self.substep(true);
                    return true;
                }
                "ArrowLeft" | "PageUp" => {
                    self.substep(false);
                    return true;
                }
                _ => {}
            }
        }
        self.stepper
            .borrow()
            .as_ref()
            .is_some_and(|s| s.on_key(event))
    }

    /// One sub-step forward or back: within the iteration, else to the next iteration's first
    /// sub-step or the previous one's last.
    fn substep(&self, forward: bool) {
        let count = self
            .run
            .borrow()
            .shown()
            .last()
            .map_or(0, |r| phases(r).len());
        let last = count.saturating_sub(1);
        let at = self.phase.get().unwrap_or(last).min(last);
        self.substep_driving.set(true);
        if forward {
            if count > 0 && at < last {
                self.phase.set(Some(at + 1));
                self.update();
            } else {
                let before = self.run.borrow().shown().iterations();
                self.phase.set(Some(0));
                self.command(Command::Step);
                if self.run.borrow().shown().iterations() == before {
                    self.phase.set(Some(at));
                }
            }
        } else if count > 0 && at > 0 {
            self.phase.set(Some(at - 1));
            self.update();
        } else {
            self.phase.set(None);
            self.command(Command::Back);
        }
        self.substep_driving.set(false);
    }

    // ---------- The run to its end ----------

    /// One slice of the run to its end (a small run finishes in the first): the stepper's
    /// length grows with it, the URL's `it` is gone to once reached; the next slice is
    /// scheduled as another task until the end.
    fn finish_slice(&self) {
        self.finish_slice_for(FINISH_SLICE_MS);
    }

    /// [`Inner::finish_slice`] for about `budget_ms`.
    fn finish_slice_for(&self, budget_ms: f64) {
        let done = match self.run.try_borrow_mut() {
            Ok(mut run) => run.finish_for(budget_ms),
            Err(_) => false,
        };
        if let Some(s) = self.stepper.borrow().as_ref() {
            s.model_changed();
        }
        if let Some(it) = self.pending_it.get() {
            let reached = self.run.borrow().finished.iterations() as u64 >= it;
            if done || reached {
                self.pending_it.set(None);
                self.command(Command::Seek(it));
            }
        }
        self.show_finishing();
        if done {
            self.finisher.cancel();
        } else {
            self.finisher.schedule(0);
        }
    }

    /// One slice of a big `rrt_nodes.csv` being written (the file offered at its end).
    fn csv_slice(&self) {
        let more = match self.run.try_borrow() {
            Ok(run) => self.exports.write_slice(&run),
            Err(_) => true,
        };
        if more {
            self.csv_more.schedule(0);
        }
        self.show_finishing();
    }

    /// The progress of the run to its end, and the CSV downloads enabled once it is there.
    fn show_finishing(&self) {
        let Ok(run) = self.run.try_borrow() else {
            return;
        };
        let done = run.is_finished();
        let text = (!done).then(|| run.progress_text());
        self.finishing.set_text_content(text.as_deref());
        dom::show(&self.finishing, !done);
        let _ = self
            .finishing
            .set_attribute("data-state", if done { "done" } else { "running" });
        self.exports.enable_csv(done);
    }

    // ---------- Editing ----------

    /// A field changed: a valid set restarts the run, a refused one keeps the last run.
    fn edited(&self) {
        let current = self.state.borrow().clone();
        let checked = self.params.borrow_mut().check(&current);
        if let Some(next) = checked {
            if next.texts != current.texts {
                self.set_state(next, true);
            }
        }
    }

    /// A new state: the world redrawn, the run restarted at iteration 0 (now, or at the end
    /// of a drag when `restart` is false), the command lines and the URL.
    fn set_state(&self, next: PageState, restart: bool) {
        *self.state.borrow_mut() = next;
        self.redraw_world();
        if restart {
            self.restart();
        } else {
            self.update_marks();
        }
    }

    /// The run of the current state from iteration 0, paused, ready to step.
    fn restart(&self) {
        let state = self.state.borrow().clone();
        let setup = match state.setup() {
            Ok(s) => s,
            Err(e) => {
                web_sys::console::warn_1(&js_error(&e));
                return;
            }
        };
        let generation = self.run.borrow().generation + 1;
        match Run::new(&setup, generation) {
            Ok(run) => *self.run.borrow_mut() = run,
            Err(e) => {
                web_sys::console::warn_1(&js_error(&e));
                return;
            }
        }
        *self.run_state.borrow_mut() = state.clone();
        self.phase.set(None);
        self.pending_it.set(None);
        self.exports.cancel();
        self.csv_more.cancel();
        self.exports.update(&state);
        self.exports.commands.clear_status();
        // Reset: the stepper goes to 0 and reads the new run's length (then grows with it).
        self.command(Command::Reset);
        self.finish_slice();
        if let Some(url) = self.url.as_ref() {
            url.write_now();
        }
    }

    fn show_refusal(&self, refusal: Option<Refusal>) {
        self.refusal.set(refusal);
    }

    fn add_box(&self) {
        let current = self.state.borrow().clone();
        match add_box(&current) {
            Ok(next) => {
                self.selected.set(Some(next.obstacles.len() - 1));
                self.show_refusal(None);
                self.set_state(next, true);
            }
            Err(r) => self.show_refusal(Some(r)),
        }
    }

    fn delete_box(&self) {
        let current = self.state.borrow().clone();
        if current.obstacles.is_empty() {
            return;
        }
        let index = self.selected.get().unwrap_or(usize::MAX);
        self.selected.set(None);
        self.key_target.set(None);
        self.show_refusal(None);
        self.set_state(delete_box(&current, index), true);
    }

    fn recipe_world(&self) {
        let current = self.state.borrow().clone();
        let recipe = PageState::default();
        let next = PageState {
            obstacles: recipe.obstacles,
            start: recipe.start,
            goal: recipe.goal,
            ..current.clone()
        };
        self.selected.set(None);
        self.key_target.set(None);
        self.show_refusal(None);
        if next != current {
            self.set_state(next, true);
        }
    }

    /// A drag on the world view.
    fn on_drag(&self, ev: DragEvent<Grab>) {
        match ev {
            DragEvent::Start { handle, at, .. } => {
                self.command(Command::Pause);
                let from = self.world.borrow().frame.world(at);
                *self.dragging.borrow_mut() = Some((handle, from, self.state.borrow().clone()));
                self.selected.set(match handle {
                    Grab::Box(i) | Grab::Corner(i, _) => Some(i),
                    _ => self.selected.get(),
                });
                focus_without_scroll(&self.world.borrow().canvas.top().canvas);
                self.update_marks();
            }
            DragEvent::Move { at, .. } => {
                let Some((grab, from, before)) = self.dragging.borrow().clone() else {
                    return;
                };
                let to = self.world.borrow().frame.world(at);
                match drag(&before, grab, from, to) {
                    Ok(next) => {
                        self.show_refusal(None);
                        if next != *self.state.borrow() {
                            let live = next
                                .setup()
                                .is_ok_and(|s| s.params.max_iter <= LIVE_RESTART_MAX_ITER);
                            self.set_state(next, live);
                        }
                    }
                    Err(r) => self.show_refusal(Some(r)),
                }
            }
            DragEvent::End { .. } => {
                self.dragging.borrow_mut().take();
                let stale = {
                    let (s, r) = (self.state.borrow(), self.run_state.borrow());
                    (s.obstacles.clone(), s.start, s.goal) != (r.obstacles.clone(), r.start, r.goal)
                };
                if stale {
                    self.restart();
                }
                self.update_marks();
                if let Some(url) = self.url.as_ref() {
                    url.write_now();
                }
            }
            DragEvent::Tap { at } => {
                let frame = self.world.borrow().frame;
                let hit = hit_test(&frame, &self.state.borrow(), at, 22.0);
                if let Some(Grab::Box(i) | Grab::Corner(i, _)) = hit {
                    self.selected.set(Some(i));
                    self.update_marks();
                }
            }
            DragEvent::Hover(at) => {
                let frame = self.world.borrow().frame;
                let hit = hit_test(
                    &frame,
                    &self.state.borrow(),
                    at,
                    world::WorldView::hit_radius(false),
                );
                if hit != self.hover.get() {
                    self.hover.set(hit);
                    if let Some(d) = self.drag.borrow().as_ref() {
                        d.set_hover_cursor(match hit {
                            Some(Grab::Corner(_, 0 | 2)) => "nesw-resize",
                            Some(Grab::Corner(..)) => "nwse-resize",
                            Some(_) => "grab",
                            None => "",
                        });
                    }
                    self.update_marks();
                }
            }
            DragEvent::Leave => {
                if self.hover.replace(None).is_some() {
                    self.update_marks();
                }
            }
        }
    }

    // ---------- Drawing ----------

    /// Layer 0 and the touch handles.
    fn redraw_world(&self) {
        let state = self.state.borrow();
        let tol = state
            .setup()
            .map_or(crate::recipes::rrt_2d::GOAL_TOL, |s| s.world.goal_tol);
        let world = self.world.borrow();
        if !world.is_sized() {
            return;
        }
        world.draw_world(&state, tol, Ink::current());
        if let Some(d) = self.drag.borrow().as_ref() {
            d.set_handles(&world.handles(&state));
        }
    }

    /// Sizes changed: refit and redraw everything.
    fn relayout(&self) {
        self.world.borrow_mut().fit();
        if let Some(d) = self.drag.borrow().as_ref() {
            d.relayout();
        }
        self.redraw_world();
        self.update();
    }

    /// The sub-step shown in sub-step mode.
    fn shown_phase(&self) -> Option<Phase> {
        let run = self.run.borrow();
        let r = run.shown().last()?;
        let i = self.phase.get()?;
        phases(r).get(i).copied()
    }

    /// Layer 1 up to the node shown, a big tree over several tasks.
    fn draw_tree_now(&self) {
        let phase = if self.substep_mode.checked() {
            self.shown_phase()
        } else {
            None
        };
        let Ok(run) = self.run.try_borrow() else {
            return;
        };
        // Before its outcome (sub-step mode), the iteration's new nodes are not drawn yet.
        let mut upto = run.shown().nodes().len();
        if phase.is_some_and(|p| p != Phase::Outcome) {
            upto -= match run.shown().last().map(|r| r.outcome) {
                Some(RrtOutcome::Added { .. }) => 1,
                Some(RrtOutcome::GoalReached { .. }) => 2,
                _ => 0,
            };
        }
        let complete = self
            .world
            .borrow_mut()
            .draw_tree_for_a_task(&run, upto, Ink::current());
        if complete {
            self.tree_more.cancel();
        } else {
            self.tree_more.schedule(0);
        }
    }

    fn update_marks(&self) {
        let phase = if self.substep_mode.checked() {
            self.shown_phase()
        } else {
            None
        };
        self.draw_marks_with(phase);
    }

    fn draw_marks_with(&self, phase: Option<Phase>) {
        let Ok(run) = self.run.try_borrow() else {
            return;
        };
        let state = self.state.borrow();
        self.world.borrow().draw_marks(
            &run,
            phase,
            self.selected.get(),
            self.hover.get(),
            &state,
            Ink::current(),
        );
    }

    /// The run moved: tree, marks, sub-steps, counters, URL.
    fn update(&self) {
        if !self.substep_driving.get() {
            self.phase.set(None);
        }
        let started = now_ms();
        let phase = if self.substep_mode.checked() {
            self.shown_phase()
        } else {
            None
        };
        self.draw_tree_now();
        self.draw_marks_with(phase);
        let draw_ms = now_ms() - started;
        let Ok(run) = self.run.try_borrow() else {
            return;
        };
        self.substeps.show(run.shown().last(), phase);
        self.counters.show(&run, self.playing());
        let work = run.advance_ms + now_ms() - started;
        drop(run);
        bench_record(work, draw_ms);
        if let Some(url) = self.url.as_ref() {
            url.write_at_most_every(URL_EVERY_MS);
        }
    }

    /// The language changed.
    fn relocalize(&self) {
        let _ = dom::relocalize(&self.root);
        self.params.borrow().form.relocalize();
        self.url_notice.relocalize();
        self.key_target.relocalize();
        if let Some(s) = self.stepper.borrow().as_ref() {
            s.relocalize();
        }
        self.exports.relocalize();
        self.refusal.relocalize();
        self.show_finishing();
        self.redraw_world();
        self.update();
    }
}

/// Bench builds keep every frame's work in `window.__rrtFrameMs` (advance + draw, ms) and
/// `window.__rrtDrawMs` (the drawing alone).
fn bench_record(work_ms: f64, draw_ms: f64) {
    use crate::ui::kit::bench_log::{push_ms, KEEP_ALL};
    push_ms("__rrtFrameMs", work_ms, KEEP_ALL);
    push_ms("__rrtDrawMs", draw_ms, KEEP_ALL);
}

/// The page's model for its exercises (none while its state holds none).
fn lend_model(inner: &Inner, lend: &mut dyn FnMut(&PageModel)) {
    if let Ok(setup) = inner.state.borrow().setup() {
        lend(&PageModel::Rrt(&setup));
    }
}
