//! What paper 5's lab shows: its figures, the eigenvalues of each method's linearised
//! update, and the paper's output file.

use crate::estimators::{Method, linearised_eigenvalues};
use crate::model::{Diagram, DiagramPoint, Figure, OutputFile, ParamValues};

use super::params::METHODS;

pub(super) const FIGURES: &[Figure] = &[
    Figure::new(
        "Attitude error (all methods)",
        &[
            "gn9.err_deg",
            "lm10.err_deg",
            "search11.err_deg",
            "reint.err_deg",
            "raw.err_deg",
        ],
    )
    .log(),
    Figure::new(
        "Angles of method (9) and the reference",
        &[
            "gn9.angle_1_rad",
            "gn9.angle_2_rad",
            "gn9.angle_3_rad",
            "truth.angle_1_rad",
            "truth.angle_2_rad",
            "truth.angle_3_rad",
        ],
    ),
    Figure::new(
        "Correction p (9)",
        &["gn9.p_x_deg_s", "gn9.p_y_deg_s", "gn9.p_z_deg_s"],
    ),
    Figure::new(
        "Correction p (variant)",
        &["reint.p_x_deg_s", "reint.p_y_deg_s", "reint.p_z_deg_s"],
    ),
    Figure::new(
        "Condition number of UᵀQU",
        &["gn9.cond_utqu", "lm10.cond_utqu", "reint.cond_utqu"],
    )
    .log(),
    Figure::new(
        "Singular values of UᵀQU (9)",
        &["gn9.sv1", "gn9.sv2", "gn9.sv3"],
    )
    .log(),
    Figure::new("Step size s of method (11)", &["search11.step_s"]),
    Figure::new("References received", &["sensors.reference"]),
];

/// The paper's output file: rows of (t, angle₁, angle₂, angle₃) of the chosen method,
/// ending at its first row within tolerance.
pub(super) fn output_file(p: &ParamValues) -> OutputFile {
    let id = METHODS.get(p.index("output_method")).map_or("gn9", |m| m.0);
    OutputFile {
        columns: vec![
            "t_s".into(),
            format!("{id}.angle_1_rad"),
            format!("{id}.angle_2_rad"),
            format!("{id}.angle_3_rad"),
        ],
        headers: ["time", "angle1", "angle2", "angle3"]
            .map(String::from)
            .to_vec(),
        stop: Some(format!("{id}.within_tol")),
    }
}

/// The eigenvalues of each method's linearised update for the current Δt and ε.
pub(super) fn diagrams(p: &ParamValues) -> Vec<Diagram> {
    let (dt, eps) = (p.get("interval_s"), p.get("eps"));
    let mut points = Vec::new();
    // Each point takes the colour of the filter whose update it linearises (the
    // re-integrating variant's for "(11) and variant", Method::Reintegrate).
    for (name, method, source) in [
        ("(9)", Method::Plain, "gn9"),
        ("(10)", Method::Regularised, "lm10"),
        ("(11) and variant", Method::Reintegrate, "reint"),
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
        title: format!("Eigenvalues of the linearised update (Δt = {dt} s, ε = {eps})"),
        unit_circle: true,
        points,
    }]
}
