//! One exercise's state on its page, between the learner and the progress record
//! ([`LearnerProgress`]): what each act does to both, so that `cargo test` covers the rules;
//! the page draws the state (`data-exercise-state`, [`Phase::key`]).
//!
//! - A prediction or a choice has [`TRIES`] tries: a wrong first try shows the hint and leaves
//!   one more; a wrong last try reveals the answer. A right try is right (and done).
//! - "Show the answer" before a right try reveals it and counts as a try that was not right, so
//!   an answer given after a reveal is never "right at the first try".
//! - After right or revealed, "Try again" opens the exercise again; the record keeps its
//!   attempts and its done.
//! - A goal is done when it is met once the learner has changed the page. Met by the state the
//!   page opened with (a teacher's link may set it up), it shows as met, not done, and is
//!   recorded at the learner's first change that keeps it met: the link never marks it done.
//! - An exercise done in the record opens as done.

use crate::view::exercises::Kind;
use crate::view::learner_progress::{ExerciseProgress, LearnerProgress};

/// Tries of a prediction or a choice: the first, then one more after the hint.
pub const TRIES: u32 = 2;

/// Where an exercise stands on the page.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Phase {
    /// Nothing typed or answered in this visit.
    Open,
    /// A prediction typed, not committed.
    Predicting,
    /// A wrong try, with one more to come (the hint shows).
    Wrong,
    /// Right: the truth and the explanation show.
    Right,
    /// The answer shown without a right try.
    Revealed,
    /// A goal met, or an exercise done in an earlier visit.
    Done,
}

impl Phase {
    /// The word of `data-exercise-state`.
    pub fn key(self) -> &'static str {
        match self {
            Phase::Open => "open",
            Phase::Predicting => "predicting",
            Phase::Wrong => "wrong",
            Phase::Right => "right",
            Phase::Revealed => "revealed",
            Phase::Done => "done",
        }
    }

    /// Whether the answer (the truth, the right choice, the explanation) shows.
    pub fn shows_answer(self) -> bool {
        matches!(self, Phase::Right | Phase::Revealed)
    }
}

/// An answer committed, as the page shows it beside the truth.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Committed {
    /// A prediction and the truth it was measured against, in the exercise's unit.
    Number { value: f64, truth: f64 },
    /// A choice, counting from 0.
    Choice(usize),
}

/// One exercise's state in this visit of its page.
#[derive(Debug, Clone, PartialEq)]
pub struct ExerciseState {
    pub phase: Phase,
    /// Tries in this visit (since the page opened or "Try again").
    pub tries: u32,
    /// Whether the hint shows.
    pub hint: bool,
    /// The last answer committed.
    pub last: Option<Committed>,
    /// A goal met by the state the page opened with, not yet by the learner's use of it.
    pub met_by_link: bool,
}

impl ExerciseState {
    /// The state an exercise opens in, from its record.
    pub fn opened(record: ExerciseProgress) -> ExerciseState {
        ExerciseState {
            phase: if record.done {
                Phase::Done
            } else {
                Phase::Open
            },
            tries: 0,
            hint: false,
            last: None,
            met_by_link: false,
        }
    }

    /// Whether an answer can be committed now.
    pub fn takes_answer(&self) -> bool {
        matches!(self.phase, Phase::Open | Phase::Predicting | Phase::Wrong)
    }

    /// The prediction field's text changed: empty or not.
    pub fn typed(&mut self, empty: bool) {
        match (self.phase, empty) {
            (Phase::Open, false) => self.phase = Phase::Predicting,
            (Phase::Predicting, true) => self.phase = Phase::Open,
            _ => {}
        }
    }

    /// The learner asked for the hint.
    pub fn show_hint(&mut self) {
        self.hint = true;
    }

    /// A committed answer to exercise `id`, right or not: counted in `record`; the phase
    /// follows the rules of the module docs. Nothing happens when no answer is taken now.
    pub fn answered(
        &mut self,
        id: &str,
        committed: Committed,
        right: bool,
        record: &mut LearnerProgress,
    ) {
        if !self.takes_answer() {
            return;
        }
        record.record_answer(id, right);
        self.tries += 1;
        self.last = Some(committed);
        self.phase = if right {
            Phase::Right
        } else if self.tries < TRIES {
            self.hint = true;
            Phase::Wrong
        } else {
            Phase::Revealed
        };
    }

    /// "Show the answer": revealed, counted as a try that was not right (when an answer was
    /// still taken).
    pub fn reveal(&mut self, id: &str, record: &mut LearnerProgress) {
        if self.takes_answer() {
            record.record_answer(id, false);
            self.tries += 1;
            self.phase = Phase::Revealed;
        }
    }

    /// "Try again" after right, revealed or done: open, with its tries again.
    pub fn again(&mut self, kind: Kind) {
        if matches!(kind, Kind::Goal) {
            return;
        }
        if matches!(self.phase, Phase::Right | Phase::Revealed | Phase::Done) {
            *self = ExerciseState {
                phase: Phase::Open,
                ..ExerciseState::opened(ExerciseProgress::default())
            };
        }
    }

