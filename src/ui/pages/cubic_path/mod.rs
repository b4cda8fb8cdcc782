//! The cubic path (`#/cubic-path`): position, velocity and acceleration of the recipe's cubic
//! on three panels sharing the time axis, recomputed while a value is dragged (a slider, a
//! field, or the end point q1 at T on the position plot); a cursor readout at the hovered time;
//! the quintic and the same-time trapezoid as optional overlays (not exported: the CSV stays
//! the recipe's, byte for byte what `bsv cubic-path` writes).
//!
//! Components: `plots` (the kit plot with the end-point drag and the cursor) and the kit's
//! [`RecipeControls`] (form + sliders + URL + exports) and readouts; the numbers come from the
//! pure `crate::view::cubic_path`.

mod plots;

use std::cell::{Cell, RefCell};
use std::rc::{Rc, Weak};

use wasm_bindgen::prelude::*;
use web_sys::{Element, HtmlInputElement, KeyboardEvent};

use crate::pyfmt::py_float;
use crate::recipes::cubic_path::{compute, params_from_args, CubicParams, CubicPath, INFO};
use crate::ui::kit::readouts::{self, Readouts};
use crate::ui::kit::recipe_controls::{self, record_frame_ms, RecipeControls};
use crate::ui::kit::scope::Scope;
use crate::ui::kit::url_state::UrlWriter;
use crate::ui::page::{MountCtx, Page, PageDef, Shortcut};
use crate::ui::schedule::now_ms;
use crate::ui::{ctx, dom};
use crate::view::cubic_path::readouts as numbers;
use crate::view::signal::{sig, snap, Slider};

/// The page, as the shell's page table lists it.
pub const PAGE: PageDef = PageDef::of::<CubicPage>("cubic-path", "cubic-title", "cubic-blurb");

const P: &str = "cubic";
const PNG: &str = "cubic_path_plots.png";
/// The overlays (URL key = `data-overlay`).
const OVERLAYS: [&str; 2] = ["quintic", "trapezoid"];
const SLIDERS: [Slider; 4] = [
    Slider {
        name: "q0",
        min: -3.2,
        max: 3.2,
        step: 0.01,
    },
    Slider {
        name: "q1",
        min: -3.2,
        max: 3.2,
        step: 0.01,
    },
    Slider {
        name: "T",
        min: 0.1,
        max: 5.0,
        step: 0.01,
    },
    Slider {
        name: "dt",
        min: 0.001,
        max: 0.2,
        step: 0.001,
    },
];
/// `(data-readout, label id)`.
const READOUTS: [(&str, &str); 13] = [
    ("peak-velocity", "cubic-ro-peak-v"),
    ("peak-velocity-t", "cubic-ro-peak-v-t"),
    ("peak-acceleration", "cubic-ro-peak-a"),
    ("peak-acceleration-t", "cubic-ro-peak-a-t"),
    ("a0", "cubic-ro-a0"),
    ("a1", "cubic-ro-a1"),
    ("a2", "cubic-ro-a2"),
    ("a3", "cubic-ro-a3"),
    ("rows", "cubic-ro-rows"),
    ("cursor-t", "cubic-ro-cursor-t"),
    ("cursor-q", "cubic-ro-cursor-q"),
    ("cursor-qd", "cubic-ro-cursor-qd"),
    ("cursor-qdd", "cubic-ro-cursor-qdd"),
];

/// The mounted page.
pub struct CubicPage(Rc<Inner>);

struct Inner {
    root: Element,
    controls: RecipeControls<CubicParams>,
    plots: RefCell<plots::Plots>,
    readouts: Readouts,
    path: RefCell<(CubicParams, CubicPath)>,
    overlays: Cell<[bool; 2]>,
    url: RefCell<Option<UrlWriter>>,
    scope: RefCell<Scope>,
}

