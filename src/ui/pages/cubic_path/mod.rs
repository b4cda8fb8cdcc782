//! The cubic path (`#/cubic-path`): position, velocity and acceleration of the recipe's cubic
//! on three panels sharing the time axis, recomputed while a value is dragged (a slider, a
//! field, or the end point q1 at T on the position plot); a cursor readout at the hovered time;
//! the quintic and the same-time trapezoid as optional overlays (not exported: the CSV stays
//! the recipe's, byte for byte what `bsv cubic-path` writes).
//!
//! Components: `plots` (the kit's signal plot with the end-point drag and the cursor) in the
//! kit's signal-page shell ([`crate::ui::kit::signal_page`]: markup, controls, readouts, URL);
//! the numbers come from the pure `crate::view::cubic_path`.

mod plots;

use std::cell::{Cell, RefCell};
use std::rc::Weak;

use wasm_bindgen::prelude::*;
use web_sys::{Element, HtmlInputElement, KeyboardEvent};

use crate::pyfmt::py_float;
use crate::recipes::cubic_path::{
    params_from_args, samples, CubicParams, CubicPath, CubicSample, INFO,
};
use crate::ui::ctx;
use crate::ui::kit::recipe_controls::{Parse, RecipeControls};
use crate::ui::kit::signal_page::{change, Fit, RunFrom, Shell, SignalPage, SignalSpec};
use crate::ui::page::{MountCtx, Shortcut};
use crate::view::cubic_path::{readouts as numbers, Peak};
use crate::view::signal::{sig, snap, Slider};

const P: &str = "cubic";
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

/// The page's keys.
const KEYS: [Shortcut; 3] = [
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
];

/// The page's state: the path shown and which overlays are on.
pub struct CubicPage {
    shell: Shell<CubicParams>,
    plots: RefCell<plots::Plots>,
    path: RefCell<(CubicParams, CubicPath)>,
    overlays: Cell<[bool; 2]>,
}

/// What the page builds before it exists.
pub struct Parts {
    plots: plots::Plots,
    path: (CubicParams, CubicPath),
    overlays: [bool; 2],
}

impl SignalPage for CubicPage {
    type Params = CubicParams;
    type Row = CubicSample;
    type Parts = Parts;
    const SPEC: SignalSpec = SignalSpec {
        prefix: P,
        info: &INFO,
        png: "cubic_path_plots.png",
        layers: 4,
        sliders: &SLIDERS,
        readouts: &READOUTS,
        explain: &["what", "input", "steps", "expected"],
        keys: &KEYS,
        own_keys: &OVERLAYS,
    };
    const PARSE: Parse<CubicParams> = params_from_args;

    fn stage_markup() -> String {
        let overlays: String = OVERLAYS
            .iter()
            .map(|o| format!("<label class=\"sig-check\"><input type=\"checkbox\" data-overlay=\"{o}\"><span data-i18n=\"cubic-overlay-{o}\"></span></label>"))
            .collect();
        format!(
            "<div class=\"sig-checks\">{overlays}</div><p class=\"sig-note\" data-i18n=\"cubic-drag-hint\"></p>"
        )
    }

    fn prepare(
        ctx: &MountCtx,
        root: &Element,
        controls: &RecipeControls<CubicParams>,
        stage: &Element,
        rows: Vec<CubicSample>,
    ) -> Result<Parts, JsValue> {
        let params = controls.value();
        let path = path_of(&params, rows);
        let overlays = OVERLAYS.map(|o| ctx.get(o) == Some("1"));
        for (o, on) in OVERLAYS.iter().zip(overlays) {
            crate::ui::dom::find::<HtmlInputElement>(root, &format!("[data-overlay=\"{o}\"]"), P)?
                .set_checked(on);
        }
        Ok(Parts {
            plots: plots::Plots::new(stage)?,
            path: (params, path),
            overlays,
        })
    }

    fn new(shell: Shell<CubicParams>, parts: Parts) -> CubicPage {
        CubicPage {
            shell,
            plots: RefCell::new(parts.plots),
            path: RefCell::new(parts.path),
            overlays: Cell::new(parts.overlays),
        }
    }

    fn shell(&self) -> &Shell<CubicParams> {
        &self.shell
    }

    fn install(&self, me: &Weak<CubicPage>) -> Result<(), JsValue> {
        for (k, o) in OVERLAYS.iter().enumerate() {
            let input: Element =
                crate::ui::dom::find(&self.shell.root, &format!("[data-overlay=\"{o}\"]"), P)?;
            self.shell.with_scope(|scope| {
                scope.listen_for(&input, "change", me, move |p: &CubicPage, e| {
                    let on = e
                        .target()
                        .and_then(|t| t.dyn_into::<HtmlInputElement>().ok())
                        .is_some_and(|i| i.checked());
                    let mut all = p.overlays.get();
                    all[k] = on;
                    p.overlays.set(all);
                    p.redraw(Fit::Refit, false);
                    p.shell.url.schedule();
                })
            })?;
        }
        self.plots.borrow_mut().attach(me, &self.shell.stage)
    }

