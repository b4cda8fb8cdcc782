//! The wasm API as JavaScript sees it (runs under `wasm-pack test --node`): `runRecipe` errors
//! are real JS `Error`s with the CLI's message, `listRecipes` describes every recipe, and the
//! stepping handles reproduce the recipes' reference runs.
#![cfg(target_arch = "wasm32")]

use bsv_playground::api::{list_recipes, run_recipe, PendulumHandle, RrtHandle};
use wasm_bindgen::{JsCast, JsValue};
use wasm_bindgen_test::wasm_bindgen_test as test;

fn strings(v: &[&str]) -> Vec<String> {
    v.iter().map(|s| s.to_string()).collect()
}

fn csv_rows(text: &str) -> Vec<Vec<f64>> {
    text.lines()
        .skip(1)
        .map(|l| {
            l.split(',')
                .map(|c| c.parse().unwrap_or(f64::NAN))
                .collect()
        })
        .collect()
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-12 + 1e-9 * b.abs()
}

#[test]
fn run_recipe_errors_are_js_errors_naming_the_argument() {
    let err = run_recipe("ik-workspace", strings(&["0.12", "abc"]), None).unwrap_err();
    let err: js_sys::Error = JsValue::from(err).dyn_into().expect("a JS Error");
    assert_eq!(err.message(), "L2: 'abc' is not a number");
    let err = run_recipe("nope", vec![], None).unwrap_err();
    let err: js_sys::Error = JsValue::from(err).dyn_into().expect("a JS Error");
    assert!(String::from(err.message()).contains("unknown recipe 'nope'"));
}

#[test]
fn list_recipes_describes_all_twelve() {
    let list = js_sys::Array::from(&list_recipes().unwrap());
    assert_eq!(list.length(), 12);
    let first = list.get(0);
    let id = js_sys::Reflect::get(&first, &"id".into()).unwrap();
    assert_eq!(id.as_string().as_deref(), Some("pendulum-energy"));
    let args = js_sys::Array::from(&js_sys::Reflect::get(&first, &"args".into()).unwrap());
    let default = js_sys::Reflect::get(&args.get(0), &"default".into()).unwrap();
    assert_eq!(default.as_string().as_deref(), Some("5"));
}

#[test]
fn rrt_handle_grows_the_reference_tree_step_by_step() {
    let mut rrt = RrtHandle::new(strings(&["7", "800"])).unwrap();
    let mut last = 0;
    while !rrt.done() {
        let nodes = rrt.step(10);
        assert!(nodes >= last);
        last = nodes;
    }
    assert!(rrt.found());
    let reference = csv_rows(include_str!("golden/rrt_default/rrt_nodes.csv"));
    let (nodes, parents) = (rrt.nodes(), rrt.parents());
    assert_eq!(nodes.len(), reference.len() * 2);
    for (i, row) in reference.iter().enumerate() {
        assert!(
            close(nodes[2 * i], row[1]) && close(nodes[2 * i + 1], row[2]),
            "node {i}"
        );
        assert_eq!(parents[i] as f64, row[3], "parent of {i}");
    }
    let path = csv_rows(include_str!("golden/rrt_default/rrt_path.csv"));
    assert_eq!(rrt.path().len(), path.len() * 2);
    assert!(RrtHandle::new(strings(&["7", "999999"])).is_err());
}

#[test]
fn pendulum_handle_advances_through_the_reference_run() {
    let mut pendulum = PendulumHandle::new(vec![]).unwrap();
    let reference = csv_rows(include_str!("golden/pendulum_default/pendulum_energy.csv"));
    let mut rows = pendulum.advance(1000);
    rows.extend(pendulum.advance(1500));
    assert_eq!(rows.len(), reference.len() * 7);
    for (i, want) in reference.iter().enumerate() {
        for (c, w) in want.iter().enumerate() {
            assert!(
                close(rows[7 * i + c], *w),
                "row {i} column {c}: {} vs {w}",
                rows[7 * i + c]
            );
        }
    }
    assert!(close(pendulum.time_s(), 5.0));
    let err = PendulumHandle::new(strings(&["5", "--integrator", "leapfrog"])).err();
    assert!(err.is_some());
}
