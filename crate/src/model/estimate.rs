//! What sensors deliver and what estimators publish.

use super::cycle::Teaching;
use super::data::LabData;
use super::params::ParamValues;
use super::quantity::{Quantity, StateInfo, StateKind};
use super::series::Extras;
use super::trouble::Trouble;
use crate::math::WzAttitude;
use nalgebra::{UnitQuaternion, Vector3};

/// What the sensors delivered at one step. Fields a lab's sensors don't have stay `None`.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Measurements {
    /// Time of the sample (s).
    pub t_s: f64,
    /// Three-axis gyro reading in body axes (rad/s).
    pub gyro_body_rad_s: Option<Vector3<f64>>,
    /// Accelerometer specific force in body axes, in units of g.
    pub accel_body_g: Option<Vector3<f64>>,
    /// Single-axis gyro reading (rad/s).
    pub gyro_axis_rad_s: Option<f64>,
    /// Magnetometer reading in body axes (nT).
    pub mag_body_nt: Option<Vector3<f64>>,
    /// Sun direction in body axes (unit), from whichever sun-sensor head sees the sun.
    pub sun_body: Option<Vector3<f64>>,
    /// Star-tracker attitude, relative to the reference frame of the lab (paper 2: the
    /// orbital frame).
    pub star_q_ref_from_body: Option<UnitQuaternion<f64>>,
    /// What the lab's flight computer knows besides its sensors, typed by the estimator that
    /// reads it (paper 2's orbit, models and wheels: `estimators::Onboard`; paper 4's
    /// controller command: `estimators::ControlInput`).
    pub lab: LabData,
}

/// Health of an estimator, shown in the UI and recorded.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum EstimatorStatus {
    /// Running normally.
    #[default]
    Ok,
    /// The state or covariance became non-finite or lost positive definiteness.
    Diverged(Trouble),
    /// The measurements cannot determine the state right now.
    Unobservable(Trouble),
}

/// The healthy status, for estimators that never fail.
pub static STATUS_OK: EstimatorStatus = EstimatorStatus::Ok;

impl EstimatorStatus {
    /// 0 = ok, 1 = diverged, 2 = unobservable (the recorded value).
    pub fn code(&self) -> f64 {
        match self {
            Self::Ok => 0.0,
            Self::Diverged(_) => 1.0,
            Self::Unobservable(_) => 2.0,
        }
    }

    /// True unless diverged or unobservable.
    pub fn is_ok(&self) -> bool {
        *self == Self::Ok
    }
}

/// An estimated attitude in the estimator's own parameters; conversions are made only
/// where something needs them (a plot of yaw, the 3D ghost).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum Attitude {
    /// No attitude (a single-axis estimator publishes an angle instead).
    #[default]
    None,
    /// A full attitude as `q_ref_from_body`.
    Quaternion(UnitQuaternion<f64>),
    /// A full attitude in paper 3's (w, z).
    Wz(WzAttitude),
    /// The vertical only, as paper 3's w (its z means nothing).
    Tilt(WzAttitude),
}

impl Attitude {
    /// The full attitude as a quaternion (converted from (w, z) if need be).
    pub fn quaternion(&self) -> Option<UnitQuaternion<f64>> {
        match self {
            Self::Quaternion(q) => Some(*q),
            Self::Wz(wz) => Some(wz.to_quaternion()),
            Self::None | Self::Tilt(_) => None,
        }
    }

    /// The (w, z) parameters, for estimators that work in them.
    pub fn wz(&self) -> Option<WzAttitude> {
        match self {
            Self::Wz(wz) | Self::Tilt(wz) => Some(*wz),
            _ => None,
        }
    }

    /// The reference vertical in body axes (all but `None`).
    pub fn vertical_in_body(&self) -> Option<Vector3<f64>> {
        match self {
            Self::Quaternion(q) => Some(crate::math::vertical_in_body(q)),
            Self::Wz(wz) | Self::Tilt(wz) => Some(wz.vertical_in_body()),
            Self::None => None,
        }
    }

    /// A full attitude (not tilt only, not none).
    pub fn is_full(&self) -> bool {
        matches!(self, Self::Quaternion(_) | Self::Wz(_))
    }

    /// Every number in it is finite.
    pub fn is_finite(&self) -> bool {
        match self {
            Self::None => true,
            Self::Quaternion(q) => q.coords.iter().all(|c| c.is_finite()),
            Self::Wz(wz) | Self::Tilt(wz) => {
                wz.u.is_finite() && wz.v.is_finite() && wz.z_rad.is_finite()
            }
        }
    }
}

/// The uniform, heap-free record every estimator publishes each step. A field is `None`
/// when the estimator does not estimate that quantity.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Estimate {
    /// Estimated attitude.
    pub attitude: Attitude,
    /// Estimated angle of a single-axis estimator (rad).
    pub angle_rad: Option<f64>,
    /// Estimated body rate (rad/s).
    pub rate_body_rad_s: Option<Vector3<f64>>,
}

impl Estimate {
    /// The attitude as a quaternion: the full attitude, or for a single-axis estimator the
    /// turn by its angle about body z (what the 3D view draws).
    pub fn quaternion(&self) -> Option<UnitQuaternion<f64>> {
        self.attitude.quaternion().or_else(|| {
            self.angle_rad
                .map(|a| UnitQuaternion::from_axis_angle(&Vector3::z_axis(), a))
        })
    }

