//! The stepper widget: a toolbar to walk a page's model step by step (start, back, play/pause,
//! step, end, reset), a speed choice, a scrub slider and the position "12 / 50,000"; the keys
//! of [`keymap::STEPPER`] (`→`/PageDown step, `←`/PageUp back, Space play/pause, Home/End,
//! `r` reset) through [`StepperWidget::on_key`], which the page calls from its `on_key` (the
//! shell only forwards keys while the page, not a control, has focus).
//!
//! The state machine is [`crate::view::stepper`] (natively tested); this file turns clicks,
//! keys and animation frames into its commands and calls the page's [`StepModel`]. Buttons
//! carry `data-action="start|back|run|step|end|reset"`; the run button has `aria-pressed`.

use std::cell::{Cell, RefCell};
use std::rc::Rc;

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::{Element, HtmlInputElement, HtmlSelectElement, KeyboardEvent};

use crate::ui::kit::keymap;
use crate::ui::kit::scope::{FrameLoop, Scope};
use crate::ui::schedule::now_ms;
use crate::ui::{ctx, dom};
use crate::view::stepper::{key_command, position_message};
pub use crate::view::stepper::{Command, Length, Speed, StepModel, Stepper};

/// How a stepper is set up.
pub struct StepperOptions {
    /// The speeds offered, in order (at least one).
    pub speeds: Vec<Speed>,
    /// Index into `speeds` of the starting speed.
    pub initial_speed: usize,
    /// The label of a speed in the current language (default: "100 / s", "As fast as
    /// possible"); the pendulum page shows "0.1×" … "10×".
    pub speed_label: Box<dyn Fn(Speed) -> String>,
    /// `data-testid` of the widget (buttons are found by `data-action` inside it).
    pub testid: &'static str,
}

impl Default for StepperOptions {
    fn default() -> StepperOptions {
        StepperOptions {
            speeds: vec![
                Speed::PerSecond(10.0),
                Speed::PerSecond(100.0),
                Speed::PerSecond(1000.0),
                Speed::Max,
            ],
            initial_speed: 1,
            speed_label: Box::new(default_speed_label),
            testid: "stepper",
        }
    }
}

/// "100 / s" or "As fast as possible", in the current language.
pub fn default_speed_label(speed: Speed) -> String {
    match speed {
        Speed::PerSecond(rate) => ctx::t_args("kit-stepper-speed-rate", &[("rate", rate.into())]),
        Speed::Max => ctx::t("kit-stepper-speed-max"),
    }
}

const BUTTONS: &[(&str, &str, &str)] = &[
    // (data-action, symbol shown, Fluent id of the accessible name)
    ("start", "⇤", "kit-stepper-start"),
    ("back", "◀", "kit-stepper-back"),
    ("run", "▶", "kit-stepper-run"),
    ("step", "▶|", "kit-stepper-step"),
    ("end", "⇥", "kit-stepper-end"),
    ("reset", "↺", "kit-stepper-reset"),
];

struct Els {
    root: Element,
    buttons: Vec<(&'static str, Element)>,
    scrub: HtmlInputElement,
    speed: HtmlSelectElement,
    position: Element,
}

struct Inner<M: StepModel + 'static> {
    model: Rc<RefCell<M>>,
    state: RefCell<Stepper>,
    els: Els,
    speeds: Vec<Speed>,
    speed_label: Box<dyn Fn(Speed) -> String>,
    on_change: Box<dyn Fn(u64)>,
    frame: RefCell<Option<FrameLoop>>,
    last_frame_ms: Cell<Option<f64>>,
    last_work_ms: Cell<f64>,
    /// Whether a frame's work, for [`Speed::Max`], includes the page's redraw.
    work_counts_redraw: Cell<bool>,
    /// The play state the run button shows (its label is looked up only when this changes;
    /// `None` after a language change).
    shown_playing: Cell<Option<bool>>,
}

/// A stepper driving `M`. Dropping it removes its listeners and stops playing.
pub struct StepperWidget<M: StepModel + 'static> {
    inner: Rc<Inner<M>>,
    _scope: Scope,
}

