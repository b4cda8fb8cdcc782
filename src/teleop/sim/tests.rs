#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use super::*;
use crate::teleop::episode::{episode_csv, metrics, Episode};
use crate::teleop::metrics::EpisodeMetrics;
use crate::teleop::pilot::{fly, plan, Waypoint};
use crate::teleop::scene::{FINGER_LENGTH, FINGER_RADIUS};

fn sim(config: SceneConfig) -> Sim {
    Sim::new(config).unwrap()
}

fn held_for(cmd: Command, n: usize) -> Vec<Command> {
    vec![cmd; n]
}

const UP: Command = Command {
    dx: 0.0,
    dz: 1.0,
    dphi: 0.0,
    gripper_closed: false,
};
const DOWN: Command = Command {
    dx: 0.0,
    dz: -1.0,
    dphi: 0.0,
    gripper_closed: false,
};

/// Events with their steps.
fn events(episode: &Episode) -> Vec<(u64, Event)> {
    episode
        .records
        .iter()
        .flat_map(|r| r.events.iter().map(move |e| (r.step, *e)))
        .collect()
}

/// The one collision of `episode` and its step (there must be exactly one).
fn only_collision(episode: &Episode) -> (u64, Event) {
    let ev = events(episode);
    let collisions: Vec<_> = ev
        .iter()
        .filter(|(_, e)| matches!(e, Event::Collision { .. }))
        .collect();
    assert_eq!(collisions.len(), 1, "{ev:?}");
    *collisions[0]
}

/// Checks that the arm of `s` moves up at once, without an event.
fn moves_up_at_once(s: &mut Sim) {
    let before = s.state().q;
    let r = s.step(&UP);
    assert_ne!(r.q, before);
    assert_eq!(r.events, vec![]);
}

/// The pick-place plan up to (and including) the waypoint that closes the gripper.
fn grasp_plan(config: &SceneConfig) -> Vec<Waypoint> {
    plan(config).into_iter().take(3).collect()
}

/// `grasp` lifted to 5 cm above the table.
fn lifted(grasp: &Waypoint) -> Waypoint {
    Waypoint { z: 0.05, ..*grasp }
}

#[test]
fn closing_on_the_block_grasps_it_and_it_moves_with_the_gripper() {
    let config = SceneConfig::default();
    let mut waypoints = grasp_plan(&config);
    waypoints.push(lifted(&waypoints[2]));
    let episode = fly(config, waypoints, 2000).unwrap();
    let ev = events(&episode);
    assert_eq!(ev.iter().filter(|(_, e)| *e == Event::Grasp).count(), 1);
    let (grasp_step, _) = ev[0];
    let at_grasp = &episode.records[grasp_step as usize - 1];
    assert!(at_grasp.gripper_closed && at_grasp.held);
    let last = episode.records.last().unwrap();
    assert!(last.held);
    assert!((last.z - 0.05).abs() < 0.001);
    // The block keeps its place in the gripper (the gripper still points down).
    let offset_then = (at_grasp.block_x - at_grasp.x, at_grasp.block_z - at_grasp.z);
    let offset_now = (last.block_x - last.x, last.block_z - last.z);
    assert!((offset_then.0 - offset_now.0).abs() < 1e-9);
    assert!((offset_then.1 - offset_now.1).abs() < 1e-9);
    assert!(last.block_z > 0.03);
}

#[test]
fn closing_on_nothing_is_a_grasp_miss() {
    let mut s = sim(SceneConfig::default());
    let r = s.step(&Command::idle(true));
    assert_eq!(r.events, vec![Event::GraspMiss]);
    assert!(r.gripper_closed && !r.held);
    // Opening an empty gripper is no event.
    assert_eq!(s.step(&Command::idle(false)).events, vec![]);
}

#[test]
fn opening_high_above_the_table_drops_the_block_and_it_falls_to_the_table() {
    let config = SceneConfig::default();
    let mut waypoints = grasp_plan(&config);
    let lift = Waypoint {
        hold_steps: 0,
        ..lifted(&waypoints[2])
    };
    let open = Waypoint {
        gripper_closed: false,
        hold_steps: 40,
        ..lift
    };
    waypoints.extend([lift, open]);
    let episode = fly(config, waypoints, 3000).unwrap();
    let ev = events(&episode);
    let release = ev.iter().find(|(_, e)| *e == Event::Release).unwrap().0;
    assert!(ev.contains(&(release, Event::Drop)));
    // Free fall from 5 cm to the table: about sqrt(2 h / g) = 0.1 s.
    let rest = TABLE_Z + BLOCK_HALF;
    let landed = episode
        .records
        .iter()
        .find(|r| r.block_z == rest && r.step > release)
        .unwrap();
    let fall_steps = landed.step - release;
    assert!((9..=12).contains(&fall_steps), "{fall_steps}");
    let last = episode.records.last().unwrap();
    assert_eq!((last.block_z, last.held), (rest, false));
    assert_eq!(metrics_of(&episode).drops, 1);
}

