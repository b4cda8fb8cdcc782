//! The IK page's whole state (link lengths, pose, elbow branch, toggles, recipe parameters)
//! and its URL form: `#/ik-2r?L1=0.12&L2=0.1&q1=0.3&q2=0.8&elbow=down&ws=1&...`.
//!
//! Every value is validated the way the form validates it ([`validate`]); a URL value that
//! fails is ignored (the default stays) and its key is reported so that the page can say so.
//! Numbers are written in Rust's shortest round-trip form, so opening a URL restores the
//! exact `f64`s it was made from.

use crate::args::{in_range, parse_f64, parse_i64};
use crate::error::RecipeError;
use crate::planar2r::{Arm, Elbow};
use crate::recipes::ik_workspace::{self, WorkspaceParams};
use crate::recipes::jacobian_2r::{self, SweepParams};
use crate::recipes::manip_grid::{self, GridParams};

/// The page's own starting values; the recipe parameters' defaults come from the kernels
/// (`WorkspaceParams::default()`, `SweepParams::default()`, `GridParams::default()`).
pub mod defaults {
    /// Starting pose (rad): q2 is the jacobian-2r recipe's fixed 0.8.
    pub const Q1: f64 = 0.3;
    pub const Q2: f64 = 0.8;
    /// Heatmap cells per axis.
    pub const HEATMAP_N: i64 = 256;
}

/// Limits the form states in its hints.
pub mod limits {
    /// Link lengths: `LINK_MIN_M <= L <= L_MAX_M` metres (the kernels accept up to 1 km; a
    /// classroom arm is far below 10 m).
    pub const L_MAX_M: f64 = 10.0;
    /// Heatmap resolution range.
    pub const HEATMAP_MIN: i64 = 64;
    pub const HEATMAP_MAX: i64 = 1024;
}

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

/// Validates `text` for `field` and returns `p` with it applied, or the error to show beside
/// the field (`p` itself is never changed on error). After the field's own checks, the three
/// kernels validate the whole parameter set, so every download made from it succeeds.
pub fn validate(p: &Params, field: Field, text: &str) -> Result<Params, RecipeError> {
    let next = validate_value(p, field, text)?;
    next.check_kernels()?;
    Ok(next)
}

/// [`validate`] without the kernels' checks of the whole set.
fn validate_value(p: &Params, field: Field, text: &str) -> Result<Params, RecipeError> {
    let key = field.key();
    let mut next = *p;
    let value = |text: &str| parse_f64(key, text);
    match field {
        Field::L1 | Field::L2 => {
            let v = in_range(key, value(text)?, ik_workspace::LINK_MIN_M, limits::L_MAX_M)?;
            if field == Field::L1 {
                next.l1 = v;
            } else {
                next.l2 = v;
            }
        }
        Field::HalfMm => next.half_mm = value(text)?,
        Field::StepMm => next.step_mm = value(text)?,
        Field::Q1Start => next.q1_start = value(text)?,
        Field::Q1Stop => next.q1_stop = value(text)?,
        Field::Q1Step => next.q1_step = value(text)?,
        Field::HeatmapN => {
            let n = parse_i64(key, text)?;
            let n = in_range(
                key,
                n as f64,
                limits::HEATMAP_MIN as f64,
                limits::HEATMAP_MAX as f64,
            )?;
            next.heatmap_n = n as usize;
        }
        Field::ManipN => {
            let n = parse_i64(key, text)?;
            in_range(key, n as f64, 1.0, manip_grid::MAX_N as f64)?;
            next.manip_n = n;
        }
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
