//! The cubic path (`#/cubic-path`): position, velocity and acceleration of the recipe's cubic
//! on three panels sharing the time axis, recomputed while a value is dragged (a slider, a
//! field, or the end point q1 at T on the position plot); a cursor readout at the hovered time;
//! the quintic and the same-time trapezoid as optional overlays (not exported: the CSV stays
//! the recipe's, byte for byte what `bsv cubic-path` writes).
//!
//! A drill on the signal kit ([`crate::ui::kit::signal_page`]): `page` (its spec, readouts
//! and the end-point drag) and `plots` (the panels, overlays and handle); the numbers come
//! from the pure `crate::view::cubic_path`.

mod page;
mod plots;

pub use self::page::CubicPage;
use crate::ui::kit::signal_page::Signal;
use crate::ui::page::PageDef;

/// The page, as the shell's page table lists it.
pub const PAGE: PageDef =
    PageDef::of::<Signal<CubicPage>>("cubic-path", "cubic-title", "cubic-blurb");
