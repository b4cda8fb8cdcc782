//! The PID step response (`#/pid-step`): y, r and u over the steps, live while Kp, Ki, Kd, tau
//! and steps are dragged (sliders beside their fields); rise time, overshoot, settling time,
//! steady-state error and peak u from the exact samples (`crate::view::pid_step`); a ghost of
//! the previous gains stays drawn until the next change, so a class compares tunings; the
//! recipe's warning when the loop diverges. The CSV is the recipe's (`bsv pid-step`).
//!
//! Components: `plots` (the kit's signal plot: y and r above, u below, and the ghost) in the
//! kit's signal-page shell ([`crate::ui::kit::signal_page`]: markup, controls, readouts, URL).

mod plots;

use std::cell::{Cell, RefCell};
use std::rc::{Rc, Weak};

use wasm_bindgen::prelude::*;
use web_sys::{Element, KeyboardEvent};

use crate::error::RecipeWarning;
use crate::pyfmt::py_round;
use crate::recipes::pid_step::{params_from_args, warnings, PidParams, PidSample, INFO};
use crate::ui::kit::recipe_controls::{Parse, RecipeControls};
use crate::ui::kit::signal_page::{change, RunFrom, Shell, SignalPage, SignalSpec};
use crate::ui::page::{MountCtx, Shortcut};
use crate::ui::{ctx, dom};
use crate::view::form::fluent_args;
use crate::view::pid_step::{figures, rows, StepFigures};
use crate::view::signal::{sig, snap, Slider};

const P: &str = "pid";
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

/// The run shown (its figures and warnings), the run the ghost is drawn from (a new ghost, a
/// new generation), and the last committed run. Runs are shared, never copied (a million rows
/// are 40 MB).
pub struct Runs {
    now: Rc<Vec<PidSample>>,
    figures: StepFigures,
    warnings: Vec<RecipeWarning>,
    committed: Rc<Vec<PidSample>>,
    ghost: Option<Rc<Vec<PidSample>>>,
    ghost_generation: u64,
}

impl Runs {
    /// The run `rows` with no ghost, committed.
    fn first(rows: Vec<PidSample>) -> Runs {
        let now = Rc::new(rows);
        Runs {
            figures: figures(&now),
            warnings: warnings(&now),
            committed: now.clone(),
            now,
            ghost: None,
            ghost_generation: 0,
        }
    }
}

/// The page's keys.
const KEYS: [Shortcut; 2] = [
    Shortcut {
        keys: "↑ ↓",
        message_id: "pid-key-kp",
    },
    Shortcut {
        keys: "r",
        message_id: "signals-key-reset",
    },
];

/// The page's state: the runs and whether a change is under way.
pub struct PidPage {
    shell: Shell<PidParams>,
    plots: RefCell<plots::Plots>,
    warning: Element,
    runs: RefCell<Runs>,
    changing: Cell<bool>,
}

/// What the page builds before it exists.
pub struct Parts {
    plots: plots::Plots,
    warning: Element,
    runs: Runs,
}

impl SignalPage for PidPage {
    type Params = PidParams;
    type Row = PidSample;
    type Parts = Parts;
    const SPEC: SignalSpec = SignalSpec {
        prefix: P,
        info: &INFO,
        png: "pid_step_plots.png",
        layers: 3,
        sliders: &SLIDERS,
        readouts: &READOUTS,
        explain: &[
            "gains", "plant", "toy", "real", "input", "steps", "expected",
        ],
        keys: &KEYS,
        own_keys: &[],
    };
    const PARSE: Parse<PidParams> = params_from_args;

    fn stage_markup() -> String {
        format!(
            "<p class=\"sig-warning\" data-{P}=\"warning\" data-testid=\"pid-step-warning\" role=\"alert\" hidden></p>\
             <p class=\"sig-note\" data-i18n=\"pid-ghost-note\"></p>"
        )
    }

    fn readouts_markup() -> String {
        "<p class=\"sig-note\" data-i18n=\"pid-ro-note\"></p>".into()
    }

    fn prepare(
        _ctx: &MountCtx,
        root: &Element,
        _controls: &RecipeControls<PidParams>,
        stage: &Element,
        rows: Vec<PidSample>,
    ) -> Result<Parts, JsValue> {
        Ok(Parts {
            plots: plots::Plots::new(stage)?,
            warning: dom::find(root, &format!("[data-{P}=\"warning\"]"), P)?,
            runs: Runs::first(rows),
        })
    }

    fn new(shell: Shell<PidParams>, parts: Parts) -> PidPage {
        PidPage {
            shell,
            plots: RefCell::new(parts.plots),
            warning: parts.warning,
            runs: RefCell::new(parts.runs),
            changing: Cell::new(false),
        }
    }

    fn shell(&self) -> &Shell<PidParams> {
        &self.shell
    }

