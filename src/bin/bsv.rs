//! `bsv`: the BSV recipes from a command line, with the Python recipes' arguments and outputs.
//!
//! ```text
//! bsv <recipe-id> [the recipe's positional arguments] [--flag value ...] [--out DIR]
//! bsv --help | bsv <recipe-id> --help
//! bsv teleop-replay <episode csv>
//! bsv so101-dataset <so101_episode_<n>.csv ...> --out DIR [--labels so101_episodes.csv]
//! ```
//! Writes the recipe's CSV file(s) into `DIR` (default: the current folder) and prints the
//! recipe's summary line exactly as the Python recipe does. Bad input: exit code 2 and a
//! one-line message naming the argument, with nothing written. Files are written to temporary
//! names first and renamed only when every file is complete.
//!
//! `bsv teleop-replay` re-runs a Robot Pilot episode (`teleop_episode_<n>.csv`, see
//! [`bsv_playground::teleop::episode`], or the SO-101's `so101_episode_<n>.csv`, see
//! [`bsv_playground::so101::episode`]) from its start state and commands: exit 0 and its
//! metrics when every recorded step comes back bit for bit, exit 1 naming the first step and
//! column that differ, exit 2 for a file that cannot be read as an episode.
//!
//! `bsv so101-dataset` writes the labelled SO-101 episodes of a practice session as a LeRobot
//! v3.0 dataset folder (see [`bsv_playground::so101::dataset`]), the same files the page's
//! zip holds.

use std::fs;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use bsv_playground::args::{ArgKind, ArgSpec};
use bsv_playground::pyfmt::human;
use bsv_playground::recipes::{self, Recipe, RecipeOutput};

/// Input files larger than the kernel accepts are refused before reading.
use bsv_playground::recipes::traj_resample::MAX_INPUT_BYTES;

fn main() -> ExitCode {
    let raw: Vec<String> = std::env::args().skip(1).collect();
    match cli(&raw) {
        Ok(()) => ExitCode::SUCCESS,
        Err(Failure::Usage(msg)) => {
            eprintln!("bsv: {msg}");
            ExitCode::from(2)
        }
        Err(Failure::Io(msg)) | Err(Failure::Mismatch(msg)) => {
            eprintln!("bsv: {msg}");
            ExitCode::from(1)
        }
    }
}

enum Failure {
    /// Bad input: exit code 2.
    Usage(String),
    /// Could not write the output: exit code 1.
    Io(String),
    /// A replayed episode differs from its recording: exit code 1.
    Mismatch(String),
}

fn cli(raw: &[String]) -> Result<(), Failure> {
    let Some(id) = raw.first() else {
        print!("{}", general_help());
        return Err(Failure::Usage(
            "no recipe given (see the list above)".to_string(),
        ));
    };
    if id == "--help" || id == "-h" || id == "help" {
        print!("{}", general_help());
        return Ok(());
    }
    if id == "--version" {
        println!("bsv {}", env!("CARGO_PKG_VERSION"));
        return Ok(());
    }
    if id == TELEOP_REPLAY {
        return teleop_replay(&raw[1..]);
    }
    if id == SO101_DATASET {
        return so101_dataset(&raw[1..]);
    }
    let recipe = recipes::find(id).ok_or_else(|| {
        Failure::Usage(format!(
            "unknown recipe '{id}'; recipes: {}",
            recipe_ids().join(", ")
        ))
    })?;
    let rest = &raw[1..];
    if rest.iter().any(|a| a == "--help" || a == "-h") {
        print!("{}", recipe_help(recipe));
        return Ok(());
    }
    let (args, out_dir) = split_out_dir(rest).map_err(Failure::Usage)?;
    let inputs = read_inputs(recipe, &args)?;
    let output = recipes::run_with_inputs(id, &args, inputs)
        .map_err(|e| Failure::Usage(format!("{id}: {e}")))?;
    write_files(&out_dir, &output)?;
    println!("{}", output.summary);
    for warning in &output.warnings {
        eprintln!("bsv: {id}: {warning}");
    }
    Ok(())
}

