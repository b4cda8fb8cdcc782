//! The trapezoidal profile (`#/trapezoid-profile`): position, velocity and acceleration over
//! time on three panels sharing the time axis, the accelerate / cruise / brake phases shaded
//! and labelled; says when the move is a triangle (too short to reach vmax) and shows t_acc,
//! t_flat, t_total and the peak velocity reached. vmax and amax are dragged on the velocity
//! plot (or with the sliders); the CSV is the recipe's (`bsv trapezoid-profile`).
//!
//! Components: `plots` (the kit plot, phase bands, the two drag handles), the kit's
//! [`RecipeControls`] and readouts; the numbers come from `crate::view::trapezoid_profile`.

mod plots;

use std::cell::RefCell;
use std::rc::{Rc, Weak};

use wasm_bindgen::prelude::*;
use web_sys::{Element, KeyboardEvent};

use crate::pyfmt::py_float;
use crate::recipes::trapezoid_profile::{params_from_args, TrapParams, TrapSample, INFO};
use crate::ui::kit::readouts::{self, Readouts};
use crate::ui::kit::recipe_controls::{self, record_frame_ms, RecipeControls};
use crate::ui::kit::scope::Scope;
use crate::ui::kit::url_state::UrlWriter;
use crate::ui::page::{MountCtx, Page, PageDef, Shortcut};
use crate::ui::schedule::now_ms;
use crate::ui::{ctx, dom};
use crate::view::signal::{sig, snap, Slider};
use crate::view::trapezoid_profile::{phases, samples};

/// The page, as the shell's page table lists it.
pub const PAGE: PageDef = PageDef::of::<TrapPage>("trapezoid-profile", "trap-title", "trap-blurb");

const P: &str = "trap";
const PNG: &str = "trap_profile_plots.png";
const SLIDERS: [Slider; 4] = [
    Slider {
        name: "distance",
        min: 0.0,
        max: 5.0,
        step: 0.05,
    },
    Slider {
        name: "vmax",
        min: 0.05,
        max: 3.0,
        step: 0.01,
    },
    Slider {
        name: "amax",
        min: 0.05,
        max: 5.0,
        step: 0.01,
    },
    Slider {
        name: "dt",
        min: 0.001,
        max: 0.1,
        step: 0.001,
    },
];
/// `(data-readout, label id)`.
const READOUTS: [(&str, &str); 11] = [
    ("shape", "trap-ro-shape"),
    ("t-acc", "trap-ro-t-acc"),
    ("t-flat", "trap-ro-t-flat"),
    ("t-total", "trap-ro-t-total"),
    ("v-peak", "trap-ro-v-peak"),
    ("final-s", "trap-ro-final-s"),
    ("rows", "trap-ro-rows"),
    ("cursor-t", "trap-ro-cursor-t"),
    ("cursor-s", "trap-ro-cursor-s"),
    ("cursor-v", "trap-ro-cursor-v"),
    ("cursor-a", "trap-ro-cursor-a"),
];

/// The mounted page.
pub struct TrapPage(Rc<Inner>);

struct Inner {
    controls: RecipeControls<TrapParams>,
    plots: RefCell<plots::Plots>,
    readouts: Readouts,
    triangle_note: Element,
    /// The parameters and the kernel's samples (`view::trapezoid_profile::samples`).
    profile: RefCell<(TrapParams, Vec<TrapSample>)>,
    url: RefCell<Option<UrlWriter>>,
    scope: RefCell<Scope>,
}

fn markup() -> String {
    let (form, notice, exports) = recipe_controls::markup(P, &INFO, PNG, "signals-png");
    let explain: String = ["what", "input", "steps", "expected"]
        .iter()
        .map(|k| format!("<h3 data-i18n=\"trap-explain-{k}-title\"></h3><p data-i18n=\"trap-explain-{k}\"></p>"))
        .collect();
    format!(
        "<div class=\"sig\"><header class=\"sig-head\"><h1 data-i18n=\"trap-title\"></h1>\
         <p class=\"sig-lede\" data-i18n=\"recipe-trapezoid-profile-blurb\"></p>{notice}</header>\
         <div class=\"sig-top\"><section class=\"sig-card\"><h2 data-i18n=\"trap-plots-title\"></h2>\
         <div class=\"sig-stage\" data-{P}=\"stage\"><canvas class=\"sig-layer\" aria-hidden=\"true\"></canvas>\
         <canvas class=\"sig-layer\" aria-hidden=\"true\"></canvas><canvas class=\"sig-layer\" aria-hidden=\"true\"></canvas>\
         <canvas class=\"sig-layer\" data-testid=\"trapezoid-profile-canvas\" role=\"img\" tabindex=\"0\" \
         data-i18n-attr=\"aria-label=trap-canvas-label\"></canvas></div>\
         <p class=\"sig-warning\" data-{P}=\"triangle\" data-testid=\"trapezoid-profile-triangle\" role=\"status\" \
         data-i18n=\"trap-triangle\" hidden></p><p class=\"sig-note\" data-i18n=\"trap-drag-hint\"></p></section>\
         <div class=\"sig-side\"><section class=\"sig-card\"><h2 data-i18n=\"signals-readouts-title\"></h2>{ro}{live}</section>\
         <section class=\"sig-card\"><h2 data-i18n=\"signals-params-title\"></h2>{form}</section></div></div>\
         <section class=\"sig-card\"><h2 data-i18n=\"signals-exports-title\"></h2>{exports}</section>\
         <section class=\"sig-card sig-explain\"><h2 data-i18n=\"signals-explain-title\"></h2>{explain}\
         <h3 data-i18n=\"signals-quirks-title\"></h3><p data-i18n=\"recipe-trapezoid-profile-quirks\"></p></section></div>",
        ro = readouts::markup(P, &READOUTS),
        live = readouts::live_markup(P),
    )
}

