//! Robot Pilot practice (`#/teleop`): teleoperate the kernel's simulated arm
//! (`crate::teleop`) through a whole practice session of the Academy's five modules,
//! record and label episodes, replay them, compare two sessions and export the evidence.
//! A practice simulator: not a safety-rated controller, and not NVIDIA software.
//!
//! The page is a struct of components, one file each: `live` (the simulation at 100 Hz),
//! `devices`, `scene_view`, `readouts`, `controls` (the live arm's buttons), `session_panel`
//! (`module_bar` with the preflight, `episode_table`, the file opener), `label_panel`, the
//! kit's failure review (`crate::ui::kit::review`),
//! `settings`, `exports` and `loading` (both in slices), `files` (writing and reading the
//! session's files: a wasm chunk of their own), `gamepad_offer` and
//! the kit's `pilot_session::StorageWarning`, over `sessions` (the two sessions and their storage).
//! This file wires them: mount, events to components, the frame loop. The loop asks for
//! frames only while something can change (`crate::view::teleop_input::FrameDemand`). The
//! session is saved after every episode and label, every two seconds while recording and on
//! `pagehide`; an episode cut off by a reload comes back as interrupted.

mod bench;
mod controls;
pub(super) mod devices;
mod episode_table;
mod exports;
mod files;
mod gamepad_offer;
mod label_panel;
mod live;
mod loading;
mod markup;
mod module_bar;
mod readouts;
mod scene_view;
mod session_panel;
mod sessions;
mod settings;

use std::cell::RefCell;
use std::rc::{Rc, Weak};

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::{Element, Event as DomEvent, HtmlCanvasElement, KeyboardEvent, PointerEvent};

use crate::teleop::session::{episode_file_name, InputDevice, Module};
use crate::ui::kit::canvas::{focus_without_scroll, Ink};
use crate::ui::kit::chunk_fns::ChunkFns;
use crate::ui::kit::exercise_slot::ExerciseSlot;
use crate::ui::kit::late_page::LatePage;
use crate::ui::kit::pilot_session::{open_error_text, StorageWarning, RESTORE_TEXTS};
use crate::ui::kit::review::{Review, SharedReplay};
use crate::ui::kit::scope::{FrameLoop, Scope};
use crate::ui::kit::store;
use crate::ui::page::{MountCtx, Page, Shortcut};
use crate::ui::page_frame;
use crate::ui::schedule::now_ms;
use crate::ui::{ctx, dom};
use crate::view::exercises::{self, PageModel};
use crate::view::teleop_input::{key_action, KeyAction};

use controls::{Controls, Ended};
use devices::Devices;
use exports::Exports;
use gamepad_offer::GamepadOffer;
use label_panel::LabelPanel;
use live::{Live, SettingsEdit};
use loading::{Loaded, Loader, Stored};
use markup::{find, role, REVIEW};
use readouts::{EpisodeLine, Readouts};
use scene_view::SceneView;
use session_panel::{PanelAction, SessionPanel};
use sessions::Sessions;
use settings::SettingsForm;

/// The page's components.
struct Inner {
    me: Weak<Inner>,
    root: Element,
    canvas: HtmlCanvasElement,
    stage: Element,
    live: RefCell<Live>,
    devices: RefCell<Devices>,
    sessions: Sessions,
    view: RefCell<SceneView>,
    readouts: Readouts,
    controls: Controls,
    offer: GamepadOffer,
    storage: StorageWarning,
    panel: SessionPanel,
    settings: RefCell<SettingsForm>,
    labels: RefCell<LabelPanel>,
    review: Review,
    /// The episode replayed in the failure review.
    replay: RefCell<Option<SharedReplay<crate::teleop::Episode>>>,
    exports: Rc<Exports>,
    /// Writing and reading the session's files, once their chunk is here.
    files: ChunkFns<files::Files>,
    loader: Rc<Loader>,
    frame: RefCell<Option<FrameLoop>>,
    scope: RefCell<Scope>,
    /// The exercises section, made once the page is.
    exercises: RefCell<Option<ExerciseSlot>>,
}

/// The Robot Pilot page: built at once, or, when the browser holds a stored session, once
/// the files' chunk (which reads it) is here.
pub struct TeleopPage(LatePage<Rc<Inner>>);

