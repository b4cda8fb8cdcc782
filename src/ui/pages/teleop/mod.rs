//! Robot Pilot practice (`#/teleop`): teleoperate the kernel's simulated arm
//! (`crate::teleop`) through a whole practice session of the Academy's five modules,
//! record and label episodes, replay them, compare two sessions and export the evidence.
//! A practice simulator: not a safety-rated controller, and not NVIDIA software.
//!
//! The page is a struct of components, one file each: `scene_view` (the arm, scene and trail
//! on the canvas), `devices` (keys, gamepad, clutch), `settings` (the validated form),
//! `label_panel`, `episode_table` (episodes and the repeatability table), `exports` (the
//! downloads, long files written in slices), `review` (replay under the kit's stepper, the
//! timeline), `markup` and `bench`. This file holds the live
//! simulation (`Live`) and the session, and wires them.
//!
//! The simulation runs at a fixed 100 Hz on the kit's frame loop: each displayed frame takes
//! the whole 10 ms steps its interval owes (`crate::view::teleop_input::Accumulator`), and a
//! key press between two steps gets one at once, so at latency 0 the arm moves on the next
//! frame. The loop asks for frames only while something can change
//! (`crate::view::teleop_input::FrameDemand`): an idle page requests none, and the next input
//! asks for one. An episode starts at the pilot's first input after a reset (an idle arm is not
//! timed), and ends at success, at the time box, by End episode or by a reset. The session
//! is saved in localStorage after every episode and label, every two seconds while
//! recording and on `pagehide`; an episode cut off by a reload comes back as interrupted.

mod bench;
mod devices;
mod episode_table;
mod exports;
mod label_panel;
mod markup;
mod review;
mod scene_view;
mod settings;

use std::cell::{Cell, RefCell};
use std::rc::{Rc, Weak};

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::{Element, Event as DomEvent, HtmlCanvasElement, KeyboardEvent, PointerEvent};

use crate::teleop::session::{
    category_from_id, label_from_id, EpisodeEntry, InputDevice, Module, Session, SessionError,
    SessionLoader, EPISODES_NAME, EVIDENCE_NAME, RECORD_TARGET,
};
use crate::teleop::{Command, Episode, Event, Sim, StepRecord};
use crate::ui::kit::canvas::{focus_without_scroll, Ink};
use crate::ui::kit::readouts::Readouts;
use crate::ui::kit::scope::{FrameLoop, Scope};
use crate::ui::kit::stepper::{Speed, StepperOptions, StepperWidget};
use crate::ui::page::{MountCtx, Page, Shortcut};
use crate::ui::schedule::{now_ms, Timer};
use crate::ui::{ctx, dom};
use crate::view::teleop::{metres, radians, sensitivity_defaults, Settings, SettingsTexts};
use crate::view::teleop_input::{key_action, Accumulator, FrameDemand, KeyAction};

use devices::{Clutch, Devices};
use exports::Exports;
use label_panel::LabelPanel;
use review::{Replay, Timeline};
use scene_view::SceneView;
use settings::SettingsForm;

/// localStorage key of the session in progress.
const STORE_KEY: &str = "bsv.teleop.session";
/// localStorage key of the first session (for the repeatability comparison).
const FIRST_KEY: &str = "bsv.teleop.first";
/// Where a stored session that no longer simulates is kept (the page then starts a new one,
/// and saving it would otherwise overwrite the pilot's only copy).
const UNREADABLE_KEY: &str = "bsv.teleop.session.unreadable";
/// Save the session in progress at least this often while recording, ms.
const SAVE_EVERY_MS: f64 = 2000.0;
/// Longest slice of work simulating stored sessions again, ms (then the tab paints and
/// takes input before the next).
const LOAD_SLICE_MS: f64 = 12.0;
/// Steps simulated between two looks at the clock while loading (about 3 ms in wasm).
const LOAD_CHUNK_STEPS: usize = 500;
/// How long a joint-limit or singularity notice stays after its last event, ms.
const STOP_NOTICE_MS: f64 = 600.0;
/// The tip has moved (preflight) once this far from its start, m.
const MOVED_M: f64 = 0.002;

/// The page's keys, for the `?` overlay.
const KEYS: &[Shortcut] = &[
    Shortcut {
        keys: "W / S",
        message_id: "teleop-key-x",
    },
    Shortcut {
        keys: "Q / E",
        message_id: "teleop-key-z",
    },
    Shortcut {
        keys: "→ ← / ↑ ↓",
        message_id: "teleop-key-arrows",
    },
    Shortcut {
        keys: "T / G",
        message_id: "teleop-key-phi",
    },
    Shortcut {
        keys: "K",
        message_id: "teleop-key-gripper",
    },
    Shortcut {
        keys: "R",
        message_id: "teleop-key-reset",
    },
    Shortcut {
        keys: "L",
        message_id: "teleop-key-clear",
    },
    Shortcut {
        keys: "Space",
        message_id: "teleop-key-engage",
    },
];

/// The live simulation and the episode being driven.
struct Live {
    sim: Sim,
    settings: Settings,
    /// A valid settings edit waiting for the next reset.
    pending: Option<Settings>,
    commands: Vec<Command>,
    records: Vec<StepRecord>,
    /// The first input after the reset arrived (the episode's clock runs).
    started: bool,
    /// The episode ended (success, timeout, End episode); no more steps until a reset.
    ended: bool,
    engaged: bool,
    acc: Accumulator,
    last_frame_ms: Option<f64>,
    /// Until when the stop notice shows, and its text id and argument.
    stop: Option<(f64, &'static str, String)>,
}

impl Live {
    fn new(settings: Settings) -> Result<Live, JsValue> {
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

    fn episode(&self) -> Episode {
        Episode {
            config: self.sim.config().clone(),
            start: self.sim.start_state().clone(),
            commands: self.commands.clone(),
            records: self.records.clone(),
        }
    }

    fn tip(&self) -> (f64, f64) {
        let p = crate::teleop::fk(&self.sim.config().arm, &self.sim.state().q);
        (p.x, p.z)
    }
}

/// A new session with the default pilot id and the keyboard.
fn new_session() -> Session {
    Session::new("pilot", InputDevice::Keyboard, &iso_now())
}

/// What became of the stored session on load.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Stored {
    /// None was stored.
    None,
    /// It was simulated again and is shown.
    Restored,
    /// It did not simulate again (or could not be read): a new session was started and the
    /// stored text kept under [`UNREADABLE_KEY`].
    Unreadable,
}

/// The stored sessions (the one in progress, then the first) being simulated again, in
/// slices of at most [`LOAD_SLICE_MS`]: ten minute-long episodes are 60,000 steps, several
/// hundred ms in one task. Until they are done the page is inert and saves nothing.
struct Loading {
    /// The stored session's text, if any (kept aside if it does not simulate).
    stored: Option<String>,
    /// The stored session without its episodes (pilot, device, module), if it could be read:
    /// the page's session while the episodes are simulated again.
    interim: Option<Session>,
    session: Option<SessionLoader>,
    first: Option<SessionLoader>,
    /// The sessions simulated again (`None`: none stored, or one that does not simulate).
    session_done: Option<Session>,
    first_done: Option<Session>,
    /// Steps of the loaders already finished, and of all.
    steps_finished: usize,
    steps_total: usize,
}

impl Loading {
    fn new(stored: Option<String>, first: Option<SessionLoader>) -> Loading {
        let session = stored.as_deref().and_then(SessionLoader::new);
        let interim = session.as_ref().map(|l| {
            let mut s = l.session().clone();
            s.episodes.clear();
            s
        });
        let steps_total = [&session, &first]
            .iter()
            .filter_map(|l| l.as_ref())
            .map(|l| l.progress().1)
            .sum();
        Loading {
            stored,
            interim,
            session,
            first,
            session_done: None,
            first_done: None,
            steps_finished: 0,
            steps_total,
        }
    }

