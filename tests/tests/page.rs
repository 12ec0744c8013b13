//! Page test: loads the built site in headless Chromium through chromedriver (W3C WebDriver
//! over HTTP), waits until the app has drawn frames, fails on app errors, severe console
//! entries or panics, and checks that a screenshot is not blank.
//!
//! Ignored in the normal run: `cargo xtask test` builds `dist/`, serves it and runs
//! `cargo test -p attlab-tests --test page -- --ignored --nocapture` with `ATTLAB_PAGE_URL`
//! (and `ATTLAB_DIST` for the offline check, which serves `dist/` itself so that it can cut
//! the network: it stops its server and loads the page again).
#![cfg(not(target_arch = "wasm32"))]

use base64::Engine as _;
use serde_json::{Value, json};
use std::collections::HashSet;
use std::io::{BufRead, BufReader, Write};
use std::net::{TcpListener, TcpStream};
use std::path::PathBuf;
use std::process::{Child, Command, Stdio};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::thread::sleep;
use std::time::{Duration, Instant};

/// The real Chromium binary (`/usr/bin/chromium` is a wrapper script).
const CHROMIUM: &str = "/usr/lib/chromium/chromium";
/// Debian's chromedriver; `CHROMEDRIVER` overrides it.
const DEFAULT_CHROMEDRIVER: &str = "/usr/bin/chromedriver";
/// Headless flags: software WebGL2 (SwiftShader), no network chatter, fixed window.
const CHROMIUM_ARGS: &[&str] = &[
    "--headless=new",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-dev-shm-usage",
    "--enable-unsafe-swiftshader",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--window-size=1280,800",
    // Unquantised `performance.memory` for the soak.
    "--enable-precise-memory-info",
];
/// Frames the app must have drawn.
const MIN_FRAMES: f64 = 30.0;
/// How long to wait for those frames.
const FRAME_TIMEOUT: Duration = Duration::from_secs(60);
/// Screenshot checks: a blank or near-blank canvas fails them.
const MIN_LUMA_STD_DEV: f64 = 5.0;
/// Fewest distinct RGB colours the screenshot must have.
const MIN_DISTINCT_COLOURS: usize = 64;
/// Reads `window.attlabStatus` as JSON text (or null before the app runs).
const STATUS_SCRIPT: &str =
    "return window.attlabStatus ? JSON.stringify(window.attlabStatus) : null;";

/// The workspace's `target/page-test/` folder (screenshot and chromedriver log).
fn out_dir() -> PathBuf {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..");
    let dir = root.join("target").join("page-test");
    std::fs::create_dir_all(&dir).expect("create target/page-test");
    dir.canonicalize().unwrap_or(dir)
}

/// A free loopback port (bound, then released for chromedriver).
fn free_port() -> u16 {
    let listener = TcpListener::bind("127.0.0.1:0").expect("bind a loopback port");
    listener.local_addr().expect("local address").port()
}

/// A chromedriver child process, killed on drop, and an HTTP client for it.
struct Driver {
    child: Child,
    base: String,
    agent: ureq::Agent,
}

impl Driver {
    /// Starts chromedriver on a free port and waits until it reports ready.
    fn start() -> Driver {
        let exe = std::env::var("CHROMEDRIVER").unwrap_or_else(|_| DEFAULT_CHROMEDRIVER.into());
        let port = free_port();
        let log = out_dir().join("chromedriver.log");
        let child = Command::new(&exe)
            .arg(format!("--port={port}"))
            .arg(format!("--log-path={}", log.display()))
            .stdin(Stdio::null())
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .unwrap_or_else(|e| panic!("cannot start {exe}: {e}"));
        let agent = ureq::AgentBuilder::new()
            .timeout(Duration::from_secs(120))
            .build();
        let driver = Driver {
            child,
            base: format!("http://127.0.0.1:{port}"),
            agent,
        };
        let deadline = Instant::now() + Duration::from_secs(20);
        loop {
            let ready = driver
                .call("GET", "/status", None)
                .is_ok_and(|v| v["ready"] == true);
            if ready {
                return driver;
            }
            assert!(
                Instant::now() < deadline,
                "chromedriver did not get ready on port {port}"
            );
            sleep(Duration::from_millis(100));
        }
    }

