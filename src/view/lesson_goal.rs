//! A teacher's own goal on a lesson step: up to [`MAX_GOALS`] conditions on the readouts of the
//! step's page (`data-readout`), each a readout, `<`, `>` or "within ± of", and a value in the
//! readout's unit. Presenting the step checks them live on the numbers the page shows.
//!
//! A condition travels in the lesson's link as `<readout><op><value>[±<tolerance>]` (`op`: `<`,
//! `>`, `~` for within; conditions joined by `;`), and in the lesson file as an object
//! `{"readout", "op": "<" | ">" | "within", "value", "tolerance"}` ([`crate::view::lesson_file`]).
//! The readouts a page offers, with their units, are [`readouts_of`].

use serde::Serialize;

use crate::pyfmt::py_float;
use crate::view::embed::parse_number;

/// The most conditions a step holds.
pub const MAX_GOALS: usize = 3;
/// The longest readout key.
pub const MAX_READOUT_CHARS: usize = 40;

/// How a condition compares the readout with its value.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum GoalOp {
    /// The readout is below the value.
    #[serde(rename = "<")]
    Below,
    /// The readout is above the value.
    #[serde(rename = ">")]
    Above,
    /// The readout is within ± the tolerance of the value (bounds included).
    #[serde(rename = "within")]
    Within,
}

impl GoalOp {
    /// The word of the file's `op`.
    pub fn word(self) -> &'static str {
        match self {
            GoalOp::Below => "<",
            GoalOp::Above => ">",
            GoalOp::Within => "within",
        }
    }

    /// The op of the file's word.
    pub fn of_word(word: &str) -> Option<GoalOp> {
        [GoalOp::Below, GoalOp::Above, GoalOp::Within]
            .into_iter()
            .find(|op| op.word() == word)
    }
}

/// One condition of a teacher's goal.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct GoalCondition {
    /// The page's readout (`data-readout`).
    pub readout: String,
    pub op: GoalOp,
    /// In the readout's unit.
    pub value: f64,
    /// For [`GoalOp::Within`]: how far from `value` still counts, in the readout's unit.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tolerance: Option<f64>,
}

impl GoalCondition {
    /// Whether the condition is well formed: a readout key (lowercase letters, digits, `-`
    /// and `_`, at most [`MAX_READOUT_CHARS`]), a finite value, and a tolerance of 0 or more
    /// exactly when the op is within.
    pub fn is_valid(&self) -> bool {
        let key = &self.readout;
        let key_ok = !key.is_empty()
            && key.chars().count() <= MAX_READOUT_CHARS
            && key
                .chars()
                .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '-' || c == '_');
        let tolerance_ok = match (self.op, self.tolerance) {
            (GoalOp::Within, Some(t)) => t.is_finite() && t >= 0.0,
            (GoalOp::Within, None) => false,
            (_, t) => t.is_none(),
        };
        key_ok && self.value.is_finite() && tolerance_ok
    }

    /// Whether `reading` (the readout's number; `None` when the page shows none) meets the
    /// condition.
    pub fn met(&self, reading: Option<f64>) -> bool {
        let Some(x) = reading.filter(|x| x.is_finite()) else {
            return false;
        };
        match self.op {
            GoalOp::Below => x < self.value,
            GoalOp::Above => x > self.value,
            GoalOp::Within => (x - self.value).abs() <= self.tolerance.unwrap_or(0.0),
        }
    }

    /// The condition as the link writes it.
    pub fn to_link(&self) -> String {
        let value = number_text(self.value);
        match (self.op, self.tolerance) {
            (GoalOp::Below, _) => format!("{}<{value}", self.readout),
            (GoalOp::Above, _) => format!("{}>{value}", self.readout),
            (GoalOp::Within, t) => {
                format!("{}~{value}±{}", self.readout, number_text(t.unwrap_or(0.0)))
            }
        }
    }

    /// One condition of a link (`None` if it is not one).
    pub fn from_link(text: &str) -> Option<GoalCondition> {
        let at = text.find(['<', '>', '~'])?;
        let (readout, rest) = text.split_at(at);
        let mut chars = rest.chars();
        let op = match chars.next()? {
            '<' => GoalOp::Below,
            '>' => GoalOp::Above,
            _ => GoalOp::Within,
        };
        let rest = chars.as_str();
        let (value, tolerance) = match op {
            GoalOp::Within => {
                let (value, tolerance) = rest.split_once('±')?;
                (value, Some(parse_number(tolerance)?))
            }
            _ => (rest, None),
        };
        let condition = GoalCondition {
            readout: readout.to_owned(),
            op,
            value: parse_number(value)?,
            tolerance,
        };
        condition.is_valid().then_some(condition)
    }

    /// The conditions as the link's `g<n>` value.
    pub fn list_to_link(goals: &[GoalCondition]) -> String {
        goals
            .iter()
            .map(GoalCondition::to_link)
            .collect::<Vec<_>>()
            .join(";")
    }

    /// The conditions of a link's `g<n>` value (`None` if one is not a condition, or there are
    /// more than [`MAX_GOALS`]).
    pub fn list_from_link(text: &str) -> Option<Vec<GoalCondition>> {
        let goals = text
            .split(';')
            .map(GoalCondition::from_link)
            .collect::<Option<Vec<_>>>()?;
        (goals.len() <= MAX_GOALS).then_some(goals)
    }
}