    /// Simulates until `until_ms` ([`now_ms`] clock) or the end; `true` when both are done.
    fn run_until(&mut self, until_ms: f64) -> bool {
        loop {
            let (slot, out) = if self.session.is_some() {
                (&mut self.session, &mut self.session_done)
            } else if self.first.is_some() {
                (&mut self.first, &mut self.first_done)
            } else {
                return true;
            };
            let result = slot.as_mut().and_then(|l| l.run(LOAD_CHUNK_STEPS));
            if result != Some(false) {
                if let Some(l) = slot.take() {
                    self.steps_finished += l.progress().1;
                    *out = if result == Some(true) {
                        l.finish()
                    } else {
                        None
                    };
                }
            }
            if now_ms() >= until_ms {
                return self.session.is_none() && self.first.is_none();
            }
        }
    }

    /// Once done: the session simulated again, or else a new one for the stored pilot and
    /// device (or the defaults); and whether a stored session did not simulate (its text is
    /// then kept under [`UNREADABLE_KEY`]).
    fn outcome(&mut self) -> (Session, Stored) {
        if let Some(session) = self.session_done.take() {
            return (session, Stored::Restored);
        }
        let fresh = match &self.interim {
            Some(s) => Session::new(&s.pilot_id, s.input_device, &iso_now()),
            None => new_session(),
        };
        match &self.stored {
            Some(text) => {
                dom::storage_set(UNREADABLE_KEY, text);
                (fresh, Stored::Unreadable)
            }
            None => (fresh, Stored::None),
        }
    }

    /// Percent of the steps simulated.
    fn percent(&self) -> u32 {
        let current = [&self.session, &self.first]
            .iter()
            .filter_map(|l| l.as_ref())
            .map(|l| l.progress().0)
            .sum::<usize>();
        let done = (self.steps_finished + current).min(self.steps_total);
        (done * 100)
            .checked_div(self.steps_total)
            .map_or(100, |p| p as u32)
    }
}

struct Els {
    engage: Element,
    gripper: Element,
    reset: Element,
    end: Element,
    next: Element,
    device_status: Element,
    ended: Element,
    stop: Element,
    module_help: Element,
    review: Element,
    review_title: Element,
    review_event: Element,
    stepper_slot: Element,
    restored: Element,
    loading: Element,
    open: Element,
    open_error: Element,
    status: Element,
    session_line: Element,
    episodes_body: Element,
    compare_body: Element,
    modules: Vec<(Module, Element)>,
    devices: Vec<(InputDevice, Element)>,
    check_moved: Element,
    check_reset: Element,
    canvas: HtmlCanvasElement,
}

/// The page's state.
pub struct Inner {
    me: Weak<Inner>,
    root: Element,
    els: Els,
    live: RefCell<Live>,
    devices: RefCell<Devices>,
    session: RefCell<Session>,
    first: RefCell<Option<Session>>,
    view: RefCell<SceneView>,
    readouts: Readouts,
    settings: RefCell<SettingsForm>,
    texts: RefCell<SettingsTexts>,
    labels: RefCell<LabelPanel>,
    replay: RefCell<Option<Rc<RefCell<Replay>>>>,
    stepper: RefCell<Option<StepperWidget<Replay>>>,
    timeline: RefCell<Timeline>,
    frame: RefCell<Option<FrameLoop>>,
    exports: Exports,
    /// The next slice of a file being written.
    export_timer: RefCell<Option<Rc<Timer>>>,
    /// Stored sessions still being simulated again, and the timer of the next slice.
    loading: RefCell<Option<Loading>>,
    load_timer: RefCell<Option<Rc<Timer>>>,
    last_save_ms: Cell<f64>,
    /// The device status shown (`None`: to be written).
    shown_device: RefCell<Option<String>>,
    /// The stop notice shown (written only when it changes).
    shown_stop: RefCell<String>,
    scope: RefCell<Scope>,
}

/// The Robot Pilot page.
pub struct TeleopPage(Rc<Inner>);

fn find<T: JsCast>(root: &Element, sel: &str) -> Result<T, JsValue> {
    dom::find(root, sel, "teleop")
}

fn role<T: JsCast>(root: &Element, name: &str) -> Result<T, JsValue> {
    find(root, &format!("[data-tele=\"{name}\"]"))
}

fn iso_now() -> String {
    js_sys::Date::new_0()
        .to_iso_string()
        .as_string()
        .unwrap_or_default()
}

impl Page for TeleopPage {
    fn mount(ctx: MountCtx) -> Result<TeleopPage, JsValue> {
        let root = ctx.root.clone();
        root.set_inner_html(&markup::page());
        dom::relocalize(&root)?;
        // The stored sessions are simulated again: at once when that is short, else in
        // slices after the first paint (the page inert meanwhile, its session the stored
        // one's pilot, device and module without episodes).
        let mut loading = Loading::new(
            dom::storage_get(STORE_KEY),
            dom::storage_get(FIRST_KEY).and_then(|t| SessionLoader::new(&t)),
        );
        let load_started_ms = now_ms();
        let loaded = loading.run_until(load_started_ms + LOAD_SLICE_MS);
        bench::record_load(now_ms() - load_started_ms);
        let (session, first, stored, loading) = if loaded {
            let (session, stored) = loading.outcome();
            (session, loading.first_done.take(), stored, None)
        } else {
            let session = loading.interim.clone().unwrap_or_else(new_session);
            (session, None, Stored::None, Some(loading))
        };
        let mut texts = SettingsTexts::defaults(session.input_device);
        texts.pilot = session.pilot_id.clone();
        for (k, v) in &ctx.query {
            if crate::view::teleop::FIELDS.contains(&k.as_str()) && k != "pilot" {
                texts.set(k, v);
            }
        }
        let mut form = SettingsForm::find(role(&root, "settings")?)?;
        form.show(&texts);
        let settings = match form.check() {
            Some(s) => s,
            None => {
                texts = SettingsTexts::defaults(session.input_device);
                texts.pilot = "pilot".into();
                form.show(&texts);
                form.check()
                    .ok_or_else(|| JsValue::from_str("teleop: default settings refused"))?
            }
        };
        let live = Live::new(settings)?;
        let modules = Module::ALL
            .iter()
            .map(|m| Ok((*m, find(&root, &format!("[data-module=\"{}\"]", m.id()))?)))
            .collect::<Result<Vec<_>, JsValue>>()?;
        let device_els = InputDevice::ALL
            .iter()
            .map(|d| Ok((*d, find(&root, &format!("[data-device=\"{}\"]", d.id()))?)))
            .collect::<Result<Vec<_>, JsValue>>()?;
        let els = Els {
            engage: find(&root, "[data-action=\"engage\"]")?,
            gripper: find(&root, "[data-action=\"gripper\"]")?,
            reset: find(&root, "[data-action=\"reset\"]")?,
            end: find(&root, "[data-action=\"end-episode\"]")?,
            next: find(&root, "[data-action=\"next-module\"]")?,
            device_status: role(&root, "device-status")?,
            ended: role(&root, "ended")?,
            stop: role(&root, "stop")?,
            module_help: role(&root, "module-help")?,
            review: role(&root, "review")?,
            review_title: role(&root, "review-title")?,
            review_event: role(&root, "review-event")?,
            stepper_slot: role(&root, "stepper")?,
            restored: role(&root, "restored")?,
            loading: role(&root, "loading")?,
            open: role(&root, "open")?,
            open_error: role(&root, "open-error")?,
            status: role(&root, "status")?,
            session_line: role(&root, "session-line")?,
            episodes_body: find(&root, "[data-tele=\"episodes\"] tbody")?,
            compare_body: find(&root, "[data-tele=\"compare\"] tbody")?,
            modules,
            devices: device_els,
            check_moved: find(&root, "[data-check=\"moved\"]")?,
            check_reset: find(&root, "[data-check=\"reset\"]")?,
            canvas: find(&root, "[data-testid=\"teleop-canvas\"]")?,
        };
        let view = SceneView::find(&role(&root, "stage")?)?;
        let timeline = Timeline::new(find(&root, "[data-testid=\"teleop-timeline\"]")?)?;
        let readouts = Readouts::find(&root)?;
        let labels = LabelPanel::find(&root)?;
        let exports = Exports::find(&root)?;
        let inner = Rc::new_cyclic(|me: &Weak<Inner>| Inner {
            me: me.clone(),
            root: root.clone(),
            els,
            live: RefCell::new(live),
            devices: RefCell::new(Devices::default()),
            session: RefCell::new(session),
            first: RefCell::new(first),
            view: RefCell::new(view),
            readouts,
            settings: RefCell::new(form),
            texts: RefCell::new(texts),
            labels: RefCell::new(labels),
            replay: RefCell::new(None),
            stepper: RefCell::new(None),
            timeline: RefCell::new(timeline),
            frame: RefCell::new(None),
            exports,
            export_timer: RefCell::new(None),
            loading: RefCell::new(None),
            load_timer: RefCell::new(None),
            last_save_ms: Cell::new(0.0),
            shown_device: RefCell::new(None),
            shown_stop: RefCell::new(String::new()),
            scope: RefCell::new(Scope::new()),
        });
        inner.install()?;
        inner.view.borrow_mut().fit();
        let sliced = loading.is_some();
        *inner.loading.borrow_mut() = loading;
        if sliced {
            inner.set_busy(true);
            inner.schedule_load();
        }
        inner.show_session(stored);
        inner.write_url();
        Ok(TeleopPage(inner))
    }

