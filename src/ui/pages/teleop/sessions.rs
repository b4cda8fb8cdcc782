//! The session in progress and the first session (the repeatability comparison's other
//! side), and their copies in localStorage: which modules they open, how one session gives
//! way to another (the one replaced is kept as the first when it has episodes), and saving.
//! Only the commands of an episode are stored; its records are simulated again on load.
//! A store the browser refuses (its storage full, or turned off) leaves the sessions in
//! memory, unchanged, and marks them unsaved until a later store succeeds.

use std::cell::{Cell, RefCell};

use crate::teleop::session::{Module, Session};
use crate::teleop::{Episode, Label};
use crate::ui::kit::store;
use crate::ui::schedule::now_ms;

/// localStorage key of the session in progress.
pub const STORE_KEY: &str = "bsv.teleop.session";
/// localStorage key of the first session (for the repeatability comparison).
pub const FIRST_KEY: &str = "bsv.teleop.first";
/// Where a stored session that no longer simulates is kept (the page then starts a new one,
/// and saving it would otherwise overwrite the pilot's only copy).
pub const UNREADABLE_KEY: &str = "bsv.teleop.session.unreadable";
/// Save the session in progress at least this often while recording, ms.
const SAVE_EVERY_MS: f64 = 2000.0;

/// The time now, ISO 8601.
pub fn iso_now() -> String {
    js_sys::Date::new_0()
        .to_iso_string()
        .as_string()
        .unwrap_or_default()
}

/// A new session with the default pilot id and the keyboard.
pub fn new_session() -> Session {
    Session::new(
        "pilot",
        crate::ui::kit::pilot_session::default_device(),
        &iso_now(),
    )
}

/// The two sessions.
pub struct Sessions {
    pub current: RefCell<Session>,
    pub first: RefCell<Option<Session>>,
    /// Saving is held while the stored sessions are still being loaded (what is stored
    /// stays until they are).
    held: Cell<bool>,
    last_save_ms: Cell<f64>,
    /// The browser refused the last store of the current session, of the first session.
    unsaved: Cell<(bool, bool)>,
}

impl Sessions {
    pub fn new(current: Session, first: Option<Session>) -> Sessions {
        Sessions {
            current: RefCell::new(current),
            first: RefCell::new(first),
            held: Cell::new(false),
            last_save_ms: Cell::new(0.0),
            unsaved: Cell::new((false, false)),
        }
    }

    /// Holds (or releases) saving.
    pub fn hold(&self, on: bool) {
        self.held.set(on);
    }

    /// The current session's module.
    pub fn module(&self) -> Module {
        self.current.borrow().module
    }

    /// Whether module `m` can be entered.
    pub fn allows(&self, m: Module) -> bool {
        let s = self.current.borrow();
        match m {
            Module::Preflight | Module::BasicControl => true,
            Module::RecordTen => s.preflight.passed() || !s.episodes.is_empty(),
            Module::FailureReview => !s.episodes.is_empty(),
            Module::Repeatability => !s.episodes.is_empty() || self.first.borrow().is_some(),
        }
    }

    /// `session` becomes the current one; the one it replaces becomes the first session when
    /// it has episodes (with `keep_first`, only when there is no first session yet).
    pub fn replace(&self, session: Session, keep_first: bool) {
        let old = std::mem::replace(&mut *self.current.borrow_mut(), session);
        if keep_first && self.first.borrow().is_some() {
            return;
        }
        if !old.episodes.is_empty() {
            *self.first.borrow_mut() = Some(old);
            self.save_first();
        }
    }

    /// Repeatability: the current session becomes the first (its end time set if it has
    /// none), a second one starts (same pilot and device, preflight carried over) at Record
    /// ten. `false` when the current one has no episodes (nothing changes).
    pub fn start_second(&self) -> bool {
        let first = self.current.borrow_mut().start_second(&iso_now());
        let Some(first) = first else {
            return false;
        };
        *self.first.borrow_mut() = Some(first);
        self.save_first();
        true
    }

    /// A new session for the same pilot and device.
    pub fn start_new(&self) {
        let (pilot, device) = {
            let s = self.current.borrow();
            (s.pilot_id.clone(), s.input_device)
        };
        self.replace(Session::new(&pilot, device, &iso_now()), false);
    }

    /// Records a just-ended episode in the current session: its number, and whether it was
    /// recorded labelled SUCCESS. A SUCCESS the rules propose (the goal held, no failure
    /// event before it) is so labelled at once, as Isaac Lab's recorder marks a successful
    /// demonstration: it counts in the figures and the evidence, and the pilot may relabel it.
    pub fn record(&self, episode: Episode) -> (usize, bool) {
        let mut s = self.current.borrow_mut();
        let n = s.record(episode, false);
        let Some(entry) = s.episodes.last_mut() else {
            return (n, false);
        };
        let success = entry.proposal() == (Label::Success, None);
        if success {
            entry.set_label(Label::Success, None, "");
        }
        (n, success)
    }

    /// Whether a save is due while recording.
    pub fn save_due(&self) -> bool {
        now_ms() - self.last_save_ms.get() > SAVE_EVERY_MS
    }

    /// Stores the current session with the episode under way (`in_progress`, asked only
    /// when saving: its commands).
    pub fn save(&self, in_progress: impl FnOnce() -> Option<Episode>) {
        if self.held.get() {
            return;
        }
        self.last_save_ms.set(now_ms());
        let in_progress = in_progress();
        let json = self.current.borrow().to_json(in_progress.as_ref());
        let refused = store::save(STORE_KEY, &json).is_err();
        self.unsaved.set((refused, self.unsaved.get().1));
    }

    /// Stores the first session.
    pub fn save_first(&self) {
        if self.held.get() {
            return;
        }
        if let Some(first) = self.first.borrow().as_ref() {
            let refused = store::save(FIRST_KEY, &first.to_json(None)).is_err();
            self.unsaved.set((self.unsaved.get().0, refused));
        }
    }

    /// Whether the browser refused to store a session (it lives only in this tab).
    pub fn unsaved(&self) -> bool {
        let (current, first) = self.unsaved.get();
        current || first
    }
}