    fn query(&self) -> Vec<(String, String)> {
        let mut pairs = self.shell.controls.url_pairs();
        for (o, on) in OVERLAYS.iter().zip(self.overlays.get()) {
            if on {
                pairs.push((o.to_string(), "1".into()));
            }
        }
        pairs
    }

    fn kernel(p: &CubicParams) -> Option<(Box<dyn Iterator<Item = CubicSample>>, u64)> {
        let rows = samples(p).ok()?;
        let n = rows.len() as u64;
        Some((Box::new(rows), n))
    }

    fn show_run(&self, params: CubicParams, rows: Vec<CubicSample>, from: RunFrom) {
        *self.path.borrow_mut() = (params, path_of(&params, rows));
        let dragging = self.plots.borrow().dragging();
        let fit = Fit::for_change(dragging, &self.shell.controls);
        let peak = self.redraw(fit, false).map_or(0.0, |p| p.value);
        if from == RunFrom::Mount {
            return;
        }
        self.shell.readouts.announce(&ctx::t_strings(
            "cubic-live",
            &[
                ("q1", py_float(params.q1)),
                ("T", py_float(params.duration_s)),
                ("peak", sig(peak, 4)),
            ],
        ));
    }

    fn redraw_all(&self) {
        self.redraw(Fit::Refit, true);
    }

    fn slider_released(&self) {
        self.redraw(Fit::Refit, false);
    }

    fn png(&self) {
        self.plots.borrow().png(CubicPage::SPEC.png);
    }

    fn on_key(&self, event: &KeyboardEvent) -> bool {
        let p = self.path.borrow().0;
        let k = if event.shift_key() { 10.0 } else { 1.0 };
        let controls = &self.shell.controls;
        let next = match event.key().as_str() {
            "ArrowUp" => controls.set_text("q1", &snap(p.q1 + 0.01 * k, 0.01), false),
            "ArrowDown" => controls.set_text("q1", &snap(p.q1 - 0.01 * k, 0.01), false),
            "ArrowRight" => controls.set_text("T", &snap(p.duration_s + 0.01 * k, 0.01), false),
            "ArrowLeft" => {
                controls.set_text("T", &snap((p.duration_s - 0.01 * k).max(0.01), 0.01), false)
            }
            "r" | "R" => controls.reset(),
            _ => return false,
        };
        if let Some(p) = next {
            change(self, p);
        }
        true
    }
}

impl CubicPage {
    /// Readouts and plots; `fit` says what the axes do (kept while a handle is dragged, held
    /// while a slider moves), `resized` refits the canvases (size, language, mode). The peak
    /// velocity.
    fn redraw(&self, fit: Fit, resized: bool) -> Option<Peak> {
        let (params, path) = &*self.path.borrow();
        let r = numbers(params, path);
        if let Some(v) = r.peak_velocity {
            self.shell
                .show_numbers(&[("peak-velocity", v.value), ("peak-velocity-t", v.t)]);
        }
        if let Some(a) = r.peak_acceleration {
            self.shell
                .show_numbers(&[("peak-acceleration", a.value), ("peak-acceleration-t", a.t)]);
        }
        let c = r.coefficients;
        self.shell
            .show_numbers(&[("a0", c.a0), ("a1", c.a1), ("a2", c.a2), ("a3", c.a3)]);
        let rows = r.rows.to_string();
        self.shell.readouts.set_with_value("rows", &rows, &rows);
        let sample = self
            .plots
            .borrow_mut()
            .show(params, path, self.overlays.get(), fit, resized);
        self.show_cursor_readouts(sample);
        r.peak_velocity
    }

    /// The cursor on the plots and its readouts: the CSV row at the hovered time.
    fn show_cursor(&self) {
        let sample = self.plots.borrow_mut().cursor(&self.path.borrow().1);
        self.show_cursor_readouts(sample);
    }

    fn show_cursor_readouts(&self, sample: Option<CubicSample>) {
        if let Some(s) = sample {
            self.shell.show_numbers(&[
                ("cursor-t", s.t),
                ("cursor-q", s.q),
                ("cursor-qd", s.qd),
                ("cursor-qdd", s.qdd),
            ]);
        }
    }
}

/// The recipe's path of `p` from its samples.
fn path_of(p: &CubicParams, samples: Vec<CubicSample>) -> CubicPath {
    CubicPath {
        q0: p.q0,
        q1: p.q1,
        duration_s: p.duration_s,
        samples,
    }
}
