//! The page's second stage, a wasm chunk of its own (`ik2r_more`, loaded by `panels_status`)
//! that arrives after the arm is live: the joint-space heatmap, the sweep plot, the parameters
//! form, the downloads and the workspace grid's kernel. The page reaches them only through
//! [`Panels`] (a trait object made here), so none of their code is in the first stage; they
//! report input to the page by calling it.

use std::cell::RefCell;
use std::rc::{Rc, Weak};

use glam::DVec2;
use wasm_bindgen::prelude::*;
use web_sys::{Element, EventTarget, HtmlCanvasElement};

use super::exports::{self, Exports};
use super::heat::{HeatHost, HeatPanel};
use super::markup::{role, LATER_SELECTOR};
use super::params::ParamsForm;
use super::sweep::SweepPlot;
use super::workspace::{self, WorkspaceImage};
use crate::planar2r::{Arm, Kinematics};
use crate::recipes::ik_workspace::{Workspace, WorkspaceParams};
use crate::ui::dom;
use crate::ui::kit::canvas::Ink;
use crate::ui::kit::drag::{DragEvent, PointerKind};
use crate::ui::kit::scope::Scope;
use crate::view::exercises::Exercise;
use crate::view::heatmap::Rgb;
use crate::view::ik2r::{Params, State, WsColor};

/// What the page asks of its second stage.
pub(super) trait Panels {
    /// The correctly rounded numbers of the arm (the first stage has the platform's).
    fn kinematics(&self) -> &'static dyn Kinematics;
    /// The page's exercises: their checks use the correctly rounded numbers.
    fn exercises(&self) -> &'static [Exercise];
    /// The canvases changed size.
    fn layout(&self, ink: Ink);
    /// The heatmap's painted grid, axes and legend.
    fn draw_heat_background(&self, ink: Ink);
    /// The sweep plot's axes for `p` in the current language.
    fn set_plot_axes(&self, p: &Params);
    /// The heatmap marker and hovered cell, with the marker's touch handle when `handle`.
    fn draw_marker(&self, st: &State, ghost: Option<(f64, f64)>, ink: Ink, handle: bool);
    /// The sweep plot's series and cursor.
    fn draw_plot(&self, st: &State, ink: Ink);
    /// The download panel's command lines for `st`.
    fn update_commands(&self, st: &State);
    /// Whether a pointer drags the heatmap marker.
    fn dragging(&self) -> bool;
    /// Whether `target` (a key's) is the heatmap.
    fn is_heatmap(&self, target: Option<EventTarget>) -> bool;
    /// The texts the panels format themselves, in the current language.
    fn relocalize(&self, st: &State, ghost: Option<(f64, f64)>);
    /// Recomputes and paints the heatmap for `arm` on an `n × n` grid; whether it worked.
    fn recompute_heatmap(&self, arm: &Arm, n: usize) -> bool;
    /// Writes every field of the form from `p` (Reset).
    fn fill_params(&self, p: &Params);
    /// The ik-workspace recipe's grid for `wp`.
    fn workspace_grid(&self, wp: &WorkspaceParams) -> Result<Workspace, String>;
    /// The workspace grid's overlay image.
    fn workspace_image(
        &self,
        ws: &Workspace,
        colour: WsColor,
        l1: f64,
        l2: f64,
        lut: &[Rgb],
        previous: Option<WorkspaceImage>,
    ) -> Result<WorkspaceImage, JsValue>;
    /// The page unmounts: the drags let go of their listeners.
    fn detach(&self);
}

/// What the second stage asks of the page (the page implements it).
pub(super) trait PanelsHost {
    /// The page's root element.
    fn root(&self) -> Element;
    /// The page's state.
    fn state(&self) -> State;
    /// The page's scope (the panels' listeners go there).
    fn scope(&self) -> std::cell::RefMut<'_, Scope>;
    /// The form's parameters changed from `old` to `next`.
    fn apply_params(&self, old: Params, next: Params);
    /// The arm view as one canvas (its PNG).
    fn flatten_arm(&self) -> Result<HtmlCanvasElement, JsValue>;
    /// A drag of the heatmap marker ended.
    fn end_heat_drag(&self);
    /// The arm to the joint angles `q1`, `q2`.
    fn set_pose(&self, q1: f64, q2: f64);
    /// The state into the URL.
    fn write_url(&self);
    /// The pose of the heatmap cell under the pointer (a ghost arm in the arm view).
    fn ghost(&self) -> Option<(f64, f64)>;
    fn set_ghost(&self, ghost: Option<(f64, f64)>);
    /// The drag frame needs drawing.
    fn frame_changed(&self);
    /// The second stage is built: the page draws it from now on.
    fn panels_arrived(&self, panels: Rc<dyn Panels>);
}

/// Builds the second stage into the page's markup (what the `ik2r_more` chunk hands the page).
pub(super) type BuildFn = fn(&Rc<dyn PanelsHost>) -> Result<Rc<dyn Panels>, JsValue>;

/// The panels of the second stage.
struct LoadedPanels {
    page: Weak<dyn PanelsHost>,
    heat: RefCell<HeatPanel>,
    sweep: RefCell<SweepPlot>,
    params: RefCell<ParamsForm>,
    exports: RefCell<Exports>,
}

