//! Run-time choice of the instruction set for the hot loops (no physics here).
//!
//! The crate is compiled for the baseline of its target (x86-64: SSE2; aarch64: NEON, FMA), so that
//! one build runs on every CPU of that architecture. The loops where the time goes — the step and
//! step-loop bodies of [`crate::Stepper`] (every method), the ensemble blocks of [`crate::ensemble`]
//! and the string stepper's steps — run their body through [`fastest`], which compiles it once more for each
//! of these x86-64 levels and picks the best one the CPU has, once per process:
//!
//! | level | instructions | CPUs (roughly) |
//! |---|---|---|
//! | `x86-64-v4` | AVX-512 F/BW/CD/DQ/VL, AVX2, FMA | Intel Skylake-SP and later AVX-512 parts, AMD since Zen 4 |
//! | `x86-64-v3` | AVX2, FMA, BMI1/2, F16C, LZCNT, MOVBE | Intel since Haswell (2013), AMD since Excavator / Zen |
//! | baseline | what the build targets (SSE2 on x86-64) | everything else, and every non-x86 CPU |
//!
//! **The numbers do not depend on the choice.** Rust never contracts a·b + c into a fused
//! multiply-add by itself, and the kernels that want one write it explicitly (`f64::mul_add`, see
//! `integrate::rattle_kernel::fmadd`), which is the correctly rounded fused operation on every CPU:
//! one instruction where the level has FMA (x86-64-v3 and up, every aarch64), the C library's `fma`
//! elsewhere (exact, but much slower: the baseline level is a correct fallback, not a fast one).
//! Wider vectors only change how many lanes one instruction handles, never an operation's rounding.
//! So a trajectory gets the same bits at every level, the ensemble and the single-trajectory path
//! agree bit for bit whichever level each ran at, and `tests/isa.rs` checks both against
//! [`set_baseline_only`].

use std::sync::atomic::{AtomicBool, Ordering};

/// When set, [`fastest`] runs the baseline code (for tests comparing the levels, and for users who
/// want to rule the wider instructions out).
static BASELINE_ONLY: AtomicBool = AtomicBool::new(false);

/// Runs `work` compiled for the best instruction-set level of this CPU (module doc).
///
/// `work` must be an `#[inline(always)]` closure, and what it calls on the hot path
/// `#[inline(always)]` too: only code inlined into the chosen clone is compiled for its level
/// (a function the compiler keeps out of line runs at the baseline, correct but slower).
#[inline(always)]
pub fn fastest<R>(work: impl FnOnce() -> R) -> R {
    if BASELINE_ONLY.load(Ordering::Relaxed) {
        work()
    } else {
        on_best_level(work)
    }
}

#[multiversion::multiversion(targets(
    "x86_64+avx512f+avx512bw+avx512cd+avx512dq+avx512vl+avx2+avx+fma+bmi1+bmi2+f16c+lzcnt+movbe+popcnt+sse4.2",
    "x86_64+avx2+avx+fma+bmi1+bmi2+f16c+lzcnt+movbe+popcnt+sse4.2",
))]
fn on_best_level<R, F: FnOnce() -> R>(work: F) -> R {
    work()
}

/// The level [`fastest`] runs at on this CPU: `"x86-64-v4"`, `"x86-64-v3"` or `"baseline"`.
pub fn selected() -> &'static str {
    if BASELINE_ONLY.load(Ordering::Relaxed) {
        return "baseline";
    }
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
        // the features of the AVX-512 clone of `on_best_level` (multiversion 0.8 adds none of its own)
        let v4 =
            has!("avx512f") && has!("avx512bw") && has!("avx512cd") && has!("avx512dq") && has!("avx512vl");
        if v3 && v4 {
            return "x86-64-v4";
        }
        if v3 {
            return "x86-64-v3";
        }
    }
    "baseline"
}

/// Restricts (`true`) or frees (`false`) [`fastest`] to the baseline level, process-wide, for the
/// calls that start after it.
pub fn set_baseline_only(on: bool) {
    BASELINE_ONLY.store(on, Ordering::Relaxed);
}
