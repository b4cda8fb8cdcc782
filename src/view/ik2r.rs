//! The IK page's pure view models (`#/ik-2r`): its state and URL form, its form's fields (the
//! recipes' arguments, checked by [`Params::from_texts`]), the arm view's world ↔ screen transform, the hit tests of
//! tip, elbow and links, the link label placement, the heatmap grid, the Jacobian sweep that
//! is plotted, the readout texts and the export command lines. No web-sys: `cargo test` runs
//! all of it.
//!
//! URL: `#/ik-2r?L1=0.12&L2=0.1&q1=0.3&q2=0.8&elbow=down&ws=1&...`. Every value is validated
//! the way the form checks it (its argument's limits, then the kernels' checks of the whole
//! set); a URL value that fails is ignored (the
//! default stays) and its key is reported so that the page can say so. Numbers are written in
//! Rust's shortest round-trip form, so opening a URL restores the exact `f64`s it was made
//! from.

use std::f64::consts::PI;

use glam::{DAffine2, DVec2};

use crate::args::{parse_f64, ArgSpec};
use crate::error::RecipeError;
use crate::numtext;
use crate::planar2r::{wrap_angle, Arm, ArmShape, Elbow, PoseReport};
use crate::recipes::ik_workspace::{self, WorkspaceParams};
use crate::recipes::jacobian_2r::{self, SweepParams};
use crate::recipes::manip_grid::{self, GridParams};
use crate::view::command_line::RunArgs;
use crate::view::drag::HandleShape;
use crate::view::form::FieldDef;
use crate::view::heatmap::GridAxis;
use crate::view::url::{IgnoredKey, UrlState};

/// The page's own starting values; the recipe parameters' defaults come from the kernels
/// (`WorkspaceParams::default()`, `SweepParams::default()`, `GridParams::default()`).
pub mod defaults {
    /// Starting pose (rad): q2 is the jacobian-2r recipe's fixed 0.8.
    pub const Q1: f64 = 0.3;
    pub const Q2: f64 = 0.8;
    /// Heatmap cells per axis.
    pub const HEATMAP_N: i64 = 256;
}

/// The page's own argument: the heatmap's cells per axis (it only changes the picture; the
/// recipes' arguments come from their kernels, see [`Field::spec`]).
pub static HEATMAP_RES: ArgSpec =
    ArgSpec::integer("res", "256", "heatmap cells per axis", 64, 1024)
        .unit("cells")
        .hint("ik2r-hint-res");

/// How the workspace grid cells are coloured.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum WsColor {
    /// Reachable or not.
    Reach,
    /// |det J| of the elbow-down solution.
    Manip,
    /// FK round-trip error (log scale).
    Error,
}

impl WsColor {
    /// The URL / `<select>` value.
    pub fn key(self) -> &'static str {
        match self {
            WsColor::Reach => "reach",
            WsColor::Manip => "manip",
            WsColor::Error => "err",
        }
    }

    /// Parses a URL / `<select>` value.
    pub fn from_key(key: &str) -> Option<WsColor> {
        match key {
            "reach" => Some(WsColor::Reach),
            "manip" => Some(WsColor::Manip),
            "err" => Some(WsColor::Error),
            _ => None,
        }
    }
}

/// The recipe parameters the form edits (always valid: the form only stores valid values).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Params {
    pub l1: f64,
    pub l2: f64,
    pub half_mm: f64,
    pub step_mm: f64,
    pub q1_start: f64,
    pub q1_stop: f64,
    pub q1_step: f64,
    pub heatmap_n: usize,
    pub manip_n: i64,
}

impl Default for Params {
    fn default() -> Self {
        let ws = WorkspaceParams::default();
        let sweep = SweepParams::default();
        Params {
            l1: ws.l1,
            l2: ws.l2,
            half_mm: ws.half_mm,
            step_mm: ws.step_mm,
            q1_start: sweep.q1_start,
            q1_stop: sweep.q1_stop,
            q1_step: sweep.q1_step,
            heatmap_n: defaults::HEATMAP_N as usize,
            manip_n: GridParams::default().n,
        }
    }
}

impl Params {
    /// The arm these lengths make.
    pub fn arm(&self) -> Arm {
        Arm {
            l1: self.l1,
            l2: self.l2,
        }
    }

