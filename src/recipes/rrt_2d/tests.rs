#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use super::geometry::norm;
use super::*;
use crate::recipes::testkit::run_strs;

/// Steps a tree to the end, checking that each event changes the tree as it says.
fn step_to_end(params: &RrtParams) -> (Rrt, Vec<RrtStep>) {
    let mut rrt = Rrt::new(params).unwrap();
    let mut events = Vec::new();
    while !rrt.is_done() {
        let before = rrt.nodes().len();
        let event = rrt.step();
        let added = match event {
            RrtStep::Added {
                nearest, id, point, ..
            } => {
                assert_eq!(id, before);
                assert_eq!(rrt.nodes()[id], point);
                assert_eq!(rrt.parents()[id], Some(nearest));
                1
            }
            RrtStep::Found { id, goal_id, .. } => {
                assert_eq!((id, goal_id), (before, before + 1));
                assert_eq!(rrt.nodes()[goal_id], params.goal);
                2
            }
            RrtStep::Rejected { .. } | RrtStep::Sampled { .. } => 0,
            RrtStep::Exhausted => panic!("Exhausted before done"),
        };
        assert_eq!(rrt.nodes().len(), before + added);
        events.push(event);
    }
    assert_eq!(rrt.step(), RrtStep::Exhausted);
    (rrt, events)
}

#[test]
fn stepping_builds_the_same_tree_as_the_recipe_run() {
    for seed in [7, 42, 3] {
        let params = RrtParams {
            seed,
            ..RrtParams::default()
        };
        let (stepped, events) = step_to_end(&params);
        let batch = run(&params).unwrap();
        assert_eq!(stepped.nodes(), batch.nodes(), "seed {seed}");
        assert_eq!(stepped.parents(), batch.parents(), "seed {seed}");
        assert_eq!(stepped.iterations(), events.len());
        assert_eq!(output(&stepped), output(&batch));
    }
    // Seed 7 is the golden run: 91 nodes, 33 path points (Python's printed line).
    let (stepped, events) = step_to_end(&RrtParams::default());
    assert_eq!((stepped.nodes().len(), stepped.path().len()), (91, 33));
    assert!(matches!(
        events.last(),
        Some(RrtStep::Found { goal_id: 90, .. })
    ));
    assert_eq!(
        output(&stepped).file("rrt_nodes.csv"),
        Some(include_str!(
            "../../../tests/golden/rrt_default/rrt_nodes.csv"
        ))
    );
}

#[test]
fn tree_respects_the_world() {
    let (rrt, events) = step_to_end(&RrtParams {
        seed: 11,
        max_iter: 400,
        ..RrtParams::default()
    });
    for (i, (p, parent)) in rrt.nodes().iter().zip(rrt.parents()).enumerate().skip(1) {
        assert!((0.0..=1.0).contains(&p[0]) && (0.0..=1.0).contains(&p[1]));
        assert!(!OBSTACLE.contains(*p), "node {i} in the obstacle");
        let parent = parent.unwrap();
        assert!(parent < i);
        let q = rrt.nodes()[parent];
        let edge = norm([p[0] - q[0], p[1] - q[1]]);
        // Tree edges are at most STEP long, except the final jump to the goal.
        assert!(
            edge <= STEP + 1e-15 || Some(i) == rrt.found(),
            "edge {i}: {edge}"
        );
        assert!(segment_clear(q, *p));
    }
    for event in events {
        if let RrtStep::Rejected {
            point,
            reason: RejectReason::Collision,
            nearest,
            ..
        } = event
        {
            assert!(!segment_clear(rrt.nodes()[nearest], point));
        }
    }
}

#[test]
fn unreachable_goal_exhausts_the_budget() {
    // A goal inside the obstacle: every extension into the box is rejected.
    let params = RrtParams {
        seed: 7,
        max_iter: 300,
        goal: [0.5, 0.5],
    };
    let (rrt, events) = step_to_end(&params);
    assert_eq!(rrt.iterations(), 300);
    assert_eq!(events.len(), 300);
    assert_eq!(rrt.found(), None);
    assert!(rrt.path().is_empty());
    assert!(rrt.path_length().is_nan());
    assert!(events.iter().any(|e| matches!(
        e,
        RrtStep::Rejected {
            reason: RejectReason::Collision,
            ..
        }
    )));

    let out = run_strs::<Entry>(&["7", "300", "--goal-x", "0.5", "--goal-y=0.5"]).unwrap();
    assert_eq!(out.file("rrt_path.csv"), Some("x,y\r\n"));
    assert_eq!(
        out.summary,
        format!(
            "RRT nodes={} path_pts=0 length=nan -> rrt_path.csv, rrt_nodes.csv",
            rrt.nodes().len()
        )
    );
}

#[test]
fn nodes_csv_in_parts_is_the_whole_file() {
    let rrt = run(&RrtParams::default()).unwrap();
    let whole = output(&rrt);
    let n = rrt.nodes().len();
    let parts: String = [0..1, 1..40, 40..41, 41..n + 5, n + 5..n + 9]
        .into_iter()
        .map(|rows| nodes_csv_part(&rrt, rows))
        .collect();
    assert_eq!(Some(parts.as_str()), whole.file("rrt_nodes.csv"));
}

#[test]
fn zero_iterations_write_only_the_start() {
    let out = run_strs::<Entry>(&["7", "0"]).unwrap();
    assert_eq!(
        out.file("rrt_nodes.csv"),
        Some("id,x,y,parent\r\n0,0.1,0.1,-1\r\n")
    );
    assert_eq!(
        out.summary,
        "RRT nodes=1 path_pts=0 length=nan -> rrt_path.csv, rrt_nodes.csv"
    );
}

#[test]
fn segment_check_uses_twelve_points() {
    // This segment is inside the box only for t in [0.5, 0.52], between the check points
    // 5/11 and 6/11, so it counts as clear although it cuts the corner (the quirk).
    let (a, b) = ([0.30, 0.302], [0.40, 0.202]);
    let t = 0.51;
    assert!(OBSTACLE.contains([a[0] * (1.0 - t) + b[0] * t, a[1] * (1.0 - t) + b[1] * t]));
    assert!(segment_clear(a, b));
    // Through the box: the check point t = 6/11 is inside.
    assert!(!segment_clear([0.30, 0.30], [0.40, 0.30]));
    assert!(segment_clear([0.1, 0.1], [0.3, 0.1]));
}

#[test]
fn rejects_bad_arguments() {
    let err = |v: &[&str]| run_strs::<Entry>(v).unwrap_err();
    assert!(matches!(err(&["-1"]), RecipeError::OutOfRange { .. }));
    assert!(matches!(
        err(&["9223372036854775808"]),
        RecipeError::OutOfRange { .. }
    ));
    assert!(matches!(err(&["1.5"]), RecipeError::NotAnInteger { .. }));
    assert!(matches!(err(&["7", "-3"]), RecipeError::OutOfRange { .. }));
    assert!(matches!(
        err(&["7", "1000001"]),
        RecipeError::TooLarge {
            limit: 1_000_000,
            ..
        }
    ));
    assert!(matches!(
        err(&["7", "800", "--goal-x", "1.2"]),
        RecipeError::OutOfRange { .. }
    ));
    assert!(matches!(
        err(&["7", "800", "--goal-y", "nan"]),
        RecipeError::NotFinite { .. }
    ));
    assert!(Rrt::new(&RrtParams {
        seed: u64::MAX,
        ..RrtParams::default()
    })
    .is_err());
}
