//! The browser UI (wasm32 only): the app shell and its pages. PLACEHOLDER until it lands.

pub mod page;
