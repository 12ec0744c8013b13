//! No CSV cell reads `inf` or `NaN`: a missing or non-finite value is an empty cell (the
//! promise of docs/cli.md), in every lab's run at its defaults — paper 5's past the divergence of
//! method (9) at t ≈ 1107 s, where the condition number of a singular UᵀQU is infinite.
#![cfg(not(target_arch = "wasm32"))]

use attlab::labs;
use attlab::model::ParamValues;
use attlab::sim::{CsvSink, Selection, SimOptions, Simulation};
use std::io::Write;

/// A writer that keeps nothing but the rows' non-numeric letters: a number written by the
/// CSV sink holds digits, `.`, `-`, `e` and commas only.
#[derive(Default)]
struct Letters {
    past_header: bool,
    found: Vec<u8>,
    bytes: usize,
}

impl Write for Letters {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        for &b in buf {
            if !self.past_header {
                self.past_header = b == b'\n';
                continue;
            }
            self.bytes += 1;
            if b.is_ascii_alphabetic() && b != b'e' && self.found.len() < 64 {
                self.found.push(b);
            }
        }
        Ok(buf.len())
    }

    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

#[test]
fn no_cell_of_any_labs_csv_reads_inf_or_nan() {
    for lab in labs::all() {
        let options = SimOptions {
            selection: Selection::All,
            budget_bytes: 1 << 20,
        };
        let params = ParamValues::defaults(lab.params());
        let mut sim = Simulation::with_options(*lab, params, 1, options).expect("all series");
        let mut sink = CsvSink::new(Letters::default(), sim.specs()).expect("header");
        let end_s = if lab.id() == "p5" {
            1500.0
        } else {
            20_000.0 * sim.dt_s()
        };
        while sim.t_s() < end_s {
            sim.step();
            sink.row(sim.last_row()).expect("row");
        }
        let (letters, rows) = sink.into_inner().expect("flushed");
        assert!(letters.bytes > 0, "{}: nothing written", lab.id());
        assert!(
            letters.found.is_empty(),
            "{} ({rows} rows to t = {:.0} s): letters in the cells: {}",
            lab.id(),
            sim.t_s(),
            String::from_utf8_lossy(&letters.found)
        );
    }
}
