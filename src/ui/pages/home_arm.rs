//! The live arm at the top of the home page: the recipes' default 2R arm (0.12 m, 0.10 m) in a
//! small view. Dragging the tip moves it by inverse kinematics on the current elbow branch
//! (pinned to the reach `|L1 − L2| ≤ r ≤ L1 + L2`), dragging a link turns one joint, a tap or
//! a mouse press on empty space sends the tip there, and with the view focused the arrow keys
//! move the tip; the joint angles read out under it and a link opens the same pose on the IK
//! page. Pointer input is the kit's drag: a finger on the arm drags it, a finger anywhere else
//! scrolls the page.

use std::cell::{Cell, RefCell};
use std::rc::Rc;

use glam::DVec2;
use wasm_bindgen::prelude::*;
use web_sys::{Element, KeyboardEvent};

use crate::planar2r::{wrap_angle, Arm, ArmShape, Elbow, Sketch};
use crate::ui::dom;
use crate::ui::kit::canvas::{disc, focus_without_scroll, ring, Ink, LayeredCanvas};
use crate::ui::kit::drag::{Drag, DragEvent, PointerKind};
use crate::ui::kit::frame::FrameLoop;
use crate::ui::kit::scope::Scope;
use crate::ui::page::Shortcut;
use crate::ui::pages::ik2r::arm_colour as colour;
use crate::ui::router;
use crate::view::ik2r::{
    elbow_of, extent_m, fmt_fixed, handles, hit_test, joints_on_screen, num, part_at, Grab, ViewXf,
};

/// The recipes' default arm, drawn with the platform's `f64` functions: its angles are shown
/// to a tenth of a degree and passed on to the IK page to six decimals, so the correctly
/// rounded ones (and their 28 KB of wasm) are not needed before the home page's first frame.
const ARM: Sketch = Sketch(Arm::DEFAULT);

/// The pose it opens with: the IK page's (q1 0.3 rad, q2 0.8 rad, elbow down).
const START: (f64, f64) = (0.3, 0.8);

/// How far an arrow key moves the tip, metres (with Shift: [`NUDGE_FINE_M`]).
const NUDGE_M: f64 = 0.005;
const NUDGE_FINE_M: f64 = 0.001;

/// The keys of the focused arm, for the page's `?` list.
pub(crate) const KEYS: &[Shortcut] = &[Shortcut {
    keys: "← ↑ → ↓",
    message_id: "home-arm-key-nudge",
}];

/// The view, its readouts and its link; listeners and the frame loop go away on drop.
pub(crate) struct HomeArm {
    canvas: RefCell<LayeredCanvas>,
    /// The top canvas (it takes focus and the arrow keys).
    canvas_el: Element,
    /// Joint angles (q1, q2), radians.
    pose: Cell<(f64, f64)>,
    q1_out: Element,
    q2_out: Element,
    open: Element,
    drag: RefCell<Option<Drag<Grab>>>,
    frame: RefCell<Option<FrameLoop>>,
    scope: RefCell<Scope>,
}

/// The figure's markup: the stage with its canvas, the hint, the two angles and the link.
const MARKUP: &str = "<div class=\"home-arm-stage\" data-home-arm=\"stage\">\
    <canvas class=\"home-arm-layer\" data-testid=\"home-arm-canvas\" role=\"img\" tabindex=\"0\" \
    data-i18n-attr=\"aria-label=home-arm-label\" aria-describedby=\"home-arm-hint home-arm-values\">\
    </canvas></div>\
    <figcaption><p class=\"home-arm-hint\" id=\"home-arm-hint\" data-i18n=\"home-arm-hint\"></p>\
    <p class=\"home-arm-values\" id=\"home-arm-values\"><span class=\"home-arm-name\">q1</span>\
    <output class=\"home-arm-value\" data-testid=\"home-arm-q1\"></output>\
    <span class=\"home-arm-name\">q2</span>\
    <output class=\"home-arm-value\" data-testid=\"home-arm-q2\"></output></p>\
    <a class=\"home-arm-open\" data-testid=\"home-arm-open\"><span data-i18n=\"home-arm-open\"></span>\
    <span class=\"arrow\" aria-hidden=\"true\">\u{a0}→</span></a></figcaption>";

