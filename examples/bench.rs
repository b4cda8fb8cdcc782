//! Native half of `make bench`: each case of `bsv_playground::bench::CASES`, median of 5 runs.

use std::time::Instant;

use bsv_playground::bench::{self, CASES};

fn main() {
    println!("| case | native median ms | min ms | output rows |");
    println!("|---|---:|---:|---:|");
    for case in CASES {
        let mut times = Vec::new();
        let mut rows = 0;
        for _ in 0..5 {
            let inputs = bench::inputs(case);
            let start = Instant::now();
            match bench::run(case, inputs) {
                Ok(out) => {
                    rows = out
                        .files
                        .iter()
                        .map(|f| f.text.lines().count() - 1)
                        .max()
                        .unwrap_or(0)
                }
                Err(e) => {
                    println!("| {} | error: {e} | | |", case.name);
                    break;
                }
            }
            times.push(start.elapsed().as_secs_f64() * 1e3);
        }
        if times.is_empty() {
            continue;
        }
        let min = times.iter().copied().fold(f64::INFINITY, f64::min);
        println!(
            "| {} | {:.1} | {:.1} | {rows} |",
            case.name,
            bench::median(&mut times),
            min
        );
    }
}
