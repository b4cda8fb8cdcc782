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
//! How the work is split so that a drag frame stays cheap: every canvas is two stacked layers;
//! backgrounds (grid, annulus, workspace overlay, painted heatmap, plot axes) are redrawn only
//! when parameters, size, language or projector mode change; a drag frame computes one pose
//! report, writes the readouts and redraws the arm layer, the heatmap marker and the sweep
//! series, once per animation frame. Heatmap and workspace recomputes are debounced and run
//! only on parameter changes. The URL is rewritten on drag end and (debounced) on edits.
//!
//! Files: [`state`] (state and URL), [`view`] (arm view drawing), [`pointer`] (pointer and
//! drag), [`heatmap`], [`workspace`] (overlay), [`plots`], [`readouts`], [`form`]
//! (parameters), [`controls`] (toolbar, form, download and copy handlers), [`texts`] (text the
//! page formats itself), [`downloads`], [`explain`] (explanation panel), [`keys`], [`markup`],
//! [`canvas`] (HiDPI layers), [`bench`] (timing hooks).

mod bench;
mod canvas;
mod controls;
mod downloads;
mod explain;
mod form;
mod heatmap;
mod keys;
mod markup;
mod plots;
mod pointer;
mod readouts;
mod state;
mod texts;
mod view;
mod workspace;

use std::cell::{Cell, RefCell};
use std::rc::{Rc, Weak};

use glam::DVec2;
use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::{
    Element, Event, HtmlCanvasElement, HtmlInputElement, HtmlSelectElement, KeyboardEvent,
    ResizeObserver,
};

use self::canvas::{projector_scale, Layer};
use self::heatmap::{HeatGrid, HeatLayout};
use self::plots::{PlotSpec, SweepPoint};
use self::state::{elbow_of, Params, State, WsColor};
use self::view::{Grab, ViewXf, WorkspaceImage};
use crate::planar2r::{wrap_angle, Elbow};
use crate::recipes::ik_workspace::{Workspace, WorkspaceParams};
use crate::ui::ctx;
use crate::ui::dom::{self, Listener};
use crate::ui::page::{MountCtx, PageDef, PageHandle, Shortcut};

/// The page, as the shell's page table lists it.
pub const PAGE: PageDef = PageDef {
    id: "ik-2r",
    title_id: "ik2r-title",
    blurb_id: "ik2r-blurb",
    mount,
};

fn mount(ctx: MountCtx) -> Result<Box<dyn PageHandle>, JsValue> {
    let page = Page::build(ctx)?;
    Ok(Box::new(Handle(page)))
}

/// What needs redrawing on the next animation frame.
mod dirty {
    /// Canvas sizes or the view transform.
    pub const LAYOUT: u32 = 1;
    pub const ARM_BG: u32 = 2;
    pub const HEAT_BG: u32 = 4;
    pub const PLOT_BG: u32 = 8;
    /// Readouts, arm layer, heatmap marker (the drag frame).
    pub const FRAME: u32 = 16;
    pub const PLOT_FG: u32 = 32;
    pub const ALL: u32 = 63;
}

/// The elements the page drives.
struct Els {
    arm_stage: Element,
    heat_stage: Element,
    plot_stage: Element,
    arm_canvas: HtmlCanvasElement,
    heat_canvas: HtmlCanvasElement,
    clamp_note: Element,
    url_notice: Element,
    view_notes: Element,
    ws_summary: Element,
    heat_hover: Element,
    copy_status: Element,
    elbow_down: HtmlInputElement,
    elbow_up: HtmlInputElement,
    ws_toggle: HtmlInputElement,
    ws_color: HtmlSelectElement,
}