/// Builds the figure (stage, readouts, link) at the end of `parent`.
pub(crate) fn mount(parent: &Element) -> Result<Rc<HomeArm>, JsValue> {
    let figure = dom::el_class("figure", "home-arm")?;
    figure.set_attribute("data-testid", "home-arm")?;
    figure.set_inner_html(MARKUP);
    dom::relocalize(&figure)?;
    dom::append(parent, &figure)?;
    let find = |selector: &str| dom::find::<Element>(&figure, selector, "home arm");
    let stage = find("[data-home-arm=\"stage\"]")?;
    let canvas = find("canvas")?;
    let arm = Rc::new(HomeArm {
        canvas: RefCell::new(LayeredCanvas::from_stage(&stage)?),
        canvas_el: canvas.clone(),
        pose: Cell::new(START),
        q1_out: find("[data-testid=\"home-arm-q1\"]")?,
        q2_out: find("[data-testid=\"home-arm-q2\"]")?,
        open: find("[data-testid=\"home-arm-open\"]")?,
        drag: RefCell::new(None),
        frame: RefCell::new(None),
        scope: RefCell::new(Scope::new()),
    });
    let weak = Rc::downgrade(&arm);
    {
        let mut scope = arm.scope.borrow_mut();
        *arm.frame.borrow_mut() = Some(scope.frame_loop(&weak, |a, _| a.draw()));
        scope.observe_resize(&[&stage], &weak, |a| a.relayout())?;
    }
    let (w_hit, w_on) = (weak.clone(), weak.clone());
    let drag = Drag::attach(
        &stage,
        &canvas,
        move |at, kind| w_hit.upgrade()?.grab_at(at, kind),
        move |ev| {
            if let Some(a) = w_on.upgrade() {
                a.on_drag(ev);
            }
        },
    )?;
    *arm.drag.borrow_mut() = Some(drag);
    arm.show_values();
    arm.relayout();
    Ok(arm)
}

impl HomeArm {
    /// Redraws in the next frame (projector mode changed).
    pub(crate) fn request(&self) {
        if let Some(frame) = self.frame.borrow().as_ref() {
            frame.request();
        }
    }

    fn xf(&self) -> ViewXf {
        let (w, h) = self.canvas.borrow().size();
        ViewXf::fit(w, h, extent_m(&Arm::DEFAULT, None))
    }

    /// An arrow key with the arm focused moves the tip 5 mm (Shift: 1 mm); whether it did.
    pub(crate) fn on_key(&self, event: &KeyboardEvent) -> bool {
        let focused = dom::document()
            .ok()
            .and_then(|d| d.active_element())
            .is_some_and(|active| active == self.canvas_el);
        if !focused {
            return false;
        }
        let step = if event.shift_key() {
            NUDGE_FINE_M
        } else {
            NUDGE_M
        };
        let direction = match event.key().as_str() {
            "ArrowLeft" => DVec2::new(-1.0, 0.0),
            "ArrowRight" => DVec2::new(1.0, 0.0),
            "ArrowUp" => DVec2::new(0.0, 1.0),
            "ArrowDown" => DVec2::new(0.0, -1.0),
            _ => return false,
        };
        let (q1, q2) = self.pose.get();
        let (x, y) = ARM.fk(q1, q2);
        self.move_tip(DVec2::new(x, y) + direction * step);
        true
    }

    /// A finger takes only the arm itself; a mouse or pen press anywhere takes the tip.
    fn grab_at(&self, at: DVec2, kind: PointerKind) -> Option<Grab> {
        let (q1, q2) = self.pose.get();
        let xf = self.xf();
        if kind == PointerKind::Touch {
            part_at(&xf, &ARM, q1, q2, at, true)
        } else {
            Some(hit_test(&xf, &ARM, q1, q2, at, false))
        }
    }

    fn on_drag(&self, ev: DragEvent<Grab>) {
        match ev {
            DragEvent::Start { handle, at, .. } => {
                focus_without_scroll(&self.canvas_el);
                self.move_part(handle, at)
            }
            DragEvent::Move { handle, at } => self.move_part(handle, at),
            DragEvent::Tap { at } => self.move_part(Grab::Tip, at),
            DragEvent::Hover(at) => {
                let (q1, q2) = self.pose.get();
                let over = part_at(&self.xf(), &ARM, q1, q2, at, false).is_some();
                if let Some(d) = self.drag.borrow().as_ref() {
                    d.set_hover_cursor(if over { "grab" } else { "" });
                }
            }
            DragEvent::Leave | DragEvent::End { .. } => {}
        }
    }

    /// The pointer at `at` holds `part`: the tip by IK (pinned to the reach), a link by its
    /// joint angle.
    fn move_part(&self, part: Grab, at: DVec2) {
        let (q1, q2) = self.pose.get();
        let p = self.xf().world(at);
        let next = match part {
            Grab::Tip => return self.move_tip(p),
            Grab::Q1 => (p.y.atan2(p.x), q2),
            Grab::Q2 => {
                let (ex, ey) = ARM.elbow(q1);
                (q1, wrap_angle((p.y - ey).atan2(p.x - ex) - q1))
            }
        };
        self.set_pose(next);
    }

