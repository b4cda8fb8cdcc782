//! The DH forward-kinematics page (`#/dh-fk`), plain Rust: the frames of the recipe's 3R chain
//! to draw (from the kernel's own products, so the view and the CSV agree), the joint sliders'
//! edits of the `angles` text, the "show one row" walk through a row's four elementary
//! transforms, and the page's own URL keys.
//!
//! ```text
//! modified (Craig) DH, row i:   T_{i-1,i} = Rx(α_{i-1}) · Tx(a_{i-1}) · Rz(θ_i) · Tz(d_i)
//! the walk:  M_0 = T_{i-1},  M_k = M_{k-1} · E_k  (k = 1..4),  M_4 = T_i
//! ```
//!
//! Between two steps the moving frame is `M_{k-1} · E_k(s)` with the elementary transform's
//! angle or length scaled by `s ∈ [0, 1]` (the animation), so `s = 1` lands exactly on `M_k`.

use glam::{DMat3, DMat4, DVec3, DVec4};
use nalgebra::Matrix4;

use crate::camera3d::Preset;
use crate::pyfmt::py_float;
use crate::recipes::dh_fk::{forward_kinematics, MdhLink, DEMO_CHAIN, JOINTS};
use crate::view::scene3d::AxisPalette;
use crate::view::url::IgnoredKey;

/// The point the view looks at and the radius it frames, metres: every pose of the chain
/// lies within a2 = 0.25 of joint 2 (d1 = 0.10 above the base); the target leans towards the
/// recipe's default pose (reaching out along +x, down to the ground) so it fills the view.
pub const VIEW_TARGET: [f64; 3] = [0.07, 0.02, 0.05];
pub const VIEW_RADIUS: f64 = 0.22;

/// A frame of the chain as the view draws it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DrawFrame {
    /// 0 for the base, `i` after joint `i`.
    pub index: usize,
    pub origin: DVec3,
    /// Columns: the frame's x, y, z axes in base coordinates.
    pub rotation: DMat3,
}

/// A 4×4 transform of the kernel as glam's (column-major) matrix.
pub fn to_glam(m: &Matrix4<f64>) -> DMat4 {
    DMat4::from_cols(
        DVec4::new(m[(0, 0)], m[(1, 0)], m[(2, 0)], m[(3, 0)]),
        DVec4::new(m[(0, 1)], m[(1, 1)], m[(2, 1)], m[(3, 1)]),
        DVec4::new(m[(0, 2)], m[(1, 2)], m[(2, 2)], m[(3, 2)]),
        DVec4::new(m[(0, 3)], m[(1, 3)], m[(2, 3)], m[(3, 3)]),
    )
}

/// Origin and rotation of a transform.
pub fn frame_of(index: usize, t: &DMat4) -> DrawFrame {
    DrawFrame {
        index,
        origin: t.w_axis.truncate(),
        rotation: DMat3::from_mat4(*t),
    }
}

/// The base frame and the three joint frames at joint angles `q` (the kernel's products).
pub fn draw_frames(q: &[f64; JOINTS]) -> Vec<DrawFrame> {
    forward_kinematics(&DEMO_CHAIN, q)
        .iter()
        .map(|f| frame_of(f.index, &to_glam(&f.transform)))
        .collect()
}

/// One of the four elementary transforms of a modified-DH row, in the order applied.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Elementary {
    /// Rotation about x by α_{i-1}.
    RotX,
    /// Translation along x by a_{i-1}.
    TransX,
    /// Rotation about z by θ_i.
    RotZ,
    /// Translation along z by d_i.
    TransZ,
}

impl Elementary {
    pub const ALL: [Elementary; 4] = [
        Elementary::RotX,
        Elementary::TransX,
        Elementary::RotZ,
        Elementary::TransZ,
    ];

