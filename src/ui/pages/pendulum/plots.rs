//! The plots (the kit's plot widget): energies (the recipe's ke, pe, total and the capsule's
//! true energy), angle, rate and the relative energy error on a log axis, sharing the time
//! axis with a cursor at the state shown; and the phase portrait (θ, ω) with the undamped
//! separatrix. Rows are appended as they are stepped (the widget draws only the new points,
//! never the history).

use wasm_bindgen::JsValue;
use web_sys::Element;

use crate::recipes::pendulum_energy::Integrator;
use crate::ui::ctx;
use crate::ui::kit::canvas::Ink;
use crate::ui::kit::plot::{AxisSpec, Mark, PanelSpec, Plot, PlotSpec, SeriesSpec};
use crate::view::palette;
use crate::view::pendulum::{separatrix, Track};

/// The error panel's range (log axis): from rounding-error level to far beyond blow-up.
const ERROR_RANGE: (f64, f64) = (1e-12, 1e2);
/// At most this many phase points per track.
const PHASE_POINTS: u64 = 6000;

/// The plots component.
pub struct Plots {
    pub time: Plot,
    pub phase: Plot,
    /// The stages, where [`Plots::describe`] writes `data-series`.
    stages: [Element; 2],
    /// What `data-series` holds on each stage.
    described: [String; 2],
    /// Rows appended per track.
    appended: Vec<usize>,
    stride: usize,
}

fn series(name: String, rgb: (u8, u8, u8), alpha: f64, mark: Mark) -> SeriesSpec {
    SeriesSpec {
        name,
        rgb,
        mark,
        width: 1.6,
        alpha,
    }
}

fn int_name(i: Integrator) -> String {
    ctx::t(match i {
        Integrator::Euler => "pendulum-s-euler",
        Integrator::Rk4 => "pendulum-s-rk4",
    })
}

impl Plots {
    /// Wraps the two stages.
    pub fn find(time: &Element, phase: &Element) -> Result<Plots, JsValue> {
        Ok(Plots {
            time: Plot::new(time)?,
            phase: Plot::new(phase)?,
            stages: [time.clone(), phase.clone()],
            described: [String::new(), String::new()],
            appended: Vec::new(),
            stride: 1,
        })
    }

    /// New axes and series for `tracks` (empties the data).
    pub fn reset(&mut self, tracks: &[Track], steps: u64) {
        let Some(first) = tracks.first() else {
            return;
        };
        let p = *first.start().params();
        let inertia = first.start().joint_inertia();
        let e0 = first.start().true_energy();
        let pe0 = p.mass_kg
            * crate::recipes::pendulum_energy::GRAVITY
            * p.length_m
            * (1.0 - p.angle_deg.to_radians().cos());
        let e_max = e0.max(pe0).max(1e-9) * 1.15;
        let theta_max = p.angle_deg.to_radians().abs().max(0.1) * 1.1;
        let omega_max = (2.0 * e0.max(1e-12) / inertia).sqrt().max(0.1) * 1.15;
        let names: Vec<String> = tracks
            .iter()
            .map(|t| int_name(t.start().params().integrator))
            .collect();
        let two = tracks.len() > 1;
        // In compare mode each energy curve is tagged with its integrator ("ke (RK4)").
        let tag = |k: usize, id: &str| {
            if two {
                ctx::t_strings(
                    "pendulum-s-tagged",
                    &[("what", ctx::t(id)), ("integrator", names[k].clone())],
                )
            } else {
                ctx::t(id)
            }
        };
        // Okabe–Ito colours per track (the page's integrator first, the second one's other
        // hues): ke, pe, total, true energy (also the angle, rate, error and phase curves).
        // KE and PE cross and the total lies on the true energy: each pair stays apart with
        // every common colour-vision deficiency (the total is black, the true energy blue).
        const KE: [(u8, u8, u8); 2] = [palette::VERMILION.rgb, palette::ORANGE.rgb];
        const PE: [(u8, u8, u8); 2] = [palette::SKY_BLUE.rgb, palette::REDDISH_PURPLE.rgb];
        const TOTAL: [(u8, u8, u8); 2] = [palette::BLACK.rgb, (110, 110, 110)];
        const TRUE: [(u8, u8, u8); 2] = [palette::BLUE.rgb, palette::BLUISH_GREEN.rgb];
        let mut energy = Vec::new();
        let mut theta = Vec::new();
        let mut omega = Vec::new();
        let mut error = Vec::new();
        // The separatrix is one series: upper branch, a break, lower branch (one legend entry).
        let mut phase = vec![series(
            ctx::t("pendulum-s-separatrix"),
            (120, 120, 120),
            0.8,
            Mark::Line,
        )];
        // Energy series of track k: ke, pe, total, true energy at 4k..4k+3.
        for (k, name) in names.iter().enumerate() {
            let c = k.min(1);
            let alpha = if k == 0 { 1.0 } else { 0.75 };
            let line = |name: String, rgb| series(name, rgb, alpha, Mark::Line);
            energy.push(line(tag(k, "pendulum-s-ke"), KE[c]));
            energy.push(line(tag(k, "pendulum-s-pe"), PE[c]));
            energy.push(line(tag(k, "pendulum-s-total"), TOTAL[c]));
            energy.push(line(tag(k, "pendulum-s-true"), TRUE[c]));
            theta.push(line(name.clone(), TRUE[c]));
            omega.push(line(name.clone(), TRUE[c]));
            error.push(line(name.clone(), TRUE[c]));
            phase.push(line(name.clone(), TRUE[c]));
        }
        let axis = |title: &str, unit: &str, range: (f64, f64)| AxisSpec {
            title: ctx::t(title),
            unit: if unit.is_empty() {
                String::new()
            } else {
                ctx::t(unit)
            },
            range,
        };
        self.time.clear();
        self.time.set_spec(PlotSpec {
            x: axis("pendulum-ax-t", "pendulum-unit-s", (0.0, p.duration_s)),
            panels: vec![
                PanelSpec {
                    y: axis("pendulum-ax-energy", "pendulum-unit-j", (0.0, e_max)),
                    series: energy,
                },
                PanelSpec {
                    y: axis(
                        "pendulum-ax-theta",
                        "pendulum-unit-rad",
                        (-theta_max, theta_max),
                    ),
                    series: theta,
                },
                PanelSpec {
                    y: axis(
                        "pendulum-ax-omega",
                        "pendulum-unit-rad-s",
                        (-omega_max, omega_max),
                    ),
                    series: omega,
                },
                PanelSpec {
                    y: axis("pendulum-ax-error", "", ERROR_RANGE),
                    series: error,
                },
            ],
            cursor_rgb: (194, 65, 12),
        });
        self.time.clear();
        self.time.set_log_y(3, true);
        let pi = std::f64::consts::PI;
        let x_max = p.angle_deg.to_radians().abs().max(pi) * 1.05;
        let sep = separatrix(&p, inertia, 200);
        let w_max = sep.iter().map(|s| s.1).fold(omega_max, f64::max) * 1.1;
        self.phase.set_spec(PlotSpec {
            x: axis("pendulum-ax-theta", "pendulum-unit-rad", (-x_max, x_max)),
            panels: vec![PanelSpec {
                y: axis("pendulum-ax-omega", "pendulum-unit-rad-s", (-w_max, w_max)),
                series: phase,
            }],
            cursor_rgb: (194, 65, 12),
        });
        self.phase.clear();
        let lower: Vec<(f64, f64)> = sep.iter().map(|&(t, w)| (t, -w)).collect();
        let mut both = sep;
        both.push((f64::NAN, f64::NAN));
        both.extend(lower);
        self.phase.set_series(0, 0, both);
        self.appended = vec![0; tracks.len()];
        self.stride = (steps / PHASE_POINTS).max(1) as usize;
        self.time.redraw_all();
        self.phase.redraw_all();
    }

