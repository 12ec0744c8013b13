//! Paper 2's plots and presets: Figs. 4–8 and the lab's own views, and the scenarios a
//! student switches to (model error, outages, the constant gain, Fig. 7's bias model).

use super::{mekf, sensors, truth};
use crate::model::{Preset, SeriesKey, q};
use crate::page::Figure;

/// The start of a run the errors' figures leave out of their scale: the filters' first
/// readings (the sensors at 1 Hz) and a few seconds more.
const STEADY_AFTER_S: f64 = 5.0;

pub(super) const FIGURES: &[Figure] = &[
    Figure::new(
        "fig4-attitude",
        "ST+Gyro attitude errors (Fig. 4)",
        &[
            SeriesKey::new("st-gyro", &q::ERR_X_DEG),
            SeriesKey::new("st-gyro", &q::ERR_Y_DEG),
            SeriesKey::new("st-gyro", &q::ERR_Z_DEG),
        ],
    )
    // The filters start 2° off (±6° at 3σ) and settle at the first star-tracker reading: the
    // steady error, the paper's result, had been a flat line at 0.
    .steady_after(STEADY_AFTER_S),
    Figure::new(
        "fig5-rate",
        "ST+Gyro rate errors (Fig. 5)",
        &[
            SeriesKey::new("st-gyro", &q::RATE_ERR_X_DEG_S),
            SeriesKey::new("st-gyro", &q::RATE_ERR_Y_DEG_S),
            SeriesKey::new("st-gyro", &q::RATE_ERR_Z_DEG_S),
        ],
    )
    .steady_after(STEADY_AFTER_S),
    Figure::new(
        "every-filter",
        "Attitude error of every filter",
        &[
            SeriesKey::new("st-gyro-mag-sun", &q::ERR_DEG),
            SeriesKey::new("st-gyro-mag", &q::ERR_DEG),
            SeriesKey::new("st-mag-sun", &q::ERR_DEG),
            SeriesKey::new("st-mag-mbias", &q::ERR_DEG),
            SeriesKey::new("mag-sun-gyro", &q::ERR_DEG),
            SeriesKey::new("mag-sun-gyro-gbias", &q::ERR_DEG),
            SeriesKey::new("mag-sun-gyro-mbias", &q::ERR_DEG),
            SeriesKey::new("st-gyro", &q::ERR_DEG),
            SeriesKey::new("st-gyro-gbias", &q::ERR_DEG),
            SeriesKey::new("mag-sun", &q::ERR_DEG),
            SeriesKey::new("mag-gyro", &q::ERR_DEG),
            SeriesKey::new("st", &q::ERR_DEG),
            SeriesKey::new("st-gyro-reduced", &q::ERR_DEG),
            SeriesKey::new("mag-sun-dist", &q::ERR_DEG),
            SeriesKey::new("st-dist", &q::ERR_DEG),
            SeriesKey::new("st-gyro-const", &q::ERR_DEG),
        ],
    )
    .log(),
    Figure::new(
        "fig6-gyro-bias",
        "Gyro bias: truth and estimates (Fig. 6)",
        &[
            SeriesKey::sensors(&sensors::GYRO_BIAS[0]),
            SeriesKey::sensors(&sensors::GYRO_BIAS[1]),
            SeriesKey::new("st-gyro-gbias", &mekf::GBIAS_X_DEG_S),
            SeriesKey::new("st-gyro-gbias", &mekf::GBIAS_Y_DEG_S),
            SeriesKey::new("st-gyro-reduced", &mekf::GBIAS_X_DEG_S),
            SeriesKey::new("st-gyro-reduced", &mekf::GBIAS_Y_DEG_S),
        ],
    ),
    Figure::new(
        "fig7-mag-bias",
        "Magnetometer bias: truth and estimate (Fig. 7)",
        &[
            SeriesKey::sensors(&sensors::MAG_BIAS[0]),
            SeriesKey::sensors(&sensors::MAG_BIAS[2]),
            SeriesKey::new("mag-sun-gyro-mbias", &mekf::MBIAS_X_NT),
            SeriesKey::new("mag-sun-gyro-mbias", &mekf::MBIAS_Z_NT),
        ],
    ),
    Figure::new(
        "fig8-disturbance",
        "Disturbance estimates against the truth (Fig. 8, Table 4)",
        &[
            SeriesKey::truth(&truth::DIST_TRUE[0]),
            SeriesKey::new("st-dist", &mekf::D_X_S2),
            SeriesKey::new("st-gyro-gbias-dist", &mekf::D_X_S2),
            SeriesKey::new("mag-sun-dist", &mekf::D_X_S2),
            SeriesKey::new("mag-sun-gyro-gbias-dist", &mekf::D_X_S2),
        ],
    ),
    Figure::new(
        "nees",
        "Consistency: NEES of the attitude (χ²₃: 95 % in 0.22…9.35)",
        &[
            SeriesKey::nees_att("st-gyro"),
            SeriesKey::nees_att("mag-sun-gyro"),
            SeriesKey::nees_att("mag-sun"),
            SeriesKey::nees_att("mag-gyro"),
            SeriesKey::nees_att("st"),
        ],
    )
    .log(),
    Figure::new(
        "p-diagonal",
        "P diagonal, ST+Gyro and Mag+Sun+Gyro (log; attitude rad², rate rad²/s²)",
        &[
            SeriesKey::variance("st-gyro", &mekf::ATT_X),
            SeriesKey::variance("st-gyro", &mekf::ATT_Y),
            SeriesKey::variance("st-gyro", &mekf::ATT_Z),
            SeriesKey::variance("st-gyro", &mekf::RATE_X),
            SeriesKey::variance("st-gyro", &mekf::RATE_Y),
            SeriesKey::variance("st-gyro", &mekf::RATE_Z),
            SeriesKey::variance("mag-sun-gyro", &mekf::ATT_X),
            SeriesKey::variance("mag-sun-gyro", &mekf::ATT_Y),
            SeriesKey::variance("mag-sun-gyro", &mekf::ATT_Z),
        ],
    )
    .log(),
    Figure::new(
        "nis",
        "NIS per update",
        &[
            SeriesKey::new("st-gyro", &mekf::NIS),
            SeriesKey::new("mag-sun-gyro", &mekf::NIS),
            SeriesKey::new("mag-sun", &mekf::NIS),
            SeriesKey::new("mag-gyro", &mekf::NIS),
        ],
    )
    .log(),
    Figure::new(
        "outages",
        "Outages: eclipse, sun seen, star tracker",
        &[
            SeriesKey::sensors(&sensors::ECLIPSE),
            SeriesKey::sensors(&sensors::SUN_SEEN),
            SeriesKey::sensors(&sensors::STAR_AVAILABLE),
        ],
    ),
    Figure::new(
        "wheel-momentum",
        "Wheel momentum",
        &[
            SeriesKey::truth(&truth::WHEEL_H[0]),
            SeriesKey::truth(&truth::WHEEL_H[1]),
            SeriesKey::truth(&truth::WHEEL_H[2]),
        ],
    ),
    Figure::new(
        "constant-gain",
        "Constant gain against its EKF (§3.3, Table 5)",
        &[
            SeriesKey::new("mag-sun-gyro", &q::ERR_DEG),
            SeriesKey::new("mag-sun-gyro-const", &q::ERR_DEG),
            SeriesKey::new("st-gyro", &q::ERR_DEG),
            SeriesKey::new("st-gyro-const", &q::ERR_DEG),
        ],
    )
    .log(),
    Figure::new(
        "fig7-field-turn",
        "Magnetometer bias as a turn of the field: truth and estimate (Fig. 7)",
        &[
            SeriesKey::sensors(&sensors::MAG_TURN[0]),
            SeriesKey::sensors(&sensors::MAG_TURN[1]),
            SeriesKey::sensors(&sensors::MAG_TURN[2]),
            SeriesKey::new("mag-sun-gyro-mturn", &mekf::MTURN_X_DEG),
            SeriesKey::new("mag-sun-gyro-mturn", &mekf::MTURN_Y_DEG),
            SeriesKey::new("mag-sun-gyro-mturn", &mekf::MTURN_Z_DEG),
        ],
    ),
];

