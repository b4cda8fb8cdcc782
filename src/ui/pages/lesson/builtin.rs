//! The three built-in lessons, about ten minutes each, in the language shown: their routes and
//! page steps here, their titles and notes in Fluent (`lesson-builtin-<key>-...`).

use crate::ui::ctx;
use crate::view::lesson::{Lesson, LessonStep};

/// (key, [(route, page steps)]).
pub const BUILTIN: [(&str, &[(&str, u32)]); 3] = [
    (
        "ik",
        &[
            ("#/ik-2r", 0),
            ("#/ik-2r?q1=0.3&q2=0.05", 0),
            ("#/drills?recipe=jacobian-2r", 0),
            ("#/teleop", 0),
        ],
    ),
    (
        "energy",
        &[
            ("#/pendulum-energy?damping=0", 0),
            ("#/pendulum-energy?damping=0&compare=1", 0),
            ("#/pendulum-energy?damping=0&timestep=0.01&compare=1", 0),
            ("#/pid-step", 0),
        ],
    ),
    (
        "planning",
        &[
            ("#/rrt-2d?it=0", 5),
            ("#/cubic-path", 0),
            ("#/trapezoid-profile", 0),
            ("#/traj-resample", 0),
        ],
    ),
];

/// The built-in lesson shown, ready to present, while the user has none of their own.
pub const FIRST: &str = "ik";

/// Built-in lesson `key` in the current language, keeping only steps whose page exists.
pub fn lesson(key: &str, is_page: impl Fn(&str) -> bool) -> Option<Lesson> {
    let (_, steps) = BUILTIN.iter().find(|(k, _)| *k == key)?;
    let steps = steps
        .iter()
        .enumerate()
        .map(|(i, (route, page_steps))| LessonStep {
            route: (*route).to_owned(),
            title: ctx::t(&format!("lesson-builtin-{key}-{}-title", i + 1)),
            note: ctx::t(&format!("lesson-builtin-{key}-{}-note", i + 1)),
            page_steps: *page_steps,
        })
        .filter(|s| is_page(&s.page()))
        .collect();
    Some(Lesson {
        title: ctx::t(&format!("lesson-builtin-{key}-title")),
        steps,
    })
}
