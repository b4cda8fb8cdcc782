//! The live simulation and the episode being driven: the kernel's [`Sim`] at a fixed
//! 100 Hz, each displayed frame taking the whole 10 ms steps its interval owes
//! ([`Accumulator`]; an input between two steps gets one at once). An episode starts at the
//! pilot's first input after a reset (an idle arm is not timed) and ends at success, at the
//! time box, or when the page ends it; a valid settings edit applies at once between
//! episodes, else at the next reset.

use wasm_bindgen::JsValue;

use crate::teleop::session::InputDevice;
use crate::teleop::{Command, Episode, Event, Sim, StepRecord};
use crate::view::teleop::Settings;
use crate::view::teleop_input::{Accumulator, FrameDemand};

use super::devices::Devices;
use super::scene_view::SceneView;

/// How long a joint-limit or singularity notice stays after its last event, ms.
const STOP_NOTICE_MS: f64 = 600.0;
/// The tip has moved (preflight) once this far from its start, m.
const MOVED_M: f64 = 0.002;

/// The live simulation.
pub struct Live {
    pub sim: Sim,
    pub settings: Settings,
    /// A valid settings edit waiting for the next reset.
    pending: Option<Settings>,
    pub commands: Vec<Command>,
    records: Vec<StepRecord>,
    /// The first input after the reset arrived (the episode's clock runs).
    pub started: bool,
    /// The episode ended (success, timeout, End episode); no more steps until a reset.
    pub ended: bool,
    pub engaged: bool,
    acc: Accumulator,
    last_frame_ms: Option<f64>,
    /// Until when the stop notice shows, and its text id and argument.
    pub stop: Option<(f64, &'static str, String)>,
}

/// What one frame's steps did.
#[derive(Debug, Default, Clone, Copy)]
pub struct Stepped {
    /// The episode reached success or the time box.
    pub ended: bool,
    /// The device in use moved the tip away from its start (the preflight check).
    pub moved_by_device: bool,
}

/// What became of a valid settings edit.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SettingsEdit {
    /// In force at once: a new simulation, the episode cleared.
    Applied,
    /// Waiting for the next reset (an episode is under way).
    Pending,
    /// Nothing changed (the same settings, or a configuration the kernel refused).
    Unchanged,
}

impl Live {
    pub fn new(settings: Settings) -> Result<Live, JsValue> {
        let sim =
            Sim::new(settings.config.clone()).map_err(|e| JsValue::from_str(&e.to_string()))?;
        Ok(Live {
            sim,
            settings,
            pending: None,
            commands: Vec::new(),
            records: Vec::new(),
            started: false,
            ended: false,
            engaged: true,
            acc: Accumulator::default(),
            last_frame_ms: None,
            stop: None,
        })
    }

    /// The episode so far.
    pub fn episode(&self) -> Episode {
        Episode {
            config: self.sim.config().clone(),
            start: self.sim.start_state().clone(),
            commands: self.commands.clone(),
            records: self.records.clone(),
        }
    }

    /// The episode so far without its records (what is stored: the records are simulated
    /// again on load).
    pub fn commands_only(&self) -> Episode {
        Episode {
            config: self.sim.config().clone(),
            start: self.sim.start_state().clone(),
            commands: self.commands.clone(),
            records: Vec::new(),
        }
    }

    /// The tip's position (x, z), m.
    pub fn tip(&self) -> (f64, f64) {
        let p = crate::teleop::fk(&self.sim.config().arm, &self.sim.state().q);
        (p.x, p.z)
    }

    /// An episode with steps is running (not yet ended).
    pub fn under_way(&self) -> bool {
        self.started && !self.ended && !self.commands.is_empty()
    }

    /// Engage or pause (the next frame counts no time from the last one).
    pub fn toggle_engaged(&mut self) {
        self.engaged = !self.engaged;
        self.acc.clear();
        self.last_frame_ms = None;
    }

    /// Forgets the last frame's time (frames stopped: the next counts no time from it).
    pub fn idle(&mut self) {
        self.last_frame_ms = None;
    }

