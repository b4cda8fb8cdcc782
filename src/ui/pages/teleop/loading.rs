//! The stored sessions (the one in progress, then the first) simulated again on mount, in
//! slices of at most [`LOAD_SLICE_MS`]: ten minute-long episodes are 60,000 steps, several
//! hundred ms in one task. The first slice runs at mount; when that is not enough the rest
//! run in the next tasks, with a progress line (`data-tele="loading"`) and everything below
//! the header inert (nothing the pilot does can change a session not yet loaded).

use std::cell::RefCell;
use std::rc::{Rc, Weak};

use wasm_bindgen::JsValue;
use web_sys::Element;

use crate::teleop::session::{Session, SessionLoader};
use crate::ui::kit::scope::Scope;
use crate::ui::schedule::{now_ms, Timer};
use crate::ui::{ctx, dom};

use super::bench;
use super::files::Restore;
use super::markup::role;
use super::sessions::{iso_now, new_session, FIRST_KEY, STORE_KEY, UNREADABLE_KEY};

/// Longest slice of work simulating stored sessions again, ms (then the tab paints and
/// takes input before the next).
const LOAD_SLICE_MS: f64 = 12.0;
/// Steps simulated between two looks at the clock while loading (about 3 ms in wasm).
const LOAD_CHUNK_STEPS: usize = 500;

/// What became of the stored session on load.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Stored {
    /// None was stored.
    None,
    /// It was simulated again and is shown.
    Restored,
    /// It did not simulate again (or could not be read): a new session was started and the
    /// stored text kept under [`UNREADABLE_KEY`].
    Unreadable,
}

/// The sessions to show: the current one, the first one, and what became of the stored one.
pub struct Loaded {
    pub session: Session,
    pub first: Option<Session>,
    pub stored: Stored,
}

/// The stored sessions being simulated again.
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
    fn new(stored: Option<String>, first: Option<SessionLoader>, read: Restore) -> Loading {
        let session = stored.as_deref().and_then(read);
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
    /// device (or the defaults); the first session; and whether a stored session did not
    /// simulate (its text is then kept under [`UNREADABLE_KEY`]).
    fn outcome(&mut self) -> Loaded {
        let first = self.first_done.take();
        if let Some(session) = self.session_done.take() {
            return Loaded {
                session,
                first,
                stored: Stored::Restored,
            };
        }
        let session = match &self.interim {
            Some(s) => Session::new(&s.pilot_id, s.input_device, &iso_now()),
            None => new_session(),
        };
        let stored = match &self.stored {
            Some(text) => {
                dom::storage_set(UNREADABLE_KEY, text);
                Stored::Unreadable
            }
            None => Stored::None,
        };
        Loaded {
            session,
            first,
            stored,
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

/// What the loader hands over once the slices are done.
type OnLoaded = Box<dyn Fn(Loaded)>;

/// The loading component: the stored sessions still being simulated, the progress line and
/// the timer of the next slice.
pub struct Loader {
    root: Element,
    line: Element,
    loading: RefCell<Option<Loading>>,
    timer: Rc<Timer>,
    on_loaded: RefCell<Option<OnLoaded>>,
    _scope: Scope,
}

impl Loader {
    /// Reads the stored sessions with `read` (`None`: none is stored) and simulates them for
    /// one slice: the sessions to show at once (the stored ones when that was enough, else
    /// the stored session's pilot, device and module without episodes while the rest is
    /// simulated in slices). `root` holds the progress line.
    pub fn start(root: &Element, read: Option<Restore>) -> Result<(Rc<Loader>, Loaded), JsValue> {
        let line = role(root, "loading")?;
        let mut loading = match read {
            Some(read) => Loading::new(
                dom::storage_get(STORE_KEY),
                dom::storage_get(FIRST_KEY).and_then(|t| read(&t)),
                read,
            ),
            None => Loading::new(None, None, |_| None),
        };
        let started_ms = now_ms();
        let loaded = loading.run_until(started_ms + LOAD_SLICE_MS);
        bench::record_load(now_ms() - started_ms);
        let (shown, loading) = if loaded {
            (loading.outcome(), None)
        } else {
            let session = loading.interim.clone().unwrap_or_else(new_session);
            let shown = Loaded {
                session,
                first: None,
                stored: Stored::None,
            };
            (shown, Some(loading))
        };
        let loader = Rc::new_cyclic(|me: &Weak<Loader>| {
            let mut scope = Scope::new();
            let timer = scope.timer(me, Loader::slice);
            Loader {
                root: root.clone(),
                line,
                loading: RefCell::new(loading),
                timer,
                on_loaded: RefCell::new(None),
                _scope: scope,
            }
        });
        Ok((loader, shown))
    }

    /// Whether stored sessions are still being simulated.
    pub fn is_loading(&self) -> bool {
        self.loading.borrow().is_some()
    }

    /// Simulates the rest in slices (the page busy meanwhile), then hands the sessions to
    /// `on_loaded`.
    pub fn continue_in_slices(&self, on_loaded: impl Fn(Loaded) + 'static) {
        *self.on_loaded.borrow_mut() = Some(Box::new(on_loaded));
        if self.is_loading() {
            self.set_busy(true);
            self.timer.schedule(0);
        }
    }

    /// One slice; at the end, the sessions handed over.
    fn slice(&self) {
        let started_ms = now_ms();
        let done = match self.loading.borrow_mut().as_mut() {
            Some(l) => l.run_until(started_ms + LOAD_SLICE_MS),
            None => return,
        };
        bench::record_load(now_ms() - started_ms);
        if !done {
            self.render();
            self.timer.schedule(0);
            return;
        }
        let Some(mut l) = self.loading.borrow_mut().take() else {
            return;
        };
        self.set_busy(false);
        let loaded = l.outcome();
        if let Some(f) = self.on_loaded.borrow().as_ref() {
            f(loaded);
        }
    }

    /// The progress line shown, and everything below the header inert (or back).
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
        self.render();
        dom::show(&self.line, on);
    }

    /// The progress line in the current language.
    pub fn render(&self) {
        if let Some(l) = self.loading.borrow().as_ref() {
            let text = ctx::t_args("teleop-loading", &[("percent", l.percent().into())]);
            self.line.set_text_content(Some(&text));
        }
    }
}
