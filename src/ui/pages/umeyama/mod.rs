//! Umeyama alignment (`#/umeyama-2d`): the source points X (drag them; click or tap empty
//! space to add one; remove the selected one with the button or Delete), the true similarity
//! (fields, sliders, and two handles in the view: the translation and the rotation/scale), the
//! noise σ, the seed and n; the noisy targets Y, the aligned points `s R X + t` with their
//! residuals, and the estimate against the truth. The stepper walks the fit, centroids to
//! rmse, each step with its matrices (`crate::view::umeyama_2d`).
//!
//! Components, one file each: `view` (the canvas), `steps` (the stepper's model and the step
//! panel), `selection` (the status line), `markup`; the kit's [`RecipeControls`] is the form
//! (the recipe's arguments and `--scale --angle --tx --ty --mirror --x`), the URL (keys = the
//! CLI's argument names) and the exports. Every edit goes through the form's texts, so the
//! downloads and the command line are `bsv umeyama-2d` with the same words. A drag's or
//! slider's frame (budget 4 ms) checks only the fields it changed and writes only what changed.
//!
//! The page comes in two stages. The first (the page's chunk) is what makes it live: the
//! markup, the view with its drags and keys, the form and the URL, the readouts, the stepper
//! and its step panel. The second (`more`, a chunk of its own fetched as soon as the first is
//! mounted: the exports' command lines, downloads and copies, the PNG) is reached only through
//! [`more::More`]; until it is in, a line stands in for the exports (`more_status`) and
//! everything else works without it. Once in, it shows the run as it is then.

mod markup;
mod more;
mod more_status;
mod selection;
mod steps;
mod view;

use std::cell::{Cell, RefCell};
use std::rc::{Rc, Weak};

use glam::DVec2;
use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::{Element, KeyboardEvent, MouseEvent};

use crate::i18n::FluentArg;
use crate::pyfmt::py_float;
use crate::recipes::umeyama_2d::{setup_from_args, UmeyamaSetup, INFO, POINTS_CSV};
use crate::ui::kit::canvas::{focus_without_scroll, Ink};
use crate::ui::kit::drag::{Drag, DragEvent, PointerKind};
use crate::ui::kit::exercise_slot::ExerciseSlot;
use crate::ui::kit::keymap;
use crate::ui::kit::message_line::MessageLine;
use crate::ui::kit::page_root::PageRoot;
use crate::ui::kit::readouts::Readouts;
use crate::ui::kit::recipe_controls::RecipeControls;
use crate::ui::kit::scope::Scope;
use crate::ui::kit::stepper::{Command, StepperWidget};
use crate::ui::kit::url_state::UrlWriter;
use crate::ui::page::{MountCtx, Page, Shortcut};
use crate::ui::schedule::{now_ms, Timer};
use crate::ui::{ctx, dom};
use crate::view::drag::HandleShape;
use crate::view::exercises::umeyama_2d::EXERCISES;
use crate::view::exercises::PageModel;
use crate::view::signal::{sig, Slider};
use crate::view::umeyama_2d::{
    add_point, editable, hit_test, key_step_target, move_point, new_point_spot, next_selection,
    points_text, remove_point, rotation_key_target, rotation_texts, selected_point,
    translation_texts, Grab, Refusal, Scene, Step, STEPS,
};
use markup::P;