/// Removes `--out DIR` / `--out=DIR` from the arguments.
fn split_out_dir(args: &[String]) -> Result<(Vec<String>, PathBuf), String> {
    let mut rest = Vec::new();
    let mut out = PathBuf::from(".");
    let mut iter = args.iter();
    while let Some(arg) = iter.next() {
        if arg == "--out" {
            out = iter
                .next()
                .map(PathBuf::from)
                .ok_or("--out needs a folder")?;
        } else if let Some(dir) = arg.strip_prefix("--out=") {
            out = PathBuf::from(dir);
        } else {
            rest.push(arg.clone());
        }
    }
    Ok((rest, out))
}

/// Reads the files that path arguments (`ArgKind::File` in the recipe's facts) name, so the
/// kernel gets their text.
fn read_inputs(recipe: &Recipe, args: &[String]) -> Result<Vec<(String, String)>, Failure> {
    let mut inputs = Vec::new();
    let id = recipe.info.id;
    let positional: Vec<&String> = args.iter().filter(|a| !a.starts_with("--")).collect();
    let file_args = recipe.info.args.iter().enumerate();
    for (index, _) in file_args.filter(|(_, a)| a.kind == ArgKind::File) {
        let Some(path) = positional.get(index).filter(|p| !p.is_empty()) else {
            continue;
        };
        let fail = |e: std::io::Error| Failure::Usage(format!("{id}: cannot read '{path}': {e}"));
        let len = fs::metadata(path.as_str()).map_err(fail)?.len();
        if len > MAX_INPUT_BYTES {
            return Err(Failure::Usage(format!(
                "{id}: '{path}' is {} bytes; the limit is {} bytes",
                human(len as f64),
                human(MAX_INPUT_BYTES as f64)
            )));
        }
        let bytes = fs::read(path.as_str()).map_err(fail)?;
        let text = recipes::decode_input(path, &bytes)
            .map_err(|e| Failure::Usage(format!("{id}: {e}")))?;
        inputs.push(((*path).clone(), text));
    }
    Ok(inputs)
}

/// Writes every file under a temporary name, then renames them all: nothing half-written.
fn write_files(dir: &Path, output: &RecipeOutput) -> Result<(), Failure> {
    let io = |what: &str, path: &Path, e: std::io::Error| {
        Failure::Io(format!("cannot {what} '{}': {e}", path.display()))
    };
    fs::create_dir_all(dir).map_err(|e| io("create folder", dir, e))?;
    let mut staged = Vec::new();
    for file in &output.files {
        let final_path = dir.join(&file.name);
        let tmp_path = dir.join(format!(".{}.partial-{}", file.name, std::process::id()));
        let result = fs::File::create(&tmp_path)
            .and_then(|mut f| f.write_all(file.text.as_bytes()).and_then(|_| f.sync_all()));
        if let Err(e) = result {
            let _ = fs::remove_file(&tmp_path);
            for (tmp, _) in &staged {
                let _ = fs::remove_file(tmp);
            }
            return Err(io("write", &final_path, e));
        }
        staged.push((tmp_path, final_path));
    }
    for (tmp, final_path) in &staged {
        fs::rename(tmp, final_path).map_err(|e| io("write", final_path, e))?;
    }
    Ok(())
}

fn recipe_ids() -> Vec<&'static str> {
    recipes::RECIPES.iter().map(|r| r.info.id).collect()
}

