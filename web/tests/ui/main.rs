//! The app clicked through natively with egui_kittest (AccessKit), no browser and no GPU:
//! switch lab, move a slider, reset, export. Every action goes through the panels'
//! commands, so these also check that the panels emit and the state applies them.
#![cfg(not(target_arch = "wasm32"))]

use attlab::labs;
use attlab::model::ParamValues;
use attlab_web::AttLabApp;
use attlab_web::state::{IoCommand, RunCommand};
use egui::accesskit::{Action, ActionData, ActionRequest, Role};
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT, Queryable};

mod a11y;
mod accuracy;
mod axes;
mod body3d;
mod clock;
mod decimals;
mod fill;
mod keyboard;
mod legend;
mod lesson_screen;
mod lessons;
mod live;
mod narrow;
mod png;
mod refusals;
mod replay;
mod shader;
mod side_panel;
mod status;
mod support;
mod sweep_table;
mod teacher;
mod travel;

use support::{harness_for, harness_from_link, painted};

fn harness(lab_id: &str) -> Harness<'static, AttLabApp> {
    let lab = labs::find(lab_id).expect("registered");
    let mut app = AttLabApp::with_state(lab, ParamValues::defaults(lab.params()), 1, 1.0);
    app.apply(RunCommand::SetPlaying(false).into());
    // The app's own fonts: a label with a glyph no font has fails the test (egui_kittest
    // refuses to draw tofu), so a missing symbol in any label is caught here.
    Harness::builder()
        .with_size(egui::vec2(1400.0, 900.0))
        .with_context_setup(attlab_web::app::setup_context)
        .build_ui_state(|ui, app: &mut AttLabApp| app.frame(ui), app)
}

/// Lab `lab_id`'s page with the collapsed section `heading` opened and `button` in it
/// pressed (both found by their accessible names).
fn press_in_section(lab_id: &str, heading: &str, button: &str) -> Harness<'static, AttLabApp> {
    let mut h = harness(lab_id);
    h.get_by_label(heading).scroll_to_me();
    h.run();
    h.get_by_label(heading).click();
    h.run_steps(3);
    h.get_by_label(button).scroll_to_me();
    h.run();
    h.get_by_label(button).click();
    h.run();
    h
}

