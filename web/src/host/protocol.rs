//! The messages of the host API, version [`API`]: what a page that embeds the lab sends
//! (a [`Request`]) and what the lab answers and reports (events as JSON, built by
//! [`event`]), documented in docs/embed.md. Parsing is pure: a message that is not JSON, not for this API, of an
//! unknown type or with a bad argument is refused with a [`HostError`] and changes nothing.

use serde_json::{Map, Value, json};

/// The API's version: every message carries it as `"api": 1`.
pub const API: u64 = 1;

/// One request of the host page.
#[derive(Clone, Debug, PartialEq)]
pub struct Request {
    /// The host's own tag for the request, echoed as `re` in the answer.
    pub id: Option<Value>,
    /// What it asks.
    pub action: Action,
}

/// What a request asks the lab to do.
#[derive(Clone, Debug, PartialEq)]
pub enum Action {
    /// Set parameters: key → a number, or a choice's name.
    Set(Vec<(String, Value)>),
    /// Apply a preset of the lab, by its id.
    Preset(String),
    /// Switch to another lab, by its id.
    Lab(String),
    /// Run.
    Play,
    /// Pause.
    Pause,
    /// Pause, then one step.
    Step,
    /// Restart with the same seed.
    Reset,
    /// Simulated seconds per wall-clock second.
    Speed(f64),
    /// Open the lab's lesson at a step: its number (1-based) or its id.
    Lesson(StepRef),
    /// Choose an answer (1-based) to the open step's question.
    Answer(usize),
    /// Report the state now (a `state` event).
    Get,
}

/// A lesson step, as the host names it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum StepRef {
    /// Its number, from 1.
    Number(usize),
    /// Its stable id (`upside-down`).
    Id(String),
}

/// Why a message was refused: its code for programs (`error` events' `code`), and what the
/// reader's message in the catalogue (`host-error-<code>`) needs.
#[derive(Clone, Debug, PartialEq)]
pub enum HostError {
    /// Not JSON: where the text stopped parsing (line and column from 1), or (0, 0) for a
    /// value JSON cannot hold.
    NotJson(usize, usize),
    /// JSON, but not an object with `"api"`: not a message of this API.
    NotOurs,
    /// Another version of the API.
    Version(String),
    /// A `type` this version does not know.
    UnknownType(String),
    /// An argument missing or of the wrong kind: which one, and the catalogue's message
    /// (`host-must-*`) for what it must be.
    BadArgument(&'static str, &'static str),
    /// A parameter's value refused (unknown key, out of range…), in words.
    Param(String),
    /// The link locks this parameter's control.
    Locked(String),
    /// No preset with this id in the lab.
    NoPreset(String),
    /// No lab with this id.
    NoLab(String),
    /// The lab has no lesson.
    NoLesson,
    /// The lesson has no such step.
    NoStep(String),
    /// The open step asks no question (or no lesson is open).
    NoQuestion,
    /// The question has no such answer.
    NoAnswer(usize),
    /// The sending page's origin is not one the link allows.
    Origin(String),
}

impl HostError {
    /// The error's code in an `error` event.
    pub fn code(&self) -> &'static str {
        match self {
            Self::NotJson(..) => "not-json",
            Self::NotOurs => "not-attlab",
            Self::Version(_) => "api-version",
            Self::UnknownType(_) => "unknown-type",
            Self::BadArgument(..) => "bad-argument",
            Self::Param(_) => "bad-parameter",
            Self::Locked(_) => "locked",
            Self::NoPreset(_) => "no-preset",
            Self::NoLab(_) => "no-lab",
            Self::NoLesson => "no-lesson",
            Self::NoStep(_) => "no-step",
            Self::NoQuestion => "no-question",
            Self::NoAnswer(_) => "no-answer",
            Self::Origin(_) => "origin-not-allowed",
        }
    }

    /// The catalogue message's arguments.
    pub fn arguments(&self) -> Vec<(&'static str, String)> {
        match self {
            Self::NotJson(line, column) => {
                vec![("line", line.to_string()), ("column", column.to_string())]
            }
            Self::Version(v) => vec![("version", v.clone()), ("api", API.to_string())],
            Self::UnknownType(t) => vec![("type", t.clone())],
            Self::BadArgument(name, _) => vec![("name", (*name).to_string())],
            Self::Param(words) => vec![("why", words.clone())],
            Self::Locked(label) => vec![("label", label.clone())],
            Self::NoPreset(id) | Self::NoLab(id) | Self::NoStep(id) => vec![("id", id.clone())],
            Self::NoAnswer(k) => vec![("answer", k.to_string())],
            Self::Origin(origin) => vec![("origin", origin.clone())],
            Self::NotOurs | Self::NoLesson | Self::NoQuestion => Vec::new(),
        }
    }

    /// What it says in `lang`.
    pub fn words(&self, lang: attlab::i18n::Lang) -> String {
        let mut args: Vec<(&str, attlab::i18n::FluentValue<'_>)> = (self.arguments().into_iter())
            .map(|(name, value)| (name, value.into()))
            .collect();
        if let Self::BadArgument(_, must) = self {
            args.push(("must", attlab::i18n::t(lang, must).into()));
        }
        attlab::i18n::t_with(lang, &format!("host-error-{}", self.code()), &args)
    }
}

