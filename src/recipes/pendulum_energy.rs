//! Recipe `pendulum-energy` (`mujoco_pendulum_energy.py`): a damped capsule pendulum stepped
//! exactly as MuJoCo steps it, logging the recipe's point-mass energy and the true energy.
//!
//! Model (the recipe's MJCF): a hinge about `y` at the origin, a capsule from `(0,0,0)` to
//! `(0,0,-L)` of radius `r` and mass `m`, joint damping `b`, gravity `g = 9.81`.
//!
//! ```text
//! capsule inertia (MuJoCo):  mc = m Vc / (Vc + Vs),  ms = m Vs / (Vc + Vs),
//!                            Vc = pi r² L,  Vs = 4/3 pi r³
//!   Iyy_com = mc (3 r² + L²) / 12 + ms (2 r²/5 + L²/4 + 3 L r / 8)
//!   I       = Iyy_com + m (L/2)²                       (about the hinge, no armature)
//! a(θ, ω)   = (−m g (L/2) sin θ − b ω) / I
//! Euler (MuJoCo default, implicit damping):
//!   acc = (−m g (L/2) sin θ − b ω) / (I + h b);  ω += h acc;  θ += h ω
//! RK4: classic four stages on (θ, ω) with a(θ, ω) (damping explicit)
//! ```
//!
//! Row `i` of the recipe CSV: `t = i h` (the step index times `h`, although the state is the one
//! *after* step `i`), θ and ω after the step, and the recipe's point-mass energy (tip mass `m`
//! at `L`): `ke = ½ m (L ω)²`, `pe = m g (z_tip + L)` with `z_tip = −L cos θ_s`, where `θ_s` is the
//! angle at which MuJoCo last computed positions: for Euler the angle *before* the step, for RK4
//! the fourth-stage angle `θ + h ω₃` (`ω₃ = ω + h/2 k₂`), not the final one.
//!
//! Beside it, [`PendulumRow::true_energy`] is the capsule's mechanical energy
//! `½ I ω² + m g z_com` with `z_com = (L/2)(1 − cos θ)`: the height of the centre of mass above
//! its lowest point, so it is 0 with the pendulum hanging at rest. It uses the state after the
//! step. With `b = 0` it is conserved up to the integrator's error; the recipe's point-mass
//! figure is not an energy of this body at all.

use super::info::RecipeInfo;
use super::kernel::{float_csv_with, plan_of, Kernel, Progress, RunResult};
use super::output::RecipeOutput;
use super::picture::{
    lines,
    series::{BLUE, GREEN, ORANGE},
    Picture, Table,
};
use crate::args::{finite, in_range, positive, rows_within, ArgKind, ArgSpec, Args, Bound};
use crate::error::{RecipeError, RecipeWarning};
use crate::pyfmt::fixed;

/// Gravity of the recipe's model, m/s².
pub const GRAVITY: f64 = 9.81;

/// The most steps (CSV rows) one run may take.
pub const MAX_STEPS: u64 = 1_000_000;

/// The CSV file the recipe writes.
pub const CSV_NAME: &str = "pendulum_energy.csv";

const CSV_HEADER: [&str; 6] = ["t_s", "theta_rad", "omega_rad_s", "ke_j", "pe_j", "total_j"];

const ARGS: [ArgSpec; 1] = [
    ArgSpec::number("duration_s", "5", "simulated time in seconds")
        .unit("s")
        .limits(Bound::Excl(0.0), Bound::None)
        .hint("recipe-pendulum-energy-hint-duration_s"),
];

const POSITIVE: ArgSpec = ArgSpec::number("", "", "").limits(Bound::Excl(0.0), Bound::None);

const FLAG_DAMPING: ArgSpec = ArgSpec::number("damping", "0.05", "hinge damping b, N·m·s/rad")
    .unit("N·m·s/rad")
    .limits(Bound::Incl(0.0), Bound::None)
    .hint("recipe-pendulum-energy-hint-damping");
