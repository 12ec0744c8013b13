//! What makes the site publishable: its public address (one place, `site/address.txt`, or
//! `--address`), the build's version and commit (`version.json`, and the About line through
//! `index.html`), the teacher notes (`attlab teacher`, into `teacher/`) and, with
//! `--archive`, the site as a `.tar.gz` and a `.zip` for a school's own server or an LMS.

use crate::cmd::{self, Result};
use std::fs;
use std::io::Write as _;
use std::path::{Path, PathBuf};

/// The file that holds the site's public address.
pub const ADDRESS_FILE: &str = "site/address.txt";

/// The site's public address: `given` (`--address`) or the one line of [`ADDRESS_FILE`]
/// that is not a comment; `None` when neither has one. An address must be http(s) and end
/// in `/` (a `/` is added to one without).
pub fn address(given: Option<&str>) -> Result<Option<String>> {
    let from_file = || -> Result<Option<String>> {
        let path = cmd::root().join(ADDRESS_FILE);
        let text = fs::read_to_string(&path).map_err(|e| format!("reading {ADDRESS_FILE}: {e}"))?;
        Ok(address_in(&text))
    };
    let raw = match given {
        Some(a) => Some(a.trim().to_string()).filter(|a| !a.is_empty()),
        None => from_file()?,
    };
    let Some(raw) = raw else {
        return Ok(None);
    };
    if !(raw.starts_with("https://") || raw.starts_with("http://")) {
        return Err(
            format!("the site's address `{raw}` must start with https:// or http://").into(),
        );
    }
    Ok(Some(if raw.ends_with('/') {
        raw
    } else {
        format!("{raw}/")
    }))
}

/// The address line of `text` (the address file): the first line that is neither empty nor
/// a `#` comment.
pub fn address_in(text: &str) -> Option<String> {
    (text.lines())
        .map(str::trim)
        .find(|l| !l.is_empty() && !l.starts_with('#'))
        .map(str::to_string)
}

/// The build: version, commit and the commit's date.
pub struct Build {
    /// The workspace's version.
    pub version: String,
    /// The commit, short, with `+changes` if the work tree differs from it.
    pub commit: String,
    /// The commit's date, YYYY-MM-DD.
    pub date: String,
}

/// The build of this checkout (`unknown` where git cannot say: a copy without `.git`).
pub fn build() -> Build {
    let git = |args: &[&str]| cmd::probe(cmd::new("git").args(args)).map(|s| s.trim().to_string());
    let mut commit = git(&["rev-parse", "--short=12", "HEAD"]).unwrap_or_else(|| "unknown".into());
    if git(&["status", "--porcelain", "--untracked-files=no"]).is_some_and(|s| !s.is_empty()) {
        commit.push_str("+changes");
    }
    Build {
        version: env!("CARGO_PKG_VERSION").to_string(),
        commit,
        date: git(&["log", "-1", "--format=%cs"]).unwrap_or_else(|| "unknown".into()),
    }
}

/// The build as JSON: `version.json` and the page's About line.
pub fn build_json(build: &Build, address: Option<&str>) -> String {
    serde_json::json!({
        "name": "Attitude Lab",
        "version": build.version,
        "commit": build.commit,
        "date": build.date,
        "address": address,
    })
    .to_string()
}

/// Writes the teacher notes into `dist/teacher` with the CLI (`attlab teacher`).
pub fn teacher_notes(dist: &Path, build: &Build, address: Option<&str>) -> Result<()> {
    let mut notes = cmd::cargo();
    notes.args([
        "run", "-q", "-p", "attlab", "--bin", "attlab", "--", "teacher", "--out",
    ]);
    notes
        .arg(dist.join("teacher"))
        .args(["--commit", &build.commit]);
    if let Some(a) = address {
        notes.args(["--address", a]);
    }
    cmd::run(&mut notes)
}

/// Writes `dist` as `attitude-lab-<version>.tar.gz` and `.zip` (every file under one folder
/// of that name) into `target/site-archive/`; returns both paths.
pub fn archive(dist: &Path, build: &Build) -> Result<[PathBuf; 2]> {
    let name = format!("attitude-lab-{}", build.version);
    let out = cmd::target_dir().join("site-archive");
    fs::create_dir_all(&out).map_err(|e| format!("creating {}: {e}", out.display()))?;
    let files = files_under(dist)?;
    let tgz = out.join(format!("{name}.tar.gz"));
    let gz = flate2::write::GzEncoder::new(
        fs::File::create(&tgz).map_err(|e| format!("creating {}: {e}", tgz.display()))?,
        flate2::Compression::best(),
    );
    let mut tar = tar::Builder::new(gz);
    for (path, rel) in &files {
        tar.append_path_with_name(path, Path::new(&name).join(rel))
            .map_err(|e| format!("adding {} to {}: {e}", path.display(), tgz.display()))?;
    }
    tar.into_inner()?.finish()?.flush()?;
    let zip_path = out.join(format!("{name}.zip"));
    let mut zip = zip::ZipWriter::new(
        fs::File::create(&zip_path).map_err(|e| format!("creating {}: {e}", zip_path.display()))?,
    );
    let options = zip::write::SimpleFileOptions::default()
        .compression_method(zip::CompressionMethod::Deflated);
    for (path, rel) in &files {
        let inside = format!("{name}/{}", rel.to_string_lossy().replace('\\', "/"));
        zip.start_file(inside, options)?;
        zip.write_all(&fs::read(path).map_err(|e| format!("reading {}: {e}", path.display()))?)?;
    }
    zip.finish()?;
    Ok([tgz, zip_path])
}