/// Puts the downloads panel in its place, finds and fills the panels under the page's root,
/// wires their listeners into the page's scope and shows them.
pub(super) fn build(page: &Rc<dyn PanelsHost>) -> Result<Rc<dyn Panels>, JsValue> {
    let root = page.root();
    let slot: Element = role(&root, "downloads")?;
    slot.set_outer_html(&exports::markup());
    let params = page.state().params;
    let (heat, sweep) = (HeatPanel::find(&root)?, SweepPlot::find(&root)?);
    let (form, exports) = (ParamsForm::build(&root, &params)?, Exports::find(&root)?);
    let panels = Rc::new(LoadedPanels {
        page: Rc::downgrade(page),
        heat: RefCell::new(heat),
        sweep: RefCell::new(sweep),
        params: RefCell::new(form),
        exports: RefCell::new(exports),
    });
    let weak = Rc::downgrade(&panels);
    panels.heat.borrow_mut().attach(&weak)?;
    {
        let mut scope = page.scope();
        panels
            .params
            .borrow()
            .attach(&weak, &mut scope, |p: &LoadedPanels, target| {
                let Some(page) = p.page.upgrade() else {
                    return;
                };
                let old = page.state().params;
                let next = p.params.borrow_mut().on_input(target, old);
                page.apply_params(old, next);
            })?;
        panels.exports.borrow().attach(
            &weak,
            &mut scope,
            |p: &LoadedPanels, file| {
                let Some(page) = p.page.upgrade() else {
                    return;
                };
                let st = page.state();
                p.exports
                    .borrow()
                    .download(file, &st, || page.flatten_arm());
            },
            |p: &LoadedPanels, key| p.exports.borrow().copy(key),
        )?;
    }
    dom::relocalize(&root)?;
    for element in dom::matching(&root, LATER_SELECTOR)? {
        dom::show(&element, true);
    }
    Ok(panels)
}

impl LoadedPanels {
    /// A drag, tap or hover on the heatmap.
    fn on_heat(&self, page: &dyn PanelsHost, ev: DragEvent<()>) {
        let at = match ev {
            DragEvent::Start { at, .. } | DragEvent::Move { at, .. } | DragEvent::Tap { at } => at,
            DragEvent::End { .. } => {
                page.end_heat_drag();
                return;
            }
            DragEvent::Hover(at) => {
                let ghost = self.heat.borrow().pose_at(at);
                self.set_ghost(page, ghost);
                return;
            }
            DragEvent::Leave => {
                self.set_ghost(page, None);
                return;
            }
        };
        self.set_ghost(page, None);
        let cell = self.heat.borrow().pose_at(at);
        if let Some((q1, q2)) = cell {
            page.set_pose(q1, q2);
        }
        if matches!(ev, DragEvent::Tap { .. }) {
            page.write_url();
        }
    }

    /// The pose of the heatmap cell under the pointer (a ghost arm in the arm view).
    fn set_ghost(&self, page: &dyn PanelsHost, ghost: Option<(f64, f64)>) {
        if page.ghost() == ghost {
            return;
        }
        page.set_ghost(ghost);
        let p = page.state().params;
        self.heat.borrow().relocalize(&p, ghost);
        page.frame_changed();
    }
}

impl HeatHost for LoadedPanels {
    fn heat_grab(&self, at: DVec2, kind: PointerKind) -> Option<()> {
        let page = self.page.upgrade()?;
        let st = page.state();
        self.heat.borrow().grabs(&st, at, kind)
    }

    fn on_heat(&self, ev: DragEvent<()>) {
        if let Some(page) = self.page.upgrade() {
            LoadedPanels::on_heat(self, &*page, ev);
        }
    }
}

impl Panels for LoadedPanels {
    fn kinematics(&self) -> &'static dyn Kinematics {
        crate::planar2r::EXACT
    }

    fn exercises(&self) -> &'static [Exercise] {
        &crate::view::exercises::ik2r::EXERCISES
    }

    fn layout(&self, ink: Ink) {
        self.heat.borrow_mut().layout(ink);
        self.sweep.borrow_mut().resized();
    }

    fn draw_heat_background(&self, ink: Ink) {
        self.heat.borrow().draw_background(ink);
    }

    fn set_plot_axes(&self, p: &Params) {
        self.sweep.borrow_mut().set_axes(p);
    }

    fn draw_marker(&self, st: &State, ghost: Option<(f64, f64)>, ink: Ink, handle: bool) {
        self.heat.borrow().draw_marker(st, ghost, ink, handle);
    }

    fn draw_plot(&self, st: &State, ink: Ink) {
        self.sweep.borrow_mut().draw(st, ink);
    }

    fn update_commands(&self, st: &State) {
        self.exports.borrow().update_commands(st);
    }

    fn dragging(&self) -> bool {
        self.heat.try_borrow().is_ok_and(|h| h.dragging())
    }

    fn is_heatmap(&self, target: Option<EventTarget>) -> bool {
        self.heat.try_borrow().is_ok_and(|h| h.is_canvas(target))
    }

    fn relocalize(&self, st: &State, ghost: Option<(f64, f64)>) {
        self.heat.borrow().relocalize(&st.params, ghost);
        self.params.borrow().relocalize();
        self.exports.borrow().relocalize();
        self.sweep.borrow_mut().relocalize(&st.params);
    }

    fn recompute_heatmap(&self, arm: &Arm, n: usize) -> bool {
        self.heat.borrow_mut().recompute(arm, n)
    }

    fn fill_params(&self, p: &Params) {
        self.params.borrow_mut().fill(p);
    }

    fn workspace_grid(&self, wp: &WorkspaceParams) -> Result<Workspace, String> {
        crate::recipes::ik_workspace::compute(wp).map_err(|e| e.to_string())
    }

    fn workspace_image(
        &self,
        ws: &Workspace,
        colour: WsColor,
        l1: f64,
        l2: f64,
        lut: &[Rgb],
        previous: Option<WorkspaceImage>,
    ) -> Result<WorkspaceImage, JsValue> {
        workspace::render(ws, colour, l1, l2, lut, previous)
    }

    fn detach(&self) {
        self.heat.borrow_mut().detach();
    }
}
