//! Pure view models of the browser pages: plain Rust, no web-sys, so `cargo test` covers them
//! natively (the wasm-only `crate::ui` module draws what these compute).
//!
//! - [`url`]: the URL codec (`#/<page>?k=v`, percent-encoding, `lang`).
//! - [`stepper`]: the stepper's state machine (step, back, play at a speed, scrub).

pub mod stepper;
pub mod url;
