//! The worker threads of the ensembles (rayon's global pool), one per CPU and, by default, each
//! bound to its own CPU. No physics.
//!
//! Why bound: the ensemble kernel splits a run into blocks that two or more workers take in turn, and
//! a short run (10³ steps of 4096 starts: 5 ms) is fast only if every worker gets a CPU of its own at
//! once. Measured on a 2-CPU virtual machine, a run started after the process had been idle for a few
//! tens of milliseconds often woke both workers onto the same CPU (the other one, halted by the host,
//! looks busy to the guest's scheduler), and the two shared it for the whole run: 11 ms instead of
//! 6, each worker waiting 4–6 ms in the run queue (`/proc/self/task/*/schedstat`). Bound, every run
//! took 6.1–6.6 ms. Work stealing keeps the cost of binding small when another program loads one of
//! the CPUs: the worker there takes fewer blocks, the others more.
//!
//! Rules: the pool has `RAYON_NUM_THREADS` threads (default: the CPUs this process may use); worker
//! k is bound to the k-th of those CPUs only on Linux, when the pool has exactly one worker per
//! allowed CPU and more than one, and unless `PENDULAB_BIND_THREADS=0`. A pool of another size is
//! left to the scheduler (two processes of one thread each would otherwise share one CPU). The
//! workers are named `pendulab-0`, `pendulab-1`, … (as `top -H` and `/proc/<pid>/task/*/comm` show).

use std::sync::OnceLock;

/// What [`start_pool`] did: the number of workers and whether they are bound to CPUs.
#[derive(Debug, Clone, Copy)]
pub(crate) struct PoolInfo {
    pub threads: usize,
    pub bound: bool,
}

static POOL: OnceLock<PoolInfo> = OnceLock::new();

/// Starts rayon's global pool by the module doc's rules (once; later calls return the first
/// answer). If the pool was started already (by something else in this library), it is kept.
pub(crate) fn start_pool() -> PoolInfo {
    *POOL.get_or_init(|| {
        let cpus = allowed_cpus();
        let wanted = std::env::var("PENDULAB_BIND_THREADS").map_or(true, |v| v.trim() != "0");
        let threads = pool_size();
        let bind = wanted && cpus.len() > 1 && threads == cpus.len();
        let mut builder =
            rayon::ThreadPoolBuilder::new().num_threads(threads).thread_name(|k| format!("pendulab-{k}"));
        if bind {
            let cpus = cpus.clone();
            builder = builder.start_handler(move |k| bind_current_thread(cpus[k % cpus.len()]));
        }
        match builder.build_global() {
            Ok(()) => PoolInfo { threads, bound: bind },
            Err(_) => PoolInfo { threads: rayon::current_num_threads(), bound: false },
        }
    })
}

/// The pool's size: `RAYON_NUM_THREADS` if set to a positive number, else rayon's default (one per
/// CPU this process may use).
fn pool_size() -> usize {
    let from_env = std::env::var("RAYON_NUM_THREADS").ok().and_then(|s| s.trim().parse::<usize>().ok());
    match from_env {
        Some(n) if n > 0 => n,
        _ => std::thread::available_parallelism().map_or(1, |n| n.get()),
    }
}

/// The CPUs this process may run on (Linux: its affinity mask; elsewhere none are listed, and
/// nothing is bound).
#[cfg(target_os = "linux")]
fn allowed_cpus() -> Vec<usize> {
    // SAFETY: cpu_set_t is plain data; sched_getaffinity writes at most size_of::<cpu_set_t>() bytes.
    unsafe {
        let mut set: libc::cpu_set_t = std::mem::zeroed();
        if libc::sched_getaffinity(0, std::mem::size_of::<libc::cpu_set_t>(), &mut set) != 0 {
            return Vec::new();
        }
        (0..libc::CPU_SETSIZE as usize).filter(|&c| libc::CPU_ISSET(c, &set)).collect()
    }
}

#[cfg(not(target_os = "linux"))]
fn allowed_cpus() -> Vec<usize> {
    Vec::new()
}

/// Binds the calling thread to `cpu` (a failure leaves it unbound: binding only speeds up).
#[cfg(target_os = "linux")]
fn bind_current_thread(cpu: usize) {
    // SAFETY: as in allowed_cpus; pid 0 is the calling thread.
    unsafe {
        let mut set: libc::cpu_set_t = std::mem::zeroed();
        libc::CPU_SET(cpu, &mut set);
        libc::sched_setaffinity(0, std::mem::size_of::<libc::cpu_set_t>(), &set);
    }
}

#[cfg(not(target_os = "linux"))]
fn bind_current_thread(_cpu: usize) {}
