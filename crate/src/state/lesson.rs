//! The lesson items of a link: `lesson=<lab>` and `step=<n>` (read before the parameters,
//! which are given relative to the step), `answers=2b.5a`, and the controls a teacher hides
//! or locks (`hide=`, `lock=`).

use super::{ALL_CONTROLS, LessonLink, LinkFault, UrlState, UrlStateError};
use crate::labs;
use crate::page::Lab;

/// Ids of the labs that have a lesson (for error messages).
fn lesson_ids() -> String {
    labs::all()
        .iter()
        .filter(|l| l.lesson().is_some())
        .map(|l| l.id())
        .collect::<Vec<_>>()
        .join(", ")
}

/// Reads `lesson=` and `step=` items (position, key, value, item): the lab the lesson
/// belongs to (it wins over `lab=`) and the step, 1 when not given. Bad items become errors.
pub(super) fn parse<'a>(
    mut lab: &'static dyn Lab,
    items: impl Iterator<Item = (usize, &'a str, &'a str, &'a str)>,
    errors: &mut Vec<UrlStateError>,
) -> (&'static dyn Lab, Option<LessonLink>) {
    let mut lesson = None;
    let mut step: Option<(usize, &str, &str)> = None;
    let err = UrlStateError::of;
    for (pos, key, value, item) in items {
        match key {
            "lesson" => match labs::find(value).filter(|l| l.lesson().is_some()) {
                Some(l) => {
                    lab = l;
                    lesson = Some(LessonLink {
                        step: 1,
                        answers: Vec::new(),
                    });
                }
                None => errors.push(err(pos, item, LinkFault::NoSuchLesson(lesson_ids()))),
            },
            _ => step = Some((pos, value, item)),
        }
    }
    let Some((pos, value, item)) = step else {
        return (lab, lesson);
    };
    let Some(link) = lesson.as_mut() else {
        errors.push(err(pos, item, LinkFault::StepWithoutLesson));
        return (lab, lesson);
    };
    let steps = lab.lesson().map_or(0, |l| l.steps.len());
    match value.parse::<usize>() {
        Ok(n) if (1..=steps).contains(&n) => link.step = n,
        _ => errors.push(err(pos, item, LinkFault::NoSuchStep(steps))),
    }
    (lab, lesson)
}

/// Applies `answers=`, `hide=` or `lock=`.
pub(super) fn apply_list(
    state: &mut UrlState,
    lab: &'static dyn Lab,
    key: &str,
    value: &str,
) -> Result<(), LinkFault> {
    if key == "answers" {
        let answers = parse_answers(lab, value)?;
        return match state.lesson.as_mut() {
            Some(link) => {
                link.answers = answers;
                Ok(())
            }
            None => Err(LinkFault::AnswersWithoutLesson),
        };
    }
    let keys = parse_controls(lab, value)?;
    if key == "hide" {
        state.hide = keys;
    } else {
        state.lock = keys;
    }
    Ok(())
}

/// `2b.5a`: each a step with a question and an answer letter it offers.
fn parse_answers(lab: &dyn Lab, value: &str) -> Result<Vec<(usize, usize)>, LinkFault> {
    let lesson = lab.lesson().ok_or(LinkFault::NoLesson)?;
    value
        .split('.')
        .filter(|s| !s.is_empty())
        .map(|part| {
            let bad = || LinkFault::NotAnAnswer(part.to_string());
            let letter = part
                .chars()
                .last()
                .filter(char::is_ascii_lowercase)
                .ok_or_else(bad)?;
            let step: usize = part[..part.len() - 1].parse().map_err(|_| bad())?;
            let answer = usize::from(letter as u8 - b'a') + 1;
            let offered = lesson
                .step(step)
                .and_then(|s| s.question)
                .map_or(0, |q| q.answers.len());
            if answer > offered {
                return Err(LinkFault::NoSuchAnswer { step, letter });
            }
            Ok((step, answer))
        })
        .collect()
}

/// `key.key` or `all`: parameters of the lab.
fn parse_controls(lab: &dyn Lab, value: &str) -> Result<Vec<String>, LinkFault> {
    value
        .split('.')
        .filter(|s| !s.is_empty())
        .map(|key| {
            if key == ALL_CONTROLS || lab.params().iter().any(|p| p.key == key) {
                Ok(key.to_string())
            } else {
                Err(LinkFault::NotAParameter {
                    key: key.to_string(),
                    lab: lab.id(),
                })
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn lesson_lab() -> &'static dyn Lab {
        labs::all()
            .iter()
            .copied()
            .find(|l| l.lesson().is_some_and(|l| l.steps.len() >= 2))
            .expect("a lab with a lesson")
    }

    #[test]
    fn a_lesson_link_round_trips_with_its_answers_and_controls() {
        let lab = lesson_lab();
        let lesson = lab.lesson().unwrap();
        let (n, q) = lesson
            .steps
            .iter()
            .enumerate()
            .find_map(|(i, s)| Some((i + 1, s.question?)))
            .expect("a question");
        let key = lab.params()[0].key;
        let link = format!(
            "lesson={}&step=2&answers={n}{}&hide={key}&lock=all",
            lab.id(),
            char::from(b'a' + (q.answers.len() as u8 - 1))
        );
        let (state, errors) = UrlState::parse(&link);
        assert!(errors.is_empty(), "{errors:?}");
        assert_eq!(state.lab_id, lab.id());
        let l = state.lesson.clone().unwrap();
        assert_eq!((l.step, l.answers.clone()), (2, vec![(n, q.answers.len())]));
        assert_eq!(
            (state.hide.clone(), state.lock.clone()),
            (vec![key.to_string()], vec!["all".to_string()])
        );
        let step = lesson.step(2).unwrap();
        assert_eq!(
            state.params,
            crate::lessons::step_params(lab, step).unwrap()
        );
        let (back, errors) = UrlState::parse(&state.encode());
        assert!(errors.is_empty(), "{errors:?}");
        assert_eq!(back, state);
    }

    #[test]
    fn a_moved_slider_on_a_step_is_kept_relative_to_the_step() {
        let lab = lesson_lab();
        let (mut state, _) = UrlState::parse(&format!("lesson={}&step=2", lab.id()));
        let spec = &lab.params()[0];
        let moved = if state.params.get(spec.key) == spec.max {
            spec.min
        } else {
            spec.max
        };
        state.params.set(lab.params(), spec.key, moved).unwrap();
        let (back, errors) = UrlState::parse(&state.encode());
        assert!(errors.is_empty(), "{errors:?}");
        assert_eq!(back.params.get(spec.key), moved);
    }

    #[test]
    fn bad_lesson_items_are_named_and_the_rest_kept() {
        let lab = lesson_lab();
        let (state, errors) = UrlState::parse(&format!(
            "lesson=warp&step=2&lesson={}&step=99&answers=1z.x&hide=nope&lock=all",
            lab.id()
        ));
        assert_eq!(state.lab_id, lab.id());
        assert_eq!(state.lesson.as_ref().map(|l| l.step), Some(1));
        assert_eq!(state.lock, vec!["all".to_string()]);
        let positions: Vec<usize> = errors.iter().map(|e| e.position).collect();
        assert_eq!(positions, vec![1, 4, 5, 6], "{errors:?}");
        assert!(errors[0].reason.contains("no such lesson"));
        assert!(errors[1].reason.contains("step must be"));
        let (_, errors) = UrlState::parse("step=2");
        assert!(errors[0].reason.contains("needs a lesson"), "{errors:?}");
    }
}