const FLAG_ANGLE: ArgSpec = ArgSpec::number(
    "angle-deg",
    "120",
    "starting angle from hanging down, degrees",
)
.unit("deg")
.hint("recipe-pendulum-energy-hint-angle-deg");
const FLAG_TIMESTEP: ArgSpec = ArgSpec {
    name: "timestep",
    default: "0.002",
    help: "integrator step h, seconds",
    unit: Some("s"),
    hint_id: "recipe-pendulum-energy-hint-timestep",
    ..POSITIVE
};
const FLAG_LENGTH: ArgSpec = ArgSpec {
    name: "length",
    default: "0.3",
    help: "capsule length L, metres",
    unit: Some("m"),
    hint_id: "recipe-pendulum-energy-hint-length",
    ..POSITIVE
};
const FLAG_MASS: ArgSpec = ArgSpec {
    name: "mass",
    default: "0.2",
    help: "capsule mass m, kg",
    unit: Some("kg"),
    hint_id: "recipe-pendulum-energy-hint-mass",
    ..POSITIVE
};
const FLAG_RADIUS: ArgSpec = ArgSpec {
    name: "radius",
    default: "0.01",
    help: "capsule radius r, metres",
    unit: Some("m"),
    hint_id: "recipe-pendulum-energy-hint-radius",
    ..POSITIVE
};
const FLAG_INTEGRATOR: ArgSpec = ArgSpec::number(
    "integrator",
    "euler",
    "euler (MuJoCo default, implicit damping) or rk4",
)
.kind(ArgKind::Choice(&["euler", "rk4"]))
.hint("recipe-pendulum-energy-hint-integrator");

const FLAGS: [ArgSpec; 7] = [
    FLAG_DAMPING,
    FLAG_ANGLE,
    FLAG_TIMESTEP,
    FLAG_LENGTH,
    FLAG_MASS,
    FLAG_RADIUS,
    FLAG_INTEGRATOR,
];

/// What the recipe is, takes and writes.
pub const INFO: RecipeInfo = RecipeInfo {
    id: "pendulum-energy",
    python: "mujoco_pendulum_energy.py",
    args: &ARGS,
    flags: &FLAGS,
    writes: &[CSV_NAME],
    quirks_id: "recipe-pendulum-energy-quirks",
    plan: plan_of::<Entry>,
    page: Some("pendulum-energy"),
};

/// MuJoCo's integrator choice.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Integrator {
    /// Semi-implicit Euler with implicit joint damping (MuJoCo's default, the recipe's).
    #[default]
    Euler,
    /// Classic 4-stage Runge-Kutta (`integrator="RK4"`).
    Rk4,
}

impl Integrator {
    /// The choices as the `--integrator` flag spells them.
    pub const CHOICES: &'static str = "euler, rk4";

    /// Parses `euler` / `rk4` (any case).
    pub fn parse(text: &str) -> Result<Integrator, RecipeError> {
        match text.trim().to_ascii_lowercase().as_str() {
            "euler" => Ok(Integrator::Euler),
            "rk4" => Ok(Integrator::Rk4),
            _ => Err(RecipeError::BadChoice {
                param: FLAG_INTEGRATOR.name.to_string(),
                value: text.to_string(),
                choices: Integrator::CHOICES.to_string(),
            }),
        }
    }
}

/// The pendulum and the run length; `Default` is the recipe's model and duration.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PendulumParams {
    /// Simulated time, seconds; the run takes `int(duration_s / timestep_s)` steps.
    pub duration_s: f64,
    /// Hinge damping `b`, N·m·s/rad.
    pub damping: f64,
    /// Starting angle from hanging straight down, degrees (starting velocity is 0).
    pub angle_deg: f64,
    /// Integrator step `h`, seconds.
    pub timestep_s: f64,
    /// Capsule length `L`, metres (the tip is at `L` from the hinge).
    pub length_m: f64,
    /// Capsule mass `m`, kg.
    pub mass_kg: f64,
    /// Capsule radius `r`, metres.
    pub radius_m: f64,
    /// Euler (MuJoCo's default) or RK4.
    pub integrator: Integrator,
}

