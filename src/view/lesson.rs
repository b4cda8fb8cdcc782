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

use serde::{Deserialize, Serialize};

use crate::view::url;

/// The `format` field of a lesson file.
pub const FORMAT: &str = "bsv-lesson";
/// The lesson file version this build reads and writes.
pub const VERSION: u32 = 1;
/// Limits that keep a lesson (and its URL) reasonable.
pub const MAX_STEPS: usize = 60;
pub const MAX_TITLE_CHARS: usize = 120;
pub const MAX_NOTE_CHARS: usize = 1000;
pub const MAX_PAGE_STEPS: u32 = 1000;
/// A lesson file larger than this is refused before parsing.
pub const MAX_FILE_BYTES: usize = 512 * 1024;

/// One step: a page state, its title and note, and page steps before moving on.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase", deny_unknown_fields)]
pub struct LessonStep {
    /// The permalink of the page state, `#/<page>?...` (no `lang`: the presenter's language
    /// applies).
    pub route: String,
    pub title: String,
    #[serde(default)]
    pub note: String,
    /// How many times the page's stepper steps (PageDown) on this step before "next" moves to
    /// the following step.
    #[serde(default)]
    pub page_steps: u32,
}

/// A lesson: a title and its steps.
#[derive(Debug, Clone, PartialEq, Eq, Default, Serialize, Deserialize)]
pub struct Lesson {
    pub title: String,
    pub steps: Vec<LessonStep>,
}

/// The file form: the lesson with its format and version.
#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct LessonFile {
    format: String,
    version: u32,
    title: String,
    steps: Vec<LessonStep>,
}

/// What is wrong with a lesson file or URL, for a localized message (`lesson-error-<id>` with
/// the details as arguments).
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum LessonError {
    /// Not JSON at all, or not the shape of a lesson; `detail` is the parser's words.
    NotALesson { detail: String },
    /// `format` is not `bsv-lesson`.
    WrongFormat { found: String },
    /// A newer (or unknown) version.
    WrongVersion { found: u32 },
    /// Bigger than [`MAX_FILE_BYTES`].
    TooBig { bytes: usize },
    /// More than [`MAX_STEPS`] steps.
    TooManySteps { count: usize },
    /// Step `step` (from 1): its route names no page of the app.
    UnknownPage { step: usize, page: String },
    /// Step `step` (from 1): a text longer than its limit (`field`: `title` or `note`).
    TooLong { step: usize, field: &'static str },
    /// Step `step` (from 1): more page steps than [`MAX_PAGE_STEPS`].
    TooManyPageSteps { step: usize },
    /// The lesson's own title is longer than [`MAX_TITLE_CHARS`].
    TitleTooLong,
}

impl LessonError {
    /// The Fluent id of the message.
    pub fn message_id(&self) -> &'static str {
        match self {
            LessonError::NotALesson { .. } => "lesson-error-not-a-lesson",
            LessonError::WrongFormat { .. } => "lesson-error-format",
            LessonError::WrongVersion { .. } => "lesson-error-version",
            LessonError::TooBig { .. } => "lesson-error-too-big",
            LessonError::TooManySteps { .. } => "lesson-error-too-many-steps",
            LessonError::UnknownPage { .. } => "lesson-error-unknown-page",
            LessonError::TooLong { .. } => "lesson-error-too-long",
            LessonError::TooManyPageSteps { .. } => "lesson-error-page-steps",
            LessonError::TitleTooLong => "lesson-error-title-too-long",
        }
    }

    /// The message's arguments (name, value).
    pub fn args(&self) -> Vec<(&'static str, String)> {
        match self {
            LessonError::NotALesson { detail } => vec![("detail", detail.clone())],
            LessonError::WrongFormat { found } => vec![("found", found.clone())],
            LessonError::WrongVersion { found } => vec![("found", found.to_string())],
            LessonError::TooBig { bytes } => vec![("bytes", bytes.to_string())],
            LessonError::TooManySteps { count } => {
                vec![("count", count.to_string()), ("max", MAX_STEPS.to_string())]
            }
            LessonError::UnknownPage { step, page } => {
                vec![("step", step.to_string()), ("page", page.clone())]
            }
            LessonError::TooLong { step, field } => {
                vec![("step", step.to_string()), ("field", (*field).to_owned())]
            }
            LessonError::TooManyPageSteps { step } => vec![
                ("step", step.to_string()),
                ("max", MAX_PAGE_STEPS.to_string()),
            ],
            LessonError::TitleTooLong => vec![("max", MAX_TITLE_CHARS.to_string())],
        }
    }
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
        let file = LessonFile {
            format: FORMAT.to_owned(),
            version: VERSION,
            title: self.title.clone(),
            steps: self.steps.clone(),
        };
        // Serializing plain strings and numbers cannot fail.
        serde_json::to_string_pretty(&file).unwrap_or_default() + "\n"
    }

    /// Reads a lesson file, checking its format, version and limits.
    pub fn from_json(text: &str, is_page: impl Fn(&str) -> bool) -> Result<Lesson, LessonError> {
        if text.len() > MAX_FILE_BYTES {
            return Err(LessonError::TooBig { bytes: text.len() });
        }
        let value: serde_json::Value = serde_json::from_str(text.trim_start_matches('\u{feff}'))
            .map_err(|e| LessonError::NotALesson {
                detail: e.to_string(),
            })?;
        let format = value.get("format").and_then(|f| f.as_str()).unwrap_or("");
        if format != FORMAT {
            return Err(LessonError::WrongFormat {
                found: format.to_owned(),
            });
        }
        let version = value.get("version").and_then(|v| v.as_u64()).unwrap_or(0);
        if version != u64::from(VERSION) {
            return Err(LessonError::WrongVersion {
                found: u32::try_from(version).unwrap_or(u32::MAX),
            });
        }
        let file: LessonFile =
            serde_json::from_value(value).map_err(|e| LessonError::NotALesson {
                detail: e.to_string(),
            })?;
        let lesson = Lesson {
            title: file.title,
            steps: file
                .steps
                .into_iter()
                .map(|s| LessonStep {
                    route: without_lang(&s.route),
                    ..s
                })
                .collect(),
        };
        lesson.validate(is_page)?;
        Ok(lesson)
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
        assert!(matches!(bad("not json"), LessonError::NotALesson { .. }));
        assert_eq!(
            bad(r#"{"format":"other","version":1}"#),
            LessonError::WrongFormat {
                found: "other".into()
            }
        );
        assert_eq!(
            bad(r#"{"format":"bsv-lesson","version":2,"title":"","steps":[]}"#),
            LessonError::WrongVersion { found: 2 }
        );
        assert!(matches!(
            bad(r##"{"format":"bsv-lesson","version":1,"title":"","steps":[{"route":"#/x"}]}"##),
            LessonError::NotALesson { .. }
        ));
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
        assert!(matches!(
            bad(&" ".repeat(MAX_FILE_BYTES + 1)),
            LessonError::TooBig { .. }
        ));
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
