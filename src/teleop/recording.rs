//! Recording an arm's episode, whatever the arm: [`ArmSim`] is what recording needs of a
//! simulation (the planar arm's [`crate::teleop::Sim`], the SO-101's [`crate::so101::Sim`]),
//! [`EpisodeOf`] an episode (its configuration, start state, commands and what each step
//! did) and [`Recorder`] a simulation recording one. `crate::teleop::Episode` and
//! `crate::so101::Episode` are `EpisodeOf` their arm's simulation; each arm keeps its own
//! CSV, figures and rules.

use std::fmt::Debug;

use serde::de::DeserializeOwned;
use serde::{Deserialize, Serialize};

use super::error::TeleopError;
use super::events::{Event, Outcome};

/// Why a simulation would not start (the configuration's error).
pub type StartError = TeleopError;

/// What recording, replaying and the failure review need of an arm's simulation.
pub trait ArmSim: Clone + Debug + Sized {
    /// The scene and controller a run starts from.
    type Config: Clone + Debug + PartialEq + Serialize + DeserializeOwned;
    /// The whole state of the scene between steps.
    type State: Clone + Debug + PartialEq + Serialize + DeserializeOwned;
    /// The operator's input for one step.
    type Command: Copy + Debug + PartialEq + Serialize + DeserializeOwned;
    /// What one step did.
    type Record: Clone + Debug + PartialEq + Serialize + DeserializeOwned;
    /// Whether a step taken after the episode ended is recorded too.
    const RECORDS_AFTER_END: bool;

    /// The simulation at the start of `config` (refused: the configuration's error).
    fn start(config: Self::Config) -> Result<Self, TeleopError>;
    /// The start state.
    fn start_state(&self) -> &Self::State;
    /// How the episode ended, once it has.
    fn done(&self) -> Option<Outcome>;
    /// One step with `cmd`.
    fn advance(&mut self, cmd: &Self::Command) -> Self::Record;
    /// Steps taken since the start.
    fn steps_taken(&self) -> u64;
    /// Back to the start state.
    fn restart(&mut self);
    /// `cmd` as it is recorded (axes clamped, NaN as 0).
    fn sanitize(cmd: &Self::Command) -> Self::Command;
    /// The events of `record`.
    fn events(record: &Self::Record) -> &[Event];
}

/// Implements [`ArmSim`] for an arm's `Sim` whose inherent `new`, `start_state`, `done`,
/// `step` and `reset` do what the trait asks and whose `state()` counts its `step`s, with the
/// `Command`'s `sanitized` and the `StepRecord`'s `events`: `arm_sim!(Sim, SceneConfig, State,
/// Command, StepRecord, records_after_end)`.
macro_rules! arm_sim {
    ($sim:ty, $config:ty, $state:ty, $command:ty, $record:ty, $after_end:expr) => {
        impl $crate::teleop::recording::ArmSim for $sim {
            type Config = $config;
            type State = $state;
            type Command = $command;
            type Record = $record;
            const RECORDS_AFTER_END: bool = $after_end;

            fn start(config: $config) -> Result<$sim, $crate::teleop::recording::StartError> {
                <$sim>::new(config)
            }

            fn start_state(&self) -> &$state {
                <$sim>::start_state(self)
            }

            fn done(&self) -> Option<$crate::teleop::events::Outcome> {
                <$sim>::done(self)
            }

            fn advance(&mut self, cmd: &$command) -> $record {
                self.step(cmd)
            }

            fn steps_taken(&self) -> u64 {
                self.state().step
            }

            fn restart(&mut self) {
                self.reset();
            }

            fn sanitize(cmd: &$command) -> $command {
                cmd.sanitized()
            }

            fn events(record: &$record) -> &[$crate::teleop::events::Event] {
                &record.events
            }
        }
    };
}
pub(crate) use arm_sim;

/// One attempt: everything needed to replay it and what it produced.
#[derive(Serialize, Deserialize)]
#[serde(bound = "")]
pub struct EpisodeOf<S: ArmSim> {
    /// The scene and controller it ran with.
    pub config: S::Config,
    /// The state the episode started from.
    pub start: S::State,
    /// The operator's commands, one per step.
    pub commands: Vec<S::Command>,
    /// What each step produced (same length as `commands`).
    pub records: Vec<S::Record>,
}

impl<S: ArmSim> Clone for EpisodeOf<S> {
    fn clone(&self) -> Self {
        EpisodeOf {
            config: self.config.clone(),
            start: self.start.clone(),
            commands: self.commands.clone(),
            records: self.records.clone(),
        }
    }
}

impl<S: ArmSim> PartialEq for EpisodeOf<S> {
    fn eq(&self, other: &Self) -> bool {
        self.config == other.config
            && self.start == other.start
            && self.commands == other.commands
            && self.records == other.records
    }
}

impl<S: ArmSim> Debug for EpisodeOf<S> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Episode")
            .field("config", &self.config)
            .field("start", &self.start)
            .field("commands", &self.commands)
            .field("records", &self.records)
            .finish()
    }
}

impl<S: ArmSim> EpisodeOf<S> {
    /// How the episode ended (`None`: ended by the pilot or interrupted).
    pub fn outcome(&self) -> Option<Outcome> {
        Outcome::of_events(self.records.iter().map(S::events))
    }

    /// Runs `commands` from the start of `config` and records the episode; stops early when
    /// the episode ends (success or timeout).
    pub fn record(config: S::Config, commands: &[S::Command]) -> Result<Self, TeleopError> {
        let mut recorder = Recorder::<S>::new(config)?;
        for cmd in commands {
            if recorder.sim().done().is_some() {
                break;
            }
            recorder.step(cmd);
        }
        Ok(recorder.into_episode())
    }
}

/// A simulation that records every step into an [`EpisodeOf`].
#[derive(Debug, Clone)]
pub struct Recorder<S: ArmSim> {
    sim: S,
    episode: EpisodeOf<S>,
}

impl<S: ArmSim> Recorder<S> {
    /// A recorder at the start state of `config`.
    pub fn new(config: S::Config) -> Result<Self, TeleopError> {
        let sim = S::start(config.clone())?;
        let episode = EpisodeOf {
            config,
            start: sim.start_state().clone(),
            commands: Vec::new(),
            records: Vec::new(),
        };
        Ok(Recorder { sim, episode })
    }

    /// Steps the simulation with `cmd` and records the step (once the episode has ended,
    /// only an arm that [`ArmSim::RECORDS_AFTER_END`] records it).
    pub fn step(&mut self, cmd: &S::Command) -> S::Record {
        let done = self.sim.done().is_some();
        let record = self.sim.advance(cmd);
        if S::RECORDS_AFTER_END || !done {
            self.episode.commands.push(S::sanitize(cmd));
            self.episode.records.push(record.clone());
        }
        record
    }

    /// The simulation (for drawing and readouts).
    pub fn sim(&self) -> &S {
        &self.sim
    }

    /// The episode so far.
    pub fn episode(&self) -> &EpisodeOf<S> {
        &self.episode
    }

    /// The recorded episode.
    pub fn into_episode(self) -> EpisodeOf<S> {
        self.episode
    }

    /// Starts a new episode from the start state (the recording so far is dropped: take it
    /// with [`Self::episode`] first).
    pub fn reset(&mut self) {
        self.sim.restart();
        self.episode.commands.clear();
        self.episode.records.clear();
    }
}
