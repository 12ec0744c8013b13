//! Eq. 4: the controller cannot know the rig's arms, motors and inertia exactly, so the
//! constant command u₀ that holds it level is only known to lie in an interval,
//! u₀ ∈ [f(ω_max, l_min, J_max), f(ω_min, l_max, J_min)]. Here each arm, each motor's thrust
//! (the lever's weight torque) and the inertia are known to ±u; u₀ is multilinear in the
//! arms and thrusts and monotone in 1/J, so its extremes lie at the corners of that box,
//! which are all evaluated.

use super::plant::{Plant, Scales};
use crate::model::{ParamValues, fmt_sig};
use crate::page::ParamNote;

/// The parameter: how well the geometry is known (± %).
pub(super) const UNCERTAINTY_PCT: &str = "geometry_uncertainty_pct";

/// (lowest, highest) u₀ (rad/s²) over the corners of the uncertainty box ±`uncertainty`
/// (a fraction) around `plant`'s geometry.
pub fn u0_interval(plant: &Plant, uncertainty: f64) -> (f64, f64) {
    // The lever has one thrust (its weight torque) and the inertia; a quadrotor four arms,
    // four thrusts and the inertia.
    let factors = if plant.is_lever() { 2 } else { 9 };
    let mut range = (f64::INFINITY, f64::NEG_INFINITY);
    for corner in 0..1u32 << factors {
        let at = |bit: usize| {
            if corner >> bit & 1 == 1 {
                1.0 + uncertainty
            } else {
                1.0 - uncertainty
            }
        };
        let scales = if plant.is_lever() {
            Scales {
                thrusts: [at(0), 1.0, 1.0, 1.0],
                inertia: at(1),
                ..Scales::NOMINAL
            }
        } else {
            Scales {
                arms: [at(0), at(1), at(2), at(3)],
                thrusts: [at(4), at(5), at(6), at(7)],
                inertia: at(8),
            }
        };
        let u0 = plant.level_u0_scaled(&scales);
        range = (range.0.min(u0), range.1.max(u0));
    }
    range
}

/// The note under the uncertainty slider: eq. 4's interval and the u₀ this rig needs.
pub(super) fn note(p: &ParamValues) -> ParamNote {
    let plant = Plant::new(p);
    let (lo, hi) = u0_interval(&plant, p.get(UNCERTAINTY_PCT) / 100.0);
    ParamNote::info(
        UNCERTAINTY_PCT,
        "note-u0-range",
        vec![
            ("lo", fmt_sig(lo)),
            ("hi", fmt_sig(hi)),
            ("needed", fmt_sig(plant.hover_u0())),
        ],
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::ParamSpec;

    fn plant(assignments: &[(&str, f64)]) -> Plant {
        let specs: &[ParamSpec] = super::super::PARAMS;
        let mut p = ParamValues::defaults(specs);
        for (k, v) in assignments {
            p.set(specs, k, *v).unwrap();
        }
        Plant::new(&p)
    }

    #[test]
    fn the_lever_s_interval_is_the_closed_form() {
        // u₀ = M_g / J with both known to ±10 %: [0.9/1.1, 1.1/0.9] · M_g/J.
        let lever = plant(&[("rig", 0.0), ("lever_torque_n_m", 0.05)]);
        let (lo, hi) = u0_interval(&lever, 0.1);
        let nominal = 0.05 / 2e-3;
        assert!((lo - nominal * 0.9 / 1.1).abs() < 1e-9, "{lo}");
        assert!((hi - nominal * 1.1 / 0.9).abs() < 1e-9, "{hi}");
        assert!((lever.hover_u0() - nominal).abs() < 1e-9);
    }

    #[test]
    fn the_needed_u0_lies_inside_and_the_interval_shrinks_to_it() {
        let quad = plant(&[("rig", 2.0)]);
        let needed = quad.hover_u0();
        assert!(
            needed.abs() > 1.0,
            "the asymmetric rig needs u₀ ≠ 0: {needed}"
        );
        let (lo, hi) = u0_interval(&quad, 0.05);
        assert!(lo < needed && needed < hi, "{lo} {needed} {hi}");
        let (lo0, hi0) = u0_interval(&quad, 0.0);
        assert!((lo0 - needed).abs() < 1e-9 && (hi0 - needed).abs() < 1e-9);
        // The symmetric rig needs 0, and uncertainty spreads u₀ both ways.
        let (lo, hi) = u0_interval(&plant(&[("rig", 1.0)]), 0.05);
        assert!(lo < 0.0 && hi > 0.0 && (lo + hi).abs() < 1e-9, "{lo} {hi}");
    }
}
