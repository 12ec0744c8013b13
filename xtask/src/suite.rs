//! `cargo xtask test`: every check, in order, stopping at the first failure, then a summary
//! table and the plain closing line `N passed, M failed`.

use crate::cmd::{self, Result};
use crate::{site, tools};
use attlab_serve as serve;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// Test counts from cargo's `test result:` lines.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Counts {
    /// Tests that passed.
    pub passed: u64,
    /// Tests that failed.
    pub failed: u64,
    /// Tests that were ignored.
    pub ignored: u64,
}

impl Counts {
    /// Adds another set of counts to this one.
    fn add(&mut self, other: Counts) {
        self.passed += other.passed;
        self.failed += other.failed;
        self.ignored += other.ignored;
    }
}

/// Sums every `test result: … N passed; M failed; K ignored; …` line of `cargo test` in
/// `output`, and every `Summary [ T s] N tests run: N passed, M failed, K skipped` line of
/// cargo-nextest (its skipped tests are the ignored ones; a test that timed out or could not
/// start counts as failed). `None` when there is no such line.
pub fn parse_counts(output: &str) -> Option<Counts> {
    let mut total: Option<Counts> = None;
    for line in output.lines() {
        let line = line.trim();
        let nextest = line
            .strip_prefix("Summary [")
            .and_then(|rest| rest.split_once(']'))
            .map(|(_, rest)| rest);
        let Some(rest) = line.strip_prefix("test result:").or(nextest) else {
            continue;
        };
        let words: Vec<&str> = rest
            .split([' ', ';', ','])
            .filter(|w| !w.is_empty())
            .collect();
        let mut counts = Counts::default();
        for pair in words.windows(2) {
            let Ok(n) = pair[0].parse::<u64>() else {
                continue;
            };
            match pair[1] {
                "passed" => counts.passed += n,
                "failed" | "timed" | "exec" => counts.failed += n,
                "ignored" | "skipped" => counts.ignored += n,
                _ => {}
            }
        }
        total.get_or_insert_with(Counts::default).add(counts);
    }
    total
}

/// One finished step of the run.
struct StepResult {
    name: String,
    ok: bool,
    counts: Option<Counts>,
    took: Duration,
}

/// The steps run so far.
#[derive(Default)]
struct Suite {
    steps: Vec<StepResult>,
}

impl Suite {
    /// Runs a step that is not a test suite; its error stops the run.
    fn step<T>(&mut self, name: &str, body: impl FnOnce() -> Result<T>) -> Result<T> {
        banner(name);
        let start = Instant::now();
        let result = body();
        self.record(name, result.is_ok(), None, start);
        result.map_err(|e| format!("step `{name}` failed: {e}").into())
    }

    /// Runs a command as a plain check (fmt, clippy).
    fn check(&mut self, name: &str, mut command: Command) -> Result<()> {
        self.step(name, || cmd::run(&mut command))
    }

    /// Runs a `cargo test` command, counting its results.
    fn tests(&mut self, name: &str, mut command: Command) -> Result<()> {
        banner(name);
        let start = Instant::now();
        let (ok, output) = match cmd::run_tee(&mut command) {
            Ok(done) => done,
            Err(e) => {
                self.record(name, false, None, start);
                return Err(e);
            }
        };
        let counts = parse_counts(&output);
        self.record(name, ok, counts, start);
        if ok {
            Ok(())
        } else {
            Err(format!(
                "step `{name}` failed: `{}` exited non-zero",
                cmd::describe(&command)
            )
            .into())
        }
    }

    /// Waits for a test run started beside the others and records it (its time is its own,
    /// from its start: it overlaps the steps run meanwhile).
    fn finish_beside(&mut self, name: &str, beside: crate::beside::Beside) -> Result<()> {
        banner(name);
        let start = Instant::now();
        let (ok, output, took) = match beside.finish() {
            Ok(done) => done,
            Err(e) => {
                self.record(name, false, None, start);
                return Err(e);
            }
        };
        let counts = parse_counts(&output);
        self.steps.push(StepResult {
            name: name.to_string(),
            ok,
            counts,
            took,
        });
        if ok {
            Ok(())
        } else {
            Err(format!("step `{name}` failed").into())
        }
    }

