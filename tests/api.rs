//! The wasm API as JavaScript sees it (runs under `wasm-pack test --node`): `runRecipe` errors
//! are real JS `Error`s with the CLI's message, `listRecipes` describes every recipe, and the
//! stepping handles reproduce the recipes' reference runs.
#![cfg(all(target_arch = "wasm32", feature = "api"))]

use bsv_playground::api::{
    list_recipes, plan_recipe, run_recipe, run_recipe_with_progress, PendulumHandle, RrtHandle,
};
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

fn get(v: &JsValue, key: &str) -> JsValue {
    js_sys::Reflect::get(v, &key.into()).unwrap()
}

#[test]
fn list_recipes_exposes_the_facts() {
    let list = js_sys::Array::from(&list_recipes().unwrap());
    // manip-grid (10th): n is an integer from 1 to 1024 with a hint; the page is ik-2r.
    let manip = list.get(9);
    assert_eq!(get(&manip, "id").as_string().as_deref(), Some("manip-grid"));
    assert_eq!(get(&manip, "page").as_string().as_deref(), Some("ik-2r"));
    assert_eq!(
        get(&manip, "quirksId").as_string().as_deref(),
        Some("recipe-manip-grid-quirks")
    );
    let args = js_sys::Array::from(&get(&manip, "args"));
    let l1 = args.get(0);
    assert_eq!(get(&l1, "unit").as_string().as_deref(), Some("m"));
    assert_eq!(get(&get(&l1, "max"), "value").as_f64(), Some(10.0));
    let n = args.get(2);
    assert_eq!(get(&n, "kind").as_string().as_deref(), Some("integer"));
    assert_eq!(get(&get(&n, "min"), "value").as_f64(), Some(1.0));
    assert_eq!(get(&get(&n, "max"), "value").as_f64(), Some(1024.0));
    assert_eq!(get(&get(&n, "max"), "inclusive").as_bool(), Some(true));
    assert_eq!(
        get(&n, "hintId").as_string().as_deref(),
        Some("recipe-manip-grid-hint-n")
    );
    assert_eq!(
        get(&n, "labelId").as_string().as_deref(),
        Some("recipe-manip-grid-arg-n")
    );
    // pendulum-energy's integrator is a choice.
    let flags = js_sys::Array::from(&get(&list.get(0), "flags"));
    let integrator = flags.get(6);
    assert_eq!(
        get(&integrator, "kind").as_string().as_deref(),
        Some("choice")
    );
    assert_eq!(
        js_sys::Array::from(&get(&integrator, "choices")).length(),
        2
    );
    assert!(get(&integrator, "min").is_null() || get(&integrator, "min").is_undefined());
}

#[test]
fn progress_runs_match_plain_runs_and_report_up_to_the_plan() {
    let args = strings(&["0.12", "0.10", "64"]);
    let plain = run_recipe("manip-grid", args.clone(), None).unwrap();
    let calls = js_sys::Array::new();
    let keep = calls.clone();
    let cb = wasm_bindgen::closure::Closure::<dyn FnMut(f64, f64)>::new(move |d: f64, t: f64| {
        keep.push(&js_sys::Array::of2(&d.into(), &t.into()));
    });
    let tracked = run_recipe_with_progress(
        "manip-grid",
        args.clone(),
        None,
        cb.as_ref().unchecked_ref(),
    )
    .unwrap();
    let text = |v: &JsValue| {
        let files = js_sys::Array::from(&get(v, "files"));
        get(&files.get(0), "text").as_string().unwrap()
    };
    assert_eq!(text(&plain), text(&tracked));
    assert_eq!(plan_recipe("manip-grid", args, None).unwrap(), 4096.0);
    let last = js_sys::Array::from(&calls.get(calls.length() - 1));
    assert_eq!(last.get(0).as_f64(), Some(4096.0));
    assert!(calls.length() <= 102, "{}", calls.length());
    // Warnings come with the run.
    let run = run_recipe("pid-step", strings(&["1e9"]), None).unwrap();
    let warnings = js_sys::Array::from(&get(&run, "warnings"));
    assert_eq!(
        get(&warnings.get(0), "id").as_string().as_deref(),
        Some("warn-not-finite")
    );
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
    assert!(RrtHandle::new(strings(&["7", "1000001"])).is_err());
}

#[test]
fn rrt_handle_steps_back_exactly_and_describes_each_iteration() {
    let args = strings(&[
        "7",
        "2000",
        "--obstacle",
        "0.2,0.3,0.4,0.9",
        "--obstacle",
        "0.6,0,0.8,0.7",
        "--goal",
        "0.95,0.85",
    ]);
    let mut rrt = RrtHandle::new(args.clone()).unwrap();
    assert!(rrt.record().unwrap().is_null());
    assert_eq!(
        rrt.obstacles(),
        vec![0.2, 0.3, 0.4, 0.9, 0.6, 0.0, 0.8, 0.7]
    );
    assert_eq!(rrt.seek(150), 150);
    let (nodes, parents, counts) = (rrt.nodes(), rrt.parents(), rrt.counts());
    assert_eq!(counts.iter().sum::<u32>(), 150);
    assert_eq!(counts[0] as usize + 1, rrt.node_count());
    let record = rrt.record().unwrap();
    let get = |k: &str| js_sys::Reflect::get(&record, &k.into()).unwrap();
    assert_eq!(get("iteration").as_f64(), Some(150.0));
    assert!(get("outcome").as_string().is_some());
    let later = rrt.seek(400);
    assert!(later > 150);
    assert_eq!(rrt.back((later - 150) as u32), 150);
    assert_eq!(
        (rrt.nodes(), rrt.parents(), rrt.counts()),
        (nodes, parents, counts)
    );
    assert_eq!(rrt.nodes_from(rrt.node_count() - 1).len(), 2);
    // The end of the stepped run is runRecipe's output.
    rrt.seek(u32::MAX);
    let stepped = rrt.output().unwrap();
    let batch = run_recipe("rrt-2d", args, None).unwrap();
    let summary = |v: &JsValue| {
        js_sys::Reflect::get(v, &"summary".into())
            .unwrap()
            .as_string()
    };
    assert_eq!(summary(&stepped), summary(&batch));
    assert!(RrtHandle::new(strings(&["7", "800", "--start", "0.5,0.5"])).is_err());
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
