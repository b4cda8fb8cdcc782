//! The stored form of a session (localStorage): each episode as its configuration, start
//! state and run-length coded command stream ([`StoredEpisode`]). The records are simulated
//! again on load, bit for bit (the kernel is deterministic), which keeps ten minute-long
//! episodes well under the browser's storage quota; [`SessionLoader`] does it in slices so
//! that a page never blocks its tab for long.

use serde::{Deserialize, Serialize};

use super::kind::{control_summary, each_event, run_steps, PracticeEpisode};
use super::practice::{
    category_from_id, label_from_id, label_id, InputDevice, Module, Preflight, Session,
};
use crate::teleop::episode::Episode;
use crate::teleop::scene::SceneConfig;
use crate::teleop::sim::{Command, Sim, State, StepRecord};

/// Version of [`StoredSession`].
pub const STORED_VERSION: u32 = 1;

/// The stored form of a session (localStorage): episodes as [`StoredEpisode`]s.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StoredSession<S = StoredEpisode> {
    pub version: u32,
    pub pilot_id: String,
    pub input_device: InputDevice,
    pub module: Module,
    pub preflight: Preflight,
    pub started_at: String,
    pub ended_at: Option<String>,
    pub episodes: Vec<StoredEntry<S>>,
    /// The episode being recorded when the page last saved (comes back interrupted).
    pub in_progress: Option<S>,
}

/// A stored episode entry.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StoredEntry<S = StoredEpisode> {
    pub episode: S,
    pub label: Option<String>,
    pub category: Option<String>,
    pub note: String,
    pub interrupted: bool,
}

/// An episode as stored: configuration, start state and the run-length coded commands.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StoredEpisode {
    pub config: SceneConfig,
    pub start: State,
    /// `(count, command)`: `count` steps of the same command.
    pub runs: Vec<(u32, Command)>,
}

impl StoredEpisode {
    /// The commands of `episode`, run-length coded.
    pub fn of(episode: &Episode) -> StoredEpisode {
        StoredEpisode {
            config: episode.config.clone(),
            start: episode.start.clone(),
            runs: run_length(&episode.commands),
        }
    }

    /// The command stream.
    pub fn commands(&self) -> Vec<Command> {
        let mut out = Vec::new();
        for (n, c) in &self.runs {
            for _ in 0..*n {
                out.push(*c);
            }
        }
        out
    }
}

/// Run-length coding of a command stream.
pub fn run_length<C: Copy + PartialEq>(commands: &[C]) -> Vec<(u32, C)> {
    let mut runs: Vec<(u32, C)> = Vec::new();
    for c in commands {
        match runs.last_mut() {
            Some((n, last)) if last == c && *n < u32::MAX => *n += 1,
            _ => runs.push((1, *c)),
        }
    }
    runs
}

impl<E: PracticeEpisode> Session<E> {
    /// The stored form, with the episode in progress (if any).
    pub fn stored(&self, in_progress: Option<&E>) -> StoredSession<E::Stored> {
        StoredSession {
            version: STORED_VERSION,
            pilot_id: self.pilot_id.clone(),
            input_device: self.input_device,
            module: self.module,
            preflight: self.preflight,
            started_at: self.started_at.clone(),
            ended_at: self.ended_at.clone(),
            episodes: self
                .episodes
                .iter()
                .map(|e| StoredEntry {
                    episode: e.episode.stored(),
                    label: e.label.map(|l| label_id(l).to_string()),
                    category: e.category.map(|c| c.id().to_string()),
                    note: e.note.clone(),
                    interrupted: e.interrupted,
                })
                .collect(),
            in_progress: in_progress.filter(|e| e.steps() > 0).map(E::stored),
        }
    }

    /// The stored session as JSON.
    pub fn to_json(&self, in_progress: Option<&E>) -> String {
        serde_json::to_string(&self.stored(in_progress)).unwrap_or_default()
    }

    /// A session from its stored JSON; an episode in progress comes back as an interrupted
    /// episode at the end. `None` if the text is not a stored session of this version or an
    /// episode does not simulate again. All at once: [`SessionLoader`] does the same in slices.
    pub fn from_json(text: &str) -> Option<Session<E>> {
        let mut loader = SessionLoader::new(text)?;
        while !loader.run(usize::MAX)? {}
        loader.finish()
    }
}

/// A stored session simulated again in slices of steps ([`SessionLoader::run`]), so that a
/// page opening ten minute-long episodes (60,000 steps) never blocks its tab for long; the
/// session it gives ([`SessionLoader::finish`]) is [`Session::from_json`]'s, bit for bit.
#[derive(Debug, Clone)]
pub struct SessionLoader<E: PracticeEpisode = Episode> {
    /// The session so far (the episodes simulated again, in order).
    session: Session<E>,
    /// Episodes still to simulate, in order (the one in progress last, interrupted).
    pending: std::collections::VecDeque<StoredEntry<E::Stored>>,
    /// The episode being simulated: its entry (episode taken out) and its simulation.
    current: Option<(StoredEntry<()>, E::Loading)>,
    steps_total: usize,
    steps_done: usize,
}

