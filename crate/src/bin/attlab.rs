//! `attlab`: the headless command-line tool (reproduce, run, bench).

// A panic in the product is a bug to report, not an answer: fallible paths return typed
// errors. Tests may unwrap (clippy.toml allows it in tests).
#![deny(clippy::unwrap_used, clippy::expect_used)]

#[cfg(not(target_arch = "wasm32"))]
mod cli;

/// The system allocator, counting: `attlab fuzz` checks each set's heap with it.
#[cfg(not(target_arch = "wasm32"))]
#[global_allocator]
static HEAP: &stats_alloc::StatsAlloc<std::alloc::System> = &stats_alloc::INSTRUMENTED_SYSTEM;

#[cfg(not(target_arch = "wasm32"))]
fn main() -> std::process::ExitCode {
    cli::main()
}

#[cfg(target_arch = "wasm32")]
fn main() {}
