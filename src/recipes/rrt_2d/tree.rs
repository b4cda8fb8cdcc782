//! [`Rrt`], the stepping handle: one call of [`Rrt::step`] / [`Rrt::step_record`] = one loop
//! iteration, with its sub-steps in an [`RrtIteration`]; [`Rrt::seek`] goes to the state after
//! any iteration, backwards too (an RNG checkpoint every [`CHECKPOINT_EVERY`] iterations, then
//! an exact replay of at most that many). The recipe run drives the same handle to the end, so
//! a stepped tree equals the batch tree. An [`RrtCursor`] reads a run as it stood at any
//! earlier iteration without copying it (its tree is a prefix of the run's; the run logs each
//! iteration's nearest node, so a replay needs no search).

use super::geometry::{distance, nearest_linear, path_length};
use super::iteration::{plan_iteration, RrtCounts, RrtIteration, RrtOutcome, RrtStep};
use super::nearest_index::NearestIndex;
use super::world::{RrtParams, RrtSetup, RrtWorld};
use crate::error::RecipeError;
use crate::rng::NumpyRng;

/// Iterations between two RNG checkpoints of [`Rrt`] (a step back replays at most this many).
pub const CHECKPOINT_EVERY: usize = 64;

#[derive(Debug, Clone)]
struct Checkpoint {
    rng: NumpyRng,
    nodes: usize,
    counts: RrtCounts,
}

/// An RRT being grown one iteration at a time, backwards too.
#[derive(Debug, Clone)]
pub struct Rrt {
    rng: NumpyRng,
    goal: [f64; 2],
    max_iter: usize,
    world: RrtWorld,
    iterations: usize,
    nodes: Vec<[f64; 2]>,
    parents: Vec<Option<usize>>,
    found: Option<usize>,
    index: NearestIndex,
    counts: RrtCounts,
    /// The state before iteration `k * CHECKPOINT_EVERY + 1`, for every `k` reached.
    checkpoints: Vec<Checkpoint>,
    last: Option<RrtIteration>,
    /// The node nearest the goal and its distance (`None`: not known, ask the index). Every
    /// goal-biased sample asks for it; a new node replaces it only when strictly nearer, as
    /// `argmin` keeps the first index.
    goal_nearest: Option<(usize, f64)>,
    /// Search by [`nearest_linear`] instead of the index (the reference, for tests and the
    /// benchmark's "before").
    linear: bool,
    /// The nearest node of each iteration (iteration `k` at `k - 1`): a [`RrtCursor`] replays
    /// an iteration from it without a search.
    nearest_log: Vec<u32>,
}

impl Rrt {
    /// A tree holding only the start node in the recipe's world, after validating `params`
    /// (a goal inside the box is allowed: it is never reached).
    pub fn new(params: &RrtParams) -> Result<Rrt, RecipeError> {
        Rrt::with_setup(&RrtSetup {
            params: *params,
            ..RrtSetup::default()
        })
    }

    /// A tree holding only `setup.world.start`, after validating `setup`.
    pub fn with_setup(setup: &RrtSetup) -> Result<Rrt, RecipeError> {
        setup.validate()?;
        let start = setup.world.start;
        let mut index = NearestIndex::new();
        index.insert(&[start], 0);
        let rng = NumpyRng::new(setup.params.seed);
        Ok(Rrt {
            checkpoints: vec![Checkpoint {
                rng: rng.clone(),
                nodes: 1,
                counts: RrtCounts::default(),
            }],
            rng,
            goal: setup.params.goal,
            max_iter: setup.params.max_iter,
            world: setup.world.clone(),
            iterations: 0,
            nodes: vec![start],
            parents: vec![None],
            found: None,
            index,
            counts: RrtCounts::default(),
            last: None,
            goal_nearest: None,
            linear: false,
            nearest_log: Vec::new(),
        })
    }

    /// Runs one iteration of the recipe's loop (or returns [`RrtStep::Exhausted`] when done).
    pub fn step(&mut self) -> RrtStep {
        self.step_record()
            .map_or(RrtStep::Exhausted, |r| r.as_step())
    }

    /// Runs one iteration and returns its sub-steps (`None` when done).
    pub fn step_record(&mut self) -> Option<RrtIteration> {
        if self.is_done() {
            return None;
        }
        if self.iterations % CHECKPOINT_EVERY == 0
            && self.checkpoints.len() == self.iterations / CHECKPOINT_EVERY
        {
            self.checkpoints.push(Checkpoint {
                rng: self.rng.clone(),
                nodes: self.nodes.len(),
                counts: self.counts,
            });
        }
        let record = self.iterate();
        self.last = Some(record);
        Some(record)
    }

