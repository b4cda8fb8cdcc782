//! Lessons a teacher presents: an ordered list of steps, each a page state (the permalink every
//! page keeps, `#/<page>?...`) with a title, a short note, and how many times the page's own
//! stepper steps (PageDown) before the lesson moves on ("step the RRT 5 times").
//!
//! A lesson travels three ways, all checked here: as the `#/lesson?...` URL (indexed keys:
//! `title`, then `r1`, `t1`, `n1`, `k1` for step 1's route, title, note and page steps...), as a
//! `.json` file ([`Lesson::to_json`] / [`Lesson::from_json`], the format `bsv-lesson` version 1),
//! and in the browser's storage (the same JSON). A bad file or URL gets a message naming what is
//! wrong ([`LessonError`]); nothing half-read replaces the current lesson.
//!
//! [`Presenter`] walks a lesson: `next` first steps the page as often as the step says, then
//! goes to the next step; `back` goes to the previous step.

use serde::Serialize;

use crate::view::url;

mod file;

pub use file::{Expected, LessonError, FORMAT, MAX_DEPTH, MAX_FILE_BYTES, VERSION};

/// Limits that keep a lesson (and its URL) reasonable.
pub const MAX_STEPS: usize = 60;
pub const MAX_TITLE_CHARS: usize = 120;
pub const MAX_NOTE_CHARS: usize = 1000;
pub const MAX_PAGE_STEPS: u32 = 1000;

/// One step: a page state, its title and note, and page steps before moving on.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct LessonStep {
    /// The permalink of the page state, `#/<page>?...` (no `lang`: the presenter's language
    /// applies).
    pub route: String,
    pub title: String,
    pub note: String,
    /// How many times the page's stepper steps (PageDown) on this step before "next" moves to
    /// the following step.
    pub page_steps: u32,
}

/// A lesson: a title and its steps.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Lesson {
    pub title: String,
    pub steps: Vec<LessonStep>,
}

impl LessonStep {
    /// A step for the page state `route` (its `lang` removed).
    pub fn of_route(route: &str, title: &str) -> LessonStep {
        LessonStep {
            route: without_lang(route),
            title: title.to_owned(),
            note: String::new(),
            page_steps: 0,
        }
    }

    /// The page id of the step's route.
    pub fn page(&self) -> String {
        url::parse_hash(&self.route).page
    }
}

/// `route` without its `lang` key, so a lesson plays in the presenter's language.
pub fn without_lang(route: &str) -> String {
    let parsed = url::parse_hash(route);
    url::build_hash(&parsed.page, &parsed.page_query())
}

impl Lesson {
    /// Checks the limits and that every step names a page (`is_page`).
    pub fn validate(&self, is_page: impl Fn(&str) -> bool) -> Result<(), LessonError> {
        if self.title.chars().count() > MAX_TITLE_CHARS {
            return Err(LessonError::TitleTooLong);
        }
        if self.steps.len() > MAX_STEPS {
            return Err(LessonError::TooManySteps {
                count: self.steps.len(),
            });
        }
        for (i, step) in self.steps.iter().enumerate() {
            let n = i + 1;
            let page = step.page();
            if !is_page(&page) || page == "lesson" {
                return Err(LessonError::UnknownPage { step: n, page });
            }
            if step.title.chars().count() > MAX_TITLE_CHARS {
                return Err(LessonError::TooLong {
                    step: n,
                    field: "title",
                });
            }
            if step.note.chars().count() > MAX_NOTE_CHARS {
                return Err(LessonError::TooLong {
                    step: n,
                    field: "note",
                });
            }
            if step.page_steps > MAX_PAGE_STEPS {
                return Err(LessonError::TooManyPageSteps { step: n });
            }
        }
        Ok(())
    }

    /// The `.json` file text (pretty, stable key order).
    pub fn to_json(&self) -> String {
        file::to_json(self)
    }

    /// Reads a lesson file: its size, text, nesting, JSON, format, version, every field by
    /// name, and the limits (the checks of [`file`]).
    pub fn from_json(text: &str, is_page: impl Fn(&str) -> bool) -> Result<Lesson, LessonError> {
        file::from_json(text, is_page, false)
    }

