//! The PID step drill: its sliders, readouts and key; the runs (the one shown, the last
//! committed, the ghost), their figures, warnings and announcement.

use crate::view::exercises::{self, Exercise, PageModel};
use std::cell::{Cell, RefCell};

use wasm_bindgen::JsValue;
use web_sys::Element;

use super::plots::{self, Plots};
use crate::error::RecipeWarning;
use crate::recipes::pid_step::{self, params_from_args, warnings, PidParams, PidSample};
use crate::recipes::run_raw_of;
use crate::ui::kit::signal_page::{boxed, Arrows, Draw, Kit, Run, RunFrom, SignalPage, SignalSpec};
use crate::ui::{ctx, dom};
use crate::view::form::fluent_args;
use crate::view::pid_step::{figures, rows, stops_short, StepFigures, TUNED_GAINS};
use crate::view::signal::{sig, Slider};

/// What the page reads off every row of a run: its figures and warnings.
pub struct Summary {
    figures: StepFigures,
    warnings: Vec<RecipeWarning>,
}

/// A run of the recipe: its gains, samples and summary.
type Response = Run<PidParams, PidSample, Summary>;

/// The run the ghost is drawn from (a new ghost, a new generation) and the last committed run
/// (runs are shared, never copied).
struct Runs {
    committed: Response,
    ghost: Option<Response>,
    ghost_generation: u64,
}

impl Runs {
    /// The run `run` with no ghost, committed.
    fn first(run: &Response) -> Runs {
        Runs {
            committed: run.clone(),
            ghost: None,
            ghost_generation: 0,
        }
    }
}

/// The page's state: the runs and whether a change is under way.
pub struct PidPage {
    plots: RefCell<Plots>,
    warning: Element,
    /// Why the run stops short of the setpoint, and the button to tuned gains.
    short: Element,
    short_text: Element,
    runs: RefCell<Runs>,
    changing: Cell<bool>,
}

impl SignalPage for PidPage {
    type Params = PidParams;
    type Row = PidSample;
    type Summary = Summary;
    type Handle = ();
    const SPEC: SignalSpec<PidParams, PidSample> = SignalSpec {
        prefix: "pid",
        info: &pid_step::INFO,
        run: run_raw_of::<pid_step::Entry>,
        parse: params_from_args,
        // The kernel's loop: the CSV's rows, times unrounded.
        kernel: |p| rows(p).map(boxed),
        thin: |to, s| to.push(s.t, &[s.y, s.u]),
        png: "pid_step_plots.png",
        layers: 3,
        sliders: &[
            Slider::new("Kp", 0.0, 10.0, 0.05),
            Slider::new("Ki", 0.0, 5.0, 0.05),
            Slider::new("Kd", 0.0, 1.0, 0.01),
            Slider::new("tau", 0.0, 5.0, 0.05),
            Slider::new("steps", 0.0, 1000.0, 10.0),
        ],
        readouts: &[
            ("rise-time", "pid-ro-rise"),
            ("overshoot", "pid-ro-overshoot"),
            ("settling-time", "pid-ro-settling"),
            ("steady-state-error", "pid-ro-sse"),
            ("peak-u", "pid-ro-peak-u"),
            ("peak-u-t", "pid-ro-peak-u-t"),
            ("final-y", "pid-ro-final-y"),
        ],
        explain: &[
            "gains", "plant", "toy", "real", "input", "steps", "expected",
        ],
        nudges: &[Arrows::UpDown.nudge("pid-key-kp", "Kp", |p| p.kp, 0.05, f64::NEG_INFINITY)],
        overlays: &[],
        // Why the run stops short, and the button to tuned gains, right under the curves.
        under_plot: "<p class=\"sig-warning\" data-pid=\"warning\" \
                     data-testid=\"pid-step-warning\" role=\"alert\" hidden></p>\
                     <div class=\"sig-note pid-short\" data-pid=\"short\" \
                     data-testid=\"pid-step-short\" hidden><p data-pid=\"short-text\"></p>\
                     <button type=\"button\" class=\"tool-button\" data-action=\"pid-tuned\" \
                     data-i18n=\"pid-tuned\"></button></div>\
                     <p class=\"sig-note\" data-i18n=\"pid-ghost-note\"></p>",
        under_readouts: "<p class=\"sig-note\" data-i18n=\"pid-ro-note\"></p>",
    };

    const EXERCISES: &'static [Exercise] = &exercises::pid_step::EXERCISES;

