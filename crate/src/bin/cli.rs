//! The CLI proper (native only).

use attlab::analysis::fuzz::{self, FuzzConfig};
use attlab::analysis::readme;
use attlab::labs;
use attlab::model::{Lab, ParamKind, ParamValues, Reproduction};
use attlab::sim::{CsvSink, Selection, SimOptions, Simulation};
use clap::{Parser, Subcommand};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

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
    Labs,
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
        /// Rewrite the tables between the `<!-- reproduce:ID -->` markers of this README.
        #[arg(long)]
        readme: Option<PathBuf>,
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
        /// Gyro logs: unit of the rate column, deg_s, mdeg_s or rad_s.
        #[arg(long, default_value = "deg_s")]
        rate_unit: String,
        /// Unit of the time column, s or ms (default: s for a gyro log, ms — Arduino
        /// millis() — for an IMU log).
        #[arg(long)]
        time_unit: Option<String>,
        /// IMU logs: accelerometer columns in counts of ±2/4/8/16 g (counts2 … counts16; the
        /// chip's power-on counts2 by default), g or mps2.
        #[arg(long, default_value = "counts2")]
        accel_unit: String,
        /// IMU logs: gyro columns in counts of ±250/500/1000/2000 °/s (counts250 …; the
        /// power-on counts250 by default), deg_s or rad_s.
        #[arg(long, default_value = "counts250")]
        gyro_unit: String,
        /// Output CSV file.
        #[arg(long)]
        csv: PathBuf,
        /// Parameter override `key=value` (repeatable).
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
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
        Command::Labs => {
            list_labs();
            Ok(true)
        }
        Command::Reproduce {
            lab,
            json,
            markdown,
            readme,
        } => reproduce(&lab, json.as_deref(), markdown, readme.as_deref()),
        Command::Fuzz { sets, steps, seed } => Ok(run_fuzz(sets, steps, seed)),
        Command::Run {
            lab,
            seed,
            duration,
            csv,
            set,
            preset,
            all_series,
        } => run(
            &lab,
            seed,
            duration,
            &csv,
            preset.as_deref(),
            &set,
            all_series,
        )
        .map(|()| true),
        Command::Replay {
            lab,
            log,
            rate_unit,
            time_unit,
            accel_unit,
            gyro_unit,
            csv,
            set,
        } => replay(
            &lab,
            &log,
            LogUnits {
                rate: &rate_unit,
                time: time_unit.as_deref(),
                accel: &accel_unit,
                gyro: &gyro_unit,
            },
            &csv,
            &set,
        )
        .map(|()| true),
        Command::Bench { steps, lab } => match lab.as_deref().map(find_lab).transpose() {
            Ok(only) => {
                bench(steps.max(10), only);
                Ok(true)
            }
            Err(e) => Err(e),
        },
    };
    match result {
        Ok(true) => ExitCode::SUCCESS,
        Ok(false) => ExitCode::from(1),
        Err(message) => {
            eprintln!("attlab: error: {message}");
            ExitCode::from(2)
        }
    }
}

fn find_lab(id: &str) -> Result<&'static dyn Lab, String> {
    labs::find(id).ok_or_else(|| format!("no lab `{id}`; labs: {}", labs::ids()))
}

fn list_labs() {
    for lab in labs::all() {
        println!("{} — {}\n  paper: {}", lab.id(), lab.title(), lab.paper());
        for p in lab.presets() {
            println!("  --preset {:?} ({})", p.name, p.help);
        }
        for p in lab.params() {
            let range = match p.kind {
                ParamKind::Choice(options) => options
                    .iter()
                    .enumerate()
                    .map(|(i, o)| format!("{i} = {o}"))
                    .collect::<Vec<_>>()
                    .join(" | "),
                ParamKind::Toggle => "0 | 1".to_string(),
                _ => format!("{} … {} {}", p.min, p.max, p.unit),
            };
            println!(
                "  --set {}=<{range}> (default {}) {}",
                p.key, p.default, p.label
            );
        }
    }
}

