//! The link part: the shareable fragment of the current state, kept in the address bar, and
//! a link pasted into the open tab loaded.

use super::{AppState, Effect};
use crate::platform;
use attlab::state::UrlState;

/// What the address bar said after the state's own last write, and where in the page it
/// was (the lab and the lesson step): moving to another place is a new history entry.
#[derive(Clone, Debug, Default, PartialEq)]
pub(super) struct UrlSync {
    last_fragment: String,
    last_seen_fragment: String,
    last_place: Option<Place>,
    /// History entries the writes added (the browser's Back walks them).
    entries_added: usize,
}

/// Where the reader is: the lab and the lesson step. Back and Forward walk these; a moved
/// slider or a paused run replaces the entry of the place it is in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Place {
    lab: &'static str,
    step: Option<usize>,
}

/// What the link part does.
#[derive(Clone, Debug, PartialEq)]
pub enum UrlCommand {
    /// Copy the link of the current state to the clipboard.
    CopyLink,
    /// Write the state into the address bar when it changed, or load a link the reader
    /// pasted there (the frame loop asks every frame).
    Sync,
    /// Load lab, seed, speed, presenter mode and parameters from a link's fragment.
    Load(String),
    /// Hide the link's bad items.
    DismissProblems,
}

impl AppState {
    pub(super) fn apply_url(&mut self, command: UrlCommand) -> Option<Effect> {
        match command {
            UrlCommand::CopyLink => {
                // The whole address, so the link opens the page from a chat or an e-mail.
                let page = platform::page_address().unwrap_or_default();
                return Some(Effect::Clipboard(format!("{page}#{}", self.fragment())));
            }
            UrlCommand::Sync => self.sync_url(),
            UrlCommand::Load(fragment) => self.load_fragment(&fragment),
            UrlCommand::DismissProblems => self.link_problems.clear(),
        }
        None
    }

    /// The shareable link fragment of the current state.
    pub fn fragment(&self) -> String {
        let (cursor_s, what_ifs) = self.travel_link();
        UrlState {
            lab_id: self.sim.lab().id(),
            seed: self.run.seed,
            speed: self.run.speed,
            params: self.sim.params().clone(),
            presenter: self.view.presenter,
            theme: self.view.theme,
            lang: self.view.lang,
            lesson: self.lesson.as_ref().map(super::LessonState::link),
            hide: self.view.hide.clone(),
            lock: self.view.lock.clone(),
            embed: self.view.embed,
            origins: self.view.origins.clone(),
            cursor_s,
            what_ifs,
        }
        .encode()
    }

    /// Loads a link's fragment; its bad items become messages, the messages already shown
    /// stay, and so do where exports go and a log being picked.
    fn load_fragment(&mut self, fragment: &str) {
        self.sim.release_recorder();
        self.run.sweep = None;
        let mut next = Self::from_fragment(fragment);
        // A control the page locks stays locked, at its value, whatever the new fragment
        // asks (a student editing the address bar): only a fresh page load takes a new lock.
        if next.sim.lab().id() == self.sim.lab().id() {
            next.keep_locks_of(self);
        }
        let mut kept = std::mem::take(&mut self.messages);
        kept.append(&mut next.messages);
        next.messages = kept;
        next.io.keep_from(&mut self.io);
        *self = next;
    }

    /// Locks what `before` locked, at `before`'s values, restarting the run if one of them
    /// differs.
    fn keep_locks_of(&mut self, before: &Self) {
        let specs = self.sim.lab().params();
        let locked: Vec<&'static str> = (specs.iter())
            .filter(|s| before.view.locks(s.key))
            .map(|s| s.key)
            .collect();
        let mut params = self.sim.params().clone();
        let mut held = Vec::new();
        for key in &locked {
            if !self.view.locks(key) {
                self.view.lock.push((*key).to_string());
            }
            let kept = before.sim.params().get(key);
            if params.get(key) != kept && params.set(specs, key, kept).is_ok() {
                held.push(*key);
            }
        }
        if !held.is_empty() {
            let tab = self.view.plots.tab;
            self.sim =
                super::run::simulation(self.sim.lab(), params, self.run.seed, tab, self.tiles());
            self.say_locked(&held);
        }
    }

    /// Writes the current state into the URL when it changed — or, when the reader changed
    /// the URL (a link pasted into the open tab), loads what it asks for.
    fn sync_url(&mut self) {
        // Compared with what the address bar said right after our own last write, so a
        // browser that spells our fragment differently cannot make us reload every frame.
        if let Some(now) = platform::current_fragment()
            && !self.url.last_fragment.is_empty()
            && now != self.url.last_seen_fragment
        {
            self.load_fragment(&now);
        }
        let fragment = self.fragment();
        if fragment != self.url.last_fragment {
            let place = Place {
                lab: self.sim.lab().id(),
                step: self.lesson.as_ref().map(|l| l.step),
            };
            // The first write after a load (the page's, a pasted link's, Back's) replaces.
            let moved = self.url.last_place.is_some_and(|p| p != place);
            platform::set_fragment(&fragment, moved);
            self.url.entries_added += usize::from(moved);
            self.url.last_seen_fragment = platform::current_fragment().unwrap_or_default();
            self.url.last_fragment = fragment;
            self.url.last_place = Some(place);
        }
    }

    /// How many history entries the address bar's writes have added since this state was
    /// loaded: one per lesson step or lab moved to (Back and Forward walk them).
    pub fn history_entries_added(&self) -> usize {
        self.url.entries_added
    }
}
