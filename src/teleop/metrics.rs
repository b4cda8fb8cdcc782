//! Per-episode figures: what the pilot's review and the repeatability comparison show.
//!
//! - `duration_s`: the last step's time; `path_m`: the tip's path length (sum of the straight
//!   segments between successive steps, from the start pose).
//! - `efficiency = ideal / path_m`, at most 1: the ideal path is the straight distance the task
//!   needed for what was achieved — to the edge of each reached target in turn (reach), from
//!   the start tip to the block if it was grasped, plus from the block's start to where it
//!   rests if the episode succeeded (pick tasks). 0 when the tip did not move.
//! - counts of events: collisions, joint-limit, speed-limit and singularity stops, grasps,
//!   grasp misses, drops, targets reached; the smallest manipulability on the way (start
//!   included).
//! - Fitts (reach tasks, when a target was reached): per reached target `i`,
//!   `ID_i = log2(D_i / W_i + 1)` with `D_i` the distance from the tip, when the previous
//!   target was confirmed (or at the start), to target `i`'s centre and `W_i` its diameter;
//!   `MT_i` the time from that moment until the tip entered target `i` for the hold that
//!   confirmed it (so the `success_steps` dwell is not counted); `id_bits` is the mean `ID_i`
//!   and `throughput_bits_per_s` the mean of `ID_i / MT_i` (ISO 9241-9's "mean of means").

#![warn(missing_docs)]

use serde::{Deserialize, Serialize};

use super::arm::{fk, manipulability};
use super::scene::{SceneConfig, Task};
use super::sim::{Event, Outcome, Sim, State, StepRecord};

/// Fitts' law figures of a reach episode.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Fitts {
    /// Mean index of difficulty of the reached targets, bits.
    pub id_bits: f64,
    /// Mean of ID / movement time, bits/s.
    pub throughput_bits_per_s: f64,
    /// How many targets the means are over.
    pub targets: usize,
}

/// The figures of one episode (see the module docs).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct EpisodeMetrics {
    /// Time of the last step, s.
    pub duration_s: f64,
    /// Length of the tip's path, m.
    pub path_m: f64,
    /// Ideal path / path, in [0, 1].
    pub efficiency: f64,
    /// [`Event::Collision`] count.
    pub collisions: u32,
    /// [`Event::JointLimit`] count.
    pub joint_limit_stops: u32,
    /// [`Event::SpeedLimit`] count.
    pub speed_limit_stops: u32,
    /// [`Event::Singularity`] count.
    pub singularity_stops: u32,
    /// [`Event::Grasp`] count.
    pub grasps: u32,
    /// [`Event::GraspMiss`] count.
    pub grasp_misses: u32,
    /// [`Event::Drop`] count.
    pub drops: u32,
    /// [`Event::TargetReached`] count.
    pub targets_reached: u32,
    /// The smallest [`manipulability`] of the episode, start included.
    pub min_manipulability: f64,
    /// Fitts' figures (reach tasks with a target reached).
    pub fitts: Option<Fitts>,
    /// The first failure event (grasp miss, drop, collision, timeout) and its step.
    pub first_failure: Option<(u64, Event)>,
    /// `None`: the episode was ended by the pilot or interrupted.
    pub outcome: Option<Outcome>,
}

fn dist(a: (f64, f64), b: (f64, f64)) -> f64 {
    let (dx, dz) = (a.0 - b.0, a.1 - b.1);
    (dx * dx + dz * dz).sqrt()
}

impl EpisodeMetrics {
    /// Figures with no event counted yet: the duration, the start's manipulability and the
    /// outcome given, the path and efficiency 0.
    pub fn empty(duration_s: f64, min_manipulability: f64, outcome: Option<Outcome>) -> Self {
        EpisodeMetrics {
            duration_s,
            path_m: 0.0,
            efficiency: 0.0,
            collisions: 0,
            joint_limit_stops: 0,
            speed_limit_stops: 0,
            singularity_stops: 0,
            grasps: 0,
            grasp_misses: 0,
            drops: 0,
            targets_reached: 0,
            min_manipulability,
            fitts: None,
            first_failure: None,
            outcome,
        }
    }

    /// Counts event `e` of step `step` (and keeps the first failure).
    pub fn count(&mut self, step: u64, e: &Event) {
        match e {
            Event::Collision { .. } => self.collisions += 1,
            Event::JointLimit { .. } => self.joint_limit_stops += 1,
            Event::SpeedLimit { .. } => self.speed_limit_stops += 1,
            Event::Singularity => self.singularity_stops += 1,
            Event::Grasp => self.grasps += 1,
            Event::GraspMiss => self.grasp_misses += 1,
            Event::Drop => self.drops += 1,
            Event::TargetReached { .. } => self.targets_reached += 1,
            _ => {}
        }
        if self.first_failure.is_none() && e.is_failure() {
            self.first_failure = Some((step, *e));
        }
    }

    /// The figures of an episode run with `config` from `start`, from its `records` (no
    /// re-simulation).
    pub fn of(config: &SceneConfig, start: &State, records: &[StepRecord]) -> EpisodeMetrics {
        let arm = &config.arm;
        let start_tip = fk(arm, &start.q);
        let mut m = EpisodeMetrics::empty(
            records.last().map_or(0.0, |r| r.t_s),
            manipulability(arm, &start.q),
            Outcome::of(records),
        );
        let mut prev = (start_tip.x, start_tip.z);
        let mut ideal = 0.0;
        // Reach: where and when the previous target was confirmed; Fitts per target.
        let mut leg_start = (prev, 0.0);
        let mut fitts: Vec<(f64, f64)> = Vec::new();
        let dwell_s = f64::from(config.success_steps.saturating_sub(1)) * Sim::DT;
        for r in records {
            let tip = (r.x, r.z);
            m.path_m += dist(prev, tip);
            prev = tip;
            m.min_manipulability = m.min_manipulability.min(r.manipulability);
            for e in &r.events {
                m.count(r.step, e);
                if let Event::TargetReached { index } = e {
                    if let Some(t) = config.task.targets().get(*index) {
                        let d = dist(leg_start.0, (t.x, t.z));
                        ideal += (d - t.radius).max(0.0);
                        let id =
                            crate::math::log(d / (2.0 * t.radius) + 1.0) / std::f64::consts::LN_2;
                        let movement_s = r.t_s - dwell_s - leg_start.1;
                        if movement_s > 0.0 {
                            fitts.push((id, id / movement_s));
                        }
                    }
                    leg_start = (tip, r.t_s);
                }
            }
        }
        if !matches!(config.task, Task::Reach { .. }) {
            let block0 = (start.block.x, start.block.z);
            if m.grasps > 0 {
                ideal += dist((start_tip.x, start_tip.z), block0);
            }
            if m.outcome == Some(Outcome::Success) {
                if let Some(last) = records.last() {
                    ideal += dist(block0, (last.block_x, last.block_z));
                }
            }
        }
        if m.path_m > 0.0 {
            m.efficiency = (ideal / m.path_m).min(1.0);
        }
        if !fitts.is_empty() {
            let n = fitts.len() as f64;
            m.fitts = Some(Fitts {
                id_bits: fitts.iter().map(|f| f.0).sum::<f64>() / n,
                throughput_bits_per_s: fitts.iter().map(|f| f.1).sum::<f64>() / n,
                targets: fitts.len(),
            });
        }
        m
    }
}

#[cfg(test)]
mod tests;
