//! Paper 2's Table 2 (sensor sets → states) and Table 3 (their tuning and accuracy) as data:
//! every filter of the lab is a row here, not a copy of code.

use crate::estimators::{MekfConfig, SensorSet, StateSet};

pub use super::filter_row::{FilterRow, QSource};

const fn set(star: bool, gyro: bool, mag: bool, sun: bool) -> SensorSet {
    SensorSet {
        star,
        gyro,
        mag,
        sun,
    }
}

const fn cfg(
    id: &'static str,
    label: &'static str,
    sensors: SensorSet,
    states: StateSet,
) -> MekfConfig {
    MekfConfig {
        id,
        label,
        sensors,
        states,
        disturbance: false,
        constant_gain: false,
        inertia_kg_m2: super::INERTIA_KG_M2,
    }
}

const fn row(
    config: MekfConfig,
    q: [f64; 3],
    q_from: QSource,
    att: Option<f64>,
    rate: Option<f64>,
) -> FilterRow {
    FilterRow {
        config,
        q,
        q_from,
        paper_att_deg: att,
        paper_rate_deg_s: rate,
        paper_bias: None,
        starts_as: None,
    }
}

/// Table 2's st, the base of its constant-gain variant.
const ST: FilterRow = row(
    cfg(
        "st",
        "12 ST [λ,ω]",
        set(true, false, false, false),
        StateSet::AttRate,
    ),
    [1e-6, 1.2e-6, 0.0],
    QSource::Table3,
    Some(8e-4),
    Some(6e-4),
);

/// Table 2's st gyro gbias, the base of its constant-gain variant.
const ST_GYRO_GBIAS: FilterRow = row(
    cfg(
        "st-gyro-gbias",
        "9 ST+Gyro [λ,ω,Δω]",
        set(true, true, false, false),
        StateSet::AttRateGyroBias,
    ),
    [1e-6, 1.2e-6, 1e-8],
    QSource::Ours,
    Some(5e-4),
    Some(4e-4),
);

/// Table 2's st gyro reduced, the base of its constant-gain variant.
const ST_GYRO_REDUCED: FilterRow = row(
    cfg(
        "st-gyro-reduced",
        "ST+Gyro reduced [λ,Δω]",
        set(true, true, false, false),
        StateSet::AttGyroBias,
    ),
    [1e-6, 0.0, 1e-8],
    QSource::Ours,
    None,
    None,
);

/// Table 2's mag sun gyro, the base of its constant-gain variant.
const MAG_SUN_GYRO: FilterRow = row(
    cfg(
        "mag-sun-gyro",
        "5 Mag+Sun+Gyro [λ,ω]",
        set(false, true, true, true),
        StateSet::AttRate,
    ),
    [5e-6, 5e-4, 0.0],
    QSource::Table3Uncertain,
    Some(2e-2),
    None,
);

/// Table 2's mag sun gyro mbias, the base of its constant-gain variant (Δb to 400 nT).
const MAG_SUN_GYRO_MBIAS: FilterRow = FilterRow {
    paper_bias: Some(400.0),
    ..row(
        cfg(
            "mag-sun-gyro-mbias",
            "7 Mag+Sun+Gyro [λ,ω,Δb]",
            set(false, true, true, true),
            StateSet::AttRateMagBias,
        ),
        [5e-6, 5e-4, 5e-4],
        QSource::Ours,
        None,
        None,
    )
};

/// Table 2's mag sun, the base of its constant-gain variant.
const MAG_SUN: FilterRow = row(
    cfg(
        "mag-sun",
        "10 Mag+Sun [λ,ω]",
        set(false, false, true, true),
        StateSet::AttRate,
    ),
    [5e-6, 2e-6, 0.0],
    QSource::Ours,
    Some(0.12),
    None,
);

/// Table 2's mag sun gyro gbias, the base of its Table 4 variant.
const MAG_SUN_GYRO_GBIAS: FilterRow = row(
    cfg(
        "mag-sun-gyro-gbias",
        "6 Mag+Sun+Gyro [λ,ω,Δω]",
        set(false, true, true, true),
        StateSet::AttRateGyroBias,
    ),
    [1e-6, 3e-3, 1e-7],
    QSource::Ours,
    Some(2e-2),
    None,
);

/// Filter `base` with the parallel disturbance filter (§3.2), as filter `id`: Table 4's
/// accuracy where it is readable.
const fn with_disturbance(
    base: FilterRow,
    id: &'static str,
    label: &'static str,
    att: Option<f64>,
) -> FilterRow {
    FilterRow {
        config: MekfConfig {
            id,
            label,
            disturbance: true,
            ..base.config
        },
        paper_att_deg: att,
        paper_rate_deg_s: None,
        paper_bias: None,
        starts_as: Some(base.config.id),
        ..base
    }
}