/// Parses one message's data: a JSON text (a host may send a string) or the JSON of the
/// object it posted.
pub fn parse(text: &str) -> Result<Request, HostError> {
    let not_json = |e: serde_json::Error| HostError::NotJson(e.line(), e.column());
    let value: Value = serde_json::from_str(text).map_err(not_json)?;
    // A host that posted a JSON string of the object.
    let value = match value {
        Value::String(inner) => serde_json::from_str(&inner).map_err(not_json)?,
        other => other,
    };
    let Value::Object(message) = value else {
        return Err(HostError::NotOurs);
    };
    match message.get("api") {
        None => return Err(HostError::NotOurs),
        Some(v) if v.as_u64() == Some(API) => {}
        Some(v) => return Err(HostError::Version(v.to_string())),
    }
    let id = message.get("id").cloned();
    let kind = message
        .get("type")
        .and_then(Value::as_str)
        .ok_or(HostError::BadArgument("type", "host-must-string"))?;
    let action = action(kind, &message)?;
    Ok(Request { id, action })
}

/// The `id` of a message's text, if it has one (to answer a refused message by it).
pub fn id_of(text: &str) -> Option<Value> {
    let value: Value = serde_json::from_str(text).ok()?;
    let value = match value {
        Value::String(inner) => serde_json::from_str(&inner).ok()?,
        other => other,
    };
    value.get("id").cloned()
}

/// The action of a message of type `kind`.
fn action(kind: &str, m: &Map<String, Value>) -> Result<Action, HostError> {
    let text = |name: &'static str| {
        (m.get(name).and_then(Value::as_str))
            .map(str::to_string)
            .ok_or(HostError::BadArgument(name, "host-must-string"))
    };
    Ok(match kind {
        "set" => {
            let params = (m.get("params").and_then(Value::as_object))
                .filter(|p| !p.is_empty())
                .ok_or(HostError::BadArgument("params", "host-must-params"))?;
            let pairs = params.iter().map(|(k, v)| (k.clone(), v.clone())).collect();
            Action::Set(pairs)
        }
        "preset" => Action::Preset(text("id")?),
        "lab" => Action::Lab(text("id")?),
        "play" => Action::Play,
        "pause" => Action::Pause,
        "step" => Action::Step,
        "reset" => Action::Reset,
        "speed" => Action::Speed(
            (m.get("value").and_then(Value::as_f64))
                .filter(|v| v.is_finite() && *v > 0.0)
                .ok_or(HostError::BadArgument("value", "host-must-positive"))?,
        ),
        "lesson" => Action::Lesson(match m.get("step") {
            Some(Value::String(id)) => StepRef::Id(id.clone()),
            Some(n) => StepRef::Number(
                (n.as_u64().and_then(|n| usize::try_from(n).ok()))
                    .filter(|n| *n >= 1)
                    .ok_or(HostError::BadArgument("step", "host-must-step"))?,
            ),
            None => StepRef::Number(1),
        }),
        "answer" => Action::Answer(
            (m.get("choice").and_then(Value::as_u64))
                .and_then(|n| usize::try_from(n).ok())
                .filter(|n| *n >= 1)
                .ok_or(HostError::BadArgument("choice", "host-must-answer"))?,
        ),
        "get" => Action::Get,
        other => return Err(HostError::UnknownType(other.to_string())),
    })
}

/// The `type` of a request's action, as the host wrote it (for `ok` answers).
pub fn kind(action: &Action) -> &'static str {
    match action {
        Action::Set(_) => "set",
        Action::Preset(_) => "preset",
        Action::Lab(_) => "lab",
        Action::Play => "play",
        Action::Pause => "pause",
        Action::Step => "step",
        Action::Reset => "reset",
        Action::Speed(_) => "speed",
        Action::Lesson(_) => "lesson",
        Action::Answer(_) => "answer",
        Action::Get => "get",
    }
}

