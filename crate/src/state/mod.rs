//! The shareable state of the app in a URL fragment:
//! `#lab=free-rotation&seed=1&speed=1&gyro_bias_deg_s=0.1` (and `presenter=1` for the
//! projector: large type, thick lines, only the controls that matter).
//!
//! Parsing never fails as a whole: every bad item is reported with its position and text,
//! and everything good is kept.

use crate::i18n::Lang;
use crate::labs;
use crate::model::{ParamError, ParamValues};
use crate::page::Lab;
use thiserror::Error;

mod fault;
mod lesson;
mod travel;

pub use fault::LinkFault;
pub use travel::{MAX_WHAT_IFS, WhatIfLink};

/// What a URL fragment asks for.
#[derive(Clone, Debug, PartialEq)]
pub struct UrlState {
    /// The lab.
    pub lab_id: &'static str,
    /// RNG seed.
    pub seed: u64,
    /// Simulation speed (× real time).
    pub speed: f64,
    /// The lab's parameters.
    pub params: ParamValues,
    /// Presenter mode (for a projector).
    pub presenter: bool,
    /// The colour theme asked for; `None` follows the mode (light in presenter mode).
    pub theme: Option<Theme>,
    /// The language asked for; `None` follows the reader's browser.
    pub lang: Option<Lang>,
    /// The lab's lesson at a step, with the reader's answers (`lesson=p2&step=4&answers=2b`).
    pub lesson: Option<LessonLink>,
    /// Parameters whose controls the page hides (`hide=key.key`, `all` for every one).
    pub hide: Vec<String>,
    /// Parameters whose controls the page shows but locks (`lock=key.key`, or `all`).
    pub lock: Vec<String>,
    /// Embedded in another page (`embed=1`): the views and the plot without the page's
    /// panels, for a slide or a course page's `<iframe>`.
    pub embed: bool,
    /// The other web origins whose pages may drive this one by `postMessage` and hear its
    /// events (`origin=https://example.org`, repeated; `*` for any): see docs/embed.md. The
    /// page's own origin always may.
    pub origins: Vec<String>,
    /// The timeline's cursor (s), when it is off now (`at=`).
    pub cursor_s: Option<f64>,
    /// The "what if" branches (`whatif=`, at most [`travel::MAX_WHAT_IFS`]).
    pub what_ifs: Vec<WhatIfLink>,
}

/// Where a link opens a lesson, and the answers chosen so far.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct LessonLink {
    /// The step (1-based).
    pub step: usize,
    /// (step, answer), both 1-based, in the order given: `answers=2b.5a` is step 2's second
    /// answer and step 5's first.
    pub answers: Vec<(usize, usize)>,
}

impl LessonLink {
    /// The link's spelling of the answers: step number and answer letter, dot separated.
    pub fn encode_answers(&self) -> String {
        self.answers
            .iter()
            .map(|(step, answer)| format!("{step}{}", char::from(b'a' + (*answer as u8 - 1))))
            .collect::<Vec<_>>()
            .join(".")
    }
}

/// The word a link uses for every parameter in `hide=` and `lock=`.
pub const ALL_CONTROLS: &str = "all";

/// The parameters a lab opens with for a lesson step (its defaults without one); a link's
/// parameters are given relative to these.
pub fn base_params(lab: &'static dyn Lab, lesson: Option<&LessonLink>) -> ParamValues {
    lesson
        .and_then(|l| lab.lesson()?.step(l.step))
        .and_then(|step| crate::lessons::step_params(lab, step).ok())
        .unwrap_or_else(|| ParamValues::defaults(lab.params()))
}

/// The page's colour theme.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Theme {
    /// Light panels in dark type: for projectors, which wash dark backgrounds out.
    Light,
    /// Dark panels: for a screen in a dim room.
    Dark,
}

impl Theme {
    /// The word in a link (`theme=light`).
    pub fn slug(self) -> &'static str {
        match self {
            Self::Light => "light",
            Self::Dark => "dark",
        }
    }

    /// The theme a page without an explicit choice shows: light in presenter mode.
    pub fn for_mode(presenter: bool) -> Self {
        if presenter { Self::Light } else { Self::Dark }
    }
}

pub use crate::page::SPEED_RANGE;

