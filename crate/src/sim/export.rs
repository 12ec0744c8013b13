//! Exports of a run: every sample of every series as CSV (through a re-run, since the
//! recorder keeps only what its budget allows), and a paper's own output file.

use super::rerun::{RerunError, RerunItem};
use super::{CsvSink, Selection, SimError, SimOptions, Simulation, csv_cell};
use crate::model::ParamValues;
use crate::page::Lab;

impl Simulation {
    /// Writes every sample of every series of the run so far as CSV (see
    /// [`Simulation::rerun`]); returns the number of rows.
    pub fn export_csv<W: std::io::Write>(&self, out: W) -> Result<u64, SimError> {
        let mut out = Some(out);
        let mut sink: Option<CsvSink<W>> = None;
        self.rerun(Selection::All, |item| -> Result<(), SimError> {
            match item {
                // The specs come once, before any row.
                RerunItem::Specs(specs) => {
                    if let Some(w) = out.take() {
                        sink = Some(CsvSink::new(w, specs)?);
                    }
                    Ok(())
                }
                RerunItem::Row(row) => match sink.as_mut() {
                    Some(s) => Ok(s.row(row)?),
                    None => Ok(()),
                },
            }
        })
        .map_err(|e| match e {
            RerunError::Setup(e) | RerunError::Sink(e) => e,
        })?;
        match sink {
            Some(s) => Ok(s.finish()?),
            None => Ok(0),
        }
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
) -> Result<(u64, bool), SimError> {
    let mut names: Vec<&str> = file.columns.iter().map(String::as_str).collect();
    if let Some(stop) = &file.stop {
        names.push(stop);
    }
    let mut sim = Simulation::with_options(lab, params, seed, SimOptions::named(&names))?;
    let cols: Vec<usize> = file
        .columns
        .iter()
        .map(|c| sim.series_index(c))
        .collect::<Result<_, _>>()?;
    let stop = file
        .stop
        .as_deref()
        .map(|s| sim.series_index(s))
        .transpose()?;
    let mut writer = ::csv::Writer::from_writer(out);
    writer.write_record(&file.headers)?;
    let mut rows = 0;
    let end = duration_s - 1e-9 * sim.dt_s();
    loop {
        let row = sim.last_row();
        writer.write_record(cols.iter().map(|c| csv_cell(row[*c])))?;
        rows += 1;
        if stop.is_some_and(|s| row[s] > 0.5) {
            writer.flush()?;
            return Ok((rows, true));
        }
        if sim.t_s() >= end {
            break;
        }
        sim.step();
    }
    writer.flush()?;
    Ok((rows, false))
}