fn reproduce(
    which: &str,
    json: Option<&Path>,
    markdown: bool,
    readme_path: Option<&Path>,
) -> Result<bool, String> {
    let selected: Vec<&'static dyn Lab> = if which == "all" {
        labs::all().to_vec()
    } else {
        vec![find_lab(which)?]
    };
    let mut reports: Vec<Reproduction> = Vec::new();
    for lab in selected {
        let rep = lab
            .reproduce()
            .map_err(|e| format!("{}: the reproduction could not be computed: {e}", lab.id()))?;
        if markdown {
            println!("### {}\n\n{}", rep.lab, rep.to_markdown());
        } else {
            println!("{}", rep.to_table());
            print_timings(lab, 200_000);
        }
        reports.push(rep);
    }
    if let Some(path) = json {
        let text = serde_json::to_string_pretty(&reports).map_err(|e| e.to_string())?;
        std::fs::write(path, text).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    }
    if let Some(path) = readme_path {
        let mut text = std::fs::read_to_string(path)
            .map_err(|e| format!("cannot read {}: {e}", path.display()))?;
        for rep in &reports {
            text =
                readme::with_table(&text, rep).map_err(|e| format!("{}: {e}", path.display()))?;
        }
        std::fs::write(path, text).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
        println!("updated {} tables in {}", reports.len(), path.display());
    }
    let failures: Vec<String> = reports.iter().flat_map(Reproduction::failures).collect();
    for f in &failures {
        println!("FAILS: {f}");
    }
    Ok(failures.is_empty())
}

fn run_fuzz(sets: usize, steps: usize, seed: u64) -> bool {
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
        "{} sets, {} with an estimator flagging itself (diverged/unobservable), largest recorder {:.1} MiB, {} failures",
        sets,
        report.flagged,
        report.max_memory_bytes as f64 / (1 << 20) as f64,
        report.failures.len()
    );
    for f in &report.failures {
        println!("FAIL {f}");
    }
    report.failures.is_empty()
}

fn run(
    lab_id: &str,
    seed: u64,
    duration: Option<f64>,
    csv_path: &Path,
    preset: Option<&str>,
    set: &[String],
    every_series: bool,
) -> Result<(), String> {
    let lab = find_lab(lab_id)?;
    let params = params_from(lab, preset, set)?;
    let duration_s = duration.unwrap_or(lab.default_duration_s());
    if !(duration_s.is_finite() && duration_s > 0.0 && duration_s <= 1e6) {
        return Err(format!(
            "--duration must be a number of seconds in (0, 1e6], got {duration_s}"
        ));
    }
    if let (false, Some(file)) = (every_series, lab.output_file(&params)) {
        let out = std::fs::File::create(csv_path)
            .map_err(|e| format!("cannot create {}: {e}", csv_path.display()))?;
        let (rows, stopped) = attlab::sim::write_output_file(
            lab,
            params,
            seed,
            duration_s,
            &file,
            std::io::BufWriter::new(out),
        )?;
        println!(
            "wrote the paper's output file, {rows} rows ({}) to {}{}",
            file.headers.join(", "),
            csv_path.display(),
            if stopped {
                ", ending at the first row within tolerance"
            } else {
                " (the tolerance was not reached)"
            }
        );
        return Ok(());
    }
    let mut sim = Simulation::with_options(lab, params.clone(), seed, all_series())
        .map_err(|e| e.to_string())?;
    let rows = stream_csv(&mut sim, duration_s, csv_path)?;
    let sidecar = csv_path.with_extension("json");
    let meta = serde_json::json!({
        "attlab_version": env!("CARGO_PKG_VERSION"),
        "lab": lab.id(),
        "title": lab.title(),
        "paper": lab.paper(),
        "seed": seed,
        "duration_s": duration_s,
        "dt_s": sim.dt_s(),
        "rows": rows,
        "params": lab.params().iter().map(|p| serde_json::json!({
            "key": p.key, "value": params.get(p.key), "unit": p.unit, "label": p.label,
            "default": p.default, "min": p.min, "max": p.max,
        })).collect::<Vec<_>>(),
        "series": sim.specs(),
        "missing_values": "empty cells",
        "csv": csv_path.file_name().map(|n| n.to_string_lossy().to_string()),
    });
    let text = serde_json::to_string_pretty(&meta).map_err(|e| e.to_string())?;
    std::fs::write(&sidecar, text)
        .map_err(|e| format!("cannot write {}: {e}", sidecar.display()))?;
    println!(
        "wrote {rows} rows × {} series to {} and parameters to {}",
        sim.specs().len(),
        csv_path.display(),
        sidecar.display()
    );
    Ok(())
}

/// The unit flags of `attlab replay`.
struct LogUnits<'a> {
    rate: &'a str,
    time: Option<&'a str>,
    accel: &'a str,
    gyro: &'a str,
}

