//! The series catalogue: every quantity a source (the truth or an estimator) can record —
//! its name, unit, plot group and the covariance state that bounds it — and the list of
//! candidate columns a lab's truth, sensors and estimators offer before selection.

use super::quantities::{
    ANGLE_1, ATTITUDE_3, ERRORS_1, ERRORS_3, QInfo, RATE_1, RATE_3, RATE_ERRORS_3, TILT_ERRORS,
    state_label,
};
pub(super) use super::quantities::{N_Q, Q};
use crate::model::{
    Estimator, Quantity, SensorModel, SeriesGroup, SeriesKey, SeriesSpec, StateInfo, StateKind,
    TIME, TRUTH, TruthModel,
};

use SeriesGroup as G;
use StateKind as K;

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
        "nT" => "nT²",
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
pub(super) fn standard(c: &Candidate, figure_series: &[SeriesKey], sphere: bool) -> bool {
    if figure_series.iter().any(|k| k.is(&c.spec.name)) {
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
        spec: SeriesSpec::new(TIME, "s", G::Time).labelled("time t"),
    }];
    let (att, rate) = if single_axis {
        (ANGLE_1, RATE_1)
    } else {
        (ATTITUDE_3, RATE_3)
    };
    let truth_src = Owner {
        prefix: TRUTH,
        label: "Truth",
        src: 0,
        states: None,
    };
    for list in [att, rate] {
        truth_src.push_all(&mut out, list.iter(), &Source::Truth);
    }
    for (j, spec) in truth.extra_series().into_iter().enumerate() {
        out.push(Candidate {
            source: Source::TruthExtra(j),
            spec: owned_label("Truth", spec),
        });
    }
    for (j, spec) in sensors.extra_series().into_iter().enumerate() {
        out.push(Candidate {
            source: Source::SensorExtra(j),
            spec: owned_label("Sensors", spec),
        });
    }
    for (i, e) in estimators.iter().enumerate() {
        let owner = Owner {
            prefix: e.id(),
            label: e.label(),
            src: i + 1,
            states: Some(e.covariance_states()),
        };
        if single_axis {
            single_axis_candidates(&mut out, &owner, i, e.as_ref());
        } else {
            three_axis_candidates(&mut out, &owner, i, e.as_ref());
        }
        internal_candidates(&mut out, &owner, i, e.as_ref(), single_axis);
    }
    out
}

/// A lab's own series (truth or sensor extras) with the owner's name before its label.
fn owned_label(owner: &str, spec: SeriesSpec) -> SeriesSpec {
    if spec.has_label() {
        let label = format!("{owner}: {}", spec.label);
        spec.labelled(label)
    } else {
        spec
    }
}

/// Who records a group of series: the truth (source 0) or estimator `src − 1`.
struct Owner<'a> {
    prefix: &'static str,
    label: &'a str,
    src: usize,
    states: Option<&'static [StateInfo]>,
}

impl Owner<'_> {
    /// The owner's series of `quantity` in `group`: `prefix.key`, "label: quantity".
    fn spec(&self, quantity: &'static Quantity, group: SeriesGroup) -> SeriesSpec {
        let label = format!("{}: {}", self.label, quantity.label);
        SeriesSpec::of(SeriesKey::new(self.prefix, quantity), group)
            .labelled(label)
            .from_source(self.src)
    }

    /// The owner's series of every quantity in `list`, each bounded by its covariance state
    /// where the owner has one.
    fn push_all(
        &self,
        out: &mut Vec<Candidate>,
        list: impl Iterator<Item = &'static QInfo>,
        make: &dyn Fn(Q) -> Source,
    ) {
        for info in list {
            let mut spec = self.spec(info.quantity, info.group);
            if let (Some(kind), Some(states)) = (info.band, self.states)
                && let Some(state) = states.iter().find(|s| s.kind == kind)
            {
                spec = spec.with_band(
                    SeriesKey::variance(self.prefix, state).name(),
                    unit_scale_to_display(state.unit),
                );
            }
            out.push(Candidate {
                source: make(info.q),
                spec,
            });
        }
    }
}

