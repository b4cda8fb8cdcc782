//! The Planar 2R IK playground (`#/ik-2r`): drag the tip of a two-link arm and watch IK, the
//! Jacobian, manipulability, the joint-space heatmap and the jacobian-2r sweep follow; edit
//! the recipe parameters; download the ik-workspace, jacobian-2r and manip-grid CSVs.
//!
//! ```text
//! IK:  c2 = (x² + y² − L1² − L2²) / (2 L1 L2),  q2 = ±acos c2,
//!      q1 = atan2(y, x) − atan2(L2 sin q2, L1 + L2 cos q2)
//! J  = [ −L1 s1 − L2 s12   −L2 s12 ;  L1 c1 + L2 c12   L2 c12 ],   det J = L1 L2 sin q2
//! w  = sqrt(det(J Jᵀ)) = |det J|,   ellipse semi-axes σ_max ≥ σ_min (singular values of J)
//! ```
//!
//! Components, one file each (`arm`, `heat`, `sweep`, `params`, `readouts`, `exports`, `keys`,
//! `bench`), own their elements, drawing and `relocalize`, and report input to the page through
//! their host traits or callbacks; this file holds the state ([`State`]) and redraws what each
//! change made dirty, once per animation frame.
//!
//! The page comes in two stages. The first (the page's chunk) is what makes it live: the
//! markup, the arm view, the readouts, the keys, the state and its URL, the frame loop. The
//! second (`panels`, a chunk of its own fetched as soon as the first is mounted: the heatmap,
//! the sweep plot, the form, the downloads, the workspace grid's kernel) is reached only
//! through [`panels::Panels`]; until it is in, a line stands in for it (`panels_status`) and
//! everything else works without it. Once in, it draws from the state as it is then.

mod arm;
mod bench;
mod explain;
mod exports;
mod heat;
mod keys;
mod markup;
mod panels;
mod panels_status;
mod params;
mod readouts;
mod sweep;
mod workspace;

use std::cell::{Cell, RefCell};
use std::rc::{Rc, Weak};

use wasm_bindgen::prelude::*;
use web_sys::{Element, KeyboardEvent};

pub(crate) use self::arm::colour as arm_colour;
use self::arm::{ArmControl, ArmHost};
#[cfg(feature = "bench")]
use self::bench::BenchHost;
use self::keys::KeyAction;
use self::panels::{Panels, PanelsHost};
use crate::planar2r::{wrap_angle, Elbow, Kinematics};
use crate::ui::dom;
use crate::ui::kit::canvas::Ink;
use crate::ui::kit::drag::{DragEvent, PointerKind};
use crate::ui::kit::exercise_link::WithModel;
use crate::ui::kit::exercise_slot::ExerciseSlot;
use crate::ui::kit::scope::{FrameLoop, Scope};
use crate::ui::kit::url_state::{UrlNotice, UrlWriter};
use crate::ui::page::{self, MountCtx, Shortcut};
use crate::ui::page_frame;
use crate::ui::schedule::{now_ms, Timer};
use crate::view::exercises::PageModel;
use crate::view::ik2r::{elbow_of, Grab, Params, State, WsColor};
use crate::view::url::UrlState;

/// What needs redrawing on the next animation frame.
mod dirty {
    /// Canvas sizes and the view transforms.
    pub const LAYOUT: u32 = 1;
    pub const ARM_BG: u32 = 2;
    pub const HEAT_BG: u32 = 4;
    pub const PLOT_AXES: u32 = 8;
    /// Readouts, arm layer, heatmap marker (the drag frame).
    pub const FRAME: u32 = 16;
    pub const PLOT_DATA: u32 = 32;
    pub const ALL: u32 = 63;
}

