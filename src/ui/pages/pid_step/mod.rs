//! The PID step response (`#/pid-step`): y, r and u over the steps, live while Kp, Ki, Kd, tau
//! and steps are dragged (sliders beside their fields); rise time, overshoot, settling time,
//! steady-state error and peak u from the exact samples (`crate::view::pid_step`); a ghost of
//! the previous gains stays drawn until the next change, so a class compares tunings; the
//! recipe's warning when the loop diverges. The CSV is the recipe's (`bsv pid-step`).
//!
//! Components: `plots` (the kit plot: y and r above, u below, and the ghost), the kit's
//! [`RecipeControls`] (form + sliders + URL + exports) and readouts.

mod plots;

use std::cell::{Cell, RefCell};
use std::rc::{Rc, Weak};

use wasm_bindgen::prelude::*;
use web_sys::{Element, KeyboardEvent};

use crate::pyfmt::{py_float, py_round};
use crate::recipes::pid_step::{params_from_args, warnings, PidParams, PidSample, INFO};
use crate::ui::kit::readouts::{self, Readouts};
use crate::ui::kit::recipe_controls::{self, record_frame_ms, RecipeControls};
use crate::ui::kit::scope::Scope;
use crate::ui::kit::url_state::UrlWriter;
use crate::ui::page::{MountCtx, Page, PageDef, Shortcut};
use crate::ui::schedule::now_ms;
use crate::ui::{ctx, dom};
use crate::view::form::fluent_args;
use crate::view::pid_step::{figures, response, StepFigures};
use crate::view::signal::{sig, snap, Slider};

/// The page, as the shell's page table lists it.
pub const PAGE: PageDef = PageDef::of::<PidPage>("pid-step", "pid-title", "pid-blurb");

const P: &str = "pid";
const PNG: &str = "pid_step_plots.png";
const SLIDERS: [Slider; 5] = [
    Slider {
        name: "Kp",
        min: 0.0,
        max: 10.0,
        step: 0.05,
    },
    Slider {
        name: "Ki",
        min: 0.0,
        max: 5.0,
        step: 0.05,
    },
    Slider {
        name: "Kd",
        min: 0.0,
        max: 1.0,
        step: 0.01,
    },
    Slider {
        name: "tau",
        min: 0.0,
        max: 5.0,
        step: 0.05,
    },
    Slider {
        name: "steps",
        min: 0.0,
        max: 1000.0,
        step: 10.0,
    },
];
/// `(data-readout, label id)`.
const READOUTS: [(&str, &str); 11] = [
    ("rise-time", "pid-ro-rise"),
    ("overshoot", "pid-ro-overshoot"),
    ("settling-time", "pid-ro-settling"),
    ("steady-state-error", "pid-ro-sse"),
    ("peak-u", "pid-ro-peak-u"),
    ("peak-u-t", "pid-ro-peak-u-t"),
    ("final-y", "pid-ro-final-y"),
    ("cursor-t", "pid-ro-cursor-t"),
    ("cursor-r", "pid-ro-cursor-r"),
    ("cursor-y", "pid-ro-cursor-y"),
    ("cursor-u", "pid-ro-cursor-u"),
];

/// The mounted page.
pub struct PidPage(Rc<Inner>);

/// The run shown (and its figures), the run the ghost is drawn from (a new ghost, a new
/// generation), and the last committed run.
struct Runs {
    now: Vec<PidSample>,
    figures: StepFigures,
    committed: Vec<PidSample>,
    ghost: Option<Vec<PidSample>>,
    ghost_generation: u64,
}

struct Inner {
    root: Element,
    controls: RecipeControls<PidParams>,
    plots: RefCell<plots::Plots>,
    readouts: Readouts,
    warning: Element,
    runs: RefCell<Runs>,
    changing: Cell<bool>,
    url: RefCell<Option<UrlWriter>>,
    scope: RefCell<Scope>,
}

