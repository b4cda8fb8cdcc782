#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use super::*;
use crate::recipes::kernel::run_of;
use crate::recipes::testkit::args_strs;

fn parse_err(text: &str) -> RecipeError {
    parse_trajectory(text).unwrap_err()
}

#[test]
fn arg_defaults_are_the_params_defaults() {
    assert_eq!(
        ResampleParams::from_args(&Args::default()).unwrap(),
        ResampleParams::default()
    );
}

#[test]
fn sample_resamples_like_the_recipe() {
    let out = run_of::<Entry>(&Args::default()).unwrap();
    assert_eq!(
        out.summary,
        "wrote labeled synthetic sample: traj_sample_labeled.csv\n\
         resampled 5 -> 28 rows at dt=0.02s -> traj_resampled.csv"
    );
    assert_eq!(out.file(SAMPLE_NAME), Some(SAMPLE));
    let csv = out.file(RESAMPLED_NAME).unwrap();
    assert!(csv.starts_with("t_s,q1,q2\r\n0.000000,0.00000000,0.00000000\r\n"));
    assert!(csv.ends_with("0.540000,0.60666667,0.50666667\r\n"));
}

#[test]
fn reference_runs_are_byte_identical() {
    let out = run_of::<Entry>(&Args::default()).unwrap();
    assert_eq!(
        out.file(RESAMPLED_NAME),
        Some(include_str!(
            "../../../tests/golden/resample_default/traj_resampled.csv"
        ))
    );
    assert_eq!(
        out.file(SAMPLE_NAME),
        Some(include_str!(
            "../../../tests/golden/resample_default/traj_sample_labeled.csv"
        ))
    );
    let input = include_str!("../../../tests/golden/resample_3joint/input.csv");
    let params = ResampleParams {
        csv_path: "input.csv".into(),
        dt: 0.05,
    };
    let out = run_text(&params, input).unwrap();
    assert_eq!(
        out.file(RESAMPLED_NAME),
        Some(include_str!(
            "../../../tests/golden/resample_3joint/traj_resampled.csv"
        ))
    );
    assert_eq!(
        out.summary,
        "resampled 40 -> 79 rows at dt=0.05s -> traj_resampled.csv"
    );
}

#[test]
fn empty_path_means_the_sample_and_unknown_paths_are_named() {
    let args = args_strs::<Entry>(&["", "0.05"]).unwrap();
    assert!(run_of::<Entry>(&args)
        .unwrap()
        .summary
        .contains("resampled 5 -> 12 rows"));
    let args = args_strs::<Entry>(&["mine.csv"]).unwrap();
    assert_eq!(
        run_of::<Entry>(&args).unwrap_err(),
        RecipeError::InputMissing {
            name: "mine.csv".into()
        }
    );
    let args = args.with_inputs(vec![("mine.csv".into(), "t_s,a\n0,1\n1,3\n".into())]);
    let out = run_of::<Entry>(&args).unwrap();
    assert_eq!(
        out.summary,
        "resampled 2 -> 51 rows at dt=0.02s -> traj_resampled.csv"
    );
    assert_eq!(out.files.len(), 1);
}

#[test]
fn bom_crlf_quotes_and_blank_lines() {
    let text = "\u{feff}\"t_s\",\"q,1\",note,q2\r\n\r\n0,\" 1.5 \",\"a \"\"quoted\"\"\nnote\",2\r\n1,2.5,x,4\r\n\r\n";
    let traj = parse_trajectory(text).unwrap();
    assert_eq!(traj.columns, vec!["q,1", "q2"]);
    assert_eq!(traj.t, vec![0.0, 1.0]);
    assert_eq!(traj.q, vec![vec![1.5, 2.5], vec![2.0, 4.0]]);
    // A joint name that needs quoting is quoted in the output, as csv.writer does.
    let out = resample(&traj, 0.5).unwrap().to_csv();
    assert!(out.starts_with("t_s,\"q,1\",q2\r\n"));
    // Lone \r line ends, no trailing newline, underscores like float().
    let traj = parse_trajectory("t_s,q\r0,1_000\r1,2").unwrap();
    assert_eq!(traj.q, vec![vec![1000.0, 2.0]]);
}

#[test]
fn repeated_column_takes_the_last_value_like_dictreader() {
    let traj = parse_trajectory("t_s,q,q\n0,x,1\n1,y,2\n").unwrap();
    assert_eq!(traj.columns, vec!["q"]);
    assert_eq!(traj.q, vec![vec![1.0, 2.0]]);
}

