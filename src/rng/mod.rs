//! numpy-compatible random numbers: `np.random.default_rng(seed)` = SeedSequence + PCG64,
//! with `random()`, `standard_normal()` and `normal()` bit for bit.
//!
//! - SeedSequence (pool of four 32-bit words, all arithmetic mod 2^32):
//!   `hashmix(v) = { v ^= h; h *= MULT_A; v *= h; v ^ (v >> 16) }` with `h` starting at
//!   `INIT_A` and shared by one mixing; `mix(x, y) = r ^ (r >> 16)` with
//!   `r = MIX_MULT_L x - MIX_MULT_R y`. The state is eight words from the same recipe with
//!   `INIT_B`/`MULT_B`, paired (lo, hi) into four u64.
//! - PCG64 (XSL-RR 128/64): `s <- s * M + inc` (mod 2^128), then
//!   `out = rotr64(hi(s) ^ lo(s), hi(s) >> 58)`.
//! - `random() = (next_u64 >> 11) * 2^-53`.
//! - `standard_normal()`: numpy's 256-layer ziggurat ([`ziggurat_tables`]); the tail and the
//!   wedges use `ln_1p` and `exp`, which come from the platform's libm. They only decide the
//!   rare (< 1 %) rejection cases, so a one-ulp libm difference could only matter there.
//! - `normal(loc, scale) = loc + scale * standard_normal()`.

pub mod ziggurat_tables;

use crate::error::RecipeError;
use ziggurat_tables::{FI_DOUBLE, KI_DOUBLE, WI_DOUBLE, ZIGGURAT_NOR_INV_R, ZIGGURAT_NOR_R};

const INIT_A: u32 = 0x43b0_d7e5;
const MULT_A: u32 = 0x931e_8875;
const INIT_B: u32 = 0x8b51_f9dd;
const MULT_B: u32 = 0x58f3_8ded;
const MIX_MULT_L: u32 = 0xca01_f9dd;
const MIX_MULT_R: u32 = 0x4973_f715;
const XSHIFT: u32 = 16;
const POOL_SIZE: usize = 4;

/// PCG's default 128-bit multiplier (numpy's `PCG64`, not `PCG64DXSM`).
const PCG_MULTIPLIER: u128 = 0x2360_ED05_1FC6_5DA4_4385_DF64_9FCC_F645;

/// The largest seed the recipes accept: `2^63 - 1` (numpy takes any non-negative integer; the
/// command line and the UI keep seeds within a signed 64-bit integer).
pub const SEED_MAX: u64 = i64::MAX as u64;

/// numpy's `SeedSequence(seed).generate_state(4, np.uint64)`: the four words that seed PCG64.
pub fn seed_sequence_state(seed: u64) -> [u64; 4] {
    // The entropy as little-endian 32-bit words, without high zero words ([0] for 0).
    let low = seed as u32;
    let high = (seed >> 32) as u32;
    let entropy: &[u32] = if high == 0 { &[low] } else { &[low, high] };

    let mut hash_const = INIT_A;
    let mut hashmix = |value: u32| -> u32 {
        let mut v = value ^ hash_const;
        hash_const = hash_const.wrapping_mul(MULT_A);
        v = v.wrapping_mul(hash_const);
        v ^ (v >> XSHIFT)
    };
    let mix = |x: u32, y: u32| -> u32 {
        let r = MIX_MULT_L
            .wrapping_mul(x)
            .wrapping_sub(MIX_MULT_R.wrapping_mul(y));
        r ^ (r >> XSHIFT)
    };

    let mut pool = [0u32; POOL_SIZE];
    for (i, word) in pool.iter_mut().enumerate() {
        *word = hashmix(entropy.get(i).copied().unwrap_or(0));
    }
    for src in 0..POOL_SIZE {
        for dst in 0..POOL_SIZE {
            if src != dst {
                let hashed = hashmix(pool[src]);
                pool[dst] = mix(pool[dst], hashed);
            }
        }
    }
    // A u64 seed has at most two words, so the "extra entropy" loop of numpy never runs.

    let mut hash_const = INIT_B;
    let mut words = [0u32; 2 * POOL_SIZE];
    for (k, word) in words.iter_mut().enumerate() {
        let mut d = pool[k % POOL_SIZE] ^ hash_const;
        hash_const = hash_const.wrapping_mul(MULT_B);
        d = d.wrapping_mul(hash_const);
        *word = d ^ (d >> XSHIFT);
    }
    let mut state = [0u64; 4];
    for (k, s) in state.iter_mut().enumerate() {
        *s = u64::from(words[2 * k]) | (u64::from(words[2 * k + 1]) << 32);
    }
    state
}

/// `np.random.default_rng(seed)`: a PCG64 stream seeded through SeedSequence.
///
/// # Example
/// ```
/// use bsv_playground::rng::NumpyRng;
/// let mut rng = NumpyRng::new(0);
/// assert_eq!(rng.random(), 0.6369616873214543); // np.random.default_rng(0).random()
/// ```
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct NumpyRng {
    state: u128,
    increment: u128,
}

