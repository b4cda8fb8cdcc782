//! Pure view models of the browser pages: plain Rust, no web-sys, so `cargo test` covers them
//! natively (the wasm-only `crate::ui` module draws what these compute).
//!
//! - [`url`]: the URL codec (`#/<page>?k=v`, percent-encoding, `lang`).
//! - [`form`]: the parameter form's fields and validation; [`command_line`]: `bsv` / `python`
//!   lines of a run; [`table`]: CSV previews and rounded cells.
//! - [`stepper`]: the stepper's state machine (step, back, play at a speed, scrub).

pub mod command_line;
pub mod form;
pub mod stepper;
pub mod table;
pub mod url;