impl Page for TeleopPage {
    fn mount(ctx: MountCtx) -> Result<TeleopPage, JsValue> {
        let stored = store::holds_any(&[sessions::STORE_KEY, sessions::FIRST_KEY]);
        LatePage::mount(
            ctx,
            stored,
            markup::page,
            RESTORE_TEXTS,
            files::load,
            Inner::mount,
        )
        .map(TeleopPage)
    }

    fn settled(&self) -> bool {
        self.0.is_built()
    }

    fn relocalize(&self) {
        self.0.relocalize(|p| p.relocalize());
    }

    fn set_projector(&self, _on: bool) {
        self.0.with(|p| p.relayout());
    }

    fn shortcuts(&self) -> Vec<Shortcut> {
        let mut keys = markup::KEYS.to_vec();
        keys.extend_from_slice(crate::ui::kit::keymap::STEPPER);
        keys
    }

    fn on_key(&self, event: &KeyboardEvent) -> bool {
        // The page body has focus (the canvas's own listener takes keys first): L stays
        // the shell's language key here.
        if event.code() == "KeyL" {
            return false;
        }
        self.0
            .with(|p| !p.loader.is_loading() && p.key_down(event))
            .unwrap_or(false)
    }

    fn on_key_over_control(&self, event: &KeyboardEvent) -> bool {
        self.0.with(|p| p.key_over_control(event)).unwrap_or(false)
    }
}

impl Drop for TeleopPage {
    fn drop(&mut self) {
        self.0.with(|p| p.save());
    }
}

impl Inner {
    /// Builds the page under `ctx.root`; `files` (the files' chunk) reads the stored sessions
    /// (`None`: none is stored, and the chunk is fetched now).
    fn mount(ctx: &MountCtx, files: Option<files::Files>) -> Result<Rc<Inner>, JsValue> {
        let root = ctx.root.clone();
        page_frame::fill(&root, &markup::page())?;
        dom::relocalize(&root)?;
        // The stored sessions are simulated again: at once when that is short, else in
        // slices after the first paint (the page inert meanwhile, its session the stored
        // one's pilot, device and module without episodes).
        let (loader, loaded) = Loader::start(&root, files.map(|f| f.restore))?;
        let (form, settings) = SettingsForm::mount(
            &root,
            &ctx.query,
            loaded.session.input_device,
            &loaded.session.pilot_id,
        )?;
        let stage: Element = role(&root, "stage")?;
        let canvas = find(&root, "[data-testid=\"teleop-canvas\"]")?;
        let live = Live::new(settings)?;
        let view = SceneView::find(&stage)?;
        let readouts = Readouts::find(&root)?;
        let controls = Controls::find(&root)?;
        let offer = GamepadOffer::find(&root)?;
        let storage = StorageWarning::find(&root, crate::teleop::session::EPISODES_NAME)?;
        let panel = SessionPanel::find(&root)?;
        let labels = LabelPanel::find(&root)?;
        let review = Review::find(&root, REVIEW)?;
        let exports = Exports::find(&root)?;
        let inner = Rc::new_cyclic(|me: &Weak<Inner>| Inner {
            me: me.clone(),
            root: root.clone(),
            canvas,
            stage,
            live: RefCell::new(live),
            devices: RefCell::new(Devices::default()),
            sessions: Sessions::new(loaded.session, loaded.first),
            view: RefCell::new(view),
            readouts,
            controls,
            offer,
            storage,
            panel,
            settings: RefCell::new(form),
            labels: RefCell::new(labels),
            review,
            replay: RefCell::new(None),
            exports,
            files: files.map_or_else(ChunkFns::default, ChunkFns::ready),
            loader,
            frame: RefCell::new(None),
            scope: RefCell::new(Scope::new()),
            exercises: RefCell::new(None),
        });
        inner.install()?;
        inner.view.borrow_mut().fit();
        inner.sessions.hold(inner.loader.is_loading());
        let me = inner.me.clone();
        inner.loader.continue_in_slices(move |loaded| {
            if let Some(p) = me.upgrade() {
                p.loaded(loaded);
            }
        });
        inner.show_session(loaded.stored);
        inner.settings.borrow().write_url();
        // Fetched once the page is painted, so that a download need not wait and the first
        // frame does not wait on its requests; a failure is said only when the pilot asks for
        // a file.
        crate::ui::schedule::after_paint_for(&inner.me, |p| p.with_files(false, |_, _| {}))?;
        let me = inner.me.clone();
        let exercises = ExerciseSlot::new(
            &root,
            &exercises::teleop::EXERCISES,
            Box::new(move |use_model| {
                if let Some(p) = me.upgrade() {
                    let live = p.live.borrow();
                    let (arm, q) = (&live.sim.config().arm, live.sim.state().q);
                    use_model(&PageModel::Teleop { arm, q });
                }
            }),
        )?;
        *inner.exercises.borrow_mut() = Some(exercises);
        Ok(inner)
    }

