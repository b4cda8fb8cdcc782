//! The page's practice state: the session of SO-101 episodes (`crate::teleop::session`), the
//! episode being recorded, engaged or paused, the episode waiting for its label, and the
//! episode being replayed in the failure review, and the first session of the repeatability
//! comparison. Episodes are recorded in the record-ten module and after (the
//! earlier modules are practice: an attempt there is not kept); every recorded attempt stays
//! in the session, failures too.

use crate::so101::episode::{Episode, EpisodeRecorder};
use crate::so101::sim::{Command, StepRecord};
use crate::so101::SceneConfig;
use crate::teleop::session::{InputDevice, Module, Session};
use crate::teleop::sim::Outcome;
use crate::teleop::{FailureCategory, Label};
use crate::ui::kit::review::SharedReplay;

/// localStorage key of the session.
pub const STORE_KEY: &str = "bsv.so101.session";
/// localStorage key of the first session (the repeatability comparison's other side).
pub const FIRST_KEY: &str = "bsv.so101.first";

/// How the last episode ended, for the notice over the view.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Ended {
    /// By the kernel (success or timeout), recorded as episode `n` (0: practice, not kept).
    Outcome(Outcome, usize),
    /// By the pilot, recorded as episode `n` (0: practice, not kept).
    Pilot(usize),
}

/// The practice state (engaged from the start: the view opens ready to move).
pub struct Practice {
    pub session: Session<Episode>,
    /// The first session, once a second one started (or a session was opened over one with
    /// episodes).
    pub first: Option<Session<Episode>>,
    pub config: SceneConfig,
    pub recorder: EpisodeRecorder,
    pub engaged: bool,
    pub ended: Option<Ended>,
    /// The episode (number) whose label panel is open, and the pilot's choice so far.
    pub labelling: Option<usize>,
    pub choice: (Option<Label>, Option<FailureCategory>),
    /// The episode replayed in the failure review (the views draw its state).
    pub replay: Option<SharedReplay<Episode>>,
}

impl Practice {
    /// A practice over `session` with `config` (the default config if it is refused; `None`
    /// if that is refused too, which the kernel's tests rule out).
    pub fn new(session: Session<Episode>, config: SceneConfig) -> Option<Practice> {
        let (config, recorder) = match EpisodeRecorder::new(config.clone()) {
            Ok(r) => (config, r),
            Err(_) => {
                let c = SceneConfig::default_for(false);
                let r = EpisodeRecorder::new(c.clone()).ok()?;
                (c, r)
            }
        };
        Some(Practice {
            session,
            first: None,
            config,
            recorder,
            engaged: true,
            ended: None,
            labelling: None,
            choice: (None, None),
            replay: None,
        })
    }

    /// Whether the current module keeps episodes.
    pub fn records(&self) -> bool {
        self.session.module.records()
    }

    /// One 10 ms step with `cmd` while engaged; the episode ends when the kernel says so.
    pub fn step(&mut self, cmd: &Command) -> Option<StepRecord> {
        if !self.engaged || self.replay.is_some() || self.recorder.sim().done().is_some() {
            return None;
        }
        // The episode's clock starts with the pilot's first input.
        let start = self.recorder.sim().start_state();
        if self.recorder.episode().commands.is_empty()
            && !cmd.moves()
            && cmd.gripper_closed == start.gripper_closed
        {
            return None;
        }
        let r = self.recorder.step(cmd);
        self.session.preflight.moved |= cmd.moves();
        if let Some(outcome) = self.recorder.sim().done() {
            let n = self.keep(false);
            self.ended = Some(Ended::Outcome(outcome, n));
            self.engaged = false;
        }
        Some(r)
    }

    /// The episode so far is kept (in a recording module, with at least one step); returns
    /// its number (0 if not kept) and starts a fresh one.
    fn keep(&mut self, interrupted: bool) -> usize {
        let episode = self.recorder.episode().clone();
        self.recorder.reset();
        if !self.records() || episode.commands.is_empty() {
            return 0;
        }
        let n = self.session.record(episode, interrupted);
        self.open_label(n);
        n
    }

