//! PNG export of any canvas: the canvas's pixels (at its backing-store resolution, so HiDPI
//! canvases export sharp) offered as a download, no server round trip. Layered canvases are
//! composited first with [`flatten`], onto an opaque background so the file looks as on
//! screen in any viewer.

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::{CanvasRenderingContext2d, HtmlCanvasElement};

use crate::ui::{dom, download};

/// Offers the pixels of `canvas` as a PNG called `file_name`.
pub fn download(canvas: &HtmlCanvasElement, file_name: &str) -> Result<(), JsValue> {
    download::download_canvas_png(canvas, file_name)
}

/// A new canvas of `width` × `height` (at least 1 × 1) filled with `background`, and its 2D
/// context.
fn filled(
    width: u32,
    height: u32,
    background: &str,
) -> Result<(HtmlCanvasElement, CanvasRenderingContext2d), JsValue> {
    let out = dom::el("canvas")?.dyn_into::<HtmlCanvasElement>()?;
    out.set_width(width.max(1));
    out.set_height(height.max(1));
    let context = out
        .get_context("2d")?
        .ok_or_else(|| JsValue::from_str("png: no 2d context"))?
        .dyn_into::<CanvasRenderingContext2d>()?;
    context.set_fill_style_str(background);
    context.fill_rect(0.0, 0.0, f64::from(width), f64::from(height));
    Ok((out, context))
}

/// A new canvas the size of the first layer with `background` (a CSS colour) and every layer
/// drawn on it in order (bottom first): what a stack of layered canvases shows.
pub fn flatten(
    layers: &[&HtmlCanvasElement],
    background: &str,
) -> Result<HtmlCanvasElement, JsValue> {
    let (width, height) = layers
        .first()
        .map(|c| (c.width(), c.height()))
        .unwrap_or((1, 1));
    let (out, context) = filled(width, height, background)?;
    for layer in layers {
        context.draw_image_with_html_canvas_element_and_dw_and_dh(
            layer,
            0.0,
            0.0,
            f64::from(width),
            f64::from(height),
        )?;
    }
    Ok(out)
}

/// [`flatten`] then [`download()`].
pub fn download_layers(
    layers: &[&HtmlCanvasElement],
    background: &str,
    file_name: &str,
) -> Result<(), JsValue> {
    download(&flatten(layers, background)?, file_name)
}

/// Several layered canvases in one PNG, side by side (left to right, tops aligned): each
/// group is [`flatten`]ed onto `background`, then they are joined and offered as `file_name`.
pub fn download_stacked(
    groups: &[&[&HtmlCanvasElement]],
    background: &str,
    file_name: &str,
) -> Result<(), JsValue> {
    let parts = groups
        .iter()
        .map(|layers| flatten(layers, background))
        .collect::<Result<Vec<_>, _>>()?;
    let width: u32 = parts.iter().map(HtmlCanvasElement::width).sum();
    let height = parts
        .iter()
        .map(HtmlCanvasElement::height)
        .max()
        .unwrap_or(1);
    let (out, context) = filled(width, height, background)?;
    let mut x = 0.0;
    for part in &parts {
        context.draw_image_with_html_canvas_element(part, x, 0.0)?;
        x += f64::from(part.width());
    }
    download(&out, file_name)
}
