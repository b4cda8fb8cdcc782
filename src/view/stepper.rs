//! The stepper's state machine: where a stepping page is (`index` of `0..=len`, `0` the start,
//! `len` every step done), whether it plays and how fast. Plain Rust: the DOM widget
//! (`crate::ui::kit::stepper`) turns buttons, keys, the scrub slider and animation frames into
//! [`Command`]s and [`Stepper::tick`]s and hands the resulting index to the page's
//! [`StepModel`].
//!
//! - Step back is exact: the model is asked for `go_to(index - 1)`, never to undo arithmetic.
//! - Playing at [`Speed::PerSecond`] advances `rate × elapsed` steps, carrying the fraction to
//!   the next frame, so 0.5 steps/s steps once every two seconds and 6,000 steps/s does 100 a
//!   frame at 60 Hz. Frames further apart than [`MAX_FRAME_MS`] (a background tab) count as
//!   that long: coming back never jumps thousands of steps.
//! - [`Speed::Max`] ("as fast as possible") sizes its chunk to the time the model took: the
//!   chunk is scaled by the frame budget ([`FRAME_BUDGET_MS`] unless the page sets its own)
//!   over the last frame's work, at most doubled or halved a frame, so a frame's work settles
//!   at the budget rather than swinging up to twice it; a 50,000-iteration RRT plays out in
//!   seconds and the tab stays responsive.
//! - Playing stops by itself at the end (a bounded model); an unbounded one (a simulation) runs
//!   until paused.
//!
//! # Example
//! ```
//! use bsv_playground::view::stepper::{Command, Length, Speed, StepModel, Stepper};
//!
//! /// A model whose state is just the number of steps done (the RRT page keeps its tree's
//! /// history, so any index is one look-up away).
//! struct Counter { at: u64 }
//! impl StepModel for Counter {
//!     fn length(&self) -> Length { Length::Finite(50_000) }
//!     fn go_to(&mut self, index: u64) { self.at = index; }
//! }
//!
//! let mut model = Counter { at: 0 };
//! let mut stepper = Stepper::new(Speed::PerSecond(60.0));
//! stepper.apply(Command::Step, &mut model);
//! stepper.apply(Command::Step, &mut model);
//! stepper.apply(Command::Back, &mut model);
//! assert_eq!(model.at, 1);
//! stepper.apply(Command::End, &mut model);
//! assert_eq!((stepper.index(), model.at), (50_000, 50_000));
//! stepper.apply(Command::Seek(120), &mut model);
//! stepper.apply(Command::Toggle, &mut model);
//! stepper.tick(250.0, 0.0, &mut model); // a quarter second at 60 steps/s
//! assert_eq!(model.at, 135);
//! ```

/// How many steps a model has.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Length {
    /// `n` steps: indices `0..=n`.
    Finite(u64),
    /// No end (a simulation that can always take one more timestep).
    Unbounded,
}

impl Length {
    /// The last index, if any.
    pub fn end(self) -> Option<u64> {
        match self {
            Length::Finite(n) => Some(n),
            Length::Unbounded => None,
        }
    }
}

/// What a stepping page steps through. `go_to` is called with every index the user asks for
/// (exactly one call per change); the page redraws after it.
pub trait StepModel {
    /// How many steps there are (read again before every move: it may change).
    fn length(&self) -> Length;
    /// Show the state after `index` steps.
    fn go_to(&mut self, index: u64);
    /// Start over (new run, new seed...). The default goes back to the start.
    fn reset(&mut self) {
        self.go_to(0);
    }
}

/// Playing speed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Speed {
    /// Steps per second (a pendulum at 100 timesteps per simulated second plays at
    /// `Speed::times_real_time(1.0, 100.0)`).
    PerSecond(f64),
    /// As many steps per frame as keep the frame within budget.
    Max,
}

impl Speed {
    /// `multiple` × real time for a model taking `steps_per_second` steps per simulated second
    /// (0.1× … 10× on the pendulum page).
    pub fn times_real_time(multiple: f64, steps_per_second: f64) -> Speed {
        Speed::PerSecond(multiple * steps_per_second)
    }
}

/// Longest frame interval a tick counts, ms.
pub const MAX_FRAME_MS: f64 = 250.0;
/// Work per frame [`Speed::Max`] aims under, ms.
pub const FRAME_BUDGET_MS: f64 = 8.0;
/// Largest chunk [`Speed::Max`] takes in one frame.
pub const MAX_CHUNK: u64 = 1 << 20;