    /// Goal `id` checked on the page's state (`met`), `changed` telling whether the learner
    /// has changed the page since it opened; recorded in `record` when met by the learner.
    /// Whether it was recorded now.
    pub fn goal_checked(
        &mut self,
        id: &str,
        met: bool,
        changed: bool,
        record: &mut LearnerProgress,
    ) -> bool {
        if self.phase == Phase::Done {
            return false;
        }
        if met && changed {
            record.record_goal_met(id);
            self.phase = Phase::Done;
            self.met_by_link = false;
            return true;
        }
        self.met_by_link = met;
        false
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::view::learner_progress::Standing;
    #[cfg(target_family = "wasm")]
    use wasm_bindgen_test::wasm_bindgen_test as test;

    const ID: &str = "pid-final-y";

    fn number(value: f64) -> Committed {
        Committed::Number { value, truth: 0.8 }
    }

    #[test]
    fn a_right_first_try_is_right_and_done_at_the_first_try() {
        let mut record = LearnerProgress::new("test");
        let mut s = ExerciseState::opened(record.get(ID));
        assert_eq!(s.phase, Phase::Open);
        s.typed(false);
        assert_eq!(s.phase.key(), "predicting");
        s.typed(true);
        assert_eq!(s.phase, Phase::Open);
        s.answered(ID, number(0.79), true, &mut record);
        assert_eq!(s.phase, Phase::Right);
        assert!(s.phase.shows_answer() && !s.hint);
        assert_eq!(record.get(ID).standing(), Standing::FirstTry);
        // Right takes no more answers until "Try again".
        s.answered(ID, number(5.0), false, &mut record);
        assert_eq!((s.phase, record.get(ID).attempts), (Phase::Right, 1));
        // Opened again later, it is done.
        assert_eq!(ExerciseState::opened(record.get(ID)).phase, Phase::Done);
    }

    #[test]
    fn a_wrong_try_shows_the_hint_and_leaves_one_more() {
        let mut record = LearnerProgress::new("test");
        let mut s = ExerciseState::opened(record.get(ID));
        s.answered(ID, number(5.0), false, &mut record);
        assert_eq!((s.phase, s.hint, s.tries), (Phase::Wrong, true, 1));
        assert!(!s.phase.shows_answer());
        // Typing again keeps it wrong until the next commit.
        s.typed(false);
        assert_eq!(s.phase, Phase::Wrong);
        s.answered(ID, number(0.8), true, &mut record);
        assert_eq!(s.phase, Phase::Right);
        assert_eq!(record.get(ID).standing(), Standing::Later);
        assert_eq!(record.get(ID).attempts, 2);

        // Two wrong tries reveal the answer.
        let mut other = LearnerProgress::new("test");
        let mut s = ExerciseState::opened(other.get(ID));
        s.answered(ID, number(5.0), false, &mut other);
        s.answered(ID, number(4.0), false, &mut other);
        assert_eq!(s.phase, Phase::Revealed);
        assert_eq!(s.last, Some(number(4.0)));
        assert_eq!(other.get(ID).standing(), Standing::NotYet);
    }

    #[test]
    fn a_reveal_counts_as_a_try_that_was_not_right() {
        let mut record = LearnerProgress::new("test");
        let mut s = ExerciseState::opened(record.get(ID));
        s.reveal(ID, &mut record);
        assert_eq!(s.phase.key(), "revealed");
        assert_eq!(record.get(ID).attempts, 1);
        // Try again, right: done, but later, not at the first try.
        s.again(Kind::Choose {
            choices: 3,
            right: 1,
        });
        assert_eq!((s.phase, s.tries, s.hint), (Phase::Open, 0, false));
        s.answered(ID, Committed::Choice(1), true, &mut record);
        assert_eq!(record.get(ID).standing(), Standing::Later);
        // A reveal after right changes nothing.
        s.reveal(ID, &mut record);
        assert_eq!((s.phase, record.get(ID).attempts), (Phase::Right, 2));
    }

    #[test]
    fn a_goal_met_by_the_link_waits_for_the_learners_change() {
        let id = "pid-tune";
        let mut record = LearnerProgress::new("test");
        let mut s = ExerciseState::opened(record.get(id));
        assert!(!s.goal_checked(id, true, false, &mut record));
        assert_eq!((s.phase, s.met_by_link), (Phase::Open, true));
        assert_eq!(record.get(id).attempts, 0);
        // Not met any more: no longer "met by the link".
        assert!(!s.goal_checked(id, false, true, &mut record));
        assert!(!s.met_by_link);
        assert!(s.goal_checked(id, true, true, &mut record));
        assert_eq!(s.phase.key(), "done");
        assert_eq!(record.get(id).standing(), Standing::FirstTry);
        // Done stays done; met again records nothing more.
        assert!(!s.goal_checked(id, true, true, &mut record));
        assert!(!s.goal_checked(id, false, true, &mut record));
        assert_eq!((s.phase, record.get(id).attempts), (Phase::Done, 1));
        // A goal has no "Try again".
        s.again(Kind::Goal);
        assert_eq!(s.phase, Phase::Done);
    }
}