    /// Every number in it is finite.
    pub fn is_finite(&self) -> bool {
        self.attitude.is_finite()
            && self.angle_rad.is_none_or(f64::is_finite)
            && self
                .rate_body_rad_s
                .is_none_or(|r| r.iter().all(|c| c.is_finite()))
    }
}

/// What an estimator estimates: decides which of its series exist (a tilt-only estimator
/// has no yaw, a single-axis one no vertical).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Outputs {
    /// A full attitude (`q_ref_from_body`).
    pub attitude: bool,
    /// The vertical, hence pitch and roll (`wz` or `q_ref_from_body`).
    pub tilt: bool,
    /// A single-axis angle.
    pub angle: bool,
    /// A body rate.
    pub rate: bool,
}

impl Outputs {
    /// What `e` has.
    pub fn of(e: &Estimate) -> Self {
        Self {
            attitude: e.attitude.is_full(),
            tilt: e.attitude != Attitude::None,
            angle: e.angle_rad.is_some(),
            rate: e.rate_body_rad_s.is_some(),
        }
    }
}

/// An estimator's covariance now: what each state is, and the symmetric n×n matrix
/// (column-major, SI units).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Covariance<'a> {
    /// The states, in matrix order.
    pub states: &'static [StateInfo],
    /// The n×n matrix, column-major (nalgebra's `as_slice()`).
    pub matrix: &'a [f64],
}

impl Covariance<'_> {
    /// Number of states.
    pub fn dim(&self) -> usize {
        self.states.len()
    }

    /// Element (i, j).
    pub fn get(&self, i: usize, j: usize) -> f64 {
        self.matrix[j * self.dim() + i]
    }

    /// Index of the state of kind `kind`.
    pub fn index_of(&self, kind: StateKind) -> Option<usize> {
        self.states.iter().position(|s| s.kind == kind)
    }

    /// Variance of the state of kind `kind`.
    pub fn variance_of(&self, kind: StateKind) -> Option<f64> {
        self.index_of(kind).map(|i| self.get(i, i))
    }
}

/// How a lab turns its parameters into an estimator's tuning: a function of the lab's own,
/// so that only the lab reads its keys (an estimator never looks one up, and a key the lab
/// lacks is the lab's own bug, which its tests find). An estimator built with one re-tunes
/// on every live parameter change; one built without keeps the tuning it was built with.
pub type Tuner<T> = fn(&ParamValues) -> T;

/// An attitude estimator in the simulation loop. One file per estimator, each citing its
/// paper and equations; a lab lists its estimators in [`super::LabRun::estimators`].
pub trait Estimator: Send + dyn_clone::DynClone {
    /// Short stable id used in series names, e.g. `quat-rk4`.
    fn id(&self) -> &'static str;
    /// Human label for legends.
    fn label(&self) -> &'static str;
    /// Takes new parameter values (a slider moved); effective from the next step.
    fn apply_params(&mut self, params: &ParamValues);
    /// Processes the measurements of one step of length `dt_s`.
    fn step(&mut self, measurements: &Measurements, dt_s: f64);
    /// The current estimate.
    fn estimate(&self) -> Estimate;
    /// What it estimates (by default: what its first estimate has; an estimator with no
    /// estimate before its first measurement says so here).
    fn outputs(&self) -> Outputs {
        Outputs::of(&self.estimate())
    }
    /// Health.
    fn status(&self) -> &EstimatorStatus {
        &STATUS_OK
    }
    /// The body axis about which the estimator's sensors say nothing now (e.g. the field
    /// direction for a gyro plus a magnetometer alone), drawn on the body in the 3D view.
    fn unobservable_axis_body(&self) -> Option<Vector3<f64>> {
        None
    }
    /// The covariance it carries (or predicts), if any.
    fn covariance(&self) -> Option<Covariance<'_>> {
        None
    }
    /// The states [`Estimator::covariance`] describes (fixed for an estimator), so series can
    /// be laid out before the first step.
    fn covariance_states(&self) -> &'static [StateInfo] {
        &[]
    }
    /// The innovation components it publishes: key, label and unit of each.
    fn innovation_quantities(&self) -> &'static [Quantity] {
        &[]
    }
    /// The last innovation, in the order of [`Estimator::innovation_quantities`].
    fn innovation(&self) -> &[f64] {
        &[]
    }
    /// Internals worth plotting (e.g. the channels of a blend): key, label and unit of each.
    fn extra_quantities(&self) -> &'static [Quantity] {
        &[]
    }
    /// Writes the internals of [`Estimator::extra_quantities`] into `out` (same length).
    fn extras(&self, _out: &mut Extras<'_>) {}
    /// What the filter shows of its own working, if it is small enough to teach with (the
    /// page's step-through panel): none by default.
    fn teaching(&self) -> Option<&dyn Teaching> {
        None
    }
    /// The heap its clone allocates beyond its own struct (bytes; a time-travel snapshot is
    /// a clone, `sim::history` counts them): only a model that keeps a growing buffer says
    /// more than 0.
    fn heap_bytes(&self) -> usize {
        0
    }
}

dyn_clone::clone_trait_object!(Estimator);
