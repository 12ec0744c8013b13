//! Clippy inside the native test build instead of in a check build of its own.
//!
//! `cargo clippy` is cargo with `RUSTC_WORKSPACE_WRAPPER` set to `clippy-driver` (rustc
//! with clippy's lints) and the lint levels in `CLIPPY_ARGS`, running `cargo check`. The
//! same two variables on a `cargo build` lint every workspace crate while compiling it for
//! real; dependencies are compiled by plain rustc, as under `cargo clippy`. So one build of
//! every target in the test profile both lints and builds what nextest, the doctests and the
//! page tests then run, and the dependencies are compiled once instead of once checked and
//! once built. Every command that shares that build must carry the same variables: cargo
//! counts the wrapper in each workspace crate's fingerprint and would rebuild them without.

use crate::cmd::{self, Result};
use std::path::PathBuf;
use std::process::Command;

/// The lint levels `cargo clippy -- -D warnings` passes: each argument followed by the
/// separator clippy-driver splits `CLIPPY_ARGS` at.
const CLIPPY_ARGS: &str = "-D__CLIPPY_HACKERY__warnings__CLIPPY_HACKERY__";

/// `clippy-driver` of the active toolchain, to wrap rustc with.
#[derive(Clone, Debug)]
pub struct Lints {
    driver: PathBuf,
}

impl Lints {
    /// Finds `clippy-driver` next to the active toolchain's rustc (`rustc --print sysroot`).
    pub fn find() -> Result<Self> {
        let rustc = std::env::var_os("RUSTC").unwrap_or_else(|| "rustc".into());
        let sysroot = cmd::probe(cmd::new(rustc).args(["--print", "sysroot"]))
            .ok_or("`rustc --print sysroot` failed: cannot find clippy-driver")?;
        let exe = format!("clippy-driver{}", std::env::consts::EXE_SUFFIX);
        let driver = PathBuf::from(sysroot.trim()).join("bin").join(exe);
        if !driver.is_file() {
            return Err(format!(
                "{} is missing: `rustup component add clippy` installs it",
                driver.display()
            )
            .into());
        }
        Ok(Lints { driver })
    }

    /// Makes `command`'s compiles of workspace crates lint as `cargo clippy -- -D warnings`.
    pub fn apply(&self, command: &mut Command) {
        command
            .env("RUSTC_WORKSPACE_WRAPPER", &self.driver)
            .env("CLIPPY_ARGS", CLIPPY_ARGS);
    }

    /// The build that lints: every target of every workspace crate (as `cargo clippy
    /// --workspace --all-targets`), in the test profile that nextest and `cargo test` use.
    pub fn build_command(&self) -> Command {
        let mut build = cmd::cargo();
        build.args(["build", "--workspace", "--all-targets", "--profile", "test"]);
        self.apply(&mut build);
        build
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A one-file crate in a fresh folder of the system's temporary directory (outside this
    /// workspace), with `body` as its `main.rs`.
    fn scratch_crate(name: &str, body: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("attlab-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(dir.join("src")).unwrap();
        let manifest = format!(
            "[package]\nname = \"{name}\"\nversion = \"0.1.0\"\nedition = \"2024\"\n\n\
             [workspace]\n"
        );
        std::fs::write(dir.join("Cargo.toml"), manifest).unwrap();
        std::fs::write(dir.join("src/main.rs"), body).unwrap();
        dir
    }

    /// `cargo build` of the crate in `dir`, with or without the lints; its success and stderr.
    fn build(dir: &PathBuf, lints: Option<&Lints>) -> (bool, String) {
        let mut build = cmd::cargo();
        build
            .args(["build", "--quiet", "--offline"])
            .current_dir(dir)
            .env_remove("RUSTC_WORKSPACE_WRAPPER")
            .env_remove("CLIPPY_ARGS")
            .env("CARGO_TARGET_DIR", dir.join("target"));
        if let Some(lints) = lints {
            lints.apply(&mut build);
        }
        let output = build.output().unwrap();
        let stderr = String::from_utf8_lossy(&output.stderr).into_owned();
        (output.status.success(), stderr)
    }

    /// The build that replaces `cargo clippy` must fail where `cargo clippy -- -D warnings`
    /// fails: a clippy-only warning (comparing a bool with `true`, which rustc accepts)
    /// stops it, and the same crate builds without the wrapper.
    #[test]
    fn a_clippy_warning_fails_the_linted_build_and_not_the_plain_one() {
        let body = "fn main() {\n    let b = std::env::args().count() > 1;\n    \
                    if b == true {\n        println!(\"more\");\n    }\n}\n";
        let dir = scratch_crate("lints-probe", body);
        let lints = Lints::find().unwrap();
        let (plain_ok, plain_err) = build(&dir, None);
        let (linted_ok, linted_err) = build(&dir, Some(&lints));
        let _ = std::fs::remove_dir_all(&dir);
        assert!(
            plain_ok,
            "the crate should build without clippy: {plain_err}"
        );
        assert!(!linted_ok, "the linted build passed a clippy warning");
        assert!(
            linted_err.contains("clippy::bool_comparison"),
            "the linted build failed, but not on clippy's lint: {linted_err}"
        );
    }
}