fn replay(
    lab_id: &str,
    log_path: &Path,
    units: LogUnits<'_>,
    csv_path: &Path,
    set: &[String],
) -> Result<(), String> {
    use attlab::sensors::{
        AccelUnit, GyroUnit, ImuScales, RateUnit, TimeUnit, parse_imu_log, parse_rate_log,
    };
    let lab = find_lab(lab_id)?;
    let names = |all: &[&str]| all.join(", ");
    let imu = lab.accepts_imu_log();
    if !imu && !lab.accepts_rate_log() {
        return Err(format!(
            "lab {lab_id} does not replay logs: use p1 (gyro log) or p4 (IMU log)"
        ));
    }
    let time_unit = match units.time.unwrap_or(if imu { "ms" } else { "s" }) {
        "s" => TimeUnit::Seconds,
        "ms" => TimeUnit::Milliseconds,
        other => return Err(format!("--time-unit `{other}`: use s or ms")),
    };
    let text = std::fs::read_to_string(log_path)
        .map_err(|e| format!("cannot read {}: {e}", log_path.display()))?;
    let log = if imu {
        let accel = AccelUnit::from_name(units.accel).ok_or_else(|| {
            format!(
                "--accel-unit `{}`: use one of {}",
                units.accel,
                names(&AccelUnit::ALL.map(|(_, n)| n))
            )
        })?;
        let gyro = GyroUnit::from_name(units.gyro).ok_or_else(|| {
            format!(
                "--gyro-unit `{}`: use one of {}",
                units.gyro,
                names(&GyroUnit::ALL.map(|(_, n)| n))
            )
        })?;
        parse_imu_log(
            &text,
            ImuScales {
                time: time_unit,
                accel,
                gyro,
            },
        )
    } else {
        let rate_unit = RateUnit::from_name(units.rate).ok_or_else(|| {
            format!(
                "--rate-unit `{}`: use one of {}",
                units.rate,
                names(&RateUnit::ALL.map(|(_, n)| n))
            )
        })?;
        parse_rate_log(&text, rate_unit, time_unit)
    };
    for e in &log.errors {
        eprintln!("attlab: {}: skipped {e}", log_path.display());
    }
    let params = params_from(lab, None, set)?;
    let (samples, skipped) = (log.t_s.len(), log.errors.len());
    let duration = log.t_s.last().copied().unwrap_or(0.0) - log.t_s.first().copied().unwrap_or(0.0);
    let mut sim = Simulation::replay(lab, params, log, all_series())
        .map_err(|e| format!("{}: {e}", log_path.display()))?;
    stream_csv(&mut sim, duration, csv_path)?;
    println!(
        "replayed {samples} samples ({skipped} lines skipped) over {duration:.2} s into {}",
        csv_path.display()
    );
    Ok(())
}

/// The lab's defaults, then the named preset, then the `key=value` overrides; every bad
/// item is reported.
fn params_from(
    lab: &'static dyn Lab,
    preset: Option<&str>,
    set: &[String],
) -> Result<ParamValues, String> {
    let mut params = ParamValues::defaults(lab.params());
    if let Some(name) = preset {
        let names = || {
            lab.presets()
                .iter()
                .map(|p| p.name)
                .collect::<Vec<_>>()
                .join(", ")
        };
        let p = lab
            .presets()
            .iter()
            .find(|p| p.name == name)
            .ok_or_else(|| format!("no preset `{name}` in {} (presets: {})", lab.id(), names()))?;
        for (k, v) in p.values {
            params.set(lab.params(), k, *v).map_err(|e| e.to_string())?;
        }
    }
    let errors = params.apply_assignments(lab.params(), set.iter().map(String::as_str));
    if errors.is_empty() {
        Ok(params)
    } else {
        Err(errors
            .iter()
            .map(ToString::to_string)
            .collect::<Vec<_>>()
            .join("; "))
    }
}

/// Every series, in a small recorder: the CSV gets every sample as it is made.
fn all_series() -> SimOptions {
    SimOptions {
        selection: Selection::All,
        budget_bytes: 1 << 20,
    }
}

/// Writes the header and the current row, then steps until `duration_s`, one row per step.
/// Returns the number of rows written.
fn stream_csv(sim: &mut Simulation, duration_s: f64, csv_path: &Path) -> Result<u64, String> {
    let file = std::fs::File::create(csv_path)
        .map_err(|e| format!("cannot create {}: {e}", csv_path.display()))?;
    let io = |e: csv::Error| format!("writing {}: {e}", csv_path.display());
    let mut out = CsvSink::new(std::io::BufWriter::new(file), sim.specs()).map_err(io)?;
    out.row(sim.last_row()).map_err(io)?;
    let end = duration_s - 1e-9 * sim.dt_s();
    while sim.t_s() < end {
        sim.step();
        out.row(sim.last_row()).map_err(io)?;
    }
    out.finish().map_err(io)
}

