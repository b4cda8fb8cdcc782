//! The step rules both practice arms share, the planar arm's [`super::Sim`] and the SO-101's
//! [`crate::so101::Sim`]: the order of a step ([`step`], each arm's part of it [`Steps`]), the
//! latency queue, the input noise, a joint step scaled to the speed limits, joint position
//! limits, events on a rising edge, a falling object, the goal held for `success_steps` steps
//! and the time box. Arithmetic only, in a fixed order, so that both simulations stay bit for
//! bit the same natively and in wasm.

#![warn(missing_docs)]

use std::collections::VecDeque;

use super::events::{Event, Outcome, GRAVITY, LIMIT_REARM_RAD};
use crate::rng::NumpyRng;

/// What every arm's step works on besides its own motion: the latency queue, the noise, the
/// clock, the time box and whether the episode ended.
pub struct Run<'a, C> {
    /// Commands given but not yet applied.
    pub pending: &'a mut VecDeque<C>,
    /// Steps a command waits before it acts.
    pub latency_steps: u32,
    /// Standard deviation of the noise added to each axis.
    pub noise_sigma: f64,
    /// The noise's generator.
    pub rng: &'a mut NumpyRng,
    /// Steps taken.
    pub step: &'a mut u64,
    /// Time since the start, s.
    pub t_s: &'a mut f64,
    /// Steps per second.
    pub rate_hz: u32,
    /// The time box, s.
    pub time_box_s: f64,
    /// Set when the episode ended.
    pub done: &'a mut Option<Outcome>,
}

/// An arm's part of [`step`].
pub trait Steps {
    /// The operator's input for one step.
    type Command: Copy;

    /// `cmd` with its axes clamped to [−1, 1], NaN read as 0.
    fn sanitized(cmd: &Self::Command) -> Self::Command;
    /// No motion, the gripper as it is.
    fn idle(&self) -> Self::Command;
    /// Whether `cmd` closes the gripper.
    fn closes(cmd: &Self::Command) -> bool;
    /// `cmd` with `noise` applied to its axes, in the arm's axis order.
    fn noisy(cmd: Self::Command, noise: impl FnOnce(&mut [f64])) -> Self::Command;
    /// What the step works on besides the arm's own motion.
    fn run(&mut self) -> Run<'_, Self::Command>;
    /// The applied command's motion: IK, speed and position limits, contact.
    fn move_arm(&mut self, applied: &Self::Command, events: &mut Vec<Event>);
    /// The gripper follows the command: grasp, miss, release, drop.
    fn operate_gripper(&mut self, close: bool, events: &mut Vec<Event>);
    /// The object follows the gripper, falls, or rests.
    fn move_object(&mut self);
    /// The goal condition, counted after the clock advanced.
    fn check_goal(&mut self, events: &mut Vec<Event>);
}

/// The [`Steps`] methods that read what both arms' `Sim`s hold alike (`config`'s
/// `latency_steps`, `noise_sigma` and `time_box_s`; `state`'s `pending`, `step`, `t_s`,
/// `done` and `gripper_closed`; `rng`; `RATE_HZ`; the command's `sanitized`, `idle` and
/// `gripper_closed`), inside `impl Steps for Sim`: `run_parts!(Command);`.
macro_rules! run_parts {
    ($command:ty) => {
        fn sanitized(cmd: &$command) -> $command {
            cmd.sanitized()
        }

        fn idle(&self) -> $command {
            <$command>::idle(self.state.gripper_closed)
        }

        fn closes(cmd: &$command) -> bool {
            cmd.gripper_closed
        }

        fn run(&mut self) -> $crate::teleop::rules::Run<'_, $command> {
            let s = &mut self.state;
            $crate::teleop::rules::Run {
                pending: &mut s.pending,
                latency_steps: self.config.latency_steps,
                noise_sigma: self.config.noise_sigma,
                rng: &mut self.rng,
                step: &mut s.step,
                t_s: &mut s.t_s,
                rate_hz: Self::RATE_HZ,
                time_box_s: self.config.time_box_s,
                done: &mut s.done,
            }
        }
    };
}
pub(crate) use run_parts;

/// One step of `arm` with `cmd`: the command (sanitized), the command applied and the
/// step's events, for the arm's record of the step. After the episode ended nothing changes:
/// the command applied is idle and there are no events. Else, in order: the command enters
/// the latency queue and the one `latency_steps` old leaves it ([`delayed`]); noise is added
/// to its axes ([`add_noise`]); the arm moves, the gripper and the object follow; the clock
/// advances ([`tick`]); the goal is counted; then the time box ([`time_box`]).
pub fn step<A: Steps>(arm: &mut A, cmd: &A::Command) -> (A::Command, A::Command, Vec<Event>) {
    let cmd = A::sanitized(cmd);
    if arm.run().done.is_some() {
        return (cmd, arm.idle(), Vec::new());
    }
    let mut events = Vec::new();
    let idle = arm.idle();
    let run = arm.run();
    let delayed = delayed(run.pending, run.latency_steps, cmd, idle);
    let applied = A::noisy(delayed, |axes| add_noise(axes, run.noise_sigma, run.rng));
    arm.move_arm(&applied, &mut events);
    arm.operate_gripper(A::closes(&applied), &mut events);
    arm.move_object();
    let run = arm.run();
    tick(run.step, run.t_s, run.rate_hz);
    arm.check_goal(&mut events);
    let run = arm.run();
    time_box(*run.t_s, run.time_box_s, run.done, &mut events);
    (cmd, applied, events)
}

