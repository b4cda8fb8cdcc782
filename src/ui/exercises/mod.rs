//! A page's exercises list: the `exercises` wasm chunk its section
//! ([`crate::ui::kit::exercise_slot`]) fetches. One card per exercise the page lends
//! ([`PageLink::exercises`], drawn by its `card` module), the page's progress, and the progress
//! file's panel ([`ProgressPanel`]).
//!
//! Every verdict is the kernel's ([`Exercise::check`] on the model the page lends), never a
//! reading of the page's text. A prediction's answer is read with
//! [`crate::view::prediction_text`]; what each act does to the card and to the record is
//! [`crate::view::exercise_state`]'s; the record is saved at once
//! ([`crate::ui::kit::progress_store`]).
//!
//! Goals are checked live: after the learner's input on the page (an edit, a key, a drag
//! let go; every [`LIVE_MS`] while a drag goes on) and when the page says its state changed.
//! A goal counts as met by the learner once they have used the page: an input of theirs on it
//! since the list came, or its address changed from the one it opened with (a change made
//! before the list came).
//!
//! While the learner predicts, the page's readouts that show the answer are blurred (the
//! `hidden` module), and so are those of the exercise a presented lesson step is about
//! ([`PRESENT_EXERCISE_ATTR`]) until the presenter reveals it: the class predicts first. Its
//! card opens for an answer even if this browser's learner answered it before. The list's strings ([`FILES`]) and style ([`STYLES`]) come with it,
//! before it is drawn.

mod card;
mod hidden;

use std::cell::{Cell, RefCell};
use std::rc::{Rc, Weak};

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::{Element, Event};

use self::card::{note_of, Card, Note};
use crate::i18n::FluentArg;
use crate::ui::dom::{self, Listener};
use crate::ui::kit::exercise_link::{
    ExerciseList, ListChunk, PageLink, PRESENT_EXERCISE_ATTR, PRESENT_EXERCISE_EVENT,
};
use crate::ui::kit::lang_follow::LangFollow;
use crate::ui::kit::late_style;
use crate::ui::kit::progress_panel::ProgressPanel;
use crate::ui::kit::progress_store;
use crate::ui::schedule::{now_ms, Timer};
use crate::ui::{ctx, lang_files, router};
use crate::view::exercise_state::{Committed, ExerciseState, Phase};
use crate::view::exercises::{Answer, CheckError, Exercise, Kind, Verdict};
use crate::view::prediction_text::parse_prediction;

/// What the chunk hands the page's slot.
pub const CHUNK: ListChunk = ListChunk { mount };

/// How long after the learner's last input the goals are checked, ms.
pub const AFTER_INPUT_MS: i32 = 120;
/// How often goals are checked while a drag goes on, ms.
pub const LIVE_MS: f64 = 250.0;
/// The list's Fluent files.
pub const FILES: [&str; 2] = ["exercises.ftl", "progress.ftl"];
/// The list's stylesheets ([`late_style`]).
pub const STYLES: [&str; 2] = ["exercises", "progress"];

/// A mounted list.
struct List {
    link: Rc<PageLink>,
    cards: RefCell<Vec<Card>>,
    lede: Element,
    panel: RefCell<Option<Rc<ProgressPanel>>>,
    check: Timer,
    /// Whether the learner has used the page since the list came.
    used: Cell<bool>,
    /// The card whose prediction field has focus (its answer's readouts are blurred).
    aiming: Cell<Option<usize>>,
    /// When the goals were last checked during a drag, ms.
    live_at: Cell<f64>,
    listeners: RefCell<Vec<Listener>>,
    follow: RefCell<Option<LangFollow>>,
}

/// The list as the slot holds it.
struct Mounted(Rc<List>);

impl ExerciseList for Mounted {
    fn changed(&self) {
        self.0.live_change();
    }
}

