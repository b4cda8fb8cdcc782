//! Fluent bundles embedded from `locales/`, language choice and per-message fallback.
//! PLACEHOLDER until the shell lands.
