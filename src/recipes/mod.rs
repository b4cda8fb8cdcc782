//! The twelve BSV recipes, one module each: a parameter struct with the recipe's defaults,
//! validation, a typed run, and the CSV table(s) plus the summary line the Python recipe prints.
//!
//! Each module states its facts once, in its `INFO` ([`RecipeInfo`]): arguments with kind,
//! unit, limits and hint ([`ArgSpec`](crate::args::ArgSpec)), the files it writes, its quirks
//! text, its cost estimate and its home-card picture ([`picture`]). Each implements
//! [`Kernel`], the one shape of every recipe: `params` (parse → validate) → `rows` (rows of
//! work, without running; `INFO.plan`) → `run` (with progress) → CSV. The CLI, `runRecipe`, the pages and
//! the tests reach them all the same way: [`run`] / [`run_with_progress`] with the recipe id
//! and command-line style arguments.

pub mod cubic_path;
pub mod dh_fk;
pub mod ik_workspace;
pub mod info;
pub mod jacobian_2r;
pub mod kernel;
pub mod manip_grid;
pub mod output;
pub mod pendulum_energy;
pub mod picture;
pub mod pid_step;
pub mod rrt_2d;
pub mod se3_relative;
pub mod traj_resample;
pub mod trapezoid_profile;
pub mod umeyama_2d;

#[cfg(test)]
pub(crate) mod testkit;

pub use crate::args::Plan;
pub use info::RecipeInfo;
pub use kernel::{
    plan_of, run_of, run_progress_of, run_raw_of, Kernel, PageRecipe, Progress, Recipe, RunRaw,
    RunWithProgress,
};
pub use output::{CsvFile, RecipeOutput};

use crate::args::Args;
use crate::error::RecipeError;

/// All recipes, in the order of the BSV page.
pub const RECIPES: [Recipe; 12] = [
    Recipe::of::<pendulum_energy::Entry>(pendulum_energy::picture),
    Recipe::of::<ik_workspace::Entry>(ik_workspace::picture),
    Recipe::of::<traj_resample::Entry>(traj_resample::picture),
    Recipe::of::<dh_fk::Entry>(dh_fk::picture),
    Recipe::of::<jacobian_2r::Entry>(jacobian_2r::picture),
    Recipe::of::<cubic_path::Entry>(cubic_path::picture),
    Recipe::of::<se3_relative::Entry>(se3_relative::picture),
    Recipe::of::<rrt_2d::Entry>(rrt_2d::picture),
    Recipe::of::<pid_step::Entry>(pid_step::picture),
    Recipe::of::<manip_grid::Entry>(manip_grid::picture),
    Recipe::of::<trapezoid_profile::Entry>(trapezoid_profile::picture),
    Recipe::of::<umeyama_2d::Entry>(umeyama_2d::picture),
];

/// Each recipe's id and the page it runs on (`RecipeInfo::page`): the registry's ids without
/// its kernels, for code that must not hold every kernel (the app's shell).
pub const RECIPE_PAGES: [(&str, Option<&str>); RECIPES.len()] = {
    let mut pages = [("", None); RECIPES.len()];
    let mut i = 0;
    while i < RECIPES.len() {
        pages[i] = (RECIPES[i].info.id, RECIPES[i].info.page);
        i += 1;
    }
    pages
};

/// Every recipe's facts in the registry's order, without its kernels: for code that lists,
/// parses and plans recipes but runs them through [`run_with_inputs`] elsewhere (the drills
/// page, whose runs are a chunk of their own).
pub const INFOS: [&RecipeInfo; RECIPES.len()] = {
    let mut infos = [RECIPES[0].info; RECIPES.len()];
    let mut i = 0;
    while i < RECIPES.len() {
        infos[i] = RECIPES[i].info;
        i += 1;
    }
    infos
};

/// The facts of recipe `id` (see [`INFOS`]).
pub fn find_info(id: &str) -> Option<&'static RecipeInfo> {
    INFOS.into_iter().find(|info| info.id == id)
}

/// The page recipe `id` runs on, if it has one (see [`RECIPE_PAGES`]).
pub fn page_of(id: &str) -> Option<&'static str> {
    RECIPE_PAGES
        .iter()
        .find(|(recipe, _)| *recipe == id)
        .and_then(|(_, page)| *page)
}

