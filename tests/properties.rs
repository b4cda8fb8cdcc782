#![cfg(not(target_arch = "wasm32"))]
//! Cross-recipe properties (proptest, native only):
//!
//! - every recipe in `RECIPES`, fed random argument strings (numbers in and out of range,
//!   garbage, empty, huge, NaN, unknown flags), never panics and either fails with an error or
//!   returns well-formed output without `nan` where the Python recipe would not print one;
//! - every recipe returns `Ok` for valid arguments (its defaults, scaled), and the six recipes
//!   with typed entry points return `Ok` across their valid ranges, with the typed API and the
//!   CSV path agreeing;
//! - FK(IK(p)) = p inside the reachable annulus of a planar 2R arm, for both elbow branches.
//!
//! - `plan` (parse + validate, no run) fails exactly when the run fails, with the same error,
//!   and a run with progress gives the very same output as one without, its reports rising
//!   to `total` in at most ~100 steps.
//!
//! All twelve recipes are tested. Case counts keep the whole file to a few seconds.

use bsv_playground::planar2r::{Arm, Elbow};
use bsv_playground::recipes::{
    self, cubic_path, ik_workspace, jacobian_2r, manip_grid, pid_step, trapezoid_profile,
    RecipeOutput, RECIPES,
};
use bsv_playground::RecipeError;
use proptest::prelude::*;

/// `cases` cases; failures are reported with their minimal input, not persisted to a file.
fn config(cases: u32) -> ProptestConfig {
    ProptestConfig {
        failure_persistence: None,
        ..ProptestConfig::with_cases(cases)
    }
}

fn run(id: &str, raw: &[String]) -> Result<RecipeOutput, RecipeError> {
    recipes::run(id, raw)
}

fn has_nan(text: &str) -> bool {
    text.contains("nan") || text.contains("NaN")
}

/// Whether a CSV shows a loop that blew up: an infinity, or a number of magnitude >= 1e100.
fn shows_divergence(csv: &str) -> bool {
    csv.split(['\r', '\n', ','])
        .filter_map(|cell| cell.parse::<f64>().ok())
        .any(|v| v.is_infinite() || v.abs() >= 1e100)
}

/// Output checks shared by every `Ok`: files are the declared ones, CSV text is Python's
/// (`\r\n` rows, a header), and `nan` appears only where the reference prints it:
/// rrt-2d's summary (path length when the goal is not reached) and a diverging pid-step loop.
fn check_output(id: &str, out: &RecipeOutput, writes: &[&str]) -> Result<(), TestCaseError> {
    prop_assert!(!out.summary.is_empty(), "{id}: empty summary");
    prop_assert!(
        !out.summary.ends_with('\n'),
        "{id}: summary ends with a newline"
    );
    for file in &out.files {
        prop_assert!(
            writes.contains(&file.name.as_str()),
            "{id}: undeclared file {}",
            file.name
        );
        // csv.writer rows end in CRLF; a file Python writes verbatim (traj-resample's
        // sample) ends in LF. Either way: a header and a complete last line.
        prop_assert!(
            file.text.ends_with('\n') && file.text.lines().next().is_some_and(|h| !h.is_empty()),
            "{id}: {} is not a complete table",
            file.name
        );
        let nan_ok = id == "pid-step" && shows_divergence(&file.text);
        prop_assert!(
            nan_ok || !has_nan(&file.text),
            "{id}: nan in {}: {}",
            file.name,
            &file.text[..file.text.len().min(400)]
        );
    }
    let nan_ok =
        id == "rrt-2d" || (id == "pid-step" && out.files.iter().any(|f| shows_divergence(&f.text)));
    prop_assert!(
        nan_ok || !has_nan(&out.summary),
        "{id}: nan in summary {}",
        out.summary
    );
    Ok(())
}