/// Canvases, caches and layouts.
struct Gfx {
    arm_bg: Layer,
    arm_fg: Layer,
    heat_bg: Layer,
    heat_fg: Layer,
    plot_bg: Layer,
    plot_fg: Layer,
    /// The painted heatmap (n × n pixels) and the grid it was painted from.
    heat_img: Layer,
    heat_grid: HeatGrid,
    heat_painted: bool,
    /// The workspace grid and its overlay image, with the parameters they were made for.
    ws_data: Option<(WorkspaceParams, Workspace)>,
    ws_img: Option<WorkspaceImage>,
    ws_img_colour: Option<WsColor>,
    xf: ViewXf,
    heat_layout: HeatLayout,
    plot_spec: PlotSpec,
    /// The plotted sweep and the (params, q2) it was computed for.
    sweep: Vec<SweepPoint>,
    sweep_key: Option<(Params, f64)>,
    /// Command lines as shown, to skip unchanged writes.
    commands_shown: Vec<String>,
}

/// What a pointer is doing.
#[derive(Debug, Clone, Copy, PartialEq)]
enum DragTarget {
    Arm(Grab),
    Heatmap,
}

#[derive(Debug, Clone, Copy, PartialEq)]
struct Drag {
    pointer_id: i32,
    target: DragTarget,
}

/// Transient interaction state.
#[derive(Default)]
struct Ui {
    drag: Option<Drag>,
    /// The pointer (world, m) while it is outside the reach and the tip is pinned.
    pinned_pointer: Option<DVec2>,
    clamp_shown: bool,
    hover_grab: Option<Grab>,
    /// The pose of the heatmap cell under the pointer (drawn as a ghost arm).
    ghost: Option<(f64, f64)>,
    ignored_url_keys: Vec<String>,
}

/// A debounced `setTimeout`.
struct Timer {
    id: Cell<Option<i32>>,
    callback: RefCell<Option<Closure<dyn FnMut()>>>,
}

impl Timer {
    fn new() -> Timer {
        Timer {
            id: Cell::new(None),
            callback: RefCell::new(None),
        }
    }

    fn set_callback(&self, f: impl FnMut() + 'static) {
        *self.callback.borrow_mut() = Some(Closure::new(f));
    }

    /// (Re)starts the timer: the callback runs `ms` after the last call.
    fn schedule(&self, ms: i32) {
        let Some(window) = web_sys::window() else {
            return;
        };
        self.cancel();
        if let Some(cb) = self.callback.borrow().as_ref() {
            if let Ok(id) = window.set_timeout_with_callback_and_timeout_and_arguments_0(
                cb.as_ref().unchecked_ref(),
                ms,
            ) {
                self.id.set(Some(id));
            }
        }
    }

    fn cancel(&self) {
        if let (Some(id), Some(window)) = (self.id.take(), web_sys::window()) {
            window.clear_timeout_with_handle(id);
        }
    }

    fn fired(&self) {
        self.id.set(None);
    }
}

/// The `requestAnimationFrame` callback.
type FrameCallback = Closure<dyn FnMut(f64)>;
/// The resize observer and its callback.
type Resize = (ResizeObserver, Closure<dyn FnMut(JsValue)>);
/// A control's event handler.
type Handler = Box<dyn Fn(&Page, &Event)>;

/// The mounted page.
pub(crate) struct Page {
    root: Element,
    els: Els,
    state: RefCell<State>,
    ui: RefCell<Ui>,
    gfx: RefCell<Gfx>,
    form: RefCell<form::Form>,
    readouts: RefCell<readouts::Readouts>,
    listeners: RefCell<Vec<Listener>>,
    lut: Vec<[u8; 3]>,
    dirty: Cell<u32>,
    raf_id: Cell<Option<i32>>,
    raf_callback: RefCell<Option<FrameCallback>>,
    resize: RefCell<Option<Resize>>,
    heat_timer: Timer,
    ws_timer: Timer,
    url_timer: Timer,
    timings: bench::Timings,
    /// The last copy result's message id (shown in the downloads panel).
    copy_status: Rc<Cell<Option<&'static str>>>,
}

