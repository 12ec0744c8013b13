//! `cargo xtask`: build, serve and test orchestration for Attitude Lab.
//!
//! - `cargo xtask serve [--port 8080] [--no-opt]`: build the site into `dist/` and serve it on
//!   `127.0.0.1:PORT`.
//! - `cargo xtask dist [--no-opt]`: build the site into `dist/` only.
//! - `cargo xtask size`: the wasm raw, gzipped and brotli'd, and a twiggy profile by crate.
//! - `cargo xtask test`: fmt, clippy (native and wasm), native tests, browser tests, then the
//!   page test against the built site; ends with a summary and `N passed, M failed`.
//!
//! Each command first installs what is missing (wasm target, `wasm-bindgen-cli`, npm
//! `binaryen` in `.tools/`, Chromium and chromedriver for `test`), without ever prompting.

// A panic in the product is a bug to report, not an answer: fallible paths return typed
// errors. Tests may unwrap (clippy.toml allows it in tests).
#![deny(clippy::unwrap_used, clippy::expect_used)]

mod beside;
mod cmd;
mod publish;
use attlab_serve as serve;
mod site;
mod size;
mod suite;
mod targets;
mod tools;
mod wasm;

use site::SizeReport;
use std::process::ExitCode;

/// Default port for `serve`.
const DEFAULT_PORT: u16 = 8080;

/// Usage text.
const USAGE: &str = "usage: cargo xtask <command>

