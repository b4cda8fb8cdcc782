//! The trapezoidal profile (`#/trapezoid-profile`): position, velocity and acceleration over
//! time on three panels sharing the time axis, the accelerate / cruise / brake phases shaded
//! and labelled; says when the move is a triangle (too short to reach vmax) and shows t_acc,
//! t_flat, t_total and the peak velocity reached. vmax and amax are dragged on the velocity
//! plot (or with the sliders); the CSV is the recipe's (`bsv trapezoid-profile`).
//!
//! Components: `plots` (the kit's signal plot, phase bands, the two drag handles) in the kit's
//! signal-page shell ([`crate::ui::kit::signal_page`]: markup, controls, readouts, URL); the
//! numbers come from the kernel's samples and `crate::view::trapezoid_profile`.

mod plots;

use std::cell::RefCell;
use std::rc::Weak;

use wasm_bindgen::prelude::*;
use web_sys::{Element, KeyboardEvent};

use crate::recipes::trapezoid_profile::{params_from_args, TrapParams, TrapSample, INFO};
use crate::ui::kit::recipe_controls::{Parse, RecipeControls};
use crate::ui::kit::signal_page::{change, Fit, RunFrom, Shell, SignalPage, SignalSpec};
use crate::ui::page::{MountCtx, Shortcut};
use crate::ui::{ctx, dom};
use crate::view::signal::{sig, snap, Slider};
use crate::view::trapezoid_profile::{phases, rows, Phases};

const P: &str = "trap";
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

/// The page's keys.
const KEYS: [Shortcut; 3] = [
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
];

/// The page's state: the profile shown.
pub struct TrapPage {
    shell: Shell<TrapParams>,
    plots: RefCell<plots::Plots>,
    triangle_note: Element,
    /// The parameters and the kernel's samples (unrounded t).
    profile: RefCell<(TrapParams, Vec<TrapSample>)>,
}

/// What the page builds before it exists.
pub struct Parts {
    plots: plots::Plots,
    triangle_note: Element,
    profile: (TrapParams, Vec<TrapSample>),
}

fn shape_id(ph: &Phases) -> &'static str {
    if ph.triangle {
        "trap-shape-triangle"
    } else {
        "trap-shape-trapezoid"
    }
}

impl SignalPage for TrapPage {
    type Params = TrapParams;
    type Row = TrapSample;
    type Parts = Parts;
    const SPEC: SignalSpec = SignalSpec {
        prefix: P,
        info: &INFO,
        png: "trap_profile_plots.png",
        layers: 4,
        sliders: &SLIDERS,
        readouts: &READOUTS,
        explain: &["what", "input", "steps", "expected"],
        keys: &KEYS,
        own_keys: &[],
    };
    const PARSE: Parse<TrapParams> = params_from_args;

    fn stage_markup() -> String {
        format!(
            "<p class=\"sig-warning\" data-{P}=\"triangle\" data-testid=\"trapezoid-profile-triangle\" role=\"status\" \
             data-i18n=\"trap-triangle\" hidden></p><p class=\"sig-note\" data-i18n=\"trap-drag-hint\"></p>"
        )
    }

    fn prepare(
        _ctx: &MountCtx,
        root: &Element,
        controls: &RecipeControls<TrapParams>,
        stage: &Element,
        rows: Vec<TrapSample>,
    ) -> Result<Parts, JsValue> {
        let params = controls.value();
        Ok(Parts {
            plots: plots::Plots::new(stage)?,
            triangle_note: dom::find(root, &format!("[data-{P}=\"triangle\"]"), P)?,
            profile: (params, rows),
        })
    }

    fn new(shell: Shell<TrapParams>, parts: Parts) -> TrapPage {
        TrapPage {
            shell,
            plots: RefCell::new(parts.plots),
            triangle_note: parts.triangle_note,
            profile: RefCell::new(parts.profile),
        }
    }

    fn shell(&self) -> &Shell<TrapParams> {
        &self.shell
    }

    fn install(&self, me: &Weak<TrapPage>) -> Result<(), JsValue> {
        self.plots.borrow_mut().attach(me, &self.shell.stage)
    }

