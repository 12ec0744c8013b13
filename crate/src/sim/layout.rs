//! The row layout: one table of columns, each a (source, quantity) pair, that yields both the
//! series specs (names, units, plots, ±3σ bands) and, every step, the row of values. Only
//! the selected columns exist, and a derived quantity (Euler angles, the vertical, (u, v),
//! errors) is computed only when a selected column needs it: the loop costs what is recorded.

use crate::math::{
    EulerYpr, WzAttitude, WzChart, dcm_from_quaternion, pitch_roll_of_vertical,
    small_angle_error_body, wrap_pi,
};
use crate::model::{
    Attitude, Estimate, Estimator, Lab, PlotTab, SensorModel, SeriesGroup, SeriesSpec, StateInfo,
    StateKind, TruthModel, TruthState,
};
use thiserror::Error;

/// Which series a simulation records.
#[derive(Clone, Debug, PartialEq)]
pub enum Selection {
    /// Every series the lab has (CSV exports, `attlab run`).
    All,
    /// What the page shows: the lab's figures, every estimator's errors with their
    /// covariance, innovations and status, and the vertical and (u, v) of three-axis labs.
    Standard,
    /// Exactly these series (analysis). A name that does not exist is an error.
    Named(Vec<String>),
    /// What a view shows: these series where the lab has them, the variances that bound
    /// them, and every estimator's status. The page records this and re-runs the simulation
    /// when another view needs series it has not recorded, so derived quantities are
    /// computed only for what someone looks at.
    View(Vec<String>),
}

impl Selection {
    /// `Named` from string slices.
    pub fn named(names: &[&str]) -> Self {
        Self::Named(names.iter().map(|s| s.to_string()).collect())
    }

    /// What the page records while `tab` is shown: the tab's series, and the vertical and
    /// (u, v) of every source where the lab has them (the sphere and the w plane draw them),
    /// and the outages the plots shade. `available` is every series the lab has.
    pub fn for_tab(lab: &dyn Lab, available: &[SeriesSpec], tab: PlotTab) -> Self {
        let figures = lab.figures();
        let mut names: Vec<String> = match tab {
            PlotTab::Figure(i) => figures
                .get(i)
                .map(|f| f.series.iter().map(|s| s.to_string()).collect())
                .unwrap_or_default(),
            PlotTab::Group(g) => available
                .iter()
                .filter(|s| s.group == g)
                .map(|s| s.name.clone())
                .collect(),
        };
        names.extend(
            available
                .iter()
                .filter(|s| s.group == SeriesGroup::Sphere && !s.name.ends_with(".z_deg"))
                .map(|s| s.name.clone()),
        );
        // Outages are shaded on every tab.
        names.extend(
            lab.outages()
                .iter()
                .filter(|o| available.iter().any(|s| s.name == o.series))
                .map(|o| o.series.to_string()),
        );
        Self::View(names)
    }
}

/// A series asked for that the lab does not have.
#[derive(Clone, Debug, Error, PartialEq)]
#[error("no series `{name}` in lab `{lab}` (it has: {known})")]
pub struct UnknownSeries {
    /// The name asked for.
    pub name: String,
    /// The lab.
    pub lab: String,
    /// Every series the lab has, comma separated.
    pub known: String,
}

/// A quantity of the truth or of an estimate, derived from its attitude, rate or angle.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Q {
    Yaw,
    Pitch,
    Roll,
    Kx,
    Ky,
    Kz,
    U,
    V,
    Z,
    RateX,
    RateY,
    RateZ,
    Angle,
    Rate1,
    ErrDeg,
    TiltErr,
    PitchErr,
    RollErr,
    ErrX,
    ErrY,
    ErrZ,
    RateErrX,
    RateErrY,
    RateErrZ,
    AngleErr,
    RateErr1,
}

const N_Q: usize = Q::RateErr1 as usize + 1;

/// What each quantity is called, its unit and plot, and the covariance state bounding it.
struct QInfo {
    q: Q,
    name: &'static str,
    unit: &'static str,
    group: SeriesGroup,
    band: Option<StateKind>,
}

