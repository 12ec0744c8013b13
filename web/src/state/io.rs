//! The I/O part: recorded logs replayed through the lab's estimators (the file picked,
//! its units, the lab's example log) and the exports (every sample as CSV, the paper's own
//! output file, a Python snippet, PNGs).

use super::{AppState, Effect, PngTarget};
use crate::pick::{self, Picked};
use crate::platform;
use attlab::model::PlotTab;
use attlab::model::{LogFormat, ParamValues};
use attlab::sim::{SimError, SimOptions, Simulation};
use std::collections::BTreeMap;

/// Logs to load and where exports go.
#[derive(Default)]
pub struct IoState {
    /// The unit choices of each log format changed from its defaults (by format id).
    units: BTreeMap<&'static str, ParamValues>,
    /// Name and sample count of the log being replayed.
    pub replaying: Option<(String, usize)>,
    /// Where exports go without a dialog (desktop scripting and tests); `None` asks.
    pub save_dir: Option<std::path::PathBuf>,
    file_slot: pick::FileSlot,
}

impl IoState {
    /// The unit choices for logs of `format`.
    pub fn units_for(&self, format: &LogFormat) -> ParamValues {
        self.units
            .get(format.id)
            .cloned()
            .unwrap_or_else(|| format.default_units())
    }

    /// Where a picked file arrives: the chooser's result, or what a desktop script or a
    /// test delivers as if it had been chosen (the app takes it on the next frame).
    pub fn file_slot(&self) -> pick::FileSlot {
        self.file_slot.clone()
    }

    /// Keeps where exports go and a log being picked from `old` (a link loaded).
    pub(super) fn keep_from(&mut self, old: &mut IoState) {
        self.save_dir = old.save_dir.take();
        self.file_slot = std::mem::take(&mut old.file_slot);
    }
}

/// What the I/O part does.
#[derive(Clone, Debug, PartialEq)]
pub enum IoCommand {
    /// Save every sample of the run so far as CSV.
    ExportCsv,
    /// Save the paper's own output file (labs that define one).
    ExportOutputFile,
    /// Ask for a log file to replay.
    LoadLog,
    /// Take the picked log if it arrived (the frame loop asks every frame).
    TakePickedLog,
    /// Leave the replay and simulate again.
    EndReplay,
    /// One unit choice (`key`, one of the format's unit parameters) for logs of the lab's
    /// format.
    SetLogUnit(&'static str, f64),
    /// Replay the log the lab ships.
    LoadExampleLog,
    /// Replay these bytes as the lab's kind of log, under this name (what the file picker
    /// delivers; tests and scripts give a log directly).
    ReplayLog(String, Vec<u8>),
    /// Copy a pandas snippet that loads the exported CSV and draws the current plot tab.
    CopyPython,
    /// Save a PNG of a view or of every plot tab (taken by the app over the next frames).
    ExportPng(PngTarget),
    /// Save exports into this folder without asking (desktop scripting and tests).
    SetSaveDir(Option<std::path::PathBuf>),
}

impl AppState {
    pub(super) fn apply_io(&mut self, command: IoCommand) -> Option<Effect> {
        match command {
            IoCommand::ExportCsv => self.start_csv_export(),
            IoCommand::ExportOutputFile => self.export_output_file(),
            IoCommand::LoadLog => pick::pick_text_file(&self.io.file_slot),
            IoCommand::TakePickedLog => self.take_picked_log(),
            IoCommand::EndReplay => {
                let (lab, params) = (self.sim.lab(), self.sim.params().clone());
                self.restart(lab, params);
            }
            IoCommand::SetLogUnit(key, value) => self.set_log_unit(key, value),
            IoCommand::ReplayLog(name, bytes) => self.start_replay(name, &bytes),
            IoCommand::LoadExampleLog => self.replay_example(),
            IoCommand::CopyPython => {
                self.say("msg-python-copied", &[]);
                return Some(Effect::Clipboard(self.python_snippet()));
            }
            IoCommand::ExportPng(target) => return Some(Effect::Png(target)),
            IoCommand::SetSaveDir(dir) => self.io.save_dir = dir,
        }
        None
    }

    /// Replays the log the lab ships, with the unit choices it is written in (which the
    /// panel then shows).
    fn replay_example(&mut self) {
        let page = self.sim.lab().page();
        let (Some(log), Some(format)) = (page.example_log, page.log_format) else {
            return self.warn("msg-no-example-log", &[]);
        };
        match log.unit_values(format) {
            Ok(units) => {
                self.io.units.insert(format.id, units);
                self.start_replay(log.name.into(), log.text.as_bytes());
            }
            Err(e) => self.refused_unit(format.units, &e),
        }
    }

    /// Takes a picked log, if one arrived, and starts replaying it (bad lines are listed as
    /// messages with their line numbers; the good ones are used).
    fn take_picked_log(&mut self) {
        let Some(picked) = self.io.file_slot.borrow_mut().take() else {
            return;
        };
        match picked {
            Picked::File { name, bytes } => self.start_replay(name, &bytes),
            Picked::Unreadable { name, why } => {
                self.warn(
                    "msg-file-unreadable",
                    &[("name", name.into()), ("why", why.into())],
                );
            }
            Picked::Refused => self.warn("msg-picker-refused", &[]),
        }
    }

    /// Sets unit choice `key` of the lab's log format (a value out of its range is a
    /// message, the choice stays).
    fn set_log_unit(&mut self, key: &'static str, value: f64) {
        let Some(format) = self.sim.lab().page().log_format else {
            return self.warn("msg-no-logs", &[]);
        };
        let mut units = self.io.units_for(format);
        match units.set(format.units, key, value) {
            Ok(()) => {
                self.io.units.insert(format.id, units);
            }
            Err(e) => self.refused_unit(format.units, &e),
        }
    }

