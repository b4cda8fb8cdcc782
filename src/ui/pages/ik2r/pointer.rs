//! Pointer input (mouse, pen and touch alike, through Pointer Events with
//! `setPointerCapture`, `pointercancel` and `touch-action: none`):
//!
//! - arm view: grabbing the tip (or empty space) drags the tip by IK on the current branch,
//!   pinned to the reach when the pointer leaves the annulus; grabbing the elbow or link 1
//!   turns q1 (`q1 = atan2(y, x)` of the pointer), link 2 turns q2 (`q2 = atan2(p − elbow) − q1`);
//! - heatmap: hovering a cell previews its pose (ghost arm), pressing or dragging sets it.

use std::rc::Weak;

use glam::DVec2;
use wasm_bindgen::{JsCast, JsValue};
use web_sys::{Element, Event, HtmlCanvasElement, PointerEvent};

use super::frame::dirty;
use super::view::{self, Grab};
use super::{heatmap, Drag, DragTarget, Page};
use crate::planar2r::wrap_angle;
use crate::ui::dom::Listener;

/// The pointer's position in the canvas, CSS px (fractional where the browser gives it).
fn local(canvas: &HtmlCanvasElement, e: &PointerEvent) -> DVec2 {
    let r = canvas.get_bounding_client_rect();
    let coord = |name: &str, fallback: i32| {
        js_sys::Reflect::get(e, &JsValue::from_str(name))
            .ok()
            .and_then(|v| v.as_f64())
            .unwrap_or(f64::from(fallback))
    };
    DVec2::new(
        coord("clientX", e.client_x()) - r.left(),
        coord("clientY", e.client_y()) - r.top(),
    )
}

fn set_class(element: &Element, class: &str, on: bool) {
    let _ = element.class_list().toggle_with_force(class, on);
}