    /// The ik-workspace recipe's parameters.
    pub fn workspace(&self) -> WorkspaceParams {
        WorkspaceParams {
            l1: self.l1,
            l2: self.l2,
            half_mm: self.half_mm,
            step_mm: self.step_mm,
        }
    }

    /// The jacobian-2r recipe's parameters at elbow angle `q2`.
    pub fn sweep(&self, q2: f64) -> SweepParams {
        SweepParams {
            l1: self.l1,
            l2: self.l2,
            q1_start: self.q1_start,
            q1_stop: self.q1_stop,
            q1_step: self.q1_step,
            q2,
        }
    }

    /// The manip-grid recipe's parameters.
    pub fn grid(&self) -> GridParams {
        GridParams {
            l1: self.l1,
            l2: self.l2,
            n: self.manip_n,
        }
    }

    /// Runs the three kernels' own validation (sizes, ranges, `q1_stop >= q1_start`).
    pub fn check_kernels(&self) -> Result<(), RecipeError> {
        self.workspace().validate()?;
        self.sweep(0.0).validate()?;
        self.grid().validate()
    }
}

/// One editable parameter: its URL key (also the form field's key and the name in
/// error messages).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Field {
    L1,
    L2,
    HalfMm,
    StepMm,
    Q1Start,
    Q1Stop,
    Q1Step,
    HeatmapN,
    ManipN,
}

impl Field {
    /// All fields, in form order.
    pub const ALL: [Field; 9] = [
        Field::L1,
        Field::L2,
        Field::HalfMm,
        Field::StepMm,
        Field::Q1Start,
        Field::Q1Stop,
        Field::Q1Step,
        Field::HeatmapN,
        Field::ManipN,
    ];

    /// URL key and the parameter name used in error messages (the recipes' names).
    pub fn key(self) -> &'static str {
        match self {
            Field::L1 => "L1",
            Field::L2 => "L2",
            Field::HalfMm => "half_mm",
            Field::StepMm => "step_mm",
            Field::Q1Start => "q1_start",
            Field::Q1Stop => "q1_stop",
            Field::Q1Step => "q1_step",
            Field::HeatmapN => "res",
            Field::ManipN => "n",
        }
    }

    /// The argument this field sets, as its recipe states it (L1, L2 as all three 2R recipes
    /// take them; the heatmap resolution is the page's [`HEATMAP_RES`]).
    pub fn spec(self) -> &'static ArgSpec {
        let info = match self {
            Field::L1 | Field::L2 | Field::HalfMm | Field::StepMm => &ik_workspace::INFO,
            Field::Q1Start | Field::Q1Stop | Field::Q1Step => &jacobian_2r::INFO,
            Field::ManipN => &manip_grid::INFO,
            Field::HeatmapN => return &HEATMAP_RES,
        };
        let key = self.key();
        info.args
            .iter()
            .find(|a| a.name == key)
            .unwrap_or(&HEATMAP_RES)
    }

    /// The fieldset of the form it sits in: arm, workspace grid, Jacobian sweep, maps.
    pub fn group(self) -> usize {
        match self {
            Field::L1 | Field::L2 => 0,
            Field::HalfMm | Field::StepMm => 1,
            Field::Q1Start | Field::Q1Stop | Field::Q1Step => 2,
            Field::HeatmapN | Field::ManipN => 3,
        }
    }

    /// The form field (label `ik2r-field-<key>`, the recipe's hint and default).
    pub fn def(self) -> FieldDef {
        FieldDef {
            spec: self.spec(),
            flag: false,
            label_id: format!("ik2r-field-{}", self.key()),
            group: self.group(),
        }
    }

    /// The field's current value in `p`, as text (shortest round-trip form).
    pub fn text(self, p: &Params) -> String {
        match self {
            Field::L1 => num(p.l1),
            Field::L2 => num(p.l2),
            Field::HalfMm => num(p.half_mm),
            Field::StepMm => num(p.step_mm),
            Field::Q1Start => num(p.q1_start),
            Field::Q1Stop => num(p.q1_stop),
            Field::Q1Step => num(p.q1_step),
            Field::HeatmapN => p.heatmap_n.to_string(),
            Field::ManipN => p.manip_n.to_string(),
        }
    }
}

