//! The live part: a phone's sensors or an Arduino over a serial port driving the lab's
//! estimators as the samples arrive. The samples go through the importer's rules
//! ([`attlab::sensors::live`]) into the replay's log, and the run steps onto each sample as
//! it becomes final — never waiting: a frame without data draws what there is. The sliders
//! keep working; the record saves as a log `attlab replay` reads to the same estimates.

use super::AppState;
use crate::live_io;
use attlab::i18n::{self, Lang};
use attlab::sensors::ImuScales;
use attlab::sensors::live::{LiveStream, PHONE_SCALES, phone_line, phone_to_body, zero_mount};
use attlab::sim::{SharedLog, SimOptions, Simulation};
use nalgebra::{UnitQuaternion, Vector3};
use std::collections::VecDeque;
use web_time::{Duration, Instant};

/// The rate the phone's sensors are asked for (Hz).
pub const PHONE_HZ: f64 = 60.0;
/// Baud rates offered for a serial port (115 200 is the usual MPU-6050 sketch's).
pub const BAUDS: [u32; 5] = [9600, 38400, 57600, 115_200, 230_400];
/// A stream silent this long is said to have stalled (once, until data come again).
const STALL: Duration = Duration::from_secs(2);
/// How many bad lines are said as messages (the rest are counted).
const SHOWN_ERRORS: usize = 12;

/// Where the samples come from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LiveSource {
    /// This device's gyro and accelerometer.
    Phone,
    /// A serial port at this baud rate.
    Serial(u32),
}

/// A live session.
pub struct LiveState {
    /// Where the samples come from.
    pub source: LiveSource,
    stream: LiveStream,
    log: SharedLog,
    /// The turn from the phone's body axes to the lab's ("zero").
    mount: UnitQuaternion<f64>,
    /// The last accelerometer reading in body axes before the mount (for "zero").
    last_accel_body_g: Option<Vector3<f64>>,
    /// Arrival times of the samples of the last second (the rate shown).
    arrivals: VecDeque<Instant>,
    last_data: Option<Instant>,
    stalled: bool,
    errors_said: usize,
    /// The browser API delivering.
    pub api: String,
    /// Still delivering.
    pub running: bool,
    /// The run is this session's (the replay of its log).
    bound: bool,
}

impl LiveState {
    /// Samples per second over the last second.
    pub fn rate_hz(&self) -> usize {
        self.arrivals.len()
    }

    /// Good lines recorded so far.
    pub fn recorded(&self) -> usize {
        self.stream.recorded_lines()
    }

    /// Lines rejected so far.
    pub fn rejected(&self) -> usize {
        self.stream.counts().rejected
    }

    /// Whether "zero" applies (the phone's samples are turned before they are recorded).
    pub fn can_zero(&self) -> bool {
        self.source == LiveSource::Phone && self.last_accel_body_g.is_some()
    }
}

/// What the live part does.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LiveCommand {
    /// Start this source (a tap: the browser may ask for permission or a port).
    Start(LiveSource),
    /// Take the pose held now as level (the phone).
    Zero,
    /// End the stream: the run and the record stay.
    Stop,
    /// Save the record as CSV.
    SaveRecord,
    /// Leave the session and simulate again.
    Leave,
}

impl AppState {
    /// The live session, if one is open.
    pub fn live(&self) -> Option<&LiveState> {
        self.live.as_ref()
    }

    pub(super) fn apply_live(&mut self, command: LiveCommand) {
        match command {
            LiveCommand::Start(source) => self.start_live(source),
            LiveCommand::Zero => {
                if let Some(live) = self.live.as_mut()
                    && let Some(a) = live.last_accel_body_g
                {
                    live.mount = zero_mount(a);
                    self.say("msg-live-zeroed", &[]);
                }
            }
            LiveCommand::Stop => self.stop_live(),
            LiveCommand::SaveRecord => self.save_live_record(),
            LiveCommand::Leave => {
                self.stop_live();
                self.live = None;
                let (lab, params) = (self.sim.lab(), self.sim.params().clone());
                self.restart(lab, params);
            }
        }
    }

