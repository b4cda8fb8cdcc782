//! One exercise's card: its markup (`data-exercise`, `data-exercise-state`, the prediction
//! field, the choices, Check, Hint, Show the answer, Try again) and its drawing in the current
//! language from its state ([`ExerciseState`]), the truth beside the prediction, the hint
//! and, once the answer shows, the explanation. What the learner's acts do is the list's
//! (`super`); the card only shows.

use wasm_bindgen::prelude::*;
use web_sys::{Element, HtmlInputElement};

use crate::i18n::FluentArg;
use crate::ui::{ctx, dom};
use crate::view::exercise_state::{Committed, ExerciseState, Phase};
use crate::view::exercises::{CheckError, Exercise, Kind, Tolerance};
use crate::view::learner_progress::{ExerciseProgress, Standing};
use crate::view::prediction_text::{unit_text, value_text, PredictionError};

/// What the card says beside its state (a check that could not be made, a refused number).
#[derive(Debug, Clone, PartialEq)]
pub enum Note {
    /// The typed prediction is not a number.
    Typed(PredictionError),
    /// The page's state gives no truth (a run too short...).
    NoTruth,
    /// The kernel refused the page's state: its message.
    Failed(String),
}

/// One exercise's card.
pub struct Card {
    pub exercise: &'static Exercise,
    pub state: ExerciseState,
    /// The record's standing when the card opened done (said as "done, right at the first
    /// try" or "done").
    pub standing: Standing,
    /// The truth shown by "Show the answer" before any try was committed.
    pub shown_truth: Option<f64>,
    pub note: Option<Note>,
    element: Element,
}

impl Card {
    /// The card of `exercise`, in the state its record opens it in.
    pub fn new(exercise: &'static Exercise, record: ExerciseProgress) -> Result<Card, JsValue> {
        let element = dom::el_class("li", "ex-card")?;
        element.set_attribute("data-exercise", exercise.id)?;
        element.set_inner_html(&markup(exercise));
        Ok(Card {
            exercise,
            state: ExerciseState::opened(record),
            standing: record.standing(),
            shown_truth: None,
            note: None,
            element,
        })
    }

    pub fn element(&self) -> &Element {
        &self.element
    }

    /// The prediction field (predictions only).
    pub fn field(&self) -> Option<HtmlInputElement> {
        use wasm_bindgen::JsCast;
        self.element
            .query_selector("[data-field=\"prediction\"]")
            .ok()
            .flatten()
            .and_then(|e| e.dyn_into().ok())
    }

    fn part(&self, name: &str) -> Option<Element> {
        self.element
            .query_selector(&format!("[data-part=\"{name}\"]"))
            .ok()
            .flatten()
    }

    /// Part `name` shows `text` (hidden without); text already shown is left as it is, so
    /// that a live region says only what changed.
    fn set_part(&self, name: &str, text: Option<String>) {
        if let Some(part) = self.part(name) {
            dom::show(&part, text.is_some());
            if part.text_content() != text {
                part.set_text_content(text.as_deref());
            }
        }
    }

    fn show_action(&self, action: &str, shown: bool) {
        let selector = format!("[data-action=\"{action}\"]");
        if let Ok(Some(button)) = self.element.query_selector(&selector) {
            dom::show(&button, shown);
        }
    }

    /// Draws the card in the current language.
    pub fn draw(&self) {
        let e = self.exercise;
        let s = &self.state;
        let _ = self
            .element
            .set_attribute("data-exercise-state", s.phase.key());
        let kind = match e.kind {
            Kind::Predict { .. } => "exercise-kind-predict",
            Kind::Goal => "exercise-kind-goal",
            Kind::Choose { .. } => "exercise-kind-choose",
        };
        self.set_part("kind", Some(ctx::t(kind)));
        self.set_part(
            "state",
            Some(ctx::t(&format!("exercise-state-{}", s.phase.key()))),
        );
        self.set_part("prompt", Some(ctx::t(&e.prompt_id())));
        self.set_part("label", Some(ctx::t("exercise-prediction-label")));
        self.set_part("error", self.note_text());
        self.set_part("verdict", self.verdict());
        self.set_part("hint", s.hint.then(|| ctx::t(&e.hint_id())));
        self.set_part("explain", self.explanation());
        let takes = s.takes_answer();
        let goal = matches!(e.kind, Kind::Goal);
        self.show_action("commit", takes);
        self.show_action("reveal", takes && !goal);
        self.show_action("hint", !(s.hint || goal && s.phase == Phase::Done));
        self.show_action("again", !goal && !takes);
        for (action, id) in [
            ("commit", "exercise-commit"),
            ("hint", "exercise-hint"),
            ("reveal", "exercise-reveal"),
            ("again", "exercise-again"),
        ] {
            if let Ok(Some(button)) = self
                .element
                .query_selector(&format!("[data-action=\"{action}\"]"))
            {
                button.set_text_content(Some(&ctx::t(id)));
            }
        }
        if let Some(field) = self.field() {
            set_flag(&field, "disabled", !takes);
            let invalid = matches!(self.note, Some(Note::Typed(_)));
            let _ = field.set_attribute("aria-invalid", if invalid { "true" } else { "false" });
        }
        self.draw_choices();
    }

