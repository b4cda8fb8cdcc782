//! The arm view: its toolbar (elbow branch, workspace grid and colour, Reset), the stage with
//! two layers (background: millimetre grid, reachable annulus `|L1 − L2| ≤ r ≤ L1 + L2`,
//! workspace overlay; top: links, joints, tip, manipulability ellipse, ghost pose, the pinned
//! pointer), the drag of tip and links, the out-of-reach note and the notes under the view.
//!
//! Pointer input (kit drag): grabbing the tip (or, with a mouse, empty space) drags the tip
//! by IK on the current branch, pinned to the reach when the pointer leaves the annulus; the
//! elbow or link 1 turns q1 (`q1 = atan2(y, x)` of the pointer), link 2 turns q2
//! (`q2 = atan2(p − elbow) − q1`). A finger on the arm drags it; a finger anywhere else
//! scrolls the page, and a tap there moves the tip.
//!
//! The ellipse is the image of the unit joint-speed circle, `{ J q̇ : |q̇| ≤ 1 }`: semi-axes
//! `σ_max`, `σ_min` along the left singular vectors of `J`, drawn at [`ELLIPSE_SCALE`].

use std::cell::RefCell;
use std::f64::consts::PI;
use std::rc::Weak;

use glam::DVec2;
use wasm_bindgen::prelude::*;
use web_sys::{
    CanvasRenderingContext2d, Element, HtmlCanvasElement, HtmlInputElement, HtmlSelectElement,
};

use super::markup::role;
use super::panels::Panels;
use super::workspace::WorkspaceImage;
use crate::planar2r::{Elbow, PoseReport, Sketch};
use crate::recipes::ik_workspace::{Workspace, WorkspaceParams};
use crate::ui::ctx::{self, t_strings};
use crate::ui::dom::{show, Listener};
use crate::ui::kit::canvas::{dash, focus_without_scroll, solid, Ink, LayeredCanvas};
use crate::ui::kit::drag::{Drag, DragEvent, PointerKind};
use crate::ui::schedule::now_ms;
use crate::view::heatmap::{viridis, Rgb};
use crate::view::ik2r::{
    self, extent_m, fmt_fixed, format_mm, grid_step_mm, joints_on_screen, link_label_centres, num,
    part_at, Grab, State, ViewXf, WsColor, ELLIPSE_SCALE,
};

/// Colours of the arm view (the home page's arm uses them too).
pub(crate) mod colour {
    pub const BG: &str = "#fbfcfe";
    pub const GRID: &str = "#e4e8ef";
    pub const AXIS: &str = "#9aa5b5";
    pub const LABEL: &str = "#5b6575";
    pub const ANNULUS: &str = "rgba(46, 125, 209, 0.08)";
    pub const ANNULUS_EDGE: &str = "rgba(46, 125, 209, 0.55)";
    pub const LINK1: &str = "#1f4e8c";
    pub const LINK2: &str = "#2e7dd1";
    pub const JOINT_FILL: &str = "#ffffff";
    pub const JOINT_EDGE: &str = "#1d2633";
    pub const TIP: &str = "#d9480f";
    pub const ELLIPSE_FILL: &str = "rgba(217, 72, 15, 0.12)";
    pub const ELLIPSE_EDGE: &str = "rgba(217, 72, 15, 0.85)";
    pub const GHOST: &str = "rgba(90, 100, 115, 0.55)";
    pub const PIN: &str = "rgba(217, 72, 15, 0.7)";
    pub const HOVER: &str = "rgba(255, 196, 0, 0.45)";
    pub const LABEL_HALO: &str = "rgba(251, 252, 254, 0.85)";
}

/// What the arm view's pointer and toolbar ask of the page.
pub(super) trait ArmHost: 'static {
    /// The part of the arm a pointer of `kind` grabs at canvas point `at` (see [`grab_at`]).
    fn grab_at(&self, at: DVec2, kind: PointerKind) -> Option<Grab>;
    /// A drag, tap or hover on the view.
    fn on_arm(&self, ev: DragEvent<Grab>);
    /// A toolbar control changed.
    fn on_control(&self, control: ArmControl);
}

