//! What a practice arm's step detects ([`Event`]), how an episode ends ([`Outcome`]) and the
//! constants of the rules both arms share (`super::rules`): plain data, used by the planar
//! arm's `super::sim` and the SO-101's `crate::so101::sim`.

#![warn(missing_docs)]

use serde::{Deserialize, Serialize};

/// Gravity for a released block, m/s².
pub const GRAVITY: f64 = 9.81;
/// A joint that hit a position limit reports [`Event::JointLimit`] again only after it has
/// moved this far from the limit, rad (so pressing against a limit is one stop, however the
/// IK jitters along it).
pub const LIMIT_REARM_RAD: f64 = 0.01;

/// How an episode ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum Outcome {
    /// The goal condition held long enough.
    Success,
    /// The time box ran out.
    Timeout,
}

impl Outcome {
    /// How steps with these events ended: the last [`Event::Success`] or [`Event::Timeout`]
    /// among them (`None`: ended by the pilot or interrupted).
    pub fn of_events<'a>(steps: impl DoubleEndedIterator<Item = &'a [Event]>) -> Option<Outcome> {
        steps.rev().find_map(|events| {
            events.iter().find_map(|e| match e {
                Event::Success => Some(Outcome::Success),
                Event::Timeout => Some(Outcome::Timeout),
                _ => None,
            })
        })
    }

    /// `success`, `timeout`.
    pub fn id(self) -> &'static str {
        match self {
            Outcome::Success => "success",
            Outcome::Timeout => "timeout",
        }
    }
}

/// Something the step detected. Links and joints count from 1; link 4 in a collision is the
/// carried block; target indices count from 0 (as [`crate::teleop::sim::State::target_index`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum Event {
    /// The gripper closed on the block.
    Grasp,
    /// The gripper closed on nothing.
    GraspMiss,
    /// The gripper opened and let the block go.
    Release,
    /// The block fell from the gripper outside the goal.
    Drop,
    /// A motion was stopped by contact of this link (1–3; 4 = the carried block).
    Collision {
        /// 1–3 a link (the fingers are link 3), 4 the carried block.
        link: u8,
    },
    /// This joint (1–3) hit a position limit.
    JointLimit {
        /// 1 shoulder, 2 elbow, 3 wrist.
        joint: u8,
    },
    /// This joint's (1–3) speed limit cut the step.
    SpeedLimit {
        /// 1 shoulder, 2 elbow, 3 wrist.
        joint: u8,
    },
    /// Motion was commanded near a singularity (or the IK could not solve).
    Singularity,
    /// Reach target `index` (from 0) was held long enough.
    TargetReached {
        /// Index into the task's targets, from 0.
        index: usize,
    },
    /// The episode succeeded.
    Success,
    /// The time box ran out.
    Timeout,
}

impl Event {
    /// `grasp`, `grasp-miss`, `release`, `drop`, `collision`, `joint-limit`, `speed-limit`,
    /// `singularity`, `target-reached`, `success`, `timeout`.
    pub fn id(&self) -> &'static str {
        match self {
            Event::Grasp => "grasp",
            Event::GraspMiss => "grasp-miss",
            Event::Release => "release",
            Event::Drop => "drop",
            Event::Collision { .. } => "collision",
            Event::JointLimit { .. } => "joint-limit",
            Event::SpeedLimit { .. } => "speed-limit",
            Event::Singularity => "singularity",
            Event::TargetReached { .. } => "target-reached",
            Event::Success => "success",
            Event::Timeout => "timeout",
        }
    }

    /// The link, joint or target index the event names, if any.
    pub fn arg(&self) -> Option<usize> {
        match self {
            Event::Collision { link } => Some(usize::from(*link)),
            Event::JointLimit { joint } | Event::SpeedLimit { joint } => Some(usize::from(*joint)),
            Event::TargetReached { index } => Some(*index),
            _ => None,
        }
    }

    /// The event as the episode CSV writes it: the id, then `:` and the argument if any
    /// (`collision:2`, `target-reached:0`).
    pub fn text(&self) -> String {
        match self.arg() {
            Some(arg) => format!("{}:{arg}", self.id()),
            None => self.id().to_string(),
        }
    }

    /// Reads [`Self::text`] back.
    pub fn from_text(text: &str) -> Option<Event> {
        let (id, arg) = match text.split_once(':') {
            Some((id, arg)) => (id, Some(arg.parse::<usize>().ok()?)),
            None => (text, None),
        };
        let small = |a: usize| u8::try_from(a).ok();
        Some(match (id, arg) {
            ("grasp", None) => Event::Grasp,
            ("grasp-miss", None) => Event::GraspMiss,
            ("release", None) => Event::Release,
            ("drop", None) => Event::Drop,
            ("collision", Some(a)) => Event::Collision { link: small(a)? },
            ("joint-limit", Some(a)) => Event::JointLimit { joint: small(a)? },
            ("speed-limit", Some(a)) => Event::SpeedLimit { joint: small(a)? },
            ("singularity", None) => Event::Singularity,
            ("target-reached", Some(index)) => Event::TargetReached { index },
            ("success", None) => Event::Success,
            ("timeout", None) => Event::Timeout,
            _ => return None,
        })
    }

    /// Whether the event is a failure the pilot should review (grasp miss, drop, collision,
    /// timeout).
    pub fn is_failure(&self) -> bool {
        matches!(
            self,
            Event::GraspMiss | Event::Drop | Event::Collision { .. } | Event::Timeout
        )
    }
}