/// The recipe with this id.
pub fn find(id: &str) -> Option<&'static Recipe> {
    RECIPES.iter().find(|r| r.info.id == id)
}

/// Runs recipe `id` with command-line style arguments.
///
/// # Example
/// ```
/// let out = bsv_playground::recipes::run("pid-step", &[]).unwrap();
/// assert_eq!(out.summary, "wrote 80 PID samples final_y=0.7967 -> pid_step.csv");
/// ```
pub fn run(id: &str, raw: &[String]) -> Result<RecipeOutput, RecipeError> {
    run_with_inputs(id, raw, Vec::new())
}

/// Parses command-line style arguments for recipe `id` (for handles that take the recipe's
/// arguments, such as the wasm `RrtHandle`).
pub fn parse_args(id: &str, raw: &[String]) -> Result<Args, RecipeError> {
    let recipe = find(id).ok_or_else(|| RecipeError::UnknownRecipe { id: id.to_string() })?;
    Args::parse(raw, recipe.info.args, recipe.info.flags)
}

/// Runs recipe `id` with arguments and input files `(name, text)` that path arguments name
/// (traj-resample's CSV).
pub fn run_with_inputs(
    id: &str,
    raw: &[String],
    inputs: Vec<(String, String)>,
) -> Result<RecipeOutput, RecipeError> {
    let recipe = find(id).ok_or_else(|| RecipeError::UnknownRecipe { id: id.to_string() })?;
    (recipe.run)(&parse_args(id, raw)?.with_inputs(inputs))
}

/// [`run_with_inputs`] reporting `progress(done, total)` rows of work, at most every ~1 %.
/// The output is bit for bit that of [`run_with_inputs`].
pub fn run_with_progress(
    id: &str,
    raw: &[String],
    inputs: Vec<(String, String)>,
    progress: &mut dyn FnMut(u64, u64),
) -> Result<RecipeOutput, RecipeError> {
    let recipe = find(id).ok_or_else(|| RecipeError::UnknownRecipe { id: id.to_string() })?;
    (recipe.run_progress)(&parse_args(id, raw)?.with_inputs(inputs), progress)
}

/// The cost of running recipe `id` with these arguments and inputs, without running it
/// (argument errors come out here as they would from a run).
pub fn plan(id: &str, raw: &[String], inputs: Vec<(String, String)>) -> Result<Plan, RecipeError> {
    let recipe = find(id).ok_or_else(|| RecipeError::UnknownRecipe { id: id.to_string() })?;
    (recipe.info.plan)(&parse_args(id, raw)?.with_inputs(inputs))
}

/// The text of input file `name` from its bytes: the one decoding policy of the CLI and the
/// pages. The bytes must be UTF-8 text (a byte-order mark is allowed; the CSV reader drops it);
/// anything else is refused, never guessed or replaced, so a page and `bsv` always read the
/// same numbers from the same file: a UTF-16 byte-order mark is named as such, a NUL byte as
/// a binary file (with its line and its byte in the line), else the offset of the first byte
/// that is not valid UTF-8.
///
/// ```
/// use bsv_playground::error::RecipeError;
/// use bsv_playground::recipes::decode_input;
/// assert_eq!(decode_input("a.csv", b"t_s,q1\n").unwrap(), "t_s,q1\n");
/// assert_eq!(
///     decode_input("a.csv", b"t_s,q\xe9\n"),
///     Err(RecipeError::InputNotUtf8 { name: "a.csv".into(), offset: 5 })
/// );
/// assert_eq!(
///     decode_input("a.csv", b"t_s,q1\r\n0,\x001\n"),
///     Err(RecipeError::InputBinary { name: "a.csv".into(), line: 2, column: 3 })
/// );
/// ```
pub fn decode_input(name: &str, bytes: &[u8]) -> Result<String, RecipeError> {
    if bytes.starts_with(&[0xFF, 0xFE]) || bytes.starts_with(&[0xFE, 0xFF]) {
        return Err(RecipeError::InputUtf16 {
            name: name.to_string(),
        });
    }
    if let Some(at) = bytes.iter().position(|&b| b == 0) {
        let (line, column) = line_and_column(bytes, at);
        return Err(RecipeError::InputBinary {
            name: name.to_string(),
            line,
            column,
        });
    }
    match std::str::from_utf8(bytes) {
        Ok(text) => Ok(text.to_string()),
        Err(e) => Err(RecipeError::InputNotUtf8 {
            name: name.to_string(),
            offset: e.valid_up_to() as u64,
        }),
    }
}