impl Default for PendulumParams {
    fn default() -> Self {
        PendulumParams {
            duration_s: 5.0,
            damping: 0.05,
            angle_deg: 120.0,
            timestep_s: 0.002,
            length_m: 0.3,
            mass_kg: 0.2,
            radius_m: 0.01,
            integrator: Integrator::Euler,
        }
    }
}

impl PendulumParams {
    /// Checks the model (what [`Pendulum::new`] needs) without the run length: positive
    /// timestep, length, mass and radius, non-negative damping, finite angle.
    pub fn validate_model(&self) -> Result<(), RecipeError> {
        for (spec, value) in [
            (&FLAG_TIMESTEP, self.timestep_s),
            (&FLAG_LENGTH, self.length_m),
            (&FLAG_MASS, self.mass_kg),
            (&FLAG_RADIUS, self.radius_m),
        ] {
            finite(spec.name, value)?;
            positive(spec.name, value)?;
        }
        finite(FLAG_DAMPING.name, self.damping)?;
        in_range(FLAG_DAMPING.name, self.damping, 0.0, f64::INFINITY)?;
        finite(FLAG_ANGLE.name, self.angle_deg)?;
        let inertia = capsule_joint_inertia(self.length_m, self.mass_kg, self.radius_m);
        if !(inertia.is_finite() && inertia > 0.0) {
            // Extreme sizes (a radius of 1e-200 m...) under- or overflow the capsule formula.
            return Err(RecipeError::OutOfRange {
                param: FLAG_RADIUS.name.to_string(),
                value: self.radius_m,
                min: 0.0,
                max: f64::INFINITY,
            });
        }
        Ok(())
    }

    /// Checks everything and returns the number of steps, `int(duration_s / timestep_s)`:
    /// at least 1 (the recipe cannot report a drift without rows) and at most [`MAX_STEPS`].
    pub fn validate(&self) -> Result<u64, RecipeError> {
        finite(ARGS[0].name, self.duration_s)?;
        positive(ARGS[0].name, self.duration_s)?;
        self.validate_model()?;
        let steps = rows_within(
            ARGS[0].name,
            &[FLAG_TIMESTEP.name],
            (self.duration_s / self.timestep_s).trunc(),
            MAX_STEPS,
        )?;
        if steps == 0 {
            return Err(RecipeError::OutOfRange {
                param: ARGS[0].name.to_string(),
                value: self.duration_s,
                min: self.timestep_s,
                max: self.timestep_s * MAX_STEPS as f64,
            });
        }
        Ok(steps)
    }

    /// Reads the recipe's positional argument and flags.
    pub fn from_args(args: &Args) -> Result<PendulumParams, RecipeError> {
        Ok(PendulumParams {
            duration_s: args.f64(0, &ARGS[0])?,
            damping: args.flag_f64(&FLAG_DAMPING)?,
            angle_deg: args.flag_f64(&FLAG_ANGLE)?,
            timestep_s: args.flag_f64(&FLAG_TIMESTEP)?,
            length_m: args.flag_f64(&FLAG_LENGTH)?,
            mass_kg: args.flag_f64(&FLAG_MASS)?,
            radius_m: args.flag_f64(&FLAG_RADIUS)?,
            integrator: Integrator::parse(args.flag_text(&FLAG_INTEGRATOR))?,
        })
    }
}

/// Joint inertia of the capsule about the hinge, with MuJoCo's capsule formula (see module
/// docs): `Iyy_com + m (L/2)²`.
pub fn capsule_joint_inertia(length_m: f64, mass_kg: f64, radius_m: f64) -> f64 {
    let (l, r, m) = (length_m, radius_m, mass_kg);
    let pi = std::f64::consts::PI;
    let cylinder_volume = pi * r * r * l;
    let sphere_volume = 4.0 * pi * r * r * r / 3.0;
    let density = m / (cylinder_volume + sphere_volume);
    let cylinder_mass = density * cylinder_volume;
    let sphere_mass = density * sphere_volume;
    let iyy_com = cylinder_mass * (3.0 * r * r + l * l) / 12.0
        + sphere_mass * (2.0 * r * r / 5.0 + l * l / 4.0 + 3.0 * l * r / 8.0);
    iyy_com + m * (l / 2.0) * (l / 2.0)
}