    fn install(&self, me: &Weak<PidPage>) -> Result<(), JsValue> {
        let form = self.shell.role(P, "form")?;
        self.shell.with_scope(|scope| {
            scope.listen_for(&form, "change", me, |p: &PidPage, _| p.commit())
        })?;
        self.plots.borrow_mut().attach(me, &self.shell.stage)
    }

    /// The kernel's loop ([`crate::view::pid_step::rows`]: the CSV's rows, times unrounded).
    fn kernel(p: &PidParams) -> Option<(Box<dyn Iterator<Item = PidSample>>, u64)> {
        let (rows, n) = rows(p)?;
        Some((Box::new(rows), n))
    }

    /// A run: the first change after a committed one turns the committed run into the ghost.
    /// The page's first run has no ghost; a run computed in slices and finished after its
    /// input ended is committed at once (the input's `change` came before it).
    fn show_run(&self, _params: PidParams, rows: Vec<PidSample>, from: RunFrom) {
        {
            let mut runs = self.runs.borrow_mut();
            if from == RunFrom::Mount {
                *runs = Runs::first(rows);
            } else {
                if !self.changing.replace(true) {
                    // The committed run becomes the ghost; the next commit replaces it.
                    runs.ghost = Some(std::mem::take(&mut runs.committed));
                    runs.ghost_generation += 1;
                }
                runs.figures = figures(&rows);
                runs.warnings = warnings(&rows);
                runs.now = Rc::new(rows);
            }
        }
        self.redraw(false);
        if from == RunFrom::Slices && !self.shell.controls.sliding() {
            self.commit();
        }
        let f = self.runs.borrow().figures;
        // The unit belongs to a number only: "not reached" stands alone.
        let or_none = |x: Option<f64>, unit_id: &str| {
            x.map_or_else(
                || ctx::t("pid-ro-none"),
                |x| ctx::t_strings(unit_id, &[("value", sig(x, 3))]),
            )
        };
        if from == RunFrom::Mount {
            return;
        }
        self.shell.readouts.announce(&ctx::t_strings(
            "pid-live",
            &[
                ("rise", or_none(f.rise_time, "pid-live-seconds")),
                ("overshoot", or_none(f.overshoot_pct, "pid-live-percent")),
                ("settling", or_none(f.settling_time, "pid-live-seconds")),
            ],
        ));
    }

    fn redraw_all(&self) {
        self.redraw(true);
    }

    fn png(&self) {
        self.plots.borrow().png(PidPage::SPEC.png);
    }

    fn on_key(&self, event: &KeyboardEvent) -> bool {
        let kp = self.shell.controls.value().kp;
        let k = if event.shift_key() { 10.0 } else { 1.0 };
        let controls = &self.shell.controls;
        let next = match event.key().as_str() {
            "ArrowUp" => controls.set_text("Kp", &snap(kp + 0.05 * k, 0.05), false),
            "ArrowDown" => controls.set_text("Kp", &snap(kp - 0.05 * k, 0.05), false),
            "r" | "R" => controls.reset(),
            _ => return false,
        };
        if let Some(p) = next {
            change(self, p);
        }
        self.commit();
        true
    }
}

impl PidPage {
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
        let runs = self.runs.borrow();
        let f = runs.figures;
        let ro = &self.shell.readouts;
        let show = |key: &str, x: Option<f64>, digits: usize| match x {
            Some(x) => self.shell.show_number(key, x, digits),
            None => ro.set_with_value(key, &ctx::t("pid-ro-none"), ""),
        };
        show("rise-time", f.rise_time, 4);
        show("overshoot", f.overshoot_pct, 3);
        show("settling-time", f.settling_time, 4);
        show("steady-state-error", f.steady_state_error, 4);
        show("peak-u", f.peak_u.map(|p| p.1), 4);
        show("peak-u-t", f.peak_u.map(|p| p.0), 4);
        show("final-y", f.final_y, 4);
        let text: Vec<String> = runs
            .warnings
            .iter()
            .map(|w| ctx::t_args(w.message_id(), &fluent_args(w.message_args())))
            .collect();
        self.warning.set_text_content(Some(&text.join(" ")));
        dom::show(&self.warning, !text.is_empty());
        let sample = self.plots.borrow_mut().show(
            &runs.now,
            runs.ghost
                .as_deref()
                .map(|g| (runs.ghost_generation, g.as_slice())),
            resized,
        );
        drop(runs);
        self.show_cursor_readouts(sample);
    }

    /// The cursor on the plots and its readouts: the CSV row at the hovered time.
    fn show_cursor(&self) {
        let sample = self.plots.borrow_mut().cursor(&self.runs.borrow().now);
        self.show_cursor_readouts(sample);
    }

    fn show_cursor_readouts(&self, sample: Option<PidSample>) {
        if let Some(s) = sample {
            self.shell.show_numbers(&[
                ("cursor-t", py_round(s.t, 4)),
                ("cursor-r", s.r),
                ("cursor-y", s.y),
                ("cursor-u", s.u),
            ]);
        }
    }
}