    /// Records a finished step.
    fn record(&mut self, name: &str, ok: bool, counts: Option<Counts>, start: Instant) {
        let took = start.elapsed();
        self.steps.push(StepResult {
            name: name.to_string(),
            ok,
            counts,
            took,
        });
    }

    /// Prints the table and the closing `N passed, M failed` line. A failed step without
    /// failed tests of its own (fmt, clippy, a build error) counts as one failure.
    fn print_summary(&self, total_time: Duration) {
        println!();
        println!(
            "{:<34} {:>6} {:>7} {:>7} {:>8} {:>7}",
            "step", "result", "passed", "failed", "ignored", "time"
        );
        let mut total = Counts::default();
        for step in &self.steps {
            let mut counts = step.counts.unwrap_or_default();
            if !step.ok && counts.failed == 0 {
                counts.failed = 1;
            }
            total.add(counts);
            let cell = |n: u64| {
                if step.counts.is_some() || !step.ok {
                    n.to_string()
                } else {
                    "-".into()
                }
            };
            println!(
                "{:<34} {:>6} {:>7} {:>7} {:>8} {:>6}s",
                step.name,
                if step.ok { "ok" } else { "FAILED" },
                cell(counts.passed),
                cell(counts.failed),
                cell(counts.ignored),
                step.took.as_secs()
            );
        }
        println!(
            "{:<34} {:>6} {:>7} {:>7} {:>8} {:>6}s",
            "total",
            "",
            total.passed,
            total.failed,
            total.ignored,
            total_time.as_secs()
        );
        println!();
        println!("{} passed, {} failed", total.passed, total.failed);
    }
}

/// Prints a step heading.
fn banner(name: &str) {
    println!("\n==== xtask test: {name} ====");
}

/// A cargo command from space-separated arguments, with no stdin.
fn cargo(args: &str) -> Command {
    let mut command = cmd::cargo();
    command.args(args.split_whitespace()).stdin(Stdio::null());
    command
}

/// Runs everything; prints the summary whatever happens.
pub fn run() -> Result<()> {
    let start = Instant::now();
    let mut suite = Suite::default();
    let outcome = run_steps(&mut suite);
    suite.print_summary(start.elapsed());
    outcome
}

/// The steps, in order; the first failure stops the run.
fn run_steps(suite: &mut Suite) -> Result<()> {
    suite.step("install missing tools", || {
        tools::ensure_components()?;
        tools::ensure_browser()?;
        tools::ensure_wasm_tools(true)
    })?;
    suite.check("fmt", cargo("fmt --all -- --check"))?;
    let native_clippy = "clippy --workspace --all-targets -- -D warnings";
    suite.check("clippy (native)", cargo(native_clippy))?;
    // Every target that builds for wasm32: the libraries, binaries and tests, and the one
    // wasm bench (`cargo xtask bench` runs it; natively its code is compiled out, so nothing
    // else checks it). The other criterion benches and the examples are native-only.
    let wasm_clippy = format!(
        "clippy --target {} -p attlab -p attlab-web -p attlab-tests --lib --bins --tests \
         --bench wasm_kinematics -- -D warnings",
        tools::WASM_TARGET
    );
    suite.check("clippy (wasm)", cargo(&wasm_clippy))?;
    // A stale intra-doc link or a broken doc comment fails the run.
    suite.step("cargo doc", || {
        let metadata = cmd::cargo()
            .args(["metadata", "--no-deps", "--format-version", "1"])
            .output()
            .map_err(|e| format!("could not run cargo metadata: {e}"))?;
        if !metadata.status.success() {
            let why = String::from_utf8_lossy(&metadata.stderr);
            return Err(format!("cargo metadata failed: {why}").into());
        }
        let targets = crate::targets::doc_target_args(&String::from_utf8_lossy(&metadata.stdout))?;
        let mut doc = cargo("doc --workspace --no-deps");
        doc.args(targets).env("RUSTDOCFLAGS", "-D warnings");
        cmd::run(&mut doc)
    })?;
    native_tests(suite)?;
    let dist = site_and_wasm_tests(suite)?;
    page_tests(suite, &dist)
}

