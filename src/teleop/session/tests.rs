use serde_json::{json, Map, Value};

use super::*;
use crate::teleop::episode::{Episode, FailureCategory, Label};
use crate::teleop::scene::SceneConfig;
use crate::teleop::sim::Command;

const START: &str = "2026-12-02T05:00:00.000Z";
const END: &str = "2026-12-02T05:30:00.000Z";

fn push(n: usize, dx: f64, dz: f64, closed: bool) -> Vec<Command> {
    vec![
        Command {
            dx,
            dz,
            dphi: 0.0,
            gripper_closed: closed,
        };
        n
    ]
}

fn episode(commands: &[Command]) -> Episode {
    Episode::record(SceneConfig::default(), commands).expect("default config")
}

/// A session of three labelled episodes (a success-less move, a grasp miss, a dive into
/// the table).
fn session() -> Session {
    let mut s = Session::new("Pilot 7", InputDevice::Keyboard, START);
    s.module = Module::RecordTen;
    s.preflight = Preflight {
        moved: true,
        reset_verified: Some(true),
    };
    let mut moves = push(40, 1.0, 0.0, false);
    moves.extend(push(20, 0.0, 1.0, false));
    s.record(episode(&moves), false);
    s.record(episode(&push(30, 0.0, 0.0, true)), false);
    s.record(episode(&push(150, 0.0, -1.0, false)), false);
    s.episodes[0].set_label(
        Label::Partial,
        Some(FailureCategory::GoalMiss),
        "went, \"almost\"",
    );
    s.episodes[1].set_label(Label::Failure, Some(FailureCategory::GraspMiss), "");
    s.episodes[2].set_label(Label::Failure, Some(FailureCategory::Collision), "");
    s
}

