#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use super::control::{ik_step, sigma_min};
use super::episode::{episode_csv, parse_episode_csv, replay, Episode};
use super::kinematics::{chain, fk, jacobian, mul_t, norm, rotation_vector, Jacobian};
use super::model::joint_limits;
use super::scene::{SceneConfig, CUBE_HALF};
use super::sim::{Command, Sim};
use crate::teleop::control::{ControlParams, IkMethod};
use crate::teleop::sim::{Event, Outcome};

const GOLDEN: &str = include_str!("../../tests/golden/so101/fk.csv");

fn golden_rows() -> Vec<[f64; 17]> {
    GOLDEN
        .lines()
        .skip(1)
        .map(|l| {
            let mut row = [0.0; 17];
            for (o, c) in row.iter_mut().zip(l.split(',')) {
                *o = c.parse().unwrap();
            }
            row
        })
        .collect()
}

#[test]
fn tool_frame_matches_mujoco_to_1e_9_at_256_joint_vectors() {
    let rows = golden_rows();
    assert!(rows.len() >= 200, "{} rows", rows.len());
    let mut worst: f64 = 0.0;
    for row in &rows {
        let q = [row[0], row[1], row[2], row[3], row[4]];
        let f = fk(&q);
        for i in 0..3 {
            worst = worst.max((f.pos[i] - row[5 + i]).abs());
            for j in 0..3 {
                worst = worst.max((f.rot[i][j] - row[8 + 3 * i + j]).abs());
            }
        }
    }
    assert!(worst < 1e-9, "worst difference {worst:e}");
}

fn fd_jacobian(q: &[f64; 5], h: f64) -> Jacobian {
    let mut j = [[0.0; 5]; 6];
    for c in 0..5 {
        let (mut a, mut b) = (*q, *q);
        a[c] += h;
        b[c] -= h;
        let (fa, fb) = (fk(&a), fk(&b));
        let w = rotation_vector(&mul_t(&fa.rot, &fb.rot));
        for r in 0..3 {
            j[r][c] = (fa.pos[r] - fb.pos[r]) / (2.0 * h);
            j[r + 3][c] = w[r] / (2.0 * h);
        }
    }
    j
}

#[test]
fn jacobian_matches_finite_differences() {
    for row in golden_rows().iter().take(64) {
        let q = [row[0], row[1], row[2], row[3], row[4]];
        let (j, fd) = (jacobian(&q), fd_jacobian(&q, 1e-6));
        for r in 0..6 {
            for c in 0..5 {
                assert!((j[r][c] - fd[r][c]).abs() < 1e-8, "{q:?} [{r}][{c}]");
            }
        }
    }
}

/// The stretched-out pose: shoulder lift, elbow and wrist flex lined up with the tool, found
/// by shrinking coordinate steps on the smallest singular value.
fn stretched() -> [f64; 5] {
    let mut q = [0.0, 0.6, -1.4, 0.0, 0.0];
    let mut step = 0.1;
    while step > 1e-12 {
        let mut improved = false;
        for k in 2..4 {
            for s in [step, -step] {
                let mut t = q;
                t[k] += s;
                if sigma_min(&jacobian(&t)) < sigma_min(&jacobian(&q)) {
                    q = t;
                    improved = true;
                }
            }
        }
        if !improved {
            step /= 2.0;
        }
    }
    q
}

