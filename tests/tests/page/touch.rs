//! Real touch on a phone's and a tablet's screen: swipes from the edges and across, taps, a
//! long press and two-finger pinches, sent as W3C touch actions, which chromedriver passes
//! through the browser's own input (its gesture recogniser decides what a swipe does, as on
//! a device). The page fuzz's own events are synthetic DOM events, which never reach it:
//! with the browser's default touch handling a sideways swipe went Back, out of the app, and
//! every touchstart came non-cancelable (a console error each), while the synthetic fuzz
//! saw nothing.

use super::*;

/// Gestures per touch window.
const GESTURES: u32 = 24;

/// A small seeded generator (SplitMix64), so a fuzz seed replays the same gestures.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// One tick of a finger: where it is (viewport CSS pixels) and what it does.
fn at(x: f64, y: f64, ms: u64) -> Value {
    json!({ "type": "pointerMove", "x": x.round() as i64, "y": y.round() as i64,
            "duration": ms, "origin": "viewport" })
}

/// The two fingers' ticks for one gesture (the second pauses while the first works alone,
/// so their ticks stay aligned).
fn gesture(rng: &mut Rng, (w, h): (f64, f64)) -> (Vec<Value>, Vec<Value>) {
    let down = json!({ "type": "pointerDown", "button": 0 });
    let up = json!({ "type": "pointerUp", "button": 0 });
    let pause = |ms: u64| json!({ "type": "pause", "duration": ms });
    let inside = |v: f64, size: f64| v.clamp(1.0, size - 2.0);
    let (x0, y0) = (rng.next() * w, rng.next() * h);
    let kind = rng.next();
    let one: Vec<Value> = if kind < 0.35 {
        // From an edge across the screen: what a browser takes for Back or Forward.
        let from_left = rng.next() < 0.5;
        let (xa, xb) = if from_left {
            (2.0, 0.85 * w)
        } else {
            (w - 3.0, 0.15 * w)
        };
        let mut ticks = vec![at(xa, y0, 0), down.clone()];
        ticks.extend((1..=5).map(|k| at(xa + (xb - xa) * f64::from(k) / 5.0, y0, 25)));
        ticks.push(up.clone());
        ticks
    } else if kind < 0.55 {
        // A swipe in any direction, on a view, the plot or the bar.
        let (x1, y1) = (
            inside(x0 + (rng.next() - 0.5) * w, w),
            inside(y0 + (rng.next() - 0.5) * h, h),
        );
        let mut ticks = vec![at(x0, y0, 0), down.clone()];
        ticks.extend((1..=4).map(|k| {
            let f = f64::from(k) / 4.0;
            at(x0 + (x1 - x0) * f, y0 + (y1 - y0) * f, 30)
        }));
        ticks.push(up.clone());
        ticks
    } else if kind < 0.8 {
        vec![at(x0, y0, 0), down.clone(), pause(50), up.clone()]
    } else if kind < 0.85 {
        // A long press, as a slow finger on a button.
        vec![at(x0, y0, 0), down.clone(), pause(1500), up.clone()]
    } else {
        // Two fingers apart or together about a point.
        let (cx, cy) = (inside(x0, w), inside(y0, h));
        let (d0, d1) = if rng.next() < 0.5 {
            (20.0, 90.0)
        } else {
            (90.0, 20.0)
        };
        let finger = |sign: f64| {
            let mut ticks = vec![at(inside(cx + sign * d0, w), cy, 0), down.clone()];
            ticks.extend((1..=4).map(|k| {
                let d = d0 + (d1 - d0) * f64::from(k) / 4.0;
                at(inside(cx + sign * d, w), cy, 30)
            }));
            ticks.push(up.clone());
            ticks
        };
        return (finger(-1.0), finger(1.0));
    };
    let idle = one.iter().map(|_| pause(0)).collect();
    (one, idle)
}

/// [`GESTURES`] random gestures from `seed` in a window of `size` CSS pixels, in one
/// WebDriver call; the problems of sending them.
pub(crate) fn gestures(session: &Session<'_>, seed: u64, (w, h): (u32, u32)) -> Vec<String> {
    let mut rng = Rng(seed ^ 0x7_0C4E);
    let (mut first, mut second) = (Vec::new(), Vec::new());
    for _ in 0..GESTURES {
        let (a, b) = gesture(&mut rng, (f64::from(w), f64::from(h)));
        first.extend(a);
        second.extend(b);
        first.push(json!({ "type": "pause", "duration": 120 }));
        second.push(json!({ "type": "pause", "duration": 120 }));
    }
    let finger = |id: &str, actions: Vec<Value>| {
        json!({ "type": "pointer", "id": id, "parameters": { "pointerType": "touch" },
                "actions": actions })
    };
    let body = json!({ "actions": [finger("finger1", first), finger("finger2", second)] });
    let mut problems = Vec::new();
    if let Err(e) = session.call("POST", "/actions", Some(&body)) {
        problems.push(format!("the touch gestures failed: {e}"));
    }
    let _ = session.call("DELETE", "/actions", None);
    problems
}

/// That the page is still the app at `base` (its fragment may have changed: a tap can pick
/// another lab), not the page before it in the history.
pub(crate) fn still_home(session: &Session<'_>, base: &str) -> Vec<String> {
    match session.execute("return [location.origin + location.pathname, location.href];") {
        Ok(Value::Array(at)) if at[0].as_str().is_some_and(|here| base.starts_with(here)) => {
            Vec::new()
        }
        Ok(Value::Array(at)) => vec![format!(
            "the touches took the browser away from the app at {base}: it is at {}",
            at[1]
        )],
        other => vec![format!(
            "cannot read the page's address after the touches: {other:?}"
        )],
    }
}