/// A click this soon after a drag ended is the drag's own (ms).
const CLICK_AFTER_DRAG_MS: f64 = 400.0;
/// How long the selection's status line waits after the last change of the points (a key
/// held down, a typed `x`) before it says where the selected point is, ms: a screen reader
/// hears where it stopped, not every step.
const SELECTION_SETTLE_MS: i32 = 400;
/// The page's keys besides the stepper's (on the focused view or the page, never in a
/// field): `n` / Shift + `n` select the next / previous point, then the translation handle,
/// then the rotation handle; Shift + arrows move a point or the translation by the drag grid,
/// and turn (← →, by the angle grid) or scale (↑ ↓) the rotation handle, through the very
/// path a pointer drag takes; `a` adds a point, Delete removes the selected one.
const KEYS: [Shortcut; 4] = [
    keymap::key("n  Shift + n", "umeyama-key-select"),
    keymap::key("Shift + ← ↑ → ↓", "umeyama-key-move"),
    keymap::key("Delete  Backspace", "umeyama-key-delete"),
    keymap::key("a", "umeyama-key-add"),
];
/// The URL key of the step shown (the rest are the CLI's argument names).
const STEP_KEY: &str = "step";
const SLIDERS: [Slider; 6] = [
    Slider {
        name: "sigma",
        min: 0.0,
        max: 0.5,
        step: 0.005,
    },
    Slider {
        name: "n",
        min: 2.0,
        max: 40.0,
        step: 1.0,
    },
    Slider {
        name: "scale",
        min: 0.1,
        max: 3.0,
        step: 0.01,
    },
    Slider {
        name: "angle",
        min: -180.0,
        max: 180.0,
        step: 0.5,
    },
    Slider {
        name: "tx",
        min: -3.0,
        max: 3.0,
        step: 0.01,
    },
    Slider {
        name: "ty",
        min: -3.0,
        max: 3.0,
        step: 0.01,
    },
];

/// The mounted page.
pub struct UmeyamaPage {
    inner: Rc<Inner>,
    _exercises: ExerciseSlot,
}

struct Inner {
    me: Weak<Inner>,
    root: PageRoot,
    controls: RecipeControls<UmeyamaSetup>,
    scene: RefCell<Scene>,
    view: RefCell<view::SceneView>,
    panel: steps::StepPanel,
    model: Rc<RefCell<steps::StepIndex>>,
    stepper: RefCell<Option<StepperWidget<steps::StepIndex>>>,
    drag: RefCell<Option<Drag<Grab>>>,
    dragging: Cell<Option<Grab>>,
    /// A point or one of the truth's handles (`n` and Shift + `n` go round them).
    selected: Cell<Option<Grab>>,
    hover: Cell<Option<Grab>>,
    /// Why the last edit of the points was refused.
    refusal: MessageLine<Refusal>,
    /// When the input being handled arrived (a drag move, a slider), ms: its frame's work
    /// counts from there (the form's check included).
    work_started: Cell<Option<f64>>,
    /// When the last drag ended, ms: the click the browser sends after it is not an add.
    drag_ended: Cell<f64>,
    /// The status line: which point is selected and where (or that none is).
    selection: selection::SelectionLine,
    /// Says the selection once the points stop changing.
    selection_timer: Rc<Timer>,
    edited: Element,
    points_button: Option<Element>,
    readouts: Readouts,
    /// The touch handles placed last (`None`: place them at the next redraw).
    handles_placed: RefCell<Option<Vec<HandleShape>>>,
    /// Shift + arrows are moving a point: the touch handles wait until the status line
    /// settles ([`Inner::show_selection`]).
    key_moving: Cell<bool>,
    /// Whether the edited notice shows now (`None`: not set yet).
    edited_shown: Cell<Option<bool>>,
    url: RefCell<Option<UrlWriter>>,
    /// The second stage (exports, PNG), once its chunk is in.
    more: RefCell<Option<Rc<dyn more::More>>>,
    scope: RefCell<Scope>,
}

/// Why an edit of the points was refused, in the current language.
fn refusal_text(r: Refusal) -> String {
    ctx::t_args(
        r.message_id(),
        &[("count", FluentArg::Number(r.count() as f64))],
    )
}