/// One thing the user asked the stepper to do.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Command {
    /// One step forward (pauses).
    Step,
    /// One step back, exactly (pauses).
    Back,
    /// Play, or pause if playing.
    Toggle,
    /// Play from here (from the start if at the end).
    Play,
    /// Stop playing.
    Pause,
    /// Jump to index 0 (pauses).
    Start,
    /// Jump to the last index (pauses; nothing on an unbounded model).
    End,
    /// Jump to an index (the scrub slider; clamped to the model's length).
    Seek(u64),
    /// Start over: pause and call the model's `reset`.
    Reset,
    /// Change the speed (keeps playing or not).
    SetSpeed(Speed),
}

/// The stepper's state.
#[derive(Debug, Clone, PartialEq)]
pub struct Stepper {
    index: u64,
    playing: bool,
    speed: Speed,
    /// Fraction of a step carried between frames at [`Speed::PerSecond`].
    carry: f64,
    /// Steps per frame at [`Speed::Max`].
    chunk: u64,
    /// Work per frame [`Speed::Max`] aims under, ms ([`FRAME_BUDGET_MS`] unless set).
    budget_ms: f64,
}

impl Stepper {
    /// At the start, paused.
    pub fn new(speed: Speed) -> Stepper {
        Stepper {
            index: 0,
            playing: false,
            speed,
            carry: 0.0,
            chunk: 1,
            budget_ms: FRAME_BUDGET_MS,
        }
    }

    /// Sets the work per frame [`Speed::Max`] aims under, ms (a page whose frames must stay
    /// short; ignored unless finite and positive).
    pub fn set_frame_budget(&mut self, budget_ms: f64) {
        if budget_ms.is_finite() && budget_ms > 0.0 {
            self.budget_ms = budget_ms;
        }
    }

    /// Steps done: `0..=len`.
    pub fn index(&self) -> u64 {
        self.index
    }

    /// Whether it is playing.
    pub fn playing(&self) -> bool {
        self.playing
    }

    /// The playing speed.
    pub fn speed(&self) -> Speed {
        self.speed
    }

    /// Whether step back / start can move (`false` at index 0).
    pub fn can_back(&self) -> bool {
        self.index > 0
    }

    /// Whether step / end can move for a model of length `len`.
    pub fn can_step(&self, len: Length) -> bool {
        len.end().is_none_or(|end| self.index < end)
    }

    /// Does `command`; the model's `go_to` (or `reset`) is called once if the index changes
    /// (or on reset). Returns whether anything the widget shows changed.
    pub fn apply(&mut self, command: Command, model: &mut dyn StepModel) -> bool {
        let len = model.length();
        let before = (self.index, self.playing, self.speed);
        match command {
            Command::Step => {
                self.pause();
                self.move_to(self.index.saturating_add(1), len, model);
            }
            Command::Back => {
                self.pause();
                self.move_to(self.index.saturating_sub(1), len, model);
            }
            Command::Toggle if self.playing => self.pause(),
            Command::Toggle | Command::Play => {
                if !self.can_step(len) {
                    self.move_to(0, len, model);
                }
                self.playing = self.can_step(len);
                self.carry = 0.0;
                self.chunk = 1;
            }
            Command::Pause => self.pause(),
            Command::Start => {
                self.pause();
                self.move_to(0, len, model);
            }
            Command::End => {
                self.pause();
                if let Some(end) = len.end() {
                    self.move_to(end, len, model);
                }
            }
            Command::Seek(index) => {
                self.move_to(index, len, model);
            }
            Command::Reset => {
                self.pause();
                self.index = 0;
                model.reset();
                return true;
            }
            Command::SetSpeed(speed) => {
                self.speed = match speed {
                    Speed::PerSecond(rate) if !(rate.is_finite() && rate > 0.0) => self.speed,
                    speed => speed,
                };
                self.carry = 0.0;
            }
        }
        before != (self.index, self.playing, self.speed)
    }