/// One step's results: the recipe's CSV row plus the true energy.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PendulumRow {
    /// `i h` for the `i`-th step (0-based), as the recipe writes it.
    pub t_s: f64,
    /// Angle after the step, radians from hanging down.
    pub theta: f64,
    /// Angular velocity after the step, rad/s.
    pub omega: f64,
    /// Recipe's kinetic energy `½ m (L ω)²`, J (tip point mass).
    pub ke: f64,
    /// Recipe's potential energy `m g (z_tip + L)`, J, at the angle MuJoCo last evaluated.
    pub pe: f64,
    /// `ke + pe`, J.
    pub total: f64,
    /// Capsule's mechanical energy `½ I ω² + m g (L/2)(1 − cos θ)`, J, after the step.
    pub true_energy: f64,
}

/// A swinging pendulum: build it once, call [`Pendulum::step`] per frame. The recipe run uses
/// the same handle.
///
/// # Example
/// ```
/// use bsv_playground::recipes::pendulum_energy::{Pendulum, PendulumParams};
/// let params = PendulumParams::default();
/// let mut pendulum = Pendulum::new(&params).unwrap();
/// let row = pendulum.step();
/// // The recipe's first row: potential energy at the starting 120°, m g (L + L/2).
/// assert!((row.pe - 0.2 * 9.81 * 0.45).abs() < 1e-12);
/// assert!(row.omega < 0.0 && pendulum.steps_taken() == 1);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Pendulum {
    params: PendulumParams,
    inertia: f64,
    theta: f64,
    omega: f64,
    /// Angle at which positions were last evaluated (MuJoCo's `site_xpos`).
    theta_evaluated: f64,
    steps_taken: u64,
}

impl Pendulum {
    /// The pendulum at rest at `angle_deg`, after [`PendulumParams::validate_model`] (the
    /// run length is not checked: a handle steps as long as it is asked to).
    pub fn new(params: &PendulumParams) -> Result<Pendulum, RecipeError> {
        params.validate_model()?;
        let theta = params.angle_deg.to_radians();
        Ok(Pendulum {
            params: *params,
            inertia: capsule_joint_inertia(params.length_m, params.mass_kg, params.radius_m),
            theta,
            omega: 0.0,
            theta_evaluated: theta,
            steps_taken: 0,
        })
    }

    /// The parameters it was built with.
    pub fn params(&self) -> &PendulumParams {
        &self.params
    }

    /// Joint inertia about the hinge, kg·m².
    pub fn joint_inertia(&self) -> f64 {
        self.inertia
    }

    /// Current angle, radians from hanging down.
    pub fn theta(&self) -> f64 {
        self.theta
    }

    /// Current angular velocity, rad/s.
    pub fn omega(&self) -> f64 {
        self.omega
    }

    /// Steps taken so far.
    pub fn steps_taken(&self) -> u64 {
        self.steps_taken
    }

    /// Simulated time of the current state, `steps_taken · h`, seconds.
    pub fn time_s(&self) -> f64 {
        self.steps_taken as f64 * self.params.timestep_s
    }

    /// Tip position `(x, z)` in metres for the current angle: `(−L sin θ, −L cos θ)`.
    pub fn tip_xz(&self) -> (f64, f64) {
        let l = self.params.length_m;
        (
            -l * crate::math::sin(self.theta),
            -l * crate::math::cos(self.theta),
        )
    }

    /// Capsule's mechanical energy of the current state (see [`PendulumRow::true_energy`]).
    pub fn true_energy(&self) -> f64 {
        let p = &self.params;
        let z_com = p.length_m / 2.0 * (1.0 - crate::math::cos(self.theta));
        0.5 * self.inertia * self.omega * self.omega + p.mass_kg * GRAVITY * z_com
    }

