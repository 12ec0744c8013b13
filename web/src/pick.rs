//! Picking a log file: the desktop's own dialog (rfd), and in the browser the page's own
//! hidden `<input type="file">`, clicked. The browser's chooser then opens directly, with
//! nothing over the canvas: rfd's web dialog instead covers the whole page with a card of its
//! own (English "Ok"/"Cancel", pressed again after choosing) that takes every pointer event
//! from the canvas until it is closed, and whose "Cancel" leaves its future pending.

/// What became of a request for a file. The browser's chooser is asynchronous, so the app
/// polls the [`FileSlot`] each frame.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Picked {
    /// The file's name and bytes. Bytes, not text: the importer reports a line that is not
    /// UTF-8 by its number and keeps the others.
    File {
        /// The file's name as the system gives it.
        name: String,
        /// Its contents.
        bytes: Vec<u8>,
    },
    /// The file was chosen but could not be read.
    Unreadable {
        /// The file's name or path.
        name: String,
        /// What the system said.
        why: String,
    },
    /// The browser opened no chooser: it opens one only right after a click or a key press
    /// (a script's click, or one that comes too late, is refused).
    Refused,
}

/// Where a picked file arrives.
pub type FileSlot = std::rc::Rc<std::cell::RefCell<Option<Picked>>>;

/// The id of the page's file input (page tests hand it a file).
pub const INPUT_ID: &str = "attlab-file-input";

/// The extensions a log may have.
const LOG_EXTENSIONS: [&str; 3] = ["csv", "txt", "log"];

/// Asks the user for a text file (a CSV log) and puts what became of it into `slot`. A
/// chooser closed without a file leaves `slot` empty.
pub fn pick_text_file(slot: &FileSlot) {
    #[cfg(target_arch = "wasm32")]
    if let Err(e) = web::pick(slot) {
        *slot.borrow_mut() = Some(Picked::Unreadable {
            name: String::new(),
            why: format!("{e:?}"),
        });
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        let Some(path) = rfd::FileDialog::new()
            .add_filter("log", &LOG_EXTENSIONS)
            .pick_file()
        else {
            return;
        };
        *slot.borrow_mut() = Some(read_path(&path));
    }
}

/// Reads the file at `path` as a [`Picked`].
#[cfg(not(target_arch = "wasm32"))]
fn read_path(path: &std::path::Path) -> Picked {
    let name = path.file_name().map_or_else(
        || path.display().to_string(),
        |n| n.to_string_lossy().into_owned(),
    );
    match std::fs::read(path) {
        Ok(bytes) => Picked::File { name, bytes },
        Err(e) => Picked::Unreadable {
            name: path.display().to_string(),
            why: e.to_string(),
        },
    }
}

#[cfg(target_arch = "wasm32")]
mod web {
    use super::{FileSlot, INPUT_ID, LOG_EXTENSIONS, Picked};
    use std::cell::RefCell;
    use wasm_bindgen::JsCast;
    use wasm_bindgen::prelude::*;
    use web_sys::HtmlInputElement;

    thread_local! {
        /// The input's change handler: one at a time, the previous one dropped when a new
        /// pick replaces it (a chooser closed without a file never calls it).
        static ON_CHANGE: RefCell<Option<Closure<dyn FnMut()>>> = const { RefCell::new(None) };
    }

    /// Clicks the page's file input (made on first use) with a handler that reads the file
    /// chosen into `slot`; says [`Picked::Refused`] when the browser will open no chooser.
    pub(super) fn pick(slot: &FileSlot) -> Result<(), JsValue> {
        let input = file_input()?;
        // A file chosen twice running must still fire `change`.
        input.set_value("");
        let (arrival, source) = (slot.clone(), input.clone());
        let handler = Closure::<dyn FnMut()>::new(move || {
            let Some(file) = source.files().and_then(|files| files.get(0)) else {
                return;
            };
            let slot = arrival.clone();
            wasm_bindgen_futures::spawn_local(async move {
                *slot.borrow_mut() = Some(read(file).await);
            });
        });
        input.set_onchange(Some(handler.as_ref().unchecked_ref()));
        ON_CHANGE.with(|h| *h.borrow_mut() = Some(handler));
        if !user_activated() {
            *slot.borrow_mut() = Some(Picked::Refused);
        }
        input.click();
        Ok(())
    }

    /// The page's hidden file input, made and added to the body on first use.
    fn file_input() -> Result<HtmlInputElement, JsValue> {
        let document = web_sys::window()
            .and_then(|w| w.document())
            .ok_or("no document")?;
        if let Some(found) = document.get_element_by_id(INPUT_ID) {
            return Ok(found.dyn_into()?);
        }
        let input: HtmlInputElement = document.create_element("input")?.dyn_into()?;
        input.set_id(INPUT_ID);
        input.set_type("file");
        let accept: Vec<String> = LOG_EXTENSIONS.iter().map(|e| format!(".{e}")).collect();
        input.set_accept(&accept.join(","));
        input.set_hidden(true);
        document.body().ok_or("no body")?.append_child(&input)?;
        Ok(input)
    }

    /// Whether the page may open a chooser now (`navigator.userActivation.isActive`); true
    /// where the browser does not say.
    fn user_activated() -> bool {
        let Some(navigator) = web_sys::window().map(|w| w.navigator()) else {
            return true;
        };
        js_sys::Reflect::get(&navigator, &"userActivation".into())
            .ok()
            .filter(|a| a.is_object())
            .and_then(|a| js_sys::Reflect::get(&a, &"isActive".into()).ok())
            .and_then(|active| active.as_bool())
            .unwrap_or(true)
    }

    /// The chosen file's name and bytes.
    async fn read(file: web_sys::File) -> Picked {
        let name = file.name();
        match wasm_bindgen_futures::JsFuture::from(file.array_buffer()).await {
            Ok(buffer) => Picked::File {
                name,
                bytes: js_sys::Uint8Array::new(&buffer).to_vec(),
            },
            Err(e) => Picked::Unreadable {
                name,
                why: e.as_string().unwrap_or_else(|| format!("{e:?}")),
            },
        }
    }
}

#[cfg(all(test, not(target_arch = "wasm32")))]
mod tests {
    use super::*;

    #[test]
    fn a_file_on_disk_is_read_with_its_name_and_bytes() {
        let dir = std::env::temp_dir().join(format!("attlab-pick-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("temp dir");
        let path = dir.join("log.csv");
        std::fs::write(&path, b"t,gx\n0,1\n").expect("written");
        assert_eq!(
            read_path(&path),
            Picked::File {
                name: "log.csv".into(),
                bytes: b"t,gx\n0,1\n".to_vec()
            }
        );
        let missing = dir.join("missing.csv");
        match read_path(&missing) {
            Picked::Unreadable { name, why } => {
                assert_eq!(name, missing.display().to_string());
                assert!(!why.is_empty());
            }
            other => panic!("a missing file read as {other:?}"),
        }
        let _ = std::fs::remove_dir_all(&dir);
    }
}