    /// One animation frame while playing: `elapsed_ms` since the last frame and `work_ms`, the
    /// time the model took on the last frame's `go_to` (for [`Speed::Max`]). Moves the model
    /// at most once; returns whether it moved.
    pub fn tick(&mut self, elapsed_ms: f64, work_ms: f64, model: &mut dyn StepModel) -> bool {
        if !self.playing {
            return false;
        }
        let len = model.length();
        let steps = match self.speed {
            Speed::PerSecond(rate) => {
                let elapsed = if elapsed_ms.is_finite() {
                    elapsed_ms.clamp(0.0, MAX_FRAME_MS)
                } else {
                    0.0
                };
                self.carry += rate * elapsed / 1000.0;
                // A hair of slack so that 6 × (1/6) is one step, not 0.999…
                let whole = (self.carry + 1e-9).floor();
                self.carry = (self.carry - whole).max(0.0);
                whole as u64
            }
            Speed::Max => {
                let low = (self.chunk / 2).max(1);
                let high = (self.chunk * 2).min(MAX_CHUNK);
                self.chunk = if work_ms > 0.0 && work_ms.is_finite() {
                    let aimed = self.chunk as f64 * self.budget_ms / work_ms;
                    (aimed.floor() as u64).clamp(low, high)
                } else {
                    high
                };
                self.chunk
            }
        };
        let moved = steps > 0 && self.move_to(self.index.saturating_add(steps), len, model);
        if !self.can_step(len) {
            self.pause();
        }
        moved
    }

    /// The model's length changed (new parameters): keeps the index inside it.
    pub fn clamp_to(&mut self, model: &mut dyn StepModel) {
        let len = model.length();
        if let Some(end) = len.end() {
            if self.index > end {
                self.move_to(end, len, model);
            }
        }
        if !self.can_step(len) {
            self.pause();
        }
    }

    fn pause(&mut self) {
        self.playing = false;
        self.carry = 0.0;
    }

    fn move_to(&mut self, index: u64, len: Length, model: &mut dyn StepModel) -> bool {
        let index = len.end().map_or(index, |end| index.min(end));
        if index == self.index {
            return false;
        }
        self.index = index;
        model.go_to(index);
        true
    }
}

/// The stepper's command for a key (`→`/PageDown step, `←`/PageUp back, space play/pause,
/// Home/End, `r` reset), ignoring modified keys. Presenter remotes send PageUp/PageDown.
pub fn key_command(key: &str, ctrl_alt_meta: bool) -> Option<Command> {
    if ctrl_alt_meta {
        return None;
    }
    Some(match key {
        "ArrowRight" | "PageDown" => Command::Step,
        "ArrowLeft" | "PageUp" => Command::Back,
        " " | "Spacebar" => Command::Toggle,
        "Home" => Command::Start,
        "End" => Command::End,
        "r" | "R" => Command::Reset,
        _ => return None,
    })
}

