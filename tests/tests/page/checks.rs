//! What the page tests check: app status, console entries, the screenshot, PNG exports.

use super::*;

/// A page test in its own Chromium: `check` gets a session and the page's address (without
/// its fragment) and returns its problems, timed as phase `name`; the test fails listing them.
pub(crate) fn page_test(name: &str, check: impl FnOnce(&Session<'_>, &str) -> Vec<String>) {
    let url = std::env::var("ATTLAB_PAGE_URL").expect("set ATTLAB_PAGE_URL to the served dist/");
    let base = url.split('#').next().unwrap_or(&url).to_string();
    let driver = Driver::start();
    let session = Session::new(&driver);
    let problems = timed(name, || check(&session, &base));
    drop(session);
    assert!(
        problems.is_empty(),
        "{name} page test failed:\n  - {}",
        problems.join("\n  - ")
    );
}

/// Runs one phase of a page test and prints how long it took (the CI log's breakdown of the
/// page step).
pub(crate) fn timed<T>(phase: &str, body: impl FnOnce() -> T) -> T {
    let start = Instant::now();
    let out = body();
    println!(
        "page test: phase `{phase}` took {:.1} s",
        start.elapsed().as_secs_f64()
    );
    out
}

/// Problems with the app's own status object.
pub(crate) fn status_problems(status: &Value) -> Vec<String> {
    let mut problems = Vec::new();
    let frames = status["frames"].as_f64().unwrap_or(0.0);
    if frames < MIN_FRAMES {
        problems.push(format!(
            "only {frames} frames drawn in {FRAME_TIMEOUT:?} (want {MIN_FRAMES})"
        ));
    }
    match status["errors"].as_array() {
        Some(errors) if errors.is_empty() => {}
        Some(errors) => problems.push(format!("attlabStatus.errors is not empty: {errors:?}")),
        None => problems.push("attlabStatus.errors is missing".into()),
    }
    problems
}

/// Prints console entries; returns problems for SEVERE entries and panics.
pub(crate) fn console_problems(entries: &[Value]) -> Vec<String> {
    println!("page test: {} console entries", entries.len());
    let mut problems = Vec::new();
    for entry in entries {
        let level = entry["level"].as_str().unwrap_or("?");
        let message = entry["message"].as_str().unwrap_or("");
        println!("  console [{level}] {message}");
        if level == "SEVERE" || message.contains("panicked") {
            problems.push(format!("console [{level}] {message}"));
        }
    }
    problems
}

/// Decodes a PNG into 8-bit RGB pixels.
pub(crate) fn rgb_pixels(png_bytes: &[u8]) -> Result<Vec<[u8; 3]>, String> {
    let mut decoder = png::Decoder::new(std::io::Cursor::new(png_bytes));
    decoder.set_transformations(png::Transformations::normalize_to_color8());
    let mut reader = decoder.read_info().map_err(|e| e.to_string())?;
    let size = reader
        .output_buffer_size()
        .ok_or("the PNG is too large for memory")?;
    let mut buffer = vec![0; size];
    let info = reader.next_frame(&mut buffer).map_err(|e| e.to_string())?;
    let channels = info.color_type.samples();
    let pixels = buffer[..info.buffer_size()]
        .chunks_exact(channels)
        .map(|p| match channels {
            1 | 2 => [p[0], p[0], p[0]],
            _ => [p[0], p[1], p[2]],
        });
    Ok(pixels.collect())
}

/// Checks the screenshot is not blank; prints its statistics.
pub(crate) fn screenshot_problems(png_bytes: &[u8]) -> Vec<String> {
    let pixels = match rgb_pixels(png_bytes) {
        Ok(pixels) if !pixels.is_empty() => pixels,
        Ok(_) => return vec!["the screenshot has no pixels".into()],
        Err(e) => return vec![format!("the screenshot is not a PNG: {e}")],
    };
    let luma =
        |p: &[u8; 3]| 0.299 * f64::from(p[0]) + 0.587 * f64::from(p[1]) + 0.114 * f64::from(p[2]);
    #[allow(clippy::cast_precision_loss)]
    let n = pixels.len() as f64;
    let mean = pixels.iter().map(luma).sum::<f64>() / n;
    let std_dev = (pixels.iter().map(|p| (luma(p) - mean).powi(2)).sum::<f64>() / n).sqrt();
    let colours = pixels.iter().collect::<HashSet<_>>().len();
    println!(
        "page test: screenshot luma mean {mean:.1}, std dev {std_dev:.1}, {colours} distinct colours"
    );
    let mut problems = Vec::new();
    if std_dev < MIN_LUMA_STD_DEV {
        problems.push(format!(
            "screenshot looks blank: luma std dev {std_dev:.2} < {MIN_LUMA_STD_DEV}"
        ));
    }
    if colours < MIN_DISTINCT_COLOURS {
        problems.push(format!(
            "screenshot has only {colours} colours (want {MIN_DISTINCT_COLOURS})"
        ));
    }
    problems
}

/// The console's problems since the last read and the screenshot's (saved as
/// `target/page-test/{file}`), each prefixed with `tag`; a console or screenshot that
/// cannot be read is a problem too.
pub(crate) fn console_and_screenshot(session: &Session<'_>, tag: &str, file: &str) -> Vec<String> {
    let mut problems = Vec::new();
    match session.console() {
        Ok(entries) => problems.extend(console_problems(&entries)),
        Err(e) => problems.push(format!("reading the console log failed: {e}")),
    }
    match session.screenshot() {
        Ok(png_bytes) => {
            let path = out_dir().join(file);
            if let Some(dir) = path.parent() {
                std::fs::create_dir_all(dir).expect("make the screenshot's folder");
            }
            std::fs::write(&path, &png_bytes).expect("save the screenshot");
            println!("page test: screenshot saved to {}", path.display());
            problems.extend(screenshot_problems(&png_bytes));
        }
        Err(e) => problems.push(format!("taking a screenshot failed: {e}")),
    }
    problems
        .into_iter()
        .map(|p| format!("{tag}: {p}"))
        .collect()
}

/// Key p on p1 saves a PNG of every plot tab: the status reports a plots picture taller
/// than one tab (the tabs are stacked) within 30 s.
pub(crate) fn png_export_problems(session: &Session<'_>, base: &str) -> Vec<String> {
    if let Err(e) = session.open(&format!("{base}#lab=p1")) {
        return vec![format!("png: navigate failed: {e}")];
    }
    let status = wait_for_frames(session);
    let mut problems: Vec<String> = status_problems(&status)
        .into_iter()
        .map(|p| format!("png: {p}"))
        .collect();
    if let Err(e) = press_key(session, "p", "KeyP") {
        problems.push(format!("png: pressing p failed: {e}"));
        return problems;
    }
    let start = Instant::now();
    let mut png = Value::Null;
    while start.elapsed() < Duration::from_secs(30) && png.is_null() {
        sleep(Duration::from_millis(250));
        if let Ok(Value::String(text)) = session.execute(STATUS_SCRIPT) {
            let status: Value = serde_json::from_str(&text).unwrap_or(Value::Null);
            png = status["lastPng"].clone();
        }
    }
    println!("page test: PNG export: {png}");
    let name = png["name"].as_str().unwrap_or_default();
    let (w, h, n) = (
        png["width"].as_f64().unwrap_or(0.0),
        png["height"].as_f64().unwrap_or(0.0),
        png["bytes"].as_f64().unwrap_or(0.0),
    );
    if !name.starts_with("attlab-p1-") || !name.ends_with("-plots.png") {
        problems.push(format!(
            "png: no plots PNG within 30 s of key p (lastPng = {png})"
        ));
    } else if w < 300.0 || h < 2.0 * 150.0 || n < 5000.0 {
        problems.push(format!(
            "png: {name} is {w}×{h} pixels, {n} bytes: not several stacked plot tabs"
        ));
    }
    problems.extend(console_and_screenshot(session, "png", "screenshot-png.png"));
    problems
}
