//! The `bsv` command line as a user runs it: files byte-identical to the Python recipe's,
//! the summary line on stdout, exit code 2 and nothing written on bad input.
#![cfg(not(target_arch = "wasm32"))]

use std::path::PathBuf;
use std::process::{Command, Output};

fn bsv(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_bsv"))
        .args(args)
        .output()
        .expect("run bsv")
}

fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("bsv-cli-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn writes_byte_identical_csv_and_prints_summary() {
    // jacobian-2r's reference run is byte-identical (ik-workspace's is within 1e-9 only:
    // the reference numpy used Intel's SVML acos/atan2, which are not correctly rounded).
    let dir = temp_dir("jacobian");
    let out = bsv(&["jacobian-2r", "--out", dir.to_str().unwrap()]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(
        String::from_utf8_lossy(&out.stdout),
        include_str!("golden/jacobian_default/stdout.txt")
    );
    let written = std::fs::read_to_string(dir.join("jacobian_2r.csv")).unwrap();
    assert_eq!(
        written,
        include_str!("golden/jacobian_default/jacobian_2r.csv")
    );
}

#[test]
fn reads_an_input_file_by_path() {
    let dir = temp_dir("resample");
    let input = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/golden/resample_3joint/input.csv"
    );
    let out = bsv(&[
        "traj-resample",
        input,
        "0.05",
        "--out",
        dir.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let summary = String::from_utf8_lossy(&out.stdout);
    assert_eq!(summary, include_str!("golden/resample_3joint/stdout.txt"));
    assert!(dir.join("traj_resampled.csv").exists());
}

#[test]
fn bad_input_exits_2_names_the_argument_and_writes_nothing() {
    let dir = temp_dir("bad");
    let out = bsv(&[
        "ik-workspace",
        "0.12",
        "abc",
        "--out",
        dir.to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("L2") && err.contains("abc"), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 0);

    let out = bsv(&["no-such-recipe"]);
    assert_eq!(out.status.code(), Some(2));
    let out = bsv(&["traj-resample", "/no/such/file.csv"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("/no/such/file.csv"));
}

#[test]
fn help_lists_every_recipe_with_defaults() {
    let out = bsv(&["--help"]);
    assert!(out.status.success());
    let text = String::from_utf8_lossy(&out.stdout);
    for r in &bsv_playground::recipes::RECIPES {
        assert!(
            text.contains(r.info.id),
            "{} missing from --help",
            r.info.id
        );
    }
    let out = bsv(&["pendulum-energy", "--help"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("duration_s") && text.contains("--integrator"),
        "{text}"
    );
}
