//! The live description of the run for a screen reader (a polite live region, see `a11y`):
//! the lab, the time, whether it runs, and the ghost's estimator against the truth with its
//! own 3σ ("ST+Gyro [λ,ω]: attitude error 0.00081°, within its 3σ band of 0.0021°").
//! While the run goes on it is refreshed every ten seconds; a pause, a lab or an estimator
//! change refreshes it at once.

use super::{arg, num_arg, tr_with};
use crate::state::AppState;
use attlab::i18n;
use std::time::Duration;
use web_time::Instant;

/// How often a running description is refreshed (a screen reader reads each one).
pub const EVERY: Duration = Duration::from_secs(10);

/// The description of the run now, in the reader's language.
pub fn describe(app: &AppState) -> String {
    let sim = app.shown();
    let lab = sim.lab();
    let lang = app.view().lang();
    let title = i18n::lab_text(lang, &i18n::lab_title_id(lab.id()), lab.title());
    let state = if app.run().playing {
        tr_with(
            app,
            "live-running",
            &[("speed", num_arg(app, app.run().speed))],
        )
    } else {
        tr_with(app, "live-paused", &[])
    };
    let mut text = tr_with(
        app,
        "live-run",
        &[
            ("lab", arg(title)),
            ("t", num_arg(app, format!("{:.1}", sim.t_s()))),
            ("state", arg(state)),
        ],
    );
    let i = app
        .view()
        .ghost_index
        .min(sim.estimators().len().saturating_sub(1));
    if let Some(g) = sim.glance(i) {
        let name = super::estimator_name(app, i);
        let (error, band) = (significant(g.error_deg), significant(g.three_sigma_deg));
        let args = [
            ("name", arg(name)),
            ("error", num_arg(app, error)),
            ("band", num_arg(app, band)),
        ];
        let id = match g.within() {
            Some(true) => "live-within",
            Some(false) => "live-outside",
            None if g.error_deg.is_finite() => "live-error",
            None => "live-no-truth",
        };
        text.push(' ');
        text.push_str(&tr_with(app, id, &args));
    }
    text
}

/// `x` to two significant digits, in plain decimals a student reads aloud (no exponent
/// between 10⁻⁶ and 10⁶).
pub fn significant(x: f64) -> String {
    if !x.is_finite() {
        return "—".into();
    }
    if x == 0.0 {
        return "0".into();
    }
    let magnitude = x.abs().log10().floor() as i32;
    if !(-6..6).contains(&magnitude) {
        return format!("{x:.1e}");
    }
    let decimals = (1 - magnitude).max(0) as usize;
    format!("{x:.decimals$}")
}

/// When to hand the screen reader a new description.
#[derive(Debug, Default)]
pub struct Narration {
    last: String,
    at: Option<Instant>,
    key: Option<(bool, &'static str, usize)>,
}

impl Narration {
    /// The description to publish now, if one is due: the first, one after a pause, a lab or
    /// an estimator change, or a changed one ten seconds after the last.
    pub fn due(&mut self, app: &AppState, now: Instant) -> Option<String> {
        let key = (
            app.run().playing,
            app.sim().lab().id(),
            app.view().ghost_index,
        );
        let changed = self.key != Some(key);
        let stale = self.at.is_none_or(|at| now.duration_since(at) >= EVERY);
        if !changed && !stale {
            return None;
        }
        let text = describe(app);
        if text == self.last {
            return None;
        }
        self.key = Some(key);
        self.at = Some(now);
        self.last = text.clone();
        Some(text)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_significant_digits_in_plain_decimals() {
        assert_eq!(significant(0.000_812_3), "0.00081");
        assert_eq!(significant(12.34), "12");
        assert_eq!(significant(1.26), "1.3");
        assert_eq!(significant(0.0), "0");
        assert_eq!(significant(f64::NAN), "—");
        assert_eq!(significant(3.2e-9), "3.2e-9");
    }
}
