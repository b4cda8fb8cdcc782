//! Lessons a teacher presents: an ordered list of steps, each a page state (the permalink every
//! page keeps, `#/<page>?...`) with a title, a short note, and how many times the page's own
//! stepper steps (PageDown) before the lesson moves on ("step the RRT 5 times").
//!
//! A step may name a section of its page as its focus ([`crate::view::sections`]): presenting
//! the step brings that section into view (without one, the page's main view). A step may also
//! be one of its page's exercises ([`crate::view::exercises::PAGE_IDS`]): presented, the step
//! brings the page's exercises into view with that exercise's answer hidden until "next"
//! reveals it (a goal shows live whether it is met). And a step may hold the teacher's own goal
//! ([`crate::view::lesson_goal`]): conditions on the page's readouts, checked live.
//!
//! A lesson travels three ways, all checked here: as the `#/lesson?...` URL (indexed keys:
//! `title`, then `r1`, `t1`, `n1`, `k1`, `f1`, `x1`, `g1` for step 1's route, title, note, page
//! steps, focus, exercise and goal...), as a `.json` file (format `bsv-lesson` version 3,
//! versions 2 and 1 read too; read and
//! written by [`crate::view::lesson_file`]), and in the browser's storage (the same JSON). A bad
//! file or URL gets a message naming what is wrong ([`LessonError`]); nothing half-read replaces
//! the current lesson. A focus its page does not have is no error: [`Lesson::take_unknown_focuses`]
//! removes it and names it for the page's notice.
//!
//! [`Presenter`] walks a lesson: `next` first reveals the step's exercise, then steps the page
//! as often as the step says, then goes to the next step; `back` goes to the previous step.

use serde::Serialize;

use crate::error::RecipeError;
use crate::pyfmt::{group_u64, size_text};
use crate::view::exercises::ids_of_page;
use crate::view::json_file;
use crate::view::lesson_goal::{GoalCondition, MAX_GOALS};
use crate::view::sections;
use crate::view::url::{self, IgnoredKey};

/// The `format` field of a lesson file.
pub const FORMAT: &str = "bsv-lesson";
/// The lesson file version this build writes (it reads this one and [`FIRST_VERSION`]).
pub const VERSION: u32 = 3;
/// The first lesson file version, without `focus`: read as before.
pub const FIRST_VERSION: u32 = 1;
/// A lesson file larger than this is refused unread (60 steps with notes of 1,000 Japanese
/// characters are about 200 KiB).
pub const MAX_FILE_BYTES: u64 = 512 * 1024;
/// Deepest nesting of arrays and objects read (a lesson has 3: file, steps, step).
pub const MAX_DEPTH: usize = 16;
/// Longest text from a file quoted in a message (a field name, a format, a page).
pub const MAX_QUOTED_CHARS: usize = 40;
/// Limits that keep a lesson (and its URL) reasonable.
pub const MAX_STEPS: usize = 60;
pub const MAX_TITLE_CHARS: usize = 120;
pub const MAX_NOTE_CHARS: usize = 1000;
pub const MAX_PAGE_STEPS: u32 = 1000;

/// One step: a page state, its title and note, and page steps before moving on.
#[derive(Debug, Clone, PartialEq, Serialize)]
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
    /// The section of the page the step is about (`data-section` id); `None`: the page's main
    /// view.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub focus: Option<String>,
    /// The id of one of the page's exercises the step is about (`data-exercise`); `None`:
    /// none.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub exercise: Option<String>,
    /// The teacher's own goal: conditions on the page's readouts, checked live while the step
    /// is presented.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub goals: Vec<GoalCondition>,
}

/// A lesson: a title and its steps.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Lesson {
    pub title: String,
    pub steps: Vec<LessonStep>,
}

/// What a field should hold (the `expected` argument of a message).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Expected {
    Text,
    WholeNumber,
    List,
}

impl Expected {
    fn word(self) -> &'static str {
        match self {
            Expected::Text => "text",
            Expected::WholeNumber => "number",
            Expected::List => "list",
        }
    }
}

