//! HiDPI layered canvases: a stage element holding stacked `<canvas>` layers whose backing
//! stores are `CSS size × devicePixelRatio` and which are drawn in CSS pixels (the context
//! transform carries the ratio) — resize them from the scope's `observe_resize` — and
//! [`Ink`], the line and type scale of normal and projector mode
//! (text sizes come from `ctx::scaled_font_px`: in projector mode no canvas text is smaller
//! than `ctx::PROJECTOR_MIN_FONT_PX`, 24 CSS px).
//!
//! Typical use: backgrounds (grids, axes, painted images) on layer 0, redrawn only when the
//! size, the language or the data change; per-frame marks on the top layer.

use std::f64::consts::TAU;

use glam::DVec2;
use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::{CanvasRenderingContext2d, Document, Element, HtmlCanvasElement};

use crate::ui::{ctx, dom};

/// One canvas and its 2D context, sized in CSS pixels.
pub struct Layer {
    pub canvas: HtmlCanvasElement,
    pub ctx: CanvasRenderingContext2d,
    /// Size in CSS pixels.
    pub css_w: f64,
    pub css_h: f64,
    /// Device pixels per CSS pixel.
    pub dpr: f64,
}

impl Layer {
    /// Wraps an existing canvas.
    pub fn new(canvas: HtmlCanvasElement) -> Result<Layer, JsValue> {
        let ctx = canvas
            .get_context("2d")?
            .ok_or_else(|| JsValue::from_str("canvas 2d context unavailable"))?
            .dyn_into::<CanvasRenderingContext2d>()?;
        Ok(Layer {
            canvas,
            ctx,
            css_w: 0.0,
            css_h: 0.0,
            dpr: 1.0,
        })
    }

    /// A canvas that is never attached to the document (a cache, an image).
    pub fn offscreen(doc: &Document) -> Result<Layer, JsValue> {
        let canvas = doc
            .create_element("canvas")?
            .dyn_into::<HtmlCanvasElement>()?;
        Layer::new(canvas)
    }

    /// Sets the CSS size and pixel ratio; returns whether the backing store changed (which
    /// also clears it).
    pub fn resize(&mut self, css_w: f64, css_h: f64, dpr: f64) -> bool {
        let css_w = css_w.max(1.0);
        let css_h = css_h.max(1.0);
        let dpr = if dpr.is_finite() && dpr > 0.0 {
            dpr
        } else {
            1.0
        };
        let w = (css_w * dpr).round().max(1.0) as u32;
        let h = (css_h * dpr).round().max(1.0) as u32;
        let changed = self.canvas.width() != w || self.canvas.height() != h;
        if changed {
            self.canvas.set_width(w);
            self.canvas.set_height(h);
        }
        self.css_w = css_w;
        self.css_h = css_h;
        self.dpr = dpr;
        changed
    }

    /// Resets the transform to CSS pixels and clears everything.
    pub fn begin(&self) {
        let ctx = &self.ctx;
        let _ = ctx.set_transform(1.0, 0.0, 0.0, 1.0, 0.0, 0.0);
        ctx.clear_rect(
            0.0,
            0.0,
            f64::from(self.canvas.width()),
            f64::from(self.canvas.height()),
        );
        let _ = ctx.set_transform(self.dpr, 0.0, 0.0, self.dpr, 0.0, 0.0);
    }
}

/// Stacked canvases filling one stage element (bottom layer first).
pub struct LayeredCanvas {
    pub stage: Element,
    pub layers: Vec<Layer>,
}

impl LayeredCanvas {
    /// Wraps the `<canvas>` children of `stage`, in document order (bottom first).
    pub fn from_stage(stage: &Element) -> Result<LayeredCanvas, JsValue> {
        let mut layers = Vec::new();
        for c in dom::matching(stage, ":scope > canvas")? {
            layers.push(Layer::new(c.dyn_into::<HtmlCanvasElement>()?)?);
        }
        if layers.is_empty() {
            return Err(JsValue::from_str("kit canvas: the stage has no canvas"));
        }
        Ok(LayeredCanvas {
            stage: stage.clone(),
            layers,
        })
    }

    /// Creates `n` canvases (class `class`) in `stage`; all but the top one are
    /// `aria-hidden`.
    pub fn create(stage: &Element, n: usize, class: &str) -> Result<LayeredCanvas, JsValue> {
        for i in 0..n.max(1) {
            let c = dom::el_class("canvas", class)?;
            if i + 1 < n {
                c.set_attribute("aria-hidden", "true")?;
            }
            dom::append(stage, &c)?;
        }
        LayeredCanvas::from_stage(stage)
    }

