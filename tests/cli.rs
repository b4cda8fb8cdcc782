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
fn utf16_and_binary_inputs_are_refused_by_name_as_the_pages_refuse_them() {
    let dir = temp_dir("hostile");
    let out_dir = dir.join("out");
    std::fs::create_dir_all(&out_dir).unwrap();
    // Big-endian UTF-16 (the mark FE FF), as some editors save "Unicode" text.
    let utf16 = b"\xfe\xff\x00t\x00_\x00s\x00,\x00q\x001\x00\n\x000\x00,\x001\x00\n".to_vec();
    for (name, bytes, says) in [
        ("excel.csv", utf16, "excel.csv' is UTF-16 text"),
        (
            "nul.csv",
            b"t_s,q1\n0,1\n0.1,2\x00\n".to_vec(),
            "nul.csv' holds a NUL byte (line 3, byte 6 of the line)",
        ),
    ] {
        std::fs::write(dir.join(name), bytes).unwrap();
        let out = bsv(&[
            "traj-resample",
            dir.join(name).to_str().unwrap(),
            "--out",
            out_dir.to_str().unwrap(),
        ]);
        assert_eq!(out.status.code(), Some(2));
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(says), "{err}");
        assert_eq!(std::fs::read_dir(&out_dir).unwrap().count(), 0);
    }
}