fn general_help() -> String {
    let mut s = String::from(
        "bsv: the BotShelf Vampire robotics recipes (research, education and simulation only)\n\n\
         usage: bsv <recipe-id> [arguments] [--out DIR]\n       bsv <recipe-id> --help\n\n\
         recipes (arguments with their defaults):\n",
    );
    for r in &recipes::RECIPES {
        let args: Vec<String> = r
            .info
            .args
            .iter()
            .map(|a| format!("{}={}", a.name, a.default))
            .collect();
        s.push_str(&format!(
            "  {:<18} {:<40} ({})\n",
            r.info.id,
            args.join(" "),
            r.info.python
        ));
    }
    s.push_str(
        "\nEach writes the same CSV file(s) and prints the same line as its Python recipe.\n",
    );
    s.push_str(&format!(
        "\nalso:\n  {TELEOP_REPLAY:<18} <episode csv>   replay a Robot Pilot episode exactly and print its metrics\n"
    ));
    s.push_str(&format!(
        "  {SO101_DATASET:<18} <so101_episode_<n>.csv ...> --out DIR   the labelled SO-101 episodes as a LeRobot dataset\n"
    ));
    s
}

/// The replay subcommand's name.
const TELEOP_REPLAY: &str = "teleop-replay";

fn teleop_replay_help() -> String {
    format!(
        "usage: bsv {TELEOP_REPLAY} <episode csv>\n\n\
         Replays a Robot Pilot episode (teleop_episode_<n>.csv from the #/teleop page, or\n\
         so101_episode_<n>.csv from the #/so101 page) from the\n\
         start state and the command stream in the file, checks that every recorded step is\n\
         reproduced bit for bit, and prints the episode's metrics.\n\n\
         exit 0  every step reproduced; the metrics on stdout\n\
         exit 1  a step differs: the first differing step and column on stderr\n\
         exit 2  the file cannot be read as an episode (the row and column named)\n"
    )
}

/// `bsv teleop-replay <episode csv>`.
fn teleop_replay(args: &[String]) -> Result<(), Failure> {
    use bsv_playground::teleop::{self, episode::MAX_EPISODE_BYTES};
    if args.iter().any(|a| a == "--help" || a == "-h") {
        print!("{}", teleop_replay_help());
        return Ok(());
    }
    let [path] = args else {
        return Err(Failure::Usage(format!(
            "{TELEOP_REPLAY}: needs exactly one episode CSV file, got {} arguments (see bsv {TELEOP_REPLAY} --help)",
            args.len()
        )));
    };
    let text = read_text(TELEOP_REPLAY, path, MAX_EPISODE_BYTES)?;
    let unread = |e: teleop::TeleopError| Failure::Usage(format!("{TELEOP_REPLAY}: '{path}': {e}"));
    let differs = |m: teleop::ReplayMismatch| {
        Failure::Mismatch(format!("{TELEOP_REPLAY}: '{path}': not reproduced: {m}"))
    };
    if text.starts_with(bsv_playground::so101::episode::MARKER) {
        use bsv_playground::so101;
        let episode = so101::parse_episode_csv(&text).map_err(unread)?;
        let metrics = so101::replay(&episode).map_err(differs)?;
        let c = &episode.config;
        let (label, category) = episode.proposed_label();
        let head = (episode.records.len(), c.task_id(), c.control.method.id());
        print!("{}", replay_report(head, &metrics, label, category));
        return Ok(());
    }
    let episode = teleop::parse_episode_csv(&text).map_err(unread)?;
    let metrics = teleop::replay(&episode).map_err(differs)?;
    let c = &episode.config;
    let (label, category) = teleop::proposed_label(&episode);
    let head = (episode.records.len(), c.task.id(), c.control.method.id());
    print!("{}", replay_report(head, &metrics, label, category));
    Ok(())
}