fn metrics_of(e: &Episode) -> EpisodeMetrics {
    metrics(e)
}

#[test]
fn setting_the_block_down_outside_the_goal_is_no_drop() {
    let config = SceneConfig::default();
    let mut waypoints = grasp_plan(&config);
    let open = Waypoint {
        gripper_closed: false,
        hold_steps: 5,
        ..waypoints[2]
    };
    waypoints.push(open);
    let episode = fly(config, waypoints, 2000).unwrap();
    let ev: Vec<Event> = events(&episode).into_iter().map(|(_, e)| e).collect();
    assert_eq!(ev, vec![Event::Grasp, Event::Release]);
}

#[test]
fn driving_into_the_table_is_one_collision_and_the_arm_stops() {
    let config = SceneConfig::default();
    let episode = Episode::record(config, &held_for(DOWN, 300)).unwrap();
    let (step, event) = only_collision(&episode);
    assert_eq!(event, Event::Collision { link: 3 });
    // From then on the arm does not move, and nothing reaches below the table.
    let stopped = &episode.records[step as usize - 1];
    let last = episode.records.last().unwrap();
    assert_eq!(stopped.q, last.q);
    assert!(last.z - FINGER_RADIUS >= TABLE_Z);
    // Moving away works at once.
    let mut s = sim(SceneConfig::default());
    for c in held_for(DOWN, 300) {
        s.step(&c);
    }
    moves_up_at_once(&mut s);
}

#[test]
fn a_link_touching_the_resting_block_is_a_collision_and_the_block_stays() {
    let config = SceneConfig::default();
    let (bx, bz) = Layout::of(&config.task).block_start;
    // The open gripper pointing down, lowered over the block and pressed on: the palm
    // (link 3, FINGER_LENGTH behind the tip, radius link_radius) meets the block's top.
    let descend = |x: f64| {
        let above = Waypoint {
            x,
            z: bz + 0.04,
            phi: Some(-std::f64::consts::FRAC_PI_2),
            gripper_closed: false,
            hold_steps: 0,
        };
        let press = Waypoint {
            z: TABLE_Z - 0.02,
            hold_steps: 0,
            ..above
        };
        fly(config.clone(), vec![above, press], 1500).unwrap()
    };
    let episode = descend(bx);
    assert_eq!(only_collision(&episode).1, Event::Collision { link: 3 });
    let ev = events(&episode);
    assert!(!ev
        .iter()
        .any(|(_, e)| *e == Event::Grasp || *e == Event::GraspMiss));
    let last = episode.records.last().unwrap();
    // Stopped where the palm's capsule touches the block's top, above the table contact.
    let touch_z = bz + BLOCK_HALF + config.arm.link_radius - FINGER_LENGTH;
    assert!(
        (last.z - touch_z).abs() < 0.002,
        "tip z {} (touch at {touch_z})",
        last.z
    );
    assert!(last.z > TABLE_Z + FINGER_RADIUS + 0.002);
    // The block is not pushed.
    assert_eq!((last.block_x, last.block_z), (bx, bz));
    // The same descent beside the block goes down to the table.
    let beside = descend(bx + 0.05);
    let low = beside.records.last().unwrap();
    assert!(
        low.z < TABLE_Z + FINGER_RADIUS + 0.002,
        "{} {:?}",
        low.z,
        events(&beside)
    );
    // Moving away from the block works at once.
    let mut s = sim(config.clone());
    for c in &episode.commands {
        s.step(c);
    }
    moves_up_at_once(&mut s);
}

#[test]
fn pressing_the_carried_block_into_the_table_is_a_collision_of_link_4() {
    let config = SceneConfig::default();
    let mut waypoints = grasp_plan(&config);
    let press = Waypoint {
        z: TABLE_Z - 0.01,
        hold_steps: 0,
        ..waypoints[2]
    };
    waypoints.push(press);
    let episode = fly(config, waypoints, 1000).unwrap();
    let ev = events(&episode);
    assert!(
        ev.iter().any(|(_, e)| *e == Event::Collision { link: 4 }),
        "{ev:?}"
    );
    let last = episode.records.last().unwrap();
    assert!(last.block_z - BLOCK_HALF >= TABLE_Z - CONTACT_SLOP_M);
}