/// The mounted page.
pub(crate) struct Page {
    me: Weak<Page>,
    root: Element,
    state: RefCell<State>,
    /// The pose of the heatmap cell under the pointer (a ghost arm in the arm view).
    ghost: RefCell<Option<(f64, f64)>>,
    /// Names the values of the opened link that were not valid.
    url_notice: UrlNotice,
    url: UrlWriter,
    arm: RefCell<arm::ArmView>,
    readouts: RefCell<readouts::Readouts>,
    /// The second stage (heatmap, sweep plot, form, downloads), once its chunk is in.
    panels: RefCell<Option<Rc<dyn Panels>>>,
    /// The exercises section, made with the second stage (their checks are the correctly
    /// rounded numbers it brings).
    exercises: RefCell<Option<ExerciseSlot>>,
    /// The tip target of the last IK, while the pose it gave came from the platform's
    /// functions (before the second stage brings the correctly rounded ones): the pose is
    /// solved again from it when they arrive.
    fast_tip: Cell<Option<(f64, f64)>>,
    /// The plot waits one frame (the frame after the second stage came draws the rest).
    plot_next_frame: Cell<bool>,
    /// The page's frame loop (its scope's).
    frames: FrameLoop,
    /// Listeners, timers, the frame loop and the resize observer; dropped on unmount.
    scope: RefCell<Scope>,
    heat_timer: Rc<Timer>,
    ws_timer: Rc<Timer>,
    /// Hides the out-of-reach note a key press showed.
    clamp_timer: Rc<Timer>,
    timings: bench::Timings,
}

fn mount(ctx: MountCtx) -> Result<Rc<Page>, JsValue> {
    let root = ctx.root.clone();
    page_frame::fill(
        &root,
        &markup::page(&readouts::markup(), &readouts::strip_markup()),
    )?;
    let (state, ignored) = State::read(&ctx.query);
    let url_notice = UrlNotice::new(markup::role(&root, "url-notice")?, ignored)?;
    let (arm, readouts) = (arm::ArmView::find(&root)?, readouts::Readouts::find(&root)?);
    let more: Element = markup::role(&root, "more")?;
    let page = Rc::new_cyclic(|weak: &Weak<Page>| {
        let mut scope = Scope::new();
        Page {
            me: weak.clone(),
            exercises: RefCell::new(None),
            frames: scope.dirty_frame_loop(weak, |p: &Page, bits, _| p.frame(bits)),
            heat_timer: scope.timer(weak, Page::recompute_heatmap),
            ws_timer: scope.timer(weak, Page::recompute_workspace),
            clamp_timer: scope.timer(weak, |p: &Page| p.arm.borrow_mut().set_clamp(false)),
            url: UrlWriter::new(&mut scope, weak, |p: &Page| p.state.borrow().write()),
            scope: RefCell::new(scope),
            url_notice,
            arm: RefCell::new(arm),
            readouts: RefCell::new(readouts),
            panels: RefCell::new(None),
            fast_tip: Cell::new(None),
            plot_next_frame: Cell::new(false),
            root,
            state: RefCell::new(state),
            ghost: RefCell::new(None),
            timings: bench::Timings::install(),
        }
    });
    dom::relocalize(&page.root)?;
    page.install(&Rc::downgrade(&page))?;
    page.arm.borrow().sync_controls(&state);
    page.relocalize_texts();
    page.invalidate(dirty::ALL);
    panels_status::show_loading(&more)?;
    // Fetched once the arm is painted, so that the first frame does not wait on its requests.
    let host: Rc<dyn PanelsHost> = page.clone();
    let host = Rc::downgrade(&host);
    crate::ui::schedule::after_paint(move || panels_status::load(host, more))?;
    Ok(page)
}

impl PanelsHost for Page {
    fn root(&self) -> Element {
        self.root.clone()
    }

    fn state(&self) -> State {
        *self.state.borrow()
    }

