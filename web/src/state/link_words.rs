//! A bad item of a link, in words a student knows: the slider's label rather than its key,
//! the value the page keeps instead, the slider a mistyped key most likely meant — and no
//! list of the lab's forty internal names.

use attlab::i18n::{self, FluentValue, Lang};
use attlab::model::{Lab, ParamError, ParamKind, ParamSpec, ParamValues};
use attlab::state::UrlStateError;

/// What a link's bad item says on the page, in `lang`.
pub fn link_problem(lang: Lang, lab: &dyn Lab, e: &UrlStateError) -> String {
    let item = (
        "item",
        FluentValue::from(format!("{} “{}”", e.position, e.text)),
    );
    let Some(param) = &e.param else {
        return i18n::t_with(lang, "link-bad", &[item, ("why", e.reason.clone().into())]);
    };
    let spec_of = |key: &str| lab.params().iter().find(|s| s.key == key);
    let (id, key) = match param {
        ParamError::Unknown { key, .. } => {
            return match nearest(lab, key) {
                Some(spec) => i18n::t_with(
                    lang,
                    "link-unknown-near",
                    &[item, ("label", label(lang, lab, spec).into())],
                ),
                None => i18n::t_with(lang, "link-unknown", &[item]),
            };
        }
        ParamError::NotANumber { key, .. } | ParamError::NotFinite { key } => {
            ("link-not-a-number", key)
        }
        ParamError::OutOfRange { key, .. } => ("link-out-of-range", key),
        ParamError::NotInteger { key, .. } => ("link-not-whole", key),
        ParamError::NoSuchOption { key, .. } => ("link-no-option", key),
        ParamError::Malformed { .. } => return i18n::t_with(lang, "link-malformed", &[item]),
    };
    let Some(spec) = spec_of(key) else {
        return i18n::t_with(lang, "link-bad", &[item, ("why", e.reason.clone().into())]);
    };
    let kept = ParamValues::defaults(lab.params()).get(spec.key);
    let range = match spec.kind {
        ParamKind::Choice(options) => (0..options.len())
            .map(|i| {
                let id = i18n::param_option_id(lab.id(), spec.key, i);
                i18n::lab_text(lang, &id, options[i])
            })
            .collect::<Vec<_>>()
            .join(", "),
        _ => format!("{} … {} {}", spec.min, spec.max, spec.unit)
            .trim_end()
            .to_string(),
    };
    let args = [
        item,
        ("label", label(lang, lab, spec).into()),
        ("range", range.into()),
        ("kept", shown(spec, kept).into()),
    ];
    i18n::t_with(lang, id, &args)
}

/// A parameter's label in `lang`.
fn label(lang: Lang, lab: &dyn Lab, spec: &ParamSpec) -> String {
    i18n::lab_text(lang, &i18n::param_label_id(lab.id(), spec.key), spec.label)
}

/// A value as the slider shows it, with its unit.
fn shown(spec: &ParamSpec, v: f64) -> String {
    format!("{v} {}", spec.unit).trim_end().to_string()
}

/// The lab's parameter whose key is nearest to `key` (an edit distance of at most a third of
/// its length), if any.
fn nearest<'a>(lab: &'a dyn Lab, key: &str) -> Option<&'a ParamSpec> {
    let (best, distance) = lab
        .params()
        .iter()
        .map(|s| (s, strsim::levenshtein(s.key, key)))
        .min_by_key(|(_, d)| *d)?;
    (distance <= (key.chars().count() / 3).max(2)).then_some(best)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn problems(link: &str) -> Vec<String> {
        let (url, errors) = attlab::state::UrlState::parse(link);
        let lab = attlab::labs::find(url.lab_id).expect("registered");
        errors
            .iter()
            .map(|e| link_problem(Lang::En, lab, e))
            .collect()
    }

    #[test]
    fn a_bad_item_is_named_by_its_slider_and_says_what_is_kept() {
        let p = problems("lab=free-rotation&gyro_noise_deg_s=abc&gyro_bias_deg_s=99");
        assert_eq!(p.len(), 2, "{p:?}");
        assert!(
            p[0].contains("Gyro noise σ") && p[0].contains("0.02 °/s"),
            "{}",
            p[0]
        );
        assert!(p[1].contains("Gyro bias") && p[1].contains("…"), "{}", p[1]);
        assert!(
            !p.iter()
                .any(|m| m.contains("_deg_s=") && m.contains("this lab has"))
        );
    }

    #[test]
    fn a_mistyped_key_names_the_slider_it_meant_and_lists_no_keys() {
        let p = problems("lab=free-rotation&gyro_nois_deg_s=0.1&zzz=1");
        assert!(p[0].contains("Gyro noise σ"), "{}", p[0]);
        assert!(!p[1].contains("inertia_x_kg_m2"), "{}", p[1]);
        let ru = {
            let (url, errors) = attlab::state::UrlState::parse("lab=p1&n_window=abc");
            let lab = attlab::labs::find(url.lab_id).expect("registered");
            errors
                .iter()
                .map(|e| link_problem(Lang::Ru, lab, e))
                .collect::<Vec<_>>()
        };
        assert!(ru.iter().all(|m| !m.is_empty()), "{ru:?}");
    }
}
