//! Exports of a run: every sample of every series as CSV (through a re-run, since the
//! recorder keeps only what its budget allows), and a paper's own output file.

use super::rerun::RerunItem;
use super::{CsvSink, Selection, SimOptions, Simulation, csv_cell};
use crate::model::{Lab, ParamValues};

impl Simulation {
    /// Writes every sample of every series of the run so far as CSV (see
    /// [`Simulation::rerun`]); returns the number of rows.
    pub fn export_csv<W: std::io::Write>(&self, out: W) -> Result<u64, String> {
        let mut sink: Option<CsvSink<W>> = None;
        let mut out = Some(out);
        self.rerun(Selection::All, |item| match item {
            RerunItem::Specs(specs) => {
                let w = out.take().ok_or_else(|| "writer used twice".to_string())?;
                sink = Some(CsvSink::new(w, specs).map_err(|e| e.to_string())?);
                Ok(())
            }
            RerunItem::Row(row) => sink
                .as_mut()
                .ok_or_else(|| "row before header".to_string())?
                .row(row)
                .map_err(|e| e.to_string()),
        })
        .map_err(|e| e.to_string())?;
        sink.ok_or_else(|| "no header written".to_string())?
            .finish()
            .map_err(|e| e.to_string())
    }
}

/// Runs `lab` from its start for at most `duration_s` and writes the paper's output file
/// `file` (its columns under its headers, one row per step), ending at the first row where
/// `file.stop` is 1. Returns the rows written and whether the stop row was reached.
pub fn write_output_file<W: std::io::Write>(
    lab: &'static dyn Lab,
    params: ParamValues,
    seed: u64,
    duration_s: f64,
    file: &crate::model::OutputFile,
    out: W,
) -> Result<(u64, bool), String> {
    let mut names: Vec<&str> = file.columns.iter().map(String::as_str).collect();
    if let Some(stop) = &file.stop {
        names.push(stop);
    }
    let mut sim = Simulation::with_options(lab, params, seed, SimOptions::named(&names))
        .map_err(|e| e.to_string())?;
    let cols: Vec<usize> = file
        .columns
        .iter()
        .map(|c| sim.series_index(c))
        .collect::<Result<_, _>>()
        .map_err(|e| e.to_string())?;
    let stop = file
        .stop
        .as_deref()
        .map(|s| sim.series_index(s))
        .transpose()
        .map_err(|e| e.to_string())?;
    let mut writer = ::csv::Writer::from_writer(out);
    let io = |e: ::csv::Error| e.to_string();
    writer.write_record(&file.headers).map_err(io)?;
    let mut rows = 0;
    let end = duration_s - 1e-9 * sim.dt_s();
    loop {
        let row = sim.last_row();
        writer
            .write_record(cols.iter().map(|c| csv_cell(row[*c])))
            .map_err(io)?;
        rows += 1;
        if stop.is_some_and(|s| row[s] > 0.5) {
            writer.flush().map_err(|e| e.to_string())?;
            return Ok((rows, true));
        }
        if sim.t_s() >= end {
            break;
        }
        sim.step();
    }
    writer.flush().map_err(|e| e.to_string())?;
    Ok((rows, false))
}