    fn scope(&self) -> std::cell::RefMut<'_, Scope> {
        self.scope.borrow_mut()
    }

    fn apply_params(&self, old: Params, next: Params) {
        Page::apply_params(self, old, next);
    }

    fn flatten_arm(&self) -> Result<web_sys::HtmlCanvasElement, JsValue> {
        self.arm.borrow().flatten()
    }

    fn end_heat_drag(&self) {
        Page::end_heat_drag(self);
    }

    fn set_pose(&self, q1: f64, q2: f64) {
        Page::set_pose(self, q1, q2);
    }

    fn write_url(&self) {
        Page::write_url(self);
    }

    fn ghost(&self) -> Option<(f64, f64)> {
        *self.ghost.borrow()
    }

    fn set_ghost(&self, ghost: Option<(f64, f64)>) {
        *self.ghost.borrow_mut() = ghost;
    }

    fn frame_changed(&self) {
        Page::frame_changed(self);
    }

    fn panels_arrived(&self, panels: Rc<dyn Panels>) {
        Page::panels_arrived(self, panels);
    }
}

impl Page {
    /// Wires the resize observer (the arm's stage and those the second stage fills), the
    /// arm's listeners and bench hooks.
    fn install(&self, weak: &Weak<Page>) -> Result<(), JsValue> {
        let stages: Vec<Element> = ["arm-stage", "heat-stage", "plot-stage"]
            .into_iter()
            .map(|name| markup::role(&self.root, name))
            .collect::<Result<_, _>>()?;
        let mut scope = self.scope.borrow_mut();
        scope.observe_resize(&stages.iter().collect::<Vec<_>>(), weak, |p: &Page| {
            p.invalidate(dirty::ALL)
        })?;
        let mut listeners = Vec::new();
        self.arm.borrow_mut().attach(weak, &mut listeners)?;
        for l in listeners {
            scope.keep(l);
        }
        bench::install_hooks(weak)?;
        Ok(())
    }

    fn unmount(&self) {
        drop(std::mem::take(&mut *self.scope.borrow_mut()));
        self.arm.borrow_mut().detach();
        if let Some(panels) = self.panels() {
            panels.detach();
        }
        bench::remove_hooks();
    }

    /// The second stage, if it is in.
    fn panels(&self) -> Option<Rc<dyn Panels>> {
        self.panels.borrow().clone()
    }

