//! The page embedded in a host page on another loopback origin, driven by `postMessage`
//! (docs/embed.md), refused from an origin its link does not allow; a screenshot of a lab
//! in a 960×540 frame; and the teacher notes printed to PDF by Chromium.

use super::*;
use std::io::{Read as _, Write as _};

/// The host page: an iframe of the page whose `src` is the host's own query (`?src=…`),
/// the lab's events kept in `window.events`, and `window.send(message)`.
const HOST_HTML: &str = r#"<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>Host page</title>
<style>body { margin: 0; background: #d9dde3; } iframe { border: 0; display: block; margin: 20px; }</style>
</head><body>
<iframe id="lab" width="960" height="540" title="Attitude Lab"></iframe>
<script>
  const frame = document.getElementById('lab');
  frame.src = new URLSearchParams(location.search).get('src');
  const labOrigin = new URL(frame.src).origin;
  window.events = [];
  addEventListener('message', (e) => { if (e.origin === labOrigin) window.events.push(e.data); });
  window.send = (message) => frame.contentWindow.postMessage(message, labOrigin);
</script>
</body></html>"#;

/// Serves [`HOST_HTML`] on a free loopback port for the test's life; returns the port.
fn host_server() -> u16 {
    let listener = TcpListener::bind("127.0.0.1:0").expect("bind the host's port");
    let port = listener.local_addr().expect("host address").port();
    std::thread::spawn(move || {
        for stream in listener.incoming().flatten() {
            let mut stream = stream;
            let mut request = [0u8; 4096];
            let _ = stream.read(&mut request);
            let reply = format!(
                "HTTP/1.1 200 OK\r\nContent-Type: text/html; charset=utf-8\r\nContent-Length: {}\r\nConnection: close\r\n\r\n{HOST_HTML}",
                HOST_HTML.len()
            );
            let _ = stream.write_all(reply.as_bytes());
        }
    });
    port
}

/// The host page at `host` embedding `page` + `#fragment`.
fn host_url(host: &str, page: &str, fragment: &str) -> String {
    let src: String =
        form_urlencoded::byte_serialize(format!("{page}#{fragment}").as_bytes()).collect();
    format!("{host}/?src={src}")
}

/// The events the host has heard so far.
fn events(session: &Session<'_>) -> Vec<Value> {
    session
        .execute("return JSON.stringify(window.events || []);")
        .ok()
        .and_then(|v| v.as_str().and_then(|t| serde_json::from_str(t).ok()))
        .unwrap_or_default()
}

/// Waits (up to `secs`) for an event `found` accepts; returns it.
fn wait_event(session: &Session<'_>, secs: u64, found: impl Fn(&Value) -> bool) -> Option<Value> {
    let deadline = Instant::now() + Duration::from_secs(secs);
    while Instant::now() < deadline {
        if let Some(e) = events(session).into_iter().find(|e| found(e)) {
            return Some(e);
        }
        sleep(Duration::from_millis(250));
    }
    None
}

/// Sends `message` from the host page.
fn send(session: &Session<'_>, message: &Value) -> Result<(), String> {
    session
        .execute(&format!("window.send({message}); return true;"))
        .map(|_| ())
}

/// The host on an allowed origin drives the lab; one on another origin is refused.
pub(crate) fn embed_problems(session: &Session<'_>, base: &str) -> Vec<String> {
    let mut problems = Vec::new();
    let port = host_server();
    let allowed = format!("http://127.0.0.1:{port}");
    let fragment = format!("lab=p4&embed=1&origin={allowed}");
    if let Err(e) = session.open(&host_url(&allowed, base, &fragment)) {
        return vec![format!("opening the host page: {e}")];
    }
    let Some(ready) = wait_event(session, 120, |e| e["type"] == "ready") else {
        return vec![format!(
            "no ready event from the embedded lab: heard {:?}",
            events(session)
        )];
    };
    println!("page test: embed: ready {ready}");
    let lesson = attlab::labs::find("p4")
        .and_then(|l| l.lesson())
        .expect("p4 has a lesson");
    let asks = 1
        + (lesson.steps.iter())
            .position(|s| s.question.is_some())
            .expect("a question");
    let requests = [
        json!({"api": 1, "type": "lesson", "step": asks, "id": 1}),
        json!({"api": 1, "type": "answer", "choice": 1, "id": 2}),
        json!({"api": 1, "type": "lesson", "step": 2, "id": 3}),
        json!({"api": 1, "type": "set", "params": {"gamma": 0.02}, "id": 4}),
        json!({"api": 1, "type": "pause", "id": 5}),
        json!({"api": 1, "type": "fly", "id": 6}),
        json!({"api": 1, "type": "get", "id": 7}),
    ];
    for r in &requests {
        if let Err(e) = send(session, r) {
            problems.push(format!("sending {r}: {e}"));
        }
    }
    for id in 1..=5 {
        if wait_event(session, 30, |e| e["type"] == "ok" && e["re"] == id).is_none() {
            problems.push(format!(
                "request {id} was not answered ok: {:?}",
                events(session)
            ));
        }
    }
    match wait_event(session, 30, |e| e["type"] == "answered") {
        Some(e) if e["step"] == asks && e["answer"] == 1 && e["supported"].is_u64() => {}
        other => problems.push(format!("answered event: {other:?}")),
    }
    match wait_event(session, 30, |e| e["re"] == 6) {
        Some(e) if e["type"] == "error" && e["code"] == "unknown-type" => {}
        other => problems.push(format!("a bad message's answer: {other:?}")),
    }
    match wait_event(session, 30, |e| e["type"] == "state") {
        Some(s)
            if s["re"] == 7
                && s["lesson"]["step"] == 2
                && s["params"]["gamma"] == 0.02
                && s["playing"] == false => {}
        other => problems.push(format!("the state after the requests: {other:?}")),
    }
    problems.extend(tick_problems(session));
    problems.extend(console_problems(&session.console().unwrap_or_default()));
    problems.extend(refused_problems(session, base, port, &fragment));
    problems
}

/// Ticks go on while the lab is paused (a frame a second for the host), with each filter's
/// error.
fn tick_problems(session: &Session<'_>) -> Vec<String> {
    let mut problems = Vec::new();
    let ticks = |session: &Session<'_>| {
        events(session)
            .into_iter()
            .filter(|e| e["type"] == "tick")
            .count()
    };
    let before = ticks(session);
    match wait_event(session, 30, |e| {
        e["type"] == "tick" && e["step"] == 2 && e["playing"] == false
    }) {
        Some(t) if t["errors_deg"].as_object().is_some_and(|m| !m.is_empty()) => {}
        other => problems.push(format!("a tick after the pause: {other:?}")),
    }
    sleep(Duration::from_secs(2));
    if ticks(session) <= before {
        problems.push("the ticks stopped".into());
    }
    problems
}