/// One argument as a user might type it: numbers of every size and sign, integers, lists,
/// special values, garbage.
fn arg_text() -> impl Strategy<Value = String> {
    prop_oneof![
        4 => (-10.0f64..10.0).prop_map(|v| v.to_string()),
        2 => (-1e4f64..1e4).prop_map(|v| format!("{v:e}")),
        2 => (-50i64..3000).prop_map(|v| v.to_string()),
        2 => any::<f64>().prop_map(|v| v.to_string()),
        1 => any::<i64>().prop_map(|v| v.to_string()),
        1 => (-3.0f64..3.0, -3.0f64..3.0, -3.0f64..3.0)
            .prop_map(|(a, b, c)| format!("{a},{b},{c}")),
        3 => prop::sample::select(vec![
            "0", "-0", "0.0", "1", "-1", "1e308", "-1e308", "1e-308", "5e-324", "1e400",
            "-1e400", "nan", "NaN", "inf", "-inf", "infinity", "", " ", "abc", "1,2", "1,2,3",
            "1,,2", "1e-12", "99999999999999999999", "-99999999999999999999", "--", "-", ".",
            "1_000", "0x10", "１", "1e", "+5", " 3 ", "euler", "rk4", "2.5e-6", "1000001",
            "1024", "1025", "1001",
        ])
        .prop_map(str::to_string),
        1 => "[ -~]{0,12}",
    ]
}

/// A recipe index, positional arguments and (flag selector, value, unknown-flag) triples.
fn raw_call() -> impl Strategy<Value = (usize, Vec<String>, Vec<(usize, String, bool)>)> {
    (
        0..RECIPES.len(),
        prop::collection::vec(arg_text(), 0..=13),
        prop::collection::vec(
            (any::<usize>(), arg_text(), prop::bool::weighted(0.1)),
            0..=3,
        ),
    )
}

proptest! {
    #![proptest_config(config(160))]

    #[test]
    fn random_arguments_never_panic((index, positional, flags) in raw_call()) {
        let recipe = &RECIPES[index];
        let info = recipe.info;
        let mut raw = positional;
        for (pick, value, unknown) in flags {
            if unknown || info.flags.is_empty() {
                raw.push("--no-such-flag".to_string());
            } else {
                raw.push(format!("--{}", info.flags[pick % info.flags.len()].name));
            }
            raw.push(value);
        }
        let plan = recipes::plan(info.id, &raw, Vec::new());
        match run(info.id, &raw) {
            Ok(out) => {
                check_output(info.id, &out, info.writes)?;
                prop_assert!(plan.is_ok(), "{}: plan {plan:?} but the run is Ok", info.id);
            }
            Err(e) => {
                // Every error renders, and one naming parameters names real ones.
                prop_assert!(!e.to_string().is_empty());
                prop_assert_eq!(e.param(), e.params().first().copied());
                for param in e.params() {
                    let known = info.args.iter().chain(info.flags).any(|a| a.name == param);
                    prop_assert!(known || param == "out", "{}: unknown param {param} in {e}", info.id);
                }
                // plan rejects what the run rejects, with the same error.
                prop_assert_eq!(plan, Err(e));
            }
        }
    }
}

/// Whether every comma-separated part of a default is a number (so it can be scaled).
fn numeric_default(text: &str) -> bool {
    !text.is_empty() && text.split(',').all(|p| p.trim().parse::<f64>().is_ok())
}

/// A default scaled by `factor`: integers stay integers, lists scale element-wise.
fn scaled(text: &str, factor: f64) -> String {
    text.split(',')
        .map(|part| {
            let part = part.trim();
            match part.parse::<i64>() {
                Ok(i) => ((i as f64 * factor).round() as i64)
                    .max(i.min(1))
                    .to_string(),
                Err(_) => {
                    let v: f64 = part.parse().unwrap_or(0.0);
                    (v * factor).to_string()
                }
            }
        })
        .collect::<Vec<_>>()
        .join(",")
}

proptest! {
    #![proptest_config(config(48))]

    #[test]
    fn scaled_defaults_are_accepted(
        index in 0..RECIPES.len(),
        factors in prop::collection::vec((0.5f64..1.5, any::<bool>()), 13),
    ) {
        let info = RECIPES[index].info;
        // Pass a prefix of the positional arguments, up to the first non-numeric default
        // (a path, a choice), varying each numeric one or leaving its default text.
        let mut raw = Vec::new();
        for (spec, (factor, vary)) in info.args.iter().zip(&factors) {
            if !numeric_default(spec.default) {
                break;
            }
            raw.push(if *vary { scaled(spec.default, *factor) } else { spec.default.to_string() });
        }
        match run(info.id, &raw) {
            Ok(out) => check_output(info.id, &out, info.writes)?,
            Err(e) => prop_assert!(false, "{} {raw:?}: {e}", info.id),
        }
    }
}