/// The position line under the stepper: its Fluent id and arguments, the numbers grouped by
/// thousands (`Step 1,204 of 228,608`; Japanese groups them alike, `228,608 ステップ中 1,204`).
/// Fluent's own number formatting would print `228608`.
pub fn position_message(
    index: u64,
    end: Option<u64>,
) -> (&'static str, Vec<(&'static str, String)>) {
    let index = ("index", crate::pyfmt::group_u64(index));
    match end {
        Some(end) => (
            "kit-stepper-position",
            vec![index, ("len", crate::pyfmt::group_u64(end))],
        ),
        None => ("kit-stepper-position-open", vec![index]),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Records every call, like a page would redraw.
    struct Model {
        len: Length,
        at: u64,
        calls: Vec<u64>,
        resets: u32,
    }

    fn model(len: Length) -> Model {
        Model {
            len,
            at: 0,
            calls: Vec::new(),
            resets: 0,
        }
    }

    impl StepModel for Model {
        fn length(&self) -> Length {
            self.len
        }
        fn go_to(&mut self, index: u64) {
            self.at = index;
            self.calls.push(index);
        }
        fn reset(&mut self) {
            self.resets += 1;
            self.at = 0;
        }
    }

    #[test]
    fn step_and_back_are_exact_and_stop_at_the_ends() {
        let mut m = model(Length::Finite(3));
        let mut s = Stepper::new(Speed::PerSecond(10.0));
        assert!(!s.apply(Command::Back, &mut m), "nothing before the start");
        for _ in 0..5 {
            s.apply(Command::Step, &mut m);
        }
        assert_eq!((s.index(), m.at), (3, 3));
        assert_eq!(
            m.calls,
            vec![1, 2, 3],
            "one go_to per change, none past the end"
        );
        s.apply(Command::Back, &mut m);
        assert_eq!(m.at, 2);
        s.apply(Command::Start, &mut m);
        assert_eq!(m.at, 0);
        s.apply(Command::End, &mut m);
        assert_eq!(m.at, 3);
        assert!(!s.can_step(m.len) && s.can_back());
    }

    #[test]
    fn seek_clamps_to_the_length() {
        let mut m = model(Length::Finite(50_000));
        let mut s = Stepper::new(Speed::Max);
        s.apply(Command::Seek(70_000), &mut m);
        assert_eq!(m.at, 50_000);
        s.apply(Command::Seek(12_345), &mut m);
        assert_eq!(m.at, 12_345);
        assert_eq!(m.calls, vec![50_000, 12_345]);
    }

    #[test]
    fn playing_advances_rate_times_time_and_carries_fractions() {
        let mut m = model(Length::Finite(1_000));
        let mut s = Stepper::new(Speed::PerSecond(10.0));
        s.apply(Command::Toggle, &mut m);
        assert!(s.playing());
        // 60 Hz frames at 10 steps/s: one step every 6 frames, 10 per second exactly.
        let mut moves = 0;
        for _ in 0..60 {
            if s.tick(1000.0 / 60.0, 0.0, &mut m) {
                moves += 1;
            }
        }
        assert_eq!((moves, m.at), (10, 10));
        // 0.5 steps/s (pendulum at 0.005×): one step in two seconds.
        s.apply(Command::SetSpeed(Speed::PerSecond(0.5)), &mut m);
        for _ in 0..7 {
            s.tick(250.0, 0.0, &mut m);
        }
        assert_eq!(m.at, 10, "1.75 s at 0.5 steps/s");
        s.tick(250.0, 0.0, &mut m);
        assert_eq!(m.at, 11, "2 s at 0.5 steps/s");
        assert!(s.playing(), "a speed change keeps playing");
    }

    #[test]
    fn a_background_tab_does_not_jump() {
        let mut m = model(Length::Unbounded);
        let mut s = Stepper::new(Speed::times_real_time(10.0, 100.0));
        s.apply(Command::Play, &mut m);
        s.tick(60_000.0, 0.0, &mut m);
        assert_eq!(m.at, 250, "1000 steps/s × 250 ms at most");
        s.tick(f64::NAN, 0.0, &mut m);
        s.tick(-5.0, 0.0, &mut m);
        assert_eq!(m.at, 250);
    }

    #[test]
    fn playing_stops_at_the_end_and_replays_from_the_start() {
        let mut m = model(Length::Finite(5));
        let mut s = Stepper::new(Speed::PerSecond(1000.0));
        s.apply(Command::Play, &mut m);
        s.tick(100.0, 0.0, &mut m);
        assert_eq!(m.at, 5);
        assert!(!s.playing(), "stopped at the end");
        assert!(!s.tick(100.0, 0.0, &mut m));
        s.apply(Command::Toggle, &mut m);
        assert_eq!(m.at, 0, "play at the end starts over");
        assert!(s.playing());
        s.apply(Command::Step, &mut m);
        assert!(!s.playing(), "a step pauses");
        assert_eq!(m.at, 1);
    }

    #[test]
    fn as_fast_as_possible_grows_and_shrinks_its_chunk_with_the_work() {
        let mut m = model(Length::Finite(50_000));
        let mut s = Stepper::new(Speed::Max);
        s.apply(Command::Play, &mut m);
        let mut frames = 0;
        while s.playing() {
            // The work grows with the chunk: 1 ms per 1,000 steps.
            let work = s.chunk as f64 / 1000.0;
            s.tick(16.0, work, &mut m);
            frames += 1;
            assert!(
                s.chunk <= 32_768,
                "chunk {} too large for the budget",
                s.chunk
            );
        }
        assert_eq!(m.at, 50_000);
        assert!(frames < 30, "{frames} frames for 50,000 steps");
        // Slow work shrinks the chunk back to one step a frame.
        s.apply(Command::Start, &mut m);
        s.apply(Command::Play, &mut m);
        for _ in 0..30 {
            s.tick(16.0, 100.0, &mut m);
        }
        assert_eq!(s.chunk, 1);
    }

    #[test]
    fn a_smaller_frame_budget_keeps_chunks_smaller() {
        let mut m = model(Length::Finite(1_000_000));
        let mut s = Stepper::new(Speed::Max);
        s.set_frame_budget(1.5);
        s.set_frame_budget(f64::NAN);
        s.apply(Command::Play, &mut m);
        for _ in 0..40 {
            // 1 ms per 1,000 steps: the budget allows about 1,500 a frame.
            let work = s.chunk as f64 / 1000.0;
            s.tick(16.0, work, &mut m);
            assert!(s.chunk <= 4096, "chunk {}", s.chunk);
        }
        assert!(s.chunk >= 1024, "chunk {}", s.chunk);
    }

    #[test]
    fn as_fast_as_possible_settles_at_the_budget() {
        let mut m = model(Length::Finite(10_000_000));
        let mut s = Stepper::new(Speed::Max);
        s.set_frame_budget(0.8);
        s.apply(Command::Play, &mut m);
        let mut works = Vec::new();
        for _ in 0..60 {
            // 0.2 ms of drawing a frame, then 1 ms per 1,000 steps.
            let work = 0.2 + s.chunk as f64 / 1000.0;
            works.push(work);
            s.tick(16.0, work, &mut m);
        }
        // Past the first frames, no frame's work swings above the budget.
        let settled = &works[20..];
        assert!(settled.iter().all(|w| *w <= 0.8 + 1e-9), "{settled:?}");
        assert!(settled.iter().all(|w| *w >= 0.6), "{settled:?}");
    }

    #[test]
    fn unbounded_models_have_no_end() {
        let mut m = model(Length::Unbounded);
        let mut s = Stepper::new(Speed::PerSecond(100.0));
        assert!(!s.apply(Command::End, &mut m));
        s.apply(Command::Seek(u64::MAX), &mut m);
        assert_eq!(m.at, u64::MAX);
        s.apply(Command::Step, &mut m);
        assert_eq!(m.at, u64::MAX, "saturates");
    }

    #[test]
    fn reset_pauses_and_calls_the_model() {
        let mut m = model(Length::Finite(10));
        let mut s = Stepper::new(Speed::PerSecond(1.0));
        s.apply(Command::Seek(7), &mut m);
        s.apply(Command::Play, &mut m);
        assert!(s.apply(Command::Reset, &mut m));
        assert_eq!((s.index(), m.at, m.resets, s.playing()), (0, 0, 1, false));
    }

    #[test]
    fn bad_speeds_are_refused_and_a_shorter_model_clamps() {
        let mut m = model(Length::Finite(10));
        let mut s = Stepper::new(Speed::PerSecond(2.0));
        for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            s.apply(Command::SetSpeed(Speed::PerSecond(bad)), &mut m);
            assert_eq!(s.speed(), Speed::PerSecond(2.0));
        }
        s.apply(Command::Seek(9), &mut m);
        m.len = Length::Finite(4);
        s.clamp_to(&mut m);
        assert_eq!((s.index(), m.at), (4, 4));
    }

    #[test]
    fn keys_map_to_commands() {
        assert_eq!(key_command("ArrowRight", false), Some(Command::Step));
        assert_eq!(key_command("PageDown", false), Some(Command::Step));
        assert_eq!(key_command("ArrowLeft", false), Some(Command::Back));
        assert_eq!(key_command("PageUp", false), Some(Command::Back));
        assert_eq!(key_command(" ", false), Some(Command::Toggle));
        assert_eq!(key_command("Home", false), Some(Command::Start));
        assert_eq!(key_command("End", false), Some(Command::End));
        assert_eq!(key_command("r", false), Some(Command::Reset));
        assert_eq!(key_command("ArrowRight", true), None);
        assert_eq!(key_command("x", false), None);
    }

    #[test]
    fn the_position_groups_its_digits_in_both_languages() {
        use crate::i18n::{FluentArg, I18n, Lang};
        let i18n = I18n::new();
        let say = |lang, index, end| {
            let (id, args) = position_message(index, end);
            let args: Vec<(&str, FluentArg)> =
                args.into_iter().map(|(k, v)| (k, v.into())).collect();
            i18n.t_args(lang, id, &args)
        };
        assert_eq!(say(Lang::En, 0, Some(228_608)), "Step 0 of 228,608");
        assert_eq!(
            say(Lang::Ja, 1_204, Some(228_608)),
            "228,608 ステップ中 1,204"
        );
        assert_eq!(say(Lang::En, 999, Some(1_000)), "Step 999 of 1,000");
        assert_eq!(say(Lang::Ja, 12_345_678, None), "ステップ 12,345,678");
    }
}
