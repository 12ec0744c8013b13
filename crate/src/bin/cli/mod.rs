//! The CLI proper (native only).

use attlab::analysis::fuzz::{self, FuzzConfig};
use attlab::analysis::readme;
use attlab::i18n::{self, Lang};
use attlab::labs;
use attlab::model::{ParamKind, Reproduction};
use attlab::page::Lab;
use clap::{Parser, Subcommand};
use rayon::prelude::*;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

mod bench;
mod branch;
mod run;

use bench::{bench, print_timings};
use run::{LogUnits, Output, replay, run};

/// Attitude Lab, headless: reproduce the papers, run a lab to CSV, time the estimators.
#[derive(Parser, Debug)]
#[command(name = "attlab", version, about)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// List the labs and their parameters.
    Labs {
        /// Language of the labels and help: `en` or `ru` (the flags stay as written).
        #[arg(long, default_value = "en")]
        lang: String,
    },
    /// Run a lab's paper scenarios and print measured numbers beside the paper's: each row
    /// is a measurement, or a check that matches or (declared, with the reason) differs.
    Reproduce {
        /// Lab id, or `all`.
        lab: String,
        /// Also write the tables as JSON to this file.
        #[arg(long)]
        json: Option<PathBuf>,
        /// Print the tables as Markdown instead of plain text.
        #[arg(long)]
        markdown: bool,
        /// Rewrite each lab's table between the `<!-- reproduce:ID -->` markers of its
        /// chapter (`README.md` in the lab's folder, in this checkout).
        #[arg(long)]
        readme: bool,
    },
    /// Run random parameter sets of every lab and check what must always hold (no panic,
    /// finite estimates or a diverged status, symmetric PSD covariances, fixed memory).
    Fuzz {
        /// Parameter sets, spread over the labs.
        #[arg(long, default_value_t = 1000)]
        sets: usize,
        /// Steps per set.
        #[arg(long, default_value_t = 2000)]
        steps: usize,
        /// Seed of the parameter draws.
        #[arg(long, default_value_t = 1)]
        seed: u64,
    },
    /// Run a lab and write every recorded series to CSV (plus a JSON sidecar).
    Run {
        /// Lab id (see `attlab labs`).
        #[arg(long)]
        lab: String,
        /// RNG seed.
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// Simulated time (s); default: the lab's.
        #[arg(long)]
        duration: Option<f64>,
        /// Output CSV file; the sidecar is the same name with `.json`.
        #[arg(long)]
        csv: PathBuf,
        /// Parameter override `key=value` (repeatable).
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
        /// A named preset of the lab (see `attlab labs`), applied before `--set`.
        #[arg(long)]
        preset: Option<String>,
        /// Write every series even for a lab whose paper defines its own output file.
        #[arg(long)]
        all_series: bool,
        /// Refuse a run whose CSV would exceed this many megabytes (estimated before it
        /// starts from a short probe run).
        #[arg(long, default_value_t = 2000.0)]
        max_csv_mb: f64,
        /// Also run a "what if" from this moment (s) with the `--what-if` changes, written
        /// beside the CSV as `<name>.whatif.csv` (the same random numbers from there on).
        #[arg(long)]
        branch_at: Option<f64>,
        /// A change `key=value` of the what-if run (repeatable; with `--branch-at`).
        #[arg(long = "what-if", value_name = "KEY=VALUE", requires = "branch_at")]
        what_if: Vec<String>,
    },
    /// Run a lab's estimators on a recorded log and write the series: a gyro log (CSV: time,
    /// rate; p1) or an Arduino MPU-6050 log (CSV: time, ax, ay, az, gx, gy, gz; p4).
    Replay {
        /// Lab id (p1 for a gyro log, p4 for an IMU log).
        #[arg(long)]
        lab: String,
        /// The log file.
        #[arg(long)]
        log: PathBuf,
        /// Gyro logs: unit of the rate column, deg_s (default), mdeg_s or rad_s.
        #[arg(long)]
        rate_unit: Option<String>,
        /// Unit of the time column, s or ms (default: s for a gyro log, ms — Arduino
        /// millis() — for an IMU log).
        #[arg(long)]
        time_unit: Option<String>,
        /// IMU logs: accelerometer columns in counts of ±2/4/8/16 g (counts2 … counts16; the
        /// chip's power-on counts2 by default), g or mps2.
        #[arg(long)]
        accel_unit: Option<String>,
        /// IMU logs: gyro columns in counts of ±250/500/1000/2000 °/s (counts250 …; the
        /// power-on counts250 by default), deg_s or rad_s.
        #[arg(long)]
        gyro_unit: Option<String>,
        /// Any of the log format's unit settings as `key=value` (repeatable), e.g. a gyro
        /// log of raw counts: `--log-set rate_counts=24-bit --log-set count_scale=0.0238
        /// --log-set count_zero=1258` (an unknown key lists the format's settings).
        #[arg(long = "log-set", value_name = "KEY=VALUE")]
        log_set: Vec<String>,
        /// Output CSV file.
        #[arg(long)]
        csv: PathBuf,
        /// Parameter override `key=value` (repeatable).
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
        /// Refuse a run whose CSV would exceed this many megabytes (estimated before it
        /// starts from a short probe run).
        #[arg(long, default_value_t = 2000.0)]
        max_csv_mb: f64,
    },
    /// Write the teacher notes (a printable page per lesson, in English and Russian, and an
    /// index) into a folder: `cargo xtask dist` puts them in the site's `teacher/`.
    Teacher {
        /// The folder (created if missing).
        #[arg(long)]
        out: PathBuf,
        /// The site's public address, ending in `/`: the notes' links and QR codes point there
        /// (without it, links are relative to the site and there are no QR codes).
        #[arg(long)]
        address: Option<String>,
        /// The commit the site is built from (the notes' footer).
        #[arg(long, default_value = "unknown")]
        commit: String,
    },
    /// Time one simulation step of every lab and one step of every estimator.
    Bench {
        /// Steps to time per item.
        #[arg(long, default_value_t = 20_000)]
        steps: usize,
        /// Only this lab.
        #[arg(long)]
        lab: Option<String>,
    },
}

