//! The page kit: what every page is built from. Each widget owns its elements, state and
//! listeners; pure parts (codecs, state machines, view models) live in [`crate::view`].
//!
//! - [`worker`]: long recipe runs in a Web Worker (same wasm), with progress and cancel.
//! - [`progress`]: the progress panel of such a run (bar, rows, time left, Cancel).

pub mod progress;
pub mod worker;