    /// Reads the lesson kept in the browser's storage: [`Lesson::from_json`], except that a
    /// lesson without steps (the user removed them all) is fine.
    pub fn from_stored(text: &str, is_page: impl Fn(&str) -> bool) -> Result<Lesson, LessonError> {
        file::from_json(text, is_page, true)
    }

    /// The lesson as the query of `#/lesson` (indexed keys, see the module docs).
    pub fn to_query(&self) -> Vec<(String, String)> {
        let mut q = vec![("title".to_owned(), self.title.clone())];
        for (i, step) in self.steps.iter().enumerate() {
            let n = i + 1;
            q.push((format!("r{n}"), step.route.clone()));
            q.push((format!("t{n}"), step.title.clone()));
            if !step.note.is_empty() {
                q.push((format!("n{n}"), step.note.clone()));
            }
            if step.page_steps > 0 {
                q.push((format!("k{n}"), step.page_steps.to_string()));
            }
        }
        q
    }

    /// Reads a lesson from the query of `#/lesson`; `Ok(None)` when the query holds none.
    pub fn from_query(
        query: &[(String, String)],
        is_page: impl Fn(&str) -> bool,
    ) -> Result<Option<Lesson>, LessonError> {
        let get = |key: &str| {
            query
                .iter()
                .find(|(k, _)| k == key)
                .map(|(_, v)| v.as_str())
        };
        if get("r1").is_none() {
            return Ok(None);
        }
        let mut lesson = Lesson {
            title: get("title").unwrap_or("").to_owned(),
            steps: Vec::new(),
        };
        for n in 1.. {
            let Some(route) = get(&format!("r{n}")) else {
                break;
            };
            if n > MAX_STEPS {
                return Err(LessonError::TooManySteps { count: n });
            }
            let page_steps = match get(&format!("k{n}")) {
                None => 0,
                Some(k) => k
                    .parse::<u32>()
                    .map_err(|_| LessonError::TooManyPageSteps { step: n })?,
            };
            lesson.steps.push(LessonStep {
                route: without_lang(route),
                title: get(&format!("t{n}")).unwrap_or("").to_owned(),
                note: get(&format!("n{n}")).unwrap_or("").to_owned(),
                page_steps,
            });
        }
        lesson.validate(is_page)?;
        Ok(Some(lesson))
    }

    /// Moves step `from` to position `to` (both clamped).
    pub fn move_step(&mut self, from: usize, to: usize) {
        if from < self.steps.len() {
            let step = self.steps.remove(from);
            let to = to.min(self.steps.len());
            self.steps.insert(to, step);
        }
    }
}

/// What a press of "next" or "back" does while presenting.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PresenterAction {
    /// Step the page's own stepper once (PageDown to the page).
    StepPage,
    /// Show lesson step `index` (from 0).
    Show(usize),
    /// Already at the end (or the start): nothing to do.
    Stay,
}

/// Where a presentation stands: the step shown and how many page steps it has done.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Presenter {
    pub index: usize,
    pub page_steps_done: u32,
}

impl Presenter {
    /// "Next": step the page while the step asks for it, then the following lesson step.
    pub fn next(&mut self, lesson: &Lesson) -> PresenterAction {
        let Some(step) = lesson.steps.get(self.index) else {
            return PresenterAction::Stay;
        };
        if self.page_steps_done < step.page_steps {
            self.page_steps_done += 1;
            return PresenterAction::StepPage;
        }
        if self.index + 1 < lesson.steps.len() {
            self.index += 1;
            self.page_steps_done = 0;
            PresenterAction::Show(self.index)
        } else {
            PresenterAction::Stay
        }
    }

    /// "Back": the previous lesson step (its page state from the start).
    pub fn back(&mut self) -> PresenterAction {
        if self.index == 0 {
            if self.page_steps_done > 0 {
                self.page_steps_done = 0;
                return PresenterAction::Show(0);
            }
            return PresenterAction::Stay;
        }
        self.index -= 1;
        self.page_steps_done = 0;
        PresenterAction::Show(self.index)
    }

