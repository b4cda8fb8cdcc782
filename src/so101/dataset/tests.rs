#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use super::stats::{FeatureStats, Precision};
use super::*;
use crate::so101::scene::{SceneConfig, CUBE_HALF};
use crate::so101::sim::{Command, Sim};
use crate::so101::tests::fly;
use crate::teleop::sim::Outcome;

/// A brisk scripted pick and place (about 6 s): over the cube, down, close, up, across,
/// down, open, until the cube has rested in the goal.
fn pick_and_place() -> Episode {
    let config = SceneConfig::default_for(false);
    let mut sim = Sim::new(config.clone()).unwrap();
    let mut out = Vec::new();
    let cube = sim.state().cube.pos;
    let goal = config.goal;
    fly(
        &mut sim,
        [cube[0], cube[1], cube[2] + 0.06],
        false,
        110,
        &mut out,
    );
    fly(&mut sim, cube, false, 90, &mut out);
    fly(&mut sim, cube, true, 3, &mut out);
    fly(&mut sim, [cube[0], cube[1], 0.08], true, 80, &mut out);
    fly(&mut sim, [goal[0], goal[1], 0.08], true, 130, &mut out);
    let place = [goal[0], goal[1], CUBE_HALF + 0.003];
    fly(&mut sim, place, true, 90, &mut out);
    fly(&mut sim, place, false, 40, &mut out);
    Episode::record(config, &out).unwrap()
}

/// 150 steps along x and down, the gripper closed on nothing from step 121 (a grasp miss).
fn grasp_miss() -> Episode {
    let commands: Vec<Command> = (0..150)
        .map(|k| Command::with_axes([0.6, 0.2, -0.3, 0.0, 0.1, -0.2], k >= 120))
        .collect();
    Episode::record(SceneConfig::default_for(false), &commands).unwrap()
}

#[test]
fn the_scripted_pick_and_place_succeeds() {
    let ep = pick_and_place();
    assert_eq!(ep.outcome(), Some(Outcome::Success));
    assert!(ep.records.len() < 700, "{} steps", ep.records.len());
}

#[test]
fn frames_sample_every_fourth_step_in_follower_units() {
    let ep = grasp_miss();
    let frames = episode_frames(&ep).unwrap();
    assert_eq!(frames.len(), 150usize.div_ceil(STEPS_PER_FRAME));
    // Frame 0 is the start state; frame k the state after step 4k.
    let deg = |q: [f64; 5]| q.map(|a| a.to_degrees() as f32);
    assert_eq!(frames[0].state[..5], deg(ep.start.q));
    assert_eq!(frames[3].state[..5], deg(ep.records[11].q));
    // Open jaw, then closed on nothing (the grasp miss at step 121 = frame 30's step).
    let open = gripper_percent(crate::so101::scene::JAW_OPEN) as f32;
    assert!((open - 55.97).abs() < 0.01, "{open}");
    assert_eq!(frames[29].state[5], open);
    assert_eq!(frames[30].state[5], open);
    assert_eq!(frames[30].action[5], gripper_percent(0.0) as f32);
    assert_eq!(frames[31].state[5], gripper_percent(0.0) as f32);
    // The action is where the step was told to go: with no contact, where it went.
    assert_eq!(frames[3].action[..5], deg(ep.records[12].q));
    // The cube rests at its start; the goal is the config's.
    let env = frames[7].environment;
    assert_eq!(env[..3], ep.start.cube.pos.map(|x| x as f32));
    assert_eq!(env[3], 0.0);
    assert_eq!(env[4..], ep.config.goal.map(|x| x as f32));
}

#[test]
fn a_tampered_or_empty_episode_is_refused() {
    let mut ep = grasp_miss();
    ep.records[40].q[1] += 1e-12;
    assert_eq!(
        episode_frames(&ep),
        Err(DatasetError::NotReplayed { step: 41 })
    );
    let empty = Episode::record(SceneConfig::default_for(false), &[]).unwrap();
    let mut builder = DatasetBuilder::new();
    assert_eq!(
        builder.add_episode(&empty, Label::Failure, None, ""),
        Err(DatasetError::EmptyEpisode)
    );
    assert_eq!(builder.finish().unwrap_err(), DatasetError::NoEpisodes);
}

