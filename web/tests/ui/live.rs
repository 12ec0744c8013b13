//! The live-sensors part of the log panel on the desktop, where there are no browser
//! sensors: it is there for the labs that read an IMU's log (p3 and p4), and starting a
//! source says why it cannot, without leaving the simulation.

use super::press_in_section as press_in_log_panel;
use egui_kittest::kittest::Queryable;

#[test]
fn starting_the_phone_on_the_desktop_says_why_it_cannot_and_keeps_simulating() {
    for lab in ["p3", "p4"] {
        let mut h = press_in_log_panel(
            lab,
            "Real data: an Arduino MPU-6050 log",
            "Use this phone's sensors",
        );
        let messages = h.state().state.messages().to_vec();
        assert!(
            messages
                .iter()
                .any(|m| m.is_error && m.text.contains("live sensors run in the web page")),
            "{lab}: {messages:?}"
        );
        assert!(
            h.state().state.live().is_none(),
            "{lab}: no session without a source"
        );
        let before = h.state().state.sim().steps();
        h.run_steps(5);
        assert!(
            h.state().state.sim().replay_log().is_none(),
            "{lab}: still the simulation"
        );
        assert!(h.state().state.sim().steps() >= before, "{lab}");
    }
}

#[test]
fn the_serial_button_and_its_baud_choice_are_named_for_a_screen_reader() {
    let h = press_in_log_panel(
        "p4",
        "Real data: an Arduino MPU-6050 log",
        "Arduino over USB (Web Serial)",
    );
    let messages = h.state().state.messages();
    assert!(
        messages
            .iter()
            .any(|m| m.text.contains("Web Serial runs in the web page")),
        "{messages:?}"
    );
    assert!(
        h.query_by_label("baud").is_some(),
        "the baud choice has a name"
    );
}
