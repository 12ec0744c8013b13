//! The timeline and "What if…" through the app's commands and panels: a seek shows the
//! moment (the main run keeps its time), a slider moved at the cursor waits for the
//! what-if and leaves the main run alone, the what-if catches up and summarises, Remove
//! drops it; a link's `at=` and `whatif=` are carried out and written back.

use super::*;
use attlab_web::state::TravelCommand;

#[test]
fn a_seek_shows_the_moment_and_a_what_if_runs_beside_the_main_run() {
    let mut h = harness("p4");
    for _ in 0..3000 {
        h.state_mut().apply(RunCommand::StepOnce.into());
    }
    let now = h.state().state.sim().t_s();
    h.state_mut().apply(TravelCommand::Seek(1.234).into());
    h.run_steps(3);
    let state = &h.state().state;
    let shown = state.shown().t_s();
    assert!((shown - 1.234).abs() <= state.sim().dt_s(), "shown {shown}");
    assert_eq!(state.sim().t_s(), now, "the main run holds");
    assert!(h.query_by_label("Live").is_some() && h.query_by_label("What if…").is_some());
    let gamma = state.sim().params().get("gamma");
    h.state_mut()
        .apply(RunCommand::SetParam("gamma", gamma * 10.0).into());
    assert_eq!(h.state().state.sim().params().get("gamma"), gamma);
    assert_eq!(h.state().state.slider_params().get("gamma"), gamma * 10.0);
    h.get_by_label("What if…").click();
    h.run_steps(20);
    let state = &h.state().state;
    assert!(state.travel().cursor.is_none(), "back to now");
    assert_eq!(state.travel().branches.len(), 1);
    assert_eq!(
        state.travel().branches[0].sim().steps(),
        state.sim().steps()
    );
    let texts = painted(&h).join("\n");
    assert!(texts.contains("attitude error over the next"), "{texts}");
    assert!(state.fragment().contains("whatif="), "{}", state.fragment());
    h.get_by_label("Remove").click();
    h.run_steps(2);
    assert!(h.state().state.travel().branches.is_empty());
}

#[test]
fn a_links_cursor_and_what_if_are_carried_out_and_written_back() {
    let mut h = harness_from_link("lab=p3&at=4&whatif=2:gyro_noise_deg_s=0.5");
    h.run_steps(30);
    let state = &h.state().state;
    assert!(state.sim().t_s() >= 4.0 - state.sim().dt_s());
    assert_eq!(state.travel().branches.len(), 1);
    let fragment = state.fragment();
    assert!(fragment.contains("whatif=2"), "{fragment}");
    assert!(fragment.contains("gyro_noise_deg_s"), "{fragment}");
}