/// The toolbar's controls.
#[derive(Debug, Clone, Copy)]
pub(super) enum ArmControl {
    Elbow(Elbow),
    /// The workspace grid shown or hidden.
    Workspace(bool),
    Colour(WsColor),
    Reset,
}

/// The part of the arm a pointer of `kind` grabs at canvas point `at`: a finger grabs only
/// the arm itself (elsewhere it scrolls); a mouse or pen grabs the nearest part.
pub(super) fn grab_at(xf: &ViewXf, st: &State, at: DVec2, kind: PointerKind) -> Option<Grab> {
    let arm = Sketch(st.params.arm());
    if kind == PointerKind::Touch {
        part_at(xf, &arm, st.q1, st.q2, at, true)
    } else {
        Some(ik2r::hit_test(xf, &arm, st.q1, st.q2, at, kind.is_coarse()))
    }
}

/// The arm view component.
pub(super) struct ArmView {
    canvas: LayeredCanvas,
    stage: Element,
    /// The top canvas (tests read the geometry from its `data-*` attributes).
    top: HtmlCanvasElement,
    pub xf: ViewXf,
    drag: Option<Drag<Grab>>,
    /// The part under a mouse (highlighted).
    hover: Option<Grab>,
    /// The pointer (world, m) while it is outside the reach and the tip is pinned.
    pinned_pointer: Option<DVec2>,
    clamp_shown: bool,
    /// The workspace grid with the parameters it was made for, and its overlay image.
    ws: Option<(WorkspaceParams, Workspace)>,
    ws_img: Option<WorkspaceImage>,
    ws_img_colour: Option<WsColor>,
    lut: Vec<Rgb>,
    /// The font the top layer's context has (set once per layout, with the text direction:
    /// setting a canvas font resolves it against the page's style, which costs a style
    /// recalculation after DOM writes).
    top_font: RefCell<String>,
    clamp_note: Element,
    view_notes: Element,
    ws_summary: Element,
    elbow_down: HtmlInputElement,
    elbow_up: HtmlInputElement,
    ws_toggle: HtmlInputElement,
    ws_color: HtmlSelectElement,
    reset: Element,
}

impl ArmView {
    pub fn find(root: &Element) -> Result<ArmView, JsValue> {
        let stage: Element = role(root, "arm-stage")?;
        Ok(ArmView {
            canvas: LayeredCanvas::from_stage(&stage)?,
            top: role(root, "arm-fg")?,
            stage,
            xf: ViewXf::fit(100.0, 100.0, 1.0),
            drag: None,
            hover: None,
            pinned_pointer: None,
            clamp_shown: false,
            ws: None,
            ws_img: None,
            ws_img_colour: None,
            lut: viridis(),
            top_font: RefCell::new(String::new()),
            clamp_note: role(root, "clamp-note")?,
            view_notes: role(root, "view-notes")?,
            ws_summary: role(root, "ws-summary")?,
            elbow_down: role(root, "elbow-down")?,
            elbow_up: role(root, "elbow-up")?,
            ws_toggle: role(root, "ws-toggle")?,
            ws_color: role(root, "ws-color")?,
            reset: role(root, "reset")?,
        })
    }

    /// The drag and the toolbar's listeners, reporting to `host`.
    pub fn attach<H: ArmHost>(
        &mut self,
        host: &Weak<H>,
        out: &mut Vec<Listener>,
    ) -> Result<(), JsValue> {
        let (w_hit, w_on) = (host.clone(), host.clone());
        let top: Element = self.top.clone().into();
        self.drag = Some(Drag::attach(
            &self.stage,
            &self.top,
            move |at, kind| w_hit.upgrade()?.grab_at(at, kind),
            move |ev: DragEvent<Grab>| {
                if let Some(host) = w_on.upgrade() {
                    if matches!(ev, DragEvent::Start { .. }) {
                        focus_without_scroll(&top);
                    }
                    host.on_arm(ev);
                }
            },
        )?);
        for (input, elbow) in [(&self.elbow_down, Elbow::Down), (&self.elbow_up, Elbow::Up)] {
            out.push(Listener::for_page(
                input,
                "change",
                host,
                move |h: &H, _| h.on_control(ArmControl::Elbow(elbow)),
            )?);
        }
        let toggle = self.ws_toggle.clone();
        out.push(Listener::for_page(
            &self.ws_toggle,
            "change",
            host,
            move |h: &H, _| h.on_control(ArmControl::Workspace(toggle.checked())),
        )?);
        let select = self.ws_color.clone();
        out.push(Listener::for_page(
            &self.ws_color,
            "change",
            host,
            move |h: &H, _| {
                if let Some(c) = WsColor::from_key(&select.value()) {
                    h.on_control(ArmControl::Colour(c));
                }
            },
        )?);
        out.push(Listener::for_page(
            &self.reset,
            "click",
            host,
            |h: &H, _| h.on_control(ArmControl::Reset),
        )?);
        Ok(())
    }