/// The line (from 1; `\r\n`, `\n` and `\r` end a line) and the byte in that line (from 1)
/// of byte `at`.
fn line_and_column(bytes: &[u8], at: usize) -> (u64, u64) {
    let before = bytes.get(..at).unwrap_or_default();
    let mut line = 1u64;
    let mut line_start = 0usize;
    for (i, &b) in before.iter().enumerate() {
        let ends = b == b'\n' || (b == b'\r' && before.get(i + 1) != Some(&b'\n'));
        if ends {
            line += 1;
            line_start = i + 1;
        }
    }
    (line, (at - line_start) as u64 + 1)
}

#[cfg(test)]
mod tests {
    #[cfg(target_arch = "wasm32")]
    use wasm_bindgen_test::wasm_bindgen_test as test;

    use super::testkit::{assert_defaults_in_one_place, strings};
    use super::*;
    use crate::args::{ArgKind, Bound};
    use crate::error::RecipeWarning;
    use crate::i18n::{I18n, Lang};
    use crate::pyfmt::human;

    /// Every hint and quirks id has a message in both languages, and the English hint states
    /// each finite limit of the argument as a person writes it (the facts and the words agree).
    #[test]
    fn hints_and_quirks_exist_and_state_the_limits() {
        let i18n = I18n::new();
        for recipe in RECIPES {
            let info = recipe.info;
            for lang in Lang::ALL {
                assert!(
                    i18n.has_message(lang, info.quirks_id),
                    "{lang:?} {}",
                    info.quirks_id
                );
            }
            assert_eq!(info.quirks_id, format!("recipe-{}-quirks", info.id));
            for (spec, flag) in info.all_args() {
                assert!(
                    !spec.hint_id.is_empty(),
                    "{} {}: no hint",
                    info.id,
                    spec.name
                );
                for lang in Lang::ALL {
                    assert!(
                        i18n.has_message(lang, spec.hint_id),
                        "{lang:?} {}",
                        spec.hint_id
                    );
                    assert!(i18n.has_message(lang, &spec.label_id(info.id, flag)));
                }
                let en = i18n.t(Lang::En, spec.hint_id);
                let ja = i18n.t(Lang::Ja, spec.hint_id);
                for bound in [spec.min, spec.max] {
                    if let Some(v) = bound.value() {
                        let words = human(v.abs());
                        assert!(
                            en.contains(&words),
                            "{}: {en:?} lacks {words}",
                            spec.hint_id
                        );
                        assert!(
                            ja.contains(&words),
                            "{}: {ja:?} lacks {words}",
                            spec.hint_id
                        );
                    }
                }
                if let ArgKind::Choice(choices) = spec.kind {
                    assert!(choices.iter().all(|c| en.contains(c)), "{en}");
                }
            }
        }
        assert_eq!(i18n.take_warnings(), Vec::<String>::new());
    }

    #[test]
    fn every_recipe_has_a_title_a_blurb_and_a_label_per_argument() {
        let i18n = I18n::new();
        let mut missing = Vec::new();
        for recipe in RECIPES {
            let info = recipe.info;
            let mut ids = vec![
                format!("recipe-{}-title", info.id),
                format!("recipe-{}-blurb", info.id),
            ];
            ids.extend(
                info.args
                    .iter()
                    .map(|a| format!("recipe-{}-arg-{}", info.id, a.name)),
            );
            ids.extend(
                info.flags
                    .iter()
                    .map(|a| format!("recipe-{}-flag-{}", info.id, a.name)),
            );
            for id in ids {
                for lang in Lang::ALL {
                    if !i18n.has_message(lang, &id) {
                        missing.push(format!("{}: {id}", lang.code()));
                    }
                }
            }
        }
        assert!(
            missing.is_empty(),
            "no message for:\n{}",
            missing.join("\n")
        );
    }

