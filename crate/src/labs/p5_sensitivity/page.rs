//! What paper 5's lab shows: its figures, the eigenvalues of each method's linearised
//! update, and the paper's output file.

use crate::estimators::{Method, linearised_eigenvalues};
use crate::model::{OutputFile, ParamValues, SeriesKey, TIME, q};
use crate::page::{Diagram, DiagramPoint, Figure};

use super::params::METHODS;
use super::truth::ANGLES;
use crate::estimators::sensitivity;

pub(super) const FIGURES: &[Figure] = &[
    Figure::new(
        "error",
        "Attitude error (all methods)",
        &[
            SeriesKey::new("gn9", &q::ERR_DEG),
            SeriesKey::new("lm10", &q::ERR_DEG),
            SeriesKey::new("search11", &q::ERR_DEG),
            SeriesKey::new("reint", &q::ERR_DEG),
            SeriesKey::new("raw", &q::ERR_DEG),
        ],
    )
    .log(),
    Figure::new(
        "angles",
        "Angles of method (9) and the reference",
        &[
            SeriesKey::new("gn9", &sensitivity::ANGLE_1_RAD),
            SeriesKey::new("gn9", &sensitivity::ANGLE_2_RAD),
            SeriesKey::new("gn9", &sensitivity::ANGLE_3_RAD),
            SeriesKey::truth(&sensitivity::ANGLE_1_RAD),
            SeriesKey::truth(&sensitivity::ANGLE_2_RAD),
            SeriesKey::truth(&sensitivity::ANGLE_3_RAD),
        ],
    ),
    Figure::new(
        "correction-9",
        "Correction p (9)",
        &[
            SeriesKey::new("gn9", &sensitivity::P_X_DEG_S),
            SeriesKey::new("gn9", &sensitivity::P_Y_DEG_S),
            SeriesKey::new("gn9", &sensitivity::P_Z_DEG_S),
        ],
    ),
    Figure::new(
        "correction-variant",
        "Correction p (variant)",
        &[
            SeriesKey::new("reint", &sensitivity::P_X_DEG_S),
            SeriesKey::new("reint", &sensitivity::P_Y_DEG_S),
            SeriesKey::new("reint", &sensitivity::P_Z_DEG_S),
        ],
    ),
    Figure::new(
        "condition",
        "Condition number of UᵀQU",
        &[
            SeriesKey::new("gn9", &sensitivity::COND_UTQU),
            SeriesKey::new("lm10", &sensitivity::COND_UTQU),
            SeriesKey::new("reint", &sensitivity::COND_UTQU),
        ],
    )
    .log(),
    Figure::new(
        "singular-values",
        "Singular values of UᵀQU (9)",
        &[
            SeriesKey::new("gn9", &sensitivity::SV1),
            SeriesKey::new("gn9", &sensitivity::SV2),
            SeriesKey::new("gn9", &sensitivity::SV3),
        ],
    )
    .log(),
    Figure::new(
        "step-size",
        "Step size s of method (11)",
        &[SeriesKey::new("search11", &sensitivity::STEP_S)],
    ),
    Figure::new(
        "references",
        "References received",
        &[SeriesKey::sensors(&super::sensors::REFERENCE)],
    ),
];

/// The paper's output file: rows of (t, angle₁, angle₂, angle₃) of the chosen method,
/// ending at its first row within tolerance.
pub(super) fn output_file(p: &ParamValues) -> OutputFile {
    let id = METHODS.get(p.index("output_method")).map_or("gn9", |m| m.0);
    OutputFile {
        columns: std::iter::once(TIME.to_string())
            .chain(ANGLES.iter().map(|q| SeriesKey::new(id, q).name()))
            .collect(),
        headers: ["time", "angle1", "angle2", "angle3"]
            .map(String::from)
            .to_vec(),
        stop: Some(SeriesKey::new(id, &sensitivity::WITHIN_TOL).name()),
    }
}

/// The eigenvalues of each method's linearised update for the current Δt and ε.
pub(super) fn diagrams(p: &ParamValues) -> Vec<Diagram> {
    let (dt, eps) = (p.get("interval_s"), p.get("eps"));
    let mut points = Vec::new();
    // Each point takes the colour of the filter whose update it linearises (the
    // re-integrating variant's for (11), Method::Reintegrate).
    // The points are notation only ("(11) λ1"): (11) and the re-integrating variant share
    // one linearised update, drawn in the variant's colour.
    for (name, method, source) in [
        ("(9)", Method::Plain, "gn9"),
        ("(10)", Method::Regularised, "lm10"),
        ("(11)", Method::Reintegrate, "reint"),
    ] {
        for (k, l) in linearised_eigenvalues(method, dt, eps).iter().enumerate() {
            points.push(DiagramPoint {
                label: format!("{name} λ{}", k + 1),
                xy: [l.re, l.im],
                source: Some(source),
            });
        }
    }
    vec![Diagram {
        id: "eigenvalues",
        title: "Eigenvalues of the linearised update",
        detail: vec![("Δt", dt, "s"), ("ε", eps, "")],
        unit_circle: true,
        points,
    }]
}
