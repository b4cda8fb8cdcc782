//! The view: two HiDPI canvas layers, below the world's grid and axes (drawn again only when
//! the frame, the size or the ink change: a drag's frames keep it), above the source points X
//! (draggable), the noisy targets Y, the aligned points `s R X + t` with their residual lines,
//! the true similarity's handles (translation and rotation/scale), and what the current
//! teaching step adds (centroids, centred sets, the covariance's columns, the SVD's axes, the
//! scale circles, the translation arrow), redrawn whole on every change. The marks of one
//! kind and colour go in one path (one stroke or fill for all the residuals, all the points),
//! and the labels are small images drawn once per font (canvas text makes Chromium bring the
//! page's style up to date first, after the form's and the slider's changes), drawn from
//! `ImageBitmap`s once made: a drag's frame makes a few dozen canvas calls and draws no text.
//! Where the points, the handles and the tick labels are (CSS px) is written on the top canvas
//! for tests.

use std::cell::{Cell, RefCell};
use std::rc::Rc;

use glam::DVec2;
use wasm_bindgen::closure::Closure;
use wasm_bindgen::{JsCast, JsValue};
use web_sys::{CanvasRenderingContext2d, Element, HtmlCanvasElement, ImageBitmap};

use crate::ui::kit::canvas::{dash, ring, solid, Ink, LayeredCanvas};
use crate::view::drag::HandleShape;
use crate::view::umeyama_2d::{label_corner, rotation_handle, svd, Frame, Grab, Scene, Step};

const BG: &str = "#fbfcfe";
const GRID: &str = "#e6eaf0";
const AXIS: &str = "#9aa4b2";
/// Tick labels: 4.5:1 and more on the ground.
const TICK: &str = "#4a5360";
const X_COL: &str = "#1a4d8f";
const Y_COL: &str = "#c2410c";
const ALIGNED: &str = "#15803d";
const RESIDUAL: &str = "#b91c1c";
const TRUTH: &str = "#7c3aed";
const FAINT: &str = "rgba(74, 83, 96, 0.25)";
const SELECT: &str = "#f59e0b";
const SELECT_EDGE: &str = "#1f2937";

/// Margin around what is shown, CSS px.
const MARGIN: f64 = 34.0;
/// A label's box lies this far (CSS px) right or left of and above or below its mark...
const LABEL_GAP: f64 = 5.0;
/// ...and at least this far from any other mark (a handle, a point).
const LABEL_CLEAR: f64 = 4.0;

/// What is highlighted.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Marks {
    /// A point or one of the truth's handles.
    pub selected: Option<Grab>,
    pub hover: Option<Grab>,
}

/// What the grid layer depends on: the frame, the CSS size and the ink.
type GridKey = (Frame, (f64, f64), Ink);

/// The view component.
pub struct SceneView {
    /// The grid's layer below, the marks' layer on top.
    pub canvas: LayeredCanvas,
    pub frame: Frame,
    /// What the grid layer shows now: frame, size and ink (`None`: draw it).
    grid_drawn: Cell<Option<GridKey>>,
    /// The labels drawn so far, in the label font and pixel ratio they were drawn for.
    labels: RefCell<Labels>,
    /// The texts of the [`PX_ATTRS`] now.
    px_written: RefCell<[String; 3]>,
}

/// Where the points, the translation handle and the rotation handle are (CSS px, for tests
/// and assistive tools), attributes of the top canvas written only when they change.
const PX_ATTRS: [&str; 3] = ["data-points-px", "data-handle-t", "data-handle-r"];

/// The label images of one font and pixel ratio.
#[derive(Default)]
struct Labels {
    font: String,
    /// The font's size, CSS px.
    font_px: f64,
    dpr: f64,
    drawn: Vec<Label>,
}

/// One label's text drawn once into a canvas of its own.
struct Label {
    text: &'static str,
    fill: &'static str,
    /// `None`: it could not be made; the text is drawn directly.
    image: Option<LabelImage>,
}

