//! The keys of a focused slider, as the WAI-ARIA slider pattern has them: ←/→ (and ↓/↑) move
//! a twentieth of the rail, with Shift a hundredth, PageUp/PageDown a tenth, Home/End go to
//! the ends. egui's own slider moves one point per arrow press, which on a 200-point rail
//! takes a keyboard user two hundred presses to cross; these steps are along the rail as
//! drawn (on a logarithmic slider a step multiplies the value), so every slider crosses in
//! twenty presses.

use attlab::model::{ParamKind, ParamSpec, Scale};
use egui::{Key, Modifiers};

/// A slider's rail: its range and how values are laid along it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rail {
    /// Value at the left end.
    pub min: f64,
    /// Value at the right end.
    pub max: f64,
    /// Logarithmic spacing (a step multiplies the value).
    pub log: bool,
    /// Values are whole numbers.
    pub integer: bool,
}

/// What the keys asked for, along the rail (0 = left end, 1 = right end).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum RailMove {
    /// Move by this fraction of the rail (negative: to the left).
    By(f64),
    /// Go to this place (0 or 1).
    To(f64),
}

/// The smallest positive value of a logarithmic rail that starts at zero (egui's
/// `smallest_positive` of the same sliders): zero sits at the left end, then this value.
pub const LOG_SMALLEST_POSITIVE: f64 = 1e-4;

impl Rail {
    /// The rail of a parameter's slider.
    pub fn of(spec: &ParamSpec) -> Self {
        Self {
            min: spec.min,
            max: spec.max,
            log: spec.scale == Scale::Log,
            integer: spec.kind == ParamKind::Integer,
        }
    }

    /// The place of `value` along the rail, 0..=1.
    pub fn position(&self, value: f64) -> f64 {
        let (lo, hi) = (self.min, self.max);
        if !value.is_finite() || lo.is_nan() || hi.is_nan() || hi <= lo {
            return 0.0;
        }
        let x = if self.log {
            let lo_pos = self.log_start();
            if value <= lo_pos {
                0.0
            } else {
                (value / lo_pos).ln() / (hi / lo_pos).ln()
            }
        } else {
            (value - lo) / (hi - lo)
        };
        x.clamp(0.0, 1.0)
    }

    /// The value at place `x` (0..=1) along the rail.
    pub fn value_at(&self, x: f64) -> f64 {
        let x = x.clamp(0.0, 1.0);
        let (lo, hi) = (self.min, self.max);
        let v = if self.log {
            let lo_pos = self.log_start();
            if x <= 0.0 {
                lo
            } else {
                lo_pos * (hi / lo_pos).powf(x)
            }
        } else {
            lo + x * (hi - lo)
        };
        let v = if self.integer { v.round() } else { v };
        v.clamp(lo.min(hi), hi.max(lo))
    }

    /// The first positive value of a logarithmic rail: its minimum, or for a rail from zero
    /// [`LOG_SMALLEST_POSITIVE`].
    fn log_start(&self) -> f64 {
        if self.min > 0.0 {
            self.min
        } else {
            LOG_SMALLEST_POSITIVE.min(self.max)
        }
    }

    /// `value` moved as `step` asks. A whole-number slider moves at least one unit, so no
    /// press is lost to rounding.
    pub fn moved(&self, value: f64, step: RailMove) -> f64 {
        let to = match step {
            RailMove::To(x) => return self.value_at(x),
            RailMove::By(dx) => self.value_at(self.position(value) + dx),
        };
        if self.integer && to == value && step != RailMove::By(0.0) {
            let unit = if matches!(step, RailMove::By(dx) if dx > 0.0) {
                1.0
            } else {
                -1.0
            };
            return (value + unit).clamp(self.min, self.max);
        }
        to
    }
}

/// Where `value` sits along the rail of `spec`'s slider, 0..=1: the key steps are fractions
/// of it.
pub fn rail_position(spec: &ParamSpec, value: f64) -> f64 {
    Rail::of(spec).position(value)
}

/// Every key pressed this frame, in order, with its modifiers (each press counts: a held
/// key repeats faster than a slow frame draws).
pub fn presses(
    input: &egui::InputState,
) -> impl Iterator<Item = (egui::Key, egui::Modifiers)> + '_ {
    input.events.iter().filter_map(|event| match event {
        egui::Event::Key {
            key,
            pressed: true,
            modifiers,
            ..
        } => Some((*key, *modifiers)),
        _ => None,
    })
}

/// The move the keys pressed this frame ask for, if any (the last key of the frame wins
/// for Home/End; arrows and pages add up).
pub fn rail_move(input: &egui::InputState) -> Option<RailMove> {
    let mut by = 0.0;
    let mut to = None;
    for (key, modifiers) in presses(input) {
        match key_move(key, modifiers) {
            Some(RailMove::By(dx)) => by += dx,
            Some(RailMove::To(x)) => to = Some(x),
            None => {}
        }
    }
    match to {
        Some(x) => Some(RailMove::To(x)),
        None if by != 0.0 => Some(RailMove::By(by)),
        None => None,
    }
}

