//! The share part: the teacher's link for the current state or the lesson step, with
//! controls hidden or locked and presenter mode chosen, and its QR code for the class's
//! phones. The dialog's choices live here while it is open; the link is built from the same
//! [`UrlState`] the address bar holds, so it opens exactly what it says.

use super::AppState;
use crate::platform;
use attlab::state::{ALL_CONTROLS, UrlState};

/// What the teacher chose in the share dialog.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct ShareOptions {
    /// The link opens the lesson step from its start, without the changes made since.
    pub from_step: bool,
    /// The link opens in presenter mode.
    pub presenter: bool,
    /// The link carries the answers chosen so far (a student sends theirs to the teacher).
    pub answers: bool,
    /// Parameters whose controls the link hides (or [`ALL_CONTROLS`]).
    pub hide: Vec<&'static str>,
    /// Parameters whose controls the link locks (or [`ALL_CONTROLS`]).
    pub lock: Vec<&'static str>,
}

/// What the share part does.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ShareCommand {
    /// Open the dialog with the page's current choices.
    Open,
    /// Close it.
    Close,
    /// Copy the link to the clipboard.
    Copy,
    /// Copy the `<iframe>` snippet that embeds the link in a slide or a course page.
    CopyEmbed,
    /// Link the lesson step from its start (or the state as it is now).
    FromStep(bool),
    /// Open the link in presenter mode.
    Presenter(bool),
    /// Carry the answers chosen so far.
    Answers(bool),
    /// Hide (or show) the control of this parameter (or every one, [`ALL_CONTROLS`]).
    Hide(&'static str, bool),
    /// Lock (or unlock) it.
    Lock(&'static str, bool),
}

/// A QR code as modules: `width` × `width`, row by row, `true` dark (no quiet zone).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct QrModules {
    /// Modules per side.
    pub width: usize,
    /// Dark or light, row by row.
    pub dark: Vec<bool>,
}

/// Why a link has no QR code.
#[derive(Clone, Debug, PartialEq)]
pub enum QrError {
    /// The link is longer than a QR code holds.
    TooLong {
        /// The link's length in bytes.
        bytes: usize,
    },
    /// The encoder's other refusals (its own words; none can happen for a link's bytes).
    Other {
        /// What the encoder said.
        detail: String,
    },
}

impl QrError {
    /// The reason in `lang`.
    pub fn words(&self, lang: attlab::i18n::Lang) -> String {
        use attlab::i18n::t_with;
        match self {
            QrError::TooLong { bytes } => {
                t_with(lang, "error-qr-too-long", &[("bytes", (*bytes).into())])
            }
            QrError::Other { detail } => {
                t_with(lang, "error-qr-other", &[("detail", detail.clone().into())])
            }
        }
    }
}

/// The QR code of `text` (error correction level M), or why it cannot be made.
pub fn qr(text: &str) -> Result<QrModules, QrError> {
    let code = qrcode::QrCode::new(text.as_bytes()).map_err(|e| match e {
        qrcode::types::QrError::DataTooLong => QrError::TooLong { bytes: text.len() },
        other => QrError::Other {
            detail: other.to_string(),
        },
    })?;
    let dark = code
        .to_colors()
        .into_iter()
        .map(|c| c == qrcode::Color::Dark)
        .collect();
    Ok(QrModules {
        width: code.width(),
        dark,
    })
}

fn toggle(list: &mut Vec<&'static str>, key: &'static str, on: bool) {
    list.retain(|k| *k != key);
    if on {
        list.push(key);
    }
}

impl AppState {
    /// The share dialog's choices, while it is open.
    pub fn share(&self) -> Option<&ShareOptions> {
        self.share.as_ref()
    }

