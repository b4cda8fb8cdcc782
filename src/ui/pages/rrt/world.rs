//! The world view: the unit square on three HiDPI layers. Layer 0 holds the world (grid,
//! boxes with their corner handles, start, goal and its tolerance circle), redrawn when the
//! world, the size or the mode changes; layer 1 the tree, to which only new edges are
//! appended while it grows (redrawn whole only after a step back or a new run); layer 2, the
//! top, the marks of the moment: the newest node, the found path, the current iteration's
//! sub-steps, the selected box.

use wasm_bindgen::JsValue;
use web_sys::{CanvasRenderingContext2d, Element};

use crate::recipes::rrt_2d::{check_points, RrtIteration, RrtOutcome};
use crate::ui::kit::canvas::{dash, disc, ring, solid, Ink, LayeredCanvas};
use crate::ui::schedule::now_ms;
use crate::view::drag::HandleShape;
use crate::view::palette;
use crate::view::rrt::{corners, Frame, Grab, PageState, Phase};

use super::run::Run;

/// Tree nodes drawn at a time, chunks drawn for up to [`TREE_MS_PER_TASK`] per task; a
/// bigger tree is drawn over the next tasks.
const TREE_NODES_PER_CHUNK: usize = 1_000;
/// Time spent drawing tree chunks per task, ms.
const TREE_MS_PER_TASK: f64 = 8.0;

const BG: &str = "#fbfcfe";
const GRID: &str = "#e6eaf0";
const BOX_FILL: &str = "#cfd6e0";
const BOX_EDGE: &str = "#4b5563";
// Start and goal: Okabe–Ito bluish green and vermilion (apart with every common
// colour-vision deficiency), also labelled S and G.
const START: &str = palette::BLUISH_GREEN.hex;
const GOAL: &str = palette::VERMILION.hex;
const TREE: &str = "rgba(26, 77, 143, 0.55)";
const NODE: &str = "rgba(26, 77, 143, 0.8)";
const PATH: &str = "#c2410c";
const MARK: &str = "#7c3aed";
// A refused candidate and its colliding check point: near-black, so that it never relies on
// red against the orange of an added one.
const HIT: &str = "#111827";

/// Margin around the square, CSS px.
const MARGIN: f64 = 14.0;

/// The view component.
pub struct WorldView {
    pub canvas: LayeredCanvas,
    pub frame: Frame,
    /// Nodes drawn on the tree layer, and the run generation they belong to.
    tree_drawn: usize,
    tree_generation: Option<u64>,
    /// Whether [`WorldView::fit`] has measured the stage: until then (the mount's task, before
    /// the first layout) nothing is drawn.
    sized: bool,
}

impl WorldView {
    /// Wraps the canvases of `stage`.
    pub fn find(stage: &Element) -> Result<WorldView, JsValue> {
        Ok(WorldView {
            canvas: LayeredCanvas::from_stage(stage)?,
            frame: Frame::fit(1.0, 1.0, 0.0),
            tree_drawn: 0,
            tree_generation: None,
            sized: false,
        })
    }

    /// Sizes the layers to the stage (a resize, projector mode); the tree is redrawn whole
    /// next time.
    pub fn fit(&mut self) {
        self.canvas.fit();
        let (w, h) = self.canvas.size();
        self.frame = Frame::fit(w, h, MARGIN);
        self.tree_generation = None;
        self.sized = true;
    }

    /// Whether the layers have their size (the view is drawn from then on).
    pub fn is_sized(&self) -> bool {
        self.sized
    }

    /// Hit radius of handles, px.
    pub fn hit_radius(coarse: bool) -> f64 {
        if coarse {
            22.0
        } else {
            10.0
        }
    }

