//! Every reference run in `tests/golden/` (copied from `shared/golden/`) reproduced: headers
//! and row counts exact, numbers within 1e-9 relative, the summary line identical. The same
//! body runs natively (`cargo test`) and under `wasm-pack test --node` through `runRecipe`.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

mod common;
use common::{assert_csv_close, run, stdout};

macro_rules! golden {
    ($name:ident, $dir:literal, $id:literal, [$($arg:literal),*], inputs [$($input:literal),*], files [$($file:literal),+], summary $summary:expr) => {
        #[test]
        fn $name() {
            let inputs: &[(&str, &str)] = &[$(($input, include_str!(concat!("golden/", $dir, "/", $input)))),*];
            let out = run($id, &[$($arg),*], inputs).unwrap_or_else(|e| panic!("{}: {e}", $dir));
            $(
                assert_csv_close(
                    concat!($dir, "/", $file),
                    include_str!(concat!("golden/", $dir, "/", $file)),
                    out.file($file),
                );
            )+
            let summary: Option<&str> = $summary;
            if let Some(want) = summary {
                assert_eq!(out.summary, stdout(want), "{} summary", $dir);
            }
        }
    };
}

macro_rules! stdout_of {
    ($dir:literal) => {
        Some(include_str!(concat!("golden/", $dir, "/stdout.txt")))
    };
}

golden!(pendulum_default, "pendulum_default", "pendulum-energy", [], inputs [], files ["pendulum_energy.csv"], summary stdout_of!("pendulum_default"));
golden!(pendulum_2s, "pendulum_2s", "pendulum-energy", ["2"], inputs [], files ["pendulum_energy.csv"], summary stdout_of!("pendulum_2s"));
golden!(pend_undamped_euler, "pend_undamped_euler", "pendulum-energy", ["5", "--damping", "0", "--integrator", "euler"], inputs [], files ["pendulum_energy.csv"], summary None);
golden!(pend_undamped_rk4, "pend_undamped_rk4", "pendulum-energy", ["5", "--damping", "0", "--integrator", "rk4"], inputs [], files ["pendulum_energy.csv"], summary None);
golden!(ik_default, "ik_default", "ik-workspace", [], inputs [], files ["ik_workspace.csv"], summary stdout_of!("ik_default"));
golden!(ik_fine, "ik_fine", "ik-workspace", ["0.2", "0.15", "400", "5"], inputs [], files ["ik_workspace.csv"], summary stdout_of!("ik_fine"));
golden!(resample_default, "resample_default", "traj-resample", [], inputs [], files ["traj_resampled.csv", "traj_sample_labeled.csv"], summary stdout_of!("resample_default"));
golden!(resample_3joint, "resample_3joint", "traj-resample", ["input.csv", "0.05"], inputs ["input.csv"], files ["traj_resampled.csv"], summary stdout_of!("resample_3joint"));
golden!(dh_default, "dh_default", "dh-fk", [], inputs [], files ["dh_fk.csv"], summary stdout_of!("dh_default"));
golden!(dh_other, "dh_other", "dh-fk", ["1.0,-0.5,2.0"], inputs [], files ["dh_fk.csv"], summary stdout_of!("dh_other"));
golden!(jacobian_default, "jacobian_default", "jacobian-2r", [], inputs [], files ["jacobian_2r.csv"], summary stdout_of!("jacobian_default"));
golden!(cubic_default, "cubic_default", "cubic-path", [], inputs [], files ["cubic_path.csv"], summary stdout_of!("cubic_default"));
golden!(se3_default, "se3_default", "se3-relative", [], inputs [], files ["se3_relative.csv"], summary stdout_of!("se3_default"));
golden!(rrt_default, "rrt_default", "rrt-2d", [], inputs [], files ["rrt_path.csv", "rrt_nodes.csv"], summary stdout_of!("rrt_default"));
golden!(rrt_seed42, "rrt_seed42", "rrt-2d", ["42", "800"], inputs [], files ["rrt_path.csv", "rrt_nodes.csv"], summary stdout_of!("rrt_seed42"));
golden!(pid_default, "pid_default", "pid-step", [], inputs [], files ["pid_step.csv"], summary stdout_of!("pid_default"));
golden!(manip_default, "manip_default", "manip-grid", [], inputs [], files ["manip_ellipse.csv"], summary stdout_of!("manip_default"));
golden!(trap_default, "trap_default", "trapezoid-profile", [], inputs [], files ["trap_profile.csv"], summary stdout_of!("trap_default"));
golden!(trap_triangle, "trap_triangle", "trapezoid-profile", ["0.2", "1.0", "2.0", "0.005"], inputs [], files ["trap_profile.csv"], summary stdout_of!("trap_triangle"));
golden!(umeyama_default, "umeyama_default", "umeyama-2d", [], inputs [], files ["umeyama_2d.csv"], summary stdout_of!("umeyama_default"));