/// One key's move: the slider pattern's steps.
pub fn key_move(key: Key, modifiers: Modifiers) -> Option<RailMove> {
    let arrow = if modifiers.shift { 0.01 } else { 0.05 };
    if modifiers.ctrl || modifiers.alt || modifiers.command || modifiers.mac_cmd {
        return None;
    }
    Some(match key {
        Key::ArrowRight | Key::ArrowUp => RailMove::By(arrow),
        Key::ArrowLeft | Key::ArrowDown => RailMove::By(-arrow),
        Key::PageUp => RailMove::By(0.1),
        Key::PageDown => RailMove::By(-0.1),
        Key::Home => RailMove::To(0.0),
        Key::End => RailMove::To(1.0),
        _ => return None,
    })
}

/// After `ui.add(slider)`: when the slider has the keyboard, its keys move the value along
/// the rail from `before` (egui's one-point nudge of this frame is replaced) and the arrows
/// of both directions stay with the slider. Returns the new value, if a key moved it.
pub fn handle(ui: &egui::Ui, response: &egui::Response, rail: Rail, before: f64) -> Option<f64> {
    if !response.has_focus() || ui.ctx().text_edit_focused() {
        return None;
    }
    ui.memory_mut(|m| {
        m.set_focus_lock_filter(
            response.id,
            egui::EventFilter {
                horizontal_arrows: true,
                vertical_arrows: true,
                ..Default::default()
            },
        );
    });
    let step = ui.input(rail_move)?;
    let v = rail.moved(before, step);
    (v != before).then_some(v)
}

#[cfg(test)]
mod tests {
    use super::*;

    const LINEAR: Rail = Rail {
        min: -10.0,
        max: 30.0,
        log: false,
        integer: false,
    };

    #[test]
    fn arrows_move_a_twentieth_shift_a_hundredth_pages_a_tenth() {
        let none = Modifiers::NONE;
        let step = |key, m| LINEAR.moved(10.0, key_move(key, m).expect("a slider key"));
        approx::assert_relative_eq!(step(Key::ArrowRight, none), 12.0);
        approx::assert_relative_eq!(step(Key::ArrowDown, none), 8.0);
        approx::assert_relative_eq!(step(Key::ArrowLeft, Modifiers::SHIFT), 9.6);
        approx::assert_relative_eq!(step(Key::PageUp, none), 14.0);
        assert_eq!(step(Key::Home, none), -10.0);
        assert_eq!(step(Key::End, none), 30.0);
        assert_eq!(key_move(Key::ArrowRight, Modifiers::CTRL), None);
        assert_eq!(key_move(Key::A, none), None);
    }

    #[test]
    fn the_ends_hold() {
        assert_eq!(LINEAR.moved(29.5, RailMove::By(0.05)), 30.0);
        assert_eq!(LINEAR.moved(-10.0, RailMove::By(-0.1)), -10.0);
    }

    #[test]
    fn a_log_rail_multiplies() {
        let rail = Rail {
            min: 1e-6,
            max: 1e-2,
            log: true,
            integer: false,
        };
        // Four decades in twenty steps: a fifth of a decade per arrow.
        let up = rail.moved(1e-4, RailMove::By(0.05));
        approx::assert_relative_eq!(up, 1e-4 * 10f64.powf(0.2), max_relative = 1e-12);
        // A rail from zero: zero is the left end; the next place is on the log scale.
        let from_zero = Rail { min: 0.0, ..rail };
        assert_eq!(from_zero.position(0.0), 0.0);
        assert_eq!(from_zero.moved(1e-4, RailMove::To(0.0)), 0.0);
        assert!(from_zero.moved(0.0, RailMove::By(0.05)) > LOG_SMALLEST_POSITIVE);
    }

    #[test]
    fn a_whole_number_rail_moves_at_least_one() {
        let rail = Rail {
            min: 0.0,
            max: 5.0,
            log: false,
            integer: true,
        };
        assert_eq!(rail.moved(2.0, RailMove::By(0.05)), 3.0);
        assert_eq!(rail.moved(2.0, RailMove::By(-0.01)), 1.0);
        assert_eq!(rail.moved(5.0, RailMove::By(0.05)), 5.0);
        let wide = Rail {
            max: 4000.0,
            ..rail
        };
        assert_eq!(wide.moved(1000.0, RailMove::By(0.05)), 1200.0);
    }

    #[test]
    fn a_degenerate_rail_does_not_move_or_fail() {
        let flat = Rail {
            min: 1.0,
            max: 1.0,
            log: false,
            integer: false,
        };
        assert_eq!(flat.moved(1.0, RailMove::By(0.05)), 1.0);
        assert_eq!(LINEAR.position(f64::NAN), 0.0);
    }
}