    /// The touch overlay shapes: start, goal, every box's centre and corners (a finger
    /// anywhere else scrolls the page).
    pub fn handles(&self, state: &PageState) -> Vec<HandleShape> {
        let r = WorldView::hit_radius(true);
        let mut shapes = vec![
            HandleShape::Circle {
                centre: self.frame.px(state.start),
                radius: r,
            },
            HandleShape::Circle {
                centre: self.frame.px(state.goal),
                radius: r,
            },
        ];
        for b in &state.obstacles {
            shapes.push(HandleShape::Circle {
                centre: self
                    .frame
                    .px([0.5 * (b.x_min + b.x_max), 0.5 * (b.y_min + b.y_max)]),
                radius: r,
            });
            for c in corners(b) {
                shapes.push(HandleShape::Circle {
                    centre: self.frame.px(c),
                    radius: r * 0.8,
                });
            }
        }
        shapes
    }

    /// Layer 0: the world of `state` with the goal tolerance `goal_tol`.
    pub fn draw_world(&self, state: &PageState, goal_tol: f64, ink: Ink) {
        if !self.sized {
            return;
        }
        let layer = self.canvas.layer(0);
        layer.begin();
        let c = &layer.ctx;
        let f = &self.frame;
        c.set_fill_style_str(BG);
        c.fill_rect(f.left, f.top, f.side, f.side);
        c.set_stroke_style_str(GRID);
        c.set_line_width(ink.line);
        c.begin_path();
        for k in 1..10 {
            let t = f64::from(k) / 10.0;
            let a = f.px([t, 0.0]);
            let b = f.px([t, 1.0]);
            c.move_to(a.x, a.y);
            c.line_to(b.x, b.y);
            let a = f.px([0.0, t]);
            let b = f.px([1.0, t]);
            c.move_to(a.x, a.y);
            c.line_to(b.x, b.y);
        }
        c.stroke();
        c.set_stroke_style_str(BOX_EDGE);
        c.set_line_width(1.5 * ink.line);
        c.stroke_rect(f.left, f.top, f.side, f.side);
        c.set_font(&ink.font(12.0, true));
        for (i, b) in state.obstacles.iter().enumerate() {
            let p0 = f.px([b.x_min, b.y_max]);
            let p1 = f.px([b.x_max, b.y_min]);
            c.set_fill_style_str(BOX_FILL);
            c.fill_rect(p0.x, p0.y, p1.x - p0.x, p1.y - p0.y);
            c.set_stroke_style_str(BOX_EDGE);
            c.set_line_width(1.5 * ink.line);
            c.stroke_rect(p0.x, p0.y, p1.x - p0.x, p1.y - p0.y);
            c.set_fill_style_str(BOX_EDGE);
            let _ = c.fill_text(
                &(i + 1).to_string(),
                p0.x + 4.0 * ink.line,
                p0.y + ink.text_px(12.0) + 2.0,
            );
            for corner in corners(b) {
                let p = f.px(corner);
                let s = 3.5 * ink.line;
                c.fill_rect(p.x - s, p.y - s, 2.0 * s, 2.0 * s);
            }
        }
        // The goal's tolerance circle.
        let g = f.px(state.goal);
        let _ = c.set_line_dash(&dash(5.0 * ink.line, 4.0 * ink.line));
        ring(c, g, f.len(goal_tol), GOAL, ink.line);
        let _ = c.set_line_dash(&solid());
        disc(c, f.px(state.start), 7.0 * ink.line, START);
        disc(c, g, 7.0 * ink.line, GOAL);
        c.set_fill_style_str("#111827");
        let _ = c.fill_text(
            "S",
            f.px(state.start).x + 9.0 * ink.line,
            f.px(state.start).y - 8.0,
        );
        let _ = c.fill_text("G", g.x + 9.0 * ink.line, g.y - 8.0);
    }

    /// [`WorldView::draw_tree`] in chunks of [`TREE_NODES_PER_CHUNK`] for up to
    /// [`TREE_MS_PER_TASK`]; `true` once the tree is drawn to `upto` (else the rest waits for
    /// the next tasks).
    pub fn draw_tree_for_a_task(&mut self, run: &Run, upto: usize, ink: Ink) -> bool {
        let started = now_ms();
        let mut complete = self.draw_tree(run, upto, TREE_NODES_PER_CHUNK, ink);
        while !complete && now_ms() - started < TREE_MS_PER_TASK {
            complete = self.draw_tree(run, upto, TREE_NODES_PER_CHUNK, ink);
        }
        complete
    }

