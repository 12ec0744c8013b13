//! The lesson part: which step of the lab's lesson is open, the answers chosen, and what a
//! step does to the run and the view. A step is absolute (see [`attlab::page::Lesson`]):
//! entering one restarts the run from t = 0 with the step's parameters, shows its tab and
//! filters at its speed, and pauses where it says, so every student sees the same picture.
//! A question step waits for an answer before it runs; the answer stays (in the link too).

use super::{AppState, run::simulation};
use attlab::model::{ParamValues, SeriesKey};
use attlab::page::LessonStep;
use attlab::page::default_tab;
use attlab::state::LessonLink;

/// The lesson under way.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct LessonState {
    /// The step shown (1-based).
    pub step: usize,
    /// Answers chosen: (step, answer), both 1-based, one per step.
    pub answers: Vec<(usize, usize)>,
}

impl LessonState {
    /// The answer chosen at `step`, if any (1-based).
    pub fn answer(&self, step: usize) -> Option<usize> {
        self.answers
            .iter()
            .find(|(s, _)| *s == step)
            .map(|(_, a)| *a)
    }

    /// As the link spells it.
    pub fn link(&self) -> LessonLink {
        LessonLink {
            step: self.step,
            answers: self.answers.clone(),
        }
    }
}

/// What the lesson part does.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LessonCommand {
    /// Open the lab's lesson at its first step.
    Start,
    /// Go to step n (1-based).
    Go(usize),
    /// Choose answer k (1-based) to the current step's question; the step then runs.
    Answer(usize),
    /// Leave the lesson (the run and the parameters stay as they are).
    Close,
}

impl AppState {
    /// The lesson under way, if any.
    pub fn lesson(&self) -> Option<&LessonState> {
        self.lesson.as_ref()
    }

