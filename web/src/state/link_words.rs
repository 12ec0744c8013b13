//! A bad item of a link, or a refused value, in words a student knows: the slider's label rather than its key,
//! the value the page keeps instead, the slider a mistyped key most likely meant — and no
//! list of the lab's forty internal names.

use attlab::i18n::{self, FluentValue, Lang};
use attlab::model::{ParamError, ParamSpec, ParamValues};
use attlab::page::Lab;
use attlab::state::UrlStateError;

/// What a link's bad item says on the page, in `lang`.
pub fn link_problem(lang: Lang, lab: &dyn Lab, e: &UrlStateError) -> String {
    let item = (
        "item",
        FluentValue::from(format!("{} “{}”", e.position, e.text)),
    );
    let Some(param) = &e.param else {
        // A page setting's, a lesson's or a list's fault in the reader's words.
        let why = e
            .fault
            .as_ref()
            .map_or_else(|| e.reason.clone(), |f| f.words(lang));
        return i18n::t_with(lang, "link-bad", &[item, ("why", why.into())]);
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
    let args = [
        item,
        ("label", label(lang, lab, spec).into()),
        ("range", range(lang, lab, spec).into()),
        ("kept", shown(lang, spec, kept).into()),
    ];
    i18n::t_with(lang, id, &args)
}

pub use attlab::i18n::errors::param_problem;
use attlab::i18n::errors::{param_label as label, param_range as range, param_shown as shown};

/// The lab's parameter whose key, or whose label spelled as a key, is nearest to `key` (an
/// edit distance of at most a third of its length), if any: `gyro_sigma_deg_s` is paper
/// 2's "Gyro σ" (`gyro_noise_deg_s`), which the keys alone had taken for "Gyro bias"
/// (`gyro_bias_deg_s`, one letter nearer).
fn nearest<'a>(lab: &'a dyn Lab, key: &str) -> Option<&'a ParamSpec> {
    let (best, distance) = lab
        .params()
        .iter()
        .map(|s| {
            let by_key = strsim::levenshtein(s.key, key);
            (s, by_key.min(strsim::levenshtein(&spelled(s), key)))
        })
        .min_by_key(|(_, d)| *d)?;
    (distance <= (key.chars().count() / 3).max(2)).then_some(best)
}

/// A parameter's English label spelled as a key would be, with its key's unit at the end:
/// "Gyro σ" of `gyro_noise_deg_s` is `gyro_sigma_deg_s`.
fn spelled(spec: &ParamSpec) -> String {
    let mut words: Vec<String> = Vec::new();
    for word in spec.label.split(|c: char| !c.is_alphanumeric()) {
        let word: String = word.chars().map(greek).collect::<String>().to_lowercase();
        if !word.is_empty() {
            words.push(word);
        }
    }
    // The key's unit: its words after the last that is not a unit's.
    let units = [
        "deg", "s", "rad", "hz", "nt", "m", "mm", "kg", "m2", "g", "pct", "sqrt",
    ];
    let tail: Vec<&str> = (spec.key.rsplit('_'))
        .take_while(|w| units.contains(w))
        .collect();
    words.extend(tail.into_iter().rev().map(str::to_string));
    words.join("_")
}

/// A Greek letter's name, as a key spells it (others as they are).
fn greek(c: char) -> String {
    let name = match c {
        'σ' => "sigma",
        'γ' => "gamma",
        'ω' => "omega",
        'θ' => "theta",
        'ϑ' => "theta",
        'φ' => "phi",
        'ψ' => "psi",
        'ε' => "eps",
        'α' => "alpha",
        'λ' => "lambda",
        'Δ' => "delta",
        'ζ' => "zeta",
        'τ' => "tau",
        _ => return c.to_string(),
    };
    name.to_string()
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
    fn a_key_spelled_from_a_label_names_that_slider() {
        let p = problems("lab=p2&gyro_sigma_deg_s=1e9");
        assert_eq!(p.len(), 1, "{p:?}");
        assert!(
            p[0].contains("Gyro σ") && !p[0].contains("Gyro bias"),
            "{}",
            p[0]
        );
        let lab = attlab::labs::find("p2").unwrap();
        let noise = lab
            .params()
            .iter()
            .find(|s| s.key == "gyro_noise_deg_s")
            .unwrap();
        assert_eq!(spelled(noise), "gyro_sigma_deg_s");
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

    /// Each refused value, in both languages: named by the slider's label (Russian in
    /// Russian), with the value given and what the slider takes; never by its key.
    #[test]
    fn a_refused_value_is_said_by_the_sliders_label_in_the_readers_language() {
        let lab = attlab::labs::find("free-rotation").expect("registered");
        let key = "gyro_noise_deg_s";
        let spec = lab
            .params()
            .iter()
            .find(|s| s.key == key)
            .expect("a slider");
        let mut values = ParamValues::defaults(lab.params());
        let refused = [
            values.set(lab.params(), key, 1e9),
            values.set(lab.params(), key, f64::NAN),
            values.set_text(lab.params(), key, "abc"),
            values.set(lab.params(), "no_such_key", 1.0),
        ];
        for lang in Lang::ALL {
            let label = label(lang, lab, spec);
            for r in &refused {
                let e = r.as_ref().expect_err("refused");
                let said = param_problem(lang, lab, lab.params(), e);
                assert!(
                    !said.contains(key) && !said.contains('{'),
                    "{lang:?}: {said}"
                );
                match e {
                    ParamError::Unknown { .. } => assert!(said.contains("no_such_key"), "{said}"),
                    _ => assert!(said.contains(&label), "{lang:?}: {said} lacks {label}"),
                }
                if let ParamError::OutOfRange { .. } = e {
                    assert!(said.contains("1000000000") && said.contains('…'), "{said}");
                }
                if lang == Lang::Ru {
                    assert!(said.chars().any(|c| ('а'..='я').contains(&c)), "{said}");
                }
            }
        }
        let label_ru = label(Lang::Ru, lab, spec);
        assert_ne!(label_ru, spec.label, "the slider has a Russian label");
    }
}