    /// The arm's numbers: the platform's functions until the second stage brings the
    /// correctly rounded ones (what the recipes and the exports compute).
    fn kin(&self) -> &'static dyn Kinematics {
        self.panels
            .borrow()
            .as_ref()
            .map_or(crate::planar2r::FAST, |p| p.kinematics())
    }

    /// The second stage is in (built into the page's markup): a pose the first stage solved
    /// is solved again with the correctly rounded functions, and it draws from the state now.
    fn panels_arrived(&self, panels: Rc<dyn Panels>) {
        *self.panels.borrow_mut() = Some(panels.clone());
        let me = self.me.clone();
        let model: WithModel = Box::new(move |use_model| {
            if let Some(page) = me.upgrade() {
                use_model(&PageModel::Ik2r(&page.state.borrow()));
            }
        });
        match ExerciseSlot::new(&self.root, panels.exercises(), model) {
            Ok(slot) => *self.exercises.borrow_mut() = Some(slot),
            Err(error) => web_sys::console::error_2(&"BSV Playground: exercises".into(), &error),
        }
        if let Some((x, y)) = self.fast_tip.take() {
            let solved = {
                let mut st = self.state.borrow_mut();
                let solved = self.kin().ik(&st.params.arm(), x, y, st.elbow);
                if let Some((q1, q2)) = solved {
                    st.q1 = q1;
                    st.q2 = q2;
                }
                solved.is_some()
            };
            if solved {
                self.schedule_url();
            }
        }
        let st = *self.state.borrow();
        panels.relocalize(&st, *self.ghost.borrow());
        panels.update_commands(&st);
        self.recompute_heatmap();
        if st.show_ws {
            self.recompute_workspace();
        }
        // The panels' markup is laid out in a task of its own, and their plot is drawn a
        // frame after the rest: three short tasks on a phone instead of one long one.
        self.plot_next_frame.set(true);
        self.frames.invalidate_after_layout(dirty::ALL);
    }

    /// Marks parts dirty for the next animation frame.
    fn invalidate(&self, bits: u32) {
        self.frames.invalidate(bits);
    }

    /// One animation frame: whatever is dirty, backgrounds first.
    fn frame(&self, bits: u32) {
        let st = *self.state.borrow();
        let ink = Ink::current();
        let panels = self.panels();
        if bits & dirty::LAYOUT != 0 {
            self.readouts.borrow_mut().layout();
            self.arm.borrow_mut().layout(&st);
            if let Some(panels) = &panels {
                panels.layout(ink);
            }
        }
        if bits & dirty::ARM_BG != 0 {
            self.arm.borrow().draw_background(&st, ink);
        }
        if let (true, Some(panels)) = (bits & dirty::HEAT_BG != 0, &panels) {
            panels.draw_heat_background(ink);
        }
        if let (true, Some(panels)) = (bits & dirty::PLOT_AXES != 0, &panels) {
            panels.set_plot_axes(&st.params);
        }
        if bits & dirty::FRAME != 0 {
            let t0 = now_ms();
            self.draw_frame();
            self.timings.push("frame", now_ms() - t0);
        }
        let plot = dirty::PLOT_DATA | dirty::PLOT_AXES | dirty::LAYOUT;
        if bits & plot != 0 && self.plot_next_frame.take() {
            self.invalidate(dirty::PLOT_DATA);
            return;
        }
        if let (true, Some(panels)) = (bits & plot != 0, &panels) {
            let t0 = now_ms();
            panels.draw_plot(&st, ink);
            self.timings.push("plot", now_ms() - t0);
        }
    }

    /// The drag frame: pose report, readouts, arm layer, heatmap marker; when no drag is on,
    /// also the touch handles and the command line that follows q2 (a drag's last frame
    /// brings them up to date).
    fn draw_frame(&self) {
        let st = *self.state.borrow();
        let ink = Ink::current();
        let report = self.kin().report(&st.params.arm(), st.q1, st.q2);
        let ghost = *self.ghost.borrow();
        let dragging = self.dragging();
        let pinned = {
            let arm = self.arm.borrow();
            arm.draw_frame(&st, &report, ghost, ink, !dragging);
            arm.clamp_shown()
        };
        self.readouts.borrow_mut().update(&report, pinned);
        if let Some(panels) = self.panels() {
            panels.draw_marker(&st, ghost, ink, !dragging);
            if !dragging {
                panels.update_commands(&st);
            }
        }
    }

    /// Whether a pointer drags the arm or the heatmap marker.
    fn dragging(&self) -> bool {
        self.arm.borrow().dragging() || self.panels().is_some_and(|p| p.dragging())
    }

    /// Texts the page formats itself, in the current language.
    fn relocalize_texts(&self) {
        self.url_notice.relocalize();
        let st = *self.state.borrow();
        self.arm.borrow().relocalize(&st);
        let report = self.kin().report(&st.params.arm(), st.q1, st.q2);
        let pinned = self.arm.borrow().clamp_shown();
        self.readouts.borrow().relocalize(&report, pinned);
        if let Some(panels) = self.panels() {
            panels.relocalize(&st, *self.ghost.borrow());
        }
    }

    fn relocalize(&self) {
        self.relocalize_texts();
        self.invalidate(dirty::ARM_BG | dirty::HEAT_BG | dirty::PLOT_AXES | dirty::FRAME);
    }

    // ---------- State changes ----------

    /// Writes the state into the URL now.
    fn write_url(&self) {
        self.url.write_now();
    }

    fn schedule_url(&self) {
        self.url.schedule();
    }

    /// The pose changed (drag, key, heatmap): redraw the frame layers.
    fn pose_changed(&self) {
        self.invalidate(dirty::FRAME | dirty::PLOT_DATA);
        if !self.dragging() {
            self.schedule_url();
        }
    }

    /// Sets the pose, keeping the elbow switch in step with q2's sign.
    fn set_pose(&self, q1: f64, q2: f64) {
        {
            let mut st = self.state.borrow_mut();
            st.q1 = q1;
            st.q2 = q2;
            st.elbow = elbow_of(q2);
        }
        self.fast_tip.set(None);
        self.arm.borrow().sync_controls(&self.state.borrow());
        self.pose_changed();
    }

    /// Moves the tip to `(x, y)` (m) by IK on the current branch; a point outside the reach
    /// is pinned to the nearest reachable one. Returns whether it was pinned.
    fn move_tip(&self, x: f64, y: f64) -> bool {
        let (arm, elbow) = {
            let st = self.state.borrow();
            (st.params.arm(), st.elbow)
        };
        let kin = self.kin();
        let (cx, cy, pinned) = kin.clamp_to_reach(&arm, x, y);
        if let Some((q1, q2)) = kin.ik(&arm, cx, cy, elbow) {
            let mut st = self.state.borrow_mut();
            st.q1 = q1;
            st.q2 = q2;
            self.fast_tip.set((!kin.exact()).then_some((cx, cy)));
        }
        self.pose_changed();
        pinned
    }

    /// A key move of the tip: like a drag, a target out of reach shows the note (for a
    /// moment, as there is no pointer to let go of).
    fn nudge_tip(&self, dx: f64, dy: f64) {
        let (x, y) = {
            let st = self.state.borrow();
            self.kin().fk(&st.params.arm(), st.q1, st.q2)
        };
        let pinned = self.move_tip(x + dx, y + dy);
        self.arm.borrow_mut().set_clamp(pinned);
        if pinned {
            self.clamp_timer.schedule(2500);
        }
    }

    /// Whether a key's `target` is the heatmap (its arrows turn the joints).
    fn is_heatmap(&self, target: Option<web_sys::EventTarget>) -> bool {
        self.panels().is_some_and(|p| p.is_heatmap(target))
    }

    /// One key; `true` when it was the page's.
    fn on_key(&self, event: &KeyboardEvent) -> bool {
        let Some(action) = keys::action(event, self.is_heatmap(event.target())) else {
            return false;
        };
        match action {
            KeyAction::Nudge(dx, dy) => self.nudge_tip(dx, dy),
            KeyAction::Turn(d1, d2) => self.turn(d1, d2),
            KeyAction::FlipElbow => {
                let elbow = self.state.borrow().elbow.flipped();
                self.set_elbow(elbow);
            }
            KeyAction::Reset => self.reset(),
            KeyAction::ToggleWorkspace => {
                let on = !self.state.borrow().show_ws;
                self.set_workspace_visible(on);
            }
        }
        true
    }

    /// Turns the joints by `(d1, d2)` rad.
    fn turn(&self, d1: f64, d2: f64) {
        let (q1, q2) = {
            let st = self.state.borrow();
            (st.q1, st.q2)
        };
        self.set_pose(wrap_angle(q1 + d1), wrap_angle(q2 + d2));
    }

    /// Flips to `elbow`, keeping the tip where it is.
    fn set_elbow(&self, elbow: Elbow) {
        {
            let mut st = self.state.borrow_mut();
            if elbow != st.elbow {
                let (arm, kin) = (st.params.arm(), self.kin());
                let (x, y) = kin.fk(&arm, st.q1, st.q2);
                let (cx, cy, _) = kin.clamp_to_reach(&arm, x, y);
                st.elbow = elbow;
                if let Some((n1, n2)) = kin.ik(&arm, cx, cy, elbow) {
                    st.q1 = n1;
                    st.q2 = n2;
                    self.fast_tip.set((!kin.exact()).then_some((cx, cy)));
                }
            }
        }
        self.arm.borrow().sync_controls(&self.state.borrow());
        self.pose_changed();
    }

    fn set_workspace_visible(&self, on: bool) {
        self.state.borrow_mut().show_ws = on;
        let st = *self.state.borrow();
        self.arm.borrow().sync_controls(&st);
        if on {
            self.recompute_workspace();
        }
        self.arm.borrow().relocalize(&st);
        self.invalidate(dirty::LAYOUT | dirty::ARM_BG | dirty::FRAME);
        self.schedule_url();
    }

    fn set_ws_colour(&self, colour: WsColor) {
        self.state.borrow_mut().ws_color = colour;
        let st = *self.state.borrow();
        if let Some(panels) = self.panels() {
            self.arm
                .borrow_mut()
                .refresh_workspace_image(&st, panels.as_ref());
        }
        self.invalidate(dirty::ARM_BG);
        self.schedule_url();
    }

    /// New (valid) parameters from the form: what depends on which value is redrawn or
    /// recomputed.
    fn apply_params(&self, old: Params, next: Params) {
        if old == next {
            return;
        }
        self.state.borrow_mut().params = next;
        let show_ws = self.state.borrow().show_ws;
        let arm_changed = old.l1 != next.l1 || old.l2 != next.l2;
        let mut bits = dirty::FRAME | dirty::PLOT_DATA;
        if arm_changed {
            bits |= dirty::LAYOUT | dirty::ARM_BG | dirty::PLOT_AXES;
        }
        if arm_changed || old.heatmap_n != next.heatmap_n {
            self.heat_timer.schedule(120);
        }
        if arm_changed || old.half_mm != next.half_mm || old.step_mm != next.step_mm {
            if show_ws {
                self.ws_timer.schedule(200);
                bits |= dirty::LAYOUT | dirty::ARM_BG;
            } else {
                self.arm.borrow_mut().forget_workspace();
            }
        }
        if (old.q1_start, old.q1_stop, old.q1_step) != (next.q1_start, next.q1_stop, next.q1_step) {
            bits |= dirty::PLOT_AXES;
        }
        let st = *self.state.borrow();
        self.arm.borrow().relocalize(&st);
        if let Some(panels) = self.panels() {
            panels.update_commands(&st);
        }
        self.invalidate(bits);
        self.schedule_url();
    }

    /// Back to the defaults (key `r`, Reset button).
    fn reset(&self) {
        let old = self.state.borrow().params;
        *self.state.borrow_mut() = State::default();
        self.fast_tip.set(None);
        self.url_notice.set(Vec::new());
        *self.ghost.borrow_mut() = None;
        let st = *self.state.borrow();
        {
            let mut arm = self.arm.borrow_mut();
            arm.set_clamp(false);
            arm.forget_workspace();
            arm.sync_controls(&st);
        }
        if let Some(panels) = self.panels() {
            panels.fill_params(&st.params);
            panels.update_commands(&st);
        }
        if old != st.params {
            self.heat_timer.schedule(0);
        }
        self.relocalize_texts();
        self.invalidate(dirty::ALL);
        self.write_url();
    }

    /// Recomputes and paints the heatmap for the current L1, L2 and resolution.
    fn recompute_heatmap(&self) {
        let Some(panels) = self.panels() else {
            return;
        };
        let p = self.state.borrow().params;
        let t0 = now_ms();
        if panels.recompute_heatmap(&p.arm(), p.heatmap_n) {
            self.timings.push("heatmap", now_ms() - t0);
        }
        self.invalidate(dirty::HEAT_BG | dirty::FRAME);
    }

    /// Recomputes the workspace grid when its parameters changed, then its overlay (its
    /// kernel is the second stage's: without it the grid waits).
    fn recompute_workspace(&self) {
        let Some(panels) = self.panels() else {
            return;
        };
        let st = *self.state.borrow();
        let computed = self
            .arm
            .borrow_mut()
            .recompute_workspace(&st, panels.as_ref());
        if let Some(ms) = computed {
            self.timings.push("workspace", ms);
        }
        self.arm.borrow().relocalize(&st);
        self.invalidate(dirty::ARM_BG);
    }

    // ---------- Pointer input ----------

    /// A drag on the arm view.
    fn on_arm(&self, ev: DragEvent<Grab>) {
        match ev {
            DragEvent::Start { handle, at, .. } | DragEvent::Move { handle, at } => {
                self.drag_arm(handle, at);
            }
            DragEvent::Tap { at } => {
                self.drag_arm(Grab::Tip, at);
                self.arm.borrow_mut().end_drag();
                self.write_url();
            }
            DragEvent::End { .. } => {
                self.arm.borrow_mut().end_drag();
                self.invalidate(dirty::FRAME);
                self.write_url();
            }
            DragEvent::Hover(at) => {
                let st = *self.state.borrow();
                if self.arm.borrow_mut().hover(&st, Some(at)) {
                    self.invalidate(dirty::FRAME);
                }
            }
            DragEvent::Leave => {
                let st = *self.state.borrow();
                if self.arm.borrow_mut().hover(&st, None) {
                    self.invalidate(dirty::FRAME);
                }
            }
        }
    }

    /// Applies a drag of `grab` to canvas point `at`.
    fn drag_arm(&self, grab: Grab, at: glam::DVec2) {
        let world = self.arm.borrow().xf.world(at);
        let st = *self.state.borrow();
        let arm = st.params.arm();
        match grab {
            Grab::Tip => {
                let pinned = self.move_tip(world.x, world.y);
                self.clamp_timer.cancel();
                self.arm.borrow_mut().set_pinned(pinned.then_some(world));
            }
            Grab::Q1 => self.set_pose(world.y.atan2(world.x), st.q2),
            Grab::Q2 => {
                let (ex, ey) = self.kin().elbow(&arm, st.q1);
                let q2 = wrap_angle((world.y - ey).atan2(world.x - ex) - st.q1);
                self.set_pose(st.q1, q2);
            }
        }
    }

    /// A drag on the heatmap ended.
    fn end_heat_drag(&self) {
        self.invalidate(dirty::FRAME);
        self.write_url();
    }

    /// Something the drag frame shows changed (the heatmap's ghost pose).
    fn frame_changed(&self) {
        self.invalidate(dirty::FRAME);
    }
}