impl Page for TrapPage {
    fn mount(ctx: MountCtx) -> Result<TrapPage, JsValue> {
        let root = ctx.root.clone();
        root.set_inner_html(&markup());
        dom::relocalize(&root)?;
        let controls =
            RecipeControls::mount(&root, P, &INFO, &SLIDERS, &ctx.query, &[], params_from_args)?;
        let params = controls.value();
        let profile = samples(&params);
        let stage: Element = dom::find(&root, &format!("[data-{P}=\"stage\"]"), P)?;
        let (plots, readouts) = (plots::Plots::new(&stage)?, Readouts::find(&root)?);
        let triangle_note = dom::find(&root, &format!("[data-{P}=\"triangle\"]"), P)?;
        let inner = Rc::new_cyclic(|me: &Weak<Inner>| {
            let mut scope = Scope::new();
            let url = UrlWriter::new(&mut scope, me, |p: &Inner| p.controls.url_pairs());
            Inner {
                controls,
                plots: RefCell::new(plots),
                readouts,
                triangle_note,
                profile: RefCell::new((params, profile)),
                url: RefCell::new(Some(url)),
                scope: RefCell::new(scope),
            }
        });
        inner.install(&Rc::downgrade(&inner), &stage)?;
        inner.redraw(true, true);
        Ok(TrapPage(inner))
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
                message_id: "trap-key-vmax",
            },
            Shortcut {
                keys: "← →",
                message_id: "trap-key-amax",
            },
            Shortcut {
                keys: "r",
                message_id: "signals-key-reset",
            },
        ]
    }

    fn on_key(&self, event: &KeyboardEvent) -> bool {
        let p = self.0.profile.borrow().0;
        let k = if event.shift_key() { 10.0 } else { 1.0 };
        let (vmax, amax) = (p.vmax.abs(), p.amax.abs());
        let next = match event.key().as_str() {
            "ArrowUp" => self
                .0
                .controls
                .set_text("vmax", &snap(vmax + 0.01 * k, 0.01), false),
            "ArrowDown" => {
                self.0
                    .controls
                    .set_text("vmax", &snap((vmax - 0.01 * k).max(0.01), 0.01), false)
            }
            "ArrowRight" => self
                .0
                .controls
                .set_text("amax", &snap(amax + 0.01 * k, 0.01), false),
            "ArrowLeft" => {
                self.0
                    .controls
                    .set_text("amax", &snap((amax - 0.01 * k).max(0.01), 0.01), false)
            }
            "r" | "R" => self.0.controls.reset(),
            _ => return false,
        };
        if let Some(p) = next {
            self.0.changed(p);
        }
        true
    }
}

impl Inner {
    fn install(&self, me: &Weak<Inner>, stage: &Element) -> Result<(), JsValue> {
        let mut scope = self.scope.borrow_mut();
        self.controls.attach(
            &mut scope,
            me,
            |p| &p.controls,
            Inner::changed,
            |p| p.plots.borrow().png(PNG),
        )?;
        scope.observe_resize(&[stage], me, |p| p.redraw(true, true))?;
        drop(scope);
        self.plots.borrow_mut().attach(me, stage)
    }

    /// New valid arguments: recompute and redraw now.
    fn changed(&self, params: TrapParams) {
        let profile = samples(&params);
        *self.profile.borrow_mut() = (params, profile);
        let dragging = self.plots.borrow().dragging();
        self.redraw(!dragging, false);
        let ph = phases(&params);
        let shape = if ph.triangle {
            "trap-shape-triangle"
        } else {
            "trap-shape-trapezoid"
        };
        self.readouts.announce(&ctx::t_strings(
            "trap-live",
            &[
                ("shape", ctx::t(shape)),
                ("total", sig(ph.t_total, 4)),
                ("peak", sig(ph.v_peak, 4)),
            ],
        ));
        if let Some(url) = self.url.borrow().as_ref() {
            url.schedule();
        }
    }

    /// Readouts, the triangle note and the plots; `refit` rescales the axes, `resized` refits
    /// the canvases (size, language, mode).
    fn redraw(&self, refit: bool, resized: bool) {
        let t0 = now_ms();
        let (params, profile) = &*self.profile.borrow();
        let ph = phases(params);
        let ro = &self.readouts;
        let show = |key: &str, x: f64| ro.set_with_value(key, &sig(x, 4), &py_float(x));
        let shape = if ph.triangle {
            "trap-shape-triangle"
        } else {
            "trap-shape-trapezoid"
        };
        ro.set_with_value(
            "shape",
            &ctx::t(shape),
            if ph.triangle { "triangle" } else { "trapezoid" },
        );
        show("t-acc", ph.t_acc);
        show("t-flat", ph.t_flat);
        show("t-total", ph.t_total);
        show("v-peak", ph.v_peak);
        if let Some(last) = profile.last() {
            show("final-s", last.s);
        }
        let rows = profile.len().to_string();
        ro.set_with_value("rows", &rows, &rows);
        dom::show(&self.triangle_note, ph.triangle);
        self.plots
            .borrow_mut()
            .show(params, profile, &ph, refit, resized);
        self.show_cursor();
        record_frame_ms(now_ms() - t0);
    }

    /// The cursor on the plots and its readouts: the CSV row at the hovered time.
    fn show_cursor(&self) {
        let sample = self.plots.borrow_mut().cursor(&self.profile.borrow().1);
        let Some(s) = sample else {
            return;
        };
        let show = |key: &str, x: f64| self.readouts.set_with_value(key, &sig(x, 4), &py_float(x));
        show("cursor-t", s.t);
        show("cursor-s", s.s);
        show("cursor-v", s.v);
        show("cursor-a", s.a);
    }
}
