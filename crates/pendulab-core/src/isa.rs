//! Run-time choice of the instruction set for the hot loops (no physics here).
//!
//! The crate is compiled for the baseline of its target (x86-64: SSE2; aarch64: NEON, FMA), so that
//! one build runs on every CPU of that architecture. The loops where the time goes — the step and
//! step-loop bodies of [`crate::Stepper`] (every method; DOP853's stages and dense output included),
//! the ensemble blocks of [`crate::ensemble`], the string stepper's steps, and the exact solution's
//! states ([`crate::exact::ExactSolution::state_and_azimuth`] and the batches of `states_at`, with the
//! Jacobi functions, F, Π and Carlson's R_F, R_J, R_C inlined) — run their body through [`fastest`],
//! which compiles it once more for each of these x86-64 levels and picks the best one the CPU has,
//! once per process:
//!
//! | level | instructions | CPUs (roughly) |
//! |---|---|---|
//! | `x86-64-v4` | AVX-512 F/BW/CD/DQ/VL, AVX2, FMA | Intel Skylake-SP and later AVX-512 parts, AMD since Zen 4 |
//! | `x86-64-v3` | AVX2, FMA, BMI1/2, F16C, LZCNT, MOVBE | Intel since Haswell (2013), AMD since Excavator / Zen |
//! | baseline | what the build targets (SSE2 on x86-64) | everything else, and every non-x86 CPU |
//!
//! **The numbers do not depend on the choice.** Rust never contracts a·b + c into a fused
//! multiply-add by itself, and the hot kernels contain none: the RATTLE kernel's multiply-adds
//! (`integrate::rattle_kernel::fmadd`, shared with the ensemble) are plain a·b + c with two roundings
//! (decided with measurements in docs/performance.md, "No CPU left behind": a fused operation is one
//! instruction only where the CPU has FMA, and an exact software routine, about 13 ns a call,
//! on older x86-64 CPUs and in WebAssembly, which made those 3–20× slower; the opt-in
//! `rattle_kernel::Arithmetic::Fused` uses it, with the same bits at every level too). + − × ÷ and √ are
//! correctly rounded on every CPU, so every level computes the same bits; wider vectors only change
//! how many lanes one instruction handles, never an operation's rounding. `f64::round` (a C library
//! call at the SSE2 baseline) is written as [`round`], the same function in a few additions and
//! comparisons. Where an exact product is needed (the range reductions of the exact solution,
//! `elliptic::jacobi`, `exact::planar`, `exact::generic`), `f64::mul_add` is kept: correctly rounded
//! everywhere, a few calls per exact state. The C library's `sin`, `atan2`, … are called at every
//! level alike. So a trajectory or an exact state gets the same bits at every level, the ensemble and
//! the single-trajectory path agree bit for bit whichever level each ran at, `tests/isa.rs` checks
//! all of them against [`set_baseline_only`] (and, on an AVX-512 CPU, at x86-64-v3 through
//! [`set_max_level`]), and `tests/rattle_unfused.rs` checks RATTLE and the ensemble against a step
//! written out with explicit unfused arithmetic.
//!
//! The clones are `#[target_feature]` copies of the work, one per level, chosen by a feature test
//! cached on first use — what the `multiversion` crate generates, written out here so that
//! [`set_max_level`] can choose a lower level than the CPU's best at run time (to measure, on this
//! AVX-512 machine, what an AVX2-only CPU runs), and so that code inside the work can ask which level
//! it runs at ([`current`]: the ensemble picks its tile width by it).
//!
//! On other architectures (aarch64: FMA is part of the baseline) the targets above do not apply and
//! [`fastest`] runs its work as compiled; nothing here is x86-specific outside
//! `cfg(target_arch = "x86_64")` (`make check-aarch64` type-checks the crate for aarch64).

use std::sync::atomic::{AtomicU8, Ordering};

/// An instruction-set level of the hot loops (module doc), ordered from the narrowest to the widest.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Level {
    /// What the build targets (SSE2 on x86-64; every level on other architectures).
    Baseline = 0,
    /// `x86-64-v3`: AVX2, FMA, BMI1/2, F16C, LZCNT, MOVBE.
    V3 = 1,
    /// `x86-64-v4`: AVX-512 F/BW/CD/DQ/VL on top of v3.
    V4 = 2,
}