    fn relocalize(&self) {
        self.0.relocalize();
    }

    fn set_projector(&self, _on: bool) {
        self.0.relayout();
    }

    fn shortcuts(&self) -> Vec<Shortcut> {
        let mut keys = KEYS.to_vec();
        keys.extend_from_slice(crate::ui::kit::keymap::STEPPER);
        keys
    }

    fn on_key(&self, event: &KeyboardEvent) -> bool {
        // The page body has focus (the canvas's own listener takes keys first): L stays
        // the shell's language key here.
        if event.code() == "KeyL" || self.0.loading.borrow().is_some() {
            return false;
        }
        self.0.key_down(event)
    }
}

impl Drop for TeleopPage {
    fn drop(&mut self) {
        self.0.save();
    }
}

impl Inner {
    /// Listeners: buttons, keys, pointer, form, files, storage on pagehide, resizes.
    fn install(&self) -> Result<(), JsValue> {
        let mut scope = self.scope.borrow_mut();
        let me = &self.me;
        let frame = scope.dirty_frame_loop(me, |p: &Inner, _bits, t| p.frame(t));
        frame.request();
        *self.frame.borrow_mut() = Some(frame);
        *self.export_timer.borrow_mut() = Some(scope.timer(me, Inner::export_slice));
        *self.load_timer.borrow_mut() = Some(scope.timer(me, Inner::load_slice));
        scope.listen_for(&self.els.engage, "click", me, |p, _| p.toggle_engage())?;
        scope.listen_for(&self.els.gripper, "click", me, |p, _| p.toggle_gripper())?;
        scope.listen_for(&self.els.reset, "click", me, |p, _| p.reset())?;
        scope.listen_for(&self.els.end, "click", me, |p, _| p.end_episode())?;
        scope.listen_for(&self.els.next, "click", me, |p, _| {
            let next = p.session.borrow().module.next();
            if p.module_allowed(next) {
                p.enter_module(next);
            }
        })?;
        for (m, el) in &self.els.modules {
            let m = *m;
            scope.listen_for(el, "click", me, move |p, _| {
                if p.module_allowed(m) {
                    p.enter_module(m);
                }
            })?;
        }
        for (d, el) in &self.els.devices {
            let d = *d;
            scope.listen_for(el, "click", me, move |p, _| p.choose_device(d))?;
        }
        // Keys on the canvas: taken before the shell sees them (L is "clear" here).
        let canvas = self.els.canvas.clone();
        scope.listen_for(&canvas, "keydown", me, |p, e| {
            if let Some(k) = e.dyn_ref::<KeyboardEvent>() {
                if crate::ui::kit::keymap::has_command_modifier(k) || crate::ui::overlay::is_open()
                {
                    return;
                }
                if p.key_down(k) {
                    e.prevent_default();
                    e.stop_propagation();
                }
            }
        })?;
        let window = dom::window()?;
        scope.listen_for(&window, "keyup", me, |p, e| {
            if let Some(k) = e.dyn_ref::<KeyboardEvent>() {
                p.devices.borrow_mut().keys.release(&k.code());
            }
        })?;
        scope.listen_for(&window, "blur", me, |p, _| {
            p.devices.borrow_mut().keys.clear()
        })?;
        scope.listen_for(&window, "pagehide", me, |p, _| p.save())?;
        // A pad is polled once per frame while connected; an idle page polls nothing until
        // one connects.
        scope.listen_for(&window, "gamepadconnected", me, |p, _| p.request_frame())?;
        scope.listen_for(&canvas, "pointerdown", me, |p, e| p.pointer_down(e))?;
        scope.listen_for(&canvas, "pointermove", me, |p, e| p.pointer_move(e))?;
        for ev in ["pointerup", "pointercancel", "lostpointercapture"] {
            scope.listen_for(&canvas, ev, me, |p, e| p.pointer_up(e))?;
        }
        // Label panel.
        let panel = self.labels.borrow().root.clone();
        scope.listen_for(&panel, "click", me, |p, e| p.label_click(e))?;
        // Episodes table actions and downloads (delegated).
        scope.listen_for(&self.root, "click", me, |p, e| p.table_click(e))?;
        // Settings.
        let form = self.settings.borrow().element.clone();
        scope.listen_for(&form, "input", me, |p, _| p.settings_edited())?;
        scope.listen_for(&form, "change", me, |p, _| p.settings_edited())?;
        scope.listen_for(&form, "submit", me, |_, e| e.prevent_default())?;
        scope.listen_for(&self.els.open, "change", me, |p, _| p.open_files())?;
        let stage: Element = role(&self.root, "stage")?;
        let review = self.els.review.clone();
        scope.observe_resize(&[&stage, &review], me, |p| p.relayout())?;
        Ok(())
    }

    // ---- Keys, pointer, buttons ----

    /// A key went down on the canvas or the page body; `true` if taken.
    fn key_down(&self, event: &KeyboardEvent) -> bool {
        if self.in_review() {
            return self
                .stepper
                .borrow()
                .as_ref()
                .is_some_and(|s| s.on_key(event));
        }
        let code = event.code();
        let Some(action) = key_action(&code) else {
            return false;
        };
        let repeat = event.repeat();
        match action {
            KeyAction::Hold { .. } => {
                let mut d = self.devices.borrow_mut();
                if d.keys.press(&code) {
                    d.fresh = true;
                }
            }
            _ if repeat => {}
            KeyAction::ToggleGripper => self.toggle_gripper(),
            KeyAction::Reset => self.reset(),
            KeyAction::Clear => self.devices.borrow_mut().clear(),
            KeyAction::Engage => self.toggle_engage(),
        }
        self.request_frame();
        true
    }

