//! The link part: the shareable fragment of the current state, kept in the address bar, and
//! a link pasted into the open tab loaded.

use super::{AppState, Effect};
use crate::platform;
use attlab::state::UrlState;

/// What the address bar said after the state's own last write.
#[derive(Clone, Debug, Default, PartialEq)]
pub(super) struct UrlSync {
    last_fragment: String,
    last_seen_fragment: String,
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
        }
        .encode()
    }

    /// Loads a link's fragment; its bad items become messages, the messages already shown
    /// stay, and so do where exports go and a log being picked.
    fn load_fragment(&mut self, fragment: &str) {
        self.sim.release_recorder();
        self.run.sweep = None;
        let mut next = Self::from_fragment(fragment);
        let mut kept = std::mem::take(&mut self.messages);
        kept.append(&mut next.messages);
        next.messages = kept;
        next.io.keep_from(&mut self.io);
        *self = next;
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
            platform::set_fragment(&fragment);
            self.url.last_seen_fragment = platform::current_fragment().unwrap_or_default();
            self.url.last_fragment = fragment;
        }
    }
}
