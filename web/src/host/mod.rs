//! The host API: a page that embeds the lab in an `<iframe>` (a slide, a course page)
//! drives it by `postMessage` and hears what happens (docs/embed.md). [`protocol`] parses
//! and words the messages; this module checks each request against the state and turns it
//! into the app's own [`Command`]s, so a host can do nothing a reader's click could not (a
//! control the link locks stays locked), and builds the events; [`bridge`] is the browser's
//! side (a no-op on the desktop).

pub mod bridge;
pub mod protocol;

use crate::state::{AppState, Command, LessonCommand, RunCommand};
use attlab::i18n;
use protocol::{Action, HostError, StepRef, event};
use serde_json::{Map, Value, json};
use std::time::Duration;
use web_time::Instant;

/// How often a `tick` event reports the run (wall clock).
pub const TICK_EVERY: Duration = Duration::from_secs(1);

/// The app's commands that carry out `action` in `state`, or why it is refused (then
/// nothing changes: every value is checked before any is set).
pub fn commands(state: &AppState, action: &Action) -> Result<Vec<Command>, HostError> {
    let lab = state.sim().lab();
    let lang = state.view().lang();
    Ok(match action {
        Action::Set(pairs) => set(state, pairs)?,
        Action::Preset(id) => {
            let preset = lab.preset(id).ok_or(HostError::NoPreset(id.clone()))?;
            vec![RunCommand::ApplyPreset(preset.id).into()]
        }
        Action::Lab(id) => {
            let next = attlab::labs::find(id).ok_or(HostError::NoLab(id.clone()))?;
            vec![RunCommand::SelectLab(next).into()]
        }
        Action::Play => vec![RunCommand::SetPlaying(true).into()],
        Action::Pause => vec![RunCommand::SetPlaying(false).into()],
        Action::Step => vec![
            RunCommand::SetPlaying(false).into(),
            RunCommand::StepOnce.into(),
        ],
        Action::Reset => vec![RunCommand::Reset.into()],
        Action::Speed(v) => {
            let (lo, hi) = attlab::state::SPEED_RANGE;
            if !(lo..=hi).contains(v) {
                let why = i18n::t_with(
                    lang,
                    "link-fault-speed",
                    &[
                        ("lo", i18n::number(lang, &lo.to_string()).into()),
                        ("hi", i18n::number(lang, &hi.to_string()).into()),
                    ],
                );
                return Err(HostError::Param(why));
            }
            vec![RunCommand::SetSpeed(*v).into()]
        }
        Action::Lesson(step) => {
            let lesson = lab.lesson().ok_or(HostError::NoLesson)?;
            let n = match step {
                StepRef::Number(n) => Some(*n).filter(|n| lesson.step(*n).is_some()),
                StepRef::Id(id) => lesson.number_of(id),
            };
            let n = n.ok_or_else(|| {
                HostError::NoStep(match step {
                    StepRef::Number(n) => n.to_string(),
                    StepRef::Id(id) => id.clone(),
                })
            })?;
            vec![LessonCommand::Go(n).into()]
        }
        Action::Answer(k) => {
            let question = (state.lesson_step())
                .and_then(|s| s.question)
                .ok_or(HostError::NoQuestion)?;
            if *k > question.answers.len() {
                return Err(HostError::NoAnswer(*k));
            }
            vec![LessonCommand::Answer(*k).into()]
        }
        Action::Get => Vec::new(),
    })
}

/// `set`'s commands: each key a parameter of the lab whose control the link does not lock,
/// each value a number (or a choice's name) the slider accepts.
fn set(state: &AppState, pairs: &[(String, Value)]) -> Result<Vec<Command>, HostError> {
    let lab = state.sim().lab();
    let lang = state.view().lang();
    let specs = lab.params();
    let mut params = state.sim().params().clone();
    let mut out = Vec::new();
    for (key, value) in pairs {
        let set = match value {
            Value::Number(n) => params.set(specs, key, n.as_f64().unwrap_or(f64::NAN)),
            Value::String(text) => params.set_text(specs, key, text),
            _ => {
                let must = i18n::t(lang, "host-must-value");
                return Err(HostError::Param(format!("{key}: {must}")));
            }
        };
        set.map_err(|e| HostError::Param(i18n::errors::param_problem(lang, lab, specs, &e)))?;
        let Some(spec) = specs.iter().find(|s| s.key == key) else {
            continue;
        };
        if state.view().locks(spec.key) {
            let id = i18n::param_label_id(lab.id(), spec.key);
            return Err(HostError::Locked(i18n::lab_text(lang, &id, spec.label)));
        }
        out.push(RunCommand::SetParam(spec.key, params.get(spec.key)).into());
    }
    Ok(out)
}

/// What the lab is doing now, as the `ready` and `state` events report it.
pub fn snapshot(state: &AppState) -> Map<String, Value> {
    let sim = state.sim();
    let lab = sim.lab();
    let params: Map<String, Value> = (lab.params().iter())
        .filter_map(|p| Some((p.key.to_string(), json!(sim.params().try_get(p.key).ok()?))))
        .collect();
    let estimators: Vec<&str> = sim.estimators().iter().map(|e| e.id()).collect();
    let fields = json!({
        "lab": lab.id(),
        "t": sim.t_s(),
        "playing": state.run().playing,
        "speed": state.run().speed,
        "seed": state.run().seed,
        "lesson": state.lesson().map(|l| json!({
            "step": l.step,
            "id": state.lesson_step().map(|s| s.id),
            "steps": lab.lesson().map_or(0, |x| x.steps.len()),
        })),
        "params": params,
        "estimators": estimators,
        "version": env!("CARGO_PKG_VERSION"),
    });
    match fields {
        Value::Object(map) => map,
        _ => Map::new(),
    }
}

