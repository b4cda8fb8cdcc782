//! The RRT stepper page (`#/rrt-2d`) without the browser: the page's state and its URL codec
//! (the CLI's own argument names as keys, plus `it`), the run's command-line arguments, the
//! world editor's hit tests and edits with the reasons an edit is refused, and the texts of an
//! iteration's sub-steps with the pseudocode line that decided it.
//!
//! The kernel ([`crate::recipes::rrt_2d`]) says what the recipe is; this file only turns the
//! page's state into its arguments, so a download equals `bsv rrt-2d` with the same words.

use glam::DVec2;

use crate::args::ArgSpec;
use crate::error::RecipeError;
use crate::recipes::rrt_2d::{
    self, Obstacle, RrtIteration, RrtOutcome, RrtSetup, DEFAULT_GOAL, FLAG_GOAL_BIAS,
    FLAG_GOAL_TOL, FLAG_STEP, INFO, OBSTACLE, START,
};
use crate::view::command_line::RunArgs;
use crate::view::form::FieldDef;
use crate::view::url::{IgnoredKey, UrlState};

/// Most boxes the page's editor holds (the CLI takes more).
pub const MAX_BOXES: usize = 8;
/// Grid of the editor: dragged coordinates are rounded to this (so URLs and command lines
/// stay short, and the CLI reads the same numbers).
pub const GRID: f64 = 0.001;
/// Smallest side of a box resized by a corner.
pub const MIN_SIDE: f64 = 0.02;
/// Side of a new box.
pub const NEW_SIDE: f64 = 0.15;
/// The URL key of the iteration shown.
pub const IT_KEY: &str = "it";

/// The form's fields, in order: the two positional arguments, then three options.
pub const FORM_FIELDS: [&str; 5] = ["seed", "max_iter", "step", "goal-bias", "goal-tol"];

/// The arg spec of a form field.
fn spec_of(name: &str) -> Option<&'static ArgSpec> {
    INFO.args
        .iter()
        .chain(INFO.flags.iter())
        .find(|s| s.name == name)
}

/// The form's fields as the kit form builds them.
pub fn form_fields() -> Vec<FieldDef> {
    FORM_FIELDS
        .iter()
        .filter_map(|name| {
            let spec = spec_of(name)?;
            let flag = !INFO.args.iter().any(|a| a.name == *name);
            Some(FieldDef {
                spec,
                flag,
                label_id: spec.label_id(INFO.id, flag),
                group: usize::from(flag),
            })
        })
        .collect()
}

/// `v` on the editor's grid.
pub fn snap(v: f64) -> f64 {
    let s = (v / GRID).round() * GRID;
    // Print 0.35 rather than 0.35000000000000003: round through the decimal text.
    format!("{s:.3}").parse().unwrap_or(s)
}

/// A number as the command line writes it (`0.35`, `1`, `0.001`).
pub fn num(v: f64) -> String {
    format!("{v}")
}

/// `x,y`.
pub fn point_text(p: [f64; 2]) -> String {
    format!("{},{}", num(p[0]), num(p[1]))
}

/// `x0,y0,x1,y1`.
pub fn box_text(b: &Obstacle) -> String {
    let c = b.corners();
    format!("{},{},{},{}", num(c[0]), num(c[1]), num(c[2]), num(c[3]))
}

/// The page's whole state: the form's texts (valid ones), the world, the iteration shown.
#[derive(Debug, Clone, PartialEq)]
pub struct PageState {
    /// The texts of [`FORM_FIELDS`], in order.
    pub texts: Vec<String>,
    pub obstacles: Vec<Obstacle>,
    pub start: [f64; 2],
    pub goal: [f64; 2],
    /// The iteration shown (0 = only the start).
    pub it: u64,
}

impl Default for PageState {
    fn default() -> Self {
        PageState {
            texts: FORM_FIELDS
                .iter()
                .map(|n| spec_of(n).map_or("", |s| s.default).to_string())
                .collect(),
            obstacles: vec![OBSTACLE],
            start: START,
            goal: DEFAULT_GOAL,
            it: 0,
        }
    }
}

