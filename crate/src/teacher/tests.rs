//! The notes say every question, answer, why and step link of every lesson, in both
//! languages, and their words are all in both catalogues.

use super::html::esc;
use super::*;
use crate::i18n::lesson_id;

/// The message ids of a Fluent file.
fn ids(text: &str) -> Vec<&str> {
    (text.lines())
        .filter_map(|l| l.split_once(" = ").map(|(id, _)| id.trim()))
        .filter(|id| !id.starts_with('#') && !id.is_empty())
        .collect()
}

#[test]
fn both_languages_have_the_same_words() {
    let en = ids(include_str!("../../locales/teacher/en.ftl"));
    let ru = ids(include_str!("../../locales/teacher/ru.ftl"));
    assert_eq!(en, ru);
    assert!(en.len() > 40);
}

#[test]
fn every_question_answer_and_step_link_is_in_the_notes() {
    let dir = std::env::temp_dir().join(format!("attlab-teacher-{}", std::process::id()));
    let build = Build::new(Some("https://attlab.example/site/"), "0.1.0", "abc1234").unwrap();
    let written = write(&dir, &build).unwrap();
    let labs = labs_with_lessons();
    assert_eq!(labs.len(), 6, "six lessons");
    // The choice, and per language the index and a page per lab.
    assert_eq!(written.len(), 1 + 2 * (1 + labs.len()));
    for lang in Lang::ALL {
        for lab in &labs {
            let path = dir.join(lang.code()).join(format!("{}.html", lab.id()));
            let html = std::fs::read_to_string(&path).unwrap();
            assert!(
                !html.contains(">teacher-"),
                "{}: a message id shows",
                path.display()
            );
            let lesson = lab.lesson().unwrap();
            let word = |step: &str, part: &str, english: &str| {
                esc(&crate::i18n::lab_text(
                    lang,
                    &lesson_id(lab.id(), Some(step), part),
                    english,
                ))
            };
            for (i, step) in lesson.steps.iter().enumerate() {
                let link = esc(&build.link(&step_fragment(*lab, i + 1, lang)));
                let (state, errors) =
                    crate::state::UrlState::parse(&step_fragment(*lab, i + 1, lang));
                assert!(errors.is_empty(), "{errors:?}");
                assert_eq!(state.lesson.map(|l| l.step), Some(i + 1));
                let mut said = vec![
                    ("link", link.clone()),
                    ("text", word(step.id, "text", step.text)),
                    ("title", word(step.id, "title", step.title)),
                ];
                if let Some(q) = &step.question {
                    said.push(("ask", word(step.id, "ask", q.ask)));
                    said.push(("why", word(step.id, "why", q.why)));
                    for (k, a) in q.answers.iter().enumerate() {
                        said.push(("answer", word(step.id, &format!("answer-{}", k + 1), a)));
                    }
                }
                for (what, text) in said {
                    assert!(
                        html.contains(&text),
                        "{} {} step {}: its {what} is missing: {text}",
                        lang.code(),
                        lab.id(),
                        i + 1
                    );
                }
                // The QR code sits beside the link.
                assert!(html.contains(&format!("id=\"step-{}\"", i + 1)));
            }
            assert_eq!(
                html.matches("<svg").count(),
                lesson.steps.len(),
                "{}",
                path.display()
            );
            assert!(html.contains(&esc(lab.reference())));
        }
        let index = std::fs::read_to_string(dir.join(lang.code()).join("index.html")).unwrap();
        for lab in &labs {
            assert!(index.contains(&format!("href=\"{}.html\"", lab.id())));
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn without_an_address_the_links_are_relative_and_there_are_no_qr_codes() {
    let build = Build::new(None, "0.1.0", "abc1234").unwrap();
    let lab = labs_with_lessons()[0];
    let html = lab_page(lab, &Words::new(Lang::En), &build);
    assert!(html.contains("href=\"../../index.html#lesson="));
    assert!(!html.contains("<svg"));
    assert!(Build::new(Some("ftp://x/"), "0", "0").is_err());
    assert!(Build::new(Some("https://x.org"), "0", "0").is_err());
}

#[test]
fn the_declared_differences_come_from_the_chapters() {
    // Paper 4's chapter declares the worst γ and Table 1's magnitude as differences and its
    // argmin as a match after calibration.
    let p4 = crate::labs::find("p4").unwrap();
    let rows = model_rows(p4);
    assert!(rows.iter().any(|r| r[3].starts_with("differs")), "{rows:?}");
    assert!(
        rows.iter().any(|r| r[3].contains("after calibration")),
        "{rows:?}"
    );
    assert!(rows.iter().all(|r| !r[0].is_empty() && !r[3].is_empty()));
}
