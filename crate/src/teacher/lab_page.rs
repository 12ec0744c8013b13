//! One lab's notes: the lesson, step by step, then the model against the paper.

use super::html::{esc, page, qr_svg};
use super::{Build, Words, step_fragment};
use crate::i18n::{self, Lang, lab_text, lesson_id};
use crate::model::{Measure, ParamValues, SeriesKey};
use crate::page::{Lab, Lesson, LessonStep};
use rand::SeedableRng as _;
use std::fmt::Write as _;

/// The notes of `lab`'s lesson in `words`' language (an empty page body for a lab without
/// a lesson).
pub fn lab_page(lab: &'static dyn Lab, words: &Words, build: &Build) -> String {
    let lang = words.lang();
    let title = lab_text(lang, &i18n::lab_title_id(lab.id()), lab.title());
    let heading = words.t("teacher-notes-for", &[("lab", title.clone())]);
    let mut body = header(lab, words);
    let _ = writeln!(body, "<h1>{}</h1>", esc(&heading));
    if let Some(lesson) = lab.lesson() {
        lesson_part(&mut body, lab, lesson, words, build);
    }
    model_part(&mut body, lab, words);
    let _ = writeln!(
        body,
        "<h2>{}</h2>\n<p>{}</p>\n<footer>{}</footer>",
        esc(&words.t("teacher-reference", &[])),
        esc(lab.reference()),
        esc(&words.t(
            "teacher-footer",
            &[
                ("version", build.version.clone()),
                ("commit", build.commit.clone())
            ]
        ))
    );
    page(lang, &heading, &body)
}

/// The line above the title: the way back to the index and to the other language.
fn header(lab: &dyn Lab, words: &Words) -> String {
    let other = match words.lang() {
        Lang::En => Lang::Ru,
        Lang::Ru => Lang::En,
    };
    format!(
        "<header><a href=\"index.html\">{}</a><a href=\"../{}/{}.html\" lang=\"{}\">{}</a></header>\n",
        esc(&words.t("teacher-home", &[])),
        other.code(),
        lab.id(),
        other.code(),
        esc(&words.t("teacher-other-lang", &[]))
    )
}

/// A word of the lesson (`part` of step `step`, or of the lesson) in `lang`.
fn lesson_word(lab: &dyn Lab, step: Option<&str>, part: &str, english: &str, lang: Lang) -> String {
    lab_text(lang, &lesson_id(lab.id(), step, part), english)
}

/// The goal, the time it takes, the way in, and every step.
fn lesson_part(out: &mut String, lab: &dyn Lab, lesson: &Lesson, words: &Words, build: &Build) {
    let lang = words.lang();
    let wall_s: f64 = lesson.steps.iter().filter_map(wall_seconds).sum();
    let minutes = i18n::number(lang, &format!("{:.0}", (wall_s / 60.0).ceil().max(1.0)));
    let first = build.link(&step_fragment(lab, 1, lang));
    let presenter = format!("{first}&presenter=1");
    let _ = writeln!(
        out,
        "<h2>{}</h2>\n<p>{}</p>\n<p>{} <em>{}</em></p>\n<p>{}</p>\n<p class=\"no-print\"><a href=\"{}\">{}</a> · <a href=\"{}\">{}</a></p>",
        esc(&words.t("teacher-goal", &[])),
        esc(&lesson_word(lab, None, "title", lesson.title, lang)),
        esc(&words.t("teacher-paper", &[])),
        esc(&lab_text(lang, &i18n::lab_paper_id(lab.id()), lab.paper())),
        esc(&words.t(
            "teacher-steps",
            &[
                ("count", lesson.steps.len().to_string()),
                ("minutes", minutes)
            ]
        )),
        esc(&first),
        esc(&words.t("teacher-open", &[])),
        esc(&presenter),
        esc(&words.t("teacher-open-presenter", &[])),
    );
    let names = estimator_names(lab);
    for (i, step) in lesson.steps.iter().enumerate() {
        step_part(
            out,
            lab,
            (i + 1, lesson.steps.len()),
            step,
            &names,
            words,
            build,
        );
    }
}

/// Seconds on the clock a step runs before it pauses (at its speed), if it pauses.
fn wall_seconds(step: &LessonStep) -> Option<f64> {
    Some(step.pause_at_s? / step.speed.unwrap_or(1.0))
}