#[test]
fn an_input_that_is_not_utf8_is_refused_naming_the_byte_offset() {
    let dir = temp_dir("latin1");
    let input = dir.join("latin1.csv");
    // `é` in Latin-1 (0xE9) on the second line: byte 23 of the file, counted from 0.
    std::fs::write(&input, b"t_s,q1,note\n0.0,0.0,caf\xe9\n0.1,1.0,x\n").unwrap();
    let out_dir = dir.join("out");
    std::fs::create_dir_all(&out_dir).unwrap();
    let out = bsv(&[
        "traj-resample",
        input.to_str().unwrap(),
        "--out",
        out_dir.to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("is not UTF-8 text: byte 23 "), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert_eq!(std::fs::read_dir(&out_dir).unwrap().count(), 0);
    // A byte-order mark is UTF-8: read as the file without it.
    let bom = dir.join("bom.csv");
    std::fs::write(&bom, b"\xef\xbb\xbft_s,q1\r\n0.0,0.0\r\n0.1,1.0\r\n").unwrap();
    let out = bsv(&[
        "traj-resample",
        bom.to_str().unwrap(),
        "0.05",
        "--out",
        out_dir.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
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

/// The two-box world of the RRT tests: boxes, a moved start and goal, another step.
const TWO_BOXES: [&str; 14] = [
    "rrt-2d",
    "7",
    "3000",
    "--obstacle",
    "0.2,0.3,0.4,0.9",
    "--obstacle",
    "0.6,0,0.8,0.7",
    "--start",
    "0.05,0.1",
    "--goal",
    "0.95,0.85",
    "--step",
    "0.04",
    "--goal-tol=0.05",
];

#[test]
fn rrt_world_options_write_the_stepped_tree_byte_for_byte() {
    use bsv_playground::recipes::rrt_2d::{self, Obstacle, Rrt, RrtParams, RrtSetup, RrtWorld};
    let dir = temp_dir("rrt-two-boxes");
    let mut args = TWO_BOXES.to_vec();
    args.extend(["--out", dir.to_str().unwrap()]);
    let out = bsv(&args);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    // The reference: the typed stepper with the recipe's linear nearest-node scan.
    let setup = RrtSetup {
        params: RrtParams {
            seed: 7,
            max_iter: 3000,
            goal: [0.95, 0.85],
        },
        world: RrtWorld {
            start: [0.05, 0.1],
            obstacles: vec![
                Obstacle {
                    x_min: 0.2,
                    y_min: 0.3,
                    x_max: 0.4,
                    y_max: 0.9,
                },
                Obstacle {
                    x_min: 0.6,
                    y_min: 0.0,
                    x_max: 0.8,
                    y_max: 0.7,
                },
            ],
            step: 0.04,
            goal_tol: 0.05,
            ..RrtWorld::default()
        },
        goal_checked: true,
    };
    let mut rrt = Rrt::with_setup(&setup).unwrap();
    rrt.set_linear_search(true);
    while rrt.step_record().is_some() {}
    let want = rrt_2d::output(&rrt);
    for name in ["rrt_nodes.csv", "rrt_path.csv"] {
        let written = std::fs::read(dir.join(name)).unwrap();
        assert_eq!(written, want.file(name).unwrap().as_bytes(), "{name}");
    }
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(stdout.trim_end(), want.summary);
    // The goal is reached around both boxes; no node lies in a box; edges are <= the step.
    let path = rrt.path();
    assert!(path.len() > 20, "{}", path.len());
    assert_eq!(path.first(), Some(&[0.05, 0.1]));
    assert_eq!(path.last(), Some(&[0.95, 0.85]));
    assert!(stdout.starts_with(&format!(
        "RRT nodes={} path_pts={} ",
        rrt.nodes().len(),
        path.len()
    )));
    for p in rrt.nodes() {
        assert!(!setup.world.collides(*p), "{p:?}");
    }
    // The same arguments without the options are the recipe's run, not this one.
    let recipe = bsv(&["rrt-2d", "7", "3000", "--out", dir.to_str().unwrap()]);
    assert_ne!(recipe.stdout, out.stdout);
}

#[test]
fn rrt_world_options_are_refused_with_the_flag_named() {
    let refused = |extra: &[&str]| {
        let mut args = vec!["rrt-2d", "7", "100"];
        args.extend(extra);
        let out = bsv(&args);
        assert_eq!(out.status.code(), Some(2), "{extra:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        err.trim_end()
            .trim_start_matches("bsv: rrt-2d: ")
            .to_string()
    };
    assert_eq!(
        refused(&["--start", "0.5,0.5"]),
        "start: (0.5, 0.5) lies inside obstacle 1 (edges included); move it out of the box"
    );
    assert_eq!(
        refused(&["--obstacle", "0.2,0.2,0.4,0.4", "--goal", "0.4,0.3"]),
        "goal: (0.4, 0.3) lies inside obstacle 1 (edges included); move it out of the box"
    );
    assert_eq!(
        refused(&[
            "--obstacle",
            "0.1,0.5,0.2,0.6",
            "--obstacle",
            "0.6,0.2,0.4,0.3"
        ]),
        "obstacle 2 (0.6,0.2,0.4,0.3): needs x0 <= x1 and y0 <= y1 (x0,y0,x1,y1)"
    );
    assert_eq!(
        refused(&["--obstacle", "0.1,0.2,0.3"]),
        "obstacle: need 4 values, got 3"
    );
    assert_eq!(
        refused(&["--goal", "1.2,0.5"]),
        "goal: must be between 0 and 1 (it is 1.2)"
    );
    assert_eq!(
        refused(&["--step", "0"]),
        "step: must be between 0.001 and 1 (it is 0)"
    );
    assert_eq!(
        refused(&["--goal-bias", "abc"]),
        "goal-bias: 'abc' is not a number"
    );
    assert_eq!(
        refused(&["--goal-tol", "2"]),
        "goal-tol: must be between 0.001 and 1.5 (it is 2)"
    );
    let many: Vec<&str> = (0..33)
        .flat_map(|_| ["--obstacle", "0.5,0.5,0.6,0.6"])
        .collect();
    assert_eq!(refused(&many), "obstacle: given 33 times; at most 32");
    assert_eq!(refused(&["--start", "0.1"]), "start: need 2 values, got 1");
    // `none` empties the square; the aliases still allow a goal inside the recipe's box.
    let dir = temp_dir("rrt-refused");
    let out_dir = dir.to_str().unwrap();
    let out = bsv(&["rrt-2d", "7", "800", "--obstacle", "none", "--out", out_dir]);
    assert!(out.status.success());
    let out = bsv(&[
        "rrt-2d", "7", "50", "--goal-x", "0.5", "--goal-y", "0.5", "--out", out_dir,
    ]);
    assert!(out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("inside the obstacle"));
}

/// A scripted pick-and-place episode as the page exports it.
fn teleop_episode_csv() -> (String, bsv_playground::teleop::Episode) {
    use bsv_playground::teleop::pilot::{fly, plan};
    use bsv_playground::teleop::{episode_csv, SceneConfig};
    let config = SceneConfig::default();
    let episode = fly(config.clone(), plan(&config), 6000).unwrap();
    (episode_csv(&episode), episode)
}

/// `bsv teleop-replay` of `text` saved as `name` in a fresh folder `dir`, which must exit 0:
/// its stdout and output.
fn replayed(dir: &str, name: &str, text: &str) -> (String, std::process::Output) {
    let dir = temp_dir(dir);
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    let out = bsv(&["teleop-replay", path.to_str().unwrap()]);
    let stdout = String::from_utf8_lossy(&out.stdout).into_owned();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    (stdout, out)
}

#[test]
fn teleop_replay_reproduces_an_episode_and_prints_its_metrics() {
    use bsv_playground::pyfmt::py_float;
    let (text, episode) = teleop_episode_csv();
    let (stdout, out) = replayed("teleop-ok", "teleop_episode_1.csv", &text);
    let m = bsv_playground::teleop::metrics(&episode);
    assert!(stdout.starts_with(&format!(
        "replayed {} steps of pick-place (dls): every recorded step reproduced exactly\n",
        episode.records.len()
    )));
    assert!(stdout.contains("\noutcome: success\n"), "{stdout}");
    assert!(stdout.contains(&format!("\nduration_s: {}\n", py_float(m.duration_s))));
    assert!(stdout.contains(&format!("\npath_m: {}\n", py_float(m.path_m))));
    assert!(stdout.contains("\ngrasps: 1\n"));
    assert!(stdout.contains("\nproposed_label: SUCCESS\n"));
    assert!(out.stderr.is_empty());
}

/// An episode CSV with cell `column` of step `step` (from 1) one ulp above `value`.
fn nudged_step(text: &str, step: usize, column: usize, value: f64) -> String {
    let header_row = text.lines().position(|l| l.starts_with("t_s,")).unwrap();
    let nudged = bsv_playground::pyfmt::py_float(f64::from_bits(value.to_bits() + 1));
    let lines: Vec<String> = text
        .lines()
        .enumerate()
        .map(|(i, l)| {
            if i != header_row + step {
                return l.to_string();
            }
            let mut cells: Vec<&str> = l.split(',').collect();
            cells[column] = &nudged;
            cells.join(",")
        })
        .collect();
    lines.join("\n")
}

#[test]
fn teleop_replay_exits_1_naming_the_first_differing_step() {
    let dir = temp_dir("teleop-tampered");
    let (text, episode) = teleop_episode_csv();
    // Step 57's z, one ulp off.
    let z = episode.records[56].z;
    let path = dir.join("tampered.csv");
    std::fs::write(&path, nudged_step(&text, 57, 13, z)).unwrap();
    let out = bsv(&["teleop-replay", path.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("step 57: z differs"), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(out.stdout.is_empty());
}

#[test]
fn teleop_replay_refuses_bad_files_with_exit_2() {
    let dir = temp_dir("teleop-bad");
    let (text, _) = teleop_episode_csv();
    let header_row = text.lines().position(|l| l.starts_with("t_s,")).unwrap();
    let bad = text
        .lines()
        .enumerate()
        .map(|(i, l)| {
            if i == header_row + 3 {
                l.replacen(",0,", ",x,", 1)
            } else {
                l.to_string()
            }
        })
        .collect::<Vec<_>>()
        .join("\n");
    let path = dir.join("bad.csv");
    std::fs::write(&path, bad).unwrap();
    let out = bsv(&["teleop-replay", path.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains(&format!("row {}, column gripper_cmd: 'x'", header_row + 4)),
        "{err}"
    );
    let not_episode = dir.join("traj.csv");
    std::fs::write(&not_episode, "t_s,q1\n0.0,0.0\n").unwrap();
    let out = bsv(&["teleop-replay", not_episode.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("not a teleop episode file"));
    for args in [
        &["teleop-replay"][..],
        &["teleop-replay", "/no/such/episode.csv"],
        &["teleop-replay", "a.csv", "b.csv"],
    ] {
        let out = bsv(args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert_eq!(String::from_utf8_lossy(&out.stderr).lines().count(), 1);
    }
    let out = bsv(&["teleop-replay", "--help"]);
    assert_eq!(out.status.code(), Some(0));
    assert!(String::from_utf8_lossy(&out.stdout).contains("exit 1"));
    let out = bsv(&["--help"]);
    assert!(String::from_utf8_lossy(&out.stdout).contains("teleop-replay"));
}

#[test]
fn umeyama_options_write_the_points_and_leave_the_recipe_alone() {
    let dir = temp_dir("umeyama-options");
    let d = dir.to_str().unwrap();
    // No options: the recipe's one file, its golden summary.
    let recipe = bsv(&["umeyama-2d", "--out", d]);
    assert!(recipe.status.success());
    assert_eq!(
        String::from_utf8_lossy(&recipe.stdout),
        include_str!("golden/umeyama_default/stdout.txt")
    );
    assert!(!dir.join("umeyama_points.csv").exists());
    // Points and a mirrored truth: both files, the points file one row per point.
    let out = bsv(&[
        "umeyama-2d",
        "0",
        "3",
        "3",
        "--x",
        "0,0;1,0;0,1",
        "--mirror",
        "yes",
        "--angle",
        "90",
        "--out",
        d,
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let points = std::fs::read_to_string(dir.join("umeyama_points.csv")).unwrap();
    let mut lines = points.lines();
    assert_eq!(
        lines.next(),
        Some("x,y,target_x,target_y,aligned_x,aligned_y")
    );
    // (0, 1) mirrored to (0, -1), turned 90° to (1, 0), scaled 1.3, moved by (0.4, -0.2).
    let third: Vec<f64> = points
        .lines()
        .nth(3)
        .unwrap()
        .split(',')
        .map(|v| v.parse().unwrap())
        .collect();
    assert_eq!(&third[..2], &[0.0, 1.0]);
    assert!(
        (third[2] - 1.7).abs() < 1e-12 && (third[3] + 0.2).abs() < 1e-12,
        "{points}"
    );
    let csv = std::fs::read_to_string(dir.join("umeyama_2d.csv")).unwrap();
    assert!(csv.trim_end().ends_with(",1.3,90.0"), "{csv}");
    // A pair that is not two numbers is refused, naming --x.
    let bad = bsv(&["umeyama-2d", "0.02", "3", "--x", "0,0;1,0;0"]);
    assert_eq!(bad.status.code(), Some(2));
    assert_eq!(
        String::from_utf8_lossy(&bad.stderr).trim_end(),
        "bsv: umeyama-2d: x: need 2 values, got 1"
    );
}

/// An SO-101 episode: 120 steps along x and down, then the gripper closed on nothing.
fn so101_episode_csv() -> (String, bsv_playground::so101::Episode) {
    use bsv_playground::so101::{episode_csv, Command, Episode, SceneConfig};
    let commands: Vec<Command> = (0..150)
        .map(|k| Command::with_axes([0.6, 0.2, -0.3, 0.0, 0.1, -0.2], k >= 120))
        .collect();
    let episode = Episode::record(SceneConfig::default_for(false), &commands).unwrap();
    (episode_csv(&episode), episode)
}

#[test]
fn teleop_replay_takes_so101_episodes_too() {
    let (text, episode) = so101_episode_csv();
    let (stdout, _) = replayed("so101-ok", "so101_episode_1.csv", &text);
    let dir = temp_dir("so101-tampered");
    assert!(stdout.starts_with(&format!(
        "replayed {} steps of pick-place (dls): every recorded step reproduced exactly\n",
        episode.records.len()
    )));
    assert!(stdout.contains("\ngrasp_misses: 1\n"), "{stdout}");
    assert!(
        stdout.contains("\nproposed_label: FAILURE (grasp-miss)\n"),
        "{stdout}"
    );
    // One ulp off in step 40's q2: exit 1 naming it.
    let tampered = dir.join("tampered.csv");
    let q2 = episode.records[39].q[1];
    std::fs::write(&tampered, nudged_step(&text, 40, 16, q2)).unwrap();
    let out = bsv(&["teleop-replay", tampered.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("step 40: q2 differs"), "{err}");
}

/// The scripted SO-101 session of `tests/so101/session/`.
fn session_file(name: &str) -> String {
    format!("{}/tests/so101/session/{name}", env!("CARGO_MANIFEST_DIR"))
}

#[test]
fn so101_dataset_writes_the_labelled_episodes_as_the_kernel_does() {
    use bsv_playground::so101::dataset::dataset_files;
    use bsv_playground::so101::parse_episode_csv;
    use bsv_playground::teleop::{FailureCategory, Label};
    let dir = temp_dir("so101-dataset");
    let out_dir = dir.join("so101-practice");
    let episodes: Vec<String> = (1..=3)
        .map(|n| session_file(&format!("so101_episode_{n}.csv")))
        .collect();
    // Given out of order: the dataset takes them by number.
    let mut args = vec!["so101-dataset", &episodes[2], &episodes[1], &episodes[0]];
    args.extend(["--out", out_dir.to_str().unwrap()]);
    let out = bsv(&args);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(
        String::from_utf8_lossy(&out.stdout),
        format!(
            "wrote a LeRobot v3.0 dataset to {}: 2 episodes (1 SUCCESS, 1 FAILURE, 0 PARTIAL), 167 frames at 25 fps; 1 unlabelled episode left out\n",
            out_dir.display()
        )
    );
    // The same bytes as the kernel's (the page's zip) for episodes 1 and 2 as labelled.
    let read =
        |n: usize| parse_episode_csv(&std::fs::read_to_string(&episodes[n]).unwrap()).unwrap();
    let (one, two) = (read(0), read(1));
    let want = dataset_files(&[
        (&one, Label::Success, None, "scripted pick and place"),
        (
            &two,
            Label::Failure,
            Some(FailureCategory::GraspMiss),
            "closed on nothing, \"early\"",
        ),
    ])
    .unwrap();
    for (name, bytes) in &want {
        let got = std::fs::read(out_dir.join(name)).unwrap();
        assert!(got == *bytes, "{name} differs from the kernel's");
    }
    let mut written = Vec::new();
    for dir in ["meta", "meta/episodes/chunk-000", "data/chunk-000"] {
        for entry in std::fs::read_dir(out_dir.join(dir)).unwrap() {
            let entry = entry.unwrap();
            if entry.path().is_file() {
                written.push(format!("{dir}/{}", entry.file_name().to_string_lossy()));
            }
        }
    }
    written.sort();
    let mut names: Vec<String> = want.iter().map(|(n, _)| n.clone()).collect();
    names.sort();
    assert_eq!(written, names, "no other file, no partial file left");
}

#[test]
fn so101_dataset_refuses_bad_input_naming_the_file() {
    let dir = temp_dir("so101-dataset-bad");
    let out_dir = dir.join("out");
    let out = out_dir.to_str().unwrap();
    let one = session_file("so101_episode_1.csv");
    let run = |args: &[&str]| {
        let o = bsv(args);
        (
            o.status.code(),
            String::from_utf8_lossy(&o.stderr).into_owned(),
        )
    };
    // No --out, no episode, a name without the number.
    let (code, err) = run(&["so101-dataset", &one]);
    assert_eq!(code, Some(2));
    assert!(err.contains("--out DIR is needed"), "{err}");
    let (code, _) = run(&["so101-dataset", "--out", out]);
    assert_eq!(code, Some(2));
    let renamed = dir.join("episode.csv");
    std::fs::copy(&one, &renamed).unwrap();
    let (code, err) = run(&["so101-dataset", renamed.to_str().unwrap(), "--out", out]);
    assert_eq!(code, Some(2));
    assert!(
        err.contains("episode.csv': not named so101_episode_<n>.csv"),
        "{err}"
    );
    // No so101_episodes.csv beside it.
    let alone = dir.join("so101_episode_1.csv");
    std::fs::copy(&one, &alone).unwrap();
    let (code, err) = run(&["so101-dataset", alone.to_str().unwrap(), "--out", out]);
    assert_eq!(code, Some(2));
    assert!(err.contains("so101_episodes.csv"), "{err}");
    // Only the unlabelled episode.
    let labels = session_file("so101_episodes.csv");
    let three = session_file("so101_episode_3.csv");
    let (code, err) = run(&["so101-dataset", &three, "--labels", &labels, "--out", out]);
    assert_eq!(code, Some(2));
    assert!(err.contains("none of the 1 episodes is labelled"), "{err}");
    // A step that does not replay: exit 1 naming the file and the step.
    let text = std::fs::read_to_string(&one).unwrap();
    let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
    let row = lines[60].replacen(",0.0,", ",0.5,", 1);
    assert_ne!(row, lines[60]);
    lines[60] = row;
    std::fs::write(&alone, lines.join("\n") + "\n").unwrap();
    let (code, err) = run(&[
        "so101-dataset",
        alone.to_str().unwrap(),
        "--labels",
        &labels,
        "--out",
        out,
    ]);
    assert_eq!(code, Some(1), "{err}");
    assert!(
        err.contains("so101_episode_1.csv': not reproduced: step 57"),
        "{err}"
    );
    assert!(!out_dir.exists(), "nothing written on failure");
    // Help, and the listing.
    let help = bsv(&["so101-dataset", "--help"]);
    assert!(help.status.success());
    assert!(String::from_utf8_lossy(&help.stdout).contains("LeRobotDataset(repo_id, root=DIR)"));
    let listing = String::from_utf8_lossy(&bsv(&["--help"]).stdout).into_owned();
    assert!(listing.contains("so101-dataset"), "{listing}");
}