impl Page for UmeyamaPage {
    fn mount(ctx: MountCtx) -> Result<UmeyamaPage, JsValue> {
        let exercises_root = ctx.root.clone();
        let root = PageRoot::fill(&ctx.root, &markup::page(), P, P)?;
        let controls = RecipeControls::mount_later(
            &root,
            P,
            &INFO,
            &SLIDERS,
            &ctx.query,
            &[STEP_KEY],
            setup_from_args,
        )?;
        controls.check_only_edits();
        let scene = Scene::new(&controls.value())
            .ok_or_else(|| JsValue::from_str("umeyama: a run without points"))?;
        let start_step = ctx
            .get(STEP_KEY)
            .and_then(|s| s.trim().parse::<u64>().ok())
            .map_or(0, |s| s.min(STEPS.len() as u64 - 1));
        let stage: Element = root.role("stage")?;
        let view = view::SceneView::find(&stage)?;
        let panel = steps::StepPanel::find(&root)?;
        let readouts = Readouts::find(&root)?;
        let refusal = MessageLine::new(root.role("message")?, refusal_text);
        let selection = selection::SelectionLine::new(root.role("selection")?);
        let edited = root.role("edited")?;
        let points_button = root
            .query_selector(&format!("[data-download=\"{POINTS_CSV}\"]"))
            .ok()
            .flatten();
        let inner = Rc::new_cyclic(|me: &Weak<Inner>| {
            let mut scope = Scope::new();
            let url = UrlWriter::new(&mut scope, me, Inner::query);
            let selection_timer = scope.timer(me, Inner::show_selection);
            Inner {
                me: me.clone(),
                root,
                controls,
                scene: RefCell::new(scene),
                view: RefCell::new(view),
                panel,
                model: Rc::new(RefCell::new(steps::StepIndex { index: start_step })),
                stepper: RefCell::new(None),
                drag: RefCell::new(None),
                dragging: Cell::new(None),
                selected: Cell::new(None),
                hover: Cell::new(None),
                refusal,
                work_started: Cell::new(None),
                drag_ended: Cell::new(f64::NEG_INFINITY),
                selection,
                selection_timer,
                edited,
                points_button,
                readouts,
                handles_placed: RefCell::new(None),
                key_moving: Cell::new(false),
                edited_shown: Cell::new(None),
                url: RefCell::new(Some(url)),
                more: RefCell::new(None),
                scope: RefCell::new(scope),
            }
        });
        inner.install(&stage)?;
        inner.build_stepper()?;
        {
            let scene = inner.scene.borrow();
            inner.view.borrow_mut().fit(&scene);
        }
        inner.command(Command::Seek(start_step));
        inner.show_run();
        inner.redraw();
        inner.show_selection();
        let more: Element = inner.root.role("more")?;
        more_status::show_loading(&more)?;
        let me = Rc::downgrade(&inner);
        let root = (*inner.root).clone();
        // Fetched once the page is painted, so that the first frame does not wait on its
        // requests.
        crate::ui::schedule::after_paint(move || {
            more_status::load(
                root,
                more,
                Rc::new(move |built| {
                    if let Some(page) = me.upgrade() {
                        page.more_arrived(built);
                    }
                }),
            )
        })?;
        let exercises = ExerciseSlot::lending(&exercises_root, &EXERCISES, &inner, lend_model)?;
        Ok(UmeyamaPage {
            inner,
            _exercises: exercises,
        })
    }

    fn relocalize(&self) {
        self.inner.controls.relocalize();
        if let Some(s) = self.inner.stepper.borrow().as_ref() {
            s.relocalize();
        }
        self.inner.refusal.relocalize();
        self.inner.selection.forget();
        self.inner.show_selection();
        self.inner.redraw();
    }

    fn set_projector(&self, _on: bool) {
        self.inner.relayout();
    }

    fn shortcuts(&self) -> Vec<Shortcut> {
        keymap::with_stepper(&KEYS)
    }