    pub fn detach(&mut self) {
        self.drag = None;
    }

    pub fn dragging(&self) -> bool {
        self.drag.as_ref().is_some_and(|d| d.active().is_some())
    }

    /// Whether the out-of-reach note is up (a drag or a key move is pinned to the reach).
    pub fn clamp_shown(&self) -> bool {
        self.clamp_shown
    }

    /// The pointer left the reach (`Some`, world m) or came back; shows the note.
    pub fn set_pinned(&mut self, pointer: Option<DVec2>) {
        self.pinned_pointer = pointer;
        self.set_clamp(pointer.is_some());
    }

    /// The drag ended: no pinned pointer, no note.
    pub fn end_drag(&mut self) {
        self.pinned_pointer = None;
        self.set_clamp(false);
    }

    /// Shows or hides the "out of reach" note.
    pub fn set_clamp(&mut self, visible: bool) {
        if self.clamp_shown != visible {
            self.clamp_shown = visible;
            show(&self.clamp_note, visible);
        }
    }

    /// A mouse at `at` (or gone): the part under it; returns whether the highlight changed.
    pub fn hover(&mut self, st: &State, at: Option<DVec2>) -> bool {
        let part =
            at.and_then(|p| part_at(&self.xf, &Sketch(st.params.arm()), st.q1, st.q2, p, false));
        if part == self.hover {
            return false;
        }
        self.hover = part;
        if let Some(d) = &self.drag {
            d.set_hover_cursor(if part.is_some() { "grab" } else { "" });
        }
        true
    }

    /// Radio buttons, checkbox and select from the state.
    pub fn sync_controls(&self, st: &State) {
        self.elbow_down.set_checked(st.elbow == Elbow::Down);
        self.elbow_up.set_checked(st.elbow == Elbow::Up);
        self.ws_toggle.set_checked(st.show_ws);
        self.ws_color.set_value(st.ws_color.key());
    }

    /// Sizes the layers and fits the view to the arm (and the workspace grid when shown).
    pub fn layout(&mut self, st: &State) {
        self.canvas.fit();
        // A resized canvas has its context state reset.
        self.top_font.borrow_mut().clear();
        if let Some(d) = &self.drag {
            d.relayout();
        }
        let (w, h) = self.canvas.size();
        let ws_half = st.show_ws.then_some(st.params.half_mm / 1000.0);
        self.xf = ViewXf::fit(w, h, extent_m(&st.params.arm(), ws_half));
        let o = self.xf.origin();
        let c = &self.top;
        let _ = c.set_attribute("data-origin-x", &o.x.to_string());
        let _ = c.set_attribute("data-origin-y", &o.y.to_string());
        let _ = c.set_attribute("data-px-per-m", &self.xf.px_per_m.to_string());
    }

    /// The notes under the view and the workspace summary.
    pub fn relocalize(&self, st: &State) {
        let (inner, outer) = st.params.arm().reach();
        let notes = t_strings(
            "ik2r-view-notes",
            &[
                ("inner", fmt_fixed(inner * 1000.0, 1)),
                ("outer", fmt_fixed(outer * 1000.0, 1)),
                ("scale", num(ELLIPSE_SCALE)),
            ],
        );
        self.view_notes.set_text_content(Some(&notes));
        match (&self.ws, st.show_ws) {
            (Some((_, ws)), true) => {
                let (nx, ny) = (ws.xs_mm.len(), ws.ys_mm.len());
                let text = t_strings(
                    "ik2r-ws-summary",
                    &[
                        ("nx", nx.to_string()),
                        ("ny", ny.to_string()),
                        ("cells", (nx * ny).to_string()),
                        ("reachable", ws.reachable_count().to_string()),
                    ],
                );
                self.ws_summary.set_text_content(Some(&text));
                show(&self.ws_summary, true);
            }
            _ => show(&self.ws_summary, false),
        }
    }

