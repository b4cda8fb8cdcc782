//! The progress panel's view model (`crate::ui::kit::progress` draws it): how far a long run
//! is, as a percentage for the bar, rows done of total with digit grouping, the time it has
//! taken and an estimate of the time left. Plain Rust, tested natively.

/// A run is not estimated before it has taken this long or done this share of its rows: the
/// first moments (worker start, allocation) say little about the rate.
const ESTIMATE_AFTER_MS: f64 = 700.0;
const ESTIMATE_AFTER_FRACTION: f64 = 0.02;

/// What the progress panel shows for `done` of `total` rows after `elapsed_ms`.
#[derive(Debug, Clone, PartialEq)]
pub struct ProgressView {
    /// Rows done, never more than `total`.
    pub done: u64,
    pub total: u64,
    /// 0 to 100, for the bar (`aria-valuenow` carries `done` itself).
    pub percent: f64,
    /// `done` and `total` as a person writes them (`1,048,576`).
    pub done_text: String,
    pub total_text: String,
    /// Whole seconds since the run started.
    pub elapsed: Clock,
    /// Whole seconds left at the rate so far (rounded up); `None` until there is a rate.
    pub remaining: Option<Clock>,
}

/// A duration in minutes and seconds, as the panel says it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Clock {
    pub minutes: u64,
    pub seconds: u64,
}

impl Clock {
    /// Whole seconds, split.
    pub fn from_seconds(total: u64) -> Clock {
        Clock {
            minutes: total / 60,
            seconds: total % 60,
        }
    }
}

/// Digits in groups of three with commas (`1048576` → `1,048,576`), in English and Japanese
/// alike.
pub fn group_digits(n: u64) -> String {
    crate::pyfmt::group_u64(n)
}

/// The panel for `done` of `total` rows after `elapsed_ms` milliseconds (a total of 0 means
/// "not known yet": 0 %).
pub fn progress_view(done: u64, total: u64, elapsed_ms: f64) -> ProgressView {
    let done = done.min(total);
    let fraction = if total == 0 {
        0.0
    } else {
        done as f64 / total as f64
    };
    let elapsed_ms = if elapsed_ms.is_finite() {
        elapsed_ms.max(0.0)
    } else {
        0.0
    };
    let remaining = (done > 0
        && done < total
        && (elapsed_ms >= ESTIMATE_AFTER_MS || fraction >= ESTIMATE_AFTER_FRACTION)
        && elapsed_ms >= 100.0)
        .then(|| {
            let left_ms = elapsed_ms * (total - done) as f64 / done as f64;
            Clock::from_seconds((left_ms / 1000.0).ceil() as u64)
        });
    ProgressView {
        done,
        total,
        percent: (fraction * 1000.0).round() / 10.0,
        done_text: group_digits(done),
        total_text: group_digits(total),
        elapsed: Clock::from_seconds((elapsed_ms / 1000.0).floor() as u64),
        remaining,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn digits_are_grouped_by_three() {
        assert_eq!(group_digits(0), "0");
        assert_eq!(group_digits(999), "999");
        assert_eq!(group_digits(1000), "1,000");
        assert_eq!(group_digits(1_048_576), "1,048,576");
        assert_eq!(group_digits(u64::MAX), "18,446,744,073,709,551,615");
    }

    #[test]
    fn a_quarter_done_after_three_seconds_leaves_nine() {
        let v = progress_view(262_144, 1_048_576, 3_000.0);
        assert_eq!(v.percent, 25.0);
        assert_eq!(v.done_text, "262,144");
        assert_eq!(v.total_text, "1,048,576");
        assert_eq!(
            v.elapsed,
            Clock {
                minutes: 0,
                seconds: 3
            }
        );
        assert_eq!(
            v.remaining,
            Some(Clock {
                minutes: 0,
                seconds: 9
            })
        );
    }

    #[test]
    fn long_runs_are_said_in_minutes_and_the_estimate_rounds_up() {
        // 10 % in 75.5 s: 679.5 s left, said as 11 min 20 s.
        let v = progress_view(100, 1000, 75_500.0);
        assert_eq!(
            v.elapsed,
            Clock {
                minutes: 1,
                seconds: 15
            }
        );
        assert_eq!(
            v.remaining,
            Some(Clock {
                minutes: 11,
                seconds: 20
            })
        );
        assert_eq!(v.percent, 10.0);
    }

    #[test]
    fn no_estimate_before_a_rate_is_known_nor_once_done() {
        assert_eq!(progress_view(0, 500, 5_000.0).remaining, None);
        assert_eq!(
            progress_view(1, 1000, 200.0).remaining,
            None,
            "0.1 % after 0.2 s"
        );
        assert!(
            progress_view(30, 1000, 200.0).remaining.is_some(),
            "3 % after 0.2 s"
        );
        assert_eq!(progress_view(1000, 1000, 4_000.0).remaining, None);
        assert_eq!(progress_view(0, 0, 10.0).percent, 0.0);
    }

    #[test]
    fn done_is_capped_and_bad_clocks_read_zero() {
        let v = progress_view(7, 5, f64::NAN);
        assert_eq!((v.done, v.percent), (5, 100.0));
        assert_eq!(v.elapsed, Clock::from_seconds(0));
        assert_eq!(progress_view(1, 3, -50.0).elapsed.seconds, 0);
        assert_eq!(progress_view(1, 3, 0.0).percent, 33.3);
    }
}
