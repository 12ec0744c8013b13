//! The page under random input: bursts of random pointer presses, moves and releases,
//! wheel turns, touches and keys on the canvas of every lab, then a check that nothing
//! broke — no console error, no panic, no app error, and a page that still draws.
//!
//! The events come from a seeded generator in the page (mulberry32), so a seed replays the
//! same events: a failure prints it with the command that replays it. `cargo xtask test`
//! sends [`CI_EVENTS_PER_LAB`] events to each lab; `cargo xtask fuzz-page --minutes M`
//! goes on round the labs for M minutes.

use super::*;

/// Events per lab in `cargo xtask test`.
pub(crate) const CI_EVENTS_PER_LAB: u32 = 2000;
/// Events in one burst (the page draws between bursts).
const BURST: u32 = 40;
/// Frames the app draws between two bursts, as it would between a user's gestures.
const FRAMES_BETWEEN: u32 = 2;

/// The script that sends every burst of a window in one WebDriver call (each call took
/// ~0.6 s while SwiftShader kept both cores busy): `BURST_SEEDS` (a JS array of 32-bit
/// seeds, one per burst) and `COUNT` are replaced; after each burst it waits for
/// [`FRAMES_BETWEEN`] frames (at most 5 s). It resolves to one verdict per burst: `ok`, or
/// what went wrong. Keys include Tab, the arrows, Space, Enter, Escape, the app's shortcuts
/// and digits; pointers land anywhere on the canvas, half of them near the last one
/// (drags), with the wheel and touches mixed in.
const BURST_SCRIPT: &str = r#"
const burst = (seed) => {
Error.stackTraceLimit = 64;
let s = seed >>> 0;
const rnd = () => {
  s = (s + 0x6D2B79F5) >>> 0;
  let t = s;
  t = Math.imul(t ^ (t >>> 15), t | 1);
  t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
  return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
};
const c = document.querySelector('canvas');
if (!c) return 'no canvas';
const r = c.getBoundingClientRect();
let x = r.left + r.width / 2, y = r.top + r.height / 2;
const move = () => {
  if (rnd() < 0.5) { x = r.left + rnd() * r.width; y = r.top + rnd() * r.height; }
  else { x += (rnd() - 0.5) * 80; y += (rnd() - 0.5) * 80; }
};
const keys = ['Tab', 'ArrowLeft', 'ArrowRight', 'ArrowUp', 'ArrowDown', ' ', 'Enter',
  'Escape', 'Home', 'End', 'PageUp', 'PageDown', 'f', 'l', 'r', 's', 'n', 'b', 'h', '?', '1',
  '2', '3', '0', 'a', 'Backspace', 'Delete', '-', '.', 'e'];
const pointer = (type, buttons) => c.dispatchEvent(new PointerEvent(type, {
  clientX: x, clientY: y, button: 0, buttons, pointerId: 1, pointerType: 'mouse',
  bubbles: true, cancelable: true }));
const touch = (type) => {
  const t = new Touch({ identifier: 7, target: c, clientX: x, clientY: y });
  const list = type === 'touchend' ? [] : [t];
  c.dispatchEvent(new TouchEvent(type, { touches: list, targetTouches: list,
    changedTouches: [t], bubbles: true, cancelable: true }));
};
for (let i = 0; i < COUNT; i++) {
  const kind = rnd();
  if (kind < 0.30) { move(); pointer('pointerdown', 1); pointer('pointerup', 0); }
  else if (kind < 0.50) { move(); c.dispatchEvent(new MouseEvent('mousemove', {
    clientX: x, clientY: y, bubbles: true })); }
  else if (kind < 0.60) { move(); pointer('pointerdown', 1); move();
    c.dispatchEvent(new MouseEvent('mousemove', { clientX: x, clientY: y, buttons: 1,
      bubbles: true })); pointer('pointerup', 0); }
  else if (kind < 0.70) { move(); c.dispatchEvent(new WheelEvent('wheel', { clientX: x,
    clientY: y, deltaY: (rnd() - 0.5) * 600, deltaX: (rnd() - 0.5) * 100, bubbles: true,
    cancelable: true })); }
  else if (kind < 0.80) { move(); touch('touchstart'); move(); touch('touchmove');
    touch('touchend'); }
  else {
    const key = keys[Math.floor(rnd() * keys.length)];
    const shift = rnd() < 0.2;
    for (const type of ['keydown', 'keyup']) {
      c.dispatchEvent(new KeyboardEvent(type, { key, shiftKey: shift, bubbles: true,
        cancelable: true }));
    }
  }
}
return 'ok';
};
return (async () => {
  const verdicts = [];
  for (const seed of BURST_SEEDS) {
    try { verdicts.push(burst(seed)); }
    catch (e) { verdicts.push('threw ' + e + '\n' + (e && e.stack)); }
    await attlabLater(FRAMES_BETWEEN, 5000);
  }
  return verdicts;
})();
"#;