    /// Layer 1: the tree's first `upto` nodes, appending the ones not drawn yet (the whole
    /// tree after a step back, a new run, a resize, or fewer nodes asked for: sub-step mode
    /// hides the iteration's new node until its outcome), at most `most` nodes per call;
    /// `true` once the tree is drawn to `upto`.
    fn draw_tree(&mut self, run: &Run, upto: usize, most: usize, ink: Ink) -> bool {
        if !self.sized {
            return true;
        }
        let layer = self.canvas.layer(1);
        let shown = run.shown();
        let all = shown.nodes();
        let nodes = &all[..upto.min(all.len())];
        let parents = shown.parents();
        if self.tree_generation != Some(run.generation) || nodes.len() < self.tree_drawn {
            layer.begin();
            self.tree_drawn = 0;
            self.tree_generation = Some(run.generation);
        }
        if self.tree_drawn >= nodes.len() {
            return true;
        }
        let whole = nodes;
        let nodes = &whole[..whole.len().min(self.tree_drawn.saturating_add(most.max(1)))];
        let c = &layer.ctx;
        let f = &self.frame;
        c.set_stroke_style_str(TREE);
        c.set_line_width(ink.line);
        c.begin_path();
        for (node, parent) in nodes[self.tree_drawn..]
            .iter()
            .zip(&parents[self.tree_drawn..])
        {
            if let Some(p) = parent.and_then(|i| whole.get(i)) {
                let a = f.px(*p);
                let b = f.px(*node);
                c.move_to(a.x, a.y);
                c.line_to(b.x, b.y);
            }
        }
        c.stroke();
        c.set_fill_style_str(NODE);
        let s = 1.2 * ink.line;
        c.begin_path();
        for node in &nodes[self.tree_drawn..] {
            let p = f.px(*node);
            c.rect(p.x - s, p.y - s, 2.0 * s, 2.0 * s);
        }
        c.fill();
        self.tree_drawn = nodes.len();
        self.tree_drawn >= whole.len()
    }

    /// Layer 2: the path, the newest node, the iteration's sub-steps up to `phase`, the
    /// selected or hovered box.
    pub fn draw_marks(
        &self,
        run: &Run,
        phase: Option<Phase>,
        selected: Option<usize>,
        hover: Option<Grab>,
        state: &PageState,
        ink: Ink,
    ) {
        if !self.sized {
            return;
        }
        let layer = self.canvas.top();
        layer.begin();
        let c = &layer.ctx;
        let f = &self.frame;
        c.set_line_cap("round");
        c.set_line_join("round");
        let path = run.shown().path();
        if path.len() > 1 {
            c.set_stroke_style_str(PATH);
            c.set_line_width(4.0 * ink.line);
            c.begin_path();
            for (k, p) in path.iter().enumerate() {
                let q = f.px(*p);
                if k == 0 {
                    c.move_to(q.x, q.y);
                } else {
                    c.line_to(q.x, q.y);
                }
            }
            c.stroke();
        }
        for (i, b) in state.obstacles.iter().enumerate() {
            let hovered = matches!(hover, Some(Grab::Box(j) | Grab::Corner(j, _)) if j == i);
            if selected == Some(i) || hovered {
                let p0 = f.px([b.x_min, b.y_max]);
                let p1 = f.px([b.x_max, b.y_min]);
                c.set_stroke_style_str(MARK);
                c.set_line_width(2.5 * ink.line);
                c.stroke_rect(p0.x, p0.y, p1.x - p0.x, p1.y - p0.y);
            }
        }
        if let Some(Grab::Corner(i, k)) = hover {
            if let Some(b) = state.obstacles.get(i) {
                ring(
                    c,
                    f.px(corners(b)[usize::from(k)]),
                    7.0 * ink.line,
                    MARK,
                    2.0 * ink.line,
                );
            }
        }
        if let Some(g @ (Grab::Start | Grab::Goal)) = hover {
            let p = if g == Grab::Start {
                state.start
            } else {
                state.goal
            };
            ring(c, f.px(p), 11.0 * ink.line, MARK, 2.0 * ink.line);
        }
        let Some(r) = run.shown().last() else {
            return;
        };
        self.draw_iteration(c, r, phase.unwrap_or(Phase::Outcome), ink);
    }

