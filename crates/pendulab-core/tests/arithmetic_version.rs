//! `Arithmetic::version()` pins its bits: for each arithmetic and its current version, a digest of the
//! final states of RATTLE runs (three starts on a sphere of l = 1.3 m, g = 9.81 m/s², 2000 steps of
//! h = 1 ms, where the fused series stops after y³ at every step, and of h = 10 ms, where it does at
//! some steps only) must be the one recorded below for that version. A change to the kernel that
//! changes any bit of an arithmetic's results fails here: then bump that arithmetic's `version()`
//! (records of older results, such as a sweep's manifest, are then refused on resume instead of
//! mixed with the new numbers) and record the new digest under the new version. Both arithmetics give
//! the same bits on every CPU (`tests/rattle_unfused.rs`), so the digests hold on every machine.
//! SI units: \[m\], [m/s], \[s\].

use pendulab_core::integrate::rattle_kernel::Arithmetic;
use pendulab_core::isa;
use pendulab_core::{IdealPendulum, Method, Params, SolveOptions, State, Stepper};

/// (arithmetic, version, FNV-1a digest of the final states' bits) — one row per arithmetic, its
/// current version; the versions before are in `Arithmetic::version`'s history.
const PINNED: [(Arithmetic, u32, u64); 2] =
    [(Arithmetic::Unfused, 1, 0x3878_5550_33bf_41b0), (Arithmetic::Fused, 1, 0xff94_7c69_e077_5f32)];

/// FNV-1a (64 bit) over the bytes of `words`.
fn fnv1a(words: &[u64]) -> u64 {
    let mut hash: u64 = 0xcbf2_9ce4_8422_2325;
    for byte in words.iter().flat_map(|w| w.to_le_bytes()) {
        hash ^= u64::from(byte);
        hash = hash.wrapping_mul(0x0000_0100_0000_01b3);
    }
    hash
}

/// The bits of the final x and v of every run with `arithmetic`.
fn final_bits(arithmetic: Arithmetic) -> Vec<u64> {
    let (l, m, g, steps) = (1.3, 0.7, 9.81, 2000);
    let params = Params::new(l, m, g).unwrap();
    let ideal = IdealPendulum::new(l, m, g).unwrap();
    let mut bits = Vec::new();
    for h in [1e-3, 1e-2] {
        let opts = SolveOptions { method: Method::Rattle, dt: h, ..SolveOptions::default() };
        for (th, ph, thd, phd) in [(1.1, 0.2, 0.3, 1.4), (0.4, 0.0, 0.0, 2.5), (2.7, 1.0, -0.5, 0.3)] {
            let s0 = State::from_angles(&params, th, ph, thd, phd).unwrap();
            let mut st = Stepper::new(ideal, 0.0, s0, &opts).unwrap();
            st.set_arithmetic(arithmetic).unwrap();
            st.step_n(steps).unwrap();
            let s = st.state();
            bits.extend(s.x.to_array().iter().chain(s.v.to_array().iter()).map(|a| a.to_bits()));
        }
    }
    bits
}

/// At the best instruction-set level of this CPU and at the baseline (where the fused arithmetic's
/// `f64::mul_add` is a software fma): the same digest.
#[test]
fn each_arithmetic_gives_the_bits_of_its_version() {
    let digests: Vec<u64> = Arithmetic::ALL.iter().map(|&a| fnv1a(&final_bits(a))).collect();
    isa::set_baseline_only(true);
    let baseline: Vec<u64> = Arithmetic::ALL.iter().map(|&a| fnv1a(&final_bits(a))).collect();
    isa::set_baseline_only(false);
    assert_eq!(digests, baseline, "the best level ({}) and the baseline differ", isa::selected());
    assert_ne!(digests[0], digests[1], "the two arithmetics give other bits (the test's teeth)");
    for (&arithmetic, digest) in Arithmetic::ALL.iter().zip(digests) {
        let &(_, version, pinned) = PINNED.iter().find(|p| p.0 == arithmetic).unwrap();
        assert_eq!(
            arithmetic.version(),
            version,
            "{arithmetic:?}: version() and the pinned version differ; record its digest under the new version"
        );
        assert_eq!(
            digest,
            pinned,
            "the {} arithmetic's bits changed (digest {digest:#018x}, pinned {pinned:#018x} for version \
             {version}): bump Arithmetic::version() for it and pin the new digest here",
            arithmetic.name()
        );
    }
}