/// A label's image: its canvas and CSS size.
///
/// Once the browser has made it, the image is drawn from an `ImageBitmap` of the canvas: a
/// canvas drawn into another one is copied ("snapshot") on every draw, now and then for
/// milliseconds, which a bitmap never needs.
struct LabelImage {
    canvas: HtmlCanvasElement,
    bitmap: Rc<RefCell<Option<ImageBitmap>>>,
    w: f64,
    h: f64,
}

impl LabelImage {
    /// `text` in `font` and `fill` at `dpr` device pixels per CSS pixel.
    fn new(text: &str, fill: &str, font: &str, dpr: f64) -> Option<LabelImage> {
        let document = web_sys::window()?.document()?;
        let canvas: HtmlCanvasElement = document.create_element("canvas").ok()?.dyn_into().ok()?;
        let ctx: CanvasRenderingContext2d = canvas.get_context("2d").ok()??.dyn_into().ok()?;
        ctx.set_font(font);
        let m = ctx.measure_text(text).ok()?;
        const PAD: f64 = 2.0;
        let finite = |v: f64| if v.is_finite() { v.max(0.0) } else { 0.0 };
        let left = finite(m.actual_bounding_box_left()) + PAD;
        let right = finite(m.actual_bounding_box_right()).max(finite(m.width())) + PAD;
        let ascent = finite(m.actual_bounding_box_ascent()) + PAD;
        let descent = finite(m.actual_bounding_box_descent()) + PAD;
        canvas.set_width(((left + right) * dpr).ceil().max(1.0) as u32);
        canvas.set_height(((ascent + descent) * dpr).ceil().max(1.0) as u32);
        // The new size reset the context.
        ctx.set_transform(dpr, 0.0, 0.0, dpr, 0.0, 0.0).ok()?;
        ctx.set_font(font);
        ctx.set_fill_style_str(fill);
        ctx.fill_text(text, left, ascent).ok()?;
        let bitmap = Rc::new(RefCell::new(None));
        if let Ok(promise) =
            web_sys::window()?.create_image_bitmap_with_html_canvas_element(&canvas)
        {
            let slot = Rc::downgrade(&bitmap);
            let made = Closure::once_into_js(move |made: JsValue| {
                if let (Some(slot), Ok(made)) = (slot.upgrade(), made.dyn_into::<ImageBitmap>()) {
                    *slot.borrow_mut() = Some(made);
                }
            });
            // A refusal leaves the canvas drawn, as before.
            let refused = Closure::once_into_js(|_: JsValue| {});
            crate::ui::dom::then(&promise, &made, &refused);
        }
        Some(LabelImage {
            bitmap,
            w: f64::from(canvas.width()) / dpr,
            h: f64::from(canvas.height()) / dpr,
            canvas,
        })
    }
}

/// Appends `value@px` to a tick list (`;` between).
fn push_tick(list: &mut String, value: &str, px: f64) {
    if !list.is_empty() {
        list.push(';');
    }
    list.push_str(&format!("{value}@{px:.1}"));
}

fn line(c: &CanvasRenderingContext2d, a: DVec2, b: DVec2, stroke: &str, width: f64) {
    c.set_stroke_style_str(stroke);
    c.set_line_width(width);
    c.begin_path();
    c.move_to(a.x, a.y);
    c.line_to(b.x, b.y);
    c.stroke();
}

fn arrow(c: &CanvasRenderingContext2d, a: DVec2, b: DVec2, stroke: &str, width: f64) {
    line(c, a, b, stroke, width);
    let d = b - a;
    let len = d.length();
    if len < 1.0 {
        return;
    }
    let u = d / len;
    let n = DVec2::new(-u.y, u.x);
    let head = (4.0 * width).min(len * 0.4);
    c.set_fill_style_str(stroke);
    c.begin_path();
    c.move_to(b.x, b.y);
    let p1 = b - u * head * 2.0 + n * head;
    let p2 = b - u * head * 2.0 - n * head;
    c.line_to(p1.x, p1.y);
    c.line_to(p2.x, p2.y);
    c.close_path();
    c.fill();
}

