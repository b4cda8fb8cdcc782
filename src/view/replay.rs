//! A recorded episode replayed under the stepper (the failure review of `#/teleop` and
//! `#/so101`): the arm's simulation run again from the episode's start state with its own
//! commands, so every step shown is exactly the recorded one (the kernels are deterministic).
//! Stepping back starts again from the start state: nothing is undone by arithmetic.

use std::cell::RefCell;
use std::rc::Rc;

use crate::teleop::session::Replayable;
use crate::teleop::sim::Event;
use crate::view::stepper::{Length, StepModel};

/// The stepper's model: an episode and the simulation replaying it.
pub struct Replay<E: Replayable> {
    /// The episode's number in its session.
    pub number: usize,
    /// Shared with the session (no copy of its steps).
    pub episode: Rc<E>,
    sim: Option<E::Sim>,
    /// Steps taken by `sim`.
    at: u64,
    /// The first failure event's step (from 1) and the event.
    pub first_failure: Option<(u64, Event)>,
}

impl<E: Replayable> Replay<E> {
    /// Replays episode `number` from its start state.
    pub fn new(number: usize, episode: Rc<E>, first_failure: Option<(u64, Event)>) -> Replay<E> {
        let sim = episode.start_sim();
        Replay {
            number,
            episode,
            sim,
            at: 0,
            first_failure,
        }
    }

    /// Steps taken.
    pub fn index(&self) -> u64 {
        self.at
    }

    /// The simulation after [`Replay::index`] steps (`None`: the configuration is refused).
    pub fn sim(&self) -> Option<&E::Sim> {
        self.sim.as_ref()
    }

    /// The events of the last step shown.
    pub fn events_now(&self) -> &[Event] {
        match self.at.checked_sub(1) {
            Some(i) => self.episode.step_events(i as usize),
            None => &[],
        }
    }
}

impl<E: Replayable> StepModel for Replay<E> {
    fn length(&self) -> Length {
        Length::Finite(self.episode.steps() as u64)
    }

    fn go_to(&mut self, index: u64) {
        let Some(sim) = self.sim.as_mut() else {
            return;
        };
        let index = index.min(self.episode.steps() as u64);
        if index < self.at {
            E::reset_sim(sim);
            self.at = 0;
        }
        while self.at < index {
            if !self.episode.step_sim(sim, self.at as usize) {
                break;
            }
            self.at += 1;
        }
    }
}

/// What the review's stepper and timeline read of a replay, whatever the arm: one stepper
/// and one timeline (one copy of their code) serve every episode kind.
pub trait ReplaySteps {
    /// The episode's number in its session.
    fn number(&self) -> usize;
    /// Steps recorded.
    fn steps(&self) -> u64;
    /// Steps shown.
    fn index(&self) -> u64;
    /// Shows the state after `index` steps.
    fn go_to(&mut self, index: u64);
    /// The first failure event's step (from 1) and the event.
    fn first_failure(&self) -> Option<(u64, Event)>;
    /// The events of the last step shown.
    fn events_now(&self) -> Vec<Event>;
    /// Calls `f(step from 1, t_s, event)` for every event of the episode, in order.
    fn for_each_event(&self, f: &mut dyn FnMut(usize, f64, &Event));
}

/// A replay shared with its page (which draws the replayed state); a call while the page
/// holds it does nothing.
impl<E: Replayable> ReplaySteps for Rc<RefCell<Replay<E>>> {
    fn number(&self) -> usize {
        self.try_borrow().map_or(0, |r| r.number)
    }

    fn steps(&self) -> u64 {
        self.try_borrow().map_or(0, |r| r.episode.steps() as u64)
    }

    fn index(&self) -> u64 {
        self.try_borrow().map_or(0, |r| r.at)
    }

    fn go_to(&mut self, index: u64) {
        if let Ok(mut r) = self.try_borrow_mut() {
            StepModel::go_to(&mut *r, index);
        }
    }

    fn first_failure(&self) -> Option<(u64, Event)> {
        self.try_borrow().ok()?.first_failure
    }

    fn events_now(&self) -> Vec<Event> {
        self.try_borrow()
            .map_or_else(|_| Vec::new(), |r| r.events_now().to_vec())
    }

    fn for_each_event(&self, f: &mut dyn FnMut(usize, f64, &Event)) {
        if let Ok(r) = self.try_borrow() {
            r.episode.for_each_event(f);
        }
    }
}

/// The review stepper's model: any replay.
pub struct AnyReplay(pub Box<dyn ReplaySteps>);

impl StepModel for AnyReplay {
    fn length(&self) -> Length {
        Length::Finite(self.0.steps())
    }

    fn go_to(&mut self, index: u64) {
        self.0.go_to(index);
    }
}

#[cfg(test)]
mod tests {
    #[cfg(target_arch = "wasm32")]
    use wasm_bindgen_test::wasm_bindgen_test as test;

    use super::*;
    use crate::so101::{Command, Episode, SceneConfig};

    #[test]
    fn a_replay_shows_each_recorded_step_back_and_forth() {
        let mut commands = vec![Command::with_axes([1.0, 0.0, -1.0, 0.0, 0.0, 0.3], false); 40];
        commands.push(Command::idle(true));
        let episode = Episode::record(SceneConfig::default_for(false), &commands).unwrap();
        let mut replay = Replay::new(1, Rc::new(episode.clone()), None);
        assert_eq!(replay.length(), Length::Finite(41));
        for index in [41, 7, 30, 0, 12] {
            replay.go_to(index);
            assert_eq!(replay.index(), index);
            let shown = replay.sim().unwrap().snapshot();
            match index.checked_sub(1) {
                Some(i) => {
                    let r = &episode.records[i as usize];
                    assert_eq!((shown.q, shown.tool, shown.cube), (r.q, r.tool, r.cube));
                    assert_eq!(shown.step, r.step);
                }
                None => assert_eq!(shown.q, episode.start.q),
            }
        }
        replay.go_to(41);
        assert_eq!(replay.events_now(), episode.records[40].events.as_slice());
        replay.go_to(1_000);
        assert_eq!(replay.index(), 41);
        // The same replay through the stepper's model, shared with the page.
        let shared = Rc::new(RefCell::new(replay));
        let mut any = AnyReplay(Box::new(shared.clone()));
        assert_eq!(any.length(), Length::Finite(41));
        any.go_to(3);
        assert_eq!(shared.borrow().index(), 3);
        assert_eq!(any.0.events_now(), episode.records[2].events);
        let held = shared.borrow();
        any.go_to(9);
        assert_eq!(held.index(), 3, "a replay the page holds is left as it is");
    }
}