const fn qi(q: Q, name: &'static str, unit: &'static str, group: SeriesGroup) -> QInfo {
    QInfo {
        q,
        name,
        unit,
        group,
        band: None,
    }
}

const fn qb(q: Q, name: &'static str, unit: &'static str, kind: StateKind) -> QInfo {
    QInfo {
        q,
        name,
        unit,
        group: SeriesGroup::Error,
        band: Some(kind),
    }
}

/// A three-axis source's attitude and rate.
const ATTITUDE_3: &[QInfo] = &[
    qi(Q::Yaw, "yaw_deg", "deg", SeriesGroup::Attitude),
    qi(Q::Pitch, "pitch_deg", "deg", SeriesGroup::Attitude),
    qi(Q::Roll, "roll_deg", "deg", SeriesGroup::Attitude),
    qi(Q::Kx, "k_x", "", SeriesGroup::Sphere),
    qi(Q::Ky, "k_y", "", SeriesGroup::Sphere),
    qi(Q::Kz, "k_z", "", SeriesGroup::Sphere),
    qi(Q::U, "u", "", SeriesGroup::Sphere),
    qi(Q::V, "v", "", SeriesGroup::Sphere),
    qi(Q::Z, "z_deg", "deg", SeriesGroup::Sphere),
];
const RATE_3: &[QInfo] = &[
    qi(Q::RateX, "rate_x_deg_s", "deg/s", SeriesGroup::Rate),
    qi(Q::RateY, "rate_y_deg_s", "deg/s", SeriesGroup::Rate),
    qi(Q::RateZ, "rate_z_deg_s", "deg/s", SeriesGroup::Rate),
];
const ERRORS_3: &[QInfo] = &[
    qi(Q::ErrDeg, "err_deg", "deg", SeriesGroup::Error),
    qb(Q::ErrX, "err_x_deg", "deg", StateKind::AttitudeAxis(0)),
    qb(Q::ErrY, "err_y_deg", "deg", StateKind::AttitudeAxis(1)),
    qb(Q::ErrZ, "err_z_deg", "deg", StateKind::AttitudeAxis(2)),
];
const TILT_ERRORS: &[QInfo] = &[
    qi(Q::TiltErr, "tilt_err_deg", "deg", SeriesGroup::Error),
    qi(Q::PitchErr, "pitch_err_deg", "deg", SeriesGroup::Error),
    qi(Q::RollErr, "roll_err_deg", "deg", SeriesGroup::Error),
];
const RATE_ERRORS_3: &[QInfo] = &[
    qb(
        Q::RateErrX,
        "rate_err_x_deg_s",
        "deg/s",
        StateKind::RateAxis(0),
    ),
    qb(
        Q::RateErrY,
        "rate_err_y_deg_s",
        "deg/s",
        StateKind::RateAxis(1),
    ),
    qb(
        Q::RateErrZ,
        "rate_err_z_deg_s",
        "deg/s",
        StateKind::RateAxis(2),
    ),
];
/// A single-axis source (paper 1): the angle about the axis and its rate.
const ANGLE_1: &[QInfo] = &[qi(Q::Angle, "angle_deg", "deg", SeriesGroup::Attitude)];
const RATE_1: &[QInfo] = &[qi(Q::Rate1, "rate_deg_s", "deg/s", SeriesGroup::Rate)];
const ERRORS_1: &[QInfo] = &[
    qb(Q::AngleErr, "angle_err_deg", "deg", StateKind::Angle),
    qb(Q::RateErr1, "rate_err_deg_s", "deg/s", StateKind::Rate),
];

/// Where a column's value comes from.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Source {
    Time,
    Truth(Q),
    TruthExtra(usize),
    SensorExtra(usize),
    Est(usize, Q),
    Variance(usize, usize),
    Cross(usize, usize, usize),
    Innovation(usize, usize),
    Extra(usize, usize),
    Status(usize),
    /// NEES of estimator i's attitude: eᵀP⁻¹e with e the small-angle error (truth) and P the
    /// attitude block of its own covariance.
    NeesAtt(usize),
}

/// Values derived from one attitude source in one step, computed only where needed.
#[derive(Clone, Copy, Debug)]
struct Derived {
    values: [f64; N_Q],
}