    fn pointer_world(&self, e: &PointerEvent) -> (f64, f64) {
        let x = f64::from(e.offset_x());
        let y = f64::from(e.offset_y());
        self.view.borrow().transform.to_world(x, y)
    }

    fn pointer_down(&self, e: &DomEvent) {
        focus_without_scroll(&self.els.canvas);
        let Some(e) = e.dyn_ref::<PointerEvent>() else {
            return;
        };
        if self.in_review() || (e.pointer_type() == "mouse" && e.button() != 0) {
            return;
        }
        e.prevent_default();
        let _ = self.els.canvas.set_pointer_capture(e.pointer_id());
        let at = self.pointer_world(e);
        let tip = self.live.borrow().tip();
        let mut d = self.devices.borrow_mut();
        d.clutch = Some(Clutch {
            pointer_id: e.pointer_id(),
            pointer_start: at,
            tip_start: tip,
            target: tip,
        });
        d.fresh = true;
        drop(d);
        self.request_frame();
    }

    fn pointer_move(&self, e: &DomEvent) {
        let Some(e) = e.dyn_ref::<PointerEvent>() else {
            return;
        };
        let at = self.pointer_world(e);
        let mut d = self.devices.borrow_mut();
        if let Some(c) = d.clutch.as_mut() {
            if c.pointer_id == e.pointer_id() {
                c.target = (
                    c.tip_start.0 + at.0 - c.pointer_start.0,
                    c.tip_start.1 + at.1 - c.pointer_start.1,
                );
                d.fresh = true;
                drop(d);
                self.request_frame();
            }
        }
    }

    fn pointer_up(&self, e: &DomEvent) {
        let Some(e) = e.dyn_ref::<PointerEvent>() else {
            return;
        };
        let mut d = self.devices.borrow_mut();
        if d.clutch.is_some_and(|c| c.pointer_id == e.pointer_id()) {
            d.clutch = None;
        }
    }

    fn toggle_engage(&self) {
        {
            let mut live = self.live.borrow_mut();
            live.engaged = !live.engaged;
            live.acc.clear();
            live.last_frame_ms = None;
        }
        self.render_buttons();
        self.request_frame();
    }

    fn toggle_gripper(&self) {
        {
            let mut d = self.devices.borrow_mut();
            d.gripper_closed = !d.gripper_closed;
            d.fresh = true;
        }
        self.render_buttons();
        self.request_frame();
    }

    fn request_frame(&self) {
        if let Some(f) = self.frame.borrow().as_ref() {
            f.request();
        }
    }

    // ---- The live simulation ----

    /// One displayed frame: poll the pad, step the simulation, draw, readouts.
    fn frame(&self, t_ms: f64) {
        if self.loading.borrow().is_some() {
            // Stored sessions are still being loaded: no input drives the arm yet.
            return;
        }
        if self.in_review() {
            self.animate(false);
            return;
        }
        let started_ms = now_ms();
        let dead_zone = self.live.borrow().settings.dead_zone;
        let (pad_changed, pad_toggled) = self.devices.borrow_mut().poll_pad(dead_zone);
        if pad_changed || self.shown_device.borrow().is_none() {
            self.render_device_status();
        }
        if pad_toggled {
            self.render_buttons();
        }
        let mut ended_now = false;
        let mut moved_by_device = false;
        {
            let mut live = self.live.borrow_mut();
            let mut devices = self.devices.borrow_mut();
            let elapsed = live.last_frame_ms.map_or(0.0, |last| t_ms - last);
            live.last_frame_ms = Some(t_ms);
            let fresh = std::mem::take(&mut devices.fresh);
            if live.engaged && !live.ended {
                let gripper = devices.gripper_closed;
                let axes = devices.axes(live.tip());
                let any =
                    axes.iter().any(|v| *v != 0.0) || gripper != live.sim.state().gripper_closed;
                if !live.started && any {
                    live.started = true;
                    live.acc.clear();
                }
                if live.started {
                    let n = live.acc.steps(elapsed, fresh);
                    for _ in 0..n {
                        let axes = devices.axes(live.tip());
                        let cmd = Command {
                            dx: axes[0],
                            dz: axes[1],
                            dphi: axes[2],
                            gripper_closed: gripper,
                        };
                        let rec = live.sim.step(&cmd);
                        for ev in &rec.events {
                            match ev {
                                Event::JointLimit { joint } => {
                                    live.stop = Some((
                                        t_ms + STOP_NOTICE_MS,
                                        "teleop-stop-limit",
                                        joint.to_string(),
                                    ))
                                }
                                Event::Singularity => {
                                    live.stop = Some((
                                        t_ms + STOP_NOTICE_MS,
                                        "teleop-stop-singular",
                                        String::new(),
                                    ))
                                }
                                _ => {}
                            }
                        }
                        self.view.borrow_mut().push_trail(rec.x, rec.z);
                        live.commands.push(cmd);
                        live.records.push(rec);
                        if live.sim.done().is_some() {
                            ended_now = true;
                            break;
                        }
                    }
                    let device = self.session.borrow().input_device;
                    let used = match device {
                        InputDevice::Keyboard => devices.keys.any(),
                        InputDevice::Gamepad => devices.pad_out.active,
                        InputDevice::Pointer => devices.clutch.is_some(),
                    };
                    if used {
                        let start =
                            crate::teleop::fk(&live.sim.config().arm, &live.sim.start_state().q);
                        let tip = live.tip();
                        moved_by_device = (tip.0 - start.x).hypot(tip.1 - start.z) > MOVED_M;
                    }
                } else {
                    live.acc.clear();
                }
            }
        }
        if moved_by_device {
            let mut s = self.session.borrow_mut();
            if s.module == Module::Preflight && !s.preflight.moved {
                s.preflight.moved = true;
                drop(s);
                self.render_checks();
            }
        }
        if ended_now {
            self.episode_ended();
        }
        self.draw_live(t_ms);
        bench::record(now_ms() - started_ms);
        if self.recording_in_progress() && now_ms() - self.last_save_ms.get() > SAVE_EVERY_MS {
            self.save();
        }
        let busy = self.frame_demand().needs_frames(t_ms);
        self.animate(busy);
    }

    /// What keeps frames coming after this one.
    fn frame_demand(&self) -> FrameDemand {
        let live = self.live.borrow();
        let d = self.devices.borrow();
        FrameDemand {
            keys_held: d.keys.any(),
            pad_connected: d.pad_name.is_some(),
            clutch_held: d.clutch.is_some(),
            episode_running: live.engaged && live.started && !live.ended,
            fresh_input: d.fresh,
            notice_until_ms: live.stop.as_ref().map(|(until, _, _)| *until),
        }
    }

    /// Keeps the frames coming, or lets them stop (idle: the next frame, asked for by an
    /// input, counts no time from this one).
    fn animate(&self, on: bool) {
        if !on {
            self.live.borrow_mut().last_frame_ms = None;
        }
        if let Some(f) = self.frame.borrow().as_ref() {
            f.set_animating(on);
        }
    }

    fn recording_in_progress(&self) -> bool {
        let live = self.live.borrow();
        self.session.borrow().module.records() && live.started && !live.ended
    }

