//! The SE(3) page's exercises (`#/se3-relative`): predict how far apart the frames are, place
//! B just ahead of a turned A in A's own terms, and what swapping A and B does. The relative
//! pose is the kernel's ([`Se3Params::relative`], `T_A⁻¹ T_B`).

use nalgebra::Matrix3;

use super::exercise::{model_of, CheckError, Exercise, PageModel, Tolerance};
use crate::recipes::se3_relative::{rpy_to_rotation, Pose, Se3Params};

/// The page's route id.
pub const PAGE: &str = "se3-relative";

/// `se3-ahead`: B's place in A's frame, m (along A's x axis).
pub const AHEAD_M: f64 = 0.1;
/// `se3-ahead`: how close B must be to that place, m, and to A's orientation, rad.
pub const AHEAD_TOL_M: f64 = 0.001;
pub const AHEAD_TOL_RAD: f64 = 0.01;
/// `se3-ahead`: A must be turned at least this far from the world's axes, rad (else A's
/// frame is the world's and the exercise is no exercise).
pub const A_TURNED_RAD: f64 = 0.1;

/// The page's exercises, in the order it lists them.
#[rustfmt::skip]
pub const EXERCISES: [Exercise; 3] = [
    Exercise::predict("se3-distance", PAGE, "m", Tolerance::Relative(0.05), distance_truth),
    Exercise::goal("se3-ahead", PAGE, ahead_met),
    // 1: the inverse of the relative pose.
    Exercise::choose("se3-swap", PAGE, 4, 1),
];

/// The angle of a rotation matrix, rad (0 to π).
fn rotation_angle(r: &Matrix3<f64>) -> f64 {
    ((r.trace() - 1.0) / 2.0).clamp(-1.0, 1.0).acos()
}

fn pose_angle(p: &Pose) -> f64 {
    rotation_angle(&rpy_to_rotation(p.roll, p.pitch, p.yaw))
}

/// `se3-distance`: the distance between the frames' origins, `|p_rel|`, m (the same in A's
/// frame as in the world's).
pub fn distance_m(p: &Se3Params) -> Result<f64, CheckError> {
    let rel = p.relative()?;
    Ok((rel.x * rel.x + rel.y * rel.y + rel.z * rel.z).sqrt())
}

fn distance_truth(model: &PageModel) -> Result<f64, CheckError> {
    distance_m(model_of!(model, Se3, "se3-distance"))
}

/// `se3-ahead`: with A turned at least [`A_TURNED_RAD`], B sits [`AHEAD_M`] along A's x axis
/// with A's orientation: the relative pose within [`AHEAD_TOL_M`] of `(0.1, 0, 0)` and its
/// rotation within [`AHEAD_TOL_RAD`] of none.
pub fn b_ahead_of_a(p: &Se3Params) -> Result<bool, CheckError> {
    let rel = p.relative()?;
    let off = ((rel.x - AHEAD_M).powi(2) + rel.y * rel.y + rel.z * rel.z).sqrt();
    Ok(pose_angle(&p.a) >= A_TURNED_RAD && off <= AHEAD_TOL_M && pose_angle(&rel) <= AHEAD_TOL_RAD)
}

fn ahead_met(model: &PageModel) -> Result<bool, CheckError> {
    b_ahead_of_a(model_of!(model, Se3, "se3-ahead"))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::recipes::se3_relative::relative_transform;
    use crate::view::exercises::exercise::test_attribute::test;
    crate::view::exercises::exercise::page_check!(|p: &Se3Params| PageModel::Se3(p));

    #[test]
    fn se3_distance_is_the_length_of_the_offset() {
        let p = Se3Params::default();
        let truth = distance_m(&p).unwrap();
        assert!((truth - 0.0129f64.sqrt()).abs() < 1e-15, "{truth}");
        assert!(check("se3-distance", &p, Answer::Number(0.11)).right());
        // Adding the components is not a distance.
        assert!(!check("se3-distance", &p, Answer::Number(0.17)).right());
        // Turning A changes the relative coordinates, not the distance.
        let turned = Se3Params {
            a: Pose::from_array([0.0, 0.0, 0.0, 0.4, -0.2, 1.0]),
            ..p
        };
        assert!((distance_m(&turned).unwrap() - truth).abs() < 1e-15);
        let (r, q) = (turned.relative().unwrap(), p.relative().unwrap());
        assert!((r.x - q.x).abs() + (r.y - q.y).abs() + (r.z - q.z).abs() > 0.01);
    }

    #[test]
    fn se3_ahead_is_along_as_own_axis() {
        let yaw = 0.8;
        let a = Pose::from_array([0.2, 0.1, 0.0, 0.0, 0.0, yaw]);
        let ahead = Se3Params {
            a,
            b: Pose::from_array([
                0.2 + AHEAD_M * yaw.cos(),
                0.1 + AHEAD_M * yaw.sin(),
                0.0,
                0.0,
                0.0,
                yaw,
            ]),
        };
        assert_eq!(
            check("se3-ahead", &ahead, Answer::PageState),
            Verdict::Goal { met: true }
        );
        // Along the world's x axis instead: 0.064 m off in A's frame.
        let world_x = Se3Params {
            a,
            b: Pose::from_array([0.3, 0.1, 0.0, 0.0, 0.0, yaw]),
        };
        assert!(!check("se3-ahead", &world_x, Answer::PageState).right());
        // The right place with the world's orientation.
        let unturned_b = Se3Params {
            b: Pose {
                yaw: 0.0,
                ..ahead.b
            },
            ..ahead
        };
        assert!(!b_ahead_of_a(&unturned_b).unwrap());
        // A not turned: the world's axes are A's.
        let plain = Se3Params {
            a: Pose::default(),
            b: Pose::from_array([0.1, 0.0, 0.0, 0.0, 0.0, 0.0]),
        };
        assert!(!b_ahead_of_a(&plain).unwrap());
    }

    #[test]
    fn se3_swap_gives_the_inverse() {
        let p = Se3Params::default();
        let ab = relative_transform(&p.a, &p.b);
        let swapped = Se3Params { a: p.b, b: p.a };
        let ba = relative_transform(&swapped.a, &swapped.b);
        let product = ab * ba;
        assert!((product - nalgebra::Matrix4::identity()).abs().max() < 1e-15);
        // Not the negated numbers: with B turned, its origin seen from B is not −p_rel.
        let rel = p.relative().unwrap();
        let back = swapped.relative().unwrap();
        assert!((back.x + rel.x).abs() > 1e-3);
        assert!(check("se3-swap", &p, Answer::Choice(1)).right());
        for wrong in [0, 2, 3] {
            assert!(!check("se3-swap", &p, Answer::Choice(wrong)).right());
        }
    }
}