fn find<T: JsCast>(root: &Element, selector: &str) -> Result<T, JsValue> {
    root.query_selector(selector)?
        .ok_or_else(|| JsValue::from_str(&format!("ik-2r: missing {selector}")))?
        .dyn_into::<T>()
        .map_err(|_| JsValue::from_str(&format!("ik-2r: wrong element type for {selector}")))
}

fn role<T: JsCast>(root: &Element, name: &str) -> Result<T, JsValue> {
    find(root, &format!("[data-ik2r=\"{name}\"]"))
}

/// `performance.now()` in milliseconds.
fn now_ms() -> f64 {
    web_sys::window()
        .and_then(|w| w.performance())
        .map_or(0.0, |p| p.now())
}

fn show(element: &Element, visible: bool) {
    if visible {
        let _ = element.remove_attribute("hidden");
    } else {
        let _ = element.set_attribute("hidden", "");
    }
}

/// Text for Fluent arguments: `("name", value)`.
fn t_args(id: &str, args: &[(&str, String)]) -> String {
    let args: Vec<(&str, crate::i18n::FluentArg)> =
        args.iter().map(|(k, v)| (*k, v.clone().into())).collect();
    ctx::t_args(id, &args)
}

impl Page {
    fn build(mount: MountCtx) -> Result<Rc<Page>, JsValue> {
        let root = mount.root.clone();
        root.set_inner_html(&markup::page());
        let doc = dom::document()?;
        let els = Els {
            arm_stage: role(&root, "arm-stage")?,
            heat_stage: role(&root, "heat-stage")?,
            plot_stage: role(&root, "plot-stage")?,
            arm_canvas: role(&root, "arm-fg")?,
            heat_canvas: role(&root, "heat-fg")?,
            clamp_note: role(&root, "clamp-note")?,
            url_notice: role(&root, "url-notice")?,
            view_notes: role(&root, "view-notes")?,
            ws_summary: role(&root, "ws-summary")?,
            heat_hover: role(&root, "heat-hover")?,
            copy_status: role(&root, "copy-status")?,
            elbow_down: role(&root, "elbow-down")?,
            elbow_up: role(&root, "elbow-up")?,
            ws_toggle: role(&root, "ws-toggle")?,
            ws_color: role(&root, "ws-color")?,
        };
        let gfx = Gfx {
            arm_bg: Layer::new(role(&root, "arm-bg")?)?,
            arm_fg: Layer::new(els.arm_canvas.clone())?,
            heat_bg: Layer::new(role(&root, "heat-bg")?)?,
            heat_fg: Layer::new(els.heat_canvas.clone())?,
            plot_bg: Layer::new(role(&root, "plot-bg")?)?,
            plot_fg: Layer::new(role(&root, "plot-fg")?)?,
            heat_img: Layer::offscreen(&doc)?,
            heat_grid: HeatGrid {
                n: 0,
                values: Vec::new(),
                scale_max: 1.0,
            },
            heat_painted: false,
            ws_data: None,
            ws_img: None,
            ws_img_colour: None,
            xf: ViewXf::fit(100.0, 100.0, 1.0),
            heat_layout: HeatLayout::new(100.0, 100.0, 1.0),
            plot_spec: PlotSpec::new(0.0, 1.0, 0.1, 0.1),
            sweep: Vec::new(),
            sweep_key: None,
            commands_shown: Vec::new(),
        };
        let (state, ignored) = State::from_query(&mount.query);
        let form = form::Form::find(&root)?;
        let readouts = readouts::Readouts::find(&root)?;
        let page = Rc::new(Page {
            root: root.clone(),
            els,
            state: RefCell::new(state),
            ui: RefCell::new(Ui {
                ignored_url_keys: ignored,
                ..Ui::default()
            }),
            gfx: RefCell::new(gfx),
            form: RefCell::new(form),
            readouts: RefCell::new(readouts),
            listeners: RefCell::new(Vec::new()),
            lut: heatmap::colour_lut(),
            dirty: Cell::new(0),
            raf_id: Cell::new(None),
            raf_callback: RefCell::new(None),
            resize: RefCell::new(None),
            heat_timer: Timer::new(),
            ws_timer: Timer::new(),
            url_timer: Timer::new(),
            timings: bench::Timings::install(),
            copy_status: Rc::new(Cell::new(None)),
        });
        dom::relocalize(&root)?;
        page.install(&page)?;
        page.sync_controls();
        page.form.borrow_mut().fill(&state.params);
        page.update_texts();
        page.recompute_heatmap();
        if state.show_ws {
            page.recompute_workspace();
        }
        page.update_commands();
        page.invalidate(dirty::ALL);
        Ok(page)
    }

