//! One iteration of the recipe's loop and its record: sample → nearest → steer → check → add,
//! the sub-steps a page shows, the outcome, and the counts by outcome.

use super::geometry::{check_points, norm};
use super::world::{RrtWorld, MIN_EXTENSION, SEGMENT_CHECKS};
use crate::rng::NumpyRng;

/// Why a candidate node was not added.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RejectReason {
    /// The candidate lies outside the unit square.
    OutOfBounds,
    /// A check point of the segment from the nearest node lies in an obstacle.
    Collision,
}

/// What one iteration did.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum RrtStep {
    /// The sample fell on its nearest node (`|d| < 1e-12`): nothing to extend.
    Sampled { sample: [f64; 2], nearest: usize },
    /// Node `id` at `point` was added with parent `nearest`.
    Added {
        sample: [f64; 2],
        nearest: usize,
        id: usize,
        point: [f64; 2],
    },
    /// The candidate `point` (extended from `nearest`) was not added.
    Rejected {
        sample: [f64; 2],
        nearest: usize,
        point: [f64; 2],
        reason: RejectReason,
    },
    /// Node `id` at `point` was added and reaches the goal, which became node `goal_id`.
    Found {
        sample: [f64; 2],
        nearest: usize,
        id: usize,
        point: [f64; 2],
        goal_id: usize,
    },
    /// No iteration ran: the budget is spent or the goal was already reached.
    Exhausted,
}

/// How an iteration ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RrtOutcome {
    /// Node `id` was added.
    Added { id: usize },
    /// The candidate left the unit square.
    OutOfSquare,
    /// A check point of the segment lies in a box.
    Collision,
    /// The sample lies on its nearest node (`|d| < 1e-12`).
    ZeroLength,
    /// Node `id` was added and the goal, node `goal_id`, with it: the search is over.
    GoalReached { id: usize, goal_id: usize },
}

impl RrtOutcome {
    /// A short stable name: `added`, `out-of-square`, `collision`, `zero-length`,
    /// `goal-reached`.
    pub fn name(&self) -> &'static str {
        match self {
            RrtOutcome::Added { .. } => "added",
            RrtOutcome::OutOfSquare => "out-of-square",
            RrtOutcome::Collision => "collision",
            RrtOutcome::ZeroLength => "zero-length",
            RrtOutcome::GoalReached { .. } => "goal-reached",
        }
    }
}

/// A segment check that failed: the first of the 12 points inside a box.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Hit {
    /// Which check point (0 = the segment's start, 11 = its end).
    pub point: usize,
    /// Which box (0-based, the first containing the point).
    pub obstacle: usize,
}

/// The sub-steps of one iteration: sample → nearest → steer → check → add.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RrtIteration {
    /// 1-based number of this iteration.
    pub iteration: usize,
    /// The sample `q`.
    pub sample: [f64; 2],
    /// Whether `q` is the goal itself (the goal-biased draw).
    pub goal_sample: bool,
    /// Index of the nearest node and its position.
    pub nearest: usize,
    pub from: [f64; 2],
    /// `|q - n_i|`, as the recipe computes it.
    pub distance: f64,
    /// The steered candidate (`None` when the extension has zero length).
    pub candidate: Option<[f64; 2]>,
    /// Whether the 12-point segment check ran (the candidate is in the square).
    pub checked: bool,
    /// The first colliding check point, if the check failed.
    pub hit: Option<Hit>,
    /// For an added node: its distance to the goal, and, when within the tolerance, the
    /// goal segment's first colliding point (`Some(None)` = clear: goal reached).
    pub to_goal: Option<f64>,
    pub goal_hit: Option<Option<Hit>>,
    pub outcome: RrtOutcome,
}

impl RrtIteration {
    /// The 12 check points of the segment nearest → candidate, as the recipe computes them
    /// (`None` when there is no candidate).
    pub fn check_points(&self) -> Option<[[f64; 2]; SEGMENT_CHECKS]> {
        self.candidate.map(|c| check_points(self.from, c))
    }