/// The English names of the lab's estimators at its defaults, by id.
fn estimator_names(lab: &dyn Lab) -> Vec<(&'static str, &'static str)> {
    let params = ParamValues::defaults(lab.params());
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(1);
    let run = lab.build(&params, &mut rng);
    run.estimators.iter().map(|e| (e.id(), e.label())).collect()
}

/// One step: its link and QR code, its text, how long it runs, what to say, its question.
fn step_part(
    out: &mut String,
    lab: &dyn Lab,
    (n, count): (usize, usize),
    step: &LessonStep,
    names: &[(&'static str, &'static str)],
    words: &Words,
    build: &Build,
) {
    let lang = words.lang();
    let word = |part: &str, english: &str| lesson_word(lab, Some(step.id), part, english, lang);
    let link = build.link(&step_fragment(lab, n, lang));
    let qr = match (&build.address, qr_svg(&link)) {
        (Some(_), Some(svg)) => format!("<div class=\"qr\">{svg}</div>"),
        _ => String::new(),
    };
    let _ = writeln!(
        out,
        "<section class=\"step\" id=\"step-{n}\">\n<h2>{}</h2>\n<div class=\"step-head\">\n<div>\n<p>{}</p>\n<p>{}: <a class=\"link\" href=\"{}\">{}</a></p>",
        esc(&words.t(
            "teacher-step",
            &[
                ("n", n.to_string()),
                ("count", count.to_string()),
                ("title", word("title", step.title))
            ]
        )),
        esc(&word("text", step.text)),
        esc(&words.t("teacher-link", &[])),
        esc(&link),
        esc(&link),
    );
    if build.address.is_none() {
        let _ = writeln!(
            out,
            "<p class=\"note\">{}</p>",
            esc(&words.t("teacher-qr-missing", &[]))
        );
    }
    let _ = writeln!(out, "</div>\n{qr}\n</div>");
    let _ = writeln!(out, "<h3>{}</h3>\n<ul>", esc(&words.t("teacher-say", &[])));
    for line in what_to_say(lab, step, names, words) {
        let _ = writeln!(out, "<li>{}</li>", esc(&line));
    }
    out.push_str("</ul>\n");
    if let Some(q) = &step.question {
        let _ = writeln!(
            out,
            "<h3>{}</h3>\n<p><strong>{}</strong></p>\n<ol type=\"a\">",
            esc(&words.t("teacher-question", &[])),
            esc(&word("ask", q.ask))
        );
        for (k, english) in q.answers.iter().enumerate() {
            let text = word(&format!("answer-{}", k + 1), english);
            let (class, mark) = if k == q.answer {
                (
                    " class=\"right\"",
                    format!(" — {}", words.t("teacher-answer-shown", &[])),
                )
            } else {
                ("", String::new())
            };
            let _ = writeln!(out, "<li{class}>{}{}</li>", esc(&text), esc(&mark));
        }
        let _ = writeln!(
            out,
            "</ol>\n<p><em>{}:</em> {}</p>",
            esc(&words.t("teacher-why", &[])),
            esc(&word("why", q.why))
        );
    }
    out.push_str("</section>\n");
}

/// The lines to say while the step runs, from what the step sets and shows.
fn what_to_say(
    lab: &dyn Lab,
    step: &LessonStep,
    names: &[(&'static str, &'static str)],
    words: &Words,
) -> Vec<String> {
    let lang = words.lang();
    let list = |items: Vec<String>| items.join(i18n::list_separator(lang));
    let speed = i18n::number(lang, &step.speed.unwrap_or(1.0).to_string());
    let mut lines = vec![match step.pause_at_s {
        Some(t) => words.t(
            "teacher-runs-to",
            &[
                ("t", i18n::number(lang, &t.to_string())),
                ("speed", speed),
                (
                    "wall",
                    i18n::number(lang, &format!("{:.0}", wall_seconds(step).unwrap_or(t))),
                ),
            ],
        ),
        None => words.t("teacher-runs-on", &[("speed", speed)]),
    }];
    if step.question.is_some() {
        lines.push(words.t("teacher-say-question", &[]));
    }
    let sliders: Vec<String> = (step.highlight.iter())
        .filter_map(|k| lab.params().iter().find(|p| p.key == *k))
        .map(|p| lab_text(lang, &i18n::param_label_id(lab.id(), p.key), p.label))
        .collect();
    if !sliders.is_empty() {
        lines.push(words.t("teacher-say-sliders", &[("names", list(sliders))]));
    }
    let name_of = |id: &str| {
        let english = names.iter().find(|(i, _)| *i == id).map_or(id, |(_, l)| *l);
        i18n::estimator_name(lang, lab.id(), id, english)
    };
    let tiles: Vec<String> = step
        .tiles
        .iter()
        .map(|k| tile_name(lab, k, &name_of, words))
        .collect();
    if !tiles.is_empty() {
        lines.push(words.t("teacher-say-tiles", &[("names", list(tiles))]));
    }
    if !step.show.is_empty() {
        let shown = step.show.iter().map(|id| name_of(id)).collect();
        lines.push(words.t("teacher-say-filters", &[("names", list(shown))]));
    }
    if let Some(sweep) = step
        .sweep
        .and_then(|id| lab.sweeps().iter().find(|s| s.id == id))
    {
        let name = lab_text(
            lang,
            &i18n::sweep_id(lab.id(), sweep.id, "title"),
            sweep.title,
        );
        lines.push(words.t("teacher-say-sweep", &[("name", name)]));
    }
    if !step.terms.is_empty() {
        lines.push(words.t("teacher-say-cycle", &[]));
    }
    if step.pause_at_s.is_some() {
        lines.push(words.t("teacher-say-pause", &[]));
    }
    lines
}