    /// The kernel's samples ([`crate::view::trapezoid_profile::rows`]: the CSV's rows, times
    /// unrounded).
    fn kernel(p: &TrapParams) -> Option<(Box<dyn Iterator<Item = TrapSample>>, u64)> {
        let (rows, n) = rows(p)?;
        Some((Box::new(rows), n))
    }

    fn show_run(&self, params: TrapParams, rows: Vec<TrapSample>, from: RunFrom) {
        *self.profile.borrow_mut() = (params, rows);
        let dragging = self.plots.borrow().dragging();
        self.redraw(Fit::for_change(dragging, &self.shell.controls), false);
        let ph = phases(&params);
        let (total, peak) = (ph.t_total, ph.v_peak);
        if from == RunFrom::Mount {
            return;
        }
        self.shell.readouts.announce_settled(300.0, move || {
            ctx::t_strings(
                "trap-live",
                &[
                    ("shape", ctx::t(shape_id(&ph))),
                    ("total", sig(total, 4)),
                    ("peak", sig(peak, 4)),
                ],
            )
        });
    }

    fn redraw_all(&self) {
        self.plots.borrow_mut().relocalize();
        self.redraw(Fit::Refit, true);
    }

    fn slider_released(&self) {
        self.redraw(Fit::Refit, false);
    }

    fn png(&self) {
        self.plots.borrow().png(TrapPage::SPEC.png);
    }

    fn on_key(&self, event: &KeyboardEvent) -> bool {
        let p = self.profile.borrow().0;
        let k = if event.shift_key() { 10.0 } else { 1.0 };
        let (vmax, amax) = (p.vmax.abs(), p.amax.abs());
        let controls = &self.shell.controls;
        let set = |name: &str, value: f64| controls.set_text(name, &snap(value, 0.01), false);
        let next = match event.key().as_str() {
            "ArrowUp" => set("vmax", vmax + 0.01 * k),
            "ArrowDown" => set("vmax", (vmax - 0.01 * k).max(0.01)),
            "ArrowRight" => set("amax", amax + 0.01 * k),
            "ArrowLeft" => set("amax", (amax - 0.01 * k).max(0.01)),
            "r" | "R" => controls.reset(),
            _ => return false,
        };
        if let Some(p) = next {
            change(self, p);
        }
        true
    }
}

impl TrapPage {
    /// Readouts, the triangle note and the plots; `fit` says what the axes do, `resized`
    /// refits the canvases (size, language, mode).
    fn redraw(&self, fit: Fit, resized: bool) {
        let (params, profile) = &*self.profile.borrow();
        let ph = phases(params);
        let ro = &self.shell.readouts;
        ro.set_with_value(
            "shape",
            &ctx::t(shape_id(&ph)),
            if ph.triangle { "triangle" } else { "trapezoid" },
        );
        self.shell.show_numbers(&[
            ("t-acc", ph.t_acc),
            ("t-flat", ph.t_flat),
            ("t-total", ph.t_total),
            ("v-peak", ph.v_peak),
        ]);
        if let Some(last) = profile.last() {
            self.shell.show_number("final-s", last.s, 4);
        }
        let rows = profile.len().to_string();
        ro.set_with_value("rows", &rows, &rows);
        dom::show(&self.triangle_note, ph.triangle);
        let sample = self
            .plots
            .borrow_mut()
            .show(params, profile, &ph, fit, resized);
        self.show_cursor_readouts(sample);
    }

    /// The cursor on the plots and its readouts: the CSV row at the hovered time.
    fn show_cursor(&self) {
        let sample = self.plots.borrow_mut().cursor(&self.profile.borrow().1);
        self.show_cursor_readouts(sample);
    }

    fn show_cursor_readouts(&self, sample: Option<TrapSample>) {
        if let Some(s) = sample {
            self.shell.show_numbers(&[
                ("cursor-t", s.t),
                ("cursor-s", s.s),
                ("cursor-v", s.v),
                ("cursor-a", s.a),
            ]);
        }
    }
}