fn single_file(out: &RecipeOutput) -> &str {
    out.files.first().map_or("", |f| f.text.as_str())
}

fn strings(values: &[f64]) -> Vec<String> {
    values.iter().map(|v| v.to_string()).collect()
}

proptest! {
    #![proptest_config(config(40))]

    #[test]
    fn ik_workspace_valid_and_typed_equals_csv(
        l1 in 0.01f64..1.0,
        l2 in 0.01f64..1.0,
        half_mm in 0.0f64..1500.0,
        per_axis in 1u32..60,
    ) {
        let step_mm = (2.0 * half_mm / f64::from(per_axis)).max(0.5);
        let params = ik_workspace::WorkspaceParams { l1, l2, half_mm, step_mm };
        let ws = ik_workspace::compute(&params).map_err(|e| TestCaseError::fail(e.to_string()))?;
        let out = run("ik-workspace", &strings(&[l1, l2, half_mm, step_mm]))
            .map_err(|e| TestCaseError::fail(e.to_string()))?;
        prop_assert_eq!(single_file(&out), ws.to_csv());
        prop_assert_eq!(&out.summary, &ws.summary());
        check_output("ik-workspace", &out, ik_workspace::INFO.writes)?;
        // Reachable exactly inside the annulus (away from its rims), FK error tiny.
        let (inner, outer) = Arm { l1, l2 }.reach();
        let ny = ws.ys_mm.len();
        for (k, &reachable) in ws.reachable.iter().enumerate() {
            let r = (ws.xs_mm[k / ny] / 1000.0).hypot(ws.ys_mm[k % ny] / 1000.0);
            if r < inner * (1.0 - 1e-9) || r > outer * (1.0 + 1e-9) {
                prop_assert!(!reachable);
            } else if r > inner * (1.0 + 1e-9) + 1e-12 && r < outer * (1.0 - 1e-9) {
                prop_assert!(reachable);
                prop_assert!(ws.err_mm[k] < 1e-6 * (l1 + l2) * 1000.0);
            }
        }
    }

    #[test]
    fn jacobian_valid_and_typed_equals_csv(
        l1 in 0.01f64..2.0,
        l2 in 0.01f64..2.0,
        q1_start in -10.0f64..10.0,
        span in 0.0f64..5.0,
        q1_step in 0.005f64..1.0,
        q2 in -7.0f64..7.0,
    ) {
        let params = jacobian_2r::SweepParams {
            l1, l2, q1_start, q1_stop: q1_start + span, q1_step, q2,
        };
        let rows = jacobian_2r::sweep(&params).map_err(|e| TestCaseError::fail(e.to_string()))?;
        let out = run("jacobian-2r", &strings(&[l1, l2, q1_start, q1_start + span, q1_step, q2]))
            .map_err(|e| TestCaseError::fail(e.to_string()))?;
        prop_assert_eq!(single_file(&out), jacobian_2r::to_csv(&rows));
        prop_assert_eq!(&out.summary, &jacobian_2r::summary(&rows));
        check_output("jacobian-2r", &out, jacobian_2r::INFO.writes)?;
        let scale = (l1 + l2) * (l1 + l2);
        for r in &rows {
            prop_assert!((r.det_j - l1 * l2 * q2.sin()).abs() <= 1e-12 * scale);
            prop_assert!((r.sigma_min * r.sigma_max - r.det_j.abs()).abs() <= 1e-12 * scale);
            prop_assert!((r.manipulability - r.det_j.abs()).abs() <= 1e-6 * (l1 + l2));
        }
    }

    #[test]
    fn manip_grid_valid_and_typed_equals_csv(l1 in 0.01f64..2.0, l2 in 0.01f64..2.0, n in 1i64..48) {
        let grid = manip_grid::grid(&manip_grid::GridParams { l1, l2, n })
            .map_err(|e| TestCaseError::fail(e.to_string()))?;
        let out = run("manip-grid", &[l1.to_string(), l2.to_string(), n.to_string()])
            .map_err(|e| TestCaseError::fail(e.to_string()))?;
        prop_assert_eq!(single_file(&out), grid.to_csv());
        prop_assert_eq!(&out.summary, &grid.summary());
        check_output("manip-grid", &out, manip_grid::INFO.writes)?;
        let mut fast = vec![0.0f32; grid.det_j.len()];
        manip_grid::fill_abs_det(l1, l2, n, &mut fast).map_err(|e| TestCaseError::fail(e.to_string()))?;
        for (f, d) in fast.iter().zip(&grid.det_j) {
            prop_assert!((f64::from(*f) - d.abs()).abs() <= 1e-6 * l1 * l2 + 1e-15);
        }
    }

    #[test]
    fn cubic_valid_and_typed_equals_csv(
        q0 in -100.0f64..100.0,
        q1 in -100.0f64..100.0,
        duration_s in 0.01f64..100.0,
        intervals in 1u32..2000,
    ) {
        let dt_s = duration_s / f64::from(intervals);
        let path = cubic_path::compute(&cubic_path::CubicParams { q0, q1, duration_s, dt_s })
            .map_err(|e| TestCaseError::fail(e.to_string()))?;
        let out = run("cubic-path", &strings(&[q0, q1, duration_s, dt_s]))
            .map_err(|e| TestCaseError::fail(e.to_string()))?;
        prop_assert_eq!(single_file(&out), path.to_csv());
        prop_assert_eq!(&out.summary, &path.summary());
        check_output("cubic-path", &out, cubic_path::INFO.writes)?;
        let n = path.samples.len() as i64;
        prop_assert!((n - i64::from(intervals) - 1).abs() <= 1, "{n} rows for {intervals} intervals");
        let first = path.samples[0];
        prop_assert_eq!((first.q, first.qd), (q0, 0.0));
    }

    #[test]
    fn pid_valid_and_typed_equals_csv(
        kp in -10.0f64..10.0,
        ki in -10.0f64..10.0,
        kd in -1.0f64..1.0,
        tau in 0.0f64..10.0,
        steps in 0i64..1500,
    ) {
        let params = pid_step::PidParams { kp, ki, kd, tau, steps };
        let rows = pid_step::simulate(&params).map_err(|e| TestCaseError::fail(e.to_string()))?;
        let mut raw = strings(&[kp, ki, kd, tau]);
        raw.push(steps.to_string());
        let out = run("pid-step", &raw).map_err(|e| TestCaseError::fail(e.to_string()))?;
        prop_assert_eq!(single_file(&out), pid_step::to_csv(&rows));
        prop_assert_eq!(&out.summary, &pid_step::summary(&rows));
        check_output("pid-step", &out, pid_step::INFO.writes)?;
        prop_assert_eq!(rows.len() as i64, steps);
        for (k, row) in rows.iter().enumerate() {
            prop_assert_eq!(row.t, k as f64 / 20.0);
        }
    }

    #[test]
    fn trapezoid_valid_and_typed_equals_csv(
        distance in -100.0f64..100.0,
        vmax in 0.01f64..100.0,
        amax in 0.01f64..100.0,
        signs in (any::<bool>(), any::<bool>()),
        intervals in 1u32..5000,
    ) {
        // 2 vmax/amax + D/vmax bounds t_total from above in both branches.
        let bound = 2.0 * vmax / amax + distance.abs() / vmax;
        let dt = bound / f64::from(intervals);
        let vmax_arg = if signs.0 { -vmax } else { vmax };
        let amax_arg = if signs.1 { -amax } else { amax };
        let params = trapezoid_profile::TrapParams { distance, vmax: vmax_arg, amax: amax_arg, dt };
        let profile = trapezoid_profile::compute(&params)
            .map_err(|e| TestCaseError::fail(e.to_string()))?;
        let out = run("trapezoid-profile", &strings(&[distance, vmax_arg, amax_arg, dt]))
            .map_err(|e| TestCaseError::fail(e.to_string()))?;
        prop_assert_eq!(single_file(&out), profile.to_csv());
        prop_assert_eq!(&out.summary, &profile.summary());
        check_output("trapezoid-profile", &out, trapezoid_profile::INFO.writes)?;
        let rows = profile.samples.len() as f64;
        let expected = (profile.t_total / dt).floor() + 1.0;
        prop_assert!((rows - expected).abs() <= 1.0, "{rows} rows, expected about {expected}");
        prop_assert!(profile.vmax_used <= vmax * (1.0 + 1e-12));
        for s in &profile.samples {
            prop_assert!(s.a == amax || s.a == 0.0 || s.a == -amax);
            prop_assert!(s.v.abs() <= profile.vmax_used * (1.0 + 1e-9) + 1e-12);
        }
    }
}