/// A host on `localhost` (not the origin the link allows) is answered only with
/// `origin-not-allowed` and hears no events.
fn refused_problems(session: &Session<'_>, base: &str, port: u16, fragment: &str) -> Vec<String> {
    let mut problems = Vec::new();
    let other = format!("http://localhost:{port}");
    if let Err(e) = session.open(&host_url(&other, base, fragment)) {
        return vec![format!("opening the refused host: {e}")];
    }
    let deadline = Instant::now() + Duration::from_secs(120);
    let mut refused = None;
    while refused.is_none() && Instant::now() < deadline {
        let _ = send(session, &json!({"api": 1, "type": "play", "id": 9}));
        refused = wait_event(session, 1, |e| e["type"] == "error");
    }
    match refused {
        Some(e) if e["code"] == "origin-not-allowed" && e["re"].is_null() => {
            println!("page test: embed: refused from {other}: {}", e["message"]);
        }
        got => problems.push(format!(
            "a host on {other} was not refused cleanly: {got:?}"
        )),
    }
    sleep(Duration::from_secs(2));
    let heard: Vec<Value> = (events(session).into_iter())
        .filter(|e| e["type"] != "error")
        .collect();
    if !heard.is_empty() {
        problems.push(format!("a refused host heard events: {heard:?}"));
    }
    problems.extend(console_problems(&session.console().unwrap_or_default()));
    problems
}