/// Filter `base` with its gain frozen (§3.3), as filter `id`: the same sensors, states and
/// q, Table 5's accuracy where it is readable.
const fn frozen(
    base: FilterRow,
    id: &'static str,
    label: &'static str,
    att: Option<f64>,
    rate: Option<f64>,
) -> FilterRow {
    FilterRow {
        config: MekfConfig {
            id,
            label,
            constant_gain: true,
            ..base.config
        },
        paper_att_deg: att,
        paper_rate_deg_s: rate,
        paper_bias: None,
        starts_as: Some(base.config.id),
        ..base
    }
}

/// Mag+Sun with the parallel disturbance filter (§3.2; Table 4).
const MAG_SUN_DIST: FilterRow = row(
    MekfConfig {
        disturbance: true,
        ..cfg(
            "mag-sun-dist",
            "Mag+Sun [λ,ω] + disturbance filter (§3.2)",
            set(false, false, true, true),
            StateSet::AttRate,
        )
    },
    [5e-6, 2e-6, 0.0],
    QSource::Ours,
    Some(3e-2),
    None,
);

/// ST with the parallel disturbance filter (§3.2; Table 4).
const ST_DIST: FilterRow = row(
    MekfConfig {
        disturbance: true,
        ..cfg(
            "st-dist",
            "ST [λ,ω] + disturbance filter (§3.2)",
            set(true, false, false, false),
            StateSet::AttRate,
        )
    },
    [1e-6, 1.2e-6, 0.0],
    QSource::Ours,
    Some(8e-4),
    Some(1e-4),
);

/// Table 4's ST+Gyro [λ,ω,Δω] with the disturbance filter.
const ST_GYRO_GBIAS_DIST: FilterRow = with_disturbance(
    ST_GYRO_GBIAS,
    "st-gyro-gbias-dist",
    "ST+Gyro [λ,ω,Δω] + disturbance filter (Table 4)",
    Some(8e-4),
);

/// Table 4's Mag+Sun+Gyro [λ,ω,Δω] with the disturbance filter (Δω to 5e-4 °/s).
const MAG_SUN_GYRO_GBIAS_DIST: FilterRow = FilterRow {
    paper_bias: Some(5e-4),
    ..with_disturbance(
        MAG_SUN_GYRO_GBIAS,
        "mag-sun-gyro-gbias-dist",
        "Mag+Sun+Gyro [λ,ω,Δω] + disturbance filter (Table 4)",
        Some(2e-2),
    )
};

