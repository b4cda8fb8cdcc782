//! Pure view models of the pages: plain Rust (no web-sys), tested natively by `cargo test`.
//! The wasm-only `ui` module draws what these compute.

pub mod drag;
pub mod heatmap;
pub mod ik2r;
pub mod plot;