/// A number as a field or a link shows it: Python's `repr` (the shortest text that reads back
/// the same), without a trailing `.0`.
pub fn number_text(x: f64) -> String {
    let text = py_float(x);
    match text.strip_suffix(".0") {
        Some(whole) => whole.to_owned(),
        None => text,
    }
}

/// Each page's readouts a goal may name, with the units of the numbers they hold (their
/// `data-value`, else their text; empty for a pure number or a count).
const PAGE_READOUTS: &[(&str, &[(&str, &str)])] = &[
    (
        "ik-2r",
        &[
            ("q1_deg", "°"),
            ("q2_deg", "°"),
            ("x_mm", "mm"),
            ("y_mm", "mm"),
            ("det_j", "m²"),
            ("manipulability", "m²"),
            ("sigma_min", "m"),
            ("sigma_max", "m"),
        ],
    ),
    ("dh-fk", &[("x", "m"), ("y", "m"), ("z", "m")]),
    ("se3-relative", &[("x", "m"), ("y", "m"), ("z", "m")]),
    (
        "umeyama-2d",
        &[
            ("scale", ""),
            ("angle", "°"),
            ("tx", ""),
            ("ty", ""),
            ("rmse", ""),
        ],
    ),
    (
        "pendulum-energy",
        &[
            ("theta", "rad"),
            ("omega", "rad/s"),
            ("total", "J"),
            ("period", "s"),
        ],
    ),
    (
        "pid-step",
        &[
            ("rise-time", "s"),
            ("overshoot", "%"),
            ("settling-time", "s"),
            ("final-y", ""),
        ],
    ),
    (
        "cubic-path",
        &[("peak-velocity", "rad/s"), ("peak-acceleration", "rad/s²")],
    ),
    (
        "trapezoid-profile",
        &[
            ("t-acc", "s"),
            ("t-flat", "s"),
            ("t-total", "s"),
            ("v-peak", ""),
        ],
    ),
    ("traj-resample", &[("rows_out", ""), ("duration", "s")]),
    (
        "rrt-2d",
        &[
            ("iteration", ""),
            ("nodes", ""),
            ("path_points", ""),
            ("length", ""),
        ],
    ),
    (
        "teleop",
        &[
            ("q1", "rad"),
            ("q2", "rad"),
            ("q3", "rad"),
            ("manipulability", "m²"),
            ("time", "s"),
        ],
    ),
    (
        "so101",
        &[
            ("x", "m"),
            ("y", "m"),
            ("z", "m"),
            ("q2", "rad"),
            ("q3", "rad"),
            ("manipulability", "m³"),
            ("time", "s"),
        ],
    ),
];

/// The readouts a goal on page `page` may name, with their units (none for a page without
/// readouts).
pub fn readouts_of(page: &str) -> &'static [(&'static str, &'static str)] {
    PAGE_READOUTS
        .iter()
        .find(|(p, _)| *p == page)
        .map_or(&[], |(_, readouts)| readouts)
}

/// Every page's readouts a goal may name (for the test that they are on the pages).
pub fn all_readouts() -> &'static [(&'static str, &'static [(&'static str, &'static str)])] {
    PAGE_READOUTS
}

