//! Robot Pilot on the SO-101 (`#/so101`): TheRobotStudio's five-joint arm in 3D
//! (`crate::so101`), flown with Isaac Lab's Se3Keyboard and Se3Gamepad mappings or the clutch
//! gizmo on the tool, through the same practice session as `#/teleop` (modules, labelled
//! episodes, replay, the repeatability summary, the Academy's evidence file). A practice
//! simulator: not a safety-rated controller, and not NVIDIA software.
//!
//! Components, one file each: `markup`, `devices` (keys, gamepad, gizmo clutch), `files` (the
//! session's files, written and read back: a wasm chunk of their own), `practice`
//! (the session, the first session and the episode being recorded), `session_view` (modules,
//! label panel, episodes table, summary, repeatability table, storage warning) and `views`
//! (the kit's orbit view of the world and the wrist camera), with the kit's failure review
//! (`crate::ui::kit::review`). This file wires them: mount, events, the frame loop (a fixed
//! 100 Hz simulation whatever the display rate, `crate::view::teleop_input::Accumulator`),
//! the settings in the URL, the saved-files opener, storage (a refused save leaves the
//! session in memory, said by the storage warning).

mod dataset_export;
mod devices;
mod files;
mod markup;
mod practice;
mod session_view;
mod views;

use std::cell::{Cell, RefCell};
use std::rc::{Rc, Weak};

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::{Element, Event as DomEvent, HtmlInputElement, HtmlSelectElement, KeyboardEvent};

use crate::so101::input::{key_action, press, KeyAction};
use crate::so101::sim::Command;
use crate::so101::{Episode, SceneConfig};
use crate::teleop::session::PracticeEpisode;
use crate::teleop::session::{
    category_from_id, clean_pilot_id, label_from_id, InputDevice, Module, Session, SessionLoader,
    EVIDENCE_NAME,
};
use crate::ui::kit::bench_log::push_ms;
use crate::ui::kit::chunk_fns::ChunkFns;
use crate::ui::kit::drag::DragEvent;
use crate::ui::kit::exercise_slot::ExerciseSlot;
use crate::ui::kit::frame::FrameLoop;
use crate::ui::kit::late_page::LatePage;
use crate::ui::kit::pilot_session::{clear_files, read_files, EPISODE_CSVS, RESTORE_TEXTS};
use crate::ui::kit::readouts::Readouts;
use crate::ui::kit::review::Review;
use crate::ui::kit::scope::Scope;
use crate::ui::kit::store;
use crate::ui::kit::{pilot_control, pilot_session};
use crate::ui::page::{MountCtx, Page, Shortcut};
use crate::ui::page_frame;
use crate::ui::schedule::now_ms;
use crate::ui::{ctx, dom};
use crate::view::exercises::{self, PageModel};
use crate::view::so101::{apply_settings, drag_axes, settings_texts, Handle, SETTING_KEYS};
use crate::view::teleop_input::{Accumulator, GAMEPAD_DEAD_ZONE};
use glam::DVec3;

use devices::Devices;
use practice::{Ended, Practice, FIRST_KEY, STORE_KEY};
use session_view::{OpenProblem, SessionView};
use views::{Shared, Views};

/// Save the session this often while recording, ms.
const SAVE_EVERY_MS: f64 = 2000.0;

/// The arm's buttons and notices.
struct Live {
    engage: Element,
    control: Element,
    gripper: Element,
    offer: Element,
    offer_text: Element,
    ended: Element,
    buttons: Element,
}

struct Inner {
    me: Weak<Inner>,
    root: Element,
    practice: Rc<RefCell<Practice>>,
    devices: Rc<RefCell<Devices>>,
    views: RefCell<Option<Views>>,
    readouts: Readouts,
    session: SessionView,
    live: Live,
    acc: Cell<Accumulator>,
    last_frame: Cell<Option<f64>>,
    /// When the session was last stored while flying (from the mount: an untouched page's
    /// first frame stores nothing; leaving the page stores it).
    last_save: Cell<f64>,
    offer_declined: Cell<bool>,
    frame: RefCell<Option<FrameLoop>>,
    scope: RefCell<Scope>,
    /// The views' hold on the state (kept alive with the page).
    shared: RefCell<Option<Rc<Shared>>>,
    review: Review,
    /// The stored session being simulated again, while it is; then the first session.
    loader: RefCell<Option<SessionLoader<Episode>>>,
    first_loader: RefCell<Option<SessionLoader<Episode>>>,
    load_timer: RefCell<Option<Rc<crate::ui::schedule::Timer>>>,
    restored: Element,
    /// Writing and reading the session's files, once their chunk is here.
    files: ChunkFns<files::Files>,
    /// The LeRobot dataset's export.
    dataset: dataset_export::DatasetSlot,
    /// The exercises section, made once the page is.
    exercises: RefCell<Option<ExerciseSlot>>,
}