    /// Wires listeners, timers, the animation-frame callback and the resize observer.
    fn install(&self, rc: &Rc<Page>) -> Result<(), JsValue> {
        let weak = Rc::downgrade(rc);
        {
            let w = weak.clone();
            *self.raf_callback.borrow_mut() = Some(Closure::new(move |_t: f64| {
                if let Some(page) = w.upgrade() {
                    page.raf_id.set(None);
                    page.frame();
                }
            }));
        }
        let on = |w: &Weak<Page>, f: fn(&Page)| {
            let w = w.clone();
            move || {
                if let Some(page) = w.upgrade() {
                    f(&page);
                }
            }
        };
        self.heat_timer.set_callback(on(&weak, |p| {
            p.heat_timer.fired();
            p.recompute_heatmap();
        }));
        self.ws_timer.set_callback(on(&weak, |p| {
            p.ws_timer.fired();
            p.recompute_workspace();
        }));
        self.url_timer.set_callback(on(&weak, |p| {
            p.url_timer.fired();
            p.write_url();
        }));

        // Resize: every stage.
        let w = weak.clone();
        let resize_cb = Closure::<dyn FnMut(JsValue)>::new(move |_entries: JsValue| {
            if let Some(page) = w.upgrade() {
                page.invalidate(dirty::ALL);
            }
        });
        let observer = ResizeObserver::new(resize_cb.as_ref().unchecked_ref())?;
        observer.observe(&self.els.arm_stage);
        observer.observe(&self.els.heat_stage);
        observer.observe(&self.els.plot_stage);
        *self.resize.borrow_mut() = Some((observer, resize_cb));

        let mut listeners = Vec::new();
        pointer::install(self, &weak, &mut listeners)?;
        self.install_controls(&weak, &mut listeners)?;
        *self.listeners.borrow_mut() = listeners;
        bench::install_hooks(&weak)?;
        Ok(())
    }

    /// Marks parts dirty and asks for one animation frame.
    fn invalidate(&self, bits: u32) {
        self.dirty.set(self.dirty.get() | bits);
        if self.raf_id.get().is_some() {
            return;
        }
        let Some(window) = web_sys::window() else {
            return;
        };
        if let Some(cb) = self.raf_callback.borrow().as_ref() {
            if let Ok(id) = window.request_animation_frame(cb.as_ref().unchecked_ref()) {
                self.raf_id.set(Some(id));
            }
        }
    }

    /// One animation frame: whatever is dirty, backgrounds first.
    fn frame(&self) {
        let bits = self.dirty.replace(0);
        if bits == 0 {
            return;
        }
        if bits & dirty::LAYOUT != 0 {
            self.layout();
        }
        if bits & dirty::ARM_BG != 0 {
            self.draw_arm_background();
        }
        if bits & dirty::HEAT_BG != 0 {
            self.draw_heat_background();
        }
        if bits & dirty::PLOT_BG != 0 {
            self.draw_plot_background();
        }
        if bits & dirty::FRAME != 0 {
            let t0 = now_ms();
            self.draw_frame();
            self.timings.push("frame", now_ms() - t0);
        }
        if bits & dirty::PLOT_FG != 0 {
            let t0 = now_ms();
            self.draw_plot_series();
            self.timings.push("plot", now_ms() - t0);
        }
    }