/// The wasm tests, built and run beside the site's build: each leaves a core partly idle on
/// its own (the site's last crate and its fat LTO run on one; the wasm tests wait for their
/// browser), and neither reuses the other's build (another profile, so only the build
/// scripts and proc macros are built twice). In a build directory of their own, as cargo
/// locks one for a whole build. Returns the site's folder.
fn site_and_wasm_tests(suite: &mut Suite) -> Result<PathBuf> {
    let mut browser = cargo(&format!(
        "test --target {} -p attlab-tests",
        tools::WASM_TARGET
    ));
    // Each lab's reproduction runs inside one test call; the default 20 s per call is too
    // short for the 600-s scenarios of paper 1 on a loaded 2-core machine.
    tools::headless_test_env(&mut browser, 600);
    browser.env("CARGO_TARGET_DIR", cmd::target_dir().join("wasm-tests"));
    let log = cmd::target_dir().join("wasm-tests.log");
    let wasm = suite.step("start the wasm tests beside", || {
        // Only the test targets with wasm tests: the others are native-only (empty on
        // wasm32; the wasm clippy checks that they compile), and linking each of them and
        // starting the runner for it cost 22 s of CPU (110 s against 88 s, built from
        // scratch) beside the site's build, for no test.
        for target in crate::targets::wasm_test_targets(&cmd::root().join("tests/tests"))? {
            browser.args(["--test", &target]);
        }
        crate::beside::spawn(browser, log)
    })?;
    // Without wasm-opt: `cargo xtask dist` runs it and ships whichever output is smaller
    // gzipped, and for this app that is wasm-bindgen's (-O2 makes the download 3 % bigger),
    // so the page tests test the file a host serves, and the run saves wasm-opt's ~65 s.
    let dist = suite.step("build site (dist/)", || {
        site::build(false, site::SizeReport::Gzip)
    });
    // Reported even when the site failed (rather than killed unseen).
    let wasm = suite.finish_beside("test (wasm, headless Chromium)", wasm);
    let dist = dist?;
    wasm?;
    Ok(dist)
}

/// The page tests against `dist`, served on loopback, with the soak, the lessons and the
/// fuzz beside them (see `beside`).
fn page_tests(suite: &mut Suite, dist: &Path) -> Result<()> {
    let server = suite.step("serve dist/", || Ok(serve::start(dist, 0)?))?;
    println!("xtask: serving {} at {}", dist.display(), server.url());
    // Every page test but those beside them, one at a time: most of them count frames, and
    // a third Chromium at their priority on the 2 cores would slow the frames of the other
    // two (the soak beside them is niced).
    // `--workspace`, as the native tests: the same features for every dependency, so the
    // page test reuses that build (`-p attlab-tests` alone re-resolved them and rebuilt 71
    // crates, 83 s in CI).
    let mut page = cargo(&format!(
        "test --workspace --test page -- --ignored --nocapture --test-threads=1 --skip {SOAK} --skip {}",
        BESIDE.join(" --skip ")
    ));
    page.env("ATTLAB_PAGE_URL", server.url());
    page.env("ATTLAB_DIST", dist);
    page.env("CHROMEDRIVER", tools::CHROMEDRIVER);
    let soak = suite.step("start the soak beside, niced", || {
        crate::beside::start(&server.url(), CI_SOAK_MINUTES, &[SOAK], SOAK_NICENESS)
    })?;
    let beside = suite.step("start the lessons and fuzz beside", || {
        crate::beside::start(&server.url(), CI_SOAK_MINUTES, &BESIDE, 0)
    })?;
    // A failed page test stops the runs beside it (dropped: killed); a failure among those
    // lets the other finish and be reported.
    suite.tests("page (headless Chromium)", page)?;
    let lessons_and_fuzz = suite.finish_beside("lessons, fuzz, beside", beside);
    let soak = suite.finish_beside(&format!("soak ({CI_SOAK_MINUTES} min), niced beside"), soak);
    lessons_and_fuzz.and(soak)
}

/// The soak, run beside the other page tests in a run of its own, niced: it keeps each lab
/// for its seconds at the highest speed and takes whatever cycles it is given.
const SOAK: &str = "soak";

/// The page tests `cargo xtask test` runs beside the others in one run (exact names, one
/// after the other in the order of their names): the lessons and the fuzz (its default:
/// one round of random input per lab). The lessons wait on the clock more than on the cores;
/// the fuzz keeps one core busy with the app's UI passes, which the other page tests, mostly
/// painting, left partly idle (see `beside`).
const BESIDE: [&str; 2] = [
    "lessons_open_at_their_step_and_pause",
    "page_survives_random_input",
];

