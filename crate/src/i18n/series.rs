//! Series labels in the reader's language, derived from the typed key a series was named
//! from: the owner (the truth, the sensors, an estimator) and the measure (a declared
//! quantity, a variance, a covariance, the NEES, the health) each come from the catalogue,
//! and are put together as the English label is ("ST+Gyro [λ,ω]: attitude error about x").
//!
//! The English label the core built stays the reference: a label is composed only when its
//! English twin composes to exactly the label the core gave (a test checks that every series
//! of every lab does), so a translation can never name a different thing than the English.

use super::{Lang, has, lab_text, t, t_with};
use crate::model::{Measure, ParamValues, SENSORS, SeriesSpec, StateInfo, StateKind, TIME, TRUTH};
use crate::page::Lab;
use crate::sim::Simulation;

/// The id of an estimator's name in the catalogue.
pub fn estimator_id(lab_id: &str, estimator_id: &str) -> String {
    format!("lab-{lab_id}-estimator-{estimator_id}")
}

/// The id of a declared quantity's label in the catalogue (quantities are shared across labs
/// by key; a test checks that one key always has one label).
pub fn quantity_id(key: &str) -> String {
    format!("q-{key}")
}

/// The words of a lab's series a translation takes: each estimator's name and each declared
/// quantity's label (`(id, English)`), over the lab's default parameters and each preset (a
/// preset may bring other estimators).
pub fn lab_series_words(lab: &'static dyn Lab) -> Vec<(String, &'static str)> {
    let mut settings = vec![ParamValues::defaults(lab.params())];
    for preset in lab.presets() {
        let mut p = ParamValues::defaults(lab.params());
        for (k, v) in preset.values {
            // A preset's values are the lab's own (the registry's tests check them).
            let _ = p.set(lab.params(), k, *v);
        }
        settings.push(p);
    }
    let mut out = Vec::new();
    // A replay's own series (what was logged), where the lab reads logs: a two-line log of
    // its format.
    if let Some(format) = lab.page().log_format {
        let zeros = vec!["0"; format.columns.saturating_sub(1)].join(",");
        let text = format!("0,{zeros}\n1,{zeros}\n");
        let log = (format.parse)(text.as_bytes(), &format.default_units());
        let options = crate::sim::SimOptions::default();
        if let Ok(sim) = Simulation::replay(lab, settings[0].clone(), log, options) {
            for spec in sim.available_specs() {
                if let Some(Measure::Quantity(q)) = spec.key.map(|k| k.measure) {
                    out.push((quantity_id(q.key), q.label));
                }
            }
        }
    }
    for params in settings {
        let mut sim = Simulation::new(lab, params, 1);
        // The scene's directions exist from the first step on.
        sim.step();
        for e in sim.estimators() {
            out.push((estimator_id(lab.id(), e.id()), e.label()));
        }
        for v in sim.scene().vectors {
            out.push((super::scene_id(lab.id(), v.label), v.label));
        }
        for spec in sim.available_specs() {
            if let Some(Measure::Quantity(q)) = spec.key.map(|k| k.measure) {
                out.push((quantity_id(q.key), q.label));
            }
        }
    }
    out.sort();
    out.dedup();
    out
}

/// An estimator's name in `lang` (its English label without a translation).
pub fn estimator_name(lang: Lang, lab_id: &str, id: &str, english: &str) -> String {
    lab_text(lang, &estimator_id(lab_id, id), english)
}

/// The label of `spec` in `lang`, without its unit; the English label where no translation
/// composes.
pub fn series_label(lang: Lang, lab_id: &str, spec: &SeriesSpec) -> String {
    if lang == Lang::En {
        return spec.label.clone();
    }
    compose(lang, lab_id, spec).unwrap_or_else(|| spec.label.clone())
}

/// The legend of `spec` in `lang`: its label and its unit, e.g. "ST+Gyro: attitude error
/// about x [°]".
pub fn series_legend(lang: Lang, lab_id: &str, spec: &SeriesSpec) -> String {
    series_legend_parts(lang, lab_id, spec).joined()
}

/// A legend in its two parts: who produced the series and what it measures with its unit,
/// so a legend can name an owner once above several of its series, or a shared measure
/// once above several owners.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LegendParts {
    /// The truth, the sensors or an estimator ("ST+Gyro \[λ,ω\]"); `None` for a series
    /// without one (the time, a series named by hand).
    pub owner: Option<String>,
    /// The measure and its unit ("attitude error about x [°]").
    pub what: String,
}

impl LegendParts {
    /// The whole legend, "owner: what".
    pub fn joined(&self) -> String {
        joined(self.owner.as_deref(), &self.what)
    }
}