    /// `rx`, `tx`, `rz`, `tz` (Fluent ids, test hooks).
    pub fn id(self) -> &'static str {
        match self {
            Elementary::RotX => "rx",
            Elementary::TransX => "tx",
            Elementary::RotZ => "rz",
            Elementary::TransZ => "tz",
        }
    }

    /// How it is written for row `row` (1-based): `Rx(α0)`, `Tx(a0)`, `Rz(θ1)`, `Tz(d1)`.
    pub fn symbol(self, row: usize) -> String {
        let prev = row.saturating_sub(1);
        match self {
            Elementary::RotX => format!("Rx(α{prev})"),
            Elementary::TransX => format!("Tx(a{prev})"),
            Elementary::RotZ => format!("Rz(θ{row})"),
            Elementary::TransZ => format!("Tz(d{row})"),
        }
    }

    /// Its amount in `link` with joint angle `theta` (rad or m).
    pub fn amount(self, link: &MdhLink, theta: f64) -> f64 {
        match self {
            Elementary::RotX => link.alpha,
            Elementary::TransX => link.a,
            Elementary::RotZ => theta,
            Elementary::TransZ => link.d,
        }
    }

    /// The transform for `amount` (an angle in rad or a length in m).
    pub fn matrix(self, amount: f64) -> DMat4 {
        match self {
            Elementary::RotX => DMat4::from_rotation_x(amount),
            Elementary::TransX => DMat4::from_translation(DVec3::new(amount, 0.0, 0.0)),
            Elementary::RotZ => DMat4::from_rotation_z(amount),
            Elementary::TransZ => DMat4::from_translation(DVec3::new(0.0, 0.0, amount)),
        }
    }

    /// Whether it turns (an angle) rather than moves (a length).
    pub fn is_rotation(self) -> bool {
        matches!(self, Elementary::RotX | Elementary::RotZ)
    }
}

/// Steps of a row's walk: 0 (the parent frame) to 4 (the row's frame).
pub const WALK_STEPS: usize = 4;

/// "Show one row": the walk from frame `row - 1` to frame `row` through the four elementary
/// transforms.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RowWalk {
    /// 1-based row (joint) number.
    pub row: usize,
    pub link: MdhLink,
    /// θ_row = q_row + offset.
    pub theta: f64,
    /// T_{row-1}: base to the parent frame.
    pub parent: DMat4,
}

impl RowWalk {
    /// The walk of `row` (clamped to 1..=3) at joint angles `q`.
    pub fn new(q: &[f64; JOINTS], row: usize) -> RowWalk {
        let row = row.clamp(1, JOINTS);
        let frames = forward_kinematics(&DEMO_CHAIN, q);
        let link = DEMO_CHAIN[row - 1];
        RowWalk {
            row,
            link,
            theta: q[row - 1] + link.theta_offset,
            parent: to_glam(&frames[row - 1].transform),
        }
    }

    /// The amount of elementary transform `k` (1..=4).
    pub fn amount(&self, k: usize) -> f64 {
        Elementary::ALL[k.clamp(1, WALK_STEPS) - 1].amount(&self.link, self.theta)
    }

    /// `E_k` (1..=4) in full.
    pub fn elementary(&self, k: usize) -> DMat4 {
        let k = k.clamp(1, WALK_STEPS);
        Elementary::ALL[k - 1].matrix(self.amount(k))
    }

    /// `E_1 · … · E_step`: from the parent frame to the moving frame after `step` steps.
    pub fn local(&self, step: usize) -> DMat4 {
        (1..=step.min(WALK_STEPS)).fold(DMat4::IDENTITY, |m, k| m * self.elementary(k))
    }

    /// `M_step`: base to the moving frame after `step` steps.
    pub fn at(&self, step: usize) -> DMat4 {
        self.parent * self.local(step)
    }

    /// The moving frame a fraction `s` of the way through step `step` (1..=4):
    /// `M_{step-1} · E_step(s · amount)`; `s` is clamped to [0, 1].
    pub fn between(&self, step: usize, s: f64) -> DMat4 {
        let step = step.clamp(1, WALK_STEPS);
        let s = if s.is_finite() {
            s.clamp(0.0, 1.0)
        } else {
            1.0
        };
        self.at(step - 1) * Elementary::ALL[step - 1].matrix(s * self.amount(step))
    }
}

/// The `angles` text after joint `joint` (0-based) is set to `value` by its slider: the other
/// items keep their text when `current` has three that parse, else the last valid angles
/// `valid` are written (Python's `repr`).
pub fn set_joint_text(current: &str, valid: &[f64; JOINTS], joint: usize, value: &str) -> String {
    let items: Vec<&str> = current.split(',').map(str::trim).collect();
    let keep = items.len() == JOINTS && items.iter().all(|t| t.parse::<f64>().is_ok());
    (0..JOINTS)
        .map(|i| {
            if i == joint {
                value.to_string()
            } else if keep {
                items[i].to_string()
            } else {
                py_float(valid[i])
            }
        })
        .collect::<Vec<_>>()
        .join(",")
}

/// The page's own URL keys (the recipe's `angles` is the command line's).
pub const OWN_KEYS: [&str; 4] = ["view", "row", "step", "axes"];

/// The page's own state in the URL: the preset view, the row walked and its step, the axis
/// colours.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PageQuery {
    pub view: Preset,
    /// 1..=3.
    pub row: usize,
    /// 0..=4.
    pub step: usize,
    pub palette: AxisPalette,
}