/// One bad item in a URL fragment.
#[derive(Clone, Debug, Error, PartialEq)]
#[error("URL item {position} `{text}`: {reason}")]
pub struct UrlStateError {
    /// 1-based position of the item.
    pub position: usize,
    /// The item as written.
    pub text: String,
    /// What was wrong.
    pub reason: String,
    /// The parameter's own error, when the item set a lab parameter (the page words it with
    /// the slider's label).
    pub param: Option<ParamError>,
    /// What was wrong, typed, when the item was not a lab parameter (the page says it in
    /// the reader's language; `reason` is its English).
    pub fault: Option<LinkFault>,
}

impl UrlStateError {
    /// The error of item `position` (`text` as written) refused for `fault`.
    fn of(position: usize, text: &str, fault: LinkFault) -> Self {
        Self {
            position,
            text: text.to_string(),
            reason: fault.to_string(),
            param: None,
            fault: Some(fault),
        }
    }
}

/// Why [`UrlState::apply_item`] refused an item: a lab parameter's error or a link fault.
enum Refused {
    Param(ParamError),
    Fault(LinkFault),
}

impl UrlState {
    /// Defaults of `lab`.
    pub fn defaults(lab: &'static dyn Lab) -> Self {
        Self {
            lab_id: lab.id(),
            seed: 1,
            speed: 1.0,
            params: ParamValues::defaults(lab.params()),
            presenter: false,
            theme: None,
            lang: None,
            lesson: None,
            hide: Vec::new(),
            lock: Vec::new(),
            embed: false,
            origins: Vec::new(),
            cursor_s: None,
            what_ifs: Vec::new(),
        }
    }

    /// Encodes as a fragment (without `#`), percent-encoded; parameters at their default are
    /// left out.
    pub fn encode(&self) -> String {
        let mut out = form_urlencoded::Serializer::new(String::new());
        out.append_pair("lab", self.lab_id)
            .append_pair("seed", &self.seed.to_string())
            .append_pair("speed", &self.speed.to_string());
        if self.presenter {
            out.append_pair("presenter", "1");
        }
        if let Some(theme) = self.theme {
            out.append_pair("theme", theme.slug());
        }
        if let Some(lang) = self.lang {
            out.append_pair("lang", lang.code());
        }
        if self.embed {
            out.append_pair("embed", "1");
        }
        for origin in &self.origins {
            out.append_pair("origin", origin);
        }
        travel::encode(self, &mut out);
        if let Some(lesson) = &self.lesson {
            out.append_pair("lesson", self.lab_id)
                .append_pair("step", &lesson.step.to_string());
            if !lesson.answers.is_empty() {
                out.append_pair("answers", &lesson.encode_answers());
            }
        }
        for (key, list) in [("hide", &self.hide), ("lock", &self.lock)] {
            if !list.is_empty() {
                out.append_pair(key, &list.join("."));
            }
        }
        if let Some(lab) = labs::find(self.lab_id) {
            let base = base_params(lab, self.lesson.as_ref());
            for spec in lab.params() {
                if let Ok(v) = self.params.try_get(spec.key)
                    && Ok(v) != base.try_get(spec.key)
                {
                    out.append_pair(spec.key, &v.to_string());
                }
            }
        }
        out.finish()
    }

    /// Parses a fragment (with or without `#`; percent-decoded by `form_urlencoded`). Unknown
    /// or invalid items are returned as errors with their position; the rest is applied on
    /// top of the defaults of the named (or first) lab.
    pub fn parse(fragment: &str) -> (Self, Vec<UrlStateError>) {
        let fragment = fragment.trim_start_matches('#');
        let raw: Vec<&str> = fragment.split('&').filter(|s| !s.is_empty()).collect();
        let items: Vec<(usize, String, Option<String>, &str)> = raw
            .iter()
            .enumerate()
            .map(|(i, item)| {
                let (k, v) = form_urlencoded::parse(item.as_bytes())
                    .next()
                    .map(|(k, v)| (k.into_owned(), v.into_owned()))
                    .unwrap_or_default();
                let value = item.contains('=').then_some(v);
                (i + 1, k, value, *item)
            })
            .collect();
        let mut errors = Vec::new();
        let err = UrlStateError::of;
        let mut lab = labs::all()[0];
        for (pos, key, value, item) in &items {
            if let ("lab", Some(id)) = (key.as_str(), value) {
                match labs::find(id) {
                    Some(l) => lab = l,
                    None => errors.push(err(*pos, item, LinkFault::NoSuchLab(labs::ids()))),
                }
            }
        }
        let lesson_items = items
            .iter()
            .filter(|(_, k, _, _)| k == "lesson" || k == "step")
            .map(|(pos, k, v, item)| (*pos, k.as_str(), v.as_deref().unwrap_or(""), *item));
        let (lab, lesson) = lesson::parse(lab, lesson_items, &mut errors);
        let mut state = Self::defaults(lab);
        state.params = base_params(lab, lesson.as_ref());
        state.lesson = lesson;
        for (pos, key, value, item) in &items {
            let Some(value) = value else {
                errors.push(err(*pos, item, LinkFault::NotKeyValue));
                continue;
            };
            if matches!(key.as_str(), "lesson" | "step") {
                continue;
            }
            match state.apply_item(lab, key, value) {
                Ok(()) => {}
                Err(Refused::Param(e)) => errors.push(UrlStateError {
                    position: *pos,
                    text: item.to_string(),
                    reason: e.to_string(),
                    param: Some(e),
                    fault: None,
                }),
                Err(Refused::Fault(f)) => errors.push(err(*pos, item, f)),
            }
        }
        (state, errors)
    }