    fn gravity_torque(&self, theta: f64) -> f64 {
        let p = &self.params;
        -p.mass_kg * GRAVITY * (p.length_m / 2.0) * crate::math::sin(theta)
    }

    /// `a(θ, ω)` with explicit damping.
    fn acceleration(&self, theta: f64, omega: f64) -> f64 {
        (self.gravity_torque(theta) - self.params.damping * omega) / self.inertia
    }

    /// Advances one step of `h` and returns the recipe's row for it.
    pub fn step(&mut self) -> PendulumRow {
        let h = self.params.timestep_s;
        let row_index = self.steps_taken;
        match self.params.integrator {
            Integrator::Euler => {
                let b = self.params.damping;
                // mj_forward at the current state, then implicit-damping Euler.
                self.theta_evaluated = self.theta;
                let acc =
                    (self.gravity_torque(self.theta) - b * self.omega) / (self.inertia + h * b);
                self.omega += h * acc;
                self.theta += h * self.omega;
            }
            Integrator::Rk4 => {
                let (theta0, omega0) = (self.theta, self.omega);
                let k1 = self.acceleration(theta0, omega0);
                let (theta1, omega1) = (theta0 + h * (0.5 * omega0), omega0 + h * (0.5 * k1));
                let k2 = self.acceleration(theta1, omega1);
                let (theta2, omega2) = (theta0 + h * (0.5 * omega1), omega0 + h * (0.5 * k2));
                let k3 = self.acceleration(theta2, omega2);
                let (theta3, omega3) = (theta0 + h * omega2, omega0 + h * k3);
                let k4 = self.acceleration(theta3, omega3);
                // MuJoCo's last mj_forward was at the fourth stage.
                self.theta_evaluated = theta3;
                let (b0, b1) = (1.0 / 6.0, 1.0 / 3.0);
                let d_theta = b0 * omega0 + b1 * omega1 + b1 * omega2 + b0 * omega3;
                let d_omega = b0 * k1 + b1 * k2 + b1 * k3 + b0 * k4;
                self.theta = theta0 + h * d_theta;
                self.omega = omega0 + h * d_omega;
            }
        }
        self.steps_taken += 1;
        let p = &self.params;
        let l = p.length_m;
        let z_tip = -l * crate::math::cos(self.theta_evaluated);
        let pe = p.mass_kg * GRAVITY * (z_tip + l);
        let ke = 0.5 * p.mass_kg * (l * self.omega) * (l * self.omega);
        PendulumRow {
            t_s: row_index as f64 * h,
            theta: self.theta,
            omega: self.omega,
            ke,
            pe,
            total: ke + pe,
            true_energy: self.true_energy(),
        }
    }
}

/// All rows of a run: `int(duration / h)` steps from the starting angle.
pub fn simulate(params: &PendulumParams) -> Result<Vec<PendulumRow>, RecipeError> {
    simulate_with(params, &mut Progress::silent())
}

/// [`simulate`] reporting its steps as the first half of `progress`.
pub fn simulate_with(
    params: &PendulumParams,
    progress: &mut Progress,
) -> Result<Vec<PendulumRow>, RecipeError> {
    let steps = params.validate()?;
    let mut pendulum = Pendulum::new(params)?;
    Ok((0..steps)
        .map(|k| {
            progress.phase_at(0, 2, k, steps);
            pendulum.step()
        })
        .collect())
}

/// Relative growth of the body's true energy above its start (in %) beyond which a run is
/// reported: damping only removes energy, so growth is the integrator's error.
pub const ENERGY_GROWTH_WARN_PERCENT: f64 = 1.0;

/// What looks wrong with a run: the body's true energy grew (the step is too large).
pub fn warnings(params: &PendulumParams, rows: &[PendulumRow]) -> Vec<RecipeWarning> {
    let Ok(start) = Pendulum::new(params).map(|p| p.true_energy()) else {
        return Vec::new();
    };
    let peak = rows
        .iter()
        .map(|r| r.true_energy)
        .fold(f64::NEG_INFINITY, f64::max);
    // Energy is measured from the lowest point: a start at rest hanging down has none.
    if start > 0.0 && peak.is_finite() {
        let percent = (peak - start) / start * 100.0;
        if percent > ENERGY_GROWTH_WARN_PERCENT {
            return vec![RecipeWarning::EnergyGrows { percent }];
        }
    }
    Vec::new()
}

