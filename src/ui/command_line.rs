//! Shell quoting for the command lines the pages show: the one builder is
//! [`crate::view::command_line`] (natively tested); this re-export keeps `ui::command_line`
//! paths working.

pub use crate::view::command_line::shell_word;
