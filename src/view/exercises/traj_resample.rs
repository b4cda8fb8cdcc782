//! The resampling page's exercises (`#/traj-resample`): predict the number of rows of the
//! new grid, pick a step that misses the trajectory's peak, and whether linear interpolation
//! can pass a sample. The resampled table is the kernel's ([`resample`]).

use super::exercise::{CheckError, Exercise, PageModel, Tolerance};
use crate::recipes::traj_resample::{resample, Resampled, Trajectory};

/// The page's route id.
pub const PAGE: &str = "traj-resample";

/// `traj-miss-peak`: how far below the first joint's peak the resampled peak must stay.
pub const MISS_PEAK_BY: f64 = 0.05;

/// The page's exercises, in the order it lists them.
#[rustfmt::skip]
pub const EXERCISES: [Exercise; 3] = [
    Exercise::predict("traj-rows", PAGE, "", Tolerance::Absolute(0.0), rows_truth),
    Exercise::goal("traj-miss-peak", PAGE, miss_peak_met),
    // 1: no, every new value lies between two samples.
    Exercise::choose("traj-between", PAGE, 3, 1),
];

/// The page's trajectory and step, or the error for another page's model.
fn model<'a>(
    model: &PageModel<'a>,
    exercise: &'static str,
) -> Result<(&'a Trajectory, f64), CheckError> {
    match *model {
        PageModel::TrajResample(trajectory, dt) => Ok((trajectory, dt)),
        other => Err(CheckError::OtherPage {
            exercise,
            page: other.page(),
        }),
    }
}

fn resampled(trajectory: &Trajectory, dt: f64) -> Result<Resampled, CheckError> {
    Ok(resample(trajectory, dt)?)
}

/// `traj-rows`: the rows of the resampled table (without its header).
pub fn rows(trajectory: &Trajectory, dt: f64) -> Result<f64, CheckError> {
    Ok(resampled(trajectory, dt)?.t.len() as f64)
}

fn rows_truth(m: &PageModel) -> Result<f64, CheckError> {
    let (trajectory, dt) = model(m, "traj-rows")?;
    rows(trajectory, dt)
}

fn peak(values: &[f64]) -> f64 {
    values.iter().copied().fold(f64::NEG_INFINITY, f64::max)
}

/// `traj-miss-peak`: the first joint's resampled peak is at least [`MISS_PEAK_BY`] below its
/// peak in the samples (the new grid steps over it).
pub fn misses_peak(trajectory: &Trajectory, dt: f64) -> Result<bool, CheckError> {
    let new = resampled(trajectory, dt)?;
    match (trajectory.q.first(), new.q.first()) {
        (Some(old), Some(new)) => Ok(peak(new) <= peak(old) - MISS_PEAK_BY),
        _ => Ok(false),
    }
}

fn miss_peak_met(m: &PageModel) -> Result<bool, CheckError> {
    let (trajectory, dt) = model(m, "traj-miss-peak")?;
    misses_peak(trajectory, dt)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::recipes::traj_resample::{parse_trajectory, SAMPLE};
    use crate::view::exercises::exercise::test_attribute::test;
    crate::view::exercises::exercise::page_check!(|dt: f64| PageModel::TrajResample(
        &parse_trajectory(SAMPLE).unwrap(),
        dt
    ));

    #[test]
    fn traj_rows_counts_the_new_grid() {
        let sample = parse_trajectory(SAMPLE).unwrap();
        // 0 to 0.55 s every 0.02 s: 0.00 ... 0.54, 28 rows (0.56 is past the end).
        assert_eq!(rows(&sample, 0.02).unwrap(), 28.0);
        assert!(check("traj-rows", 0.02, Answer::Number(28.0)).right());
        assert!(!check("traj-rows", 0.02, Answer::Number(27.0)).right());
        // 0.55 / 0.05 = 11 steps: the end itself is a row.
        assert_eq!(rows(&sample, 0.05).unwrap(), 12.0);
        assert!(!check("traj-rows", 0.05, Answer::Number(11.0)).right());
    }

    #[test]
    fn traj_miss_peak_needs_a_coarse_grid_off_the_peak() {
        let sample = parse_trajectory(SAMPLE).unwrap();
        // The peak, q1 = 0.7 at 0.4 s: 0.02 s and 0.2 s land on it, 0.3 s does not.
        assert!(!check("traj-miss-peak", 0.02, Answer::PageState).right());
        assert!(!misses_peak(&sample, 0.2).unwrap());
        assert_eq!(
            check("traj-miss-peak", 0.3, Answer::PageState),
            Verdict::Goal { met: true }
        );
        let new = resample(&sample, 0.3).unwrap();
        assert!((peak(&new.q[0]) - (0.5 + 0.2 / 3.0)).abs() < 1e-12);
        assert!(matches!(
            find("traj-miss-peak")
                .unwrap()
                .check(&PageModel::TrajResample(&sample, 0.0), Answer::PageState),
            Err(CheckError::Kernel(_))
        ));
    }

    #[test]
    fn traj_between_no_value_passes_the_samples() {
        let sample = parse_trajectory(SAMPLE).unwrap();
        for dt in [0.003, 0.02, 0.07, 0.3] {
            let new = resample(&sample, dt).unwrap();
            for (old, new) in sample.q.iter().zip(&new.q) {
                let lo = old.iter().copied().fold(f64::INFINITY, f64::min);
                assert!(new.iter().all(|v| (lo..=peak(old)).contains(v)), "{dt}");
            }
        }
        assert!(check("traj-between", 0.02, Answer::Choice(1)).right());
        assert!(!check("traj-between", 0.02, Answer::Choice(0)).right());
        assert!(!check("traj-between", 0.02, Answer::Choice(2)).right());
    }
}
