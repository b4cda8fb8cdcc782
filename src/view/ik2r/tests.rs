use super::*;
use crate::view::drag::dist_to_segment;
use crate::view::url::query as q;

#[test]
fn url_round_trip_restores_every_bit() {
    let mut st = State::default();
    st.params.l1 = 0.15;
    st.params.l2 = 0.08;
    st.params.heatmap_n = 128;
    st.params.q1_step = 0.25;
    st.q1 = 0.5123456789012345;
    st.q2 = -1.2;
    st.elbow = Elbow::Up;
    st.show_ws = true;
    st.ws_color = WsColor::Manip;
    let written: Vec<(String, String)> = st
        .query_pairs()
        .into_iter()
        .map(|(k, v)| (k.to_string(), v))
        .collect();
    let (back, ignored) = State::from_query(&written);
    assert_eq!(back, st);
    assert!(ignored.is_empty());
    assert!(written.contains(&("q1".to_string(), "0.5123456789012345".to_string())));
    // The kit's URL contract: read(write(s)) == s, nothing ignored.
    assert_eq!(<State as UrlState>::read(&st.write()), (st, Vec::new()));
    let (_, bad) = <State as UrlState>::read(&q(&[("q1", "zz")]));
    assert_eq!(bad, vec![IgnoredKey::invalid("q1")]);
    let (back, bad) = <State as UrlState>::read(&q(&[("q1", "0.5"), ("q2", "x"), ("zoom", "2")]));
    assert_eq!(back.q1, 0.5);
    assert_eq!(
        bad,
        vec![IgnoredKey::invalid("q2"), IgnoredKey::unknown("zoom")]
    );
}

#[test]
fn url_values_that_fail_are_ignored_and_named() {
    let (st, ignored) = State::from_query(&q(&[
        ("L2", "abc"),
        ("q1", "zz"),
        ("res", "5000"),
        ("elbow", "sideways"),
        ("half_mm", "1"),
        ("step_mm", "0.0001"),
        ("other", "kept for another page"),
    ]));
    let d = State::default();
    assert_eq!(st.params, d.params);
    assert_eq!(st.q1, d.q1);
    for key in ["L2", "q1", "res", "elbow", "half_mm", "step_mm"] {
        assert!(ignored.iter().any(|k| k == key), "{key} in {ignored:?}");
    }
    assert!(!ignored.iter().any(|k| k == "other"));
    // Without `elbow`, q2's sign picks the branch.
    let (up, _) = State::from_query(&q(&[("q2", "-0.5")]));
    assert_eq!(up.elbow, Elbow::Up);
}

/// The kit form's validation of the page's fields, as the page runs it.
fn form_check(values: &[(Field, &str)], changed: Field) -> crate::view::form::Checked<Params> {
    let texts: Vec<Option<String>> = Field::ALL
        .iter()
        .map(|f| {
            values
                .iter()
                .find(|(g, _)| g == f)
                .map(|(_, t)| t.to_string())
        })
        .collect();
    let changed = Field::ALL.iter().position(|f| *f == changed);
    crate::view::form::validate(&form_fields(), &texts, changed, Params::from_texts, |_| {
        None
    })
}

fn at(fields: &[usize]) -> Vec<Field> {
    fields.iter().map(|i| Field::ALL[*i]).collect()
}

#[test]
fn the_form_is_the_recipes_arguments_and_the_heatmap_resolution() {
    for field in Field::ALL {
        assert_eq!(field.spec().name, field.key(), "{field:?}");
        assert_eq!(field.def().label_id, format!("ik2r-field-{}", field.key()));
    }
    assert_eq!(
        Field::L1.spec().max,
        crate::args::Bound::Incl(ik_workspace::LINK_MAX_M)
    );
    assert_eq!(Field::ManipN.spec().hint_id, "recipe-manip-grid-hint-n");
    assert_eq!(Field::HeatmapN.def().inputmode(), "numeric");
    assert_eq!(
        Field::Q1Start.def().inputmode(),
        "text",
        "a negative angle needs a minus"
    );
    let p = Params::default();
    let texts: Vec<Option<String>> = p.texts().into_iter().map(Some).collect();
    assert_eq!(Params::from_texts(&texts), Ok(p));
    assert_eq!(Params::from_texts(&[]), Ok(p), "no text: the defaults");
    let missing = crate::view::field::missing_messages(&form_fields());
    assert_eq!(missing, Vec::<String>::new());
}

