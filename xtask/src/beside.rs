//! Runs started beside the others instead of after them, their output in a log printed when
//! they end: the wasm tests beside the site's build (see `suite`), and page tests beside the
//! other page tests: the lessons and the page fuzz in one run (the test runner takes them in
//! the order of their names), the soak in a run of its own at a lower CPU priority. The
//! lessons wait on the clock more than on the cores: they run to their pauses at the lesson's
//! speed, so a slower frame does not make them take much longer. The fuzz is the other kind:
//! eframe runs a UI pass for every press and key it is sent, on the page's one thread, while
//! the page tests beside it mostly wait for SwiftShader's frames, which left a core partly
//! idle: with the fuzz among them the page tests took 433 s with both cores 84 % busy, with
//! it beside them 388 s at 95 % (one machine, one run after the other). The soak keeps each
//! lab for its seconds whatever the cores do, and runs each at the highest speed, so it takes
//! every cycle it is given: run last after the fuzz it held the step for a minute with the
//! page tests done; niced from the start it takes the cycles the others leave (a third
//! Chromium at their priority would slow the frames they count). cargo holds its build
//! directory for as long as its tests run, so the page runs use the page tests' binary
//! itself (built by then).

use crate::cmd::Result;
use std::fs::File;
use std::path::PathBuf;
use std::process::{Child, Command, Stdio};
use std::time::{Duration, SystemTime};

/// A test run in the background: its process, log and start.
pub struct Beside {
    child: Child,
    log: PathBuf,
    start: SystemTime,
    line: String,
}

/// Starts the page tests named `tests` (exact names, run one at a time, in the order of their
/// names, as the test runner sorts them) against `url` in the background, a soak among them
/// running for `soak_minutes`; at `niceness` (as `nice -n`; 0: the caller's priority).
pub fn start(url: &str, soak_minutes: f64, tests: &[&str], niceness: u8) -> Result<Beside> {
    let exe = page_test_binary()?;
    let package = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../tests");
    let dir = package.join("../target/page-test");
    let first = tests.first().copied().unwrap_or("page");
    let log = dir.join(format!("beside-{first}.log"));
    let nice = niceness > 0 && crate::cmd::probe(Command::new("nice").arg("true")).is_some();
    if niceness > 0 && !nice {
        println!("xtask: no `nice` on this machine: {first} runs at the usual priority");
    }
    let mut command = if nice {
        let mut nice = Command::new("nice");
        nice.args(["-n", &niceness.to_string()]).arg(&exe);
        nice
    } else {
        Command::new(&exe)
    };
    command
        .args(["--ignored", "--nocapture", "--exact", "--test-threads=1"])
        .args(tests)
        .env("ATTLAB_PAGE_URL", url)
        .env("ATTLAB_SOAK_MINUTES", soak_minutes.to_string())
        .env("CHROMEDRIVER", crate::tools::CHROMEDRIVER)
        .current_dir(&package);
    spawn(command, log)
}

/// Starts `command` in the background, its stdout and stderr written to `log`.
pub fn spawn(mut command: Command, log: PathBuf) -> Result<Beside> {
    if let Some(dir) = log.parent() {
        std::fs::create_dir_all(dir).map_err(|e| format!("cannot make {}: {e}", dir.display()))?;
    }
    let out = File::create(&log).map_err(|e| format!("cannot write {}: {e}", log.display()))?;
    let err = out.try_clone()?;
    command.stdin(Stdio::null()).stdout(out).stderr(err);
    let line = crate::cmd::describe(&command);
    println!("$ {line} > {} &", log.display());
    let child = command
        .spawn()
        .map_err(|e| format!("could not start `{line}`: {e}"))?;
    Ok(Beside {
        child,
        log,
        start: SystemTime::now(),
        line,
    })
}

impl Beside {
    /// Waits for the run to end; prints its log. Returns whether it passed, its output and
    /// how long it ran: until its log was last written (its closing `test result` line), not
    /// until this wait, which comes after the steps run meanwhile.
    pub fn finish(mut self) -> Result<(bool, String, Duration)> {
        let status = self
            .child
            .wait()
            .map_err(|e| format!("waiting for `{}`: {e}", self.line))?;
        let ended = std::fs::metadata(&self.log).and_then(|m| m.modified());
        let took = ended
            .ok()
            .and_then(|t| t.duration_since(self.start).ok())
            .unwrap_or_default();
        let output = std::fs::read_to_string(&self.log)
            .map_err(|e| format!("cannot read {}: {e}", self.log.display()))?;
        println!("{output}");
        Ok((status.success(), output, took))
    }
}

impl Drop for Beside {
    /// A run still going when its step is abandoned (a failed page test) is stopped with it.
    fn drop(&mut self) {
        if matches!(self.child.try_wait(), Ok(None)) {
            let _ = self.child.kill();
            let _ = self.child.wait();
        }
    }
}

/// The page tests' binary: cargo names it (building it if it is not yet built).
fn page_test_binary() -> Result<PathBuf> {
    let output = crate::cmd::cargo()
        .args(["test", "--workspace", "--test", "page", "--no-run"])
        .args(["--message-format", "json-render-diagnostics"])
        .stdin(Stdio::null())
        .stderr(Stdio::inherit())
        .output()
        .map_err(|e| format!("could not ask cargo for the page tests' binary: {e}"))?;
    if !output.status.success() {
        return Err("building the page tests failed".into());
    }
    let stdout = String::from_utf8_lossy(&output.stdout);
    stdout
        .lines()
        .filter_map(|line| serde_json::from_str::<serde_json::Value>(line).ok())
        .filter(|v| v["reason"] == "compiler-artifact" && v["target"]["name"] == "page")
        .find_map(|v| v["executable"].as_str().map(PathBuf::from))
        .ok_or_else(|| "cargo named no binary for the page tests".into())
}
