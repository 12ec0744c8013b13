//! The time-travel part: the timeline's cursor (a moment of the run shown again) and the
//! "what if" branches run beside the main run. The run keeps its snapshots
//! (`Simulation::keep_history`); a seek restores one and steps on to the cursor, a branch
//! does the same and runs on with the sliders moved at the cursor. Both advance within the
//! frame's budget, a slice at a time.

use super::AppState;
use attlab::sim::{Branch, Seek, Selection, SimOptions, Simulation, TravelError};
use attlab::state::WhatIfLink;
use web_time::{Duration, Instant};

/// At most this many branches beside the main run.
pub const MAX_BRANCHES: usize = 3;

/// What a branch records (its own recorder, beside the main run's).
const BRANCH_BUDGET_BYTES: usize = 4 << 20;

/// Wall time per frame given to a seek or to branches catching up.
const TRAVEL_BUDGET: Duration = Duration::from_millis(10);

/// The moment the timeline's cursor shows, while it is off "now".
pub struct Cursor {
    seek: Seek,
    /// The sliders moved at the cursor: a "what if" made now would use them.
    pub changes: Vec<(&'static str, f64)>,
    /// Whether the run was playing when the cursor left "now" ("Live" brings that back).
    was_playing: bool,
}

impl Cursor {
    /// The run at the cursor (once the seek is there; on its way before).
    pub fn sim(&self) -> &Simulation {
        self.seek.sim()
    }

    /// The moment asked for (s).
    pub fn t_s(&self) -> f64 {
        self.seek.target_s()
    }

    /// Whether the shown state is at the moment yet.
    pub fn ready(&self) -> bool {
        self.seek.done()
    }
}

/// Time travel's state.
#[derive(Default)]
pub struct TravelState {
    /// The cursor, when it is off now.
    pub cursor: Option<Cursor>,
    /// The branches, oldest first.
    pub branches: Vec<Branch>,
    /// What a link asked for and the run has not reached yet: the run goes there as fast
    /// as the frame's budget allows, then branches and seeks.
    pub plan: Option<Plan>,
}

/// A link's cursor and branches, waiting for the run to reach them.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Plan {
    /// The cursor (s).
    pub cursor_s: Option<f64>,
    /// The branches.
    pub what_ifs: Vec<WhatIfLink>,
}

impl Plan {
    /// The time the run must reach (s).
    pub fn target_s(&self) -> f64 {
        (self.what_ifs.iter().map(|w| w.at_s))
            .chain(self.cursor_s)
            .fold(0.0, f64::max)
    }
}

/// What the timeline and the branch chips ask for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TravelCommand {
    /// Show the run at this moment (s); the run pauses.
    Seek(f64),
    /// Move the cursor by this many seconds (negative: back); a step when 0 is given as
    /// `StepFrames`.
    Nudge(f64),
    /// Move the cursor by this many of the run's steps.
    StepFrames(i64),
    /// Back to now; the run plays again if it was playing.
    Live,
    /// Start a branch at the cursor with the sliders moved there.
    WhatIf,
    /// Remove branch `i`.
    Drop(usize),
    /// Make branch `i` the main run (re-run from t = 0 as a job).
    Promote(usize),
}

impl AppState {
    /// The run the views show: the one at the timeline's cursor, or the main run.
    pub fn shown(&self) -> &Simulation {
        self.travel.cursor.as_ref().map_or(&self.sim, Cursor::sim)
    }