/// The command `latency_steps` old: `cmd` enters the queue (which starts full of `idle`
/// commands), the oldest leaves it; `cmd` itself without latency.
pub fn delayed<C: Copy>(pending: &mut VecDeque<C>, latency_steps: u32, cmd: C, idle: C) -> C {
    if latency_steps == 0 {
        return cmd;
    }
    pending.push_back(cmd);
    pending.pop_front().unwrap_or(idle)
}

/// Adds `sigma × N(0, 1)` to each axis, in order (one draw per axis).
pub fn add_noise(axes: &mut [f64], sigma: f64, rng: &mut NumpyRng) {
    if sigma > 0.0 {
        for v in axes.iter_mut() {
            *v += sigma * rng.standard_normal();
        }
    }
}

/// Scales the whole joint step `dq` down (its direction kept) so that no joint moves faster
/// than `qd_max` over `dt`; [`Event::SpeedLimit`] names the joint that limited it when the
/// previous step (`was`) was not limited. Returns whether this step was.
pub fn limit_speed(
    dq: &mut [f64],
    qd_max: &[f64],
    dt: f64,
    was: bool,
    events: &mut Vec<Event>,
) -> bool {
    let mut worst = (1.0, 0usize);
    for (i, d) in dq.iter().enumerate() {
        let ratio = d.abs() / (qd_max[i] * dt);
        if ratio > worst.0 {
            worst = (ratio, i);
        }
    }
    let limited = worst.0 > 1.0;
    if limited {
        for d in dq.iter_mut() {
            *d /= worst.0;
        }
        if !was {
            events.push(Event::SpeedLimit {
                joint: worst.1 as u8 + 1,
            });
        }
    }
    limited
}

/// `q + dq` clamped joint by joint into `limits` (lower, upper) into `out`; a joint that
/// reaches its limit is [`Event::JointLimit`] once, until it leaves the limit by
/// [`LIMIT_REARM_RAD`] (`at_limit` keeps which joints rest there).
pub fn clamp_to_limits(
    q: &[f64],
    dq: &[f64],
    limits: &[(f64, f64)],
    at_limit: &mut [bool],
    out: &mut [f64],
    events: &mut Vec<Event>,
) {
    for (i, (lo, hi)) in limits.iter().enumerate() {
        let target = q[i] + dq[i];
        let clamped = target.clamp(*lo, *hi);
        let near_limit = (clamped - lo).min(hi - clamped) < LIMIT_REARM_RAD;
        let now = clamped != target || (at_limit[i] && near_limit);
        if now && !at_limit[i] {
            events.push(Event::JointLimit { joint: i as u8 + 1 });
        }
        at_limit[i] = now;
        out[i] = clamped;
    }
}

/// [`Event::Collision`] for each link (from 1) in contact now and not on the last step;
/// `was` becomes `now`.
pub fn new_contacts(now: &[bool], was: &mut [bool], events: &mut Vec<Event>) {
    for (i, (n, w)) in now.iter().zip(was.iter_mut()).enumerate() {
        if *n && !*w {
            events.push(Event::Collision { link: i as u8 + 1 });
        }
        *w = *n;
    }
}

/// One explicit-Euler step (g = [`GRAVITY`]) of an object of half height `half` falling
/// towards `support`; `true` when it came to rest on it.
pub fn fall(z: &mut f64, vz: &mut f64, half: f64, support: f64, dt: f64) -> bool {
    *vz -= GRAVITY * dt;
    *z += *vz * dt;
    if *z - half <= support {
        *z = support + half;
        *vz = 0.0;
        return true;
    }
    false
}

/// Counts the steps the goal condition `holds` in a row; `true` (and the count back to 0)
/// when it reached `needed`.
pub fn goal_held(count: &mut u32, holds: bool, needed: u32) -> bool {
    *count = if holds { *count + 1 } else { 0 };
    if *count < needed {
        return false;
    }
    *count = 0;
    true
}

/// Advances the clock by one step of a `rate_hz` simulation.
pub fn tick(step: &mut u64, t_s: &mut f64, rate_hz: u32) {
    *step += 1;
    *t_s = *step as f64 / f64::from(rate_hz);
}

/// The time box: at `t_s ≥ time_box_s` an episode not yet done ends ([`Event::Timeout`]).
pub fn time_box(t_s: f64, time_box_s: f64, done: &mut Option<Outcome>, events: &mut Vec<Event>) {
    if done.is_none() && t_s >= time_box_s {
        *done = Some(Outcome::Timeout);
        events.push(Event::Timeout);
    }
}