    /// Sizes every layer from its stage and recomputes the transforms.
    fn layout(&self) {
        let dpr = web_sys::window().map_or(1.0, |w| w.device_pixel_ratio());
        let scale = projector_scale(ctx::projector());
        let size = |e: &Element| {
            let r = e.get_bounding_client_rect();
            (r.width().max(1.0), r.height().max(1.0))
        };
        // The canvases fill their stage's padding box; measure a canvas, not the stage.
        let st = *self.state.borrow();
        let mut gfx = self.gfx.borrow_mut();
        let (aw, ah) = size(&gfx.arm_fg.canvas);
        let (hw, hh) = size(&gfx.heat_fg.canvas);
        let (pw, ph) = size(&gfx.plot_fg.canvas);
        gfx.arm_bg.resize(aw, ah, dpr);
        gfx.arm_fg.resize(aw, ah, dpr);
        gfx.heat_bg.resize(hw, hh, dpr);
        gfx.heat_fg.resize(hw, hh, dpr);
        gfx.plot_bg.resize(pw, ph, dpr);
        gfx.plot_fg.resize(pw, ph, dpr);
        let arm = st.params.arm();
        let ws_half = st.show_ws.then_some(st.params.half_mm / 1000.0);
        gfx.xf = ViewXf::fit(aw, ah, view::extent_m(&arm, ws_half));
        gfx.heat_layout = HeatLayout::new(hw, hh, scale);
        let lay = gfx.heat_layout;
        let o = gfx.xf.origin();
        let c = &self.els.arm_canvas;
        let _ = c.set_attribute("data-origin-x", &o.x.to_string());
        let _ = c.set_attribute("data-origin-y", &o.y.to_string());
        let _ = c.set_attribute("data-px-per-m", &gfx.xf.px_per_m.to_string());
        let h = &self.els.heat_canvas;
        let _ = h.set_attribute("data-plot-x", &lay.x.to_string());
        let _ = h.set_attribute("data-plot-y", &lay.y.to_string());
        let _ = h.set_attribute("data-plot-size", &lay.size.to_string());
        let _ = h.set_attribute("data-grid-n", &gfx.heat_grid.n.to_string());
    }

    fn draw_arm_background(&self) {
        let st = *self.state.borrow();
        let gfx = self.gfx.borrow();
        let ws = if st.show_ws {
            gfx.ws_img.as_ref()
        } else {
            None
        };
        view::draw_background(
            &gfx.arm_bg,
            &gfx.xf,
            &st.params.arm(),
            ws,
            projector_scale(ctx::projector()),
            &ctx::t("ik2r-unit-mm"),
        );
    }

    fn draw_heat_background(&self) {
        let gfx = self.gfx.borrow();
        let labels = heatmap::HeatLabels {
            q1_axis: ctx::t("ik2r-heatmap-axis-q1"),
            q2_axis: ctx::t("ik2r-heatmap-axis-q2"),
            legend_title: ctx::t("ik2r-heatmap-legend"),
            singular: ctx::t("ik2r-heatmap-singular"),
        };
        heatmap::draw_background(
            &gfx.heat_bg,
            &gfx.heat_layout,
            &heatmap::HeatPicture {
                image: gfx.heat_painted.then_some(&gfx.heat_img),
                grid_n: gfx.heat_grid.n,
                lut: &self.lut,
                scale_max: gfx.heat_grid.scale_max,
            },
            &labels,
            projector_scale(ctx::projector()),
        );
    }

    fn plot_labels() -> plots::PlotLabels {
        plots::PlotLabels {
            x_desc: ctx::t("ik2r-plot-x"),
            top_desc: ctx::t("ik2r-plot-top"),
            bottom_desc: ctx::t("ik2r-plot-bottom"),
        }
    }

