//! The browser's live sensors, as a platform part beside [`crate::platform`]: the phone's
//! gyro and accelerometer (the Generic Sensor API's `Gyroscope` and `Accelerometer` where
//! present, otherwise the `devicemotion` event, with iOS's permission prompt) and a serial
//! port (Web Serial: an Arduino printing MPU-6050 lines).
//!
//! A small script (installed once, as `window.attlabLive`) listens to the browser and
//! queues what arrives; the frame loop takes the queue every frame ([`poll`]), so the page
//! never waits for data. The queues are bounded: a tab in the background does not grow
//! them without end, and what was dropped is counted. On the desktop there are no such
//! sensors: starting one says so.

/// What arrived since the last [`poll`].
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Polled {
    /// Phone samples, eight numbers each: time (ms), accelerometer x, y, z (m/s², with
    /// gravity, the phone's axes), gyro x, y, z (the phone's axes), and the gyro's unit in
    /// °/s (1 for `devicemotion`'s °/s, 180/π for the Gyroscope sensor's rad/s).
    pub samples: Vec<f64>,
    /// Bytes from the serial port.
    pub bytes: Vec<u8>,
    /// The source is starting (a prompt open) or delivering.
    pub running: bool,
    /// Why it stopped or failed, if it did.
    pub error: Option<LiveReason>,
    /// Something the user must do (iOS: tap once more to allow the sensors), or that
    /// happened and was got over (a serial read error).
    pub note: Option<LiveReason>,
    /// Which browser API delivers (`Gyroscope + Accelerometer`, `devicemotion`, `Web Serial`).
    pub api: String,
    /// Samples or bytes dropped because the queue was full (the page was not drawing).
    pub dropped: u64,
}

/// Why a live source stopped or could not start, or what it asks of the reader: a code the
/// page says in the reader's language (catalogue id `live-why-<code>`), and the browser's
/// own detail (its error's message, as the browser wrote it; empty when there is none).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct LiveReason {
    /// What happened, e.g. `unplugged`, `no-serial`, `tap-again`.
    pub code: String,
    /// The browser's words, if any.
    pub detail: String,
}

impl LiveReason {
    /// A reason with no detail.
    pub fn new(code: &str) -> Self {
        Self {
            code: code.into(),
            detail: String::new(),
        }
    }
}

