//! The sections of every page: the parts a lesson step can bring into view (its `focus`),
//! marked `data-section="<id>"` in the page's markup (on a view's stage, the canvas and what
//! is drawn with it; on a card otherwise) and named by Fluent (`section-<id>` in `pages.ftl`,
//! loaded on every page, so that any page can name any section; `crate::ui::dom` writes the
//! name as `data-section-name`). The table is known without the page being open: the lesson
//! editor offers a step's sections from it, and a lesson's focus is checked against it. A
//! page's first section is its main live view: what a step without a focus brings into view.
//! Every page with exercises ends with its `exercises` section
//! ([`crate::view::exercises::PAGE_IDS`]).

/// Route id → its sections, the main live view first, then in the page's order.
#[rustfmt::skip]
pub const PAGE_SECTIONS: &[(&str, &[&str])] = &[
    ("home", &["arm", "drills", "recipes", "tools"]),
    ("ik-2r", &["arm", "readouts", "heatmap", "sweep", "form", "exports", "explain", "exercises"]),
    ("dh-fk", &["arm", "readouts", "joints", "table", "row", "poses", "exports", "explain", "exercises"]),
    ("se3-relative", &["frames", "readouts", "poses", "matrices", "rotations", "exports", "explain", "exercises"]),
    ("umeyama-2d", &["points", "stepper", "readouts", "form", "exports", "explain", "exercises"]),
    ("pendulum-energy", &["pendulum", "stepper", "readouts", "plot", "form", "exports", "explain", "exercises"]),
    ("pid-step", SIGNAL),
    ("cubic-path", SIGNAL),
    ("trapezoid-profile", SIGNAL),
    ("traj-resample", &["plot", "readouts", "form", "exports", "explain", "exercises"]),
    ("rrt-2d", &["world", "stepper", "substeps", "readouts", "form", "exports", "explain", "exercises"]),
    ("teleop", &["world", "readouts", "device", "session", "form", "explain", "exercises"]),
    ("so101", &["arm", "wrist", "device", "readouts", "session", "form", "keys", "exercises"]),
    ("drills", &["form", "result", "explain"]),
    ("lesson", &["lessons", "steps"]),
];

/// The sections of a signal page (`crate::ui::kit::signal_page`).
const SIGNAL: &[&str] = &[
    "plot",
    "form",
    "readouts",
    "exports",
    "explain",
    "exercises",
];

/// The sections of page `page` (none for a page without sections or an unknown page).
pub fn of(page: &str) -> &'static [&'static str] {
    PAGE_SECTIONS
        .iter()
        .find(|(id, _)| *id == page)
        .map_or(&[], |(_, sections)| sections)
}

/// Whether page `page` has section `section`.
pub fn has(page: &str, section: &str) -> bool {
    of(page).contains(&section)
}

/// The main live view of page `page`: what a step without a focus brings into view.
pub fn main_view(page: &str) -> Option<&'static str> {
    of(page).first().copied()
}

/// The Fluent id of section `section`'s name.
pub fn name_id(section: &str) -> String {
    format!("section-{section}")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::i18n::{I18n, Lang};

    #[test]
    fn every_section_is_named_in_both_languages() {
        let i18n = I18n::new();
        for (page, sections) in PAGE_SECTIONS {
            assert!(!sections.is_empty(), "{page}");
            for (i, section) in sections.iter().enumerate() {
                assert!(!sections[..i].contains(section), "{page}: {section} twice");
                for lang in Lang::ALL {
                    assert!(
                        i18n.has_message(lang, &name_id(section)),
                        "{lang:?} {section}"
                    );
                }
            }
        }
    }

    #[test]
    fn every_page_with_exercises_ends_with_their_section() {
        for (page, _) in crate::view::exercises::PAGE_IDS {
            assert_eq!(of(page).last(), Some(&"exercises"), "{page}");
        }
        assert!(!has("drills", "exercises") && !has("lesson", "exercises"));
    }

    #[test]
    fn a_page_knows_its_sections_and_its_main_view() {
        assert_eq!(main_view("ik-2r"), Some("arm"));
        assert_eq!(main_view("pid-step"), Some("plot"));
        assert!(has("ik-2r", "heatmap") && !has("ik-2r", "world") && !has("nope", "arm"));
        assert_eq!(of("nope"), &[] as &[&str]);
    }
}