pub(super) const PRESETS: &[Preset] = &[
    Preset {
        id: "no-model-error",
        name: "no model error",
        help: "The onboard field model equals the truth",
        values: &[("onboard_field", 0.0)],
    },
    Preset {
        id: "model-error-400",
        name: "model error 400 nT",
        help: "The paper's 'errors up to 400 nT' of the onboard field model",
        values: &[("onboard_field", 2.0), ("model_error_nt", 400.0)],
    },
    Preset {
        id: "star-tracker-blinded",
        name: "star tracker blinded",
        help: "A 90° sun exclusion: the star tracker is out whenever the sun is above the horizon of its boresight",
        values: &[("star_sun_exclusion_deg", 90.0)],
    },
    Preset {
        id: "noon-midnight",
        name: "noon–midnight orbit (long eclipse)",
        help: "Ascending node at 12 h: the longest eclipse, the sun sensors dark for a third of the orbit (Reset)",
        values: &[("ltan_h", 12.0)],
    },
    Preset {
        id: "dawn-dusk",
        name: "dawn–dusk orbit (no eclipse)",
        help: "Ascending node at 18 h: the sun is always seen (Reset)",
        values: &[("ltan_h", 18.0)],
    },
    Preset {
        id: "sun-along-field",
        name: "sun ∥ field",
        help: "The sun half a degree from the field direction: the vector filters without a star tracker lose the rotation about it and say so",
        values: &[("sun_along_field", 1.0), ("sun_field_angle_deg", 0.5)],
    },
    Preset {
        id: "gyro-one-vector",
        name: "gyro + one vector (drift)",
        help: "A gyro bias of 0.02 °/s; Mag+Gyro sees the field only, and with the sun heads narrowed to ±10° Mag+Sun+Gyro mostly does too — pick one as the ghost: the unobservable axis is drawn on the body, the drift about it shows on the error plots",
        values: &[("gyro_bias_deg_s", 0.02), ("sun_fov_deg", 10.0)],
    },
    Preset {
        id: "sensors-10hz",
        name: "sensors at 10 Hz",
        help: "Every sensor at the prediction rate: errors shrink roughly with √rate",
        values: &[
            ("vector_rate_hz", 10.0),
            ("gyro_rate_hz", 10.0),
            ("star_rate_hz", 10.0),
        ],
    },
    Preset {
        id: "constant-gain",
        name: "constant gain (§3.3)",
        help: "The gains freeze at 60 s. The field and the sun then turn in the body frame along the orbit: within minutes the frozen Mag+Sun+Gyro gain loses the attitude while its EKF keeps tracking, and a star-tracker set's frozen gain stays its EKF's (see the constant-gain plot)",
        values: &[("freeze_after_s", 60.0)],
    },
    Preset {
        id: "fig7-field-turn",
        name: "Fig. 7: bias as a turn of the field",
        help: "The magnetometer reads the field turned by 2° (the paper's bias model, its size ours): the filter 7′ estimates the turn in degrees; the component along the field settles only as the field turns along the orbit",
        values: &[("mag_turn_deg", 2.0)],
    },
];