/// Every file under `dir`, with its path relative to `dir`, in path order.
fn files_under(dir: &Path) -> Result<Vec<(PathBuf, PathBuf)>> {
    let mut out = Vec::new();
    let mut folders = vec![dir.to_path_buf()];
    while let Some(folder) = folders.pop() {
        for entry in
            fs::read_dir(&folder).map_err(|e| format!("reading {}: {e}", folder.display()))?
        {
            let path = entry?.path();
            if path.is_dir() {
                folders.push(path);
            } else {
                let rel = path
                    .strip_prefix(dir)
                    .map(Path::to_path_buf)
                    .unwrap_or_default();
                out.push((path, rel));
            }
        }
    }
    out.sort();
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_address_is_the_files_one_line_or_none() {
        assert_eq!(address_in("# a comment\n\n# more\n"), None);
        assert_eq!(
            address_in("# a comment\nhttps://x.org/lab/\n").as_deref(),
            Some("https://x.org/lab/")
        );
        assert_eq!(
            address(Some("https://x.org/lab")).unwrap().as_deref(),
            Some("https://x.org/lab/")
        );
        assert!(address(Some("x.org")).is_err());
        // The repository's own file parses (with or without a line).
        assert!(address(None).is_ok());
    }

    #[test]
    fn the_workflow_parses_and_runs_the_readmes_build_command() {
        let root = cmd::root();
        let text = fs::read_to_string(root.join(".github/workflows/pages.yml")).unwrap();
        let docs = yaml_rust2::YamlLoader::load_from_str(&text).unwrap();
        let jobs = &docs[0]["jobs"];
        let runs: Vec<&str> = (jobs["build"]["steps"].as_vec().unwrap().iter())
            .filter_map(|s| s["run"].as_str())
            .collect();
        assert_eq!(runs.len(), 1, "{runs:?}");
        let readme = fs::read_to_string(root.join("README.md")).unwrap();
        // The README's build command, as its code block gives it.
        let build = (readme.lines())
            .find_map(|l| l.strip_prefix("cargo xtask dist"))
            .map(|rest| {
                format!(
                    "cargo xtask dist{}",
                    rest.split('#').next().unwrap_or_default().trim_end()
                )
            })
            .expect("the README gives `cargo xtask dist`");
        assert!(
            runs[0].starts_with(&build),
            "the workflow runs `{}`, the README says `{build}`",
            runs[0]
        );
        assert_eq!(docs[0]["permissions"]["pages"].as_str(), Some("write"));
        let uses: Vec<&str> = (jobs["deploy"]["steps"].as_vec().unwrap().iter())
            .filter_map(|s| s["uses"].as_str())
            .collect();
        assert!(
            uses.iter().any(|u| u.starts_with("actions/deploy-pages")),
            "{uses:?}"
        );
    }

    #[test]
    fn an_archive_holds_every_file_of_the_site_under_one_folder() {
        let dir = std::env::temp_dir().join(format!("xtask-archive-{}", std::process::id()));
        fs::create_dir_all(dir.join("pkg")).unwrap();
        fs::write(dir.join("index.html"), "<html>").unwrap();
        fs::write(dir.join("pkg/a.wasm"), [0u8, 97, 115, 109]).unwrap();
        let build = Build {
            version: "9.9.9-test".into(),
            commit: "c".into(),
            date: "d".into(),
        };
        let [tgz, zip_path] = archive(&dir, &build).unwrap();
        let mut names = Vec::new();
        let mut reader = zip::ZipArchive::new(fs::File::open(&zip_path).unwrap()).unwrap();
        for i in 0..reader.len() {
            names.push(reader.by_index(i).unwrap().name().to_string());
        }
        assert_eq!(
            names,
            [
                "attitude-lab-9.9.9-test/index.html",
                "attitude-lab-9.9.9-test/pkg/a.wasm"
            ]
        );
        let gz = flate2::read::GzDecoder::new(fs::File::open(&tgz).unwrap());
        let mut tar = tar::Archive::new(gz);
        let in_tar: Vec<String> = (tar.entries().unwrap())
            .map(|e| e.unwrap().path().unwrap().to_string_lossy().into_owned())
            .collect();
        assert_eq!(in_tar, names);
        let _ = fs::remove_dir_all(&dir);
        let _ = fs::remove_file(tgz);
        let _ = fs::remove_file(zip_path);
    }
}
