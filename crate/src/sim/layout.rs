//! The row layout: one table of columns, each a (source, quantity) pair from the
//! [catalogue](super::catalogue), that yields both the series specs (names, units, plots,
//! ±3σ bands) and, every step, the row of values. Only the selected columns exist, and a
//! derived quantity is computed only when a selected column needs it: the loop costs what is
//! recorded.

use super::catalogue::{Candidate, Q, Source, bit, candidates, error_truth_needs, standard};
use super::derived::{Derived, NAN_DERIVED, derive, nees_att};
use super::selection::{Selection, UnknownSeries};
use crate::model::{
    Attitude, Estimate, Estimator, Extras, SensorModel, SeriesKey, SeriesSpec, TruthModel,
    TruthState,
};

/// The column table of one simulation.
#[derive(Clone, Debug)]
pub struct Layout {
    columns: Vec<Source>,
    specs: Vec<SeriesSpec>,
    available: Vec<SeriesSpec>,
    single_axis: bool,
    truth_needs: u32,
    est_needs: Vec<u32>,
    any_truth_extra: bool,
    any_extra: Vec<bool>,
    truth_extra_buf: Vec<f64>,
    any_sensor_extra: bool,
    sensor_extra_buf: Vec<f64>,
    extra_bufs: Vec<Vec<f64>>,
    /// The keys of the truth's, the sensors' and each estimator's own quantities, in the
    /// order their values are written ([`Extras`] checks it).
    truth_extra_keys: Vec<Box<str>>,
    sensor_extra_keys: Vec<Box<str>>,
    extra_keys: Vec<Vec<Box<str>>>,
    est_derived: Vec<Derived>,
}

impl Layout {
    /// The layout of `truth` and `estimators`, keeping the `selection` (with `figures`, the
    /// series the lab's figures draw).
    pub fn new(
        lab_id: &str,
        truth: &dyn TruthModel,
        sensors: &dyn SensorModel,
        estimators: &[Box<dyn Estimator>],
        selection: &Selection,
        figure_series: &[SeriesKey],
        sphere: bool,
    ) -> Result<Self, UnknownSeries> {
        let single_axis = truth.state().angle_rad.is_some();
        let candidates = candidates(truth, sensors, estimators, single_axis);
        let keep = keep_mask(lab_id, &candidates, selection, figure_series, sphere)?;
        let available: Vec<SeriesSpec> = candidates.iter().map(|c| c.spec.clone()).collect();
        let mut columns = Vec::new();
        let mut specs = Vec::new();
        for (c, k) in candidates.into_iter().zip(keep) {
            if k {
                columns.push(c.source);
                specs.push(c.spec);
            }
        }
        // A band is drawn only when its variance series is recorded too.
        let names: Vec<String> = specs.iter().map(|s| s.name.clone()).collect();
        for s in &mut specs {
            if s.band.as_ref().is_some_and(|(v, _)| !names.contains(v)) {
                s.band = None;
            }
        }
        let n_est = estimators.len();
        let mut truth_needs = 0;
        let mut est_needs = vec![0u32; n_est];
        let mut any_truth_extra = false;
        let mut any_sensor_extra = false;
        let mut any_extra = vec![false; n_est];
        for col in &columns {
            match *col {
                Source::Truth(q) => truth_needs |= bit(q),
                Source::Est(i, q) => {
                    est_needs[i] |= bit(q);
                    // Errors need the truth's own attitude quantities too.
                    truth_needs |= error_truth_needs(q);
                }
                Source::NeesAtt(i) => {
                    est_needs[i] |= bit(Q::ErrX) | bit(Q::ErrY) | bit(Q::ErrZ);
                }
                Source::TruthExtra(_) => any_truth_extra = true,
                Source::SensorExtra(_) => any_sensor_extra = true,
                Source::Extra(i, _) => any_extra[i] = true,
                _ => {}
            }
        }
        let extra_keys: Vec<Vec<Box<str>>> = estimators
            .iter()
            .map(|e| keys_of_estimator(e.as_ref()))
            .collect();
        let truth_extra_keys = keys_of(&truth.extra_series());
        let sensor_extra_keys = keys_of(&sensors.extra_series());
        let sensor_extra_len = sensor_extra_keys.len();
        Ok(Self {
            columns,
            specs,
            available,
            single_axis,
            truth_needs,
            est_needs,
            any_truth_extra,
            extra_bufs: extra_keys.iter().map(|k| vec![f64::NAN; k.len()]).collect(),
            any_extra,
            truth_extra_buf: vec![f64::NAN; truth_extra_keys.len()],
            any_sensor_extra: any_sensor_extra && sensor_extra_len > 0,
            sensor_extra_buf: vec![f64::NAN; sensor_extra_len],
            truth_extra_keys,
            sensor_extra_keys,
            extra_keys,
            est_derived: vec![NAN_DERIVED; n_est],
        })
    }

    /// The series, in row order (series 0 is `t_s`).
    pub fn specs(&self) -> &[SeriesSpec] {
        &self.specs
    }

    /// Every series the lab has, recorded or not.
    pub fn available(&self) -> &[SeriesSpec] {
        &self.available
    }

    /// Number of columns.
    pub fn len(&self) -> usize {
        self.columns.len()
    }