/// The page script. Its reasons are codes with the browser's detail (`L.fail(code,
/// detail)`, `L.say(code, detail)`); the page words them ([`LiveReason`]).
#[cfg_attr(not(target_arch = "wasm32"), allow(dead_code))]
pub(crate) const GLUE: &str = r#"
if (!window.attlabLive) {
  const MAX_SAMPLES = 8 * 60000, MAX_BYTES = 4 << 20;
  const L = window.attlabLive = { samples: [], chunks: [], bytes: 0, running: false,
    starting: false, error: null, note: null, api: '', dropped: 0, halt: null };
  L.reset = () => { if (L.halt) { try { L.halt(); } catch (e) {} } L.samples = []; L.chunks = [];
    L.bytes = 0; L.running = false; L.starting = true; L.error = null; L.note = null; L.api = '';
    L.dropped = 0; L.halt = null; };
  const why = (code, detail) => [code, detail === undefined ? '' : String(detail)];
  L.fail = (code, detail) => { if (L.running || L.starting) { L.error = why(code, detail); }
    L.running = false; L.starting = false; };
  L.say = (code, detail) => { L.note = why(code, detail); };
  L.run = (api) => { L.running = true; L.starting = false; L.api = api; };
  // Full (the page has not drawn for minutes): a new sample is dropped and counted; the
  // gap it leaves is the clock's to show.
  L.push = (t, a, g, unit) => {
    if (L.samples.length >= MAX_SAMPLES) { L.dropped++; return; }
    L.samples.push(t, a[0], a[1], a[2], g[0], g[1], g[2], unit);
  };
  const motion = () => {
    const h = (e) => { const a = e.accelerationIncludingGravity, r = e.rotationRate;
      if (!a || !r || a.x === null || r.alpha === null) return;
      L.push(e.timeStamp, [a.x, a.y, a.z], [r.beta, r.gamma, r.alpha], 1); };
    window.addEventListener('devicemotion', h);
    L.run('devicemotion');
    L.halt = () => window.removeEventListener('devicemotion', h);
  };
  const askThenMotion = () => DeviceMotionEvent.requestPermission().then((s) => {
      if (s === 'granted') { motion(); } else { L.fail('permission-denied'); } });
  L.startPhone = (hz) => {
    L.reset();
    if ('Gyroscope' in window && 'Accelerometer' in window) {
      try {
        const acc = new Accelerometer({ frequency: hz }), gyr = new Gyroscope({ frequency: hz });
        let a = null;
        acc.addEventListener('reading', () => { a = [acc.x, acc.y, acc.z]; });
        gyr.addEventListener('reading', () => {
          if (a) L.push(gyr.timestamp, a, [gyr.x, gyr.y, gyr.z], 180 / Math.PI); });
        const onError = (e) => L.fail('sensor-error', e.error.name + ': ' + e.error.message);
        acc.addEventListener('error', onError); gyr.addEventListener('error', onError);
        acc.start(); gyr.start();
        L.run('Gyroscope + Accelerometer');
        L.halt = () => { acc.stop(); gyr.stop(); };
        return;
      } catch (e) { /* no access: the event below */ }
    }
    if (!('DeviceMotionEvent' in window)) { L.fail('no-motion'); return; }
    if (typeof DeviceMotionEvent.requestPermission !== 'function') { motion(); return; }
    // iOS asks inside a tap: now, if this tap still counts, else at the next one.
    askThenMotion().catch(() => {
      L.say('tap-again');
      const again = () => askThenMotion().catch((e) => L.fail('sensor-error', e));
      window.addEventListener('touchend', again, { once: true });
      window.addEventListener('click', again, { once: true });
    });
  };
  L.startSerial = async (baud) => {
    L.reset();
    if (!('serial' in navigator)) {
      L.fail('no-serial');
      return;
    }
    let port, reader;
    try { port = await navigator.serial.requestPort(); }
    catch (e) { L.fail('no-port', e.message); return; }
    try { await port.open({ baudRate: baud }); }
    catch (e) { L.fail('cannot-open', e.message); return; }
    L.run('Web Serial');
    let stopped = false;
    L.halt = () => { stopped = true; if (reader) reader.cancel().catch(() => {}); };
    const gone = (e) => { if (e.target === port) L.fail('unplugged'); };
    navigator.serial.addEventListener('disconnect', gone);
    // A read error (a framing error, an overrun) is not the end: the port gives a new
    // stream. The end is the device closing it, unplugging, or Stop.
    let closed = false;
    while (!stopped && !closed && L.running) {
      if (!port.readable) { L.fail('unplugged'); break; }
      reader = port.readable.getReader();
      try {
        for (;;) {
          const { value, done } = await reader.read();
          if (done) { closed = true; break; }
          if (L.bytes + value.length > MAX_BYTES) { L.dropped += value.length; continue; }
          L.chunks.push(value); L.bytes += value.length;
        }
      } catch (e) { L.say('read-error', e.message); }
      finally { reader.releaseLock(); }
    }
    if (closed && !stopped) L.fail('closed');
    navigator.serial.removeEventListener('disconnect', gone);
    L.running = false;
    try { await port.close(); } catch (e) {}
  };
  L.stop = () => { if (L.halt) { try { L.halt(); } catch (e) {} } L.halt = null; L.running = false;
    L.starting = false; };
  L.poll = () => {
    const bytes = new Uint8Array(L.bytes); let at = 0;
    for (const c of L.chunks) { bytes.set(c, at); at += c.length; }
    const out = { samples: new Float64Array(L.samples), bytes, running: L.running || L.starting,
      error: L.error, note: L.note, api: L.api, dropped: L.dropped };
    L.samples = []; L.chunks = []; L.bytes = 0; L.error = null; L.note = null; L.dropped = 0;
    return out;
  };
}
"#;

/// Calls `method` of the page script `window[global]` with `args`, installing the script
/// (`glue`, which defines it) on first use. The page's small scripts (live sensors, sweep
/// workers) are called through here.
#[cfg(target_arch = "wasm32")]
pub(crate) fn call_glue(
    global: &str,
    glue: &str,
    method: &str,
    args: &[wasm_bindgen::JsValue],
) -> Result<wasm_bindgen::JsValue, GlueError> {
    use wasm_bindgen::{JsCast as _, JsValue};
    let threw = |e: JsValue| GlueError::Threw {
        detail: format!("{e:?}"),
    };
    let window = web_sys::window().ok_or(GlueError::NoWindow)?;
    let get = || js_sys::Reflect::get(&window, &JsValue::from_str(global));
    if get().map_or(true, |v| v.is_undefined()) {
        js_sys::Function::new_no_args(glue)
            .call0(&JsValue::NULL)
            .map_err(threw)?;
    }
    let object = get().map_err(threw)?;
    let f: js_sys::Function = js_sys::Reflect::get(&object, &method.into())
        .map_err(threw)?
        .dyn_into()
        .map_err(|_| GlueError::NotAFunction {
            name: [global, method].join("."),
        })?;
    let args: js_sys::Array = args.iter().collect();
    f.apply(&object, &args).map_err(threw)
}