    // ---------- Workspace overlay ----------

    /// Drops the cached grid (its parameters changed while it was hidden).
    pub fn forget_workspace(&mut self) {
        self.ws = None;
    }

    /// Recomputes the workspace grid (with the second stage's kernel, `panels`) if its
    /// parameters changed, then the overlay; returns how long the grid's computation
    /// (`ik_workspace::compute`) took, ms, if it ran.
    pub fn recompute_workspace(&mut self, st: &State, panels: &dyn Panels) -> Option<f64> {
        let wp = st.params.workspace();
        let stale = self.ws.as_ref().is_none_or(|(p, _)| *p != wp);
        let mut compute_ms = None;
        if stale {
            let t0 = now_ms();
            match panels.workspace_grid(&wp) {
                Ok(ws) => {
                    compute_ms = Some(now_ms() - t0);
                    self.ws = Some((wp, ws));
                    self.ws_img_colour = None;
                }
                Err(e) => {
                    web_sys::console::warn_1(&format!("ik-2r workspace: {e}").into());
                    return None;
                }
            }
        }
        self.refresh_workspace_image(st, panels);
        compute_ms
    }

    /// Re-renders the overlay from the cached grid (a colour change needs no recompute).
    pub fn refresh_workspace_image(&mut self, st: &State, panels: &dyn Panels) {
        let Some((wp, ws)) = self.ws.as_ref() else {
            return;
        };
        if self.ws_img_colour == Some(st.ws_color) && self.ws_img.is_some() {
            return;
        }
        let previous = self.ws_img.take();
        match panels.workspace_image(ws, st.ws_color, wp.l1, wp.l2, &self.lut, previous) {
            Ok(img) => {
                self.ws_img = Some(img);
                self.ws_img_colour = Some(st.ws_color);
            }
            Err(e) => web_sys::console::warn_2(&"ik-2r workspace".into(), &e),
        }
    }

    // ---------- Drawing ----------