/// Mounts the list of the page's exercises in its section, once its strings and style are
/// here.
fn mount(link: Rc<PageLink>) -> Result<Box<dyn ExerciseList>, JsValue> {
    let list = Rc::new(List {
        link,
        cards: RefCell::new(Vec::new()),
        lede: dom::el_class("p", "ex-lede")?,
        panel: RefCell::new(None),
        check: Timer::default(),
        used: Cell::new(false),
        aiming: Cell::new(None),
        live_at: Cell::new(0.0),
        listeners: RefCell::new(Vec::new()),
        follow: RefCell::new(None),
    });
    let weak = Rc::downgrade(&list);
    list.check.set_callback(&weak, List::check_goals);
    load(weak);
    Ok(Box::new(Mounted(list)))
}

/// Fetches the list's strings and style, then builds it; if the strings cannot be fetched,
/// the section says so with Retry.
fn load(list: Weak<List>) {
    wasm_bindgen_futures::spawn_local(async move {
        let strings = lang_files::load(ctx::lang(), &FILES).await;
        for sheet in STYLES {
            late_style::linked(sheet).await;
        }
        let Some(me) = list.upgrade() else { return };
        let built = match strings {
            Ok(()) => me.build(&list),
            Err(_) => me.show_failed(&list),
        };
        if let Err(error) = built {
            web_sys::console::error_2(&"BSV Playground: exercises".into(), &error);
        }
    });
}

/// Whether the list's strings are here in the language shown: right after a switch of
/// language they are not until [`LangFollow`] has fetched them, and the list is drawn then;
/// a goal checked meanwhile (a pilot page's frame) draws nothing.
fn strings_here() -> bool {
    FILES.iter().all(|file| ctx::has_file(ctx::lang(), file))
}

/// Whether `target` is inside `element`.
fn inside(element: &Element, target: Option<web_sys::EventTarget>) -> bool {
    target
        .and_then(|t| t.dyn_into::<web_sys::Node>().ok())
        .is_some_and(|node| element.contains(Some(&node)))
}

impl List {
    /// Builds the cards, the page's count and the progress panel, listens, and checks the
    /// goals a first time.
    fn build(&self, me: &Weak<List>) -> Result<(), JsValue> {
        let section = &self.link.section;
        if let Some(status) = section.query_selector(".ex-status")? {
            status.remove_attribute("data-i18n")?;
            dom::show(&status, false);
        }
        let record = progress_store::load();
        let cards = self
            .link
            .exercises
            .iter()
            .map(|e| Card::new(e, record.get(e.id)))
            .collect::<Result<Vec<_>, _>>()?;
        dom::append(section, &self.lede)?;
        let items = dom::el_class("ol", "ex-list")?;
        for card in &cards {
            dom::append(&items, card.element())?;
        }
        dom::append(section, &items)?;
        *self.cards.borrow_mut() = cards;
        let imported = me.clone();
        let panel = ProgressPanel::new(move || {
            if let Some(list) = imported.upgrade() {
                list.record_changed_elsewhere();
            }
        })?;
        dom::append(section, panel.element())?;
        *self.panel.borrow_mut() = Some(panel);
        self.listen(me)?;
        self.open_presented();
        let redraw = me.clone();
        *self.follow.borrow_mut() = Some(LangFollow::new(&FILES, move || {
            if let Some(list) = redraw.upgrade() {
                if let Some(panel) = list.panel.borrow().as_ref() {
                    panel.relocalize();
                }
                list.draw_all();
            }
        })?);
        self.check_goals();
        self.draw_all();
        Ok(())
    }

    /// The section says the strings could not be fetched, with Retry (which fetches them).
    fn show_failed(&self, me: &Weak<List>) -> Result<(), JsValue> {
        let Some(status) = self.link.section.query_selector(".ex-status")? else {
            return Ok(());
        };
        dom::set_i18n(&status, "exercises-load-failed")?;
        let retry = dom::el_i18n("button", "tool-button", "page-load-retry")?;
        retry.set_attribute("type", "button")?;
        dom::append(&status, &dom::el_text("span", "", " ")?)?;
        dom::append(&status, &retry)?;
        dom::show(&status, true);
        let again = me.clone();
        self.listeners
            .borrow_mut()
            .push(Listener::new(&retry, "click", move |_| {
                load(again.clone())
            })?);
        Ok(())
    }