/// Segments `a`–`b`, one path stroked once.
fn segments(
    c: &CanvasRenderingContext2d,
    pairs: impl Iterator<Item = (DVec2, DVec2)>,
    stroke: &str,
    width: f64,
) {
    c.set_stroke_style_str(stroke);
    c.set_line_width(width);
    c.begin_path();
    for (a, b) in pairs {
        c.move_to(a.x, a.y);
        c.line_to(b.x, b.y);
    }
    c.stroke();
}

/// Circles of radius `r` around `centres`, one path.
fn circles(c: &CanvasRenderingContext2d, centres: impl Iterator<Item = DVec2>, r: f64) {
    c.begin_path();
    for p in centres {
        c.move_to(p.x + r, p.y);
        let _ = c.arc(p.x, p.y, r, 0.0, std::f64::consts::TAU);
    }
}

/// Filled discs (the source points).
fn discs(c: &CanvasRenderingContext2d, centres: impl Iterator<Item = DVec2>, r: f64, fill: &str) {
    c.set_fill_style_str(fill);
    circles(c, centres, r);
    c.fill();
}

/// Stroked circles (the aligned points, the centred X).
/// The selection ring of radius `r` around `at`: amber, edged in dark so it stands out on
/// the light ground (3:1 and more).
fn selection_ring(c: &CanvasRenderingContext2d, at: DVec2, r: f64, lw: f64) {
    ring(c, at, r, SELECT, 2.5 * lw);
    ring(c, at, r + 1.75 * lw, SELECT_EDGE, lw);
}

fn rings(
    c: &CanvasRenderingContext2d,
    centres: impl Iterator<Item = DVec2>,
    r: f64,
    stroke: &str,
    width: f64,
) {
    c.set_stroke_style_str(stroke);
    c.set_line_width(width);
    circles(c, centres, r);
    c.stroke();
}

/// Filled squares of half side `half` (the targets), one path.
fn squares(
    c: &CanvasRenderingContext2d,
    centres: impl Iterator<Item = DVec2>,
    half: f64,
    fill: &str,
) {
    c.set_fill_style_str(fill);
    c.begin_path();
    for p in centres {
        c.rect(p.x - half, p.y - half, 2.0 * half, 2.0 * half);
    }
    c.fill();
}

fn diamond(c: &CanvasRenderingContext2d, p: DVec2, r: f64, stroke: &str, width: f64) {
    c.set_stroke_style_str(stroke);
    c.set_line_width(width);
    c.begin_path();
    c.move_to(p.x, p.y - r);
    c.line_to(p.x + r, p.y);
    c.line_to(p.x, p.y + r);
    c.line_to(p.x - r, p.y);
    c.close_path();
    c.stroke();
}

fn cross(c: &CanvasRenderingContext2d, p: DVec2, r: f64, stroke: &str, width: f64) {
    line(
        c,
        p - DVec2::new(r, 0.0),
        p + DVec2::new(r, 0.0),
        stroke,
        width,
    );
    line(
        c,
        p - DVec2::new(0.0, r),
        p + DVec2::new(0.0, r),
        stroke,
        width,
    );
}

impl SceneView {
    /// Wraps the canvas of `stage`.
    pub fn find(stage: &Element) -> Result<SceneView, JsValue> {
        Ok(SceneView {
            canvas: LayeredCanvas::from_stage(stage)?,
            frame: Frame::fit(([-1.0, -1.0], [1.0, 1.0]), (100.0, 100.0), 0.0),
            grid_drawn: Cell::new(None),
            labels: RefCell::new(Labels::default()),
            px_written: RefCell::new(Default::default()),
        })
    }

