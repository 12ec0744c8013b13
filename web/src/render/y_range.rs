//! The range of a plot's value axis where egui_plot's own fit to all the data misleads: a
//! run whose values are all the same to rounding, and a figure whose run starts with a
//! transient (a filter that starts degrees off and settles at its first measurement), which
//! fits its value axis to what comes after it, where the paper's result is: fitted to the
//! whole run, paper 2's steady error and its ±3σ band had been a flat line at 0 under the
//! first second's ±6°. Zooming out (the wheel, a pinch) shows the transient, and a note on
//! the plot says it is there.

use attlab::record::Recorder;
use egui::{Color32, Ui};

/// Points per series read for the range (the plot's own thinning).
const POINTS: usize = 1500;

/// The value range of `shown` series (index into `rec`, colour) after `from_s`, with their
/// ±3σ bands where `bands` draws them (none on a `log` plot), padded a tenth each way; `None`
/// until the run is past `from_s` by as much again (before that, the whole run is the
/// transient) or where nothing finite is drawn after it.
pub fn steady(
    rec: &Recorder,
    shown: &[(usize, Color32)],
    log: bool,
    from_s: f64,
    bands: bool,
) -> Option<(f64, f64)> {
    let mut lo = f64::INFINITY;
    let mut hi = f64::NEG_INFINITY;
    let mut last_t = f64::NEG_INFINITY;
    let mut take = |t: f64, y: f64| {
        last_t = last_t.max(t);
        let y = if log { y.log10() } else { y };
        if t >= from_s && y.is_finite() {
            lo = lo.min(y);
            hi = hi.max(y);
        }
    };
    for (i, _) in shown {
        for p in rec.plot_points(*i, POINTS) {
            take(p[0], p[1]);
        }
        let band = rec.specs()[*i].band.as_ref().filter(|_| bands && !log);
        if let Some((var, scale)) = band.and_then(|(name, s)| rec.index_of(name).map(|v| (v, *s))) {
            for p in rec.plot_points(var, POINTS) {
                let sigma3 = 3.0 * p[1].max(0.0).sqrt() * scale;
                take(p[0], sigma3);
                take(p[0], -sigma3);
            }
        }
    }
    if std::env::var("NOSTEADY").is_ok() || last_t < 2.0 * from_s || lo > hi {
        return None;
    }
    let pad = 0.1 * (hi - lo).max(f64::EPSILON * hi.abs().max(1.0));
    Some((lo - pad, hi + pad))
}

/// A y range to show when every value drawn is the same to rounding (a lesson step paused
/// at t = 0; log10 of two equal errors): egui_plot fits the data's own range, 10⁻¹⁶ wide,
/// and its marks read "0.301029995663981". The value ± a tenth of it, at least ± 1, as
/// egui_plot does for an exactly flat line. `None` when the values spread (or there are
/// none).
pub fn flat(points: &[Vec<[f64; 2]>], log: bool) -> Option<(f64, f64)> {
    let shown = |y: f64| -> f64 { if log { y.log10() } else { y } };
    let (lo, hi) = points
        .iter()
        .flatten()
        .map(|p| shown(p[1]))
        .filter(|y| y.is_finite())
        .fold(
            (f64::INFINITY, f64::NEG_INFINITY),
            |(lo, hi): (f64, f64), y| (lo.min(y), hi.max(y)),
        );
    let scale = lo.abs().max(hi.abs()).max(1.0);
    if lo > hi || hi - lo > 1e-9 * scale {
        return None;
    }
    let centre = 0.5 * (lo + hi);
    let pad = (0.1 * centre.abs()).max(1.0);
    Some((centre - pad, centre + pad))
}

/// The note in the plot's top-left corner that the first seconds are off its scale.
pub fn note(ui: &Ui, plot: egui::Rect, text: &str) {
    let colour = ui.visuals().weak_text_color();
    let font = egui::TextStyle::Small.resolve(ui.style());
    ui.painter().text(
        plot.left_top() + egui::vec2(6.0, 4.0),
        egui::Align2::LEFT_TOP,
        text,
        font,
        colour,
    );
}

#[cfg(test)]
mod tests {
    use super::*;
    use attlab::model::{SeriesGroup, SeriesSpec};

    /// An error that starts at 6° and settles to ±0.01° after 1 s, with a variance whose
    /// 3σ is 6° at first and 0.02° after, over 60 s at 10 Hz.
    fn settling() -> Recorder {
        let specs = vec![
            SeriesSpec::new("t_s", "s", SeriesGroup::Time),
            SeriesSpec::new("e", "deg", SeriesGroup::Error).with_band("p".into(), 1.0),
            SeriesSpec::new("p", "deg2", SeriesGroup::Covariance),
        ];
        let mut rec = Recorder::with_window(specs, 1000);
        for k in 0..600 {
            let t = f64::from(k) * 0.1;
            let (e, var) = if t < 1.0 {
                (6.0, 4.0)
            } else {
                (0.01 * (t * 7.0).sin(), 4.4e-5)
            };
            rec.push(&[t, e, var]);
        }
        rec
    }

    #[test]
    fn a_settled_figure_is_scaled_to_its_steady_part_with_its_band() {
        let rec = settling();
        let shown = [(1, Color32::RED)];
        let (lo, hi) = steady(&rec, &shown, false, 5.0, true).expect("past 10 s");
        // The band (±3·√4.4e-5 ≈ ±0.0199°) sets the range, padded by a tenth; the 6° at the
        // start is off it.
        assert!(
            hi > 0.0199 && hi < 0.025 && lo < -0.0199 && lo > -0.025,
            "{lo} {hi}"
        );
        let (lo, hi) = steady(&rec, &shown, false, 5.0, false).expect("past 10 s");
        assert!(
            hi < 0.0125 && lo > -0.0125 && hi > 0.0099,
            "without the band: {lo} {hi}"
        );
        // Before the run is past twice the transient, the whole run shows.
        assert_eq!(steady(&rec, &shown, false, 40.0, true), None);
    }

    #[test]
    fn a_flat_run_gets_a_readable_range_and_a_spread_one_none() {
        let two = |a: f64, b: f64| vec![vec![[0.0, a]], vec![[0.0, b]]];
        // log10 of two equal errors of 2°, the second one ulp off.
        let (lo, hi) = flat(&two(2.0, 2.0 + 4e-16), true).expect("flat");
        assert!(
            (lo + 0.69897).abs() < 1e-4 && (hi - 1.30103).abs() < 1e-4,
            "{lo} {hi}"
        );
        assert_eq!(flat(&two(360.0, 360.0), false), Some((324.0, 396.0)));
        assert_eq!(flat(&two(0.0, 0.0), false), Some((-1.0, 1.0)));
        assert_eq!(flat(&two(0.0, 1e-6), false), None);
        assert_eq!(flat(&two(2.0, 2.1), true), None);
        assert_eq!(flat(&[], false), None);
        assert_eq!(flat(&two(f64::NAN, f64::NAN), false), None);
        // A log plot draws no value ≤ 0 and ignores it here too.
        assert_eq!(flat(&two(0.0, 0.0), true), None);
    }
}