    /// Draws the live scene and writes the readouts.
    fn draw_live(&self, t_ms: f64) {
        let live = self.live.borrow();
        let g = live.sim.geometry();
        let clutch = self.devices.borrow().clutch.map(|c| c.target);
        self.view.borrow_mut().draw(&g, clutch, Ink::current());
        let state = live.sim.state();
        let pose = g.tip;
        let r = &self.readouts;
        r.set("x", &metres(pose.x));
        r.set("z", &metres(pose.z));
        r.set("phi", &radians(pose.phi));
        r.set("q1", &radians(state.q[0]));
        r.set("q2", &radians(state.q[1]));
        r.set("q3", &radians(state.q[2]));
        let m = crate::teleop::manipulability(&live.sim.config().arm, &state.q);
        r.set("manipulability", &format!("{m:.5}"));
        r.set("time", &format!("{:.2}", state.t_s));
        let stop_text = match &live.stop {
            Some((until, id, arg)) if *until > t_ms => {
                ctx::t_strings(id, &[("joint", arg.clone())])
            }
            _ => String::new(),
        };
        if *self.shown_stop.borrow() != stop_text {
            self.els.stop.set_text_content(Some(&stop_text));
            *self.shown_stop.borrow_mut() = stop_text;
        }
    }

    /// Writes the readouts that change with the session, not the frame.
    fn render_state_readouts(&self) {
        let live = self.live.borrow();
        let s = self.session.borrow();
        let episode = if s.module.records() {
            format!("{} / {}", s.episodes.len() + 1, RECORD_TARGET)
        } else {
            ctx::t("teleop-episode-practice")
        };
        self.readouts.set("episode", &episode);
        let (state_id, state_value) = if live.engaged {
            ("teleop-state-engaged", "engaged")
        } else {
            ("teleop-state-paused", "paused")
        };
        self.readouts
            .set_with_value("state", &ctx::t(state_id), state_value);
        let closed = self.devices.borrow().gripper_closed;
        let (gid, gv) = if closed {
            ("teleop-gripper-closed", "closed")
        } else {
            ("teleop-gripper-open", "open")
        };
        self.readouts.set_with_value("gripper", &ctx::t(gid), gv);
    }

    /// The engage and gripper buttons' texts and pressed states, and the readouts they set.
    fn render_buttons(&self) {
        let engaged = self.live.borrow().engaged;
        self.els.engage.set_text_content(Some(&ctx::t(if engaged {
            "teleop-pause"
        } else {
            "teleop-engage"
        })));
        let _ = self
            .els
            .engage
            .set_attribute("aria-pressed", if engaged { "true" } else { "false" });
        let closed = self.devices.borrow().gripper_closed;
        self.els.gripper.set_text_content(Some(&ctx::t(if closed {
            "teleop-gripper-open-button"
        } else {
            "teleop-gripper-close-button"
        })));
        let _ = self
            .els
            .gripper
            .set_attribute("aria-pressed", if closed { "true" } else { "false" });
        self.render_state_readouts();
    }

    fn render_device_status(&self) {
        let device = self.session.borrow().input_device;
        let text = match device {
            InputDevice::Gamepad => match self.devices.borrow().pad_name.clone() {
                Some(name) => ctx::t_strings("teleop-pad-connected", &[("name", name)]),
                None => ctx::t("teleop-pad-none"),
            },
            InputDevice::Keyboard => ctx::t("teleop-keyboard-hint"),
            InputDevice::Pointer => ctx::t("teleop-pointer-hint"),
        };
        if self.shown_device.borrow().as_deref() != Some(&text) {
            self.els.device_status.set_text_content(Some(&text));
            *self.shown_device.borrow_mut() = Some(text);
        }
    }

    /// The simulation reached success or the time box.
    fn episode_ended(&self) {
        self.finish_episode();
    }

    /// End episode (the button): the episode ends here (recorded in Record ten).
    fn end_episode(&self) {
        let has_steps = !self.live.borrow().commands.is_empty();
        if has_steps && !self.live.borrow().ended {
            self.finish_episode();
        } else if !has_steps {
            self.show_status("teleop-end-nothing");
        }
    }

    /// Ends the current episode: recorded and offered for labelling in Record ten.
    fn finish_episode(&self) {
        let episode = {
            let mut live = self.live.borrow_mut();
            live.ended = true;
            live.episode()
        };
        let outcome = self.live.borrow().sim.done();
        let module = self.session.borrow().module;
        let text = match outcome {
            Some(crate::teleop::Outcome::Success) => ctx::t_strings(
                "teleop-ended-success",
                &[(
                    "t",
                    format!("{:.2}", episode.records.last().map_or(0.0, |r| r.t_s)),
                )],
            ),
            Some(crate::teleop::Outcome::Timeout) => ctx::t("teleop-ended-timeout"),
            None => ctx::t("teleop-ended-pilot"),
        };
        self.els.ended.set_text_content(Some(&text));
        dom::show(&self.els.ended, true);
        if module.records() {
            let n = self.session.borrow_mut().record(episode, false);
            self.open_label(n);
            self.render_session();
            self.save();
        }
    }

    /// R or Reset: the scene back to its start (a new configuration if one is waiting); in
    /// Record ten an episode under way is ended and recorded first; in preflight the reset
    /// is checked against a fresh start state, bit for bit.
    fn reset(&self) {
        let under_way = {
            let live = self.live.borrow();
            live.started && !live.ended && !live.commands.is_empty()
        };
        if under_way && self.session.borrow().module.records() {
            self.finish_episode();
        }
        {
            let mut live = self.live.borrow_mut();
            if let Some(s) = live.pending.take() {
                match Sim::new(s.config.clone()) {
                    Ok(sim) => {
                        live.sim = sim;
                        live.settings = s;
                    }
                    Err(e) => web_sys::console::warn_1(&JsValue::from_str(&e.to_string())),
                }
            } else {
                live.sim.reset();
            }
            live.commands.clear();
            live.records.clear();
            live.started = false;
            live.ended = false;
            live.acc.clear();
            live.stop = None;
        }
        self.view.borrow_mut().trail.clear();
        {
            let mut d = self.devices.borrow_mut();
            d.clutch = None;
            d.gripper_closed = false;
        }
        let verified = {
            let live = self.live.borrow();
            Sim::new(live.sim.config().clone())
                .map(|fresh| fresh.start_state() == live.sim.state())
                .unwrap_or(false)
        };
        {
            let mut s = self.session.borrow_mut();
            if s.module == Module::Preflight && s.preflight.moved {
                s.preflight.reset_verified = Some(verified);
            }
        }
        dom::show(&self.els.ended, false);
        dom::show(&self.els.restored, false);
        self.render_checks();
        self.render_buttons();
        self.render_modules();
        self.save();
        self.request_frame();
    }

    // ---- Modules ----

    fn module_allowed(&self, m: Module) -> bool {
        let s = self.session.borrow();
        match m {
            Module::Preflight | Module::BasicControl => true,
            Module::RecordTen => s.preflight.passed() || !s.episodes.is_empty(),
            Module::FailureReview => !s.episodes.is_empty(),
            Module::Repeatability => !s.episodes.is_empty() || self.first.borrow().is_some(),
        }
    }

    fn in_review(&self) -> bool {
        self.session.borrow().module == Module::FailureReview
    }

    /// Records the episode under way, if the module records (before the module or the
    /// session changes: an attempt is never dropped).
    fn settle_episode(&self) {
        let under_way = {
            let live = self.live.borrow();
            live.started && !live.ended && !live.commands.is_empty()
        };
        if under_way && self.session.borrow().module.records() {
            self.finish_episode();
        }
    }