    fn start_live(&mut self, source: LiveSource) {
        live_io::stop();
        let started = match source {
            LiveSource::Phone => live_io::start_phone(PHONE_HZ),
            LiveSource::Serial(baud) => live_io::start_serial(baud),
        };
        if let Err(why) = started {
            let why = live_reason(self.view.lang(), &why);
            return self.warn("msg-live-failed", &[("why", why.into())]);
        }
        let scales = match source {
            LiveSource::Phone => PHONE_SCALES,
            LiveSource::Serial(_) => self.serial_scales(),
        };
        self.live = Some(LiveState {
            source,
            stream: LiveStream::new(scales),
            log: SharedLog::default(),
            mount: UnitQuaternion::identity(),
            last_accel_body_g: None,
            arrivals: VecDeque::new(),
            last_data: None,
            stalled: false,
            errors_said: 0,
            api: String::new(),
            running: true,
            bound: false,
        });
        self.say("msg-live-waiting", &[]);
    }

    /// The serial stream's units: the log panel's unit choices for the lab's format.
    fn serial_scales(&self) -> ImuScales {
        match self.sim.lab().page().log_format {
            Some(format) => attlab::sensors::imu_scales(&self.io.units_for(format)),
            None => ImuScales::default(),
        }
    }

    fn stop_live(&mut self) {
        live_io::stop();
        self.take_live_data(Instant::now());
        if let Some(live) = self.live.as_mut()
            && !live.stream.ended()
        {
            live.stream.finish();
            live.running = false;
        }
        self.bind_and_step(Instant::now());
    }

    /// A frame of a live session: what arrived goes in, the run steps onto every sample
    /// that is final (within the frame's budget; the rest next frame).
    pub(super) fn advance_live(&mut self, now: Instant) {
        self.take_live_data(now);
        self.bind_and_step(now);
    }

    fn take_live_data(&mut self, now: Instant) {
        let Some(live) = self.live.as_mut() else {
            return;
        };
        if live.stream.ended() {
            return;
        }
        let polled = live_io::poll();
        if !polled.api.is_empty() {
            live.api.clone_from(&polled.api);
        }
        let before = live.stream.recorded_lines();
        for s in polled.samples.chunks_exact(8) {
            let (accel, gyro) = (
                Vector3::new(s[1], s[2], s[3]),
                Vector3::new(s[4], s[5], s[6]),
            );
            live.last_accel_body_g = Some(phone_to_body(accel));
            let line = phone_line(s[0], accel, gyro, s[7], &live.mount);
            live.stream.push_line(&line);
        }
        live.stream.push_bytes(&polled.bytes);
        let arrived = live.stream.recorded_lines() - before;
        live.arrivals.extend(std::iter::repeat_n(now, arrived));
        let second = Duration::from_secs(1);
        while live
            .arrivals
            .front()
            .is_some_and(|t| now.duration_since(*t) > second)
        {
            live.arrivals.pop_front();
        }
        if arrived > 0 || live.last_data.is_none() {
            live.last_data = Some(now);
            live.stalled = false;
        }
        let silent = live
            .last_data
            .is_some_and(|t| now.duration_since(t) > STALL);
        let stall = silent && !live.stalled && live.running;
        live.stalled |= stall;
        let ended = live.running && !polled.running;
        if ended {
            live.running = false;
            live.stream.finish();
        }
        let news = LiveNews {
            stall,
            dropped: polled.dropped,
            ended: ended
                .then(|| (polled.error).unwrap_or_else(|| live_io::LiveReason::new("stopped"))),
            note: polled.note,
        };
        self.say_live_news(news);
    }

