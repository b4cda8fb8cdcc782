//! Failure review, shared by the Robot Pilot pages: one recorded episode replayed under the
//! kit's stepper (play, pause, step, scrub) by [`crate::view::replay::Replay`] (through
//! [`ReplaySteps`], so one copy of this code serves every arm), and a
//! timeline under the stepper with every event as a mark and the first failure marked
//! (`data-first-failure`, the step from 1). The marks differ in shape as well as colour
//! (Okabe–Ito): failures crosses, successes rings, warnings squares, releases ticks, the first
//! failure a triangle; the legend under the timeline says so. [`Review`] is the component
//! (`data-<attr>="review"`: the title, the stepper, the timeline, the legend and the events
//! line, [`markup`]); the page draws its scene of the replayed state.

use std::cell::RefCell;
use std::rc::Rc;

use wasm_bindgen::JsValue;
use web_sys::{Element, HtmlCanvasElement, KeyboardEvent};

use crate::teleop::session::{EpisodeEntry, Replayable};
use crate::teleop::sim::Event;
use crate::ui::kit::canvas::{Ink, Layer};
use crate::ui::kit::stepper::{Speed, StepperOptions, StepperWidget};
use crate::ui::{ctx, dom};
use crate::view::palette;
use crate::view::replay::{AnyReplay, Replay, ReplaySteps};

/// Releases on the timeline (neutral: neither a failure nor a success).
const GREY: &str = "#4a5360";

/// Where a page's review lives: its `data-<attr>` roles and the test ids of its stepper and
/// timeline.
#[derive(Debug, Clone, Copy)]
pub struct ReviewIds {
    /// `tele` finds `[data-tele="review"]`, `[data-tele="stepper"]`, ...
    pub attr: &'static str,
    /// `data-testid` of the stepper.
    pub stepper: &'static str,
    /// `data-testid` of the timeline canvas.
    pub timeline: &'static str,
}

/// The review's markup (hidden until shown).
#[inline(never)]
pub fn markup(ids: ReviewIds) -> String {
    let a = ids.attr;
    let key = |class: &str, mark: &str, id: &str| {
        format!(
            "<li><span class=\"kit-key kit-key-{class}\" aria-hidden=\"true\">{mark}</span>\
             <span data-i18n=\"teleop-legend-{id}\"></span></li>"
        )
    };
    format!(
        "<div class=\"kit-review\" data-{a}=\"review\" hidden>\
         <p class=\"kit-review-title\" data-{a}=\"review-title\"></p>\
         <div data-{a}=\"stepper\"></div>\
         <canvas class=\"kit-timeline\" data-testid=\"{timeline}\" role=\"img\" \
         data-i18n-attr=\"aria-label=teleop-timeline-label\"></canvas>\
         <ul class=\"kit-legend\" data-{a}=\"timeline-legend\">{fail}{success}{warn}{release}{first}{now}</ul>\
         <p class=\"kit-review-event\" data-{a}=\"review-event\"></p></div>",
        timeline = ids.timeline,
        fail = key("fail", "✕", "failure"),
        success = key("success", "○", "success"),
        warn = key("warn", "■", "warning"),
        release = key("release", "|", "release"),
        first = key("fail", "▼", "first-failure"),
        now = key("now", "┃", "now"),
    )
}

/// The timeline under the stepper.
struct Timeline {
    layer: Layer,
}

impl Timeline {
    /// Sizes the canvas to its box.
    fn fit(&mut self) {
        let dpr = web_sys::window().map_or(1.0, |w| w.device_pixel_ratio());
        let r = self.layer.canvas.get_bounding_client_rect();
        self.layer
            .resize(r.width().max(1.0), r.height().max(1.0), dpr);
    }