/// A single-axis estimator's angle and rate with their errors.
fn single_axis_candidates(out: &mut Vec<Candidate>, o: &Owner<'_>, i: usize, e: &dyn Estimator) {
    let make = |q| Source::Est(i, q);
    let outputs = e.outputs();
    if outputs.angle {
        o.push_all(out, ANGLE_1.iter().chain(&ERRORS_1[..1]), &make);
    }
    if outputs.rate {
        o.push_all(out, RATE_1.iter().chain(&ERRORS_1[1..]), &make);
    }
}

/// A three-axis estimator's attitude (or tilt), rate and errors, in the recorded order.
fn three_axis_candidates(out: &mut Vec<Candidate>, o: &Owner<'_>, i: usize, e: &dyn Estimator) {
    let make = |q| Source::Est(i, q);
    let outputs = e.outputs();
    let (full, tilt) = (outputs.attitude, outputs.tilt);
    if tilt {
        let list = ATTITUDE_3
            .iter()
            .filter(|q| full || !matches!(q.q, Q::Yaw | Q::Z));
        o.push_all(out, list, &make);
    }
    if outputs.rate {
        o.push_all(out, RATE_3.iter().chain(RATE_ERRORS_3), &make);
    }
    if full {
        o.push_all(out, ERRORS_3[..1].iter(), &make);
    }
    if tilt {
        o.push_all(out, TILT_ERRORS.iter(), &make);
    }
    if full {
        o.push_all(out, ERRORS_3[1..].iter(), &make);
    }
}

/// An estimator's covariance, NEES, innovations, internals and health.
fn internal_candidates(
    out: &mut Vec<Candidate>,
    o: &Owner<'_>,
    i: usize,
    e: &dyn Estimator,
    single_axis: bool,
) {
    let (id, states) = (o.prefix, e.covariance_states());
    let mut push = |source: Source, key: SeriesKey, label: String, unit, group| {
        let spec = SeriesSpec::new(String::new(), unit, group)
            .keyed(key)
            .labelled(format!("{}: {label}", o.label))
            .from_source(o.src);
        out.push(Candidate { source, spec });
    };
    for (k, s) in states.iter().enumerate() {
        let label = format!("variance of the {}", state_label(s));
        let name = SeriesKey::variance(id, s);
        push(
            Source::Variance(i, k),
            name,
            label,
            squared(s.unit),
            G::Covariance,
        );
    }
    let has_att_block = (0..3).all(|a| states.iter().any(|s| s.kind == K::AttitudeAxis(a)));
    if has_att_block && e.outputs().attitude && !single_axis {
        let label = "attitude NEES eᵀP⁻¹e".to_string();
        push(
            Source::NeesAtt(i),
            SeriesKey::nees_att(id),
            label,
            "",
            G::Error,
        );
    }
    if let [a, b] = states {
        let label = format!(
            "covariance of the {} and the {}",
            state_label(a),
            state_label(b)
        );
        let name = SeriesKey::covariance(id, a, b);
        push(
            Source::Cross(i, 0, 1),
            name,
            label,
            cross_unit(a.unit, b.unit),
            G::Covariance,
        );
    }
    for (k, q) in e.innovation_quantities().iter().enumerate() {
        let name = SeriesKey::new(id, q);
        push(
            Source::Innovation(i, k),
            name,
            q.label.to_string(),
            q.unit,
            G::Innovation,
        );
    }
    for (k, q) in e.extra_quantities().iter().enumerate() {
        let name = SeriesKey::new(id, q);
        push(
            Source::Extra(i, k),
            name,
            q.label.to_string(),
            q.unit,
            G::Lab,
        );
    }
    let label = "health (0 = ok)".to_string();
    let name = SeriesKey::status(id);
    push(Source::Status(i), name, label, "", G::Lab);
}