    /// Raw arguments with every argument at its default except `name` = `value`.
    fn with(info: &RecipeInfo, name: &str, value: &str) -> Vec<String> {
        let mut raw = Vec::new();
        let index = info.args.iter().position(|a| a.name == name);
        for (i, a) in info.args.iter().enumerate() {
            if Some(i) == index {
                raw.push(value.to_string());
                break;
            }
            raw.push(a.default.to_string());
        }
        if index.is_none() {
            raw.extend([format!("--{name}"), value.to_string()]);
        }
        raw
    }

    /// A value just outside each finite limit is refused, with the error naming the argument
    /// first: the limit in the facts is the one the kernel enforces.
    #[test]
    fn just_outside_each_limit_is_refused_naming_the_argument() {
        let mut checked = 0;
        for recipe in RECIPES {
            let info = recipe.info;
            for (spec, _) in info.all_args() {
                let whole = matches!(spec.kind, ArgKind::Integer | ArgKind::Seed);
                let below = match spec.min {
                    Bound::None => None,
                    Bound::Excl(m) => Some(m),
                    Bound::Incl(m) if whole => Some(m - 1.0),
                    Bound::Incl(0.0) => Some(-0.001),
                    Bound::Incl(m) => Some(m - m.abs() * 0.5),
                };
                let above = match spec.max {
                    Bound::None => None,
                    Bound::Excl(m) => Some(m),
                    Bound::Incl(m) if whole && m > 1e18 => Some(1e19),
                    Bound::Incl(m) if whole => Some(m + 1.0),
                    Bound::Incl(m) => Some(m + m.abs().max(1.0)),
                };
                assert!(
                    spec.kind == ArgKind::File || spec.check_text(spec.default).is_ok(),
                    "{} {}: default refused by its own facts",
                    info.id,
                    spec.name
                );
                for value in [below, above].into_iter().flatten() {
                    let raw = with(info, spec.name, &value.to_string());
                    // The field alone is refused, as the run refuses it.
                    let field = spec.check_text(&value.to_string()).unwrap_err();
                    assert_eq!(field.param(), Some(spec.name));
                    let err = run(info.id, &raw).unwrap_err();
                    assert_eq!(err.param(), Some(spec.name), "{} {raw:?}: {err}", info.id);
                    assert_eq!(plan(info.id, &raw, Vec::new()), Err(err));
                    checked += 1;
                }
            }
        }
        assert!(checked >= 40, "{checked}");
    }

    /// Each recipe's arguments left off give its `Params::default()`.
    #[test]
    fn defaults_in_one_place() {
        assert_defaults_in_one_place::<pendulum_energy::Entry>();
        assert_defaults_in_one_place::<ik_workspace::Entry>();
        assert_defaults_in_one_place::<traj_resample::Entry>();
        assert_defaults_in_one_place::<dh_fk::Entry>();
        assert_defaults_in_one_place::<jacobian_2r::Entry>();
        assert_defaults_in_one_place::<cubic_path::Entry>();
        assert_defaults_in_one_place::<se3_relative::Entry>();
        assert_defaults_in_one_place::<rrt_2d::Entry>();
        assert_defaults_in_one_place::<pid_step::Entry>();
        assert_defaults_in_one_place::<manip_grid::Entry>();
        assert_defaults_in_one_place::<trapezoid_profile::Entry>();
        assert_defaults_in_one_place::<umeyama_2d::Entry>();
    }