    fn on_key(&self, event: &KeyboardEvent) -> bool {
        let p = &self.inner;
        if !keymap::has_command_modifier(event) {
            match (event.key().as_str(), event.shift_key()) {
                ("Delete" | "Backspace", _) => p.remove_point(),
                ("a" | "A", _) => p.add_point_button(),
                ("n" | "N", back) => p.select_next(!back),
                ("ArrowLeft", true) => p.nudge_point((-1.0, 0.0)),
                ("ArrowRight", true) => p.nudge_point((1.0, 0.0)),
                ("ArrowUp", true) => p.nudge_point((0.0, 1.0)),
                ("ArrowDown", true) => p.nudge_point((0.0, -1.0)),
                _ => return p.stepper_key(event),
            }
            return true;
        }
        p.stepper_key(event)
    }
}

impl Inner {
    /// The URL: the arguments as the command line has them, and the step shown.
    fn query(&self) -> Vec<(String, String)> {
        let mut pairs = self.controls.url_pairs();
        let index = self.model.try_borrow().map_or(0, |m| m.index);
        if index > 0 {
            pairs.push((STEP_KEY.to_string(), index.to_string()));
        }
        pairs
    }

    fn step(&self) -> Step {
        Step::at(self.model.try_borrow().map_or(0, |m| m.index))
    }

    /// Listeners: the form (through the kit), n typed over edited points, the tools, the
    /// view's drags and clicks, resizes.
    fn install(&self, stage: &Element) -> Result<(), JsValue> {
        let me = &self.me;
        let mut scope = self.scope.borrow_mut();
        self.controls.attach(
            &mut scope,
            me,
            |p| &p.controls,
            Inner::changed,
            |p| p.download_png(),
        )?;
        // A new n draws the recipe's random points again: edited points are dropped first.
        for selector in ["[data-field=\"n\"]", "[data-slider=\"n\"]"] {
            if let Ok(Some(el)) = self.root.query_selector(selector) {
                scope.listen_for(&el, "input", me, |p, _| {
                    if p.controls.value().points.is_some() {
                        if let Some(setup) = p.controls.set_texts(&[("x", "")], None) {
                            p.changed(setup);
                        }
                    }
                })?;
            }
        }
        // A slider's input reaches it before the form's listener: the frame's work starts here.
        for slider in dom::matching(&self.root, "[data-slider]")? {
            scope.listen_for(&slider, "input", me, |p, _| {
                p.work_started.set(Some(now_ms()));
            })?;
        }
        let form: Element = self.root.role("form")?;
        scope.listen_for(&form, "change", me, |p, _| p.write_url_now())?;
        for (action, f) in [
            ("add", Inner::add_point_button as fn(&Inner)),
            ("remove", Inner::remove_point),
            ("mirror", Inner::mirror_preset),
            ("recipe", Inner::recipe_run),
        ] {
            let button: Element = self.root.find(&format!("[data-action=\"{action}\"]"))?;
            scope.listen_for(&button, "click", me, move |p, _| f(p))?;
        }
        let top = self.view.borrow().canvas.top().canvas.clone();
        scope.listen_for(stage, "click", me, |p, e| {
            if let Some(m) = e.dyn_ref::<MouseEvent>() {
                p.clicked(m);
            }
        })?;
        scope.observe_resize(&[stage], me, |p| p.relayout())?;
        drop(scope);
        let (w_hit, w_on) = (self.me.clone(), self.me.clone());
        *self.drag.borrow_mut() = Some(Drag::attach(
            stage,
            &top,
            move |at, kind| {
                let p = w_hit.upgrade()?;
                let view = p.view.borrow();
                let radius = view::SceneView::hit_radius(kind.is_coarse());
                let hit = hit_test(&view.frame, &p.scene.borrow(), at, radius);
                // A finger grabs only a handle; anywhere else it scrolls the page.
                if kind == PointerKind::Touch && hit.is_none() {
                    return None;
                }
                hit
            },
            move |ev| {
                if let Some(p) = w_on.upgrade() {
                    p.on_drag(ev);
                }
            },
        )?);
        Ok(())
    }

