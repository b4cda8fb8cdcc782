//! The live numbers, on the kit's readouts ([`crate::ui::kit::readouts`]): the tip (x, z,
//! φ), the joints, the manipulability and the time, of the live arm or of the replayed step;
//! the episode number, engaged or paused and the gripper (`data-readout="state"` and
//! `"gripper"` also carry `data-value`); and the stop notice of a joint limit or a
//! singularity (`data-tele="stop"`), written only when it changes.

use std::cell::RefCell;

use wasm_bindgen::JsValue;
use web_sys::Element;

use crate::teleop::session::RECORD_TARGET;
use crate::teleop::{SceneGeometry, Sim, StepRecord};
use crate::ui::ctx;
use crate::ui::kit::readouts as kit;
use crate::view::teleop::{metres, radians};

use super::markup::role;

/// The readouts.
pub struct Readouts {
    values: kit::Readouts,
    stop: Element,
    /// The stop notice shown.
    shown_stop: RefCell<String>,
}

/// The episode line: which episode of the session (in a recording module) or practice.
pub enum EpisodeLine {
    /// Recording the episode after `done` recorded ones.
    Recording {
        done: usize,
    },
    Practice,
}

impl Readouts {
    /// Finds the readouts under `root`.
    pub fn find(root: &Element) -> Result<Readouts, JsValue> {
        Ok(Readouts {
            values: kit::Readouts::find(root)?,
            stop: role(root, "stop")?,
            shown_stop: RefCell::new(String::new()),
        })
    }

    /// The pose: tip (m, rad), joints (rad), manipulability and time (s).
    fn pose(&self, tip: (f64, f64, f64), q: &[f64; 3], manipulability: f64, t_s: f64) {
        let r = &self.values;
        r.set("x", &metres(tip.0));
        r.set("z", &metres(tip.1));
        r.set("phi", &radians(tip.2));
        r.set("q1", &radians(q[0]));
        r.set("q2", &radians(q[1]));
        r.set("q3", &radians(q[2]));
        r.set("manipulability", &format!("{manipulability:.5}"));
        r.set("time", &format!("{t_s:.2}"));
    }

    /// The live arm at `t_ms` (`g`: its scene now), and its stop notice while it lasts.
    pub fn show_live(
        &self,
        sim: &Sim,
        g: &SceneGeometry,
        stop: Option<&(f64, &'static str, String)>,
        t_ms: f64,
    ) {
        let state = sim.state();
        let pose = g.tip;
        let m = crate::teleop::manipulability(&sim.config().arm, &state.q);
        self.pose((pose.x, pose.z, pose.phi), &state.q, m, state.t_s);
        let stop_text = match stop {
            Some((until, id, arg)) if *until > t_ms => {
                ctx::t_strings(id, &[("joint", arg.clone())])
            }
            _ => String::new(),
        };
        if *self.shown_stop.borrow() != stop_text {
            self.stop.set_text_content(Some(&stop_text));
            *self.shown_stop.borrow_mut() = stop_text;
        }
    }

    /// A recorded step.
    pub fn show_record(&self, r: &StepRecord) {
        self.pose((r.x, r.z, r.phi), &r.q, r.manipulability, r.t_s);
    }

    /// The episode line, engaged or paused, and the gripper.
    pub fn show_state(&self, episode: EpisodeLine, engaged: bool, gripper_closed: bool) {
        let episode = match episode {
            EpisodeLine::Recording { done } => format!("{} / {}", done + 1, RECORD_TARGET),
            EpisodeLine::Practice => ctx::t("teleop-episode-practice"),
        };
        self.values.set("episode", &episode);
        let (state_id, state_value) = if engaged {
            ("teleop-state-engaged", "engaged")
        } else {
            ("teleop-state-paused", "paused")
        };
        self.values
            .set_with_value("state", &ctx::t(state_id), state_value);
        let (gid, gv) = if gripper_closed {
            ("teleop-gripper-closed", "closed")
        } else {
            ("teleop-gripper-open", "open")
        };
        self.values.set_with_value("gripper", &ctx::t(gid), gv);
    }
}