    /// The background layer: workspace overlay, grid with millimetre labels, annulus.
    pub fn draw_background(&self, st: &State, ink: Ink) {
        let layer = self.canvas.layer(0);
        let xf = &self.xf;
        layer.begin();
        let ctx = &layer.ctx;
        let (w, h) = (layer.css_w, layer.css_h);
        ctx.set_fill_style_str(colour::BG);
        ctx.fill_rect(0.0, 0.0, w, h);

        if let (true, Some(ws)) = (st.show_ws, self.ws_img.as_ref()) {
            let a = xf.screen(ws.x_min, ws.y_max);
            let b = xf.screen(ws.x_max, ws.y_min);
            ctx.set_image_smoothing_enabled(false);
            let _ = ctx.draw_image_with_html_canvas_element_and_dw_and_dh(
                &ws.layer.canvas,
                a.x,
                a.y,
                b.x - a.x,
                b.y - a.y,
            );
            ctx.set_image_smoothing_enabled(true);
        }

        // Grid: lines every `step` mm, labels on the axes.
        let step_mm = grid_step_mm(w.min(h) / 2.0 / xf.px_per_m);
        let step_px = step_mm / 1000.0 * xf.px_per_m;
        let o = xf.origin();
        let n_x = ((w / 2.0) / step_px).ceil() as i64 + 1;
        let n_y = ((h / 2.0) / step_px).ceil() as i64 + 1;
        ctx.set_line_width(1.0);
        ctx.set_stroke_style_str(colour::GRID);
        ctx.begin_path();
        for i in -n_x..=n_x {
            let x = (o.x + i as f64 * step_px).round() + 0.5;
            ctx.move_to(x, 0.0);
            ctx.line_to(x, h);
        }
        for j in -n_y..=n_y {
            let y = (o.y - j as f64 * step_px).round() + 0.5;
            ctx.move_to(0.0, y);
            ctx.line_to(w, y);
        }
        ctx.stroke();

        ctx.set_stroke_style_str(colour::AXIS);
        ctx.set_line_width(ink.line);
        ctx.begin_path();
        ctx.move_to(0.0, o.y.round() + 0.5);
        ctx.line_to(w, o.y.round() + 0.5);
        ctx.move_to(o.x.round() + 0.5, 0.0);
        ctx.line_to(o.x.round() + 0.5, h);
        ctx.stroke();

        // Reachable annulus.
        let (inner, outer) = st.params.arm().reach();
        let (r_out, r_in) = (outer * xf.px_per_m, inner * xf.px_per_m);
        ctx.set_fill_style_str(colour::ANNULUS);
        ctx.begin_path();
        let _ = ctx.arc(o.x, o.y, r_out, 0.0, 2.0 * PI);
        if r_in > 0.0 {
            ctx.move_to(o.x + r_in, o.y);
            let _ = ctx.arc_with_anticlockwise(o.x, o.y, r_in, 0.0, 2.0 * PI, true);
        }
        ctx.fill();
        ctx.set_stroke_style_str(colour::ANNULUS_EDGE);
        ctx.set_line_width(1.5 * ink.line);
        let _ = ctx.set_line_dash(&dash(6.0 * ink.line, 4.0 * ink.line));
        ctx.begin_path();
        let _ = ctx.arc(o.x, o.y, r_out, 0.0, 2.0 * PI);
        ctx.stroke();
        if r_in > 0.5 {
            ctx.begin_path();
            let _ = ctx.arc(o.x, o.y, r_in, 0.0, 2.0 * PI);
            ctx.stroke();
        }
        let _ = ctx.set_line_dash(&solid());

        // Millimetre labels along the axes (every other line, or fewer, when crowded).
        ctx.set_fill_style_str(colour::LABEL);
        ctx.set_font(&ink.font(11.0, false));
        let label_w = ink.text_px(11.0) * 3.6;
        let label_every = (label_w / step_px).ceil().max(1.0) as i64;
        // Only labels whole inside the canvas (a cut "-400" would read "00").
        const EDGE: f64 = 3.0;
        let text_h = ink.text_px(11.0);
        let mut boxes = String::new();
        ctx.set_text_align("center");
        ctx.set_text_baseline("top");
        for i in -n_x..=n_x {
            if i == 0 || i % label_every != 0 {
                continue;
            }
            let text = format_mm(i as f64 * step_mm);
            let x = o.x + i as f64 * step_px;
            let half = ctx.measure_text(&text).map(|m| m.width()).unwrap_or(0.0) / 2.0;
            if x - half < EDGE || x + half > w - EDGE {
                continue;
            }
            let _ = ctx.fill_text(&text, x, o.y + 4.0);
            if !boxes.is_empty() {
                boxes.push(';');
            }
            boxes.push_str(&format!("{text}@{:.1},{:.1}", x - half, x + half));
        }
        // Where the x labels are (`text@left,right`, CSS px), for tests.
        let _ = self.top.set_attribute("data-x-labels", &boxes);
        ctx.set_text_align("right");
        ctx.set_text_baseline("middle");
        for j in -n_y..=n_y {
            if j == 0 || j % label_every != 0 {
                continue;
            }
            let y = o.y - j as f64 * step_px;
            if y - text_h / 2.0 < EDGE || y + text_h / 2.0 > h - EDGE {
                continue;
            }
            let _ = ctx.fill_text(&format_mm(j as f64 * step_mm), o.x - 5.0, y);
        }
        let unit = ctx::t("ik2r-unit-mm");
        ctx.set_font(&ink.font(12.0, true));
        ctx.set_text_align("right");
        ctx.set_text_baseline("bottom");
        let _ = ctx.fill_text(&format!("x [{unit}]"), w - 6.0, o.y - 4.0);
        ctx.set_text_align("left");
        ctx.set_text_baseline("top");
        let _ = ctx.fill_text(&format!("y [{unit}]"), o.x + 6.0, 6.0);
    }

