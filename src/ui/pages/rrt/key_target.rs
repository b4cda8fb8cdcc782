//! The world editor by keyboard: `n` chooses the start, the goal or a box in turn, `c` a
//! corner of that box (each corner in turn, then the whole box again), Shift + arrows move
//! the choice by [`KEY_STEP`] through the same `crate::view::rrt::drag` a pointer takes (a
//! corner resizes its box); a status line says what is chosen.

use crate::i18n::FluentArg;
use crate::ui::ctx;
use crate::view::rrt::{corners, Grab, PageState};

/// How far Shift + an arrow moves the start, the goal, a box or a corner (world units: the
/// square is 1).
pub const KEY_STEP: f64 = 0.01;
/// The corners `c` chooses in turn ([`Grab::Corner`] numbering): top right, top left, bottom
/// left, bottom right.
const CORNER_ORDER: [u8; 4] = [2, 3, 0, 1];
/// Fluent ids of "corner k of box n", by [`Grab::Corner`] numbering.
const CORNER_IDS: [&str; 4] = [
    "rrt-corner-bottom-left",
    "rrt-corner-bottom-right",
    "rrt-corner-top-right",
    "rrt-corner-top-left",
];

/// `n`: what comes after `current` among the start, the goal and each of the `boxes`,
/// round again.
pub fn next_target(current: Option<Grab>, boxes: usize) -> Grab {
    match current {
        None => Grab::Start,
        Some(Grab::Start) => Grab::Goal,
        Some(Grab::Goal) if boxes > 0 => Grab::Box(0),
        Some(Grab::Box(i) | Grab::Corner(i, _)) if i + 1 < boxes => Grab::Box(i + 1),
        _ => Grab::Start,
    }
}

/// `c`: a corner of the chosen box (of the `selected` one when the start or the goal is
/// chosen): the top-right corner first, then the others anticlockwise, then the whole box
/// again. `None` without a box.
pub fn next_corner(current: Option<Grab>, selected: Option<usize>, boxes: usize) -> Option<Grab> {
    let next = match current {
        Some(Grab::Box(i)) if i < boxes => Grab::Corner(i, CORNER_ORDER[0]),
        Some(Grab::Corner(i, k)) if i < boxes => match CORNER_ORDER.iter().position(|&c| c == k) {
            Some(at) if at + 1 < CORNER_ORDER.len() => Grab::Corner(i, CORNER_ORDER[at + 1]),
            _ => Grab::Box(i),
        },
        _ => match selected.filter(|&i| i < boxes) {
            Some(i) => Grab::Corner(i, CORNER_ORDER[0]),
            None if boxes > 0 => Grab::Corner(0, CORNER_ORDER[0]),
            None => return None,
        },
    };
    Some(next)
}

/// Where a key move of `grab` starts in `state` (a box moves by its offset alone).
pub fn start_point(state: &PageState, grab: Grab) -> [f64; 2] {
    match grab {
        Grab::Start => state.start,
        Grab::Goal => state.goal,
        Grab::Corner(i, k) => state
            .obstacles
            .get(i)
            .map_or([0.0, 0.0], |b| corners(b)[usize::from(k) % 4]),
        Grab::Box(_) => [0.0, 0.0],
    }
}

/// The status line: what Shift + arrows move, in the current language.
pub fn text(grab: Grab) -> String {
    let what = match grab {
        Grab::Start => ctx::t("rrt-point-start"),
        Grab::Goal => ctx::t("rrt-point-goal"),
        Grab::Box(i) => ctx::t_args("rrt-box-n", &[("n", FluentArg::Number((i + 1) as f64))]),
        Grab::Corner(i, k) => ctx::t_args(
            CORNER_IDS[usize::from(k) % CORNER_IDS.len()],
            &[("n", FluentArg::Number((i + 1) as f64))],
        ),
    };
    ctx::t_args("rrt-key-target", &[("what", FluentArg::Text(what))])
}