/// Attaches the pointer listeners of the arm view and the heatmap.
pub(super) fn install(
    page: &Page,
    weak: &Weak<Page>,
    out: &mut Vec<Listener>,
) -> Result<(), JsValue> {
    let arm: Element = page.els.arm_canvas.clone().into();
    let heat: Element = page.els.heat_canvas.clone().into();
    type Handler = fn(&Page, &PointerEvent);
    let arm_events: [(&'static str, Handler); 6] = [
        ("pointerdown", arm_down),
        ("pointermove", arm_move),
        ("pointerup", arm_end),
        ("pointercancel", arm_end),
        ("lostpointercapture", arm_end),
        ("pointerleave", arm_leave),
    ];
    let heat_events: [(&'static str, Handler); 6] = [
        ("pointerdown", heat_down),
        ("pointermove", heat_move),
        ("pointerup", heat_end),
        ("pointercancel", heat_end),
        ("lostpointercapture", heat_end),
        ("pointerleave", heat_leave),
    ];
    for (target, events) in [(&arm, arm_events), (&heat, heat_events)] {
        for (name, handler) in events {
            let w = weak.clone();
            out.push(Listener::new(target, name, move |e: Event| {
                if let (Some(page), Some(pe)) = (w.upgrade(), e.dyn_ref::<PointerEvent>()) {
                    handler(&page, pe);
                }
            })?);
        }
    }
    // A long press on a phone must not open the context menu over the arm.
    for target in [&arm, &heat] {
        out.push(Listener::new(target, "contextmenu", |e: Event| {
            e.prevent_default()
        })?);
    }
    Ok(())
}

fn is_touch(e: &PointerEvent) -> bool {
    e.pointer_type() != "mouse"
}

fn arm_down(page: &Page, e: &PointerEvent) {
    if !e.is_primary() || (e.pointer_type() == "mouse" && e.button() != 0) {
        return;
    }
    e.prevent_default();
    let pos = local(&page.els.arm_canvas, e);
    let (arm, q1, q2) = {
        let st = page.state.borrow();
        (st.params.arm(), st.q1, st.q2)
    };
    let xf = page.gfx.borrow().xf;
    let grab = view::hit_test(&xf, &arm, q1, q2, pos, is_touch(e));
    let _ = page.els.arm_canvas.set_pointer_capture(e.pointer_id());
    page.ui.borrow_mut().drag = Some(Drag {
        pointer_id: e.pointer_id(),
        target: DragTarget::Arm(grab),
    });
    set_class(&page.els.arm_canvas, "ik2r-grabbing", true);
    drag_arm(page, grab, pos);
}

/// Applies a drag of `grab` to canvas point `pos`.
fn drag_arm(page: &Page, grab: Grab, pos: DVec2) {
    let xf = page.gfx.borrow().xf;
    let world = xf.world(pos);
    let (arm, q1, q2) = {
        let st = page.state.borrow();
        (st.params.arm(), st.q1, st.q2)
    };
    match grab {
        Grab::Tip => {
            let pinned = page.move_tip(world.x, world.y);
            page.ui.borrow_mut().pinned_pointer = pinned.then_some(world);
            page.set_clamp_note(pinned);
        }
        Grab::Q1 => page.set_pose(world.y.atan2(world.x), q2),
        Grab::Q2 => {
            let (ex, ey) = arm.elbow(q1);
            let q2_new = wrap_angle((world.y - ey).atan2(world.x - ex) - q1);
            page.set_pose(q1, q2_new);
        }
    }
}

fn arm_move(page: &Page, e: &PointerEvent) {
    let drag = page.ui.borrow().drag;
    let pos = local(&page.els.arm_canvas, e);
    match drag {
        Some(Drag {
            pointer_id,
            target: DragTarget::Arm(grab),
        }) if pointer_id == e.pointer_id() => {
            e.prevent_default();
            drag_arm(page, grab, pos);
        }
        None if e.pointer_type() != "touch" => {
            let (arm, q1, q2) = {
                let st = page.state.borrow();
                (st.params.arm(), st.q1, st.q2)
            };
            let xf = page.gfx.borrow().xf;
            let grab = view::hit_test(&xf, &arm, q1, q2, pos, false);
            let [_, elbow, tip] = view::joints_on_screen(&xf, &arm, q1, q2);
            // Hover highlight only when the pointer is really on a part (not empty space).
            let on_part = pos.distance(tip) <= 16.0
                || pos.distance(elbow) <= 13.0
                || view::dist_to_segment(pos, elbow, tip) <= 11.0
                || view::dist_to_segment(pos, xf.origin(), elbow) <= 11.0;
            let hover = on_part.then_some(grab);
            let changed = {
                let mut ui = page.ui.borrow_mut();
                let changed = ui.hover_grab != hover;
                ui.hover_grab = hover;
                changed
            };
            if changed {
                set_class(&page.els.arm_canvas, "ik2r-can-grab", hover.is_some());
                page.invalidate(dirty::FRAME);
            }
        }
        _ => {}
    }
}

fn arm_end(page: &Page, e: &PointerEvent) {
    let ended = {
        let mut ui = page.ui.borrow_mut();
        match ui.drag {
            Some(d) if d.pointer_id == e.pointer_id() && matches!(d.target, DragTarget::Arm(_)) => {
                ui.drag = None;
                ui.pinned_pointer = None;
                true
            }
            _ => false,
        }
    };
    if ended {
        let _ = page.els.arm_canvas.release_pointer_capture(e.pointer_id());
        set_class(&page.els.arm_canvas, "ik2r-grabbing", false);
        page.set_clamp_note(false);
        page.invalidate(dirty::FRAME);
        page.write_url();
    }
}

fn arm_leave(page: &Page, _e: &PointerEvent) {
    let changed = {
        let mut ui = page.ui.borrow_mut();
        let changed = ui.drag.is_none() && ui.hover_grab.is_some();
        if changed {
            ui.hover_grab = None;
        }
        changed
    };
    if changed {
        set_class(&page.els.arm_canvas, "ik2r-can-grab", false);
        page.invalidate(dirty::FRAME);
    }
}

/// The grid pose under canvas point `pos` of the heatmap.
fn heat_cell(page: &Page, pos: DVec2) -> Option<(f64, f64)> {
    let gfx = page.gfx.borrow();
    let n = gfx.heat_grid.n.max(2);
    gfx.heat_layout
        .cell_at(pos.x, pos.y, n)
        .map(|(i, j)| (heatmap::grid_q(i, n), heatmap::grid_q(j, n)))
}

fn heat_down(page: &Page, e: &PointerEvent) {
    if !e.is_primary() || (e.pointer_type() == "mouse" && e.button() != 0) {
        return;
    }
    let pos = local(&page.els.heat_canvas, e);
    let Some((q1, q2)) = heat_cell(page, pos) else {
        return;
    };
    e.prevent_default();
    let _ = page.els.heat_canvas.set_pointer_capture(e.pointer_id());
    {
        let mut ui = page.ui.borrow_mut();
        ui.drag = Some(Drag {
            pointer_id: e.pointer_id(),
            target: DragTarget::Heatmap,
        });
        ui.ghost = None;
    }
    page.update_hover_text();
    page.set_pose(q1, q2);
}

fn heat_move(page: &Page, e: &PointerEvent) {
    let pos = local(&page.els.heat_canvas, e);
    let drag = page.ui.borrow().drag;
    match drag {
        Some(Drag {
            pointer_id,
            target: DragTarget::Heatmap,
        }) if pointer_id == e.pointer_id() => {
            if let Some((q1, q2)) = heat_cell(page, pos) {
                page.set_pose(q1, q2);
            }
        }
        None if e.pointer_type() != "touch" => {
            let ghost = heat_cell(page, pos);
            let changed = {
                let mut ui = page.ui.borrow_mut();
                let changed = ui.ghost != ghost;
                ui.ghost = ghost;
                changed
            };
            if changed {
                page.update_hover_text();
                page.invalidate(dirty::FRAME);
            }
        }
        _ => {}
    }
}

fn heat_end(page: &Page, e: &PointerEvent) {
    let ended = {
        let mut ui = page.ui.borrow_mut();
        match ui.drag {
            Some(d) if d.pointer_id == e.pointer_id() && d.target == DragTarget::Heatmap => {
                ui.drag = None;
                true
            }
            _ => false,
        }
    };
    if ended {
        let _ = page.els.heat_canvas.release_pointer_capture(e.pointer_id());
        page.invalidate(dirty::FRAME);
        page.write_url();
    }
}

fn heat_leave(page: &Page, _e: &PointerEvent) {
    let changed = {
        let mut ui = page.ui.borrow_mut();
        let changed = ui.ghost.is_some();
        ui.ghost = None;
        changed
    };
    if changed {
        page.update_hover_text();
        page.invalidate(dirty::FRAME);
    }
}
