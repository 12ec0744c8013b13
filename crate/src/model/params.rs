//! Lab parameters: the specification a slider is generated from, and validated values.

pub use super::param_error::ParamError;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// How a slider maps its position to the value.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum Scale {
    /// Uniform steps.
    Linear,
    /// Logarithmic (for noise levels and windows spanning decades); with `min` = 0 the
    /// slider is logarithmic above 1e-4 and reaches 0 at its left end.
    Log,
}

/// What kind of value a parameter holds.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub enum ParamKind {
    /// Any real number in range.
    Real,
    /// Integers only (window sizes, counts).
    Integer,
    /// 0 = off, 1 = on.
    Toggle,
    /// Index into the listed option names.
    Choice(&'static [&'static str]),
}

/// One parameter of a lab: the source of its slider, its CLI `--set` key and URL key.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct ParamSpec {
    /// Stable key with its unit in the name, e.g. `gyro_bias_deg_s`.
    pub key: &'static str,
    /// Label for the slider.
    pub label: &'static str,
    /// Unit shown beside the value ("" when dimensionless).
    pub unit: &'static str,
    /// Smallest allowed value.
    pub min: f64,
    /// Largest allowed value.
    pub max: f64,
    /// Value the lab starts with (the paper's setting where there is one).
    pub default: f64,
    /// Slider mapping.
    pub scale: Scale,
    /// Value kind.
    pub kind: ParamKind,
    /// One sentence on what the parameter does, shown on hover.
    pub help: &'static str,
    /// True when a change only takes effect at the next reset (e.g. an initial condition).
    pub needs_reset: bool,
    /// Key of another parameter that must be non-zero for this one to act (e.g. the time of
    /// an impulse acts only when the impulse has a size), or one of [`Self::active_when`].
    /// The page greys the slider out while it does not act, unless the parameter is also
    /// [`Self::outside_run`].
    pub requires: Option<&'static str>,
    /// The values of [`Self::requires`] with which this parameter acts (a choice's options:
    /// the tumble's rate acts in the tumbling motion only); empty: any non-zero value.
    pub active_when: &'static [f64],
    /// True when the parameter shapes only what is shown or exported beside the run (whose
    /// angles a paper's output file holds, a note under a slider), not the run itself. With
    /// [`Self::requires`], it acts on the run too while that parameter is non-zero (paper
    /// 1's body mass: the string check always, the run only in the 5-DOF body model).
    pub outside_run: bool,
}

impl ParamSpec {
    /// A real-valued, linear, live parameter.
    pub const fn real(
        key: &'static str,
        label: &'static str,
        unit: &'static str,
        min: f64,
        max: f64,
        default: f64,
    ) -> Self {
        Self {
            key,
            label,
            unit,
            min,
            max,
            default,
            scale: Scale::Linear,
            kind: ParamKind::Real,
            help: "",
            needs_reset: false,
            requires: None,
            active_when: &[],
            outside_run: false,
        }
    }

    /// Same, on a log slider.
    pub const fn log(self) -> Self {
        Self {
            scale: Scale::Log,
            ..self
        }
    }

    /// Integer valued.
    pub const fn integer(self) -> Self {
        Self {
            kind: ParamKind::Integer,
            ..self
        }
    }

    /// Applies at the next reset only.
    pub const fn on_reset(self) -> Self {
        Self {
            needs_reset: true,
            ..self
        }
    }

    /// Acts only while parameter `key` is non-zero.
    pub const fn requires(self, key: &'static str) -> Self {
        Self {
            requires: Some(key),
            ..self
        }
    }

    /// Acts only while parameter `key` (a choice) has one of `values`.
    pub const fn requires_one_of(self, key: &'static str, values: &'static [f64]) -> Self {
        Self {
            requires: Some(key),
            active_when: values,
            ..self
        }
    }

    /// Whether this parameter acts on a run of `params` (what it requires, if anything, is
    /// on).
    pub fn acts_in(&self, params: &ParamValues) -> bool {
        self.requires.is_none_or(|key| {
            let v = params.get(key);
            if self.active_when.is_empty() {
                v != 0.0
            } else {
                self.active_when.contains(&v)
            }
        })
    }

    /// A value of the parameter it requires with which this one acts (none for a parameter
    /// that requires none): the first of [`Self::active_when`], else `dep_max`.
    pub fn acting_value(&self, dep_max: f64) -> Option<f64> {
        self.requires?;
        Some(self.active_when.first().copied().unwrap_or(dep_max))
    }

    /// Shapes only what is shown or exported beside the run, not the run.
    pub const fn outside_run(self) -> Self {
        Self {
            outside_run: true,
            ..self
        }
    }

    /// With a help text.
    pub const fn help(self, help: &'static str) -> Self {
        Self { help, ..self }
    }

    /// An on/off switch.
    pub const fn toggle(key: &'static str, label: &'static str, default_on: bool) -> Self {
        let default = if default_on { 1.0 } else { 0.0 };
        Self {
            kind: ParamKind::Toggle,
            ..Self::real(key, label, "", 0.0, 1.0, default)
        }
    }

