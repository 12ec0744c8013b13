//! Builds the static site in `dist/`: the release wasm (`web` profile), `wasm-bindgen`,
//! `wasm-opt -O2` (cached by input hash), `index.html` and `assets/`.

use crate::cmd::{self, Result};
use crate::{publish, tools, wasm};
use flate2::Compression;
use flate2::write::GzEncoder;
use sha2::{Digest, Sha256};
use std::fs;
use std::io::Write;
use std::path::{Path, PathBuf};

/// The web crate's package name.
const WEB_PACKAGE: &str = "attlab-web";
/// The web crate's library name (the wasm file stem).
const WEB_LIB: &str = "attlab_web";
/// The cargo profile for the page build (defined in the root Cargo.toml).
const WEB_PROFILE: &str = "web";
/// The optimisation level passed to `wasm-opt`.
const OPT_LEVEL: &str = "-O2";

/// Files of `site/` copied to the root of `dist/` (the service worker is written with the
/// build's hash: [`write_versioned`]).
const SITE_FILES: &[&str] = &[
    "sweep-worker.js",
    "manifest.json",
    "icon-192.png",
    "icon-512.png",
];

/// The `dist/` folder.
pub fn dist_dir() -> PathBuf {
    cmd::root().join("dist")
}

/// How much of the download's size a build reports.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SizeReport {
    /// Raw and gzipped (under a second).
    Gzip,
    /// Raw, gzipped and brotli'd at quality 11 (about 35 s for the 6-MB wasm on this
    /// project's machine, even with brotli optimised): `dist` and `size`, whose figures
    /// docs/measured.md quotes.
    WithBrotli,
}

/// Builds the whole site into `dist/` and returns that folder. `optimise` runs `wasm-opt`;
/// `sizes` says which compressed sizes of the wasm to print. The site's address is the one
/// of `site/address.txt`, if any.
pub fn build(optimise: bool, sizes: SizeReport) -> Result<PathBuf> {
    build_for(optimise, sizes, None)
}

/// [`build`] for the public address `address` (`--address`; `None`: the address file's).
pub fn build_for(optimise: bool, sizes: SizeReport, address: Option<&str>) -> Result<PathBuf> {
    let address = publish::address(address)?;
    tools::ensure_wasm_tools(optimise)?;
    let raw = build_wasm()?;
    let dist = dist_dir();
    if dist.exists() {
        fs::remove_dir_all(&dist).map_err(|e| format!("removing {}: {e}", dist.display()))?;
    }
    let pkg = dist.join("pkg");
    bindgen(&raw, &pkg)?;
    let bg = pkg.join(format!("{WEB_LIB}_bg.wasm"));
    if optimise {
        optimise_wasm(&raw, &bg)?;
    } else {
        println!("xtask: --no-opt: skipping wasm-opt");
    }
    write_versioned(&pkg, &dist)?;
    let build = publish::build();
    write_build_info(&dist, &publish::build_json(&build, address.as_deref()))?;
    publish::teacher_notes(&dist, &build, address.as_deref())?;
    // The sweep worker, the app manifest and its icons (offline and installable).
    for name in SITE_FILES {
        copy_file(&cmd::root().join("site").join(name), &dist.join(name))?;
    }
    let assets = cmd::root().join("assets");
    if assets.is_dir() {
        copy_dir(&assets, &dist.join("assets"))?;
    }
    join_russian(&dist.join("assets/locales/ru.ftl"))?;
    report_size(&bg, sizes)?;
    println!("xtask: site ready in {}", dist.display());
    Ok(dist)
}

/// The placeholder in `index.html` and `site/sw.js` for the build's hash (see
/// [`write_versioned`]).
const BUILD_PLACEHOLDER: &str = "__ATTLAB_BUILD__";

/// The files written with the build's hash: (source under the repository's root, name in
/// `dist/`).
const VERSIONED_FILES: [(&str, &str); 2] = [("index.html", "index.html"), ("site/sw.js", "sw.js")];