    /// Applies one `key=value` item of a link to the state, or says what is wrong with it
    /// (and, for a lab parameter, its error).
    fn apply_item(&mut self, lab: &'static dyn Lab, key: &str, value: &str) -> Result<(), Refused> {
        if matches!(key, "answers" | "hide" | "lock") {
            return lesson::apply_list(self, lab, key, value).map_err(Refused::Fault);
        }
        if matches!(key, "at" | "whatif") {
            return travel::apply(self, lab, key, value).map_err(Refused::Fault);
        }
        if !matches!(
            key,
            "lab" | "seed" | "speed" | "presenter" | "theme" | "lang" | "embed" | "origin"
        ) {
            return self
                .params
                .set_text(lab.params(), key, value)
                .map_err(Refused::Param);
        }
        self.apply_setting(key, value).map_err(Refused::Fault)
    }

    /// Applies one of the page's own settings (not a lab parameter).
    fn apply_setting(&mut self, key: &str, value: &str) -> Result<(), LinkFault> {
        match key {
            "lab" => {}
            "seed" => {
                self.seed = value.parse::<u64>().map_err(|_| LinkFault::Seed)?;
            }
            "speed" => match value.parse::<f64>() {
                Ok(s) if (SPEED_RANGE.0..=SPEED_RANGE.1).contains(&s) => self.speed = s,
                _ => {
                    let (lo, hi) = SPEED_RANGE;
                    return Err(LinkFault::Speed { lo, hi });
                }
            },
            "presenter" => match value {
                "1" | "true" | "on" => self.presenter = true,
                "0" | "false" | "off" => self.presenter = false,
                _ => return Err(LinkFault::Presenter),
            },
            "theme" => match value {
                "light" => self.theme = Some(Theme::Light),
                "dark" => self.theme = Some(Theme::Dark),
                _ => return Err(LinkFault::Theme),
            },
            "lang" => {
                let lang = Lang::from_tag(value).ok_or(LinkFault::Lang)?;
                self.lang = Some(lang);
            }
            "embed" => match value {
                "1" | "true" | "on" => self.embed = true,
                "0" | "false" | "off" => self.embed = false,
                _ => return Err(LinkFault::Embed),
            },
            "origin" => {
                let origin =
                    web_origin(value).ok_or_else(|| LinkFault::Origin(value.to_string()))?;
                if !self.origins.contains(&origin) {
                    self.origins.push(origin);
                }
            }
            _ => {}
        }
        Ok(())
    }
}

