//! Failure review: one recorded episode replayed under the kit's stepper (play, pause, step,
//! scrub), the scene simulated again from the episode's start state and commands (exactly the
//! recorded states: the kernel is deterministic), and a timeline under the stepper with every
//! event as a mark and the first failure marked (`data-first-failure`, the step from 1). The
//! marks differ in shape as well as colour (Okabe–Ito): failures crosses, successes rings,
//! warnings squares, the first failure a triangle; the legend under the timeline says so.
//! [`Review`] is the component (`data-tele="review"`): the stepper, the timeline, the title
//! and the events line.

use std::cell::RefCell;
use std::rc::Rc;

use wasm_bindgen::JsValue;
use web_sys::{Element, HtmlCanvasElement, KeyboardEvent};

use crate::teleop::session::EpisodeEntry;
use crate::teleop::{Episode, Event, SceneGeometry, Sim};
use crate::ui::kit::canvas::{Ink, Layer};
use crate::ui::kit::stepper::{Length, Speed, StepModel, StepperOptions, StepperWidget};
use crate::ui::{ctx, dom};
use crate::view::palette;

use super::markup::{find, role};
use super::readouts::Readouts;
use super::scene_view::SceneView;

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

/// The failure review.
pub struct Review {
    pub root: Element,
    title: Element,
    event: Element,
    stepper_slot: Element,
    timeline: RefCell<Timeline>,
    replay: RefCell<Option<Rc<RefCell<Replay>>>>,
    stepper: RefCell<Option<StepperWidget<Replay>>>,
}

impl Review {
    /// Finds the review under `root`.
    pub fn find(root: &Element) -> Result<Review, JsValue> {
        let timeline = Timeline::new(find(root, "[data-testid=\"teleop-timeline\"]")?)?;
        Ok(Review {
            timeline: RefCell::new(timeline),
            root: role(root, "review")?,
            title: role(root, "review-title")?,
            event: role(root, "review-event")?,
            stepper_slot: role(root, "stepper")?,
            replay: RefCell::new(None),
            stepper: RefCell::new(None),
        })
    }

    /// Shows or hides the review.
    pub fn show(&self, on: bool) {
        dom::show(&self.root, on);
    }

    /// Replays `entry` (episode `n`) under a new stepper; `on_step` runs on every step shown
    /// (it draws the review).
    pub fn start(&self, n: usize, entry: &EpisodeEntry, on_step: impl Fn() + 'static) {
        self.stop();
        let first = entry
            .metrics
            .first_failure
            .as_ref()
            .map(|(step, ev)| (*step, *ev));
        let model = Rc::new(RefCell::new(Replay::new(n, entry.episode.clone(), first)));
        *self.replay.borrow_mut() = Some(model.clone());
        let widget = StepperWidget::new(
            &self.stepper_slot,
            model,
            StepperOptions {
                speeds: vec![
                    Speed::PerSecond(25.0),
                    Speed::PerSecond(100.0),
                    Speed::PerSecond(400.0),
                ],
                initial_speed: 1,
                testid: "teleop-stepper",
                ..StepperOptions::default()
            },
            move |_| on_step(),
        );
        match widget {
            Ok(w) => *self.stepper.borrow_mut() = Some(w),
            Err(e) => web_sys::console::warn_1(&e),
        }
        self.render_title(n);
        self.timeline.borrow_mut().fit();
    }

    /// Drops the replay and its stepper.
    pub fn stop(&self) {
        self.stepper.borrow_mut().take();
        self.replay.borrow_mut().take();
        dom::clear(&self.stepper_slot);
    }

    /// A key for the stepper; `true` if taken.
    pub fn on_key(&self, event: &KeyboardEvent) -> bool {
        self.stepper
            .borrow()
            .as_ref()
            .is_some_and(|s| s.on_key(event))
    }

    /// Sizes the timeline to its box.
    pub fn fit(&self) {
        self.timeline.borrow_mut().fit();
    }

    fn render_title(&self, n: usize) {
        self.title.set_text_content(Some(&ctx::t_strings(
            "teleop-review-title",
            &[("n", n.to_string())],
        )));
    }

    /// Draws the replayed step: the scene and its trail in `view`, the timeline, the step's
    /// numbers in `readouts`, the first failure and the step's events.
    pub fn draw(&self, view: &mut SceneView, readouts: &Readouts) {
        let Some(model) = self.replay.borrow().clone() else {
            return;
        };
        let Ok(replay) = model.try_borrow() else {
            return;
        };
        let ink = Ink::current();
        if let Some(g) = replay.geometry() {
            view.trail = replay.trail();
            view.draw(&g, None, ink);
        }
        self.timeline.borrow().draw(&replay, ink);
        let i = replay.index() as usize;
        if let Some(r) = i.checked_sub(1).and_then(|k| replay.episode.records.get(k)) {
            readouts.show_record(r);
        }
        let events: Vec<String> = replay
            .events_now()
            .iter()
            .map(|e| ctx::t(&format!("teleop-ev-{}", e.id())))
            .collect();
        let first = replay
            .first_failure
            .map(|(step, ev)| {
                ctx::t_strings(
                    "teleop-first-failure",
                    &[
                        ("event", ctx::t(&format!("teleop-ev-{}", ev.id()))),
                        ("step", step.to_string()),
                    ],
                )
            })
            .unwrap_or_else(|| ctx::t("teleop-no-failure"));
        let text = if events.is_empty() {
            first
        } else {
            format!("{first} · {}", events.join(", "))
        };
        self.event.set_text_content(Some(&text));
    }

    /// The stepper and the title in the current language.
    pub fn relocalize(&self) {
        if let Some(s) = self.stepper.borrow().as_ref() {
            s.relocalize();
        }
        if let Some(model) = self.replay.borrow().as_ref() {
            let n = model.borrow().number;
            self.render_title(n);
        }
    }
}