/// Shortest text that parses back to the same `f64` (`0.1`, `200`, `-1.57`).
pub fn num(v: f64) -> String {
    format!("{v}")
}

/// The form's fields, in [`Field::ALL`] order.
pub fn form_fields() -> Vec<FieldDef> {
    Field::ALL.iter().map(|f| f.def()).collect()
}

impl Params {
    /// The text of every field, in [`Field::ALL`] order.
    pub fn texts(&self) -> Vec<String> {
        Field::ALL.iter().map(|f| f.text(self)).collect()
    }

    /// The parameters the form's texts give (in [`Field::ALL`] order; `None` is the default,
    /// a blank text is not a number), each value checked against its argument's limits, then
    /// the three kernels' checks of the whole set, so that every download made from them
    /// succeeds. This is the form's check for `crate::view::form::validate`.
    pub fn from_texts(texts: &[Option<String>]) -> Result<Params, RecipeError> {
        let mut p = Params::default();
        for (field, text) in Field::ALL.iter().zip(texts) {
            if let Some(text) = text {
                p = validate_value(&p, *field, text)?;
            }
        }
        p.check_kernels()?;
        Ok(p)
    }
}

/// `p` with `text` for `field`, checked against the field's own limits ([`ArgSpec::check_text`]:
/// a number, a whole number in any notation), or the error (`p` itself never changes).
fn validate_value(p: &Params, field: Field, text: &str) -> Result<Params, RecipeError> {
    let v = field.spec().check_text(text)?;
    let mut next = *p;
    match field {
        Field::L1 => next.l1 = v,
        Field::L2 => next.l2 = v,
        Field::HalfMm => next.half_mm = v,
        Field::StepMm => next.step_mm = v,
        Field::Q1Start => next.q1_start = v,
        Field::Q1Stop => next.q1_stop = v,
        Field::Q1Step => next.q1_step = v,
        Field::HeatmapN => next.heatmap_n = v as usize,
        Field::ManipN => next.manip_n = v as i64,
    }
    Ok(next)
}

/// Most rows of the Jacobian sweep (the kernel's limit).
pub const SWEEP_ROWS_MAX: u64 = jacobian_2r::MAX_SAMPLES;

/// The page's state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct State {
    pub params: Params,
    /// Joint angles (rad), as IK returned them or as dragged.
    pub q1: f64,
    pub q2: f64,
    /// The IK branch used for tip drags and arrow keys.
    pub elbow: Elbow,
    /// Workspace grid shown over the arm view.
    pub show_ws: bool,
    pub ws_color: WsColor,
}

impl Default for State {
    fn default() -> Self {
        State {
            params: Params::default(),
            q1: defaults::Q1,
            q2: defaults::Q2,
            elbow: Elbow::Down,
            show_ws: false,
            ws_color: WsColor::Reach,
        }
    }
}