    /// One WebDriver call; returns the response's `value`.
    fn call(&self, method: &str, path: &str, body: Option<&Value>) -> Result<Value, String> {
        let request = self.agent.request(method, &format!("{}{path}", self.base));
        let response = match body {
            Some(body) => request.send_json(body),
            None => request.call(),
        };
        match response {
            Ok(response) => response
                .into_json::<Value>()
                .map(|mut v| v["value"].take())
                .map_err(|e| format!("{method} {path}: bad JSON: {e}")),
            Err(ureq::Error::Status(code, response)) => {
                let text = response.into_string().unwrap_or_default();
                Err(format!("{method} {path}: HTTP {code}: {text}"))
            }
            Err(e) => Err(format!("{method} {path}: {e}")),
        }
    }
}

impl Drop for Driver {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// A browser session, deleted on drop (which also closes Chromium).
struct Session<'a> {
    driver: &'a Driver,
    id: String,
}

impl<'a> Session<'a> {
    /// Opens headless Chromium with browser console logging on.
    fn new(driver: &'a Driver) -> Session<'a> {
        let caps = json!({ "capabilities": { "alwaysMatch": {
            "browserName": "chrome",
            "goog:chromeOptions": { "binary": CHROMIUM, "args": CHROMIUM_ARGS },
            "goog:loggingPrefs": { "browser": "ALL" },
        }}});
        let value = driver
            .call("POST", "/session", Some(&caps))
            .expect("new session");
        let id = value["sessionId"].as_str().expect("session id").to_string();
        let version = &value["capabilities"]["browserVersion"];
        println!("page test: Chromium {version}, session {id}");
        Session { driver, id }
    }

    /// A call on this session (`path` is relative to `/session/{id}`).
    fn call(&self, method: &str, path: &str, body: Option<&Value>) -> Result<Value, String> {
        self.driver
            .call(method, &format!("/session/{}{path}", self.id), body)
    }

    /// Loads `url` afresh: leaves the page first, since a change of the fragment alone
    /// does not reload it.
    fn open(&self, url: &str) -> Result<(), String> {
        let _ = self.call("POST", "/url", Some(&json!({ "url": "about:blank" })));
        self.call("POST", "/url", Some(&json!({ "url": url })))
            .map(|_| ())
    }

    /// Runs a synchronous script and returns its result.
    fn execute(&self, script: &str) -> Result<Value, String> {
        self.call(
            "POST",
            "/execute/sync",
            Some(&json!({ "script": script, "args": [] })),
        )
    }

    /// The browser console entries since the last call (chromedriver's log endpoint).
    fn console(&self) -> Result<Vec<Value>, String> {
        let value = self.call("POST", "/se/log", Some(&json!({ "type": "browser" })))?;
        value
            .as_array()
            .cloned()
            .ok_or_else(|| format!("log is not an array: {value}"))
    }

    /// A PNG screenshot of the viewport.
    fn screenshot(&self) -> Result<Vec<u8>, String> {
        let value = self.call("GET", "/screenshot", None)?;
        let text = value.as_str().ok_or("screenshot is not a string")?;
        base64::engine::general_purpose::STANDARD
            .decode(text)
            .map_err(|e| e.to_string())
    }
}

impl Drop for Session<'_> {
    fn drop(&mut self) {
        if let Err(e) = self
            .driver
            .call("DELETE", &format!("/session/{}", self.id), None)
        {
            eprintln!("page test: deleting the session failed: {e}");
        }
    }
}

/// Polls `window.attlabStatus` until it reports `MIN_FRAMES` frames or the timeout passes.
/// Returns the last status seen (`Null` if the app never set one).
fn wait_for_frames(session: &Session<'_>) -> Value {
    let start = Instant::now();
    let mut status = Value::Null;
    while start.elapsed() < FRAME_TIMEOUT {
        match session.execute(STATUS_SCRIPT) {
            Ok(Value::String(text)) => status = serde_json::from_str(&text).unwrap_or(Value::Null),
            Ok(_) => {}
            Err(e) => println!("page test: reading attlabStatus failed: {e}"),
        }
        if status["frames"].as_f64().is_some_and(|f| f >= MIN_FRAMES) {
            println!(
                "page test: {MIN_FRAMES} frames after {:.1} s",
                start.elapsed().as_secs_f64()
            );
            break;
        }
        sleep(Duration::from_millis(250));
    }
    status
}