    /// Listeners: buttons, keys, pointer, form, files, storage on pagehide, resizes.
    fn install(&self) -> Result<(), JsValue> {
        let mut scope = self.scope.borrow_mut();
        let me = &self.me;
        let frame = scope.dirty_frame_loop(me, |p: &Inner, _bits, t| p.frame(t));
        frame.request();
        *self.frame.borrow_mut() = Some(frame);
        let c = &self.controls;
        scope.listen_for(&c.engage, "click", me, |p, _| p.toggle_engage())?;
        scope.listen_for(&c.gripper, "click", me, |p, _| p.toggle_gripper())?;
        scope.listen_for(&c.reset, "click", me, |p, _| p.reset())?;
        scope.listen_for(&c.end, "click", me, |p, _| p.end_episode())?;
        scope.listen_for(&self.offer.accept, "click", me, |p, _| {
            p.offer.hide();
            p.choose_device(InputDevice::Gamepad);
        })?;
        scope.listen_for(&self.offer.dismiss, "click", me, |p, _| {
            p.offer.decline();
            focus_without_scroll(&p.canvas);
        })?;
        scope.listen_for(&self.panel.bar.next, "click", me, |p, _| {
            let next = p.sessions.module().next();
            if p.sessions.allows(next) {
                p.enter_module(next);
            }
        })?;
        for (m, el) in &self.panel.bar.modules {
            let m = *m;
            scope.listen_for(el, "click", me, move |p, _| {
                if p.sessions.allows(m) {
                    p.enter_module(m);
                }
            })?;
        }
        for (d, el) in &self.panel.bar.devices {
            let d = *d;
            scope.listen_for(el, "click", me, move |p, _| p.choose_device(d))?;
        }
        // Keys on the canvas: taken before the shell sees them (L is "clear" here).
        let canvas = self.canvas.clone();
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
        let panel = self.labels.borrow().root.clone();
        scope.listen_for(&panel, "click", me, |p, e| p.label_click(e))?;
        // The episodes table's actions and the downloads (delegated).
        scope.listen_for(&self.root, "click", me, |p, e| p.panel_click(e))?;
        let form = self.settings.borrow().element.clone();
        scope.listen_for(&form, "input", me, |p, _| p.settings_edited())?;
        scope.listen_for(&form, "change", me, |p, _| p.settings_edited())?;
        scope.listen_for(&form, "submit", me, |_, e| e.prevent_default())?;
        scope.listen_for(&self.panel.open, "change", me, |p, _| p.open_files())?;
        scope.observe_resize(&[&self.stage, &self.review.root], me, |p| p.relayout())?;
        Ok(())
    }

    // ---- Keys, pointer, buttons ----

    /// A key went down on the canvas or the page body; `true` if taken.
    fn key_down(&self, event: &KeyboardEvent) -> bool {
        if self.in_review() {
            return self.review.on_key(event);
        }
        let code = event.code();
        let Some(action) = key_action(&code) else {
            return false;
        };
        let repeat = event.repeat();
        match action {
            KeyAction::Hold { .. } => self.devices.borrow_mut().press_key(&code),
            _ if repeat => {}
            KeyAction::ToggleGripper => self.toggle_gripper(),
            KeyAction::Reset => self.reset(),
            KeyAction::Clear => self.devices.borrow_mut().clear(),
            KeyAction::Engage => self.toggle_engage(),
        }
        self.request_frame();
        true
    }

    /// A key while a control has focus (the focus stays on a tab, button, check box or slider
    /// after a click): the arm's hold keys, K and R still drive it; Space and Enter stay the
    /// control's, L the shell's language key.
    fn key_over_control(&self, k: &KeyboardEvent) -> bool {
        if self.loader.is_loading() || self.in_review() {
            return false;
        }
        let driving = matches!(
            key_action(&k.code()),
            Some(KeyAction::Hold { .. } | KeyAction::ToggleGripper | KeyAction::Reset)
        );
        driving && self.key_down(k)
    }

