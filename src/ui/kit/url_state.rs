//! A page's state in the URL: the [`UrlState`] trait (read from the decoded query, reporting
//! the keys it could not use; write back as ordered pairs), a debounced [`UrlWriter`] over
//! [`router::replace_query`], and the [`UrlNotice`] that tells the user, in their language,
//! which keys of the link they opened were ignored or invalid.
//!
//! The pure part (the trait, [`IgnoredKey`]) is in [`crate::view::url`], so a page's round
//! trip `read(write(s)) == s` is a native `cargo test`.

use std::cell::{Cell, RefCell};
use std::rc::{Rc, Weak};

use wasm_bindgen::JsValue;
use web_sys::Element;

use crate::ui::kit::scope::Scope;
use crate::ui::schedule::{now_ms, Timer};
use crate::ui::{ctx, dom, router};
pub use crate::view::url::{IgnoredKey, IgnoredReason, UrlState};

/// How long edits wait before the URL is rewritten, ms.
pub const DEBOUNCE_MS: i32 = 300;

/// Rewrites the URL with the page's pairs: at once ([`UrlWriter::write_now`], e.g. on drag
/// end) or debounced ([`UrlWriter::schedule`], while typing). Owned by the page's scope.
pub struct UrlWriter {
    timer: Rc<Timer>,
    write: Box<dyn Fn()>,
    /// When [`UrlWriter::write_at_most_every`] last wrote, ms.
    written: Cell<f64>,
}

impl UrlWriter {
    /// A writer of `pairs(page)`, its timer held by `scope`.
    pub fn new<P: 'static>(
        scope: &mut Scope,
        page: &Weak<P>,
        pairs: impl Fn(&P) -> Vec<(String, String)> + 'static,
    ) -> UrlWriter {
        let pairs = Rc::new(pairs);
        let timer = {
            let pairs = pairs.clone();
            scope.timer(page, move |p| router::replace_query(&pairs(p)))
        };
        let page = page.clone();
        let write = Box::new(move || {
            if let Some(p) = page.upgrade() {
                router::replace_query(&pairs(&p));
            }
        });
        UrlWriter {
            timer,
            write,
            written: Cell::new(0.0),
        }
    }

    /// Writes now (and drops a pending debounced write).
    pub fn write_now(&self) {
        self.timer.cancel();
        (self.write)();
    }

    /// Writes [`DEBOUNCE_MS`] after the last call.
    pub fn schedule(&self) {
        self.timer.schedule(DEBOUNCE_MS);
    }

    /// Writes `ms` after the last call (0: in a task of its own, e.g. after a big result,
    /// where `history.replaceState` alone can take tens of milliseconds).
    pub fn schedule_in(&self, ms: i32) {
        self.timer.schedule(ms);
    }

    /// While something plays (the debounced write would never fire): writes now when the
    /// last write of this method is more than `every_ms` ago, else schedules one.
    pub fn write_at_most_every(&self, every_ms: f64) {
        let now = now_ms();
        if now - self.written.get() > every_ms {
            self.written.set(now);
            self.write_now();
        } else {
            self.schedule();
        }
    }

    /// Counts now as a write of [`UrlWriter::write_at_most_every`]: its first write waits.
    pub fn hold_from_now(&self) {
        self.written.set(now_ms());
    }
}

thread_local! {
    /// The keys the notice rendered last names (the mounted page's).
    static SHOWN_KEYS: RefCell<Vec<IgnoredKey>> = const { RefCell::new(Vec::new()) };
}

/// The keys of its link the page mounted last did not use, as its notice names them (none
/// if it has no notice): the embedding API's check of a `setState`. Cleared by
/// [`forget_shown_keys`] before a mount.
pub fn shown_keys() -> Vec<IgnoredKey> {
    SHOWN_KEYS.with_borrow(Vec::clone)
}

/// Forgets the keys [`shown_keys`] gives (a page is about to be mounted).
pub fn forget_shown_keys() {
    SHOWN_KEYS.with_borrow_mut(Vec::clear);
}