fn markup() -> String {
    let (form, notice, exports) = recipe_controls::markup(P, &INFO, PNG, "signals-png");
    let overlays: String = OVERLAYS
        .iter()
        .map(|o| format!("<label class=\"sig-check\"><input type=\"checkbox\" data-overlay=\"{o}\"><span data-i18n=\"cubic-overlay-{o}\"></span></label>"))
        .collect();
    let explain: String = ["what", "input", "steps", "expected"]
        .iter()
        .map(|k| format!("<h3 data-i18n=\"cubic-explain-{k}-title\"></h3><p data-i18n=\"cubic-explain-{k}\"></p>"))
        .collect();
    format!(
        "<div class=\"sig\"><header class=\"sig-head\"><h1 data-i18n=\"cubic-title\"></h1>\
         <p class=\"sig-lede\" data-i18n=\"recipe-cubic-path-blurb\"></p>{notice}</header>\
         <div class=\"sig-top\"><section class=\"sig-card\"><h2 data-i18n=\"cubic-plots-title\"></h2>\
         <div class=\"sig-stage\" data-{P}=\"stage\"><canvas class=\"sig-layer\" aria-hidden=\"true\"></canvas>\
         <canvas class=\"sig-layer\" aria-hidden=\"true\"></canvas><canvas class=\"sig-layer\" aria-hidden=\"true\"></canvas>\
         <canvas class=\"sig-layer\" \
         data-testid=\"cubic-path-canvas\" role=\"img\" tabindex=\"0\" data-i18n-attr=\"aria-label=cubic-canvas-label\"></canvas></div>\
         <div class=\"sig-checks\">{overlays}</div><p class=\"sig-note\" data-i18n=\"cubic-drag-hint\"></p></section>\
         <div class=\"sig-side\"><section class=\"sig-card\"><h2 data-i18n=\"signals-readouts-title\"></h2>{ro}{live}</section>\
         <section class=\"sig-card\"><h2 data-i18n=\"signals-params-title\"></h2>{form}</section></div></div>\
         <section class=\"sig-card\"><h2 data-i18n=\"signals-exports-title\"></h2>{exports}</section>\
         <section class=\"sig-card sig-explain\"><h2 data-i18n=\"signals-explain-title\"></h2>{explain}\
         <h3 data-i18n=\"signals-quirks-title\"></h3><p data-i18n=\"recipe-cubic-path-quirks\"></p></section></div>",
        ro = readouts::markup(P, &READOUTS),
        live = readouts::live_markup(P),
    )
}

impl Page for CubicPage {
    fn mount(ctx: MountCtx) -> Result<CubicPage, JsValue> {
        let root = ctx.root.clone();
        root.set_inner_html(&markup());
        dom::relocalize(&root)?;
        let controls = RecipeControls::mount(
            &root,
            P,
            &INFO,
            &SLIDERS,
            &ctx.query,
            &OVERLAYS,
            params_from_args,
        )?;
        let params = controls.value();
        let path = compute(&params).map_err(|e| JsValue::from_str(&e.to_string()))?;
        let overlays = OVERLAYS.map(|o| ctx.get(o) == Some("1"));
        for (o, on) in OVERLAYS.iter().zip(overlays) {
            dom::find::<HtmlInputElement>(&root, &format!("[data-overlay=\"{o}\"]"), P)?
                .set_checked(on);
        }
        let stage: Element = dom::find(&root, &format!("[data-{P}=\"stage\"]"), P)?;
        let (plots, readouts) = (plots::Plots::new(&stage)?, Readouts::find(&root)?);
        let inner = Rc::new_cyclic(|me: &Weak<Inner>| {
            let mut scope = Scope::new();
            let url = UrlWriter::new(&mut scope, me, Inner::query);
            Inner {
                plots: RefCell::new(plots),
                readouts,
                root,
                controls,
                path: RefCell::new((params, path)),
                overlays: Cell::new(overlays),
                url: RefCell::new(Some(url)),
                scope: RefCell::new(scope),
            }
        });
        inner.install(&Rc::downgrade(&inner), &stage)?;
        inner.redraw(true, true);
        Ok(CubicPage(inner))
    }

    fn relocalize(&self) {
        self.0.controls.relocalize();
        self.0.redraw(true, true);
    }

    fn set_projector(&self, _on: bool) {
        self.0.redraw(true, true);
    }

    fn shortcuts(&self) -> Vec<Shortcut> {
        vec![
            Shortcut {
                keys: "↑ ↓",
                message_id: "cubic-key-q1",
            },
            Shortcut {
                keys: "← →",
                message_id: "cubic-key-t",
            },
            Shortcut {
                keys: "r",
                message_id: "signals-key-reset",
            },
        ]
    }