    fn pointer_world(&self, e: &PointerEvent) -> (f64, f64) {
        let x = f64::from(e.offset_x());
        let y = f64::from(e.offset_y());
        self.view.borrow().transform.to_world(x, y)
    }

    fn pointer_down(&self, e: &DomEvent) {
        focus_without_scroll(&self.canvas);
        let Some(e) = e.dyn_ref::<PointerEvent>() else {
            return;
        };
        if self.in_review() || (e.pointer_type() == "mouse" && e.button() != 0) {
            return;
        }
        e.prevent_default();
        let _ = self.canvas.set_pointer_capture(e.pointer_id());
        let at = self.pointer_world(e);
        let tip = self.live.borrow().tip();
        self.devices.borrow_mut().grab(e.pointer_id(), at, tip);
        self.request_frame();
    }

    fn pointer_move(&self, e: &DomEvent) {
        let Some(e) = e.dyn_ref::<PointerEvent>() else {
            return;
        };
        let at = self.pointer_world(e);
        let moved = self.devices.borrow_mut().drag(e.pointer_id(), at);
        if moved {
            self.request_frame();
        }
    }

    fn pointer_up(&self, e: &DomEvent) {
        if let Some(e) = e.dyn_ref::<PointerEvent>() {
            self.devices.borrow_mut().release(e.pointer_id());
        }
    }

    fn toggle_engage(&self) {
        self.live.borrow_mut().toggle_engaged();
        self.render_buttons();
        self.request_frame();
    }

    /// K or the gripper button: toggles the commanded gripper while engaged; paused, the arm
    /// takes no command, so neither does the gripper.
    fn toggle_gripper(&self) {
        if !self.live.borrow().engaged {
            return;
        }
        self.devices.borrow_mut().toggle_gripper();
        self.render_buttons();
        self.request_frame();
    }

    fn request_frame(&self) {
        if let Some(f) = self.frame.borrow().as_ref() {
            f.request();
        }
    }

    // ---- The frame ----