    fn draw_iteration(
        &self,
        c: &CanvasRenderingContext2d,
        r: &RrtIteration,
        upto: Phase,
        ink: Ink,
    ) {
        let f = &self.frame;
        let reached = |p: Phase| (p as u8) <= (upto as u8);
        let sample = f.px(r.sample);
        let from = f.px(r.from);
        // Sample: a cross (a star when it is the goal-biased draw).
        let s = 6.0 * ink.line;
        c.set_stroke_style_str(MARK);
        c.set_line_width(2.0 * ink.line);
        c.begin_path();
        c.move_to(sample.x - s, sample.y - s);
        c.line_to(sample.x + s, sample.y + s);
        c.move_to(sample.x - s, sample.y + s);
        c.line_to(sample.x + s, sample.y - s);
        if r.goal_sample {
            c.move_to(sample.x - 1.4 * s, sample.y);
            c.line_to(sample.x + 1.4 * s, sample.y);
            c.move_to(sample.x, sample.y - 1.4 * s);
            c.line_to(sample.x, sample.y + 1.4 * s);
        }
        c.stroke();
        if !reached(Phase::Nearest) {
            return;
        }
        // Nearest: a ring and a dashed line to the sample.
        ring(c, from, 6.0 * ink.line, MARK, 2.0 * ink.line);
        let _ = c.set_line_dash(&dash(4.0 * ink.line, 4.0 * ink.line));
        c.set_line_width(ink.line);
        c.begin_path();
        c.move_to(from.x, from.y);
        c.line_to(sample.x, sample.y);
        c.stroke();
        let _ = c.set_line_dash(&solid());
        let Some(cand) = r.candidate else {
            return;
        };
        if !reached(Phase::Steer) {
            return;
        }
        let cp = f.px(cand);
        let colour = match r.outcome {
            RrtOutcome::Added { .. } | RrtOutcome::GoalReached { .. } => PATH,
            _ => HIT,
        };
        let show_outcome = reached(Phase::Outcome);
        c.set_stroke_style_str(if show_outcome { colour } else { MARK });
        c.set_line_width(2.5 * ink.line);
        c.begin_path();
        c.move_to(from.x, from.y);
        c.line_to(cp.x, cp.y);
        c.stroke();
        let q = 4.5 * ink.line;
        c.set_fill_style_str(if show_outcome { colour } else { MARK });
        c.fill_rect(cp.x - q, cp.y - q, 2.0 * q, 2.0 * q);
        if reached(Phase::Check) && r.checked {
            let hit = r.hit.map(|h| h.point);
            for (k, p) in check_points(r.from, cand).iter().enumerate() {
                let at = f.px(*p);
                if Some(k) == hit {
                    disc(c, at, 4.5 * ink.line, HIT);
                    ring(c, at, 8.0 * ink.line, HIT, 2.0 * ink.line);
                } else {
                    disc(c, at, 2.8 * ink.line, "#ffffff");
                    ring(c, at, 2.8 * ink.line, "#111827", ink.line);
                }
            }
        }
        if show_outcome
            && matches!(
                r.outcome,
                RrtOutcome::Added { .. } | RrtOutcome::GoalReached { .. }
            )
        {
            ring(c, cp, 9.0 * ink.line, PATH, 2.5 * ink.line);
        }
    }
}