    /// The learner's acts in the section, and their input on the page.
    fn listen(&self, me: &Weak<List>) -> Result<(), JsValue> {
        let section = &self.link.section;
        let mut listeners = self.listeners.borrow_mut();
        listeners.push(Listener::for_page(section, "click", me, |list, event| {
            list.on_click(event);
        })?);
        listeners.push(Listener::for_page(section, "submit", me, |list, event| {
            event.prevent_default();
            if let Some(i) = list.card_of(event.target()) {
                list.commit(i);
            }
        })?);
        listeners.push(Listener::for_page(section, "input", me, |list, event| {
            if let Some(i) = list.card_of(event.target()) {
                list.typed(i);
            }
        })?);
        for (kind, entering) in [("focusin", true), ("focusout", false)] {
            listeners.push(Listener::for_page(
                section,
                kind,
                me,
                move |list, event| {
                    let on_field = event
                        .target()
                        .and_then(|t| t.dyn_into::<Element>().ok())
                        .is_some_and(|e| e.has_attribute("data-field"));
                    if on_field {
                        list.aiming
                            .set(entering.then(|| list.card_of(event.target())).flatten());
                        list.hide_answers();
                    }
                },
            )?);
        }
        let root = self.link.root.clone();
        for kind in ["input", "change", "pointerup", "click"] {
            listeners.push(Listener::capture_for_page(
                &root,
                kind,
                me,
                |list, event| {
                    if list.used_page(event) {
                        list.check.schedule(AFTER_INPUT_MS);
                    }
                },
            )?);
        }
        listeners.push(Listener::capture_for_page(
            &root,
            "pointermove",
            me,
            |list, event| {
                let pressed = js_sys::Reflect::get(event, &JsValue::from_str("buttons"))
                    .ok()
                    .and_then(|b| b.as_f64())
                    .is_some_and(|b| b > 0.0);
                if pressed && list.used_page(event) {
                    list.live_change();
                }
            },
        )?);
        let window = dom::window()?;
        listeners.push(Listener::for_page(
            &window,
            PRESENT_EXERCISE_EVENT,
            me,
            |list, _| {
                list.open_presented();
                list.draw_all();
            },
        )?);
        listeners.push(Listener::for_page(&window, "keyup", me, |list, event| {
            if list.used_page(event) {
                list.check.schedule(AFTER_INPUT_MS);
            }
        })?);
        Ok(())
    }

    /// Whether `event` is the learner's input on the page outside the list (noted as a use
    /// of the page).
    fn used_page(&self, event: &Event) -> bool {
        let used = !inside(&self.link.section, event.target());
        if used {
            self.used.set(true);
        }
        used
    }

    /// The page's state changed during a drag (or a pilot's frame, driven by the learner):
    /// the goals are checked in the next task, at most every [`LIVE_MS`].
    fn live_change(&self) {
        self.used.set(true);
        let now = now_ms();
        if now - self.live_at.get() >= LIVE_MS {
            self.live_at.set(now);
            self.check.schedule(0);
        }
    }

    /// The card of the element `target` is in.
    fn card_of(&self, target: Option<web_sys::EventTarget>) -> Option<usize> {
        let element = target?.dyn_into::<Element>().ok()?;
        let card = element.closest("[data-exercise]").ok()??;
        let id = card.get_attribute("data-exercise")?;
        self.cards.borrow().iter().position(|c| c.exercise.id == id)
    }

    fn on_click(&self, event: &Event) {
        let Some(target) = event.target().and_then(|t| t.dyn_into::<Element>().ok()) else {
            return;
        };
        let Some(i) = self.card_of(event.target()) else {
            return;
        };
        let Ok(Some(button)) = target.closest("button") else {
            return;
        };
        if let Some(n) = button
            .get_attribute("data-choice")
            .and_then(|n| n.parse::<usize>().ok())
        {
            self.choose(i, n.saturating_sub(1));
            return;
        }
        match button.get_attribute("data-action").as_deref() {
            Some("hint") => self.with_card(i, |card, _| card.state.show_hint()),
            Some("reveal") => self.reveal(i),
            Some("again") => self.with_card(i, |card, _| {
                card.state.again(card.exercise.kind);
                card.note = None;
                card.shown_truth = None;
                if let Some(field) = card.field() {
                    field.set_value("");
                }
            }),
            _ => {}
        }
    }