#[test]
fn success_after_the_goal_condition_held_success_steps_steps() {
    for (task, success_steps) in [
        (Task::PickPlace, 10),
        (Task::PickPlace, 1),
        (Task::PickPlaceObstacle, 25),
    ] {
        let config = SceneConfig {
            task,
            success_steps,
            ..SceneConfig::default()
        };
        let layout = Layout::of(&config.task);
        let goal = layout.goal.unwrap();
        let episode = fly(config.clone(), plan(&config), 6000).unwrap();
        let last = episode.records.last().unwrap();
        assert_eq!(
            last.events.last(),
            Some(&Event::Success),
            "{:?}",
            config.task
        );
        assert_eq!(episode.outcome(), Some(Outcome::Success));
        // The condition (released, at rest on the table inside the goal's x range) holds
        // on exactly the last `success_steps` records.
        let holds = |r: &StepRecord| {
            !r.held && r.block_z == TABLE_Z + BLOCK_HALF && (goal.x0..=goal.x1).contains(&r.block_x)
        };
        let n = episode.records.len();
        let k = success_steps as usize;
        assert!(episode.records[n - k..].iter().all(holds));
        assert!(!holds(&episode.records[n - k - 1]));
        // Later steps change nothing.
        let mut s = sim(config);
        for c in &episode.commands {
            s.step(c);
        }
        let done = s.state().clone();
        let r = s.step(&UP);
        assert_eq!((r.events.len(), s.state()), (0, &done));
    }
}

#[test]
fn reach_targets_in_order_then_success() {
    let config = SceneConfig::with_task(Task::from_id("reach").unwrap());
    let episode = fly(config.clone(), plan(&config), 6000).unwrap();
    let reached: Vec<usize> = events(&episode)
        .iter()
        .filter_map(|(_, e)| match e {
            Event::TargetReached { index } => Some(*index),
            _ => None,
        })
        .collect();
    assert_eq!(reached, vec![0, 1, 2, 3, 4, 5]);
    assert_eq!(episode.outcome(), Some(Outcome::Success));
}

#[test]
fn timeout_at_the_time_box() {
    let config = SceneConfig {
        time_box_s: 1.0,
        ..SceneConfig::default()
    };
    let mut s = sim(config);
    for step in 1..=100 {
        let r = s.step(&Command::default());
        assert_eq!(r.t_s, step as f64 / 100.0);
        if step < 100 {
            assert_eq!(r.events, vec![]);
        } else {
            assert_eq!(r.events, vec![Event::Timeout]);
        }
    }
    assert_eq!(s.done(), Some(Outcome::Timeout));
    let r = s.step(&UP);
    assert_eq!((r.events.len(), r.step), (0, 100));
}

#[test]
fn latency_delays_by_exactly_the_set_steps() {
    for latency_steps in [0u32, 1, 7, 50] {
        let config = SceneConfig {
            latency_steps,
            ..SceneConfig::default()
        };
        let mut s = sim(config);
        let pulse = Command {
            dx: 1.0,
            gripper_closed: true,
            ..Command::default()
        };
        let start_q = s.state().q;
        let first = s.step(&pulse);
        let mut records = vec![first];
        for _ in 0..60 {
            records.push(s.step(&Command::default()));
        }
        let lag = latency_steps as usize;
        for (i, r) in records.iter().enumerate() {
            if i == lag {
                assert_eq!(r.applied, pulse, "latency {latency_steps}");
                assert_ne!(r.q, start_q);
                assert!(r.gripper_closed);
                assert_eq!(r.events, vec![Event::GraspMiss]);
            } else if i < lag {
                assert_eq!(r.applied, Command::default());
                assert_eq!((r.q, r.gripper_closed), (start_q, false));
            } else {
                assert_eq!(r.applied, Command::default());
            }
        }
    }
}