/// A tile's words: what it measures and whose it is.
fn tile_name(
    lab: &dyn Lab,
    key: &SeriesKey,
    name_of: &dyn Fn(&str) -> String,
    words: &Words,
) -> String {
    let lang = words.lang();
    let what = match key.measure {
        Measure::Quantity(q) => lab_text(lang, &i18n::quantity_id(q.key), q.label),
        _ => key.name(),
    };
    let whose = if key.source == crate::model::TRUTH {
        words.t("teacher-truth", &[])
    } else {
        name_of(key.source)
    };
    let _ = lab;
    format!("{what}: {whose}")
}

/// The rows of the lab's reproduction table (its chapter, generated and checked) where it
/// differs from the paper or matches only at a setting chosen here: the cells quantity,
/// paper, measured, verdict.
pub fn model_rows(lab: &dyn Lab) -> Vec<[String; 4]> {
    let Some(chapter) = lab.study().map(|s| s.chapter()) else {
        return Vec::new();
    };
    let start = format!("<!-- reproduce:{} -->", lab.id());
    let Some(table) = chapter.text.split_once(&start).map(|(_, rest)| rest) else {
        return Vec::new();
    };
    let table = table.split("<!-- /reproduce").next().unwrap_or_default();
    table
        .lines()
        .filter(|l| l.starts_with('|') && !l.starts_with("|---"))
        .skip(1)
        .filter_map(|line| {
            let cells: Vec<String> = (line.trim_matches('|').split(" | "))
                .map(|c| c.trim().replace("\\|", "|"))
                .collect();
            let verdict = cells.last()?;
            let declared = verdict.starts_with("differs") || verdict.contains("after calibration");
            (declared && cells.len() >= 5).then(|| {
                [
                    cells[0].clone(),
                    cells[1].clone(),
                    cells[3].clone(),
                    verdict.clone(),
                ]
            })
        })
        .collect()
}

/// The model against the paper: the declared rows, or a line saying there are none.
fn model_part(out: &mut String, lab: &dyn Lab, words: &Words) {
    let _ = writeln!(out, "<h2>{}</h2>", esc(&words.t("teacher-model", &[])));
    let rows = model_rows(lab);
    if rows.is_empty() {
        let _ = writeln!(out, "<p>{}</p>", esc(&words.t("teacher-model-none", &[])));
        return;
    }
    let _ = write!(out, "<p>{}", esc(&words.t("teacher-model-intro", &[])));
    if words.lang() != Lang::En {
        let _ = write!(out, " {}", esc(&words.t("teacher-model-english", &[])));
    }
    out.push_str("</p>\n<table>\n<tr>");
    for id in [
        "teacher-col-quantity",
        "teacher-col-paper",
        "teacher-col-measured",
        "teacher-col-verdict",
    ] {
        let _ = write!(out, "<th>{}</th>", esc(&words.t(id, &[])));
    }
    out.push_str("</tr>\n");
    for row in rows {
        out.push_str("<tr>");
        for cell in row {
            let _ = write!(out, "<td lang=\"en\">{}</td>", esc(&cell));
        }
        out.push_str("</tr>\n");
    }
    out.push_str("</table>\n");
}
