//! The catalog as a whole: ids, pages, kinds and the checks' refusals.

use super::*;
use crate::recipes::RECIPE_PAGES;
use crate::view::pilot_picture;
#[cfg(target_family = "wasm")]
use wasm_bindgen_test::wasm_bindgen_test as test;

#[test]
fn ids_are_unique_kebab_case_and_pages_are_the_apps() {
    let mut seen = std::collections::BTreeSet::new();
    for e in catalog() {
        assert!(seen.insert(e.id), "duplicate id {}", e.id);
        assert!(
            e.id.split('-').all(|w| !w.is_empty()
                && w.chars()
                    .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit())),
            "{}",
            e.id
        );
        assert!(
            RECIPE_PAGES.iter().any(|(_, page)| *page == Some(e.page))
                || pilot_picture::PAGES.contains(&e.page),
            "{} on {}",
            e.id,
            e.page
        );
        assert!(e.prompt_id().starts_with("ex-") && e.message_ids().len() >= 3);
    }
    for id in [
        "ik-singular",
        "pendulum-euler-dt",
        "pid-tune",
        "trap-triangle",
        "rrt-300",
    ] {
        assert!(find(id).is_some(), "{id}");
    }
    assert_eq!(find("nope").map(|e| e.id), None);
    assert_eq!(
        of_page("pid-step").map(|e| e.id).collect::<Vec<_>>(),
        ["pid-tune", "pid-final-y", "pid-p-only", "pid-overshoot"]
    );
}

#[test]
fn the_id_table_is_the_catalogs_without_its_checks() {
    let from_table: Vec<&str> = all_ids().collect();
    let from_catalog: Vec<&str> = catalog().map(|e| e.id).collect();
    assert_eq!(from_table, from_catalog);
    for (page, ids) in PAGE_IDS {
        assert_eq!(ids_of_page(page), ids);
        assert_eq!(of_page(page).map(|e| e.id).collect::<Vec<_>>(), ids);
        assert!(ids.len() >= 3, "{page}");
    }
    assert!(ids_of_page("drills").is_empty());
    assert!(catalog().count() >= 40);
}

#[test]
fn the_required_exercises_have_their_kinds() {
    let kind = |id| find(id).map(|e| e.kind);
    assert_eq!(kind("ik-singular"), Some(Kind::Goal));
    assert!(matches!(
        kind("pendulum-euler-dt"),
        Some(Kind::Predict {
            tolerance: Tolerance::Relative(r),
            ..
        }) if r == 0.25
    ));
    for id in ["pid-tune", "trap-triangle", "rrt-300"] {
        assert_eq!(kind(id), Some(Kind::Goal), "{id}");
    }
}

#[test]
fn choices_are_in_range_and_each_has_its_messages() {
    for e in catalog() {
        if let Kind::Choose { choices, right } = e.kind {
            assert!(right < choices && (2..=6).contains(&choices), "{}", e.id);
            assert_eq!(e.choice_ids().len(), choices);
            assert_eq!(
                e.choice_ids()[0],
                (
                    format!("ex-{}-choice-1", e.id),
                    format!("ex-{}-why-1", e.id)
                )
            );
        } else {
            assert!(e.choice_ids().is_empty());
        }
    }
}

#[test]
fn tolerances_include_their_bounds_and_refuse_what_is_not_finite() {
    assert!(Tolerance::Relative(0.25).accepts(1.25, 1.0));
    assert!(!Tolerance::Relative(0.25).accepts(1.2500001, 1.0));
    assert!(Tolerance::Relative(0.25).accepts(-0.8, -1.0));
    assert!(!Tolerance::Relative(0.25).accepts(0.8, -1.0));
    assert!(Tolerance::Absolute(0.5).accepts(2.5, 3.0));
    assert!(!Tolerance::Absolute(0.5).accepts(f64::NAN, 3.0));
    assert!(!Tolerance::Absolute(0.5).accepts(3.0, f64::INFINITY));
}

#[test]
fn checks_refuse_another_pages_model_and_answers_that_do_not_fit() {
    let pid = crate::recipes::pid_step::PidParams::default();
    let model = PageModel::PidStep(&pid);
    let ik = find("ik-singular").unwrap();
    assert_eq!(
        ik.check(&model, Answer::PageState),
        Err(CheckError::OtherPage {
            exercise: "ik-singular",
            page: "pid-step"
        })
    );
    let tune = find("pid-tune").unwrap();
    assert_eq!(
        tune.check(&model, Answer::Number(1.0)),
        Err(CheckError::AnswerDoesNotFit {
            exercise: "pid-tune"
        })
    );
    let p_only = find("pid-p-only").unwrap();
    assert_eq!(
        p_only.check(&model, Answer::Choice(4)),
        Err(CheckError::NoSuchChoice {
            choice: 4,
            choices: 4
        })
    );
    assert!(p_only.check(&model, Answer::PageState).is_err());
    let final_y = find("pid-final-y").unwrap();
    assert!(final_y.check(&model, Answer::Choice(0)).is_err());
    assert!(final_y.truth(&model).is_some_and(|t| t.is_ok()));
    assert!(tune.truth(&model).is_none());
    // A prediction that is not a number is wrong, not an error.
    assert_eq!(
        final_y
            .check(&model, Answer::Number(f64::NAN))
            .map(|v| v.right()),
        Ok(false)
    );
    // The kernel's refusal of the page's state.
    let bad = crate::recipes::pid_step::PidParams {
        kp: f64::NAN,
        ..pid
    };
    assert!(matches!(
        tune.check(&PageModel::PidStep(&bad), Answer::PageState),
        Err(CheckError::Kernel(_))
    ));
}