impl<M: StepModel + 'static> StepperWidget<M> {
    /// Builds the widget at the end of `parent`. `on_change(index)` runs after every move of
    /// the model (the page redraws there).
    ///
    /// ```ignore
    /// let stepper = StepperWidget::new(&toolbar_slot, model.clone(), StepperOptions {
    ///     speeds: vec![Speed::PerSecond(10.0), Speed::PerSecond(100.0), Speed::Max],
    ///     ..StepperOptions::default()
    /// }, move |index| page.redraw(index))?;
    /// // in the page's on_key: if stepper.on_key(event) { return true; }
    /// // in the page's shortcuts(): keymap::with_stepper(&PAGE_KEYS)
    /// ```
    pub fn new(
        parent: &Element,
        model: Rc<RefCell<M>>,
        options: StepperOptions,
        on_change: impl Fn(u64) + 'static,
    ) -> Result<StepperWidget<M>, JsValue> {
        let speeds = if options.speeds.is_empty() {
            vec![Speed::PerSecond(10.0)]
        } else {
            options.speeds
        };
        let initial = speeds[options.initial_speed.min(speeds.len() - 1)];
        let els = build(parent, options.testid, &speeds)?;
        let inner = Rc::new(Inner {
            model,
            state: RefCell::new(Stepper::new(initial)),
            els,
            speeds,
            speed_label: options.speed_label,
            on_change: Box::new(on_change),
            frame: RefCell::new(None),
            last_frame_ms: Cell::new(None),
            last_work_ms: Cell::new(0.0),
            work_counts_redraw: Cell::new(false),
            shown_playing: Cell::new(None),
        });
        let mut scope = Scope::new();
        let weak = Rc::downgrade(&inner);
        *inner.frame.borrow_mut() = Some(scope.frame_loop(&weak, Inner::frame));
        for (action, button) in &inner.els.buttons {
            let command = match *action {
                "start" => Command::Start,
                "back" => Command::Back,
                "run" => Command::Toggle,
                "step" => Command::Step,
                "end" => Command::End,
                _ => Command::Reset,
            };
            scope.listen_for(button, "click", &weak, move |inner, _| inner.apply(command))?;
        }
        scope.listen_for(&inner.els.scrub, "input", &weak, |inner, _| {
            let value = inner.els.scrub.value_as_number();
            if value.is_finite() && value >= 0.0 {
                inner.apply(Command::Seek(value as u64));
            }
        })?;
        scope.listen_for(&inner.els.speed, "change", &weak, |inner, _| {
            let index = inner.els.speed.selected_index();
            if let Some(&speed) = usize::try_from(index)
                .ok()
                .and_then(|i| inner.speeds.get(i))
            {
                inner.apply(Command::SetSpeed(speed));
            }
        })?;
        inner.els.speed.set_selected_index(
            inner
                .speeds
                .iter()
                .position(|s| *s == initial)
                .and_then(|i| i32::try_from(i).ok())
                .unwrap_or(0),
        );
        inner.relocalize();
        inner.render();
        Ok(StepperWidget {
            inner,
            _scope: scope,
        })
    }

    /// The widget's element.
    pub fn element(&self) -> &Element {
        &self.inner.els.root
    }

    /// Steps done.
    pub fn index(&self) -> u64 {
        self.inner.state.borrow().index()
    }

    /// Whether it is playing.
    pub fn playing(&self) -> bool {
        self.inner.state.borrow().playing()
    }

    /// Does `command` as if the user had asked for it.
    pub fn apply(&self, command: Command) {
        self.inner.apply(command);
    }

    /// The model's length changed (new parameters): clamp the index and redraw the widget.
    pub fn model_changed(&self) {
        let moved = {
            let before = self.index();
            let mut model = self.inner.model.borrow_mut();
            self.inner.state.borrow_mut().clamp_to(&mut *model);
            before != self.index()
        };
        self.inner.render();
        if moved {
            (self.inner.on_change)(self.index());
        }
    }

    /// A key the shell forwarded to the page: the stepper's keys ([`keymap::STEPPER`]);
    /// `true` if it was one.
    pub fn on_key(&self, event: &KeyboardEvent) -> bool {
        if event.repeat() && event.key() == " " {
            return true;
        }
        match key_command(&event.key(), keymap::has_command_modifier(event)) {
            Some(command) => {
                self.inner.apply(command);
                true
            }
            None => false,
        }
    }

    /// Sets the work per frame "as fast as possible" aims under (default
    /// [`crate::view::stepper::FRAME_BUDGET_MS`], the model's `go_to` alone), and whether that
    /// work includes the page's redraw in `on_change` (a page that must keep whole frames
    /// short, such as the RRT stepper drawing its tree).
    pub fn set_frame_budget(&self, budget_ms: f64, counts_redraw: bool) {
        self.inner.state.borrow_mut().set_frame_budget(budget_ms);
        self.inner.work_counts_redraw.set(counts_redraw);
    }

    /// Re-renders the labels in the current language.
    pub fn relocalize(&self) {
        self.inner.relocalize();
        self.inner.render();
    }
}

