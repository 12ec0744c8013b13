//! The app's state and the one place that changes it. Panels read [`AppState`] and emit
//! [`Command`]s; [`AppState::apply`] carries them out after the frame is drawn. The state is
//! in parts, each owning its commands: the run ([`RunCommand`]: the simulation, the clock,
//! sweeps, jobs), the view ([`ViewCommand`]: tab, focus, hidden sources, presenter mode), I/O
//! ([`IoCommand`]: logs, exports) and the link ([`UrlCommand`]). Nothing outside `apply`
//! changes it: the parts are read
//! through `&` accessors, and what the app must do outside the state (copy to the
//! clipboard, make a PNG) comes back from `apply` as an [`Effect`].
//!
//! View state that only a widget cares about (camera angles, the sphere's orientation)
//! lives in [`View`] and is handed `&mut` to the widget that owns it, as egui does with a
//! slider's value.

mod io;
mod jobs;
mod lesson;
mod link_words;
mod live;
mod log_words;
mod pool;
mod run;
mod share;
mod slicer;
mod travel;
mod url;
mod view;

pub use io::{IoCommand, IoState};
pub use jobs::Job;
pub use lesson::{LessonCommand, LessonState};
pub use link_words::link_problem;
pub use live::{BAUDS, LiveCommand, LiveSource, LiveState};
pub use pool::SweepTiming;
pub use run::{MAX_FRAME_S, RunCommand, RunState, STEP_BUDGET, SWEEP_BUDGET};
pub use share::{QrModules, ShareCommand, ShareOptions, qr};
pub use travel::{Cursor, MAX_BRANCHES, Plan, TravelCommand, TravelState, branch_words};
pub use url::UrlCommand;
pub use view::{Focus, ViewCommand, ViewState, view_selection};

use crate::render::{body3d, riemann_sphere, single_axis};
use attlab::model::ParamValues;
use attlab::page::Lab;
use attlab::sim::Simulation;
use attlab::state::UrlState;

/// A message for the user (bad URL item, export result, divergence).
#[derive(Clone, Debug, PartialEq)]
pub struct Message {
    /// Text shown.
    pub text: String,
    /// Shown in red.
    pub is_error: bool,
    /// How many times it was said in a row (the same preset pressed five times is one
    /// line, "×5").
    pub times: usize,
}

impl Message {
    /// An error message.
    pub fn error(text: impl Into<String>) -> Self {
        Self {
            text: text.into(),
            is_error: true,
            times: 1,
        }
    }

    /// An information message.
    pub fn info(text: impl Into<String>) -> Self {
        Self {
            text: text.into(),
            is_error: false,
            times: 1,
        }
    }
}

/// What a panel (or the frame loop) asks the state to do, applied in order: a command of
/// one of the parts, or a message to show.
#[derive(Clone)]
pub enum Command {
    /// The run: lab, parameters, clock, sweeps.
    Run(RunCommand),
    /// What is shown and how.
    View(ViewCommand),
    /// Logs and exports.
    Io(IoCommand),
    /// The link.
    Url(UrlCommand),
    /// The lesson.
    Lesson(LessonCommand),
    /// The share dialog.
    Share(ShareCommand),
    /// Live sensors.
    Live(LiveCommand),
    /// The timeline and the branches.
    Travel(TravelCommand),
    /// Show this message.
    Notify(Message),
    /// Remove message `i`.
    Dismiss(usize),
}

impl From<RunCommand> for Command {
    fn from(c: RunCommand) -> Self {
        Self::Run(c)
    }
}

impl From<ViewCommand> for Command {
    fn from(c: ViewCommand) -> Self {
        Self::View(c)
    }
}

impl From<IoCommand> for Command {
    fn from(c: IoCommand) -> Self {
        Self::Io(c)
    }
}

impl From<LessonCommand> for Command {
    fn from(c: LessonCommand) -> Self {
        Self::Lesson(c)
    }
}

impl From<ShareCommand> for Command {
    fn from(c: ShareCommand) -> Self {
        Self::Share(c)
    }
}

impl From<LiveCommand> for Command {
    fn from(c: LiveCommand) -> Self {
        Self::Live(c)
    }
}

impl From<TravelCommand> for Command {
    fn from(c: TravelCommand) -> Self {
        Self::Travel(c)
    }
}

impl From<UrlCommand> for Command {
    fn from(c: UrlCommand) -> Self {
        Self::Url(c)
    }
}

/// What the app must do outside the state after a command.
#[derive(Clone, Debug, PartialEq)]
pub enum Effect {
    /// Put this text on the clipboard.
    Clipboard(String),
    /// Make a PNG of this (the app captures it over the next frames).
    Png(PngTarget),
}

/// What a PNG export shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PngTarget {
    /// The lab's view with this index (in `Page::views`).
    View(usize),
    /// Every plot tab, one below the other.
    Plots,
}

/// Widget-owned view state: the camera and the sphere change by dragging; the phase
/// trails remember what the views drew (never read by the simulation).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct View {
    /// 3D camera.
    pub camera: body3d::OrbitCamera,
    /// Sphere orientation.
    pub sphere: riemann_sphere::SphereView,
    /// Phase-portrait trails of a single-axis lab.
    pub trails: single_axis::PhaseTrails,
}

