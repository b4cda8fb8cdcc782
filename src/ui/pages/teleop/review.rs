//! Failure review: one recorded episode replayed under the kit's stepper (play, pause, step,
//! scrub), the scene simulated again from the episode's start state and commands (exactly the
//! recorded states: the kernel is deterministic), and a timeline under the stepper with every
//! event as a mark and the first failure marked (`data-first-failure`, the step from 1). The
//! marks differ in shape as well as colour (Okabe–Ito): failures crosses, successes rings,
//! warnings squares, the first failure a triangle; the legend under the timeline says so.

use std::rc::Rc;

use wasm_bindgen::JsValue;
use web_sys::HtmlCanvasElement;

use crate::teleop::{Episode, Event, SceneGeometry, Sim};
use crate::ui::kit::canvas::{Ink, Layer};
use crate::ui::kit::stepper::{Length, StepModel};
use crate::view::palette;

/// Releases on the timeline (neutral: neither a failure nor a success).
const GREY: &str = "#4a5360";

/// The stepper's model: an episode and the replaying simulation.
pub struct Replay {
    pub number: usize,
    /// Shared with the session (no copy of its steps).
    pub episode: Rc<Episode>,
    sim: Option<Sim>,
    /// Steps taken by `sim`.
    at: u64,
    /// The first failure event's step (from 1) and the event.
    pub first_failure: Option<(u64, Event)>,
}

impl Replay {
    /// Replays episode `number`.
    pub fn new(number: usize, episode: Rc<Episode>, first_failure: Option<(u64, Event)>) -> Replay {
        let sim = Sim::new(episode.config.clone()).ok();
        Replay {
            number,
            episode,
            sim,
            at: 0,
            first_failure,
        }
    }

    /// Steps taken.
    pub fn index(&self) -> u64 {
        self.at
    }

    /// The scene now.
    pub fn geometry(&self) -> Option<SceneGeometry> {
        self.sim.as_ref().map(Sim::geometry)
    }

    /// The tip positions of steps 1 to `at`.
    pub fn trail(&self) -> Vec<(f64, f64)> {
        self.episode
            .records
            .iter()
            .take(self.at as usize)
            .map(|r| (r.x, r.z))
            .collect()
    }

    /// The events of the last step shown.
    pub fn events_now(&self) -> &[Event] {
        self.at
            .checked_sub(1)
            .and_then(|i| self.episode.records.get(i as usize))
            .map_or(&[], |r| r.events.as_slice())
    }
}

impl StepModel for Replay {
    fn length(&self) -> Length {
        Length::Finite(self.episode.commands.len() as u64)
    }

    fn go_to(&mut self, index: u64) {
        let Some(sim) = self.sim.as_mut() else {
            return;
        };
        let index = index.min(self.episode.commands.len() as u64);
        if index < self.at {
            sim.reset();
            self.at = 0;
        }
        while self.at < index {
            let Some(cmd) = self.episode.commands.get(self.at as usize) else {
                break;
            };
            sim.step(cmd);
            self.at += 1;
        }
    }
}

/// The timeline under the stepper.
pub struct Timeline {
    pub layer: Layer,
}

impl Timeline {
    /// Wraps the timeline canvas.
    pub fn new(canvas: HtmlCanvasElement) -> Result<Timeline, JsValue> {
        Ok(Timeline {
            layer: Layer::new(canvas)?,
        })
    }

    /// Sizes the canvas to its box.
    pub fn fit(&mut self) {
        let dpr = web_sys::window().map_or(1.0, |w| w.device_pixel_ratio());
        let r = self.layer.canvas.get_bounding_client_rect();
        self.layer
            .resize(r.width().max(1.0), r.height().max(1.0), dpr);
    }

    /// Draws the events of `replay` and its position; writes `data-first-failure`.
    pub fn draw(&self, replay: &Replay, ink: Ink) {
        let l = &self.layer;
        l.begin();
        let c = &l.ctx;
        let (w, h) = (l.css_w, l.css_h);
        let n = replay.episode.commands.len().max(1) as f64;
        let x_of = |step: f64| 6.0 + (w - 12.0) * step / n;
        c.set_fill_style_str("#e3e8ef");
        c.fill_rect(6.0, h / 2.0 - 3.0, w - 12.0, 6.0);
        // Each kind of event its own colour (Okabe–Ito) and its own shape, so that colour is
        // never the only cue: failures vermilion crosses, successes bluish-green rings,
        // warnings (limits, singularity) reddish-purple squares, releases grey ticks. One
        // path per kind; a mark on the pixel column of the last one of its kind is skipped.
        let y = h / 2.0;
        let r = (h / 2.0 - 4.0).clamp(3.0, 4.0 * ink.line.max(1.0));
        let mut last = [f64::NAN; 4];
        let mut marks: [Vec<f64>; 4] = Default::default();
        for (i, rec) in replay.episode.records.iter().enumerate() {
            for e in &rec.events {
                let kind = match e {
                    Event::Collision { .. } | Event::Drop | Event::GraspMiss | Event::Timeout => 0,
                    Event::Success | Event::TargetReached { .. } | Event::Grasp => 1,
                    Event::JointLimit { .. } | Event::Singularity | Event::SpeedLimit { .. } => 2,
                    Event::Release => 3,
                };
                let x = x_of(i as f64 + 1.0).round();
                if last[kind] != x {
                    last[kind] = x;
                    marks[kind].push(x);
                }
            }
        }
        c.set_line_width(1.5 * ink.line.max(1.0));
        // Releases: grey ticks.
        c.set_stroke_style_str(GREY);
        c.begin_path();
        for x in &marks[3] {
            c.move_to(*x, y - r);
            c.line_to(*x, y + r);
        }
        c.stroke();
        // Warnings: reddish-purple squares.
        c.set_fill_style_str(palette::REDDISH_PURPLE.hex);
        c.begin_path();
        for x in &marks[2] {
            c.rect(x - r * 0.7, y - r * 0.7, r * 1.4, r * 1.4);
        }
        c.fill();
        // Successes: bluish-green rings.
        c.set_stroke_style_str(palette::BLUISH_GREEN.hex);
        c.begin_path();
        for x in &marks[1] {
            c.move_to(x + r, y);
            let _ = c.arc(*x, y, r, 0.0, std::f64::consts::TAU);
        }
        c.stroke();
        // Failures: vermilion crosses.
        c.set_stroke_style_str(palette::VERMILION.hex);
        c.set_line_width(2.0 * ink.line.max(1.0));
        c.begin_path();
        for x in &marks[0] {
            c.move_to(x - r, y - r);
            c.line_to(x + r, y + r);
            c.move_to(x - r, y + r);
            c.line_to(x + r, y - r);
        }
        c.stroke();
        if let Some((step, _)) = replay.first_failure {
            let x = x_of(step as f64);
            // The first failure: a vermilion triangle pointing down at it.
            c.set_fill_style_str(palette::VERMILION.hex);
            c.begin_path();
            c.move_to(x, h / 2.0 - r - 1.0);
            c.line_to(x - 6.0, 0.0);
            c.line_to(x + 6.0, 0.0);
            c.close_path();
            c.fill();
            let _ = l
                .canvas
                .set_attribute("data-first-failure", &step.to_string());
        } else {
            let _ = l.canvas.remove_attribute("data-first-failure");
        }
        let x = x_of(replay.index() as f64);
        c.set_fill_style_str(palette::BLUE.hex);
        c.fill_rect(x - 1.5, 0.0, 3.0, h);
    }
}