    /// Draws the events of `replay` and its position; writes `data-first-failure`.
    fn draw(&self, replay: &dyn ReplaySteps, ink: Ink) {
        let l = &self.layer;
        l.begin();
        let c = &l.ctx;
        let (w, h) = (l.css_w, l.css_h);
        let n = replay.steps().max(1) as f64;
        let x_of = |step: f64| 6.0 + (w - 12.0) * step / n;
        c.set_fill_style_str("#e3e8ef");
        c.fill_rect(6.0, h / 2.0 - 3.0, w - 12.0, 6.0);
        // Each kind of event its own colour (Okabe–Ito) and its own shape, so that colour is
        // never the only cue. One path per kind; a mark on the pixel column of the last one
        // of its kind is skipped.
        let y = h / 2.0;
        let r = (h / 2.0 - 4.0).clamp(3.0, 4.0 * ink.line.max(1.0));
        let mut last = [f64::NAN; 4];
        let mut marks: [Vec<f64>; 4] = Default::default();
        replay.for_each_event(&mut |step, _, e| {
            let kind = match e {
                Event::Collision { .. } | Event::Drop | Event::GraspMiss | Event::Timeout => 0,
                Event::Success | Event::TargetReached { .. } | Event::Grasp => 1,
                Event::JointLimit { .. } | Event::Singularity | Event::SpeedLimit { .. } => 2,
                Event::Release => 3,
            };
            let x = x_of(step as f64).round();
            if last[kind] != x {
                last[kind] = x;
                marks[kind].push(x);
            }
        });
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
        if let Some((step, _)) = replay.first_failure() {
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

/// A replay shared between the review and its page (which draws the replayed state).
pub type SharedReplay<E> = Rc<RefCell<Replay<E>>>;

/// The failure review.
pub struct Review {
    pub root: Element,
    title: Element,
    event: Element,
    stepper_slot: Element,
    timeline: RefCell<Timeline>,
    replay: RefCell<Option<Rc<RefCell<AnyReplay>>>>,
    stepper: RefCell<Option<StepperWidget<AnyReplay>>>,
    ids: ReviewIds,
}

impl Review {
    /// Finds the review (see [`markup`]) under `root`.
    #[inline(never)]
    pub fn find(root: &Element, ids: ReviewIds) -> Result<Review, JsValue> {
        let role = |name: &str| -> Result<Element, JsValue> {
            dom::find(root, &format!("[data-{}=\"{name}\"]", ids.attr), ids.attr)
        };
        let canvas: HtmlCanvasElement = dom::find(
            root,
            &format!("[data-testid=\"{}\"]", ids.timeline),
            ids.attr,
        )?;
        Ok(Review {
            root: role("review")?,
            title: role("review-title")?,
            event: role("review-event")?,
            stepper_slot: role("stepper")?,
            timeline: RefCell::new(Timeline {
                layer: Layer::new(canvas)?,
            }),
            replay: RefCell::new(None),
            stepper: RefCell::new(None),
            ids,
        })
    }

    /// Shows or hides the review.
    #[inline(never)]
    pub fn show(&self, on: bool) {
        dom::show(&self.root, on);
    }

    /// Steps `replay` under a new stepper; `on_step` runs on every step shown (the page
    /// draws the review there).
    #[inline(never)]
    pub fn start(&self, replay: Box<dyn ReplaySteps>, on_step: impl Fn() + 'static) {
        self.stop();
        let n = replay.number();
        let model = Rc::new(RefCell::new(AnyReplay(replay)));
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
                testid: self.ids.stepper,
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

    /// Replays `entry` (episode `n`) from its start state under a new stepper (see
    /// [`Review::start`]); the replay, shared with the page.
    pub fn start_entry<E: Replayable + 'static>(
        &self,
        n: usize,
        entry: &EpisodeEntry<E>,
        on_step: impl Fn() + 'static,
    ) -> SharedReplay<E> {
        let first = entry.metrics.first_failure;
        let replay = Rc::new(RefCell::new(Replay::new(n, entry.episode.clone(), first)));
        self.start(Box::new(replay.clone()), on_step);
        replay
    }

    /// Drops the replay and its stepper.
    #[inline(never)]
    pub fn stop(&self) {
        self.stepper.borrow_mut().take();
        self.replay.borrow_mut().take();
        dom::clear(&self.stepper_slot);
        self.title.set_text_content(None);
        self.event.set_text_content(None);
    }

    /// A key for the stepper; `true` if taken.
    #[inline(never)]
    pub fn on_key(&self, event: &KeyboardEvent) -> bool {
        self.stepper
            .borrow()
            .as_ref()
            .is_some_and(|s| s.on_key(event))
    }

    /// Sizes the timeline to its box.
    #[inline(never)]
    pub fn fit(&self) {
        self.timeline.borrow_mut().fit();
    }

    fn render_title(&self, n: usize) {
        self.title.set_text_content(Some(&ctx::t_strings(
            "teleop-review-title",
            &[("n", n.to_string())],
        )));
    }

    /// Says `text` in the events line (no replay: what the review waits for).
    #[inline(never)]
    pub fn show_note(&self, text: &str) {
        self.event.set_text_content(Some(text));
    }

    /// Draws the timeline and writes the first failure and the step's events; `false` when
    /// nothing is replayed.
    #[inline(never)]
    pub fn draw_marks(&self) -> bool {
        let Some(model) = self.replay.borrow().clone() else {
            return false;
        };
        let Ok(any) = model.try_borrow() else {
            return false;
        };
        let replay = any.0.as_ref();
        self.timeline.borrow().draw(replay, Ink::current());
        let events: Vec<String> = replay
            .events_now()
            .iter()
            .map(|e| ctx::t(&format!("teleop-ev-{}", e.id())))
            .collect();
        let first = replay
            .first_failure()
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
        true
    }

    /// The stepper and the title in the current language.
    #[inline(never)]
    pub fn relocalize(&self) {
        if let Some(s) = self.stepper.borrow().as_ref() {
            s.relocalize();
        }
        let n = self
            .replay
            .borrow()
            .as_ref()
            .and_then(|m| m.try_borrow().ok().map(|r| r.0.number()));
        if let Some(n) = n {
            self.render_title(n);
        }
    }
}
