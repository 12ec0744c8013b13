//! A value the page refuses is said in the reader's language by the control's label: a
//! slider's value out of its range, a log's unit choice that is none of its options.

use super::harness_from_link as page;
use super::*;

/// The last message's words after `command`, and whether it is an error.
fn said_after(h: &mut Harness<'_, AttLabApp>, command: attlab_web::state::Command) -> String {
    let before = h.state().state.messages().len();
    h.state_mut().apply(command);
    h.run();
    let messages = h.state().state.messages();
    assert_eq!(messages.len(), before + 1, "one message: {messages:?}");
    let last = messages.last().expect("a message");
    assert!(last.is_error, "{last:?}");
    last.text.clone()
}

#[test]
fn a_sliders_refused_value_is_said_by_its_label_in_russian() {
    let mut h = page("lab=free-rotation&lang=ru");
    let before = h.state().state.sim().params().get("gyro_noise_deg_s");
    let said = said_after(&mut h, RunCommand::SetParam("gyro_noise_deg_s", 1e9).into());
    assert!(said.contains("«Шум гироскопа σ»"), "{said}");
    assert!(
        said.contains("1000000000") && !said.contains("gyro_noise"),
        "{said}"
    );
    assert_eq!(
        h.state().state.sim().params().get("gyro_noise_deg_s"),
        before,
        "the run keeps its value"
    );
}

#[test]
fn a_logs_refused_unit_choice_is_said_by_its_label_in_either_language() {
    for (lang, label) in [
        ("en", "“accelerometer columns”"),
        ("ru", "«столбцы акселерометра»"),
    ] {
        let mut h = page(&format!("lab=p4&lang={lang}"));
        let said = said_after(&mut h, IoCommand::SetLogUnit("accel_unit", 99.0).into());
        assert!(
            said.contains(label) && !said.contains("accel_unit"),
            "{lang}: {said}"
        );
        // A choice is said by its options.
        let option = if lang == "ru" {
            "отсчёты, диапазон ±2 g"
        } else {
            "counts, ±2 g range"
        };
        assert!(
            said.contains(option) && said.contains("99"),
            "{lang}: {said}"
        );
    }
}

/// A link's bad page settings and lesson items are said in Russian too, a number with its
/// comma: none of the reasons the core gives in English reaches the Russian page.
#[test]
fn a_links_bad_settings_are_said_in_the_readers_language() {
    let fragment =
        "lab=free-rotation&lang=ru&speed=abc&theme=blue&presenter=2&seed=x&step=3&hide=zz";
    let h = page(fragment);
    let problems = h.state().state.link_problems();
    let (_, errors) = attlab::state::UrlState::parse(fragment);
    assert_eq!(problems.len(), 6, "{problems:#?}");
    assert_eq!(errors.len(), 6, "{errors:#?}");
    for (p, e) in problems.iter().zip(&errors) {
        assert!(e.fault.is_some(), "{e:?}");
        assert!(!p.contains(&e.reason), "{p}: the English “{}”", e.reason);
    }
    let speed = problems.iter().find(|p| p.contains("speed=abc"));
    assert!(speed.is_some_and(|p| p.contains("0,1")), "{problems:#?}");
}