/// Table 2's twelve sets (in the paper's order), the reduced variant, the disturbance and
/// constant-gain filters.
pub const FILTERS: &[FilterRow] = &[
    row(
        cfg(
            "st-gyro-mag-sun",
            "1 ST+Gyro+Mag+Sun [λ,ω]",
            set(true, true, true, true),
            StateSet::AttRate,
        ),
        [1e-6, 1.2e-6, 0.0],
        QSource::Table3,
        Some(5e-4),
        Some(4e-4),
    ),
    row(
        cfg(
            "st-gyro-mag",
            "2 ST+Gyro+Mag [λ,ω]",
            set(true, true, true, false),
            StateSet::AttRate,
        ),
        [1e-6, 1.2e-6, 0.0],
        QSource::Table3,
        Some(5e-4),
        Some(4e-4),
    ),
    row(
        cfg(
            "st-mag-sun",
            "3 ST+Mag+Sun [λ,ω]",
            set(true, false, true, true),
            StateSet::AttRate,
        ),
        [1e-6, 1.2e-6, 0.0],
        QSource::Table3,
        Some(7e-4),
        Some(6e-4),
    ),
    FilterRow {
        paper_bias: Some(80.0),
        ..row(
            cfg(
                "st-mag-mbias",
                "4 ST+Mag [λ,ω,Δb]",
                set(true, false, true, false),
                StateSet::AttRateMagBias,
            ),
            [1e-6, 1.2e-6, 1e-4],
            QSource::Table3Uncertain,
            Some(7e-4),
            Some(6e-4),
        )
    },
    MAG_SUN_GYRO,
    MAG_SUN_GYRO_GBIAS,
    MAG_SUN_GYRO_MBIAS,
    row(
        cfg(
            "st-gyro",
            "8 ST+Gyro [λ,ω]",
            set(true, true, false, false),
            StateSet::AttRate,
        ),
        [1e-6, 1.2e-6, 0.0],
        QSource::Table3,
        Some(5e-4),
        Some(4e-4),
    ),
    ST_GYRO_GBIAS,
    MAG_SUN,
    row(
        cfg(
            "mag-gyro",
            "11 Mag+Gyro [λ,ω]",
            set(false, true, true, false),
            StateSet::AttRate,
        ),
        [1e-6, 5e-6, 0.0],
        QSource::Ours,
        None,
        Some(5e-3),
    ),
    ST,
    ST_GYRO_REDUCED,
    MAG_SUN_DIST,
    ST_DIST,
    row(
        MekfConfig {
            constant_gain: true,
            ..cfg(
                "st-gyro-const",
                "ST+Gyro [λ,ω] constant gain (§3.3)",
                set(true, true, false, false),
                StateSet::AttRate,
            )
        },
        [1e-6, 1.2e-6, 0.0],
        QSource::Table3,
        Some(1.5e-3),
        None,
    ),
    // Table 5: the constant-gain variants whose states carry no disturbance.
    frozen(
        ST,
        "st-const",
        "ST [λ,ω] constant gain (Table 5)",
        None,
        Some(4e-4),
    ),
    FilterRow {
        paper_bias: Some(4e-4),
        ..frozen(
            ST_GYRO_GBIAS,
            "st-gyro-gbias-const",
            "ST+Gyro [λ,ω,Δω] constant gain (Table 5)",
            Some(1.5e-3),
            Some(3e-4),
        )
    },
    FilterRow {
        paper_bias: Some(3e-4),
        ..frozen(
            ST_GYRO_REDUCED,
            "st-gyro-reduced-const",
            "ST+Gyro [λ,Δω] constant gain (Table 5)",
            Some(1.5e-3),
            None,
        )
    },
    frozen(
        MAG_SUN_GYRO,
        "mag-sun-gyro-const",
        "Mag+Sun+Gyro [λ,ω] constant gain (Table 5)",
        Some(2e-2),
        Some(2.2e-2),
    ),
    frozen(
        MAG_SUN_GYRO_MBIAS,
        "mag-sun-gyro-mbias-const",
        "Mag+Sun+Gyro [λ,ω,Δb] constant gain (Table 5)",
        Some(2e-2),
        None,
    ),
    frozen(
        MAG_SUN,
        "mag-sun-const",
        "Mag+Sun [λ,ω] constant gain (Table 5)",
        Some(0.1),
        None,
    ),
    // Table 4's two gyro sets with the disturbance filter (the two without a gyro are
    // "mag-sun-dist" and "st-dist" above).
    ST_GYRO_GBIAS_DIST,
    MAG_SUN_GYRO_GBIAS_DIST,
    // Fig. 7's run: set 7 with the magnetometer bias as a small turn of the field (deg),
    // starting as set 7 does. Its q is ours (1e-6 rad per step for the turn).
    FilterRow {
        starts_as: Some("mag-sun-gyro-mbias"),
        ..row(
            cfg(
                "mag-sun-gyro-mturn",
                "7′ Mag+Sun+Gyro [λ,ω,Δb as a turn of the field] (Fig. 7)",
                set(false, true, true, true),
                StateSet::AttRateMagTurn,
            ),
            [5e-6, 5e-4, 1e-6],
            QSource::Ours,
            None,
            None,
        )
    },
    // Table 5's (λ, ω, d) rows: the disturbance filter keeps running behind the frozen gain.
    frozen(
        ST_DIST,
        "st-dist-const",
        "ST [λ,ω,d] constant gain (Table 5)",
        Some(8e-4),
        Some(1e-4),
    ),
    frozen(
        ST_GYRO_GBIAS_DIST,
        "st-gyro-gbias-dist-const",
        "ST+Gyro [λ,ω,Δω,d] constant gain (Table 5)",
        Some(8e-4),
        None,
    ),
    FilterRow {
        paper_bias: Some(5e-4),
        ..frozen(
            MAG_SUN_GYRO_GBIAS_DIST,
            "mag-sun-gyro-gbias-dist-const",
            "Mag+Sun+Gyro [λ,ω,Δω,d] constant gain (Table 5)",
            Some(2e-2),
            None,
        )
    },
    frozen(
        MAG_SUN_DIST,
        "mag-sun-dist-const",
        "Mag+Sun [λ,ω,d] constant gain (Table 5)",
        Some(3e-2),
        None,
    ),
];

/// The row of filter `id`.
pub fn filter(id: &str) -> Option<&'static FilterRow> {
    FILTERS.iter().find(|f| f.config.id == id)
}