proptest! {
    #![proptest_config(config(400))]

    #[test]
    fn fk_of_ik_is_identity_in_the_annulus(
        l1 in 0.001f64..10.0,
        l2 in 0.001f64..10.0,
        radius_fraction in 1e-6f64..(1.0 - 1e-6),
        angle in -std::f64::consts::PI..std::f64::consts::PI,
    ) {
        let arm = Arm { l1, l2 };
        let (inner, outer) = arm.reach();
        let r = inner + (outer - inner) * radius_fraction;
        let (x, y) = (r * angle.cos(), r * angle.sin());
        for elbow in [Elbow::Down, Elbow::Up] {
            let (q1, q2) = arm.ik(x, y, elbow).ok_or_else(|| {
                TestCaseError::fail(format!("IK failed inside the annulus at r={r}"))
            })?;
            prop_assert_eq!(q2 >= 0.0, elbow == Elbow::Down);
            let (fx, fy) = arm.fk(q1, q2);
            let tol = 1e-12 * (l1 + l2);
            prop_assert!((fx - x).abs() <= tol && (fy - y).abs() <= tol,
                "{elbow:?}: fk(ik({x}, {y})) = ({fx}, {fy})");
        }
    }
}

proptest! {
    #![proptest_config(config(24))]

    #[test]
    fn progress_never_changes_the_output(
        index in 0..RECIPES.len(),
        factors in prop::collection::vec((0.5f64..1.5, any::<bool>()), 13),
    ) {
        let info = RECIPES[index].info;
        let mut raw = Vec::new();
        for (spec, (factor, vary)) in info.args.iter().zip(&factors) {
            if !numeric_default(spec.default) {
                break;
            }
            raw.push(if *vary { scaled(spec.default, *factor) } else { spec.default.to_string() });
        }
        let plain = run(info.id, &raw).map_err(|e| TestCaseError::fail(e.to_string()))?;
        let mut reports: Vec<(u64, u64)> = Vec::new();
        let tracked = recipes::run_with_progress(info.id, &raw, Vec::new(), &mut |d, t| {
            reports.push((d, t));
        })
        .map_err(|e| TestCaseError::fail(e.to_string()))?;
        prop_assert_eq!(&plain, &tracked);
        let total = recipes::plan(info.id, &raw, Vec::new())
            .map_err(|e| TestCaseError::fail(e.to_string()))?
            .rows
            .max(1);
        prop_assert!(reports.len() <= 102, "{}: {} reports", info.id, reports.len());
        prop_assert_eq!(reports.last().copied(), Some((total, total)));
        prop_assert!(reports.windows(2).all(|w| w[0].0 <= w[1].0 && w[0].1 == w[1].1));
    }
}