#[test]
fn sha256_of_known_text() {
    assert_eq!(
        sha256_hex(b""),
        "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855"
    );
    assert_eq!(
        sha256_hex(b"abc"),
        "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad"
    );
    assert_eq!(
        sha256_hex(b"abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
        "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1"
    );
    let million = vec![b'a'; 1_000_000];
    assert_eq!(
        sha256_hex(&million),
        "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0"
    );
}

#[test]
fn sha256_fed_in_pieces_is_the_hash_of_the_whole() {
    let million = vec![b'a'; 1_000_000];
    let mut h = Sha256::new();
    for piece in million.chunks(7) {
        h.update(piece);
    }
    assert_eq!(h.len(), 1_000_000);
    assert_eq!(
        h.finish_hex(),
        "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0"
    );
    // Every length around the padding's edges (55, 56, 63, 64, 119, 120 …), cut anywhere.
    let bytes: Vec<u8> = (0u32..300).map(|i| (i * 37 % 251) as u8).collect();
    for len in [0, 1, 55, 56, 57, 63, 64, 65, 119, 120, 127, 128, 129, 300] {
        let whole = &bytes[..len];
        let want = sha256_hex(whole);
        for cut in [1, 3, 63, 64, 65, 200] {
            let mut h = Sha256::new();
            h.update(&[]);
            for piece in whole.chunks(cut) {
                h.update(piece);
            }
            assert_eq!(h.finish_hex(), want, "{len} bytes in pieces of {cut}");
        }
    }
    assert_eq!(
        sha256_hex(&bytes[..56]),
        "928e47b7ec93b2357b1dedf2f5f4fa86151cdf7b05f5d0a73cef7a2de1ee02c0"
    );
}

#[test]
fn evidence_follows_the_schema_field_by_field() {
    let s = session();
    let doc: Value = serde_json::from_str(&s.evidence(END)).expect("json");
    assert_eq!(check_evidence(&doc), Ok(()));
    let keys: Vec<&str> = doc
        .as_object()
        .expect("object")
        .keys()
        .map(String::as_str)
        .collect();
    let mut want = EVIDENCE_KEYS.to_vec();
    want.sort_unstable();
    let mut got = keys.clone();
    got.sort_unstable();
    assert_eq!(got, want, "exactly the schema's top-level keys");
    assert_eq!(doc["schemaVersion"], "0.1");
    assert_eq!(doc["evidenceId"], "teleop_pilot-7_20261202050000");
    assert_eq!(doc["pilotId"], "Pilot 7");
    assert_eq!(doc["taskId"], "pick-place");
    assert_eq!(doc["environment"], "SIMULATION");
    assert_eq!(doc["runtime"], RUNTIME);
    assert_eq!(doc["embodiment"], EMBODIMENT);
    assert_eq!(doc["inputDevice"], "keyboard");
    assert_eq!(doc["startedAt"], START);
    assert_eq!(doc["endedAt"], END);
    assert_eq!(doc["episodes"]["attempted"], 3);
    assert_eq!(doc["episodes"]["successful"], 0);
    assert_eq!(doc["episodes"]["failed"], 3);
    assert_eq!(doc["episodes"]["recoveryEpisodes"], 0);
    assert_eq!(doc["review"]["status"], "UNREVIEWED");
    // Every CSV listed with the SHA-256 of its bytes.
    let artifacts = doc["dataArtifacts"].as_array().expect("array");
    assert_eq!(artifacts.len(), 4);
    for (name, text) in s.files(END).iter().skip(1) {
        let a = artifacts
            .iter()
            .find(|a| a["uriOrRef"] == name.as_str())
            .expect("listed");
        let kind = if name == EPISODES_NAME {
            TABLE_TYPE
        } else {
            EPISODE_TYPE
        };
        assert_eq!(a["type"], kind);
        assert_eq!(a["sha256"], sha256_hex(text.as_bytes()));
        assert_eq!(a["bytes"], text.len());
    }
    // Metrics: flat values only; counts by category.
    let m = doc["metrics"].as_object().expect("metrics");
    assert!(m.values().all(|v| !v.is_array() && !v.is_object()));
    assert_eq!(m["failures.grasp-miss"], 1);
    assert_eq!(m["failures.collision"], 1);
    assert_eq!(m["failures.goal-miss"], 1);
    assert_eq!(m["failures.drop"], 0);
    assert_eq!(m["failures.operator-abort"], 0);
    assert_eq!(m["successRate"], 0.0);
    assert_eq!(m["preflightResetVerified"], true);
    assert_eq!(m["ikMethod"], "dls");
    // The dive into the table is a safety event.
    let safety = doc["safetyEvents"].as_array().expect("array");
    assert!(safety.iter().all(Value::is_string));
    assert!(safety.iter().any(|e| e
        .as_str()
        .is_some_and(|t| t.starts_with("collision: episode 3, step "))));
}

#[test]
fn each_schema_rule_names_its_field() {
    let good: Value = serde_json::from_str(&session().evidence(END)).expect("json");
    let broken = |f: &dyn Fn(&mut Map<String, Value>)| {
        let mut doc = good.clone();
        f(doc.as_object_mut().expect("object"));
        check_evidence(&doc).expect_err("refused")
    };
    let field = |name: &str| name.to_string();
    assert_eq!(
        broken(&|d| {
            d.remove("pilotId");
        }),
        EvidenceProblem::Missing {
            field: field("pilotId")
        }
    );
    assert_eq!(
        broken(&|d| {
            d.insert("extra".into(), json!(1));
        }),
        EvidenceProblem::Unexpected {
            field: field("extra")
        }
    );
    assert_eq!(
        broken(&|d| {
            d.insert("schemaVersion".into(), json!("0.2"));
        }),
        EvidenceProblem::Value {
            field: field("schemaVersion")
        }
    );
    for bad in ["teleop_", "Teleop_x", "teleop_A", "teleop_a b", "x_teleop"] {
        assert_eq!(
            broken(&|d| {
                d.insert("evidenceId".into(), json!(bad));
            }),
            EvidenceProblem::Value {
                field: field("evidenceId")
            },
            "{bad}"
        );
    }
    assert_eq!(
        broken(&|d| {
            d.insert("environment".into(), json!("REAL"));
        }),
        EvidenceProblem::Value {
            field: field("environment")
        }
    );
    assert_eq!(
        broken(&|d| {
            d.insert("endedAt".into(), json!("yesterday"));
        }),
        EvidenceProblem::Value {
            field: field("endedAt")
        }
    );
    assert_eq!(
        broken(&|d| {
            d.insert("runtimeVersion".into(), json!(1));
        }),
        EvidenceProblem::Type {
            field: field("runtimeVersion")
        }
    );
    assert_eq!(
        broken(&|d| {
            d["episodes"]["failed"] = json!(0);
        }),
        EvidenceProblem::Value {
            field: field("episodes")
        }
    );
    assert_eq!(
        broken(&|d| {
            d["episodes"]
                .as_object_mut()
                .map(|e| e.remove("recoveryEpisodes"));
        }),
        EvidenceProblem::Missing {
            field: field("episodes.recoveryEpisodes")
        }
    );
    assert_eq!(
        broken(&|d| {
            d["dataArtifacts"][0]["sha256"] = json!("abc");
        }),
        EvidenceProblem::Value {
            field: field("dataArtifacts[0].sha256")
        }
    );
    assert_eq!(
        broken(&|d| {
            d["dataArtifacts"][1]
                .as_object_mut()
                .map(|a| a.remove("uriOrRef"));
        }),
        EvidenceProblem::Missing {
            field: field("dataArtifacts[1].uriOrRef")
        }
    );
    assert_eq!(
        broken(&|d| {
            d["safetyEvents"] = json!([{"episode": 3}]);
        }),
        EvidenceProblem::Type {
            field: field("safetyEvents[0]")
        }
    );
    assert_eq!(
        broken(&|d| {
            d["metrics"]["nested"] = json!({"a": 1});
        }),
        EvidenceProblem::Type {
            field: field("metrics.nested")
        }
    );
    assert_eq!(
        broken(&|d| {
            d["review"]["status"] = json!("APPROVED");
        }),
        EvidenceProblem::Value {
            field: field("review.status")
        }
    );
    assert_eq!(
        broken(&|d| {
            d.insert("safetyEvents".into(), json!(3));
        }),
        EvidenceProblem::Type {
            field: field("safetyEvents")
        }
    );
    assert_eq!(check_evidence(&json!([1])), Err(EvidenceProblem::NotObject));
}

#[test]
fn iso_dates() {
    for ok in [START, "2026-12-02T05:00:00Z", "2026-12-02T14:00:00+09:00"] {
        assert!(is_iso8601(ok), "{ok}");
    }
    for bad in [
        "",
        "2026-12-02",
        "2026-12-02 05:00:00Z",
        "2026-12-02T05:00:00",
        "2026-12-02T05:00:00.Z",
        "2026-12-02T05:00:00+0900",
    ] {
        assert!(!is_iso8601(bad), "{bad}");
    }
    // The shape is not enough: the date and the time of day must exist.
    for impossible in [
        "2026-13-02T05:00:00Z",
        "2026-02-30T05:00:00Z",
        "2026-12-02T25:00:00Z",
    ] {
        assert!(!is_iso8601(impossible), "{impossible}");
    }
}

#[test]
fn episodes_table_rows_and_category_counts() {
    let s = session();
    let csv = s.episodes_csv();
    let mut lines = csv.lines();
    assert_eq!(lines.next(), Some(EPISODES_HEADER));
    let first = lines.next().expect("row 1");
    assert!(
        first.starts_with("1,pick-place,PARTIAL,goal-miss,\"went, \"\"almost\"\"\",0,ended,0.6,"),
        "{first}"
    );
    assert!(lines
        .next()
        .expect("row 2")
        .starts_with("2,pick-place,FAILURE,grasp-miss,,0,"));
    assert_eq!(csv.lines().count(), 4);
    let sum = s.summary();
    assert_eq!(sum.attempted, 3);
    assert_eq!(sum.partial, 1);
    let counts: Vec<(&str, usize)> = sum.by_category.iter().map(|(c, n)| (c.id(), *n)).collect();
    assert_eq!(counts[0], ("grasp-miss", 1));
    assert_eq!(counts[2], ("collision", 1));
    assert_eq!(counts[3], ("goal-miss", 1));
    assert_eq!(counts.iter().map(|(_, n)| n).sum::<usize>(), 3);
}

/// The test session, an episode interrupted while it was recorded, and the JSON stored of
/// both.
fn stored_with_interrupted() -> (Session, Episode, String) {
    let s = session();
    let in_progress = episode(&push(25, 0.5, 0.5, false));
    let json = s.to_json(Some(&in_progress));
    (s, in_progress, json)
}

#[test]
fn stored_session_round_trips_and_keeps_an_interrupted_episode() {
    let (s, in_progress, json) = stored_with_interrupted();
    let back = Session::<Episode>::from_json(&json).expect("back");
    assert_eq!(back.episodes.len(), 4, "the interrupted episode is kept");
    assert_eq!(back.episodes[..3], s.episodes[..]);
    let last = &back.episodes[3];
    assert!(last.interrupted);
    assert_eq!(last.label, None);
    assert_eq!(*last.episode, in_progress, "simulated again bit for bit");
    assert_eq!(
        last.proposal(),
        (Label::Failure, Some(FailureCategory::OperatorAbort))
    );
    assert_eq!(back.unlabelled(), Some(4));
    assert!(
        json.len() < 20_000,
        "run-length coded: {} bytes",
        json.len()
    );
    assert_eq!(Session::<Episode>::from_json("{}"), None);
}

#[test]
fn a_session_loaded_in_slices_is_the_one_loaded_at_once() {
    let (_, _, json) = stored_with_interrupted();
    let whole = Session::<Episode>::from_json(&json).expect("whole");
    for slice in [0, 1, 7, 1000] {
        let mut loader = SessionLoader::<Episode>::new(&json).expect("loader");
        let (_, total) = loader.progress();
        let steps: usize = whole.episodes.iter().map(|e| e.episode.records.len()).sum();
        assert_eq!(total, steps);
        let mut calls = 0;
        while !loader.run(slice.max(1)).expect("simulates") {
            calls += 1;
            assert!(calls <= steps, "slice {slice}: ends");
            let (done, _) = loader.progress();
            assert!(
                done <= calls * slice.max(1),
                "slice {slice}: at most {slice} a call"
            );
        }
        assert_eq!(loader.progress(), (total, total));
        assert_eq!(loader.finish(), Some(whole.clone()), "slice {slice}");
    }
    // Not finished: no session yet.
    let mut loader = SessionLoader::<Episode>::new(&json).expect("loader");
    assert_eq!(loader.run(3), Some(false));
    assert_eq!(loader.finish(), None);
    // A start state that is not the configuration's: refused, as at once.
    let mut stored: StoredSession = serde_json::from_str(&json).expect("stored");
    stored.episodes[1].episode.start.q[0] += 0.1;
    let bad = serde_json::to_string(&stored).expect("json");
    assert_eq!(Session::<Episode>::from_json(&bad), None);
    let mut loader = SessionLoader::<Episode>::new(&bad).expect("parses");
    let mut result = Some(false);
    while result == Some(false) {
        result = loader.run(5);
    }
    assert_eq!(result, None);
    assert!(SessionLoader::<Episode>::new("{}").is_none());
}

#[test]
fn saved_files_open_again_and_bad_ones_are_named() {
    let s = session();
    let files = s.files(END);
    let back = Session::<Episode>::from_files(&files).expect("opens");
    assert_eq!(back.episodes, s.episodes);
    assert_eq!(back.pilot_id, s.pilot_id);
    assert_eq!(back.evidence(END), s.evidence(END));

    let without = |name: &str| -> Vec<(String, String)> {
        files.iter().filter(|(n, _)| n != name).cloned().collect()
    };
    assert_eq!(
        Session::<Episode>::from_files(&without("teleop_episode_2.csv")),
        Err(SessionError::MissingFile {
            name: "teleop_episode_2.csv".into()
        })
    );
    let mut tampered = files.clone();
    tampered[3].1 = tampered[3].1.replacen("0.0", "0.1", 1);
    assert_eq!(
        Session::<Episode>::from_files(&tampered),
        Err(SessionError::Sha256Mismatch {
            name: "teleop_episode_2.csv".into()
        })
    );
    let mut bad_json = files.clone();
    bad_json[0].1 = "{ \"schemaVersion\": ".into();
    assert!(matches!(
        Session::<Episode>::from_files(&bad_json),
        Err(SessionError::NotJson { line: 1, .. })
    ));
    let mut extra_key = files.clone();
    extra_key[0].1 = extra_key[0].1.replacen('{', "{\"x\": 1,", 1);
    assert_eq!(
        Session::<Episode>::from_files(&extra_key),
        Err(SessionError::Evidence {
            problem: EvidenceProblem::Unexpected { field: "x".into() }
        })
    );
}

#[test]
fn repeatability_compares_side_by_side() {
    let first = session();
    let mut second = Session::new("Pilot 7", InputDevice::Keyboard, END);
    second.record(episode(&push(30, 0.0, 0.0, true)), false);
    second.episodes[0].set_label(Label::Success, Some(FailureCategory::Drop), "");
    assert_eq!(
        second.episodes[0].category, None,
        "a success has no category"
    );
    let rows = compare(&first.summary(), &second.summary());
    let ids: Vec<&str> = rows.iter().map(|r| r.id.as_str()).collect();
    assert_eq!(
        &ids[..5],
        &[
            "attempted",
            "success-rate",
            "mean-time",
            "efficiency",
            "collisions"
        ]
    );
    assert_eq!(ids.len(), 15);
    assert_eq!(rows[0].first, Some(3.0));
    assert_eq!(rows[1].first, Some(0.0));
    assert_eq!(rows[1].second, Some(1.0));
    assert_eq!(rows[5].id, "grasp-miss");
    assert_eq!((rows[5].first, rows[5].second), (Some(1.0), Some(0.0)));
}

#[test]
fn modules_in_order() {
    let ids: Vec<&str> = Module::ALL.iter().map(|m| m.id()).collect();
    assert_eq!(
        ids,
        [
            "preflight",
            "basic-control",
            "record-ten",
            "failure-review",
            "repeatability"
        ]
    );
    assert_eq!(Module::Repeatability.next(), Module::Repeatability);
    assert_eq!(Module::from_id("record-ten"), Some(Module::RecordTen));
    assert!(Module::RecordTen.records() && !Module::BasicControl.records());
    assert_eq!(clean_pilot_id(&"x".repeat(100)).len(), PILOT_ID_MAX);
}

/// The Academy's published schema, validated by a real JSON Schema validator (formats
/// asserted): a fresh session, a session with a failure of every category, and one stored
/// and loaded again.
#[cfg(not(target_arch = "wasm32"))]
mod academy_schema {
    use super::*;

    const SCHEMA: &str = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../shared/robot-pilot/teleop-session-evidence-v0.1.schema.json"
    );

    fn validator() -> jsonschema::Validator {
        let text = std::fs::read_to_string(SCHEMA).expect("the Academy's schema beside the repo");
        let schema: Value = serde_json::from_str(&text).expect("schema is JSON");
        jsonschema::options()
            .should_validate_formats(true)
            .build(&schema)
            .expect("a valid schema")
    }

    fn assert_valid<E: PracticeEpisode>(session: &Session<E>) {
        assert_valid_text(&session.evidence(END));
    }

    /// The evidence `text` as JSON, valid against the schema and our reader's rules.
    fn assert_valid_text(text: &str) -> Value {
        let doc: Value = serde_json::from_str(text).expect("json");
        let errors: Vec<String> = validator()
            .iter_errors(&doc)
            .map(|e| format!("{} at {}", e, e.instance_path()))
            .collect();
        assert!(errors.is_empty(), "{}", errors.join("\n"));
        assert_eq!(check_evidence(&doc), Ok(()));
        doc
    }

    #[test]
    fn a_fresh_session_is_valid() {
        assert_valid(&Session::<Episode>::new(
            "Pilot 7",
            InputDevice::Keyboard,
            START,
        ));
    }

    #[test]
    fn failures_of_every_category_are_valid() {
        let mut s = session();
        for (i, category) in CATEGORIES.iter().enumerate() {
            s.record(episode(&push(10 + i, 0.0, -1.0, false)), i % 3 == 0);
            let n = s.episodes.len() - 1;
            s.episodes[n].set_label(Label::Failure, Some(*category), "see \"notes\"");
        }
        s.record(episode(&push(5, 1.0, 0.0, false)), false);
        assert_valid(&s);
        let doc = s.evidence_value(END);
        for category in CATEGORIES {
            assert!(doc["metrics"][format!("failures.{}", category.id())].as_u64() >= Some(1));
        }
        assert!(!doc["safetyEvents"].as_array().expect("array").is_empty());
    }

    #[test]
    fn a_session_loaded_from_storage_is_valid() {
        let s = session();
        let in_progress = episode(&push(12, 0.0, 1.0, false));
        let back = Session::<Episode>::from_json(&s.to_json(Some(&in_progress))).expect("loads");
        assert_valid(&back);
    }

    #[test]
    fn an_so101_session_is_valid_and_names_the_so101() {
        use crate::so101::{Command as Cmd, Episode as So101Episode, SceneConfig as So101Config};
        let mut s: Session<So101Episode> = Session::new("Pilot 7", InputDevice::Gamepad, START);
        for (i, obstacle) in [false, true].into_iter().enumerate() {
            let cmds: Vec<Cmd> = (0..80 + i * 40)
                .map(|k| Cmd::with_axes([0.5, 0.0, -0.2, 0.0, 0.0, 0.1], k > 60))
                .collect();
            let ep = So101Episode::record(So101Config::default_for(obstacle), &cmds).expect("ok");
            s.record(ep, i == 1);
        }
        s.episodes[0].set_label(Label::Failure, Some(FailureCategory::GraspMiss), "");
        assert_valid(&s);
        let doc = s.evidence_value(END);
        assert_eq!(doc["embodiment"], crate::so101::EMBODIMENT);
        assert_eq!(doc["dataArtifacts"][0]["uriOrRef"], "so101_episodes.csv");
        assert_eq!(doc["dataArtifacts"][2]["uriOrRef"], "so101_episode_2.csv");
        let back = Session::<So101Episode>::from_files(&s.files(END)).expect("reads back");
        assert_eq!(back.episodes.len(), 2);
        assert_eq!(back.episodes[0].label, Some(Label::Failure));
        let stored = Session::<So101Episode>::from_json(&s.to_json(None)).expect("loads");
        assert_eq!(stored.episodes, s.episodes);
        assert_valid(&stored);
    }

    #[test]
    fn a_dataset_zip_is_listed_after_the_episodes_and_the_files_still_read_back() {
        use crate::teleop::session::{ExtraArtifact, DATASET_TYPE};
        let s = session();
        let zip = Artifact::of_bytes("so101_lerobot_v3.zip", b"PK\x03\x04 not really a zip");
        let extra = [ExtraArtifact {
            kind: DATASET_TYPE,
            media_type: "application/zip",
            artifact: zip.clone(),
        }];
        let text = s.evidence_with_extra(END, &s.episode_artifacts(), &extra);
        let doc = assert_valid_text(&text);
        let listed = doc["dataArtifacts"].as_array().expect("array");
        let last = listed.last().expect("listed");
        assert_eq!(last["type"], DATASET_TYPE);
        assert_eq!(last["uriOrRef"], "so101_lerobot_v3.zip");
        assert_eq!(last["sha256"], zip.sha256.as_str());
        assert_eq!(last["mediaType"], "application/zip");
        assert_eq!(listed.len(), s.episodes.len() + 2);
        // The session's files with this evidence still open as the session.
        let mut files = s.files(END);
        files[0].1 = text;
        let back = Session::<Episode>::from_files(&files).expect("reads back");
        assert_eq!(back.episodes.len(), s.episodes.len());
    }

    #[test]
    fn the_validator_refuses_the_old_artifact_shape() {
        let mut doc = session().evidence_value(END);
        doc["dataArtifacts"][0] = json!({"path": "teleop_episodes.csv", "sha256": null});
        assert!(!validator().is_valid(&doc));
    }
}

#[test]
fn the_empty_summary_is_the_summary_of_no_episode() {
    assert_eq!(Summary::empty(), Summary::of::<crate::teleop::Episode>(&[]));
    assert_eq!(Summary::empty(), Summary::of::<crate::so101::Episode>(&[]));
}
