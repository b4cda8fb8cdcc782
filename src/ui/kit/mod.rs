//! The page kit: widgets and panels every live page is built from.

pub mod canvas;
pub mod drag;
pub mod frame;
pub mod heatmap;
pub mod plot;