/// An event of type `kind` with `fields`, stamped with the API's version.
pub fn event(kind: &str, fields: Value) -> Value {
    let mut out = json!({ "api": API, "type": kind });
    if let (Value::Object(out), Value::Object(fields)) = (&mut out, fields) {
        out.extend(fields);
    }
    out
}

/// The answer to a request that was carried out.
pub fn ok(request: &Request) -> Value {
    event(
        "ok",
        json!({ "re": request.id.clone(), "request": kind(&request.action) }),
    )
}

/// The answer to a refused message (`id` when the message had one), in `lang`.
pub fn error(id: Option<Value>, e: &HostError, lang: attlab::i18n::Lang) -> Value {
    event(
        "error",
        json!({ "re": id, "code": e.code(), "message": e.words(lang) }),
    )
}

/// Whether a page of `origin` may drive a page of `own` origin whose link allows
/// `allowed` (`origin=` items; `*` allows every origin, `null` a page from a file).
pub fn allowed(origin: &str, own: &str, allowed: &[String]) -> bool {
    origin == own || allowed.iter().any(|a| a == "*" || a == origin)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn requests_parse_from_objects_and_strings() {
        let r = parse(r#"{"api":1,"type":"set","id":7,"params":{"gamma":0.002}}"#).unwrap();
        assert_eq!(r.id, Some(json!(7)));
        assert_eq!(r.action, Action::Set(vec![("gamma".into(), json!(0.002))]));
        let r = parse(r#""{\"api\":1,\"type\":\"lesson\",\"step\":\"upside-down\"}""#).unwrap();
        assert_eq!(r.action, Action::Lesson(StepRef::Id("upside-down".into())));
        assert_eq!(
            parse(r#"{"api":1,"type":"lesson","step":3}"#)
                .unwrap()
                .action,
            Action::Lesson(StepRef::Number(3))
        );
        assert_eq!(
            parse(r#"{"api":1,"type":"pause"}"#).unwrap().action,
            Action::Pause
        );
    }

    #[test]
    fn bad_messages_are_refused_with_their_code() {
        let code = |text: &str| parse(text).map(|_| ()).unwrap_err().code();
        assert_eq!(code("{nope"), "not-json");
        assert_eq!(code(r#"{"type":"play"}"#), "not-attlab");
        assert_eq!(code("[1,2]"), "not-attlab");
        assert_eq!(code(r#"{"api":2,"type":"play"}"#), "api-version");
        assert_eq!(code(r#"{"api":1,"type":"fly"}"#), "unknown-type");
        assert_eq!(code(r#"{"api":1}"#), "bad-argument");
        assert_eq!(
            code(r#"{"api":1,"type":"set","params":{}}"#),
            "bad-argument"
        );
        assert_eq!(
            code(r#"{"api":1,"type":"speed","value":-1}"#),
            "bad-argument"
        );
        assert_eq!(
            code(r#"{"api":1,"type":"lesson","step":0}"#),
            "bad-argument"
        );
        assert_eq!(
            code(r#"{"api":1,"type":"answer","choice":"b"}"#),
            "bad-argument"
        );
    }

    #[test]
    fn every_error_has_words_in_both_languages() {
        let all = [
            HostError::NotJson(1, 2),
            HostError::NotOurs,
            HostError::Version("2".into()),
            HostError::UnknownType("fly".into()),
            HostError::BadArgument("step", "host-must-step"),
            HostError::Param("why".into()),
            HostError::Locked("Gyro bias".into()),
            HostError::NoPreset("x".into()),
            HostError::NoLab("x".into()),
            HostError::NoLesson,
            HostError::NoStep("9".into()),
            HostError::NoQuestion,
            HostError::NoAnswer(5),
            HostError::Origin("http://evil.example".into()),
        ];
        for e in &all {
            for lang in [attlab::i18n::Lang::En, attlab::i18n::Lang::Ru] {
                let words = e.words(lang);
                assert!(
                    !words.contains("host-error") && !words.contains("{$"),
                    "{lang:?} {}: {words}",
                    e.code()
                );
            }
        }
    }

    #[test]
    fn origins_are_allowed_by_the_link_or_by_being_the_pages_own() {
        let own = "http://127.0.0.1:8080";
        assert!(allowed(own, own, &[]));
        assert!(!allowed("http://localhost:8080", own, &[]));
        let link = ["http://localhost:8080".to_string()];
        assert!(allowed("http://localhost:8080", own, &link));
        assert!(!allowed("http://localhost:9", own, &link));
        assert!(allowed("null", own, &["*".to_string()]));
    }
}