#[test]
fn dls_stays_bounded_at_the_stretched_out_singularity_where_pinv_does_not() {
    let q = stretched();
    let j = jacobian(&q);
    assert!(sigma_min(&j) < 1e-6, "sigma {}", sigma_min(&j));
    // Outward along the arm: from the shoulder-lift joint to the tool, 1 mm.
    let c = chain(&q, 0.0);
    let d = super::kinematics::sub(&c.tool.pos, &c.bodies[2].pos);
    let n = norm(&d);
    let dx = [
        d[0] / n * 1e-3,
        d[1] / n * 1e-3,
        d[2] / n * 1e-3,
        0.0,
        0.0,
        0.0,
    ];
    let dls = ControlParams::DEFAULT;
    let size = |v: [f64; 5]| v.iter().map(|x| x * x).sum::<f64>().sqrt();
    let dq_dls = ik_step(&dls, &j, &dx).unwrap();
    assert!(
        size(dq_dls) <= 1e-3 / (2.0 * 0.01) + 1e-12,
        "{}",
        size(dq_dls)
    );
    let adaptive = ControlParams {
        method: IkMethod::AdaptiveDls,
        ..dls
    };
    assert!(size(ik_step(&adaptive, &j, &dx).unwrap()) <= size(dq_dls) + 1e-15);
    let pinv = ControlParams {
        method: IkMethod::Pinv,
        ..dls
    };
    // pinv: a step a thousand times DLS's, or none at an exactly singular JᵀJ.
    if let Some(dq) = ik_step(&pinv, &j, &dx) {
        assert!(size(dq) > 1e3 * size(dq_dls), "pinv {}", size(dq));
    }
    // Away from it the methods agree.
    let q = [0.1, -0.8, 0.8, 1.4, 0.2];
    let j = jacobian(&q);
    let dx = [1e-3, 0.0, 0.0, 0.0, 0.0, 0.0];
    let (a, b) = (
        ik_step(&dls, &j, &dx).unwrap(),
        ik_step(&pinv, &j, &dx).unwrap(),
    );
    assert!((size(a) - size(b)).abs() < 0.05 * size(b));
}

#[test]
fn each_axis_moves_the_tool_its_way() {
    let config = SceneConfig::default_for(false);
    for (axis, sign) in [
        (0, 1.0),
        (0, -1.0),
        (1, 1.0),
        (1, -1.0),
        (2, 1.0),
        (2, -1.0),
    ] {
        let mut sim = Sim::new(config.clone()).unwrap();
        let p0 = sim.snapshot().tool;
        let mut a = [0.0; 6];
        a[axis] = sign;
        for _ in 0..20 {
            sim.step(&Command::with_axes(a, false));
        }
        let p1 = sim.snapshot().tool;
        let moved = (p1[axis] - p0[axis]) * sign;
        // Up to 0.1 m/s for 0.2 s, and more along the axis than across it (y needs the pan,
        // which also turns the tool: DLS shares the step with the yaw it was not asked for).
        assert!(moved > 0.005, "axis {axis} {sign}: {moved}");
        for other in (0..3).filter(|o| *o != axis) {
            assert!(
                (p1[other] - p0[other]).abs() < moved,
                "axis {axis} moved {other}"
            );
        }
    }
    // Yaw (C/V) turns the tool about z.
    // Pitch (about y) and yaw (about z); roll about x is the turn a five-joint arm pointing
    // down has no joint for (see the orientation-error test).
    for (axis, sign) in [(4, 1.0), (4, -1.0), (5, 1.0), (5, -1.0)] {
        let mut sim = Sim::new(config.clone()).unwrap();
        let r0 = sim.chain().tool.rot;
        let mut a = [0.0; 6];
        a[axis] = sign;
        for _ in 0..20 {
            sim.step(&Command::with_axes(a, false));
        }
        let w = rotation_vector(&mul_t(&sim.chain().tool.rot, &r0));
        // The readouts (from pointing down) turn the same way.
        let rpy = sim.snapshot().rpy;
        assert!(
            rpy[axis - 3] * sign > 0.02,
            "readout {axis} {sign}: {rpy:?}"
        );
        // 0.16 rad asked; pitching the wrist also moves the tool, which DLS holds back.
        assert!(w[axis - 3] * sign > 0.02, "axis {axis} {sign}: {w:?}");
    }
}

/// The default scene after `steps` steps of the open gripper driven by `axes`, and the
/// events of those steps.
fn driven(axes: [f64; 6], steps: usize) -> (Sim, Vec<Event>) {
    let mut sim = Sim::new(SceneConfig::default_for(false)).unwrap();
    let events = (0..steps)
        .flat_map(|_| sim.step(&Command::with_axes(axes, false)).events)
        .collect();
    (sim, events)
}

#[test]
fn joint_limits_clamp_and_are_reported() {
    let (sim, events) = driven([0.0, 1.0, 0.0, 0.0, 0.0, 0.0], 1500);
    let q = sim.state().q;
    for (v, (lo, hi)) in q.iter().zip(joint_limits()) {
        assert!(*v >= lo && *v <= hi);
    }
    assert!(
        events
            .iter()
            .any(|e| matches!(e, Event::JointLimit { .. } | Event::Collision { .. })),
        "{events:?}"
    );
}