    /// Appends the rows stepped since the last call and moves the cursor to `index`.
    pub fn update(&mut self, tracks: &[Track], index: usize) {
        for (k, track) in tracks.iter().enumerate() {
            let Some(done) = self.appended.get(k).copied() else {
                continue;
            };
            let rows = track.rows();
            if rows.len() <= done {
                continue;
            }
            let new = &rows[done..];
            let h = track.start().params().timestep_s;
            let state_t = |i: usize| (done + i + 1) as f64 * h;
            let pts = |f: &dyn Fn(usize) -> f64| -> Vec<(f64, f64)> {
                (0..new.len()).map(|i| (state_t(i), f(i))).collect()
            };
            self.time.append(0, 4 * k, &pts(&|i| new[i].ke));
            self.time.append(0, 4 * k + 1, &pts(&|i| new[i].pe));
            self.time.append(0, 4 * k + 2, &pts(&|i| new[i].total));
            self.time
                .append(0, 4 * k + 3, &pts(&|i| new[i].true_energy));
            self.time.append(1, k, &pts(&|i| new[i].theta));
            self.time.append(2, k, &pts(&|i| new[i].omega));
            self.time
                .append(3, k, &pts(&|i| track.energy_error(done + i + 1).abs()));
            let phase: Vec<(f64, f64)> = new
                .iter()
                .enumerate()
                .filter(|(i, _)| (done + i) % self.stride == 0)
                .map(|(_, r)| (r.theta, r.omega))
                .collect();
            self.phase.append(0, 1 + k, &phase);
            self.appended[k] = rows.len();
        }
        let h = tracks
            .first()
            .map_or(0.0, |t| t.start().params().timestep_s);
        self.time.set_cursor(Some(index as f64 * h));
        // The state shown, on the phase portrait.
        self.phase.set_markers(
            tracks
                .iter()
                .map(|t| {
                    let (theta, omega, _) = t.state(index);
                    (0, (theta, omega))
                })
                .collect(),
        );
    }

    /// Writes on each stage what its panels hold (a test hook, written when the animation
    /// stops, not per frame): `data-series` = panels separated by `;`, each a `|`-separated
    /// list of `name=points` (series without a name are left out).
    pub fn describe(&mut self) {
        for (k, plot) in [&self.time, &self.phase].into_iter().enumerate() {
            let Some(spec) = plot.spec() else {
                continue;
            };
            let text = spec
                .panels
                .iter()
                .enumerate()
                .map(|(p, panel)| {
                    panel
                        .series
                        .iter()
                        .enumerate()
                        .filter(|(_, s)| !s.name.is_empty())
                        .map(|(i, s)| format!("{}={}", s.name, plot.series(p, i).len()))
                        .collect::<Vec<_>>()
                        .join("|")
                })
                .collect::<Vec<_>>()
                .join(";");
            if text != self.described[k] {
                let _ = self.stages[k].set_attribute("data-series", &text);
                self.described[k] = text;
            }
        }
    }

    /// Draws what changed.
    pub fn draw(&mut self, ink: Ink) {
        let _ = self.time.draw(ink);
        let _ = self.phase.draw(ink);
    }
}