    fn build_stepper(&self) -> Result<(), JsValue> {
        let slot: Element = self.root.role("stepper")?;
        let me = self.me.clone();
        let widget = StepperWidget::new(
            &slot,
            self.model.clone(),
            steps::stepper_options(),
            move |_| {
                if let Some(p) = me.upgrade() {
                    p.redraw();
                    if let Some(url) = p.url.borrow().as_ref() {
                        url.schedule();
                    }
                }
            },
        )?;
        *self.stepper.borrow_mut() = Some(widget);
        Ok(())
    }

    fn stepper_key(&self, event: &KeyboardEvent) -> bool {
        self.stepper
            .borrow()
            .as_ref()
            .is_some_and(|s| s.on_key(event))
    }

    fn command(&self, command: Command) {
        if let Some(s) = self.stepper.borrow().as_ref() {
            s.apply(command);
        }
    }

    fn write_url_now(&self) {
        if let Some(url) = self.url.borrow().as_ref() {
            url.write_now();
        }
    }

    // ---------- Runs ----------

    /// New valid arguments: the new run, shown now.
    fn changed(&self, setup: UmeyamaSetup) {
        let started = self.work_started.take().unwrap_or_else(now_ms);
        bench::record_to("__umeyamaFormMs", now_ms() - started);
        let Some(scene) = Scene::new(&setup) else {
            return;
        };
        let count = scene.x.len();
        *self.scene.borrow_mut() = scene;
        if matches!(self.selected.get(), Some(Grab::Point(i)) if i >= count) {
            self.selected.set(None);
        }
        // During a drag of the view the status line waits for its end.
        if self.dragging.get().is_none() {
            let scene = self.scene.borrow();
            self.view.borrow_mut().refit_if_needed(&scene);
            if !self.selection.says(&scene, self.selected.get()) {
                self.selection_timer.schedule(SELECTION_SETTLE_MS);
            }
        }
        self.show_run();
        self.redraw_from(started);
        let fit = self.scene.borrow().fit();
        self.readouts.announce(&ctx::t_strings(
            "umeyama-live",
            &[
                ("scale", sig(fit.scale, 4)),
                ("angle", sig(fit.rotation_deg, 4)),
                ("rmse", sig(fit.rmse, 3)),
            ],
        ));
        if let Some(url) = self.url.borrow().as_ref() {
            url.schedule();
        }
    }

    /// What depends on the run alone: the edited notice and the points download.
    fn show_run(&self) {
        let recipe = self.scene.borrow().setup.is_recipe();
        if self.edited_shown.replace(Some(!recipe)) == Some(!recipe) {
            return;
        }
        dom::show(&self.edited, !recipe);
        if let Some(b) = &self.points_button {
            dom::show(b, !recipe);
        }
    }

    fn download_png(&self) {
        if let Some(more) = self.more.borrow().as_ref() {
            more.save_png(&self.view.borrow().canvas);
        }
    }

    /// The second stage is in: the exports show the run as it is now.
    fn more_arrived(&self, more: Rc<dyn more::More>) {
        self.controls.set_exports(more.exports());
        *self.more.borrow_mut() = Some(more);
        if let Ok(later) = self.root.role::<Element>("later") {
            dom::show(&later, true);
        }
    }

    // ---------- Editing ----------

    /// The points now (the recipe's, on the editor's grid, until edited).
    fn points(&self) -> Vec<[f64; 2]> {
        let scene = self.scene.borrow();
        match &scene.setup.points {
            Some(p) => p.clone(),
            None => editable(&scene.x),
        }
    }

    /// New points: through the form's `x` and `n`.
    fn set_points(&self, points: &[[f64; 2]]) {
        let text = points_text(points);
        let n = points.len().to_string();
        if let Some(setup) = self.controls.set_texts(&[("x", &text), ("n", &n)], None) {
            self.changed(setup);
        }
    }