/// What is wrong with a lesson file or URL, for a localized message (`lesson-error-<id>` with
/// the details as arguments). `step` counts from 1; `None` is the lesson itself.
#[derive(Debug, Clone, PartialEq)]
pub enum LessonError {
    /// The browser could not read the file (its reason).
    NotText { detail: String },
    /// Not UTF-8 text ([`crate::recipes::decode_input`]'s error; a page says it localized).
    Decode(RecipeError),
    /// Bigger than [`MAX_FILE_BYTES`].
    TooBig { bytes: u64 },
    /// Nothing in it (or only spaces).
    EmptyFile,
    /// Arrays or objects nested deeper than [`MAX_DEPTH`]; where the limit is passed.
    TooDeep { line: usize, column: usize },
    /// Not JSON: where the parser stopped.
    NotJson { line: usize, column: usize },
    /// JSON, but not an object (`kind`: array, text, number, true/false, null).
    NotAnObject { kind: &'static str },
    /// Step `step` is not an object.
    StepNotAnObject { step: usize },
    /// An object without `format` (another program's JSON).
    NoFormat,
    /// `format` is not `bsv-lesson`.
    WrongFormat { found: String },
    /// A newer (or unknown) version.
    WrongVersion { found: u64 },
    /// A field this version does not know.
    UnknownField { step: Option<usize>, field: String },
    /// A required field is absent.
    MissingField {
        step: Option<usize>,
        field: &'static str,
    },
    /// A field holds the wrong kind of value.
    WrongType {
        step: Option<usize>,
        field: &'static str,
        expected: Expected,
    },
    /// No steps: nothing to present.
    NoSteps,
    /// More than [`MAX_STEPS`] steps.
    TooManySteps { count: usize },
    /// Step `step`: its route names no page of the app.
    UnknownPage { step: usize, page: String },
    /// Step `step`: a text longer than its limit (`field`: `title` or `note`).
    TooLong { step: usize, field: &'static str },
    /// Step `step`: more page steps than [`MAX_PAGE_STEPS`].
    TooManyPageSteps { step: usize },
    /// Step `step`: its goal `goal` (from 1) is not a readout, an op and a value (with a
    /// tolerance for within), or there are more than [`MAX_GOALS`] (`goal` is then the first
    /// too many).
    BadGoal { step: usize, goal: usize },
    /// Step `step`: its exercise is none of its page's.
    UnknownExercise {
        step: usize,
        page: String,
        exercise: String,
    },
    /// The lesson's own title is longer than [`MAX_TITLE_CHARS`].
    TitleTooLong,
}

impl LessonError {
    /// The Fluent id of the message.
    pub fn message_id(&self) -> &'static str {
        use LessonError::*;
        let at_step = |step: &Option<usize>| step.is_some();
        match self {
            NotText { .. } | Decode(_) => "lesson-error-not-text",
            TooBig { .. } => "lesson-error-too-big",
            EmptyFile => "lesson-error-empty-file",
            TooDeep { .. } => "lesson-error-too-deep",
            NotJson { .. } => "lesson-error-not-json",
            NoFormat => "lesson-error-no-format",
            NotAnObject { .. } => "lesson-error-not-an-object",
            StepNotAnObject { .. } => "lesson-error-step-not-an-object",
            NoSteps => "lesson-error-no-steps",
            WrongFormat { .. } => "lesson-error-format",
            WrongVersion { .. } => "lesson-error-version",
            TitleTooLong => "lesson-error-title-too-long",
            UnknownField { step, .. } if at_step(step) => "lesson-error-step-unknown-field",
            UnknownField { .. } => "lesson-error-unknown-field",
            MissingField { step, .. } if at_step(step) => "lesson-error-step-missing-field",
            MissingField { .. } => "lesson-error-missing-field",
            WrongType { step, .. } if at_step(step) => "lesson-error-step-wrong-type",
            WrongType { .. } => "lesson-error-wrong-type",
            TooManySteps { .. } => "lesson-error-too-many-steps",
            UnknownPage { .. } => "lesson-error-unknown-page",
            TooLong { .. } => "lesson-error-too-long",
            TooManyPageSteps { .. } => "lesson-error-page-steps",
            UnknownExercise { .. } => "lesson-error-unknown-exercise",
            BadGoal { .. } => "lesson-error-goal",
        }
    }

    /// The message's arguments (name, value).
    pub fn args(&self) -> Vec<(&'static str, String)> {
        use LessonError::*;
        let step_arg = |step: &Option<usize>| step.map(|n| ("step", n.to_string()));
        match self {
            NotText { detail } => vec![("detail", detail.clone())],
            Decode(error) => vec![("detail", error.to_string())],
            TooBig { bytes } => vec![
                ("size", size_text(*bytes)),
                ("bytes", group_u64(*bytes)),
                ("limit", size_text(MAX_FILE_BYTES)),
            ],
            EmptyFile | NoFormat | NoSteps => vec![],
            TooDeep { line, column } => vec![
                ("line", line.to_string()),
                ("column", column.to_string()),
                ("max", MAX_DEPTH.to_string()),
            ],
            NotJson { line, column } => {
                vec![("line", line.to_string()), ("column", column.to_string())]
            }
            NotAnObject { kind } => vec![("kind", (*kind).to_owned())],
            StepNotAnObject { step } => vec![("step", step.to_string())],
            WrongFormat { found } => vec![("found", quoted(found))],
            WrongVersion { found } => {
                vec![
                    ("found", found.to_string()),
                    ("version", VERSION.to_string()),
                ]
            }
            UnknownField { step, field } => {
                let mut args = vec![("field", quoted(field))];
                args.extend(step_arg(step));
                args
            }
            MissingField { step, field } => {
                let mut args = vec![("field", (*field).to_owned())];
                args.extend(step_arg(step));
                args
            }
            WrongType {
                step,
                field,
                expected,
            } => {
                let mut args = vec![
                    ("field", (*field).to_owned()),
                    ("expected", expected.word().to_owned()),
                ];
                args.extend(step_arg(step));
                args
            }
            TooManySteps { count } => {
                vec![("count", count.to_string()), ("max", MAX_STEPS.to_string())]
            }
            UnknownPage { step, page } => {
                vec![("step", step.to_string()), ("page", quoted(page))]
            }
            TooLong { step, field } => vec![
                ("step", step.to_string()),
                ("field", (*field).to_owned()),
                (
                    "max",
                    if *field == "note" {
                        MAX_NOTE_CHARS
                    } else {
                        MAX_TITLE_CHARS
                    }
                    .to_string(),
                ),
            ],
            TooManyPageSteps { step } => vec![
                ("step", step.to_string()),
                ("max", MAX_PAGE_STEPS.to_string()),
            ],
            TitleTooLong => vec![("max", MAX_TITLE_CHARS.to_string())],
            BadGoal { step, goal } => vec![
                ("step", step.to_string()),
                ("goal", goal.to_string()),
                ("max", MAX_GOALS.to_string()),
            ],
            UnknownExercise {
                step,
                page,
                exercise,
            } => vec![
                ("step", step.to_string()),
                ("page", quoted(page)),
                ("exercise", quoted(exercise)),
            ],
        }
    }
}

/// Text from a file for a message ([`json_file::quoted`] to [`MAX_QUOTED_CHARS`]).
fn quoted(text: &str) -> String {
    json_file::quoted(text, MAX_QUOTED_CHARS)
}

impl LessonStep {
    /// A step for the page state `route` (its `lang` removed).
    pub fn of_route(route: &str, title: &str) -> LessonStep {
        LessonStep {
            route: without_lang(route),
            title: title.to_owned(),
            note: String::new(),
            page_steps: 0,
            focus: None,
            exercise: None,
            goals: Vec::new(),
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
            if step.goals.len() > MAX_GOALS {
                return Err(LessonError::BadGoal {
                    step: n,
                    goal: MAX_GOALS + 1,
                });
            }
            if let Some(j) = step.goals.iter().position(|g| !g.is_valid()) {
                return Err(LessonError::BadGoal {
                    step: n,
                    goal: j + 1,
                });
            }
            if let Some(exercise) = &step.exercise {
                if !ids_of_page(&page).contains(&exercise.as_str()) {
                    return Err(LessonError::UnknownExercise {
                        step: n,
                        page,
                        exercise: exercise.clone(),
                    });
                }
            }
        }
        Ok(())
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
            if let Some(focus) = &step.focus {
                q.push((format!("f{n}"), focus.clone()));
            }
            if let Some(exercise) = &step.exercise {
                q.push((format!("x{n}"), exercise.clone()));
            }
            if !step.goals.is_empty() {
                q.push((format!("g{n}"), GoalCondition::list_to_link(&step.goals)));
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
            let goals = match get(&format!("g{n}")) {
                None => Vec::new(),
                Some(g) => GoalCondition::list_from_link(g)
                    .ok_or(LessonError::BadGoal { step: n, goal: 1 })?,
            };
            lesson.steps.push(LessonStep {
                route: without_lang(route),
                title: get(&format!("t{n}")).unwrap_or("").to_owned(),
                note: get(&format!("n{n}")).unwrap_or("").to_owned(),
                page_steps,
                focus: get(&format!("f{n}")).map(str::to_owned),
                exercise: get(&format!("x{n}")).map(str::to_owned),
                goals,
            });
        }
        lesson.validate(is_page)?;
        Ok(Some(lesson))
    }

