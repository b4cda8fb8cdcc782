//! Shared by the golden tests: run a recipe (natively through `recipes::run_with_inputs`, in
//! wasm through the exported `runRecipe`) and compare CSVs the way `shared/tools/csvcmp.py` does.

#![allow(dead_code)]

/// Files `(name, text)` and the summary line of one run.
pub struct Run {
    pub files: Vec<(String, String)>,
    pub summary: String,
}

impl Run {
    pub fn file(&self, name: &str) -> &str {
        match self.files.iter().find(|(n, _)| n == name) {
            Some((_, t)) => t,
            None => panic!(
                "run wrote no {name}; it wrote {:?}",
                self.files.iter().map(|f| &f.0).collect::<Vec<_>>()
            ),
        }
    }
}

#[cfg(not(target_arch = "wasm32"))]
pub fn run(id: &str, args: &[&str], inputs: &[(&str, &str)]) -> Result<Run, String> {
    let args: Vec<String> = args.iter().map(|s| s.to_string()).collect();
    let inputs = inputs
        .iter()
        .map(|(n, t)| (n.to_string(), t.to_string()))
        .collect();
    let out =
        bsv_playground::recipes::run_with_inputs(id, &args, inputs).map_err(|e| e.to_string())?;
    Ok(Run {
        files: out.files.into_iter().map(|f| (f.name, f.text)).collect(),
        summary: out.summary,
    })
}

#[cfg(target_arch = "wasm32")]
pub fn run(id: &str, args: &[&str], inputs: &[(&str, &str)]) -> Result<Run, String> {
    use wasm_bindgen::JsValue;
    let args: Vec<String> = args.iter().map(|s| s.to_string()).collect();
    let obj = js_sys::Object::new();
    for (n, t) in inputs {
        js_sys::Reflect::set(&obj, &JsValue::from_str(n), &JsValue::from_str(t))
            .map_err(|e| format!("{e:?}"))?;
    }
    let value = bsv_playground::api::run_recipe(id, args, Some(obj))
        .map_err(|e| JsValue::from(e).as_ref().clone())
        .map_err(|e: JsValue| {
            js_sys::Error::from(e)
                .message()
                .as_string()
                .unwrap_or_default()
        })?;
    let out: bsv_playground::api::JsRun =
        serde_wasm_bindgen::from_value(value).map_err(|e| e.to_string())?;
    Ok(Run {
        files: out.files.into_iter().map(|f| (f.name, f.text)).collect(),
        summary: out.summary,
    })
}

fn num(s: &str) -> Option<f64> {
    let t = s.trim();
    match t {
        "nan" => Some(f64::NAN),
        "inf" => Some(f64::INFINITY),
        "-inf" => Some(f64::NEG_INFINITY),
        _ => t.parse().ok(),
    }
}

fn rows(text: &str) -> Vec<Vec<String>> {
    text.lines()
        .filter(|l| !l.is_empty())
        .map(|l| l.split(',').map(str::to_string).collect())
        .collect()
}

/// Headers exact, row counts equal, empty cells empty in both, numbers within
/// `1e-12 + 1e-9 |ref|` (nan equals nan); panics with the first differences.
pub fn assert_csv_close(what: &str, reference: &str, produced: &str) {
    let (r, g) = (rows(reference), rows(produced));
    assert_eq!(r.first(), g.first(), "{what}: header");
    assert_eq!(r.len(), g.len(), "{what}: row count");
    let mut bad = Vec::new();
    for (i, (rr, gg)) in r.iter().zip(&g).enumerate().skip(1) {
        assert_eq!(rr.len(), gg.len(), "{what}: line {} cell count", i + 1);
        for (c, (x, y)) in rr.iter().zip(gg).enumerate() {
            if x == y {
                continue;
            }
            match (num(x), num(y)) {
                (Some(a), Some(b)) if a.is_nan() && b.is_nan() => {}
                (Some(a), Some(b)) if (a - b).abs() <= 1e-12 + 1e-9 * a.abs() => {}
                _ => bad.push(format!("line {} col {}: {x} vs {y}", i + 1, r[0][c])),
            }
        }
    }
    assert!(
        bad.is_empty(),
        "{what}: {} cells differ, first: {:?}",
        bad.len(),
        &bad[..bad.len().min(5)]
    );
}

/// The stdout of a reference run, without its final newline.
pub fn stdout(text: &str) -> &str {
    text.trim_end_matches(['\n', '\r'])
}