    /// Switches to module `m`: the live arm (reset) or the review.
    fn enter_module(&self, m: Module) {
        self.settle_episode();
        let was = self.session.borrow().module;
        self.session.borrow_mut().module = m;
        if m == Module::FailureReview {
            self.devices.borrow_mut().clear();
            dom::show(&self.els.review, true);
            let pick = {
                let s = self.session.borrow();
                s.episodes
                    .iter()
                    .find(|e| e.metrics.first_failure.is_some())
                    .or(s.episodes.first())
                    .map(|e| e.number)
            };
            if let Some(n) = pick {
                self.start_replay(n);
            }
        } else {
            self.stop_replay();
            dom::show(&self.els.review, false);
            if was != m {
                self.reset();
            }
        }
        self.render_modules();
        self.render_session();
        self.save();
        self.request_frame();
    }

    fn render_modules(&self) {
        let current = self.session.borrow().module;
        for (m, el) in &self.els.modules {
            if *m == current {
                let _ = el.set_attribute("aria-current", "step");
            } else {
                let _ = el.remove_attribute("aria-current");
            }
            let _ = el.set_attribute(
                "aria-disabled",
                if self.module_allowed(*m) {
                    "false"
                } else {
                    "true"
                },
            );
        }
        let next = current.next();
        let next_ok = next != current && self.module_allowed(next);
        let _ = self
            .els
            .next
            .set_attribute("aria-disabled", if next_ok { "false" } else { "true" });
        let live_module = current != Module::FailureReview;
        for el in [
            &self.els.engage,
            &self.els.gripper,
            &self.els.end,
            &self.els.reset,
        ] {
            dom::show(el, live_module);
        }
        if !live_module {
            dom::show(&self.els.ended, false);
        }
        let help = ctx::t_strings(
            &format!("teleop-help-{}", current.id()),
            &[("target", RECORD_TARGET.to_string())],
        );
        self.els.module_help.set_text_content(Some(&help));
        let preflight = find::<Element>(&self.root, "[data-tele=\"preflight\"]");
        if let Ok(p) = preflight {
            dom::show(&p, current == Module::Preflight);
        }
        self.render_checks();
        self.render_state_readouts();
    }

    fn render_checks(&self) {
        let s = self.session.borrow();
        let mark = |el: &Element, state: &str| {
            let _ = el.set_attribute("data-state", state);
        };
        mark(
            &self.els.check_moved,
            if s.preflight.moved { "done" } else { "todo" },
        );
        mark(
            &self.els.check_reset,
            match s.preflight.reset_verified {
                Some(true) => "done",
                Some(false) => "failed",
                None => "todo",
            },
        );
        for (d, el) in &self.els.devices {
            let _ = el.set_attribute(
                "aria-checked",
                if *d == s.input_device {
                    "true"
                } else {
                    "false"
                },
            );
        }
        drop(s);
        self.render_modules_enabled();
    }

    fn render_modules_enabled(&self) {
        for (m, el) in &self.els.modules {
            let _ = el.set_attribute(
                "aria-disabled",
                if self.module_allowed(*m) {
                    "false"
                } else {
                    "true"
                },
            );
        }
        let current = self.session.borrow().module;
        let next = current.next();
        let next_ok = next != current && self.module_allowed(next);
        let _ = self
            .els
            .next
            .set_attribute("aria-disabled", if next_ok { "false" } else { "true" });
    }

    fn choose_device(&self, device: InputDevice) {
        let old = {
            let mut s = self.session.borrow_mut();
            let old = s.input_device;
            s.input_device = device;
            if old != device {
                s.preflight = Default::default();
            }
            old
        };
        if old != device {
            // The sensitivities follow the device while they are the old device's defaults.
            let (op, or) = sensitivity_defaults(old);
            let (np, nr) = sensitivity_defaults(device);
            let mut t = self.settings.borrow().texts();
            if t.pos_sensitivity.trim().parse::<f64>().ok() == Some(op) {
                t.pos_sensitivity = np.to_string();
            }
            if t.rot_sensitivity.trim().parse::<f64>().ok() == Some(or) {
                t.rot_sensitivity = nr.to_string();
            }
            self.settings.borrow().show(&t);
            self.settings_edited();
        }
        *self.shown_device.borrow_mut() = None;
        self.render_device_status();
        self.render_checks();
        self.save();
    }

    // ---- Labels ----

    fn open_label(&self, n: usize) {
        let s = self.session.borrow();
        if let Some(entry) = s.episodes.get(n.wrapping_sub(1)) {
            self.labels.borrow_mut().open(entry);
        }
    }

    fn label_click(&self, e: &DomEvent) {
        let Some(target) = e.target().and_then(|t| t.dyn_into::<Element>().ok()) else {
            return;
        };
        let Ok(Some(button)) = target.closest("button") else {
            return;
        };
        if let Some(id) = button.get_attribute("data-label") {
            if let Some(l) = label_from_id(&id) {
                self.labels.borrow_mut().pick_label(l);
            }
        } else if let Some(id) = button.get_attribute("data-category") {
            if let Some(c) = category_from_id(&id) {
                self.labels.borrow_mut().pick_category(c);
            }
        } else if button.get_attribute("data-action").as_deref() == Some("confirm-label") {
            let (n, label, category, note) = {
                let p = self.labels.borrow();
                (p.episode, p.label, p.category, p.note_text())
            };
            if let Some(n) = n {
                if let Some(entry) = self.session.borrow_mut().episodes.get_mut(n - 1) {
                    entry.set_label(label, category, &note);
                }
                self.labels.borrow_mut().close();
                self.render_session();
                self.save();
                let next = self.session.borrow().unlabelled();
                if let Some(next) = next {
                    self.open_label(next);
                } else {
                    focus_without_scroll(&self.els.canvas);
                }
            }
        }
    }

    // ---- Episodes, downloads, files ----

    fn table_click(&self, e: &DomEvent) {
        let Some(target) = e.target().and_then(|t| t.dyn_into::<Element>().ok()) else {
            return;
        };
        let Ok(Some(button)) = target.closest("button") else {
            return;
        };
        let num = |attr: &str| {
            button
                .get_attribute(attr)
                .and_then(|v| v.parse::<usize>().ok())
        };
        if let Some(n) = num("data-replay") {
            if self.session.borrow().module != Module::FailureReview {
                self.enter_module(Module::FailureReview);
            }
            self.start_replay(n);
        } else if let Some(n) = num("data-relabel") {
            self.open_label(n);
        } else if let Some(file) = button.get_attribute("data-download") {
            self.download(&file);
        } else {
            match button.get_attribute("data-action").as_deref() {
                Some("second-session") => self.second_session(),
                Some("new-session") => self.new_session(),
                _ => {}
            }
        }
    }

    fn download(&self, file: &str) {
        let started_ms = now_ms();
        let more = self
            .exports
            .download(file, &self.session.borrow(), &iso_now());
        bench::record_export(now_ms() - started_ms);
        if more {
            self.schedule_export();
        }
    }

    /// One slice of a file being written (the file offered at its end).
    fn export_slice(&self) {
        let started_ms = now_ms();
        let more = self.exports.write_slice();
        bench::record_export(now_ms() - started_ms);
        if more {
            self.schedule_export();
        }
    }

    fn schedule_export(&self) {
        if let Some(t) = self.export_timer.borrow().as_ref() {
            t.schedule(0);
        }
    }

