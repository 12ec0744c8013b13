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

use crate::model::{Lab, LogFormat};

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
) -> Result<crate::model::RateLog, String> {
    let format = lab.page().log_format.ok_or_else(|| {
        let replaying: Vec<&str> = all()
            .iter()
            .filter(|l| l.page().log_format.is_some())
            .map(|l| l.id())
            .collect();
        format!(
            "lab {} does not replay logs; these do: {}",
            lab.id(),
            replaying.join(", ")
        )
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
        let readers: Vec<(&str, &LogFormat)> = all()
            .iter()
            .filter_map(|l| l.page().log_format.map(|f| (l.id(), f)))
            .filter(|(_, f)| f.columns == width)
            .collect();
        let looks = match readers.first() {
            Some((_, f)) => {
                let labs: Vec<&str> = (readers.iter())
                    .filter(|(_, g)| g.id == f.id)
                    .map(|(id, _)| *id)
                    .collect();
                let s = if labs.len() == 1 { "" } else { "s" };
                format!(
                    " It looks like {} (read by lab{s} {}).",
                    f.name,
                    labs.join(", ")
                )
            }
            None => String::new(),
        };
        return Err(format!(
            "{n} lines have {width} numbers and {own} have {}: lab {} reads {}, {} numbers a line.{looks}",
            format.columns,
            lab.id(),
            format.name,
            format.columns
        ));
    }
    if log.median_dt_s().is_none() {
        let first = log
            .errors
            .first()
            .map_or(String::new(), |e| format!("; first bad line: {e}"));
        return Err(format!(
            "the log needs at least two samples with increasing times ({}{first})",
            log.counts
        ));
    }
    (format.check)(&log, units)?;
    Ok(log)
}
