#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use super::*;
use crate::teleop::pilot::{fly, plan};

fn flown(config: SceneConfig) -> Episode {
    let waypoints = plan(&config);
    fly(config, waypoints, 6000).unwrap()
}

fn noisy_reach() -> SceneConfig {
    SceneConfig {
        task: Task::from_id("reach").unwrap(),
        noise_sigma: 0.05,
        noise_seed: 42,
        latency_steps: 3,
        control: ControlParams {
            method: IkMethod::AdaptiveDls,
            ..ControlParams::DEFAULT
        },
        ..SceneConfig::default()
    }
}

#[test]
fn csv_round_trip_and_replay() {
    for config in [SceneConfig::default(), noisy_reach()] {
        let episode = flown(config);
        let text = episode_csv(&episode);
        assert!(text.starts_with(MARKER));
        let back = parse_episode_csv(&text).unwrap();
        assert_eq!(back, episode);
        assert_eq!(episode_csv(&back), text);
        let m = replay(&back).unwrap();
        assert_eq!(m, metrics(&episode));
        // CRLF line ends and a byte-order mark read the same.
        let crlf = format!("\u{feff}{}", text.replace('\n', "\r\n"));
        assert_eq!(parse_episode_csv(&crlf).unwrap(), episode);
    }
}

#[test]
fn csv_written_in_slices_is_the_same_bytes() {
    let episode = flown(noisy_reach());
    let whole = episode_csv(&episode);
    let n = episode.records.len();
    assert!(n > 1000, "{n} steps");
    assert!(episode.records.iter().any(|r| !r.events.is_empty()));
    for slice in [1, 97, 1024, n, n + 5] {
        let mut text = episode_csv_head(&episode);
        let mut next = 0;
        while next < n {
            push_episode_csv_rows(&mut text, &episode, next..next + slice);
            next += slice;
        }
        assert_eq!(text, whole, "slices of {slice} rows");
    }
    // Ranges past the end write nothing.
    let mut tail = String::new();
    push_episode_csv_rows(&mut tail, &episode, n..n + 10);
    push_episode_csv_rows(&mut tail, &episode, n + 3..n + 1);
    assert_eq!(tail, "");
}

#[test]
fn csv_rows_are_formatted_like_the_recipes() {
    let episode = flown(SceneConfig::default());
    let text = episode_csv(&episode);
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some(MARKER));
    assert_eq!(lines.next(), Some("# links,0.12,0.1,0.06"));
    let header = lines.find(|l| !l.starts_with('#')).unwrap();
    assert_eq!(header, COLUMNS.join(","));
    let first = lines.next().unwrap();
    assert!(first.starts_with("0.01,"), "{first}");
    let grasp = text.lines().find(|l| l.ends_with(",grasp")).unwrap();
    assert_eq!(grasp.split(',').count(), COLUMNS.len());
    assert!(text.lines().last().unwrap().ends_with(",release") || text.ends_with("success\n"));
}

/// Replaces one cell of step `step`'s row.
fn tamper(text: &str, step: usize, column: &str, value: &str) -> String {
    let col = COLUMNS.iter().position(|c| *c == column).unwrap();
    let header_row = text.lines().position(|l| l.starts_with("t_s,")).unwrap();
    text.lines()
        .enumerate()
        .map(|(i, line)| {
            if i == header_row + step {
                let mut cells: Vec<&str> = line.split(',').collect();
                cells[col] = value;
                cells.join(",")
            } else {
                line.to_string()
            }
        })
        .collect::<Vec<_>>()
        .join("\n")
}