    /// Opens saved files (the evidence, the episodes table and the episodes' CSVs): a good
    /// set becomes the current session (the one it replaces is kept as the first session
    /// when none is), a bad one leaves everything as it was and says what is wrong.
    fn open_files(&self) {
        let files = js_sys::Reflect::get(&self.els.open, &JsValue::from_str("files"))
            .unwrap_or(JsValue::UNDEFINED);
        let len = js_sys::Reflect::get(&files, &JsValue::from_str("length"))
            .ok()
            .and_then(|v| v.as_f64())
            .unwrap_or(0.0) as u32;
        if len == 0 {
            return;
        }
        let collected: Rc<RefCell<Vec<(String, String)>>> = Rc::new(RefCell::new(Vec::new()));
        let left = Rc::new(Cell::new(len));
        let failed: Rc<RefCell<Option<String>>> = Rc::new(RefCell::new(None));
        for i in 0..len {
            let Ok(file) = js_sys::Reflect::get_u32(&files, i) else {
                continue;
            };
            let name = js_sys::Reflect::get(&file, &JsValue::from_str("name"))
                .ok()
                .and_then(|n| n.as_string())
                .unwrap_or_default();
            let Ok(blob) = file.dyn_into::<web_sys::Blob>() else {
                left.set(left.get() - 1);
                continue;
            };
            let me = self.me.clone();
            let (collected, left, failed) = (collected.clone(), left.clone(), failed.clone());
            let file_name = name.clone();
            crate::ui::kit::input_file::read_text(&name, &blob, move |result| {
                match result {
                    Ok(text) => collected.borrow_mut().push((file_name, text)),
                    Err(_) => *failed.borrow_mut() = Some(file_name),
                }
                left.set(left.get().saturating_sub(1));
                if left.get() == 0 {
                    if let Some(p) = me.upgrade() {
                        let bad = failed.borrow().clone();
                        p.files_read(&collected.borrow(), bad);
                    }
                }
            });
        }
    }

    fn files_read(&self, files: &[(String, String)], unreadable: Option<String>) {
        let _ = js_sys::Reflect::set(
            &self.els.open,
            &JsValue::from_str("value"),
            &JsValue::from_str(""),
        );
        if let Some(name) = unreadable {
            self.show_open_error(ctx::t_strings("teleop-open-unreadable", &[("name", name)]));
            return;
        }
        match Session::from_files(files) {
            Ok(session) => {
                self.settle_episode();
                dom::show(&self.els.open_error, false);
                let old = std::mem::replace(&mut *self.session.borrow_mut(), session);
                if self.first.borrow().is_none() && !old.episodes.is_empty() {
                    *self.first.borrow_mut() = Some(old);
                    self.save_first();
                }
                self.labels.borrow_mut().close();
                self.enter_module(Module::FailureReview);
                self.show_status("teleop-opened");
            }
            Err(e) => self.show_open_error(open_error_text(&e)),
        }
    }

    fn show_open_error(&self, text: String) {
        self.els.open_error.set_text_content(Some(&text));
        dom::show(&self.els.open_error, true);
    }

    fn show_status(&self, id: &str) {
        self.els.status.set_text_content(Some(&ctx::t(id)));
    }

    /// Repeatability: the current session becomes the first, a second one starts (same pilot
    /// and device, preflight carried over) at Record ten.
    fn second_session(&self) {
        self.settle_episode();
        let (pilot, device, preflight, has) = {
            let s = self.session.borrow();
            (
                s.pilot_id.clone(),
                s.input_device,
                s.preflight,
                !s.episodes.is_empty(),
            )
        };
        if !has {
            self.show_status("teleop-second-nothing");
            return;
        }
        let mut second = Session::new(&pilot, device, &iso_now());
        second.preflight = preflight;
        let mut old = std::mem::replace(&mut *self.session.borrow_mut(), second);
        old.ended_at.get_or_insert_with(iso_now);
        *self.first.borrow_mut() = Some(old);
        self.save_first();
        self.labels.borrow_mut().close();
        self.enter_module(Module::RecordTen);
        self.show_status("teleop-second-started");
    }

    /// A new session (the current one is kept as the first session when it has episodes).
    fn new_session(&self) {
        self.settle_episode();
        let (pilot, device) = {
            let s = self.session.borrow();
            (s.pilot_id.clone(), s.input_device)
        };
        let old = std::mem::replace(
            &mut *self.session.borrow_mut(),
            Session::new(&pilot, device, &iso_now()),
        );
        if !old.episodes.is_empty() {
            *self.first.borrow_mut() = Some(old);
            self.save_first();
        }
        self.labels.borrow_mut().close();
        self.enter_module(Module::Preflight);
        self.show_status("teleop-new-started");
    }

    // ---- Review ----

    fn start_replay(&self, n: usize) {
        let entry: Option<EpisodeEntry> = self
            .session
            .borrow()
            .episodes
            .get(n.wrapping_sub(1))
            .cloned();
        let Some(entry) = entry else {
            return;
        };
        self.stop_replay();
        let first = entry
            .metrics
            .first_failure
            .as_ref()
            .map(|(step, ev)| (*step, *ev));
        let model = Rc::new(RefCell::new(Replay::new(n, entry.episode.clone(), first)));
        *self.replay.borrow_mut() = Some(model.clone());
        let me = self.me.clone();
        let widget = StepperWidget::new(
            &self.els.stepper_slot,
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
            move |_| {
                if let Some(p) = me.upgrade() {
                    p.draw_replay();
                }
            },
        );
        match widget {
            Ok(w) => *self.stepper.borrow_mut() = Some(w),
            Err(e) => web_sys::console::warn_1(&e),
        }
        self.els.review_title.set_text_content(Some(&ctx::t_strings(
            "teleop-review-title",
            &[("n", n.to_string())],
        )));
        self.timeline.borrow_mut().fit();
        self.draw_replay();
    }

    fn stop_replay(&self) {
        self.stepper.borrow_mut().take();
        self.replay.borrow_mut().take();
        dom::clear(&self.els.stepper_slot);
    }