/// Steps simulated again per slice of the load (a few ms of work).
const LOAD_SLICE_STEPS: usize = 1500;

/// What a slice of a stored session's load did.
enum LoadStep {
    /// No session being loaded.
    Idle,
    /// More slices to go.
    More,
    /// Finished: the session (`None`: it did not simulate again).
    Done(Option<Session<Episode>>),
}

/// One slice of the load in `slot`.
fn run_loader(slot: &RefCell<Option<SessionLoader<Episode>>>) -> LoadStep {
    let mut slot = slot.borrow_mut();
    let Some(loader) = slot.as_mut() else {
        return LoadStep::Idle;
    };
    match loader.run(LOAD_SLICE_STEPS) {
        Some(false) => LoadStep::More,
        step => LoadStep::Done(
            slot.take()
                .filter(|_| step.is_some())
                .and_then(|l| l.finish()),
        ),
    }
}

/// The SO-101 page: built at once, or, when the browser holds a stored session, once the
/// files' chunk (which reads it) is here.
pub struct So101Page(LatePage<Rc<Inner>>);

fn iso_now() -> String {
    js_sys::Date::new_0()
        .to_iso_string()
        .as_string()
        .unwrap_or_default()
}

fn find<T: JsCast>(root: &Element, selector: &str) -> Result<T, JsValue> {
    dom::find(root, selector, "so101")
}

impl Page for So101Page {
    fn mount(ctx: MountCtx) -> Result<So101Page, JsValue> {
        let stored = store::holds_any(&[STORE_KEY, FIRST_KEY]);
        LatePage::mount(
            ctx,
            stored,
            markup::page,
            RESTORE_TEXTS,
            files::load,
            Inner::mount,
        )
        .map(So101Page)
    }

    fn settled(&self) -> bool {
        self.0.is_built()
    }

    fn relocalize(&self) {
        self.0.relocalize(|p| {
            p.show_all();
            p.dataset.relocalize();
            if let Some(v) = p.views.borrow().as_ref() {
                v.relocalize();
            }
        });
    }

    fn set_projector(&self, _on: bool) {
        self.0.with(|p| {
            if let Some(v) = p.views.borrow().as_ref() {
                v.relayout();
            }
            p.review.fit();
            p.draw_replay();
        });
    }

    fn shortcuts(&self) -> Vec<Shortcut> {
        let mut keys = markup::KEYS.to_vec();
        keys.extend_from_slice(crate::ui::kit::orbit::KEYS);
        keys.extend_from_slice(crate::ui::kit::keymap::STEPPER);
        keys
    }

    fn on_key(&self, event: &KeyboardEvent) -> bool {
        if event.code() == "KeyL" {
            return false;
        }
        self.0.with(|p| p.key_down(event, false)).unwrap_or(false)
    }

    /// The arm's hold keys, K and R while a control has focus (the focus stays on a tab,
    /// button, check box or slider after a click); Space and Enter stay the control's.
    fn on_key_over_control(&self, event: &KeyboardEvent) -> bool {
        let driving = matches!(
            key_action(&event.code()),
            Some(KeyAction::Hold { .. } | KeyAction::ToggleGripper | KeyAction::Reset)
        );
        driving && self.0.with(|p| p.key_down(event, false)).unwrap_or(false)
    }
}

