//! [`PracticeEpisode`]: what the session needs of an arm's episodes, so that the planar arm
//! (`#/teleop`, [`crate::teleop::Episode`]) and the SO-101 (`#/so101`,
//! [`crate::so101::Episode`]) share one session, its stored form and its files.

use serde::de::DeserializeOwned;
use serde::Serialize;

use crate::teleop::episode::{FailureCategory, Label};
use crate::teleop::metrics::EpisodeMetrics;
use crate::teleop::recording::{ArmSim, EpisodeOf};
use crate::teleop::sim::Event;

/// An arm's episode, as a practice session records, stores, exports and reads it back.
pub trait PracticeEpisode: Clone + PartialEq + std::fmt::Debug + Sized {
    /// The stored form (configuration, start state, run-length coded commands).
    type Stored: Clone + PartialEq + std::fmt::Debug + Serialize + DeserializeOwned;
    /// A stored episode being simulated again.
    type Loading: Clone + std::fmt::Debug;
    /// `embodiment` of the evidence.
    const EMBODIMENT: &'static str;
    /// The start of the session's CSV names: `<prefix>_episodes.csv`,
    /// `<prefix>_episode_<n>.csv`.
    const FILE_PREFIX: &'static str;

    /// The episode's figures.
    fn metrics(&self) -> EpisodeMetrics;
    /// The task's id.
    fn task_id(&self) -> &'static str;
    /// The episode's time series file.
    fn csv(&self) -> String;
    /// An episode from its time series file (the kernel's message on error).
    fn parse_csv(text: &str) -> Result<Self, String>;
    /// Whether the commands reproduce every recorded step bit for bit.
    fn replays(&self) -> bool;
    /// The label and category the page proposes.
    fn proposed_label(&self) -> (Label, Option<FailureCategory>);
    /// Calls `f(step from 1, t_s, event)` for every event, in order.
    fn for_each_event(&self, f: &mut dyn FnMut(usize, f64, &Event));
    /// Steps recorded.
    fn steps(&self) -> usize;
    /// The IK method id, λ, the latency in steps and the noise σ.
    fn control_summary(&self) -> (&'static str, f64, u32, f64);
    /// The stored form.
    fn stored(&self) -> Self::Stored;
    /// Steps of a stored episode.
    fn stored_steps(stored: &Self::Stored) -> usize;
    /// Starts simulating a stored episode again (`None`: its configuration is refused or its
    /// start state is not the configuration's).
    fn load(stored: Self::Stored) -> Option<Self::Loading>;
    /// Simulates up to `max_steps` more steps; returns how many it did.
    fn load_run(loading: &mut Self::Loading, max_steps: usize) -> usize;
    /// Whether every step is simulated.
    fn load_done(loading: &Self::Loading) -> bool;
    /// The episode simulated again.
    fn loaded(loading: Self::Loading) -> Self;

    /// `<prefix>_episodes.csv`.
    fn episodes_name() -> String {
        format!("{}_episodes.csv", Self::FILE_PREFIX)
    }

    /// `<prefix>_episode_<n>.csv`.
    fn episode_file_name(n: usize) -> String {
        format!("{}_episode_{n}.csv", Self::FILE_PREFIX)
    }
}

/// An episode that can be simulated again step by step (the failure review's replay, a view
/// model of the pages): the arm's simulation at the episode's start state,
/// stepped with the episode's own commands.
pub trait Replayable: PracticeEpisode {
    /// The arm's simulation.
    type Sim;
    /// The simulation at the episode's start (`None`: its configuration is refused).
    fn start_sim(&self) -> Option<Self::Sim>;
    /// Back to the start state.
    fn reset_sim(sim: &mut Self::Sim);
    /// Steps `sim` with command `i` (from 0); `false` when there is no such command.
    fn step_sim(&self, sim: &mut Self::Sim, i: usize) -> bool;
    /// The events of step `i` (from 0; none past the end).
    fn step_events(&self, i: usize) -> &[Event];
}

/// Every arm's episode replays through its own simulation.
impl<S: ArmSim> Replayable for EpisodeOf<S>
where
    EpisodeOf<S>: PracticeEpisode,
{
    type Sim = S;

    fn start_sim(&self) -> Option<S> {
        S::start(self.config.clone()).ok()
    }

    fn reset_sim(sim: &mut S) {
        sim.restart();
    }

    fn step_sim(&self, sim: &mut S, i: usize) -> bool {
        let Some(c) = self.commands.get(i) else {
            return false;
        };
        sim.advance(c);
        true
    }

    fn step_events(&self, i: usize) -> &[Event] {
        self.records.get(i).map_or(&[], |r| S::events(r))
    }
}

/// [`PracticeEpisode::for_each_event`] over records given as `(t_s, events)`, steps from 1.
pub fn each_event<'a>(
    records: impl Iterator<Item = (f64, &'a [Event])>,
    f: &mut dyn FnMut(usize, f64, &Event),
) {
    for (i, (t_s, events)) in records.enumerate() {
        for e in events {
            f(i + 1, t_s, e);
        }
    }
}

/// [`PracticeEpisode::control_summary`] of a controller, latency and noise.
pub fn control_summary(
    c: &crate::teleop::control::ControlParams,
    latency_steps: u32,
    noise_sigma: f64,
) -> (&'static str, f64, u32, f64) {
    (c.method.id(), c.lambda, latency_steps, noise_sigma)
}

/// Steps of a run-length coded command stream.
pub fn run_steps<C>(runs: &[(u32, C)]) -> usize {
    runs.iter().map(|(n, _)| *n as usize).sum()
}