/// The `tick` event: the time and each estimator's attitude (or angle) error now, in
/// degrees, by its id (`null` where the run has no truth).
pub fn tick(state: &AppState) -> Value {
    let sim = state.sim();
    let errors: Map<String, Value> = (sim.estimators().iter().enumerate())
        .map(|(i, e)| {
            let error = (sim.glance(i))
                .map(|g| g.error_deg)
                .filter(|v| v.is_finite());
            (e.id().to_string(), json!(error))
        })
        .collect();
    event(
        "tick",
        json!({
            "lab": sim.lab().id(),
            "t": sim.t_s(),
            "playing": state.run().playing,
            "step": state.lesson().map(|l| l.step),
            "errors_deg": errors,
        }),
    )
}

/// The events that report the state as it changes: `ready` once, then a `tick` each
/// second and an `answered` for each question answered.
#[derive(Debug, Default)]
pub struct Reporter {
    /// The `ready` event went out.
    ready: bool,
    /// When the last tick went out.
    last_tick: Option<Instant>,
    /// The lab and the answers seen at the last report.
    answers: (String, Vec<(usize, usize)>),
}

impl Reporter {
    /// The events due at `now`.
    pub fn due(&mut self, state: &AppState, now: Instant) -> Vec<Value> {
        let mut out = Vec::new();
        let lab = state.sim().lab();
        let answers = state
            .lesson()
            .map(|l| l.answers.clone())
            .unwrap_or_default();
        if !self.ready {
            self.ready = true;
            out.push(event("ready", Value::Object(snapshot(state))));
        } else if self.answers.0 == lab.id() {
            for &(step, answer) in answers.iter().filter(|a| !self.answers.1.contains(a)) {
                let Some(s) = lab.lesson().and_then(|l| l.step(step)) else {
                    continue;
                };
                let supported = s.question.map(|q| q.answer + 1);
                out.push(event(
                    "answered",
                    json!({
                        "lab": lab.id(),
                        "step": step,
                        "id": s.id,
                        "answer": answer,
                        "supported": supported,
                    }),
                ));
            }
        }
        self.answers = (lab.id().to_string(), answers);
        if self
            .last_tick
            .is_none_or(|t| now.duration_since(t) >= TICK_EVERY)
        {
            self.last_tick = Some(now);
            out.push(tick(state));
        }
        out
    }
}

#[cfg(test)]
mod tests;

/// The host API in the frame loop: the bridge to the embedding page and the reporter.
#[derive(Default)]
pub struct HostLink {
    bridge: bridge::Bridge,
    reporter: Reporter,
}

impl HostLink {
    /// Starts listening for a host's messages (in the page).
    pub fn install(ctx: &egui::Context) -> Self {
        Self {
            bridge: bridge::Bridge::install(ctx),
            reporter: Reporter::default(),
        }
    }

    /// Carries out the requests that arrived, each answered with `ok` (or, for `get`, a
    /// `state` event) or an `error`.
    pub fn serve(&mut self, state: &mut AppState) {
        let own = self.bridge.own_origin();
        for message in self.bridge.take() {
            let lang = state.view().lang();
            let answer = if protocol::allowed(&message.origin, &own, &state.view().origins) {
                let request = (message.data.clone())
                    .ok_or(HostError::NotJson(0, 0))
                    .and_then(|text| protocol::parse(&text));
                match request {
                    Ok(request) => match commands(state, &request.action) {
                        Ok(list) => {
                            for c in list {
                                let _ = state.apply(c);
                            }
                            if request.action == Action::Get {
                                let mut fields = snapshot(state);
                                fields.insert("re".into(), request.id.clone().unwrap_or_default());
                                event("state", Value::Object(fields))
                            } else {
                                protocol::ok(&request)
                            }
                        }
                        Err(e) => protocol::error(request.id, &e, lang),
                    },
                    Err(e) => {
                        let id = message.data.as_deref().and_then(protocol::id_of);
                        protocol::error(id, &e, lang)
                    }
                }
            } else {
                protocol::error(None, &HostError::Origin(message.origin.clone()), lang)
            };
            self.bridge.answer(&message, &answer);
        }
    }

    /// Sends the events due at `now` to the embedding page, if the link allows it; while
    /// one hears them, `ctx` draws at least once per [`TICK_EVERY`] (a paused page draws
    /// only on input, and the ticks need a frame).
    pub fn report(&mut self, state: &AppState, now: Instant, ctx: &egui::Context) {
        let events = self.reporter.due(state, now);
        let own = self.bridge.own_origin();
        let origins = &state.view().origins;
        if (self.bridge).report(&events, |o| protocol::allowed(o, &own, origins)) {
            ctx.request_repaint_after(TICK_EVERY);
        }
    }
}
