//! Sweeps on every core: the points, their order and every number are the same in one
//! thread, in four, and in the page's frame-by-frame slices (`Sweep::advance`), for a
//! one-parameter sweep with seeds and scores and for a grid.
#![cfg(not(target_arch = "wasm32"))]

use attlab::analysis::sweep::Sweep;
use attlab::labs;
use attlab::model::ParamValues;

/// Sweep `index` of `lab` over the first `values` of its values.
fn sweep(lab: &str, index: usize, values: usize) -> Sweep {
    let lab = labs::find(lab).expect("lab");
    let spec = lab.sweeps()[index];
    Sweep::new(lab, spec, ParamValues::defaults(lab.params()), 3)
        .with_values(spec.values[..values].to_vec())
}

/// Every number of the result, bit for bit (Debug prints each f64 so that it reads back
/// exactly, and a NaN as NaN).
fn fingerprint(s: &Sweep) -> String {
    format!("{:?}\n{:?}", s.points, s.skipped)
}

fn in_threads(threads: usize, s: Sweep) -> Sweep {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("a thread pool")
        .install(|| s.run_to_end())
}

#[test]
fn a_sweep_gives_the_same_numbers_in_one_thread_in_four_and_in_frame_slices() {
    for (lab, index, values) in [("p4", 0, 4), ("p4", 1, 3)] {
        let one = in_threads(1, sweep(lab, index, values));
        let four = in_threads(4, sweep(lab, index, values));
        let mut sliced = sweep(lab, index, values);
        while !sliced.advance(997) {}
        let points = one.points.len();
        let grid = one.spec().grid.map_or(1, |g| g.values.len());
        assert_eq!(
            points,
            values * grid,
            "{lab} sweep {index}: every point ran"
        );
        assert!(
            one.points
                .iter()
                .any(|p| p.rms.iter().any(|r| r.is_finite() && *r > 0.0)),
            "{lab} sweep {index}: the runs measured something"
        );
        assert_eq!(
            fingerprint(&one),
            fingerprint(&four),
            "{lab} sweep {index}: 1 vs 4 threads"
        );
        assert_eq!(
            fingerprint(&one),
            fingerprint(&sliced),
            "{lab} sweep {index}: threads vs slices"
        );
        assert!(sliced.is_done() && one.is_done() && (one.progress() - 1.0).abs() < 1e-12);
    }
}
