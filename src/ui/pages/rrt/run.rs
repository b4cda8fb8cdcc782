//! The run of the page: the recipe's tree grown to its end in time slices between frames,
//! and the iteration shown, a cursor into it; the stepper's model.

use crate::error::RecipeError;
use crate::recipes::rrt_2d::{Rrt, RrtAt, RrtCursor, RrtSetup};
use crate::ui::kit::stepper::{Length, StepModel};
use crate::ui::schedule::now_ms;

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