/// A scripted pilot: fly the tool to `target` (P control on the position, clamped).
pub(super) fn fly(
    sim: &mut Sim,
    target: [f64; 3],
    close: bool,
    steps: usize,
    out: &mut Vec<Command>,
) {
    for _ in 0..steps {
        let p = sim.snapshot().tool;
        let mut a = [0.0; 6];
        for i in 0..3 {
            a[i] = ((target[i] - p[i]) * 40.0).clamp(-1.0, 1.0);
        }
        let c = Command::with_axes(a, close);
        out.push(c);
        sim.step(&c);
    }
}

/// Flies the open gripper above the cube, then down around it.
fn over_the_cube(sim: &mut Sim, out: &mut Vec<Command>) {
    let cube = sim.state().cube.pos;
    fly(sim, [cube[0], cube[1], cube[2] + 0.06], false, 200, out);
    fly(sim, cube, false, 200, out);
}

fn pick_and_place(config: &SceneConfig) -> Vec<Command> {
    let mut sim = Sim::new(config.clone()).unwrap();
    let mut out = Vec::new();
    let cube = sim.state().cube.pos;
    let goal = config.goal;
    over_the_cube(&mut sim, &mut out);
    fly(&mut sim, cube, true, 5, &mut out);
    fly(&mut sim, [cube[0], cube[1], 0.1], true, 200, &mut out);
    fly(&mut sim, [goal[0], goal[1], 0.1], true, 250, &mut out);
    fly(
        &mut sim,
        [goal[0], goal[1], CUBE_HALF + 0.003],
        true,
        200,
        &mut out,
    );
    fly(
        &mut sim,
        [goal[0], goal[1], CUBE_HALF + 0.003],
        false,
        40,
        &mut out,
    );
    out
}

#[test]
fn a_scripted_pick_and_place_succeeds_and_replays_bit_for_bit() {
    let config = SceneConfig::default_for(false);
    let commands = pick_and_place(&config);
    let ep = Episode::record(config, &commands).unwrap();
    let events: Vec<Event> = ep.records.iter().flat_map(|r| r.events.clone()).collect();
    assert!(events.contains(&Event::Grasp), "{events:?}");
    assert_eq!(ep.outcome(), Some(Outcome::Success), "{events:?}");
    // Success comes after the cube rested in the goal 10 steps.
    let release = ep
        .records
        .iter()
        .position(|r| r.events.contains(&Event::Release))
        .unwrap();
    let success = ep
        .records
        .iter()
        .position(|r| r.events.contains(&Event::Success))
        .unwrap();
    assert!(success >= release + 10);
    let text = episode_csv(&ep);
    let back = parse_episode_csv(&text).unwrap();
    assert_eq!(back, ep);
    let m = replay(&back).unwrap();
    assert_eq!(m.outcome, Some(Outcome::Success));
    assert!(
        m.efficiency > 0.3 && m.efficiency <= 1.0,
        "{}",
        m.efficiency
    );
    // A changed number is found.
    let mut bad = back.clone();
    bad.records[50].q[2] += 1e-15;
    let err = replay(&bad).unwrap_err();
    assert_eq!((err.step, err.field.as_str()), (51, "q3"));
}

#[test]
fn latency_and_noise_replay_exactly() {
    let mut config = SceneConfig::default_for(true);
    config.latency_steps = 7;
    config.noise_sigma = 0.2;
    config.noise_seed = 42;
    let commands: Vec<Command> = (0..400)
        .map(|i| {
            Command::with_axes(
                [0.5, -0.3, if i < 200 { -0.4 } else { 0.6 }, 0.0, 0.3, -0.2],
                i > 300,
            )
        })
        .collect();
    let a = Episode::record(config.clone(), &commands).unwrap();
    let b = Episode::record(config, &commands).unwrap();
    assert_eq!(episode_csv(&a), episode_csv(&b));
    assert!(replay(&parse_episode_csv(&episode_csv(&a)).unwrap()).is_ok());
    // The first 7 applied commands are the idle ones the queue starts with (plus noise).
    assert!(!a.records[0].applied.gripper_closed);
    assert_ne!(a.records[0].applied.dx, 0.0);
}