/// The soak's `nice -n` beside the page tests: its Chromium gets about a tenth of a core
/// while the others keep both busy (CFS weights 110 against 1024), and the rest when they
/// wait.
const SOAK_NICENESS: u8 = 10;

/// The native tests. With cargo-nextest (on this project's machines): every test of every
/// binary in one pool, so a binary of one long test no longer leaves a core idle while the
/// next waits (`cargo test` runs its binaries one after the other: 170 s against 142 s for
/// the same tests and doctests, built), then the doctests, which nextest does not run.
/// Without it, `cargo test`, as before.
fn native_tests(suite: &mut Suite) -> Result<()> {
    if cmd::probe(cmd::cargo().args(["nextest", "--version"])).is_none() {
        println!("xtask: cargo-nextest is not installed; the native tests run with `cargo test`");
        return suite.tests("test (native)", cargo("test --workspace --no-fail-fast"));
    }
    let nextest = cargo("nextest run --workspace --no-fail-fast --color never");
    let doc = cargo("test --workspace --doc --no-fail-fast");
    let first = suite.tests("test (native, nextest)", nextest);
    // The doctests run even when a test failed, as `cargo test --no-fail-fast` would.
    let second = suite.tests("doctests (native)", doc);
    first.and(second)
}

/// The page fuzz against `url` for `minutes` (`cargo xtask test` runs one round per lab
/// instead, beside the other page tests).
pub fn fuzz_command(url: &str, minutes: f64) -> Command {
    let mut fuzz = cargo(
        "test --workspace --test page -- --ignored --nocapture --exact page_survives_random_input",
    );
    fuzz.env("ATTLAB_PAGE_URL", url);
    fuzz.env("ATTLAB_FUZZ_MINUTES", minutes.to_string());
    fuzz.env("CHROMEDRIVER", tools::CHROMEDRIVER);
    fuzz
}

/// Minutes of the soak inside `cargo xtask test`: 5 s of each lab per round, two samples
/// each. What only the soak checks is the memory of one long-lived page across lab switches
/// (every switch happens as in a longer soak; a leak that grows with time has half as long to
/// show as at 2 min); that every lab starts, runs and keeps its console clean, the other page
/// tests check, and `cargo xtask soak` (10 min by default) is the deep run.
const CI_SOAK_MINUTES: f64 = 1.0;

/// The page test's soak against `url` for `minutes`.
pub fn soak_command(url: &str, minutes: f64) -> Command {
    let mut soak = cargo("test --workspace --test page -- --ignored --nocapture --exact soak");
    soak.env("ATTLAB_PAGE_URL", url);
    soak.env("ATTLAB_SOAK_MINUTES", minutes.to_string());
    soak.env("CHROMEDRIVER", tools::CHROMEDRIVER);
    soak
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sums_result_lines() {
        let out = "running 2 tests\n\
            test result: ok. 5 passed; 0 failed; 1 ignored; 0 measured; 0 filtered out; finished in 0.01s\n\
            noise\n   test result: FAILED. 2 passed; 3 failed; 0 ignored; 0 measured; 0 filtered out\n";
        assert_eq!(
            parse_counts(out),
            Some(Counts {
                passed: 7,
                failed: 3,
                ignored: 1
            })
        );
        assert_eq!(parse_counts("no tests here"), None);
    }

    #[test]
    fn sums_nextest_summaries() {
        let out = "        PASS [   0.740s] (303/313) attlab-web::ui reset_restarts_at_zero\n\
            ────────────\n     Summary [ 135.904s] 313 tests run: 313 passed, 8 skipped\n";
        assert_eq!(
            parse_counts(out),
            Some(Counts {
                passed: 313,
                failed: 0,
                ignored: 8
            })
        );
        let out = "     Summary [  12.001s] 20 tests run: 16 passed, 2 failed, 1 timed out, \
            1 exec failed, 3 skipped\n";
        assert_eq!(
            parse_counts(out),
            Some(Counts {
                passed: 16,
                failed: 4,
                ignored: 3
            })
        );
    }
}