/// Paper 3's lesson step 3 in a 960×540 frame, answered and run to its pause: the
/// screenshot docs/embed.md shows (`target/page-test/screens/embed-p3.png`).
pub(crate) fn embed_screenshot(session: &Session<'_>, base: &str) -> Vec<String> {
    let port = host_server();
    let host = format!("http://127.0.0.1:{port}");
    let fragment = format!("lesson=p3&step=3&lang=en&embed=1&origin={host}");
    if let Err(e) = session.set_viewport(Some((1000, 580)), false) {
        return vec![format!("viewport: {e}")];
    }
    if let Err(e) = session.open(&host_url(&host, base, &fragment)) {
        return vec![format!("opening the host page: {e}")];
    }
    if wait_event(session, 120, |e| e["type"] == "ready").is_none() {
        return vec!["no ready event for the screenshot".into()];
    }
    let _ = send(session, &json!({"api": 1, "type": "answer", "choice": 2}));
    let paused = wait_event(session, 240, |e| {
        e["type"] == "tick" && e["playing"] == false && e["t"].as_f64().is_some_and(|t| t >= 29.9)
    });
    let mut problems = Vec::new();
    if paused.is_none() {
        problems.push("the embedded step did not reach its pause at 30 s".into());
    }
    sleep(Duration::from_secs(1));
    match session.screenshot() {
        Ok(png) => {
            let path = out_dir().join("screens").join("embed-p3.png");
            let _ = std::fs::create_dir_all(path.parent().unwrap_or(&out_dir()));
            match std::fs::write(&path, png) {
                Ok(()) => println!("page test: embed: screenshot {}", path.display()),
                Err(e) => problems.push(format!("writing {}: {e}", path.display())),
            }
        }
        Err(e) => problems.push(format!("screenshot: {e}")),
    }
    let _ = session.set_viewport(None, false);
    problems
}

/// Every lab's teacher notes in both languages, printed to PDF by Chromium: each prints,
/// and its page count is reported (`target/page-test/teacher/` keeps the PDFs).
pub(crate) fn teacher_print_problems(session: &Session<'_>, base: &str) -> Vec<String> {
    let mut problems = Vec::new();
    let folder = out_dir().join("teacher");
    let _ = std::fs::create_dir_all(&folder);
    let labs: Vec<&str> = (attlab::labs::all().iter())
        .filter(|l| l.lesson().is_some())
        .map(|l| l.id())
        .collect();
    for lang in ["en", "ru"] {
        for lab in &labs {
            let url = format!("{base}teacher/{lang}/{lab}.html");
            if let Err(e) = session.open(&url) {
                problems.push(format!("{url}: {e}"));
                continue;
            }
            let title = session
                .execute("return document.title;")
                .unwrap_or_default();
            let pdf = session
                .cdp_value(
                    "Page.printToPDF",
                    json!({ "printBackground": false, "preferCSSPageSize": true }),
                )
                .and_then(|v| {
                    let data = v["data"].as_str().ok_or("no data")?.to_string();
                    base64::engine::general_purpose::STANDARD
                        .decode(data)
                        .map_err(|e| e.to_string())
                });
            match pdf {
                Ok(bytes) => {
                    let pages = pdf_pages(&bytes);
                    println!(
                        "page test: teacher notes {lang}/{lab}: {title} — {pages} A4 pages, {} kB",
                        bytes.len() / 1024
                    );
                    if pages == 0 || pages > 20 {
                        problems.push(format!("{url} printed to {pages} pages"));
                    }
                    let _ = std::fs::write(folder.join(format!("{lab}-{lang}.pdf")), bytes);
                }
                Err(e) => problems.push(format!("{url}: printing: {e}")),
            }
        }
    }
    problems.extend(console_problems(&session.console().unwrap_or_default()));
    problems
}

/// The number of pages of a PDF: its `/Type /Page` objects (not `/Pages`).
fn pdf_pages(pdf: &[u8]) -> usize {
    let text = String::from_utf8_lossy(pdf);
    text.match_indices("/Type /Page")
        .filter(|(i, m)| !text[i + m.len()..].starts_with('s'))
        .count()
}