#[test]
fn every_message_exists_in_both_languages_and_formats_cleanly() {
    use crate::i18n::{FluentArg, I18n, Lang};
    let i18n = I18n::from_sources(&MESSAGE_SOURCES);
    for e in catalog() {
        for id in e.message_ids() {
            for lang in Lang::ALL {
                assert!(i18n.has_message(lang, &id), "{lang:?} {id}");
                let text = i18n.t_args(lang, &id, &[("truth", FluentArg::from("1.5 s"))]);
                assert!(
                    !text.is_empty() && !text.contains('{'),
                    "{lang:?} {id}: {text}"
                );
            }
        }
        // A prediction's explanation shows the truth.
        if matches!(e.kind, Kind::Predict { .. }) {
            for lang in Lang::ALL {
                let text = i18n.t_args(lang, &e.explain_id(), &[("truth", FluentArg::from("<T>"))]);
                assert!(text.contains("<T>"), "{lang:?} {}", e.id);
            }
        }
    }
    assert_eq!(i18n.take_warnings(), Vec::<String>::new());
}

#[test]
fn both_message_files_hold_the_same_ids_and_no_first_load_holds_them() {
    let ids = |text: &str| -> Vec<String> {
        text.lines()
            .filter_map(|line| line.split_once(" = ").map(|(id, _)| id))
            .filter(|id| !id.starts_with(['#', ' ']) && !id.is_empty())
            .map(str::to_owned)
            .collect()
    };
    let (en, ja) = (ids(MESSAGE_SOURCES[0].2), ids(MESSAGE_SOURCES[1].2));
    assert_eq!(en, ja);
    assert!(en.len() > 100);
    assert!(crate::i18n::FILE_NAMES.contains(&MESSAGE_FILE));
    assert!(!crate::i18n::FIRST_FILES.contains(&MESSAGE_FILE));
}

#[test]
fn each_page_module_lists_its_own_exercises_and_model() {
    use crate::recipes::{
        cubic_path::CubicParams, dh_fk::DhParams, pendulum_energy::PendulumParams,
        pid_step::PidParams, rrt_2d::RrtSetup, se3_relative::Se3Params,
        trapezoid_profile::TrapParams, umeyama_2d::UmeyamaSetup,
    };
    let ik = crate::view::ik2r::State::default();
    let (pendulum, pid, trap) = (
        PendulumParams::default(),
        PidParams::default(),
        TrapParams::default(),
    );
    let (rrt, cubic, dh) = (
        RrtSetup::default(),
        CubicParams::default(),
        DhParams::default(),
    );
    let (se3, umeyama) = (Se3Params::default(), UmeyamaSetup::default());
    let sample =
        crate::recipes::traj_resample::parse_trajectory(crate::recipes::traj_resample::SAMPLE)
            .unwrap();
    let arm = crate::teleop::ArmParams::DEFAULT;
    let pages: [(&str, &[Exercise], PageModel); 12] = [
        (ik2r::PAGE, &ik2r::EXERCISES, PageModel::Ik2r(&ik)),
        (dh_fk::PAGE, &dh_fk::EXERCISES, PageModel::DhFk(&dh)),
        (
            se3_relative::PAGE,
            &se3_relative::EXERCISES,
            PageModel::Se3(&se3),
        ),
        (
            umeyama_2d::PAGE,
            &umeyama_2d::EXERCISES,
            PageModel::Umeyama(&umeyama),
        ),
        (
            pendulum::PAGE,
            &pendulum::EXERCISES,
            PageModel::Pendulum(&pendulum),
        ),
        (
            pid_step::PAGE,
            &pid_step::EXERCISES,
            PageModel::PidStep(&pid),
        ),
        (
            cubic_path::PAGE,
            &cubic_path::EXERCISES,
            PageModel::CubicPath(&cubic),
        ),
        (
            trapezoid_profile::PAGE,
            &trapezoid_profile::EXERCISES,
            PageModel::Trapezoid(&trap),
        ),
        (
            traj_resample::PAGE,
            &traj_resample::EXERCISES,
            PageModel::TrajResample(&sample, 0.02),
        ),
        (rrt::PAGE, &rrt::EXERCISES, PageModel::Rrt(&rrt)),
        (
            teleop::PAGE,
            &teleop::EXERCISES,
            PageModel::Teleop {
                arm: &arm,
                q: [0.3, 0.8, 0.0],
            },
        ),
        (
            so101::PAGE,
            &so101::EXERCISES,
            PageModel::So101 { q: [0.0; 5] },
        ),
    ];
    for (page, exercises, model) in pages {
        assert_eq!(model.page(), page);
        assert!(exercises.len() >= 3, "{page}");
        for e in exercises {
            assert_eq!(e.page, page, "{}", e.id);
            // Every check runs on its page's default state without an error.
            let answer = match e.kind {
                Kind::Predict { .. } => Answer::Number(0.0),
                Kind::Goal => Answer::PageState,
                Kind::Choose { .. } => Answer::Choice(0),
            };
            assert!(e.check(&model, answer).is_ok(), "{}", e.id);
        }
    }
    assert_eq!(
        catalog().count(),
        pages.iter().map(|(_, list, _)| list.len()).sum::<usize>()
    );
}