// ---- rrt-2d: the stepper, its step back, and the quadtree nearest-node search ----

mod rrt {
    use super::config;
    use bsv_playground::recipes::{
        self,
        rrt_2d::{
            self, nearest_linear, NearestIndex, Obstacle, Rrt, RrtParams, RrtSetup, RrtWorld,
        },
    };
    use proptest::prelude::*;

    /// A random world: 0 to 3 boxes, a start and goal outside them, the planner's constants.
    fn world() -> impl Strategy<Value = RrtSetup> {
        let corner = (0.0..1.0f64, 0.0..1.0f64, 0.02..0.4f64, 0.02..0.4f64);
        (
            prop::collection::vec(corner, 0..4),
            (0.0..=1.0f64, 0.0..=1.0f64, 0.0..=1.0f64, 0.0..=1.0f64),
            (0u64..1000, 0usize..1500),
            (0.005..0.2f64, 0.0..0.5f64, 0.01..0.2f64),
        )
            .prop_map(
                |(boxes, (sx, sy, gx, gy), (seed, max_iter), (step, bias, tol))| {
                    let obstacles = boxes
                        .into_iter()
                        .map(|(x, y, w, h)| Obstacle {
                            x_min: x,
                            y_min: y,
                            x_max: (x + w).min(1.0),
                            y_max: (y + h).min(1.0),
                        })
                        .collect();
                    RrtSetup {
                        params: RrtParams {
                            seed,
                            max_iter,
                            goal: [gx, gy],
                        },
                        world: RrtWorld {
                            start: [sx, sy],
                            obstacles,
                            step,
                            goal_bias: bias,
                            goal_tol: tol,
                        },
                        goal_checked: true,
                    }
                },
            )
            .prop_filter("start and goal outside the boxes", |s| {
                !s.world.collides(s.world.start) && !s.world.collides(s.params.goal)
            })
    }