/// A page's own first sentence of the notice, formatted in the current language on each
/// render (e.g. the drills page's "This link names a drill that does not exist").
pub type NoticeLead = Box<dyn Fn() -> String>;

/// The localized notice about the keys of the opened link the page ignored: hidden when there
/// are none; "This link's … were ignored: L2, q1" otherwise, re-rendered on a language switch.
/// A page may put a sentence of its own first ([`UrlNotice::set_lead`]).
pub struct UrlNotice {
    element: Element,
    keys: RefCell<Vec<IgnoredKey>>,
    lead: RefCell<Option<NoticeLead>>,
}

impl UrlNotice {
    /// Drives `element` (the page places it; it gets `role="status"`).
    pub fn new(element: Element, keys: Vec<IgnoredKey>) -> Result<UrlNotice, JsValue> {
        element.set_attribute("role", "status")?;
        let notice = UrlNotice {
            element,
            keys: RefCell::new(keys),
            lead: RefCell::new(None),
        };
        notice.relocalize();
        Ok(notice)
    }

    /// The element.
    pub fn element(&self) -> &Element {
        &self.element
    }

    /// Replaces the keys shown (empty: hide), e.g. cleared after a reset.
    pub fn set(&self, keys: Vec<IgnoredKey>) {
        *self.keys.borrow_mut() = keys;
        self.relocalize();
    }

    /// The keys shown now.
    pub fn keys(&self) -> Vec<IgnoredKey> {
        self.keys.borrow().clone()
    }

    /// Puts the page's own sentence first (`None`: none), shown even without keys.
    pub fn set_lead(&self, lead: Option<NoticeLead>) {
        *self.lead.borrow_mut() = lead;
        self.relocalize();
    }

    /// Replaces the keys and the lead at once (one render).
    pub fn set_all(&self, keys: Vec<IgnoredKey>, lead: Option<NoticeLead>) {
        *self.keys.borrow_mut() = keys;
        *self.lead.borrow_mut() = lead;
        self.relocalize();
    }

    /// Re-renders the text in the current language.
    pub fn relocalize(&self) {
        SHOWN_KEYS.with_borrow_mut(|shown| shown.clone_from(&self.keys.borrow()));
        let lead = self.lead.borrow().as_ref().map(|lead| lead());
        let keys = notice_text(&self.keys.borrow());
        let text = match (lead, keys) {
            (Some(lead), Some(keys)) => Some(format!("{lead} {keys}")),
            (lead, keys) => lead.or(keys),
        };
        dom::show(&self.element, text.is_some());
        self.element.set_text_content(text.as_deref());
    }
}

/// The notice's text for `keys`, `None` when there are none.
pub fn notice_text(keys: &[IgnoredKey]) -> Option<String> {
    let list = |reason: IgnoredReason| -> Vec<String> {
        keys.iter()
            .filter(|k| k.reason == reason)
            .map(|k| k.key.clone())
            .collect()
    };
    let mut parts = Vec::new();
    let unknown = list(IgnoredReason::Unknown);
    if !unknown.is_empty() {
        parts.push(ctx::t_strings(
            "kit-url-unknown",
            &[("keys", unknown.join(", "))],
        ));
    }
    let invalid = list(IgnoredReason::Invalid);
    if !invalid.is_empty() {
        parts.push(ctx::t_strings(
            "kit-url-invalid",
            &[("keys", invalid.join(", "))],
        ));
    }
    let flagged = list(IgnoredReason::Flagged);
    if !flagged.is_empty() {
        parts.push(ctx::t_strings(
            "kit-url-flagged",
            &[("keys", flagged.join(", "))],
        ));
    }
    for name in list(IgnoredReason::File) {
        parts.push(ctx::t_strings("kit-url-file", &[("name", name)]));
    }
    (!parts.is_empty()).then(|| parts.join(" "))
}
