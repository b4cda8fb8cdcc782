//! The small picture on each recipe card and page tile of the home page ([`crate::view::card_picture`]):
//! the kernels run at their defaults after the first paint, one card per task, so the page
//! shows at once and no task is long. The tiles of the Robot Pilot pages, which have no
//! recipe, show their scenes at the start ([`crate::view::pilot_picture`]).

use std::rc::Rc;

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::{CanvasRenderingContext2d, Element, HtmlCanvasElement};

use crate::ui::{dom, schedule};
use crate::view::card_picture::{self, Mark, Picture};
use crate::view::heatmap;
use crate::view::palette;
use crate::view::pilot_picture;

/// Okabe–Ito colours of the palette slots (`card_picture::series`; slot 3 is a neutral grey).
const PALETTE: [&str; 5] = [
    palette::BLUE.hex,
    palette::ORANGE.hex,
    palette::BLUISH_GREEN.hex,
    "#B8BEC6",
    palette::VERMILION.hex,
];

/// The element id of recipe `id`'s card blurb, the picture's description.
pub(crate) fn blurb_id(id: &str) -> String {
    format!("recipe-blurb-{id}")
}

/// The (empty) canvas of recipe `id`'s card, named for screen readers and described by the
/// card's blurb (element [`blurb_id`]).
pub(crate) fn canvas(id: &str) -> Result<Element, JsValue> {
    let canvas = dom::el_class("canvas", "card-picture")?;
    canvas.set_attribute("data-testid", &format!("card-picture-{id}"))?;
    canvas.set_attribute("data-recipe", id)?;
    canvas.set_attribute("role", "img")?;
    canvas.set_attribute("aria-describedby", &blurb_id(id))?;
    dom::set_i18n_attrs(&canvas, &[("aria-label", &format!("home-picture-{id}"))])?;
    Ok(canvas)
}

/// The picture on the tile of page `page_id`: recipe `recipe`'s, or else the page's scene at
/// its start ([`pilot_picture`]). The tile's text names it: the canvas is hidden from screen
/// readers.
pub(crate) fn tile_canvas(page_id: &str, recipe: Option<&str>) -> Result<Element, JsValue> {
    let canvas = dom::el_class("canvas", "tile-picture")?;
    canvas.set_attribute("data-testid", &format!("tile-picture-{page_id}"))?;
    match recipe {
        Some(id) => canvas.set_attribute("data-recipe", id)?,
        None => canvas.set_attribute("data-scene", page_id)?,
    }
    canvas.set_attribute("aria-hidden", "true")?;
    Ok(canvas)
}

/// Whether page `page_id` (one without a recipe) has a picture of its scene for its tile.
pub(crate) fn has_scene(page_id: &str) -> bool {
    pilot_picture::PAGES.contains(&page_id)
}

/// Draws every tile and card picture under `root` (in document order: the tiles of the first
/// screen first), one per task after the first paint.
pub(crate) fn draw_all(root: &Element) -> Result<(), JsValue> {
    let queue: Rc<Vec<HtmlCanvasElement>> = Rc::new(
        dom::matching(root, "canvas.tile-picture, canvas.card-picture")?
            .into_iter()
            .filter_map(|e| e.dyn_into::<HtmlCanvasElement>().ok())
            .collect(),
    );
    schedule::after_paint(move || next(queue, 0))
}

fn next(queue: Rc<Vec<HtmlCanvasElement>>, i: usize) {
    let Some(canvas) = queue.get(i) else {
        return;
    };
    // A canvas no longer in the document: the user left the home page.
    if !canvas.is_connected() {
        return;
    }
    let aspect = f64::from(canvas.client_width().max(1)) / f64::from(canvas.client_height().max(1));
    let picture = match canvas.get_attribute("data-recipe") {
        Some(id) => card_picture::default_picture(&id, aspect),
        None => canvas
            .get_attribute("data-scene")
            .and_then(|page| pilot_picture::picture(&page, aspect)),
    };
    if let Some(picture) = picture {
        if draw(canvas, &picture).is_ok() {
            let _ = canvas.set_attribute("data-drawn", "1");
        }
    }
    let rest = Rc::clone(&queue);
    let _ = schedule::after_paint(move || next(rest, i + 1));
}