impl NumpyRng {
    /// The generator `np.random.default_rng(seed)` returns.
    pub fn new(seed: u64) -> NumpyRng {
        let [s0, s1, s2, s3] = seed_sequence_state(seed);
        let init_state = (u128::from(s0) << 64) | u128::from(s1);
        let init_seq = (u128::from(s2) << 64) | u128::from(s3);
        let mut rng = NumpyRng {
            state: 0,
            increment: (init_seq << 1) | 1,
        };
        rng.step();
        rng.state = rng.state.wrapping_add(init_state);
        rng.step();
        rng
    }

    fn step(&mut self) {
        self.state = self
            .state
            .wrapping_mul(PCG_MULTIPLIER)
            .wrapping_add(self.increment);
    }

    /// The next raw 64-bit output (`bit_generator.random_raw()`).
    pub fn next_u64(&mut self) -> u64 {
        self.step();
        let high = (self.state >> 64) as u64;
        let low = self.state as u64;
        (high ^ low).rotate_right((high >> 58) as u32)
    }

    /// `Generator.random()`: a float in [0, 1) with 53 random bits.
    pub fn random(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * (1.0 / 9_007_199_254_740_992.0)
    }

    /// `Generator.standard_normal()`: numpy's 256-layer ziggurat.
    pub fn standard_normal(&mut self) -> f64 {
        loop {
            let mut r = self.next_u64();
            let layer = (r & 0xff) as usize;
            r >>= 8;
            let negative = r & 1 == 1;
            let rabs = (r >> 1) & 0x000f_ffff_ffff_ffff;
            let mut x = rabs as f64 * WI_DOUBLE[layer];
            if negative {
                x = -x;
            }
            if rabs < KI_DOUBLE[layer] {
                return x; // inside the layer's rectangle: about 99 % of draws
            }
            if layer == 0 {
                // The tail beyond r (Marsaglia's method); numpy uses 1 - U to avoid log(0).
                loop {
                    let xx = -ZIGGURAT_NOR_INV_R * crate::math::log1p(-self.random());
                    let yy = -crate::math::log1p(-self.random());
                    if yy + yy > xx * xx {
                        return if (rabs >> 8) & 1 == 1 {
                            -(ZIGGURAT_NOR_R + xx)
                        } else {
                            ZIGGURAT_NOR_R + xx
                        };
                    }
                }
            }
            // In the wedge: accept under the density, else draw again.
            let f_outer = FI_DOUBLE[layer - 1];
            let f_inner = FI_DOUBLE[layer];
            if (f_outer - f_inner) * self.random() + f_inner < crate::math::exp(-0.5 * x * x) {
                return x;
            }
        }
    }

    /// `Generator.normal(loc, scale)` = `loc + scale * standard_normal()`.
    pub fn normal(&mut self, loc: f64, scale: f64) -> f64 {
        loc + scale * self.standard_normal()
    }
}

/// Checks a recipe's RNG seed: at most [`SEED_MAX`] (`2^63 - 1`).
pub fn check_seed(param: &str, seed: u64) -> Result<u64, RecipeError> {
    if seed <= SEED_MAX {
        Ok(seed)
    } else {
        Err(seed_out_of_range(param, seed as f64))
    }
}

/// Parses a recipe's RNG seed like Python's `int()`, accepting `[0, 2^63)`. Whole numbers
/// outside that range are [`RecipeError::OutOfRange`], anything else
/// [`RecipeError::NotAnInteger`].
pub fn parse_seed(param: &str, text: &str) -> Result<u64, RecipeError> {
    let cleaned = text.trim().replace('_', "");
    match cleaned.parse::<i128>() {
        Ok(value) => match u64::try_from(value) {
            Ok(seed) => check_seed(param, seed),
            Err(_) => Err(seed_out_of_range(param, value as f64)),
        },
        Err(_) => Err(RecipeError::NotAnInteger {
            param: param.to_string(),
            value: text.to_string(),
        }),
    }
}

fn seed_out_of_range(param: &str, value: f64) -> RecipeError {
    RecipeError::OutOfRange {
        param: param.to_string(),
        value,
        min: 0.0,
        max: SEED_MAX as f64,
    }
}

#[cfg(test)]
mod tests {
    // The same tests run natively and, under `wasm-pack test --node`, as wasm.
    #[cfg(target_arch = "wasm32")]
    use wasm_bindgen_test::wasm_bindgen_test as test;

    use super::*;
    use serde_json::Value;

    const VECTORS: &str = include_str!("../../tests/golden/rng/numpy_default_rng_vectors.json");