/// What `teleop-replay` prints for a reproduced episode: one `name: value` line per figure.
/// `head` is the steps, the task id and the IK method id.
fn replay_report(
    head: (usize, &str, &str),
    m: &bsv_playground::teleop::EpisodeMetrics,
    label: bsv_playground::teleop::Label,
    category: Option<bsv_playground::teleop::FailureCategory>,
) -> String {
    use bsv_playground::pyfmt::py_float;
    let mut s = format!(
        "replayed {} steps of {} ({}): every recorded step reproduced exactly\n",
        head.0, head.1, head.2
    );
    let mut line = |name: &str, value: String| s.push_str(&format!("{name}: {value}\n"));
    line(
        "outcome",
        m.outcome
            .map_or("none (ended by the pilot)", |o| o.id())
            .to_string(),
    );
    line("duration_s", py_float(m.duration_s));
    line("path_m", py_float(m.path_m));
    line("efficiency", py_float(m.efficiency));
    line("collisions", m.collisions.to_string());
    line("joint_limit_stops", m.joint_limit_stops.to_string());
    line("speed_limit_stops", m.speed_limit_stops.to_string());
    line("singularity_stops", m.singularity_stops.to_string());
    line("grasps", m.grasps.to_string());
    line("grasp_misses", m.grasp_misses.to_string());
    line("drops", m.drops.to_string());
    line("targets_reached", m.targets_reached.to_string());
    line("min_manipulability", py_float(m.min_manipulability));
    if let Some(f) = m.fitts {
        line("fitts_id_bits", py_float(f.id_bits));
        line(
            "fitts_throughput_bits_per_s",
            py_float(f.throughput_bits_per_s),
        );
    }
    line(
        "first_failure",
        m.first_failure.map_or("none".to_string(), |(step, e)| {
            format!("{} at step {step}", e.text())
        }),
    );
    line(
        "proposed_label",
        match category {
            Some(c) => format!("{} ({})", label.id(), c.id()),
            None => label.id().to_string(),
        },
    );
    s
}

fn recipe_help(recipe: &Recipe) -> String {
    let info = recipe.info;
    let names: Vec<String> = info.args.iter().map(|a| format!("[{}]", a.name)).collect();
    let mut s = format!(
        "usage: bsv {} {}{} [--out DIR]\n\nSame as: python {} {}\nWrites: {}\n\narguments:\n",
        info.id,
        names.join(" "),
        if info.flags.is_empty() {
            ""
        } else {
            " [options]"
        },
        info.python,
        info.args
            .iter()
            .map(|a| a.name)
            .collect::<Vec<_>>()
            .join(" "),
        info.writes.join(", "),
    );
    for a in info.args {
        s.push_str(&spec_line(a.name, a));
    }
    if !info.flags.is_empty() {
        s.push_str("\noptions (beyond the Python recipe):\n");
        for f in info.flags {
            s.push_str(&spec_line(&format!("--{}", f.name), f));
        }
    }
    s.push_str("  --out DIR      folder for the CSV files (default: current folder)\n");
    s
}

/// The help's line of an argument or option called `name`: what it is, its default and limits.
fn spec_line(name: &str, spec: &ArgSpec) -> String {
    format!(
        "  {name:<14} {} (default {}; {})\n",
        spec.help,
        show_default(spec.default),
        spec.limits_text()
    )
}

fn show_default(d: &str) -> &str {
    if d.is_empty() {
        "none"
    } else {
        d
    }
}

/// The dataset subcommand's name.
const SO101_DATASET: &str = "so101-dataset";

fn so101_dataset_help() -> String {
    use bsv_playground::so101::dataset::{CODEBASE_VERSION, FPS};
    format!(
        "usage: bsv {SO101_DATASET} <so101_episode_<n>.csv ...> --out DIR [--labels FILE]\n\n\
         Writes the labelled episodes of an SO-101 practice session (the #/so101 page's session\n\
         download) as a LeRobot dataset, format {CODEBASE_VERSION}, in DIR: meta/info.json,\n\
         meta/stats.json, meta/tasks.parquet, meta/episodes/chunk-000/file-000.parquet,\n\
         data/chunk-000/file-000.parquet and meta/bsv_labels.json, the files the page's zip holds.\n\
         LeRobotDataset(repo_id, root=DIR) loads it. {FPS} frames per second (every 4th step).\n\n\
         The labels come from so101_episodes.csv beside the first episode file, or from\n\
         --labels FILE. Only labelled episodes go in, in the order of their numbers (the n\n\
         of so101_episode_<n>.csv); each is replayed from its start state first.\n\n\
         exit 0  the dataset written; a summary line on stdout\n\
         exit 1  an episode does not replay, or a file cannot be written\n\
         exit 2  bad arguments, or a file that cannot be read (named)\n"
    )
}

