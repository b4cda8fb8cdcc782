//! The run of the page: the recipe's tree grown to its end in time slices between frames,
//! and the iteration shown, a cursor into it; the stepper's model.

use crate::error::RecipeError;
use crate::i18n::FluentArg;
use crate::pyfmt::group_u64;
use crate::recipes::rrt_2d::{Rrt, RrtAt, RrtCursor, RrtSetup};
use crate::ui::ctx;
use crate::ui::kit::stepper::{Length, Speed, StepModel, StepperOptions};
use crate::ui::schedule::now_ms;

/// Playing speeds: iterations per second, then as fast as possible.
const SPEEDS: [Speed; 5] = [
    Speed::PerSecond(1.0),
    Speed::PerSecond(10.0),
    Speed::PerSecond(100.0),
    Speed::PerSecond(1000.0),
    Speed::Max,
];
/// 10 iterations a second.
const DEFAULT_SPEED: usize = 1;
/// Work per frame (iterations + drawing) playing as fast as possible aims at, ms: the stepper
/// scales its chunk by this over the last frame's work, so frames stay well under 2 ms.
pub const FRAME_BUDGET_MS: f64 = 1.0;

/// The stepper over the run: its speeds, labelled in iterations per second.
pub fn stepper_options() -> StepperOptions {
    StepperOptions {
        speeds: SPEEDS.to_vec(),
        initial_speed: DEFAULT_SPEED,
        speed_label: Box::new(|speed| match speed {
            Speed::PerSecond(rate) => ctx::t_args("rrt-speed", &[("rate", rate.into())]),
            Speed::Max => ctx::t("kit-stepper-speed-max"),
        }),
        testid: "rrt-2d-stepper",
    }
}

/// The run: grown to its end in time slices between frames (its length and the exports),
/// and the iteration shown, a cursor into it (the tree shown is a prefix of the run's: no
/// copy, End and any jump replay at most 64 iterations without a search).
pub struct Run {
    /// The run to its end, as far as the slices have grown it.
    pub finished: Rrt,
    /// The iteration shown.
    pub cursor: RrtCursor,
    /// Changes whenever the tree shown shrinks or is another run's (the tree layer is then
    /// redrawn whole).
    pub generation: u64,
    /// Time the last `go_to` took, ms.
    pub advance_ms: f64,
}

impl Run {
    pub fn new(setup: &RrtSetup, generation: u64) -> Result<Run, RecipeError> {
        let finished = Rrt::with_setup(setup)?;
        Ok(Run {
            cursor: finished.cursor(),
            finished,
            generation,
            advance_ms: 0.0,
        })
    }

    /// The run as it stood at the iteration shown.
    pub fn shown(&self) -> RrtAt<'_> {
        self.finished.at(&self.cursor)
    }

    /// Whether the run to its end is complete (its length known, the exports ready).
    pub fn is_finished(&self) -> bool {
        self.finished.is_done()
    }

    /// "Running to the end: 12,345 of 1,000,000 iterations", in the current language.
    pub fn progress_text(&self) -> String {
        ctx::t_args(
            "rrt-finishing",
            &[
                (
                    "it",
                    FluentArg::Text(group_u64(self.finished.iterations() as u64)),
                ),
                (
                    "max",
                    FluentArg::Text(group_u64(self.finished.max_iter() as u64)),
                ),
            ],
        )
    }

    /// Grows the run to its end for about `budget_ms`; `true` once it is complete.
    pub fn finish_for(&mut self, budget_ms: f64) -> bool {
        let started = now_ms();
        while !self.finished.is_done() {
            for _ in 0..256 {
                if self.finished.step_record().is_none() {
                    break;
                }
            }
            if now_ms() - started >= budget_ms {
                break;
            }
        }
        self.finished.is_done()
    }
}

impl StepModel for Run {
    /// The iterations known: the whole run once finished, else as far as it has grown.
    fn length(&self) -> Length {
        Length::Finite(self.finished.iterations() as u64)
    }
    fn go_to(&mut self, index: u64) {
        let started = now_ms();
        let k = usize::try_from(index).unwrap_or(usize::MAX);
        if k < self.shown().iterations() {
            self.generation += 1;
        }
        self.finished.seek_cursor(&mut self.cursor, k);
        self.advance_ms = now_ms() - started;
    }
}