    /// A choice among named options (value = index).
    pub const fn choice(
        key: &'static str,
        label: &'static str,
        options: &'static [&'static str],
        default: usize,
    ) -> Self {
        let max = if options.is_empty() {
            0.0
        } else {
            (options.len() - 1) as f64
        };
        Self {
            kind: ParamKind::Choice(options),
            ..Self::real(key, label, "", 0.0, max, default as f64)
        }
    }

    /// Checks one value against this spec.
    pub fn validate(&self, value: f64) -> Result<f64, ParamError> {
        if !value.is_finite() {
            return Err(ParamError::NotFinite {
                key: self.key.to_string(),
            });
        }
        if value < self.min || value > self.max {
            return Err(ParamError::OutOfRange {
                key: self.key.to_string(),
                value,
                min: self.min,
                max: self.max,
                unit: self.unit.to_string(),
            });
        }
        match self.kind {
            ParamKind::Real => Ok(value),
            _ if value.fract() != 0.0 => Err(ParamError::NotInteger {
                key: self.key.to_string(),
                value,
            }),
            _ => Ok(value),
        }
    }
}

/// Validated values of every parameter of one lab, by key.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ParamValues {
    values: BTreeMap<String, f64>,
}

impl ParamValues {
    /// An upper bound of the heap a clone of these values allocates (bytes): B-tree nodes
    /// hold at least five entries each (464 bytes a node at most for `String` keys and
    /// `f64` values), and each key's text.
    pub fn heap_bytes(&self) -> usize {
        let nodes = self.values.len() / 5 + 1;
        nodes * 464 + self.values.keys().map(String::len).sum::<usize>()
    }

    /// Every parameter at its default.
    pub fn defaults(specs: &[ParamSpec]) -> Self {
        Self {
            values: specs
                .iter()
                .map(|s| (s.key.to_string(), s.default))
                .collect(),
        }
    }

    /// Value of `key`, one of the lab's own parameters.
    ///
    /// # Panics
    /// When `key` is not a parameter of this lab: a typo in a lab's own code, which the
    /// registry tests catch (every lab is built and stepped with random parameter sets).
    /// Keys from users go through [`ParamValues::set`] and come back as
    /// [`ParamError::Unknown`]; use [`ParamValues::try_get`] where a key may not exist.
    pub fn get(&self, key: &str) -> f64 {
        match self.values.get(key) {
            Some(v) => *v,
            None => panic!(
                "parameter `{key}` is not declared by this lab (declared: {})",
                self.values.keys().cloned().collect::<Vec<_>>().join(", ")
            ),
        }
    }

    /// Value of `key`, or [`ParamError::Unknown`].
    pub fn try_get(&self, key: &str) -> Result<f64, ParamError> {
        self.values
            .get(key)
            .copied()
            .ok_or_else(|| ParamError::Unknown {
                key: key.to_string(),
                known: self.values.keys().cloned().collect::<Vec<_>>().join(", "),
            })
    }

    /// Value of a toggle.
    pub fn flag(&self, key: &str) -> bool {
        self.get(key) >= 0.5
    }

    /// Value of an integer or choice parameter.
    pub fn index(&self, key: &str) -> usize {
        let v = self.get(key);
        if v.is_finite() && v >= 0.0 {
            v.round() as usize
        } else {
            0
        }
    }

    /// Sets `key` after validating against `specs`.
    pub fn set(&mut self, specs: &[ParamSpec], key: &str, value: f64) -> Result<(), ParamError> {
        let spec = find_spec(specs, key)?;
        let value = spec.validate(value)?;
        self.values.insert(key.to_string(), value);
        Ok(())
    }

    /// Sets `key` from text (`"0.1"`), validating.
    pub fn set_text(
        &mut self,
        specs: &[ParamSpec],
        key: &str,
        text: &str,
    ) -> Result<(), ParamError> {
        let spec = find_spec(specs, key)?;
        let value = match (text.trim().parse::<f64>(), spec.kind) {
            (Ok(v), _) => v,
            (Err(_), ParamKind::Choice(options)) => choice_by_name(key, options, text)? as f64,
            (Err(_), ParamKind::Toggle) => match text.trim().to_ascii_lowercase().as_str() {
                "on" | "true" | "yes" => 1.0,
                "off" | "false" | "no" => 0.0,
                _ => {
                    return Err(ParamError::NotANumber {
                        key: key.to_string(),
                        text: text.to_string(),
                    });
                }
            },
            (Err(_), _) => {
                return Err(ParamError::NotANumber {
                    key: key.to_string(),
                    text: text.to_string(),
                });
            }
        };
        self.set(specs, key, value)
    }