    /// The tip to world point `p` (m) by IK on the current branch, pinned to the reach.
    fn move_tip(&self, p: DVec2) {
        let (q1, q2) = self.pose.get();
        let (x, y, _) = ARM.clamp_to_reach(p.x, p.y);
        self.set_pose(ARM.ik(x, y, elbow_of(q2)).unwrap_or((q1, q2)));
    }

    fn set_pose(&self, next: (f64, f64)) {
        if next.0.is_finite() && next.1.is_finite() && next != self.pose.get() {
            self.pose.set(next);
            self.show_values();
            self.request();
        }
    }

    /// The angles in degrees and the link that opens this pose on the IK page.
    fn show_values(&self) {
        let (q1, q2) = self.pose.get();
        for (out, q) in [(&self.q1_out, q1), (&self.q2_out, q2)] {
            out.set_text_content(Some(&format!("{}°", fmt_fixed(q.to_degrees(), 1))));
            let _ = out.set_attribute("data-value", &num(q));
        }
        let elbow = if elbow_of(q2) == Elbow::Down {
            "down"
        } else {
            "up"
        };
        let href = router::build_hash(
            "ik-2r",
            &[
                ("q1".to_string(), fmt_fixed(q1, 6)),
                ("q2".to_string(), fmt_fixed(q2, 6)),
                ("elbow".to_string(), elbow.to_string()),
            ],
        );
        let _ = self.open.set_attribute("href", &href);
    }

    fn relayout(&self) {
        if let Ok(mut canvas) = self.canvas.try_borrow_mut() {
            canvas.fit();
        }
        if let Some(d) = self.drag.borrow().as_ref() {
            d.relayout();
        }
        // Resizing a canvas clears it: draw at once, not a frame later.
        self.draw();
    }

    fn draw(&self) {
        let Ok(canvas) = self.canvas.try_borrow() else {
            return;
        };
        let layer = canvas.top();
        layer.begin();
        let c = &layer.ctx;
        let ink = Ink::current();
        let (q1, q2) = self.pose.get();
        let xf = self.xf();
        let (w, h) = canvas.size();
        let o = xf.origin();
        let (inner, outer) = Arm::DEFAULT.reach();
        c.set_fill_style_str(colour::BG);
        c.fill_rect(0.0, 0.0, w, h);
        // The reachable annulus, then the axes through the base.
        disc(c, o, outer * xf.px_per_m, colour::ANNULUS);
        disc(c, o, inner * xf.px_per_m, colour::BG);
        for r in [inner, outer] {
            ring(c, o, r * xf.px_per_m, colour::ANNULUS_EDGE, ink.line);
        }
        c.set_stroke_style_str(colour::GRID);
        c.set_line_width(ink.line);
        c.begin_path();
        c.move_to(0.0, o.y);
        c.line_to(w, o.y);
        c.move_to(o.x, 0.0);
        c.line_to(o.x, h);
        c.stroke();
        // Links, joints and the tip.
        let [base, elbow, tip] = joints_on_screen(&xf, &ARM, q1, q2);
        c.set_line_cap("round");
        for (a, b, colour) in [(base, elbow, colour::LINK1), (elbow, tip, colour::LINK2)] {
            c.set_stroke_style_str(colour);
            c.set_line_width(7.0 * ink.line);
            c.begin_path();
            c.move_to(a.x, a.y);
            c.line_to(b.x, b.y);
            c.stroke();
        }
        for p in [base, elbow] {
            disc(c, p, 6.0 * ink.line, colour::JOINT_FILL);
            ring(c, p, 6.0 * ink.line, colour::JOINT_EDGE, 2.0 * ink.line);
        }
        disc(c, tip, 10.0 * ink.line, colour::TIP);
        ring(c, tip, 10.0 * ink.line, colour::JOINT_FILL, 2.0 * ink.line);
        ring(c, tip, 15.0 * ink.line, colour::TIP, ink.line);
        // Where the tip is, in CSS px of the canvas (for tests, as on the IK page).
        let top = &layer.canvas;
        let _ = top.set_attribute("data-tip-x", &format!("{:.2}", tip.x));
        let _ = top.set_attribute("data-tip-y", &format!("{:.2}", tip.y));
        drop(canvas);
        // The touch handles: the tip, the elbow and both links.
        if let Some(d) = self.drag.borrow().as_ref() {
            let shapes: Vec<_> = handles(&xf, &ARM, q1, q2, true)
                .into_iter()
                .map(|(_, shape)| shape)
                .collect();
            d.set_handles(&shapes);
        }
    }
}