impl PageState {
    /// The text of form field `name`.
    pub fn text(&self, name: &str) -> &str {
        FORM_FIELDS
            .iter()
            .position(|n| *n == name)
            .and_then(|i| self.texts.get(i))
            .map_or("", |s| s.trim())
    }

    /// Whether the world and the planner's constants are the recipe's (then the Python
    /// recipe makes the same files).
    pub fn is_recipe_world(&self) -> bool {
        self.flags().is_empty()
    }

    /// The options that differ from the recipe: `(name, value)`, in `bsv --help` order.
    pub fn flags(&self) -> Vec<(String, String)> {
        let mut flags = Vec::new();
        if self.obstacles != [OBSTACLE] {
            if self.obstacles.is_empty() {
                flags.push(("obstacle".to_string(), "none".to_string()));
            }
            for b in &self.obstacles {
                flags.push(("obstacle".to_string(), box_text(b)));
            }
        }
        if self.start != START {
            flags.push(("start".to_string(), point_text(self.start)));
        }
        if self.goal != DEFAULT_GOAL {
            flags.push(("goal".to_string(), point_text(self.goal)));
        }
        for spec in [FLAG_STEP, FLAG_GOAL_BIAS, FLAG_GOAL_TOL] {
            let text = self.text(spec.name);
            if !text.is_empty() && text != spec.default {
                flags.push((spec.name.to_string(), text.to_string()));
            }
        }
        flags
    }

    /// The run's arguments: the positional values, then every option that differs.
    pub fn run_args(&self) -> RunArgs {
        let fields = form_fields();
        let texts: Vec<Option<String>> = self.texts.iter().map(|t| Some(t.clone())).collect();
        let mut args = RunArgs::new(INFO.id, &fields, &texts);
        args.flags = self.flags();
        args
    }

    /// The words `bsv rrt-2d` takes for this run (after the recipe id).
    pub fn cli_args(&self) -> Vec<String> {
        self.run_args().raw()
    }

    /// The run's setup, parsed from [`Self::cli_args`] exactly as the CLI parses them.
    pub fn setup(&self) -> Result<RrtSetup, RecipeError> {
        let args = INFO.parse(&self.cli_args())?;
        rrt_2d::setup_from_args(&args)
    }

    /// This state with the form's texts replaced.
    pub fn with_texts(&self, texts: Vec<String>) -> PageState {
        PageState {
            texts,
            ..self.clone()
        }
    }
}

fn parse_point(text: &str) -> Option<[f64; 2]> {
    let v = rrt_2d::FLAG_START.list(text).ok()?;
    Some([v[0], v[1]])
}

fn parse_box(text: &str) -> Option<Obstacle> {
    let v = rrt_2d::FLAG_OBSTACLE.list(text).ok()?;
    let b = Obstacle {
        x_min: v[0],
        y_min: v[1],
        x_max: v[2],
        y_max: v[3],
    };
    (b.x_min <= b.x_max && b.y_min <= b.y_max).then_some(b)
}

impl UrlState for PageState {
    fn read(query: &[(String, String)]) -> (PageState, Vec<IgnoredKey>) {
        let mut state = PageState::default();
        let mut ignored = Vec::new();
        let mut boxes: Option<Vec<Obstacle>> = None;
        let mut box_keys_bad = false;
        for (key, value) in query {
            let key = key.as_str();
            if let Some(i) = FORM_FIELDS.iter().position(|n| *n == key) {
                let ok = spec_of(key).is_some_and(|s| s.check_text(value).is_ok());
                if ok {
                    state.texts[i] = value.trim().to_string();
                } else {
                    ignored.push(IgnoredKey::invalid(key));
                }
                continue;
            }
            match key {
                "obstacle" => {
                    let list = boxes.get_or_insert_with(Vec::new);
                    if value.trim().eq_ignore_ascii_case("none") {
                        continue;
                    }
                    match parse_box(value) {
                        Some(b) if list.len() < MAX_BOXES => list.push(b),
                        _ => box_keys_bad = true,
                    }
                }
                "start" | "goal" => match parse_point(value) {
                    Some(p) if key == "start" => state.start = p,
                    Some(p) => state.goal = p,
                    None => ignored.push(IgnoredKey::invalid(key)),
                },
                IT_KEY => match value.trim().parse::<u64>() {
                    Ok(it) if it <= rrt_2d::MAX_ITER_LIMIT as u64 => state.it = it,
                    _ => ignored.push(IgnoredKey::invalid(key)),
                },
                _ => ignored.push(IgnoredKey::unknown(key)),
            }
        }
        // One bad box and the link's boxes are not the world it meant: the recipe's box.
        match boxes {
            _ if box_keys_bad => ignored.push(IgnoredKey::invalid("obstacle")),
            Some(b) => state.obstacles = b,
            None => {}
        }
        // A world the CLI refuses (a start or goal inside a box): the recipe's world, said.
        if state.setup().is_err() {
            let default = PageState::default();
            for (key, bad) in [
                ("obstacle", state.obstacles != default.obstacles),
                ("start", state.start != default.start),
                ("goal", state.goal != default.goal),
            ] {
                if bad && !ignored.iter().any(|k| k.key == key) {
                    ignored.push(IgnoredKey::invalid(key));
                }
            }
            state.obstacles = default.obstacles;
            state.start = default.start;
            state.goal = default.goal;
            if state.setup().is_err() {
                state.texts = default.texts;
            }
        }
        (state, ignored)
    }

