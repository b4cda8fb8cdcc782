//! The trapezoidal profile (`#/trapezoid-profile`): position, velocity and acceleration over
//! time on three panels sharing the time axis, the accelerate / cruise / brake phases shaded
//! and labelled; says when the move is a triangle (too short to reach vmax) and shows t_acc,
//! t_flat, t_total and the peak velocity reached. vmax and amax are dragged on the velocity
//! plot (or with the sliders); the CSV is the recipe's (`bsv trapezoid-profile`).
//!
//! A drill on the signal kit ([`crate::ui::kit::signal_page`]): `page` (its spec, readouts and
//! drags) and `plots` (the panels, phase bands and handles); the numbers come from the
//! kernel's samples and `crate::view::trapezoid_profile`.

mod page;
mod plots;

pub use self::page::TrapPage;
use crate::ui::kit::signal_page::Signal;
use crate::ui::page::PageDef;

/// The page, as the shell's page table lists it.
pub const PAGE: PageDef =
    PageDef::of::<Signal<TrapPage>>("trapezoid-profile", "trap-title", "trap-blurb");
