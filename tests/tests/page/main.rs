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
use std::net::{TcpListener, TcpStream};
use std::path::PathBuf;
use std::process::{Child, Command, Stdio};
use std::thread::sleep;
use std::time::{Duration, Instant};

mod a11y;
mod checks;
mod driver;
mod embed;
mod fuzz;
mod lessons;
mod live;
mod replay;
mod screens;
mod soak;
mod touch;
mod travel;
mod workers;

use checks::*;
use driver::*;
use replay::{click_mirrored, eventually, mirror_says};

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
/// Frames the app must have drawn after each load before a test goes on (it runs).
const MIN_FRAMES: f64 = 10.0;
/// Frames the first load must reach (it keeps running; checked once, as the wait for 30
/// frames after every load cost the page tests about 3 s a load, 63 loads).
const STEADY_FRAMES: f64 = 30.0;
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

/// Loads the page, waits for frames, and checks status, console and screenshot.
#[test]
#[ignore = "needs the built site; `cargo xtask test` runs it with ATTLAB_PAGE_URL"]
fn page_renders_without_errors() {
    let url = std::env::var("ATTLAB_PAGE_URL").expect("set ATTLAB_PAGE_URL to the served dist/");
    let start = Instant::now();
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
    let mut problems = steady_problems(&session);
    problems.extend(console_and_screenshot(
        &session,
        "first load",
        "screenshot.png",
    ));
    let base = url.split('#').next().unwrap_or(&url).to_string();
    println!(
        "page test: phase `first load` took {:.1} s",
        start.elapsed().as_secs_f64()
    );
    problems.extend(timed("keyboard walk", || {
        a11y::keyboard_walk_problems(&session, &base)
    }));
    problems.extend(timed("screens", || {
        screens::screen_problems(&session, &base)
    }));
    problems.extend(timed("png export", || png_export_problems(&session, &base)));
    drop(session);
    assert!(
        problems.is_empty(),
        "page test failed:\n  - {}",
        problems.join("\n  - ")
    );
}

/// Problems of the first load: its status once it has drawn [`STEADY_FRAMES`] frames (it
/// keeps drawing), printed.
fn steady_problems(session: &Session<'_>) -> Vec<String> {
    let mut status = wait_for_frames(session);
    let more = STEADY_FRAMES - status["frames"].as_f64().unwrap_or(0.0);
    if more > 0.0 {
        let _ = session.execute(&format!("{LATER_JS} return attlabLater({more}, 30000);"));
        status = session
            .execute(STATUS_SCRIPT)
            .ok()
            .and_then(|v| serde_json::from_str(v.as_str()?).ok())
            .unwrap_or(Value::Null);
    }
    println!("page test: attlabStatus = {status}");
    let mut problems = status_problems(&status);
    let frames = status["frames"].as_f64().unwrap_or(0.0);
    if frames < STEADY_FRAMES {
        problems.push(format!(
            "first load: {frames} frames, want {STEADY_FRAMES} (it stopped drawing)"
        ));
    }
    problems
}

