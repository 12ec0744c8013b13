//! PNG exports clicked through: key p stacks every plot tab, a view's button saves it, a
//! lab switch stops a capture.

use super::{harness, harness_saving};
use attlab::labs;
use attlab_web::AttLabApp;
use attlab_web::state::RunCommand;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;

/// Hands `image` to every screenshot the app asks for, as a renderer would, until its
/// capture ends (at most `frames` frames); `each_frame` sees the app after every frame.
fn run_capture(
    h: &mut Harness<'static, AttLabApp>,
    image: &egui::ColorImage,
    frames: usize,
    mut each_frame: impl FnMut(&AttLabApp),
) {
    for _ in 0..frames {
        h.step();
        let app = h.state_mut();
        if let Some(c) = app.capture_mut()
            && c.waiting()
        {
            c.deliver(image.clone());
        }
        each_frame(h.state());
        if h.state_mut().capture_mut().is_none() {
            return;
        }
    }
    panic!("the capture did not end within {frames} frames");
}

/// Key p saves every plot tab in one PNG: each tab is shown in turn (the simulation holds
/// still), captured and cut to the plot area, the tab the user had comes back, and the file
/// is a PNG as tall as the tabs stacked. The harness has no renderer, so the test hands
/// over the screenshots a renderer would (a frame-sized image whose pixels name their row).
#[test]
fn key_p_saves_every_plot_tab_stacked_in_one_png() {
    let (mut h, dir) = harness_saving("p1", "png");
    for _ in 0..100 {
        h.state_mut().apply(RunCommand::StepOnce.into());
    }
    h.run();
    let start_tab = h.state().state.view().plots.tab;
    let all_tabs = attlab_web::panels::tabs(&h.state().state);
    assert!(all_tabs.len() >= 3, "p1 has several plot tabs");
    h.state_mut().apply(RunCommand::SetPlaying(true).into());
    h.key_press(egui::Key::P);
    let (w, hgt) = (1400usize, 900usize);
    let frame_image = egui::ColorImage::new(
        [w, hgt],
        (0..hgt)
            .flat_map(|y| std::iter::repeat_n(egui::Color32::from_rgb(200, (y % 256) as u8, 9), w))
            .collect(),
    );
    // The frame that reads the key still runs the simulation; the capture starts after it.
    h.step();
    assert!(
        h.state_mut().capture_mut().is_some(),
        "key p starts a capture"
    );
    let mut seen = vec![h.state().state.view().plots.tab];
    let steps = h.state().state.sim().steps();
    run_capture(&mut h, &frame_image, 200, |app| {
        if seen.last() != Some(&app.state.view().plots.tab) {
            seen.push(app.state.view().plots.tab);
        }
    });
    let app = h.state();
    assert_eq!(
        app.state.sim().steps(),
        steps,
        "the simulation holds during the capture"
    );
    assert_eq!(
        app.state.view().plots.tab,
        start_tab,
        "the user's tab comes back"
    );
    // The user's tab, every tab in order, the user's tab again (a tab already on screen is
    // not shown twice in a row).
    let mut expected = vec![start_tab];
    expected.extend(all_tabs.iter().copied());
    expected.push(start_tab);
    expected.dedup();
    assert_eq!(seen, expected);
    let (name, pw, ph, _) = app.last_png().cloned().expect("a PNG was saved");
    assert!(
        name.starts_with("attlab-p1-seed1-t") && name.ends_with("-plots.png"),
        "{name}"
    );
    let bytes = std::fs::read(dir.join(&name)).expect("the file is on disk");
    let mut reader = png::Decoder::new(std::io::Cursor::new(bytes))
        .read_info()
        .expect("a PNG");
    let mut buf = vec![0; reader.output_buffer_size().expect("fits")];
    let info = reader.next_frame(&mut buf).expect("one frame");
    assert_eq!((info.width as usize, info.height as usize), (pw, ph));
    // One crop of the plot area per tab, stacked with gaps: taller than n crops of 100 px.
    assert!(
        ph > all_tabs.len() * 100,
        "{pw}×{ph} for {} tabs",
        all_tabs.len()
    );
    assert!(pw > 500 && pw <= w, "width {pw}");
    // The top-left pixel comes from the frame (red 200), not from the padding.
    assert_eq!(buf[0], 200, "top-left pixel {:?}", &buf[0..4]);
    assert!(
        app.state
            .messages()
            .iter()
            .any(|m| !m.is_error && m.text.contains("pixels")),
        "a message says where the PNG went"
    );
}

/// A view's own PNG button shows while the pointer is over the view and saves that view
/// alone: p1's dial, cut to the dial's rect.
#[test]
fn a_views_png_button_saves_that_view() {
    let (mut h, dir) = harness_saving("p1", "png-view");
    h.run();
    assert!(
        h.query_by_label("PNG").is_none(),
        "no view button without the pointer over a view"
    );
    // p1's top row: the body, the dial, the phase portrait; the dial is right of centre.
    h.event(egui::Event::PointerMoved(egui::pos2(950.0, 200.0)));
    h.run();
    h.get_by_label("PNG").click();
    let frame_image =
        egui::ColorImage::new([1400, 900], vec![egui::Color32::from_gray(99); 1400 * 900]);
    run_capture(&mut h, &frame_image, 50, |_| {});
    let (name, w, hgt, _) = h.state().last_png().cloned().expect("a PNG was saved");
    assert!(name.ends_with("-dial.png"), "{name}");
    assert!(dir.join(&name).is_file());
    // One view of three in a 1400-pixel window: narrower than a third of it, as tall as the
    // top row.
    assert!(
        (100..1400 / 3).contains(&w) && (200..700).contains(&hgt),
        "{w}×{hgt}"
    );
}

/// Switching the lab while the plots are being captured stops the capture with a message
/// and leaves the new lab on its own first tab (no old tab index carried over).
#[test]
fn switching_the_lab_stops_a_png_capture() {
    let mut h = harness("p2");
    h.run();
    h.key_press(egui::Key::P);
    h.step();
    assert!(
        h.state_mut().capture_mut().is_some(),
        "key p starts a capture"
    );
    let free = labs::find("free-rotation").expect("registered");
    h.state_mut().apply(attlab_web::state::Command::from(
        attlab_web::state::RunCommand::SelectLab(free),
    ));
    h.run();
    let app = h.state_mut();
    assert!(app.capture_mut().is_none(), "the capture stopped");
    assert!(
        app.state
            .messages()
            .iter()
            .any(|m| m.is_error && m.text.contains("the lab changed")),
        "a message says why"
    );
    assert_eq!(app.state.sim().lab().id(), "free-rotation");
    assert!(attlab_web::panels::tabs(&app.state).contains(&app.state.view().plots.tab));
}