    fn exercise_model(params: &Self::Params) -> PageModel<'_> {
        PageModel::PidStep(params)
    }

    fn summarize(_: &PidParams, rows: &[PidSample]) -> Summary {
        Summary {
            figures: figures(rows),
            warnings: warnings(rows),
        }
    }

    fn build(kit: &Kit<PidPage>) -> Result<PidPage, JsValue> {
        Ok(PidPage {
            plots: RefCell::new(Plots::default()),
            warning: kit.role("warning")?,
            short: kit.role("short")?,
            short_text: kit.role("short-text")?,
            runs: RefCell::new(Runs::first(&kit.run())),
            changing: Cell::new(false),
        })
    }

    /// A new run: the first change after a committed one turns the committed run into the
    /// ghost; the page's first run has none. Then readouts, warning and plots.
    fn show(&self, kit: &Kit<PidPage>, draw: Draw) {
        let run = kit.run();
        let mut runs = self.runs.borrow_mut();
        if draw.run == Some(RunFrom::Mount) {
            *runs = Runs::first(&run);
        } else if draw.run.is_some() && !self.changing.replace(true) {
            // A change's first run: the committed run becomes the ghost; the next commit
            // replaces it.
            runs.ghost = Some(runs.committed.clone());
            runs.ghost_generation += 1;
        }
        let f = run.summary.figures;
        let show = |key: &str, x: Option<f64>, digits: usize| match x {
            Some(x) => kit.show_number(key, x, digits),
            None => kit.readouts.set_with_value(key, &ctx::t("pid-ro-none"), ""),
        };
        show("rise-time", f.rise_time, 4);
        show("overshoot", f.overshoot_pct, 3);
        show("settling-time", f.settling_time, 4);
        show("steady-state-error", f.steady_state_error, 4);
        show("peak-u", f.peak_u.map(|p| p.1), 4);
        show("peak-u-t", f.peak_u.map(|p| p.0), 4);
        show("final-y", f.final_y, 4);
        let text: Vec<String> = (run.summary.warnings)
            .iter()
            .map(|w| ctx::t_args(w.message_id(), &fluent_args(w.message_args())))
            .collect();
        self.warning.set_text_content(Some(&text.join(" ")));
        dom::show(&self.warning, !text.is_empty());
        let short = stops_short(&run.params, &f);
        if short {
            let error = f.steady_state_error.map_or_else(String::new, |e| sig(e, 3));
            self.short_text.set_text_content(Some(&ctx::t_strings(
                "pid-short",
                &[("error", error), ("ki", sig(run.params.ki, 3))],
            )));
        }
        dom::show(&self.short, short);
        let ghost = runs.ghost.as_ref().map(|g| (runs.ghost_generation, g));
        let mut sp = kit.plot.borrow_mut();
        self.plots
            .borrow_mut()
            .set_data(&mut sp, &run, ghost, draw.resized);
        drop((sp, runs, run));
        kit.draw_plot();
        if draw.changed() {
            // The unit belongs to a number only: "not reached" stands alone.
            let or_none = |x: Option<f64>, unit_id: &str| {
                x.map_or_else(
                    || ctx::t("pid-ro-none"),
                    |x| ctx::t_strings(unit_id, &[("value", sig(x, 3))]),
                )
            };
            kit.readouts.announce(&ctx::t_strings(
                "pid-live",
                &[
                    ("rise", or_none(f.rise_time, "pid-live-seconds")),
                    ("overshoot", or_none(f.overshoot_pct, "pid-live-percent")),
                    ("settling", or_none(f.settling_time, "pid-live-seconds")),
                ],
            ));
        }
    }

    /// From 0 to the end of the run or of the ghost it is shown over, whichever is later.
    fn time_axis(&self, _: &Kit<PidPage>, params: &PidParams, draw: Draw) -> (f64, f64) {
        let runs = self.runs.borrow();
        let ghost = match draw.run {
            Some(RunFrom::Mount) => None,
            // A change's first run turns the committed run into the ghost.
            Some(_) if !self.changing.get() => Some(&runs.committed),
            _ => runs.ghost.as_ref(),
        };
        let ghost_end = ghost.and_then(|g| g.rows.last()).map(|s| s.t);
        plots::time_axis_of(plots::last_t(params), ghost_end)
    }

    /// "Try tuned gains": the tuned Kp, Ki and Kd in the fields, as if typed.
    fn action(&self, kit: &Kit<PidPage>, action: &str) -> Option<PidParams> {
        (action == "pid-tuned").then(|| kit.controls.set_texts(&TUNED_GAINS, None))?
    }

    /// The run shown is the one the next change leaves as the ghost.
    fn change_ended(&self, kit: &Kit<PidPage>) {
        if self.changing.replace(false) {
            self.runs.borrow_mut().committed = kit.run().clone();
        }
    }
}
