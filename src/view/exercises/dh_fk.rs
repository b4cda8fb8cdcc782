//! The DH page's exercises (`#/dh-fk`): predict the height of the last frame, raise it, and
//! what the last joint does to the last frame's origin. The frames are the kernel's
//! ([`DhParams::frames`]).
//!
//! The demo chain in modified DH: joint 1 turns about the vertical at height `d1 = 0.10 m`,
//! joint 2 pitches the 0.25 m link, so frame 3's origin is at height `0.10 − 0.25 sin q2`;
//! joint 3 turns frame 3 about its own z axis at that origin (`a2` comes before the joint).

use super::exercise::{model_of, CheckError, Exercise, PageModel, Tolerance};
use crate::recipes::dh_fk::DhParams;

/// The page's route id.
pub const PAGE: &str = "dh-fk";

/// `dh-raise`: the height frame 3's origin must reach, m.
pub const RAISE_TO_M: f64 = 0.3;

/// The page's exercises, in the order it lists them.
#[rustfmt::skip]
pub const EXERCISES: [Exercise; 3] = [
    Exercise::predict("dh-tip-height", PAGE, "m", Tolerance::Absolute(0.01), tip_height_truth),
    Exercise::goal("dh-raise", PAGE, raise_met),
    // 0: it stays where it is.
    Exercise::choose("dh-q3-origin", PAGE, 4, 0),
];

/// The height `z` of the last frame's origin, m.
pub fn tip_height_m(p: &DhParams) -> Result<f64, CheckError> {
    let frames = p.frames()?;
    frames
        .last()
        .map(|f| f.origin[2])
        .ok_or(CheckError::NoTruth {
            exercise: "dh-tip-height",
        })
}

fn tip_height_truth(model: &PageModel) -> Result<f64, CheckError> {
    tip_height_m(model_of!(model, DhFk, "dh-tip-height"))
}

/// `dh-raise`: the last frame's origin at [`RAISE_TO_M`] or higher.
pub fn raised(p: &DhParams) -> Result<bool, CheckError> {
    Ok(tip_height_m(p)? >= RAISE_TO_M)
}

fn raise_met(model: &PageModel) -> Result<bool, CheckError> {
    raised(model_of!(model, DhFk, "dh-raise"))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::view::exercises::exercise::test_attribute::test;
    crate::view::exercises::exercise::page_check!(|p: &DhParams| PageModel::DhFk(p));

    #[test]
    fn dh_tip_height_follows_the_second_joint() {
        let p = DhParams::default();
        let truth = tip_height_m(&p).unwrap();
        assert!(
            (truth - (0.10 - 0.25 * 0.4f64.sin())).abs() < 1e-15,
            "{truth}"
        );
        assert!(check("dh-tip-height", &p, Answer::Number(0.0)).right());
        // d1 alone forgets the pitched link.
        assert!(!check("dh-tip-height", &p, Answer::Number(0.1)).right());
    }

    #[test]
    fn dh_raise_needs_the_link_pitched_up() {
        let p = DhParams::default();
        assert_eq!(
            check("dh-raise", &p, Answer::PageState),
            Verdict::Goal { met: false }
        );
        let up = DhParams {
            q: [0.2, -1.2, -0.3],
        };
        assert!(tip_height_m(&up).unwrap() > 0.3);
        assert_eq!(
            check("dh-raise", &up, Answer::PageState),
            Verdict::Goal { met: true }
        );
        let bad = DhParams {
            q: [f64::NAN, 0.0, 0.0],
        };
        assert!(matches!(
            find("dh-raise")
                .unwrap()
                .check(&PageModel::DhFk(&bad), Answer::PageState),
            Err(CheckError::Kernel(_))
        ));
    }

    #[test]
    fn dh_q3_turns_the_last_frame_in_place() {
        let p = DhParams::default();
        let turned = DhParams {
            q: [p.q[0], p.q[1], 1.3],
        };
        let (a, b) = (p.frames().unwrap()[3], turned.frames().unwrap()[3]);
        for k in 0..3 {
            assert!((a.origin[k] - b.origin[k]).abs() < 1e-15);
        }
        assert!((a.rpy.0 - b.rpy.0).abs() + (a.rpy.2 - b.rpy.2).abs() > 0.1);
        assert!(check("dh-q3-origin", &p, Answer::Choice(0)).right());
        for wrong in 1..4 {
            assert!(!check("dh-q3-origin", &p, Answer::Choice(wrong)).right());
        }
    }
}
