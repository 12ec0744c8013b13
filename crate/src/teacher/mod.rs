//! The teacher notes: for each lab with a lesson, a printable page in English and in
//! Russian, generated from the lesson itself (so they never say other than the page): the
//! goal, each step's text, its question with every answer and why, the time the step takes,
//! its link and QR code, what to say while it runs, where the model differs from the paper
//! (the chapter's "differs" rows) and the paper's reference; and an index with the link's
//! items, embedding, live sensors and accessibility. `attlab teacher --out DIR` writes them;
//! `cargo xtask dist` puts them in the site's `teacher/` folder. Their words are in
//! `crate/locales/teacher/`, outside the page's catalogue (they are not in the wasm).

mod html;
mod index_page;
mod lab_page;

use crate::i18n::{FluentValue, Lang};
use crate::page::Lab;
use fluent_bundle::{FluentBundle, FluentResource};
use std::path::{Path, PathBuf};
use thiserror::Error;

pub use lab_page::{lab_page, model_rows};

/// Why the notes could not be written.
#[derive(Debug, Error)]
pub enum TeacherError {
    /// A file or folder could not be written.
    #[error("writing {path}: {source}")]
    Write {
        /// Where.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// The site's address is not an http(s) address ending in `/`.
    #[error("the site's address `{0}` must start with http:// or https:// and end with /")]
    Address(String),
}

/// What every page of the notes needs to know of the build.
#[derive(Clone, Debug)]
pub struct Build {
    /// The site's public address, ending in `/` (`https://…/attitude-lab/`); `None` for a
    /// copy built without one (links relative to the notes, no QR codes).
    pub address: Option<String>,
    /// The software's version.
    pub version: String,
    /// The commit it was built from.
    pub commit: String,
}

impl Build {
    /// A build for `address` (checked), `version` and `commit`.
    pub fn new(address: Option<&str>, version: &str, commit: &str) -> Result<Self, TeacherError> {
        let address = address.filter(|a| !a.is_empty());
        if let Some(a) = address
            && !((a.starts_with("https://") || a.starts_with("http://")) && a.ends_with('/'))
        {
            return Err(TeacherError::Address(a.to_string()));
        }
        Ok(Self {
            address: address.map(str::to_string),
            version: version.to_string(),
            commit: commit.to_string(),
        })
    }

    /// The link that opens `fragment` (without `#`) from a page of the notes in
    /// `teacher/<lang>/`: absolute with an address, relative to the notes without.
    pub fn link(&self, fragment: &str) -> String {
        match &self.address {
            Some(base) => format!("{base}#{fragment}"),
            None => format!("../../index.html#{fragment}"),
        }
    }
}

/// The link fragment of step `n` of `lab`'s lesson, in `lang` (English is the page's own).
pub fn step_fragment(lab: &dyn Lab, n: usize, lang: Lang) -> String {
    let lang = match lang {
        Lang::En => String::new(),
        other => format!("&lang={}", other.code()),
    };
    format!("lesson={}&step={n}{lang}", lab.id())
}

/// The notes' own catalogue in one language.
pub struct Words {
    lang: Lang,
    bundle: FluentBundle<FluentResource>,
}

impl Words {
    /// The words of `lang`.
    pub fn new(lang: Lang) -> Self {
        let source = match lang {
            Lang::En => include_str!("../../locales/teacher/en.ftl"),
            Lang::Ru => include_str!("../../locales/teacher/ru.ftl"),
        };
        let tag = lang.code().parse().unwrap_or_default();
        let mut bundle = FluentBundle::new(vec![tag]);
        bundle.set_use_isolating(false);
        // A broken entry is caught by the catalogue's test; the rest stays usable.
        let resource = FluentResource::try_new(source.to_string()).unwrap_or_else(|(r, _)| r);
        let _ = bundle.add_resource(resource);
        Self { lang, bundle }
    }

    /// The language.
    pub fn lang(&self) -> Lang {
        self.lang
    }

    /// Message `id` with `args`, or the id itself if it is missing (the test finds it).
    pub fn t(&self, id: &str, args: &[(&str, String)]) -> String {
        let Some(pattern) = self.bundle.get_message(id).and_then(|m| m.value()) else {
            return id.to_string();
        };
        let mut fluent_args = fluent_bundle::FluentArgs::new();
        for (name, value) in args {
            fluent_args.set(*name, FluentValue::from(value.clone()));
        }
        let mut errors = Vec::new();
        self.bundle
            .format_pattern(pattern, Some(&fluent_args), &mut errors)
            .into_owned()
    }
}

/// The labs that have a lesson, in the registry's order.
pub fn labs_with_lessons() -> Vec<&'static dyn Lab> {
    (crate::labs::all().iter().copied())
        .filter(|l| l.lesson().is_some())
        .collect()
}

/// Writes the notes into `dir`: `index.html` (a choice of language), and for each language
/// `<lang>/index.html` and `<lang>/<lab>.html`. Returns the files written.
pub fn write(dir: &Path, build: &Build) -> Result<Vec<PathBuf>, TeacherError> {
    let mut written = Vec::new();
    let mut put = |path: PathBuf, text: String| -> Result<(), TeacherError> {
        if let Some(parent) = path.parent() {
            std::fs::create_dir_all(parent).map_err(|source| TeacherError::Write {
                path: parent.to_path_buf(),
                source,
            })?;
        }
        std::fs::write(&path, text).map_err(|source| TeacherError::Write {
            path: path.clone(),
            source,
        })?;
        written.push(path);
        Ok(())
    };
    put(dir.join("index.html"), index_page::choice())?;
    for lang in Lang::ALL {
        let words = Words::new(lang);
        let folder = dir.join(lang.code());
        put(folder.join("index.html"), index_page::index(&words, build))?;
        for lab in labs_with_lessons() {
            let file = folder.join(format!("{}.html", lab.id()));
            put(file, lab_page(lab, &words, build))?;
        }
    }
    Ok(written)
}

#[cfg(test)]
mod tests;