    /// The top layer, the geometry attributes and, with `handles`, the touch handles (not
    /// while a drag holds the pointer: the drag's end places them).
    pub fn draw_frame(
        &self,
        st: &State,
        rep: &PoseReport,
        ghost: Option<(f64, f64)>,
        ink: Ink,
        handles: bool,
    ) {
        let layer = self.canvas.top();
        let xf = &self.xf;
        let arm = Sketch(st.params.arm());
        let s = ink.line;
        layer.begin();
        let ctx = &layer.ctx;
        let [base, elbow, tip] = joints_on_screen(xf, &arm, rep.q1, rep.q2);

        if let Some(ghost) = ghost {
            draw_ghost(ctx, xf, &arm, ghost, s);
        }
        draw_ellipse(ctx, xf, rep, tip, s);

        // Pointer outside the reach: a dashed line from the pinned tip to the pointer.
        if let Some(p) = self.pinned_pointer {
            let sp = xf.screen(p.x, p.y);
            ctx.set_stroke_style_str(colour::PIN);
            ctx.set_line_width(1.5 * s);
            let _ = ctx.set_line_dash(&dash(4.0 * s, 4.0 * s));
            ctx.begin_path();
            ctx.move_to(tip.x, tip.y);
            ctx.line_to(sp.x, sp.y);
            ctx.stroke();
            let _ = ctx.set_line_dash(&solid());
            circle(ctx, sp, 4.0 * s, None, Some(colour::PIN), 1.5 * s);
        }

        // Hover / drag highlight under the links.
        if let Some(grab) = self.drag.as_ref().and_then(|d| d.active()).or(self.hover) {
            ctx.set_stroke_style_str(colour::HOVER);
            ctx.set_line_cap("round");
            ctx.set_line_width(22.0 * s);
            ctx.begin_path();
            let (a, b) = match grab {
                Grab::Q1 => (base, elbow),
                Grab::Q2 => (elbow, tip),
                Grab::Tip => (tip, tip + DVec2::new(0.01, 0.0)),
            };
            ctx.move_to(a.x, a.y);
            ctx.line_to(b.x, b.y);
            ctx.stroke();
        }

        // Base.
        ctx.set_fill_style_str(colour::JOINT_EDGE);
        ctx.begin_path();
        ctx.move_to(base.x, base.y);
        ctx.line_to(base.x - 13.0 * s, base.y + 18.0 * s);
        ctx.line_to(base.x + 13.0 * s, base.y + 18.0 * s);
        ctx.close_path();
        ctx.fill();

        // Links, joints, tip.
        ctx.set_line_cap("round");
        ctx.set_line_width(10.0 * s);
        for (a, b, c) in [(base, elbow, colour::LINK1), (elbow, tip, colour::LINK2)] {
            ctx.set_stroke_style_str(c);
            ctx.begin_path();
            ctx.move_to(a.x, a.y);
            ctx.line_to(b.x, b.y);
            ctx.stroke();
        }
        for joint in [base, elbow] {
            circle(
                ctx,
                joint,
                7.0 * s,
                Some(colour::JOINT_FILL),
                Some(colour::JOINT_EDGE),
                2.5 * s,
            );
        }
        circle(
            ctx,
            tip,
            9.0 * s,
            Some(colour::TIP),
            Some(colour::JOINT_FILL),
            2.5 * s,
        );

        self.draw_link_labels(ctx, [base, elbow, tip], ink);

        let c = &self.top;
        let _ = c.set_attribute("data-tip-x", &tip.x.to_string());
        let _ = c.set_attribute("data-tip-y", &tip.y.to_string());
        let _ = c.set_attribute("data-elbow-x", &elbow.x.to_string());
        let _ = c.set_attribute("data-elbow-y", &elbow.y.to_string());
        if let (Some(d), true) = (&self.drag, handles) {
            let shapes = ik2r::handles(xf, &arm, rep.q1, rep.q2, true).map(|(_, shape)| shape);
            d.set_handles(&shapes);
        }
    }