    #[test]
    fn every_recipe_has_a_plan_and_defaults_run() {
        for recipe in RECIPES {
            let info = recipe.info;
            let plan = (info.plan)(&Args::default()).unwrap();
            assert!(plan.rows >= 1, "{}: {plan:?}", info.id);
            assert!(run(info.id, &[]).is_ok(), "{}", info.id);
        }
        let rows = |id: &str, raw: &[&str]| plan(id, &strings(raw), Vec::new()).unwrap().rows;
        assert_eq!(rows("pid-step", &["1", "1", "1", "1", "1e6"]), 1_000_000);
        assert_eq!(rows("manip-grid", &["0.12", "0.1", "1024"]), 1_048_576);
        assert_eq!(rows("ik-workspace", &[]), 41 * 41);
        assert_eq!(rows("cubic-path", &[]), 51);
        assert_eq!(rows("trapezoid-profile", &[]), 251);
        assert_eq!(rows("pendulum-energy", &[]), 2500);
        assert_eq!(rows("rrt-2d", &["7", "50000"]), 500_000);
        assert_eq!(rows("jacobian-2r", &[]), 16);
        // traj-resample: from the attached input's shape.
        let text = "t_s,q1,q2\n0,0,0\n0.5,1,1\n2.0,2,2\n".to_string();
        let inputs = vec![("in.csv".to_string(), text)];
        let p = plan(
            "traj-resample",
            &strings(&["in.csv", "0.01"]),
            inputs.clone(),
        );
        assert_eq!(p, Ok(Plan { rows: 201 }));
        let out = run_with_inputs(
            "traj-resample",
            &strings(&["in.csv", "0.01"]),
            inputs.clone(),
        );
        assert!(out.unwrap().summary.starts_with("resampled 3 -> 201 rows"));
        let err = plan("traj-resample", &strings(&["in.csv", "1e-7"]), inputs).unwrap_err();
        assert_eq!(err.params(), vec!["dt", "csv_path"]);
        let err = plan("traj-resample", &strings(&["other.csv"]), Vec::new()).unwrap_err();
        assert!(matches!(err, RecipeError::InputMissing { .. }));
    }

    #[test]
    fn live_pages_are_in_the_facts() {
        let pages: Vec<_> = RECIPES
            .iter()
            .filter_map(|r| r.info.page.map(|p| (r.info.id, p)))
            .collect();
        assert_eq!(
            pages,
            [
                ("pendulum-energy", "pendulum-energy"),
                ("ik-workspace", "ik-2r"),
                ("traj-resample", "traj-resample"),
                ("dh-fk", "dh-fk"),
                ("jacobian-2r", "ik-2r"),
                ("cubic-path", "cubic-path"),
                ("se3-relative", "se3-relative"),
                ("rrt-2d", "rrt-2d"),
                ("pid-step", "pid-step"),
                ("manip-grid", "ik-2r"),
                ("trapezoid-profile", "trapezoid-profile"),
                ("umeyama-2d", "umeyama-2d")
            ]
        );
    }

    #[test]
    fn warnings_flag_nonsense_and_leave_the_csv_alone() {
        let warnings = |id: &str, raw: &[&str]| run(id, &strings(raw)).unwrap().warnings;
        // pid-step: Kp = 1e9 overflows to nan; Kp = -5 runs away to -9,003,857.
        assert!(matches!(
            warnings("pid-step", &["1e9"])[..],
            [RecipeWarning::NotFinite { .. }]
        ));
        match &warnings("pid-step", &["-5"])[..] {
            [RecipeWarning::Diverged { final_value, .. }] => {
                assert_eq!(final_value.round(), -9_003_857.0)
            }
            other => panic!("{other:?}"),
        }
        assert_eq!(warnings("pid-step", &[]), vec![]);
        // rrt-2d: goal inside the box; budget too small.
        let inside = warnings(
            "rrt-2d",
            &["7", "300", "--goal-x", "0.5", "--goal-y", "0.5"],
        );
        assert_eq!(
            inside,
            vec![RecipeWarning::GoalInObstacle { x: 0.5, y: 0.5 }]
        );
        assert_eq!(
            warnings("rrt-2d", &["7", "5"]),
            vec![RecipeWarning::GoalNotReached { iterations: 5 }]
        );
        assert_eq!(warnings("rrt-2d", &[]), vec![]);
        // umeyama-2d with two pairs fits any noise exactly.
        assert_eq!(
            warnings("umeyama-2d", &["0.02", "3", "2"]),
            vec![RecipeWarning::FewPoints { n: 2 }]
        );
        assert_eq!(warnings("umeyama-2d", &[]), vec![]);
        assert_eq!(warnings("pendulum-energy", &[]), vec![]);
        // A 0.05 s Euler step without damping gains ~15 % energy: the step is too large.
        match &warnings(
            "pendulum-energy",
            &["5", "--timestep", "0.05", "--damping", "0"],
        )[..]
        {
            [RecipeWarning::EnergyGrows { percent }] => assert!((15.0..16.0).contains(percent)),
            other => panic!("{other:?}"),
        }
        // The CSV is the recipe's either way (the golden runs cover the defaults).
        let out = run("pid-step", &strings(&["1e9"])).unwrap();
        assert_eq!(
            out.summary,
            "wrote 80 PID samples final_y=nan -> pid_step.csv"
        );
        // Every warning has a message with its arguments in both languages.
        let i18n = I18n::new();
        let all = [
            RecipeWarning::Diverged {
                peak: 9_003_857.0,
                final_value: -9_003_857.0,
            },
            RecipeWarning::NotFinite { step: 12 },
            RecipeWarning::GoalNotReached { iterations: 800 },
            RecipeWarning::GoalInObstacle { x: 0.5, y: 0.5 },
            RecipeWarning::EnergyGrows { percent: 12.5 },
            RecipeWarning::FewPoints { n: 2 },
        ];
        for w in &all {
            for lang in Lang::ALL {
                let args: Vec<(&str, crate::i18n::FluentArg)> = w
                    .message_args()
                    .into_iter()
                    .map(|(k, v)| (k, v.into()))
                    .collect();
                let text = i18n.t_args(lang, w.message_id(), &args);
                for (_, v) in w.message_args() {
                    assert!(
                        text.contains(&v),
                        "{lang:?} {}: {v} not in {text}",
                        w.message_id()
                    );
                }
            }
            assert!(w.to_string().starts_with("warning: "));
        }
        assert_eq!(all[0].message_args()[1].1, "-9,003,857");
        assert_eq!(i18n.take_warnings(), Vec::<String>::new());
    }

