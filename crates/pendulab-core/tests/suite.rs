//! The core's integration tests as one test binary: each file of `tests/` is a module of this crate,
//! so the core and its dependencies are linked into one test executable instead of one per file
//! (most of `make test-rust`'s time was forty links). The files keep their names and their own module
//! doc comments, which state what each checks. One file's tests:
//! `cargo test --profile test-opt -p pendulab-core --test suite exact::` (the module path is a filter).
//! Shared helpers: `common` (the scenarios' starts, a runner, the sampled pivot of `common::sampled`).

mod common;

mod arithmetic_version;
mod bad_input;
mod conserve_conditioning;
mod convergence;
mod dop853;
mod elastic;
mod elastic_sensitivity;
mod elliptic;
mod elliptic_complement;
mod elliptic_properties;
mod ensemble;
mod ensemble_adaptive;
mod ensemble_blocks;
mod ensemble_compositions;
mod ensemble_divergence;
mod exact;
mod exact_degenerate;
mod exact_limits;
mod exact_turning_points;
mod friction;
mod fuzz_props;
mod golden;
mod halved_steps;
mod hoist;
mod invariants;
mod isa;
mod live;
mod live_error;
mod models;
mod physics;
mod pivot;
mod pivot_breaks;
mod rattle_unfused;
mod reduce;
mod roundoff;
mod sensitivity;
mod stepper_on_samples;
mod steps_on_breaks;
mod string;
mod weierstrass;