    /// One displayed frame: poll the pad, step the simulation, draw, readouts.
    fn frame(&self, t_ms: f64) {
        if self.loader.is_loading() {
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
        if pad_changed || self.panel.bar.device_unwritten() {
            self.render_device_status(false);
        }
        if pad_toggled {
            self.render_buttons();
        }
        let device = self.sessions.current.borrow().input_device;
        {
            let d = self.devices.borrow();
            self.offer
                .polled(device, d.pad_name.as_deref(), d.pad_out.active);
        }
        let stepped = self.live.borrow_mut().advance(
            t_ms,
            &mut self.devices.borrow_mut(),
            device,
            &mut self.view.borrow_mut(),
        );
        if stepped.moved_by_device {
            let mut s = self.sessions.current.borrow_mut();
            if s.module == Module::Preflight && !s.preflight.moved {
                s.preflight.moved = true;
                drop(s);
                self.panel.bar.render_checks(&self.sessions);
            }
        }
        if stepped.ended {
            self.finish_episode();
        }
        if let Some(exercises) = self.exercises.borrow().as_ref() {
            exercises.changed();
        }
        self.draw_live(t_ms);
        bench::record(now_ms() - started_ms);
        if self.recording_in_progress() && self.sessions.save_due() {
            self.save();
        }
        let busy = {
            let devices = self.devices.borrow();
            self.live.borrow().frame_demand(&devices).needs_frames(t_ms)
        };
        self.animate(busy);
    }

    /// Keeps the frames coming, or lets them stop (idle: the next frame, asked for by an
    /// input, counts no time from this one).
    fn animate(&self, on: bool) {
        if !on {
            self.live.borrow_mut().idle();
        }
        if let Some(f) = self.frame.borrow().as_ref() {
            f.set_animating(on);
        }
    }

    fn recording_in_progress(&self) -> bool {
        let live = self.live.borrow();
        self.sessions.module().records() && live.started && !live.ended
    }

    /// Draws the live scene and writes the readouts.
    fn draw_live(&self, t_ms: f64) {
        let live = self.live.borrow();
        let g = live.sim.geometry();
        let clutch = self.devices.borrow().clutch.map(|c| c.target);
        self.view.borrow_mut().draw(&g, clutch, Ink::current());
        self.readouts
            .show_live(&live.sim, &g, live.stop.as_ref(), t_ms);
    }

    /// The readouts that change with the session, not the frame.
    fn render_state_readouts(&self) {
        let engaged = self.live.borrow().engaged;
        let episode = {
            let s = self.sessions.current.borrow();
            if s.module.records() {
                EpisodeLine::Recording {
                    done: s.episodes.len(),
                }
            } else {
                EpisodeLine::Practice
            }
        };
        let closed = self.devices.borrow().gripper_closed;
        self.readouts.show_state(episode, engaged, closed);
    }

    /// The engage and gripper buttons, and the readouts they set.
    fn render_buttons(&self) {
        let engaged = self.live.borrow().engaged;
        let closed = self.devices.borrow().gripper_closed;
        let device = self.sessions.current.borrow().input_device;
        self.controls.render(engaged, closed, device);
        self.render_state_readouts();
    }

    fn render_device_status(&self, rewrite: bool) {
        let device = self.sessions.current.borrow().input_device;
        let pad_name = self.devices.borrow().pad_name.clone();
        self.panel.bar.render_device(device, pad_name, rewrite);
    }

    // ---- Episodes ----

    /// End episode (the button): the episode ends here (recorded in Record ten).
    fn end_episode(&self) {
        let (has_steps, ended) = {
            let live = self.live.borrow();
            (!live.commands.is_empty(), live.ended)
        };
        if has_steps && !ended {
            self.finish_episode();
        } else if !has_steps {
            self.panel.show_status("teleop-end-nothing");
        }
    }

    /// Ends the current episode: recorded and offered for labelling in Record ten.
    fn finish_episode(&self) {
        let (episode, outcome) = {
            let mut live = self.live.borrow_mut();
            live.ended = true;
            (live.episode(), live.sim.done())
        };
        let mut ended = Ended {
            outcome,
            t_s: episode.records.last().map_or(0.0, |r| r.t_s),
            recorded: None,
            counted_success: false,
        };
        if !self.sessions.module().records() {
            self.controls.show_ended(ended);
            return;
        }
        let (n, counted_success) = self.sessions.record(episode);
        ended.recorded = Some(n);
        ended.counted_success = counted_success;
        self.controls.show_ended(ended);
        self.open_label(n);
        self.render_session();
        self.save();
    }

    /// Records the episode under way, if the module records (before the module or the
    /// session changes: an attempt is never dropped).
    fn settle_episode(&self) {
        let under_way = self.live.borrow().under_way();
        if under_way && self.sessions.module().records() {
            self.finish_episode();
        }
    }

    /// R or Reset: the scene back to its start (a new configuration if one is waiting); in
    /// Record ten an episode under way is ended and recorded first; in preflight the reset
    /// is checked against a fresh start state, bit for bit.
    fn reset(&self) {
        self.settle_episode();
        let verified = self.live.borrow_mut().reset();
        self.view.borrow_mut().trail.clear();
        self.devices.borrow_mut().reset();
        {
            let mut s = self.sessions.current.borrow_mut();
            if s.module == Module::Preflight && s.preflight.moved {
                s.preflight.reset_verified = Some(verified);
            }
        }
        self.controls.hide_ended();
        self.panel.hide_restored();
        self.panel.bar.render_checks(&self.sessions);
        self.render_buttons();
        self.render_modules();
        self.save();
        self.request_frame();
    }

    // ---- Modules and devices ----

    fn in_review(&self) -> bool {
        self.sessions.module() == Module::FailureReview
    }

    /// Switches to module `m`: the live arm (reset) or the review.
    fn enter_module(&self, m: Module) {
        self.settle_episode();
        let was = self.sessions.module();
        self.sessions.current.borrow_mut().module = m;
        if m == Module::FailureReview {
            self.devices.borrow_mut().clear();
            self.review.show(true);
            let pick = {
                let s = self.sessions.current.borrow();
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
            self.review.stop();
            self.replay.borrow_mut().take();
            self.review.show(false);
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
        self.panel.bar.render_modules(&self.sessions);
        // The repeatability table is its module's, shown under its tab only.
        if let Ok(Some(repeat)) = self.root.query_selector("[data-tele=\"repeat\"]") {
            dom::show(&repeat, self.sessions.module() == Module::Repeatability);
        }
        self.controls.show_live(!self.in_review());
        self.render_state_readouts();
    }

    fn choose_device(&self, device: InputDevice) {
        let old = {
            let mut s = self.sessions.current.borrow_mut();
            let old = s.input_device;
            s.input_device = device;
            if old != device {
                s.preflight = Default::default();
            }
            old
        };
        if old != device {
            // The sensitivities follow the device while they are the old device's defaults.
            self.settings.borrow().follow_device(old, device);
            self.settings_edited();
        }
        self.render_device_status(true);
        self.render_buttons();
        self.panel.bar.render_checks(&self.sessions);
        self.save();
    }

    // ---- Labels, the panel's buttons, files ----

    fn open_label(&self, n: usize) {
        let s = self.sessions.current.borrow();
        self.labels.borrow_mut().open_episode(&s, n);
    }

    fn label_click(&self, e: &DomEvent) {
        if !self.labels.borrow_mut().click(e) {
            return;
        }
        self.labels
            .borrow_mut()
            .confirm(&mut self.sessions.current.borrow_mut());
        self.render_session();
        self.save();
        let next = self.sessions.current.borrow().unlabelled();
        if let Some(next) = next {
            self.open_label(next);
        } else {
            focus_without_scroll(&self.canvas);
        }
    }

    fn panel_click(&self, e: &DomEvent) {
        match SessionPanel::action_of(e) {
            Some(PanelAction::Replay(n)) => {
                if !self.in_review() {
                    self.enter_module(Module::FailureReview);
                }
                self.start_replay(n);
            }
            Some(PanelAction::Relabel(n)) => self.open_label(n),
            Some(PanelAction::Download(file)) => self.with_files(true, move |p, f| {
                p.exports.download(f, &file, &p.sessions.current.borrow());
            }),
            Some(PanelAction::DownloadEpisodeCsvs) => self.with_files(true, |p, f| {
                let s = p.sessions.current.borrow();
                for e in &s.episodes {
                    p.exports.download(f, &episode_file_name(e.number), &s);
                }
            }),
            Some(PanelAction::SecondSession) => self.second_session(),
            Some(PanelAction::NewSession) => self.new_session(),
            None => {}
        }
    }

    /// Opens saved files (the evidence, the episodes table and the episodes' CSVs).
    fn open_files(&self) {
        let me = self.me.clone();
        self.panel.read_chosen(move |files, unreadable| {
            if let Some(p) = me.upgrade() {
                p.files_read(files, unreadable);
            }
        });
    }

    /// A good set of saved files becomes the current session (the one it replaces is kept
    /// as the first session when none is); a bad one leaves everything as it was and says
    /// what is wrong.
    fn files_read(&self, files: &[(String, String)], unreadable: Option<String>) {
        self.panel.clear_chosen();
        if let Some(name) = unreadable {
            let text = ctx::t_strings("teleop-open-unreadable", &[("name", name)]);
            self.panel.show_open_error(Some(text));
            return;
        }
        let files = files.to_vec();
        self.with_files(true, move |p, f| p.session_read(f, &files));
    }

    /// Runs `then` with the files' functions: at once if their chunk is here, else once it
    /// has come; if it cannot be fetched and `say` is set, the opener's error line says so. A
    /// later download or open tries again.
    fn with_files(&self, say: bool, then: impl FnOnce(&Inner, files::Files) + 'static) {
        ChunkFns::with(
            self,
            &self.me,
            |p| &p.files,
            files::load,
            say,
            Inner::show_files_failed,
            then,
        );
    }

    /// The opener's error line says that the files' chunk could not be fetched, or no longer.
    fn show_files_failed(&self, failed: bool) {
        self.panel
            .show_open_error(failed.then(|| ctx::t("teleop-files-unloaded")));
    }

    /// The session read from saved files, or what is wrong with them.
    fn session_read(&self, f: files::Files, files: &[(String, String)]) {
        match (f.read)(files) {
            Ok(session) => {
                self.settle_episode();
                self.panel.show_open_error(None);
                self.sessions.replace(session, true);
                self.labels.borrow_mut().close();
                self.enter_module(Module::FailureReview);
                self.panel.show_status("teleop-opened");
            }
            Err(e) => self.panel.show_open_error(Some(open_error_text(
                &e,
                crate::teleop::session::EPISODES_NAME,
            ))),
        }
    }

    /// Repeatability: the current session becomes the first, a second one starts.
    fn second_session(&self) {
        self.settle_episode();
        if !self.sessions.start_second() {
            self.panel.show_status("teleop-second-nothing");
            return;
        }
        self.labels.borrow_mut().close();
        self.enter_module(Module::RecordTen);
        self.panel.show_status("teleop-second-started");
    }

    /// A new session (the current one is kept as the first session when it has episodes).
    fn new_session(&self) {
        self.settle_episode();
        self.sessions.start_new();
        self.labels.borrow_mut().close();
        self.enter_module(Module::Preflight);
        self.panel.show_status("teleop-new-started");
    }

    // ---- Review ----

    fn start_replay(&self, n: usize) {
        let entry = self
            .sessions
            .current
            .borrow()
            .episodes
            .get(n.wrapping_sub(1))
            .cloned();
        let Some(entry) = entry else {
            return;
        };
        let me = self.me.clone();
        let replay = self.review.start_entry(n, &entry, move || {
            if let Some(p) = me.upgrade() {
                p.draw_replay();
            }
        });
        *self.replay.borrow_mut() = Some(replay);
        self.draw_replay();
    }

    /// The replayed step: the timeline, the scene and its trail, the step's numbers.
    fn draw_replay(&self) {
        if !self.review.draw_marks() {
            return;
        }
        let Some(model) = self.replay.borrow().clone() else {
            return;
        };
        let Ok(replay) = model.try_borrow() else {
            return;
        };
        let steps = replay.index() as usize;
        if let Some(sim) = replay.sim() {
            let mut view = self.view.borrow_mut();
            view.trail = replay.episode.records[..steps.min(replay.episode.records.len())]
                .iter()
                .map(|r| (r.x, r.z))
                .collect();
            view.draw(&sim.geometry(), None, Ink::current());
        }
        if let Some(r) = steps
            .checked_sub(1)
            .and_then(|k| replay.episode.records.get(k))
        {
            self.readouts.show_record(r);
        }
    }

    // ---- Settings ----

    fn settings_edited(&self) {
        let checked = self.settings.borrow_mut().edited();
        let Some(settings) = checked else {
            return;
        };
        self.sessions.current.borrow_mut().pilot_id = settings.pilot_id.clone();
        let edit = self.live.borrow_mut().edit(settings);
        match edit {
            SettingsEdit::Applied => self.view.borrow_mut().trail.clear(),
            SettingsEdit::Pending => self.panel.show_status("teleop-settings-pending"),
            SettingsEdit::Unchanged => {}
        }
        self.settings.borrow().write_url();
        self.save();
        self.request_frame();
    }

    // ---- The session on screen ----

    /// The session on screen: the restored notice and the label panel of its first unlabelled
    /// episode if it was restored (or the notice that the stored one did not load and where
    /// it is kept), its module, buttons and tables.
    fn show_session(&self, stored: Stored) {
        self.panel.show_restored(stored);
        if stored == Stored::Restored {
            let unlabelled = self.sessions.current.borrow().unlabelled();
            if let Some(n) = unlabelled {
                self.open_label(n);
            }
        }
        self.enter_module(self.sessions.module());
        self.render_buttons();
        self.render_session();
    }

    /// The stored sessions, simulated again in slices, are loaded.
    fn loaded(&self, loaded: Loaded) {
        self.sessions.hold(false);
        *self.sessions.first.borrow_mut() = loaded.first;
        *self.sessions.current.borrow_mut() = loaded.session;
        self.show_session(loaded.stored);
        self.request_frame();
    }

    /// Stores the session; says so when the browser refuses (the session goes on in memory).
    fn save(&self) {
        self.sessions.save(|| {
            self.recording_in_progress()
                .then(|| self.live.borrow().commands_only())
        });
        self.render_storage();
    }

    fn render_storage(&self) {
        let episodes = self.sessions.current.borrow().episodes.len();
        self.storage.render(self.sessions.unsaved(), episodes);
    }

    fn render_session(&self) {
        self.panel.render_session(&self.sessions);
        self.render_state_readouts();
    }

    fn relayout(&self) {
        self.view.borrow_mut().fit();
        self.review.fit();
        if self.in_review() {
            self.draw_replay();
        } else {
            self.request_frame();
        }
    }

    fn relocalize(&self) {
        let _ = dom::relocalize(&self.root);
        self.exports.relocalize();
        self.loader.render();
        self.settings.borrow().render();
        self.labels.borrow().render();
        self.render_device_status(true);
        self.render_buttons();
        self.controls.render_ended();
        self.offer.render();
        self.render_storage();
        self.render_modules();
        self.render_session();
        self.review.relocalize();
        if self.in_review() {
            self.draw_replay();
        }
        self.request_frame();
    }
}
