//! chromedriver: the child process, a W3C WebDriver session, frames and keys.

use super::*;

/// A free loopback port (bound, then released for chromedriver).
pub(crate) fn free_port() -> u16 {
    let listener = TcpListener::bind("127.0.0.1:0").expect("bind a loopback port");
    listener.local_addr().expect("local address").port()
}

/// A chromedriver child process, killed on drop, and an HTTP client for it.
pub(crate) struct Driver {
    child: Child,
    base: String,
    agent: ureq::Agent,
}

impl Driver {
    /// Starts chromedriver on a free port and waits until it reports ready.
    pub(crate) fn start() -> Driver {
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
        // Generous: on a loaded 2-core CI machine chromedriver has taken over 5 s to start.
        let deadline = Instant::now() + Duration::from_secs(120);
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
    pub(crate) fn call(
        &self,
        method: &str,
        path: &str,
        body: Option<&Value>,
    ) -> Result<Value, String> {
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
pub(crate) struct Session<'a> {
    driver: &'a Driver,
    id: String,
}

impl<'a> Session<'a> {
    /// Opens headless Chromium with browser console logging on.
    pub(crate) fn new(driver: &'a Driver) -> Session<'a> {
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
    pub(crate) fn call(
        &self,
        method: &str,
        path: &str,
        body: Option<&Value>,
    ) -> Result<Value, String> {
        self.driver
            .call(method, &format!("/session/{}{path}", self.id), body)
    }

    /// Loads `url` afresh: leaves the page first, since a change of the fragment alone
    /// does not reload it.
    pub(crate) fn open(&self, url: &str) -> Result<(), String> {
        let _ = self.call("POST", "/url", Some(&json!({ "url": "about:blank" })));
        self.call("POST", "/url", Some(&json!({ "url": url })))
            .map(|_| ())
    }

    /// Runs a synchronous script and returns its result.
    pub(crate) fn execute(&self, script: &str) -> Result<Value, String> {
        self.call(
            "POST",
            "/execute/sync",
            Some(&json!({ "script": script, "args": [] })),
        )
    }

    /// The browser console entries since the last call (chromedriver's log endpoint).
    pub(crate) fn console(&self) -> Result<Vec<Value>, String> {
        let value = self.call("POST", "/se/log", Some(&json!({ "type": "browser" })))?;
        value
            .as_array()
            .cloned()
            .ok_or_else(|| format!("log is not an array: {value}"))
    }

    /// Emulates a viewport of `width` × `height` CSS pixels (Chromium's DevTools protocol
    /// through chromedriver); `None` ends the emulation.
    /// A `mobile` viewport is a phone's, with touch events on.
    pub(crate) fn set_viewport(
        &self,
        size: Option<(u32, u32)>,
        mobile: bool,
    ) -> Result<(), String> {
        let (cmd, params) = match size {
            Some((width, height)) => (
                "Emulation.setDeviceMetricsOverride",
                json!({ "width": width, "height": height, "deviceScaleFactor": 1,
                        "mobile": mobile }),
            ),
            None => ("Emulation.clearDeviceMetricsOverride", json!({})),
        };
        self.cdp(cmd, params)?;
        let touch = json!({ "enabled": mobile && size.is_some(), "maxTouchPoints": 5 });
        self.cdp("Emulation.setTouchEmulationEnabled", touch)
    }

    /// One command of Chromium's DevTools protocol, through chromedriver.
    pub(crate) fn cdp(&self, cmd: &str, params: Value) -> Result<(), String> {
        self.cdp_value(cmd, params).map(|_| ())
    }

    /// The same, returning the command's result.
    pub(crate) fn cdp_value(&self, cmd: &str, params: Value) -> Result<Value, String> {
        self.call(
            "POST",
            "/goog/cdp/execute",
            Some(&json!({ "cmd": cmd, "params": params })),
        )
    }

    /// A PNG screenshot of the viewport.
    pub(crate) fn screenshot(&self) -> Result<Vec<u8>, String> {
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
/// Returns the last status seen (`Null` if the app never set one). A page that drew too
/// few frames gets what its loader had reached printed, with the console: a page that
/// never started (attlab-serve's tiny_http once left the wasm's request unanswered) says
/// where it stopped.
pub(crate) fn wait_for_frames(session: &Session<'_>) -> Value {
    let status = poll_frames(session);
    if status["frames"].as_f64().is_none_or(|f| f < MIN_FRAMES) {
        print_start_state(session);
    }
    status
}

fn poll_frames(session: &Session<'_>) -> Value {
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

/// Prints what the page's loader got to, for a page that drew too few frames: where the
/// start-up reached (`attlabTimings`), whether the error box shows and what it says, and
/// the console.
fn print_start_state(session: &Session<'_>) {
    let script = "const e = document.getElementById('attlab_error'); \
      const l = document.getElementById('attlab_loading'); \
      return JSON.stringify({ url: location.href, readyState: document.readyState, \
        timings: window.attlabTimings || null, module: !!window.attlabWasmModule, \
        loadingShown: l ? !l.hidden : null, errorShown: e ? !e.hidden : null, \
        errorText: e && !e.hidden ? e.textContent.trim().slice(0, 2000) : null, \
        status: window.attlabStatus || null });";
    match session.execute(script) {
        Ok(state) => println!("page test: the page's loader: {state}"),
        Err(e) => println!("page test: reading the page's loader state failed: {e}"),
    }
    match session.console() {
        Ok(entries) => {
            console_problems(&entries);
        }
        Err(e) => println!("page test: reading the console failed: {e}"),
    }
}

/// JS that defines `attlabLater(n, ms)`: a promise that resolves once the app has drawn `n`
/// more frames, or after `ms`. A script that waits with it waits in the page, in one
/// WebDriver call (each call costs ~0.6 s while SwiftShader keeps both cores busy).
pub(crate) const LATER_JS: &str = "const attlabFrames = () => \
    window.attlabStatus ? window.attlabStatus.frames : 0; \
  const attlabLater = (n, ms) => new Promise(done => { \
    const until = attlabFrames() + n, t0 = performance.now(); \
    const tick = () => (attlabFrames() >= until || performance.now() - t0 > ms) \
      ? done() : requestAnimationFrame(tick); \
    tick(); });\n";

/// Time from the start of navigation to the first drawn frame (ms, `performance.now()` when
/// a poll every 20 ms first sees a frame; an upper bound by at most one poll).
pub(crate) fn first_frame_ms(session: &Session<'_>) -> Option<f64> {
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

/// Presses `key` (KeyboardEvent `key` and `code`) on the app's canvas, focusing it first
/// (eframe reads keys only while its canvas has the focus).
pub(crate) fn press_key(session: &Session<'_>, key: &str, code: &str) -> Result<(), String> {
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