    #[test]
    fn cross_field_limits_name_every_argument_in_the_hints_terms() {
        let i18n = I18n::new();
        // ik-workspace: ±1000 mm at 1 mm is a 2001 × 2001 grid, the limit 1001 × 1001.
        let err = run("ik-workspace", &strings(&["0.12", "0.1", "1000", "1"])).unwrap_err();
        assert_eq!(err.params(), vec!["step_mm", "half_mm"]);
        let en = i18n.recipe_error(Lang::En, &err);
        assert!(
            en.contains("2,001 × 2,001") && en.contains("1,001 × 1,001"),
            "{en}"
        );
        assert!(!en.contains("1002001") && !en.contains("1,002,001"), "{en}");
        let ja = i18n.recipe_error(Lang::Ja, &err);
        assert!(
            ja.contains("2,001 × 2,001") && ja.contains("1,001 × 1,001"),
            "{ja}"
        );
        // trapezoid-profile: distance = 1e9 is attributable to distance (and dt).
        let err = run("trapezoid-profile", &strings(&["1e9"])).unwrap_err();
        assert!(err.params().contains(&"distance"), "{:?}", err.params());
        assert!(err.params().contains(&"dt"));
        let en = i18n.recipe_error(Lang::En, &err);
        assert!(en.contains("1,000,000") && !en.contains("e+"), "{en}");
        // pendulum-energy: duration ÷ timestep.
        let err = run("pendulum-energy", &strings(&["5000"])).unwrap_err();
        assert_eq!(err.params(), vec!["duration_s", "timestep"]);
        // Human numbers, labels passed by the page.
        let err = run("pid-step", &strings(&["1", "1", "1", "-1"])).unwrap_err();
        assert_eq!(
            err.to_string(),
            "tau: must be between 0 and 1,000,000 (it is -1)"
        );
        let args = err.message_args_labelled(&|_| "Plant time constant τ (s)".to_string());
        assert!(args.contains(&("label", "Plant time constant τ (s)".to_string())));
        let err = run("ik-workspace", &strings(&["0.0000001"])).unwrap_err();
        assert_eq!(
            err.to_string(),
            "L1: must be between 0.000001 and 10 (it is 0.0000001)"
        );
        let err = run("umeyama-2d", &strings(&["-1"])).unwrap_err();
        assert_eq!(err.to_string(), "sigma: must be at least 0 (it is -1)");
        assert_eq!(err.message_id(), "err-too-small");
        assert_eq!(i18n.take_warnings(), Vec::<String>::new());
    }
}