const NAN_DERIVED: Derived = Derived {
    values: [f64::NAN; N_Q],
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
    truth_extra_len: usize,
    any_truth_extra: bool,
    extra_lens: Vec<usize>,
    any_extra: Vec<bool>,
    truth_extra_buf: Vec<f64>,
    any_sensor_extra: bool,
    sensor_extra_buf: Vec<f64>,
    extra_bufs: Vec<Vec<f64>>,
    est_derived: Vec<Derived>,
}

/// What a lab's estimators and truth offer, before selection.
struct Candidate {
    source: Source,
    spec: SeriesSpec,
}

fn bit(q: Q) -> u32 {
    1 << q as u32
}

/// The squared SI unit of a covariance element, for labels.
fn squared(unit: &str) -> &'static str {
    match unit {
        "rad" => "rad²",
        "rad/s" => "rad²/s²",
        "T" => "T²",
        "" => "",
        _ => "(unit)²",
    }
}

fn cross_unit(a: &str, b: &str) -> &'static str {
    match (a, b) {
        ("rad", "rad/s") | ("rad/s", "rad") => "rad²/s",
        _ if a == b => squared(a),
        _ => "",
    }
}

fn unit_scale_to_display(unit: &str) -> f64 {
    match unit {
        "rad" | "rad/s" => 1f64.to_degrees(),
        _ => 1.0,
    }
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
        figure_series: &[&str],
        sphere: bool,
    ) -> Result<Self, UnknownSeries> {
        let single_axis = truth.state().angle_rad.is_some();
        let candidates = candidates(truth, sensors, estimators, single_axis);
        let keep: Vec<bool> = match selection {
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
        let extra_lens: Vec<usize> = estimators.iter().map(|e| e.extra_names().len()).collect();
        let truth_extra_len = truth.extra_series().len();
        let sensor_extra_len = sensors.extra_series().len();
        Ok(Self {
            columns,
            specs,
            available,
            single_axis,
            truth_needs,
            est_needs,
            truth_extra_len,
            any_truth_extra,
            extra_bufs: extra_lens.iter().map(|n| vec![f64::NAN; *n]).collect(),
            extra_lens,
            any_extra,
            truth_extra_buf: vec![f64::NAN; truth_extra_len],
            any_sensor_extra: any_sensor_extra && sensor_extra_len > 0,
            sensor_extra_buf: vec![f64::NAN; sensor_extra_len],
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
        if self.any_truth_extra && self.truth_extra_len > 0 {
            truth_model.extra_values(&mut self.truth_extra_buf);
        }
        if self.any_sensor_extra {
            sensors.extra_values(&mut self.sensor_extra_buf);
        }
        for (i, e) in estimates.iter().enumerate() {
            let needs = self.est_needs[i];
            if needs != 0 {
                self.est_derived[i] = derive(needs, e, Some((truth, &truth_d)), self.single_axis);
            }
            if self.any_extra[i] && self.extra_lens[i] > 0 {
                estimators[i].extras(&mut self.extra_bufs[i]);
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

/// eᵀP⁻¹e of the attitude: e from the truth (rad), P the estimator's attitude block.
fn nees_att(e: &dyn Estimator, d: &Derived) -> f64 {
    let Some(c) = e.covariance() else {
        return f64::NAN;
    };
    let idx: Vec<usize> = (0..3)
        .filter_map(|a| c.index_of(StateKind::AttitudeAxis(a)))
        .collect();
    if idx.len() != 3 {
        return f64::NAN;
    }
    let p = nalgebra::Matrix3::from_fn(|r, k| c.get(idx[r], idx[k]));
    let err = nalgebra::Vector3::new(
        d.values[Q::ErrX as usize],
        d.values[Q::ErrY as usize],
        d.values[Q::ErrZ as usize],
    )
    .map(f64::to_radians);
    p.cholesky().map_or(f64::NAN, |ch| err.dot(&ch.solve(&err)))
}

/// The truth quantities an error quantity compares with.
fn error_truth_needs(q: Q) -> u32 {
    match q {
        Q::TiltErr | Q::PitchErr | Q::RollErr => bit(Q::Kx),
        _ => 0,
    }
}

/// Is this candidate recorded by the page?
fn standard(c: &Candidate, figure_series: &[&str], sphere: bool) -> bool {
    if figure_series.contains(&c.spec.name.as_str()) {
        return true;
    }
    match c.source {
        Source::Time | Source::Variance(..) | Source::Innovation(..) | Source::Status(_) => true,
        Source::Est(_, q) => {
            matches!(
                q,
                Q::ErrDeg | Q::TiltErr | Q::ErrX | Q::ErrY | Q::ErrZ | Q::AngleErr | Q::RateErr1
            ) || (sphere && matches!(q, Q::Kx | Q::Ky | Q::Kz | Q::U | Q::V))
        }
        Source::Truth(q) => sphere && matches!(q, Q::Kx | Q::Ky | Q::Kz | Q::U | Q::V),
        _ => false,
    }
}

/// Every series the truth and the estimators can give.
fn candidates(
    truth: &dyn TruthModel,
    sensors: &dyn SensorModel,
    estimators: &[Box<dyn Estimator>],
    single_axis: bool,
) -> Vec<Candidate> {
    let mut out = vec![Candidate {
        source: Source::Time,
        spec: SeriesSpec::new("t_s", "s", SeriesGroup::Time),
    }];
    let per_source = |out: &mut Vec<Candidate>,
                      prefix: &str,
                      src: usize,
                      list: &[QInfo],
                      make: &dyn Fn(Q) -> Source,
                      bands: Option<&'static [StateInfo]>| {
        for info in list {
            let mut spec =
                SeriesSpec::new(format!("{prefix}.{}", info.name), info.unit, info.group)
                    .from_source(src);
            if let (Some(kind), Some(states)) = (info.band, bands)
                && let Some(state) = states.iter().find(|s| s.kind == kind)
            {
                spec = spec.with_band(
                    format!("{prefix}.var_{}", state.key),
                    unit_scale_to_display(state.unit),
                );
            }
            out.push(Candidate {
                source: make(info.q),
                spec,
            });
        }
    };
    let (att, rate): (&[QInfo], &[QInfo]) = if single_axis {
        (ANGLE_1, RATE_1)
    } else {
        (ATTITUDE_3, RATE_3)
    };
    per_source(&mut out, "truth", 0, att, &Source::Truth, None);
    per_source(&mut out, "truth", 0, rate, &Source::Truth, None);
    for (j, spec) in truth.extra_series().into_iter().enumerate() {
        out.push(Candidate {
            source: Source::TruthExtra(j),
            spec,
        });
    }
    for (j, spec) in sensors.extra_series().into_iter().enumerate() {
        out.push(Candidate {
            source: Source::SensorExtra(j),
            spec,
        });
    }
    for (i, e) in estimators.iter().enumerate() {
        let id = e.id();
        let src = i + 1;
        let states = e.covariance_states();
        let outputs = e.outputs();
        let make = |q| Source::Est(i, q);
        if single_axis {
            if outputs.angle {
                per_source(&mut out, id, src, ANGLE_1, &make, Some(states));
                per_source(&mut out, id, src, &ERRORS_1[..1], &make, Some(states));
            }
            if outputs.rate {
                per_source(&mut out, id, src, RATE_1, &make, Some(states));
                per_source(&mut out, id, src, &ERRORS_1[1..], &make, Some(states));
            }
        } else {
            let (full, tilt) = (outputs.attitude, outputs.tilt);
            if tilt {
                let list: Vec<&QInfo> = ATTITUDE_3
                    .iter()
                    .filter(|q| full || !matches!(q.q, Q::Yaw | Q::Z))
                    .collect();
                for info in list {
                    per_source(
                        &mut out,
                        id,
                        src,
                        std::slice::from_ref(info),
                        &make,
                        Some(states),
                    );
                }
            }
            if outputs.rate {
                per_source(&mut out, id, src, RATE_3, &make, Some(states));
                per_source(&mut out, id, src, RATE_ERRORS_3, &make, Some(states));
            }
            if full {
                per_source(&mut out, id, src, &ERRORS_3[..1], &make, Some(states));
            }
            if tilt {
                per_source(&mut out, id, src, TILT_ERRORS, &make, Some(states));
            }
            if full {
                per_source(&mut out, id, src, &ERRORS_3[1..], &make, Some(states));
            }
        }
        for (k, s) in states.iter().enumerate() {
            out.push(Candidate {
                source: Source::Variance(i, k),
                spec: SeriesSpec::new(
                    format!("{id}.var_{}", s.key),
                    squared(s.unit),
                    SeriesGroup::Covariance,
                )
                .from_source(src),
            });
        }
        let has_att_block =
            (0..3).all(|a| states.iter().any(|s| s.kind == StateKind::AttitudeAxis(a)));
        if has_att_block && outputs.attitude && !single_axis {
            out.push(Candidate {
                source: Source::NeesAtt(i),
                spec: SeriesSpec::new(format!("{id}.nees_att"), "", SeriesGroup::Error)
                    .from_source(src),
            });
        }
        if states.len() == 2 {
            out.push(Candidate {
                source: Source::Cross(i, 0, 1),
                spec: SeriesSpec::new(
                    format!("{id}.cov_{}_{}", states[0].key, states[1].key),
                    cross_unit(states[0].unit, states[1].unit),
                    SeriesGroup::Covariance,
                )
                .from_source(src),
            });
        }
        for (k, name) in e.innovation_names().iter().enumerate() {
            out.push(Candidate {
                source: Source::Innovation(i, k),
                spec: SeriesSpec::new(format!("{id}.{name}"), "", SeriesGroup::Innovation)
                    .from_source(src),
            });
        }
        for (k, name) in e.extra_names().iter().enumerate() {
            out.push(Candidate {
                source: Source::Extra(i, k),
                spec: SeriesSpec::new(format!("{id}.{name}"), "", SeriesGroup::Lab)
                    .from_source(src),
            });
        }
        out.push(Candidate {
            source: Source::Status(i),
            spec: SeriesSpec::new(format!("{id}.status"), "", SeriesGroup::Lab).from_source(src),
        });
    }
    out
}

/// |w| above which (u, v) are recorded as missing: the point is then within ~11° of the
/// pole S, where paper 3's chart has no numerical meaning (the (u, v, z) integrator has
/// switched to s = 1/w) and the values would swamp every plot. The chart-free vertical
/// k_x, k_y, k_z is always recorded.
const W_RECORD_LIMIT: f64 = 10.0;

/// Computes the quantities in `needs` for one source; `truth` (with its derived values) is
/// given for estimates, whose errors need it.
fn derive(
    needs: u32,
    e: &Estimate,
    truth: Option<(&TruthState, &Derived)>,
    single_axis: bool,
) -> Derived {
    let mut d = [f64::NAN; N_Q];
    let has = |q: Q| needs & bit(q) != 0;
    let deg = f64::to_degrees;
    if single_axis {
        if let Some(a) = e.angle_rad {
            d[Q::Angle as usize] = deg(a);
            if let Some((t, _)) = truth
                && let Some(ta) = t.angle_rad
            {
                d[Q::AngleErr as usize] = deg(a - ta);
            }
        }
        if let Some(r) = e.rate_body_rad_s {
            d[Q::Rate1 as usize] = deg(r.z);
            if let Some((t, _)) = truth {
                d[Q::RateErr1 as usize] = deg(r.z - t.rate_body_rad_s.z);
            }
        }
        return Derived { values: d };
    }
    if let Some(r) = e.rate_body_rad_s {
        if needs & (bit(Q::RateX) | bit(Q::RateY) | bit(Q::RateZ)) != 0 {
            d[Q::RateX as usize] = deg(r.x);
            d[Q::RateY as usize] = deg(r.y);
            d[Q::RateZ as usize] = deg(r.z);
        }
        if let Some((t, _)) = truth {
            let err = r - t.rate_body_rad_s;
            d[Q::RateErrX as usize] = deg(err.x);
            d[Q::RateErrY as usize] = deg(err.y);
            d[Q::RateErrZ as usize] = deg(err.z);
        }
    }
    // The full attitude as a quaternion, converted from (w, z) only if a column needs it.
    let q_bits = bit(Q::Yaw) | bit(Q::ErrDeg) | bit(Q::ErrX) | bit(Q::ErrY) | bit(Q::ErrZ);
    let z_from_q = has(Q::Z) && !matches!(e.attitude, Attitude::Wz(w) if w.chart == WzChart::North);
    let q = if needs & q_bits != 0 || z_from_q {
        e.attitude.quaternion()
    } else {
        None
    };
    if has(Q::Yaw)
        && let Some(q) = q
    {
        d[Q::Yaw as usize] = deg(EulerYpr::yaw_of(&q));
    }
    let sphere_bits =
        bit(Q::Pitch) | bit(Q::Roll) | bit(Q::Kx) | bit(Q::Ky) | bit(Q::Kz) | bit(Q::U) | bit(Q::V);
    let tilt_bits = bit(Q::TiltErr) | bit(Q::PitchErr) | bit(Q::RollErr);
    let k = if needs & (sphere_bits | tilt_bits) != 0 {
        e.attitude.vertical_in_body()
    } else {
        None
    };
    if let Some(k) = k {
        if needs & (bit(Q::Pitch) | bit(Q::Roll) | tilt_bits) != 0 {
            // Pitch and roll depend on the vertical only (paper 3, eqs. 24–25), so a
            // tilt-only estimate still has them.
            let (pitch, roll) = pitch_roll_of_vertical(&k);
            d[Q::Pitch as usize] = deg(pitch);
            d[Q::Roll as usize] = deg(roll);
        }
        d[Q::Kx as usize] = k.x;
        d[Q::Ky as usize] = k.y;
        d[Q::Kz as usize] = k.z;
        if has(Q::U) || has(Q::V) {
            // w = (a′ + jb′)/(1 + c′) (paper 3, eq. 12), recorded only away from the pole.
            let w = if 1.0 + k.z > 0.0 {
                Some((k.x / (1.0 + k.z), k.y / (1.0 + k.z)))
            } else {
                None
            };
            if let Some((u, v)) = w.filter(|(u, v)| u * u + v * v < W_RECORD_LIMIT * W_RECORD_LIMIT)
            {
                d[Q::U as usize] = u;
                d[Q::V as usize] = v;
            }
        }
        if let Some((_, td)) = truth
            && needs & tilt_bits != 0
        {
            let kt = nalgebra::Vector3::new(
                td.values[Q::Kx as usize],
                td.values[Q::Ky as usize],
                td.values[Q::Kz as usize],
            );
            let (pt, rt) = pitch_roll_of_vertical(&kt);
            if has(Q::TiltErr) {
                d[Q::TiltErr as usize] = deg(kt.cross(&k).norm().atan2(kt.dot(&k)));
            }
            d[Q::PitchErr as usize] = d[Q::Pitch as usize] - deg(pt);
            d[Q::RollErr as usize] = deg(wrap_pi(d[Q::Roll as usize].to_radians() - rt));
        }
    }
    if has(Q::Z) {
        // z is chart dependent; record it in paper 3's chart where that chart exists.
        d[Q::Z as usize] = match (e.attitude, q) {
            (Attitude::Wz(w), _) if w.chart == WzChart::North => deg(w.z_rad),
            (_, Some(q)) => WzAttitude::from_dcm_in_chart(&dcm_from_quaternion(&q), WzChart::North)
                .map_or(f64::NAN, |w| deg(w.z_rad)),
            _ => f64::NAN,
        };
    }
    if let (Some((t, _)), Some(q)) = (truth, q)
        && needs & (bit(Q::ErrDeg) | bit(Q::ErrX) | bit(Q::ErrY) | bit(Q::ErrZ)) != 0
    {
        // The error rotation in body axes, once: its angle is the total error, its
        // scaled axis the error per axis.
        let err = small_angle_error_body(&t.q_ref_from_body, &q);
        d[Q::ErrDeg as usize] = deg(err.norm());
        d[Q::ErrX as usize] = deg(err.x);
        d[Q::ErrY as usize] = deg(err.y);
        d[Q::ErrZ as usize] = deg(err.z);
    }
    Derived { values: d }
}