#[test]
fn rejects_missing_time_column() {
    assert_eq!(
        parse_err("time,q1\n0,1\n1,2\n"),
        RecipeError::CsvMissingColumn {
            column: "t_s".into()
        }
    );
}

#[test]
fn rejects_bad_cells_naming_row_and_column() {
    assert_eq!(
        parse_err("t_s,q1,q2\n0,1,2\n0.1,abc,2\n"),
        RecipeError::CsvBadCell {
            row: 3,
            column: "q1".into(),
            value: "abc".into()
        }
    );
    assert_eq!(
        parse_err("t_s,q1\n\n0,1\n0.1,inf\n"),
        RecipeError::CsvBadCell {
            row: 4,
            column: "q1".into(),
            value: "inf".into()
        }
    );
    assert_eq!(
        parse_err("t_s,q1\n0,1\nnan,2\n"),
        RecipeError::CsvBadCell {
            row: 3,
            column: "t_s".into(),
            value: "nan".into()
        }
    );
    assert!(matches!(
        parse_err("t_s,q1\n0,1\n1,\n"),
        RecipeError::CsvBadCell { row: 3, .. }
    ));
}

#[test]
fn rejects_ragged_rows() {
    assert_eq!(
        parse_err("t_s,q1,q2\n0,1,2\n1,2\n"),
        RecipeError::CsvRagged {
            row: 3,
            expected: 3,
            got: 2
        }
    );
    assert_eq!(
        parse_err("t_s,q1\n0,1,9\n"),
        RecipeError::CsvRagged {
            row: 2,
            expected: 2,
            got: 3
        }
    );
}

#[test]
fn rejects_too_few_rows() {
    assert_eq!(
        parse_err("t_s,q1\n0,1\n"),
        RecipeError::CsvTooFewRows { rows: 1, min: 2 }
    );
    assert_eq!(
        parse_err(""),
        RecipeError::CsvTooFewRows { rows: 0, min: 2 }
    );
}

#[test]
fn rejects_time_not_strictly_increasing() {
    assert_eq!(
        parse_err("t_s,q1\n0,1\n0.5,2\n0.5,3\n"),
        RecipeError::CsvTimeNotIncreasing { row: 4 }
    );
    assert_eq!(
        parse_err("t_s,q1\n1,1\n0,2\n"),
        RecipeError::CsvTimeNotIncreasing { row: 3 }
    );
}

#[test]
fn rejects_no_joint_columns() {
    assert_eq!(
        parse_err("t_s,note\n0,a\n1,b\n"),
        RecipeError::CsvNoJointColumns
    );
}

#[test]
fn rejects_unterminated_quote() {
    assert_eq!(
        parse_err("t_s,q1\n0,1\n1,\"2\n"),
        RecipeError::CsvUnterminatedQuote { row: 3 }
    );
}

#[test]
fn rejects_oversized_input_and_output() {
    let text = "t_s,a,b\n0,0,0\n1,0,0\n2,0,0\n3,0,0\n";
    assert!(parse_with_limits(text, 100, 12).is_ok());
    assert_eq!(
        parse_with_limits(text, 20, 12).unwrap_err(),
        RecipeError::InputTooLarge {
            bytes: text.len() as u64,
            limit: 20
        }
    );
    // Stops at the third row; the message counts all four rows of three cells.
    assert_eq!(
        parse_with_limits(text, 100, 8).unwrap_err(),
        RecipeError::TooLarge {
            param: "csv_path".into(),
            count: 12,
            limit: 8,
            also: vec![],
            square: false,
        }
    );
    let traj = parse_trajectory("t_s,a,b\n0,0,0\n100,1,1\n").unwrap();
    assert!(matches!(
        resample(&traj, 1e-5),
        Err(RecipeError::TooLarge {
            count: 20_000_002,
            limit: MAX_OUTPUT_CELLS,
            ..
        })
    ));
    assert!(matches!(
        resample(&traj, 0.0),
        Err(RecipeError::NotPositive { .. })
    ));
}

#[test]
fn interp_matches_numpy_edge_cases() {
    let xp = [0.0, 1.0, 3.0];
    let fp = [0.0, 10.0, 30.0];
    // Exact sample, last sample, outside on both sides, between, NaN.
    let got = interp(&[1.0, 3.0, -1.0, 4.0, 2.0, f64::NAN], &xp, &fp);
    assert_eq!(&got[..5], &[10.0, 30.0, 0.0, 30.0, 20.0]);
    assert!(got[5].is_nan());
    // Unsorted queries give the same as sorted ones.
    assert_eq!(interp(&[2.0, 0.5], &xp, &fp), vec![20.0, 5.0]);
}

