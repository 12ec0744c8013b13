//! Replaying a recorded log in the page: every line accounted for, every sample delivered,
//! a restarted clock joined and shaded.

use super::{harness, press_in_section};
use attlab_web::state::{IoCommand, RunCommand};
use egui_kittest::kittest::Queryable;

/// Lab `lab`'s page with its example log replayed from the button under `heading`, after
/// checking that the message says "replaying {lines}" and "{rejected}".
fn replay_example(
    lab: &str,
    heading: &str,
    lines: &str,
    rejected: &str,
) -> egui_kittest::Harness<'static, attlab_web::AttLabApp> {
    let h = press_in_section(lab, heading, "Replay the example log");
    let said = h.state().state.messages().iter().any(|m| {
        !m.is_error && m.text.contains(&format!("replaying {lines}")) && m.text.contains(rejected)
    });
    assert!(said, "{:?}", h.state().state.messages());
    h
}

/// Lab `lab`'s page in `lang` after the file chooser delivered `picked` (taken on the next
/// frame).
fn picked_in(
    lab: &str,
    lang: attlab::i18n::Lang,
    picked: attlab_web::pick::Picked,
) -> egui_kittest::Harness<'static, attlab_web::AttLabApp> {
    let mut h = harness(lab);
    h.state_mut()
        .apply(attlab_web::state::ViewCommand::SetLang(lang).into());
    *h.state().state.io().file_slot().borrow_mut() = Some(picked);
    h.run();
    h
}

/// Paper 4's example log from its button: every line accounted for in the message, and the
/// replay's first step delivers the first sample.
#[test]
fn the_example_log_replays_and_says_what_became_of_every_line() {
    let mut h = replay_example(
        "p4",
        "Real data: an Arduino MPU-6050 log",
        "1000 samples of 1003 lines",
        "3 rejected",
    );
    let sim = h.state().state.sim();
    assert!(
        sim.replay_log().is_some() && sim.t_s() < 0.0,
        "starts before sample 0"
    );
    h.state_mut().apply(RunCommand::StepOnce.into());
    let sim = h.state().state.sim();
    let gyro = sim.value("sensors.gyro_deg_s").expect("the logged gyro");
    let first = sim.replay_log().expect("a replay").rate_rad_s[0].to_degrees();
    assert!(
        sim.t_s().abs() < 1e-12 && (gyro - first).abs() < 1e-9,
        "{gyro} vs {first}"
    );
}

/// Paper 1's example is raw 24-bit words: its button sets the calibration it is written
/// with, so every line is a sample and the panel shows the settings used.
#[test]
fn the_raw_count_example_sets_its_calibration_and_replays_every_line() {
    let h = replay_example(
        "p1",
        "Laboratory mode: recorded gyro log",
        "6001 samples of 6001 lines",
        "0 rejected",
    );
    let format = h.state().state.sim().lab().page().log_format.unwrap();
    let units = h.state().state.io().units_for(format);
    assert_eq!(
        (units.index("rate_counts"), units.get("count_zero")),
        (3, 1258.0)
    );
}

/// A log whose sketch restarted: the page replays both segments, says so, and shades the
/// join on the plots (the steps without a logged sample).
#[test]
fn a_restarted_log_replays_both_segments_and_shades_the_join() {
    let mut h = harness("p4");
    let mut text = String::from("ms,ax,ay,az,gx,gy,gz\n");
    for (k, t) in (0..300).chain(0..300).enumerate() {
        text += &format!("{},0,{},16384,{},0,0\n", 10 * t, k % 50, 131 * (k % 7));
    }
    h.state_mut()
        .apply(IoCommand::ReplayLog("restarted.csv".into(), text.into_bytes()).into());
    h.run();
    let said = h.state().state.messages().iter().any(|m| {
        m.text.contains("replaying 600 samples of 600 lines") && m.text.contains("clock gaps: 1")
    });
    assert!(said, "{:?}", h.state().state.messages());
    // 600 samples and the join: max(10 P, 1 s) = 1 s at P = 10 ms, 99 steps without a
    // sample and the 100th onto the second segment's first.
    for _ in 0..699 {
        h.state_mut().apply(RunCommand::StepOnce.into());
    }
    h.run();
    let sim = h.state().state.sim();
    let gap = sim
        .recorder()
        .index_of("sensors.log_sample")
        .expect("recorded for the shading");
    let flags = sim.recorder().recent_vec(gap);
    let with: usize = flags.iter().filter(|v| **v == 1.0).count();
    let without: usize = flags.iter().filter(|v| **v == 0.0).count();
    assert_eq!(
        (with, without),
        (600, 1 + 99),
        "the first row is before sample 0"
    );
    assert!(
        h.query_by_label("no logged sample (a gap or a restart of the log's clock)")
            .is_some()
    );
}

