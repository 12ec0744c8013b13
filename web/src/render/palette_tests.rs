//! The palettes checked against simulated colour vision (Machado, Oliveira and Fernandes
//! 2009, severity 1) in CIELAB, and against their backgrounds by WCAG contrast.

use super::*;

/// Machado et al.'s matrices, applied to linear RGB.
const PROTANOPIA: [[f64; 3]; 3] = [
    [0.152286, 1.052583, -0.204868],
    [0.114503, 0.786281, 0.099216],
    [-0.003882, -0.048116, 1.051998],
];
const DEUTERANOPIA: [[f64; 3]; 3] = [
    [0.367322, 0.860646, -0.227968],
    [0.280085, 0.672501, 0.047413],
    [-0.011820, 0.042940, 0.968881],
];
const TRITANOPIA: [[f64; 3]; 3] = [
    [1.255528, -0.076749, -0.178779],
    [-0.078411, 0.930809, 0.147602],
    [0.004733, 0.691367, 0.303900],
];
const IDENTITY: [[f64; 3]; 3] = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];

/// Two lines are told apart by colour alone when they are at least this far apart in
/// CIELAB (ΔE*76) for every kind of colour vision simulated.
const MIN_DELTA_E: f64 = 12.0;

/// WCAG's least contrast for graphics against their background.
const MIN_CONTRAST: f64 = 3.0;

fn linear(c: Color32) -> [f64; 3] {
    let f = |v: u8| {
        let v = f64::from(v) / 255.0;
        if v <= 0.04045 {
            v / 12.92
        } else {
            ((v + 0.055) / 1.055).powf(2.4)
        }
    };
    [f(c.r()), f(c.g()), f(c.b())]
}

fn lab(rgb: [f64; 3]) -> [f64; 3] {
    let [r, g, b] = rgb.map(|v| v.clamp(0.0, 1.0));
    let x = (0.4124 * r + 0.3576 * g + 0.1805 * b) / 0.95047;
    let y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
    let z = (0.0193 * r + 0.1192 * g + 0.9505 * b) / 1.08883;
    let f = |t: f64| {
        if t > 0.008856 {
            t.cbrt()
        } else {
            7.787 * t + 16.0 / 116.0
        }
    };
    let (fx, fy, fz) = (f(x), f(y), f(z));
    [116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)]
}

fn seen(c: Color32, m: &[[f64; 3]; 3]) -> [f64; 3] {
    let l = linear(c);
    let row = |i: usize| m[i][0] * l[0] + m[i][1] * l[1] + m[i][2] * l[2];
    lab([row(0), row(1), row(2)])
}

/// The least ΔE between two colours over normal vision and the three simulated kinds.
fn delta_e(a: Color32, b: Color32) -> f64 {
    [IDENTITY, PROTANOPIA, DEUTERANOPIA, TRITANOPIA]
        .iter()
        .map(|m| {
            let (p, q) = (seen(a, m), seen(b, m));
            ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2) + (p[2] - q[2]).powi(2)).sqrt()
        })
        .fold(f64::INFINITY, f64::min)
}

fn contrast(a: Color32, b: Color32) -> f64 {
    let lum = |c: Color32| {
        let [r, g, b] = linear(c);
        0.2126 * r + 0.7152 * g + 0.0722 * b
    };
    let (x, y) = (lum(a), lum(b));
    (x.max(y) + 0.05) / (x.min(y) + 0.05)
}

/// Paper 2 runs sixteen filters beside the truth.
const SOURCES: usize = 17;

#[test]
fn every_two_sources_differ_in_pattern_or_in_colour_for_every_kind_of_colour_vision() {
    for (name, palette) in [("dark", &DARK), ("light", &LIGHT)] {
        for a in 0..SOURCES {
            for b in a + 1..SOURCES {
                if pattern(a) != pattern(b) {
                    continue;
                }
                let d = delta_e(palette.source(a), palette.source(b));
                assert!(
                    d >= MIN_DELTA_E,
                    "{name}: sources {a} and {b} share a pattern and are ΔE {d:.1} apart"
                );
            }
        }
    }
}

#[test]
fn the_first_seven_estimators_are_apart_by_colour_alone() {
    // The labs other than paper 2 run at most seven filters: colour alone must do there.
    for (name, palette) in [("dark", &DARK), ("light", &LIGHT)] {
        for a in 0..8 {
            for b in a + 1..8 {
                let d = delta_e(palette.source(a), palette.source(b));
                assert!(d >= MIN_DELTA_E, "{name}: {a} and {b} are ΔE {d:.1} apart");
            }
        }
    }
}