    /// Writes where the points and handles of `scene` are ([`PX_ATTRS`]) where that changed.
    pub fn write_px(&self, scene: &Scene) {
        let top = &self.canvas.top().canvas;
        let px_of = |p: [f64; 2]| {
            let q = self.frame.px(p);
            format!("{:.1},{:.1}", q.x, q.y)
        };
        let truth = scene.truth();
        let texts = [
            scene
                .x
                .iter()
                .map(|p| px_of(*p))
                .collect::<Vec<_>>()
                .join(";"),
            px_of(truth.t),
            px_of(rotation_handle(&truth)),
        ];
        let mut written = self.px_written.borrow_mut();
        for ((name, text), shown) in PX_ATTRS.iter().zip(texts).zip(written.iter_mut()) {
            if *shown != text {
                let _ = top.set_attribute(name, &text);
                *shown = text;
            }
        }
    }

    /// Sizes the canvas to the stage and fits the frame to `scene`.
    pub fn fit(&mut self, scene: &Scene) {
        self.canvas.fit();
        self.grid_drawn.set(None);
        self.refit(scene);
    }

    /// Fits the frame to `scene` (not the canvas size).
    pub fn refit(&mut self, scene: &Scene) {
        self.frame = Frame::fit(scene.bounds(), self.canvas.size(), MARGIN);
    }

    /// Whether the frame still shows all of `scene`.
    pub fn shows(&self, scene: &Scene) -> bool {
        self.frame.shows(scene.bounds(), self.canvas.size())
    }

    /// Fits the frame to `scene` when it no longer shows it well
    /// ([`crate::view::umeyama_2d::Frame::needs_refit`]).
    pub fn refit_if_needed(&mut self, scene: &Scene) {
        if self.frame.needs_refit(scene.bounds(), self.canvas.size()) {
            self.refit(scene);
        }
    }

    /// Hit radius of handles, px.
    pub fn hit_radius(coarse: bool) -> f64 {
        if coarse {
            22.0
        } else {
            12.0
        }
    }

    /// The touch handles: the points and the truth's two handles.
    pub fn handles(&self, scene: &Scene) -> Vec<HandleShape> {
        let radius = SceneView::hit_radius(true);
        let truth = scene.truth();
        scene
            .x
            .iter()
            .copied()
            .chain([truth.t, rotation_handle(&truth)])
            .map(|p| HandleShape::Circle {
                centre: self.frame.px(p),
                radius,
            })
            .collect()
    }

    /// The grid, the axes and the tick labels; the ticks' texts ([`Self::tick_labels`]).
    fn grid(&self, c: &CanvasRenderingContext2d, ink: Ink) -> Option<[String; 2]> {
        let (w, h) = self.canvas.size();
        let f = &self.frame;
        let lo = f.world(DVec2::new(0.0, h));
        let hi = f.world(DVec2::new(w, 0.0));
        let span = (hi[0] - lo[0]).max(hi[1] - lo[1]);
        let step = crate::view::plot::nice_step(0.0, span, 8);
        if !(step.is_finite() && step > 0.0) {
            return None;
        }
        // Whole multiples of the step, counted: with points near ±1e308 (a huge sigma) the
        // span is not finite and `x += step` would never reach the end.
        let (Some(xs), Some(ys)) = (
            crate::view::umeyama_2d::grid_multiples(lo[0], hi[0], step),
            crate::view::umeyama_2d::grid_multiples(lo[1], hi[1], step),
        ) else {
            return None;
        };
        c.set_stroke_style_str(GRID);
        c.set_line_width(ink.line);
        c.begin_path();
        for k in xs.clone() {
            let p = f.px([k as f64 * step, 0.0]);
            c.move_to(p.x, 0.0);
            c.line_to(p.x, h);
        }
        for k in ys.clone() {
            let p = f.px([0.0, k as f64 * step]);
            c.move_to(0.0, p.y);
            c.line_to(w, p.y);
        }
        c.stroke();
        let o = f.px([0.0, 0.0]);
        line(c, DVec2::new(0.0, o.y), DVec2::new(w, o.y), AXIS, ink.line);
        line(c, DVec2::new(o.x, 0.0), DVec2::new(o.x, h), AXIS, ink.line);
        Some(self.tick_labels(c, ink, step, (xs, ys)))
    }