    /// The same iteration as the plain [`RrtStep`].
    pub fn as_step(&self) -> RrtStep {
        let (sample, nearest) = (self.sample, self.nearest);
        let point = self.candidate.unwrap_or(self.sample);
        match self.outcome {
            RrtOutcome::ZeroLength => RrtStep::Sampled { sample, nearest },
            RrtOutcome::Added { id } => RrtStep::Added {
                sample,
                nearest,
                id,
                point,
            },
            RrtOutcome::OutOfSquare | RrtOutcome::Collision => RrtStep::Rejected {
                sample,
                nearest,
                point,
                reason: if self.outcome == RrtOutcome::Collision {
                    RejectReason::Collision
                } else {
                    RejectReason::OutOfBounds
                },
            },
            RrtOutcome::GoalReached { id, goal_id } => RrtStep::Found {
                sample,
                nearest,
                id,
                point,
                goal_id,
            },
        }
    }
}

/// Iterations by outcome so far.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct RrtCounts {
    pub added: usize,
    pub out_of_square: usize,
    pub collision: usize,
    pub zero_length: usize,
}

impl RrtCounts {
    /// Counts one iteration's outcome (the goal reached counts as an added node).
    pub(super) fn note(&mut self, outcome: RrtOutcome) {
        match outcome {
            RrtOutcome::Added { .. } | RrtOutcome::GoalReached { .. } => self.added += 1,
            RrtOutcome::OutOfSquare => self.out_of_square += 1,
            RrtOutcome::Collision => self.collision += 1,
            RrtOutcome::ZeroLength => self.zero_length += 1,
        }
    }
}

/// One iteration of the recipe's loop over the tree `nodes`, the nearest node of the sample
/// given by `nearest(sample, goal_sample)`: its sub-steps and outcome (a node added gets the
/// id `nodes.len()`, the goal the next). The tree is not changed: [`Rrt`](super::Rrt) adds the
/// nodes, a [`RrtCursor`](super::RrtCursor) replays a run's iteration with the nearest node it logged.
pub(super) fn plan_iteration(
    world: &RrtWorld,
    goal: [f64; 2],
    rng: &mut NumpyRng,
    iteration: usize,
    nodes: &[[f64; 2]],
    nearest: impl FnOnce([f64; 2], bool) -> usize,
) -> RrtIteration {
    let goal_sample = rng.random() < world.goal_bias;
    let sample = if goal_sample {
        goal
    } else {
        let x = rng.random();
        let y = rng.random();
        [x, y]
    };
    let nearest = nearest(sample, goal_sample);
    let from = nodes[nearest];
    let direction = [sample[0] - from[0], sample[1] - from[1]];
    let distance = norm(direction);
    let mut record = RrtIteration {
        iteration,
        sample,
        goal_sample,
        nearest,
        from,
        distance,
        candidate: None,
        checked: false,
        hit: None,
        to_goal: None,
        goal_hit: None,
        outcome: RrtOutcome::ZeroLength,
    };
    if distance < MIN_EXTENSION {
        return record;
    }
    let reach = world.step.min(distance);
    let point = [
        from[0] + direction[0] / distance * reach,
        from[1] + direction[1] / distance * reach,
    ];
    record.candidate = Some(point);
    if !(0.0..=1.0).contains(&point[0]) || !(0.0..=1.0).contains(&point[1]) {
        record.outcome = RrtOutcome::OutOfSquare;
        return record;
    }
    record.checked = true;
    record.hit = first_hit(world, from, point);
    if record.hit.is_some() {
        record.outcome = RrtOutcome::Collision;
        return record;
    }
    let id = nodes.len();
    record.outcome = RrtOutcome::Added { id };
    let to_goal = norm([point[0] - goal[0], point[1] - goal[1]]);
    record.to_goal = Some(to_goal);
    if to_goal < world.goal_tol {
        let hit = first_hit(world, point, goal);
        record.goal_hit = Some(hit);
        if hit.is_none() {
            record.outcome = RrtOutcome::GoalReached {
                id,
                goal_id: id + 1,
            };
        }
    }
    record
}

/// The first of the 12 check points of `a -> b` inside a box of `world`.
fn first_hit(world: &RrtWorld, a: [f64; 2], b: [f64; 2]) -> Option<Hit> {
    if world.obstacles.is_empty() {
        return None;
    }
    check_points(a, b)
        .iter()
        .enumerate()
        .find_map(|(point, p)| world.box_at(*p).map(|obstacle| Hit { point, obstacle }))
}
