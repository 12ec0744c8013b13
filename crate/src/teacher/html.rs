//! The notes' HTML: escaping, the page around a body (with its screen and print styles) and
//! a step's QR code as inline SVG.

use crate::i18n::Lang;

/// `text` safe in HTML text and in a double-quoted attribute.
pub fn esc(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            _ => out.push(c),
        }
    }
    out
}

/// The styles: readable on a screen, and on paper A4 with the steps kept whole where they fit.
const STYLE: &str = "
:root { color-scheme: light; }
body { font-family: system-ui, -apple-system, 'Segoe UI', Roboto, sans-serif; max-width: 50em;
  margin: 2em auto; padding: 0 1em; line-height: 1.45; color: #1b1f24; background: #fff; }
header { display: flex; justify-content: space-between; gap: 1em; font-size: 0.9em; color: #57606a; }
h1 { font-size: 1.6em; margin: 0.6em 0 0.3em; }
h2 { font-size: 1.25em; margin: 1.4em 0 0.4em; border-bottom: 1px solid #d0d7de; }
h3 { font-size: 1.05em; margin: 0.8em 0 0.3em; }
a { color: #0550ae; }
.step { break-inside: avoid; page-break-inside: avoid; }
.step-head { display: flex; gap: 1em; align-items: flex-start; }
.step-head > div:first-child { flex: 1; }
.qr { flex: none; }
.qr svg { width: 8.5em; height: 8.5em; }
.link { font-family: ui-monospace, 'DejaVu Sans Mono', monospace; font-size: 0.85em; word-break: break-all; }
.right { font-weight: 600; }
.right::after { content: ' \\2713'; }
.note { color: #57606a; font-size: 0.9em; }
table { border-collapse: collapse; font-size: 0.85em; width: 100%; }
th, td { border: 1px solid #d0d7de; padding: 0.25em 0.4em; text-align: left; vertical-align: top; }
footer { margin-top: 2em; font-size: 0.8em; color: #57606a; }
@media print {
  @page { size: A4; margin: 15mm; }
  body { margin: 0; max-width: none; font-size: 10.5pt; }
  header a, .no-print { display: none; }
  a { color: inherit; text-decoration: none; }
  h2 { break-after: avoid; page-break-after: avoid; }
}
";

/// A whole page in `lang` titled `title` around `body`.
pub fn page(lang: Lang, title: &str, body: &str) -> String {
    format!(
        "<!DOCTYPE html>\n<html lang=\"{}\">\n<head>\n<meta charset=\"utf-8\">\n<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<link rel=\"icon\" href=\"data:,\">\n<title>{}</title>\n<style>{STYLE}</style>\n</head>\n<body>\n{body}\n</body>\n</html>\n",
        lang.code(),
        esc(title)
    )
}

/// `link` as a QR code in inline SVG (`None` if it is too long for one).
pub fn qr_svg(link: &str) -> Option<String> {
    let code = qrcode::QrCode::with_error_correction_level(link, qrcode::EcLevel::M).ok()?;
    let svg = code
        .render::<qrcode::render::svg::Color<'_>>()
        .quiet_zone(true)
        .min_dimensions(160, 160)
        .build();
    // The renderer writes an XML declaration: not allowed inside HTML.
    let start = svg.find("<svg")?;
    Some(svg[start..].to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn text_and_attributes_are_escaped() {
        assert_eq!(
            esc(r#"<a href="x">&</a>"#),
            "&lt;a href=&quot;x&quot;&gt;&amp;&lt;/a&gt;"
        );
    }

    #[test]
    fn a_link_becomes_an_svg_qr_code() {
        let svg = qr_svg("https://example.org/#lesson=p3&step=3").unwrap();
        assert!(svg.starts_with("<svg") && svg.contains("<path"), "{svg}");
    }
}