/// numpy's `RunningQuantileStats` on `np.arange(10)` as float32 and as int64 (LeRobot's
/// `get_feature_stats`, digits as it gives them).
#[test]
fn episode_statistics_are_lerobots() {
    let rows: Vec<[f64; 1]> = (0..10).map(|i| [f64::from(i)]).collect();
    let cases = [
        (
            Precision::Single,
            [
                -1.000000013351432e-10,
                -1.000000013351432e-10,
                4.001399993896484,
                8.000999450683594,
                8.999819946289062,
            ],
        ),
        (
            Precision::Double,
            [
                -1e-10,
                -1e-10,
                4.00139999998892,
                8.0010000000778,
                8.999820000099996,
            ],
        ),
    ];
    for (precision, want) in cases {
        let s = FeatureStats::of_episode(&rows, precision);
        assert_eq!(
            (s.min[0], s.max[0], s.mean[0], s.count),
            (0.0, 9.0, 4.5, 10)
        );
        assert!((s.std[0] - 8.25f64.sqrt()).abs() < 1e-12);
        let q: Vec<f64> = s.quantiles.iter().map(|q| q[0]).collect();
        assert_eq!(q, want, "{precision:?}");
    }
    let one = FeatureStats::of_episode(&[[2.5]], Precision::Single);
    assert_eq!(one.quantiles[4], vec![2.5]);
}

#[test]
fn the_builder_places_episodes_and_labels_them() {
    let (a, b) = (pick_and_place(), grasp_miss());
    let mut builder = DatasetBuilder::new();
    builder
        .add_episode(&a, Label::Success, None, "clean")
        .unwrap();
    builder
        .add_episode(
            &b,
            Label::Failure,
            Some(FailureCategory::GraspMiss),
            "closed early, \"K\"",
        )
        .unwrap();
    let (na, nb) = (a.records.len().div_ceil(4), b.records.len().div_ceil(4));
    assert_eq!((builder.episodes(), builder.frames()), (2, na + nb));
    let files = builder.clone().finish().unwrap();
    let names: Vec<&str> = files.iter().map(|f| f.0.as_str()).collect();
    assert_eq!(
        names,
        [
            INFO_PATH,
            STATS_PATH,
            TASKS_PATH,
            EPISODES_PATH,
            DATA_FILE_PATH,
            LABELS_PATH
        ]
    );
    let text = |i: usize| String::from_utf8(files[i].1.clone()).unwrap();
    let info: serde_json::Value = serde_json::from_str(&text(0)).unwrap();
    assert_eq!(info["total_episodes"], 2);
    assert_eq!(info["total_frames"], na + nb);
    assert_eq!(info["total_tasks"], 1);
    assert_eq!(info["fps"], 25);
    assert_eq!(info["splits"]["train"], "0:2");
    assert_eq!(info["features"]["action"]["names"][5], "gripper.pos");
    let stats: serde_json::Value = serde_json::from_str(&text(1)).unwrap();
    assert_eq!(stats["index"]["count"][0], na + nb);
    assert_eq!(stats["index"]["max"][0], (na + nb - 1) as f64);
    assert_eq!(stats["next.success"]["max"][0], 1.0);
    let labels: serde_json::Value = serde_json::from_str(&text(5)).unwrap();
    assert_eq!(labels["episodes"][0]["label"], "SUCCESS");
    assert_eq!(labels["episodes"][1]["category"], "grasp-miss");
    assert_eq!(labels["episodes"][1]["note"], "closed early, \"K\"");
    // Episode placement, as the episodes table states it.
    let placed: Vec<(usize, usize)> = builder.added.iter().map(|e| (e.from, e.length)).collect();
    assert_eq!(placed, [(0, na), (na, nb)]);
    // The same episodes give the same zip, byte for byte.
    let again = builder.finish().unwrap();
    assert_eq!(zip(&files).unwrap(), zip(&again).unwrap());
}

#[test]
fn the_wall_is_a_second_task() {
    let commands = vec![Command::idle(false); 8];
    let open = Episode::record(SceneConfig::default_for(false), &commands).unwrap();
    let wall = Episode::record(SceneConfig::default_for(true), &commands).unwrap();
    let mut builder = DatasetBuilder::new();
    for ep in [&wall, &open, &wall] {
        builder.add_episode(ep, Label::Failure, None, "").unwrap();
    }
    assert_eq!(builder.tasks, [TASK_OBSTACLE, TASK]);
    let tasks: Vec<usize> = builder.added.iter().map(|e| e.task_index).collect();
    assert_eq!(tasks, [0, 1, 0]);
}