    pub(super) fn apply_share(&mut self, command: ShareCommand) -> Option<super::Effect> {
        if command == ShareCommand::Open {
            let keys = |list: &[String]| {
                let lab = self.sim.lab();
                list.iter()
                    .filter_map(|k| {
                        (k == ALL_CONTROLS)
                            .then_some(ALL_CONTROLS)
                            .or_else(|| lab.params().iter().find(|p| p.key == k).map(|p| p.key))
                    })
                    .collect()
            };
            self.share = Some(ShareOptions {
                from_step: false,
                presenter: self.view.presenter,
                // A teacher's link goes to the class: its questions unanswered unless the
                // teacher (or a student sending theirs back) ticks the box.
                answers: false,
                hide: keys(&self.view.hide),
                lock: keys(&self.view.lock),
            });
            return None;
        }
        if command == ShareCommand::Copy {
            return self
                .share
                .as_ref()
                .map(|o| super::Effect::Clipboard(self.share_link(o)));
        }
        if command == ShareCommand::CopyEmbed {
            return self
                .share
                .as_ref()
                .map(|o| super::Effect::Clipboard(self.share_embed(o)));
        }
        let o = self.share.as_mut()?;
        match command {
            ShareCommand::Open | ShareCommand::Copy | ShareCommand::CopyEmbed => {}
            ShareCommand::Close => self.share = None,
            ShareCommand::FromStep(on) => o.from_step = on,
            ShareCommand::Presenter(on) => o.presenter = on,
            ShareCommand::Answers(on) => o.answers = on,
            ShareCommand::Hide(key, on) => toggle(&mut o.hide, key, on),
            ShareCommand::Lock(key, on) => toggle(&mut o.lock, key, on),
        }
        None
    }

    /// The link fragment the share dialog's choices make of the current state.
    pub fn share_fragment(&self, options: &ShareOptions) -> String {
        let lab = self.sim.lab();
        let lesson = self.lesson.as_ref().map(|l| {
            let mut link = l.link();
            if !options.answers {
                link.answers.clear();
            }
            link
        });
        let params = match (&lesson, options.from_step) {
            (Some(link), true) => attlab::state::base_params(lab, Some(link)),
            _ => self.sim.params().clone(),
        };
        let owned = |list: &[&'static str]| list.iter().map(|k| k.to_string()).collect();
        let (cursor_s, what_ifs) = self.travel_link();
        UrlState {
            lab_id: lab.id(),
            seed: self.run.seed,
            speed: self.run.speed,
            params,
            presenter: options.presenter,
            theme: self.view.theme,
            lang: self.view.lang,
            lesson,
            hide: owned(&options.hide),
            lock: owned(&options.lock),
            embed: false,
            origins: Vec::new(),
            cursor_s,
            what_ifs,
        }
        .encode()
    }

    /// The whole link the share dialog shows (the page's address and the fragment).
    pub fn share_link(&self, options: &ShareOptions) -> String {
        let page = platform::page_address().unwrap_or_default();
        format!("{page}#{}", self.share_fragment(options))
    }

    /// The `<iframe>` that embeds the share link's state in another page (`embed=1`: the
    /// views and the plot without the panels, 16:9 like a slide; docs/embed.md).
    pub fn share_embed(&self, options: &ShareOptions) -> String {
        let src = format!("{}&embed=1", self.share_link(options));
        let lab = self.sim.lab();
        let title = attlab::i18n::lab_text(
            self.view.lang(),
            &attlab::i18n::lab_title_id(lab.id()),
            lab.title(),
        );
        embed_snippet(&src, &format!("Attitude Lab: {title}"))
    }
}

/// The `<iframe>` element for `src`, titled `title` (what a screen reader announces), sized
/// like a 960×540 slide and no wider than its column; the motion sensors allowed, for a lab
/// that reads the phone's.
pub fn embed_snippet(src: &str, title: &str) -> String {
    let attr = |text: &str| {
        text.replace('&', "&amp;")
            .replace('"', "&quot;")
            .replace('<', "&lt;")
    };
    format!(
        "<iframe src=\"{}\" title=\"{}\" width=\"960\" height=\"540\" style=\"border:0;max-width:100%\" allow=\"fullscreen; accelerometer; gyroscope\" loading=\"lazy\"></iframe>",
        attr(src),
        attr(title)
    )
}