/// A file's text, refused above `limit` bytes or when it is not UTF-8 text (`what` names the
/// subcommand in the messages).
fn read_text(what: &str, path: &str, limit: u64) -> Result<String, Failure> {
    let fail = |e: std::io::Error| Failure::Usage(format!("{what}: cannot read '{path}': {e}"));
    let len = fs::metadata(path).map_err(fail)?.len();
    if len > limit {
        return Err(Failure::Usage(format!(
            "{what}: '{path}' is {} bytes; the limit is {} bytes",
            human(len as f64),
            human(limit as f64)
        )));
    }
    let bytes = fs::read(path).map_err(fail)?;
    recipes::decode_input(path, &bytes).map_err(|e| Failure::Usage(format!("{what}: {e}")))
}

/// The episode number `n` of a path ending in `so101_episode_<n>.csv`.
fn so101_episode_number(path: &str) -> Option<usize> {
    let name = Path::new(path).file_name()?.to_str()?;
    let n = name.strip_prefix("so101_episode_")?.strip_suffix(".csv")?;
    n.parse().ok().filter(|n| *n >= 1)
}

/// `bsv so101-dataset <so101_episode_<n>.csv ...> --out DIR [--labels FILE]`.
fn so101_dataset(args: &[String]) -> Result<(), Failure> {
    use bsv_playground::so101::dataset::{DatasetBuilder, DatasetError, FPS};
    use bsv_playground::so101::episode::MAX_EPISODE_BYTES;
    use bsv_playground::so101::parse_episode_csv;
    use bsv_playground::teleop::session::{parse_episodes_table, EPISODES_HEADER};
    use bsv_playground::teleop::Label;
    const WHAT: &str = SO101_DATASET;
    if args.iter().any(|a| a == "--help" || a == "-h") {
        print!("{}", so101_dataset_help());
        return Ok(());
    }
    let usage = |msg: String| Failure::Usage(format!("{WHAT}: {msg} (see bsv {WHAT} --help)"));
    let (mut paths, mut out, mut labels) = (Vec::new(), None, None);
    let mut iter = args.iter();
    while let Some(arg) = iter.next() {
        let mut value = |flag: &str| {
            iter.next()
                .cloned()
                .ok_or_else(|| usage(format!("{flag} needs a value")))
        };
        match arg.as_str() {
            "--out" => out = Some(value("--out")?),
            "--labels" => labels = Some(value("--labels")?),
            a if a.starts_with("--out=") => out = Some(a["--out=".len()..].to_string()),
            a if a.starts_with("--labels=") => labels = Some(a["--labels=".len()..].to_string()),
            a if a.starts_with("--") => return Err(usage(format!("unknown option '{a}'"))),
            a => paths.push(a.to_string()),
        }
    }
    let out = out.ok_or_else(|| usage("--out DIR is needed".to_string()))?;
    if paths.is_empty() {
        return Err(usage("no episode file given".to_string()));
    }
    let mut numbered = Vec::with_capacity(paths.len());
    for path in &paths {
        let n = so101_episode_number(path).ok_or_else(|| {
            Failure::Usage(format!(
                "{WHAT}: '{path}': not named so101_episode_<n>.csv, so its label cannot be found"
            ))
        })?;
        if numbered.iter().any(|(m, _)| *m == n) {
            return Err(Failure::Usage(format!(
                "{WHAT}: '{path}': episode {n} is given twice"
            )));
        }
        numbered.push((n, path.as_str()));
    }
    numbered.sort_by_key(|(n, _)| *n);
    let labels_path = labels.unwrap_or_else(|| {
        let dir = Path::new(numbered[0].1).parent().unwrap_or(Path::new(""));
        dir.join("so101_episodes.csv")
            .to_string_lossy()
            .into_owned()
    });
    let table = read_text(WHAT, &labels_path, MAX_EPISODE_BYTES)?;
    let rows = parse_episodes_table(&table).map_err(|cell| {
        Failure::Usage(format!(
            "{WHAT}: '{labels_path}': row {}, column {} (the header is {EPISODES_HEADER})",
            cell.row, cell.column
        ))
    })?;
    let mut builder = DatasetBuilder::new();
    let mut counts = [0usize; 3];
    let mut left_out = 0;
    for (n, path) in &numbered {
        let row = rows.iter().find(|r| r.number == *n).ok_or_else(|| {
            Failure::Usage(format!(
                "{WHAT}: '{path}': episode {n} has no row in '{labels_path}'"
            ))
        })?;
        let Some(label) = row.label else {
            left_out += 1;
            continue;
        };
        let text = read_text(WHAT, path, MAX_EPISODE_BYTES)?;
        let episode = parse_episode_csv(&text)
            .map_err(|e| Failure::Usage(format!("{WHAT}: '{path}': {e}")))?;
        builder
            .add_episode(&episode, label, row.category, &row.note)
            .map_err(|e| match e {
                DatasetError::NotReplayed { .. } => {
                    Failure::Mismatch(format!("{WHAT}: '{path}': not reproduced: {e}"))
                }
                e => Failure::Usage(format!("{WHAT}: '{path}': {e}")),
            })?;
        counts[Label::ALL.iter().position(|l| *l == label).unwrap_or(0)] += 1;
    }
    if builder.episodes() == 0 {
        return Err(Failure::Usage(format!(
            "{WHAT}: none of the {} episodes is labelled in '{labels_path}'",
            numbered.len()
        )));
    }
    let (episodes, frames) = (builder.episodes(), builder.frames());
    let files = builder
        .finish()
        .map_err(|e| Failure::Io(format!("{WHAT}: {e}")))?;
    write_tree(Path::new(&out), &files)?;
    let unlabelled = match left_out {
        0 => String::new(),
        1 => "; 1 unlabelled episode left out".to_string(),
        k => format!("; {k} unlabelled episodes left out"),
    };
    println!(
        "wrote a LeRobot v3.0 dataset to {out}: {episodes} episodes ({} {}, {} {}, {} {}), {frames} frames at {FPS} fps{unlabelled}",
        counts[0],
        Label::ALL[0].id(),
        counts[1],
        Label::ALL[1].id(),
        counts[2],
        Label::ALL[2].id(),
    );
    Ok(())
}

