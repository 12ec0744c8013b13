//! The time-travel items of a link: `at=1390` (the timeline's cursor, s) and up to three
//! `whatif=1390:key=value,key=value` (a branch from a moment with its changes; `whatif=1390`
//! alone is a branch with no change), so a teacher's link opens "at 1 390 s, with and
//! without the star tracker".

use super::{LinkFault, UrlState};
use crate::model::ParamValues;
use crate::page::Lab;

/// Branches a link may ask for (as many as the page runs beside the main run).
pub const MAX_WHAT_IFS: usize = 3;

/// A branch a link asks for.
#[derive(Clone, Debug, PartialEq)]
pub struct WhatIfLink {
    /// Its moment (s).
    pub at_s: f64,
    /// The parameters it changes there, in order.
    pub changes: Vec<(&'static str, f64)>,
}

impl WhatIfLink {
    /// The item's value: `1390:key=value,key=value`.
    pub fn encode(&self) -> String {
        let mut out = self.at_s.to_string();
        for (i, (key, value)) in self.changes.iter().enumerate() {
            out.push(if i == 0 { ':' } else { ',' });
            out.push_str(&format!("{key}={value}"));
        }
        out
    }
}

/// A time in seconds ≥ 0.
fn seconds(text: &str) -> Option<f64> {
    text.trim()
        .parse::<f64>()
        .ok()
        .filter(|t| t.is_finite() && *t >= 0.0)
}

/// Reads `at=` or `whatif=` into `state` (of `lab`).
pub(super) fn apply(
    state: &mut UrlState,
    lab: &'static dyn Lab,
    key: &str,
    value: &str,
) -> Result<(), LinkFault> {
    if key == "at" {
        state.cursor_s = Some(seconds(value).ok_or(LinkFault::At)?);
        return Ok(());
    }
    if state.what_ifs.len() >= MAX_WHAT_IFS {
        return Err(LinkFault::TooManyWhatIfs(MAX_WHAT_IFS));
    }
    let bad = || LinkFault::WhatIf(value.to_string());
    let (at, changes) = value.split_once(':').unwrap_or((value, ""));
    let at_s = seconds(at).ok_or_else(bad)?;
    let specs = lab.params();
    let mut check = ParamValues::defaults(specs);
    let mut link = WhatIfLink {
        at_s,
        changes: Vec::new(),
    };
    for change in changes.split(',').filter(|c| !c.is_empty()) {
        let (key, text) = change.split_once('=').ok_or_else(bad)?;
        let spec = (specs.iter())
            .find(|s| s.key == key && !s.needs_reset)
            .ok_or_else(bad)?;
        check.set_text(specs, spec.key, text).map_err(|_| bad())?;
        link.changes.push((spec.key, check.get(spec.key)));
    }
    state.what_ifs.push(link);
    Ok(())
}

/// Writes the cursor and the branches of `state` into `out`.
pub(super) fn encode(state: &UrlState, out: &mut form_urlencoded::Serializer<'_, String>) {
    if let Some(t) = state.cursor_s {
        out.append_pair("at", &t.to_string());
    }
    for w in &state.what_ifs {
        out.append_pair("whatif", &w.encode());
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::labs;

    #[test]
    fn the_cursor_and_the_branches_round_trip_through_the_link() {
        let lab = labs::find("p2").unwrap();
        let mut state = UrlState::defaults(lab);
        state.cursor_s = Some(1390.0);
        state.what_ifs = vec![
            WhatIfLink {
                at_s: 1390.0,
                changes: vec![("q_scale", 0.1)],
            },
            WhatIfLink {
                at_s: 1200.5,
                changes: Vec::new(),
            },
        ];
        let (back, errors) = UrlState::parse(&state.encode());
        assert!(errors.is_empty(), "{errors:?}");
        assert_eq!(back.cursor_s, Some(1390.0));
        assert_eq!(back.what_ifs, state.what_ifs);
    }

    #[test]
    fn a_bad_cursor_or_branch_is_refused_by_name_and_the_rest_kept() {
        let cases = [
            ("lab=p2&at=-3", LinkFault::At),
            ("lab=p2&whatif=x", LinkFault::WhatIf("x".into())),
            (
                "lab=p2&whatif=10:nokey=1",
                LinkFault::WhatIf("10:nokey=1".into()),
            ),
            (
                "lab=p2&whatif=10:q_scale=1e9",
                LinkFault::WhatIf("10:q_scale=1e9".into()),
            ),
            (
                "lab=p2&whatif=1&whatif=2&whatif=3&whatif=4",
                LinkFault::TooManyWhatIfs(MAX_WHAT_IFS),
            ),
        ];
        for (link, fault) in cases {
            let (state, errors) = UrlState::parse(link);
            assert_eq!(state.lab_id, "p2");
            let faults: Vec<_> = errors.iter().filter_map(|e| e.fault.clone()).collect();
            assert_eq!(faults, vec![fault], "{link}");
        }
    }
}
