//! The three built-in lessons, about ten minutes each, in the language shown: their routes and
//! page steps here, their titles and notes in Fluent (`lesson-builtin-<key>-...`).

use crate::ui::ctx;
use crate::view::lesson::{Lesson, LessonStep};

/// A built-in step: its route, its page steps, its focus (a section of the route's page) and
/// its exercise (one of the page's, or "").
type BuiltinStep = (&'static str, u32, &'static str, &'static str);

/// (key, steps): each step's note speaks of its focus only, and the controls it names are set
/// by its route.
#[rustfmt::skip]
pub const BUILTIN: [(&str, &[BuiltinStep]); 3] = [
    (
        "ik",
        &[
            ("#/ik-2r?elbow=down", 0, "arm", ""),
            ("#/ik-2r?q1=0.3&q2=0.05", 0, "heatmap", ""),
            ("#/ik-2r?q1=0.3&q2=0.05", 0, "sweep", ""),
            ("#/teleop?ik=pinv", 0, "world", ""),
        ],
    ),
    (
        "energy",
        &[
            ("#/pendulum-energy?damping=0", 0, "pendulum", ""),
            ("#/pendulum-energy?damping=0&compare=1", 0, "plot", ""),
            ("#/pendulum-energy?damping=0&timestep=0.01&compare=1", 0, "exercises", "pendulum-euler-dt"),
            ("#/pid-step", 0, "plot", ""),
        ],
    ),
    (
        "planning",
        &[
            ("#/rrt-2d?it=0", 5, "world", ""),
            ("#/cubic-path", 0, "plot", ""),
            ("#/trapezoid-profile", 0, "exercises", "trap-triangle"),
            ("#/traj-resample", 0, "plot", ""),
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
        .map(|(i, (route, page_steps, focus, exercise))| LessonStep {
            route: (*route).to_owned(),
            title: ctx::t(&format!("lesson-builtin-{key}-{}-title", i + 1)),
            note: ctx::t(&format!("lesson-builtin-{key}-{}-note", i + 1)),
            page_steps: *page_steps,
            focus: Some((*focus).to_owned()),
            exercise: (!exercise.is_empty()).then(|| (*exercise).to_owned()),
            goals: Vec::new(),
        })
        .filter(|s| is_page(&s.page()))
        .collect();
    Some(Lesson {
        title: ctx::t(&format!("lesson-builtin-{key}-title")),
        steps,
    })
}