#[test]
fn hand_built_trajectory_is_checked() {
    let traj = Trajectory {
        columns: vec!["q1".into()],
        t: vec![0.0, 1.0],
        q: vec![vec![0.0]],
    };
    assert!(matches!(
        resample(&traj, 0.1),
        Err(RecipeError::WrongCount { .. })
    ));
}

/// The bytes of a file as the CLI and the pages read them: decoded, then parsed.
fn read_file(bytes: &[u8]) -> Result<Trajectory, RecipeError> {
    parse_trajectory(&crate::recipes::decode_input("f.csv", bytes)?)
}

#[test]
fn hostile_files_are_named_with_their_place() {
    // A binary file (a PNG's first bytes): its NUL byte, with line and byte.
    let png = b"\x89PNG\r\n\x1a\n\x00\x00\x00\rIHDR";
    assert_eq!(
        read_file(png),
        Err(RecipeError::InputBinary {
            name: "f.csv".into(),
            line: 3,
            column: 1
        })
    );
    // A NUL inside a cell of an otherwise good CSV.
    assert_eq!(
        read_file(b"t_s,q1\n0,1\n0.1,2\x00\n"),
        Err(RecipeError::InputBinary {
            name: "f.csv".into(),
            line: 3,
            column: 6
        })
    );
    // UTF-16 with a byte-order mark, either order.
    let utf16: Vec<u8> = [0xFF, 0xFE]
        .into_iter()
        .chain(
            "t_s,q1\n0,1\n1,2\n"
                .encode_utf16()
                .flat_map(u16::to_le_bytes),
        )
        .collect();
    assert_eq!(
        read_file(&utf16),
        Err(RecipeError::InputUtf16 {
            name: "f.csv".into()
        })
    );
    assert!(matches!(
        read_file(&[0xFE, 0xFF, 0, b't']),
        Err(RecipeError::InputUtf16 { .. })
    ));
    // A UTF-8 byte-order mark is fine.
    assert_eq!(
        read_file(b"\xef\xbb\xbft_s,q1\n0,1\n1,2\n").map(|t| t.len()),
        Ok(2)
    );
    // A header only.
    assert_eq!(
        read_file(b"t_s,q1,q2\n"),
        Err(RecipeError::CsvTooFewRows { rows: 0, min: 2 })
    );
}

#[test]
fn a_million_columns_are_refused_from_the_header() {
    let header: Vec<String> = std::iter::once("t_s".to_string())
        .chain((1..1_000_000).map(|j| format!("q{j}")))
        .collect();
    let text = header.join(",") + "\n";
    assert_eq!(
        parse_err(&text),
        RecipeError::CsvTooManyColumns {
            count: 1_000_000,
            limit: MAX_COLUMNS as u64
        }
    );
    assert!(matches!(
        shape_of(&text),
        Err(RecipeError::CsvTooManyColumns { .. })
    ));
    // At the limit, a file still reads.
    let header: Vec<String> = std::iter::once("t_s".to_string())
        .chain((1..MAX_COLUMNS).map(|j| format!("q{j}")))
        .collect();
    let row = |t: &str| {
        std::iter::once(t)
            .chain(std::iter::repeat_n("0", MAX_COLUMNS - 1))
            .collect::<Vec<_>>()
            .join(",")
    };
    let text = format!("{}\n{}\n{}\n", header.join(","), row("0"), row("1"));
    assert_eq!(
        parse_trajectory(&text).map(|t| t.columns.len()),
        Ok(MAX_COLUMNS - 1)
    );
}

#[test]
fn cr_only_line_ends_read_as_line_ends_and_resample_the_same() {
    let lf = "t_s,q1,q2\n0,0,0\n0.1,0.2,0.1\n0.25,0.5,0.4\n";
    let cr = lf.replace('\n', "\r");
    assert_eq!(parse_trajectory(&cr), parse_trajectory(lf));
    let params = ResampleParams {
        csv_path: "cr.csv".into(),
        dt: 0.05,
    };
    assert_eq!(
        run_text(&params, &cr).map(|o| o.files[0].text.clone()),
        run_text(&params, lf).map(|o| o.files[0].text.clone())
    );
    // A bad cell in a CR-only file names its row.
    assert_eq!(
        parse_err("t_s,q1\r0,1\r0.1,x\r"),
        RecipeError::CsvBadCell {
            row: 3,
            column: "q1".into(),
            value: "x".into()
        }
    );
    assert_eq!(shape_of(&cr).map(|s| s.rows), Ok(3));
}
