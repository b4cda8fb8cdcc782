//! The cubic-path drill: its sliders, readouts, keys and overlays; the path's readouts and
//! announcement; the end point's drag.

use crate::view::exercises::{self, Exercise, PageModel};
use glam::DVec2;
use wasm_bindgen::JsValue;

use super::plots;
use crate::pyfmt::py_float;
use crate::recipes::cubic_path::{self, params_from_args, CubicParams, CubicSample};
use crate::recipes::run_raw_of;
use crate::ui::ctx;
use crate::ui::kit::signal_page::{boxed, Arrows, Draw, Kit, SignalPage, SignalSpec};
use crate::view::cubic_path::{readouts as numbers, rows, Readouts};
use crate::view::signal::{sig, Slider};

/// The page: its state is the kit's (the run, the overlays, the plot).
pub struct CubicPage;

impl SignalPage for CubicPage {
    type Params = CubicParams;
    type Row = CubicSample;
    type Summary = Readouts;
    type Handle = ();
    const SPEC: SignalSpec<CubicParams, CubicSample> = SignalSpec {
        prefix: "cubic",
        info: &cubic_path::INFO,
        run: run_raw_of::<cubic_path::Entry>,
        parse: params_from_args,
        kernel: |p| rows(p).map(boxed),
        thin: |to, s| to.push(s.t, &[s.q, s.qd, s.qdd]),
        png: "cubic_path_plots.png",
        layers: 4,
        sliders: &[
            Slider::new("q0", -3.2, 3.2, 0.01),
            Slider::new("q1", -3.2, 3.2, 0.01),
            Slider::new("T", 0.1, 5.0, 0.01),
            Slider::new("dt", 0.001, 0.2, 0.001),
        ],
        readouts: &[
            ("peak-velocity", "cubic-ro-peak-v"),
            ("peak-velocity-t", "cubic-ro-peak-v-t"),
            ("peak-acceleration", "cubic-ro-peak-a"),
            ("peak-acceleration-t", "cubic-ro-peak-a-t"),
            ("a0", "cubic-ro-a0"),
            ("a1", "cubic-ro-a1"),
            ("a2", "cubic-ro-a2"),
            ("a3", "cubic-ro-a3"),
            ("rows", "cubic-ro-rows"),
        ],
        explain: &["what", "input", "steps", "expected"],
        nudges: &[
            Arrows::UpDown.nudge("cubic-key-q1", "q1", |p| p.q1, 0.01, f64::NEG_INFINITY),
            Arrows::LeftRight.nudge("cubic-key-t", "T", |p| p.duration_s, 0.01, 0.01),
        ],
        overlays: &plots::OVERLAYS,
        under_plot: "<p class=\"sig-note\" data-i18n=\"cubic-drag-hint\"></p>",
        under_readouts: "",
    };

    /// The peaks, coefficients and row count.
    const EXERCISES: &'static [Exercise] = &exercises::cubic_path::EXERCISES;

    fn exercise_model(params: &Self::Params) -> PageModel<'_> {
        PageModel::CubicPath(params)
    }

    fn summarize(params: &CubicParams, rows: &[CubicSample]) -> Readouts {
        numbers(params, rows)
    }

    fn build(_kit: &Kit<CubicPage>) -> Result<CubicPage, JsValue> {
        Ok(CubicPage)
    }

    /// Readouts and plots; a change's run is announced with its peak velocity.
    fn show(&self, kit: &Kit<CubicPage>, draw: Draw) {
        let run = kit.run();
        let params = run.params;
        let r = *run.summary;
        if let Some(v) = r.peak_velocity {
            kit.show_numbers(&[("peak-velocity", v.value), ("peak-velocity-t", v.t)]);
        }
        if let Some(a) = r.peak_acceleration {
            kit.show_numbers(&[("peak-acceleration", a.value), ("peak-acceleration-t", a.t)]);
        }
        let c = r.coefficients;
        kit.show_numbers(&[("a0", c.a0), ("a1", c.a1), ("a2", c.a2), ("a3", c.a3)]);
        let rows = r.rows.to_string();
        kit.readouts.set_with_value("rows", &rows, &rows);
        let overlays = [kit.overlay(0), kit.overlay(1)];
        plots::set_data(&mut kit.plot.borrow_mut(), &run, overlays, draw);
        drop(run);
        kit.draw_plot();
        plots::draw_end(&mut kit.plot.borrow_mut(), &params);
        if draw.changed() {
            let peak = r.peak_velocity.map_or(0.0, |p| p.value);
            kit.readouts.announce(&ctx::t_strings(
                "cubic-live",
                &[
                    ("q1", py_float(params.q1)),
                    ("T", py_float(params.duration_s)),
                    ("peak", sig(peak, 4)),
                ],
            ));
        }
    }

    fn time_axis(&self, kit: &Kit<CubicPage>, params: &CubicParams, draw: Draw) -> (f64, f64) {
        plots::time_axis(&kit.plot.borrow(), params, draw.fit)
    }

    /// The end point dragged: q1 and T.
    fn drag(&self, kit: &Kit<CubicPage>, _: (), at: DVec2) -> Option<CubicParams> {
        let (q, t) = plots::dragged_end(&kit.plot.borrow(), at)?;
        kit.controls.set_texts(&[("q1", &q), ("T", &t)], None)
    }

    /// Mid-move.
    fn cursor_start(params: &CubicParams, _: &[CubicSample]) -> f64 {
        params.duration_s / 2.0
    }
}
