//! The selection's status line: "Point 3 of 12 selected, at (x, y)…", the handle selected,
//! or that none is. A polite live region (each write is read out), so it is written only
//! when what it says changes; the page says it at once when the selection changes, once a
//! held key or a typed `x` settles, at a drag's end (never during).

use std::cell::Cell;

use web_sys::Element;

use crate::i18n::FluentArg;
use crate::ui::ctx;
use crate::view::umeyama_2d::{num, selected_point, Grab, Scene};

/// What the line depends on: the point count, what is selected and where (a point's place;
/// the translation; the rotation handle's angle and scale).
type SelectionKey = (usize, Option<(Grab, [f64; 2])>);

/// The status line component.
pub struct SelectionLine {
    element: Element,
    /// What the line says now (`None`: not said yet).
    said: Cell<Option<SelectionKey>>,
}

fn key(scene: &Scene, selected: Option<Grab>) -> SelectionKey {
    let at = selected.and_then(|g| {
        let truth = scene.truth();
        match g {
            Grab::Point(i) => scene.x.get(i).copied(),
            Grab::Translation => Some(truth.t),
            Grab::Rotation => Some([truth.angle_deg, truth.scale]),
        }
        .map(|at| (g, at))
    });
    (scene.x.len(), at)
}

/// The view's `data-selected` for tests: a point's index, `t` or `r` (empty: none).
pub fn selected_attr(selected: Option<Grab>) -> String {
    match selected {
        Some(Grab::Point(i)) => i.to_string(),
        Some(Grab::Translation) => "t".into(),
        Some(Grab::Rotation) => "r".into(),
        None => String::new(),
    }
}

impl SelectionLine {
    /// Drives `element`.
    pub fn new(element: Element) -> SelectionLine {
        SelectionLine {
            element,
            said: Cell::new(None),
        }
    }

    /// Whether the line says `selected` of `scene` already.
    pub fn says(&self, scene: &Scene, selected: Option<Grab>) -> bool {
        self.said.get() == Some(key(scene, selected))
    }

    /// The next [`SelectionLine::show`] writes (a language switch).
    pub fn forget(&self) {
        self.said.set(None);
    }

    /// Says `selected` of `scene` unless the line says it already; `true` if it wrote.
    pub fn show(&self, scene: &Scene, selected: Option<Grab>) -> bool {
        let key = key(scene, selected);
        if self.said.replace(Some(key)) == Some(key) {
            return false;
        }
        let count = FluentArg::Number(scene.x.len() as f64);
        let truth = scene.truth();
        let text = match selected {
            Some(Grab::Translation) => ctx::t_args(
                "umeyama-selected-translation",
                &[
                    ("x", FluentArg::Text(num(truth.t[0]))),
                    ("y", FluentArg::Text(num(truth.t[1]))),
                ],
            ),
            Some(Grab::Rotation) => ctx::t_args(
                "umeyama-selected-rotation",
                &[
                    ("angle", FluentArg::Text(num(truth.angle_deg))),
                    ("scale", FluentArg::Text(num(truth.scale))),
                ],
            ),
            Some(Grab::Point(i)) => match selected_point(scene, Some(i)) {
                Some((i, at)) => ctx::t_args(
                    "umeyama-selected",
                    &[
                        ("n", FluentArg::Number((i + 1) as f64)),
                        ("count", count),
                        ("x", FluentArg::Text(num(at[0]))),
                        ("y", FluentArg::Text(num(at[1]))),
                    ],
                ),
                None => ctx::t_args("umeyama-selected-none", &[("count", count)]),
            },
            None => ctx::t_args("umeyama-selected-none", &[("count", count)]),
        };
        self.element.set_text_content(Some(&text));
        true
    }
}