    /// The command line of a setup (`{:?}` prints the shortest round-trip form of an f64).
    fn args(s: &RrtSetup) -> Vec<String> {
        let mut a = vec![s.params.seed.to_string(), s.params.max_iter.to_string()];
        let boxes: Vec<String> = s
            .world
            .obstacles
            .iter()
            .map(|b| format!("{:?},{:?},{:?},{:?}", b.x_min, b.y_min, b.x_max, b.y_max))
            .collect();
        if boxes.is_empty() {
            a.extend(["--obstacle".to_string(), "none".to_string()]);
        }
        for b in boxes {
            a.extend(["--obstacle".to_string(), b]);
        }
        let w = &s.world;
        let g = s.params.goal;
        for (flag, value) in [
            ("--start", format!("{:?},{:?}", w.start[0], w.start[1])),
            ("--goal", format!("{:?},{:?}", g[0], g[1])),
            ("--step", format!("{:?}", w.step)),
            ("--goal-bias", format!("{:?}", w.goal_bias)),
            ("--goal-tol", format!("{:?}", w.goal_tol)),
        ] {
            a.extend([flag.to_string(), value]);
        }
        a
    }

    fn stepped(setup: &RrtSetup, linear: bool) -> Rrt {
        let mut rrt = Rrt::with_setup(setup).unwrap();
        rrt.set_linear_search(linear);
        while rrt.step_record().is_some() {}
        rrt
    }