    fn write(&self) -> Vec<(String, String)> {
        let mut pairs = Vec::new();
        for (name, text) in FORM_FIELDS.iter().zip(&self.texts) {
            let is_flag = !INFO.args.iter().any(|a| a.name == *name);
            let default = spec_of(name).map_or("", |s| s.default);
            if !is_flag && text.trim() != default {
                pairs.push((name.to_string(), text.trim().to_string()));
            }
        }
        pairs.extend(self.flags());
        pairs.push((IT_KEY.to_string(), self.it.to_string()));
        pairs
    }
}

// ---------- The world view's geometry and hit tests ----------

/// Where the unit square sits on the canvas, CSS px (y up in the world, down on screen).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Frame {
    pub left: f64,
    pub top: f64,
    /// Side of the square, px.
    pub side: f64,
}

impl Frame {
    /// The largest square fitting `w × h` with `margin` px around it.
    pub fn fit(w: f64, h: f64, margin: f64) -> Frame {
        let side = (w.min(h) - 2.0 * margin).max(10.0);
        Frame {
            left: (w - side) / 2.0,
            top: (h - side) / 2.0,
            side,
        }
    }

    /// World point → px.
    pub fn px(&self, p: [f64; 2]) -> DVec2 {
        DVec2::new(
            self.left + p[0] * self.side,
            self.top + (1.0 - p[1]) * self.side,
        )
    }

    /// px → world point (not clamped).
    pub fn world(&self, at: DVec2) -> [f64; 2] {
        [
            (at.x - self.left) / self.side,
            1.0 - (at.y - self.top) / self.side,
        ]
    }

    /// A length in world units → px.
    pub fn len(&self, d: f64) -> f64 {
        d * self.side
    }
}

/// What a press grabs in the world editor.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Grab {
    Start,
    Goal,
    /// Box `i`, to move it.
    Box(usize),
    /// Corner `corner` of box `i` (0: x_min,y_min; 1: x_max,y_min; 2: x_max,y_max; 3:
    /// x_min,y_max), to resize it.
    Corner(usize, u8),
}

/// The corners of `b` in [`Grab::Corner`] order.
pub fn corners(b: &Obstacle) -> [[f64; 2]; 4] {
    [
        [b.x_min, b.y_min],
        [b.x_max, b.y_min],
        [b.x_max, b.y_max],
        [b.x_min, b.y_max],
    ]
}

/// What lies under `at` (px): the start or goal within `radius` px first, then a corner of a
/// box (the last drawn first), then a box's inside.
pub fn hit_test(frame: &Frame, state: &PageState, at: DVec2, radius: f64) -> Option<Grab> {
    let near = |p: [f64; 2]| frame.px(p).distance(at) <= radius;
    let (ds, dg) = (
        frame.px(state.start).distance(at),
        frame.px(state.goal).distance(at),
    );
    if near(state.start) || near(state.goal) {
        return Some(if ds <= dg { Grab::Start } else { Grab::Goal });
    }
    for (i, b) in state.obstacles.iter().enumerate().rev() {
        for (k, c) in corners(b).iter().enumerate() {
            if near(*c) {
                return Some(Grab::Corner(i, k as u8));
            }
        }
    }
    let p = frame.world(at);
    state
        .obstacles
        .iter()
        .rposition(|b| b.contains(p))
        .map(Grab::Box)
}