/// Entry point: parse, dispatch, map errors to a message and exit code 2.
pub fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Labs { lang } => match Lang::from_tag(&lang) {
            Some(lang) => {
                print!("{}", lab_listing(lang));
                Ok(true)
            }
            None => Err(format!("--lang {lang}: the languages are en and ru")),
        },
        Command::Reproduce {
            lab,
            json,
            markdown,
            readme,
        } => reproduce(&lab, json.as_deref(), markdown, readme),
        Command::Fuzz { sets, steps, seed } => Ok(run_fuzz(sets, steps, seed)),
        command @ Command::Run { .. } => run_command(command),
        Command::Replay {
            lab,
            log,
            rate_unit,
            time_unit,
            accel_unit,
            gyro_unit,
            log_set,
            csv,
            set,
            max_csv_mb,
        } => replay(
            &lab,
            &log,
            LogUnits {
                rate: rate_unit.as_deref(),
                time: time_unit.as_deref(),
                accel: accel_unit.as_deref(),
                gyro: gyro_unit.as_deref(),
                assignments: &log_set,
            },
            Output::new(&csv, max_csv_mb),
            &set,
        )
        .map(|()| true),
        Command::Teacher {
            out,
            address,
            commit,
        } => teacher(&out, address.as_deref(), &commit).map_err(|e| e.to_string()),
        Command::Bench { steps, lab } => match lab.as_deref().map(find_lab).transpose() {
            Ok(only) => {
                bench(steps.max(10), only);
                Ok(true)
            }
            Err(e) => Err(e),
        },
    };
    exit_code(result)
}

