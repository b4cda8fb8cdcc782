//! The joint-space manipulability heatmap: `|det J|` over `q1, q2 ∈ [−π, π]` on an `n × n`
//! grid sampled like the manip-grid recipe (`q_i = −π + 2π i / (n − 1)`), painted by the kit
//! heatmap once per parameter change; the pose marker and the hovered cell are drawn per
//! frame. Pointing at a cell previews its pose (a ghost arm); pressing, dragging or tapping
//! sets it. A finger on the marker drags it; a finger elsewhere scrolls the page.
//!
//! `det J = (−L1 s1 − L2 s12) L2 c12 + L2 s12 (L1 c1 + L2 c12)`, which is `L1 L2 sin q2`: the
//! map is a set of horizontal bands, zero (singular) on `q2 = 0` and `q2 = ±π`.

use std::f64::consts::PI;
use std::rc::Weak;

use glam::DVec2;
use wasm_bindgen::prelude::*;
use web_sys::{Element, HtmlCanvasElement};

use super::markup::role;
use crate::planar2r::{wrap_angle, Arm};
use crate::ui::ctx::{self, t_strings};
use crate::ui::kit::canvas::{dash, solid, Ink};
use crate::ui::kit::drag::{Drag, DragEvent, PointerKind};
use crate::ui::kit::heatmap::{Heatmap, HeatmapSpec, MARKER_RADIUS_PX};
use crate::view::drag::HandleShape;
use crate::view::ik2r::{fmt_fixed, fmt_sig, heat_axis, heat_fill, Params, State};

/// What the heatmap's pointer asks of the page.
pub(super) trait HeatHost: 'static {
    /// Whether a pointer of `kind` at canvas point `at` grabs the heatmap (see
    /// [`HeatPanel::grabs`]).
    fn heat_grab(&self, at: DVec2, kind: PointerKind) -> Option<()>;
    /// A drag, tap or hover on the heatmap.
    fn on_heat(&self, ev: DragEvent<()>);
}

/// The heatmap component.
pub(super) struct HeatPanel {
    map: Heatmap,
    stage: Element,
    top: HtmlCanvasElement,
    hover_text: Element,
    drag: Option<Drag<()>>,
    values: Vec<f32>,
}

const TICKS: [(f64, &str); 5] = [
    (-PI, "−π"),
    (-PI / 2.0, "−π/2"),
    (0.0, "0"),
    (PI / 2.0, "π/2"),
    (PI, "π"),
];

impl HeatPanel {
    pub fn find(root: &Element) -> Result<HeatPanel, JsValue> {
        let stage: Element = role(root, "heat-stage")?;
        Ok(HeatPanel {
            map: Heatmap::new(&stage, (-PI, PI), (-PI, PI))?,
            top: role(root, "heat-fg")?,
            hover_text: role(root, "heat-hover")?,
            stage,
            drag: None,
            values: Vec::new(),
        })
    }

    /// Whether `target` (a key's) is the heatmap's focusable canvas.
    pub fn is_canvas(&self, target: Option<web_sys::EventTarget>) -> bool {
        let canvas: &web_sys::EventTarget = self.top.as_ref();
        target.is_some_and(|t| &t == canvas)
    }

    /// The drag on the heatmap, reporting to `host`.
    pub fn attach<H: HeatHost>(&mut self, host: &Weak<H>) -> Result<(), JsValue> {
        let (w_hit, w_on) = (host.clone(), host.clone());
        self.drag = Some(Drag::attach(
            &self.stage,
            &self.top,
            move |at, kind| w_hit.upgrade()?.heat_grab(at, kind),
            move |ev: DragEvent<()>| {
                if let Some(host) = w_on.upgrade() {
                    host.on_heat(ev);
                }
            },
        )?);
        Ok(())
    }

    /// Whether a pointer of `kind` at canvas point `at` grabs the heatmap: a finger only on
    /// the marker (elsewhere it scrolls; a tap jumps), a mouse or pen anywhere on the grid.
    pub fn grabs(&self, st: &State, at: DVec2, kind: PointerKind) -> Option<()> {
        if kind == PointerKind::Touch {
            self.marker_handle(st).contains(at).then_some(())
        } else {
            self.pose_at(at).map(|_| ())
        }
    }

    pub fn detach(&mut self) {
        self.drag = None;
    }

    pub fn dragging(&self) -> bool {
        self.drag.as_ref().is_some_and(|d| d.active().is_some())
    }

    /// The grid pose under canvas point `at`.
    pub fn pose_at(&self, at: DVec2) -> Option<(f64, f64)> {
        let (i, j) = self.map.node_at(at)?;
        let axis = heat_axis(self.map.grid().0);
        Some((axis.node(i), axis.node(j)))
    }

