//! The PID step response (`#/pid-step`): y, r and u over the steps, live while Kp, Ki, Kd, tau
//! and steps are dragged (sliders beside their fields); rise time, overshoot, settling time,
//! steady-state error and peak u from the exact samples (`crate::view::pid_step`); a ghost of
//! the previous gains stays drawn until the next change, so a class compares tunings; the
//! recipe's warning when the loop diverges. The CSV is the recipe's (`bsv pid-step`).
//!
//! A drill on the signal kit ([`crate::ui::kit::signal_page`]): `page` (its spec, the runs
//! and their readouts) and `plots` (y and r above, u below, and the ghost).

mod page;
mod plots;

pub use self::page::PidPage;
use crate::ui::kit::signal_page::Signal;
use crate::ui::page::PageDef;

/// The page, as the shell's page table lists it.
pub const PAGE: PageDef = PageDef::of::<Signal<PidPage>>("pid-step", "pid-title", "pid-blurb");