impl State {
    /// The whole state as URL query pairs (the router adds `lang`).
    pub fn query_pairs(&self) -> Vec<(&'static str, String)> {
        let mut q: Vec<(&'static str, String)> = Field::ALL
            .iter()
            .map(|f| (f.key(), f.text(&self.params)))
            .collect();
        q.push(("q1", num(self.q1)));
        q.push(("q2", num(self.q2)));
        q.push((
            "elbow",
            match self.elbow {
                Elbow::Down => "down",
                Elbow::Up => "up",
            }
            .to_string(),
        ));
        q.push(("ws", if self.show_ws { "1" } else { "0" }.to_string()));
        q.push(("wsc", self.ws_color.key().to_string()));
        q
    }

    /// Restores a state from URL query pairs. Unknown keys are left alone (other pages' or
    /// the shell's); values that fail validation are skipped and their keys returned.
    pub fn from_query(query: &[(String, String)]) -> (State, Vec<String>) {
        let mut state = State::default();
        let mut ignored = Vec::new();
        let get = |key: &str| {
            query
                .iter()
                .find(|(k, _)| k == key)
                .map(|(_, v)| v.as_str())
        };
        for field in Field::ALL {
            if let Some(text) = get(field.key()) {
                match validate_value(&state.params, field, text) {
                    Ok(p) => state.params = p,
                    Err(_) => ignored.push(field.key().to_string()),
                }
            }
        }
        // Limits that involve several values (grid size, sweep length and order): a
        // combination the kernels reject falls back to the defaults of the values involved.
        let d = Params::default();
        if state.params.workspace().validate().is_err() {
            state.params.half_mm = d.half_mm;
            state.params.step_mm = d.step_mm;
            ignored.extend(["half_mm".to_string(), "step_mm".to_string()]);
        }
        if state.params.sweep(0.0).validate().is_err() {
            state.params.q1_start = d.q1_start;
            state.params.q1_stop = d.q1_stop;
            state.params.q1_step = d.q1_step;
            ignored.extend(["q1_start", "q1_stop", "q1_step"].map(String::from));
        }
        for key in ["q1", "q2"] {
            if let Some(text) = get(key) {
                match parse_f64(key, text) {
                    Ok(v) if v.abs() <= 100.0 => {
                        if key == "q1" {
                            state.q1 = v;
                        } else {
                            state.q2 = v;
                        }
                    }
                    _ => ignored.push(key.to_string()),
                }
            }
        }
        match get("elbow") {
            Some("down") => state.elbow = Elbow::Down,
            Some("up") => state.elbow = Elbow::Up,
            Some(_) => ignored.push("elbow".to_string()),
            None => {
                // Without an explicit branch, the pose's q2 decides it.
                state.elbow = elbow_of(state.q2);
            }
        }
        match get("ws") {
            Some("1") => state.show_ws = true,
            Some("0") => state.show_ws = false,
            Some(_) => ignored.push("ws".to_string()),
            None => {}
        }
        if let Some(text) = get("wsc") {
            match WsColor::from_key(text) {
                Some(c) => state.ws_color = c,
                None => ignored.push("wsc".to_string()),
            }
        }
        (state, ignored)
    }
}

/// The branch a pose is on: `q2 >= 0` (wrapped) is elbow-down, the recipes' branch.
pub fn elbow_of(q2: f64) -> Elbow {
    if crate::planar2r::wrap_angle(q2) >= 0.0 {
        Elbow::Down
    } else {
        Elbow::Up
    }
}

impl UrlState for State {
    /// [`State::from_query`]: values that fail are reported as invalid, keys the page does
    /// not have as unknown.
    fn read(query: &[(String, String)]) -> (State, Vec<IgnoredKey>) {
        let (state, ignored) = State::from_query(query);
        let known = state.query_pairs();
        let unknown = query
            .iter()
            .filter(|(key, _)| !known.iter().any(|(k, _)| k == key))
            .map(|(key, _)| IgnoredKey::unknown(key.clone()));
        let ignored = ignored.into_iter().map(IgnoredKey::invalid).chain(unknown);
        (state, ignored.collect())
    }

    fn write(&self) -> Vec<(String, String)> {
        self.query_pairs()
            .into_iter()
            .map(|(k, v)| (k.to_string(), v))
            .collect()
    }
}

impl Field {
    /// The field whose URL key is `key`.
    pub fn from_key(key: &str) -> Option<Field> {
        Field::ALL.into_iter().find(|f| f.key() == key)
    }
}

// ---------- Arm view: transform, hit tests, labels ----------

/// Drawn ellipse semi-axis = `ELLIPSE_SCALE · σ` metres.
pub const ELLIPSE_SCALE: f64 = 0.25;

/// World (m) ↔ screen (CSS px) for the arm view: the base at the centre, y up.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ViewXf {
    pub to_screen: DAffine2,
    pub to_world: DAffine2,
    /// CSS pixels per metre.
    pub px_per_m: f64,
}

impl ViewXf {
    /// Fits a disc of radius `extent_m` around the base into a `w × h` CSS-pixel view.
    pub fn fit(w: f64, h: f64, extent_m: f64) -> ViewXf {
        let extent = if extent_m.is_finite() && extent_m > 0.0 {
            extent_m
        } else {
            1.0
        };
        let s = (w.min(h) / 2.0 - 6.0).max(1.0) / extent;
        let origin = DVec2::new((w / 2.0).round(), (h / 2.0).round());
        let to_screen = DAffine2::from_cols(DVec2::new(s, 0.0), DVec2::new(0.0, -s), origin);
        ViewXf {
            to_screen,
            to_world: to_screen.inverse(),
            px_per_m: s,
        }
    }

