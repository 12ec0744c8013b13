//! Process helpers: the workspace root, building commands with a tool-aware `PATH`, running
//! them loudly, and capturing output while still streaming it to the terminal.

use std::error::Error;
use std::ffi::OsString;
use std::io::{BufRead, BufReader};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

/// The error type of every xtask step: a message for the person reading the log.
pub type BoxError = Box<dyn Error + Send + Sync>;

/// Result alias used throughout xtask.
pub type Result<T> = std::result::Result<T, BoxError>;

/// The workspace root (the folder holding the root `Cargo.toml`).
pub fn root() -> PathBuf {
    // `cargo run` sets the manifest folder at run time too; the one compiled in may belong
    // to another checkout that shares the target folder.
    let manifest = std::env::var_os("CARGO_MANIFEST_DIR")
        .map_or_else(|| PathBuf::from(env!("CARGO_MANIFEST_DIR")), PathBuf::from);
    manifest
        .parent()
        .map_or_else(|| manifest.clone(), Path::to_path_buf)
}

/// Cargo's target directory (`CARGO_TARGET_DIR` or `<root>/target`).
pub fn target_dir() -> PathBuf {
    match std::env::var_os("CARGO_TARGET_DIR") {
        Some(dir) if !dir.is_empty() => root().join(dir),
        _ => root().join("target"),
    }
}

/// Folder that `cargo install` writes binaries to (`$CARGO_HOME/bin`, default `~/.cargo/bin`).
pub fn cargo_bin_dir() -> Option<PathBuf> {
    if let Some(home) = std::env::var_os("CARGO_HOME").filter(|h| !h.is_empty()) {
        return Some(PathBuf::from(home).join("bin"));
    }
    std::env::var_os("HOME").map(|home| PathBuf::from(home).join(".cargo").join("bin"))
}

/// `PATH` with the cargo bin folder in front, so freshly installed tools are found.
fn tool_path() -> OsString {
    let mut parts: Vec<PathBuf> = cargo_bin_dir().into_iter().collect();
    if let Some(path) = std::env::var_os("PATH") {
        parts.extend(std::env::split_paths(&path));
    }
    std::env::join_paths(parts).unwrap_or_else(|_| std::env::var_os("PATH").unwrap_or_default())
}

/// A command for `program`, run in the workspace root with the tool-aware `PATH`.
pub fn new(program: impl AsRef<std::ffi::OsStr>) -> Command {
    let mut cmd = Command::new(program);
    cmd.current_dir(root()).env("PATH", tool_path());
    cmd
}

/// A `cargo` command (the same cargo that runs xtask, if known).
pub fn cargo() -> Command {
    new(std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into()))
}

/// The command line of `cmd`, for the log.
pub fn describe(cmd: &Command) -> String {
    let mut line = cmd.get_program().to_string_lossy().into_owned();
    for arg in cmd.get_args() {
        line.push(' ');
        line.push_str(&arg.to_string_lossy());
    }
    line
}

/// Runs `cmd` with inherited stdio; an error if it cannot start or exits non-zero.
pub fn run(cmd: &mut Command) -> Result<()> {
    let line = describe(cmd);
    println!("$ {line}");
    let status = cmd
        .status()
        .map_err(|e| format!("could not start `{line}`: {e}"))?;
    if status.success() {
        Ok(())
    } else {
        Err(format!("`{line}` failed ({status})").into())
    }
}

/// Runs `cmd` quietly and returns its trimmed stdout if it succeeded, `None` otherwise
/// (including when the program does not exist).
pub fn probe(cmd: &mut Command) -> Option<String> {
    let out = cmd
        .stderr(Stdio::null())
        .stdin(Stdio::null())
        .output()
        .ok()?;
    out.status
        .success()
        .then(|| String::from_utf8_lossy(&out.stdout).trim().to_string())
}

/// Runs `cmd`, streaming its stdout and stderr to ours line by line while keeping a copy of
/// both (cargo-nextest writes its results to stderr, `cargo test` to stdout).
/// Returns whether it succeeded and the captured lines (stdout's, then stderr's).
pub fn run_tee(cmd: &mut Command) -> Result<(bool, String)> {
    let line = describe(cmd);
    println!("$ {line}");
    let mut child = cmd
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| format!("could not start `{line}`: {e}"))?;
    let stderr = child.stderr.take();
    let errors = std::thread::spawn(move || {
        let mut captured = String::new();
        if let Some(stderr) = stderr {
            for text in BufReader::new(stderr)
                .lines()
                .map_while(std::io::Result::ok)
            {
                eprintln!("{text}");
                captured.push_str(&text);
                captured.push('\n');
            }
        }
        captured
    });
    let mut captured = String::new();
    if let Some(stdout) = child.stdout.take() {
        for text in BufReader::new(stdout).lines() {
            let text = text.map_err(|e| format!("reading output of `{line}`: {e}"))?;
            println!("{text}");
            captured.push_str(&text);
            captured.push('\n');
        }
    }
    let status = child
        .wait()
        .map_err(|e| format!("waiting for `{line}`: {e}"))?;
    captured.push_str(&errors.join().unwrap_or_default());
    Ok((status.success(), captured))
}

/// Whether we run as root (so `apt-get` needs no `sudo`).
pub fn is_root() -> bool {
    probe(new("id").arg("-u")).is_some_and(|uid| uid == "0")
}