fn markup() -> String {
    let (form, notice, exports) = recipe_controls::markup(P, &INFO, PNG, "signals-png");
    let explain: String = [
        "gains", "plant", "toy", "real", "input", "steps", "expected",
    ]
    .iter()
    .map(|k| {
        format!(
            "<h3 data-i18n=\"pid-explain-{k}-title\"></h3><p data-i18n=\"pid-explain-{k}\"></p>"
        )
    })
    .collect();
    format!(
        "<div class=\"sig\"><header class=\"sig-head\"><h1 data-i18n=\"pid-title\"></h1>\
         <p class=\"sig-lede\" data-i18n=\"recipe-pid-step-blurb\"></p>{notice}</header>\
         <div class=\"sig-top\"><section class=\"sig-card\"><h2 data-i18n=\"pid-plots-title\"></h2>\
         <div class=\"sig-stage\" data-{P}=\"stage\"><canvas class=\"sig-layer\" aria-hidden=\"true\"></canvas>\
         <canvas class=\"sig-layer\" aria-hidden=\"true\"></canvas><canvas class=\"sig-layer\" \
         data-testid=\"pid-step-canvas\" role=\"img\" tabindex=\"0\" data-i18n-attr=\"aria-label=pid-canvas-label\"></canvas></div>\
         <p class=\"sig-warning\" data-{P}=\"warning\" data-testid=\"pid-step-warning\" role=\"alert\" hidden></p>\
         <p class=\"sig-note\" data-i18n=\"pid-ghost-note\"></p></section>\
         <div class=\"sig-side\"><section class=\"sig-card\"><h2 data-i18n=\"signals-readouts-title\"></h2>{ro}{live}\
         <p class=\"sig-note\" data-i18n=\"pid-ro-note\"></p></section>\
         <section class=\"sig-card\"><h2 data-i18n=\"signals-params-title\"></h2>{form}</section></div></div>\
         <section class=\"sig-card\"><h2 data-i18n=\"signals-exports-title\"></h2>{exports}</section>\
         <section class=\"sig-card sig-explain\"><h2 data-i18n=\"signals-explain-title\"></h2>{explain}\
         <h3 data-i18n=\"signals-quirks-title\"></h3><p data-i18n=\"recipe-pid-step-quirks\"></p></section></div>",
        ro = readouts::markup(P, &READOUTS),
        live = readouts::live_markup(P),
    )
}

impl Page for PidPage {
    fn mount(ctx: MountCtx) -> Result<PidPage, JsValue> {
        let root = ctx.root.clone();
        root.set_inner_html(&markup());
        dom::relocalize(&root)?;
        let controls =
            RecipeControls::mount(&root, P, &INFO, &SLIDERS, &ctx.query, &[], params_from_args)?;
        let rows = response(&controls.value());
        let stage: Element = dom::find(&root, &format!("[data-{P}=\"stage\"]"), P)?;
        let (plots, readouts) = (plots::Plots::new(&stage)?, Readouts::find(&root)?);
        let warning = dom::find(&root, &format!("[data-{P}=\"warning\"]"), P)?;
        let inner = Rc::new_cyclic(|me: &Weak<Inner>| {
            let mut scope = Scope::new();
            let url = UrlWriter::new(&mut scope, me, |p: &Inner| p.controls.url_pairs());
            Inner {
                root,
                controls,
                plots: RefCell::new(plots),
                readouts,
                warning,
                runs: RefCell::new(Runs {
                    committed: rows.clone(),
                    figures: figures(&rows),
                    now: rows,
                    ghost: None,
                    ghost_generation: 0,
                }),
                changing: Cell::new(false),
                url: RefCell::new(Some(url)),
                scope: RefCell::new(scope),
            }
        });
        inner.install(&Rc::downgrade(&inner), &stage)?;
        inner
            .plots
            .borrow_mut()
            .attach(&Rc::downgrade(&inner), &stage)?;
        inner.redraw(true);
        Ok(PidPage(inner))
    }

    fn relocalize(&self) {
        self.0.controls.relocalize();
        self.0.redraw(true);
    }

    fn set_projector(&self, _on: bool) {
        self.0.redraw(true);
    }

    fn shortcuts(&self) -> Vec<Shortcut> {
        vec![
            Shortcut {
                keys: "↑ ↓",
                message_id: "pid-key-kp",
            },
            Shortcut {
                keys: "r",
                message_id: "signals-key-reset",
            },
        ]
    }