/// Sends `events` random events to the open page from `seed`, in bursts; returns the
/// problems of sending them.
fn send_events(session: &Session<'_>, seed: u64, events: u32) -> Vec<String> {
    let bursts = u64::from(events.div_ceil(BURST));
    // Each burst its own 32-bit seed, derived from the run's.
    let seeds: Vec<String> = (0..bursts)
        .map(|burst| ((seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) ^ burst) & 0xFFFF_FFFF).to_string())
        .collect();
    let script = format!("{LATER_JS}{BURST_SCRIPT}")
        .replace("BURST_SEEDS", &format!("[{}]", seeds.join(",")))
        .replace("COUNT", &BURST.to_string())
        .replace("FRAMES_BETWEEN", &FRAMES_BETWEEN.to_string());
    // The bursts and the frames between them take ~10 s; WebDriver's default script
    // timeout is 30 s.
    let _ = session.call("POST", "/timeouts", Some(&json!({ "script": 300_000 })));
    match session.execute(&script) {
        Ok(Value::Array(verdicts)) => verdicts
            .iter()
            .enumerate()
            .filter(|(_, v)| v.as_str() != Some("ok"))
            .map(|(burst, v)| format!("burst {burst}: the page said {v}"))
            .collect(),
        Ok(other) => vec![format!("the bursts returned {other}")],
        Err(e) => vec![format!("sending the bursts failed: {e}")],
    }
}

/// Whether the page still draws: its frame count grows within a few seconds of a pointer
/// move (a paused app draws only on input).
fn still_draws(session: &Session<'_>) -> Result<(), String> {
    let frames = || -> Option<f64> {
        let text = session.execute(STATUS_SCRIPT).ok()?;
        let status: Value = serde_json::from_str(text.as_str()?).ok()?;
        status["frames"].as_f64()
    };
    let before = frames().ok_or("attlabStatus is gone")?;
    let start = Instant::now();
    while start.elapsed() < Duration::from_secs(10) {
        let _ = session.execute(
            "const c = document.querySelector('canvas'); if (c) { const r = c.getBoundingClientRect(); \
             c.dispatchEvent(new MouseEvent('mousemove', { clientX: r.left + 5 + Math.random() * 10, \
             clientY: r.top + 5, bubbles: true })); }",
        );
        sleep(Duration::from_millis(250));
        if frames().is_some_and(|f| f > before) {
            return Ok(());
        }
    }
    Err(format!(
        "no frame drawn in 10 s after the events (frames stayed {before})"
    ))
}

/// The windows each lab is fuzzed at: the desktop's (no size: the browser's window, a
/// mouse), a phone's (its stacked layout, the bar and the sheet) and a tablet's, the two
/// last with touch, where real touch gestures go through the browser's own input (see
/// [`super::touch`]) after the synthetic events.
const WINDOWS: [(Option<(u32, u32)>, bool); 3] = [
    (None, false),
    (Some((390, 844)), true),
    (Some((1024, 768)), true),
];

/// One lab fuzzed from `seed`, half its events at each of [`WINDOWS`]: its problems, each
/// with the command that replays it.
pub(crate) fn fuzz_lab(
    session: &Session<'_>,
    base: &str,
    lab: &str,
    seed: u64,
    events: u32,
) -> Vec<String> {
    let mut problems = Vec::new();
    for (k, (window, touch)) in WINDOWS.iter().enumerate() {
        let size = window.map_or("the default window".to_string(), |(w, h)| {
            format!("{w}×{h}{}", if *touch { " (touch)" } else { "" })
        });
        let tag = format!(
            "fuzz {lab} at {size}, seed {seed} (replay: ATTLAB_FUZZ_SEED={seed} ATTLAB_FUZZ_LABS={lab} cargo xtask fuzz-page --minutes 0.1)"
        );
        if let Err(e) = session.set_viewport(*window, *touch) {
            problems.push(format!("{tag}: cannot emulate the window: {e}"));
            continue;
        }
        let window_seed = seed.wrapping_add((k as u64) << 32);
        let per_window = events / WINDOWS.len() as u32;
        let gestures = window.filter(|_| *touch);
        let found = fuzz_window(session, base, lab, (window_seed, per_window), gestures);
        problems.extend(found.into_iter().map(|p| format!("{tag}: {p}")));
    }
    if let Err(e) = session.set_viewport(None, false) {
        problems.push(format!("fuzz {lab}: cannot end the emulation: {e}"));
    }
    problems
}