/// Writes `index.html` and the service worker into `dist`, with the hash of the wasm and its
/// JS glue in `pkg` in place of [`BUILD_PLACEHOLDER`]: the page asks for both with
/// `?v=<hash>`, so a host may keep them for good (`attlab-serve` does: V8 then reuses its
/// compiled code on every later load) and a new build is a new URL; the service worker keeps
/// one copy of each build's files, for offline use.
fn write_versioned(pkg: &Path, dist: &Path) -> Result<()> {
    let mut hasher = Sha256::new();
    for name in [format!("{WEB_LIB}_bg.wasm"), format!("{WEB_LIB}.js")] {
        hasher.update(read(&pkg.join(name))?);
    }
    let hash = hex(&hasher.finalize()[..8]);
    for (source, name) in VERSIONED_FILES {
        let from = cmd::root().join(source);
        let text =
            fs::read_to_string(&from).map_err(|e| format!("reading {}: {e}", from.display()))?;
        let text = versioned(&text, &hash).map_err(|e| format!("{}: {e}", from.display()))?;
        let to = dist.join(name);
        fs::write(&to, text).map_err(|e| format!("writing {}: {e}", to.display()))?;
    }
    Ok(())
}

/// The placeholder in `index.html` for the build's JSON (version, commit, date, address),
/// which the page's About line reads.
const INFO_PLACEHOLDER: &str = "__ATTLAB_BUILD_INFO__";

/// Writes `version.json` into `dist` and the same JSON into its `index.html`.
fn write_build_info(dist: &Path, json: &str) -> Result<()> {
    let version = dist.join("version.json");
    fs::write(&version, format!("{json}\n"))
        .map_err(|e| format!("writing {}: {e}", version.display()))?;
    let index = dist.join("index.html");
    let html =
        fs::read_to_string(&index).map_err(|e| format!("reading {}: {e}", index.display()))?;
    if html.matches(INFO_PLACEHOLDER).count() != 1 {
        return Err(format!("index.html must hold {INFO_PLACEHOLDER} once").into());
    }
    fs::write(&index, html.replace(INFO_PLACEHOLDER, json))
        .map_err(|e| format!("writing {}: {e}", index.display()).into())
}

/// `html` with the build `hash` in place of its one [`BUILD_PLACEHOLDER`]; an error if it has
/// none (the page would ask for unversioned files) or several.
fn versioned(html: &str, hash: &str) -> std::result::Result<String, String> {
    match html.matches(BUILD_PLACEHOLDER).count() {
        1 => Ok(html.replace(BUILD_PLACEHOLDER, hash)),
        n => Err(format!(
            "expected the build placeholder {BUILD_PLACEHOLDER} once, found it {n} times"
        )),
    }
}

/// `bytes` as lower-case hex digits (a digest in a file name or a URL).
fn hex(bytes: &[u8]) -> String {
    bytes.iter().map(|b| format!("{b:02x}")).collect()
}

/// rustc's wasm for the page, before wasm-bindgen (it still has its function names).
pub fn raw_wasm() -> PathBuf {
    cmd::target_dir()
        .join(tools::WASM_TARGET)
        .join(WEB_PROFILE)
        .join(format!("{WEB_LIB}.wasm"))
}

/// `cargo build --profile web --target wasm32-unknown-unknown -p attlab-web`.
fn build_wasm() -> Result<PathBuf> {
    let mut build = cmd::cargo();
    build.args([
        "build",
        "--profile",
        WEB_PROFILE,
        "--target",
        tools::WASM_TARGET,
    ]);
    build.args(["-p", WEB_PACKAGE, "--lib"]);
    cmd::run(&mut build)?;
    let wasm = raw_wasm();
    if wasm.is_file() {
        Ok(wasm)
    } else {
        Err(format!("the build did not produce {}", wasm.display()).into())
    }
}

/// `wasm-bindgen --target web --no-typescript --remove-name-section --out-dir <pkg> <wasm>`.
fn bindgen(wasm: &Path, pkg: &Path) -> Result<()> {
    let mut bindgen = cmd::new("wasm-bindgen");
    bindgen
        .args([
            "--target",
            "web",
            "--no-typescript",
            "--remove-name-section",
        ])
        .arg("--out-dir")
        .arg(pkg)
        .arg(wasm);
    cmd::run(&mut bindgen)
}