    fn draw_plot_background(&self) {
        let p = self.state.borrow().params;
        let mut gfx = self.gfx.borrow_mut();
        gfx.plot_spec = PlotSpec::new(p.q1_start, p.q1_stop, p.l1, p.l2);
        if let Err(e) = plots::draw_background(
            &gfx.plot_bg,
            &gfx.plot_spec,
            &Self::plot_labels(),
            projector_scale(ctx::projector()),
        ) {
            web_sys::console::warn_1(&format!("ik-2r plot: {e}").into());
        }
    }

    /// The plotted sweep: the recipe's q1 values (at most 1500 of them, evenly picked) at
    /// the current q2.
    fn sweep_points(p: &Params, q2: f64) -> Vec<SweepPoint> {
        let Ok(q1s) = crate::numpy::arange(
            p.q1_start,
            p.q1_stop + 1e-12,
            p.q1_step,
            "q1_step",
            state::SWEEP_ROWS_MAX,
        ) else {
            return Vec::new();
        };
        let stride = q1s.len().div_ceil(1500).max(1);
        let arm = p.arm();
        let mut pts: Vec<SweepPoint> = q1s
            .iter()
            .step_by(stride)
            .map(|&q1| {
                let r = arm.report(q1, q2);
                SweepPoint {
                    q1,
                    det_j: r.det_j,
                    manipulability: r.manipulability,
                    sigma_min: r.ellipse.sigma_min,
                    sigma_max: r.ellipse.sigma_max,
                }
            })
            .collect();
        if let (Some(&last), Some(end)) = (q1s.last(), pts.last()) {
            if end.q1 != last {
                let r = arm.report(last, q2);
                pts.push(SweepPoint {
                    q1: last,
                    det_j: r.det_j,
                    manipulability: r.manipulability,
                    sigma_min: r.ellipse.sigma_min,
                    sigma_max: r.ellipse.sigma_max,
                });
            }
        }
        pts
    }

    fn draw_plot_series(&self) {
        let st = *self.state.borrow();
        let mut gfx = self.gfx.borrow_mut();
        let key = (st.params, st.q2);
        if gfx.sweep_key != Some(key) {
            gfx.sweep = Self::sweep_points(&st.params, st.q2);
            gfx.sweep_key = Some(key);
        }
        let marker = plots::marker_in_range(st.q1, &gfx.plot_spec);
        if let Err(e) = plots::draw_series(
            &gfx.plot_fg,
            &gfx.plot_spec,
            &gfx.sweep,
            marker,
            projector_scale(ctx::projector()),
        ) {
            web_sys::console::warn_1(&format!("ik-2r plot: {e}").into());
        }
    }

    /// The drag frame: pose report, readouts, arm layer, heatmap marker.
    fn draw_frame(&self) {
        let st = *self.state.borrow();
        let arm = st.params.arm();
        let report = arm.report(st.q1, st.q2);
        self.readouts.borrow_mut().update(&report);
        let ui = self.ui.borrow();
        let gfx = self.gfx.borrow();
        let scale = projector_scale(ctx::projector());
        let scene = view::Scene {
            arm,
            report: &report,
            ghost: ui.ghost,
            pinned_pointer: ui.pinned_pointer,
            hover: ui.drag.map_or(ui.hover_grab, |d| match d.target {
                DragTarget::Arm(g) => Some(g),
                DragTarget::Heatmap => None,
            }),
        };
        view::draw_foreground(&gfx.arm_fg, &gfx.xf, &scene, scale);
        heatmap::draw_marker(
            &gfx.heat_fg,
            &gfx.heat_layout,
            st.q1,
            st.q2,
            ui.ghost,
            scale,
        );
        let [_, elbow, tip] = view::joints_on_screen(&gfx.xf, &arm, st.q1, st.q2);
        let c = &self.els.arm_canvas;
        let _ = c.set_attribute("data-tip-x", &tip.x.to_string());
        let _ = c.set_attribute("data-tip-y", &tip.y.to_string());
        let _ = c.set_attribute("data-elbow-x", &elbow.x.to_string());
        let _ = c.set_attribute("data-elbow-y", &elbow.y.to_string());
        let h = &self.els.heat_canvas;
        let _ = h.set_attribute("data-marker-q1", &wrap_angle(st.q1).to_string());
        let _ = h.set_attribute("data-marker-q2", &wrap_angle(st.q2).to_string());
        let _ = h.set_attribute("data-marker-x", &gfx.heat_layout.x_of(st.q1).to_string());
        let _ = h.set_attribute("data-marker-y", &gfx.heat_layout.y_of(st.q2).to_string());
        drop(gfx);
        drop(ui);
        self.update_jacobian_command();
    }

