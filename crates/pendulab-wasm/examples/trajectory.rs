//! The native side of the parity test and the benchmark (crates/pendulab-wasm/tests/parity.mjs,
//! bench/wasm_steps.mjs): `trajectory SPEC_JSON` writes the float64 records of [`pendulab_wasm::run::run`]
//! to stdout (frame.json's layout, little-endian); `trajectory --time SPEC_JSON` prints the wall seconds
//! the run took instead, and beside them the CPU seconds of this thread (Linux: `/proc/thread-self/schedstat`,
//! nanoseconds; the wall seconds again elsewhere), which a loaded machine disturbs less.

use std::io::Write;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let (time, spec) = match args.as_slice() {
        [flag, spec] if flag == "--time" => (true, spec),
        [spec] => (false, spec),
        _ => {
            eprintln!("usage: trajectory [--time] SPEC_JSON");
            std::process::exit(2);
        }
    };
    let (t0, c0) = (std::time::Instant::now(), cpu_seconds());
    let records = match pendulab_wasm::run::run(spec) {
        Ok(r) => r,
        Err(e) => {
            eprintln!("error: {e}");
            std::process::exit(2);
        }
    };
    if time {
        let wall = t0.elapsed().as_secs_f64();
        let cpu = match (c0, cpu_seconds()) {
            (Some(a), Some(b)) => b - a,
            _ => wall,
        };
        println!("{wall} {cpu}");
        return;
    }
    let bytes: Vec<u8> = records.iter().flat_map(|r| r.0).flat_map(f64::to_le_bytes).collect();
    std::io::stdout().write_all(&bytes).unwrap();
}

/// The CPU time this thread has run [s] (Linux), or None.
fn cpu_seconds() -> Option<f64> {
    let text = std::fs::read_to_string("/proc/thread-self/schedstat").ok()?;
    let ns: f64 = text.split_whitespace().next()?.parse().ok()?;
    Some(ns * 1e-9)
}