#[test]
fn replay_names_the_first_tampered_step_and_field() {
    let episode = flown(SceneConfig::default());
    let text = episode_csv(&episode);
    let q1 = episode.records[56].q[0];
    let nudged = f64::from_bits(q1.to_bits() + 1);
    let bad = tamper(&text, 57, "q1", &py_float(nudged));
    let err = replay(&parse_episode_csv(&bad).unwrap()).unwrap_err();
    assert_eq!(
        err,
        ReplayMismatch {
            step: 57,
            field: "q1".to_string(),
            expected: py_float(nudged),
            got: py_float(q1),
        }
    );
    assert!(err.to_string().starts_with("step 57: q1 differs"));
    // A changed command changes what follows: the first difference is the applied
    // command of that step.
    let bad = tamper(&text, 30, "dz", "0.25");
    let err = replay(&parse_episode_csv(&bad).unwrap()).unwrap_err();
    assert_eq!((err.step, err.field.as_str()), (30, "applied_dz"));
    // A removed event.
    let grasp_step = episode
        .records
        .iter()
        .find(|r| r.events.contains(&Event::Grasp))
        .unwrap()
        .step as usize;
    let bad = tamper(&text, grasp_step, "event", "");
    let err = replay(&parse_episode_csv(&bad).unwrap()).unwrap_err();
    assert_eq!(
        (err.step as usize, err.field.as_str()),
        (grasp_step, "event")
    );
    // A changed start.
    let bad = text.replace("# start_block,0.08,", "# start_block,0.081,");
    let err = replay(&parse_episode_csv(&bad).unwrap()).unwrap_err();
    assert_eq!((err.step, err.field.as_str()), (0, "start_block_x"));
}

#[test]
fn bad_files_name_the_row_and_column() {
    let episode = flown(SceneConfig::default());
    let text = episode_csv(&episode);
    assert_eq!(
        parse_episode_csv("t_s,q1\n0.01,1\n"),
        Err(TeleopError::NotAnEpisode)
    );
    let header_row = text.lines().position(|l| l.starts_with("t_s,")).unwrap() + 1;
    let bad = tamper(&text, 4, "q2", "abc");
    assert_eq!(
        parse_episode_csv(&bad),
        Err(TeleopError::BadCell {
            row: header_row + 4,
            column: "q2".to_string(),
            value: "abc".to_string()
        })
    );
    let bad = tamper(&text, 2, "held", "yes");
    assert_eq!(parse_episode_csv(&bad).unwrap_err().field(), Some("held"));
    let bad = tamper(&text, 2, "event", "explosion");
    assert_eq!(parse_episode_csv(&bad).unwrap_err().field(), Some("event"));
    let bad = tamper(&text, 3, "x", "1,2");
    assert_eq!(
        parse_episode_csv(&bad),
        Err(TeleopError::Ragged {
            row: header_row + 3,
            expected: COLUMNS.len(),
            got: COLUMNS.len() + 1
        })
    );
    let bad = text.replace("# latency_steps,0\n", "");
    assert_eq!(
        parse_episode_csv(&bad),
        Err(TeleopError::MissingHeader {
            key: "latency_steps".to_string()
        })
    );
    let bad = text.replace("# latency_steps,0\n", "# latency_steps,99\n");
    assert_eq!(
        parse_episode_csv(&bad).unwrap_err().field(),
        Some("latency_steps")
    );
    let bad = text.replace("# method,dls", "# method,svd");
    assert_eq!(parse_episode_csv(&bad).unwrap_err().field(), Some("method"));
}

#[test]
fn proposed_labels() {
    // A clean scripted pick and place.
    let ok = flown(SceneConfig::default());
    assert_eq!(proposed_label(&ok), (Label::Success, None));
    // The steps recorded and the proposed label of an episode that failed.
    let failed = |config: SceneConfig, commands: &[Command]| {
        let episode = Episode::record(config, commands).unwrap();
        let (label, category) = proposed_label(&episode);
        assert_eq!(label, Label::Failure);
        (episode.records.len(), category)
    };
    // Timed out without progress.
    let short = SceneConfig {
        time_box_s: 1.0,
        ..SceneConfig::default()
    };
    let timeout = Some(FailureCategory::Timeout);
    assert_eq!(failed(short, &[Command::default(); 150]), (100, timeout));
    // A grasp miss first, then nothing: ended by the pilot.
    let miss = failed(SceneConfig::default(), &[Command::idle(true); 20]);
    assert_eq!(miss.1, Some(FailureCategory::GraspMiss));
    // Ended by the pilot with no failure event, with high latency: input lag.
    let laggy = SceneConfig {
        latency_steps: 30,
        ..SceneConfig::default()
    };
    let lag = failed(laggy, &[Command::default(); 20]);
    assert_eq!(lag.1, Some(FailureCategory::InputLag));
    let plain = failed(SceneConfig::default(), &[Command::default(); 20]);
    assert_eq!(plain.1, Some(FailureCategory::OperatorAbort));
    for c in FailureCategory::ALL {
        assert_eq!(FailureCategory::from_id(c.id()), Some(c));
    }
    for l in Label::ALL {
        assert_eq!(Label::from_id(l.id()), Some(l));
    }
}
