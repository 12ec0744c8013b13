//! One binary for the ordinary integration tests (one link instead of nineteen). Kept apart,
//! each for its reason: `alloc_free_step` and `memory` count the process's allocations
//! (another test's threads would count too), `browser` runs in wasm in headless Chromium,
//! and `page` drives the built site through chromedriver.
#![cfg(not(target_arch = "wasm32"))]

mod conformance;
mod conversions;
mod csv_cells;
mod cycle;
mod docs;
mod free_rotation;
mod fuzz;
mod golden;
mod house_style;
mod import_cycles;
mod importers;
mod integrators;
mod live;
mod p1;
mod p2;
mod p3;
mod p4;
mod p5;
mod reproductions;
mod sweeps;
mod time_travel;