#[test]
fn a_cross_field_limit_marks_every_field_it_involves() {
    // 2·1000/10 + 1 = 201 cells per axis is fine; 2·1000/1 + 1 = 2001 is not.
    let ok = form_check(&[(Field::HalfMm, "1000")], Field::HalfMm);
    assert_eq!(ok.value.map(|p| p.half_mm), Some(1000.0));
    let refused = form_check(
        &[(Field::HalfMm, "1000"), (Field::StepMm, "1")],
        Field::StepMm,
    );
    assert!(refused.value.is_none());
    assert_eq!(at(&refused.marked), vec![Field::HalfMm, Field::StepMm]);
    assert_eq!(
        at(&[refused.messages[0].0]),
        vec![Field::StepMm],
        "on the field changed"
    );
    let refused = form_check(
        &[(Field::HalfMm, "1000"), (Field::StepMm, "1")],
        Field::HalfMm,
    );
    assert_eq!(at(&[refused.messages[0].0]), vec![Field::HalfMm]);
    // A field's own limit: that field only; a blank field is not a number.
    let refused = form_check(&[(Field::L2, "-1")], Field::L2);
    assert_eq!(at(&refused.marked), vec![Field::L2]);
    assert!(matches!(
        refused.messages[0].1,
        RecipeError::OutOfRange { .. }
    ));
    let blank = form_check(&[(Field::L2, "")], Field::L2);
    assert!(
        matches!(blank.messages[..], [(1, RecipeError::NotANumber { .. })]),
        "{blank:?}"
    );
    let res = form_check(&[(Field::HeatmapN, "2000")], Field::HeatmapN);
    assert!(matches!(res.messages[0].1, RecipeError::OutOfRange { max, .. } if max == 1024.0));
    // Whole numbers in any notation.
    let n = form_check(
        &[(Field::ManipN, "1e2"), (Field::HeatmapN, "128.0")],
        Field::ManipN,
    );
    assert_eq!(n.value.map(|p| (p.manip_n, p.heatmap_n)), Some((100, 128)));
    assert_eq!(
        form_check(&[(Field::L2, "0.08")], Field::L2)
            .value
            .map(|p| p.l2),
        Some(0.08)
    );
}

#[test]
fn view_transform_round_trips_and_puts_y_up() {
    let xf = ViewXf::fit(800.0, 600.0, 0.25);
    assert_eq!(xf.origin(), DVec2::new(400.0, 300.0));
    assert_eq!(xf.px_per_m, (300.0 - 6.0) / 0.25);
    let p = xf.screen(0.1, 0.05);
    assert!(p.y < 300.0 && p.x > 400.0);
    let w = xf.world(p);
    assert!((w.x - 0.1).abs() < 1e-15 && (w.y - 0.05).abs() < 1e-15);
    assert_eq!(extent_m(&Arm { l1: 0.12, l2: 0.1 }, None), 0.22 * 1.08);
    // The workspace widens the view, but to at most three reaches.
    assert_eq!(
        extent_m(&Arm { l1: 0.12, l2: 0.1 }, Some(10.0)),
        0.66 * 1.08
    );
    assert_eq!(grid_step_mm(0.2376), 50.0);
    assert_eq!(format_mm(-150.0), "-150");
    assert_eq!(format_mm(2.5), "2.5");
}

#[test]
fn hit_tests_find_tip_elbow_and_links() {
    let arm = Arm { l1: 0.12, l2: 0.1 };
    let xf = ViewXf::fit(800.0, 800.0, 0.24);
    let (q1, q2) = (0.3, 0.8);
    let [base, elbow, tip] = joints_on_screen(&xf, &arm, q1, q2);
    let hit = |p: DVec2, touch| hit_test(&xf, &arm, q1, q2, p, touch);
    assert_eq!(hit(tip + DVec2::new(10.0, 5.0), false), Grab::Tip);
    assert_eq!(hit(elbow + DVec2::new(3.0, -4.0), false), Grab::Q1);
    assert_eq!(hit((elbow + tip) / 2.0, false), Grab::Q2);
    assert_eq!(hit((base + elbow) / 2.0, false), Grab::Q1);
    // Empty space: the tip (a click anywhere moves the arm), but no part for a finger.
    let empty = base + DVec2::new(-200.0, 200.0);
    assert_eq!(hit(empty, false), Grab::Tip);
    assert_eq!(part_at(&xf, &arm, q1, q2, empty, true), None);
    // A finger gets a wider tip: 20 px away is the tip for touch, nothing for the mouse
    // (20 px from the tip is also off link 2's 11 px capsule in this direction).
    let away = tip + (tip - elbow).normalize() * 20.0;
    assert_eq!(part_at(&xf, &arm, q1, q2, away, true), Some(Grab::Tip));
    assert_eq!(part_at(&xf, &arm, q1, q2, away, false), None);
}