    fn show_refusal(&self, refusal: Option<Refusal>) {
        self.refusal.set(refusal);
    }

    fn add_point_at(&self, at: [f64; 2]) {
        let points = self.points();
        match add_point(&points, at) {
            Ok(next) => {
                self.show_refusal(None);
                self.selected.set(Some(Grab::Point(next.len() - 1)));
                self.set_points(&next);
                self.show_selection_now();
                self.write_url_now();
            }
            Err(r) => self.show_refusal(Some(r)),
        }
    }

    fn add_point_button(&self) {
        let points = self.points();
        self.add_point_at(new_point_spot(&points));
    }

    fn remove_point(&self) {
        let points = self.points();
        // None selected, or a handle: the last point goes (the button's "remove").
        let index = match self.selected.get() {
            Some(Grab::Point(i)) => i,
            _ => usize::MAX,
        };
        match remove_point(&points, index) {
            Ok(next) => {
                self.show_refusal(None);
                self.selected.set(None);
                self.set_points(&next);
                self.show_selection_now();
                self.write_url_now();
            }
            Err(r) => self.show_refusal(Some(r)),
        }
    }

    /// The mirror preset: Y mirrors X, and the stepper at the reflection fix.
    fn mirror_preset(&self) {
        if let Some(setup) = self.controls.set_texts(&[("mirror", "yes")], None) {
            self.changed(setup);
        }
        let index = STEPS
            .iter()
            .position(|s| *s == Step::Reflection)
            .unwrap_or(0);
        self.command(Command::Seek(index as u64));
        self.write_url_now();
    }

    /// Back to the recipe's points and truth (σ, seed and n kept).
    fn recipe_run(&self) {
        let defaults: Vec<(&str, &str)> = INFO.flags.iter().map(|f| (f.name, f.default)).collect();
        self.selected.set(None);
        self.show_refusal(None);
        if let Some(setup) = self.controls.set_texts(&defaults, None) {
            self.changed(setup);
        }
        self.show_selection_now();
        self.write_url_now();
    }

    /// `n` (`forward`) or Shift + `n`: selects the next or previous point or handle, and says
    /// so.
    fn select_next(&self, forward: bool) {
        let count = self.scene.borrow().x.len();
        self.selected
            .set(next_selection(self.selected.get(), count, forward));
        self.show_refusal(None);
        self.show_selection_now();
        self.redraw();
    }

    /// Shift + an arrow: moves what is selected one step along `direction` as a pointer drag
    /// to there would (the same [`Inner::drag_to`]: the form, the URL, the readouts and the
    /// exports follow): a point or the translation by [`DRAG_GRID`], the rotation handle
    /// turned by ← → and scaled by ↑ ↓ ([`rotation_key_target`]); with none selected,
    /// selects the first point.
    fn nudge_point(&self, direction: (f64, f64)) {
        let Some(grab) = self.selected.get() else {
            self.select_next(true);
            return;
        };
        let to = {
            let scene = self.scene.borrow();
            match grab {
                // Where the editor holds it (`self.points()[i]`, without copying them all).
                Grab::Point(i) => selected_point(&scene, Some(i))
                    .map(|(_, from)| key_step_target(from, direction)),
                Grab::Translation => Some(key_step_target(scene.truth().t, direction)),
                Grab::Rotation => Some(rotation_key_target(&scene.truth(), direction)),
            }
        };
        let Some(to) = to else {
            return;
        };
        self.show_refusal(None);
        self.work_started.set(Some(now_ms()));
        self.key_moving.set(true);
        self.drag_to(grab, to);
        // Also when nothing moved: the settle places the handles and ends the run.
        self.selection_timer.schedule(SELECTION_SETTLE_MS);
    }

    // ---------- The selection's status line ----------

    /// Says the selection now (a pending settled update is dropped).
    fn show_selection_now(&self) {
        self.selection_timer.cancel();
        self.show_selection();
    }

