//! The workspace overlay: the ik-workspace recipe's grid (`ik_workspace::compute` with the
//! current L1, L2, half-extent and step), one image pixel per cell, drawn under the arm.
//! Cells are coloured by reachability, by `|det J| = L1 L2 |sin q2|` of the elbow-down
//! solution (relative to its largest value `L1 L2`), or by the FK round-trip error on a log
//! scale (1e-16 … 1e-10 mm); unreachable cells stay clear.

use wasm_bindgen::{Clamped, JsValue};
use web_sys::ImageData;

use crate::recipes::ik_workspace::Workspace;
use crate::ui::dom;
use crate::ui::kit::canvas::Layer;
use crate::view::heatmap::{colour_at, Rgb};
use crate::view::ik2r::WsColor;

/// The workspace grid, rendered at one pixel per cell, and the world rectangle it covers
/// (cell edges, metres).
pub struct WorkspaceImage {
    pub layer: Layer,
    pub x_min: f64,
    pub x_max: f64,
    pub y_min: f64,
    pub y_max: f64,
}

/// Paints `ws` into the image of `previous` (or a new one; resized to `nx × ny`, row 0 is the
/// largest y) and returns the overlay with the world rectangle it covers.
pub fn render(
    ws: &Workspace,
    colour: WsColor,
    l1: f64,
    l2: f64,
    lut: &[Rgb],
    previous: Option<WorkspaceImage>,
) -> Result<WorkspaceImage, JsValue> {
    let (nx, ny) = (ws.xs_mm.len(), ws.ys_mm.len());
    if nx == 0 || ny == 0 {
        return Err(JsValue::from_str("empty workspace grid"));
    }
    let mut image = match previous {
        Some(img) => img.layer,
        None => Layer::offscreen(&dom::document()?)?,
    };
    image.resize(nx as f64, ny as f64, 1.0);
    let mut rgba = vec![0u8; nx * ny * 4];
    let det_max = (l1 * l2).max(f64::MIN_POSITIVE);
    for ix in 0..nx {
        for iy in 0..ny {
            let k = ix * ny + iy;
            if !ws.reachable.get(k).copied().unwrap_or(false) {
                continue;
            }
            let q2 = ws.q2.get(k).copied().unwrap_or(f64::NAN);
            let err = ws.err_mm.get(k).copied().unwrap_or(f64::NAN);
            let (rgb, alpha) = match colour {
                WsColor::Reach => ([46, 160, 90], 110),
                WsColor::Manip => {
                    let t = (l1 * l2 * q2.sin()).abs() / det_max;
                    (colour_at(lut, t), 170)
                }
                WsColor::Error => {
                    // log10(err) from -16 (exact) to -10 mm.
                    let t = if err > 0.0 {
                        ((err.log10() + 16.0) / 6.0).clamp(0.0, 1.0)
                    } else {
                        0.0
                    };
                    (colour_at(lut, t), 170)
                }
            };
            let row = ny - 1 - iy;
            let px = (row * nx + ix) * 4;
            if let Some(p) = rgba.get_mut(px..px + 4) {
                p.copy_from_slice(&[rgb[0], rgb[1], rgb[2], alpha]);
            }
        }
    }
    let data = ImageData::new_with_u8_clamped_array_and_sh(Clamped(&rgba), nx as u32, ny as u32)?;
    let _ = image.ctx.set_transform(1.0, 0.0, 0.0, 1.0, 0.0, 0.0);
    image.ctx.put_image_data(&data, 0.0, 0.0)?;
    let first = |v: &[f64]| v.first().copied().unwrap_or(0.0) / 1000.0;
    let last = |v: &[f64]| v.last().copied().unwrap_or(0.0) / 1000.0;
    // Cell edges: half a step beyond the first and last centres.
    let half_x = if nx > 1 {
        (last(&ws.xs_mm) - first(&ws.xs_mm)) / (nx - 1) as f64 / 2.0
    } else {
        0.0005
    };
    let half_y = if ny > 1 {
        (last(&ws.ys_mm) - first(&ws.ys_mm)) / (ny - 1) as f64 / 2.0
    } else {
        0.0005
    };
    Ok(WorkspaceImage {
        layer: image,
        x_min: first(&ws.xs_mm) - half_x,
        x_max: last(&ws.xs_mm) + half_x,
        y_min: first(&ws.ys_mm) - half_y,
        y_max: last(&ws.ys_mm) + half_y,
    })
}