/// What the file chooser can deliver, taken on the app's next frame: a refused chooser and an
/// unreadable file are said in the reader's language; nothing is replayed.
#[test]
fn a_refused_chooser_and_an_unreadable_file_are_said_in_the_readers_language() {
    use attlab_web::pick::Picked;
    let cases = [
        (
            attlab::i18n::Lang::En,
            Picked::Refused,
            "opened no file window",
        ),
        (
            attlab::i18n::Lang::Ru,
            Picked::Refused,
            "не открыл окно выбора файла",
        ),
        (
            attlab::i18n::Lang::En,
            Picked::Unreadable {
                name: "gone.csv".into(),
                why: "no such file".into(),
            },
            "cannot read gone.csv: no such file",
        ),
    ];
    for (lang, picked, said) in cases {
        let h = picked_in("p4", lang, picked.clone());
        let state = &h.state().state;
        assert!(
            state
                .messages()
                .iter()
                .any(|m| m.is_error && m.text.contains(said)),
            "{picked:?} in {lang:?}: {:?}",
            state.messages()
        );
        assert!(state.io().file_slot().borrow().is_none(), "taken");
        assert!(state.sim().replay_log().is_none(), "nothing replayed");
    }
}

/// A picked log with junk lines: each bad line is said with its number, in the reader's
/// language (the reason too, not only the sentence around it), and the good lines replay.
#[test]
fn a_logs_bad_lines_are_said_in_the_readers_language() {
    use attlab::i18n::Lang;
    use attlab_web::pick::Picked;
    let log = "t,rate\n0.0,0.1\n0.1,0.2\n0.2,abc\n0.3,0.1,0.4\n0.4,0.3\n0.5,0.2\n";
    let cases = [
        (
            Lang::En,
            [
                "line 4: not a number: `abc`: `0.2,abc`",
                "line 5: expected 2 columns (time, rate), found 3: `0.3,0.1,0.4`",
            ],
        ),
        (
            Lang::Ru,
            [
                "строка 4: не число: «abc»: «0.2,abc»",
                "строка 5: ожидалось столбцов: 2 (time, rate), найдено: 3: «0.3,0.1,0.4»",
            ],
        ),
    ];
    for (lang, said) in cases {
        let file = Picked::File {
            name: "junk.csv".into(),
            bytes: log.as_bytes().to_vec(),
        };
        let h = picked_in("p1", lang, file);
        let state = &h.state().state;
        for line in said {
            assert!(
                state
                    .messages()
                    .iter()
                    .any(|m| m.is_error && m.text.contains(line)),
                "{lang:?}: no “{line}” in {:?}",
                state.messages()
            );
        }
        let log = state.sim().replay_log().expect("the good lines replay");
        assert_eq!(log.t_s.len(), 4, "{lang:?}");
    }
}

/// A log the lab cannot read at all (paper 4's IMU log picked in paper 1's lab) is refused
/// in the reader's language, naming the format it looks like in the reader's words.
#[test]
fn a_refused_log_is_said_in_the_readers_language() {
    use attlab::i18n::Lang;
    use attlab_web::pick::Picked;
    let p4 = attlab::labs::find("p4").expect("registered");
    let imu = p4.page().example_log.expect("p4 ships a log").text;
    let cases = [
        (Lang::En, "It looks like an MPU-6050 IMU log"),
        (Lang::Ru, "Похоже, это запись инерциального модуля MPU-6050"),
    ];
    for (lang, said) in cases {
        let file = Picked::File {
            name: "imu.csv".into(),
            bytes: imu.as_bytes().to_vec(),
        };
        let h = picked_in("p1", lang, file);
        let state = &h.state().state;
        let text = state
            .messages()
            .iter()
            .map(|m| m.text.clone())
            .collect::<Vec<_>>();
        assert!(
            state
                .messages()
                .iter()
                .any(|m| m.is_error && m.text.contains(said)),
            "{lang:?}: no “{said}” in {text:?}"
        );
        assert!(state.sim().replay_log().is_none(), "nothing replayed");
    }
}