    /// The status line ([`selection::SelectionLine`]) and the view's `data-selected`, when
    /// what they say changed; a settled run of Shift + arrows also places the touch handles.
    fn show_selection(&self) {
        let Ok(scene) = self.scene.try_borrow() else {
            return;
        };
        // A run of Shift + arrows has settled (or the selection changed): the touch handles
        // go where the points are now.
        if self.key_moving.replace(false) {
            if let Ok(view) = self.view.try_borrow() {
                self.place_handles(&view, &scene);
            }
        }
        let selected = self.selected.get();
        if !self.selection.show(&scene, selected) {
            return;
        }
        drop(scene);
        if let Ok(view) = self.view.try_borrow() {
            let _ = view
                .canvas
                .top()
                .canvas
                .set_attribute("data-selected", &selection::selected_attr(selected));
        }
    }

    /// A click (or tap) on the view: select the point under it, or add one on empty space.
    fn clicked(&self, e: &MouseEvent) {
        if now_ms() - self.drag_ended.get() < CLICK_AFTER_DRAG_MS {
            return;
        }
        let at = {
            let view = self.view.borrow();
            let r = view.canvas.top().canvas.get_bounding_client_rect();
            DVec2::new(
                f64::from(e.client_x()) - r.left(),
                f64::from(e.client_y()) - r.top(),
            )
        };
        let (hit, world) = {
            let view = self.view.borrow();
            let hit = hit_test(
                &view.frame,
                &self.scene.borrow(),
                at,
                view::SceneView::hit_radius(true),
            );
            (hit, view.frame.world(at))
        };
        focus_without_scroll(&self.view.borrow().canvas.top().canvas);
        match hit {
            Some(grab) => {
                self.selected.set(Some(grab));
                self.show_selection_now();
                self.redraw();
            }
            None => self.add_point_at(world),
        }
    }

    fn on_drag(&self, ev: DragEvent<Grab>) {
        match ev {
            DragEvent::Start { handle, .. } => {
                self.dragging.set(Some(handle));
                self.selected.set(Some(handle));
                self.show_selection_now();
                self.show_refusal(None);
                focus_without_scroll(&self.view.borrow().canvas.top().canvas);
                self.redraw();
            }
            DragEvent::Move { handle, at } => {
                self.work_started.set(Some(now_ms()));
                let to = self.view.borrow().frame.world(at);
                self.drag_to(handle, to);
            }
            DragEvent::End { .. } => {
                self.dragging.set(None);
                self.drag_ended.set(now_ms());
                let shows = {
                    let scene = self.scene.borrow();
                    self.view.borrow().shows(&scene)
                };
                if !shows {
                    let scene = self.scene.borrow();
                    self.view.borrow_mut().refit(&scene);
                }
                self.redraw();
                self.show_selection_now();
                self.write_url_now();
            }
            DragEvent::Hover(at) => {
                let hit = {
                    let view = self.view.borrow();
                    hit_test(
                        &view.frame,
                        &self.scene.borrow(),
                        at,
                        view::SceneView::hit_radius(false),
                    )
                };
                if hit != self.hover.get() {
                    self.hover.set(hit);
                    if let Some(d) = self.drag.borrow().as_ref() {
                        d.set_hover_cursor(if hit.is_some() { "grab" } else { "crosshair" });
                    }
                    self.redraw();
                }
            }
            DragEvent::Leave => {
                if self.hover.replace(None).is_some() {
                    self.redraw();
                }
            }
            DragEvent::Tap { .. } => {}
        }
    }