    /// No columns (never: time is always there).
    pub fn is_empty(&self) -> bool {
        self.columns.is_empty()
    }

    /// Fills `row` (resized to the columns) with this step's values.
    #[allow(clippy::too_many_arguments)]
    pub fn fill(
        &mut self,
        row: &mut Vec<f64>,
        truth_model: &dyn TruthModel,
        sensors: &dyn SensorModel,
        truth: &TruthState,
        estimators: &[Box<dyn Estimator>],
        estimates: &[Estimate],
        status_codes: &[f64],
    ) {
        let truth_d = if self.truth_needs != 0 {
            derive(
                self.truth_needs,
                &Estimate {
                    attitude: Attitude::Quaternion(truth.q_ref_from_body),
                    angle_rad: truth.angle_rad,
                    rate_body_rad_s: Some(truth.rate_body_rad_s),
                },
                None,
                self.single_axis,
            )
        } else {
            NAN_DERIVED
        };
        if self.any_truth_extra && !self.truth_extra_keys.is_empty() {
            let keys = &self.truth_extra_keys;
            truth_model.extra_values(&mut Extras::new(keys, &mut self.truth_extra_buf));
        }
        if self.any_sensor_extra {
            let keys = &self.sensor_extra_keys;
            sensors.extra_values(&mut Extras::new(keys, &mut self.sensor_extra_buf));
        }
        for (i, e) in estimates.iter().enumerate() {
            let needs = self.est_needs[i];
            if needs != 0 {
                self.est_derived[i] = derive(needs, e, Some((truth, &truth_d)), self.single_axis);
            }
            if self.any_extra[i] && !self.extra_keys[i].is_empty() {
                let keys = &self.extra_keys[i];
                estimators[i].extras(&mut Extras::new(keys, &mut self.extra_bufs[i]));
            }
        }
        let est_d = &self.est_derived;
        row.resize(self.columns.len(), f64::NAN);
        for (slot, col) in row.iter_mut().zip(&self.columns) {
            let v = match *col {
                Source::Time => truth.t_s,
                Source::Truth(q) => truth_d.values[q as usize],
                Source::TruthExtra(j) => self.truth_extra_buf[j],
                Source::SensorExtra(j) => self.sensor_extra_buf[j],
                Source::Est(i, q) => est_d[i].values[q as usize],
                Source::Variance(i, k) => {
                    estimators[i].covariance().map_or(f64::NAN, |c| c.get(k, k))
                }
                Source::Cross(i, k, l) => {
                    estimators[i].covariance().map_or(f64::NAN, |c| c.get(k, l))
                }
                Source::Innovation(i, k) => estimators[i]
                    .innovation()
                    .get(k)
                    .copied()
                    .unwrap_or(f64::NAN),
                Source::Extra(i, k) => self.extra_bufs[i][k],
                Source::Status(i) => status_codes[i],
                Source::NeesAtt(i) => nees_att(estimators[i].as_ref(), &est_d[i]),
            };
            *slot = v;
        }
    }
}

/// The keys of an estimator's own quantities, in its order.
fn keys_of_estimator(e: &dyn Estimator) -> Vec<Box<str>> {
    e.extra_quantities().iter().map(|q| q.key.into()).collect()
}

/// The quantity keys of a lab's own series (`truth.energy_j` → `energy_j`).
fn keys_of(specs: &[SeriesSpec]) -> Vec<Box<str>> {
    specs
        .iter()
        .map(|s| {
            s.name
                .split_once('.')
                .map_or(s.name.as_str(), |(_, k)| k)
                .into()
        })
        .collect()
}

/// Which of `candidates` `selection` keeps (with `figure_series`, the series the lab's
/// figures draw, and the sphere's when `sphere`); a named series the lab lacks is an error.
fn keep_mask(
    lab_id: &str,
    candidates: &[Candidate],
    selection: &Selection,
    figure_series: &[SeriesKey],
    sphere: bool,
) -> Result<Vec<bool>, UnknownSeries> {
    let keep = match selection {
        Selection::All => vec![true; candidates.len()],
        Selection::Standard => candidates
            .iter()
            .map(|c| standard(c, figure_series, sphere))
            .collect(),
        Selection::View(names) => {
            let bands: Vec<&str> = candidates
                .iter()
                .filter(|c| names.contains(&c.spec.name))
                .filter_map(|c| c.spec.band.as_ref().map(|(v, _)| v.as_str()))
                .collect();
            candidates
                .iter()
                .map(|c| {
                    matches!(c.source, Source::Time | Source::Status(_))
                        || names.contains(&c.spec.name)
                        || bands.contains(&c.spec.name.as_str())
                })
                .collect()
        }
        Selection::Named(names) => {
            let mut keep = vec![false; candidates.len()];
            keep[0] = true;
            for name in names {
                match candidates.iter().position(|c| c.spec.name == *name) {
                    Some(i) => keep[i] = true,
                    None => {
                        return Err(UnknownSeries {
                            name: name.clone(),
                            lab: lab_id.to_string(),
                            known: candidates
                                .iter()
                                .map(|c| c.spec.name.as_str())
                                .collect::<Vec<_>>()
                                .join(", "),
                        });
                    }
                }
            }
            keep
        }
    };
    Ok(keep)
}
