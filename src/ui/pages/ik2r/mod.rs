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
//! Files: `mount` (building the page, wiring its callbacks, unmounting), `frame` (dirty
//! bits, one draw per animation frame, layout), `draw` (what a frame draws), `recompute`
//! (heatmap and workspace recomputes), `pose` (pose, elbow, workspace toggle, URL writes),
//! `state` (state and URL), `view` (arm view drawing), `pointer` (pointer and drag),
//! `heatmap`, `workspace` (overlay), `plots`, `readouts`, `form` (parameters),
//! `controls` (toolbar, form, download and copy handlers), `texts` (text the page formats
//! itself), `downloads`, `explain` (explanation panel), `keys`, `markup`, `canvas`
//! (HiDPI layers), `bench` (timing hooks). This file holds the page's types and the shell's
//! handle on it.

mod bench;
mod canvas;
mod controls;
mod downloads;
mod draw;
mod explain;
mod form;
mod frame;
mod heatmap;
mod keys;
mod markup;
mod mount;
mod plots;
mod pointer;
mod pose;
mod readouts;
mod recompute;
mod state;
mod texts;
mod view;
mod workspace;

use std::cell::{Cell, RefCell};
use std::rc::Rc;

use glam::DVec2;
use wasm_bindgen::prelude::*;
use web_sys::{
    Element, HtmlCanvasElement, HtmlInputElement, HtmlSelectElement, KeyboardEvent, ResizeObserver,
};

use self::canvas::Layer;
use self::frame::dirty;
use self::heatmap::{HeatGrid, HeatLayout};
use self::plots::{PlotSpec, SweepPoint};
use self::state::{Params, State, WsColor};
use self::view::{Grab, ViewXf, WorkspaceImage};
use crate::recipes::ik_workspace::{Workspace, WorkspaceParams};
use crate::ui::dom::Listener;
use crate::ui::page::{PageDef, PageHandle, Shortcut};
use crate::ui::schedule::Timer;

/// The page, as the shell's page table lists it.
pub const PAGE: PageDef = PageDef {
    id: "ik-2r",
    title_id: "ik2r-title",
    blurb_id: "ik2r-blurb",
    mount: mount::mount,
};

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

/// The `requestAnimationFrame` callback.
type FrameCallback = Closure<dyn FnMut(f64)>;
/// The resize observer and its callback.
type Resize = (ResizeObserver, Closure<dyn FnMut(JsValue)>);

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