    /// Screen point of a world point.
    pub fn screen(&self, x: f64, y: f64) -> DVec2 {
        self.to_screen.transform_point2(DVec2::new(x, y))
    }

    /// World point of a screen point.
    pub fn world(&self, p: DVec2) -> DVec2 {
        self.to_world.transform_point2(p)
    }

    /// The base (world origin) on screen.
    pub fn origin(&self) -> DVec2 {
        self.to_screen.translation
    }
}

/// The view radius (m) for an arm, widened to show the workspace grid when it is on.
pub fn extent_m(arm: &Arm, ws_half_m: Option<f64>) -> f64 {
    let reach = arm.l1 + arm.l2;
    // A grid far larger than the arm would shrink the arm to a dot: show at most 3 reaches.
    let ws = ws_half_m.map_or(0.0, |h| h.min(3.0 * reach));
    reach.max(ws) * 1.08
}

/// A 1-2-5 step (mm) giving about six grid lines from the base to the edge.
pub fn grid_step_mm(extent_m: f64) -> f64 {
    let target = extent_m * 1000.0 / 6.0;
    let mag = 10f64.powf(target.log10().floor());
    for m in [1.0, 2.0, 5.0, 10.0] {
        if m * mag >= target {
            return m * mag;
        }
    }
    10.0 * mag
}

/// A grid label in millimetres: whole numbers without a decimal point.
pub fn format_mm(v: f64) -> String {
    let r = (v * 1000.0).round() / 1000.0;
    if r == r.trunc() {
        format!("{}", r as i64)
    } else {
        format!("{r}")
    }
}

/// What a pointer grabbed on the arm.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Grab {
    /// The tip: IK follows the pointer.
    Tip,
    /// The elbow joint or link 1: q1 follows.
    Q1,
    /// Link 2: q2 follows.
    Q2,
}

/// Screen positions of base, elbow and tip.
pub fn joints_on_screen(xf: &ViewXf, arm: &impl ArmShape, q1: f64, q2: f64) -> [DVec2; 3] {
    let (ex, ey) = arm.elbow(q1);
    let (tx, ty) = arm.fk(q1, q2);
    [xf.origin(), xf.screen(ex, ey), xf.screen(tx, ty)]
}

/// Hit radius (CSS px) of the tip for a mouse; touch targets are wider.
pub const HIT_MOUSE_PX: f64 = 16.0;
/// Hit radius (CSS px) of the tip for a finger.
pub const HIT_TOUCH_PX: f64 = 26.0;

/// The draggable parts of the arm as hit shapes, in the order they are tested (the tip
/// first: it wins where parts overlap).
pub fn handles(
    xf: &ViewXf,
    arm: &impl ArmShape,
    q1: f64,
    q2: f64,
    touch: bool,
) -> [(Grab, HandleShape); 4] {
    let [base, elbow, tip] = joints_on_screen(xf, arm, q1, q2);
    let r = if touch { HIT_TOUCH_PX } else { HIT_MOUSE_PX };
    [
        (
            Grab::Tip,
            HandleShape::Circle {
                centre: tip,
                radius: r,
            },
        ),
        (
            Grab::Q1,
            HandleShape::Circle {
                centre: elbow,
                radius: r * 0.8,
            },
        ),
        (
            Grab::Q2,
            HandleShape::Capsule {
                a: elbow,
                b: tip,
                radius: r * 0.7,
            },
        ),
        (
            Grab::Q1,
            HandleShape::Capsule {
                a: base,
                b: elbow,
                radius: r * 0.7,
            },
        ),
    ]
}

/// The part of the arm under `p`, if any.
pub fn part_at(
    xf: &ViewXf,
    arm: &impl ArmShape,
    q1: f64,
    q2: f64,
    p: DVec2,
    touch: bool,
) -> Option<Grab> {
    handles(xf, arm, q1, q2, touch)
        .into_iter()
        .find(|(_, shape)| shape.contains(p))
        .map(|(grab, _)| grab)
}

/// Which part of the arm a mouse or pen press at `p` grabs: empty space grabs the tip (the
/// tip jumps there by IK), so a click anywhere moves the arm.
pub fn hit_test(xf: &ViewXf, arm: &impl ArmShape, q1: f64, q2: f64, p: DVec2, touch: bool) -> Grab {
    part_at(xf, arm, q1, q2, p, touch).unwrap_or(Grab::Tip)
}

