//! The few things that differ between the browser and the desktop: the URL fragment, the
//! status object the page test reads, and saving a file.

/// The URL fragment at start-up (without `#`), or "" on the desktop.
pub fn initial_fragment() -> String {
    #[cfg(target_arch = "wasm32")]
    {
        web_sys::window()
            .and_then(|w| w.location().hash().ok())
            .unwrap_or_default()
            .trim_start_matches('#')
            .to_string()
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        std::env::args().nth(1).unwrap_or_default()
    }
}

/// The URL fragment now (without `#`): the page's address bar, where a reader may paste a
/// link into the open tab; `None` on the desktop.
pub fn current_fragment() -> Option<String> {
    #[cfg(target_arch = "wasm32")]
    {
        web_sys::window()
            .and_then(|w| w.location().hash().ok())
            .map(|h| h.trim_start_matches('#').to_string())
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        None
    }
}

/// Writes the URL fragment: a new history entry when `new_entry` (a lesson step, another
/// lab: Back returns to it), else in place of the current one (a slider moved). A no-op on
/// the desktop.
pub fn set_fragment(fragment: &str, new_entry: bool) {
    #[cfg(target_arch = "wasm32")]
    if let Some(history) = web_sys::window().and_then(|w| w.history().ok()) {
        let url = format!("#{fragment}");
        let state = wasm_bindgen::JsValue::NULL;
        let _ = if new_entry {
            history.push_state_with_url(&state, "", Some(&url))
        } else {
            history.replace_state_with_url(&state, "", Some(&url))
        };
    }
    #[cfg(not(target_arch = "wasm32"))]
    let _ = (fragment, new_entry);
}

/// Asks `ctx` for a frame whenever the browser moves through the history (Back, Forward) or
/// the reader edits the fragment: a paused page draws only on input, and the frame loop is
/// where the new fragment is read. A no-op on the desktop.
pub fn repaint_on_history_moves(ctx: &egui::Context) {
    #[cfg(target_arch = "wasm32")]
    {
        use wasm_bindgen::JsCast as _;
        let Some(window) = web_sys::window() else {
            return;
        };
        for event in ["popstate", "hashchange"] {
            let ctx = ctx.clone();
            let listener = wasm_bindgen::closure::Closure::<dyn FnMut()>::new(move || {
                ctx.request_repaint();
            });
            let _ =
                window.add_event_listener_with_callback(event, listener.as_ref().unchecked_ref());
            // Listens for the page's whole life.
            listener.forget();
        }
    }
    #[cfg(not(target_arch = "wasm32"))]
    let _ = ctx;
}

/// The first of the browser's languages the page speaks (`navigator.languages`); English on
/// the desktop, where the switch or `lang=` choose.
pub fn browser_lang() -> attlab::i18n::Lang {
    #[cfg(target_arch = "wasm32")]
    {
        let Some(navigator) = web_sys::window().map(|w| w.navigator()) else {
            return attlab::i18n::Lang::En;
        };
        let tags: Vec<String> = navigator
            .languages()
            .iter()
            .filter_map(|v| v.as_string())
            .chain(navigator.language())
            .collect();
        attlab::i18n::Lang::negotiate(tags.iter().map(String::as_str))
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        attlab::i18n::Lang::En
    }
}

/// Sets `<html lang>` (a screen reader reads the page in that language's voice); a no-op on
/// the desktop.
pub fn set_document_lang(code: &str) {
    #[cfg(target_arch = "wasm32")]
    if let Some(html) = web_sys::window()
        .and_then(|w| w.document())
        .and_then(|d| d.document_element())
    {
        let _ = html.set_attribute("lang", code);
    }
    #[cfg(not(target_arch = "wasm32"))]
    let _ = code;
}

/// The page's address without its fragment (`https://host/path/`), in the browser.
pub fn page_address() -> Option<String> {
    #[cfg(target_arch = "wasm32")]
    {
        let href = web_sys::window()?.location().href().ok()?;
        Some(href.split('#').next().unwrap_or_default().to_string())
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        None
    }
}

/// What the page test reads as `window.attlabStatus`.
pub struct Status<'a> {
    /// Frames drawn.
    pub frames: u64,
    /// Current lab id.
    pub lab: &'a str,
    /// Simulation steps since reset.
    pub sim_steps: u64,
    /// Bytes the recorder holds (its fixed budget).
    pub recorder_bytes: usize,
    /// Application errors (not user-input messages).
    pub errors: &'a [String],
    /// The last PNG saved: name, width, height, bytes.
    pub last_png: Option<&'a (String, usize, usize, usize)>,
    /// The window and the plot area, `[x, y, width, height]` in points, and the pixels
    /// per point (CSS pixels per point: the zoom, larger in presenter mode).
    pub layout: Option<([f32; 4], [f32; 4], f32)>,
    /// The lab's views drawn: `[index in the lab's views, x, y, width, height]`, in points.
    pub views: Vec<[f32; 5]>,
    /// The lesson step shown (1-based), if a lesson is open.
    pub lesson_step: Option<usize>,
    /// The run is playing (not paused).
    pub playing: bool,
    /// Simulation time (s).
    pub t_s: f64,
    /// Each estimator's angle now (rad; NaN for one without an angle): what a live
    /// session's page test compares with the replay of its record.
    pub angles_rad: Vec<f64>,
    /// The sweep's progress (0…1), if one is open.
    pub sweep_progress: Option<f64>,
    /// How the last sweep ran: workers (0: slices) and wall time (s) once done.
    pub sweep_timing: (usize, Option<f64>),
    /// Each finished point's first objective (or first RMS without a scoring).
    pub sweep_values: Vec<f64>,
}