impl Level {
    /// The level's name as [`selected`] gives it: `"baseline"`, `"x86-64-v3"` or `"x86-64-v4"`.
    pub fn name(self) -> &'static str {
        match self {
            Level::Baseline => "baseline",
            Level::V3 => "x86-64-v3",
            Level::V4 => "x86-64-v4",
        }
    }

    fn from_u8(k: u8) -> Self {
        match k {
            0 => Level::Baseline,
            1 => Level::V3,
            _ => Level::V4,
        }
    }
}

/// The highest level [`fastest`] may use (set by [`set_max_level`] / [`set_baseline_only`], for
/// tests comparing the levels, benchmarks of the narrower levels on a wider CPU, and users who want
/// to rule the wider instructions out).
static MAX_LEVEL: AtomicU8 = AtomicU8::new(Level::V4 as u8);

/// The best level of this CPU, detected once (`u8::MAX`: not yet).
static DETECTED: AtomicU8 = AtomicU8::new(u8::MAX);

/// The best level of this CPU (the features of each level's clone below, as the `multiversion`
/// crate would test them), detected on the first call and cached.
#[inline(always)]
pub fn detected() -> Level {
    let k = DETECTED.load(Ordering::Relaxed);
    if k != u8::MAX {
        return Level::from_u8(k);
    }
    let level = detect();
    DETECTED.store(level as u8, Ordering::Relaxed);
    level
}

#[cold]
fn detect() -> Level {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::is_x86_feature_detected as has;
        let v3 = has!("avx2")
            && has!("avx")
            && has!("fma")
            && has!("bmi1")
            && has!("bmi2")
            && has!("f16c")
            && has!("lzcnt")
            && has!("movbe")
            && has!("popcnt")
            && has!("sse4.2");
        let v4 =
            has!("avx512f") && has!("avx512bw") && has!("avx512cd") && has!("avx512dq") && has!("avx512vl");
        if v3 && v4 {
            return Level::V4;
        }
        if v3 {
            return Level::V3;
        }
    }
    Level::Baseline
}

/// The level [`fastest`] runs at now: the CPU's best, capped by [`set_max_level`].
#[inline(always)]
pub fn current() -> Level {
    detected().min(Level::from_u8(MAX_LEVEL.load(Ordering::Relaxed)))
}

/// Runs `work` compiled for the best instruction-set level of this CPU (module doc), at most the
/// level set by [`set_max_level`].
///
/// `work` must be an `#[inline(always)]` closure, and what it calls on the hot path
/// `#[inline(always)]` too: only code inlined into the chosen clone is compiled for its level
/// (a function the compiler keeps out of line runs at the baseline, correct but slower).
/// The clones are what the `multiversion` crate generates (a `#[target_feature]` copy per level,
/// chosen by a cached feature test), written out so that a lower level can be chosen at run time.
#[inline(always)]
pub fn fastest<R>(work: impl FnOnce() -> R) -> R {
    #[cfg(target_arch = "x86_64")]
    {
        match current() {
            // SAFETY: `current` is at most `detected`: the CPU has every feature of the clone.
            Level::V4 => return unsafe { on_v4(work) },
            // SAFETY: as above.
            Level::V3 => return unsafe { on_v3(work) },
            Level::Baseline => {}
        }
    }
    work()
}

/// `work` compiled for x86-64-v4 (as `multiversion`'s clone for the same target string).
///
/// # Safety
/// The CPU must have every enabled feature.
#[cfg(target_arch = "x86_64")]
#[target_feature(
    enable = "avx512f,avx512bw,avx512cd,avx512dq,avx512vl,avx2,avx,fma,bmi1,bmi2,f16c,lzcnt,movbe,popcnt,sse4.2"
)]
unsafe fn on_v4<R, F: FnOnce() -> R>(work: F) -> R {
    align_frame();
    work()
}

/// `work` compiled for x86-64-v3.
///
/// # Safety
/// The CPU must have every enabled feature.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,avx,fma,bmi1,bmi2,f16c,lzcnt,movbe,popcnt,sse4.2")]
unsafe fn on_v3<R, F: FnOnce() -> R>(work: F) -> R {
    align_frame();
    work()
}

/// Makes the calling clone align its stack frame to a cache line (64 bytes), so that the vector
/// registers it spills (AVX-512: 64 bytes, AVX2: 32) never straddle two lines. Without it the
/// frame is only 16-byte aligned and the spill slots' alignment follows the callers' stack depth:
/// the ensemble's 16-lane tiles (which spill, `ensemble/tile.rs`) ran 20–35 % slower in some frames
/// than in others — one worker of the same run slower than the other, and a change anywhere in the
/// callers moving the speed by 5–15 % (docs/performance.md, "The frame's alignment"). A 64-byte
/// aligned local that escapes makes LLVM realign the frame (one `and` of the stack pointer per call
/// of the clone) and give the spill slots their natural alignment.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn align_frame() {
    #[repr(align(64))]
    struct CacheLine(#[allow(dead_code)] [u8; 64]);
    let mut line = CacheLine([0; 64]);
    std::hint::black_box(&mut line);
}