/// Where the "L1" and "L2" labels go (their centres, CSS px): beside the middle of each link,
/// on the outside of the bend, `gap` px from the link. When the arm is folded back the links
/// lie on one line and the outsides are opposite sides, so the labels never overlap.
pub fn link_label_centres(base: DVec2, elbow: DVec2, tip: DVec2, gap: f64) -> [DVec2; 2] {
    let d1 = elbow - base;
    let d2 = tip - elbow;
    let unit = |d: DVec2| {
        let l = d.length();
        if l > 1e-9 {
            d / l
        } else {
            DVec2::X
        }
    };
    let (u1, u2) = (unit(d1), unit(d2));
    let cross = u1.x * u2.y - u1.y * u2.x;
    // Straight or folded: either side is the outside; pick one so both agree.
    let side = if cross >= 0.0 { 1.0 } else { -1.0 };
    let normal = |u: DVec2| DVec2::new(-u.y, u.x);
    [
        (base + elbow) / 2.0 - normal(u1) * side * gap,
        (elbow + tip) / 2.0 - normal(u2) * side * gap,
    ]
}

// ---------- Heatmap: |det J| over (q1, q2) ----------

/// The heatmap's axis: `n` nodes over `[−π, π]` (the manip-grid recipe's sampling).
pub fn heat_axis(n: usize) -> GridAxis {
    GridAxis {
        min: -PI,
        max: PI,
        n: n.max(2),
    }
}

/// `|det J|` of the `n × n` heatmap grid (`values[i * n + j]`, `i` over q1), with the manip-grid
/// kernel's fast path, and the colour scale's top `L1 L2` (the largest any pose reaches).
pub fn heat_fill(arm: &Arm, n: usize, values: &mut Vec<f32>) -> Result<f64, RecipeError> {
    let n = n.max(2);
    values.resize(n * n, 0.0);
    manip_grid::fill_abs_det(arm.l1, arm.l2, n as i64, values)?;
    Ok((arm.l1 * arm.l2).max(f64::MIN_POSITIVE))
}

// ---------- The Jacobian sweep plot ----------

/// One sample of the sweep.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SweepPoint {
    pub q1: f64,
    pub det_j: f64,
    pub manipulability: f64,
    pub sigma_min: f64,
    pub sigma_max: f64,
}

/// Most points the plot draws of a sweep (evenly picked, the last one always).
pub const SWEEP_PLOT_MAX: usize = 1500;

/// The plotted sweep: the recipe's q1 values (at most [`SWEEP_PLOT_MAX`] of them) at `q2`.
pub fn sweep_points(p: &Params, q2: f64) -> Vec<SweepPoint> {
    let Ok(q1s) = crate::numpy::arange(
        p.q1_start,
        p.q1_stop + 1e-12,
        p.q1_step,
        "q1_step",
        SWEEP_ROWS_MAX,
    ) else {
        return Vec::new();
    };
    let stride = q1s.len().div_ceil(SWEEP_PLOT_MAX).max(1);
    let arm = p.arm();
    let point = |q1: f64| {
        let r = arm.report(q1, q2);
        SweepPoint {
            q1,
            det_j: r.det_j,
            manipulability: r.manipulability,
            sigma_min: r.ellipse.sigma_min,
            sigma_max: r.ellipse.sigma_max,
        }
    };
    let mut pts: Vec<SweepPoint> = q1s.iter().step_by(stride).map(|&q1| point(q1)).collect();
    if let (Some(&last), Some(end)) = (q1s.last(), pts.last()) {
        if end.q1 != last {
            pts.push(point(last));
        }
    }
    pts
}

/// The plot's axis ranges: x the sweep, `|det J| ≤ L1 L2` on top, `σ ≤ sqrt((L1 + L2)² + L2²)`
/// below (fixed by the arm, so a drag never rescales the axes).
pub fn sweep_ranges(p: &Params) -> [(f64, f64); 3] {
    let (mut a, mut b) = (p.q1_start.min(p.q1_stop), p.q1_start.max(p.q1_stop));
    if b - a < 1e-9 {
        a -= 0.5;
        b += 0.5;
    }
    let det_max = (p.l1 * p.l2).max(1e-300) * 1.08;
    let sigma_max = ((p.l1 + p.l2).powi(2) + p.l2 * p.l2).sqrt().max(1e-300) * 1.08;
    [(a, b), (-det_max, det_max), (0.0, sigma_max)]
}

