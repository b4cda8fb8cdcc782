//! What a frame draws: the arm view's background (grid, annulus, workspace overlay), the
//! heatmap's background (painted grid, axes, legend), the jacobian-2r plot's axes and series,
//! and the drag frame itself (pose report, readouts, arm layer, heatmap marker).

use super::canvas::projector_scale;
use super::plots::{self, PlotSpec, SweepPoint};
use super::state::{self, Params};
use super::{heatmap, view, DragTarget, Page};
use crate::planar2r::wrap_angle;
use crate::ui::ctx;

impl Page {
    pub(super) fn draw_arm_background(&self) {
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

    pub(super) fn draw_heat_background(&self) {
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

    pub(super) fn draw_plot_background(&self) {
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

    pub(super) fn draw_plot_series(&self) {
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
    pub(super) fn draw_frame(&self) {
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
}