    /// Recomputes and paints the heatmap for the current L1, L2 and resolution.
    fn recompute_heatmap(&self) {
        let p = self.state.borrow().params;
        let t0 = now_ms();
        let ok = {
            let mut gfx = self.gfx.borrow_mut();
            let gfx = &mut *gfx;
            let filled = heatmap::fill(&p.arm(), p.heatmap_n, &mut gfx.heat_grid);
            match filled.map(|_| heatmap::paint(&gfx.heat_grid, &self.lut, &mut gfx.heat_img)) {
                Ok(Ok(())) => {
                    gfx.heat_painted = true;
                    true
                }
                Ok(Err(e)) => {
                    web_sys::console::warn_2(&"ik-2r heatmap paint".into(), &e);
                    false
                }
                Err(e) => {
                    web_sys::console::warn_1(&format!("ik-2r heatmap: {e}").into());
                    false
                }
            }
        };
        if ok {
            let n = self.gfx.borrow().heat_grid.n;
            let _ = self
                .els
                .heat_canvas
                .set_attribute("data-grid-n", &n.to_string());
            self.timings.push("heatmap", now_ms() - t0);
        }
        self.invalidate(dirty::HEAT_BG | dirty::FRAME);
    }

    /// Recomputes the workspace grid (ik_workspace::compute) when its parameters changed,
    /// then re-renders the overlay.
    fn recompute_workspace(&self) {
        let st = *self.state.borrow();
        let wp = st.params.workspace();
        let stale = self
            .gfx
            .borrow()
            .ws_data
            .as_ref()
            .is_none_or(|(p, _)| *p != wp);
        if stale {
            let t0 = now_ms();
            match crate::recipes::ik_workspace::compute(&wp) {
                Ok(ws) => {
                    let mut gfx = self.gfx.borrow_mut();
                    gfx.ws_data = Some((wp, ws));
                    gfx.ws_img_colour = None;
                }
                Err(e) => {
                    web_sys::console::warn_1(&format!("ik-2r workspace: {e}").into());
                    return;
                }
            }
            self.timings.push("workspace", now_ms() - t0);
        }
        self.refresh_workspace_image();
    }

    /// Re-renders the overlay image from the cached grid (colour mode changes need no
    /// recompute).
    fn refresh_workspace_image(&self) {
        let st = *self.state.borrow();
        {
            let mut gfx = self.gfx.borrow_mut();
            let gfx = &mut *gfx;
            let Some((wp, ws)) = gfx.ws_data.as_ref() else {
                return;
            };
            if gfx.ws_img_colour != Some(st.ws_color) || gfx.ws_img.is_none() {
                let layer = match gfx.ws_img.take() {
                    Some(img) => img.layer,
                    None => match dom::document().and_then(|d| Layer::offscreen(&d)) {
                        Ok(l) => l,
                        Err(_) => return,
                    },
                };
                match workspace::render(ws, st.ws_color, wp.l1, wp.l2, &self.lut, layer) {
                    Ok(img) => {
                        gfx.ws_img = Some(img);
                        gfx.ws_img_colour = Some(st.ws_color);
                    }
                    Err(e) => web_sys::console::warn_2(&"ik-2r workspace".into(), &e),
                }
            }
        }
        self.update_ws_summary();
        self.invalidate(dirty::ARM_BG);
    }

