//! A plot's marks on both axes: round steps (1, 2 or 5 × 10ⁿ) that give every axis at
//! least three labelled marks, and labels with the decimals their step needs. (egui_plot's
//! own marks are powers of ten: a run of 600 s had one labelled mark on its time axis, "0".)

/// The time (x) axis' marks: labelled ones at least 80 points apart, where egui_plot draws
/// an x label at full strength (it fades them from 80 down to 60 and hides closer ones).
pub fn x_marks(input: egui_plot::GridInput) -> Vec<egui_plot::GridMark> {
    marks(input, 80.0)
}

/// The value (y) axis' marks: labelled ones at least 30 points apart (egui_plot's full
/// strength for a y label).
pub fn y_marks(input: egui_plot::GridInput) -> Vec<egui_plot::GridMark> {
    marks(input, 30.0)
}

/// Grid marks at 1, 2 or 5 × 10ⁿ, the step chosen so the axis carries 4 to 10 labelled
/// marks whatever its length, but none closer than `min_points` (so on a phone's narrow
/// plot its labels stay drawn), with a finer grid of a fifth of it between them (one mark
/// per value: egui_plot labels a fine mark too where there is room, and a fine mark on a
/// coarse one would draw a second label, "1.0" over "1").
fn marks(input: egui_plot::GridInput, min_points: f64) -> Vec<egui_plot::GridMark> {
    let (lo, hi) = input.bounds;
    let span = hi - lo;
    if !(span.is_finite() && span > 0.0) {
        return Vec::new();
    }
    // The largest round step that still gives three labelled marks. (Each loop is bounded:
    // near the smallest floats a round step can stay where it is.)
    let mut step = nice_step(span / 5.0);
    for _ in 0..MAX_TRIES {
        if ((hi / step).floor() - (lo / step).ceil()) >= 2.0 {
            break;
        }
        step = nice_step(step * 0.99 / 2.5);
    }
    // egui_plot's base step is the value of its least grid spacing, 8 points.
    let per_point = input.base_step_size / 8.0;
    if per_point.is_finite() && per_point > 0.0 {
        for _ in 0..MAX_TRIES {
            if step / per_point >= min_points {
                break;
            }
            step = nice_step(step * 1.01);
        }
    }
    if !(step.is_normal() && step.is_finite()) {
        return Vec::new();
    }
    let mut out = Vec::new();
    let mut coarse = false;
    for (size, limit, fine) in [(step, 12.0, false), (step / 5.0, 60.0, true)] {
        if span / size > limit {
            continue;
        }
        let first = (lo / size).ceil() as i64;
        let last = (hi / size).floor() as i64;
        let on_coarse = |k: &i64| fine && coarse && k % 5 == 0;
        out.extend(
            (first..=last)
                .filter(|k| !on_coarse(k))
                .map(|k| egui_plot::GridMark {
                    value: k as f64 * size,
                    step_size: size,
                }),
        );
        coarse |= !fine;
    }
    out
}

/// The most round steps a search for one tries: 1, 2, 5 per decade over 40 decades.
const MAX_TRIES: usize = 120;

/// A mark's label with as many decimals as its step needs, so neighbours differ: 359.95
/// beside 360.00 (egui_plot's own rounds a step of 0.05 to one decimal, and both read
/// "360.0"), and never "-0".
pub fn tick_label(mark: egui_plot::GridMark, _range: &std::ops::RangeInclusive<f64>) -> String {
    // A step of m × 10ᵉ (m = 1, 2 or 5) needs −e decimals.
    let decimals = (-(mark.step_size.log10() + 1e-9).floor()).clamp(0.0, 15.0) as usize;
    let text = format!("{:.*}", decimals, mark.value);
    match text.strip_prefix('-') {
        Some(rest) if rest.chars().all(|c| c == '0' || c == '.') => rest.to_string(),
        _ => text,
    }
}