    /// `handle` dragged to world point `to` (a pointer drag's move, or Shift + an arrow):
    /// through the form's texts, as the command line has them.
    fn drag_to(&self, handle: Grab, to: [f64; 2]) {
        match handle {
            Grab::Point(i) => {
                let next = move_point(&self.points(), i, to);
                self.set_points(&next);
            }
            Grab::Translation => {
                let [a, b] = translation_texts(to);
                if let Some(setup) = self.controls.set_texts(&[(a.0, &a.1), (b.0, &b.1)], None) {
                    self.changed(setup);
                }
            }
            Grab::Rotation => {
                let t = self.scene.borrow().truth().t;
                let [a, b] = rotation_texts(t, to);
                if let Some(setup) = self.controls.set_texts(&[(a.0, &a.1), (b.0, &b.1)], None) {
                    self.changed(setup);
                }
            }
        }
    }

    // ---------- Drawing ----------

    fn relayout(&self) {
        {
            let scene = self.scene.borrow();
            self.view.borrow_mut().fit(&scene);
        }
        if let Some(d) = self.drag.borrow().as_ref() {
            d.relayout();
        }
        *self.handles_placed.borrow_mut() = None;
        self.redraw();
    }

    fn redraw(&self) {
        self.redraw_from(now_ms());
    }

    /// The view, the step panel and the readouts; the frame's work since `started` is
    /// recorded (bench builds).
    fn redraw_from(&self, started: f64) {
        let Ok(scene) = self.scene.try_borrow() else {
            return;
        };
        let step = self.step();
        let view = self.view.borrow();
        let draw_started = now_ms();
        view.draw(
            &scene,
            step,
            view::Marks {
                selected: self.selected.get(),
                hover: self.hover.get(),
            },
            Ink::current(),
        );
        bench::record_to("__umeyamaDrawMs", now_ms() - draw_started);
        // The touch handles matter when a touch starts: not during a drag (the pointer is
        // captured) or a run of Shift + arrows; they are placed when it ends.
        if self.dragging.get().is_none() && !self.key_moving.get() {
            self.place_handles(&view, &scene);
        }
        view.write_px(&scene);
        drop(view);
        self.panel.show(&scene, step);
        self.show_readouts(&scene);
        bench::record_to("__umeyamaFrameMs", now_ms() - started);
    }

    /// The touch overlay over the view's handles, where they are now (written only when
    /// they moved).
    fn place_handles(&self, view: &view::SceneView, scene: &Scene) {
        let shapes = view.handles(scene);
        let mut placed = self.handles_placed.borrow_mut();
        if placed.as_ref() != Some(&shapes) {
            if let Some(d) = self.drag.borrow().as_ref() {
                d.set_handles(&shapes);
            }
            *placed = Some(shapes);
        }
    }

    fn show_readouts(&self, scene: &Scene) {
        let fit = scene.fit();
        let truth = scene.truth();
        let ro = &self.readouts;
        let show = |key: &str, x: f64| ro.set_with_value(key, &sig(x, 6), &py_float(x));
        show("scale", fit.scale);
        show("angle", fit.rotation_deg);
        show("tx", fit.tx);
        show("ty", fit.ty);
        show("rmse", fit.rmse);
        show("scale-true", truth.scale);
        show("angle-true", truth.angle_deg);
        show("tx-true", truth.t[0]);
        show("ty-true", truth.t[1]);
        // The noise's own rms per point is σ √2 (two coordinates).
        show(
            "rmse-noise",
            scene.setup.params.sigma * std::f64::consts::SQRT_2,
        );
    }
}

/// Bench builds: every frame's work (drag or slider input to drawn), ms, in
/// `window.__umeyamaFrameMs`; of it, the form's check (input to valid arguments) in
/// `__umeyamaFormMs` and the canvas drawing in `__umeyamaDrawMs`.
mod bench {
    pub fn record_to(name: &str, ms: f64) {
        crate::ui::kit::bench_log::push_ms(name, ms, crate::ui::kit::bench_log::KEEP_ALL);
    }
}

/// The page's model for its exercises.
fn lend_model(inner: &Inner, lend: &mut dyn FnMut(&PageModel)) {
    lend(&PageModel::Umeyama(&inner.scene.borrow().setup))
}
