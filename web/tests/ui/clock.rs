//! The run's clock: a frame advances the simulation by the wall time since the last frame ×
//! the speed, up to [`MAX_FRAME_S`] of wall time.

use super::*;
use attlab_web::state::MAX_FRAME_S;
use std::time::{Duration, Instant};

/// The simulated time after frames at `gaps_s` (wall-clock seconds between frames) at
/// `speed`, on p4 from t = 0, and the simulation's step (s).
fn simulated_after(gaps_s: &[f64], speed: f64) -> (f64, f64) {
    let lab = labs::find("p4").expect("registered");
    let mut app = AttLabApp::with_state(lab, ParamValues::defaults(lab.params()), 1, speed);
    app.apply(RunCommand::SetPlaying(true).into());
    let mut now = Instant::now();
    app.apply(RunCommand::Advance(now).into());
    for gap in gaps_s {
        now += Duration::from_secs_f64(*gap);
        app.apply(RunCommand::Advance(now).into());
    }
    (app.state.sim().t_s(), app.state.sim().dt_s())
}

#[test]
fn a_slow_frame_advances_the_run_by_its_whole_interval() {
    // Software GL draws a frame in ~0.17 s: the run keeps the speed asked for.
    let (t_s, dt_s) = simulated_after(&[0.2, 0.2], 2.0);
    assert!((t_s - 0.8).abs() <= dt_s, "4 frames' worth at 2×: {t_s} s");
}

#[test]
fn a_long_gap_counts_as_the_longest_frame_only() {
    // A tab back from the background after a minute does not catch up on the minute.
    let (t_s, dt_s) = simulated_after(&[0.1, 60.0], 1.0);
    let want_s = 0.1 + MAX_FRAME_S;
    assert!((t_s - want_s).abs() <= dt_s, "{t_s} s, not {want_s} s");
}
