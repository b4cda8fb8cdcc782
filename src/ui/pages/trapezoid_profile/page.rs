//! The trapezoid-profile drill: its sliders, readouts and keys; the phases' readouts, the
//! triangle note and the announcement of a run; the handles' drags.

use crate::view::exercises::{self, Exercise, PageModel};
use std::cell::RefCell;

use glam::DVec2;
use wasm_bindgen::JsValue;
use web_sys::Element;

use super::plots::{self, Grab, Plots};
use crate::recipes::run_raw_of;
use crate::recipes::trapezoid_profile::{self, params_from_args, TrapParams, TrapSample};
use crate::ui::kit::signal_page::{boxed, Arrows, Draw, Kit, SignalPage, SignalSpec};
use crate::ui::{ctx, dom};
use crate::view::signal::{sig, snap, Slider};
use crate::view::trapezoid_profile::{phases, rows, Phases};

/// The page's state: the plots' labels and the triangle note.
pub struct TrapPage {
    plots: RefCell<Plots>,
    triangle_note: Element,
}

impl SignalPage for TrapPage {
    type Params = TrapParams;
    type Row = TrapSample;
    /// Nothing: the readouts come from the arguments and the last row.
    type Summary = ();
    type Handle = Grab;
    const SPEC: SignalSpec<TrapParams, TrapSample> = SignalSpec {
        prefix: "trap",
        info: &trapezoid_profile::INFO,
        run: run_raw_of::<trapezoid_profile::Entry>,
        parse: params_from_args,
        // The CSV's rows, times unrounded.
        kernel: |p| rows(p).map(boxed),
        thin: |to, s| to.push(s.t, &[s.s, s.v, s.a]),
        png: "trap_profile_plots.png",
        layers: 4,
        sliders: &[
            Slider::new("distance", 0.0, 5.0, 0.05),
            Slider::new("vmax", 0.05, 3.0, 0.01),
            Slider::new("amax", 0.05, 5.0, 0.01),
            Slider::new("dt", 0.001, 0.1, 0.001),
        ],
        readouts: &[
            ("shape", "trap-ro-shape"),
            ("t-acc", "trap-ro-t-acc"),
            ("t-flat", "trap-ro-t-flat"),
            ("t-total", "trap-ro-t-total"),
            ("v-peak", "trap-ro-v-peak"),
            ("final-s", "trap-ro-final-s"),
            ("rows", "trap-ro-rows"),
        ],
        explain: &["what", "input", "steps", "expected"],
        nudges: &[
            Arrows::UpDown.nudge("trap-key-vmax", "vmax", |p| p.vmax.abs(), 0.01, 0.01),
            Arrows::LeftRight.nudge("trap-key-amax", "amax", |p| p.amax.abs(), 0.01, 0.01),
        ],
        overlays: &[],
        under_plot: "<p class=\"sig-warning\" data-trap=\"triangle\" \
                     data-testid=\"trapezoid-profile-triangle\" role=\"status\" \
                     data-i18n=\"trap-triangle\" hidden></p>\
                     <p class=\"sig-note\" data-i18n=\"trap-drag-hint\"></p>",
        under_readouts: "",
    };

    const EXERCISES: &'static [Exercise] = &exercises::trapezoid_profile::EXERCISES;

    fn exercise_model(params: &Self::Params) -> PageModel<'_> {
        PageModel::Trapezoid(params)
    }

    fn summarize(_: &TrapParams, _: &[TrapSample]) {}

    fn build(kit: &Kit<TrapPage>) -> Result<TrapPage, JsValue> {
        Ok(TrapPage {
            plots: RefCell::new(Plots::default()),
            triangle_note: kit.role("triangle")?,
        })
    }

    /// Readouts, the triangle note and the plots.
    fn show(&self, kit: &Kit<TrapPage>, draw: Draw) {
        let run = kit.run();
        let ph = phases(&run.params);
        let ro = &kit.readouts;
        let shape = if ph.triangle { "triangle" } else { "trapezoid" };
        ro.set_with_value("shape", &ctx::t(shape_id(&ph)), shape);
        kit.show_numbers(&[
            ("t-acc", ph.t_acc),
            ("t-flat", ph.t_flat),
            ("t-total", ph.t_total),
            ("v-peak", ph.v_peak),
        ]);
        if let Some(last) = run.rows.last() {
            kit.show_number("final-s", last.s, 4);
        }
        let rows = run.rows.len().to_string();
        ro.set_with_value("rows", &rows, &rows);
        dom::show(&self.triangle_note, ph.triangle);
        let mut plots = self.plots.borrow_mut();
        if draw.resized {
            plots.relocalize();
        }
        plots::set_data(&mut kit.plot.borrow_mut(), &run, &ph, draw);
        drop(run);
        kit.draw_plot();
        plots.draw_marks(&mut kit.plot.borrow_mut(), &ph);
        if draw.changed() {
            let (total, peak) = (ph.t_total, ph.v_peak);
            kit.readouts.announce_settled(300.0, move || {
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
    }

    fn time_axis(&self, kit: &Kit<TrapPage>, params: &TrapParams, draw: Draw) -> (f64, f64) {
        plots::time_axis(&kit.plot.borrow(), &phases(params), draw.fit)
    }

    fn drag(&self, kit: &Kit<TrapPage>, handle: Grab, at: DVec2) -> Option<TrapParams> {
        let (field, value) = plots::dragged(&kit.plot.borrow(), handle, at)?;
        kit.controls
            .set_text(field, &snap(value.max(0.01), 0.01), false)
    }
}

fn shape_id(ph: &Phases) -> &'static str {
    if ph.triangle {
        "trap-shape-triangle"
    } else {
        "trap-shape-trapezoid"
    }
}