/// The edge of a solid: the tile's background, a little see-through.
const EDGE: &str = "rgba(255,255,255,0.75)";

/// How opaque a region's fill is (its outline is drawn in full).
const REGION_ALPHA: f64 = 0.3;

fn colour(series: u8) -> &'static str {
    PALETTE[usize::from(series) % PALETTE.len()]
}

/// A closed path through `points` (unit square, mapped by `at`).
fn polygon(
    ctx: &CanvasRenderingContext2d,
    points: &[glam::DVec2],
    at: &impl Fn(glam::DVec2) -> (f64, f64),
) {
    ctx.begin_path();
    for (k, p) in points.iter().enumerate() {
        let (x, y) = at(*p);
        if k == 0 {
            ctx.move_to(x, y);
        } else {
            ctx.line_to(x, y);
        }
    }
    ctx.close_path();
}

fn draw(canvas: &HtmlCanvasElement, picture: &Picture) -> Result<(), JsValue> {
    let dpr = web_sys::window().map_or(1.0, |w| w.device_pixel_ratio());
    let (w, h) = (
        f64::from(canvas.client_width().max(1)),
        f64::from(canvas.client_height().max(1)),
    );
    canvas.set_width((w * dpr).round() as u32);
    canvas.set_height((h * dpr).round() as u32);
    let ctx = canvas
        .get_context("2d")?
        .and_then(|c| c.dyn_into::<CanvasRenderingContext2d>().ok())
        .ok_or_else(|| JsValue::from_str("no 2d context"))?;
    ctx.scale(dpr, dpr)?;
    let at = |p: glam::DVec2| (p.x * w, (1.0 - p.y) * h);
    for mark in &picture.marks {
        match mark {
            Mark::Line { series, points } => {
                ctx.set_stroke_style_str(colour(*series));
                ctx.set_line_width(1.75);
                ctx.begin_path();
                for (k, p) in points.iter().enumerate() {
                    let (x, y) = at(*p);
                    if k == 0 {
                        ctx.move_to(x, y);
                    } else {
                        ctx.line_to(x, y);
                    }
                }
                ctx.stroke();
            }
            Mark::Dots { series, points } => {
                ctx.set_fill_style_str(colour(*series));
                let r = if points.len() > 400 { 1.1 } else { 2.2 };
                for p in points {
                    let (x, y) = at(*p);
                    ctx.fill_rect(x - r, y - r, 2.0 * r, 2.0 * r);
                }
            }
            Mark::Segments { series, pairs } => {
                ctx.set_stroke_style_str(colour(*series));
                ctx.set_line_width(1.25);
                ctx.begin_path();
                for (a, b) in pairs {
                    let (ax, ay) = at(*a);
                    let (bx, by) = at(*b);
                    ctx.move_to(ax, ay);
                    ctx.line_to(bx, by);
                }
                ctx.stroke();
            }
            Mark::Fill { series, points } => {
                polygon(&ctx, points, &at);
                ctx.set_fill_style_str(colour(*series));
                ctx.fill();
                // A hairline in the tile's colour parts solids that touch.
                ctx.set_stroke_style_str(EDGE);
                ctx.set_line_width(0.75);
                ctx.stroke();
            }
            Mark::Region { series, points } => {
                polygon(&ctx, points, &at);
                ctx.set_fill_style_str(colour(*series));
                ctx.set_global_alpha(REGION_ALPHA);
                ctx.fill();
                ctx.set_global_alpha(1.0);
                ctx.set_stroke_style_str(colour(*series));
                ctx.set_line_width(1.5);
                ctx.stroke();
            }
            Mark::Cells { cols, rows, values } => {
                let lut = heatmap::viridis();
                let (cw, ch) = (w / *cols as f64, h / *rows as f64);
                for (k, v) in values.iter().enumerate() {
                    let (cx, cy) = ((k % cols) as f64, (k / cols) as f64);
                    let c = heatmap::colour_at(&lut, *v);
                    ctx.set_fill_style_str(&format!("rgb({},{},{})", c[0], c[1], c[2]));
                    // Cells overlap by a pixel so no seams show.
                    ctx.fill_rect(cx * cw, h - (cy + 1.0) * ch, cw + 0.6, ch + 0.6);
                }
            }
        }
    }
    Ok(())
}