    proptest! {
        #![proptest_config(config(48))]

        /// Stepping one iteration at a time (quadtree) gives the batch run's files (the
        /// command line through `recipes::run`) and the tree of the recipe's linear scan.
        #[test]
        fn stepped_tree_is_the_batch_tree(setup in world()) {
            let rrt = stepped(&setup, false);
            let reference = stepped(&setup, true);
            prop_assert_eq!(rrt.nodes(), reference.nodes());
            prop_assert_eq!(rrt.parents(), reference.parents());
            prop_assert_eq!(rrt.counts(), reference.counts());
            let batch = recipes::run("rrt-2d", &args(&setup)).unwrap();
            let out = rrt_2d::output(&rrt);
            prop_assert_eq!(&out.files, &batch.files);
            prop_assert_eq!(&out.summary, &batch.summary);
            let c = rrt.counts();
            prop_assert_eq!(
                c.added + c.out_of_square + c.collision + c.zero_length,
                rrt.iterations()
            );
        }

        /// Going back to iteration k gives exactly a run stopped at k (tree, counters, the
        /// last record), and going forward again gives the same tree as before.
        #[test]
        fn stepping_back_then_forward_is_exact(setup in world(), a in 0usize..1500, b in 0usize..1500) {
            let (far, near) = (a.max(b), a.min(b));
            let mut rrt = Rrt::with_setup(&setup).unwrap();
            let reached = rrt.seek(far);
            let (nodes, parents, last) = (rrt.nodes().to_vec(), rrt.parents().to_vec(), rrt.last().copied());
            prop_assert_eq!(rrt.seek(near), near.min(reached));
            let mut fresh = Rrt::with_setup(&setup).unwrap();
            fresh.seek(near);
            prop_assert_eq!(rrt.nodes(), fresh.nodes());
            prop_assert_eq!(rrt.parents(), fresh.parents());
            prop_assert_eq!(rrt.counts(), fresh.counts());
            prop_assert_eq!(rrt.last(), fresh.last());
            prop_assert_eq!(rrt.found(), fresh.found());
            prop_assert_eq!(rrt.seek(far), reached);
            prop_assert_eq!(rrt.nodes(), &nodes[..]);
            prop_assert_eq!(rrt.parents(), &parents[..]);
            prop_assert_eq!(rrt.last().copied(), last);
        }

        /// A cursor over the run grown to its end reads, at any iteration it is moved to
        /// (forwards, backwards, far or near), exactly a run stopped there.
        #[test]
        fn cursor_reads_the_run_stopped_there(setup in world(), stops in prop::collection::vec(0usize..1600, 1..6)) {
            let end = stepped(&setup, false);
            let mut cursor = end.cursor();
            prop_assert_eq!(end.at(&cursor).nodes().len(), 1);
            for k in stops.into_iter().chain([usize::MAX, 1, 0]) {
                let reached = end.seek_cursor(&mut cursor, k);
                prop_assert_eq!(reached, k.min(end.iterations()));
                let mut fresh = Rrt::with_setup(&setup).unwrap();
                fresh.seek(k);
                let at = end.at(&cursor);
                prop_assert_eq!(at.iterations(), fresh.iterations());
                prop_assert_eq!(at.nodes(), fresh.nodes());
                prop_assert_eq!(at.parents(), fresh.parents());
                prop_assert_eq!(at.counts(), fresh.counts());
                prop_assert_eq!(at.last(), fresh.last());
                prop_assert_eq!(at.found(), fresh.found());
                prop_assert_eq!(at.path(), fresh.path());
            }
        }

        /// Nodes 0, 1 and 2 ulps apart: their squared distances to the query differ but
        /// often round to the same distance under the recipe's `sqrt` (a tie): the quadtree
        /// keeps the first index among them, as the linear scan does.
        #[test]
        fn quadtree_keeps_ties_of_rounded_distances(
            base in prop::collection::vec((0.0f64..1.0, 0.0f64..1.0), 1..60),
            q in (0.0f64..1.0, 0.0f64..1.0),
        ) {
            let mut nodes = Vec::new();
            for &(x, y) in &base {
                for k in [2u64, 1, 0] {
                    nodes.push([f64::from_bits(x.to_bits() + k), y]);
                }
            }
            let q = [q.0, q.1];
            prop_assert_eq!(NearestIndex::of(&nodes).nearest(q), nearest_linear(&nodes, q));
        }

        /// The quadtree returns the linear scan's node on random trees with exact ties
        /// (points and queries on a coarse lattice, repeated points), also after truncation.
        #[test]
        fn quadtree_nearest_is_the_linear_scan(
            points in prop::collection::vec((0u32..=16, 0u32..=16, any::<bool>()), 1..400),
            queries in prop::collection::vec((0u32..=32, 0u32..=32), 1..40),
            keep in 0usize..400,
        ) {
            // Lattice points (multiples of 1/16), and some off-lattice ones.
            let nodes: Vec<[f64; 2]> = points
                .iter()
                .map(|&(i, j, off)| {
                    let jitter = if off { 1e-3 * f64::from(i % 3) } else { 0.0 };
                    [f64::from(i) / 16.0 + jitter, f64::from(j) / 16.0]
                })
                .map(|p| [p[0].min(1.0), p[1]])
                .collect();
            let mut index = NearestIndex::new();
            for id in 0..nodes.len() {
                index.insert(&nodes, id);
                for &(qi, qj) in queries.iter().take(3) {
                    // Half-lattice queries: equidistant from 2 or 4 lattice points.
                    let q = [f64::from(qi) / 32.0, f64::from(qj) / 32.0];
                    prop_assert_eq!(index.nearest(q), nearest_linear(&nodes[..=id], q));
                }
            }
            for &(qi, qj) in &queries {
                let q = [f64::from(qi) / 32.0, f64::from(qj) / 32.0];
                prop_assert_eq!(index.nearest(q), nearest_linear(&nodes, q));
            }
            let keep = keep.min(nodes.len()).max(1);
            index.truncate(&nodes, keep);
            for &(qi, qj) in &queries {
                let q = [f64::from(qi) / 32.0, f64::from(qj) / 32.0];
                prop_assert_eq!(index.nearest(q), nearest_linear(&nodes[..keep], q));
            }
            prop_assert_eq!(NearestIndex::of(&nodes).nearest([0.5, 0.5]), nearest_linear(&nodes, [0.5, 0.5]));
        }
    }