/// The IK playground.
pub struct Ik2rPage(Rc<Page>);

impl page::Page for Ik2rPage {
    fn mount(ctx: MountCtx) -> Result<Ik2rPage, JsValue> {
        mount(ctx).map(Ik2rPage)
    }

    fn relocalize(&self) {
        self.0.relocalize();
    }

    fn set_projector(&self, _on: bool) {
        self.0.invalidate(dirty::ALL);
    }

    fn shortcuts(&self) -> Vec<Shortcut> {
        keys::shortcuts()
    }

    fn on_key(&self, event: &KeyboardEvent) -> bool {
        self.0.on_key(event)
    }
}

impl ArmHost for Page {
    fn grab_at(&self, at: glam::DVec2, kind: PointerKind) -> Option<Grab> {
        let st = *self.state.borrow();
        let xf = self.arm.borrow().xf;
        arm::grab_at(&xf, &st, at, kind)
    }

    fn on_arm(&self, ev: DragEvent<Grab>) {
        Page::on_arm(self, ev);
    }

    fn on_control(&self, control: ArmControl) {
        match control {
            ArmControl::Elbow(elbow) => self.set_elbow(elbow),
            ArmControl::Workspace(on) => self.set_workspace_visible(on),
            ArmControl::Colour(colour) => self.set_ws_colour(colour),
            ArmControl::Reset => self.reset(),
        }
    }
}

#[cfg(feature = "bench")]
impl BenchHost for Page {
    fn bench_frame(&self, x: f64, y: f64) {
        self.move_tip(x, y);
        self.draw_frame();
    }

    fn bench_plot(&self) {
        let st = *self.state.borrow();
        if let Some(panels) = self.panels() {
            panels.draw_plot(&st, Ink::current());
        }
    }

    fn bench_heatmap(&self, n: usize) -> bool {
        let arm = self.state.borrow().params.arm();
        let Some(panels) = self.panels() else {
            return false;
        };
        if !panels.recompute_heatmap(&arm, n) {
            return false;
        }
        panels.draw_heat_background(Ink::current());
        // Back to the page's own resolution afterwards.
        self.heat_timer.schedule(50);
        self.invalidate(dirty::FRAME);
        true
    }
}

impl Drop for Ik2rPage {
    fn drop(&mut self) {
        self.0.unmount();
    }
}