/// Runs `wasm-opt` on `bg` in place, reusing a cached output when the input is unchanged.
/// The feature flags come from the `target_features` section of rustc's output `raw`.
fn optimise_wasm(raw: &Path, bg: &Path) -> Result<()> {
    let raw_bytes = read(raw)?;
    let (flags, unknown) = wasm::opt_flags(&raw_bytes);
    if !unknown.is_empty() {
        println!("xtask: warning: wasm-opt has no flag for wasm features {unknown:?}");
    }
    let input = read(bg)?;
    let mut hasher = Sha256::new();
    hasher.update(&input);
    hasher.update(OPT_LEVEL.as_bytes());
    for flag in &flags {
        hasher.update(flag.as_bytes());
    }
    hasher.update(tools::BINARYEN_VERSION.as_bytes());
    let key = hex(&hasher.finalize());
    let cache_dir = cmd::target_dir().join("wasm-opt-cache");
    let cached = cache_dir.join(format!("{key}.wasm"));
    if cached.is_file() {
        println!("xtask: wasm-opt: cached output {}", cached.display());
        return keep_smaller(&cached, bg);
    }
    fs::create_dir_all(&cache_dir).map_err(|e| format!("creating {}: {e}", cache_dir.display()))?;
    let partial = cache_dir.join(format!("{key}.partial.wasm"));
    println!("xtask: wasm-opt {OPT_LEVEL} (takes a few minutes; cached afterwards)");
    let mut opt = cmd::new(tools::wasm_opt());
    opt.arg(OPT_LEVEL)
        .args(&flags)
        .arg(bg)
        .arg("-o")
        .arg(&partial);
    cmd::run(&mut opt)?;
    fs::rename(&partial, &cached).map_err(|e| format!("caching {}: {e}", cached.display()))?;
    keep_smaller(&cached, bg)
}

/// Ships whichever of the `wasm-opt` output and the plain `wasm-bindgen` output is smaller
/// *gzipped* (what the browser downloads): for this app `-O2` shrinks the raw file but the
/// gzipped one grows by about 3 %, so measuring beats assuming.
fn keep_smaller(optimised: &Path, bg: &Path) -> Result<()> {
    let (opt_gz, plain_gz) = (gzip_len(&read(optimised)?)?, gzip_len(&read(bg)?)?);
    println!(
        "xtask: gzipped size: wasm-opt {OPT_LEVEL} {}, without {}",
        human(opt_gz),
        human(plain_gz)
    );
    if opt_gz < plain_gz {
        println!("xtask: shipping the wasm-opt output");
        copy_file(optimised, bg)
    } else {
        println!("xtask: shipping the wasm-bindgen output (wasm-opt made the download bigger)");
        Ok(())
    }
}

/// Length of `bytes` gzipped at the best level.
fn gzip_len(bytes: &[u8]) -> Result<usize> {
    let mut gz = GzEncoder::new(Vec::new(), Compression::best());
    gz.write_all(bytes)?;
    Ok(gz.finish()?.len())
}

/// Length of `bytes` brotli-compressed at quality 11 with a 4-MiB window (what a host that
/// precompresses static files serves).
fn brotli_len(bytes: &[u8]) -> Result<usize> {
    let mut out = Vec::new();
    let params = brotli::enc::BrotliEncoderParams {
        quality: 11,
        lgwin: 22,
        ..Default::default()
    };
    brotli::BrotliCompress(&mut &bytes[..], &mut out, &params)?;
    Ok(out.len())
}

/// Prints the size of `wasm`, raw, gzipped at the best level and, if `sizes` asks,
/// brotli'd at quality 11.
fn report_size(wasm: &Path, sizes: SizeReport) -> Result<()> {
    let bytes = read(wasm)?;
    let brotli = match sizes {
        SizeReport::Gzip => String::new(),
        SizeReport::WithBrotli => format!(", {} brotli", human(brotli_len(&bytes)?)),
    };
    println!(
        "xtask: {}: {} raw, {} gzipped{brotli}",
        wasm.file_name().unwrap_or_default().to_string_lossy(),
        human(bytes.len()),
        human(gzip_len(&bytes)?),
    );
    Ok(())
}