/// `max(total) − min(total)` over the rows, the figure the recipe prints (0 without rows).
pub fn energy_drift(rows: &[PendulumRow]) -> f64 {
    let mut totals = rows.iter().map(|r| r.total);
    let Some(first) = totals.next() else {
        return 0.0;
    };
    let (lo, hi) = totals.fold((first, first), |(lo, hi), v| (lo.min(v), hi.max(v)));
    hi - lo
}

/// Runs the recipe: the CSV and the line the Python recipe prints.
pub fn run(params: &PendulumParams) -> Result<RecipeOutput, RecipeError> {
    run_with(params, &mut Progress::silent())
}

/// [`run`] reporting steps, then CSV rows, to `progress`.
pub fn run_with(
    params: &PendulumParams,
    progress: &mut Progress,
) -> Result<RecipeOutput, RecipeError> {
    let rows = simulate_with(params, progress)?;
    let table = rows
        .iter()
        .map(|r| [r.t_s, r.theta, r.omega, r.ke, r.pe, r.total]);
    let csv = float_csv_with(&CSV_HEADER, table, progress);
    let summary = format!(
        "wrote {} rows -> {CSV_NAME}; energy range drift≈{} J (damping present)",
        rows.len(),
        fixed(energy_drift(&rows), 6)
    );
    Ok(RecipeOutput::single(CSV_NAME, csv, summary).with_warnings(warnings(params, &rows)))
}

/// Reads the recipe's positional argument and flags and validates them.
pub fn params_from_args(args: &Args) -> Result<PendulumParams, RecipeError> {
    let params = PendulumParams::from_args(args)?;
    params.validate()?;
    Ok(params)
}

/// The recipe's uniform entry ([`Kernel`]).
pub struct Entry;

impl Kernel for Entry {
    type Params = PendulumParams;
    const INFO: &'static RecipeInfo = &INFO;

    fn params(args: &Args) -> Result<PendulumParams, RecipeError> {
        params_from_args(args)
    }

    fn rows(params: &PendulumParams, _args: &Args) -> Result<u64, RecipeError> {
        params.validate()
    }

    fn run(params: &PendulumParams, _args: &Args, progress: &mut Progress) -> RunResult {
        run_with(params, progress)
    }
}

/// The home card's picture: the kinetic, potential and total energy over time.
pub fn picture(output: &RecipeOutput, _aspect: f64) -> Option<Picture> {
    let t = Table::parse(output.file(CSV_NAME)?)?;
    let x = t.col("t_s")?;
    Some(lines(
        &x,
        &[
            (&t.col("ke_j")?, ORANGE),
            (&t.col("pe_j")?, GREEN),
            (&t.col("total_j")?, BLUE),
        ],
    ))
}

#[cfg(test)]
mod tests {
    #[cfg(target_arch = "wasm32")]
    use wasm_bindgen_test::wasm_bindgen_test as test;

    use super::*;
    use crate::recipes::kernel::run_of;
    use crate::recipes::testkit::args_strs;

    #[test]
    fn first_row_matches_mujoco() {
        // pendulum_default golden, row 0: pe from the starting angle (120°), z_tip = +0.15 m.
        let mut p = Pendulum::new(&PendulumParams::default()).unwrap();
        let row = p.step();
        assert_eq!(row.t_s, 0.0);
        assert!((row.theta - 2.0942317851818606).abs() < 1e-14);
        assert!((row.omega - -0.08165860566743176).abs() < 1e-14);
        assert!((row.pe - 0.8829).abs() < 1e-14);
        assert_eq!(p.steps_taken(), 1);
    }