    /// The tick labels of the grid lines `k·step` of `xs` (along the bottom edge) and `ys`
    /// (along the left edge): every line's, or every n-th's where they would crowd, the
    /// ones that fit inside the canvas. Returns what they say and where (`value@px`, CSS px,
    /// `;` between), x then y.
    fn tick_labels(
        &self,
        c: &CanvasRenderingContext2d,
        ink: Ink,
        step: f64,
        (xs, ys): (std::ops::RangeInclusive<i64>, std::ops::RangeInclusive<i64>),
    ) -> [String; 2] {
        let (w, h) = self.canvas.size();
        let f = &self.frame;
        let text_px = ink.text_px(11.0);
        let pad = 4.0;
        let text = |k: i64| crate::view::plot::tick_label(k as f64 * step, step);
        let width = |t: &str| c.measure_text(t).map(|m| m.width()).unwrap_or(0.0);
        c.set_font(&ink.font(11.0, false));
        c.set_fill_style_str(TICK);
        let step_px = step * f.scale;
        let widest = [*xs.start(), *xs.end()]
            .into_iter()
            .map(|k| width(&text(k)))
            .fold(0.0, f64::max);
        let every = |room: f64| ((room + 8.0) / step_px).ceil().max(1.0) as i64;
        let mut written = [String::new(), String::new()];
        // x: centred under their lines, above the bottom edge.
        let x_every = every(widest);
        c.set_text_align("center");
        c.set_text_baseline("bottom");
        for k in xs.filter(|k| k % x_every == 0) {
            let t = text(k);
            let x = f.px([k as f64 * step, 0.0]).x;
            let half = width(&t) / 2.0;
            if x - half < pad || x + half > w - pad {
                continue;
            }
            let _ = c.fill_text(&t, x, h - pad);
            push_tick(&mut written[0], &t, x);
        }
        // y: beside the left edge, centred on their lines, above the x labels' band.
        let y_every = every(text_px);
        c.set_text_align("left");
        c.set_text_baseline("middle");
        for k in ys.filter(|k| k % y_every == 0) {
            let t = text(k);
            let y = f.px([0.0, k as f64 * step]).y;
            if y - text_px / 2.0 < pad || y + text_px / 2.0 > h - 2.0 * pad - text_px {
                continue;
            }
            let _ = c.fill_text(&t, pad, y);
            push_tick(&mut written[1], &t, y);
        }
        c.set_text_align("start");
        c.set_text_baseline("alphabetic");
        written
    }

    /// The grid layer: background, grid, axes and tick labels, when they changed.
    fn draw_grid(&self, ink: Ink) {
        let key = (self.frame, self.canvas.size(), ink);
        if self.grid_drawn.get() == Some(key) {
            return;
        }
        let layer = self.canvas.layer(0);
        layer.begin();
        let c = &layer.ctx;
        let (w, h) = self.canvas.size();
        c.set_fill_style_str(BG);
        c.fill_rect(0.0, 0.0, w, h);
        let ticks = self.grid(c, ink).unwrap_or_default();
        // What the tick labels say and where, for tests and assistive tools.
        let top = &self.canvas.top().canvas;
        for (name, text) in ["data-ticks-x", "data-ticks-y"].into_iter().zip(ticks) {
            let _ = top.set_attribute(name, &text);
        }
        self.grid_drawn.set(Some(key));
    }

    /// Labels in `ink`'s label font at the top layer's pixel ratio from now on.
    fn label_font(&self, ink: Ink) {
        let font = ink.font(13.0, true);
        let dpr = self.canvas.top().dpr;
        let mut labels = self.labels.borrow_mut();
        if labels.font != font || labels.dpr != dpr {
            *labels = Labels {
                font,
                font_px: ink.text_px(13.0),
                dpr,
                drawn: Vec::new(),
            };
        }
    }

