//! Pure view models of the browser pages: plain Rust, no web-sys, so `cargo test` covers them
//! natively (the wasm-only `crate::ui` module draws what these compute).
//!
//! - [`progress`]: the progress panel of long runs (percent, rows, time left).
//! - [`worker`]: the preview head of a file a worker run sends back.

pub mod progress;
pub mod worker;
