//! The notes' index: the lessons, the link's items, embedding, live sensors in class and
//! accessibility; and the folder's own page, a choice of language.

use super::html::{esc, page};
use super::{Build, Words, labs_with_lessons, step_fragment};
use crate::i18n::{self, Lang, lab_text};
use std::fmt::Write as _;

/// The items of a link that are the page's own (a lab's sliders are items too, by key).
const LINK_ITEMS: [&str; 12] = [
    "lab",
    "seed",
    "speed",
    "lesson",
    "answers",
    "presenter",
    "theme",
    "lang",
    "hide",
    "lock",
    "embed",
    "origin",
];

/// `teacher/index.html`: both languages' indexes.
pub fn choice() -> String {
    let mut body = String::new();
    for lang in Lang::ALL {
        let words = Words::new(lang);
        let _ = writeln!(
            body,
            "<p lang=\"{}\"><a href=\"{}/index.html\">{}</a></p>",
            lang.code(),
            lang.code(),
            esc(&words.t("teacher-home", &[]))
        );
    }
    page(Lang::En, "Attitude Lab: teacher notes", &body)
}

/// `teacher/<lang>/index.html`.
pub fn index(words: &Words, build: &Build) -> String {
    let lang = words.lang();
    let title = words.t("teacher-home", &[]);
    let other = if lang == Lang::En { Lang::Ru } else { Lang::En };
    let mut body = format!(
        "<header><a href=\"{}\">Attitude Lab</a><a href=\"../{}/index.html\" lang=\"{}\">{}</a></header>\n<h1>{}</h1>\n<p>{}</p>\n",
        esc(&build.link("")),
        other.code(),
        other.code(),
        esc(&words.t("teacher-other-lang", &[])),
        esc(&title),
        esc(&words.t("teacher-index-intro", &[]))
    );
    lessons(&mut body, words, build);
    link_items(&mut body, words);
    for (heading, texts) in [
        ("teacher-index-embed", &["teacher-index-embed-text"][..]),
        ("teacher-index-live", &["teacher-index-live-text"][..]),
        (
            "teacher-index-a11y",
            &[
                "teacher-index-a11y-keys",
                "teacher-index-a11y-reader",
                "teacher-index-a11y-contrast",
                "teacher-index-a11y-limits",
            ][..],
        ),
    ] {
        let _ = writeln!(body, "<h2>{}</h2>", esc(&words.t(heading, &[])));
        for id in texts {
            let _ = writeln!(body, "<p>{}</p>", esc(&words.t(id, &[])));
        }
    }
    let _ = writeln!(
        body,
        "<footer>{}</footer>",
        esc(&words.t(
            "teacher-footer",
            &[
                ("version", build.version.clone()),
                ("commit", build.commit.clone())
            ]
        ))
    );
    page(lang, &title, &body)
}

/// The table of lessons: each lab's notes, its paper and its step count.
fn lessons(out: &mut String, words: &Words, build: &Build) {
    let lang = words.lang();
    let _ = writeln!(
        out,
        "<h2>{}</h2>\n<table>\n<tr><th>{}</th><th>{}</th><th>{}</th></tr>",
        esc(&words.t("teacher-index-lessons", &[])),
        esc(&words.t("teacher-index-lab-col", &[])),
        esc(&words.t("teacher-index-paper-col", &[])),
        esc(&words.t("teacher-index-steps-col", &[]))
    );
    for lab in labs_with_lessons() {
        let steps = lab.lesson().map_or(0, |l| l.steps.len());
        let title = lab_text(lang, &i18n::lab_title_id(lab.id()), lab.title());
        let _ = writeln!(
            out,
            "<tr><td><a href=\"{}.html\">{}</a></td><td>{}</td><td><a href=\"{}\">{steps}</a></td></tr>",
            lab.id(),
            esc(&title),
            esc(lab.reference()),
            esc(&build.link(&step_fragment(lab, 1, lang))),
        );
    }
    out.push_str("</table>\n");
}

/// The table of the link's own items.
fn link_items(out: &mut String, words: &Words) {
    let _ = writeln!(
        out,
        "<h2>{}</h2>\n<p>{}</p>\n<table>",
        esc(&words.t("teacher-index-link", &[])),
        esc(&words.t("teacher-index-link-intro", &[]))
    );
    for key in LINK_ITEMS {
        let _ = writeln!(
            out,
            "<tr><td><code>{key}</code></td><td>{}</td></tr>",
            esc(&words.t(&format!("teacher-param-{key}"), &[]))
        );
    }
    out.push_str("</table>\n");
}
