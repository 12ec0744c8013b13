//! Numbers as the reader's language writes them: Russian separates the decimals with a comma
//! ("0,05 °/s", as the papers and the Russian catalogue's own prose do), English with a point.
//! Every number the page formats goes through [`number`]; every number a reader types is read
//! by [`parse_number`], which in Russian takes either separator.
//!
//! Only numbers are rewritten, never prose: the Russian catalogue's section and figure
//! references ("§3.3") keep their point, as Russian print does.

use super::Lang;

/// `text`, a number as Rust formats it ("-0.050", "1.5e-3", "  12.30"), with the decimal
/// separator of `lang`.
///
/// ```
/// # use attlab::i18n::{Lang, number};
/// assert_eq!(number(Lang::Ru, "-0.050"), "-0,050");
/// assert_eq!(number(Lang::Ru, "1.5e-3"), "1,5e-3");
/// assert_eq!(number(Lang::En, "-0.050"), "-0.050");
/// ```
pub fn number(lang: Lang, text: &str) -> String {
    match lang {
        Lang::En => text.to_string(),
        Lang::Ru => text.replace('.', ","),
    }
}

/// What separates numbers in a list: a comma, or where the comma is the decimal separator
/// (Russian), a semicolon ("0,5; 1,5").
pub fn list_separator(lang: Lang) -> &'static str {
    match lang {
        Lang::En => ", ",
        Lang::Ru => "; ",
    }
}

/// A diagram's detail in the paper's notation, its numbers and units in `lang`: "Δt = 1 s,
/// ε = 0.1", "Δt = 1 с; ε = 0,1".
///
/// ```
/// # use attlab::i18n::{Lang, diagram_detail};
/// let detail = [("Δt", 1.0, "s"), ("ε", 0.1, "")];
/// assert_eq!(diagram_detail(Lang::En, &detail), "Δt = 1 s, ε = 0.1");
/// assert_eq!(diagram_detail(Lang::Ru, &detail), "Δt = 1 с; ε = 0,1");
/// ```
pub fn diagram_detail(lang: Lang, detail: &[crate::page::DiagramSetting]) -> String {
    let parts: Vec<String> = (detail.iter())
        .map(|(symbol, value, unit)| {
            let value = number(lang, &value.to_string());
            format!("{symbol} = {value} {}", super::unit(lang, unit))
                .trim_end()
                .to_string()
        })
        .collect();
    parts.join(list_separator(lang))
}

/// `value` with `decimals` decimals, in `lang` (`format!("{value:.decimals$}")`).
///
/// ```
/// # use attlab::i18n::{Lang, fixed};
/// assert_eq!(fixed(Lang::Ru, 0.25, 2), "0,25");
/// assert_eq!(fixed(Lang::En, 0.25, 1), "0.2");
/// ```
pub fn fixed(lang: Lang, value: f64, decimals: usize) -> String {
    number(lang, &format!("{value:.decimals$}"))
}

/// A number the reader typed in `lang`: spaces anywhere (thousands) and the typographic
/// minus (U+2212) as a hyphen, as egui reads a number; in Russian the decimal separator may
/// be a comma or a point. An English "1,000" is not a number (egui's own reading refuses it
/// too, so the value stays). `None` when it is not a number.
///
/// ```
/// # use attlab::i18n::{Lang, parse_number};
/// assert_eq!(parse_number(Lang::Ru, "0,05"), Some(0.05));
/// assert_eq!(parse_number(Lang::Ru, "0.05"), Some(0.05));
/// assert_eq!(parse_number(Lang::Ru, " −1 200,5 "), Some(-1200.5));
/// assert_eq!(parse_number(Lang::Ru, "1,5e-3"), Some(1.5e-3));
/// assert_eq!(parse_number(Lang::Ru, "1,2,3"), None);
/// assert_eq!(parse_number(Lang::En, "1,000"), None);
/// assert_eq!(parse_number(Lang::En, "−2.5"), Some(-2.5));
/// assert_eq!(parse_number(Lang::En, "abc"), None);
/// ```
pub fn parse_number(lang: Lang, text: &str) -> Option<f64> {
    let plain: String = text
        .chars()
        .filter(|c| !c.is_whitespace())
        .map(|c| match (c, lang) {
            ('−', _) => '-',
            (',', Lang::Ru) => '.',
            (c, _) => c,
        })
        .collect();
    plain.parse().ok()
}

/// Fluent's own formatting of a number argument, with the Russian decimal comma: the
/// formatter of the Russian bundle (an argument passed as a number still picks its plural).
pub(super) fn russian_fluent_number<M>(
    value: &fluent_bundle::FluentValue<'_>,
    _: &M,
) -> Option<String> {
    match value {
        fluent_bundle::FluentValue::Number(n) => Some(number(Lang::Ru, &n.as_string())),
        _ => None,
    }
}