// ---------- Edits ----------

/// Which point an edit is about.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Point {
    Start,
    Goal,
}

impl Point {
    /// Fluent id of its name ("the start", "the goal").
    pub fn name_id(self) -> &'static str {
        match self {
            Point::Start => "rrt-point-start",
            Point::Goal => "rrt-point-goal",
        }
    }
}

/// Why an edit of the world was refused (the old world stays).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Refusal {
    /// The point would leave the unit square.
    OutOfSquare(Point),
    /// The point would lie in box `index` (1-based).
    InBox(Point, usize),
    /// Box `index` (1-based) would cover the point.
    Covers(usize, Point),
    /// Already [`MAX_BOXES`] boxes.
    TooManyBoxes,
    /// No room for a new box clear of the start and the goal.
    NoRoom,
}

impl Refusal {
    /// Fluent id of the message and its arguments (`point` is a Fluent id to resolve).
    pub fn message(&self) -> (&'static str, Option<Point>, usize) {
        match *self {
            Refusal::OutOfSquare(p) => ("rrt-refused-outside", Some(p), 0),
            Refusal::InBox(p, i) => ("rrt-refused-in-box", Some(p), i),
            Refusal::Covers(i, p) => ("rrt-refused-covers", Some(p), i),
            Refusal::TooManyBoxes => ("rrt-refused-too-many", None, MAX_BOXES),
            Refusal::NoRoom => ("rrt-refused-no-room", None, 0),
        }
    }
}

fn in_square(p: [f64; 2]) -> bool {
    (0.0..=1.0).contains(&p[0]) && (0.0..=1.0).contains(&p[1])
}

/// Checks a world: both points in the square and outside every box.
fn check_world(s: &PageState, moved: Option<Point>) -> Result<(), Refusal> {
    for (point, p) in [(Point::Start, s.start), (Point::Goal, s.goal)] {
        if !in_square(p) {
            return Err(Refusal::OutOfSquare(point));
        }
        if let Some(i) = s.obstacles.iter().position(|b| b.contains(p)) {
            return Err(if moved == Some(point) {
                Refusal::InBox(point, i + 1)
            } else {
                Refusal::Covers(i + 1, point)
            });
        }
    }
    Ok(())
}

/// A drag of `grab` that began at world point `from` (on the state `before`) and is now at
/// `to`: the new state, or why it is refused. Boxes stay inside the square; a corner keeps
/// [`MIN_SIDE`] from the opposite one; every coordinate is snapped to [`GRID`].
pub fn drag(
    before: &PageState,
    grab: Grab,
    from: [f64; 2],
    to: [f64; 2],
) -> Result<PageState, Refusal> {
    let mut s = before.clone();
    match grab {
        Grab::Start | Grab::Goal => {
            let p = [snap(to[0]), snap(to[1])];
            let which = if grab == Grab::Start {
                s.start = p;
                Point::Start
            } else {
                s.goal = p;
                Point::Goal
            };
            check_world(&s, Some(which))?;
        }
        Grab::Box(i) => {
            let Some(b) = before.obstacles.get(i) else {
                return Ok(s);
            };
            let (w, h) = (b.x_max - b.x_min, b.y_max - b.y_min);
            let x0 = snap((b.x_min + to[0] - from[0]).clamp(0.0, 1.0 - w));
            let y0 = snap((b.y_min + to[1] - from[1]).clamp(0.0, 1.0 - h));
            s.obstacles[i] = Obstacle {
                x_min: x0,
                y_min: y0,
                x_max: snap(x0 + w).min(1.0),
                y_max: snap(y0 + h).min(1.0),
            };
            check_world(&s, None)?;
        }
        Grab::Corner(i, k) => {
            let Some(b) = before.obstacles.get(i) else {
                return Ok(s);
            };
            let x = snap(to[0].clamp(0.0, 1.0));
            let y = snap(to[1].clamp(0.0, 1.0));
            let mut n = *b;
            match k {
                0 | 3 => n.x_min = x.min(snap(b.x_max - MIN_SIDE)),
                _ => n.x_max = x.max(snap(b.x_min + MIN_SIDE)),
            }
            match k {
                0 | 1 => n.y_min = y.min(snap(b.y_max - MIN_SIDE)),
                _ => n.y_max = y.max(snap(b.y_min + MIN_SIDE)),
            }
            n.x_min = n.x_min.max(0.0);
            n.y_min = n.y_min.max(0.0);
            n.x_max = n.x_max.min(1.0);
            n.y_max = n.y_max.min(1.0);
            s.obstacles[i] = n;
            check_world(&s, None)?;
        }
    }
    Ok(s)
}