    /// A unit choice of the log format refused, said by its label in the reader's language.
    fn refused_unit(&mut self, units: &[attlab::model::ParamSpec], e: &attlab::model::ParamError) {
        let lang = self.view.lang();
        self.error(super::link_words::param_problem(
            lang,
            self.sim.lab(),
            units,
            e,
        ));
    }

    /// Parses `bytes` as the lab's kind of log and replays it: every bad line is listed
    /// (the first dozen as messages), the counts and the clock's gaps are said.
    fn start_replay(&mut self, name: String, bytes: &[u8]) {
        let lab = self.sim.lab();
        let Some(format) = lab.page().log_format else {
            return self.warn("msg-no-logs-named", &[("name", name.as_str().into())]);
        };
        let failed = |why: attlab::i18n::FluentValue<'static>| {
            (
                "msg-log-failed",
                vec![("name", name.as_str().into()), ("why", why)],
            )
        };
        let log = match attlab::labs::read_log(lab, bytes, &self.io.units_for(format)) {
            Ok(log) => log,
            Err(why) => {
                let (id, args) = failed(super::log_words::refusal(self.view.lang(), &why).into());
                return self.warn(id, &args);
            }
        };
        const SHOWN: usize = 12;
        let lang = self.view.lang();
        for e in log.errors.iter().take(SHOWN) {
            self.warn(
                "msg-log-skipped",
                &[
                    ("name", name.as_str().into()),
                    ("why", super::log_words::line_problem(lang, e).into()),
                ],
            );
        }
        if log.errors.len() > SHOWN {
            let more = log.errors.len() - SHOWN;
            self.warn(
                "msg-log-more-bad",
                &[("name", name.as_str().into()), ("n", more.into())],
            );
        }
        let (counts, gaps) = (log.counts, log.gaps.len());
        match Simulation::replay(lab, self.sim.params().clone(), log, SimOptions::default()) {
            Ok(mut sim) => {
                self.drop_jobs();
                self.end_travel();
                sim.keep_history(attlab::sim::HISTORY_BUDGET_BYTES);
                self.sim = sim;
                self.run.sweep = None;
                self.say(
                    "msg-log-replaying",
                    &[
                        ("name", name.as_str().into()),
                        ("n", counts.kept.into()),
                        ("lines", counts.data_lines.into()),
                        ("reordered", counts.reordered.into()),
                        ("merged", counts.merged.into()),
                        ("rejected", counts.rejected.into()),
                        ("gaps", gaps.into()),
                    ],
                );
                self.io.replaying = Some((name, counts.kept));
            }
            Err(why) => {
                let (id, args) = failed(self.why(&why));
                self.warn(id, &args);
            }
        }
    }

    /// Saves `bytes` as `name`, with `what` after the saved path in the message.
    pub(super) fn save(&mut self, name: &str, bytes: Vec<u8>, result: Result<String, SimError>) {
        let lang = self.view.lang();
        let message = match result {
            Ok(what) => {
                let dir = self.io.save_dir.as_deref();
                platform::save_file(name, "text/csv", bytes, dir, lang)
                    .map(|m| format!("{m} ({what})"))
                    .map_err(|e| e.words(lang).into())
            }
            Err(e) => Err(self.why(&e)),
        };
        match message {
            Ok(m) => self.info(m),
            Err(why) => self.warn("msg-export-failed", &[("why", why)]),
        }
    }

    fn export_output_file(&mut self) {
        let lab = self.sim.lab();
        let Some(file) = lab.output_file(self.sim.params()) else {
            return self.warn("msg-no-output-file", &[]);
        };
        let mut buf = Vec::new();
        let duration = self.sim.t_s().max(lab.default_duration_s());
        let seed = self.run.seed;
        let name = format!("attlab-{}-output-seed{seed}.csv", lab.id());
        let params = self.sim.params().clone();
        let result = attlab::sim::write_output_file(lab, params, seed, duration, &file, &mut buf)
            .map(|(rows, stopped)| {
                let id = if stopped {
                    "msg-output-rows-stopped"
                } else {
                    "msg-output-rows"
                };
                self.word(id, &[("n", rows.into())])
            });
        self.save(&name, buf, result);
    }

    /// The CSV file name "Export CSV" saves under.
    pub fn csv_name(&self) -> String {
        format!("attlab-{}-seed{}.csv", self.sim.lab().id(), self.sim.seed())
    }

    /// "Copy as Python" for the plot tab on screen.
    pub fn python_snippet(&self) -> String {
        let lab = self.sim.lab();
        let available = self.sim.available_specs();
        let header = |name: &str| {
            available
                .iter()
                .find(|s| s.name == name)
                .map(|s| s.header())
        };
        let (title, columns, log) = match self.view.plots.tab {
            PlotTab::Figure(f) => match lab.page().figure(f) {
                Some(fig) => {
                    let cols = fig
                        .series
                        .iter()
                        .filter_map(|n| header(&n.name()))
                        .collect();
                    (fig.title.to_string(), cols, fig.log)
                }
                None => (String::new(), Vec::new(), false),
            },
            PlotTab::Group(g) => (
                g.title().to_string(),
                available
                    .iter()
                    .filter(|s| s.group == g)
                    .map(|s| s.header())
                    .collect(),
                self.view.plots.log_covariance && g == attlab::model::SeriesGroup::Covariance,
            ),
        };
        crate::python::snippet(&self.csv_name(), &title, &columns, log)
    }
}