    /// `text` in `fill` beside `p`, clear of the marks of `avoid`
    /// ([`crate::view::umeyama_2d::label_corner`]): its image, on whole device pixels.
    fn label(
        &self,
        c: &CanvasRenderingContext2d,
        p: DVec2,
        (text, fill): (&'static str, &'static str),
        avoid: &[(DVec2, f64)],
    ) {
        let mut labels = self.labels.borrow_mut();
        let index = match labels
            .drawn
            .iter()
            .position(|l| l.text == text && l.fill == fill)
        {
            Some(i) => i,
            None => {
                let image = LabelImage::new(text, fill, &labels.font, labels.dpr);
                labels.drawn.push(Label { text, fill, image });
                labels.drawn.len() - 1
            }
        };
        let dpr = labels.dpr;
        let font_px = labels.font_px;
        let size = match &labels.drawn[index].image {
            Some(image) => DVec2::new(image.w, image.h),
            None => DVec2::new(0.6 * font_px * text.chars().count() as f64, 1.3 * font_px),
        };
        let corner = label_corner(p, size, LABEL_GAP, avoid, LABEL_CLEAR);
        match &labels.drawn[index].image {
            Some(image) => {
                let snap = |v: f64| (v * dpr).round() / dpr;
                let (x, y) = (snap(corner.x), snap(corner.y));
                let _ = match image.bitmap.borrow().as_ref() {
                    Some(bitmap) => {
                        c.draw_image_with_image_bitmap_and_dw_and_dh(bitmap, x, y, image.w, image.h)
                    }
                    None => c.draw_image_with_html_canvas_element_and_dw_and_dh(
                        &image.canvas,
                        x,
                        y,
                        image.w,
                        image.h,
                    ),
                };
            }
            None => {
                c.set_font(&labels.font);
                c.set_fill_style_str(fill);
                let _ = c.fill_text(text, corner.x, corner.y + font_px);
            }
        }
    }

