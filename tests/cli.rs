//! The `bsv` command line as a user runs it: files byte-identical to the Python recipe's,
//! the summary line on stdout, exit code 2 and nothing written on bad input.
#![cfg(not(target_arch = "wasm32"))]

use std::ops::Deref;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn bsv(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_bsv"))
        .args(args)
        .output()
        .expect("run bsv")
}

/// A fresh folder under the temp dir, removed with everything in it when dropped (also when
/// the test fails), so `cargo test` leaves no `bsv-cli-*` folders behind.
struct TempDir(PathBuf);

impl Deref for TempDir {
    type Target = Path;
    fn deref(&self) -> &Path {
        &self.0
    }
}

impl AsRef<Path> for TempDir {
    fn as_ref(&self) -> &Path {
        &self.0
    }
}

impl Drop for TempDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

fn temp_dir(name: &str) -> TempDir {
    let dir = std::env::temp_dir().join(format!("bsv-cli-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    TempDir(dir)
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

#[test]
fn temp_dirs_are_removed_when_dropped() {
    let path = {
        let dir = temp_dir("guard");
        std::fs::write(dir.join("x.csv"), "a\n").unwrap();
        assert!(dir.join("x.csv").exists());
        dir.to_path_buf()
    };
    assert!(!path.exists(), "{} left behind", path.display());
}

#[test]
fn warnings_go_to_stderr_and_the_csv_stays_the_recipes() {
    let dir = temp_dir("warn");
    let out = bsv(&["pid-step", "1e9", "--out", dir.to_str().unwrap()]);
    assert!(out.status.success());
    assert_eq!(
        String::from_utf8_lossy(&out.stdout),
        "wrote 80 PID samples final_y=nan -> pid_step.csv\n"
    );
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("warning") && err.contains("not finite from step"),
        "{err}"
    );
    let csv = std::fs::read_to_string(dir.join("pid_step.csv")).unwrap();
    assert_eq!(
        csv,
        bsv_playground::recipes::run("pid-step", &["1e9".to_string()])
            .unwrap()
            .files[0]
            .text
    );
    // A sensible run prints nothing on stderr.
    let out = bsv(&["pid-step", "--out", dir.to_str().unwrap()]);
    assert!(
        out.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

#[test]
fn messages_use_numbers_as_people_write_them() {
    let out = bsv(&["pid-step", "1", "1", "1", "-1"]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("tau: must be between 0 and 1,000,000 (it is -1)"),
        "{err}"
    );
    let out = bsv(&["rrt-2d", "1e30"]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("9,223,372,036,854,775,807"), "{err}");
    assert!(!err.contains("e+") && !err.contains(".0 "), "{err}");
    // Whole numbers in any notation.
    let dir = temp_dir("notation");
    let out = bsv(&[
        "manip-grid",
        "0.12",
        "0.10",
        "2.4e1",
        "--out",
        dir.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

#[test]
fn recipe_help_states_units_and_limits_from_the_facts() {
    let out = bsv(&["ik-workspace", "--help"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("from 0.000001 to 10 m"), "{text}");
    assert!(text.contains("more than 0 mm, no upper limit"), "{text}");
    let out = bsv(&["pendulum-energy", "--help"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("one of euler, rk4"), "{text}");
}
