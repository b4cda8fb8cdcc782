//! The Robot Pilot simulation gives the same bits natively and in wasm: fixed command streams
//! (the scripted pilot on each task, with latency, input noise and every IK method) hash to
//! constants computed natively. The same test runs under `cargo test` and
//! `wasm-pack test --node`, so a libm or float difference in either shows as a changed hash.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use bsv_playground::teleop::pilot::{fly, plan};
use bsv_playground::teleop::{ControlParams, Episode, IkMethod, SceneConfig, Task};

/// FNV-1a over 64-bit words.
struct Fnv(u64);

impl Fnv {
    fn word(&mut self, w: u64) {
        for b in w.to_le_bytes() {
            self.0 ^= u64::from(b);
            self.0 = self.0.wrapping_mul(0x100_0000_01b3);
        }
    }
    fn f(&mut self, v: f64) {
        self.word(v.to_bits());
    }
}

/// Every number, flag and event of every record, bit for bit.
fn hash(episode: &Episode) -> u64 {
    let mut h = Fnv(0xcbf2_9ce4_8422_2325);
    for r in &episode.records {
        h.word(r.step);
        for v in [
            r.t_s,
            r.cmd.dx,
            r.cmd.dz,
            r.cmd.dphi,
            r.applied.dx,
            r.applied.dz,
            r.applied.dphi,
            r.q[0],
            r.q[1],
            r.q[2],
            r.x,
            r.z,
            r.phi,
            r.block_x,
            r.block_z,
            r.manipulability,
        ] {
            h.f(v);
        }
        h.word(u64::from(r.cmd.gripper_closed) | u64::from(r.applied.gripper_closed) << 1);
        h.word(u64::from(r.gripper_closed) | u64::from(r.held) << 1);
        for e in &r.events {
            for b in e.text().bytes() {
                h.word(u64::from(b));
            }
        }
    }
    h.0
}

fn scenario(task: &str, method: IkMethod, latency_steps: u32, noise_sigma: f64) -> Episode {
    let config = SceneConfig {
        task: Task::from_id(task).unwrap(),
        control: ControlParams {
            method,
            ..ControlParams::DEFAULT
        },
        latency_steps,
        noise_sigma,
        noise_seed: 2026,
        ..SceneConfig::default()
    };
    fly(config.clone(), plan(&config), 6000).unwrap()
}

#[test]
fn fixed_command_streams_give_the_same_bits_natively_and_in_wasm() {
    let got = [
        hash(&scenario("pick-place", IkMethod::Dls, 0, 0.0)),
        hash(&scenario("pick-place-obstacle", IkMethod::Pinv, 5, 0.1)),
        hash(&scenario("reach", IkMethod::AdaptiveDls, 12, 0.3)),
        hash(&scenario("reach", IkMethod::Trans, 0, 0.05)),
    ];
    assert_eq!(got, EXPECTED);
}

/// Computed natively (x86-64 Linux) with the test above.
const EXPECTED: [u64; 4] = [
    0xab81_6026_4c68_92ba,
    0x6c0a_19bd_eaa7_2680,
    0x50d2_eb82_fc37_4c8a,
    0xc24a_4d9f_c69b_95ce,
];