/// `plot` writing its tick labels ([`tick_label`]) as the reader's language does ("0,5" in
/// Russian). (egui_plot shows no coordinates under the pointer unless given a label
/// formatter; the page gives none, so that is all it writes.)
pub fn in_language(plot: egui_plot::Plot<'_>, lang: attlab::i18n::Lang) -> egui_plot::Plot<'_> {
    use attlab::i18n::number;
    plot.x_axis_formatter(move |m, r| number(lang, &tick_label(m, r)))
        .y_axis_formatter(move |m, r| number(lang, &tick_label(m, r)))
}

/// The least of 1, 2, 5 × 10ⁿ at least `raw`.
fn nice_step(raw: f64) -> f64 {
    let decade = 10f64.powf(raw.log10().floor());
    [1.0, 2.0, 5.0, 10.0]
        .into_iter()
        .map(|m| m * decade)
        .find(|s| *s >= raw * (1.0 - 1e-9))
        .unwrap_or(10.0 * decade)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn labelled(lo: f64, hi: f64) -> Vec<f64> {
        let marks = y_marks(egui_plot::GridInput {
            bounds: (lo, hi),
            base_step_size: (hi - lo) / 1000.0,
        });
        let biggest = marks.iter().map(|m| m.step_size).fold(0.0, f64::max);
        marks
            .iter()
            .filter(|m| m.step_size == biggest)
            .map(|m| m.value)
            .collect()
    }

    #[test]
    fn every_axis_gets_at_least_three_labelled_ticks_on_round_numbers() {
        for (lo, hi) in [
            (-7.0, 7.0),
            (0.0, 0.3),
            (-2e-4, 9e-4),
            (1.6, 1.72),
            (3.0, 3e4),
        ] {
            let marks = labelled(lo, hi);
            assert!((3..=12).contains(&marks.len()), "{lo}..{hi}: {marks:?}");
            let step = marks[1] - marks[0];
            let mantissa = step / 10f64.powf(step.log10().floor());
            assert!(
                [1.0, 2.0, 5.0].iter().any(|m| (mantissa - m).abs() < 1e-6),
                "{lo}..{hi}: step {step}"
            );
        }
        // −7 … 7 (the one lone "0"): −6 … 6 in steps of 2 or 5.
        assert!(labelled(-7.0, 7.0).contains(&0.0));
        assert!(labelled(f64::NAN, 1.0).is_empty());
    }

    #[test]
    fn neighbouring_tick_labels_differ_and_zero_has_no_sign() {
        // Paper 1's angle near 360° on a projector: marks 0.05 apart.
        for (lo, hi) in [
            (359.87, 360.01),
            (-0.37, 0.42),
            (1.6, 1.72),
            (-2e-4, 9e-4),
            (-1.3, 2.9),
            (3.0, 3e4),
            (-3e-7, 4e-7),
            (-2e6, 7e6),
            (0.0, 10.0),
        ] {
            let marks = y_marks(egui_plot::GridInput {
                bounds: (lo, hi),
                base_step_size: (hi - lo) / 1000.0,
            });
            let texts: Vec<String> = marks.iter().map(|m| tick_label(*m, &(lo..=hi))).collect();
            for (m, t) in marks.iter().zip(&texts) {
                let back: f64 = t.parse().expect("a number");
                assert!(
                    (back - m.value).abs() < m.step_size * 1e-6,
                    "{lo}..{hi}: {t}"
                );
                assert!(!t.starts_with("-0") || back != 0.0, "{lo}..{hi}: {t}");
            }
            // One mark per value, so no label is drawn twice in two forms.
            for (i, a) in marks.iter().enumerate() {
                let twice = marks[i + 1..]
                    .iter()
                    .any(|b| (a.value - b.value).abs() < 1e-9 * a.step_size.max(b.step_size));
                assert!(!twice, "{lo}..{hi}: {} twice in {marks:?}", a.value);
            }
        }
        let mark = |value, step_size| egui_plot::GridMark { value, step_size };
        assert_eq!(tick_label(mark(359.95, 0.05), &(0.0..=1.0)), "359.95");
        assert_eq!(tick_label(mark(-1e-17, 0.1), &(0.0..=1.0)), "0.0");
        assert_eq!(tick_label(mark(2500.0, 500.0), &(0.0..=1.0)), "2500");
    }

    /// On a phone's plot about 300 points wide, a run of 250 s had marks every 50 s, 60
    /// points apart, where egui_plot draws no x label: the time axis' marks stand at least
    /// 80 points apart, and a value axis' 30, and at least two are labelled.
    #[test]
    fn labelled_marks_stand_as_far_apart_as_egui_plot_draws_their_labels() {
        for (lo, hi, points) in [(0.0, 250.0, 300.0), (0.0, 1.0, 320.0), (-3.0, 600.0, 150.0)] {
            let base_step_size = (hi - lo) / points * 8.0;
            let input = || egui_plot::GridInput {
                bounds: (lo, hi),
                base_step_size,
            };
            for (marks, least) in [(x_marks(input()), 80.0), (y_marks(input()), 30.0)] {
                let biggest = marks.iter().map(|m| m.step_size).fold(0.0, f64::max);
                let labelled = marks.iter().filter(|m| m.step_size == biggest).count();
                let apart = biggest / (hi - lo) * points;
                assert!(
                    apart >= least,
                    "{lo}..{hi} on {points} pt: {apart} pt apart"
                );
                assert!(labelled >= 2, "{lo}..{hi} on {points} pt: {marks:?}");
            }
        }
    }

    /// Zoomed in towards 0 until the span is a denormal float: the search for a step
    /// ends (it had stayed on one denormal step for ever), with no marks or some.
    #[test]
    fn a_span_of_the_smallest_floats_ends_the_search() {
        for (lo, hi) in [(0.0, 5e-324), (0.0, 1e-320), (1e-310, 1.0000001e-310)] {
            let marks = x_marks(egui_plot::GridInput {
                bounds: (lo, hi),
                base_step_size: (hi - lo) / 300.0 * 8.0,
            });
            assert!(marks.len() <= 200, "{lo}..{hi}: {} marks", marks.len());
        }
    }
}
