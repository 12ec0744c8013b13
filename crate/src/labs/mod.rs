//! The registry of labs: one folder (or file) per paper, all listed in [`all`]. The UI's lab
//! picker, the CLI and the conformance tests iterate this one list; registering a lab is
//! one line.

pub mod free_rotation;
pub mod p1_suspended;
pub mod p2_tabletsat;
pub mod p3_wz_sphere;
pub mod p4_quadrotor;
pub mod p5_sensitivity;

pub use free_rotation::FreeRotation;
pub use p1_suspended::SuspendedMockup;
pub use p2_tabletsat::TabletSat;
pub use p3_wz_sphere::WzSphere;
pub use p4_quadrotor::QuadrotorRoll;
pub use p5_sensitivity::SensitivityLab;

use crate::model::{LogFormat, LogRefusal, OtherFormat};
use crate::page::Lab;

/// Every lab, in menu order.
pub fn all() -> &'static [&'static dyn Lab] {
    &[
        &FreeRotation,
        &SuspendedMockup,
        &TabletSat,
        &WzSphere,
        &QuadrotorRoll,
        &SensitivityLab,
    ]
}

/// The lab with this id.
pub fn find(id: &str) -> Option<&'static dyn Lab> {
    all().iter().copied().find(|l| l.id() == id)
}

/// Comma-separated ids of all labs (for error messages).
pub fn ids() -> String {
    all().iter().map(|l| l.id()).collect::<Vec<_>>().join(", ")
}

/// Reads `bytes` as `lab`'s kind of recorded log with unit choices `units`, or says why
/// it cannot be replayed: the lab reads no logs; fewer than two samples; or most lines of
/// numbers have another width than the format's (a log of another lab's format: named,
/// with the labs that read it), or the format's own check of the units fails.
pub fn read_log(
    lab: &dyn Lab,
    bytes: &[u8],
    units: &crate::model::ParamValues,
) -> Result<crate::model::RateLog, LogRefusal> {
    let format = lab
        .page()
        .log_format
        .ok_or_else(|| LogRefusal::NotReplayed {
            lab: lab.id(),
            replaying: all()
                .iter()
                .filter(|l| l.page().log_format.is_some())
                .map(|l| l.id())
                .collect(),
        })?;
    let log = (format.parse)(bytes, units);
    let count = |width: usize| {
        log.widths
            .iter()
            .find(|(w, _)| *w == width)
            .map_or(0, |(_, n)| *n)
    };
    let own = count(format.columns);
    let widest = log.widths.iter().max_by_key(|(_, n)| *n);
    if let Some(&(width, n)) = widest.filter(|(w, n)| *w != format.columns && *n > own) {
        let readers: Vec<(&'static str, &LogFormat)> = all()
            .iter()
            .filter_map(|l| l.page().log_format.map(|f| (l.id(), f)))
            .filter(|(_, f)| f.columns == width)
            .collect();
        let other = readers.first().map(|(_, f)| OtherFormat {
            name: f.name,
            labs: (readers.iter())
                .filter(|(_, g)| g.id == f.id)
                .map(|(id, _)| *id)
                .collect(),
        });
        return Err(LogRefusal::OtherWidth {
            lines: n,
            width,
            own,
            columns: format.columns,
            lab: lab.id(),
            format: format.name,
            other,
        });
    }
    if log.median_dt_s().is_none() {
        return Err(LogRefusal::TooFewSamples {
            counts: log.counts,
            first: log.errors.first().cloned(),
        });
    }
    (format.check)(&log, units)?;
    Ok(log)
}