    /// The JSON text with every fractional number token quoted (`0.5` -> `"0.5"`), so that
    /// the tests parse floats with Rust's exact `str::parse` instead of serde_json's default
    /// parser, which can land one ulp off (it does for `0.10490011715303971`).
    fn quote_floats(json: &str) -> String {
        let mut out = String::with_capacity(json.len() + json.len() / 4);
        let mut in_string = false;
        let mut token = String::new();
        let flush = |token: &mut String, out: &mut String| {
            if token.contains(['.', 'e', 'E']) {
                out.push('"');
                out.push_str(token);
                out.push('"');
            } else {
                out.push_str(token);
            }
            token.clear();
        };
        for c in json.chars() {
            if in_string {
                out.push(c);
                in_string = c != '"';
            } else if c.is_ascii_digit() || matches!(c, '-' | '+' | '.' | 'e' | 'E') {
                token.push(c);
            } else {
                flush(&mut token, &mut out);
                out.push(c);
                in_string = c == '"';
            }
        }
        flush(&mut token, &mut out);
        out
    }

    /// `(seed, case)` for every seed in the numpy vectors file.
    fn cases() -> Vec<(u64, Value)> {
        let all: Value = serde_json::from_str(&quote_floats(VECTORS)).unwrap();
        let map = all.as_object().unwrap();
        assert_eq!(map.len(), 7, "seeds in the vectors file");
        map.iter()
            .map(|(seed, case)| (seed.parse().unwrap(), case.clone()))
            .collect()
    }

    /// The numbers (written as strings) of array `key` of `case`.
    fn parsed<T: std::str::FromStr>(case: &Value, key: &str) -> Vec<T>
    where
        T::Err: std::fmt::Debug,
    {
        case[key]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_str().unwrap().parse().unwrap())
            .collect()
    }

    #[test]
    fn seed_sequence_state_matches_numpy() {
        for (seed, case) in cases() {
            let want = parsed::<u64>(&case, "seedsequence_state_u64x4");
            assert_eq!(seed_sequence_state(seed).to_vec(), want, "seed {seed}");
        }
    }

    #[test]
    fn raw_u64_matches_numpy() {
        for (seed, case) in cases() {
            let want = parsed::<u64>(&case, "pcg64_raw_u64_first4");
            let mut rng = NumpyRng::new(seed);
            let got: Vec<u64> = (0..want.len()).map(|_| rng.next_u64()).collect();
            assert_eq!(got, want, "seed {seed}");
        }
    }

    /// For every seed, the first 8 values of `draw` are numpy's `key` values bit for bit.
    fn assert_first8_bits(key: &str, draw: fn(&mut NumpyRng) -> f64) {
        for (seed, case) in cases() {
            let want = parsed::<f64>(&case, key);
            assert_eq!(want.len(), 8);
            let mut rng = NumpyRng::new(seed);
            for (k, w) in want.iter().enumerate() {
                let got = draw(&mut rng);
                assert_eq!(
                    got.to_bits(),
                    w.to_bits(),
                    "seed {seed} draw {k}: {got} vs {w}"
                );
            }
        }
    }

    #[test]
    fn random_matches_numpy_bit_for_bit() {
        assert_first8_bits("random_first8", NumpyRng::random);
    }

    #[test]
    fn normal_matches_numpy_bit_for_bit() {
        assert_first8_bits("normal_first8", NumpyRng::standard_normal);
        // normal(0, 1) is the same stream.
        for (seed, case) in cases() {
            let want = parsed::<f64>(&case, "normal_first8");
            assert_eq!(NumpyRng::new(seed).normal(0.0, 1.0), want[0]);
        }
    }

    #[test]
    fn ziggurat_tail_and_wedges_stay_normal() {
        // 200k draws exercise the tail (layer 0) and the wedge rejections; the sample moments
        // of N(0, 1) must come out right (mean within 5 standard errors, variance within 2 %).
        let mut rng = NumpyRng::new(42);
        let n = 200_000;
        let (mut sum, mut sum_sq, mut beyond_r) = (0.0, 0.0, 0);
        for _ in 0..n {
            let x = rng.standard_normal();
            sum += x;
            sum_sq += x * x;
            if x.abs() > ZIGGURAT_NOR_R {
                beyond_r += 1;
            }
        }
        let mean = sum / n as f64;
        let var = sum_sq / n as f64 - mean * mean;
        assert!(mean.abs() < 5.0 / (n as f64).sqrt(), "mean {mean}");
        assert!((var - 1.0).abs() < 0.02, "variance {var}");
        // P(|x| > r) = 2.58e-4, so about 52 draws come from the tail.
        assert!((20..100).contains(&beyond_r), "tail draws {beyond_r}");
    }

    #[test]
    fn seeds_outside_the_range_are_rejected() {
        assert_eq!(parse_seed("seed", " 7 ").unwrap(), 7);
        assert_eq!(parse_seed("seed", "9223372036854775807").unwrap(), SEED_MAX);
        assert!(matches!(
            parse_seed("seed", "-1"),
            Err(RecipeError::OutOfRange { .. })
        ));
        assert!(matches!(
            parse_seed("seed", "9223372036854775808"),
            Err(RecipeError::OutOfRange { .. })
        ));
        assert!(matches!(
            parse_seed("seed", "7.5"),
            Err(RecipeError::NotAnInteger { .. })
        ));
        assert!(check_seed("seed", u64::MAX).is_err());
    }
}