/// Writes `files` (paths relative to `root`, folders made as needed) under temporary names,
/// then renames them all: nothing half-written.
fn write_tree(root: &Path, files: &[(String, Vec<u8>)]) -> Result<(), Failure> {
    let io = |what: &str, path: &Path, e: std::io::Error| {
        Failure::Io(format!("cannot {what} '{}': {e}", path.display()))
    };
    let mut staged = Vec::new();
    let clean = |staged: &[(PathBuf, PathBuf)]| {
        for (tmp, _) in staged {
            let _ = fs::remove_file(tmp);
        }
    };
    for (name, bytes) in files {
        let final_path = root.join(name);
        let dir = final_path.parent().unwrap_or(root);
        let file_name = final_path
            .file_name()
            .map(|f| f.to_string_lossy().into_owned())
            .unwrap_or_default();
        let tmp_path = dir.join(format!(".{file_name}.partial-{}", std::process::id()));
        let result = fs::create_dir_all(dir).and_then(|_| {
            fs::File::create(&tmp_path)
                .and_then(|mut f| f.write_all(bytes).and_then(|_| f.sync_all()))
        });
        if let Err(e) = result {
            let _ = fs::remove_file(&tmp_path);
            clean(&staged);
            return Err(io("write", &final_path, e));
        }
        staged.push((tmp_path, final_path));
    }
    for (tmp, final_path) in &staged {
        fs::rename(tmp, final_path).map_err(|e| io("write", final_path, e))?;
    }
    Ok(())
}