    /// The values the step shows as tiles (none without a lesson): the page records them
    /// with the tab's series.
    pub fn tiles(&self) -> &'static [SeriesKey] {
        self.lesson_step().map_or(&[], |s| s.tiles)
    }

    /// The step shown, if a lesson is under way.
    pub fn lesson_step(&self) -> Option<&'static LessonStep> {
        let n = self.lesson.as_ref()?.step;
        self.sim.lab().lesson()?.step(n)
    }

    pub(super) fn apply_lesson(&mut self, command: LessonCommand) {
        match command {
            LessonCommand::Start => self.go_to_step(1, Vec::new()),
            LessonCommand::Go(n) => {
                let answers = self.lesson.take().map(|l| l.answers).unwrap_or_default();
                self.go_to_step(n, answers);
            }
            LessonCommand::Answer(k) => self.answer(k),
            LessonCommand::Close => {
                self.lesson = None;
                self.run.pause_at_s = None;
                self.view.hidden.clear();
                // The lab goes on from the last step's run (a question step had left it
                // paused at t = 0, its plot empty).
                self.run.playing = true;
            }
        }
    }

    /// Opens step `n` with its parameters, from t = 0.
    fn go_to_step(&mut self, n: usize, answers: Vec<(usize, usize)>) {
        let lab = self.sim.lab();
        let Some(step) = lab.lesson().and_then(|l| l.step(n)) else {
            return;
        };
        let mut params = match attlab::lessons::step_params(lab, step) {
            Ok(p) => p,
            Err(e) => {
                self.warn("msg-lesson-bad-step", &[("why", self.why(&e))]);
                return;
            }
        };
        // The teacher's lock wins over the step's values, and the page says so.
        let held = self.hold_locked(&mut params);
        self.say_locked(&held);
        self.lesson = Some(LessonState { step: n, answers });
        self.restart_with(params, step);
        if let Some(i) = step.sweep.and_then(|id| self.sim.lab().sweep_index(id)) {
            self.apply_run(super::RunCommand::RunSweep(i));
        }
    }

    /// A fresh run of the current lab with `params`, shown as `step` says.
    fn restart_with(&mut self, params: ParamValues, step: &LessonStep) {
        let lab = self.sim.lab();
        self.run.sweep = None;
        self.view.plots.tab = step.tab.unwrap_or_else(|| default_tab(lab));
        // The step is current, so the run records its tiles.
        self.restart(lab, params);
        self.run.reset_clock();
        self.show_step(step);
    }

    /// The view, speed and clock of `step` (the run itself as it is).
    pub(super) fn show_step(&mut self, step: &LessonStep) {
        let ids: Vec<&str> = self.sim.estimators().iter().map(|e| e.id()).collect();
        self.view.hidden = if step.show.is_empty() {
            Vec::new()
        } else {
            (0..ids.len())
                .filter(|i| !step.show.contains(&ids[*i]))
                .map(|i| i + 1)
                .collect()
        };
        // The 3D ghost shows the filter the step is about, the first of its tiles' or of the
        // filters it shows that has an attitude (it had stayed on the lab's first filter
        // while a step was about another).
        let estimates = self.sim.estimates();
        let about = (step.tiles.iter().map(|t| t.source)).chain(step.show.iter().copied());
        if let Some(i) = about
            .filter_map(|id| ids.iter().position(|e| *e == id))
            .find(|i| estimates.get(*i).is_some_and(|e| e.quaternion().is_some()))
        {
            self.view.ghost_index = i;
        }
        if let Some(speed) = step.speed {
            self.run.speed = speed;
        }
        self.run.pause_at_s = step.pause_at_s.filter(|t| *t > self.sim.t_s());
        // A question waits for its answer before the run shows it.
        let waiting = step.question.is_some()
            && self
                .lesson
                .as_ref()
                .is_some_and(|l| l.answer(l.step).is_none());
        self.run.playing = !waiting;
        // On a phone the card is in the controls' sheet: a question opens it to be answered.
        self.view.sheet_open = waiting;
    }

    /// Records answer `k` to the current step's question and runs the step.
    fn answer(&mut self, k: usize) {
        let Some(step) = self.lesson_step() else {
            return;
        };
        let Some(question) = step.question else {
            return;
        };
        if k == 0 || k > question.answers.len() {
            return;
        }
        let Some(lesson) = self.lesson.as_mut() else {
            return;
        };
        let n = lesson.step;
        lesson.answers.retain(|(s, _)| *s != n);
        lesson.answers.push((n, k));
        lesson.answers.sort_unstable();
        self.run.playing = true;
        // On a phone: the sheet gives the page back to the run that shows the answer.
        self.view.sheet_open = false;
    }

    /// Opens the link's lesson step on the state the link built (its parameters are the
    /// step's with the link's changes on top).
    pub(super) fn open_lesson_link(&mut self, link: &LessonLink) {
        let Some(step) = self.sim.lab().lesson().and_then(|l| l.step(link.step)) else {
            return;
        };
        self.lesson = Some(LessonState {
            step: link.step,
            answers: link.answers.clone(),
        });
        let tab = step.tab.unwrap_or_else(|| default_tab(self.sim.lab()));
        let recorded = step
            .tiles
            .iter()
            .all(|t| self.sim.specs().iter().any(|s| t.is(&s.name)));
        if tab != self.view.plots.tab || !recorded {
            self.view.plots.tab = tab;
            let params = self.sim.params().clone();
            self.sim = simulation(self.sim.lab(), params, self.run.seed, tab, step.tiles);
        }
        self.show_step(step);
        // As walked to: the step's sweep starts too (its text reports what it finds).
        if let Some(i) = step.sweep.and_then(|id| self.sim.lab().sweep_index(id)) {
            self.apply_run(super::RunCommand::RunSweep(i));
        }
    }

    /// Whether the run has reached the step's pause (shows the answer to its question).
    pub fn lesson_revealed(&self) -> bool {
        let Some(lesson) = &self.lesson else {
            return false;
        };
        let Some(step) = self.lesson_step() else {
            return false;
        };
        lesson.answer(lesson.step).is_some()
            && step
                .pause_at_s
                .is_none_or(|t| self.sim.t_s() >= t - 0.5 * self.sim.dt_s())
    }
}
