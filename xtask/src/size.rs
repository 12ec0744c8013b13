//! `cargo xtask size`: where the page's wasm goes. Builds the site, reports the shipped
//! file raw, gzipped and brotli-compressed, then profiles the module with `twiggy` and sums
//! its items by crate.
//!
//! twiggy needs the function names, which the shipped file drops (`wasm-bindgen
//! --remove-name-section`), so it reads rustc's output before wasm-bindgen and wasm-opt: the
//! shares are of that larger, unoptimised module, which is what the source decides.

use crate::cmd::{self, Result};
use crate::{site, tools};
use std::collections::BTreeMap;

/// Rows of the by-crate table.
const TOP_CRATES: usize = 25;

/// Builds the site and prints the size report.
pub fn run() -> Result<()> {
    tools::ensure_twiggy()?;
    site::build(true, site::SizeReport::WithBrotli)?;
    let raw = site::raw_wasm();
    let mut twiggy = cmd::new("twiggy");
    twiggy.args(["top", "-n", "1000000", "-f", "csv"]).arg(&raw);
    let csv = cmd::probe(&mut twiggy).ok_or("twiggy top failed")?;
    let rows = by_crate(&csv)?;
    let total: u64 = rows.iter().map(|(_, b)| b).sum();
    println!(
        "\nxtask: {} by crate (twiggy {}, before wasm-bindgen and wasm-opt, {} bytes in all):",
        raw.display(),
        tools::TWIGGY_VERSION,
        total
    );
    println!("| part | bytes | share |\n|---|---:|---:|");
    for (name, bytes) in rows.iter().take(TOP_CRATES) {
        #[allow(clippy::cast_precision_loss)]
        let share = 100.0 * *bytes as f64 / total.max(1) as f64;
        println!("| {name} | {bytes} | {share:.1} % |");
    }
    let rest: u64 = rows.iter().skip(TOP_CRATES).map(|(_, b)| b).sum();
    println!(
        "| {} more | {rest} | |",
        rows.len().saturating_sub(TOP_CRATES)
    );
    Ok(())
}

/// Sums twiggy's `top` CSV (`Name,ShallowSize,…`, names quoted as CSV quotes them) by the
/// crate an item belongs to; sections and data segments keep their own names. Largest first.
fn by_crate(csv_text: &str) -> Result<Vec<(String, u64)>> {
    let mut reader = csv::Reader::from_reader(csv_text.as_bytes());
    let headers = reader.headers()?.clone();
    let column = |name: &str| {
        headers
            .iter()
            .position(|h| h == name)
            .ok_or_else(|| format!("twiggy CSV has no `{name}` column: {headers:?}"))
    };
    let (name_at, size_at) = (column("Name")?, column("ShallowSize")?);
    let mut sums: BTreeMap<String, u64> = BTreeMap::new();
    for (n, record) in reader.records().enumerate() {
        let record = record?;
        let (Some(name), Some(size)) = (record.get(name_at), record.get(size_at)) else {
            return Err(format!("twiggy CSV row {}: {record:?}", n + 1).into());
        };
        let size: u64 = size
            .parse()
            .map_err(|_| format!("twiggy CSV row {}: size `{size}`", n + 1))?;
        *sums.entry(owner(name)).or_default() += size;
    }
    let mut rows: Vec<(String, u64)> = sums.into_iter().collect();
    rows.sort_by(|a, b| b.1.cmp(&a.1).then(a.0.cmp(&b.0)));
    Ok(rows)
}

/// The crate an item's name starts with (`<a::B as c::D>::f` belongs to `a`), or the name
/// itself for sections, data segments and other items without a path.
fn owner(name: &str) -> String {
    let path = name
        .trim_start_matches(['<', '&', '*'])
        .trim_start_matches("mut ")
        .trim_start_matches("dyn ");
    match path.split_once("::") {
        Some((krate, _))
            if !krate.is_empty()
                && krate.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') =>
        {
            krate.to_string()
        }
        _ => name.chars().take(48).collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn items_are_summed_by_their_crate() {
        // As twiggy 0.8 writes it (names with quotes or commas are quoted).
        let csv = "Name,ShallowSize,ShallowSizePercent,RetainedSize,RetainedSizePercent\n\
                   \"\"\"function names\"\" subsection\",300,30.0,,\n\
                   <fearless_simd::Fallback as fearless_simd::Simd>::f::h1,200,20.0,,\n\
                   fearless_simd::g::h2,100,10.0,,\n\
                   \"wgpu_core::a::<T, U>::b\",50,5.0,,\n\
                   \"data segment \"\".rodata\"\"\",350,35.0,,\n";
        let rows = by_crate(csv).expect("parses");
        assert_eq!(
            rows,
            vec![
                ("data segment \".rodata\"".to_string(), 350),
                ("\"function names\" subsection".to_string(), 300),
                ("fearless_simd".to_string(), 300),
                ("wgpu_core".to_string(), 50),
            ]
        );
        assert!(by_crate("Name,ShallowSize\nx::y,12kB\n").is_err());
        assert!(by_crate("Item,Bytes\nx::y,12\n").is_err());
    }
}
