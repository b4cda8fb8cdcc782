//! Changing the pose and the view: setting (q1, q2), moving the tip by IK (pinned to the reach),
//! flipping the elbow with the tip kept in place, showing the workspace grid, the out-of-reach
//! note, and writing the state into the URL (at once, or debounced while editing).

use super::frame::dirty;
use super::state::elbow_of;
use super::Page;
use crate::planar2r::Elbow;
use crate::ui::dom::show;

impl Page {
    /// Writes the state into the URL now.
    pub(super) fn write_url(&self) {
        self.url_timer.cancel();
        let query = self.state.borrow().query_pairs();
        crate::ui::router::replace_query(&query);
    }

    pub(super) fn schedule_url(&self) {
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
    pub(super) fn set_pose(&self, q1: f64, q2: f64) {
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
    pub(super) fn move_tip(&self, x: f64, y: f64) -> bool {
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
    pub(super) fn set_elbow(&self, elbow: Elbow) {
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

    pub(super) fn set_workspace_visible(&self, on: bool) {
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
    pub(super) fn set_clamp_note(&self, visible: bool) {
        let mut ui = self.ui.borrow_mut();
        if ui.clamp_shown != visible {
            ui.clamp_shown = visible;
            show(&self.els.clamp_note, visible);
        }
    }
}