/// `1234567` → `"1234567 B (1.18 MiB)"`.
fn human(bytes: usize) -> String {
    #[allow(clippy::cast_precision_loss)]
    let mib = bytes as f64 / (1024.0 * 1024.0);
    format!("{bytes} B ({mib:.2} MiB)")
}

/// Reads a whole file, with the path in the error.
fn read(path: &Path) -> Result<Vec<u8>> {
    fs::read(path).map_err(|e| format!("reading {}: {e}", path.display()).into())
}

/// Writes every `.ftl` file of `crate/locales/ru/` and every lab folder's `ru.ftl`
/// (`crate/src/labs/*/ru.ftl`), in path order, into one file `to`: the Russian catalogue the
/// page fetches beside its wasm (the native binary includes the same files; a test of
/// `attlab::i18n` checks the two agree).
fn join_russian(to: &Path) -> Result<()> {
    let entries = |dir: &Path| -> Result<Vec<PathBuf>> {
        Ok(fs::read_dir(dir)
            .map_err(|e| format!("reading {}: {e}", dir.display()))?
            .filter_map(|e| e.ok().map(|e| e.path()))
            .collect())
    };
    let central = entries(&cmd::root().join("crate/locales/ru"))?;
    let labs = entries(&cmd::root().join("crate/src/labs"))?;
    let mut files: Vec<PathBuf> = (central.into_iter())
        .chain(labs.into_iter().map(|d| d.join("ru.ftl")))
        .filter(|p| p.is_file() && p.extension().is_some_and(|x| x == "ftl"))
        .collect();
    files.sort();
    let mut joined = String::new();
    for file in &files {
        let text =
            fs::read_to_string(file).map_err(|e| format!("reading {}: {e}", file.display()))?;
        joined.push_str(&text);
        joined.push('\n');
    }
    if let Some(parent) = to.parent() {
        fs::create_dir_all(parent).map_err(|e| format!("creating {}: {e}", parent.display()))?;
    }
    fs::write(to, joined).map_err(|e| format!("writing {}: {e}", to.display()).into())
}

/// Copies one file, creating the destination folder.
fn copy_file(from: &Path, to: &Path) -> Result<()> {
    if let Some(parent) = to.parent() {
        fs::create_dir_all(parent).map_err(|e| format!("creating {}: {e}", parent.display()))?;
    }
    fs::copy(from, to)
        .map_err(|e| format!("copying {} to {}: {e}", from.display(), to.display()))?;
    Ok(())
}

/// Copies a folder tree.
fn copy_dir(from: &Path, to: &Path) -> Result<()> {
    let entries = fs::read_dir(from).map_err(|e| format!("reading {}: {e}", from.display()))?;
    for entry in entries {
        let entry = entry?;
        let target = to.join(entry.file_name());
        if entry.file_type()?.is_dir() {
            copy_dir(&entry.path(), &target)?;
        } else {
            copy_file(&entry.path(), &target)?;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::{BUILD_PLACEHOLDER, hex, human, versioned};

    #[test]
    fn human_sizes() {
        assert_eq!(human(1024 * 1024), "1048576 B (1.00 MiB)");
    }

    #[test]
    fn digests_read_as_hex() {
        assert_eq!(hex(&[0x00, 0x0a, 0xff]), "000aff");
    }

    #[test]
    fn the_page_gets_its_build_hash_once() {
        let page = format!("const build = '?v={BUILD_PLACEHOLDER}';");
        assert_eq!(
            versioned(&page, "0a1b2c").as_deref(),
            Ok("const build = '?v=0a1b2c';")
        );
        assert!(versioned("no placeholder", "0a1b2c").is_err());
        assert!(versioned(&page.repeat(2), "0a1b2c").is_err());
        // The real page and its service worker have it.
        for text in [
            include_str!("../../index.html"),
            include_str!("../../site/sw.js"),
        ] {
            assert!(versioned(text, "0a1b2c").is_ok_and(|v| v.contains("'?v=0a1b2c'")));
        }
    }
}
