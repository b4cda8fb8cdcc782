#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use super::*;
use crate::teleop::episode::metrics;
use crate::teleop::pilot::{fly, plan};
use crate::teleop::scene::SceneConfig;

#[test]
fn reach_metrics_and_fitts() {
    let config = SceneConfig::with_task(Task::from_id("reach").unwrap());
    let episode = fly(config.clone(), plan(&config), 6000).unwrap();
    let m = metrics(&episode);
    assert_eq!(m.outcome, Some(Outcome::Success));
    assert_eq!(m.targets_reached, 6);
    let fitts = m.fitts.unwrap();
    assert_eq!(fitts.targets, 6);
    // The first target from the start tip (0.10, 0.06): D = |(0.07, −0.02)|, W = 0.04.
    let targets = config.task.targets();
    let mut prev = (0.10, 0.06);
    let mut ids = Vec::new();
    let mut t_prev = 0.0;
    let mut throughputs = Vec::new();
    let reached: Vec<&StepRecord> = episode
        .records
        .iter()
        .filter(|r| {
            r.events
                .iter()
                .any(|e| matches!(e, Event::TargetReached { .. }))
        })
        .collect();
    for (t, r) in targets.iter().zip(&reached) {
        let d = ((t.x - prev.0).powi(2) + (t.z - prev.1).powi(2)).sqrt();
        let id = (d / (2.0 * t.radius) + 1.0).log2();
        ids.push(id);
        throughputs.push(id / (r.t_s - 0.09 - t_prev));
        prev = (r.x, r.z);
        t_prev = r.t_s;
    }
    assert!((ids[0] - ((0.0053f64).sqrt() / 0.04 + 1.0).log2()).abs() < 1e-3);
    let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len() as f64;
    assert!((fitts.id_bits - mean(&ids)).abs() < 1e-12);
    assert!((fitts.throughput_bits_per_s - mean(&throughputs)).abs() < 1e-9);
    assert!(fitts.id_bits > 1.5 && fitts.id_bits < 4.3);
    // The path is at least the ideal one, so efficiency ≤ 1, and well above zero.
    assert!(m.efficiency > 0.5 && m.efficiency <= 1.0);
    assert!(m.path_m > 0.8);
    assert_eq!(m.duration_s, episode.records.last().unwrap().t_s);
}

#[test]
fn pick_place_metrics() {
    let config = SceneConfig::default();
    let episode = fly(config.clone(), plan(&config), 6000).unwrap();
    let m = metrics(&episode);
    assert_eq!(
        (m.grasps, m.drops, m.collisions, m.grasp_misses),
        (1, 0, 0, 0)
    );
    assert_eq!(m.first_failure, None);
    assert!(m.fitts.is_none());
    assert!(m.efficiency > 0.4 && m.efficiency <= 1.0);
    let min_w = episode
        .records
        .iter()
        .map(|r| r.manipulability)
        .fold(f64::INFINITY, f64::min);
    assert!(m.min_manipulability <= min_w);
}