/// The process's exit: 0 when every check held, 1 when one failed, 2 (with the message) when
/// the command could not run.
fn exit_code(result: Result<bool, String>) -> ExitCode {
    match result {
        Ok(true) => ExitCode::SUCCESS,
        Ok(false) => ExitCode::from(1),
        Err(message) => {
            eprintln!("attlab: error: {message}");
            ExitCode::from(2)
        }
    }
}

/// `attlab run`, with a what-if when `--branch-at` is given.
fn run_command(command: Command) -> Result<bool, String> {
    let Command::Run {
        lab,
        seed,
        duration,
        csv,
        set,
        preset,
        all_series,
        max_csv_mb,
        branch_at,
        what_if,
    } = command
    else {
        return Ok(false);
    };
    match branch_at {
        Some(at_s) => branch::run(branch::BranchRun {
            lab: &lab,
            seed,
            duration_s: duration,
            csv: &csv,
            preset: preset.as_deref(),
            set: &set,
            at_s,
            what_if: &what_if,
        })
        .map_err(|e| e.to_string()),
        None => run(
            &lab,
            seed,
            duration,
            Output::new(&csv, max_csv_mb),
            preset.as_deref(),
            &set,
            all_series,
        ),
    }
    .map(|()| true)
}

fn find_lab(id: &str) -> Result<&'static dyn Lab, String> {
    labs::find(id).ok_or_else(|| format!("no lab `{id}`; labs: {}", labs::ids()))
}

/// Every lab with its presets and parameters: the flags as the CLI takes them, the words in
/// `lang` (labels, help and choices from the message catalogue, as the page shows them).
fn lab_listing(lang: Lang) -> String {
    use std::fmt::Write as _;
    let mut out = String::new();
    for lab in labs::all() {
        let id = lab.id();
        let word = |msg: &str, english: &str| i18n::lab_text(lang, msg, english);
        let title = word(&i18n::lab_title_id(id), lab.title());
        let paper = i18n::t(lang, "cli-paper");
        let cited = word(&i18n::lab_paper_id(id), lab.paper());
        let _ = writeln!(out, "{id} — {title}\n  {paper}: {cited}");
        for p in lab.presets() {
            let name = word(&i18n::preset_id(id, p.id), p.name);
            let help = word(&i18n::preset_help_id(id, p.id), p.help);
            let _ = writeln!(out, "  --preset {} ({name}: {help})", p.id);
        }
        for p in lab.params() {
            let range = match p.kind {
                ParamKind::Choice(options) => options
                    .iter()
                    .enumerate()
                    .map(|(i, o)| {
                        let words = word(&i18n::param_option_id(id, p.key, i), o);
                        if words == *o {
                            format!("{i} = {o}")
                        } else {
                            format!("{i} = {o} ({words})")
                        }
                    })
                    .collect::<Vec<_>>()
                    .join(" | "),
                ParamKind::Toggle => "0 | 1".to_string(),
                _ => format!("{} … {} {}", p.min, p.max, p.unit),
            };
            let label = word(&i18n::param_label_id(id, p.key), p.label);
            let _ = writeln!(
                out,
                "  --set {}=<{range}> (default {}) {label}",
                p.key, p.default
            );
        }
    }
    out
}