    /// The frame at `t_ms`: steps the simulation with the devices' input (`device`: the one
    /// the session uses), the tip's positions added to `view`'s trail.
    pub fn advance(
        &mut self,
        t_ms: f64,
        devices: &mut Devices,
        device: InputDevice,
        view: &mut SceneView,
    ) -> Stepped {
        let mut stepped = Stepped::default();
        let elapsed = self.last_frame_ms.map_or(0.0, |last| t_ms - last);
        self.last_frame_ms = Some(t_ms);
        let fresh = std::mem::take(&mut devices.fresh);
        if !self.engaged || self.ended {
            return stepped;
        }
        let gripper = devices.gripper_closed;
        let axes = devices.axes(self.tip());
        let any = axes.iter().any(|v| *v != 0.0) || gripper != self.sim.state().gripper_closed;
        if !self.started && any {
            self.started = true;
            self.acc.clear();
        }
        if !self.started {
            self.acc.clear();
            return stepped;
        }
        let n = self.acc.steps(elapsed, fresh);
        for _ in 0..n {
            let axes = devices.axes(self.tip());
            let cmd = Command {
                dx: axes[0],
                dz: axes[1],
                dphi: axes[2],
                gripper_closed: gripper,
            };
            let rec = self.sim.step(&cmd);
            self.note_stops(&rec.events, t_ms);
            view.push_trail(rec.x, rec.z);
            self.commands.push(cmd);
            self.records.push(rec);
            if self.sim.done().is_some() {
                stepped.ended = true;
                break;
            }
        }
        let used = match device {
            InputDevice::Keyboard => devices.keys.any(),
            InputDevice::Gamepad => devices.pad_out.active,
            InputDevice::Pointer => devices.clutch.is_some(),
        };
        if used {
            let start = crate::teleop::fk(&self.sim.config().arm, &self.sim.start_state().q);
            let tip = self.tip();
            stepped.moved_by_device = (tip.0 - start.x).hypot(tip.1 - start.z) > MOVED_M;
        }
        stepped
    }

    /// A joint limit or a singularity among `events` shows its notice for a while.
    fn note_stops(&mut self, events: &[Event], t_ms: f64) {
        for ev in events {
            match ev {
                Event::JointLimit { joint } => {
                    self.stop = Some((
                        t_ms + STOP_NOTICE_MS,
                        "teleop-stop-limit",
                        joint.to_string(),
                    ))
                }
                Event::Singularity => {
                    self.stop = Some((t_ms + STOP_NOTICE_MS, "teleop-stop-singular", String::new()))
                }
                _ => {}
            }
        }
    }

    /// What keeps frames coming after this one.
    pub fn frame_demand(&self, d: &Devices) -> FrameDemand {
        FrameDemand {
            keys_held: d.keys.any(),
            pad_connected: d.pad_name.is_some(),
            clutch_held: d.clutch.is_some(),
            episode_running: self.engaged && self.started && !self.ended,
            fresh_input: d.fresh,
            notice_until_ms: self.stop.as_ref().map(|(until, _, _)| *until),
        }
    }

    /// The scene back to its start (a new configuration if one is waiting), the episode
    /// cleared; `true` when the state is bit for bit a fresh simulation's start state.
    pub fn reset(&mut self) -> bool {
        if let Some(s) = self.pending.take() {
            match Sim::new(s.config.clone()) {
                Ok(sim) => {
                    self.sim = sim;
                    self.settings = s;
                }
                Err(e) => web_sys::console::warn_1(&JsValue::from_str(&e.to_string())),
            }
        } else {
            self.sim.reset();
        }
        self.commands.clear();
        self.records.clear();
        self.started = false;
        self.ended = false;
        self.acc.clear();
        self.stop = None;
        Sim::new(self.sim.config().clone())
            .map(|fresh| fresh.start_state() == self.sim.state())
            .unwrap_or(false)
    }

    /// Takes a valid settings edit: at once between episodes, else at the next reset.
    pub fn edit(&mut self, settings: Settings) -> SettingsEdit {
        let apply_now = !self.started || self.ended;
        if self.settings == settings {
            self.pending = None;
            return SettingsEdit::Unchanged;
        }
        if !apply_now {
            self.pending = Some(settings);
            return SettingsEdit::Pending;
        }
        let Ok(sim) = Sim::new(settings.config.clone()) else {
            return SettingsEdit::Unchanged;
        };
        self.sim = sim;
        self.settings = settings;
        self.pending = None;
        self.commands.clear();
        self.records.clear();
        self.started = false;
        self.ended = false;
        SettingsEdit::Applied
    }
}