/// Everything the panels read.
pub struct AppState {
    sim: Simulation,
    run: RunState,
    view: ViewState,
    io: IoState,
    url: url::UrlSync,
    messages: Vec<Message>,
    /// The bad items of the link the page opened with, in words (shown at the top until
    /// dismissed).
    link_problems: Vec<String>,
    /// The lesson under way, if any.
    lesson: Option<LessonState>,
    /// The share dialog's choices, while it is open.
    share: Option<ShareOptions>,
    /// A live session (a phone's sensors, a serial port), while one is open.
    live: Option<LiveState>,
    /// The timeline's cursor and the branches.
    travel: TravelState,
}

impl AppState {
    /// A state for `lab` with `params`, `seed` and `speed`.
    pub fn new(lab: &'static dyn Lab, params: ParamValues, seed: u64, speed: f64) -> Self {
        let view = ViewState::for_lab(lab);
        Self {
            sim: run::simulation(lab, params, seed, view.plots.tab, &[]),
            run: RunState::new(seed, speed),
            view,
            io: IoState::default(),
            url: url::UrlSync::default(),
            messages: Vec::new(),
            link_problems: Vec::new(),
            lesson: None,
            share: None,
            live: None,
            travel: TravelState::default(),
        }
    }

    /// The state a URL fragment asks for; its bad items become messages.
    pub fn from_fragment(fragment: &str) -> Self {
        let (url, errors) = UrlState::parse(fragment);
        let lab = attlab::labs::find(url.lab_id).unwrap_or(attlab::labs::all()[0]);
        let mut state = Self::new(lab, url.params, url.seed, url.speed);
        state.view.presenter = url.presenter;
        state.view.theme = url.theme;
        state.view.lang = url.lang;
        state.view.browser_lang = crate::platform::browser_lang();
        let lang = state.view.lang();
        state.link_problems = errors.iter().map(|e| link_problem(lang, lab, e)).collect();
        state.view.hide = url.hide;
        state.view.lock = url.lock;
        state.view.embed = url.embed;
        state.view.origins = url.origins;
        if let Some(link) = &url.lesson {
            state.open_lesson_link(link);
        }
        state.plan_travel(url.cursor_s, url.what_ifs);
        state
    }

    /// The running simulation.
    pub fn sim(&self) -> &Simulation {
        &self.sim
    }

    /// The run: seed, clock, speed, statistics, the sweep.
    pub fn run(&self) -> &RunState {
        &self.run
    }

    /// What is shown and how.
    pub fn view(&self) -> &ViewState {
        &self.view
    }

    /// Logs and exports.
    pub fn io(&self) -> &IoState {
        &self.io
    }

    /// The bad items of the link the page opened with, in words.
    pub fn link_problems(&self) -> &[String] {
        &self.link_problems
    }

    /// Messages, oldest first.
    pub fn messages(&self) -> &[Message] {
        &self.messages
    }

    /// Carries out one command: the only place the app's state changes. Returns what the
    /// app must do outside the state, if anything.
    pub fn apply(&mut self, command: Command) -> Option<Effect> {
        match command {
            Command::Run(c) => self.apply_run(c),
            Command::View(c) => self.apply_view(c),
            Command::Io(c) => return self.apply_io(c),
            Command::Url(c) => return self.apply_url(c),
            Command::Lesson(c) => self.apply_lesson(c),
            Command::Share(c) => return self.apply_share(c),
            Command::Live(c) => self.apply_live(c),
            Command::Travel(c) => self.apply_travel(c),
            Command::Notify(m) => self.notify(m),
            Command::Dismiss(i) => {
                if i < self.messages.len() {
                    self.messages.remove(i);
                }
            }
        }
        None
    }

    /// Shows `message`, or counts it once more when it repeats the last one.
    fn notify(&mut self, message: Message) {
        match self.messages.last_mut() {
            Some(last) if last.text == message.text && last.is_error == message.is_error => {
                last.times += message.times;
            }
            _ => self.messages.push(message),
        }
    }

    fn info(&mut self, text: impl Into<String>) {
        self.notify(Message::info(text));
    }

    fn error(&mut self, text: impl Into<String>) {
        self.notify(Message::error(text));
    }

    /// The page's message `id` in the reader's language.
    fn word(&self, id: &str, args: &[(&str, attlab::i18n::FluentValue<'_>)]) -> String {
        attlab::i18n::t_with(self.view.lang(), id, args)
    }

    /// An information message from the catalogue.
    fn say(&mut self, id: &str, args: &[(&str, attlab::i18n::FluentValue<'_>)]) {
        let text = self.word(id, args);
        self.info(text);
    }

    /// An error message from the catalogue.
    fn warn(&mut self, id: &str, args: &[(&str, attlab::i18n::FluentValue<'_>)]) {
        let text = self.word(id, args);
        self.error(text);
    }

    /// A failure in the reader's language and the lab's words, for a message's `why`.
    fn why(&self, e: &dyn attlab::i18n::errors::Worded) -> attlab::i18n::FluentValue<'static> {
        e.words(self.view.lang(), self.sim.lab()).into()
    }
}