    /// Draws `scene` at teaching `step`.
    pub fn draw(&self, scene: &Scene, step: Step, marks: Marks, ink: Ink) {
        self.draw_grid(ink);
        let layer = self.canvas.top();
        layer.begin();
        let c = &layer.ctx;
        let f = &self.frame;
        let s = &scene.steps;
        let lw = ink.line;
        let r = 5.0 * lw;
        let centred = matches!(
            step,
            Step::Centred | Step::Covariance | Step::Svd | Step::Reflection
        );
        let faded = centred || step == Step::Centroids;
        // Correspondences X_i → Y_i.
        if step == Step::Overview || step == Step::Centroids {
            let pairs = scene.x.iter().zip(&scene.y);
            segments(c, pairs.map(|(p, q)| (f.px(*p), f.px(*q))), FAINT, lw);
        }
        c.set_global_alpha(if faded { 0.3 } else { 1.0 });
        // Aligned points and residuals (the fit's result).
        if !faded {
            c.set_line_dash(&dash(5.0 * lw, 4.0 * lw)).ok();
            let width = if step == Step::Rmse {
                3.0 * lw
            } else {
                1.6 * lw
            };
            let pairs = s.aligned.iter().zip(&scene.y);
            segments(c, pairs.map(|(a, q)| (f.px(*a), f.px(*q))), RESIDUAL, width);
            c.set_line_dash(&solid()).ok();
        }
        squares(c, scene.y.iter().map(|q| f.px(*q)), 0.9 * r, Y_COL);
        discs(c, scene.x.iter().map(|p| f.px(*p)), r, X_COL);
        let selected_point = match marks.selected {
            Some(Grab::Point(i)) => scene.x.get(i),
            _ => None,
        };
        if let Some(p) = selected_point {
            selection_ring(c, f.px(*p), r + 4.0 * lw, lw);
        }
        if let Some(Grab::Point(i)) = marks.hover {
            if marks.selected != Some(Grab::Point(i)) {
                if let Some(p) = scene.x.get(i) {
                    ring(c, f.px(*p), r + 3.0 * lw, X_COL, 1.5 * lw);
                }
            }
        }
        if !faded {
            let aligned = s.aligned.iter().map(|a| f.px(*a));
            rings(c, aligned, r + 1.5 * lw, ALIGNED, 2.0 * lw);
        }
        c.set_global_alpha(1.0);
        // The truth's handles: t, and t + s (cos θ, sin θ).
        let truth = scene.truth();
        let t = f.px(truth.t);
        let rh = f.px(rotation_handle(&truth));
        c.set_line_dash(&dash(3.0 * lw, 3.0 * lw)).ok();
        line(c, t, rh, TRUTH, 1.5 * lw);
        c.set_line_dash(&solid()).ok();
        let hover_w = |g: Grab| if marks.hover == Some(g) { 3.5 } else { 2.0 };
        diamond(c, t, 8.0 * lw, TRUTH, hover_w(Grab::Translation) * lw);
        ring(c, rh, 6.0 * lw, TRUTH, hover_w(Grab::Rotation) * lw);
        // The selected handle: the points' ring.
        let selected_handle = match marks.selected {
            Some(Grab::Translation) => Some((t, 8.0)),
            Some(Grab::Rotation) => Some((rh, 6.0)),
            _ => None,
        };
        if let Some((at, size)) = selected_handle {
            selection_ring(c, at, (size + 5.0) * lw, lw);
        }
        self.label_font(ink);
        // What a label keeps clear of: the handles and the points.
        let avoid: Vec<(DVec2, f64)> = [(t, 8.0 * lw), (rh, 6.0 * lw)]
            .into_iter()
            .chain(scene.x.iter().chain(&scene.y).map(|p| (f.px(*p), 1.3 * r)))
            .collect();
        self.label(c, t, ("t", TRUTH), &avoid);
        self.label(c, rh, ("s·R", TRUTH), &avoid);
        self.draw_step(c, scene, step, ink, &avoid);
    }