/// The page works with the network cut after one visit: the service worker serves it.
#[test]
#[ignore = "needs the built site; `cargo xtask test` runs it with ATTLAB_DIST"]
fn page_works_offline_after_one_visit() {
    let dist = PathBuf::from(std::env::var("ATTLAB_DIST").expect("set ATTLAB_DIST to dist/"));
    // A server of its own, to cut: attlab-serve closes every connection after its response,
    // so once stopped nothing is left for the reload to wait on.
    let mut server = attlab_serve::start(&dist, 0).expect("serve dist/");
    let url = server.url();
    let driver = Driver::start();
    let session = Session::new(&driver);
    session
        .call("POST", "/url", Some(&json!({ "url": url })))
        .expect("navigate");
    let status = wait_for_frames(&session);
    let mut problems = status_problems(&status);
    wait_for_service_worker(&session);
    // A reload while online, now through the worker: it has this build's wasm and glue and
    // writes neither again. The kept wasm is marked first; the mark must survive (checked
    // at the end with the cache's contents).
    if let Err(e) = async_script(&session, MARK_KEPT_WASM) {
        problems.push(format!("cannot mark the kept wasm: {e}"));
    }
    session.open(&url).expect("reload online");
    problems.extend(
        status_problems(&wait_for_frames(&session))
            .into_iter()
            .map(|p| format!("reload: {p}")),
    );
    let _ = session.console();
    // The wasm and its glue are kept in the HTTP cache (versioned URLs, `immutable`): empty
    // it, so the reload below gets every file from the service worker's cache, as it would
    // once the browser has evicted them. The worker's cache stays.
    if let Err(e) = session.cdp("Network.clearBrowserCache", json!({})) {
        problems.push(format!("cannot clear the HTTP cache: {e}"));
    }
    server.stop();
    // The network is cut: nothing listens on the port any more.
    assert!(
        TcpStream::connect(server.addr).is_err(),
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
    problems.extend(cached_build_problems(&session));
    drop(session);
    assert!(
        problems.is_empty(),
        "offline page test failed:\n  - {}",
        problems.join("\n  - ")
    );
}

/// Waits until the service worker is active (its install cached the site).
fn wait_for_service_worker(session: &Session<'_>) {
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
}

/// Runs an asynchronous script (it calls its last argument with the result).
fn async_script(session: &Session<'_>, script: &str) -> Result<Value, String> {
    session.call(
        "POST",
        "/execute/async",
        Some(&json!({ "script": script, "args": [] })),
    )
}

/// Puts the service worker's kept wasm back with a header `x-attlab-mark`: a worker that
/// wrote the file again on a later load would lose it.
const MARK_KEPT_WASM: &str = "const done = arguments[arguments.length - 1];\
    (async () => { for (const n of await caches.keys()) { const c = await caches.open(n);\
      for (const r of await c.keys()) { if (r.url.includes('/pkg/attlab_web_bg.wasm')) {\
        const kept = await c.match(r); const bytes = await kept.arrayBuffer();\
        await c.put(r, new Response(bytes, { headers: { 'content-type': 'application/wasm', 'x-attlab-mark': 'kept' } }));\
        return done(r.url); } } } done(null); })().catch((e) => done('error: ' + e));";

/// The service worker keeps this build's wasm and glue, under their versioned URLs, and no
/// other build's: each is 6 MB, and another build's glue would not run with this wasm. It
/// wrote the wasm only once: the mark [`MARK_KEPT_WASM`] put on it is still there.
fn cached_build_problems(session: &Session<'_>) -> Vec<String> {
    let script = "const done = arguments[arguments.length - 1];\
        (async () => { const pkg = []; let mark = null;\
          for (const n of await caches.keys()) { const c = await caches.open(n);\
            for (const r of await c.keys()) { const u = new URL(r.url); if (!u.pathname.includes('/pkg/')) continue;\
              pkg.push(u.pathname.split('/').pop() + u.search);\
              if (u.pathname.endsWith('.wasm')) { mark = (await c.match(r)).headers.get('x-attlab-mark'); } } }\
          done({ build: window.attlabBuild, pkg: pkg.sort(), mark }); })().catch((e) => done({ error: String(e) }));";
    let found = match async_script(session, script) {
        Ok(found) => found,
        Err(e) => return vec![format!("offline: cannot read the caches: {e}")],
    };
    let build = found["build"].as_str().unwrap_or("(none)");
    let want = json!([
        format!("attlab_web.js{build}"),
        format!("attlab_web_bg.wasm{build}")
    ]);
    let mut problems = Vec::new();
    if !build.starts_with("?v=") || found["pkg"] != want {
        problems.push(format!(
            "offline: the service worker's pkg/ files are {found}, want {want}"
        ));
    }
    if found["mark"] != json!("kept") {
        problems.push(format!(
            "offline: the service worker wrote the wasm again on a later load (its mark: {})",
            found["mark"]
        ));
    }
    println!(
        "page test (offline): the service worker keeps {}",
        found["pkg"]
    );
    problems
}

/// A step of every lab's lesson from the teacher's link on a projector (see `lessons.rs`).
/// Its own test, so that `cargo xtask test` runs it beside the other page tests (with the
/// soak and the fuzz): it waits on the lessons' own speed more than on the cores.
#[test]
#[ignore = "needs the built site; `cargo xtask test` runs it with ATTLAB_PAGE_URL"]
fn lessons_open_at_their_step_and_pause() {
    page_test("lessons", lessons::lesson_problems);
}

/// A host page on another loopback origin drives the embedded lab by `postMessage`, and
/// one on an origin the link does not allow is refused (see `embed.rs`).
#[test]
#[ignore = "needs the built site; `cargo xtask test` runs it with ATTLAB_PAGE_URL"]
fn embedded_page_is_driven_by_its_host() {
    page_test("embed", |session, base| {
        let mut problems = embed::embed_problems(session, base);
        problems.extend(embed::embed_screenshot(session, base));
        problems
    });
}

/// Every lesson's teacher notes, in both languages, printed to PDF (see `embed.rs`).
#[test]
#[ignore = "needs the built site; `cargo xtask test` runs it with ATTLAB_PAGE_URL"]
fn teacher_notes_print() {
    page_test("teacher notes", embed::teacher_print_problems);
}

/// Paper 2 seeked back by the keyboard and branched (see `travel.rs`).
#[test]
#[ignore = "needs the built site; `cargo xtask test` runs it with ATTLAB_PAGE_URL"]
fn a_run_is_seeked_back_and_branched() {
    page_test("time travel", travel::travel_problems);
}

/// Random clicks, drags, wheel, touches and keys on every lab (see `fuzz.rs`).
#[test]
#[ignore = "needs the built site; `cargo xtask test` runs it with ATTLAB_PAGE_URL"]
fn page_survives_random_input() {
    fuzz::run();
}

/// The soak: one page load, every lab in turn switched by its link in the open tab at the
/// highest speed, twice round, memory sampled; see [`soak::run`].
#[test]
#[ignore = "long: `cargo xtask soak --minutes M` (a 1-minute run is part of `cargo xtask test`)"]
fn soak() {
    soak::run();
}