/// The sweep part of the status (`progress`, `workers`, `wallS`, `values`), if a sweep is open.
#[cfg(target_arch = "wasm32")]
fn sweep_status(status: &Status<'_>) -> Option<js_sys::Object> {
    use js_sys::{Array, Object, Reflect};
    use wasm_bindgen::JsValue;
    let p = status.sweep_progress?;
    let sweep = Object::new();
    let (workers, wall_s) = status.sweep_timing;
    let values: Array = (status.sweep_values.iter())
        .map(|v| JsValue::from_f64(*v))
        .collect();
    let _ = Reflect::set(&sweep, &"progress".into(), &JsValue::from_f64(p));
    let _ = Reflect::set(
        &sweep,
        &"workers".into(),
        &JsValue::from_f64(workers as f64),
    );
    let wall = wall_s.map_or(JsValue::NULL, JsValue::from_f64);
    let _ = Reflect::set(&sweep, &"wallS".into(), &wall);
    let _ = Reflect::set(&sweep, &"values".into(), &values);
    Some(sweep)
}

/// Publishes the status (browser only).
pub fn publish_status(status: &Status<'_>) {
    #[cfg(target_arch = "wasm32")]
    {
        use js_sys::{Array, Object, Reflect};
        use wasm_bindgen::JsValue;
        let Some(w) = web_sys::window() else { return };
        let o = Object::new();
        let errors: Array = status.errors.iter().map(|e| JsValue::from_str(e)).collect();
        let _ = Reflect::set(
            &o,
            &"frames".into(),
            &JsValue::from_f64(status.frames as f64),
        );
        let _ = Reflect::set(&o, &"lab".into(), &JsValue::from_str(status.lab));
        let _ = Reflect::set(
            &o,
            &"simSteps".into(),
            &JsValue::from_f64(status.sim_steps as f64),
        );
        let _ = Reflect::set(&o, &"errors".into(), &errors);
        if let Some((name, w, h, n)) = status.last_png {
            let png = Object::new();
            let _ = Reflect::set(&png, &"name".into(), &JsValue::from_str(name));
            let _ = Reflect::set(&png, &"width".into(), &JsValue::from_f64(*w as f64));
            let _ = Reflect::set(&png, &"height".into(), &JsValue::from_f64(*h as f64));
            let _ = Reflect::set(&png, &"bytes".into(), &JsValue::from_f64(*n as f64));
            let _ = Reflect::set(&o, &"lastPng".into(), &png);
        }
        if let Some((window, plot, zoom)) = status.layout {
            let _ = Reflect::set(&o, &"zoom".into(), &JsValue::from_f64(f64::from(zoom)));
            let rect = |r: [f32; 4]| -> Array {
                r.iter().map(|v| JsValue::from_f64(f64::from(*v))).collect()
            };
            let _ = Reflect::set(&o, &"window".into(), &rect(window));
            let _ = Reflect::set(&o, &"plotArea".into(), &rect(plot));
        }
        let views: Array = status
            .views
            .iter()
            .map(|r| -> JsValue {
                r.iter()
                    .map(|v| JsValue::from_f64(f64::from(*v)))
                    .collect::<Array>()
                    .into()
            })
            .collect();
        let _ = Reflect::set(&o, &"views".into(), &views);
        if let Some(step) = status.lesson_step {
            let _ = Reflect::set(&o, &"lessonStep".into(), &JsValue::from_f64(step as f64));
        }
        let _ = Reflect::set(&o, &"playing".into(), &JsValue::from_bool(status.playing));
        let _ = Reflect::set(&o, &"tS".into(), &JsValue::from_f64(status.t_s));
        let angles: Array = status
            .angles_rad
            .iter()
            .map(|a| JsValue::from_f64(*a))
            .collect();
        let _ = Reflect::set(&o, &"anglesRad".into(), &angles);
        if let Some(sweep) = sweep_status(status) {
            let _ = Reflect::set(&o, &"sweep".into(), &sweep);
        }
        let _ = Reflect::set(
            &o,
            &"recorderBytes".into(),
            &JsValue::from_f64(status.recorder_bytes as f64),
        );
        // The wasm linear memory (it only grows): what the soak watches.
        let memory = wasm_bindgen::memory();
        if let Ok(buffer) = Reflect::get(&memory, &"buffer".into())
            && let Ok(len) = Reflect::get(&buffer, &"byteLength".into())
        {
            let _ = Reflect::set(&o, &"wasmBytes".into(), &len);
        }
        let _ = Reflect::set(&w, &"attlabStatus".into(), &o);
    }
    #[cfg(not(target_arch = "wasm32"))]
    let _ = status;
}

