//! CPU time for the examples that time kernels (`roofline_kernels`, `adaptive_ensemble_bench`): on a
//! shared machine the CPU time is what the work costs, the wall time includes waiting for a core.

/// CPU time \[s\] used by this process so far, all its threads (`CLOCK_PROCESS_CPUTIME_ID`; Linux
/// only, 0 elsewhere).
#[cfg(target_os = "linux")]
pub fn cpu_seconds() -> f64 {
    #[repr(C)]
    struct Timespec {
        tv_sec: i64,
        tv_nsec: i64,
    }
    extern "C" {
        fn clock_gettime(clock: i32, tp: *mut Timespec) -> i32;
    }
    const CLOCK_PROCESS_CPUTIME_ID: i32 = 2;
    let mut ts = Timespec { tv_sec: 0, tv_nsec: 0 };
    // SAFETY: clock_gettime writes one timespec (two 64-bit fields on 64-bit Linux) into `ts`.
    let rc = unsafe { clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &mut ts) };
    if rc == 0 {
        ts.tv_sec as f64 + ts.tv_nsec as f64 * 1e-9
    } else {
        0.0
    }
}

/// CPU time \[s\]: not measured off Linux (0).
#[cfg(not(target_os = "linux"))]
pub fn cpu_seconds() -> f64 {
    0.0
}
