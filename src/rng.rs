//! numpy-compatible random numbers: `default_rng(seed)` = SeedSequence + PCG64, with
//! `random()` and `normal()` bit for bit. PLACEHOLDER until the kernel lands.
