//! HiDPI canvas layers: a canvas whose backing store is `css size × devicePixelRatio`, drawn
//! in CSS pixels (the context transform carries the ratio), plus the projector-mode scale for
//! line widths and type.

use wasm_bindgen::{JsCast, JsValue};
use web_sys::{CanvasRenderingContext2d, Document, HtmlCanvasElement};

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

    /// A canvas that is never attached to the document (a cache).
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

/// Line-width and type scale: 1 normally, larger in projector mode.
pub fn projector_scale(on: bool) -> f64 {
    if on {
        1.6
    } else {
        1.0
    }
}

/// A CSS font string for canvas text, `size` CSS pixels before the projector scale.
pub fn font(size: f64, scale: f64, bold: bool) -> String {
    format!(
        "{}{:.1}px system-ui, -apple-system, \"Segoe UI\", \"Noto Sans JP\", \"IPAPGothic\", sans-serif",
        if bold { "600 " } else { "" },
        size * scale
    )
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