#[test]
fn every_colour_stands_out_from_the_views_and_the_plots() {
    for (name, palette) in [("dark", &DARK), ("light", &LIGHT)] {
        for (k, c) in palette.sources.iter().chain(&palette.others).enumerate() {
            for bg in [palette.view_bg, palette.plot_bg] {
                let r = contrast(*c, bg);
                assert!(
                    r >= MIN_CONTRAST,
                    "{name}: colour {k} {c:?} is {r:.2}:1 on {bg:?}"
                );
            }
        }
        for (what, c) in [("ink", palette.ink), ("error", palette.error)] {
            let r = contrast(c, palette.view_bg);
            assert!(r >= 4.5, "{name}: {what} text is {r:.2}:1");
        }
    }
}

/// The focus ring is drawn outside the control, on the panel or on a view: WCAG 2.4.11 asks
/// 3:1 against what is beside it. The panels are egui's own fill of the theme.
#[test]
fn the_focus_ring_stands_out_from_panels_controls_and_views() {
    for (name, palette, visuals) in [
        ("dark", &DARK, egui::Visuals::dark()),
        ("light", &LIGHT, egui::Visuals::light()),
    ] {
        let beside = [
            palette.view_bg,
            palette.plot_bg,
            visuals.panel_fill,
            visuals.window_fill,
            visuals.widgets.active.bg_fill,
            visuals.widgets.inactive.weak_bg_fill,
        ];
        for bg in beside {
            let r = contrast(palette.focus, bg);
            assert!(r >= MIN_CONTRAST, "{name}: the ring is {r:.2}:1 on {bg:?}");
        }
    }
}

#[test]
fn thirty_filters_get_thirty_looks() {
    // Paper 2's thirty: colour, pattern and, from the eighth, a marker.
    let looks: Vec<(Color32, LineStyle, Option<egui_plot::MarkerShape>)> = (0..=30)
        .map(|s| (DARK.source(s), pattern(s), marker(s)))
        .collect();
    for (i, a) in looks.iter().enumerate() {
        for b in &looks[i + 1..] {
            assert_ne!(a, b);
        }
    }
    // The first round of colours keeps its lines bare; the next ones differ by marker.
    assert!((0..=7).all(|s| marker(s).is_none()));
    assert!(marker(8).is_some() && marker(8) != marker(15) && marker(15) != marker(22));
}

#[test]
fn a_marker_where_two_sources_share_a_colour_only() {
    use attlab::model::{SeriesGroup, SeriesKey, SeriesSpec, q};
    let spec = |source: usize| {
        SeriesSpec::of(SeriesKey::new("kf", &q::RATE_X_DEG_S), SeriesGroup::Rate)
            .from_source(source)
    };
    let specs = [spec(1), spec(8), spec(8), spec(8)];
    // Sources 1 and 8 in one plot take the same colour: 8 gets its marker.
    let both = [(0, DARK.source(1)), (1, DARK.source(8))];
    assert_eq!(DARK.source(1), DARK.source(8));
    assert_eq!(markers(&specs, &both), vec![None, marker(8)]);
    // Source 8's x, y and z alone, coloured by position: colour tells them apart.
    let alone = [
        (1, DARK.source(8)),
        (2, DARK.others[0]),
        (3, DARK.others[1]),
    ];
    assert!(markers(&specs, &alone).iter().all(Option::is_none));
}

#[test]
fn the_simulation_is_the_published_one() {
    // Pure red as a protanope sees it (Machado et al.'s matrix, first column): dark olive.
    let l = lab([0.152286, 0.114503, -0.003882]);
    assert_eq!(seen(Color32::from_rgb(255, 0, 0), &PROTANOPIA), l);
    // Black and white: 21:1.
    assert!((contrast(Color32::BLACK, Color32::WHITE) - 21.0).abs() < 1e-9);
    // Red and green, which the palettes avoid, are close for a deuteranope.
    let d = delta_e(
        Color32::from_rgb(200, 60, 50),
        Color32::from_rgb(90, 160, 40),
    );
    assert!(d < MIN_DELTA_E, "{d}");
}

