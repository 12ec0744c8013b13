//! The view part: which plot tab is shown and how, which view is at full size, which
//! sources are hidden, presenter mode and the 3D ghost. It owns the commands that change
//! them; a tab that draws series not recorded so far re-runs the simulation for them.

use super::AppState;
use crate::render::plots::PlotState;
use attlab::i18n::Lang;
use attlab::model::{PlotTab, SeriesKey};
use attlab::page::Lab;
use attlab::sim::{Selection, Simulation};
use attlab::state::Theme;

/// What the central area shows: everything, or one view (or the plots) at full size.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Focus {
    /// The lab's views on top, the plots below.
    #[default]
    All,
    /// The lab's view with this index alone.
    View(usize),
    /// The plots alone.
    Plots,
}

impl Focus {
    /// The next focus for a lab with `views` views: each view, the plots, all.
    pub fn next(self, views: usize) -> Self {
        match self {
            Self::All if views > 0 => Self::View(0),
            Self::View(k) if k + 1 < views => Self::View(k + 1),
            Self::All | Self::View(_) => Self::Plots,
            Self::Plots => Self::All,
        }
    }
}

/// What is shown and how.
#[derive(Clone, Debug, PartialEq)]
pub struct ViewState {
    /// Plot tab and options.
    pub plots: PlotState,
    /// One view at full size, or all.
    pub focus: Focus,
    /// Sources (1 + estimator index) hidden in every view and plot.
    pub hidden: Vec<usize>,
    /// Presenter mode: large type, thick lines, only the controls that matter.
    pub presenter: bool,
    /// The theme chosen; `None` follows the mode (light in presenter mode).
    pub theme: Option<Theme>,
    /// The language chosen (the switch or `lang=` in the link); `None` follows the browser.
    pub lang: Option<Lang>,
    /// The first of the browser's languages the page speaks.
    pub browser_lang: Lang,
    /// Which estimator the 3D ghost shows.
    pub ghost_index: usize,
    /// A PNG capture is running: the views hide their buttons and the simulation holds.
    pub capturing: bool,
    /// On a narrow screen: the controls' sheet is open over the lower part of the page.
    pub sheet_open: bool,
    /// On a narrow screen: the index of the one view shown above the plots.
    pub narrow_view: usize,
    /// The keyboard dialog is open (key ? or F1, or its button).
    pub keys_help: bool,
    /// Parameters whose controls are hidden (`hide=` in the link; `all` for every one).
    pub hide: Vec<String>,
    /// Parameters whose controls are shown locked (`lock=` in the link; `all`).
    pub lock: Vec<String>,
    /// The filter-cycle panel is open.
    pub cycle_open: bool,
    /// Embedded in another page (`embed=1`): the views and the plot, without the panels.
    pub embed: bool,
    /// The other origins whose pages may drive this one (`origin=` in the link).
    pub origins: Vec<String>,
}

impl ViewState {
    /// The language shown: the one chosen, else the browser's.
    pub fn lang(&self) -> Lang {
        self.lang.unwrap_or(self.browser_lang)
    }

    /// Whether the control of parameter `key` is hidden by the link.
    pub fn hides(&self, key: &str) -> bool {
        self.hide
            .iter()
            .any(|h| h == key || h == attlab::state::ALL_CONTROLS)
    }

    /// Whether the control of parameter `key` is locked by the link.
    pub fn locks(&self, key: &str) -> bool {
        self.lock
            .iter()
            .any(|h| h == key || h == attlab::state::ALL_CONTROLS)
    }

    /// The theme shown: the one chosen, else light in presenter mode and dark otherwise.
    pub fn theme(&self) -> Theme {
        self.theme.unwrap_or(Theme::for_mode(self.presenter))
    }

    /// The view a lab opens with.
    pub fn for_lab(lab: &dyn Lab) -> Self {
        Self {
            plots: PlotState::for_lab(lab),
            focus: Focus::All,
            hidden: Vec::new(),
            presenter: false,
            theme: None,
            lang: None,
            browser_lang: Lang::En,
            ghost_index: 0,
            capturing: false,
            sheet_open: false,
            narrow_view: 0,
            keys_help: false,
            hide: Vec::new(),
            lock: Vec::new(),
            cycle_open: false,
            embed: false,
            origins: Vec::new(),
        }
    }
}

