//! Installs the tools the build and the tests need, each only when it is missing or the
//! wrong version: the wasm target, `wasm-bindgen-cli`, npm's `binaryen` (for `wasm-opt`),
//! and Debian's Chromium with its chromedriver. Nothing here ever prompts.

use crate::cmd::{self, Result};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

/// The wasm target triple.
pub const WASM_TARGET: &str = "wasm32-unknown-unknown";
/// The `wasm-bindgen-cli` version; must equal the `wasm-bindgen` crate pinned in Cargo.toml.
pub const WASM_BINDGEN_VERSION: &str = "0.2.130";
/// The npm `binaryen` major version that provides `wasm-opt`.
pub const BINARYEN_VERSION: &str = "132";
/// Where Debian's chromium-driver puts chromedriver.
pub const CHROMEDRIVER: &str = "/usr/bin/chromedriver";

/// The environment of a `wasm-bindgen-test-runner` run in headless Chromium: our
/// chromedriver, `call_s` seconds per test call, and two minutes for chromedriver to bind
/// its port. The runner's default for that is 5 s, and on a loaded 2-core CI machine
/// chromedriver once took longer: the runner killed it and failed a run whose tests had
/// never started ("driver failed to bind port during startup").
pub fn headless_test_env(command: &mut Command, call_s: u32) {
    command.env("CHROMEDRIVER", CHROMEDRIVER);
    command.env("WASM_BINDGEN_TEST_TIMEOUT", call_s.to_string());
    command.env("WASM_BINDGEN_TEST_DRIVER_TIMEOUT", "120");
}

/// Folder (gitignored) holding npm-installed tools.
fn tools_dir() -> PathBuf {
    cmd::root().join(".tools")
}

/// The npm-installed `wasm-opt`.
pub fn wasm_opt() -> PathBuf {
    tools_dir()
        .join("node_modules")
        .join(".bin")
        .join("wasm-opt")
}

/// Everything the wasm build needs: the target, `wasm-bindgen`, and (if `with_opt`) `wasm-opt`.
pub fn ensure_wasm_tools(with_opt: bool) -> Result<()> {
    ensure_wasm_target()?;
    ensure_wasm_bindgen()?;
    if with_opt {
        ensure_binaryen()?;
    }
    Ok(())
}

/// `rustup component add rustfmt clippy` when `cargo fmt` or `cargo clippy` is missing.
pub fn ensure_components() -> Result<()> {
    for (sub, component) in [("fmt", "rustfmt"), ("clippy", "clippy")] {
        if cmd::probe(cmd::cargo().args([sub, "--version"])).is_none() {
            cmd::run(cmd::new("rustup").args(["component", "add", component]))?;
        }
    }
    Ok(())
}

/// `rustup target add wasm32-unknown-unknown` unless it is installed.
fn ensure_wasm_target() -> Result<()> {
    let installed = cmd::probe(cmd::new("rustup").args(["target", "list", "--installed"]));
    match installed {
        Some(list) if list.lines().any(|l| l.trim() == WASM_TARGET) => Ok(()),
        Some(_) => cmd::run(cmd::new("rustup").args(["target", "add", WASM_TARGET])),
        None => {
            println!("xtask: rustup not found; assuming the {WASM_TARGET} std is installed");
            Ok(())
        }
    }
}

/// `cargo install wasm-bindgen-cli --version X` unless `wasm-bindgen --version` is X.
/// No `--locked`: its lockfile pins crates newer than the reachable registry has.
fn ensure_wasm_bindgen() -> Result<()> {
    let have = cmd::probe(cmd::new("wasm-bindgen").arg("--version"));
    if have
        .as_deref()
        .is_some_and(|v| v.split_whitespace().any(|w| w == WASM_BINDGEN_VERSION))
    {
        return Ok(());
    }
    println!(
        "xtask: wasm-bindgen {WASM_BINDGEN_VERSION} needed (found: {}); installing (a few minutes)",
        have.as_deref().unwrap_or("none")
    );
    let mut install = cmd::cargo();
    install
        .args([
            "install",
            "wasm-bindgen-cli",
            "--version",
            WASM_BINDGEN_VERSION,
        ])
        .stdin(Stdio::null());
    cmd::run(&mut install)
}

/// The `twiggy` version `cargo xtask size` uses.
pub const TWIGGY_VERSION: &str = "0.8.0";

/// `cargo install twiggy --version 0.8.0` unless `twiggy --version` reports it (only
/// `cargo xtask size` needs it).
pub fn ensure_twiggy() -> Result<()> {
    let have = cmd::probe(cmd::new("twiggy").arg("--version"));
    if have.as_deref().is_some_and(|v| v.contains(TWIGGY_VERSION)) {
        return Ok(());
    }
    println!("xtask: twiggy {TWIGGY_VERSION} needed; installing (a minute or two)");
    let mut install = cmd::cargo();
    install
        .args(["install", "twiggy", "--version", TWIGGY_VERSION])
        .stdin(Stdio::null());
    cmd::run(&mut install)
}

/// `npm install --prefix .tools binaryen@132` unless `.tools` already has that `wasm-opt`.
fn ensure_binaryen() -> Result<()> {
    let wanted = format!("version {BINARYEN_VERSION}");
    let have = cmd::probe(cmd::new(wasm_opt()).arg("--version"));
    if have.as_deref().is_some_and(|v| v.contains(&wanted)) {
        return Ok(());
    }
    if cmd::probe(cmd::new("npm").arg("--version")).is_none() {
        println!("xtask: npm missing; installing Debian's nodejs and npm");
        apt(&["update"])?;
        apt(&["install", "-y", "nodejs", "npm"])?;
    }
    let prefix = tools_dir();
    std::fs::create_dir_all(&prefix).map_err(|e| format!("creating {}: {e}", prefix.display()))?;
    let mut install = cmd::new("npm");
    install
        .arg("install")
        .arg("--prefix")
        .arg(&prefix)
        .args(["--no-audit", "--no-fund", "--loglevel=error"])
        .arg(format!("binaryen@{BINARYEN_VERSION}"))
        .stdin(Stdio::null());
    cmd::run(&mut install)?;
    match cmd::probe(cmd::new(wasm_opt()).arg("--version")) {
        Some(v) if v.contains(&wanted) => Ok(()),
        other => Err(format!(
            "{} reports {other:?}, wanted {wanted}",
            wasm_opt().display()
        )
        .into()),
    }
}

/// Debian's `chromium` and `chromium-driver`, unless chromedriver is already there.
pub fn ensure_browser() -> Result<()> {
    if Path::new(CHROMEDRIVER).exists() {
        return Ok(());
    }
    println!("xtask: {CHROMEDRIVER} missing; installing chromium and chromium-driver");
    apt(&["update"])?;
    apt(&["install", "-y", "chromium", "chromium-driver"])?;
    if Path::new(CHROMEDRIVER).exists() {
        Ok(())
    } else {
        Err(format!("{CHROMEDRIVER} still missing after apt-get install").into())
    }
}

/// Runs `apt-get ARGS` non-interactively, through `sudo -n` when not root.
fn apt(args: &[&str]) -> Result<()> {
    let mut command: Command = if cmd::is_root() {
        cmd::new("apt-get")
    } else {
        let mut sudo = cmd::new("sudo");
        sudo.args(["-n", "env", "DEBIAN_FRONTEND=noninteractive", "apt-get"]);
        sudo
    };
    command
        .args(args)
        .env("DEBIAN_FRONTEND", "noninteractive")
        .stdin(Stdio::null());
    cmd::run(&mut command)
}