    /// Applies `change` to card `i` (with the page's model at hand), then draws it.
    fn with_card(&self, i: usize, change: impl FnOnce(&mut Card, &Self)) {
        {
            let mut cards = self.cards.borrow_mut();
            let Some(card) = cards.get_mut(i) else { return };
            change(card, self);
        }
        self.draw_card(i);
    }

    /// `exercise` checked on the page's model now (`None` once the page is gone).
    fn verdict(&self, exercise: &Exercise, answer: Answer) -> Option<Result<Verdict, CheckError>> {
        let mut out = None;
        (self.link.with_model)(&mut |model| out = Some(exercise.check(model, answer)));
        out
    }

    fn typed(&self, i: usize) {
        self.with_card(i, |card, _| {
            let empty = card.field().is_none_or(|f| f.value().trim().is_empty());
            card.state.typed(empty);
            if matches!(card.note, Some(Note::Typed(_))) {
                card.note = None;
            }
        });
    }

    fn commit(&self, i: usize) {
        let mut refused = None;
        self.with_card(i, |card, list| {
            let Kind::Predict { unit, .. } = card.exercise.kind else {
                return;
            };
            if !card.state.takes_answer() {
                return;
            }
            let text = card.field().map(|f| f.value()).unwrap_or_default();
            let value = match parse_prediction(&text, unit) {
                Ok(value) => value,
                Err(error) => {
                    card.note = Some(Note::Typed(error));
                    return;
                }
            };
            match list.verdict(card.exercise, Answer::Number(value)) {
                Some(Ok(Verdict::Predicted { right, truth })) => {
                    card.note = None;
                    let committed = Committed::Number { value, truth };
                    let id = card.exercise.id;
                    let state = &mut card.state;
                    refused =
                        progress_store::update(&mut |r| state.answered(id, committed, right, r)).1;
                }
                Some(Err(error)) => card.note = Some(note_of(&error)),
                _ => {}
            }
        });
        self.after_record(refused);
    }

    fn choose(&self, i: usize, choice: usize) {
        let mut refused = None;
        self.with_card(i, |card, list| {
            if !card.state.takes_answer() {
                return;
            }
            if let Some(Ok(verdict)) = list.verdict(card.exercise, Answer::Choice(choice)) {
                let id = card.exercise.id;
                let state = &mut card.state;
                let committed = Committed::Choice(choice);
                refused = progress_store::update(&mut |r| {
                    state.answered(id, committed, verdict.right(), r)
                })
                .1;
            }
        });
        self.after_record(refused);
    }

    fn reveal(&self, i: usize) {
        let mut refused = None;
        self.with_card(i, |card, list| {
            if !card.state.takes_answer() {
                return;
            }
            let mut truth = None;
            (list.link.with_model)(&mut |model| truth = card.exercise.truth(model));
            match truth {
                Some(Err(error)) => {
                    card.note = Some(note_of(&error));
                    return;
                }
                Some(Ok(t)) => card.shown_truth = Some(t),
                None => {}
            }
            card.note = None;
            let id = card.exercise.id;
            let state = &mut card.state;
            refused = progress_store::update(&mut |r| state.reveal(id, r)).1;
        });
        self.after_record(refused);
    }

    /// After the record changed: the page's count, and a refused save said.
    fn after_record(&self, refused: Option<crate::ui::kit::store::Refused>) {
        self.draw_lede();
        if let Some(panel) = self.panel.borrow().as_ref() {
            panel.say_saved(refused);
        }
    }

    /// Whether the learner has used the page: an input of theirs since the list came, or its
    /// address changed since it opened.
    fn learner_changed(&self) -> bool {
        if !self.used.get() {
            let opened = router::parse_hash(&self.link.opened_hash).page_query();
            self.used
                .set(router::current_route().page_query() != opened);
        }
        self.used.get()
    }