/// What the view part does.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ViewCommand {
    /// Which estimator the 3D ghost shows.
    SetGhost(usize),
    /// Select a plot tab.
    SelectTab(PlotTab),
    /// Draw covariance elements as log10.
    SetLogCovariance(bool),
    /// Draw ±3σ bands around errors that have one.
    SetShowBands(bool),
    /// Shade (or not) the lab's outages on the plots.
    SetShowOutages(bool),
    /// Show the next view alone over the whole central area (then the plots, then all).
    CycleFocus,
    /// Hide (or show again) the source with this index (1 + estimator index) everywhere.
    ToggleSource(usize),
    /// Presenter mode on or off: large type, thick lines, only the controls that matter.
    SetPresenter(bool),
    /// A PNG capture started or ended.
    SetCapturing(bool),
    /// Choose the theme (`None`: follow the mode).
    SetTheme(Option<Theme>),
    /// Choose the language.
    SetLang(Lang),
    /// On a narrow screen: open or close the controls' sheet.
    SetSheet(bool),
    /// On a narrow screen: show the lab's view with this index above the plots.
    ShowNarrowView(usize),
    /// Open or close the keyboard dialog.
    SetKeysHelp(bool),
    /// Open or close the filter-cycle panel.
    SetCycle(bool),
}

impl AppState {
    pub(super) fn apply_view(&mut self, command: ViewCommand) {
        let view = &mut self.view;
        match command {
            ViewCommand::SetGhost(i) => view.ghost_index = i,
            ViewCommand::SelectTab(tab) => self.select_tab(tab),
            ViewCommand::SetLogCovariance(on) => view.plots.log_covariance = on,
            ViewCommand::SetShowBands(on) => view.plots.show_bands = on,
            ViewCommand::SetShowOutages(on) => view.plots.show_outages = on,
            ViewCommand::CycleFocus => {
                view.focus = view.focus.next(self.sim.lab().page().views.len())
            }
            ViewCommand::ToggleSource(i) => match view.hidden.iter().position(|h| *h == i) {
                Some(k) => {
                    view.hidden.remove(k);
                }
                None => view.hidden.push(i),
            },
            ViewCommand::SetPresenter(on) => view.presenter = on,
            ViewCommand::SetCapturing(on) => view.capturing = on,
            ViewCommand::SetTheme(theme) => view.theme = theme,
            ViewCommand::SetLang(lang) => view.lang = Some(lang),
            ViewCommand::SetSheet(open) => view.sheet_open = open,
            ViewCommand::SetKeysHelp(open) => view.keys_help = open,
            ViewCommand::SetCycle(open) => view.cycle_open = open,
            ViewCommand::ShowNarrowView(k) => {
                if k < self.sim.lab().page().views.len() {
                    view.narrow_view = k;
                }
            }
        }
    }

    /// Shows `tab`; when it draws series not recorded so far, the run is re-simulated from
    /// its start recording them (same seed, same parameter changes), a slice per frame, so
    /// the new plot covers the whole run too.
    fn select_tab(&mut self, tab: PlotTab) {
        self.view.plots.tab = tab;
        let selection = view_selection(&self.sim, tab, self.tiles());
        let Selection::View(wanted) = &selection else {
            return;
        };
        let recorded = self.sim.specs();
        if wanted.iter().all(|w| recorded.iter().any(|s| &s.name == w)) {
            return;
        }
        if self.view.capturing {
            // A PNG capture shows each tab for a few frames with the run held: re-run at
            // once, so the picture has the tab's whole history.
            if let Err(e) = self.sim.reselect(selection) {
                self.warn("msg-plot-failed", &[("why", self.why(&e))]);
            }
        } else {
            self.start_reselect(selection);
        }
    }
}

/// What the page records while `tab` is shown ([`attlab::page::tab_series`]), and the
/// lesson step's `tiles`.
pub fn view_selection(sim: &Simulation, tab: PlotTab, tiles: &[SeriesKey]) -> Selection {
    let mut names = attlab::page::tab_series(sim.lab(), sim.available_specs(), tab);
    names.extend(tiles.iter().map(SeriesKey::name));
    Selection::View(names)
}