#[test]
fn link_labels_do_not_overlap_when_the_arm_is_folded() {
    let arm = Arm { l1: 0.12, l2: 0.1 };
    let xf = ViewXf::fit(800.0, 800.0, 0.24);
    for q2 in [3.1, -3.1, PI, 2.9] {
        let [b, e, t] = joints_on_screen(&xf, &arm, 0.3, q2);
        let [l1, l2] = link_label_centres(b, e, t, 14.0);
        // Two 20 × 16 px labels: their centres must be further apart than that.
        let d = l1 - l2;
        assert!(
            d.x.abs() > 20.0 || d.y.abs() > 16.0,
            "q2 = {q2}: {l1} vs {l2}"
        );
        // Each label stays beside its own link.
        assert!((dist_to_segment(l1, b, e) - 14.0).abs() < 1e-9);
        assert!((dist_to_segment(l2, e, t) - 14.0).abs() < 1e-9);
    }
    // Bent: both labels outside the bend (away from the other link's side).
    let [b, e, t] = joints_on_screen(&xf, &arm, 0.0, 1.2);
    let [l1, _] = link_label_centres(b, e, t, 14.0);
    assert!(l1.y > b.y, "link 1 along +x, bend upwards: label below it");
}

#[test]
fn heat_fill_is_l1_l2_abs_sin_q2_on_the_recipe_grid() {
    let arm = Arm { l1: 0.12, l2: 0.1 };
    let n = 64;
    let mut values = Vec::new();
    let top = heat_fill(&arm, n, &mut values).expect("valid grid");
    assert_eq!(top, 0.12 * 0.1);
    assert_eq!(values.len(), n * n);
    let axis = heat_axis(n);
    for (i, j) in [(0, 0), (10, 20), (63, 31), (40, 48)] {
        let want = (0.12 * 0.1 * axis.node(j).sin()).abs();
        let got = f64::from(values[i * n + j]);
        assert!((got - want).abs() < 1e-7, "({i}, {j}): {got} vs {want}");
    }
    // The singular rows q2 = ±π are (nearly) zero; n is clamped to 2 at least.
    assert!(values[n - 1] < 1e-9);
    assert!(heat_fill(&arm, 1, &mut values).is_ok());
    assert_eq!(values.len(), 4);
}

#[test]
fn sweep_points_follow_the_recipe_range() {
    let p = Params::default();
    let pts = sweep_points(&p, 0.8);
    // arange(0, 1.57 + 1e-12, 0.1): 16 rows.
    assert_eq!(pts.len(), 16);
    assert_eq!(pts[0].q1, 0.0);
    let w = 0.12 * 0.1 * 0.8f64.sin();
    assert!(pts.iter().all(|s| (s.manipulability - w).abs() < 1e-15));
    let [x, top, bottom] = sweep_ranges(&p);
    assert_eq!(x, (0.0, 1.57));
    assert!(top.1 > w && top.0 == -top.1 && bottom.0 == 0.0);
    // A long sweep is thinned to SWEEP_PLOT_MAX (+ the last row).
    let long = Params { q1_step: 1e-5, ..p };
    let pts = sweep_points(&long, 0.8);
    assert!(pts.len() <= SWEEP_PLOT_MAX + 1);
    assert!((pts.last().map_or(0.0, |s| s.q1) - 1.57).abs() < 1e-4);
    assert_eq!(
        marker_in_range(0.3 + std::f64::consts::TAU, x),
        Some(0.3 + std::f64::consts::TAU - std::f64::consts::TAU)
    );
    assert_eq!(marker_in_range(-1.0, x), None);
}

#[test]
fn readouts_and_summary_texts() {
    let rep = Arm { l1: 0.12, l2: 0.1 }.report(0.3, 0.8);
    let v = readout_values(&rep);
    assert_eq!(v[0], "0.300000");
    assert_eq!(v[2], "17.189");
    assert_eq!(fmt_fixed(-0.0001, 3), "0.000");
    assert_eq!(fmt_sig(1.23456789e-6, 3), "1.23e-6");
    let s = PoseSummary::of(&rep, false);
    assert_eq!((s.q1_deg.as_str(), s.q2_deg.as_str()), ("17", "46"));
    assert_eq!(s.w, fmt_sig(rep.manipulability, 3));
    assert_eq!(s.args().len(), 5);
}

#[test]
fn exports_match_the_cli_arguments() {
    let p = Params::default();
    let (py, bsv) = export_commands(&EXPORTS[0], &p, 0.8);
    assert_eq!(bsv, "bsv ik-workspace 0.12 0.1 200 10");
    assert_eq!(py, "python planar_ik_workspace.py 0.12 0.1 200 10");
    assert_eq!(
        export_commands(&EXPORTS[1], &p, -1.2).1,
        "bsv jacobian-2r 0.12 0.1 0 1.57 0.1 -1.2"
    );
    let csv = export_csv(&EXPORTS[2], &Params { manip_n: 3, ..p }, 0.8).expect("csv");
    assert_eq!(csv.split("\r\n").filter(|l| !l.is_empty()).count(), 1 + 9);
    let wrong = Export {
        file: "nope.csv",
        ..EXPORTS[2]
    };
    assert_eq!(
        export_csv(&wrong, &p, 0.8),
        Err(ExportError::MissingFile {
            recipe: "manip-grid",
            file: "nope.csv"
        })
    );
}