    /// The values the sliders show: the run's, or at the cursor the values the run had
    /// there with the sliders moved since (what "What if…" would use).
    pub fn slider_params(&self) -> std::borrow::Cow<'_, attlab::model::ParamValues> {
        let Some(cursor) = &self.travel.cursor else {
            return std::borrow::Cow::Borrowed(self.sim.params());
        };
        let mut params = cursor.sim().params().clone();
        let specs = self.sim.lab().params();
        for (key, value) in &cursor.changes {
            let _ = params.set(specs, key, *value);
        }
        std::borrow::Cow::Owned(params)
    }

    /// Time travel's state.
    pub fn travel(&self) -> &TravelState {
        &self.travel
    }

    pub(super) fn apply_travel(&mut self, command: TravelCommand) {
        match command {
            TravelCommand::Seek(t) => self.seek_to(t),
            TravelCommand::Nudge(ds) => {
                let t = self.cursor_t() + ds;
                self.seek_to(t);
            }
            TravelCommand::StepFrames(k) => {
                let t = self.cursor_t() + k as f64 * self.sim.dt_s();
                self.seek_to(t);
            }
            TravelCommand::Live => self.go_live(),
            TravelCommand::WhatIf => self.what_if(),
            TravelCommand::Drop(i) if i < self.travel.branches.len() => {
                self.travel.branches.remove(i);
            }
            TravelCommand::Promote(i) if i < self.travel.branches.len() => self.promote(i),
            TravelCommand::Drop(_) | TravelCommand::Promote(_) => {}
        }
    }

    /// Whether time travel has work for the next frames (a seek, a branch catching up, a
    /// link's plan): the page keeps drawing while it has, paused or not.
    pub fn travel_busy(&self) -> bool {
        let travel = &self.travel;
        travel.plan.is_some()
            || travel.cursor.as_ref().is_some_and(|c| !c.ready())
            || (travel.branches.iter()).any(|b| b.sim().steps() < self.sim.steps())
    }

    /// The cursor's time, or now.
    pub fn cursor_t(&self) -> f64 {
        self.travel
            .cursor
            .as_ref()
            .map_or(self.sim.t_s(), Cursor::t_s)
    }

    fn seek_to(&mut self, t: f64) {
        let now = self.sim.t_s();
        if t >= now - 0.5 * self.sim.dt_s() {
            return self.go_live();
        }
        let first = self.sim.history_start_s().unwrap_or(0.0);
        let t = t.max(first);
        match self.sim.seek(t) {
            Ok(mut seek) => {
                seek.advance(&self.sim, 0);
                let (was_playing, changes) = match self.travel.cursor.take() {
                    Some(c) => (c.was_playing, c.changes),
                    None => (self.run.playing, Vec::new()),
                };
                self.run.playing = false;
                self.travel.cursor = Some(Cursor {
                    seek,
                    changes,
                    was_playing,
                });
                self.advance_travel(TRAVEL_BUDGET);
            }
            Err(e) => self.travel_problem(&e),
        }
    }

    fn go_live(&mut self) {
        if let Some(c) = self.travel.cursor.take() {
            self.run.playing = c.was_playing;
            self.run.reset_clock();
        }
    }

    /// A slider moved while the cursor is off now: kept for the next "what if" (the main
    /// run does not change). Returns false when the cursor is at now.
    pub(super) fn change_at_cursor(&mut self, key: &'static str, value: f64) -> bool {
        let Some(cursor) = self.travel.cursor.as_mut() else {
            return false;
        };
        cursor.changes.retain(|(k, _)| *k != key);
        cursor.changes.push((key, value));
        true
    }

    fn what_if(&mut self) {
        let Some(cursor) = self.travel.cursor.as_ref() else {
            return;
        };
        if self.travel.branches.len() >= MAX_BRANCHES {
            return self.warn("msg-branch-full", &[("most", (MAX_BRANCHES as i64).into())]);
        }
        let options = SimOptions {
            selection: Selection::Standard,
            budget_bytes: BRANCH_BUDGET_BYTES,
        };
        let changes: Vec<(&str, f64)> = cursor.changes.clone();
        match self.sim.branch(cursor.t_s(), &changes, options) {
            Ok(branch) => {
                self.travel.branches.push(branch);
                self.go_live();
            }
            Err(e) => self.travel_problem(&e),
        }
    }

    fn promote(&mut self, i: usize) {
        let budget = self.sim.options().budget_bytes;
        let history = attlab::sim::HISTORY_BUDGET_BYTES;
        let branch = self.travel.branches.remove(i);
        let selection = self.sim.options().selection.clone();
        match branch.rerun_job(selection, budget, history) {
            Ok(job) => {
                self.end_travel();
                self.start_promote(job);
            }
            Err(e) => self.warn("msg-plot-failed", &[("why", self.why(&e))]),
        }
    }

    fn travel_problem(&mut self, e: &TravelError) {
        let why = self.why(e);
        self.warn("msg-travel-failed", &[("why", why)]);
    }

    /// Moves the seek and the branches on within `budget` of wall time: the seek first
    /// (the reader is waiting for it), then each branch up to the main run.
    pub(super) fn advance_travel(&mut self, budget: Duration) {
        let start = Instant::now();
        let left = |start: Instant| budget.checked_sub(start.elapsed());
        if let Some(c) = self.travel.cursor.as_mut() {
            while !c.seek.done() && left(start).is_some() {
                c.seek.advance(&self.sim, 32);
            }
        }
        for b in &mut self.travel.branches {
            while b.sim().steps() < self.sim.steps() && left(start).is_some() {
                b.advance(&self.sim, 32);
            }
        }
    }

    /// Branches and the cursor end with the run they belong to (a reset, a new lab, a log).
    pub(super) fn end_travel(&mut self) {
        self.travel = TravelState::default();
    }

    /// The cursor and the branches as a link holds them (a plan not reached yet as it is).
    pub(super) fn travel_link(&self) -> (Option<f64>, Vec<WhatIfLink>) {
        if let Some(plan) = &self.travel.plan {
            return (plan.cursor_s, plan.what_ifs.clone());
        }
        let what_ifs = (self.travel.branches.iter())
            .map(|b| WhatIfLink {
                at_s: b.from_s(),
                changes: b.changes().to_vec(),
            })
            .collect();
        (self.travel.cursor.as_ref().map(Cursor::t_s), what_ifs)
    }

    /// Takes a link's cursor and branches: the run goes to them first.
    pub(super) fn plan_travel(&mut self, cursor_s: Option<f64>, what_ifs: Vec<WhatIfLink>) {
        if cursor_s.is_some() || !what_ifs.is_empty() {
            self.travel.plan = Some(Plan { cursor_s, what_ifs });
        }
    }

    /// Brings the run toward a link's plan within `budget`; once there, starts its branches
    /// and seeks to its cursor. Returns true while a plan is under way (the run holds its
    /// clock meanwhile).
    pub(super) fn follow_plan(&mut self, budget: Duration) -> bool {
        let Some(target) = self.travel.plan.as_ref().map(Plan::target_s) else {
            return false;
        };
        let start = Instant::now();
        while self.sim.t_s() < target - 0.5 * self.sim.dt_s() && self.sim.can_step() {
            self.sim.step();
            if self.sim.steps().is_multiple_of(16) && start.elapsed() > budget {
                return true;
            }
        }
        let Some(plan) = self.travel.plan.take() else {
            return false;
        };
        for w in &plan.what_ifs {
            let changes = w.changes.clone();
            self.travel.cursor = self.sim.seek(w.at_s).ok().map(|seek| Cursor {
                seek,
                changes,
                was_playing: self.run.playing,
            });
            self.what_if();
        }
        // The link's moment: shown on the timeline, the run paused there (at now when the
        // run stopped on it).
        if let Some(t) = plan.cursor_s {
            self.run.playing = false;
            self.seek_to(t);
        }
        self.run.reset_clock();
        true
    }
}

/// Keys of a branch's changes in words, for its chip: "ST outage: 0".
pub fn branch_words(app: &AppState, branch: &Branch) -> String {
    let lab = app.sim().lab();
    let lang = app.view().lang();
    let changes: Vec<String> = branch
        .changes()
        .iter()
        .map(|(key, value)| attlab::i18n::errors::param_at(lang, lab, key, *value))
        .collect();
    if changes.is_empty() {
        attlab::i18n::t(lang, "branch-no-change")
    } else {
        changes.join(", ")
    }
}