    /// The choices' texts and marks: the one chosen last, and the right one once shown.
    fn draw_choices(&self) {
        let Kind::Choose { right, .. } = self.exercise.kind else {
            return;
        };
        let chosen = match self.state.last {
            Some(Committed::Choice(n)) => Some(n),
            _ => None,
        };
        let shows = self.state.phase.shows_answer() || self.state.phase == Phase::Done;
        for (n, (choice_id, _)) in self.exercise.choice_ids().iter().enumerate() {
            let Ok(Some(button)) = self
                .element
                .query_selector(&format!("[data-choice=\"{}\"]", n + 1))
            else {
                continue;
            };
            button.set_text_content(Some(&ctx::t(choice_id)));
            let mark = if shows && n == right {
                "right"
            } else if chosen == Some(n) {
                "wrong"
            } else {
                ""
            };
            let _ = button.set_attribute("data-mark", mark);
            let _ = button.set_attribute(
                "aria-pressed",
                if chosen == Some(n) { "true" } else { "false" },
            );
            set_flag(&button, "disabled", !self.state.takes_answer());
        }
    }

    fn note_text(&self) -> Option<String> {
        match self.note.as_ref()? {
            Note::Typed(error) => Some(ctx::t(error.message_id())),
            Note::NoTruth => Some(ctx::t("exercise-no-truth")),
            Note::Failed(detail) => Some(ctx::t_args(
                "exercise-check-failed",
                &[("detail", FluentArg::from(detail))],
            )),
        }
    }

    fn unit(&self) -> &'static str {
        match self.exercise.kind {
            Kind::Predict { unit, .. } => unit,
            _ => "",
        }
    }

    fn tolerance_text(&self) -> String {
        match self.exercise.kind {
            Kind::Predict {
                tolerance: Tolerance::Relative(r),
                ..
            } => format!("±{} %", crate::view::signal::sig(r * 100.0, 2)),
            Kind::Predict {
                tolerance: Tolerance::Absolute(a),
                unit,
            } => format!("±{}", value_text(a, unit)),
            _ => String::new(),
        }
    }

    /// The line under the answer: right or wrong, the truth beside the prediction, the goal's
    /// standing.
    fn verdict(&self) -> Option<String> {
        let s = &self.state;
        let unit = self.unit();
        let args = |value: f64, truth: f64| {
            vec![
                ("value", FluentArg::from(value_text(value, unit))),
                ("truth", FluentArg::from(value_text(truth, unit))),
                ("tolerance", FluentArg::from(self.tolerance_text())),
                (
                    "direction",
                    FluentArg::from(if value > truth { "high" } else { "low" }),
                ),
            ]
        };
        match (self.exercise.kind, s.phase, s.last) {
            (Kind::Goal, Phase::Done, _) => Some(ctx::t("exercise-goal-done")),
            (Kind::Goal, _, _) if s.met_by_link => Some(ctx::t("exercise-goal-met-by-link")),
            (Kind::Goal, _, _) => Some(ctx::t("exercise-goal-open")),
            (_, Phase::Done, None) => Some(ctx::t(match self.standing {
                Standing::FirstTry => "exercise-done-first-try",
                _ => "exercise-done-later",
            })),
            (_, Phase::Wrong, Some(Committed::Number { value, truth })) => {
                Some(ctx::t_args("exercise-verdict-wrong", &args(value, truth)))
            }
            (_, Phase::Right, Some(Committed::Number { value, truth })) => {
                Some(ctx::t_args("exercise-verdict-right", &args(value, truth)))
            }
            (_, Phase::Revealed, Some(Committed::Number { value, truth })) => Some(ctx::t_args(
                "exercise-verdict-revealed",
                &args(value, truth),
            )),
            (_, Phase::Revealed, _) if matches!(self.exercise.kind, Kind::Predict { .. }) => {
                self.shown_truth.map(|truth| {
                    ctx::t_args(
                        "exercise-verdict-shown",
                        &[("truth", FluentArg::from(value_text(truth, unit)))],
                    )
                })
            }
            (Kind::Choose { right, .. }, phase, last) => self.choice_verdict(phase, last, right),
            _ => None,
        }
    }

    fn choice_verdict(
        &self,
        phase: Phase,
        last: Option<Committed>,
        right: usize,
    ) -> Option<String> {
        let ids = self.exercise.choice_ids();
        let why = |n: usize| ids.get(n).map(|(_, why)| ctx::t(why)).unwrap_or_default();
        let chosen = match last {
            Some(Committed::Choice(n)) => Some(n),
            _ => None,
        };
        match (phase, chosen) {
            (Phase::Right, _) => Some(ctx::t_args(
                "exercise-choice-right",
                &[("why", FluentArg::from(why(right)))],
            )),
            (Phase::Wrong, Some(n)) => Some(ctx::t_args(
                "exercise-choice-wrong",
                &[("why", FluentArg::from(why(n)))],
            )),
            (Phase::Revealed, chosen) => {
                let choice = ids.get(right).map(|(c, _)| ctx::t(c)).unwrap_or_default();
                let mut text = ctx::t_args(
                    "exercise-choice-revealed",
                    &[
                        ("choice", FluentArg::from(choice)),
                        ("why", FluentArg::from(why(right))),
                    ],
                );
                if let Some(n) = chosen.filter(|n| *n != right) {
                    text.push(' ');
                    text.push_str(&ctx::t_args(
                        "exercise-choice-wrong",
                        &[("why", FluentArg::from(why(n)))],
                    ));
                }
                Some(text)
            }
            _ => None,
        }
    }

    /// The explanation, once the answer shows (a goal's once done).
    fn explanation(&self) -> Option<String> {
        let s = &self.state;
        let e = self.exercise;
        let shows =
            s.phase.shows_answer() || (matches!(e.kind, Kind::Goal) && s.phase == Phase::Done);
        if !shows {
            return None;
        }
        let truth = match s.last {
            Some(Committed::Number { truth, .. }) => Some(truth),
            _ => self.shown_truth,
        };
        let truth = truth.map_or_else(|| "—".to_owned(), |t| value_text(t, self.unit()));
        Some(ctx::t_args(
            &e.explain_id(),
            &[("truth", FluentArg::from(truth))],
        ))
    }
}