/// The q1 to mark on the sweep: the current q1, or the same angle ±2π, if it lies in `x`.
pub fn marker_in_range(q1: f64, x: (f64, f64)) -> Option<f64> {
    let tau = std::f64::consts::TAU;
    [q1, q1 - tau, q1 + tau, wrap_angle(q1)]
        .into_iter()
        .find(|q| (x.0..=x.1).contains(q))
}

// ---------- Readouts ----------

/// The readout names (`data-readout`), in the order [`readout_values`] returns them.
pub const READOUTS: [&str; 14] = [
    "q1",
    "q2",
    "q1_deg",
    "q2_deg",
    "x_mm",
    "y_mm",
    "det_j",
    "manipulability",
    "sigma_min",
    "sigma_max",
    "j11",
    "j12",
    "j21",
    "j22",
];

/// An angle in radians: at least six significant digits and at least six decimals.
pub fn fmt_rad(x: f64) -> String {
    if !x.is_finite() {
        return x.to_string();
    }
    let a = x.abs();
    let decimals = if a > 0.0 {
        (5 - a.log10().floor() as i32).clamp(6, 12) as usize
    } else {
        6
    };
    numtext::unsigned_zero(format!("{x:.decimals$}"))
}

/// `x` with `sig` significant digits; scientific notation below 1e-4 and from 1e6.
pub fn fmt_sig(x: f64, sig: usize) -> String {
    if !x.is_finite() {
        return x.to_string();
    }
    let a = x.abs();
    if a == 0.0 {
        return "0".to_string();
    }
    if !(1e-4..1e6).contains(&a) {
        let d = sig.saturating_sub(1);
        return format!("{x:.d$e}");
    }
    let decimals = (sig as i32 - 1 - a.log10().floor() as i32).max(0) as usize;
    numtext::unsigned_zero(format!("{x:.decimals$}"))
}

/// `x` with a fixed number of decimals ([`numtext::fixed`]: never `-0.000`).
pub fn fmt_fixed(x: f64, decimals: usize) -> String {
    numtext::fixed(x, decimals)
}

/// The readout texts of a pose, in [`READOUTS`] order.
pub fn readout_values(rep: &PoseReport) -> [String; 14] {
    let j = rep.jacobian;
    [
        fmt_rad(rep.q1),
        fmt_rad(rep.q2),
        fmt_fixed(rep.q1.to_degrees(), 3),
        fmt_fixed(rep.q2.to_degrees(), 3),
        fmt_fixed(rep.x * 1000.0, 3),
        fmt_fixed(rep.y * 1000.0, 3),
        fmt_sig(rep.det_j, 6),
        fmt_sig(rep.manipulability, 6),
        fmt_sig(rep.ellipse.sigma_min, 6),
        fmt_sig(rep.ellipse.sigma_max, 6),
        fmt_sig(j[0][0], 6),
        fmt_sig(j[0][1], 6),
        fmt_sig(j[1][0], 6),
        fmt_sig(j[1][1], 6),
    ]
}

/// What the screen-reader summary says about a pose (rounded the way it is spoken: whole
/// degrees and millimetres, w to 3 significant digits), and whether the tip is pinned.
#[derive(Debug, Clone, PartialEq)]
pub struct PoseSummary {
    pub q1_deg: String,
    pub q2_deg: String,
    pub x_mm: String,
    pub y_mm: String,
    pub w: String,
    pub pinned: bool,
}

impl PoseSummary {
    pub fn of(rep: &PoseReport, pinned: bool) -> PoseSummary {
        PoseSummary {
            q1_deg: fmt_fixed(rep.q1.to_degrees(), 0),
            q2_deg: fmt_fixed(rep.q2.to_degrees(), 0),
            x_mm: fmt_fixed(rep.x * 1000.0, 0),
            y_mm: fmt_fixed(rep.y * 1000.0, 0),
            w: fmt_sig(rep.manipulability, 3),
            pinned,
        }
    }