impl<E: PracticeEpisode> SessionLoader<E> {
    /// Parses a stored session (no simulation yet); `None` if the text is not a stored
    /// session of this version.
    pub fn new(text: &str) -> Option<SessionLoader<E>> {
        let stored: StoredSession<E::Stored> = serde_json::from_str(text).ok()?;
        if stored.version != STORED_VERSION {
            return None;
        }
        let mut pending: std::collections::VecDeque<StoredEntry<E::Stored>> =
            stored.episodes.into_iter().collect();
        if let Some(p) = stored.in_progress {
            pending.push_back(StoredEntry {
                episode: p,
                label: None,
                category: None,
                note: String::new(),
                interrupted: true,
            });
        }
        let steps_total = pending.iter().map(|e| E::stored_steps(&e.episode)).sum();
        Some(SessionLoader {
            session: Session {
                pilot_id: stored.pilot_id,
                input_device: stored.input_device,
                module: stored.module,
                preflight: stored.preflight,
                started_at: stored.started_at,
                ended_at: stored.ended_at,
                episodes: Vec::new(),
            },
            pending,
            current: None,
            steps_total,
            steps_done: 0,
        })
    }

    /// Simulates up to `max_steps` more steps. `Some(true)` when every episode is done,
    /// `Some(false)` when there is more, `None` if an episode does not simulate again (refused
    /// configuration, or a start state that is not the configuration's).
    pub fn run(&mut self, max_steps: usize) -> Option<bool> {
        let mut budget = max_steps;
        loop {
            if self.current.is_none() {
                let Some(entry) = self.pending.pop_front() else {
                    return Some(true);
                };
                let loading = E::load(entry.episode)?;
                let rest = StoredEntry {
                    episode: (),
                    label: entry.label,
                    category: entry.category,
                    note: entry.note,
                    interrupted: entry.interrupted,
                };
                self.current = Some((rest, loading));
            }
            let (_, loading) = self.current.as_mut()?;
            let done = E::load_run(loading, budget);
            budget -= done;
            self.steps_done += done;
            if !E::load_done(loading) {
                return Some(false);
            }
            let (entry, loading) = self.current.take()?;
            let episode = E::loaded(loading);
            let n = self.session.record(episode, entry.interrupted);
            let e = self.session.episodes.get_mut(n - 1)?;
            e.label = entry.label.as_deref().and_then(label_from_id);
            e.category = entry.category.as_deref().and_then(category_from_id);
            e.note = entry.note;
            if budget == 0 && !self.pending.is_empty() {
                return Some(false);
            }
        }
    }

    /// The session so far: its pilot, device, module and preflight as stored, and the
    /// episodes simulated again until now.
    pub fn session(&self) -> &Session<E> {
        &self.session
    }

    /// Steps simulated so far and in all.
    pub fn progress(&self) -> (usize, usize) {
        (self.steps_done, self.steps_total)
    }

    /// The session, once [`SessionLoader::run`] said `Some(true)` (`None` before).
    pub fn finish(self) -> Option<Session<E>> {
        (self.current.is_none() && self.pending.is_empty()).then_some(self.session)
    }
}

/// The planar arm's stored episode being simulated again: its entry, simulation, commands and
/// records so far.
#[derive(Debug, Clone)]
pub struct PlanarLoading {
    config: SceneConfig,
    start: State,
    sim: Sim,
    commands: Vec<Command>,
    records: Vec<StepRecord>,
}

impl PracticeEpisode for Episode {
    type Stored = StoredEpisode;
    type Loading = PlanarLoading;
    const EMBODIMENT: &'static str = super::evidence::EMBODIMENT;
    const FILE_PREFIX: &'static str = "teleop";

    fn metrics(&self) -> crate::teleop::metrics::EpisodeMetrics {
        crate::teleop::episode::metrics(self)
    }

    fn task_id(&self) -> &'static str {
        self.config.task.id()
    }

    fn csv(&self) -> String {
        crate::teleop::episode::episode_csv(self)
    }

    fn parse_csv(text: &str) -> Result<Self, String> {
        crate::teleop::episode::parse_episode_csv(text).map_err(|e| e.to_string())
    }

    fn replays(&self) -> bool {
        crate::teleop::episode::replay(self).is_ok()
    }

    fn proposed_label(
        &self,
    ) -> (
        crate::teleop::episode::Label,
        Option<crate::teleop::episode::FailureCategory>,
    ) {
        crate::teleop::episode::proposed_label(self)
    }

    fn for_each_event(&self, f: &mut dyn FnMut(usize, f64, &crate::teleop::sim::Event)) {
        each_event(self.records.iter().map(|r| (r.t_s, &r.events[..])), f);
    }

    fn steps(&self) -> usize {
        self.commands.len()
    }

    fn control_summary(&self) -> (&'static str, f64, u32, f64) {
        let c = &self.config;
        control_summary(&c.control, c.latency_steps, c.noise_sigma)
    }

    fn stored(&self) -> StoredEpisode {
        StoredEpisode::of(self)
    }

    fn stored_steps(stored: &StoredEpisode) -> usize {
        run_steps(&stored.runs)
    }

    fn load(stored: StoredEpisode) -> Option<PlanarLoading> {
        let sim = Sim::new(stored.config.clone()).ok()?;
        if *sim.start_state() != stored.start {
            return None;
        }
        let commands = stored.commands();
        Some(PlanarLoading {
            records: Vec::with_capacity(commands.len()),
            config: stored.config,
            start: stored.start,
            sim,
            commands,
        })
    }

    fn load_run(l: &mut PlanarLoading, max_steps: usize) -> usize {
        let from = l.records.len();
        let to = l.commands.len().min(from.saturating_add(max_steps));
        for c in &l.commands[from..to] {
            l.records.push(l.sim.step(c));
        }
        to - from
    }

    fn load_done(l: &PlanarLoading) -> bool {
        l.records.len() >= l.commands.len()
    }

    fn loaded(l: PlanarLoading) -> Self {
        Episode {
            config: l.config,
            start: l.start,
            commands: l.commands,
            records: l.records,
        }
    }
}