/// Times the lab's timing items and prints each against the first (the cost comparison).
fn print_timings(lab: &'static dyn Lab, reps: usize) {
    let mut items = lab.timing_items();
    if items.is_empty() {
        return;
    }
    println!("cost (native, release build, {reps} repetitions each; measured, not a test):");
    let mut base = None;
    for item in &mut items {
        for _ in 0..reps / 10 {
            (item.run)();
        }
        let t0 = Instant::now();
        for _ in 0..reps {
            (item.run)();
        }
        let ns = t0.elapsed().as_nanos() as f64 / reps as f64;
        let b = *base.get_or_insert(ns);
        let flops = item.flops.map_or(String::new(), |f| {
            format!("   {f} FLOP counted, {:.1} FLOP/ns", f as f64 / ns)
        });
        println!(
            "  {:<40} {:>8.1} ns   ×{:.2} of the first{flops}",
            item.name,
            ns,
            ns / b
        );
    }
    println!();
}

/// Nanoseconds per call of `f`: the best of five batches of `n / 5` calls after a
/// warm-up (the least disturbed measurement on a shared machine).
fn time_ns(n: usize, mut f: impl FnMut()) -> f64 {
    for _ in 0..n / 10 {
        f();
    }
    let batch = (n / 5).max(1);
    (0..5)
        .map(|_| {
            let t0 = Instant::now();
            for _ in 0..batch {
                f();
            }
            t0.elapsed().as_nanos() as f64 / batch as f64
        })
        .fold(f64::INFINITY, f64::min)
}

fn bench(steps: usize, only: Option<&'static dyn Lab>) {
    println!(
        "{:<14} {:<38} {:>10} {:>10}",
        "lab", "item", "ns/step", "note"
    );
    let selected: Vec<&'static dyn Lab> = only.map_or_else(|| labs::all().to_vec(), |l| vec![l]);
    for lab in &selected {
        let params = ParamValues::defaults(lab.params());
        let mut sim = Simulation::new(*lab, params.clone(), 1);
        let step_ns = time_ns(steps, || sim.step());
        let memory = sim.recorder().memory_bytes();
        let series = sim.specs().len();
        let mut all = Simulation::with_options(*lab, params.clone(), 1, all_series())
            .map_err(|e| e.to_string());
        let all_ns = match &mut all {
            Ok(sim) => time_ns(steps, || sim.step()),
            Err(_) => f64::NAN,
        };
        let mut bare = Simulation::with_options(*lab, params.clone(), 1, SimOptions::named(&[]))
            .map_err(|e| e.to_string());
        let bare_ns = match &mut bare {
            Ok(sim) => time_ns(steps, || sim.step()),
            Err(_) => f64::NAN,
        };

        let mut rng = ChaCha8Rng::seed_from_u64(1);
        let mut run = lab.build(&params, &mut rng);
        let dt = lab.dt_s(&params);
        let trace = run.measurement_trace(dt, steps, &mut rng);
        let mut sum = 0.0;
        let mut lines = Vec::new();
        for est in &mut run.estimators {
            // Best of five chunks of the trace, like the simulation step.
            let ns = trace
                .chunks(trace.len().div_ceil(5).max(1))
                .map(|chunk| {
                    let t0 = Instant::now();
                    for m in chunk {
                        est.step(m, dt);
                    }
                    t0.elapsed().as_nanos() as f64 / chunk.len() as f64
                })
                .fold(f64::INFINITY, f64::min);
            std::hint::black_box(est.estimate());
            sum += ns;
            lines.push((format!("estimator {}", est.id()), ns));
        }
        let aim = 2.0 * sum + 500.0;
        println!(
            "{:<14} {:<38} {:>10.0} {:>10}",
            lab.id(),
            format!("simulation step (page: {series} series)"),
            step_ns,
            if step_ns <= aim {
                "within aim"
            } else {
                "OVER AIM"
            }
        );
        println!(
            "{:<14} {:<38} {:>10.0}",
            "", "simulation step (every series)", all_ns
        );
        println!(
            "{:<14} {:<38} {:>10.0}",
            "", "simulation step (time only)", bare_ns
        );
        for (name, ns) in lines {
            println!("{:<14} {:<38} {:>10.0}", "", name, ns);
        }
        println!(
            "{:<14} {:<38} {:>10.0} {:>10}",
            "",
            "sum of estimator steps",
            sum,
            format!("×{:.2}", step_ns / sum.max(1.0))
        );
        println!(
            "{:<14} {:<38} {:>10.0} {:>10}",
            "",
            "aim: 2 × sum + 500 ns",
            aim,
            format!("{:.2} of aim", step_ns / aim)
        );
        println!(
            "{:<14} {:<38} {:>10.1} {:>10}",
            "",
            "recorder memory (MiB, fixed)",
            memory as f64 / (1 << 20) as f64,
            format!("{} rows full rate", sim.recorder().window())
        );
        print_timings(*lab, steps * 10);
    }
    let _ = std::io::stdout().flush();
}