    fn iterate(&mut self) -> RrtIteration {
        self.iterations += 1;
        let (index, nodes, goal, linear) = (&mut self.index, &self.nodes, self.goal, self.linear);
        let goal_nearest = &mut self.goal_nearest;
        let record = plan_iteration(
            &self.world,
            goal,
            &mut self.rng,
            self.iterations,
            nodes,
            |sample, goal_sample| {
                if linear {
                    nearest_linear(nodes, sample)
                } else if goal_sample {
                    match *goal_nearest {
                        Some((i, _)) => i,
                        None => {
                            let i = index.nearest(sample);
                            *goal_nearest = Some((i, distance(nodes[i], goal)));
                            i
                        }
                    }
                } else {
                    index.nearest(sample)
                }
            },
        );
        self.nearest_log.push(record.nearest as u32);
        self.counts.note(record.outcome);
        let added = match record.outcome {
            RrtOutcome::Added { id } => [Some((id, record.nearest)), None],
            RrtOutcome::GoalReached { id, goal_id } => {
                self.found = Some(goal_id);
                [Some((id, record.nearest)), Some((goal_id, id))]
            }
            _ => [None, None],
        };
        for (id, parent) in added.into_iter().flatten() {
            let point = if Some(id) == self.found {
                self.goal
            } else {
                record.candidate.unwrap_or(record.sample)
            };
            self.nodes.push(point);
            self.parents.push(Some(parent));
            self.index.insert(&self.nodes, id);
            self.note_goal_distance(id);
        }
        record
    }

    /// Node `id` was added: it becomes the goal's nearest when strictly nearer.
    fn note_goal_distance(&mut self, id: usize) {
        if let Some((_, best)) = self.goal_nearest {
            let d = distance(self.nodes[id], self.goal);
            if d < best {
                self.goal_nearest = Some((id, d));
            }
        }
    }

    /// Goes to the state after iteration `k` (0 = only the start), forwards by stepping or
    /// backwards by restoring the last checkpoint before `k` and replaying: the tree, the
    /// counters and [`Self::last`] are exactly those of a run stopped at `k`. Stops early at
    /// the end of the run; returns the iteration reached.
    pub fn seek(&mut self, k: usize) -> usize {
        if k < self.iterations {
            // Restore the checkpoint before iteration k (k >= 1: replay at least one, so that
            // `last` is iteration k's record).
            let c = k.saturating_sub(1) / CHECKPOINT_EVERY;
            let Some(cp) = self.checkpoints.get(c).cloned() else {
                return self.iterations;
            };
            self.checkpoints.truncate(c + 1);
            self.index.truncate(&self.nodes, cp.nodes);
            self.nodes.truncate(cp.nodes);
            self.parents.truncate(cp.nodes);
            self.rng = cp.rng;
            self.counts = cp.counts;
            self.iterations = c * CHECKPOINT_EVERY;
            self.nearest_log.truncate(self.iterations);
            self.found = None;
            self.last = None;
            self.goal_nearest = None;
        }
        while self.iterations < k && self.step_record().is_some() {}
        self.iterations
    }

    /// Searches the nearest node by the linear scan of the recipe (`true`) instead of the
    /// quadtree: the same tree, in O(n) per iteration (the reference and the benchmark's
    /// "before").
    pub fn set_linear_search(&mut self, linear: bool) {
        self.linear = linear;
    }

    /// Steps back `n` iterations (to 0 at most); returns the iteration reached.
    pub fn back(&mut self, n: usize) -> usize {
        self.seek(self.iterations.saturating_sub(n))
    }

    /// The sub-steps of the last iteration run (`None` at iteration 0).
    pub fn last(&self) -> Option<&RrtIteration> {
        self.last.as_ref()
    }

    /// Iterations by outcome so far.
    pub fn counts(&self) -> RrtCounts {
        self.counts
    }

    /// The world of this run.
    pub fn world(&self) -> &RrtWorld {
        &self.world
    }

    /// The iteration budget.
    pub fn max_iter(&self) -> usize {
        self.max_iter
    }

    /// Tree nodes, the start first.
    pub fn nodes(&self) -> &[[f64; 2]] {
        &self.nodes
    }

    /// Parent of each node (`None` for the start; `-1` in the CSV).
    pub fn parents(&self) -> &[Option<usize>] {
        &self.parents
    }

    /// Start-to-goal waypoints, empty until the goal is reached.
    pub fn path(&self) -> Vec<[f64; 2]> {
        tree_path(&self.nodes, &self.parents, self.found)
    }

    /// Sum of the path's segment lengths, NaN when the goal was not reached.
    pub fn path_length(&self) -> f64 {
        path_length(&self.path())
    }

    /// Id of the goal node once reached.
    pub fn found(&self) -> Option<usize> {
        self.found
    }

    /// Iterations run so far.
    pub fn iterations(&self) -> usize {
        self.iterations
    }

    /// The goal of this run.
    pub fn goal(&self) -> [f64; 2] {
        self.goal
    }

    /// Whether the goal was reached or the iteration budget is spent.
    pub fn is_done(&self) -> bool {
        self.found.is_some() || self.iterations >= self.max_iter
    }
}

/// Where a run stood after some iteration, read from the run grown at least that far: the
/// tree then is a prefix of the run's (nodes are only ever added), so a cursor holds only the
/// counters, the RNG and the last iteration's record. [`Rrt::seek_cursor`] moves it in at
/// most [`CHECKPOINT_EVERY`] replayed iterations, each without a search (the run logged its
/// nearest nodes); [`Rrt::at`] reads the run as it stood there.
#[derive(Debug, Clone)]
pub struct RrtCursor {
    rng: NumpyRng,
    iterations: usize,
    nodes: usize,
    counts: RrtCounts,
    last: Option<RrtIteration>,
}