impl Default for PageQuery {
    fn default() -> PageQuery {
        PageQuery {
            view: Preset::Iso,
            row: 1,
            step: 0,
            palette: AxisPalette::Classic,
        }
    }
}

impl PageQuery {
    /// The state of the page's own keys in `query` and those whose value it could not use
    /// (other keys are the recipe's or reported elsewhere).
    pub fn read(query: &[(String, String)]) -> (PageQuery, Vec<IgnoredKey>) {
        let mut q = PageQuery::default();
        let mut bad = Vec::new();
        for (key, value) in query {
            let v = value.trim();
            let ok = match key.as_str() {
                "view" => Preset::from_id(v).map(|p| q.view = p).is_some(),
                "row" => v
                    .parse::<usize>()
                    .ok()
                    .filter(|r| (1..=JOINTS).contains(r))
                    .map(|r| q.row = r)
                    .is_some(),
                "step" => v
                    .parse::<usize>()
                    .ok()
                    .filter(|s| *s <= WALK_STEPS)
                    .map(|s| q.step = s)
                    .is_some(),
                "axes" => AxisPalette::from_id(v).map(|p| q.palette = p).is_some(),
                _ => true,
            };
            if !ok {
                bad.push(IgnoredKey::invalid(key.clone()));
            }
        }
        (q, bad)
    }

    /// The pairs that differ from the defaults, in [`OWN_KEYS`] order.
    pub fn write(&self) -> Vec<(String, String)> {
        let d = PageQuery::default();
        let mut out = Vec::new();
        if self.view != d.view {
            out.push(("view".into(), self.view.id().into()));
        }
        if self.row != d.row {
            out.push(("row".into(), self.row.to_string()));
        }
        if self.step != d.step {
            out.push(("step".into(), self.step.to_string()));
        }
        if self.palette != d.palette {
            out.push(("axes".into(), self.palette.id().into()));
        }
        out
    }
}

/// A number as the tables show it: 4 decimals, no negative zero.
pub fn cell(x: f64) -> String {
    crate::numtext::fixed_minus(x, 4)
}

