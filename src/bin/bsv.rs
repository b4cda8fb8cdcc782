//! `bsv <recipe-id> [args] [--out DIR]`. PLACEHOLDER until the CLI lands.
fn main() {}