    fn on_key(&self, event: &KeyboardEvent) -> bool {
        let kp = self.0.controls.value().kp;
        let k = if event.shift_key() { 10.0 } else { 1.0 };
        let next = match event.key().as_str() {
            "ArrowUp" => self
                .0
                .controls
                .set_text("Kp", &snap(kp + 0.05 * k, 0.05), false),
            "ArrowDown" => self
                .0
                .controls
                .set_text("Kp", &snap(kp - 0.05 * k, 0.05), false),
            "r" | "R" => self.0.controls.reset(),
            _ => return false,
        };
        if let Some(p) = next {
            self.0.changed(p);
        }
        self.0.commit();
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
        let form: Element = dom::find(&self.root, &format!("[data-{P}=\"form\"]"), P)?;
        scope.listen_for(&form, "change", me, |p, _| p.commit())?;
        scope.observe_resize(&[stage], me, |p| p.redraw(true))?;
        Ok(())
    }

    /// New valid arguments: the first change after a committed one turns the committed run
    /// into the ghost; then recompute and redraw now.
    fn changed(&self, params: PidParams) {
        let rows = response(&params);
        {
            let mut runs = self.runs.borrow_mut();
            if !self.changing.replace(true) {
                // The committed run becomes the ghost: no copy, the next commit replaces it.
                runs.ghost = Some(std::mem::take(&mut runs.committed));
                runs.ghost_generation += 1;
            }
            runs.figures = figures(&rows);
            runs.now = rows;
        }
        self.redraw(false);
        let f = self.runs.borrow().figures;
        // The unit belongs to a number only: "not reached" stands alone.
        let or_none = |x: Option<f64>, unit_id: &str| {
            x.map_or_else(
                || ctx::t("pid-ro-none"),
                |x| ctx::t_strings(unit_id, &[("value", sig(x, 3))]),
            )
        };
        self.readouts.announce(&ctx::t_strings(
            "pid-live",
            &[
                ("rise", or_none(f.rise_time, "pid-live-seconds")),
                ("overshoot", or_none(f.overshoot_pct, "pid-live-percent")),
                ("settling", or_none(f.settling_time, "pid-live-seconds")),
            ],
        ));
        if let Some(url) = self.url.borrow().as_ref() {
            url.schedule();
        }
    }

    /// A change ended (a slider let go, a field left, a key): the run shown is the one the
    /// next change leaves as the ghost.
    fn commit(&self) {
        if self.changing.replace(false) {
            let mut runs = self.runs.borrow_mut();
            runs.committed = runs.now.clone();
        }
    }

    /// Readouts, warning and plots.
    fn redraw(&self, resized: bool) {
        let t0 = now_ms();
        let runs = self.runs.borrow();
        let f = runs.figures;
        let ro = &self.readouts;
        let show = |key: &str, x: Option<f64>, digits: usize| match x {
            Some(x) => ro.set_with_value(key, &sig(x, digits), &py_float(x)),
            None => ro.set_with_value(key, &ctx::t("pid-ro-none"), ""),
        };
        show("rise-time", f.rise_time, 4);
        show("overshoot", f.overshoot_pct, 3);
        show("settling-time", f.settling_time, 4);
        show("steady-state-error", f.steady_state_error, 4);
        show("peak-u", f.peak_u.map(|p| p.1), 4);
        show("peak-u-t", f.peak_u.map(|p| p.0), 4);
        show("final-y", f.final_y, 4);
        let text: Vec<String> = warnings(&runs.now)
            .iter()
            .map(|w| ctx::t_args(w.message_id(), &fluent_args(w.message_args())))
            .collect();
        self.warning.set_text_content(Some(&text.join(" ")));
        dom::show(&self.warning, !text.is_empty());
        self.plots.borrow_mut().show(
            &runs.now,
            runs.ghost.as_deref().map(|g| (runs.ghost_generation, g)),
            resized,
        );
        drop(runs);
        self.show_cursor();
        record_frame_ms(now_ms() - t0);
    }

    /// The cursor on the plots and its readouts: the CSV row at the hovered time.
    fn show_cursor(&self) {
        let sample = self.plots.borrow_mut().cursor(&self.runs.borrow().now);
        let Some(s) = sample else {
            return;
        };
        let show = |key: &str, x: f64| self.readouts.set_with_value(key, &sig(x, 4), &py_float(x));
        show("cursor-t", py_round(s.t, 4));
        show("cursor-r", s.r);
        show("cursor-y", s.y);
        show("cursor-u", s.u);
    }
}