    /// Opens the label panel of episode `n` with its proposal preselected.
    pub fn open_label(&mut self, n: usize) {
        if let Some(e) = self.session.episodes.get(n.wrapping_sub(1)) {
            let (label, category) = match e.label {
                Some(l) => (l, e.category),
                None => e.proposal(),
            };
            self.labelling = Some(n);
            self.choice = (Some(label), category);
        }
    }

    /// The pilot ends the episode (End episode).
    pub fn end_episode(&mut self) -> Option<Ended> {
        if self.recorder.episode().commands.is_empty() {
            return None;
        }
        let n = self.keep(false);
        self.engaged = false;
        self.ended = Some(Ended::Pilot(n));
        self.ended
    }

    /// R: the scene back to its start (an episode with steps in a recording module is kept
    /// first), engaged for the next episode; the preflight's reset check compares the state
    /// with the start bit for bit.
    pub fn reset(&mut self) {
        if !self.recorder.episode().commands.is_empty() && self.recorder.sim().done().is_none() {
            let n = self.keep(false);
            if n > 0 {
                self.ended = Some(Ended::Pilot(n));
            }
        }
        self.recorder.reset();
        let sim = self.recorder.sim();
        let same = sim.state() == sim.start_state();
        if self.session.preflight.moved || self.session.module == Module::Preflight {
            self.session.preflight.reset_verified = Some(same);
        }
        // R starts the next episode: engaged, its clock waiting for the first input.
        self.engaged = true;
    }

    /// Repeatability: the episode under way is kept, the session becomes the first and a
    /// second one starts at Record ten (same pilot and device, preflight carried over).
    /// `false` (nothing changes) when the session has no episodes.
    pub fn start_second(&mut self, now: &str) -> bool {
        if self.records() && !self.recorder.episode().commands.is_empty() {
            self.keep(true);
        }
        let Some(first) = self.session.start_second(now) else {
            return false;
        };
        self.first = Some(first);
        self.session.module = Module::RecordTen;
        self.labelling = None;
        self.recorder.reset();
        self.engaged = true;
        self.ended = None;
        true
    }

    /// An opened session becomes the current one (the episode under way kept first); the one
    /// it replaces becomes the first session when it has episodes and there is none yet.
    pub fn replace(&mut self, session: Session<Episode>) {
        if self.records() && !self.recorder.episode().commands.is_empty() {
            self.keep(true);
        }
        let old = std::mem::replace(&mut self.session, session);
        if self.first.is_none() && !old.episodes.is_empty() {
            self.first = Some(old);
        }
        self.labelling = None;
        self.recorder.reset();
        self.ended = None;
    }

    /// Confirms the label panel's choice (with `note`).
    pub fn confirm_label(&mut self, note: &str) -> bool {
        let (Some(n), (Some(label), category)) = (self.labelling, self.choice) else {
            return false;
        };
        let Some(e) = self.session.episodes.get_mut(n - 1) else {
            return false;
        };
        e.set_label(label, category, note);
        self.labelling = None;
        true
    }

    /// A new config (settings changed): the episode in progress is kept first (interrupted);
    /// the next one is engaged, its clock waiting for the first input.
    pub fn set_config(&mut self, config: SceneConfig) -> bool {
        let Ok(recorder) = EpisodeRecorder::new(config.clone()) else {
            return false;
        };
        if !self.recorder.episode().commands.is_empty() {
            self.keep(true);
        }
        self.config = config;
        self.recorder = recorder;
        self.engaged = true;
        true
    }

    /// Chooses the input device.
    pub fn set_device(&mut self, d: InputDevice) {
        self.session.input_device = d;
    }

    /// The first session's stored form.
    pub fn first_json(&self) -> Option<String> {
        self.first.as_ref().map(|f| f.to_json(None))
    }

    /// The stored form (with the episode in progress, which comes back interrupted).
    pub fn to_json(&self) -> String {
        let progress = self.recorder.episode();
        let in_progress = (!progress.commands.is_empty() && self.records()).then_some(progress);
        self.session.to_json(in_progress)
    }
}