    /// Link labels outside the bend, on a light box (never on top of each other); a box
    /// costs a rectangle where a stroked text outline costs a second text draw per frame.
    fn draw_link_labels(&self, ctx: &CanvasRenderingContext2d, joints: [DVec2; 3], ink: Ink) {
        let [base, elbow, tip] = joints;
        let s = ink.line;
        let font_px = ink.text_px(12.0);
        let gap = 10.0 * s + font_px * 0.75;
        let (box_w, box_h) = (font_px * 1.5, font_px * 1.2);
        let font = ink.font(12.0, true);
        if *self.top_font.borrow() != font {
            ctx.set_font(&font);
            // The default direction, `inherit`, makes every text draw read the canvas's
            // computed style (a style recalculation after DOM writes); the labels are LTR.
            let _ = js_sys::Reflect::set(ctx, &"direction".into(), &"ltr".into());
            *self.top_font.borrow_mut() = font;
        }
        ctx.set_text_align("center");
        ctx.set_text_baseline("middle");
        let centres = link_label_centres(base, elbow, tip, gap);
        ctx.set_fill_style_str(colour::LABEL_HALO);
        for at in centres {
            ctx.fill_rect(at.x - box_w / 2.0, at.y - box_h / 2.0, box_w, box_h);
        }
        ctx.set_fill_style_str(colour::JOINT_EDGE);
        for (label, at) in ["L1", "L2"].into_iter().zip(centres) {
            let _ = ctx.fill_text(label, at.x, at.y);
        }
    }

    /// The arm view (both layers) as one canvas, for the PNG download.
    pub fn flatten(&self) -> Result<HtmlCanvasElement, JsValue> {
        self.canvas.flatten(colour::BG)
    }
}

/// The pose under the heatmap's pointer, dashed and grey.
fn draw_ghost(
    ctx: &CanvasRenderingContext2d,
    xf: &ViewXf,
    arm: &Sketch,
    (g1, g2): (f64, f64),
    s: f64,
) {
    let [gb, ge, gt] = joints_on_screen(xf, arm, g1, g2);
    ctx.set_stroke_style_str(colour::GHOST);
    ctx.set_line_width(5.0 * s);
    ctx.set_line_cap("round");
    let _ = ctx.set_line_dash(&dash(8.0 * s, 6.0 * s));
    ctx.begin_path();
    ctx.move_to(gb.x, gb.y);
    ctx.line_to(ge.x, ge.y);
    ctx.line_to(gt.x, gt.y);
    ctx.stroke();
    let _ = ctx.set_line_dash(&solid());
    circle(ctx, gt, 5.0 * s, Some(colour::GHOST), None, 0.0);
}

/// The manipulability ellipse at the tip; singular directions: major solid, minor dashed.
fn draw_ellipse(ctx: &CanvasRenderingContext2d, xf: &ViewXf, rep: &PoseReport, tip: DVec2, s: f64) {
    let e = rep.ellipse;
    let rx = (ELLIPSE_SCALE * e.sigma_max * xf.px_per_m).max(0.0);
    let ry = (ELLIPSE_SCALE * e.sigma_min * xf.px_per_m).max(0.0);
    let rot = -e.angle_rad;
    ctx.set_fill_style_str(colour::ELLIPSE_FILL);
    ctx.set_stroke_style_str(colour::ELLIPSE_EDGE);
    ctx.set_line_width(1.5 * s);
    ctx.begin_path();
    if ctx
        .ellipse(tip.x, tip.y, rx, ry.max(0.01), rot, 0.0, 2.0 * PI)
        .is_ok()
    {
        ctx.fill();
        ctx.stroke();
    }
    let (c, sn) = (rot.cos(), rot.sin());
    ctx.begin_path();
    ctx.move_to(tip.x - rx * c, tip.y - rx * sn);
    ctx.line_to(tip.x + rx * c, tip.y + rx * sn);
    ctx.stroke();
    let _ = ctx.set_line_dash(&dash(3.0 * s, 3.0 * s));
    ctx.begin_path();
    ctx.move_to(tip.x + ry * sn, tip.y - ry * c);
    ctx.line_to(tip.x - ry * sn, tip.y + ry * c);
    ctx.stroke();
    let _ = ctx.set_line_dash(&solid());
}

fn circle(
    ctx: &CanvasRenderingContext2d,
    c: DVec2,
    r: f64,
    fill: Option<&str>,
    stroke: Option<&str>,
    width: f64,
) {
    ctx.begin_path();
    let _ = ctx.arc(c.x, c.y, r, 0.0, 2.0 * PI);
    if let Some(f) = fill {
        ctx.set_fill_style_str(f);
        ctx.fill();
    }
    if let Some(s) = stroke {
        ctx.set_stroke_style_str(s);
        ctx.set_line_width(width);
        ctx.stroke();
    }
}