/// A harness for `lab_id` whose exports go to a fresh folder named after `tag`.
fn harness_saving(lab_id: &str, tag: &str) -> (Harness<'static, AttLabApp>, std::path::PathBuf) {
    let dir = std::env::temp_dir().join(format!("attlab-ui-{tag}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mut h = harness(lab_id);
    h.state_mut()
        .apply(IoCommand::SetSaveDir(Some(dir.clone())).into());
    (h, dir)
}

#[test]
fn switching_the_lab_from_the_picker() {
    let mut h = harness("free-rotation");
    h.get_by_role_and_label(Role::ComboBox, "Lab").click();
    h.run();
    h.get_by_label("Paper 1: suspended mock-up, one-axis gyro")
        .click();
    h.run();
    assert_eq!(h.state().state.sim().lab().id(), "p1");
    // The new lab's parameters are on the panel.
    assert!(
        h.query_by_role_and_label(Role::Slider, "Adaptation window N")
            .is_some()
    );
}

#[test]
fn moving_a_slider_changes_the_parameter_live() {
    let mut h = harness("free-rotation");
    for _ in 0..5 {
        h.state_mut().apply(RunCommand::StepOnce.into());
    }
    support::set_slider_by_accesskit(&mut h, "Gyro noise σ", 0.5);
    h.run();
    let sim = &h.state().state.sim();
    assert_eq!(sim.params().get("gyro_noise_deg_s"), 0.5);
    assert_eq!(sim.steps(), 5, "a live change does not restart the run");
}

#[test]
fn reset_restarts_at_zero() {
    let mut h = harness("p3");
    for _ in 0..50 {
        h.state_mut().apply(RunCommand::StepOnce.into());
    }
    h.get_by_label("⟲ Reset").click();
    h.run();
    assert_eq!(h.state().state.sim().steps(), 0);
}

#[test]
fn export_writes_every_sample_of_the_run() {
    let (mut h, dir) = harness_saving("p1", "export");
    for _ in 0..200 {
        h.state_mut().apply(RunCommand::StepOnce.into());
    }
    h.get_by_label("Export CSV").scroll_to_me();
    h.run();
    h.get_by_label("Export CSV").click();
    h.run();
    let path = dir.join("attlab-p1-seed1.csv");
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    assert_eq!(text.lines().count(), 1 + 201, "header and rows 0..=200");
    assert!(
        h.state()
            .state
            .messages()
            .iter()
            .any(|m| !m.is_error && m.text.contains("201 rows"))
    );
}

/// Paper 4's γ sweep from its button: it runs in slices, then its result is a table with
/// each objective's argmin, and the Q landscape fills a heat map with its optimum.
#[test]
fn the_gamma_sweep_runs_from_its_button_and_shows_its_argmins() {
    let mut h = harness("p4");
    // Two sweeps offer the button; the first is the γ sweep.
    h.query_all_by_label("Run sweep")
        .next()
        .expect("a sweep button")
        .scroll_to_me();
    h.run();
    h.query_all_by_label("Run sweep")
        .next()
        .expect("a sweep button")
        .click();
    h.run_steps(2);
    let (i, _) = h
        .state()
        .state
        .run()
        .sweep
        .as_ref()
        .map(|(i, s)| (*i, s.is_done()))
        .expect("a sweep started");
    assert_eq!(i, 0);
    while !h
        .state()
        .state
        .run()
        .sweep
        .as_ref()
        .is_some_and(|(_, s)| s.is_done())
    {
        h.state_mut()
            .apply(RunCommand::AdvanceSweep(std::time::Duration::from_millis(50)).into());
    }
    h.run_steps(4);
    for pair in [
        "J(α = 0.3, β = 0.7)",
        "J(α = 0.7, β = 0.3)",
        "J(α = 0.5, β = 0.5)",
    ] {
        // The parameter by its label, as the slider shows it (not its key `gamma`).
        let label = format!("argmin of {pair} over this sweep's 11 values: γ = det Q / det R = ");
        assert!(
            h.query_all_by_label_contains(&label).next().is_some(),
            "no '{label}' on the panel"
        );
    }
    let sweep = &h.state().state.run().sweep.as_ref().unwrap().1;
    assert_eq!(sweep.points.len(), 11);
    assert!(
        sweep
            .points
            .iter()
            .all(|p| p.runs == 5 && p.objectives.iter().all(|j| j.is_finite()))
    );
}

/// Paper 2's outages are recorded on every tab and shaded where the sensor gave nothing:
/// the shaded time matches the samples where the star tracker was out.
#[test]
fn the_star_tracker_outages_are_shaded_where_it_was_out() {
    use attlab::sim::Simulation;
    use attlab_web::render::outages::intervals as outage_intervals;
    let lab = labs::find("p2").expect("registered");
    let mut params = ParamValues::defaults(lab.params());
    params
        .set(lab.params(), "star_sun_exclusion_deg", 90.0)
        .unwrap();
    let mut sim = Simulation::new(lab, params, 1);
    sim.run_for(600.0);
    let rec = sim.recorder();
    let i = rec
        .index_of("sensors.star_available")
        .expect("recorded with the first tab");
    let shaded: f64 = outage_intervals(rec, i, 0.0)
        .iter()
        .map(|[a, b]| b - a)
        .sum();
    // Every sample, from a separate run of the same scenario.
    let trace = attlab::analysis::scenario::run_trace(
        lab,
        &["star_sun_exclusion_deg=90"],
        1,
        600.0,
        &["sensors.star_available"],
    )
    .unwrap();
    let out = trace
        .series("sensors.star_available")
        .unwrap()
        .iter()
        .filter(|v| **v == 0.0)
        .count();
    let out_s = out as f64 * sim.dt_s();
    assert!(
        out_s > 60.0,
        "the blinded tracker should be out for minutes, was out {out_s} s"
    );
    assert!(
        (shaded - out_s).abs() < 0.02 * out_s + 2.0,
        "shaded {shaded} s, out {out_s} s"
    );
}

/// Presenter mode from its button: the sliders go behind one click, the link says so, and
/// the button turns it off again.
#[test]
fn presenter_mode_hides_the_sliders_and_goes_into_the_link() {
    let mut h = harness("p4");
    h.run();
    assert!(
        h.query_by_role_and_label(Role::Slider, "Sample rate")
            .is_some()
    );
    h.get_by_label("Presenter").click();
    h.run();
    assert!(h.state().state.view().presenter);
    assert!(
        h.query_by_role_and_label(Role::Slider, "Sample rate")
            .is_none(),
        "presenter mode shows the presets, not every slider"
    );
    assert!(
        h.query_by_label("γ = 0.2: noisy").is_some(),
        "the presets stay"
    );
    assert!(h.state().state.fragment().contains("presenter=1"));
    h.get_by_label("Presenter").click();
    h.run();
    assert!(!h.state().state.view().presenter);
}

/// "Copy as Python" puts a snippet for the plot on screen on the clipboard.
#[test]
fn copy_as_python_names_the_csv_and_the_tabs_columns() {
    let mut h = harness("p4");
    h.run();
    let snippet = h.state().state.python_snippet();
    assert!(
        snippet.contains("pd.read_csv(\"attlab-p4-seed1.csv\")"),
        "{snippet}"
    );
    // p4 opens on its first figure: truth, set-point, accelerometer angle and estimates.
    for column in [
        "truth.angle_deg [deg]",
        "kf.angle_deg [deg]",
        "sensors.accel_angle_deg [deg]",
    ] {
        assert!(snippet.contains(column), "{column} missing from\n{snippet}");
    }
}

/// One click on an estimator's chip hides it everywhere; a second shows it again. The chip
/// names the estimator as a student reads it, not by its id.
#[test]
fn an_estimator_chip_hides_and_shows_it() {
    let mut h = harness("p4");
    h.run();
    assert!(
        h.query_by_label_contains("● cf").is_none(),
        "a chip shows an id"
    );
    h.get_by_label_contains("● Complementary filter").click();
    h.run();
    assert_eq!(
        h.state().state.view().hidden,
        vec![2],
        "cf is the second estimator: source 2"
    );
    h.get_by_label_contains("● Complementary filter").click();
    h.run();
    assert!(h.state().state.view().hidden.is_empty());
}

#[test]
fn a_reset_only_slider_waits_for_reset_and_says_so() {
    let mut h = harness("p1");
    for _ in 0..5 {
        h.state_mut().apply(RunCommand::StepOnce.into());
    }
    let dt_s = h.state().state.sim().dt_s();
    support::set_slider_by_accesskit(&mut h, "Gyro output rate", 300.0);
    h.run();
    let sim = &h.state().state.sim();
    assert_eq!(sim.params().get("input_rate_hz"), 300.0);
    assert_eq!(
        (sim.steps(), sim.dt_s()),
        (5, dt_s),
        "the run goes on unchanged"
    );
    h.get_by_label("Waiting for Reset: Gyro output rate.");
    // The controls scroll: bring the button into the window first, as a reader would.
    h.get_by_label("Reset now").scroll_to_me();
    h.run();
    h.get_by_label("Reset now").click();
    h.run();
    let sim = &h.state().state.sim();
    assert_eq!(sim.steps(), 0);
    assert_eq!(sim.applied_params().get("input_rate_hz"), 300.0);
    assert!(h.query_by_label("Reset now").is_none());
}

/// The legend of each lab's first plot tab speaks to a student: the source and the quantity
/// in words with the unit, never a series name like `kf.angle_deg [deg]`.
#[test]
fn every_labs_legend_shows_human_labels_with_units() {
    for lab in labs::all() {
        let mut h = harness(lab.id());
        for _ in 0..20 {
            h.state_mut().apply(RunCommand::StepOnce.into());
        }
        h.run();
        let tab = attlab::page::default_tab(*lab);
        let sim = &h.state().state.sim();
        let shown: Vec<&attlab::model::SeriesSpec> = match tab {
            attlab::model::PlotTab::Figure(id) => (lab.page().figure(id))
                .expect("the default tab is a figure of the lab")
                .series
                .iter()
                .filter_map(|n| sim.specs().iter().find(|s| n.is(&s.name)))
                .collect(),
            attlab::model::PlotTab::Group(g) => {
                sim.specs().iter().filter(|s| s.group == g).collect()
            }
        };
        let first = shown
            .first()
            .unwrap_or_else(|| panic!("{}: nothing plotted", lab.id()));
        // The legend says who and what with its unit: together, or under a heading the
        // series of one owner or of one measure share.
        let mut parts = attlab::i18n::series_legend_parts(attlab::i18n::Lang::En, lab.id(), first);
        if lab.page().figures.first().is_some_and(|f| f.log) {
            parts.what = format!("log10 {}", parts.what);
        }
        let whole = parts.joined();
        let said = |words: &str| {
            [words, &whole]
                .iter()
                .any(|w| h.query_all_by_label(w).next().is_some())
        };
        assert!(
            said(&parts.what),
            "{}: the legend has neither `{}` nor `{whole}`",
            lab.id(),
            parts.what
        );
        let owner = parts.owner.as_deref().unwrap_or(&parts.what);
        assert!(
            said(owner),
            "{}: the legend has neither `{owner}` nor `{whole}`",
            lab.id()
        );
        assert!(
            h.query_by_label_contains(&format!("{} [", first.name))
                .is_none(),
            "{}: a legend still shows the series name {}",
            lab.id(),
            first.name
        );
    }
}

/// A plot tab that needs series not recorded so far re-runs the simulation as a job, a
/// slice per frame, with its progress in the status line; the run holds meanwhile and the
/// tab then has its whole history.
#[test]
fn a_tab_that_needs_a_rerun_is_a_job_with_its_progress() {
    use attlab::model::{PlotTab, SeriesGroup};
    use attlab_web::state::ViewCommand;
    let mut h = harness("p2");
    for _ in 0..1500 {
        h.state_mut().apply(RunCommand::StepOnce.into());
    }
    let steps = h.state().state.sim().steps();
    assert_eq!(steps, 1500);
    let rates = PlotTab::Group(SeriesGroup::Rate);
    assert!(
        !h.state()
            .state
            .sim()
            .specs()
            .iter()
            .any(|s| s.group == SeriesGroup::Rate),
        "the rates are not recorded before"
    );
    h.state_mut().apply(ViewCommand::SelectTab(rates).into());
    assert!(h.state().state.run().job().is_some(), "a job, not a stall");
    h.step();
    if h.state().state.run().job().is_some() {
        h.get_by_label_contains("Re-running the simulation for this plot");
    }
    let mut frames = 1;
    while h.state().state.run().job().is_some() {
        h.step();
        frames += 1;
        assert!(frames < 5000, "the re-run never finished");
    }
    eprintln!("re-run of {steps} steps took {frames} frames");
    let sim = h.state().state.sim();
    assert_eq!(sim.steps(), steps, "the run held while it was re-run");
    let i = sim
        .specs()
        .iter()
        .position(|s| s.group == SeriesGroup::Rate)
        .expect("the rates are recorded now");
    let first = sim.recorder().plot_points(i, 10);
    assert_eq!(first.first().map(|p| p[0]), Some(0.0), "from t = 0");
}

#[test]
fn the_string_check_sits_under_the_diameter_slider_and_warns_when_too_thin() {
    let mut h = harness("p1");
    h.run();
    assert!(
        h.query_by_label_contains("with a safety factor of 1.96")
            .is_some(),
        "the paper's 0.35-mm steel string: no note under the diameter slider"
    );
    h.state_mut()
        .apply(RunCommand::SetParam("string_diameter_mm", 0.2).into());
    h.run();
    assert!(
        h.query_by_label_contains("Too thin for 1 kg").is_some(),
        "a 0.2-mm steel string under 1 kg: no warning"
    );
}