#[test]
fn a_figure_keeps_each_estimators_colour_and_gives_the_rest_others() {
    use attlab::model::{SeriesGroup, SeriesKey, SeriesSpec, q};
    let spec = |key: SeriesKey, source: usize| {
        SeriesSpec::of(key, SeriesGroup::Attitude).from_source(source)
    };
    let specs = [
        spec(SeriesKey::truth(&q::ANGLE_DEG), 0),
        spec(SeriesKey::truth(&q::RATE_DEG_S), 0),
        spec(SeriesKey::sensors(&q::ANGLE_DEG), 0),
        spec(SeriesKey::new("kf", &q::ANGLE_DEG), 1),
        spec(SeriesKey::new("cf", &q::ANGLE_DEG), 2),
    ];
    let refs: Vec<&SeriesSpec> = specs.iter().collect();
    for palette in [&DARK, &LIGHT] {
        let c = figure_colors(palette, &refs);
        assert_eq!(c[0], palette.source(0));
        assert_eq!(c[3], palette.source(1));
        assert_eq!(c[4], palette.source(2));
        for other in &c[1..3] {
            assert!((0..17).all(|s| *other != palette.source(s)), "{other:?}");
        }
        assert_ne!(c[1], c[2]);
    }
    // One filter's three axes: three different colours.
    let axes = [
        spec(SeriesKey::new("st", &q::ERR_X_DEG), 3),
        spec(SeriesKey::new("st", &q::ERR_Y_DEG), 3),
        spec(SeriesKey::new("st", &q::ERR_Z_DEG), 3),
    ];
    let refs: Vec<&SeriesSpec> = axes.iter().collect();
    let c = figure_colors(&DARK, &refs);
    assert!(c[0] != c[1] && c[1] != c[2] && c[0] != c[2], "{c:?}");
    // Free rotation's errors: one filter's x, y, z and whole angle beside another's whole
    // angle: the five in five colours, in both themes.
    let errors = [
        spec(SeriesKey::new("quat-rk4", &q::ERR_X_DEG), 1),
        spec(SeriesKey::new("quat-rk4", &q::ERR_Y_DEG), 1),
        spec(SeriesKey::new("quat-rk4", &q::ERR_Z_DEG), 1),
        spec(SeriesKey::new("uvz-rk4", &q::ERR_DEG), 2),
        spec(SeriesKey::new("quat-rk4", &q::ERR_DEG), 1),
    ];
    let refs: Vec<&SeriesSpec> = errors.iter().collect();
    for palette in [&DARK, &LIGHT] {
        let c = figure_colors(palette, &refs);
        assert_eq!(c[3], palette.source(2), "the other filter keeps its colour");
        for a in 0..c.len() {
            for b in a + 1..c.len() {
                assert_ne!(c[a], c[b], "series {a} and {b}: {c:?}");
            }
        }
    }
}

#[test]
fn one_sources_series_in_one_colour_take_the_patterns_in_turn() {
    use attlab::model::{SeriesGroup, SeriesKey, SeriesSpec, q};
    let spec =
        |key: SeriesKey, source: usize| SeriesSpec::of(key, SeriesGroup::Rate).from_source(source);
    let specs = [
        spec(SeriesKey::truth(&q::RATE_X_DEG_S), 0),
        spec(SeriesKey::truth(&q::RATE_Y_DEG_S), 0),
        spec(SeriesKey::truth(&q::RATE_Z_DEG_S), 0),
        spec(SeriesKey::new("kf", &q::RATE_X_DEG_S), 1),
    ];
    let white = DARK.source(0);
    let shown = [(0, white), (1, white), (2, white), (3, DARK.source(1))];
    let p = patterns(&specs, &shown);
    assert!(p[0] != p[1] && p[1] != p[2] && p[0] != p[2], "{p:?}");
    assert_eq!(p[3], pattern(1), "a source's only series keeps its pattern");
    // In colours of their own (a figure), the truth's series keep the truth's pattern.
    let coloured = [(0, white), (1, DARK.others[0]), (2, DARK.others[1])];
    assert!(
        patterns(&specs[..3], &coloured)
            .iter()
            .all(|s| *s == pattern(0))
    );
    // A filter's series coloured by position are solid.
    // (Its first colour may be its own source's: paper 2's set 8 takes orange both ways.)
    let by_position = [(3, DARK.source(1)), (3, DARK.source(3))];
    let solid = patterns(&specs, &by_position);
    assert!(solid.iter().all(|s| *s == LineStyle::Solid), "{solid:?}");
}