impl Drop for So101Page {
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
        // A stored session is simulated again in slices after the first paint (the page's
        // session meanwhile is the stored one's pilot, device and module without episodes).
        let restore = files.map(|f| f.restore);
        let loader = restore.and_then(|read| dom::storage_get(STORE_KEY).and_then(|t| read(&t)));
        let session = loader.as_ref().map_or_else(
            || Session::new("pilot", pilot_session::default_device(), &iso_now()),
            |l| l.session().clone(),
        );
        let first_loader =
            restore.and_then(|read| dom::storage_get(FIRST_KEY).and_then(|t| read(&t)));
        let config = apply_settings(&SceneConfig::default_for(false), &ctx.query);
        let practice = Practice::new(session, config)
            .ok_or_else(|| JsValue::from_str("so101: the default scene is refused"))?;
        let restored: Element = find(&root, "[data-so101=\"restored\"]")?;
        let live = Live {
            engage: find(&root, "[data-action=\"engage\"]")?,
            control: find(&root, "[data-so101=\"control\"]")?,
            gripper: find(&root, "[data-action=\"gripper\"]")?,
            offer: find(&root, "[data-testid=\"gamepad-offer\"]")?,
            offer_text: find(&root, "[data-so101=\"offer-text\"]")?,
            ended: find(&root, "[data-so101=\"ended\"]")?,
            buttons: find(&root, "[data-so101=\"live-buttons\"]")?,
        };
        let review = Review::find(&root, markup::REVIEW)?;
        let readouts = Readouts::find(&root)?;
        let session = SessionView::find(&root)?;
        let dataset = dataset_export::DatasetSlot::find(&root)?;
        let shared = Rc::new(Shared {
            practice: Rc::new(RefCell::new(practice)),
            devices: Rc::new(RefCell::new(Devices::default())),
        });
        let inner = Rc::new_cyclic(|me: &Weak<Inner>| Inner {
            me: me.clone(),
            root: root.clone(),
            practice: shared.practice.clone(),
            devices: shared.devices.clone(),
            views: RefCell::new(None),
            readouts,
            session,
            live,
            acc: Cell::new(Accumulator::default()),
            last_frame: Cell::new(None),
            last_save: Cell::new(now_ms()),
            offer_declined: Cell::new(false),
            frame: RefCell::new(None),
            scope: RefCell::new(Scope::new()),
            shared: RefCell::new(None),
            review,
            loader: RefCell::new(loader),
            first_loader: RefCell::new(first_loader),
            load_timer: RefCell::new(None),
            restored,
            files: files.map_or_else(ChunkFns::default, ChunkFns::ready),
            dataset,
            exercises: RefCell::new(None),
        });
        inner.write_settings();
        // The first slice of a stored session's load, then everything shown (`show_all`).
        inner.load_slice();
        if inner.loader.borrow().is_none() {
            inner.show_module();
        }
        // The views: their canvases are sized in their first frame, which comes after the
        // frame loop's layout task (kit::frame), so that the build lays nothing out.
        let me = inner.me.clone();
        let views = Views::new(&root, &shared, move |e, tool| {
            if let Some(p) = me.upgrade() {
                p.gizmo(e, tool);
            }
        })?;
        // The control state sits over the 3D view itself, below its camera buttons.
        if let Ok(Some(stage)) = root.query_selector(".so101-stage") {
            stage.append_child(&inner.live.control)?;
        }
        *inner.views.borrow_mut() = Some(views);
        *inner.shared.borrow_mut() = Some(shared);
        inner.install()?;
        // Fetched once the page is painted, so that a download need not wait and the first
        // frame does not wait on its requests; a failure is said only when the pilot asks for
        // a file.
        crate::ui::schedule::after_paint_for(&inner.me, |p| p.with_files(false, |_, _| {}))?;
        let me = inner.me.clone();
        let exercises = ExerciseSlot::new(
            &root,
            &exercises::so101::EXERCISES,
            Box::new(move |use_model| {
                if let Some(p) = me.upgrade() {
                    let q = p.practice.borrow().recorder.sim().state().q;
                    use_model(&PageModel::So101 { q });
                }
            }),
        )?;
        *inner.exercises.borrow_mut() = Some(exercises);
        Ok(inner)
    }

    fn install(&self) -> Result<(), JsValue> {
        let mut scope = self.scope.borrow_mut();
        let me = &self.me;
        let frame = scope.frame_loop(me, |p: &Inner, t| p.frame(t));
        frame.request();
        *self.frame.borrow_mut() = Some(frame);
        scope.listen_for(&self.root, "click", me, |p, e| p.click(e))?;
        let canvas = self
            .views
            .borrow()
            .as_ref()
            .map(|v| v.canvas())
            .ok_or_else(|| JsValue::from_str("so101: no view"))?;
        scope.listen_for(&canvas, "keydown", me, |p, e| {
            if let Some(k) = e.dyn_ref::<KeyboardEvent>() {
                if crate::ui::kit::keymap::has_command_modifier(k) || crate::ui::overlay::is_open()
                {
                    return;
                }
                if p.key_down(k, true) {
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
        scope.listen_for(&window, "blur", me, |p, _| p.devices.borrow_mut().clear())?;
        scope.listen_for(&window, "pagehide", me, |p, _| p.save())?;
        scope.listen_for(&window, "gamepadconnected", me, |p, _| p.request_frame())?;
        let form: Element = find(&self.root, "[data-so101=\"settings\"]")?;
        scope.listen_for(&form, "change", me, |p, _| p.settings_changed())?;
        scope.listen_for(&form, "submit", me, |_, e| e.prevent_default())?;
        let open = self.session.open.clone();
        scope.listen_for(&open, "change", me, |p, _| p.open_files())?;
        let review = self.review.root.clone();
        let wrist = self.views.borrow().as_ref().and_then(|v| v.wrist_stage());
        let wrist = wrist.unwrap_or_else(|| review.clone());
        scope.observe_resize(&[&review, &wrist], me, |p| {
            if let Some(v) = p.views.borrow().as_ref() {
                v.fit_wrist();
            }
            p.review.fit();
            p.draw_replay();
        })?;
        Ok(())
    }

    fn request_frame(&self) {
        if let Some(f) = self.frame.borrow().as_ref() {
            f.request();
        }
    }

    // ---- Input ----

    fn in_review(&self) -> bool {
        self.practice.borrow().session.module == Module::FailureReview
    }

    /// A key on the canvas (`on_canvas`) or the page; `true` if taken. Arrows and + / −
    /// orbit the view, but on the page in the failure review, where every key steps it.
    fn key_down(&self, event: &KeyboardEvent, on_canvas: bool) -> bool {
        if crate::ui::kit::keymap::is_text_entry(event.target()) {
            return false;
        }
        let review = self.in_review();
        if let Some(v) = self.views.borrow().as_ref() {
            let view_key =
                event.code().starts_with("Arrow") || matches!(event.key().as_str(), "+" | "-");
            if view_key && (on_canvas || !review) {
                return v.on_key(event);
            }
        }
        if review {
            return self.review.on_key(event);
        }
        let code = event.code();
        let Some(action) = key_action(&code) else {
            return false;
        };
        let repeat = event.repeat();
        match action {
            KeyAction::Hold { .. } => {
                let mut d = self.devices.borrow_mut();
                d.fresh |= press(&mut d.keys, &code);
            }
            _ if repeat => {}
            KeyAction::ToggleGripper => self.toggle_gripper(),
            KeyAction::Reset => self.reset(),
            KeyAction::Engage => self.toggle_engage(),
        }
        self.request_frame();
        true
    }

    /// Delegated clicks: the arm's buttons, modules, devices, labels, episodes, downloads.
    fn click(&self, e: &DomEvent) {
        let Some(target) = e.target().and_then(|t| t.dyn_into::<Element>().ok()) else {
            return;
        };
        let Ok(Some(el)) = target.closest("button") else {
            return;
        };
        let attr = |name: &str| el.get_attribute(name);
        if let Some(action) = attr("data-action") {
            let n = attr("data-episode").and_then(|n| n.parse::<usize>().ok());
            self.action(&action, n);
        } else if let Some(m) = attr("data-module").and_then(|m| Module::from_id(&m)) {
            self.enter_module(m);
        } else if let Some(d) = attr("data-device").and_then(|d| InputDevice::from_id(&d)) {
            self.practice.borrow_mut().set_device(d);
        } else if let Some(l) = attr("data-label").and_then(|l| label_from_id(&l)) {
            let mut p = self.practice.borrow_mut();
            p.choice.0 = Some(l);
            if l == crate::teleop::Label::Success {
                p.choice.1 = None;
            }
        } else if let Some(c) = attr("data-category").and_then(|c| category_from_id(&c)) {
            self.practice.borrow_mut().choice.1 = Some(c);
        } else if let Some(file) = attr("data-download").or_else(|| attr("data-save-now")) {
            self.download(&file);
            return;
        } else {
            return;
        }
        self.save();
        self.show_all();
        self.request_frame();
    }

    fn action(&self, action: &str, episode: Option<usize>) {
        match action {
            "engage" => self.toggle_engage(),
            "gripper" => self.toggle_gripper(),
            "reset" => self.reset(),
            "end-episode" => {
                let ended = self.practice.borrow_mut().end_episode();
                self.show_ended(ended);
            }
            "use-gamepad" => {
                dom::show(&self.live.offer, false);
                self.practice.borrow_mut().set_device(InputDevice::Gamepad);
            }
            "dismiss-gamepad" => {
                dom::show(&self.live.offer, false);
                self.offer_declined.set(true);
            }
            "confirm-label" => {
                let note = self.session.note.value();
                if self.practice.borrow_mut().confirm_label(&note) {
                    self.session.note.set_value("");
                }
            }
            "replay" => {
                if let Some(n) = episode {
                    self.enter_module(Module::FailureReview);
                    self.start_replay(n);
                }
            }
            "second-session" => {
                let started = self.practice.borrow_mut().start_second(&iso_now());
                self.session.status_id.set(Some(if started {
                    "teleop-second-started"
                } else {
                    "teleop-second-nothing"
                }));
                if started {
                    self.save_first();
                    self.show_module();
                }
            }
            "relabel" => {
                if let Some(n) = episode {
                    self.practice.borrow_mut().open_label(n);
                }
            }
            _ => return,
        }
        self.save();
        self.show_all();
        self.request_frame();
    }

    fn toggle_engage(&self) {
        let mut p = self.practice.borrow_mut();
        if p.recorder.sim().done().is_some() {
            p.recorder.reset();
        }
        p.engaged = !p.engaged;
        if p.engaged {
            p.ended = None;
        }
        drop(p);
        self.acc.set(Accumulator::default());
        self.show_all();
        self.request_frame();
    }

    /// K or the gripper button: toggles the commanded gripper while engaged; paused, the arm
    /// takes no command, so neither does the gripper.
    fn toggle_gripper(&self) {
        if !self.practice.borrow().engaged {
            return;
        }
        let mut d = self.devices.borrow_mut();
        d.gripper_closed = !d.gripper_closed;
        d.fresh = true;
        drop(d);
        self.show_all();
    }

    fn reset(&self) {
        self.devices.borrow_mut().clear();
        self.devices.borrow_mut().gripper_closed = false;
        let ended = {
            let mut p = self.practice.borrow_mut();
            p.reset();
            p.ended
        };
        self.show_ended(ended);
        self.save();
        self.show_all();
        self.request_frame();
    }

    /// The form's fields, by [`SETTING_KEYS`] (the check box as `true` / `false`).
    fn form_texts(&self) -> Vec<(String, String)> {
        SETTING_KEYS
            .iter()
            .filter_map(|k| {
                let el: Element = find(&self.root, &format!("[data-field=\"{k}\"]")).ok()?;
                let v = if let Some(i) = el.dyn_ref::<HtmlInputElement>() {
                    if i.type_() == "checkbox" {
                        i.checked().to_string()
                    } else {
                        i.value()
                    }
                } else {
                    el.dyn_ref::<HtmlSelectElement>()?.value()
                };
                Some((k.to_string(), v))
            })
            .collect()
    }

    fn settings_changed(&self) {
        let config = apply_settings(&self.practice.borrow().config, &self.form_texts());
        let pilot: Option<HtmlInputElement> = find(&self.root, "[data-field=\"pilot\"]").ok();
        let mut p = self.practice.borrow_mut();
        if let Some(pilot) = pilot {
            let clean = clean_pilot_id(&pilot.value());
            if !clean.is_empty() {
                p.session.pilot_id = clean;
            }
        }
        if config != p.config {
            p.set_config(config);
        }
        drop(p);
        self.write_settings();
        self.save();
        self.show_all();
        self.request_frame();
    }

    /// The form shows the config in use, and the URL holds it.
    fn write_settings(&self) {
        let p = self.practice.borrow();
        let texts = settings_texts(&p.config);
        for (k, v) in &texts {
            let Ok(el) = find::<Element>(&self.root, &format!("[data-field=\"{k}\"]")) else {
                continue;
            };
            if let Some(i) = el.dyn_ref::<HtmlInputElement>() {
                if i.type_() == "checkbox" {
                    i.set_checked(v == "true");
                } else {
                    i.set_value(v);
                }
            } else if let Some(s) = el.dyn_ref::<HtmlSelectElement>() {
                s.set_value(v);
            }
        }
        if let Ok(i) = find::<HtmlInputElement>(&self.root, "[data-field=\"pilot\"]") {
            i.set_value(&p.session.pilot_id);
        }
        crate::ui::router::replace_query(&texts);
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
        let mut problem = self.session.open_problem.borrow_mut();
        if failed {
            *problem = Some(OpenProblem::Unloaded);
        } else if matches!(*problem, Some(OpenProblem::Unloaded)) {
            *problem = None;
        }
        drop(problem);
        self.show_all();
    }

    /// Downloads `file` of the session (or, for [`EPISODE_CSVS`], every episode's CSV).
    fn download(&self, file: &str) {
        if file == crate::so101::dataset::ZIP_NAME {
            ChunkFns::with(
                self,
                &self.me,
                |p| &p.dataset.fns,
                dataset_export::load,
                true,
                |p, failed| p.dataset.show_unloaded(failed),
                |p, open| p.dataset.ui(open).start(&p.practice.borrow().session),
            );
            return;
        }
        let file = file.to_string();
        self.with_files(true, move |p, f| p.download_with(f, &file));
    }

    fn download_with(&self, f: files::Files, file: &str) {
        let now = iso_now();
        let files = (f.write)(&self.practice.borrow().session, &now);
        let every = file == EPISODE_CSVS;
        let episodes: Vec<String> = if every {
            let p = self.practice.borrow();
            p.session
                .episodes
                .iter()
                .map(|e| Episode::episode_file_name(e.number))
                .collect()
        } else {
            vec![file.to_string()]
        };
        // The evidence lists the LeRobot dataset written from the labels as they are.
        let dataset = self.dataset.artifact_for(&self.practice.borrow().session);
        let evidence = dataset.map(|d| {
            (f.evidence)(
                &self.practice.borrow().session,
                &now,
                std::slice::from_ref(&d),
            )
        });
        for (name, text) in files.iter().filter(|(n, _)| episodes.contains(n)) {
            let text = match &evidence {
                Some(e) if name == EVIDENCE_NAME => e,
                _ => text,
            };
            let mime = if name.ends_with(".json") {
                "application/json"
            } else {
                "text/csv"
            };
            if let Err(e) = crate::ui::download::download_text(name, text, mime) {
                web_sys::console::warn_1(&e);
            }
        }
    }

    /// Stores the session (not while a stored one is still being loaded); a refusal is said
    /// by the storage warning, the session going on in memory.
    fn save(&self) {
        if self.loader.borrow().is_some() {
            return;
        }
        let json = self.practice.borrow().to_json();
        let refused = store::save(STORE_KEY, &json).is_err();
        let (_, first) = self.session.unsaved.get();
        self.session.unsaved.set((refused, first));
        self.show_storage();
    }

    /// Stores the first session.
    fn save_first(&self) {
        if self.first_loader.borrow().is_some() {
            return;
        }
        let Some(json) = self.practice.borrow().first_json() else {
            return;
        };
        let refused = store::save(FIRST_KEY, &json).is_err();
        let (current, _) = self.session.unsaved.get();
        self.session.unsaved.set((current, refused));
        self.show_storage();
    }

    fn show_storage(&self) {
        if let Ok(p) = self.practice.try_borrow() {
            self.session.show(&p);
        }
    }

    /// Opens saved files (the evidence, the episodes table and the episodes' CSVs).
    fn open_files(&self) {
        let me = self.me.clone();
        read_files(&self.session.open, move |files, unreadable| {
            if let Some(p) = me.upgrade() {
                p.files_read(files, unreadable);
            }
        });
    }

    /// A good set of saved files becomes the session (the one it replaces kept as the first
    /// session when there is none), shown in the failure review; a bad one leaves everything
    /// as it was and says what is wrong.
    fn files_read(&self, files: &[(String, String)], unreadable: Option<String>) {
        clear_files(&self.session.open);
        if let Some(name) = unreadable {
            *self.session.open_problem.borrow_mut() = Some(OpenProblem::Unreadable(name));
            self.show_all();
            return;
        }
        let files = files.to_vec();
        self.with_files(true, move |p, f| p.session_read(f, &files));
    }

    fn session_read(&self, f: files::Files, files: &[(String, String)]) {
        let problem = match (f.read)(files) {
            Ok(session) => {
                self.review.stop();
                let mut p = self.practice.borrow_mut();
                p.replay = None;
                p.replace(session);
                drop(p);
                self.save_first();
                self.session.status_id.set(Some("teleop-opened"));
                self.enter_module(Module::FailureReview);
                self.save();
                None
            }
            Err(e) => Some(OpenProblem::Session(e)),
        };
        *self.session.open_problem.borrow_mut() = problem;
        self.show_all();
    }

    // ---- Modules and the failure review ----

    /// Module `m`: the failure review, or the live arm.
    fn enter_module(&self, m: Module) {
        let was_review = self.in_review();
        {
            let mut p = self.practice.borrow_mut();
            p.session.module = m;
            // Back from the review, ready to move.
            if was_review && m != Module::FailureReview {
                p.engaged = true;
            }
        }
        self.show_module();
        self.request_frame();
    }

    /// The module's part of the page: in the failure review the review (the first episode
    /// with a failure, else the first, unless one is shown), no live buttons and the live arm
    /// paused; elsewhere the live arm (`enter_module` engages it on the way back).
    fn show_module(&self) {
        let review = self.in_review();
        dom::show(&self.live.buttons, !review);
        if review {
            dom::show(&self.live.ended, false);
        }
        self.review.show(review);
        if !review {
            if self.practice.borrow_mut().replay.take().is_some() {
                self.review.stop();
            }
            return;
        }
        // The live arm rests while its episodes are reviewed (no frames, nothing announced).
        self.practice.borrow_mut().engaged = false;
        if self.practice.borrow().replay.is_some() {
            return;
        }
        self.devices.borrow_mut().clear();
        let pick = {
            let p = self.practice.borrow();
            let e = &p.session.episodes;
            e.iter()
                .find(|e| e.metrics.first_failure.is_some())
                .or(e.first())
                .map(|e| e.number)
        };
        match pick {
            Some(n) => self.start_replay(n),
            None => {
                self.review.stop();
                self.review.show_note(&ctx::t("so101-review-empty"));
            }
        }
    }

    /// Replays episode `n` under the review's stepper.
    fn start_replay(&self, n: usize) {
        let entry = self
            .practice
            .borrow()
            .session
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
        self.practice.borrow_mut().replay = Some(replay);
        self.draw_replay();
    }

    /// The replayed step: the timeline, the readouts and both views.
    fn draw_replay(&self) {
        if !self.review.draw_marks() {
            return;
        }
        self.show_readouts();
        if let Ok(v) = self.views.try_borrow() {
            if let Some(v) = v.as_ref() {
                v.redraw();
            }
        }
    }

    /// One slice of the stored sessions' load (the session, then the first session); the
    /// next in a task of its own.
    fn load_slice(&self) {
        let t0 = now_ms();
        let mut more = false;
        match run_loader(&self.loader) {
            LoadStep::More => more = true,
            LoadStep::Done(session) => {
                if let Some(session) = session {
                    self.practice.borrow_mut().session = session;
                    dom::show(&self.restored, true);
                }
                self.show_module();
                more = self.first_loader.borrow().is_some();
            }
            LoadStep::Idle => match run_loader(&self.first_loader) {
                LoadStep::More => more = true,
                LoadStep::Done(first) => self.practice.borrow_mut().first = first,
                LoadStep::Idle => {}
            },
        }
        push_ms("__so101LoadMs", now_ms() - t0, 5000);
        if more {
            let mut timer = self.load_timer.borrow_mut();
            let timer = timer.get_or_insert_with(|| {
                self.scope
                    .borrow_mut()
                    .timer(&self.me, |p: &Inner| p.load_slice())
            });
            timer.schedule(0);
        }
        self.show_all();
    }

    // ---- The frame ----

    fn frame(&self, t: f64) {
        let t0 = now_ms();
        self.frame_work(t);
        push_ms("__so101FrameMs", now_ms() - t0, 5000);
    }

    /// A frame: poll the devices, step the simulation, write the readouts, draw both views.
    fn frame_work(&self, t: f64) {
        let elapsed = self.last_frame.get().map_or(0.0, |last| t - last);
        self.last_frame.set(Some(t));
        let pad_input = self.devices.borrow_mut().poll_pad(GAMEPAD_DEAD_ZONE);
        if pad_input {
            self.offer_pad();
        }
        let fresh = std::mem::take(&mut self.devices.borrow_mut().fresh);
        let mut acc = self.acc.get();
        let n = if self.loader.borrow().is_some() {
            0
        } else {
            acc.steps(elapsed, fresh)
        };
        self.acc.set(acc);
        let preflight = self.practice.borrow().session.preflight;
        let ended = self.run_steps(n);
        if n > 0 {
            self.announce_pose();
            if let Some(exercises) = self.exercises.borrow().as_ref() {
                exercises.changed();
            }
        }
        if self.practice.borrow().session.preflight != preflight {
            self.show_all();
        }
        if ended.is_some() {
            self.show_ended(ended);
            self.save();
            self.show_all();
        } else if self.practice.borrow().engaged && t - self.last_save.get() > SAVE_EVERY_MS {
            self.last_save.set(t);
            self.save();
        }
        self.show_readouts();
        if let Some(v) = self.views.borrow().as_ref() {
            v.redraw();
        }
        let keep = {
            let p = self.practice.borrow();
            let d = self.devices.borrow();
            p.engaged || d.keys.any() || d.clutch.is_some() || d.pad_name.is_some()
        };
        if keep {
            self.request_frame();
        } else {
            self.last_frame.set(None);
            self.acc.set(Accumulator::default());
        }
    }

    /// `n` steps of the simulation (or of a replay); how the episode ended, if it did.
    fn run_steps(&self, n: u32) -> Option<Ended> {
        let mut p = self.practice.borrow_mut();
        let d = self.devices.borrow();
        let cmd = Command::with_axes(d.axes(), d.gripper_closed);
        drop(d);
        for _ in 0..n {
            p.step(&cmd);
            if p.ended.is_some() && !p.engaged {
                return p.ended;
            }
        }
        None
    }

    /// The tool's pose for screen readers, once the arm has stopped moving for a moment.
    fn announce_pose(&self) {
        let record = self.practice.borrow().recorder.sim().snapshot();
        self.readouts.announce_settled(800.0, move || {
            let gripper = ctx::t(if record.gripper_closed {
                "teleop-gripper-closed"
            } else {
                "teleop-gripper-open"
            });
            ctx::t_strings(
                "so101-live-pose",
                &[
                    ("x", crate::view::so101::mm(record.tool[0])),
                    ("y", crate::view::so101::mm(record.tool[1])),
                    ("z", crate::view::so101::mm(record.tool[2])),
                    ("gripper", gripper),
                    ("error", crate::view::so101::deg(record.orientation_error)),
                ],
            )
        });
    }

    fn offer_pad(&self) {
        let p = self.practice.borrow();
        if p.session.input_device == InputDevice::Gamepad || self.offer_declined.get() {
            return;
        }
        let name = self.devices.borrow().pad_name.clone().unwrap_or_default();
        self.live
            .offer_text
            .set_text_content(Some(&ctx::t_strings("teleop-pad-offer", &[("name", name)])));
        dom::show(&self.live.offer, true);
    }

    fn show_ended(&self, ended: Option<Ended>) {
        let text = match ended {
            Some(Ended::Outcome(_, 0) | Ended::Pilot(0)) => ctx::t("so101-ended-practice"),
            Some(Ended::Outcome(o, n)) => {
                ctx::t_strings(&format!("so101-ended-{}", o.id()), &[("n", n.to_string())])
            }
            Some(Ended::Pilot(n)) => ctx::t_strings("so101-ended-pilot", &[("n", n.to_string())]),
            None => String::new(),
        };
        self.live.ended.set_text_content(Some(&text));
        dom::show(&self.live.ended, ended.is_some());
        self.readouts.announce(&text);
    }

    fn show_all(&self) {
        let p = self.practice.borrow();
        self.session.show(&p);
        let engaged = p.engaged;
        let _ = pilot_control::show(&self.live.control, engaged, p.session.input_device);
        let _ = self
            .live
            .engage
            .set_attribute("aria-pressed", if engaged { "true" } else { "false" });
        let _ = dom::set_i18n(
            &self.live.engage,
            if engaged {
                "teleop-pause"
            } else {
                "teleop-engage"
            },
        );
        let closed = self.devices.borrow().gripper_closed;
        let _ = self
            .live
            .gripper
            .set_attribute("aria-disabled", if engaged { "false" } else { "true" });
        let _ = dom::set_i18n(
            &self.live.gripper,
            if closed {
                "teleop-gripper-open-button"
            } else {
                "teleop-gripper-close-button"
            },
        );
        drop(p);
        self.show_readouts();
    }

    fn show_readouts(&self) {
        let p = self.practice.borrow();
        let record = views::shown_record(&p);
        views::write_readouts(&self.readouts, &p, &record);
    }
}

impl Inner {
    /// A drag on the gizmo: the clutch holds while the pointer does.
    fn gizmo(&self, e: DragEvent<Handle>, tool: DVec3) {
        let camera = self
            .views
            .try_borrow()
            .ok()
            .and_then(|v| v.as_ref().map(|v| v.orbit.camera()));
        let Some(camera) = camera else {
            return;
        };
        let Ok(mut d) = self.devices.try_borrow_mut() else {
            return;
        };
        match e {
            DragEvent::Start { handle, at, .. } => {
                d.clutch = Some(devices::Clutch {
                    handle,
                    start: at,
                    now: at,
                });
                d.clutch_axes = [0.0; 6];
                d.fresh = true;
            }
            DragEvent::Move { at, .. } => {
                if let Some(c) = d.clutch.as_mut() {
                    c.now = at;
                    let (h, s) = (c.handle, c.start);
                    d.clutch_axes = drag_axes(&camera, h, tool, s, at);
                    d.fresh = true;
                }
            }
            DragEvent::End { .. } => {
                d.clutch = None;
                d.clutch_axes = [0.0; 6];
            }
            _ => {}
        }
        drop(d);
        self.request_frame();
    }
}
