//! The labs' chapters' measured tables are generated from the reproductions: each lab's
//! table sits in its chapter (`README.md` in its folder) between `<!-- reproduce:ID -->` and
//! `<!-- /reproduce:ID -->`, written by `attlab reproduce all --readme` and compared by the
//! test suite, so a chapter cannot drift from what the code measures.

use crate::model::Reproduction;

/// Why a chapter's table could not be replaced. Worded in English only because only the CLI
/// and the tests meet it: a page reader never rewrites a chapter.
#[derive(Clone, Debug, thiserror::Error, PartialEq)]
pub enum ChapterError {
    /// The chapter lacks one of the lab's markers.
    #[error("the chapter has no `{marker}` marker")]
    MissingMarker {
        /// The marker, as the chapter should have it.
        marker: String,
    },
}

/// The opening and closing markers of lab `id`'s block.
pub fn markers(id: &str) -> (String, String) {
    (
        format!("<!-- reproduce:{id} -->"),
        format!("<!-- /reproduce:{id} -->"),
    )
}

/// The text between lab `id`'s markers, if the chapter has them.
pub fn block<'a>(readme: &'a str, id: &str) -> Option<&'a str> {
    let (open, close) = markers(id);
    let start = readme.find(&open)? + open.len();
    let end = start + readme[start..].find(&close)?;
    Some(readme[start..end].trim_matches('\n'))
}

/// `readme` (a chapter) with lab `rep.lab`'s block replaced by its current table; an error when the
/// markers are missing.
pub fn with_table(readme: &str, rep: &Reproduction) -> Result<String, ChapterError> {
    let (open, close) = markers(&rep.lab);
    let start = readme
        .find(&open)
        .ok_or_else(|| ChapterError::MissingMarker {
            marker: open.clone(),
        })?
        + open.len();
    let end = start
        + readme[start..]
            .find(&close)
            .ok_or(ChapterError::MissingMarker { marker: close })?;
    Ok(format!(
        "{}\n{}{}",
        &readme[..start],
        rep.to_markdown(),
        &readme[end..]
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::Row;

    #[test]
    fn a_block_is_replaced_and_read_back() {
        let rep = Reproduction {
            lab: "x".into(),
            rows: vec![Row::measurement("m", "—", 1.5, "s")],
            notes: vec![],
        };
        let text = "intro\n<!-- reproduce:x -->\nold\n<!-- /reproduce:x -->\nend\n";
        let new = with_table(text, &rep).unwrap();
        assert_eq!(
            block(&new, "x").unwrap(),
            rep.to_markdown().trim_matches('\n')
        );
        assert!(new.starts_with("intro\n") && new.ends_with("end\n"));
        assert_eq!(
            with_table("no markers", &rep),
            Err(ChapterError::MissingMarker {
                marker: "<!-- reproduce:x -->".into()
            })
        );
        assert_eq!(
            with_table("<!-- reproduce:x -->", &rep)
                .unwrap_err()
                .to_string(),
            "the chapter has no `<!-- /reproduce:x -->` marker"
        );
    }
}