/// The rows of the CSV text (header left out), each split into its cells, exactly as written.
pub fn csv_rows(csv: &str) -> Vec<Vec<String>> {
    csv.lines()
        .skip(1)
        .filter(|l| !l.is_empty())
        .map(|l| l.split(',').map(str::to_string).collect())
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::recipes::dh_fk::{mdh_transform, DhParams};

    const Q: [f64; 3] = [0.2, 0.4, -0.3];

    fn close(a: &DMat4, b: &DMat4, tol: f64) -> bool {
        a.to_cols_array()
            .iter()
            .zip(b.to_cols_array())
            .all(|(x, y)| (x - y).abs() <= tol)
    }

    #[test]
    fn frames_are_the_kernels() {
        let frames = draw_frames(&Q);
        let kernel = DhParams { q: Q }.frames().unwrap();
        assert_eq!(frames.len(), 4);
        for (f, k) in frames.iter().zip(&kernel) {
            assert_eq!(f.index, k.index);
            assert_eq!(f.origin.to_array(), k.origin);
            for r in 0..3 {
                for c in 0..3 {
                    assert_eq!(f.rotation.col(c)[r], k.transform[(r, c)]);
                }
            }
        }
        // The tip of the recipe's default pose.
        assert_eq!(
            frames[3].origin.to_array(),
            [
                0.225675274093865,
                0.045746642824996776,
                0.002645414422837375
            ]
        );
    }

    #[test]
    fn the_four_elementary_transforms_make_the_link_transform() {
        for q in [Q, [1.0, -0.5, 2.0], [0.0; 3], [-3.0, 3.0, 0.7]] {
            let frames = draw_frames(&q);
            for row in 1..=3 {
                let walk = RowWalk::new(&q, row);
                let link = DEMO_CHAIN[row - 1];
                let mdh = to_glam(&mdh_transform(link.alpha, link.a, link.d, walk.theta));
                assert!(close(&walk.local(4), &mdh, 1e-15), "row {row}");
                assert_eq!(walk.at(0), walk.parent);
                let end = walk.at(WALK_STEPS);
                let want = DMat4::from_cols_array_2d(&[
                    frames[row].rotation.col(0).extend(0.0).to_array(),
                    frames[row].rotation.col(1).extend(0.0).to_array(),
                    frames[row].rotation.col(2).extend(0.0).to_array(),
                    frames[row].origin.extend(1.0).to_array(),
                ]);
                assert!(close(&end, &want, 1e-14), "row {row}: {end:?} vs {want:?}");
            }
        }
    }

    #[test]
    fn the_walk_moves_as_each_step_says() {
        let walk = RowWalk::new(&Q, 3);
        // Row 3: α2 = 0, a2 = 0.25, θ3 = q3, d3 = 0.
        assert_eq!(walk.amount(2), 0.25);
        assert_eq!(walk.amount(3), -0.3);
        let m1 = walk.at(1);
        let m2 = walk.at(2);
        // Tx(a2) moves the origin 0.25 m along the x axis of M_1.
        let moved = m2.w_axis.truncate() - m1.w_axis.truncate();
        assert!((moved - m1.x_axis.truncate() * 0.25).length() < 1e-15);
        // Half way through step 2, half the way.
        let half = walk.between(2, 0.5).w_axis.truncate() - m1.w_axis.truncate();
        assert!((half - moved / 2.0).length() < 1e-15);
        // s = 0 and s = 1 are the two ends; bad fractions land on the end.
        for k in 1..=WALK_STEPS {
            assert!(close(&walk.between(k, 0.0), &walk.at(k - 1), 1e-15));
            assert!(close(&walk.between(k, 1.0), &walk.at(k), 1e-15));
            assert!(close(&walk.between(k, f64::NAN), &walk.at(k), 1e-15));
        }
        // Rz(θ3) keeps the origin and the z axis.
        let (a, b) = (walk.at(2), walk.at(3));
        assert!((a.w_axis - b.w_axis).length() < 1e-15);
        assert!((a.z_axis - b.z_axis).length() < 1e-15);
        assert_eq!(Elementary::RotX.symbol(1), "Rx(α0)");
        assert_eq!(Elementary::TransZ.symbol(3), "Tz(d3)");
        assert_eq!(RowWalk::new(&Q, 9).row, 3);
        assert_eq!(RowWalk::new(&Q, 0).row, 1);
    }

    #[test]
    fn a_slider_edits_one_item_of_the_angles() {
        let valid = [0.2, 0.4, -0.3];
        assert_eq!(
            set_joint_text("0.2,0.4,-0.3", &valid, 1, "1.25"),
            "0.2,1.25,-0.3"
        );
        assert_eq!(
            set_joint_text(" 0.2 , 4e-1,-0.3", &valid, 0, "-1"),
            "-1,4e-1,-0.3"
        );
        // A bad text: the last valid angles fill in.
        assert_eq!(set_joint_text("0.2,abc", &valid, 2, "0.5"), "0.2,0.4,0.5");
        assert_eq!(set_joint_text("", &[1.0, 0.0, 2.5], 0, "3"), "3,0.0,2.5");
    }

    #[test]
    fn page_query_round_trips_and_reports_bad_values() {
        let (q, bad) = PageQuery::read(&[]);
        assert_eq!((q, bad.len()), (PageQuery::default(), 0));
        assert!(q.write().is_empty());
        let state = PageQuery {
            view: Preset::Top,
            row: 2,
            step: 3,
            palette: AxisPalette::ColorBlindSafe,
        };
        let pairs = state.write();
        assert_eq!(
            pairs,
            vec![
                ("view".to_string(), "top".to_string()),
                ("row".into(), "2".into()),
                ("step".into(), "3".into()),
                ("axes".into(), "cb".into()),
            ]
        );
        assert_eq!(PageQuery::read(&pairs), (state, vec![]));
        let query: Vec<(String, String)> = [
            ("view", "sideways"),
            ("row", "4"),
            ("step", "-1"),
            ("axes", "cb"),
            ("angles", "1,2,3"),
        ]
        .iter()
        .map(|(k, v)| (k.to_string(), v.to_string()))
        .collect();
        let (q, bad) = PageQuery::read(&query);
        assert_eq!(q.palette, AxisPalette::ColorBlindSafe);
        assert_eq!((q.view, q.row, q.step), (Preset::Iso, 1, 0));
        let keys: Vec<&str> = bad.iter().map(|k| k.key.as_str()).collect();
        assert_eq!(keys, ["view", "row", "step"]);
    }

    #[test]
    fn cells_and_csv_rows() {
        assert_eq!(cell(-1.23456), "−1.2346");
        assert_eq!(cell(-0.00001), "0.0000");
        assert_eq!(cell(-0.0), "0.0000");
        assert_eq!(cell(0.25), "0.2500");
        let rows = csv_rows("frame,x_m\n0,0.0\n1,-0.0\n");
        assert_eq!(rows, vec![vec!["0", "0.0"], vec!["1", "-0.0"]]);
    }
}
