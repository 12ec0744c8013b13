//! The series catalogue: every quantity a source (the truth or an estimator) can record —
//! its name, unit, plot group and the covariance state that bounds it — and the list of
//! candidate columns a lab's truth, sensors and estimators offer before selection.

use crate::model::{
    Estimator, SensorModel, SeriesGroup, SeriesSpec, StateInfo, StateKind, TruthModel,
};

/// A quantity of the truth or of an estimate, derived from its attitude, rate or angle.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Q {
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

pub(super) const N_Q: usize = Q::RateErr1 as usize + 1;

/// What each quantity is called, its unit and plot, and the covariance state bounding it.
pub(super) struct QInfo {
    pub(super) q: Q,
    pub(super) name: &'static str,
    pub(super) unit: &'static str,
    pub(super) group: SeriesGroup,
    pub(super) band: Option<StateKind>,
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
pub(super) enum Source {
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

/// What a lab's estimators and truth offer, before selection.
pub(super) struct Candidate {
    pub(super) source: Source,
    pub(super) spec: SeriesSpec,
}

pub(super) fn bit(q: Q) -> u32 {
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

/// The truth quantities an error quantity compares with.
pub(super) fn error_truth_needs(q: Q) -> u32 {
    match q {
        Q::TiltErr | Q::PitchErr | Q::RollErr => bit(Q::Kx),
        _ => 0,
    }
}

/// Is this candidate recorded by the page?
pub(super) fn standard(c: &Candidate, figure_series: &[&str], sphere: bool) -> bool {
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
pub(super) fn candidates(
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