/// Paper 4's example log replayed for 300 steps, and drawn.
fn p4_replayed_300_steps() -> egui_kittest::Harness<'static, attlab_web::AttLabApp> {
    let mut h = replay_example(
        "p4",
        "Real data: an Arduino MPU-6050 log",
        "1000 samples of 1003 lines",
        "3 rejected",
    );
    for _ in 0..300 {
        h.state_mut().apply(RunCommand::StepOnce.into());
    }
    h.run_steps(2);
    h
}

/// A replay has no truth: the legend says the truth's angle and every filter's error have
/// no values recorded, and says it of nothing the log or the filters give.
#[test]
fn a_replays_legend_says_which_series_have_no_values() {
    let mut h = p4_replayed_300_steps();
    const NONE: &str = " — no values recorded";
    let texts = super::legend::legend_texts(&h.state().state);
    let empty: Vec<&String> = texts.iter().filter(|t| t.contains(NONE)).collect();
    assert_eq!(
        empty,
        ["Truth: angle [°] — no values recorded"],
        "{texts:#?}"
    );
    assert!(
        texts.len() >= 6,
        "the estimates and the accelerometer: {texts:#?}"
    );
    let errors = attlab::model::PlotTab::Group(attlab::model::SeriesGroup::Error);
    super::legend::select(&mut h, errors);
    let texts = super::legend::legend_texts(&h.state().state);
    let series: Vec<&String> = texts.iter().filter(|t| t.contains(" error")).collect();
    assert!(series.len() >= 4, "{texts:#?}");
    assert!(series.iter().all(|t| t.ends_with(NONE)), "{texts:#?}");
    // The 3D view draws the estimate alone, solid, and says why.
    let app = &h.state().state;
    assert!(!app.sim().has_truth());
    assert_eq!(
        attlab_web::panels::body_captions(app, Some("KF")),
        [
            "no truth: a log holds only readings",
            "estimate (solid): KF"
        ]
    );
}

/// Paper 1's replay: its angle figure's owners share one measure, so they stand under it,
/// the truth among them saying it has no values (the marker does not break the group).
#[test]
fn a_replays_truth_without_values_stays_in_its_group() {
    let mut h = replay_example(
        "p1",
        "Laboratory mode: recorded gyro log",
        "6001 samples of 6001 lines",
        "0 rejected",
    );
    for _ in 0..50 {
        h.state_mut().apply(RunCommand::StepOnce.into());
    }
    h.run_steps(2);
    let texts = super::legend::legend_texts(&h.state().state);
    assert_eq!(
        texts.first().map(String::as_str),
        Some("angle [°]"),
        "{texts:#?}"
    );
    assert_eq!(
        texts.get(1).map(String::as_str),
        Some("Truth — no values recorded"),
        "{texts:#?}"
    );
    let marked = texts.iter().filter(|t| t.contains("no values")).count();
    assert_eq!(marked, 1, "{texts:#?}");
}

/// Every text the last frame painted.
fn texts(h: &egui_kittest::Harness<'_, attlab_web::AttLabApp>) -> Vec<String> {
    (h.output().shapes.iter())
        .filter_map(|c| match &c.shape {
            egui::epaint::Shape::Text(t) => Some(t.galley.text().to_string()),
            _ => None,
        })
        .collect()
}

/// The dial's readouts that name the truth (the number or "—", two spaces, the name).
fn truth_readouts(h: &egui_kittest::Harness<'_, attlab_web::AttLabApp>) -> Vec<String> {
    let truth = attlab::i18n::t(h.state().state.view().lang(), "truth");
    let ending = format!("  {truth}");
    texts(h)
        .into_iter()
        .filter(|text| text.ends_with(&ending))
        .collect()
}

/// A replay has no truth: paper 4's dial leaves it out (it had read "— truth" above the
/// filters' angles) and still reads the filters' angles, while the lab running its
/// simulation shows the truth's angle there.
#[test]
fn a_replays_dial_names_no_truth() {
    let mut simulated = harness("p4");
    simulated.run_steps(2);
    let shown = truth_readouts(&simulated);
    assert_eq!(
        shown.len(),
        1,
        "the simulation's truth on the dial: {shown:?}"
    );
    assert!(shown[0].contains('°'), "with its angle: {shown:?}");
    let h = p4_replayed_300_steps();
    assert_eq!(truth_readouts(&h), Vec::<String>::new());
    let angles = texts(&h).into_iter().filter(|t| t.contains("°  ")).count();
    assert!(
        angles >= 2,
        "the filters' angles on the dial: {:?}",
        texts(&h)
    );
}