    /// Recomputes and paints the grid; returns whether it worked.
    pub fn recompute(&mut self, arm: &Arm, n: usize) -> bool {
        let n = n.max(2);
        let top = match heat_fill(arm, n, &mut self.values) {
            Ok(top) => top,
            Err(e) => {
                web_sys::console::warn_1(&format!("ik-2r heatmap: {e}").into());
                return false;
            }
        };
        if let Err(e) = self.map.paint(&self.values, n, n, (0.0, top)) {
            web_sys::console::warn_2(&"ik-2r heatmap paint".into(), &e);
            return false;
        }
        let _ = self.top.set_attribute("data-grid-n", &n.to_string());
        true
    }

    pub fn layout(&mut self, ink: Ink) {
        self.map.fit(ink);
        if let Some(d) = &self.drag {
            d.relayout();
        }
        let lay = &self.map.layout;
        let h = &self.top;
        let _ = h.set_attribute("data-plot-x", &lay.x.to_string());
        let _ = h.set_attribute("data-plot-y", &lay.y.to_string());
        let _ = h.set_attribute("data-plot-size", &lay.size.to_string());
        let _ = h.set_attribute("data-grid-n", &self.map.grid().0.to_string());
    }

    /// The painted grid, axes, legend and the singular lines `q2 = 0, ±π`.
    pub fn draw_background(&self, ink: Ink) {
        let (q1, q2, legend, singular) = (
            ctx::t("ik2r-heatmap-axis-q1"),
            ctx::t("ik2r-heatmap-axis-q2"),
            ctx::t("ik2r-heatmap-legend"),
            ctx::t("ik2r-heatmap-singular"),
        );
        let spec = HeatmapSpec {
            x_title: &q1,
            y_title: &q2,
            legend_title: &legend,
            x_ticks: &TICKS,
            y_ticks: &TICKS,
        };
        self.map.draw_background(&spec, ink, |ctx, lay| {
            ctx.set_stroke_style_str("rgba(255, 80, 80, 0.95)");
            ctx.set_line_width(1.5 * ink.line);
            let _ = ctx.set_line_dash(&dash(5.0 * ink.line, 4.0 * ink.line));
            for q2 in [-PI, 0.0, PI] {
                // max then min: a panel under 2 px would make clamp's bounds cross.
                let y = lay.y_of(q2).max(lay.y + 1.0).min(lay.y + lay.size - 1.0);
                ctx.begin_path();
                ctx.move_to(lay.x, y);
                ctx.line_to(lay.x + lay.size, y);
                ctx.stroke();
            }
            let _ = ctx.set_line_dash(&solid());
            ctx.set_fill_style_str("rgba(255, 255, 255, 0.92)");
            ctx.set_font(&ink.font(11.0, true));
            ctx.set_text_align("left");
            ctx.set_text_baseline("bottom");
            let _ = ctx.fill_text(&singular, lay.x + 4.0, lay.y + lay.size / 2.0 - 3.0);
        });
    }

    /// Where a finger can grab the marker.
    fn marker_handle(&self, st: &State) -> HandleShape {
        let lay = &self.map.layout;
        HandleShape::Circle {
            centre: DVec2::new(lay.x_of(wrap_angle(st.q1)), lay.y_of(wrap_angle(st.q2))),
            radius: MARKER_RADIUS_PX + 18.0,
        }
    }

    /// The marker (current pose), the hovered cell's crosshair, the attributes tests read
    /// and, with `handle`, the marker's touch handle (not during a drag).
    pub fn draw_marker(&self, st: &State, ghost: Option<(f64, f64)>, ink: Ink, handle: bool) {
        let (q1, q2) = (wrap_angle(st.q1), wrap_angle(st.q2));
        self.map.draw_marker((q1, q2), ghost, ink);
        let lay = &self.map.layout;
        let h = &self.top;
        let _ = h.set_attribute("data-marker-q1", &q1.to_string());
        let _ = h.set_attribute("data-marker-q2", &q2.to_string());
        let _ = h.set_attribute("data-marker-x", &lay.x_of(q1).to_string());
        let _ = h.set_attribute("data-marker-y", &lay.y_of(q2).to_string());
        if let (Some(d), true) = (&self.drag, handle) {
            d.set_handles(&[self.marker_handle(st)]);
        }
    }

    /// The preview text of the hovered cell.
    pub fn relocalize(&self, p: &Params, ghost: Option<(f64, f64)>) {
        let text = match ghost {
            Some((q1, q2)) => t_strings(
                "ik2r-heatmap-hover",
                &[
                    ("q1", fmt_fixed(q1, 3)),
                    ("q2", fmt_fixed(q2, 3)),
                    ("det", fmt_sig(p.arm().det_explicit(q1, q2).abs(), 4)),
                ],
            ),
            None => String::new(),
        };
        self.hover_text.set_text_content(Some(&text));
    }
}