/// Sets or removes the boolean attribute `name` of `element`.
fn set_flag(element: &Element, name: &str, on: bool) {
    let _ = if on {
        element.set_attribute(name, "")
    } else {
        element.remove_attribute(name)
    };
}

/// What a check's refusal says on the card.
pub fn note_of(error: &CheckError) -> Note {
    match error {
        CheckError::Kernel(e) => Note::Failed(ctx::error_text(e)),
        _ => Note::NoTruth,
    }
}

/// The card's markup (texts drawn by [`Card::draw`]).
fn markup(e: &Exercise) -> String {
    let id = e.id;
    let kind = match e.kind {
        Kind::Predict { .. } => "predict",
        Kind::Goal => "goal",
        Kind::Choose { .. } => "choose",
    };
    let mut html = format!(
        "<div class=\"ex-top\"><span class=\"ex-kind\" data-part=\"kind\" data-kind=\"{kind}\"></span>\
<span class=\"ex-state\" data-part=\"state\"></span></div>\
<p class=\"ex-prompt\" id=\"ex-{id}-prompt\" data-part=\"prompt\"></p>"
    );
    match e.kind {
        Kind::Predict { unit, .. } => html.push_str(&format!(
            "<form class=\"ex-predict\" novalidate><label class=\"ex-field\">\
<span data-part=\"label\"></span><span class=\"ex-input\">\
<input type=\"text\" inputmode=\"decimal\" autocomplete=\"off\" spellcheck=\"false\" \
data-field=\"prediction\" aria-describedby=\"ex-{id}-error\">\
<span class=\"ex-unit\">{unit}</span></span></label>\
<button type=\"submit\" class=\"tool-button ex-commit\" data-action=\"commit\"></button></form>\
<p class=\"ex-error\" id=\"ex-{id}-error\" data-part=\"error\" role=\"alert\" hidden></p>",
            unit = unit_text(unit)
        )),
        Kind::Choose { choices, .. } => {
            html.push_str(&format!(
                "<div class=\"ex-choices\" role=\"group\" aria-labelledby=\"ex-{id}-prompt\">"
            ));
            for n in 1..=choices {
                html.push_str(&format!(
                    "<button type=\"button\" class=\"ex-choice\" data-choice=\"{n}\"></button>"
                ));
            }
            html.push_str("</div>");
        }
        Kind::Goal => {}
    }
    html.push_str(
        "<p class=\"ex-verdict\" data-part=\"verdict\" aria-live=\"polite\"></p>\
<p class=\"ex-hint\" data-part=\"hint\" hidden></p>\
<p class=\"ex-explain\" data-part=\"explain\" hidden></p>\
<div class=\"ex-actions\">\
<button type=\"button\" class=\"tool-button\" data-action=\"hint\"></button>\
<button type=\"button\" class=\"tool-button\" data-action=\"reveal\"></button>\
<button type=\"button\" class=\"tool-button\" data-action=\"again\" hidden></button></div>",
    );
    html
}