/// The state with one more box ([`NEW_SIDE`] square) at the first place (the centre, then a
/// grid) clear of the other boxes, else of the start and the goal only, or why not.
pub fn add_box(before: &PageState) -> Result<PageState, Refusal> {
    if before.obstacles.len() >= MAX_BOXES {
        return Err(Refusal::TooManyBoxes);
    }
    let mut places = vec![[0.5, 0.5]];
    for gy in 0..5 {
        for gx in 0..5 {
            places.push([0.15 + 0.175 * f64::from(gx), 0.15 + 0.175 * f64::from(gy)]);
        }
    }
    let overlaps = |b: &Obstacle| {
        before.obstacles.iter().any(|o| {
            b.x_min <= o.x_max && o.x_min <= b.x_max && b.y_min <= o.y_max && o.y_min <= b.y_max
        })
    };
    // A place clear of every box first, then any place clear of the start and the goal.
    for free_only in [true, false] {
        for c in &places {
            let half = NEW_SIDE / 2.0;
            let b = Obstacle {
                x_min: snap(c[0] - half),
                y_min: snap(c[1] - half),
                x_max: snap(c[0] + half),
                y_max: snap(c[1] + half),
            };
            if free_only && overlaps(&b) {
                continue;
            }
            let mut s = before.clone();
            s.obstacles.push(b);
            if check_world(&s, None).is_ok() {
                return Ok(s);
            }
        }
    }
    Err(Refusal::NoRoom)
}

/// The state without box `index` (the last one when out of range).
pub fn delete_box(before: &PageState, index: usize) -> PageState {
    let mut s = before.clone();
    if index < s.obstacles.len() {
        s.obstacles.remove(index);
    } else {
        s.obstacles.pop();
    }
    s
}

// ---------- Sub-steps and pseudocode ----------

/// The sub-steps of one iteration, in order.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Phase {
    Sample,
    Nearest,
    Steer,
    Check,
    Outcome,
}

/// The phases iteration `r` went through (a zero-length one stops after the nearest node, an
/// out-of-square one after steering).
pub fn phases(r: &RrtIteration) -> Vec<Phase> {
    match r.outcome {
        RrtOutcome::ZeroLength => vec![Phase::Sample, Phase::Nearest, Phase::Outcome],
        RrtOutcome::OutOfSquare => {
            vec![Phase::Sample, Phase::Nearest, Phase::Steer, Phase::Outcome]
        }
        _ => vec![
            Phase::Sample,
            Phase::Nearest,
            Phase::Steer,
            Phase::Check,
            Phase::Outcome,
        ],
    }
}

/// Lines of the pseudocode panel (Fluent ids `rrt-code-1` … `rrt-code-8`).
pub const CODE_LINES: usize = 8;

/// The 1-based pseudocode line that decided the outcome.
pub fn deciding_line(outcome: RrtOutcome) -> usize {
    match outcome {
        RrtOutcome::ZeroLength => 3,
        RrtOutcome::OutOfSquare => 5,
        RrtOutcome::Collision => 6,
        RrtOutcome::Added { .. } => 7,
        RrtOutcome::GoalReached { .. } => 8,
    }
}

/// The 1-based pseudocode line of `phase` of iteration `r`.
pub fn phase_line(r: &RrtIteration, phase: Phase) -> usize {
    match phase {
        Phase::Sample => 1,
        Phase::Nearest => 2,
        Phase::Steer => 4,
        Phase::Check => 6,
        Phase::Outcome => deciding_line(r.outcome),
    }
}