    /// The keys of a `#/lesson` query that hold no part of the lesson (not `title`, nor `r`,
    /// `t`, `n`, `k`, `f`, `x` or `g` of a step whose route `r<n>` is there), for the page's
    /// notice.
    pub fn ignored_keys(query: &[(String, String)]) -> Vec<IgnoredKey> {
        let has_route = |n: &str| query.iter().any(|(k, _)| *k == format!("r{n}"));
        let mut ignored: Vec<IgnoredKey> = Vec::new();
        for (key, _) in query {
            let step_key = key
                .strip_prefix(['r', 't', 'n', 'k', 'f', 'x', 'g'])
                .filter(|n| n.parse::<usize>().is_ok_and(|n| n >= 1) && !n.starts_with('0'))
                .is_some_and(has_route);
            if key != "title" && !step_key && !ignored.iter().any(|k| &k.key == key) {
                ignored.push(IgnoredKey::unknown(key.clone()));
            }
        }
        ignored
    }

    /// Removes every focus that names no section of its step's page, and names them (for the
    /// page's notice, as ignored keys of a link are).
    pub fn take_unknown_focuses(&mut self) -> Vec<UnknownFocus> {
        let mut unknown = Vec::new();
        for (i, step) in self.steps.iter_mut().enumerate() {
            let page = step.page();
            if let Some(focus) = step.focus.take_if(|f| !sections::has(&page, f)) {
                unknown.push(UnknownFocus {
                    step: i + 1,
                    page,
                    focus: quoted(&focus),
                });
            }
        }
        unknown
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

/// A step's focus that its page does not have (removed from the lesson; see
/// [`Lesson::take_unknown_focuses`]). `step` counts from 1; `focus` is quoted for a message.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct UnknownFocus {
    pub step: usize,
    pub page: String,
    pub focus: String,
}

impl UnknownFocus {
    /// The Fluent id of the notice's line.
    pub const MESSAGE_ID: &'static str = "lesson-focus-unknown";