    /// Writes the state into the URL now.
    fn write_url(&self) {
        self.url_timer.cancel();
        let query = self.state.borrow().query_pairs();
        crate::ui::router::replace_query(&query);
    }

    fn schedule_url(&self) {
        self.url_timer.schedule(300);
    }

    /// The pose changed (drag, key, heatmap): redraw the frame layers.
    fn pose_changed(&self) {
        self.invalidate(dirty::FRAME | dirty::PLOT_FG);
        if self.ui.borrow().drag.is_none() {
            self.schedule_url();
        }
    }

    /// Sets the pose, keeping q2 in (−π, π] and the elbow switch in step with q2's sign.
    fn set_pose(&self, q1: f64, q2: f64) {
        {
            let mut st = self.state.borrow_mut();
            st.q1 = q1;
            st.q2 = q2;
            st.elbow = elbow_of(q2);
        }
        self.sync_controls();
        self.pose_changed();
    }

    /// Moves the tip to `(x, y)` (m) by IK on the current branch; a point outside the reach
    /// is pinned to the nearest reachable one. Returns whether it was pinned.
    fn move_tip(&self, x: f64, y: f64) -> bool {
        let (arm, elbow) = {
            let st = self.state.borrow();
            (st.params.arm(), st.elbow)
        };
        let (cx, cy, pinned) = arm.clamp_to_reach(x, y);
        if let Some((q1, q2)) = arm.ik(cx, cy, elbow) {
            let mut st = self.state.borrow_mut();
            st.q1 = q1;
            st.q2 = q2;
        }
        self.pose_changed();
        pinned
    }

    /// Flips to `elbow`, keeping the tip where it is.
    fn set_elbow(&self, elbow: Elbow) {
        let (arm, q1, q2, current) = {
            let st = self.state.borrow();
            (st.params.arm(), st.q1, st.q2, st.elbow)
        };
        if elbow != current {
            let (x, y) = arm.fk(q1, q2);
            let (cx, cy, _) = arm.clamp_to_reach(x, y);
            let mut st = self.state.borrow_mut();
            st.elbow = elbow;
            if let Some((n1, n2)) = arm.ik(cx, cy, elbow) {
                st.q1 = n1;
                st.q2 = n2;
            }
        }
        self.sync_controls();
        self.pose_changed();
    }

    fn set_workspace_visible(&self, on: bool) {
        self.state.borrow_mut().show_ws = on;
        self.sync_controls();
        if on {
            self.recompute_workspace();
        }
        self.update_ws_summary();
        self.invalidate(dirty::LAYOUT | dirty::ARM_BG | dirty::FRAME);
        self.schedule_url();
    }

    /// Shows or hides the "out of reach" note.
    fn set_clamp_note(&self, visible: bool) {
        let mut ui = self.ui.borrow_mut();
        if ui.clamp_shown != visible {
            ui.clamp_shown = visible;
            show(&self.els.clamp_note, visible);
        }
    }

    fn relocalize(&self) {
        self.form.borrow().relocalize();
        self.update_texts();
        self.invalidate(dirty::ARM_BG | dirty::HEAT_BG | dirty::PLOT_BG | dirty::PLOT_FG);
    }

    fn unmount(&self) {
        if let (Some(id), Some(window)) = (self.raf_id.take(), web_sys::window()) {
            let _ = window.cancel_animation_frame(id);
        }
        self.heat_timer.cancel();
        self.ws_timer.cancel();
        self.url_timer.cancel();
        if let Some((observer, _)) = self.resize.borrow_mut().take() {
            observer.disconnect();
        }
        self.listeners.borrow_mut().clear();
        bench::remove_hooks();
    }
}

/// The shell's handle on the page.
struct Handle(Rc<Page>);

impl PageHandle for Handle {
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
        keys::on_key(&self.0, event)
    }

    fn unmount(&self) {
        self.0.unmount();
    }
}