/// One written-out sub-step: a Fluent id and its arguments (numbers already formatted).
#[derive(Debug, Clone, PartialEq)]
pub struct SubText {
    pub phase: Phase,
    pub id: &'static str,
    pub args: Vec<(&'static str, String)>,
}

fn f4(v: f64) -> String {
    crate::numtext::fixed(v, 4)
}

/// The text of `phase` of iteration `r`.
pub fn sub_text(r: &RrtIteration, phase: Phase) -> SubText {
    let xy = |p: [f64; 2]| vec![("x", f4(p[0])), ("y", f4(p[1]))];
    let (id, args) = match phase {
        Phase::Sample => (
            if r.goal_sample {
                "rrt-sub-sample-goal"
            } else {
                "rrt-sub-sample"
            },
            xy(r.sample),
        ),
        Phase::Nearest => {
            let mut a = xy(r.from);
            a.push(("id", r.nearest.to_string()));
            a.push(("d", f4(r.distance)));
            ("rrt-sub-nearest", a)
        }
        Phase::Steer => {
            let c = r.candidate.unwrap_or(r.sample);
            let mut a = xy(c);
            a.push(("len", f4(dist(r.from, c))));
            ("rrt-sub-steer", a)
        }
        Phase::Check => match r.hit {
            Some(h) => (
                "rrt-sub-check-hit",
                vec![
                    ("point", (h.point + 1).to_string()),
                    ("box", (h.obstacle + 1).to_string()),
                ],
            ),
            None => ("rrt-sub-check-clear", Vec::new()),
        },
        Phase::Outcome => match r.outcome {
            RrtOutcome::Added { id } => match (r.to_goal, r.goal_hit) {
                (Some(d), Some(Some(h))) => (
                    "rrt-sub-added-goal-blocked",
                    vec![
                        ("id", id.to_string()),
                        ("d", f4(d)),
                        ("point", (h.point + 1).to_string()),
                        ("box", (h.obstacle + 1).to_string()),
                    ],
                ),
                (Some(d), _) => ("rrt-sub-added", vec![("id", id.to_string()), ("d", f4(d))]),
                _ => (
                    "rrt-sub-added",
                    vec![("id", id.to_string()), ("d", "—".into())],
                ),
            },
            RrtOutcome::GoalReached { id, goal_id } => (
                "rrt-sub-goal-reached",
                vec![("id", id.to_string()), ("goal", goal_id.to_string())],
            ),
            RrtOutcome::OutOfSquare => ("rrt-sub-out-of-square", Vec::new()),
            RrtOutcome::Collision => ("rrt-sub-collision", Vec::new()),
            RrtOutcome::ZeroLength => ("rrt-sub-zero-length", Vec::new()),
        },
    };
    SubText { phase, id, args }
}

fn dist(a: [f64; 2], b: [f64; 2]) -> f64 {
    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2)).sqrt()
}