/// The scripted session of `tests/so101/session/` (the CLI's tests, `scripts/test.sh`'s
/// LeRobot check and `make check-lerobot` build their dataset from it): a pick and place
/// labelled SUCCESS, a grasp miss labelled FAILURE with a note, and an unlabelled episode.
#[cfg(not(target_arch = "wasm32"))]
fn scripted_session_files() -> Vec<(String, String)> {
    use crate::teleop::session::{InputDevice, Session};
    let mut session: Session<Episode> =
        Session::new("scripted", InputDevice::Keyboard, "2026-01-01T00:00:00Z");
    let idle = vec![Command::idle(false); 20];
    let unlabelled = Episode::record(SceneConfig::default_for(false), &idle).unwrap();
    for ep in [pick_and_place(), grasp_miss(), unlabelled] {
        session.record(ep, false);
    }
    session.episodes[0].label = Some(Label::Success);
    session.episodes[0].note = "scripted pick and place".to_string();
    session.episodes[1].label = Some(Label::Failure);
    session.episodes[1].category = Some(FailureCategory::GraspMiss);
    session.episodes[1].note = "closed on nothing, \"early\"".to_string();
    let mut files = vec![("so101_episodes.csv".to_string(), session.episodes_csv())];
    for e in &session.episodes {
        files.push((
            format!("so101_episode_{}.csv", e.number),
            crate::so101::episode_csv(&e.episode),
        ));
    }
    files
}

/// The committed session files are what the script gives (`BSV_WRITE_FIXTURES=1` rewrites
/// them).
#[cfg(not(target_arch = "wasm32"))]
#[test]
fn the_session_fixtures_are_the_scripted_session() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/so101/session");
    let write = std::env::var_os("BSV_WRITE_FIXTURES").is_some();
    for (name, text) in scripted_session_files() {
        let path = dir.join(&name);
        if write {
            std::fs::create_dir_all(&dir).unwrap();
            std::fs::write(&path, &text).unwrap();
        }
        let committed = std::fs::read_to_string(&path).unwrap_or_default();
        assert!(
            committed == text,
            "{name} differs: BSV_WRITE_FIXTURES=1 rewrites it"
        );
    }
}

/// The scripted session's dataset, zipped: the same bytes natively and in wasm (its SHA-256
/// is fixed here; a change to the format changes it on purpose).
#[test]
fn the_zip_is_the_same_bytes_everywhere() {
    use crate::teleop::session::sha256_hex;
    let one = crate::so101::parse_episode_csv(include_str!(
        "../../../tests/so101/session/so101_episode_1.csv"
    ))
    .unwrap();
    let two = crate::so101::parse_episode_csv(include_str!(
        "../../../tests/so101/session/so101_episode_2.csv"
    ))
    .unwrap();
    let files = dataset_files(&[
        (&one, Label::Success, None, "scripted pick and place"),
        (
            &two,
            Label::Failure,
            Some(FailureCategory::GraspMiss),
            "closed on nothing",
        ),
    ])
    .unwrap();
    let bytes = zip(&files).unwrap();
    assert_eq!(
        sha256_hex(&bytes),
        "2174f537a0137eeaff2eaad89a8e6c07d7916ac783a8681bfd1582b41a70cc46"
    );
}

#[test]
fn the_job_in_pieces_writes_the_same_zip_and_names_a_tampered_step() {
    let (a, b) = (pick_and_place(), grasp_miss());
    let labelled = |episode: &Episode, label| LabelledEpisode {
        episode: episode.clone(),
        label,
        category: None,
        note: "n".to_string(),
    };
    let mut job = ExportJob::new(vec![
        labelled(&a, Label::Success),
        labelled(&b, Label::Failure),
    ]);
    assert_eq!((job.done(), job.total()), (0, 2));
    let mut pieces = 0;
    let bytes = loop {
        pieces += 1;
        if let Some(done) = job.advance(50) {
            break done.unwrap();
        }
    };
    assert_eq!(job.done(), 2);
    // Every 50 steps a piece, one more per episode's end, and the writing.
    let steps = a.records.len() + b.records.len();
    assert!(pieces > steps / 50, "{pieces} pieces");
    let whole = dataset_files(&[
        (&a, Label::Success, None, "n"),
        (&b, Label::Failure, None, "n"),
    ]);
    assert_eq!(bytes, zip(&whole.unwrap()).unwrap());

    let mut tampered = b.clone();
    tampered.records[99].q[2] += 1e-9;
    let mut job = ExportJob::new(vec![
        labelled(&a, Label::Success),
        labelled(&tampered, Label::Failure),
    ]);
    let result = loop {
        if let Some(done) = job.advance(1000) {
            break done;
        }
    };
    assert_eq!(result, Err(DatasetError::NotReplayed { step: 100 }));
}