    /// The line's arguments (name, value).
    pub fn args(&self) -> Vec<(&'static str, String)> {
        vec![
            ("step", self.step.to_string()),
            ("page", self.page.clone()),
            ("focus", self.focus.clone()),
        ]
    }
}

/// What a press of "next" or "back" does while presenting.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PresenterAction {
    /// Reveal the answer of the step's exercise (its card's "Show the answer"; a goal, or an
    /// exercise already answered, has nothing to reveal: then "next" again).
    RevealExercise,
    /// Step the page's own stepper once (PageDown to the page).
    StepPage,
    /// Show lesson step `index` (from 0).
    Show(usize),
    /// Already at the end (or the start): nothing to do.
    Stay,
}

/// Where a presentation stands: the step shown, whether its exercise was revealed and how many
/// page steps it has done.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Presenter {
    pub index: usize,
    pub revealed: bool,
    pub page_steps_done: u32,
}

impl Presenter {
    /// "Next": reveal the step's exercise, step the page while the step asks for it, then the
    /// following lesson step.
    pub fn next(&mut self, lesson: &Lesson) -> PresenterAction {
        let Some(step) = lesson.steps.get(self.index) else {
            return PresenterAction::Stay;
        };
        if step.exercise.is_some() && !self.revealed {
            self.revealed = true;
            return PresenterAction::RevealExercise;
        }
        if self.page_steps_done < step.page_steps {
            self.page_steps_done += 1;
            return PresenterAction::StepPage;
        }
        if self.index + 1 < lesson.steps.len() {
            self.index += 1;
            self.page_steps_done = 0;
            self.revealed = false;
            PresenterAction::Show(self.index)
        } else {
            PresenterAction::Stay
        }
    }

