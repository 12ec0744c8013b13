//! `attlab run` and `attlab replay`: a lab's run or a recorded log through its estimators,
//! every series streamed to a CSV.

use super::find_lab;
use attlab::i18n::{self, FluentValue, Lang};
use attlab::model::ParamValues;
use attlab::page::Lab;
use attlab::sim::{CsvSink, Selection, SimOptions, Simulation, csv_cell};
use std::path::Path;

/// Where a run's CSV goes, and how large it may get.
pub(super) struct Output<'a> {
    csv: &'a Path,
    max_bytes: f64,
}

impl<'a> Output<'a> {
    pub(super) fn new(csv: &'a Path, max_csv_mb: f64) -> Self {
        Self {
            csv,
            max_bytes: max_csv_mb * 1e6,
        }
    }

    /// Refuses `what` if `rows` rows of `cells` cells (at the mean cell size of steps
    /// 300–400 of a probe run, `probe`) would exceed the limit; the message gives the estimate.
    fn check(
        &self,
        what: &str,
        mut probe: Simulation,
        rows: f64,
        cells: usize,
    ) -> Result<(), String> {
        // The first steps write short cells (zeros, round numbers): measure the later ones.
        let (mut bytes, mut n) = (0usize, 0usize);
        for k in 0..400 {
            probe.step();
            if k >= 300 {
                let row = probe.last_row();
                bytes += row.iter().map(|v| csv_cell(*v).len() + 1).sum::<usize>();
                n += row.len();
            }
        }
        let estimate = rows * cells as f64 * bytes as f64 / n.max(1) as f64;
        if estimate <= self.max_bytes {
            return Ok(());
        }
        let size = if estimate >= 1e9 {
            format!("{:.1} GB", estimate / 1e9)
        } else {
            format!("{:.1} MB", estimate / 1e6)
        };
        Err(format!(
            "{what} would write about {size} of CSV ({rows:.3e} rows × {cells} columns) to {}; \
             the limit is {} MB: shorten it, or raise the limit with --max-csv-mb",
            self.csv.display(),
            self.max_bytes / 1e6
        ))
    }
}

/// The lab's notes on these settings (what the page shows under the sliders), warnings
/// first, on standard error so the CSV on standard output stays clean.
fn print_notes(lab: &dyn Lab, params: &ParamValues) {
    let mut notes = lab.param_notes(params);
    notes.sort_by_key(|n| !n.warning);
    for note in notes {
        let args: Vec<(&str, FluentValue<'_>)> = note
            .args
            .iter()
            .map(|(k, v)| (*k, FluentValue::from(v.as_str())))
            .collect();
        let text = i18n::t_with(Lang::En, note.message, &args);
        let kind = if note.warning { "warning" } else { "note" };
        eprintln!("{kind} ({}): {text}", note.key);
    }
}

pub(super) fn run(
    lab_id: &str,
    seed: u64,
    duration: Option<f64>,
    output: Output<'_>,
    preset: Option<&str>,
    set: &[String],
    every_series: bool,
) -> Result<(), String> {
    let lab = find_lab(lab_id)?;
    let params = params_from(lab, preset, set)?;
    print_notes(lab, &params);
    let duration_s = duration.unwrap_or(lab.default_duration_s());
    if !(duration_s.is_finite() && duration_s > 0.0 && duration_s <= 1e6) {
        return Err(format!(
            "--duration must be a number of seconds in (0, 1e6], got {duration_s}"
        ));
    }
    let csv_path = output.csv;
    let probe = Simulation::with_options(lab, params.clone(), seed, all_series())
        .map_err(|e| e.to_string())?;
    let rows = (duration_s / probe.dt_s()).ceil() + 1.0;
    let cells = match (every_series, lab.output_file(&params)) {
        (false, Some(file)) => file.headers.len(),
        _ => probe.specs().len(),
    };
    output.check(&format!("--duration {duration_s} s"), probe, rows, cells)?;
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
        )
        .map_err(|e| format!("{}: {e}", csv_path.display()))?;
        println!(
            "wrote the paper's output file, {rows} rows ({}) to {}{}",
            file.headers.join(", "),
            csv_path.display(),
            match (&file.stop, stopped) {
                (None, _) => "",
                (Some(_), true) => ", ending at the first row within tolerance",
                (Some(_), false) => " (the tolerance was not reached)",
            }
        );
        return Ok(());
    }
    let mut sim = Simulation::with_options(lab, params.clone(), seed, all_series())
        .map_err(|e| e.to_string())?;
    let rows = stream_csv(&mut sim, duration_s, csv_path)?;
    let sidecar = write_sidecar(&sim, &params, seed, duration_s, rows, csv_path)?;
    println!(
        "wrote {rows} rows × {} series to {} and parameters to {}",
        sim.specs().len(),
        csv_path.display(),
        sidecar.display()
    );
    Ok(())
}