    fn draw_replay(&self) {
        let Some(model) = self.replay.borrow().clone() else {
            return;
        };
        let Ok(replay) = model.try_borrow() else {
            return;
        };
        let ink = Ink::current();
        if let Some(g) = replay.geometry() {
            let mut view = self.view.borrow_mut();
            view.trail = replay.trail();
            view.draw(&g, None, ink);
        }
        self.timeline.borrow().draw(&replay, ink);
        let i = replay.index() as usize;
        if let Some(r) = i.checked_sub(1).and_then(|k| replay.episode.records.get(k)) {
            self.readouts.set("x", &metres(r.x));
            self.readouts.set("z", &metres(r.z));
            self.readouts.set("phi", &radians(r.phi));
            self.readouts.set("q1", &radians(r.q[0]));
            self.readouts.set("q2", &radians(r.q[1]));
            self.readouts.set("q3", &radians(r.q[2]));
            self.readouts
                .set("manipulability", &format!("{:.5}", r.manipulability));
            self.readouts.set("time", &format!("{:.2}", r.t_s));
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
        self.els.review_event.set_text_content(Some(&text));
    }

    // ---- Settings ----

    fn settings_edited(&self) {
        let checked = self.settings.borrow_mut().check();
        let Some(settings) = checked else {
            return;
        };
        *self.texts.borrow_mut() = self.settings.borrow().texts();
        self.session.borrow_mut().pilot_id = settings.pilot_id.clone();
        let apply_now = {
            let live = self.live.borrow();
            !live.started || live.ended
        };
        let same = self.live.borrow().settings == settings;
        if same {
            self.live.borrow_mut().pending = None;
        } else if apply_now {
            let ok = Sim::new(settings.config.clone());
            if let Ok(sim) = ok {
                let mut live = self.live.borrow_mut();
                live.sim = sim;
                live.settings = settings;
                live.pending = None;
                live.commands.clear();
                live.records.clear();
                live.started = false;
                live.ended = false;
                drop(live);
                self.view.borrow_mut().trail.clear();
            }
        } else {
            self.live.borrow_mut().pending = Some(settings);
            self.show_status("teleop-settings-pending");
        }
        self.write_url();
        self.save();
        self.request_frame();
    }

    fn write_url(&self) {
        let t = self.texts.borrow();
        let pairs: Vec<(&str, String)> = crate::view::teleop::FIELDS
            .iter()
            .filter(|f| **f != "pilot")
            .map(|f| (*f, t.get(f).to_string()))
            .collect();
        crate::ui::router::replace_query(&pairs);
    }

    // ---- Storage ----

    /// The session on screen: the restored notice and the label panel of its first unlabelled
    /// episode if it was restored (or the notice that the stored one did not load and where
    /// it is kept), its module, buttons and tables.
    fn show_session(&self, stored: Stored) {
        match stored {
            Stored::Restored => {
                let _ = dom::set_i18n(&self.els.restored, "teleop-restored");
                dom::show(&self.els.restored, true);
                let unlabelled = self.session.borrow().unlabelled();
                if let Some(n) = unlabelled {
                    self.open_label(n);
                }
            }
            Stored::Unreadable => {
                let _ = dom::set_i18n(&self.els.restored, "teleop-store-unreadable");
                dom::show(&self.els.restored, true);
            }
            Stored::None => {}
        }
        let module = self.session.borrow().module;
        self.enter_module(module);
        self.render_buttons();
        self.render_session();
    }

    /// While stored sessions are simulated again: the progress line shown, and everything
    /// below the header inert (nothing the pilot does can change a session not yet loaded).
    fn set_busy(&self, on: bool) {
        let _ = self
            .root
            .set_attribute("aria-busy", if on { "true" } else { "false" });
        for part in dom::matching(&self.root, ".tele > :not(.tele-head)").unwrap_or_default() {
            if on {
                let _ = part.set_attribute("inert", "");
            } else {
                let _ = part.remove_attribute("inert");
            }
        }
        self.render_loading();
        dom::show(&self.els.loading, on);
    }

    fn render_loading(&self) {
        if let Some(l) = self.loading.borrow().as_ref() {
            let text = ctx::t_args("teleop-loading", &[("percent", l.percent().into())]);
            self.els.loading.set_text_content(Some(&text));
        }
    }

    fn schedule_load(&self) {
        if let Some(t) = self.load_timer.borrow().as_ref() {
            t.schedule(0);
        }
    }

    /// One slice of the stored sessions simulated again; at the end, the sessions shown.
    fn load_slice(&self) {
        let started_ms = now_ms();
        let done = match self.loading.borrow_mut().as_mut() {
            Some(l) => l.run_until(started_ms + LOAD_SLICE_MS),
            None => return,
        };
        bench::record_load(now_ms() - started_ms);
        if !done {
            self.render_loading();
            self.schedule_load();
            return;
        }
        let Some(mut l) = self.loading.borrow_mut().take() else {
            return;
        };
        self.set_busy(false);
        let (session, stored) = l.outcome();
        *self.first.borrow_mut() = l.first_done;
        *self.session.borrow_mut() = session;
        self.show_session(stored);
        self.request_frame();
    }

    fn save(&self) {
        if self.loading.borrow().is_some() {
            // The stored session is not loaded yet: what is stored stays.
            return;
        }
        self.last_save_ms.set(now_ms());
        // Only the commands are stored (the records are simulated again on load).
        let in_progress = if self.recording_in_progress() {
            let live = self.live.borrow();
            Some(Episode {
                config: live.sim.config().clone(),
                start: live.sim.start_state().clone(),
                commands: live.commands.clone(),
                records: Vec::new(),
            })
        } else {
            None
        };
        let json = self.session.borrow().to_json(in_progress.as_ref());
        dom::storage_set(STORE_KEY, &json);
    }

    fn save_first(&self) {
        if self.loading.borrow().is_some() {
            return;
        }
        if let Some(first) = self.first.borrow().as_ref() {
            dom::storage_set(FIRST_KEY, &first.to_json(None));
        }
    }

    // ---- Rendering ----

    fn render_session(&self) {
        let s = self.session.borrow();
        if let Err(e) = episode_table::render_episodes(&self.els.episodes_body, &s) {
            web_sys::console::warn_1(&e);
        }
        let sum = s.summary();
        let first = self.first.borrow().as_ref().map(Session::summary);
        if let Err(e) =
            episode_table::render_comparison(&self.els.compare_body, first.as_ref(), &sum)
        {
            web_sys::console::warn_1(&e);
        }
        let line = ctx::t_strings(
            "teleop-session-line",
            &[
                ("pilot", s.pilot_id.clone()),
                ("attempted", sum.attempted.to_string()),
                ("successful", sum.successful.to_string()),
                ("target", RECORD_TARGET.to_string()),
            ],
        );
        self.els.session_line.set_text_content(Some(&line));
        for name in [EPISODES_NAME, EVIDENCE_NAME] {
            if let Ok(b) = find::<Element>(&self.root, &format!("button[data-download=\"{name}\"]"))
            {
                b.set_text_content(Some(&ctx::t_strings(
                    "teleop-download-file",
                    &[("file", name.to_string())],
                )));
            }
        }
        drop(s);
        self.render_modules_enabled();
        self.render_state_readouts();
    }

    fn relayout(&self) {
        self.view.borrow_mut().fit();
        self.timeline.borrow_mut().fit();
        if self.in_review() {
            self.draw_replay();
        } else {
            self.request_frame();
        }
    }

    fn relocalize(&self) {
        let _ = dom::relocalize(&self.root);
        self.exports.relocalize();
        self.render_loading();
        self.settings.borrow().render();
        self.labels.borrow().render();
        *self.shown_device.borrow_mut() = None;
        self.render_device_status();
        self.render_buttons();
        self.render_modules();
        self.render_session();
        if let Some(s) = self.stepper.borrow().as_ref() {
            s.relocalize();
        }
        if let Some(model) = self.replay.borrow().as_ref() {
            let n = model.borrow().number;
            self.els.review_title.set_text_content(Some(&ctx::t_strings(
                "teleop-review-title",
                &[("n", n.to_string())],
            )));
        }
        if self.in_review() {
            self.draw_replay();
        }
        self.request_frame();
    }
}

/// A saved-files problem in the current language.
fn open_error_text(e: &SessionError) -> String {
    use crate::teleop::session::EvidenceProblem as P;
    match e {
        SessionError::MissingFile { name } => {
            ctx::t_strings("teleop-open-missing", &[("name", name.clone())])
        }
        SessionError::NotJson { file, line, column } => ctx::t_strings(
            "teleop-open-json",
            &[
                ("name", file.clone()),
                ("line", line.to_string()),
                ("column", column.to_string()),
            ],
        ),
        SessionError::Evidence { problem } => {
            let id = match problem {
                P::NotObject => "teleop-open-ev-object",
                P::Missing { .. } => "teleop-open-ev-missing",
                P::Unexpected { .. } => "teleop-open-ev-unexpected",
                P::Type { .. } => "teleop-open-ev-type",
                P::Value { .. } => "teleop-open-ev-value",
            };
            ctx::t_strings(id, &[("field", problem.field().to_string())])
        }
        SessionError::Sha256Mismatch { name } => {
            ctx::t_strings("teleop-open-sha", &[("name", name.clone())])
        }
        SessionError::NotListed { name } => {
            ctx::t_strings("teleop-open-unlisted", &[("name", name.clone())])
        }
        SessionError::Table { row, column } => ctx::t_strings(
            "teleop-open-table",
            &[("row", row.to_string()), ("column", column.clone())],
        ),
        SessionError::Episode { file, detail } => ctx::t_strings(
            "teleop-open-episode",
            &[("name", file.clone()), ("detail", detail.clone())],
        ),
        SessionError::Replay { file } => {
            ctx::t_strings("teleop-open-replay", &[("name", file.clone())])
        }
    }
}