/// `text` as a web origin a link may allow (`scheme://host[:port]`, lower case, without a
/// trailing `/`), `*` (any origin) or `null` (a page opened from a file, a sandboxed frame);
/// `None` if it is none of these (a path, a query, another scheme, spaces).
pub fn web_origin(text: &str) -> Option<String> {
    let text = text.trim_end_matches('/').to_ascii_lowercase();
    if text == "*" || text == "null" {
        return Some(text);
    }
    let (scheme, rest) = text.split_once("://")?;
    let (host, port) = match rest.rsplit_once(':') {
        // An IPv6 literal's colons sit inside its brackets.
        Some((host, port)) if !port.contains(']') => (host, Some(port)),
        _ => (rest, None),
    };
    let host_ok = !host.is_empty()
        && (host.chars())
            .all(|c| c.is_ascii_alphanumeric() || matches!(c, '.' | '-' | '[' | ']' | ':'));
    let port_ok = port.is_none_or(|p| p.parse::<u16>().is_ok());
    (matches!(scheme, "http" | "https") && host_ok && port_ok).then_some(text)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trip() {
        let lab = labs::all()[0];
        let mut s = UrlState::defaults(lab);
        s.seed = 42;
        s.speed = 10.0;
        s.params.set(lab.params(), "gyro_bias_deg_s", 0.5).unwrap();
        let (back, errors) = UrlState::parse(&format!("#{}", s.encode()));
        assert!(errors.is_empty(), "{errors:?}");
        assert_eq!(back, s);
        s.presenter = true;
        let (back, errors) = UrlState::parse(&s.encode());
        assert!(errors.is_empty(), "{errors:?}");
        assert!(back.presenter);
        let (back, errors) = UrlState::parse("presenter=maybe");
        assert!(!back.presenter);
        assert_eq!(errors.len(), 1);
        assert!(errors[0].to_string().contains("presenter must be 1 or 0"));
        let (back, errors) = UrlState::parse("theme=light");
        assert_eq!((back.theme, errors.len()), (Some(Theme::Light), 0));
        assert_eq!(UrlState::parse(&back.encode()).0.theme, Some(Theme::Light));
        let (back, errors) = UrlState::parse("theme=sepia");
        assert_eq!(back.theme, None);
        assert!(
            errors[0]
                .to_string()
                .contains("theme must be light or dark")
        );
        let (back, errors) = UrlState::parse("lang=ru");
        assert_eq!((back.lang, errors.len()), (Some(Lang::Ru), 0));
        assert_eq!(UrlState::parse(&back.encode()).0.lang, Some(Lang::Ru));
        let (back, errors) = UrlState::parse("lang=klingon");
        assert_eq!(back.lang, None);
        assert!(errors[0].to_string().contains("lang must be en or ru"));
    }

    #[test]
    fn malformed_items_are_reported_and_the_rest_kept() {
        let (s, errors) = UrlState::parse(
            "lab=free-rotation&seed=-3&gyro_bias_deg_s=0.3&junk&speed=1e9&nope=2&gyro_noise_deg_s=abc",
        );
        assert_eq!(s.lab_id, "free-rotation");
        assert_eq!(s.seed, 1);
        assert_eq!(s.params.get("gyro_bias_deg_s"), 0.3);
        let positions: Vec<usize> = errors.iter().map(|e| e.position).collect();
        assert_eq!(positions, vec![2, 4, 5, 6, 7]);
        assert!(errors[3].to_string().contains("unknown parameter `nope`"));
    }

    #[test]
    fn percent_encoding_round_trips_and_bad_escapes_are_reported_not_fatal() {
        let (s, errors) =
            UrlState::parse("lab=free%2Drotation&seed=4&gyro_bias_deg_s=0%2E5&%%%&%zz=1");
        assert_eq!(s.lab_id, "free-rotation");
        assert_eq!(s.params.get("gyro_bias_deg_s"), 0.5);
        assert_eq!(
            errors.iter().map(|e| e.position).collect::<Vec<_>>(),
            vec![4, 5]
        );
        let (back, errors) = UrlState::parse(&s.encode());
        assert!(errors.is_empty(), "{errors:?}");
        assert_eq!(back, s);
    }

    #[test]
    fn embed_and_origins_round_trip_and_bad_ones_are_refused() {
        let (s, errors) = UrlState::parse(
            "lab=p3&embed=1&origin=https%3A%2F%2FCourse.example.org%2F&origin=http://127.0.0.1:8101&origin=*",
        );
        assert!(errors.is_empty(), "{errors:?}");
        assert!(s.embed);
        assert_eq!(
            s.origins,
            ["https://course.example.org", "http://127.0.0.1:8101", "*"]
        );
        assert_eq!(UrlState::parse(&s.encode()).0, s);
        let (s, errors) = UrlState::parse(
            "embed=2&origin=ftp://x.org&origin=https://x.org/page&origin=http://h:99999&origin=null",
        );
        assert!(!s.embed);
        assert_eq!(s.origins, ["null"]);
        let faults: Vec<_> = errors.iter().map(|e| e.fault.clone()).collect();
        assert_eq!(
            faults,
            [
                Some(LinkFault::Embed),
                Some(LinkFault::Origin("ftp://x.org".into())),
                Some(LinkFault::Origin("https://x.org/page".into())),
                Some(LinkFault::Origin("http://h:99999".into())),
            ]
        );
        assert_eq!(
            web_origin("http://[::1]:8000").as_deref(),
            Some("http://[::1]:8000")
        );
    }

    #[test]
    fn unknown_lab_falls_back_to_the_first() {
        let (s, errors) = UrlState::parse("lab=warp-drive");
        assert_eq!(s.lab_id, labs::all()[0].id());
        assert_eq!(errors.len(), 1);
    }
}
