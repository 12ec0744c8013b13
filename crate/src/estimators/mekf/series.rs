//! The series a [`Mekf`] records besides the catalogue's (figures name them): NIS, and the
//! estimates of the bias and disturbance states its configuration has.

use super::{Mekf, StateSet};
use crate::model::{Extras, Quantity};

/// innovation test statistic NIS.
pub const NIS: Quantity = Quantity::new("nis", "innovation test statistic NIS", "");
/// NIS degrees of freedom.
pub const NIS_DOF: Quantity = Quantity::new("nis_dof", "NIS degrees of freedom", "");
/// gyro bias Δω_x (deg/s).
pub const GBIAS_X_DEG_S: Quantity = Quantity::new("gbias_x_deg_s", "gyro bias Δω_x", "deg/s");
/// gyro bias Δω_y (deg/s).
pub const GBIAS_Y_DEG_S: Quantity = Quantity::new("gbias_y_deg_s", "gyro bias Δω_y", "deg/s");
/// gyro bias Δω_z (deg/s).
pub const GBIAS_Z_DEG_S: Quantity = Quantity::new("gbias_z_deg_s", "gyro bias Δω_z", "deg/s");
/// magnetometer bias Δb_x (nT).
pub const MBIAS_X_NT: Quantity = Quantity::new("mbias_x_nt", "magnetometer bias Δb_x", "nT");
/// magnetometer bias Δb_y (nT).
pub const MBIAS_Y_NT: Quantity = Quantity::new("mbias_y_nt", "magnetometer bias Δb_y", "nT");
/// magnetometer bias Δb_z (nT).
pub const MBIAS_Z_NT: Quantity = Quantity::new("mbias_z_nt", "magnetometer bias Δb_z", "nT");
/// disturbance estimate d_x (1/s²).
pub const D_X_S2: Quantity = Quantity::new("d_x_s2", "disturbance estimate d_x", "1/s²");
/// disturbance estimate d_y (1/s²).
pub const D_Y_S2: Quantity = Quantity::new("d_y_s2", "disturbance estimate d_y", "1/s²");
/// disturbance estimate d_z (1/s²).
pub const D_Z_S2: Quantity = Quantity::new("d_z_s2", "disturbance estimate d_z", "1/s²");
/// magnetometer bias as a turn of the field about x (deg, Fig. 7's model).
pub const MTURN_X_DEG: Quantity = Quantity::new(
    "mturn_x_deg",
    "magnetometer bias: turn of the field about x",
    "deg",
);
/// magnetometer bias as a turn of the field about y (deg).
pub const MTURN_Y_DEG: Quantity = Quantity::new(
    "mturn_y_deg",
    "magnetometer bias: turn of the field about y",
    "deg",
);
/// magnetometer bias as a turn of the field about z (deg).
pub const MTURN_Z_DEG: Quantity = Quantity::new(
    "mturn_z_deg",
    "magnetometer bias: turn of the field about z",
    "deg",
);

const GB: [Quantity; 3] = [GBIAS_X_DEG_S, GBIAS_Y_DEG_S, GBIAS_Z_DEG_S];
const MB: [Quantity; 3] = [MBIAS_X_NT, MBIAS_Y_NT, MBIAS_Z_NT];
const MT: [Quantity; 3] = [MTURN_X_DEG, MTURN_Y_DEG, MTURN_Z_DEG];
const D: [Quantity; 3] = [D_X_S2, D_Y_S2, D_Z_S2];

/// NIS, its degrees of freedom, then the bias estimates (if any), then d (if any).
const fn list<const K: usize>(bias: Option<[Quantity; 3]>, dist: bool) -> [Quantity; K] {
    let mut out = [NIS; K];
    out[1] = NIS_DOF;
    let mut k = 2;
    if let Some(b) = bias {
        out[2] = b[0];
        out[3] = b[1];
        out[4] = b[2];
        k = 5;
    }
    if dist {
        out[k] = D[0];
        out[k + 1] = D[1];
        out[k + 2] = D[2];
    }
    out
}

/// The extra quantities of a filter with `states` and (or not) the disturbance filter.
pub(super) fn extra_quantities(states: StateSet, dist: bool) -> &'static [Quantity] {
    const BASE: [Quantity; 2] = list(None, false);
    const ONLY_D: [Quantity; 5] = list(None, true);
    const WITH: [[Quantity; 5]; 3] = [
        list(Some(GB), false),
        list(Some(MB), false),
        list(Some(MT), false),
    ];
    const WITH_D: [[Quantity; 8]; 3] = [
        list(Some(GB), true),
        list(Some(MB), true),
        list(Some(MT), true),
    ];
    match (bias_kind(states), dist) {
        (Some(k), false) => &WITH[k],
        (Some(k), true) => &WITH_D[k],
        (None, true) => &ONLY_D,
        (None, false) => &BASE,
    }
}

/// Which bias `states` carry: 0 the gyro's, 1 the magnetometer's in nT, 2 the
/// magnetometer's as a turn of the field.
fn bias_kind(states: StateSet) -> Option<usize> {
    match states {
        StateSet::AttRateGyroBias | StateSet::AttGyroBias => Some(0),
        StateSet::AttRateMagBias => Some(1),
        StateSet::AttRateMagTurn => Some(2),
        StateSet::AttRate => None,
    }
}

impl<const N: usize> Mekf<N> {
    /// Records NIS and the bias and disturbance estimates.
    pub(super) fn put_extras(&self, out: &mut Extras<'_>) {
        out.put(&NIS, self.nis[0]);
        out.put(&NIS_DOF, self.nis[1]);
        match bias_kind(self.cfg.states) {
            Some(0) => out.put_all(&GB, self.gyro_bias.map(f64::to_degrees).iter().copied()),
            Some(1) => out.put_all(&MB, self.mag_bias.iter().copied()),
            Some(_) => out.put_all(&MT, self.mag_bias.map(f64::to_degrees).iter().copied()),
            None => {}
        }
        if let Some(d) = self.dist {
            out.put_all(&D, d.d.iter().copied());
        }
    }
}