#[test]
fn closing_far_from_the_cube_is_a_miss_and_dropping_it_is_a_drop() {
    let config = SceneConfig::default_for(false);
    let mut sim = Sim::new(config.clone()).unwrap();
    let r = sim.step(&Command::idle(true));
    assert_eq!(r.events, vec![Event::GraspMiss]);
    let mut all = pick_and_place(&config);
    all.truncate(605);
    let mut sim = Sim::new(config).unwrap();
    let mut seen = Vec::new();
    for c in &all {
        seen.extend(sim.step(c).events);
    }
    assert!(sim.state().cube.held, "{seen:?}");
    let r = sim.step(&Command::idle(false));
    assert_eq!(r.events, vec![Event::Release, Event::Drop]);
    for _ in 0..100 {
        sim.step(&Command::idle(false));
    }
    assert!(sim.state().cube.resting);
    assert!((sim.state().cube.pos[2] - CUBE_HALF).abs() < 1e-12);
}

#[test]
fn going_down_into_the_table_is_a_collision_that_stops_the_arm() {
    let (mut sim, events) = driven([0.0, 0.0, -1.0, 0.0, 0.0, 0.0], 300);
    assert!(
        events.iter().any(|e| matches!(e, Event::Collision { .. })),
        "{events:?}"
    );
    let q = sim.state().q;
    sim.step(&Command::with_axes([0.0, 0.0, -1.0, 0.0, 0.0, 0.0], false));
    assert_eq!(sim.state().q, q);
}

#[test]
fn the_time_box_ends_the_episode() {
    let mut config = SceneConfig::default_for(false);
    config.time_box_s = 1.0;
    let ep = Episode::record(config, &vec![Command::idle(false); 150]).unwrap();
    assert_eq!(ep.records.len(), 100);
    assert_eq!(ep.outcome(), Some(Outcome::Timeout));
}

#[test]
fn a_yaw_the_arm_cannot_follow_shows_as_orientation_error() {
    let mut sim = Sim::new(SceneConfig::default_for(false)).unwrap();
    let mut last = 0.0;
    for _ in 0..100 {
        last = sim
            .step(&Command::with_axes([0.0, 0.0, 0.0, 1.0, 0.0, 0.0], false))
            .orientation_error;
    }
    assert!(last > 0.01, "{last}");
    let r = sim.step(&Command::idle(false));
    assert_eq!(r.orientation_error, 0.0);
}

#[test]
fn bad_files_give_errors_not_panics() {
    assert!(parse_episode_csv("").is_err());
    assert!(parse_episode_csv("# bsv so101 episode,1\n# config,{").is_err());
    let ep = Episode::record(SceneConfig::default_for(false), &[Command::idle(false); 3]).unwrap();
    let text = episode_csv(&ep);
    let cut = &text[..text.len() - 10];
    assert!(parse_episode_csv(cut).is_err());
    assert!(parse_episode_csv(&text.replace("\n0.01,", "\nx,")).is_err());
}

#[test]
fn a_grasp_needs_the_jaws_across_the_cube() {
    // Flown over the cube, then turned about z (yaw) before closing: square to the cube it
    // grasps; at 45° the jaws would close on its edges, a miss.
    for (yaw_steps, grasped) in [(0, true), (20, true), (110, false)] {
        let config = SceneConfig::default_for(false);
        let mut sim = Sim::new(config.clone()).unwrap();
        let mut out = Vec::new();
        let cube = sim.state().cube.pos;
        over_the_cube(&mut sim, &mut out);
        for _ in 0..yaw_steps {
            sim.step(&Command::with_axes([0.0, 0.0, 0.0, 0.0, 0.0, 1.0], false));
        }
        let turned = crate::so101::scene::jaw_closing(&sim.chain());
        let tool = sim.snapshot().tool;
        let d = crate::so101::kinematics::norm(&crate::so101::kinematics::sub(&cube, &tool));
        assert!(
            d <= crate::so101::scene::GRASP_TOLERANCE_M,
            "yaw steps {yaw_steps}: {d}"
        );
        let r = sim.step(&Command::idle(true));
        let expected = if grasped {
            Event::Grasp
        } else {
            Event::GraspMiss
        };
        assert_eq!(
            r.events,
            vec![expected],
            "yaw steps {yaw_steps}: {turned:?}"
        );
        assert_eq!(sim.state().cube.held, grasped);
    }
}
