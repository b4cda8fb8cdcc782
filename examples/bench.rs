//! Native half of `make bench`: each case of `bsv_playground::bench::CASES`, median of 5 runs,
//! through the typed kernel (what a page calls) and as the whole recipe (with CSV text).

use std::time::Instant;

use bsv_playground::bench::{self, BenchCase, CASES};

fn time<T>(case: &BenchCase, mut f: impl FnMut(Vec<(String, String)>) -> T) -> (f64, T) {
    let mut times = Vec::new();
    let mut last = None;
    for _ in 0..5 {
        let inputs = bench::inputs(case);
        let start = Instant::now();
        last = Some(f(inputs));
        times.push(start.elapsed().as_secs_f64() * 1e3);
    }
    let value = last.expect("5 runs");
    (bench::median(&mut times), value)
}

fn main() {
    // An optional argument keeps only the cases whose name contains it.
    let filter = std::env::args().nth(1).unwrap_or_default();
    println!("| case | native kernel ms | native recipe + CSV ms |");
    println!("|---|---:|---:|");
    for case in CASES.iter().filter(|c| c.name.contains(filter.as_str())) {
        let (kernel_ms, kernel) = time(case, |inputs| (case.kernel)(&inputs));
        let (recipe_ms, recipe) = time(case, |inputs| bench::run(case, inputs));
        if let Err(e) = kernel.as_ref().map(|_| ()).and(recipe.as_ref().map(|_| ())) {
            println!("| {} | error: {e} | |", case.name);
            continue;
        }
        println!("| {} | {kernel_ms:.1} | {recipe_ms:.1} |", case.name);
    }
}