fn reproduce(
    which: &str,
    json: Option<&Path>,
    markdown: bool,
    write_chapters: bool,
) -> Result<bool, String> {
    let selected: Vec<&'static dyn Lab> = if which == "all" {
        labs::all().to_vec()
    } else {
        vec![find_lab(which)?]
    };
    // Every lab's reproduction on every core (each is deterministic, so the order of the
    // threads changes nothing); printed in the registry's order, the timings afterwards one
    // at a time so that they are not measured beside a busy core.
    let computed: Vec<Result<Reproduction, String>> = selected
        .par_iter()
        .map(|lab| {
            lab.reproduce()
                .map_err(|e| format!("{}: the reproduction could not be computed: {e}", lab.id()))
        })
        .collect();
    let mut reports: Vec<Reproduction> = Vec::new();
    for (lab, rep) in selected.iter().zip(computed) {
        let rep = rep?;
        if markdown {
            println!("### {}\n\n{}", rep.lab, rep.to_markdown());
        } else {
            println!("{}", rep.to_table());
            print_timings(*lab, 200_000);
        }
        reports.push(rep);
    }
    if let Some(path) = json {
        let text = serde_json::to_string_pretty(&reports).map_err(|e| e.to_string())?;
        std::fs::write(path, text).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    }
    if write_chapters {
        for (lab, rep) in selected.iter().zip(&reports) {
            write_chapter(*lab, rep)?;
        }
    }
    let failures: Vec<String> = reports.iter().flat_map(Reproduction::failures).collect();
    for f in &failures {
        println!("FAILS: {f}");
    }
    Ok(failures.is_empty())
}

/// Rewrites `rep`'s table in `lab`'s chapter, found from the workspace this binary was
/// built in.
fn write_chapter(lab: &dyn Lab, rep: &Reproduction) -> Result<(), String> {
    let Some(study) = lab.study() else {
        return Err(format!("{}: the lab has no study, so no chapter", lab.id()));
    };
    let root = Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .unwrap_or(Path::new("."));
    let path = root.join(study.chapter().path());
    let text = std::fs::read_to_string(&path)
        .map_err(|e| format!("cannot read {}: {e}", path.display()))?;
    let text = readme::with_table(&text, rep).map_err(|e| format!("{}: {e}", path.display()))?;
    std::fs::write(&path, text).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    println!("updated the table in {}", path.display());
    Ok(())
}

/// The heap's live bytes, from the binary's counting allocator.
fn live_heap() -> usize {
    fuzz::live_bytes(&stats_alloc::INSTRUMENTED_SYSTEM.stats()).max(0) as usize
}

fn run_fuzz(sets: usize, steps: usize, seed: u64) -> bool {
    fuzz::count_heap_with(live_heap);
    let config = FuzzConfig { sets, steps, seed };
    let report = fuzz::run(labs::all(), config, |i, lab| {
        if i % 100 == 0 {
            eprintln!("fuzz: set {i} of {sets} ({lab})");
        }
    });
    for (lab, n) in &report.sets_per_lab {
        println!("{lab:<16} {n} sets");
    }
    println!(
        "{} sets, {} with an estimator flagging itself (diverged/unobservable), largest recorder {:.1} MiB, largest heap growth of a set {:.1} MiB, {} failures",
        sets,
        report.flagged,
        report.max_memory_bytes as f64 / (1 << 20) as f64,
        report.max_heap_bytes.unwrap_or(0) as f64 / (1 << 20) as f64,
        report.failures.len()
    );
    for f in &report.failures {
        println!("FAIL {f}");
    }
    report.failures.is_empty()
}

/// `attlab teacher`: writes the notes and says where.
fn teacher(
    out: &Path,
    address: Option<&str>,
    commit: &str,
) -> Result<bool, attlab::teacher::TeacherError> {
    use attlab::teacher::{Build, write};
    let build = Build::new(address, env!("CARGO_PKG_VERSION"), commit)?;
    let written = write(out, &build)?;
    println!(
        "attlab: {} teacher pages in {}",
        written.len(),
        out.display()
    );
    Ok(true)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_listing_speaks_russian_and_keeps_the_flags() {
        let (en, ru) = (lab_listing(Lang::En), lab_listing(Lang::Ru));
        assert!(en.contains("--set gyro_noise_deg_s=") && en.contains("Gyro noise σ"));
        assert!(ru.contains("--set gyro_noise_deg_s=") && ru.contains("Шум гироскопа σ"));
        assert!(ru.contains("Статья 1"), "lab titles in Russian");
        assert_eq!(en.lines().count(), ru.lines().count());
    }
}