commands:
  serve [--port N] [--no-opt]   build dist/ and serve it on 127.0.0.1:N (default 8080)
  dist [--no-opt] [--archive] [--address URL]
                                build dist/ only (the page, version.json, the teacher
                                notes), and print the wasm raw, gzipped and brotli'd;
                                --archive also writes it as .tar.gz and .zip into
                                target/site-archive/; --address gives the site's public
                                address (else site/address.txt's) for the notes' links
  test                          run every check and test suite (what CI runs)
  bench                         time every lab natively (attlab bench) and in headless
                                Chromium (wasm criterion bench of the labs' timing items)
  soak [--minutes M]            run the page through every lab at top speed in headless
                                Chromium for M minutes (default 10), sampling its memory
  fuzz-page [--minutes M]       random clicks, drags, wheel, touches and keys on every lab
                                in headless Chromium for M minutes (default 10); a failure
                                prints the seed (ATTLAB_FUZZ_SEED, ATTLAB_FUZZ_LABS replay it)
  size                          build dist/, print the wasm raw, gzipped and brotli'd, and
                                a twiggy profile of it by crate

--no-opt skips wasm-opt (faster build, bigger wasm).";

/// A parsed command line.
#[derive(Debug, PartialEq)]
enum Task {
    /// Build and serve.
    Serve {
        /// Port on 127.0.0.1.
        port: u16,
        /// Whether to run wasm-opt.
        optimise: bool,
    },
    /// Build only.
    Dist {
        /// Whether to run wasm-opt.
        optimise: bool,
        /// Also write the site as a .tar.gz and a .zip.
        archive: bool,
        /// The site's public address (else `site/address.txt`'s).
        address: Option<String>,
    },
    /// Everything CI runs.
    Test,
    /// Native and wasm timings (never part of `test`: these machines are noisy).
    Bench,
    /// The page through every lab for this many minutes.
    Soak {
        /// Minutes.
        minutes: f64,
    },
    /// Random input on the page for this many minutes.
    FuzzPage {
        /// Minutes.
        minutes: f64,
    },
    /// The wasm's sizes and a twiggy profile by crate.
    Size,
    /// Print usage.
    Help,
}

/// Parses the arguments after `cargo xtask`.
fn parse(args: &[String]) -> Result<Task, String> {
    let Some((command, rest)) = args.split_first() else {
        return Ok(Task::Help);
    };
    let mut port = DEFAULT_PORT;
    let mut optimise = true;
    let mut minutes = 10.0;
    let mut archive = false;
    let mut address = None;
    let mut iter = rest.iter();
    while let Some(arg) = iter.next() {
        match arg.as_str() {
            "--no-opt" if command != "test" => optimise = false,
            "--archive" if command == "dist" => archive = true,
            "--address" if command == "dist" => {
                address = Some(iter.next().ok_or("--address needs a value")?.clone());
            }
            "--minutes" if command == "soak" || command == "fuzz-page" => {
                let value = iter.next().ok_or("--minutes needs a value")?;
                minutes = value
                    .parse::<f64>()
                    .ok()
                    .filter(|m| *m > 0.0 && m.is_finite())
                    .ok_or(format!("bad minutes `{value}` (a positive number)"))?;
            }
            "--port" if command == "serve" => {
                let value = iter.next().ok_or("--port needs a value")?;
                port = value.parse().map_err(|_| format!("bad port `{value}`"))?;
            }
            other => {
                if let Some(value) = other.strip_prefix("--port=").filter(|_| command == "serve") {
                    port = value.parse().map_err(|_| format!("bad port `{value}`"))?;
                } else {
                    return Err(format!("unexpected argument `{other}` for `{command}`"));
                }
            }
        }
    }
    match command.as_str() {
        "serve" => Ok(Task::Serve { port, optimise }),
        "dist" => Ok(Task::Dist {
            optimise,
            archive,
            address,
        }),
        "test" => Ok(Task::Test),
        "bench" => Ok(Task::Bench),
        "soak" => Ok(Task::Soak { minutes }),
        "fuzz-page" => Ok(Task::FuzzPage { minutes }),
        "size" => Ok(Task::Size),
        "help" | "--help" | "-h" => Ok(Task::Help),
        other => Err(format!("unknown command `{other}`")),
    }
}

/// Runs one task.
fn run(task: Task) -> cmd::Result<()> {
    match task {
        Task::Serve { port, optimise } => {
            let dist = site::build(optimise, SizeReport::Gzip)?;
            let server = serve::start(&dist, port)?;
            println!(
                "xtask: serving {} at {} (Ctrl-C to stop)",
                dist.display(),
                server.url()
            );
            server.wait();
            Ok(())
        }
        Task::Dist {
            optimise,
            archive,
            address,
        } => {
            let dist = site::build_for(optimise, SizeReport::WithBrotli, address.as_deref())?;
            if archive {
                for file in publish::archive(&dist, &publish::build())? {
                    println!("xtask: wrote {}", file.display());
                }
            }
            Ok(())
        }
        Task::Test => suite::run(),
        Task::Bench => bench(),
        Task::Soak { minutes } => {
            tools::ensure_browser()?;
            let dist = site::build(true, SizeReport::Gzip)?;
            let server = serve::start(&dist, 0)?;
            println!("xtask: soak of {minutes} min against {}", server.url());
            cmd::run(&mut suite::soak_command(&server.url(), minutes))
        }
        Task::FuzzPage { minutes } => {
            tools::ensure_browser()?;
            let dist = site::build(true, SizeReport::Gzip)?;
            let server = serve::start(&dist, 0)?;
            println!("xtask: page fuzz of {minutes} min against {}", server.url());
            cmd::run(&mut suite::fuzz_command(&server.url(), minutes))
        }
        Task::Size => size::run(),
        Task::Help => {
            println!("{USAGE}");
            Ok(())
        }
    }
}

/// `attlab bench` natively, then the wasm criterion bench in headless Chromium.
fn bench() -> cmd::Result<()> {
    tools::ensure_components()?;
    tools::ensure_browser()?;
    tools::ensure_wasm_tools(false)?;
    let mut native = cmd::cargo();
    native.args(["run", "--release", "-p", "attlab", "--", "bench"]);
    cmd::run(&mut native)?;
    // A loaded 2-core machine can starve headless Chromium once: one retry, said aloud.
    if let Err(first) = cmd::run(&mut wasm_bench()) {
        println!("xtask: the wasm bench failed ({first}); retrying it once");
        cmd::run(&mut wasm_bench())
            .map_err(|again| format!("the wasm bench failed twice: {first}; then {again}"))?;
        println!("xtask: the wasm bench passed on its retry");
    }
    Ok(())
}

/// The wasm criterion bench in headless Chromium, built with the page's own profile (`web`),
/// so it times the code the page runs: the release profile's wasm ran paper 2's step 4.5×
/// faster than the page did while the simulation core was built for size.
fn wasm_bench() -> std::process::Command {
    let mut wasm = cmd::cargo();
    wasm.args([
        "bench",
        "--target",
        tools::WASM_TARGET,
        "--profile",
        "web",
        "-p",
        "attlab-tests",
        "--bench",
        "wasm_kinematics",
    ]);
    // The criterion run is one long synchronous call in the page (~10 s per item).
    tools::headless_test_env(&mut wasm, 600);
    wasm
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let task = match parse(&args) {
        Ok(task) => task,
        Err(e) => {
            eprintln!("xtask: {e}\n\n{USAGE}");
            return ExitCode::from(2);
        }
    };
    match run(task) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("xtask: error: {e}");
            ExitCode::FAILURE
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn args(list: &[&str]) -> Vec<String> {
        list.iter().map(|s| (*s).to_string()).collect()
    }

    #[test]
    fn parses_commands() {
        assert_eq!(parse(&args(&[])), Ok(Task::Help));
        assert_eq!(parse(&args(&["test"])), Ok(Task::Test));
        assert_eq!(parse(&args(&["bench"])), Ok(Task::Bench));
        assert_eq!(
            parse(&args(&["soak", "--minutes", "3"])),
            Ok(Task::Soak { minutes: 3.0 })
        );
        assert!(parse(&args(&["soak", "--minutes", "-1"])).is_err());
        assert_eq!(
            parse(&args(&["fuzz-page", "--minutes", "0.5"])),
            Ok(Task::FuzzPage { minutes: 0.5 })
        );
        assert!(parse(&args(&["fuzz-page", "--port", "1"])).is_err());
        assert_eq!(
            parse(&args(&["dist", "--no-opt"])),
            Ok(Task::Dist {
                optimise: false,
                archive: false,
                address: None
            })
        );
        assert_eq!(
            parse(&args(&[
                "dist",
                "--archive",
                "--address",
                "https://x.org/lab/"
            ])),
            Ok(Task::Dist {
                optimise: true,
                archive: true,
                address: Some("https://x.org/lab/".into())
            })
        );
        assert!(parse(&args(&["serve", "--archive"])).is_err());
        assert_eq!(
            parse(&args(&["serve", "--port", "9000"])),
            Ok(Task::Serve {
                port: 9000,
                optimise: true
            })
        );
        assert_eq!(
            parse(&args(&["serve", "--port=81", "--no-opt"])),
            Ok(Task::Serve {
                port: 81,
                optimise: false
            })
        );
        assert!(parse(&args(&["dist", "--port", "1"])).is_err());
        assert!(parse(&args(&["test", "--no-opt"])).is_err());
        assert!(parse(&args(&["bogus"])).is_err());
    }
}
