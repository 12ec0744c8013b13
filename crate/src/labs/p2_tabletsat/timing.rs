//! The MEKF step `attlab bench p2` times: every sensor at the prediction rate, so each step
//! carries all twelve measurement rows of the full 9-state filter.
// Only the CLI and the tests time a lab (the `study` feature).
#![cfg_attr(not(feature = "study"), allow(dead_code, unused_imports))]

use super::{INERTIA_KG_M2, PARAMS, TabletSat, p0, tuning};
use crate::estimators::{
    FULL_F, FULL_H_NONZEROS, Mekf, MekfConfig, SensorSet, StateSet, full_step_flops,
};
use crate::model::{Estimator, ParamValues, TimingItem};
use crate::page::Lab;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

/// The MEKF step the CLI times (`attlab bench p2`).
pub(super) fn timing_items() -> Vec<TimingItem> {
    // Every sensor at the prediction rate, so every step carries all twelve rows.
    let mut p = ParamValues::defaults(PARAMS);
    for (k, v) in [
        ("vector_rate_hz", 10.0),
        ("gyro_rate_hz", 10.0),
        ("star_rate_hz", 10.0),
    ] {
        // The keys and values are this lab's own and in range.
        let _ = p.set(PARAMS, k, v);
    }
    let mut rng = ChaCha8Rng::seed_from_u64(1);
    let mut run = TabletSat.build(&p, &mut rng);
    let start = run.truth.state();
    let dt = TabletSat.dt_s(&p);
    let trace = run.measurement_trace(dt, 256, &mut rng);
    let cfg = MekfConfig {
        id: "bench",
        label: "ST+Gyro+Mag+Sun [λ,ω,Δω]",
        sensors: SensorSet::ALL,
        states: StateSet::AttRateGyroBias,
        disturbance: false,
        constant_gain: false,
        inertia_kg_m2: INERTIA_KG_M2,
    };
    let fresh = Mekf::<9>::new(
        cfg,
        tuning(&p, [1e-6, 1.2e-6, 1e-8]),
        start.q_ref_from_body,
        start.rate_body_rad_s,
        p0(StateSet::AttRateGyroBias, 0.5f64.to_radians()),
    );
    let mut filter = fresh.clone();
    let mut i = 0;
    vec![TimingItem {
        name: "MEKF step: 9 states, 12 rows",
        flops: Some(full_step_flops(9, 12, FULL_H_NONZEROS, FULL_F)),
        run: Box::new(move || {
            // The trace repeats: start the filter afresh with it.
            if i % trace.len() == 0 {
                filter = fresh.clone();
            }
            filter.step(std::hint::black_box(&trace[i % trace.len()]), dt);
            i += 1;
        }),
    }]
}