    /// The summary's Fluent arguments (`ik2r-live-summary`).
    pub fn args(&self) -> Vec<(&'static str, String)> {
        vec![
            ("q1", self.q1_deg.clone()),
            ("q2", self.q2_deg.clone()),
            ("x", self.x_mm.clone()),
            ("y", self.y_mm.clone()),
            ("w", self.w.clone()),
        ]
    }
}

// ---------- Exports: the recipes' arguments and command lines ----------

/// One CSV the page offers.
#[derive(Debug, Clone, Copy)]
pub struct Export {
    /// File name (also the button's `data-download`).
    pub file: &'static str,
    /// The recipe that writes it.
    pub recipe: &'static crate::recipes::RecipeInfo,
    /// Its kernel's run.
    pub run: crate::recipes::RunRaw,
    /// Fluent id of the button.
    pub label_id: &'static str,
    /// Its arguments include the pose's q2 (the jacobian-2r sweep), not only the parameters.
    pub follows_q2: bool,
}

impl Export {
    /// The export of kernel `K`'s file `file`.
    const fn of<K: crate::recipes::Kernel>(
        file: &'static str,
        label_id: &'static str,
        follows_q2: bool,
    ) -> Export {
        Export {
            file,
            recipe: K::INFO,
            run: crate::recipes::run_raw_of::<K>,
            label_id,
            follows_q2,
        }
    }
}

/// The page's CSVs, in the order of the panel.
pub const EXPORTS: [Export; 3] = [
    Export::of::<crate::recipes::ik_workspace::Entry>("ik_workspace.csv", "ik2r-dl-ik", false),
    Export::of::<crate::recipes::jacobian_2r::Entry>("jacobian_2r.csv", "ik2r-dl-jac", true),
    Export::of::<crate::recipes::manip_grid::Entry>("manip_ellipse.csv", "ik2r-dl-manip", false),
];

/// File name of the arm view PNG.
pub const ARM_PNG: &str = "ik_2r_arm.png";

/// The positional arguments of `export` for parameters `p` and the current `q2` (the
/// Jacobian sweep is taken at the pose's q2).
pub fn export_args(export: &Export, p: &Params, q2: f64) -> Vec<String> {
    match export.recipe.id {
        "ik-workspace" => vec![num(p.l1), num(p.l2), num(p.half_mm), num(p.step_mm)],
        "jacobian-2r" => vec![
            num(p.l1),
            num(p.l2),
            num(p.q1_start),
            num(p.q1_stop),
            num(p.q1_step),
            num(q2),
        ],
        _ => vec![num(p.l1), num(p.l2), p.manip_n.to_string()],
    }
}

/// The run of `export` for parameters `p` at elbow angle `q2`, as the command lines spell it.
pub fn export_run(export: &Export, p: &Params, q2: f64) -> RunArgs {
    let fields = crate::view::form::recipe_fields(export.recipe);
    let texts: Vec<Option<String>> = export_args(export, p, q2).into_iter().map(Some).collect();
    RunArgs::new(export.recipe.id, &fields, &texts)
}

/// The equivalent command lines: `python <script> <args>` and `bsv <recipe> <args>`.
pub fn export_commands(export: &Export, p: &Params, q2: f64) -> (String, String) {
    let run = export_run(export, p, q2);
    let script = export.recipe.python;
    (run.python_command(script), run.bsv_command())
}

/// Why a CSV could not be made.
#[derive(Debug, Clone, PartialEq)]
pub enum ExportError {
    /// The recipe refused the arguments.
    Recipe(RecipeError),
    /// The recipe ran but wrote no file of this name.
    MissingFile {
        recipe: &'static str,
        file: &'static str,
    },
}

/// The CSV text, exactly as `bsv <recipe> <args>` writes it.
pub fn export_csv(export: &Export, p: &Params, q2: f64) -> Result<String, ExportError> {
    let out = (export.run)(&export_args(export, p, q2), Vec::new()).map_err(ExportError::Recipe)?;
    out.file(export.file)
        .map(str::to_string)
        .ok_or(ExportError::MissingFile {
            recipe: export.recipe.id,
            file: export.file,
        })
}

#[cfg(test)]
mod tests;