impl Rrt {
    /// A cursor at iteration 0 of this run (only the start).
    pub fn cursor(&self) -> RrtCursor {
        let mut cursor = RrtCursor {
            rng: NumpyRng::new(0),
            iterations: usize::MAX,
            nodes: 1,
            counts: RrtCounts::default(),
            last: None,
        };
        self.seek_cursor(&mut cursor, 0);
        cursor
    }

    /// Moves `cursor` (a cursor of this run) to the state after iteration `k`, at most the
    /// iterations run so far: from the RNG checkpoint before `k` unless `k` lies a little
    /// ahead, then replaying; returns the iteration reached.
    pub fn seek_cursor(&self, cursor: &mut RrtCursor, k: usize) -> usize {
        let k = k.min(self.iterations);
        if k < cursor.iterations || k - cursor.iterations > CHECKPOINT_EVERY {
            // Replay at least one iteration (k >= 1), so that `last` is iteration k's.
            let c = k.saturating_sub(1) / CHECKPOINT_EVERY;
            let Some(cp) = self.checkpoints.get(c) else {
                return cursor.iterations;
            };
            *cursor = RrtCursor {
                rng: cp.rng.clone(),
                iterations: c * CHECKPOINT_EVERY,
                nodes: cp.nodes,
                counts: cp.counts,
                last: None,
            };
        }
        while cursor.iterations < k {
            let iteration = cursor.iterations + 1;
            let Some(&nearest) = self.nearest_log.get(iteration - 1) else {
                break;
            };
            let Some(tree) = self.nodes.get(..cursor.nodes) else {
                break;
            };
            let record = plan_iteration(
                &self.world,
                self.goal,
                &mut cursor.rng,
                iteration,
                tree,
                |_, _| nearest as usize,
            );
            cursor.iterations = iteration;
            cursor.counts.note(record.outcome);
            cursor.nodes += match record.outcome {
                RrtOutcome::Added { .. } => 1,
                RrtOutcome::GoalReached { .. } => 2,
                _ => 0,
            };
            cursor.last = Some(record);
        }
        cursor.iterations
    }

    /// This run as it stood at `cursor`.
    pub fn at<'a>(&'a self, cursor: &'a RrtCursor) -> RrtAt<'a> {
        RrtAt { rrt: self, cursor }
    }
}

/// A run as it stood at a cursor ([`Rrt::at`]): the same readers as [`Rrt`]'s.
#[derive(Debug, Clone, Copy)]
pub struct RrtAt<'a> {
    rrt: &'a Rrt,
    cursor: &'a RrtCursor,
}

impl<'a> RrtAt<'a> {
    /// Tree nodes, the start first.
    pub fn nodes(&self) -> &'a [[f64; 2]] {
        let nodes = self.rrt.nodes();
        &nodes[..self.cursor.nodes.min(nodes.len())]
    }

    /// Parent of each node.
    pub fn parents(&self) -> &'a [Option<usize>] {
        let parents = self.rrt.parents();
        &parents[..self.cursor.nodes.min(parents.len())]
    }

    /// The sub-steps of the last iteration (`None` at iteration 0).
    pub fn last(&self) -> Option<&'a RrtIteration> {
        self.cursor.last.as_ref()
    }

    /// Iterations by outcome so far.
    pub fn counts(&self) -> RrtCounts {
        self.cursor.counts
    }

    /// Iterations run so far.
    pub fn iterations(&self) -> usize {
        self.cursor.iterations
    }

    /// Id of the goal node once reached (the run's last iteration reached it).
    pub fn found(&self) -> Option<usize> {
        match self.cursor.last.map(|r| r.outcome) {
            Some(RrtOutcome::GoalReached { goal_id, .. }) => Some(goal_id),
            _ => None,
        }
    }

    /// Start-to-goal waypoints, empty until the goal is reached.
    pub fn path(&self) -> Vec<[f64; 2]> {
        tree_path(self.nodes(), self.parents(), self.found())
    }

    /// Sum of the path's segment lengths, NaN when the goal was not reached.
    pub fn path_length(&self) -> f64 {
        path_length(&self.path())
    }

    /// The run's world.
    pub fn world(&self) -> &'a RrtWorld {
        self.rrt.world()
    }

    /// The run's iteration budget.
    pub fn max_iter(&self) -> usize {
        self.rrt.max_iter()
    }
}

/// The waypoints from the root to node `found` (empty for `None`).
fn tree_path(nodes: &[[f64; 2]], parents: &[Option<usize>], found: Option<usize>) -> Vec<[f64; 2]> {
    let mut path = Vec::new();
    let mut next = found;
    while let Some(i) = next {
        let (Some(point), Some(parent)) = (nodes.get(i), parents.get(i)) else {
            break;
        };
        path.push(*point);
        next = *parent;
    }
    path.reverse();
    path
}