/// Offers `contents` to the user as a file named `name`: in the browser a direct download
/// (a link to a blob, clicked at once: nothing on the page waits for a click), on the
/// desktop a save dialog. Returns a message for the user, in `lang`.
/// On the desktop, `dir` saves there without asking (scripted and headless use).
pub fn save_file(
    name: &str,
    mime: &str,
    contents: Vec<u8>,
    dir: Option<&std::path::Path>,
    lang: attlab::i18n::Lang,
) -> Result<String, SaveError> {
    use attlab::i18n::t_with;
    let _ = (mime, dir);
    #[cfg(target_arch = "wasm32")]
    {
        download(name, mime, &contents).map_err(|e| SaveError::Refused {
            detail: format!("{e:?}"),
        })?;
        Ok(t_with(lang, "saved-downloaded", &[("name", name.into())]))
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        let chosen = match dir {
            Some(dir) => Some(dir.join(name)),
            None => rfd::FileDialog::new().set_file_name(name).save_file(),
        };
        let Some(path) = chosen else {
            return Ok(attlab::i18n::t(lang, "saved-cancelled"));
        };
        let shown = path.display().to_string();
        std::fs::write(&path, contents).map_err(|e| SaveError::CannotWrite {
            path: shown.clone(),
            error: e.to_string(),
        })?;
        Ok(t_with(lang, "saved-written", &[("path", shown.into())]))
    }
}

/// Why a file could not be saved (the browser's or the system's own words inside).
#[derive(Clone, Debug, PartialEq)]
pub enum SaveError {
    /// The browser refused the download.
    Refused {
        /// What it said.
        detail: String,
    },
    /// The file could not be written.
    CannotWrite {
        /// Where.
        path: String,
        /// What the system said.
        error: String,
    },
}

impl SaveError {
    /// The reason in `lang`.
    pub fn words(&self, lang: attlab::i18n::Lang) -> String {
        use attlab::i18n::t_with;
        match self {
            SaveError::Refused { detail } => {
                t_with(lang, "save-refused", &[("detail", detail.clone().into())])
            }
            SaveError::CannotWrite { path, error } => t_with(
                lang,
                "save-cannot-write",
                &[
                    ("path", path.clone().into()),
                    ("error", error.clone().into()),
                ],
            ),
        }
    }
}

/// Downloads `contents` as `name` through a blob URL and a clicked `<a download>`; the URL
/// is revoked a minute later (the browser has the file by then).
#[cfg(target_arch = "wasm32")]
fn download(name: &str, mime: &str, contents: &[u8]) -> Result<(), wasm_bindgen::JsValue> {
    use wasm_bindgen::JsCast;
    let window = web_sys::window().ok_or("no window")?;
    let document = window.document().ok_or("no document")?;
    let bytes = js_sys::Uint8Array::from(contents);
    let options = web_sys::BlobPropertyBag::new();
    options.set_type(mime);
    let blob = web_sys::Blob::new_with_u8_array_sequence_and_options(
        &js_sys::Array::of1(&bytes),
        &options,
    )?;
    let url = web_sys::Url::create_object_url_with_blob(&blob)?;
    let a: web_sys::HtmlAnchorElement = document.create_element("a")?.dyn_into()?;
    a.set_href(&url);
    a.set_download(name);
    a.click();
    let revoke = wasm_bindgen::closure::Closure::once_into_js(move || {
        let _ = web_sys::Url::revoke_object_url(&url);
    });
    window.set_timeout_with_callback_and_timeout_and_arguments_0(revoke.unchecked_ref(), 60_000)?;
    Ok(())
}

/// What build of the page this is (the About line).
#[derive(Clone, Debug, PartialEq, Eq, serde::Deserialize)]
pub struct BuildInfo {
    /// The software's version.
    pub version: String,
    /// The commit it was built from.
    pub commit: String,
    /// The commit's date (YYYY-MM-DD).
    pub date: String,
}

/// The build: in the page, what `cargo xtask dist` wrote into `index.html` (and
/// `version.json`); on the desktop, the crate's version and `ATTLAB_COMMIT` if the build
/// had it.
pub fn build_info() -> &'static BuildInfo {
    static INFO: std::sync::OnceLock<BuildInfo> = std::sync::OnceLock::new();
    INFO.get_or_init(|| {
        let fallback = BuildInfo {
            version: env!("CARGO_PKG_VERSION").to_string(),
            commit: option_env!("ATTLAB_COMMIT")
                .unwrap_or("unknown")
                .to_string(),
            date: "unknown".to_string(),
        };
        #[cfg(target_arch = "wasm32")]
        {
            let text = web_sys::window()
                .and_then(|w| w.document())
                .and_then(|d| d.get_element_by_id("attlab_build_info"))
                .and_then(|e| e.text_content());
            text.and_then(|t| serde_json::from_str(&t).ok())
                .unwrap_or(fallback)
        }
        #[cfg(not(target_arch = "wasm32"))]
        fallback
    })
}