/// The unit of readout `readout` of page `page` ("" if unknown).
pub fn unit_of(page: &str, readout: &str) -> &'static str {
    readouts_of(page)
        .iter()
        .find(|(key, _)| *key == readout)
        .map_or("", |(_, unit)| unit)
}

#[cfg(test)]
mod tests {
    use super::*;
    #[cfg(target_family = "wasm")]
    use wasm_bindgen_test::wasm_bindgen_test as test;

    fn goal(readout: &str, op: GoalOp, value: f64, tolerance: Option<f64>) -> GoalCondition {
        GoalCondition {
            readout: readout.into(),
            op,
            value,
            tolerance,
        }
    }

    #[test]
    fn conditions_compare_the_reading() {
        let below = goal("manipulability", GoalOp::Below, 0.001, None);
        assert!(below.met(Some(0.0005)));
        assert!(!below.met(Some(0.001)));
        assert!(!below.met(None));
        assert!(!below.met(Some(f64::NAN)));
        let above = goal("overshoot", GoalOp::Above, 5.0, None);
        assert!(above.met(Some(5.5)) && !above.met(Some(5.0)));
        let within = goal("q2_deg", GoalOp::Within, 90.0, Some(5.0));
        assert!(within.met(Some(95.0)) && within.met(Some(85.0)) && !within.met(Some(95.1)));
    }

    #[test]
    fn a_condition_is_well_formed() {
        assert!(goal("q2_deg", GoalOp::Within, 90.0, Some(0.0)).is_valid());
        assert!(!goal("q2_deg", GoalOp::Within, 90.0, None).is_valid());
        assert!(!goal("q2_deg", GoalOp::Within, 90.0, Some(-1.0)).is_valid());
        assert!(!goal("q2_deg", GoalOp::Below, 90.0, Some(1.0)).is_valid());
        assert!(!goal("Q2", GoalOp::Below, 1.0, None).is_valid());
        assert!(!goal("", GoalOp::Below, 1.0, None).is_valid());
        assert!(!goal("x", GoalOp::Below, f64::INFINITY, None).is_valid());
        assert!(!goal(&"x".repeat(41), GoalOp::Below, 1.0, None).is_valid());
    }

    #[test]
    fn conditions_round_trip_through_the_link() {
        let goals = vec![
            goal("manipulability", GoalOp::Below, 0.001, None),
            goal("overshoot", GoalOp::Above, -2.5, None),
            goal("q2_deg", GoalOp::Within, 90.0, Some(5.0)),
        ];
        let link = GoalCondition::list_to_link(&goals);
        assert_eq!(link, "manipulability<0.001;overshoot>-2.5;q2_deg~90±5");
        assert_eq!(number_text(1e-5), "1e-05");
        assert_eq!(
            GoalCondition::from_link("t<1e-05").map(|g| g.value),
            Some(1e-5)
        );
        assert_eq!(GoalCondition::list_from_link(&link), Some(goals.clone()));
        let four = format!("{link};t<1");
        assert_eq!(GoalCondition::list_from_link(&four), None);
        for bad in [
            "",
            "q2",
            "q2<",
            "q2<x",
            "q2~90",
            "q2~90±-1",
            "Q2<1",
            "q2<1e999",
            "<1",
        ] {
            assert_eq!(GoalCondition::from_link(bad), None, "{bad}");
        }
    }

    #[test]
    fn typed_numbers_read_as_a_teacher_writes_them() {
        assert_eq!(parse_number(" −0.5 "), Some(-0.5));
        assert_eq!(parse_number("1e-3"), Some(0.001));
        assert_eq!(parse_number("0x10"), None);
        assert_eq!(parse_number("inf"), None);
        assert_eq!(parse_number(""), None);
    }

    #[test]
    fn every_page_with_exercises_offers_readouts_with_units_known() {
        for (page, _) in crate::view::exercises::PAGE_IDS {
            assert!(!readouts_of(page).is_empty(), "{page}");
        }
        assert_eq!(unit_of("ik-2r", "manipulability"), "m²");
        assert_eq!(unit_of("ik-2r", "nope"), "");
        assert!(readouts_of("home").is_empty());
    }
}