    fn draw_step(
        &self,
        c: &CanvasRenderingContext2d,
        scene: &Scene,
        step: Step,
        ink: Ink,
        avoid: &[(DVec2, f64)],
    ) {
        let f = &self.frame;
        let s = &scene.steps;
        let lw = ink.line;
        let r = 5.0 * lw;
        let o = f.px([0.0, 0.0]);
        let at_origin = |v: [f64; 2]| f.px(v);
        match step {
            Step::Overview => {}
            Step::Centroids => {
                for (p, col) in [(s.mu_x, X_COL), (s.mu_y, Y_COL)] {
                    let at = f.px(p);
                    ring(c, at, 9.0 * lw, col, 2.5 * lw);
                    cross(c, at, 13.0 * lw, col, 2.0 * lw);
                }
                self.label(c, f.px(s.mu_x), ("μx", X_COL), avoid);
                self.label(c, f.px(s.mu_y), ("μy", Y_COL), avoid);
                let (mx, my) = (f.px(s.mu_x), f.px(s.mu_y));
                let to_mx = scene.x.iter().map(|p| (f.px(*p), mx));
                segments(c, to_mx, "rgba(26, 77, 143, 0.25)", lw);
                let to_my = scene.y.iter().map(|q| (f.px(*q), my));
                segments(c, to_my, "rgba(194, 65, 12, 0.25)", lw);
            }
            Step::Centred | Step::Covariance | Step::Svd | Step::Reflection => {
                let pairs = s.centred_x.iter().zip(&s.centred_y);
                segments(
                    c,
                    pairs.map(|(p, q)| (at_origin(*p), at_origin(*q))),
                    FAINT,
                    lw,
                );
                let centred_x = s.centred_x.iter().map(|p| at_origin(*p));
                rings(c, centred_x, r, X_COL, 2.0 * lw);
                c.set_stroke_style_str(Y_COL);
                c.set_line_width(2.0 * lw);
                c.begin_path();
                for q in &s.centred_y {
                    let at = at_origin(*q);
                    c.rect(at.x - r, at.y - r, 2.0 * r, 2.0 * r);
                }
                c.stroke();
                cross(c, o, 10.0 * lw, "#111827", 1.5 * lw);
                if step == Step::Covariance {
                    // C's columns: where C sends the axes.
                    let col = |j: usize| [s.cov[0][j], s.cov[1][j]];
                    arrow(c, o, at_origin(col(0)), "#0f766e", 3.0 * lw);
                    arrow(c, o, at_origin(col(1)), "#0f766e", 3.0 * lw);
                    self.label(c, at_origin(col(0)), ("C e₁", "#0f766e"), avoid);
                    self.label(c, at_origin(col(1)), ("C e₂", "#0f766e"), avoid);
                }
                if step == Step::Svd || step == Step::Reflection {
                    let d = svd(s);
                    let u = if step == Step::Reflection {
                        d.u_fixed
                    } else {
                        d.u
                    };
                    for (k, (v_name, u_name)) in
                        [("v₁", "S₁u₁"), ("v₂", "S₂u₂")].into_iter().enumerate()
                    {
                        // C v_k = S_k u_k: V's axes (unit, blue) go to U's axes (scaled).
                        let v = [d.vt[k][0], d.vt[k][1]];
                        let uk = [u[0][k] * d.s[k], u[1][k] * d.s[k]];
                        arrow(c, o, at_origin(v), X_COL, 2.5 * lw);
                        arrow(c, o, at_origin(uk), Y_COL, 2.5 * lw);
                        self.label(c, at_origin(v), (v_name, X_COL), avoid);
                        self.label(c, at_origin(uk), (u_name, Y_COL), avoid);
                    }
                    if step == Step::Reflection && s.reflection_fixed() {
                        // The column the fix negated, as it was.
                        let old = [d.u[0][1] * d.s[1], d.u[1][1] * d.s[1]];
                        c.set_line_dash(&dash(4.0 * lw, 4.0 * lw)).ok();
                        arrow(c, o, at_origin(old), RESIDUAL, 2.0 * lw);
                        c.set_line_dash(&solid()).ok();
                    }
                }
            }
            Step::Scale => {
                let rx = s.var_x.sqrt() * f.scale;
                let ry = s.scale * s.var_x.sqrt() * f.scale;
                ring(c, f.px(s.mu_x), rx, X_COL, 2.0 * lw);
                ring(c, f.px(s.mu_y), ry, Y_COL, 2.0 * lw);
                self.label(
                    c,
                    f.px(s.mu_x) + DVec2::new(rx * 0.7, -rx * 0.7),
                    ("√var_x", X_COL),
                    avoid,
                );
                self.label(
                    c,
                    f.px(s.mu_y) + DVec2::new(ry * 0.7, -ry * 0.7),
                    ("s·√var_x", Y_COL),
                    avoid,
                );
            }
            Step::Translation => {
                // s R X before the translation, and t carrying it onto the targets.
                let rot = s.rotation;
                let srx = |p: &[f64; 2]| {
                    [
                        s.scale * (rot[0][0] * p[0] + rot[0][1] * p[1]),
                        s.scale * (rot[1][0] * p[0] + rot[1][1] * p[1]),
                    ]
                };
                let moved = scene.x.iter().map(|p| f.px(srx(p)));
                rings(c, moved, r, "rgba(21, 128, 61, 0.5)", 1.5 * lw);
                let from = srx(&s.mu_x);
                arrow(c, f.px(from), f.px(s.mu_y), ALIGNED, 3.0 * lw);
                arrow(c, o, f.px(s.t), ALIGNED, 2.0 * lw);
                self.label(c, f.px(s.t), ("t̂", ALIGNED), avoid);
            }
            Step::Rmse => {}
        }
    }
}
