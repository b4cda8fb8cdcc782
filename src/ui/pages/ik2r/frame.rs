//! Frame scheduling: what needs redrawing is collected as [`dirty`] bits and drawn once per
//! animation frame, backgrounds first; a resize (or the projector switch) lays every layer out
//! again from its stage and recomputes the view transforms.

use wasm_bindgen::JsCast;
use web_sys::Element;

use super::canvas::projector_scale;
use super::heatmap::HeatLayout;
use super::view::{self, ViewXf};
use super::Page;
use crate::ui::ctx;
use crate::ui::schedule::now_ms;

/// What needs redrawing on the next animation frame.
pub(super) mod dirty {
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

impl Page {
    /// Marks parts dirty and asks for one animation frame.
    pub(super) fn invalidate(&self, bits: u32) {
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
    pub(super) fn frame(&self) {
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
}