/// x rounded to the nearest integer, halfway cases away from zero: the same number as
/// [`f64::round`] for every input (±0, halves, |x| ≥ 2⁵², ±∞ and NaN included), but written with
/// additions and comparisons only, so that it stays a few inline instructions at the x86-64
/// baseline, where `f64::round` is a call into the C library (SSE2 has no rounding instruction;
/// SSE4.1's `roundsd` is what the dispatched levels would use).
///
/// For |x| < 2⁵²: (|x| + 2⁵²) − 2⁵² is |x| rounded to an integer (ties to even, both operations
/// exact but the first's rounding), one less where that went up gives ⌊|x|⌋, and |x| − ⌊|x|⌋ is exact,
/// so the half-way test is exact.
#[inline(always)]
pub fn round(x: f64) -> f64 {
    const TWO_52: f64 = 4503599627370496.0;
    let a = x.abs();
    if a >= TWO_52 || a.is_nan() {
        return x; // already an integer, or ±∞, or NaN
    }
    let r = (a + TWO_52) - TWO_52;
    let floor = if r > a { r - 1.0 } else { r };
    let up = if a - floor >= 0.5 { floor + 1.0 } else { floor };
    up.copysign(x)
}

/// The level [`fastest`] runs at now: `"x86-64-v4"`, `"x86-64-v3"` or `"baseline"`.
pub fn selected() -> &'static str {
    current().name()
}

/// Whether a fused multiply-add is one instruction where [`fastest`] runs: at x86-64-v3 and v4 (FMA)
/// and on every aarch64 CPU; not at the x86-64 baseline (SSE2: `f64::mul_add` is an exact software
/// routine there, 3–25× slower) nor in WebAssembly. The Python API's `arithmetic="auto"` (its
/// default) runs the RATTLE family fused where this is true and unfused elsewhere.
pub fn fused_is_fast() -> bool {
    cfg!(target_arch = "aarch64") || selected() != "baseline"
}

/// Caps [`fastest`] at `level` (or the CPU's best, when lower), process-wide, for the calls that
/// start after it: `set_max_level(Level::V3)` runs the AVX2 loops on an AVX-512 CPU (to measure what
/// an AVX2-only CPU runs), `Level::V4` lifts the cap.
pub fn set_max_level(level: Level) {
    MAX_LEVEL.store(level as u8, Ordering::Relaxed);
}

/// Restricts (`true`) [`fastest`] to the baseline level, or lifts every cap (`false`), process-wide,
/// for the calls that start after it (`set_max_level(Level::Baseline)` / `(Level::V4)`).
pub fn set_baseline_only(on: bool) {
    set_max_level(if on { Level::Baseline } else { Level::V4 });
}

#[cfg(test)]
mod tests {
    use super::round;

    /// `round` is `f64::round` bit for bit: halves on both sides of every sign, the neighbours of
    /// halves, signed zeros, the ends of the exact range 2⁵², infinities, NaN, and a sweep of
    /// magnitudes from 1e-300 to 1e300.
    #[test]
    fn round_is_f64_round_bit_for_bit() {
        let mut xs = vec![0.0, -0.0, 0.5, -0.5, 1.5, 2.5, -2.5, 0.49999999999999994, 4503599627370495.5];
        xs.extend([4503599627370496.0, 4503599627370497.0, 9007199254740993.0, 1e300, f64::MAX]);
        xs.extend([f64::MIN_POSITIVE, 5e-324, f64::INFINITY, f64::NAN, 1.0 - f64::EPSILON / 2.0]);
        for k in -2000..2000 {
            let h = k as f64 + 0.5;
            xs.extend([
                h,
                h.next_up(),
                h.next_down(),
                k as f64,
                (k as f64).next_up(),
                (k as f64).next_down(),
            ]);
        }
        let mut x = 1e-300f64;
        while x < 1e300 {
            xs.extend([x, -x, x * 0.7371, -x * 1.3333]);
            x *= 1.0137;
        }
        for &x in &xs {
            for x in [x, -x] {
                assert_eq!(round(x).to_bits(), x.round().to_bits(), "round({x:e})");
            }
        }
    }
}
