//! # pendulab-wasm
//!
//! The lab's engine in the page (docs/lab.md): `pendulab-core`'s live session
//! ([`pendulab_core::live`]) compiled to WebAssembly behind a plain C ABI — `extern "C"` functions over
//! linear memory, no wasm-bindgen (nothing to install but the `wasm32-unknown-unknown` target; the
//! JavaScript side is ~100 lines in `web/src/engine/`). Strings go in as UTF-8 bytes the caller writes
//! into memory from [`pl_alloc`]; every answer is left in one output buffer ([`pl_out_ptr`],
//! [`pl_out_len`]): packed messages ([`engine::pack`]) or, when a function returns −1, an error text.
//! The one import is `env.pl_now() -> f64`, the wall clock in seconds (`performance.now()/1000`),
//! for the per-tick budget. SI units throughout; frames are frame.json's float64 records.

pub mod analyses;
pub mod engine;
pub mod refusal;
pub mod run;
/// The wire format, shared with the server (`pendulab_core::live::wire`).
pub use pendulab_core::live::wire;

use engine::Engine;
use std::cell::RefCell;

#[cfg(target_arch = "wasm32")]
mod clock {
    extern "C" {
        fn pl_now() -> f64;
    }
    /// The page's wall clock [s].
    pub fn now() -> f64 {
        // SAFETY: an imported function without arguments or memory access.
        unsafe { pl_now() }
    }
}

#[cfg(not(target_arch = "wasm32"))]
mod clock {
    use std::sync::OnceLock;
    use std::time::Instant;
    /// A monotonic clock \[s\] (native builds: tests and the benchmark).
    pub fn now() -> f64 {
        static START: OnceLock<Instant> = OnceLock::new();
        START.get_or_init(Instant::now).elapsed().as_secs_f64()
    }
}

pub use clock::now;

thread_local! {
    static OUT: RefCell<Vec<u8>> = const { RefCell::new(Vec::new()) };
    static ENGINES: RefCell<Vec<Option<Engine>>> = const { RefCell::new(Vec::new()) };
}

fn set_out(bytes: Vec<u8>) {
    OUT.with(|o| *o.borrow_mut() = bytes);
}

fn input(ptr: *const u8, len: usize) -> String {
    if ptr.is_null() || len == 0 {
        return String::new();
    }
    // SAFETY: the caller wrote `len` bytes at `ptr`, memory it got from pl_alloc.
    let bytes = unsafe { std::slice::from_raw_parts(ptr, len) };
    String::from_utf8_lossy(bytes).into_owned()
}

/// `len` bytes of memory for the caller to write an input into (freed with [`pl_free`]).
#[no_mangle]
pub extern "C" fn pl_alloc(len: usize) -> *mut u8 {
    let mut v = vec![0u8; len.max(1)];
    let p = v.as_mut_ptr();
    std::mem::forget(v);
    p
}

/// Frees memory from [`pl_alloc`].
///
/// # Safety
/// `ptr` and `len` must be a pointer and length [`pl_alloc`] returned and not freed yet.
#[no_mangle]
pub unsafe extern "C" fn pl_free(ptr: *mut u8, len: usize) {
    if !ptr.is_null() {
        drop(Vec::from_raw_parts(ptr, len.max(1), len.max(1)));
    }
}

/// Where the last answer starts in memory.
#[no_mangle]
pub extern "C" fn pl_out_ptr() -> *const u8 {
    OUT.with(|o| o.borrow().as_ptr())
}

/// The last answer's length \[bytes\].
#[no_mangle]
pub extern "C" fn pl_out_len() -> usize {
    OUT.with(|o| o.borrow().len())
}

/// A new session from the configuration JSON at `ptr` ([`Engine::new`]); its handle (≥ 0) with its
/// first messages in the output, or −1 with the error text there.
#[no_mangle]
pub extern "C" fn pl_session_new(ptr: *const u8, len: usize) -> i32 {
    match Engine::new(&input(ptr, len)) {
        Ok(mut e) => {
            set_out(e.first(&now));
            ENGINES.with(|all| {
                let mut all = all.borrow_mut();
                all.push(Some(e));
                (all.len() - 1) as i32
            })
        }
        Err(msg) => {
            set_out(msg.into_bytes());
            -1
        }
    }
}

/// One tick of session `handle`: the command messages (a JSON array of strings) at `ptr`, `elapsed`
/// wall-clock seconds since the last tick, `budget` seconds of stepping allowed; 0 with the packed
/// messages in the output, or −1 with an error text.
#[no_mangle]
pub extern "C" fn pl_session_tick(handle: i32, ptr: *const u8, len: usize, elapsed: f64, budget: f64) -> i32 {
    let text = input(ptr, len);
    let messages: Vec<String> = if text.is_empty() {
        Vec::new()
    } else {
        match serde_json::from_str(&text) {
            Ok(m) => m,
            Err(e) => {
                set_out(format!("tick: the commands are not a JSON array of strings: {e}").into_bytes());
                return -1;
            }
        }
    };
    ENGINES.with(|all| match all.borrow_mut().get_mut(handle as usize).and_then(Option::as_mut) {
        Some(e) => {
            set_out(e.tick(&messages, elapsed, &now, budget));
            0
        }
        None => {
            set_out(format!("tick: no session {handle}").into_bytes());
            -1
        }
    })
}

/// Ends session `handle` (its memory is freed).
#[no_mangle]
pub extern "C" fn pl_session_free(handle: i32) {
    ENGINES.with(|all| {
        if let Some(slot) = all.borrow_mut().get_mut(handle as usize) {
            *slot = None;
        }
    });
}

/// A trajectory ([`run::run`]) from the spec JSON at `ptr`: 0 with its float64 records in the output,
/// or −1 with an error text.
#[no_mangle]
pub extern "C" fn pl_run(ptr: *const u8, len: usize) -> i32 {
    match run::run(&input(ptr, len)) {
        Ok(records) => {
            set_out(records.iter().flat_map(|r| r.0).flat_map(f64::to_le_bytes).collect());
            0
        }
        Err(msg) => {
            set_out(msg.into_bytes());
            -1
        }
    }
}

/// A REST request answered in the page ([`analyses::request`]: `{"path": "api/exact" |
/// "api/effective_potential" | "api/em_map" | "api/reduced", "body": {…}}`): its HTTP status, with the
/// JSON answer in the output.
#[no_mangle]
pub extern "C" fn pl_request(ptr: *const u8, len: usize) -> i32 {
    let (status, body) = analyses::request(&input(ptr, len));
    set_out(body.to_string().into_bytes());
    i32::from(status)
}