    /// Checks the goals not done on the page's model now; those met once the learner has
    /// changed the page are recorded done.
    fn check_goals(&self) {
        let mut met: Vec<(usize, bool)> = Vec::new();
        {
            let cards = self.cards.borrow();
            (self.link.with_model)(&mut |model| {
                for (i, card) in cards.iter().enumerate() {
                    if matches!(card.exercise.kind, Kind::Goal) && card.state.phase != Phase::Done {
                        let verdict = card.exercise.check(model, Answer::PageState);
                        met.push((i, verdict.is_ok_and(|v| v.right())));
                    }
                }
            });
        }
        if met.is_empty() {
            return;
        }
        let changed = self.learner_changed();
        let refused = {
            let mut cards = self.cards.borrow_mut();
            progress_store::update(&mut |record| {
                for (i, is_met) in &met {
                    if let Some(card) = cards.get_mut(*i) {
                        let id = card.exercise.id;
                        card.state.goal_checked(id, *is_met, changed, record);
                    }
                }
            })
            .1
        };
        for (i, _) in &met {
            self.draw_card(*i);
        }
        self.after_record(refused);
    }

    /// The record changed in another way (an import): exercises it has done show as done.
    fn record_changed_elsewhere(&self) {
        let record = progress_store::load();
        for card in self.cards.borrow_mut().iter_mut() {
            let theirs = record.get(card.exercise.id);
            if theirs.done && card.state.takes_answer() {
                card.state = ExerciseState::opened(theirs);
                card.standing = theirs.standing();
                card.note = None;
            }
        }
        self.draw_all();
    }

    fn draw_card(&self, i: usize) {
        if let Some(card) = self.cards.borrow().get(i).filter(|_| strings_here()) {
            card.draw();
        }
        self.hide_answers();
    }

    /// The exercise a presented lesson step is about, if any.
    fn presented() -> Option<String> {
        dom::document()
            .ok()?
            .document_element()?
            .get_attribute(PRESENT_EXERCISE_ATTR)
    }

    /// Opens the presented exercise's card for an answer (the class's), if it shows one.
    fn open_presented(&self) {
        let Some(id) = Self::presented() else { return };
        for card in self.cards.borrow_mut().iter_mut() {
            if card.exercise.id == id && !card.state.takes_answer() {
                card.state.again(card.exercise.kind);
                card.note = None;
                card.shown_truth = None;
            }
        }
    }

    /// Blurs the readouts that show the answer of a prediction being made (its field in use,
    /// or typed in, or a wrong try, or the presented exercise's before it is revealed), and
    /// only those.
    fn hide_answers(&self) {
        let cards = self.cards.borrow();
        let presented = Self::presented();
        let keys: Vec<&str> = cards
            .iter()
            .enumerate()
            .filter(|(i, c)| {
                let aiming = self.aiming.get() == Some(*i) && c.state.takes_answer();
                let shown = presented.as_deref() == Some(c.exercise.id) && c.state.takes_answer();
                aiming || shown || matches!(c.state.phase, Phase::Predicting | Phase::Wrong)
            })
            .flat_map(|(_, c)| hidden::answer_readouts(c.exercise.id).iter().copied())
            .collect();
        if let Err(error) = hidden::hide_only(&self.link.root, &self.link.section, &keys) {
            web_sys::console::error_2(&"BSV Playground: exercises".into(), &error);
        }
    }

    fn draw_lede(&self) {
        if !strings_here() {
            return;
        }
        let record = progress_store::load();
        let cards = self.cards.borrow();
        let done = cards
            .iter()
            .filter(|c| record.get(c.exercise.id).done)
            .count();
        let text = ctx::t_args(
            "exercises-lede",
            &[
                ("done", FluentArg::from(done)),
                ("total", FluentArg::from(cards.len())),
            ],
        );
        if self.lede.text_content().as_deref() != Some(text.as_str()) {
            self.lede.set_text_content(Some(&text));
        }
    }

    fn draw_all(&self) {
        if strings_here() {
            for card in self.cards.borrow().iter() {
                card.draw();
            }
            self.draw_lede();
        }
        self.hide_answers();
    }
}
