//! The Robot Pilot pages' input as they use it: the devices' mapping of the teleop kernel
//! ([`crate::teleop::input`]: Isaac Lab's keyboard, gamepad and the pointer clutch, named here
//! for the pages) and the pacing of the frame loop that feeds the simulation.
//!
//! The simulation runs at a fixed 100 Hz whatever the display rate: [`Accumulator`] turns the
//! frame intervals into whole steps, and a key press that arrives between two steps is given one
//! step on the next frame, so at latency 0 the arm moves on the very next displayed frame.
//!
//! The page asks for animation frames only while something can change ([`FrameDemand`]): keys
//! held, a gamepad connected (it is polled, it sends no events), the clutch held, the
//! episode's clock running or a notice waiting to time out. An idle page requests no frames;
//! the next input asks for one, and that frame steps at once.

pub use crate::teleop::input::{
    clutch_axes, key_action, HeldKeys, KeyAction, PadMapper, PadOutput, PadSnapshot,
    GAMEPAD_DEAD_ZONE,
};

/// Simulation step, ms (100 Hz).
pub const STEP_MS: f64 = 10.0;
/// Most steps one displayed frame takes (a hidden tab coming back does not replay seconds).
pub const MAX_STEPS_PER_FRAME: u32 = 25;

/// The fixed-step accumulator: frame intervals in, whole 10 ms steps out.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Accumulator {
    /// Time owed to the simulation, ms (may be negative after a step given early).
    owed_ms: f64,
}

impl Accumulator {
    /// The steps to take for a frame `elapsed_ms` after the last; `fresh_input`: an input
    /// arrived since the last frame, which then gets at least one step (taken from the next
    /// frames' time, so the rate stays 100 Hz on average).
    pub fn steps(&mut self, elapsed_ms: f64, fresh_input: bool) -> u32 {
        let elapsed = if elapsed_ms.is_finite() {
            elapsed_ms.clamp(0.0, STEP_MS * f64::from(MAX_STEPS_PER_FRAME))
        } else {
            0.0
        };
        self.owed_ms += elapsed;
        let mut n = (self.owed_ms / STEP_MS).floor().max(0.0) as u32;
        if n == 0 && fresh_input && self.owed_ms > -STEP_MS {
            n = 1;
        }
        let n = n.min(MAX_STEPS_PER_FRAME);
        self.owed_ms -= f64::from(n) * STEP_MS;
        // Never bank more than one frame's worth (a long stall is dropped, not replayed).
        self.owed_ms = self.owed_ms.min(STEP_MS * f64::from(MAX_STEPS_PER_FRAME));
        n
    }

    /// Forget the time owed (pause, reset).
    pub fn clear(&mut self) {
        self.owed_ms = 0.0;
    }
}

/// What keeps the page's frame loop running (see the module docs).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct FrameDemand {
    /// A command key is held.
    pub keys_held: bool,
    /// A gamepad is connected: it is polled every frame.
    pub pad_connected: bool,
    /// The pointer holds the clutch.
    pub clutch_held: bool,
    /// The episode's clock runs (engaged, started, not ended): a step is owed every 10 ms.
    pub episode_running: bool,
    /// An input arrived that no frame has taken yet.
    pub fresh_input: bool,
    /// A notice shows until this time (ms, the frame clock), then the frame clears it.
    pub notice_until_ms: Option<f64>,
}

impl FrameDemand {
    /// Whether another frame is needed after the frame at `now_ms`.
    pub fn needs_frames(&self, now_ms: f64) -> bool {
        self.keys_held
            || self.pad_connected
            || self.clutch_held
            || self.episode_running
            || self.fresh_input
            || self.notice_until_ms.is_some_and(|until| until > now_ms)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_idle_page_needs_no_frames() {
        let idle = FrameDemand::default();
        assert!(!idle.needs_frames(0.0));
        let each = [
            FrameDemand {
                keys_held: true,
                ..idle
            },
            FrameDemand {
                pad_connected: true,
                ..idle
            },
            FrameDemand {
                clutch_held: true,
                ..idle
            },
            FrameDemand {
                episode_running: true,
                ..idle
            },
            FrameDemand {
                fresh_input: true,
                ..idle
            },
        ];
        for d in each {
            assert!(d.needs_frames(0.0), "{d:?}");
        }
        // A notice keeps frames coming until the frame that clears it.
        let notice = FrameDemand {
            notice_until_ms: Some(600.0),
            ..idle
        };
        assert!(notice.needs_frames(599.9));
        assert!(!notice.needs_frames(600.0));
        // Idle, then a press: the first frame takes one step at once (no time owed).
        let mut acc = Accumulator::default();
        assert_eq!(acc.steps(0.0, true), 1);
    }

    #[test]
    fn accumulator_runs_at_100_hz_and_answers_a_press_at_once() {
        let mut acc = Accumulator::default();
        // 60 Hz display: 16.67 ms frames → 1 or 2 steps, 100 per second.
        let total: u32 = (0..60).map(|_| acc.steps(1000.0 / 60.0, false)).sum();
        assert!((99..=100).contains(&total), "{total}");
        let mut acc = Accumulator::default();
        assert_eq!(acc.steps(4.0, false), 0);
        assert_eq!(
            acc.steps(4.0, true),
            1,
            "a key press steps on the next frame"
        );
        assert_eq!(acc.steps(4.0, false), 0, "the early step is paid back");
        assert_eq!(acc.steps(10.0, false), 1);
        assert_eq!(acc.steps(10_000.0, false), MAX_STEPS_PER_FRAME);
        assert_eq!(acc.steps(f64::NAN, false), 0, "no time, no step");
        acc.clear();
        assert_eq!(acc.steps(0.0, false), 0);
    }
}