/// `events` random events on `lab` in the window as emulated, from `seed`; then, in a
/// touch window of `gestures` size, real touch gestures, after which the page must still be
/// on its own address (a swipe had taken the browser Back, out of the app).
fn fuzz_window(
    session: &Session<'_>,
    base: &str,
    lab: &str,
    (seed, events): (u64, u32),
    gestures: Option<(u32, u32)>,
) -> Vec<String> {
    let start = Instant::now();
    if let Err(e) = session.open(&format!("{base}#lab={lab}")) {
        return vec![format!("navigate failed: {e}")];
    }
    let status = wait_for_frames(session);
    let mut problems = status_problems(&status);
    let _ = session.console();
    problems.extend(send_events(session, seed, events));
    if let Some(size) = gestures {
        problems.extend(super::touch::gestures(session, seed, size));
        problems.extend(super::touch::still_home(session, base));
    }
    if let Err(e) = still_draws(session) {
        problems.push(e);
    }
    match session.execute(STATUS_SCRIPT) {
        Ok(Value::String(text)) => {
            let status: Value = serde_json::from_str(&text).unwrap_or(Value::Null);
            let errors = status["errors"].as_array().map_or(0, Vec::len);
            if errors > 0 {
                problems.push(format!("attlabStatus.errors: {}", status["errors"]));
            }
            println!(
                "page test: fuzz {lab}, seed {seed}: {events} events, then lab {} at frame {} ({:.1} s)",
                status["lab"],
                status["frames"],
                start.elapsed().as_secs_f64()
            );
        }
        other => problems.push(format!(
            "attlabStatus unreadable after the events: {other:?}"
        )),
    }
    match session.console() {
        Ok(entries) => problems.extend(console_problems(&entries)),
        Err(e) => problems.push(format!("reading the console failed: {e}")),
    }
    problems
}

/// The fuzz's settings from the environment: the seed (`ATTLAB_FUZZ_SEED`, else from the
/// clock), the labs (`ATTLAB_FUZZ_LABS`, comma-separated ids, else all) and the minutes
/// (`ATTLAB_FUZZ_MINUTES`; unset: one round of [`CI_EVENTS_PER_LAB`] per lab).
pub(crate) fn run() {
    let url = std::env::var("ATTLAB_PAGE_URL").expect("set ATTLAB_PAGE_URL to the served dist/");
    let base = url.split('#').next().unwrap_or(&url).to_string();
    let seed = std::env::var("ATTLAB_FUZZ_SEED")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or_else(|| {
            std::time::SystemTime::now()
                .duration_since(std::time::UNIX_EPOCH)
                .map_or(1, |d| d.as_secs())
        });
    let labs: Vec<String> = match std::env::var("ATTLAB_FUZZ_LABS") {
        Ok(list) if !list.trim().is_empty() => {
            list.split(',').map(|s| s.trim().to_string()).collect()
        }
        _ => attlab::labs::all()
            .iter()
            .map(|l| l.id().to_string())
            .collect(),
    };
    let minutes: Option<f64> = std::env::var("ATTLAB_FUZZ_MINUTES")
        .ok()
        .and_then(|m| m.parse().ok());
    let driver = Driver::start();
    let session = Session::new(&driver);
    let start = Instant::now();
    let mut problems = Vec::new();
    let mut round = 0u64;
    loop {
        for (k, lab) in labs.iter().enumerate() {
            let lab_seed = seed.wrapping_add(round * labs.len() as u64 + k as u64);
            problems.extend(fuzz_lab(&session, &base, lab, lab_seed, CI_EVENTS_PER_LAB));
        }
        round += 1;
        let more = minutes.is_some_and(|m| start.elapsed().as_secs_f64() < m * 60.0);
        if !more || !problems.is_empty() {
            break;
        }
    }
    println!(
        "page test: fuzz sent {} events in {:.0} s ({round} rounds over {} labs), base seed {seed}",
        u64::from(CI_EVENTS_PER_LAB) * round * labs.len() as u64,
        start.elapsed().as_secs_f64(),
        labs.len()
    );
    assert!(
        problems.is_empty(),
        "page fuzz failed:\n  - {}",
        problems.join("\n  - ")
    );
}