    /// Says what happened to the stream: new bad lines (the first dozen), a stall, samples
    /// dropped while the page was not drawing, the end and why.
    fn say_live_news(&mut self, news: LiveNews) {
        let Some(live) = self.live.as_mut() else {
            return;
        };
        let errors = live.stream.errors();
        let lang = self.view.lang();
        let new_errors: Vec<String> = errors
            .iter()
            .skip(live.errors_said)
            .take(SHOWN_ERRORS.saturating_sub(live.errors_said))
            .map(|e| super::log_words::line_problem(lang, e))
            .collect();
        live.errors_said += new_errors.len();
        let (recorded, name) = (live.stream.recorded_lines(), self.live_name());
        for why in new_errors {
            self.warn(
                "msg-log-skipped",
                &[("name", name.as_str().into()), ("why", why.into())],
            );
        }
        if news.stall {
            self.warn("msg-live-stalled", &[("s", STALL.as_secs().into())]);
        }
        if news.dropped > 0 {
            self.warn("msg-live-dropped", &[("n", news.dropped.into())]);
        }
        if let Some(note) = news.note {
            self.info(live_reason(lang, &note));
        }
        if let Some(why) = news.ended {
            let args = [
                ("why", live_reason(lang, &why).into()),
                ("n", recorded.into()),
            ];
            self.warn("msg-live-ended", &args);
        }
    }

    /// The session's name in messages and the record's file name.
    fn live_name(&self) -> String {
        match self.live.as_ref().map(|l| l.source) {
            Some(LiveSource::Serial(_)) => "serial".into(),
            _ => "phone".into(),
        }
    }

    /// Hands the final samples to the run's log (the run becomes the session's replay at
    /// its second sample) and steps onto them within the frame's budget.
    fn bind_and_step(&mut self, now: Instant) {
        let Some(live) = self.live.as_mut() else {
            return;
        };
        live.log.append(&live.stream.take_new());
        if !live.bound && live.log.read().t_s.len() >= 2 {
            let (lab, params) = (self.sim.lab(), self.sim.params().clone());
            match Simulation::live(lab, params, live.log.clone(), SimOptions::default()) {
                Ok(mut sim) => {
                    live.bound = true;
                    self.drop_jobs();
                    self.end_travel();
                    sim.keep_history(attlab::sim::HISTORY_BUDGET_BYTES);
                    self.sim.release_recorder();
                    self.sim = sim;
                    self.run.sweep = None;
                    self.io.replaying = None;
                }
                Err(why) => return self.warn("msg-live-failed", &[("why", self.why(&why))]),
            }
        }
        if !self.live.as_ref().is_some_and(|l| l.bound) || !self.run.playing {
            return;
        }
        let mut steps = 0u32;
        while self.sim.can_step() {
            self.sim.step();
            steps += 1;
            if steps.is_multiple_of(16) && now.elapsed() > super::STEP_BUDGET {
                break;
            }
        }
    }

    /// Saves the record: the good lines as they came, after comments that say what it is
    /// and the command that replays it.
    fn save_live_record(&mut self) {
        let Some(live) = self.live.as_ref() else {
            return self.warn("msg-live-none", &[]);
        };
        let lab = self.sim.lab().id();
        let flags = scale_flags(live.stream.scales());
        let name = format!("attlab-{lab}-live-{}.csv", self.live_name());
        let about = format!(
            "Attitude Lab live session ({}, {}): {} good lines, {} rejected.\n\
             Replay: attlab replay --lab {lab} --log {name} {flags}",
            self.live_name(),
            live.api,
            live.stream.recorded_lines(),
            live.stream.counts().rejected,
        );
        let text = live.stream.record(&about);
        let n = live.stream.recorded_lines();
        let what = self.word("msg-live-record-saved", &[("n", n.into())]);
        self.save(&name, text.into_bytes(), Ok(what));
    }
}

/// What a frame of the stream brought that the user is told.
struct LiveNews {
    stall: bool,
    dropped: u64,
    ended: Option<live_io::LiveReason>,
    note: Option<live_io::LiveReason>,
}