impl<M: StepModel + 'static> Inner<M> {
    fn apply(&self, command: Command) {
        let (changed, moved_from) = {
            let before = self.state.borrow().index();
            let Ok(mut model) = self.model.try_borrow_mut() else {
                return;
            };
            let changed = self.state.borrow_mut().apply(command, &mut *model);
            (changed, before)
        };
        let (index, playing) = {
            let state = self.state.borrow();
            (state.index(), state.playing())
        };
        if playing {
            self.last_frame_ms.set(None);
            if let Some(frame) = self.frame.borrow().as_ref() {
                frame.request();
            }
        }
        if changed {
            self.render();
        }
        if index != moved_from || command == Command::Reset {
            (self.on_change)(index);
        }
    }

    fn frame(&self, time_ms: f64) {
        let elapsed = self
            .last_frame_ms
            .replace(Some(time_ms))
            .map_or(0.0, |last| time_ms - last);
        let started = now_ms();
        let moved = {
            let Ok(mut model) = self.model.try_borrow_mut() else {
                return;
            };
            self.state
                .borrow_mut()
                .tick(elapsed, self.last_work_ms.get(), &mut *model)
        };
        let advance_ms = now_ms() - started;
        self.render();
        if moved {
            (self.on_change)(self.state.borrow().index());
        }
        self.last_work_ms.set(if self.work_counts_redraw.get() {
            now_ms() - started
        } else {
            advance_ms
        });
        if self.state.borrow().playing() {
            if let Some(frame) = self.frame.borrow().as_ref() {
                frame.request();
            }
        }
    }

    fn render(&self) {
        let len = self.model.try_borrow().map(|m| m.length()).ok();
        let state = self.state.borrow();
        let index = state.index();
        let can_step = len.is_some_and(|len| state.can_step(len));
        for (action, button) in &self.els.buttons {
            let enabled = match *action {
                "start" | "back" => state.can_back(),
                "step" => can_step,
                "end" => can_step && len.is_some_and(|l| l.end().is_some()),
                "run" => true,
                _ => true,
            };
            let _ = if enabled {
                button.remove_attribute("disabled")
            } else {
                button.set_attribute("disabled", "")
            };
            let playing = state.playing();
            if *action == "run" && self.shown_playing.replace(Some(playing)) != Some(playing) {
                let _ =
                    button.set_attribute("aria-pressed", if playing { "true" } else { "false" });
                button.set_text_content(Some(if playing { "❚❚" } else { "▶" }));
                let _ = button.set_attribute(
                    "aria-label",
                    &ctx::t(if playing {
                        "kit-stepper-pause"
                    } else {
                        "kit-stepper-run"
                    }),
                );
            }
        }
        let end = len.and_then(Length::end);
        match end {
            Some(end) => {
                self.els.scrub.set_max(&end.to_string());
                dom::show(&self.els.scrub, true);
            }
            None => dom::show(&self.els.scrub, false),
        }
        self.els.scrub.set_value_as_number(index as f64);
        let (id, args) = position_message(index, end);
        let text = ctx::t_strings(id, &args);
        self.els.position.set_text_content(Some(&text));
        let _ = self.els.scrub.set_attribute("aria-valuetext", &text);
    }

    fn relocalize(&self) {
        self.shown_playing.set(None);
        let _ = dom::relocalize(&self.els.root);
        let options = dom::matching(&self.els.speed, "option").unwrap_or_default();
        for (option, speed) in options.iter().zip(&self.speeds) {
            option.set_text_content(Some(&(self.speed_label)(*speed)));
        }
    }
}

fn build(parent: &Element, testid: &str, speeds: &[Speed]) -> Result<Els, JsValue> {
    let root = dom::el_class("div", "kit-stepper")?;
    root.set_attribute("role", "group")?;
    root.set_attribute("data-testid", testid)?;
    dom::set_i18n_attrs(&root, &[("aria-label", "kit-stepper-label")])?;
    let bar = dom::el_class("div", "kit-stepper-buttons")?;
    let mut buttons = Vec::new();
    for &(action, symbol, label_id) in BUTTONS {
        let button = dom::el_text("button", "tool-button kit-stepper-button", symbol)?;
        button.set_attribute("type", "button")?;
        button.set_attribute("data-action", action)?;
        dom::set_i18n_attrs(&button, &[("aria-label", label_id), ("title", label_id)])?;
        dom::append(&bar, &button)?;
        buttons.push((action, button));
    }
    dom::append(&root, &bar)?;

    let speed_label = dom::el_class("label", "kit-stepper-speed")?;
    dom::append(
        &speed_label,
        &dom::el_i18n("span", "", "kit-stepper-speed")?,
    )?;
    let speed = dom::el("select")?.dyn_into::<HtmlSelectElement>()?;
    speed.set_attribute("data-stepper", "speed")?;
    for _ in speeds {
        dom::append(&speed, &dom::el("option")?)?;
    }
    dom::append(&speed_label, &speed)?;
    dom::append(&root, &speed_label)?;

    let scrub = dom::el("input")?.dyn_into::<HtmlInputElement>()?;
    scrub.set_type("range");
    scrub.set_min("0");
    scrub.set_step("1");
    scrub.set_class_name("kit-stepper-scrub");
    scrub.set_attribute("data-stepper", "scrub")?;
    dom::set_i18n_attrs(&scrub, &[("aria-label", "kit-stepper-scrub")])?;
    dom::append(&root, &scrub)?;
    let position = dom::el_class("output", "kit-stepper-position")?;
    position.set_attribute("data-stepper", "position")?;
    dom::append(&root, &position)?;
    dom::append(parent, &root)?;
    Ok(Els {
        root,
        buttons,
        scrub,
        speed,
        position,
    })
}