/// Writes the JSON sidecar of a run beside its CSV; returns its path.
fn write_sidecar(
    sim: &Simulation,
    params: &ParamValues,
    seed: u64,
    duration_s: f64,
    rows: u64,
    csv_path: &Path,
) -> Result<std::path::PathBuf, String> {
    let lab = sim.lab();
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
    Ok(sidecar)
}

/// The unit flags of `attlab replay`: by the name of the unit (`--rate-unit` is `rate`),
/// then any unit setting as `key=value` (`--log-set`).
pub(super) struct LogUnits<'a> {
    pub(super) rate: Option<&'a str>,
    pub(super) time: Option<&'a str>,
    pub(super) accel: Option<&'a str>,
    pub(super) gyro: Option<&'a str>,
    pub(super) assignments: &'a [String],
}

pub(super) fn replay(
    lab_id: &str,
    log_path: &Path,
    units: LogUnits<'_>,
    output: Output<'_>,
    set: &[String],
) -> Result<(), String> {
    let lab = find_lab(lab_id)?;
    let Some(format) = lab.page().log_format else {
        return attlab::labs::read_log(lab, &[], &ParamValues::defaults(&[]))
            .map(|_| ())
            .map_err(|e| e.to_string());
    };
    let unit_values = log_units(format, &units)?;
    let bytes =
        std::fs::read(log_path).map_err(|e| format!("cannot read {}: {e}", log_path.display()))?;
    let name = log_path.display();
    let log =
        attlab::labs::read_log(lab, &bytes, &unit_values).map_err(|e| format!("{name}: {e}"))?;
    for e in &log.errors {
        eprintln!("attlab: {name}: skipped {e}");
    }
    for e in &log.notes {
        eprintln!("attlab: {name}: kept {e}");
    }
    for g in &log.gaps {
        eprintln!(
            "attlab: {name}: line {}: the clock {} from {} s to {} s; joined after {:.3} s",
            g.line,
            if g.logged_to_s < g.logged_from_s {
                "restarted"
            } else {
                "jumped"
            },
            g.logged_from_s,
            g.logged_to_s,
            g.to_s - g.from_s
        );
    }
    let params = params_from(lab, None, set)?;
    let (counts, gaps, span) = (log.counts, log.gaps.len(), log.span_s());
    let rows = span / log.period_s + 2.0;
    let probe = Simulation::replay(lab, params.clone(), log.clone(), all_series())
        .map_err(|e| format!("{name}: {e}"))?;
    let cells = probe.specs().len();
    output.check(&format!("replaying {name}"), probe, rows, cells)?;
    let mut sim =
        Simulation::replay(lab, params, log, all_series()).map_err(|e| format!("{name}: {e}"))?;
    stream_csv(&mut sim, span, output.csv)?;
    println!(
        "replayed {name}: {counts}, {gaps} clock {}, over {span:.2} s into {}",
        if gaps == 1 { "gap" } else { "gaps" },
        output.csv.display()
    );
    Ok(())
}