/// Time from the start of navigation to the first drawn frame (ms, `performance.now()` when
/// a poll every 20 ms first sees a frame; an upper bound by at most one poll).
fn first_frame_ms(session: &Session<'_>) -> Option<f64> {
    let start = Instant::now();
    while start.elapsed() < FRAME_TIMEOUT {
        if let Ok(Value::Number(ms)) = session.execute(
            "return window.attlabStatus && window.attlabStatus.frames >= 1 ? performance.now() : null;",
        ) {
            return ms.as_f64();
        }
        sleep(Duration::from_millis(20));
    }
    None
}

/// A static file server on a loopback port for `root`, which the test can stop (the
/// network cut).
struct StaticServer {
    port: u16,
    stop: Arc<AtomicBool>,
    thread: Option<std::thread::JoinHandle<()>>,
}

impl StaticServer {
    fn start(root: PathBuf) -> StaticServer {
        let listener = TcpListener::bind("127.0.0.1:0").expect("bind a loopback port");
        let port = listener.local_addr().expect("local address").port();
        listener
            .set_nonblocking(true)
            .expect("non-blocking listener");
        let stop = Arc::new(AtomicBool::new(false));
        let flag = stop.clone();
        let thread = std::thread::spawn(move || {
            while !flag.load(Ordering::SeqCst) {
                match listener.accept() {
                    Ok((stream, _)) => {
                        let root = root.clone();
                        std::thread::spawn(move || serve_one(stream, &root));
                    }
                    Err(e) if e.kind() == std::io::ErrorKind::WouldBlock => {
                        sleep(Duration::from_millis(5));
                    }
                    Err(_) => break,
                }
            }
            // The listener is dropped here: from now on connections are refused.
        });
        StaticServer {
            port,
            stop,
            thread: Some(thread),
        }
    }

    fn url(&self) -> String {
        format!("http://127.0.0.1:{}/", self.port)
    }

    /// Stops accepting; returns once the port is closed.
    fn cut(&mut self) {
        self.stop.store(true, Ordering::SeqCst);
        if let Some(t) = self.thread.take() {
            let _ = t.join();
        }
    }
}

impl Drop for StaticServer {
    fn drop(&mut self) {
        self.cut();
    }
}

/// Answers one request on `stream` with a file under `root` (404 when there is none).
fn serve_one(stream: TcpStream, root: &std::path::Path) {
    let _ = stream.set_nonblocking(false);
    let mut reader = BufReader::new(&stream);
    let mut request = String::new();
    if reader.read_line(&mut request).is_err() {
        return;
    }
    let mut line = String::new();
    while reader.read_line(&mut line).is_ok_and(|n| n > 2) {
        line.clear();
    }
    let path = request.split_whitespace().nth(1).unwrap_or("/");
    let path = path
        .split(['?', '#'])
        .next()
        .unwrap_or("/")
        .trim_start_matches('/');
    let path = if path.is_empty() { "index.html" } else { path };
    let file = root.join(path);
    let inside = !path.split('/').any(|c| c == "..");
    let (status, body) = match std::fs::read(&file) {
        Ok(b) if inside => ("200 OK", b),
        _ => ("404 Not Found", b"not found".to_vec()),
    };
    let kind = match file.extension().and_then(|e| e.to_str()) {
        Some("html") => "text/html; charset=utf-8",
        Some("js") => "text/javascript",
        Some("wasm") => "application/wasm",
        Some("json") => "application/json",
        Some("png") => "image/png",
        _ => "application/octet-stream",
    };
    let mut out = &stream;
    let _ = write!(
        out,
        "HTTP/1.1 {status}\r\nContent-Type: {kind}\r\nContent-Length: {}\r\nConnection: close\r\n\r\n",
        body.len()
    );
    let _ = out.write_all(&body);
}

