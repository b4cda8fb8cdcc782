//! The debounced recomputes that follow parameter edits: the heatmap of |det J| over
//! (q1, q2), and the ik-workspace grid with its overlay image (re-rendered alone when only the
//! colour mode changes).

use super::canvas::Layer;
use super::frame::dirty;
use super::{heatmap, workspace, Page};
use crate::ui::dom;
use crate::ui::schedule::now_ms;

impl Page {
    /// Recomputes and paints the heatmap for the current L1, L2 and resolution.
    pub(super) fn recompute_heatmap(&self) {
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
    pub(super) fn recompute_workspace(&self) {
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
    pub(super) fn refresh_workspace_image(&self) {
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
}