/// A live source's reason in `lang`: its code's message with the browser's detail; a code
/// the catalogue lacks is said as the code and the detail.
pub fn live_reason(lang: Lang, why: &live_io::LiveReason) -> String {
    let id = format!("live-why-{}", why.code);
    if i18n::has(Lang::En, &id) {
        // A browser error without a message still fills the sentence.
        let detail = match why.detail.trim() {
            "" => i18n::t(lang, "live-no-detail"),
            d => d.to_string(),
        };
        i18n::t_with(lang, &id, &[("detail", detail.into())])
    } else if why.detail.is_empty() {
        why.code.clone()
    } else {
        format!("{}: {}", why.code, why.detail)
    }
}

/// The `attlab replay` flags of `scales`.
fn scale_flags(scales: ImuScales) -> String {
    fn name<U: PartialEq + Copy>(all: &[(U, &'static str)], unit: U) -> &'static str {
        all.iter().find(|(u, _)| *u == unit).map_or("", |(_, n)| *n)
    }
    let time = match scales.time {
        attlab::sensors::TimeUnit::Seconds => "s",
        attlab::sensors::TimeUnit::Milliseconds => "ms",
    };
    format!(
        "--accel-unit {} --gyro-unit {} --time-unit {time}",
        name(&attlab::sensors::AccelUnit::ALL, scales.accel),
        name(&attlab::sensors::GyroUnit::ALL, scales.gyro),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use live_io::LiveReason;

    /// The codes the page script reports (`L.fail('…'`, `L.say('…'`), and the page's own.
    fn codes() -> Vec<String> {
        let mut out: Vec<String> = ["L.fail('", "L.say('"]
            .iter()
            .flat_map(|call| live_io::GLUE.split(call).skip(1))
            .filter_map(|rest| rest.split('\'').next())
            .map(str::to_string)
            .collect();
        out.extend(["stopped", "script", "desktop-phone", "desktop-serial"].map(String::from));
        out.sort();
        out.dedup();
        out
    }

    /// The codes given with a detail: the script's calls with a second argument, and the
    /// page's own `script` (the script's failure).
    fn detailed_codes() -> Vec<String> {
        let mut out: Vec<String> = ["L.fail('", "L.say('"]
            .iter()
            .flat_map(|call| live_io::GLUE.split(call).skip(1))
            .filter_map(|rest| rest.split_once('\''))
            .filter(|(_, after)| after.starts_with(','))
            .map(|(code, _)| code.to_string())
            .collect();
        out.push("script".into());
        out
    }

    #[test]
    fn every_reason_the_script_gives_is_said_in_both_languages() {
        let codes = codes();
        assert!(codes.len() >= 12, "{codes:?}");
        for code in &codes {
            let why = LiveReason {
                code: code.clone(),
                detail: "NotAllowedError: xyz".into(),
            };
            let en = live_reason(Lang::En, &why);
            let ru = live_reason(Lang::Ru, &why);
            assert!(
                i18n::has(Lang::Ru, &format!("live-why-{code}")),
                "{code}: no Russian"
            );
            assert!(
                i18n::has(Lang::En, &format!("live-why-{code}")),
                "{code}: {en}"
            );
            assert!(ru.chars().any(|c| ('а'..='я').contains(&c)), "{code}: {ru}");
            assert!(
                !ru.contains('{') && !en.contains('{'),
                "{code}: {en} / {ru}"
            );
            // The browser's detail is said wherever the script (or the page) gives one.
            let detailed = detailed_codes().contains(code);
            assert_eq!(en.contains("xyz"), detailed, "{code}: {en}");
            assert_eq!(ru.contains("xyz"), detailed, "{code}: {ru}");
        }
    }

    #[test]
    fn a_reason_the_catalogue_lacks_is_said_as_given() {
        let why = LiveReason {
            code: "new-thing".into(),
            detail: "details".into(),
        };
        assert_eq!(live_reason(Lang::Ru, &why), "new-thing: details");
        assert_eq!(live_reason(Lang::En, &LiveReason::new("x")), "x");
        // A detail the browser left empty.
        let bare = LiveReason::new("no-port");
        assert_eq!(
            live_reason(Lang::En, &bare),
            "no port chosen (no detail given)"
        );
        assert_eq!(
            live_reason(Lang::En, &LiveReason::new("unplugged")),
            "the device was unplugged"
        );
    }
}