/// Problems with the app's own status object.
fn status_problems(status: &Value) -> Vec<String> {
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
fn console_problems(entries: &[Value]) -> Vec<String> {
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
fn rgb_pixels(png_bytes: &[u8]) -> Result<Vec<[u8; 3]>, String> {
    let mut decoder = png::Decoder::new(png_bytes);
    decoder.set_transformations(png::Transformations::normalize_to_color8());
    let mut reader = decoder.read_info().map_err(|e| e.to_string())?;
    let mut buffer = vec![0; reader.output_buffer_size()];
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
fn screenshot_problems(png_bytes: &[u8]) -> Vec<String> {
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
fn console_and_screenshot(session: &Session<'_>, tag: &str, file: &str) -> Vec<String> {
    let mut problems = Vec::new();
    match session.console() {
        Ok(entries) => problems.extend(console_problems(&entries)),
        Err(e) => problems.push(format!("reading the console log failed: {e}")),
    }
    match session.screenshot() {
        Ok(png_bytes) => {
            let path = out_dir().join(file);
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

/// Loads the page, waits for frames, and checks status, console and screenshot.
#[test]
#[ignore = "needs the built site; `cargo xtask test` runs it with ATTLAB_PAGE_URL"]
fn page_renders_without_errors() {
    let url = std::env::var("ATTLAB_PAGE_URL").expect("set ATTLAB_PAGE_URL to the served dist/");
    let driver = Driver::start();
    let session = Session::new(&driver);
    session
        .call("POST", "/url", Some(&json!({ "url": url })))
        .expect("navigate");
    println!("page test: loaded {url}");
    match first_frame_ms(&session) {
        Some(ms) => {
            // The breakdown index.html records: bundle imported, wasm instantiated, app started.
            let timings = session
                .execute("return JSON.stringify(window.attlabTimings || {});")
                .unwrap_or(Value::Null);
            println!(
                "page test: first frame {ms:.0} ms after navigation started (timings {timings})"
            );
        }
        None => println!("page test: no first frame within {FRAME_TIMEOUT:?}"),
    }
    let status = wait_for_frames(&session);
    println!("page test: attlabStatus = {status}");
    let mut problems = status_problems(&status);
    problems.extend(console_and_screenshot(
        &session,
        "first load",
        "screenshot.png",
    ));
    // Every lab by its URL: the first frames, the console and a screenshot of each.
    let base = url.split('#').next().unwrap_or(&url).to_string();
    for lab in attlab::labs::all() {
        let id = lab.id();
        if let Err(e) = session.open(&format!("{base}#lab={id}")) {
            problems.push(format!("{id}: navigate failed: {e}"));
            continue;
        }
        let status = wait_for_frames(&session);
        println!("page test: #lab={id}: attlabStatus = {status}");
        problems.extend(
            status_problems(&status)
                .into_iter()
                .map(|p| format!("#lab={id}: {p}")),
        );
        if status["lab"].as_str() != Some(id) {
            problems.push(format!("#lab={id} opened lab {:?}", status["lab"]));
        }
        problems.extend(console_and_screenshot(
            &session,
            &format!("#lab={id}"),
            &format!("screenshot-{id}.png"),
        ));
    }
    // Presenter mode from its link: frames, no console error, and a screenshot.
    match session.open(&format!("{base}#lab=p3&presenter=1")) {
        Ok(_) => {
            let status = wait_for_frames(&session);
            problems.extend(
                status_problems(&status)
                    .into_iter()
                    .map(|p| format!("presenter: {p}")),
            );
            problems.extend(console_and_screenshot(
                &session,
                "presenter",
                "screenshot-presenter.png",
            ));
        }
        Err(e) => problems.push(format!("presenter: navigate failed: {e}")),
    }
    problems.extend(png_export_problems(&session, &base));
    drop(session);
    assert!(
        problems.is_empty(),
        "page test failed:\n  - {}",
        problems.join("\n  - ")
    );
}

/// Presses `key` (KeyboardEvent `key` and `code`) on the app's canvas, focusing it first
/// (eframe reads keys only while its canvas has the focus).
fn press_key(session: &Session<'_>, key: &str, code: &str) -> Result<(), String> {
    session.execute(
        "const c = document.querySelector('canvas'); c.focus(); \
         c.dispatchEvent(new FocusEvent('focus'));",
    )?;
    sleep(Duration::from_millis(300));
    session.execute(&format!(
        "const c = document.querySelector('canvas'); \
         for (const type of ['keydown', 'keyup']) {{ \
           c.dispatchEvent(new KeyboardEvent(type, {{ key: '{key}', code: '{code}', bubbles: true }})); \
         }}"
    ))?;
    Ok(())
}

/// Key p on p1 saves a PNG of every plot tab: the status reports a plots picture taller
/// than one tab (the tabs are stacked) within 30 s.
fn png_export_problems(session: &Session<'_>, base: &str) -> Vec<String> {
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

/// The page works with the network cut after one visit: the service worker serves it.
#[test]
#[ignore = "needs the built site; `cargo xtask test` runs it with ATTLAB_DIST"]
fn page_works_offline_after_one_visit() {
    let dist = PathBuf::from(std::env::var("ATTLAB_DIST").expect("set ATTLAB_DIST to dist/"));
    let mut server = StaticServer::start(dist);
    let url = server.url();
    let driver = Driver::start();
    let session = Session::new(&driver);
    session
        .call("POST", "/url", Some(&json!({ "url": url })))
        .expect("navigate");
    let status = wait_for_frames(&session);
    let mut problems = status_problems(&status);
    // Wait until the service worker is active (its install cached the site).
    let start = Instant::now();
    let mut ready = false;
    while start.elapsed() < FRAME_TIMEOUT && !ready {
        ready = session
            .execute("return window.attlabOfflineReady === true;")
            .is_ok_and(|v| v == Value::Bool(true));
        sleep(Duration::from_millis(100));
    }
    assert!(ready, "the service worker never became ready");
    println!(
        "page test (offline): service worker ready after {:.1} s",
        start.elapsed().as_secs_f64()
    );
    let _ = session.console();
    server.cut();
    // The network is cut: nothing listens on the port any more.
    assert!(
        TcpStream::connect(("127.0.0.1", server.port)).is_err(),
        "the server still answers"
    );
    session
        .open(&format!("{url}#lab=p4"))
        .expect("navigate offline");
    let status = wait_for_frames(&session);
    println!("page test (offline): attlabStatus = {status}");
    problems.extend(
        status_problems(&status)
            .into_iter()
            .map(|p| format!("offline: {p}")),
    );
    if status["lab"].as_str() != Some("p4") {
        problems.push(format!("offline: #lab=p4 opened lab {:?}", status["lab"]));
    }
    problems.extend(console_and_screenshot(
        &session,
        "offline",
        "screenshot-offline.png",
    ));
    drop(session);
    assert!(
        problems.is_empty(),
        "offline page test failed:\n  - {}",
        problems.join("\n  - ")
    );
}

/// One memory sample of the soak.
struct Sample {
    at_s: f64,
    lab: String,
    wasm_bytes: f64,
    js_heap_bytes: f64,
    recorder_bytes: f64,
    sim_steps: f64,
}

/// The soak: one page load, every lab in turn switched by its link in the open tab at the
/// highest speed, twice round, the JS heap and the wasm memory sampled (every minute, or more
/// often in a short soak). The first round sets the page's high-water mark (each lab's own
/// working set; wasm memory never shrinks), which is reported; the second round must not
/// grow beyond the recorder's budget — a leak would. Fails on that growth, any console
/// error, an app error, or a page that stopped simulating.
#[test]
#[ignore = "long: `cargo xtask soak --minutes M` (a 2-minute run is part of `cargo xtask test`)"]
fn soak() {
    let url = std::env::var("ATTLAB_PAGE_URL").expect("set ATTLAB_PAGE_URL to the served dist/");
    let minutes: f64 = std::env::var("ATTLAB_SOAK_MINUTES")
        .ok()
        .and_then(|m| m.parse().ok())
        .filter(|m: &f64| *m > 0.0)
        .unwrap_or(2.0);
    let base = url.split('#').next().unwrap_or(&url).to_string();
    let labs = attlab::labs::all();
    let total = Duration::from_secs_f64(minutes * 60.0);
    let rounds = 2;
    let per_lab = total / (rounds * labs.len() as u32);
    let every = Duration::from_secs(60).min(per_lab / 2);
    let mut end_of_first_round: Option<usize> = None;
    let driver = Driver::start();
    let session = Session::new(&driver);
    let first = labs[0].id();
    session
        .open(&format!("{base}#lab={first}&speed=1000"))
        .expect("navigate");
    let status = wait_for_frames(&session);
    let mut problems = status_problems(&status);
    let start = Instant::now();
    let mut samples: Vec<Sample> = Vec::new();
    let sample = |session: &Session<'_>, lab: &str| -> Result<Sample, String> {
        let v = session.execute(
            "const s = window.attlabStatus || {}; return JSON.stringify({ lab: s.lab, wasm: s.wasmBytes, rec: s.recorderBytes, steps: s.simSteps, errors: s.errors, js: performance.memory ? performance.memory.usedJSHeapSize : null });",
        )?;
        let v: Value =
            serde_json::from_str(v.as_str().unwrap_or("{}")).map_err(|e| e.to_string())?;
        if let Some(errors) = v["errors"].as_array().filter(|e| !e.is_empty()) {
            return Err(format!("app errors: {errors:?}"));
        }
        if v["lab"].as_str() != Some(lab) {
            return Err(format!("expected lab {lab}, the page shows {:?}", v["lab"]));
        }
        let num = |k: &str| v[k].as_f64().ok_or(format!("no {k} in the status: {v}"));
        Ok(Sample {
            at_s: start.elapsed().as_secs_f64(),
            lab: lab.to_string(),
            wasm_bytes: num("wasm")?,
            js_heap_bytes: num("js")?,
            recorder_bytes: num("rec")?,
            sim_steps: num("steps")?,
        })
    };
    let order: Vec<_> = (0..rounds as usize).flat_map(|_| labs.iter()).collect();
    for (k, lab) in order.iter().enumerate() {
        let id = lab.id();
        if k == labs.len() {
            end_of_first_round = samples.len().checked_sub(1);
        }
        if k > 0 {
            // A link pasted into the open tab: the app switches lab without a reload.
            let script = format!("location.hash = 'lab={id}&speed=1000'; return true;");
            if let Err(e) = session.execute(&script) {
                problems.push(format!("{id}: switching failed: {e}"));
            }
        }
        let lab_start = Instant::now();
        let mut steps_before: Option<f64> = None;
        while lab_start.elapsed() < per_lab {
            sleep(every.min(per_lab.saturating_sub(lab_start.elapsed())));
            match sample(&session, id) {
                Ok(s) => {
                    if steps_before.is_some_and(|b| s.sim_steps <= b) {
                        problems.push(format!(
                            "{id}: the simulation stopped at {} steps",
                            s.sim_steps
                        ));
                    }
                    steps_before = Some(s.sim_steps);
                    println!(
                        "soak: {:6.0} s {:14} wasm {:7.1} MiB · JS heap {:6.1} MiB · recorder {:5.1} MiB · {:9.0} steps",
                        s.at_s,
                        s.lab,
                        s.wasm_bytes / 1048576.0,
                        s.js_heap_bytes / 1048576.0,
                        s.recorder_bytes / 1048576.0,
                        s.sim_steps
                    );
                    samples.push(s);
                }
                Err(e) => problems.push(format!("{id}: {e}")),
            }
            match session.console() {
                Ok(entries) => problems.extend(
                    console_problems(&entries)
                        .into_iter()
                        .map(|p| format!("{id}: {p}")),
                ),
                Err(e) => problems.push(format!("{id}: reading the console failed: {e}")),
            }
        }
    }
    drop(session);
    let budget = samples.iter().map(|s| s.recorder_bytes).fold(0.0, f64::max);
    let mib = |b: f64| b / 1048576.0;
    match (
        samples.first(),
        end_of_first_round.and_then(|k| samples.get(k)),
        samples.last(),
    ) {
        (Some(a), Some(m), Some(b)) => {
            let wasm_growth = b.wasm_bytes - m.wasm_bytes;
            let js_growth = b.js_heap_bytes - m.js_heap_bytes;
            println!(
                "soak: {minutes} min, {rounds} rounds over {} labs: first round wasm {:.1} → {:.1} MiB (the high-water mark), second round {:+.1} MiB; JS heap second round {:+.1} MiB (recorder budget {:.1} MiB)",
                labs.len(),
                mib(a.wasm_bytes),
                mib(m.wasm_bytes),
                mib(wasm_growth),
                mib(js_growth),
                mib(budget)
            );
            if wasm_growth.is_nan() || wasm_growth > budget {
                problems.push(format!(
                    "wasm memory grew {wasm_growth} B in the second round, beyond the recorder's budget {budget} B"
                ));
            }
            if js_growth.is_nan() || js_growth > budget {
                problems.push(format!(
                    "JS heap grew {js_growth} B in the second round, beyond the recorder's budget {budget} B"
                ));
            }
        }
        _ => problems.push("too few memory samples for two rounds".into()),
    }
    assert!(
        problems.is_empty(),
        "soak failed:\n  - {}",
        problems.join("\n  - ")
    );
}