    /// Jump to step `index` (clamped).
    pub fn go(&mut self, lesson: &Lesson, index: usize) -> PresenterAction {
        if lesson.steps.is_empty() {
            return PresenterAction::Stay;
        }
        self.index = index.min(lesson.steps.len() - 1);
        self.page_steps_done = 0;
        PresenterAction::Show(self.index)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn is_page(p: &str) -> bool {
        matches!(p, "rrt-2d" | "ik-2r" | "pid-step" | "lesson")
    }

    fn sample() -> Lesson {
        Lesson {
            title: "Planning & trajectories".into(),
            steps: vec![
                LessonStep {
                    route: "#/rrt-2d?seed=7&it=0".into(),
                    title: "Step the RRT".into(),
                    note: "Watch the goal bias: every tenth sample, say why.".into(),
                    page_steps: 5,
                },
                LessonStep::of_route("#/pid-step?Kp=2&lang=ja", "PID, hotter gains"),
            ],
        }
    }

    #[test]
    fn json_round_trips_and_states_its_format() {
        let lesson = sample();
        let text = lesson.to_json();
        assert!(text.contains("\"format\": \"bsv-lesson\"") && text.contains("\"pageSteps\": 5"));
        assert_eq!(Lesson::from_json(&text, is_page), Ok(lesson));
    }

    #[test]
    fn steps_drop_the_language_of_their_route() {
        assert_eq!(sample().steps[1].route, "#/pid-step?Kp=2");
    }

    #[test]
    fn bad_files_name_what_is_wrong() {
        let bad = |text: &str| Lesson::from_json(text, is_page).unwrap_err();
        assert_eq!(
            bad(
                r##"{"format":"bsv-lesson","version":1,"title":"","steps":[{"route":"#/nope","title":"a"}]}"##
            ),
            LessonError::UnknownPage {
                step: 1,
                page: "nope".into()
            }
        );
        // A lesson cannot contain the lesson page itself.
        assert!(matches!(
            bad(
                r##"{"format":"bsv-lesson","version":1,"title":"","steps":[{"route":"#/lesson","title":"a"}]}"##
            ),
            LessonError::UnknownPage { .. }
        ));
        let long = "x".repeat(MAX_NOTE_CHARS + 1);
        let text = format!(
            r##"{{"format":"bsv-lesson","version":1,"title":"","steps":[{{"route":"#/ik-2r","title":"a","note":"{long}"}}]}}"##
        );
        assert_eq!(
            bad(&text),
            LessonError::TooLong {
                step: 1,
                field: "note"
            }
        );
        for e in [
            LessonError::TitleTooLong,
            LessonError::TooManyPageSteps { step: 2 },
        ] {
            assert!(e.message_id().starts_with("lesson-error-") && !e.args().is_empty());
        }
    }

    #[test]
    fn the_url_round_trips_through_the_codec() {
        let lesson = sample();
        let hash = url::build_hash("lesson", &lesson.to_query());
        let route = url::parse_hash(&hash);
        assert_eq!(route.page, "lesson");
        assert_eq!(Lesson::from_query(&route.query, is_page), Ok(Some(lesson)));
        assert_eq!(Lesson::from_query(&[], is_page), Ok(None));
        let bad = vec![
            ("r1".to_owned(), "#/ik-2r".to_owned()),
            ("k1".to_owned(), "many".to_owned()),
        ];
        assert_eq!(
            Lesson::from_query(&bad, is_page),
            Err(LessonError::TooManyPageSteps { step: 1 })
        );
    }

    #[test]
    fn the_presenter_steps_the_page_first_then_moves_on() {
        let lesson = sample();
        let mut p = Presenter::default();
        for _ in 0..5 {
            assert_eq!(p.next(&lesson), PresenterAction::StepPage);
        }
        assert_eq!(p.next(&lesson), PresenterAction::Show(1));
        assert_eq!(p.next(&lesson), PresenterAction::Stay);
        assert_eq!(p.back(), PresenterAction::Show(0));
        assert_eq!(p.page_steps_done, 0);
        assert_eq!(p.next(&lesson), PresenterAction::StepPage);
        assert_eq!(p.back(), PresenterAction::Show(0));
        assert_eq!(p.back(), PresenterAction::Stay);
        assert_eq!(p.go(&lesson, 9), PresenterAction::Show(1));
        assert_eq!(p.go(&Lesson::default(), 0), PresenterAction::Stay);
    }

    #[test]
    fn steps_move() {
        let mut lesson = sample();
        lesson.move_step(0, 1);
        assert_eq!(lesson.steps[1].title, "Step the RRT");
        lesson.move_step(5, 0);
        assert_eq!(lesson.steps.len(), 2);
    }
}