    #[test]
    fn undamped_true_energy_is_conserved_by_rk4_but_not_the_recipe_energy() {
        let params = PendulumParams {
            damping: 0.0,
            integrator: Integrator::Rk4,
            ..PendulumParams::default()
        };
        let rows = simulate(&params).unwrap();
        let e0 = Pendulum::new(&params).unwrap().true_energy();
        let worst = rows
            .iter()
            .map(|r| (r.true_energy - e0).abs())
            .fold(0.0, f64::max);
        assert!(worst < 1e-8 * e0, "true energy drift {worst}");
        // The tip point-mass "energy" swings by far more, even without damping.
        assert!(energy_drift(&rows) > 1e-3);
    }

    #[test]
    fn damping_drains_the_true_energy() {
        let rows = simulate(&PendulumParams::default()).unwrap();
        let first = rows.first().unwrap().true_energy;
        let last = rows.last().unwrap().true_energy;
        assert!(last < 0.9 * first, "{first} -> {last}");
    }

    #[test]
    fn hanging_at_rest_has_zero_energy_and_stays() {
        let params = PendulumParams {
            angle_deg: 0.0,
            ..PendulumParams::default()
        };
        let mut p = Pendulum::new(&params).unwrap();
        assert_eq!(p.true_energy(), 0.0);
        let row = p.step();
        assert_eq!((row.theta, row.omega, row.total), (0.0, 0.0, 0.0));
    }

    #[test]
    fn row_count_and_summary() {
        let out = run_of::<Entry>(&args_strs::<Entry>(&["0.1"]).unwrap()).unwrap();
        let csv = out.file(CSV_NAME).unwrap();
        assert_eq!(csv.lines().count(), 1 + 50);
        assert!(out
            .summary
            .starts_with("wrote 50 rows -> pendulum_energy.csv; energy range"));
        assert!(out.summary.ends_with(" J (damping present)"));
        // Same text without damping, as the recipe prints.
        let out =
            run_of::<Entry>(&args_strs::<Entry>(&["0.1", "--damping", "0"]).unwrap()).unwrap();
        assert!(out.summary.ends_with(" J (damping present)"));
    }

    #[test]
    fn rejects_bad_parameters() {
        let err = |raw: &[&str]| run_of::<Entry>(&args_strs::<Entry>(raw).unwrap()).unwrap_err();
        assert!(matches!(err(&["0"]), RecipeError::NotPositive { .. }));
        assert!(matches!(err(&["0.001"]), RecipeError::OutOfRange { .. }));
        assert!(matches!(
            err(&["5000"]),
            RecipeError::TooLarge {
                count: 2_500_000,
                limit: MAX_STEPS,
                ..
            }
        ));
        assert!(
            matches!(err(&["1", "--timestep", "0"]), RecipeError::NotPositive { param, .. } if param == "timestep")
        );
        assert!(
            matches!(err(&["1", "--length", "-1"]), RecipeError::NotPositive { param, .. } if param == "length")
        );
        assert!(
            matches!(err(&["1", "--mass", "0"]), RecipeError::NotPositive { param, .. } if param == "mass")
        );
        assert!(
            matches!(err(&["1", "--radius", "0"]), RecipeError::NotPositive { param, .. } if param == "radius")
        );
        assert!(
            matches!(err(&["1", "--damping", "-0.1"]), RecipeError::OutOfRange { param, .. } if param == "damping")
        );
        assert!(
            matches!(err(&["1", "--angle-deg", "inf"]), RecipeError::NotFinite { param } if param == "angle-deg")
        );
        assert!(
            matches!(err(&["1", "--integrator", "verlet"]), RecipeError::BadChoice { param, .. } if param == "integrator")
        );
        assert!(matches!(
            err(&["1e308", "--timestep", "1e-308"]),
            RecipeError::TooLarge { .. }
        ));
    }

    #[test]
    fn integrator_names() {
        assert_eq!(Integrator::parse("RK4").unwrap(), Integrator::Rk4);
        assert_eq!(Integrator::parse("Euler").unwrap(), Integrator::Euler);
    }
}
