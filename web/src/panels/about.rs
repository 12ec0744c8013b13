//! "About and citing": the build (version, commit, date), how to cite the software and the
//! papers, and the teacher notes of the lab shown.

use super::{arg, tr, tr_with};
use crate::state::AppState;
use egui::{RichText, Ui};

/// The folded section at the end of the controls.
pub(super) fn about(ui: &mut Ui, app: &AppState) {
    super::fit::header(ui, tr(app, "about-title"))
        .default_open(false)
        .show(ui, |ui| {
            let build = crate::platform::build_info();
            ui.label(tr_with(
                app,
                "about-build",
                &[
                    ("version", arg(&build.version)),
                    ("commit", arg(&build.commit)),
                    ("date", arg(&build.date)),
                ],
            ));
            ui.add_space(4.0);
            ui.label(RichText::new(tr(app, "about-cite")).strong());
            ui.label(
                RichText::new(tr_with(
                    app,
                    "about-cite-software",
                    &[
                        ("version", arg(&build.version)),
                        ("commit", arg(&build.commit)),
                    ],
                ))
                .small(),
            );
            ui.label(RichText::new(tr(app, "about-papers")).strong());
            let lang = app.view().lang();
            for lab in attlab::labs::all() {
                let title = attlab::i18n::lab_text(
                    lang,
                    &attlab::i18n::lab_title_id(lab.id()),
                    lab.title(),
                );
                ui.label(RichText::new(format!("{title} — {}", lab.reference())).small());
            }
            ui.add_space(4.0);
            let lab = app.sim().lab();
            if lab.lesson().is_some() {
                let notes = format!("teacher/{}/{}.html", app.view().lang().code(), lab.id());
                ui.hyperlink_to(tr(app, "about-teacher-notes"), notes);
            }
            ui.label(RichText::new(tr(app, "about-licence")).small().weak());
        });
}