    /// "Back": the previous lesson step (its page state from the start).
    pub fn back(&mut self) -> PresenterAction {
        if self.index == 0 {
            if self.page_steps_done > 0 || self.revealed {
                self.page_steps_done = 0;
                self.revealed = false;
                return PresenterAction::Show(0);
            }
            return PresenterAction::Stay;
        }
        self.index -= 1;
        self.page_steps_done = 0;
        self.revealed = false;
        PresenterAction::Show(self.index)
    }

    /// Jump to step `index` (clamped).
    pub fn go(&mut self, lesson: &Lesson, index: usize) -> PresenterAction {
        if lesson.steps.is_empty() {
            return PresenterAction::Stay;
        }
        self.index = index.min(lesson.steps.len() - 1);
        self.page_steps_done = 0;
        self.revealed = false;
        PresenterAction::Show(self.index)
    }
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    /// The pages the tests' lessons may name.
    pub(crate) fn is_page(p: &str) -> bool {
        matches!(p, "rrt-2d" | "ik-2r" | "pid-step" | "lesson")
    }

    /// A lesson of two steps, the first with every field set, the second a plain route.
    pub(crate) fn sample() -> Lesson {
        Lesson {
            title: "Planning & trajectories".into(),
            steps: vec![
                LessonStep {
                    route: "#/rrt-2d?seed=7&it=0".into(),
                    title: "Step the RRT".into(),
                    note: "Watch the goal bias: every tenth sample, say why.".into(),
                    page_steps: 5,
                    focus: Some("world".into()),
                    exercise: None,
                    goals: Vec::new(),
                },
                LessonStep::of_route("#/pid-step?Kp=2&lang=ja", "PID, hotter gains"),
            ],
        }
    }

    #[test]
    fn steps_drop_the_language_of_their_route() {
        assert_eq!(sample().steps[1].route, "#/pid-step?Kp=2");
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
    fn keys_that_hold_no_part_of_the_lesson_are_named() {
        let q = |pairs: &[(&str, &str)]| -> Vec<(String, String)> {
            pairs
                .iter()
                .map(|(k, v)| ((*k).to_owned(), (*v).to_owned()))
                .collect()
        };
        let query = q(&[
            ("title", "T"),
            ("r1", "#/ik-2r"),
            ("t1", "a"),
            ("k1", "2"),
            ("zz", "1"),
            ("t9", "x"),
            ("r01", "#/ik-2r"),
            ("zz", "2"),
            ("f1", "arm"),
            ("f2", "arm"),
        ]);
        assert_eq!(
            Lesson::ignored_keys(&query),
            vec![
                IgnoredKey::unknown("zz"),
                IgnoredKey::unknown("t9"),
                IgnoredKey::unknown("r01"),
                IgnoredKey::unknown("f2")
            ]
        );
        assert!(Lesson::ignored_keys(&sample().to_query()).is_empty());
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
    fn the_presenter_reveals_a_steps_exercise_before_stepping_the_page() {
        let mut lesson = sample();
        lesson.steps[0].exercise = Some("rrt-300".into());
        lesson.steps[0].page_steps = 1;
        let mut p = Presenter::default();
        assert_eq!(p.next(&lesson), PresenterAction::RevealExercise);
        assert_eq!(p.next(&lesson), PresenterAction::StepPage);
        assert_eq!(p.next(&lesson), PresenterAction::Show(1));
        assert!(!p.revealed);
        // Back to the step: its exercise is hidden again.
        assert_eq!(p.back(), PresenterAction::Show(0));
        assert_eq!(p.next(&lesson), PresenterAction::RevealExercise);
        assert_eq!(p.back(), PresenterAction::Show(0));
        assert_eq!(p.next(&lesson), PresenterAction::RevealExercise);
    }

    #[test]
    fn an_exercise_travels_in_the_url_and_must_be_its_pages() {
        let mut lesson = sample();
        lesson.steps[1].exercise = Some("pid-tune".into());
        let query = lesson.to_query();
        assert!(query.contains(&("x2".to_owned(), "pid-tune".to_owned())));
        assert!(Lesson::ignored_keys(&query).is_empty());
        assert_eq!(
            Lesson::from_query(&query, is_page),
            Ok(Some(lesson.clone()))
        );
        lesson.steps[1].exercise = Some("rrt-300".into());
        assert_eq!(
            Lesson::from_query(&lesson.to_query(), is_page),
            Err(LessonError::UnknownExercise {
                step: 2,
                page: "pid-step".into(),
                exercise: "rrt-300".into()
            })
        );
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