/// [`series_legend`] in its two parts. A label that does not compose from its key in `lang`
/// is one part, the whole English label with the unit.
pub fn series_legend_parts(lang: Lang, lab_id: &str, spec: &SeriesSpec) -> LegendParts {
    let LegendParts { owner, what } = series_legend_without_unit(lang, lab_id, spec);
    let what = if spec.unit.is_empty() {
        what
    } else {
        format!("{what} [{}]", super::unit(lang, spec.unit))
    };
    LegendParts { owner, what }
}

/// [`series_legend_parts`] without the unit, for a value printed with its unit after it
/// (a lesson's tile: "3.69 °" under "(u, v, z) RK4 integration: attitude error").
pub fn series_legend_without_unit(lang: Lang, lab_id: &str, spec: &SeriesSpec) -> LegendParts {
    let composed = parts(lang, lab_id, spec).filter(|(owner, what)| {
        // English is the core's own label, whatever the key says.
        lang != Lang::En || joined(owner.as_deref(), what) == spec.label
    });
    let (owner, what) = composed.unwrap_or((None, spec.label.clone()));
    LegendParts { owner, what }
}

/// The label of `spec` in `lang` from its key, or `None` when the key does not account for
/// its English label or a word has no translation.
pub fn compose(lang: Lang, lab_id: &str, spec: &SeriesSpec) -> Option<String> {
    let (owner, what) = parts(lang, lab_id, spec)?;
    Some(joined(owner.as_deref(), &what))
}

/// "owner: what", or `what` alone.
fn joined(owner: Option<&str>, what: &str) -> String {
    match owner {
        Some(owner) => format!("{owner}: {what}"),
        None => what.to_string(),
    }
}

/// The owner and the measure of `spec` in `lang`, without the unit, as [`compose`] puts
/// them together.
fn parts(lang: Lang, lab_id: &str, spec: &SeriesSpec) -> Option<(Option<String>, String)> {
    if spec.name == TIME {
        return Some((None, t(lang, "series-time")));
    }
    let key = spec.key?;
    let what_en = measure_words(Lang::En, key.measure)?;
    let rest = spec.label.strip_suffix(what_en.as_str())?;
    let what = measure_words(lang, key.measure)?;
    if rest.is_empty() {
        return Some((None, what));
    }
    let owner_en = rest.strip_suffix(": ")?;
    let owner = match key.source {
        TRUTH => t(lang, "owner-truth"),
        SENSORS => t(lang, "owner-sensors"),
        _ if lang == Lang::En => owner_en.to_string(),
        id => {
            let msg = estimator_id(lab_id, id);
            has(lang, &msg).then(|| t(lang, &msg))?
        }
    };
    // The truth's and the sensors' own words must be the core's too.
    if lang == Lang::En && owner != owner_en {
        return None;
    }
    Some((Some(owner), what))
}

/// What a measure is, in words.
fn measure_words(lang: Lang, measure: Measure) -> Option<String> {
    Some(match measure {
        Measure::Quantity(q) if lang == Lang::En => q.label.to_string(),
        Measure::Quantity(q) => {
            let id = quantity_id(q.key);
            has(lang, &id).then(|| t(lang, &id))?
        }
        Measure::Variance(s) => t_with(lang, "series-variance", &[("state", state(lang, s))]),
        Measure::Covariance(a, b) => t_with(
            lang,
            "series-covariance",
            &[("a", state(lang, a)), ("b", state(lang, b))],
        ),
        Measure::NeesAtt => t(lang, "series-nees"),
        Measure::Status => t(lang, "series-health"),
    })
}

/// A covariance state in words ("attitude about x").
fn state(lang: Lang, s: &StateInfo) -> super::FluentValue<'static> {
    const AXES: [&str; 3] = ["x", "y", "z"];
    let axis = |a: u8| AXES.get(usize::from(a)).copied().unwrap_or("?");
    let with_axis = |id: &str, a: u8| t_with(lang, id, &[("axis", axis(a).into())]);
    let words = match s.kind {
        StateKind::AttitudeAxis(a) => with_axis("state-attitude-axis", a),
        StateKind::RateAxis(a) => with_axis("state-rate-axis", a),
        StateKind::GyroBias(a) => with_axis("state-gyro-bias-axis", a),
        StateKind::MagBias(a) => with_axis("state-mag-bias-axis", a),
        StateKind::MagTurn(a) => with_axis("state-mag-turn-axis", a),
        StateKind::Angle => t(lang, "state-angle"),
        StateKind::Rate => t(lang, "state-rate"),
        StateKind::WzU => "u".into(),
        StateKind::WzV => "v".into(),
        StateKind::Other => s.key.replace('_', " "),
    };
    words.into()
}