    /// Applies `key=value` assignments; returns every error, keeping the good assignments.
    pub fn apply_assignments<'a>(
        &mut self,
        specs: &[ParamSpec],
        items: impl IntoIterator<Item = &'a str>,
    ) -> Vec<ParamError> {
        let mut errors = Vec::new();
        for item in items {
            let result = match item.split_once('=') {
                Some((k, v)) => self.set_text(specs, k.trim(), v),
                None => Err(ParamError::Malformed {
                    text: item.to_string(),
                }),
            };
            if let Err(e) = result {
                errors.push(e);
            }
        }
        errors
    }

    /// (key, value) pairs in key order.
    pub fn iter(&self) -> impl Iterator<Item = (&str, f64)> {
        self.values.iter().map(|(k, v)| (k.as_str(), *v))
    }
}

/// The index of the option of a choice parameter named by `text`: an option whose label,
/// or one of its words, equals `text` (case-insensitive), e.g. `intermediate` for
/// "y (intermediate I: flips)". Exactly one option must match.
fn choice_by_name(key: &str, options: &[&str], text: &str) -> Result<usize, ParamError> {
    let wanted = text.trim().to_lowercase();
    let matches: Vec<usize> = options
        .iter()
        .enumerate()
        .filter(|_| !wanted.is_empty())
        .filter(|(_, o)| {
            let label = o.to_lowercase();
            label == wanted
                || label
                    .split(|c: char| !c.is_alphanumeric() && c != '-' && c != '.')
                    .any(|w| w == wanted)
        })
        .map(|(i, _)| i)
        .collect();
    match matches.as_slice() {
        [i] => Ok(*i),
        _ => Err(ParamError::NoSuchOption {
            key: key.to_string(),
            text: text.to_string(),
            options: options
                .iter()
                .enumerate()
                .map(|(i, o)| format!("{i} = {o}"))
                .collect::<Vec<_>>()
                .join("; "),
        }),
    }
}

pub(crate) fn find_spec<'a>(
    specs: &'a [ParamSpec],
    key: &str,
) -> Result<&'a ParamSpec, ParamError> {
    specs
        .iter()
        .find(|s| s.key == key)
        .ok_or_else(|| ParamError::Unknown {
            key: key.to_string(),
            known: specs.iter().map(|s| s.key).collect::<Vec<_>>().join(", "),
        })
}

#[cfg(test)]
mod tests {
    use super::*;

    const SPECS: &[ParamSpec] = &[
        ParamSpec::real("sigma_deg_s", "σ", "°/s", 0.0, 1.0, 0.1),
        ParamSpec::real("window", "N", "", 1.0, 5000.0, 100.0).integer(),
    ];

    #[test]
    fn bad_assignments_are_reported_and_good_ones_kept() {
        let mut p = ParamValues::defaults(SPECS);
        let errs = p.apply_assignments(
            SPECS,
            [
                "sigma_deg_s=0.5",
                "window=2.5",
                "nope=1",
                "window",
                "sigma_deg_s=abc",
                "window=9999",
            ],
        );
        assert_eq!(p.get("sigma_deg_s"), 0.5);
        assert_eq!(p.get("window"), 100.0);
        assert_eq!(errs.len(), 5);
        assert!(matches!(errs[0], ParamError::NotInteger { .. }));
        assert!(matches!(errs[1], ParamError::Unknown { .. }));
        assert!(matches!(errs[2], ParamError::Malformed { .. }));
        assert!(matches!(errs[3], ParamError::NotANumber { .. }));
        assert!(matches!(errs[4], ParamError::OutOfRange { .. }));
        assert!(errs[4].to_string().contains("1 … 5000"));
    }

    #[test]
    fn a_choice_can_be_named() {
        const AXES: &[ParamSpec] = &[ParamSpec::choice(
            "spin_axis",
            "Spin axis",
            &[
                "x (smallest I: stable)",
                "y (intermediate I: flips)",
                "z (largest I: stable)",
            ],
            1,
        )];
        let mut p = ParamValues::defaults(AXES);
        p.set_text(AXES, "spin_axis", "Intermediate").unwrap();
        assert_eq!(p.get("spin_axis"), 1.0);
        p.set_text(AXES, "spin_axis", "z").unwrap();
        assert_eq!(p.get("spin_axis"), 2.0);
        let err = p.set_text(AXES, "spin_axis", "stable").unwrap_err();
        assert!(err.to_string().contains("0 = x"), "{err}");
        // An empty value names no option: an error listing them, the choice unchanged.
        for blank in ["", "  "] {
            let err = p.set_text(AXES, "spin_axis", blank).unwrap_err();
            assert!(err.to_string().contains("2 = z"), "{err}");
            assert_eq!(p.get("spin_axis"), 2.0);
        }
    }

    #[test]
    fn an_undeclared_key_is_an_error_not_nan() {
        let p = ParamValues::defaults(SPECS);
        assert!(matches!(p.try_get("nope"), Err(ParamError::Unknown { .. })));
        assert!(std::panic::catch_unwind(|| p.get("nope")).is_err());
    }

    #[test]
    fn non_finite_values_are_rejected() {
        let mut p = ParamValues::defaults(SPECS);
        assert!(matches!(
            p.set(SPECS, "sigma_deg_s", f64::NAN),
            Err(ParamError::NotFinite { .. })
        ));
        assert_eq!(p.get("sigma_deg_s"), 0.1);
    }
}