/// Nodes per second from two counts `ms` apart (`None` when too short to say).
pub fn rate_per_s(nodes_before: usize, nodes_now: usize, ms: f64) -> Option<f64> {
    (ms >= 200.0).then(|| nodes_now.saturating_sub(nodes_before) as f64 * 1000.0 / ms)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::recipes::rrt_2d::{output, run_setup, Rrt};
    use crate::recipes::Progress;
    use crate::view::url::query as q;

    #[test]
    fn default_is_the_recipe_and_its_command_lines() {
        let s = PageState::default();
        assert!(s.is_recipe_world());
        assert_eq!(s.cli_args(), vec!["7", "800"]);
        let args = s.run_args();
        assert_eq!(args.bsv_command(), "bsv rrt-2d 7 800");
        assert_eq!(
            args.python_command(INFO.python),
            "python rrt_2d_grid.py 7 800"
        );
        assert_eq!(s.write(), q(&[("it", "0")]));
        let setup = s.setup().unwrap();
        let rrt = run_setup(&setup, &mut Progress::silent()).unwrap();
        // The explanation panel says so.
        assert_eq!(rrt.iterations(), 120);
        // The figures for the default: 91 nodes, 33 path points, length 1.604.
        assert_eq!(
            output(&rrt).summary,
            "RRT nodes=91 path_pts=33 length=1.604 -> rrt_path.csv, rrt_nodes.csv"
        );
    }

    #[test]
    fn url_round_trip_with_two_boxes_moved_points_and_options() {
        let query = q(&[
            ("seed", "3"),
            ("obstacle", "0.2,0.3,0.4,0.5"),
            ("obstacle", "0.6,0.1,0.7,0.9"),
            ("start", "0.05,0.9"),
            ("goal", "0.95,0.1"),
            ("step", "0.04"),
            ("it", "12"),
        ]);
        let (s, ignored) = PageState::read(&query);
        assert!(ignored.is_empty(), "{ignored:?}");
        assert_eq!(s.obstacles.len(), 2);
        assert_eq!(s.it, 12);
        assert_eq!(PageState::read(&s.write()).0, s);
        assert_eq!(
            s.run_args().bsv_command(),
            "bsv rrt-2d 3 800 --obstacle 0.2,0.3,0.4,0.5 --obstacle 0.6,0.1,0.7,0.9 --start 0.05,0.9 --goal 0.95,0.1 --step 0.04"
        );
        assert!(!s.is_recipe_world());
        // The page's setup is the CLI's for the same words.
        let cli = crate::recipes::parse_args(INFO.id, &s.cli_args()).unwrap();
        assert_eq!(rrt_2d::setup_from_args(&cli).unwrap(), s.setup().unwrap());
        // No box at all.
        let (none, _) = PageState::read(&q(&[("obstacle", "none")]));
        assert!(none.obstacles.is_empty());
        assert_eq!(none.cli_args(), vec!["7", "800", "--obstacle", "none"]);
        assert_eq!(PageState::read(&none.write()).0, none);
    }

    #[test]
    fn bad_url_values_are_ignored_and_said() {
        let (s, ignored) = PageState::read(&q(&[
            ("seed", "x"),
            ("step", "5"),
            ("it", "-1"),
            ("bogus", "1"),
            ("obstacle", "0.5,0.5,0.4,0.6"),
        ]));
        assert_eq!(s.texts, PageState::default().texts);
        assert_eq!(s.obstacles, PageState::default().obstacles);
        let keys: Vec<&str> = ignored.iter().map(|k| k.key.as_str()).collect();
        assert_eq!(keys, vec!["seed", "step", "it", "bogus", "obstacle"]);
        // A goal inside the recipe's box: the recipe's world, and the key is named.
        let (s, ignored) = PageState::read(&q(&[("goal", "0.5,0.5")]));
        assert_eq!(s.goal, DEFAULT_GOAL);
        assert_eq!(ignored, vec![IgnoredKey::invalid("goal")]);
    }

    #[test]
    fn hit_tests_find_points_corners_and_boxes() {
        let f = Frame::fit(500.0, 400.0, 20.0);
        assert_eq!(f.side, 360.0);
        let s = PageState::default();
        let at = |p: [f64; 2]| f.px(p);
        assert_eq!(hit_test(&f, &s, at(START), 10.0), Some(Grab::Start));
        assert_eq!(hit_test(&f, &s, at([0.905, 0.9]), 10.0), Some(Grab::Goal));
        assert_eq!(
            hit_test(&f, &s, at([0.65, 0.75]), 10.0),
            Some(Grab::Corner(0, 2))
        );
        assert_eq!(
            hit_test(&f, &s, at([0.35, 0.25]), 10.0),
            Some(Grab::Corner(0, 0))
        );
        assert_eq!(hit_test(&f, &s, at([0.5, 0.5]), 10.0), Some(Grab::Box(0)));
        assert_eq!(hit_test(&f, &s, at([0.2, 0.8]), 10.0), None);
        let w = f.world(f.px([0.3, 0.7]));
        assert!((w[0] - 0.3).abs() < 1e-12 && (w[1] - 0.7).abs() < 1e-12);
    }

    #[test]
    fn drags_move_resize_and_refuse() {
        let s = PageState::default();
        // Move the box right by 0.1.
        let m = drag(&s, Grab::Box(0), [0.5, 0.5], [0.6, 0.5]).unwrap();
        assert_eq!(box_text(&m.obstacles[0]), "0.45,0.25,0.75,0.75");
        // Clamped at the square's edge.
        let m = drag(&s, Grab::Box(0), [0.5, 0.5], [2.0, 0.5]).unwrap();
        assert_eq!(box_text(&m.obstacles[0]), "0.7,0.25,1,0.75");
        // Covering the goal is refused.
        assert_eq!(
            drag(&s, Grab::Box(0), [0.5, 0.5], [0.8, 0.7]),
            Err(Refusal::Covers(1, Point::Goal))
        );
        // Resize by the top-right corner; it cannot cross the opposite one.
        let r = drag(&s, Grab::Corner(0, 2), [0.65, 0.75], [0.7, 0.8]).unwrap();
        assert_eq!(box_text(&r.obstacles[0]), "0.35,0.25,0.7,0.8");
        let r = drag(&s, Grab::Corner(0, 2), [0.65, 0.75], [0.0, 0.0]).unwrap();
        assert_eq!(box_text(&r.obstacles[0]), "0.35,0.25,0.37,0.27");
        // The goal into the box, or out of the square: refused.
        assert_eq!(
            drag(&s, Grab::Goal, DEFAULT_GOAL, [0.5, 0.5]),
            Err(Refusal::InBox(Point::Goal, 1))
        );
        assert_eq!(
            drag(&s, Grab::Start, START, [-0.1, 0.5]),
            Err(Refusal::OutOfSquare(Point::Start))
        );
        let g = drag(&s, Grab::Goal, DEFAULT_GOAL, [0.80049, 0.2]).unwrap();
        assert_eq!(g.goal, [0.8, 0.2]);
        assert_eq!(point_text(g.goal), "0.8,0.2");
    }

    #[test]
    fn boxes_are_added_clear_of_the_points_up_to_eight_and_deleted() {
        let mut s = PageState::default();
        while s.obstacles.len() < MAX_BOXES {
            s = add_box(&s).unwrap();
            assert!(s.setup().is_ok(), "{:?}", s.flags());
        }
        assert_eq!(add_box(&s), Err(Refusal::TooManyBoxes));
        let d = delete_box(&s, 0);
        assert_eq!(d.obstacles.len(), MAX_BOXES - 1);
        assert_eq!(d.obstacles[0], s.obstacles[1]);
        assert_eq!(delete_box(&d, 99).obstacles.len(), MAX_BOXES - 2);
    }

    #[test]
    fn sub_steps_name_the_deciding_line_for_every_outcome() {
        let setup = PageState::default().setup().unwrap();
        let mut rrt = Rrt::with_setup(&setup).unwrap();
        let mut seen = std::collections::BTreeSet::new();
        while let Some(r) = rrt.step_record() {
            let ph = phases(&r);
            assert_eq!(ph.first(), Some(&Phase::Sample));
            assert_eq!(ph.last(), Some(&Phase::Outcome));
            assert_eq!(phase_line(&r, Phase::Outcome), deciding_line(r.outcome));
            let t = sub_text(&r, Phase::Outcome);
            seen.insert(t.id);
            if r.goal_sample {
                assert_eq!(sub_text(&r, Phase::Sample).id, "rrt-sub-sample-goal");
            }
            if r.outcome == RrtOutcome::Collision {
                let h = r.hit.unwrap();
                assert_eq!(
                    sub_text(&r, Phase::Check).args,
                    vec![
                        ("point", (h.point + 1).to_string()),
                        ("box", "1".to_string())
                    ]
                );
                assert_eq!(deciding_line(r.outcome), 6);
            }
        }
        assert!(seen.contains("rrt-sub-added"));
        assert!(seen.contains("rrt-sub-collision"));
        assert!(seen.contains("rrt-sub-goal-reached"));
        let first = {
            let mut r = Rrt::with_setup(&setup).unwrap();
            r.step_record().unwrap()
        };
        let t = sub_text(&first, Phase::Nearest);
        assert_eq!(t.args[2], ("id", "0".to_string()));
        assert_eq!(rate_per_s(10, 110, 500.0), Some(200.0));
        assert_eq!(rate_per_s(10, 110, 50.0), None);
    }
}