    proptest! {
        #![proptest_config(config(24))]

        /// Each record's sub-steps agree with its outcome: the goal-biased sample is the goal,
        /// the nearest node's position is `from`, a collision's hit point is the first of the
        /// 12 inside a box (and in that box), an added node passed the whole check.
        #[test]
        fn records_explain_their_outcome(setup in world()) {
            use rrt_2d::RrtOutcome::*;
            let mut rrt = Rrt::with_setup(&setup).unwrap();
            let w = setup.world.clone();
            while let Some(r) = rrt.step_record() {
                if r.goal_sample {
                    prop_assert_eq!(r.sample, setup.params.goal);
                }
                let before = &rrt.nodes()[..r.nearest + 1];
                prop_assert_eq!(before[r.nearest], r.from);
                let points = r.check_points();
                match r.outcome {
                    ZeroLength => prop_assert!(r.candidate.is_none() && r.distance < 1e-12),
                    OutOfSquare => {
                        let c = r.candidate.unwrap();
                        prop_assert!(
                            !r.checked && (!(0.0..=1.0).contains(&c[0]) || !(0.0..=1.0).contains(&c[1]))
                        );
                    }
                    Collision => {
                        let hit = r.hit.unwrap();
                        let points = points.unwrap();
                        prop_assert!(w.obstacles[hit.obstacle].contains(points[hit.point]));
                        prop_assert!(points[..hit.point].iter().all(|p| !w.collides(*p)));
                    }
                    Added { id } | GoalReached { id, .. } => {
                        prop_assert!(r.checked && r.hit.is_none());
                        prop_assert!(points.unwrap().iter().all(|p| !w.collides(*p)));
                        prop_assert_eq!(rrt.nodes()[id], r.candidate.unwrap());
                        prop_assert_eq!(rrt.parents()[id], Some(r.nearest));
                    }
                }
            }
        }
    }

    /// Exact ties: the first index wins, whatever the tree's shape.
    #[test]
    fn ties_go_to_the_first_index() {
        let nodes = [
            [0.75, 0.5],
            [0.25, 0.5],
            [0.5, 0.75],
            [0.5, 0.25],
            [0.25, 0.5],
        ];
        let mut index = NearestIndex::of(&nodes);
        assert_eq!(nearest_linear(&nodes, [0.5, 0.5]), 0);
        assert_eq!(index.nearest([0.5, 0.5]), 0);
        assert_eq!(index.nearest([0.25, 0.5]), 1);
        // Many copies of one point and a ring of equidistant ones, across splits.
        let mut many: Vec<[f64; 2]> = (0..100).map(|_| [0.3, 0.3]).collect();
        many.extend((0..64).map(|k| {
            let a = k as f64 * std::f64::consts::TAU / 64.0;
            [0.6 + 0.1 * a.cos(), 0.6 + 0.1 * a.sin()]
        }));
        let mut index = NearestIndex::of(&many);
        for q in [[0.3, 0.3], [0.6, 0.6], [0.45, 0.45], [0.0, 1.0], [1.0, 0.0]] {
            assert_eq!(index.nearest(q), nearest_linear(&many, q), "{q:?}");
        }
        assert_eq!(index.nearest([0.3, 0.3]), 0);
    }

    /// The default world stepped to the end: the golden run (91 nodes, 33 path points), and
    /// iteration 0 holds only the start.
    #[test]
    fn default_run_is_the_golden_one_at_its_end() {
        let mut rrt = Rrt::new(&RrtParams::default()).unwrap();
        assert_eq!((rrt.nodes().len(), rrt.last()), (1, None));
        let end = rrt.seek(usize::MAX);
        assert_eq!((rrt.nodes().len(), rrt.path().len()), (91, 33));
        assert_eq!(format!("{:.3}", rrt.path_length()), "1.604");
        let last = *rrt.last().unwrap();
        assert_eq!(last.iteration, end);
        assert!(matches!(
            last.outcome,
            rrt_2d::RrtOutcome::GoalReached { goal_id: 90, .. }
        ));
        assert_eq!(rrt.seek(0), 0);
        assert_eq!((rrt.nodes().len(), rrt.last()), (1, None));
    }
}