/// Why a call into one of the page's small scripts failed.
#[derive(Clone, Debug, PartialEq)]
pub enum GlueError {
    /// No browser window (a worker, a test).
    NoWindow,
    /// The script threw (the browser's own words).
    Threw {
        /// What it threw.
        detail: String,
    },
    /// The script has no such function.
    NotAFunction {
        /// `global.method`.
        name: String,
    },
}

impl GlueError {
    /// The detail a [`LiveReason`] carries: the browser's words, or what was missing.
    pub fn detail(&self) -> String {
        match self {
            GlueError::NoWindow => "window".into(),
            GlueError::Threw { detail } => detail.clone(),
            GlueError::NotAFunction { name } => name.clone(),
        }
    }
}

/// Calls the live script's `method` with `args`.
#[cfg(target_arch = "wasm32")]
fn call(method: &str, args: &[wasm_bindgen::JsValue]) -> Result<wasm_bindgen::JsValue, GlueError> {
    call_glue("attlabLive", GLUE, method, args)
}

/// Starts the phone's motion sensors at `hz` (the iOS prompt appears inside this tap).
pub fn start_phone(hz: f64) -> Result<(), LiveReason> {
    #[cfg(target_arch = "wasm32")]
    return call("startPhone", &[hz.into()])
        .map(|_| ())
        .map_err(script_failed);
    #[cfg(not(target_arch = "wasm32"))]
    {
        let _ = hz;
        Err(LiveReason::new("desktop-phone"))
    }
}

/// Asks for a serial port and reads it at `baud`.
pub fn start_serial(baud: u32) -> Result<(), LiveReason> {
    #[cfg(target_arch = "wasm32")]
    return call("startSerial", &[baud.into()])
        .map(|_| ())
        .map_err(script_failed);
    #[cfg(not(target_arch = "wasm32"))]
    {
        let _ = baud;
        Err(LiveReason::new("desktop-serial"))
    }
}

/// The page script itself failed (it could not be installed or called).
#[cfg(target_arch = "wasm32")]
fn script_failed(why: GlueError) -> LiveReason {
    LiveReason {
        code: "script".into(),
        detail: why.detail(),
    }
}

/// Stops the source (the queue keeps what arrived).
pub fn stop() {
    #[cfg(target_arch = "wasm32")]
    let _ = call("stop", &[]);
}

/// A reason as the page script gives it (`[code, detail]`), if it gave one.
#[cfg(target_arch = "wasm32")]
fn reason(v: &wasm_bindgen::JsValue) -> Option<LiveReason> {
    use wasm_bindgen::JsCast as _;
    // `null` when there is none (Array.from would throw on it).
    let pair = v.dyn_ref::<js_sys::Array>()?;
    let code = pair.get(0).as_string()?;
    let detail = pair.get(1).as_string().unwrap_or_default();
    Some(LiveReason { code, detail })
}

/// Takes what arrived since the last call.
pub fn poll() -> Polled {
    #[cfg(target_arch = "wasm32")]
    {
        use wasm_bindgen::JsCast as _;
        let Ok(o) = call("poll", &[]) else {
            return Polled::default();
        };
        let get = |k: &str| js_sys::Reflect::get(&o, &k.into()).unwrap_or_default();
        Polled {
            samples: get("samples")
                .dyn_into::<js_sys::Float64Array>()
                .map(|a| a.to_vec())
                .unwrap_or_default(),
            bytes: get("bytes")
                .dyn_into::<js_sys::Uint8Array>()
                .map(|a| a.to_vec())
                .unwrap_or_default(),
            running: get("running").as_bool().unwrap_or(false),
            error: reason(&get("error")),
            note: reason(&get("note")),
            api: get("api").as_string().unwrap_or_default(),
            dropped: get("dropped").as_f64().unwrap_or(0.0) as u64,
        }
    }
    #[cfg(not(target_arch = "wasm32"))]
    Polled::default()
}
