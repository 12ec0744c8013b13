//! The words of a sweep's result in the reader's language: its parameters by their sliders'
//! labels and units, its series as the plots name them, its scores and objectives.

use super::super::lab_word;
use crate::state::AppState;
use attlab::analysis::sweep::{Sweep, SweepPoint};
use attlab::i18n;
use attlab::model::{SweepSpec, fmt_sig};

/// The words of a sweep's result: its parameters, series, scores and objectives in the
/// reader's language.
pub(super) struct Words<'a> {
    app: &'a AppState,
    /// The sweep's id.
    sweep: &'static str,
    on_log: bool,
}

impl Words<'_> {
    pub(super) fn of<'a>(app: &'a AppState, s: &Sweep) -> Words<'a> {
        Words {
            app,
            sweep: s.spec().id,
            on_log: s.is_on_log(),
        }
    }

    /// A parameter's label with its unit (a log's key stays as it is).
    pub(super) fn param(&self, key: &str) -> String {
        let lab = self.app.sim().lab();
        let Some(spec) = lab.params().iter().find(|p| p.key == key) else {
            return key.to_string();
        };
        let label = lab_word(self.app, &i18n::param_label_id(lab.id(), key), spec.label);
        if spec.unit.is_empty() {
            label
        } else {
            format!(
                "{label} [{}]",
                i18n::unit(self.app.view().lang(), spec.unit)
            )
        }
    }

    /// Score `j`'s name.
    pub(super) fn score(&self, j: usize, english: &str) -> String {
        let part = format!("{}score-{j}", if self.on_log { "log-" } else { "" });
        self.word(&part, english)
    }

    /// Objective `j`'s name.
    pub(super) fn objective(&self, j: usize, english: &str) -> String {
        let part = format!("{}objective-{j}", if self.on_log { "log-" } else { "" });
        self.word(&part, english)
    }

    /// Overlay line `k`'s name.
    pub(super) fn overlay(&self, k: usize, english: &str) -> String {
        self.word(&format!("overlay-{k}"), english)
    }

    fn word(&self, part: &str, english: &str) -> String {
        let lab = self.app.sim().lab().id();
        lab_word(self.app, &i18n::sweep_id(lab, self.sweep, part), english)
    }

    /// Series `k`'s legend, as the plots name it.
    pub(super) fn series(&self, s: &Sweep, k: usize) -> String {
        let Some(key) = s.spec().series.get(k) else {
            return s.legend(k);
        };
        let name = key.name();
        let found = self
            .app
            .sim()
            .available_specs()
            .iter()
            .find(|sp| sp.name == name);
        found.map_or_else(
            || s.legend(k),
            |sp| super::super::series_legend(self.app, sp),
        )
    }

    /// "parameter = value" (and the grid's) of a point.
    pub(super) fn at(&self, spec: &SweepSpec, p: &SweepPoint) -> String {
        let lang = self.app.view().lang();
        let sig = |x: f64| i18n::number(lang, &fmt_sig(x));
        let one = format!("{} = {}", self.param(spec.key), sig(p.value));
        match (spec.grid, p.grid_value) {
            (Some(g), Some(v)) => format!(
                "{one}{}{} = {}",
                i18n::list_separator(lang),
                self.param(g.key),
                sig(v)
            ),
            _ => one,
        }
    }

    /// An axis: log10 of a parameter.
    pub(super) fn log_axis(&self, key: &str) -> String {
        format!("log10 {}", self.param(key))
    }
}