    fn on_key(&self, event: &KeyboardEvent) -> bool {
        let p = self.0.path.borrow().0;
        let k = if event.shift_key() { 10.0 } else { 1.0 };
        let value = match event.key().as_str() {
            "ArrowUp" => ("q1", snap(p.q1 + 0.01 * k, 0.01)),
            "ArrowDown" => ("q1", snap(p.q1 - 0.01 * k, 0.01)),
            "ArrowRight" => ("T", snap(p.duration_s + 0.01 * k, 0.01)),
            "ArrowLeft" => ("T", snap((p.duration_s - 0.01 * k).max(0.01), 0.01)),
            "r" | "R" => {
                if let Some(p) = self.0.controls.reset() {
                    self.0.changed(p);
                }
                return true;
            }
            _ => return false,
        };
        if let Some(p) = self.0.controls.set_text(value.0, &value.1, false) {
            self.0.changed(p);
        }
        true
    }
}

impl Inner {
    fn query(&self) -> Vec<(String, String)> {
        let mut pairs = self.controls.url_pairs();
        for (o, on) in OVERLAYS.iter().zip(self.overlays.get()) {
            if on {
                pairs.push((o.to_string(), "1".into()));
            }
        }
        pairs
    }

    fn install(&self, me: &Weak<Inner>, stage: &Element) -> Result<(), JsValue> {
        let mut scope = self.scope.borrow_mut();
        self.controls.attach(
            &mut scope,
            me,
            |p| &p.controls,
            Inner::changed,
            |p| p.plots.borrow().png(PNG),
        )?;
        for (k, o) in OVERLAYS.iter().enumerate() {
            let input: Element = dom::find(&self.root, &format!("[data-overlay=\"{o}\"]"), P)?;
            scope.listen_for(&input, "change", me, move |p, e| {
                let on = e
                    .target()
                    .and_then(|t| t.dyn_into::<HtmlInputElement>().ok())
                    .is_some_and(|i| i.checked());
                let mut all = p.overlays.get();
                all[k] = on;
                p.overlays.set(all);
                p.redraw(true, false);
                p.write_url();
            })?;
        }
        scope.observe_resize(&[stage], me, |p| p.redraw(true, true))?;
        drop(scope);
        self.plots.borrow_mut().attach(me, stage)
    }

    fn write_url(&self) {
        if let Some(url) = self.url.borrow().as_ref() {
            url.schedule();
        }
    }

    /// New valid arguments: recompute and redraw now (within the input's frame).
    fn changed(&self, params: CubicParams) {
        let Ok(path) = compute(&params) else {
            return;
        };
        let peak = numbers(&params, &path)
            .peak_velocity
            .map_or(0.0, |p| p.value);
        *self.path.borrow_mut() = (params, path);
        let dragging = self.plots.borrow().dragging();
        self.redraw(!dragging, false);
        self.readouts.announce(&ctx::t_strings(
            "cubic-live",
            &[
                ("q1", py_float(params.q1)),
                ("T", py_float(params.duration_s)),
                ("peak", sig(peak, 4)),
            ],
        ));
        self.write_url();
    }

    /// Readouts and plots; `refit` rescales the axes to the data (not while dragging),
    /// `resized` refits the canvases (size, language, mode).
    fn redraw(&self, refit: bool, resized: bool) {
        let t0 = now_ms();
        let (params, path) = &*self.path.borrow();
        let r = numbers(params, path);
        let ro = &self.readouts;
        let show = |key: &str, x: f64| ro.set_with_value(key, &sig(x, 4), &py_float(x));
        if let Some(v) = r.peak_velocity {
            show("peak-velocity", v.value);
            show("peak-velocity-t", v.t);
        }
        if let Some(a) = r.peak_acceleration {
            show("peak-acceleration", a.value);
            show("peak-acceleration-t", a.t);
        }
        show("a0", r.coefficients.a0);
        show("a1", r.coefficients.a1);
        show("a2", r.coefficients.a2);
        show("a3", r.coefficients.a3);
        ro.set_with_value("rows", &r.rows.to_string(), &r.rows.to_string());
        let cursor = {
            let mut plots = self.plots.borrow_mut();
            plots.show(params, path, self.overlays.get(), refit, resized);
            plots.cursor_sample(path)
        };
        if let Some(s) = cursor {
            show("cursor-t", s.t);
            show("cursor-q", s.q);
            show("cursor-qd", s.qd);
            show("cursor-qdd", s.qdd);
        }
        record_frame_ms(now_ms() - t0);
    }
}