#[test]
fn a_joint_limit_clamps_and_is_reported_once() {
    let config = SceneConfig::default();
    let turn = Command {
        dphi: 1.0,
        ..Command::default()
    };
    let episode = Episode::record(config.clone(), &held_for(turn, 800)).unwrap();
    let limits: Vec<_> = events(&episode)
        .into_iter()
        .filter(|(_, e)| matches!(e, Event::JointLimit { .. }))
        .collect();
    assert_eq!(limits.len(), 1, "{limits:?}");
    let Event::JointLimit { joint } = limits[0].1 else {
        unreachable!()
    };
    let j = usize::from(joint) - 1;
    let last = episode.records.last().unwrap();
    assert!(last.q[j] == config.arm.q_max[j] || last.q[j] == config.arm.q_min[j]);
    for r in &episode.records {
        for i in 0..3 {
            assert!((config.arm.q_min[i]..=config.arm.q_max[i]).contains(&r.q[i]));
        }
    }
}

#[test]
fn stretching_out_reports_a_singularity() {
    let out = Command {
        dx: 1.0,
        dz: 0.4,
        ..Command::default()
    };
    let episode = Episode::record(SceneConfig::default(), &held_for(out, 600)).unwrap();
    assert!(events(&episode)
        .iter()
        .any(|(_, e)| *e == Event::Singularity));
    let min_w = metrics_of(&episode).min_manipulability;
    assert!(min_w < SINGULAR_RATIO * 0.12 * 0.10);
}

#[test]
fn the_same_commands_give_the_same_bits_and_reset_restores_the_start() {
    for (sigma, latency) in [(0.0, 0), (0.3, 12)] {
        let config = SceneConfig {
            noise_sigma: sigma,
            noise_seed: 5,
            latency_steps: latency,
            ..SceneConfig::default()
        };
        let a = fly(config.clone(), plan(&config), 3000).unwrap();
        let b = Episode::record(config.clone(), &a.commands).unwrap();
        assert_eq!(episode_csv(&a), episode_csv(&b));
        assert_eq!(a, b);
        let mut s = sim(config.clone());
        for c in &a.commands {
            s.step(c);
        }
        assert_ne!(s.state(), s.start_state());
        s.reset();
        assert_eq!(s.state(), s.start_state());
        let again: Vec<StepRecord> = a.commands.iter().map(|c| s.step(c)).collect();
        assert_eq!(again, a.records);
    }
}

#[test]
fn noise_is_seeded() {
    let noisy = |seed| SceneConfig {
        noise_sigma: 0.2,
        noise_seed: seed,
        ..SceneConfig::default()
    };
    let cmds = held_for(UP, 50);
    let a = Episode::record(noisy(1), &cmds).unwrap();
    let b = Episode::record(noisy(1), &cmds).unwrap();
    let c = Episode::record(noisy(2), &cmds).unwrap();
    assert_eq!(a.records, b.records);
    assert_ne!(a.records, c.records);
    // The first step's noise is numpy's default_rng(1).standard_normal() × sigma.
    let mut rng = NumpyRng::new(1);
    assert_eq!(a.records[0].applied.dx, 0.2 * rng.standard_normal());
    assert_eq!(a.records[0].applied.dz, 1.0 + 0.2 * rng.standard_normal());
    assert_eq!(a.records[0].cmd, UP);
}

#[test]
fn commands_are_sanitized() {
    let mut s = sim(SceneConfig::default());
    let r = s.step(&Command {
        dx: f64::NAN,
        dz: 7.0,
        dphi: -f64::INFINITY,
        gripper_closed: false,
    });
    assert_eq!((r.cmd.dx, r.cmd.dz, r.cmd.dphi), (0.0, 1.0, -1.0));
    assert!(r.q.iter().all(|q| q.is_finite()));
}

#[test]
fn event_texts_round_trip() {
    for e in [
        Event::Grasp,
        Event::GraspMiss,
        Event::Release,
        Event::Drop,
        Event::Collision { link: 4 },
        Event::JointLimit { joint: 2 },
        Event::SpeedLimit { joint: 3 },
        Event::Singularity,
        Event::TargetReached { index: 11 },
        Event::Success,
        Event::Timeout,
    ] {
        assert_eq!(Event::from_text(&e.text()), Some(e));
    }
    assert_eq!(Event::from_text("collision"), None);
    assert_eq!(Event::from_text("grasp:1"), None);
}

#[test]
fn geometry_draws_the_arm_where_fk_puts_it() {
    let s = sim(SceneConfig::with_task(Task::from_id("reach").unwrap()));
    let g = s.geometry();
    assert!((g.tip.x - 0.10).abs() < 1e-12 && (g.tip.z - 0.06).abs() < 1e-12);
    assert_eq!(g.links[0].segment.x0, 0.0);
    assert_eq!(g.targets[0].status, TargetStatus::Current);
    assert_eq!(g.targets[1].status, TargetStatus::Pending);
    assert!(g.goal.is_none());
}