/// The lab's defaults, then the named preset, then the `key=value` overrides; every bad
/// item is reported.
pub(super) fn params_from(
    lab: &'static dyn Lab,
    preset: Option<&str>,
    set: &[String],
) -> Result<ParamValues, String> {
    let mut params = ParamValues::defaults(lab.params());
    if let Some(name) = preset {
        let names = || {
            lab.presets()
                .iter()
                .map(|p| p.id)
                .collect::<Vec<_>>()
                .join(", ")
        };
        // By its id (`gamma-small`), or by its English name as the page's button reads.
        let p = (lab.presets().iter())
            .find(|p| p.id == name || p.name == name)
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
pub(super) fn all_series() -> SimOptions {
    SimOptions {
        selection: Selection::All,
        budget_bytes: 1 << 20,
    }
}

/// Writes the header and the current row, then steps until `duration_s`, one row per step.
/// Returns the number of rows written.
pub(super) fn stream_csv(
    sim: &mut Simulation,
    duration_s: f64,
    csv_path: &Path,
) -> Result<u64, String> {
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

/// The unit choices of `format` with the flags given: each flag `--<name>-unit` sets the
/// format's `<name>_unit` by an option's name. A flag the format has no such unit for is an
/// error naming the units it has.
fn log_units(
    format: &attlab::model::LogFormat,
    units: &LogUnits<'_>,
) -> Result<ParamValues, String> {
    let mut values = format.default_units();
    let given = [
        ("rate", units.rate),
        ("time", units.time),
        ("accel", units.accel),
        ("gyro", units.gyro),
    ];
    let has = || {
        format
            .units
            .iter()
            .map(|s| {
                let values = match s.kind {
                    attlab::model::ParamKind::Choice(options) => options.join("|"),
                    _ => format!("{} … {} {}", s.min, s.max, s.unit)
                        .trim_end()
                        .to_string(),
                };
                if s.key.ends_with("_unit") {
                    format!("--{} {values}", s.key.replace('_', "-"))
                } else {
                    format!("--log-set {}=<{values}>", s.key)
                }
            })
            .collect::<Vec<_>>()
            .join(", ")
    };
    for (name, value) in given {
        let Some(value) = value else { continue };
        let key = format!("{name}_unit");
        if !format.units.iter().any(|s| s.key == key) {
            return Err(format!(
                "--{name}-unit: {} has no {name} column (its units: {})",
                format.name,
                has()
            ));
        }
        values
            .set_text(format.units, &key, value)
            .map_err(|e| format!("--{name}-unit `{value}`: {e} (units: {})", has()))?;
    }
    let errors =
        values.apply_assignments(format.units, units.assignments.iter().map(String::as_str));
    match errors.as_slice() {
        [] => Ok(values),
        _ => Err(format!(
            "--log-set: {} (the settings of {}: {})",
            errors
                .iter()
                .map(ToString::to_string)
                .collect::<Vec<_>>()
                .join("; "),
            format.name,
            has()
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn units(rate: Option<&'static str>, accel: Option<&'static str>) -> LogUnits<'static> {
        LogUnits {
            rate,
            time: None,
            accel,
            gyro: None,
            assignments: &[],
        }
    }

    #[test]
    fn a_unit_flag_the_format_lacks_is_an_error_that_names_its_units() {
        let err = log_units(&attlab::sensors::RATE_LOG, &units(None, Some("g"))).unwrap_err();
        assert!(err.contains("--accel-unit"), "{err}");
        assert!(err.contains("--rate-unit deg_s|mdeg_s|rad_s"), "{err}");
        let err =
            log_units(&attlab::sensors::RATE_LOG, &units(Some("furlongs"), None)).unwrap_err();
        assert!(err.contains("furlongs"), "{err}");
        let ok = log_units(&attlab::sensors::IMU_LOG, &units(None, Some("mps2"))).unwrap();
        assert_eq!(ok.index("accel_unit"), 5);
        assert_eq!(
            ok.index("time_unit"),
            1,
            "an IMU log's time is in ms by default"
        );
    }

    #[test]
    fn log_settings_set_raw_counts_and_a_bad_one_names_the_settings() {
        let given = [
            "rate_counts=24-bit".to_string(),
            "count_zero=1258".to_string(),
        ];
        let flags = LogUnits {
            assignments: &given,
            ..units(Some("mdeg_s"), None)
        };
        let ok = log_units(&attlab::sensors::RATE_LOG, &flags).unwrap();
        assert_eq!((ok.index("rate_counts"), ok.get("count_zero")), (3, 1258.0));
        let bad = ["count_zero=lots".to_string(), "count_scael=2".to_string()];
        let flags = LogUnits {
            assignments: &bad,
            ..units(None, None)
        };
        let err = log_units(&attlab::sensors::RATE_LOG, &flags).unwrap_err();
        assert!(err.contains("lots") && err.contains("count_scael"), "{err}");
        assert!(err.contains("--log-set count_scale=<"), "{err}");
    }

    #[test]
    fn a_run_or_replay_that_would_write_too_much_is_refused_before_writing() {
        let dir = std::env::temp_dir().join(format!("attlab-bounds-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let csv = dir.join("out.csv");
        let err = run(
            "p1",
            1,
            Some(1e6),
            Output::new(&csv, 2000.0),
            None,
            &[],
            true,
        )
        .unwrap_err();
        assert!(
            err.contains("--duration 1000000 s would write about")
                && err.contains("GB of CSV (1.000e8 rows")
                && err.contains("--max-csv-mb"),
            "{err}"
        );
        assert!(!csv.exists(), "nothing written");
        // A log whose clock jumps by 4.29e9 ms half-way: a gap joined after 1 s, not a
        // 49-day replay.
        let log = dir.join("jump.csv");
        let lines: Vec<String> = (0..1000u64)
            .map(|k| {
                let t = 10 * k + if k >= 500 { 4_294_967_295 } else { 0 };
                format!("{t},0,0,16384,131,0,0")
            })
            .collect();
        std::fs::write(&log, lines.join("\n")).unwrap();
        replay(
            "p4",
            &log,
            units(None, None),
            Output::new(&csv, 2000.0),
            &[],
        )
        .unwrap();
        let rows = std::fs::read_to_string(&csv).unwrap().lines().count();
        // 1 000 samples, 99 steps of the join, the row before sample 0 and the header.
        assert_eq!(rows, 1000 + 99 + 1 + 1);
        std::fs::remove_dir_all(&dir).ok();
    }
}