    /// Layer `i` (0 = bottom); the top layer past the end.
    pub fn layer(&self, i: usize) -> &Layer {
        let last = self.layers.len() - 1;
        &self.layers[i.min(last)]
    }

    /// The top layer (the one pointer events and tests look at).
    pub fn top(&self) -> &Layer {
        self.layer(usize::MAX)
    }

    /// Sizes every layer to the top canvas's CSS box at the device pixel ratio; returns
    /// whether any backing store changed.
    pub fn fit(&mut self) -> bool {
        let dpr = web_sys::window().map_or(1.0, |w| w.device_pixel_ratio());
        let r = self.top().canvas.get_bounding_client_rect();
        let (w, h) = (r.width().max(1.0), r.height().max(1.0));
        let mut changed = false;
        for layer in &mut self.layers {
            changed |= layer.resize(w, h, dpr);
        }
        changed
    }

    /// Whether [`LayeredCanvas::fit`] has sized the layers yet.
    pub fn is_fitted(&self) -> bool {
        self.top().css_w > 0.0
    }

    /// CSS size of the layers.
    pub fn size(&self) -> (f64, f64) {
        let top = self.top();
        (top.css_w, top.css_h)
    }

    /// All layers composited on `background` into one new canvas (for a PNG export with
    /// `kit::png::download`).
    pub fn flatten(&self, background: &str) -> Result<HtmlCanvasElement, JsValue> {
        let layers: Vec<&HtmlCanvasElement> = self.layers.iter().map(|l| &l.canvas).collect();
        super::png::flatten(&layers, background)
    }
}

/// Line and type scale for canvas drawing.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ink {
    /// Line widths and marks.
    pub line: f64,
    /// The room kept for text (label areas, margins).
    pub text: f64,
    pub projector: bool,
}

impl Ink {
    /// The scale of the current mode.
    pub fn current() -> Ink {
        Ink::for_projector(ctx::projector())
    }

    /// 1 normally; in projector mode lines × 1.6, text per `ctx::scaled_font_px` (at least
    /// 24 px) and the room kept for text × 2.2.
    pub fn for_projector(on: bool) -> Ink {
        if on {
            Ink {
                line: 1.6,
                text: 2.2,
                projector: true,
            }
        } else {
            Ink {
                line: 1.0,
                text: 1.0,
                projector: false,
            }
        }
    }

    /// The CSS px size of text that is `base` px normally (never below the projector
    /// minimum in projector mode).
    pub fn text_px(&self, base: f64) -> f64 {
        ctx::scaled_font_px(base, self.projector)
    }

    /// A CSS font string for canvas text of `base` px (see [`Ink::text_px`]).
    pub fn font(&self, base: f64, bold: bool) -> String {
        font_px(self.text_px(base), bold)
    }
}

/// A CSS font string of `px` CSS pixels.
pub fn font_px(px: f64, bold: bool) -> String {
    format!(
        "{}{:.1}px system-ui, -apple-system, \"Segoe UI\", \"Noto Sans JP\", \"IPAPGothic\", sans-serif",
        if bold { "600 " } else { "" },
        px
    )
}

/// A filled disc of radius `r` CSS px at `p`.
pub fn disc(c: &CanvasRenderingContext2d, p: DVec2, r: f64, fill: &str) {
    c.set_fill_style_str(fill);
    c.begin_path();
    let _ = c.arc(p.x, p.y, r, 0.0, TAU);
    c.fill();
}

/// A circle of radius `r` at `p`, stroked `width` px.
pub fn ring(c: &CanvasRenderingContext2d, p: DVec2, r: f64, stroke: &str, width: f64) {
    c.set_stroke_style_str(stroke);
    c.set_line_width(width);
    c.begin_path();
    let _ = c.arc(p.x, p.y, r, 0.0, TAU);
    c.stroke();
}

/// `[a, b]` as a JS array for `setLineDash`.
pub fn dash(a: f64, b: f64) -> JsValue {
    let arr = js_sys::Array::new();
    arr.push(&JsValue::from_f64(a));
    arr.push(&JsValue::from_f64(b));
    arr.into()
}

/// An empty JS array (solid lines).
pub fn solid() -> JsValue {
    js_sys::Array::new().into()
}

/// Focuses `element` (a canvas taking the page's keys) without scrolling the page: a press
/// that gives the canvas focus must not move it under the pointer.
pub fn focus_without_scroll(element: &Element) {
    let options = js_sys::Object::new();
    let _ = js_sys::Reflect::set(&options, &"preventScroll".into(), &JsValue::TRUE);
    if let Ok(f) = js_sys::Reflect::get(element, &"focus".into())
        .and_then(|f| f.dyn_into::<js_sys::Function>())
    {
        let _ = f.call1(element, &options);
    }
}
