use super::*;
use crate::sensors::{AccelUnit, GyroUnit, parse_imu_log};

/// An Arduino's serial output at 100 Hz with what the real world does to it: a banner, a
/// header, a line cut in two, a duplicate, two lines swapped, a corrupted time, a
/// 15-period stall and a restart of the sketch.
fn glitchy_serial() -> (String, Vec<usize>) {
    let mut lines = vec![
        "Initializing I2C devices...".to_string(),
        "MPU6050 connection successful".to_string(),
        "ms,ax,ay,az,gx,gy,gz".to_string(),
    ];
    let sample = |t: i64, k: i64| format!("{t},{},{},16384,{},0,0", k % 7, 100 - k, 131 + k);
    for k in 0..60 {
        lines.push(sample(1000 + 10 * k, k));
    }
    lines.push("1600,1,2,3".into()); // cut short
    lines.push(sample(1600, 60));
    lines.push(sample(1600, 60)); // a duplicate
    lines.push(sample(1620, 62)); // swapped with the next
    lines.push(sample(1610, 61));
    lines.push(sample(429_496, 63)); // a corrupted time
    for k in 63..80 {
        lines.push(sample(1600 + 10 * k - 600, k));
    }
    // A stall of 15 periods, then on.
    for k in 80..100 {
        lines.push(sample(1950 + 10 * k - 800, k));
    }
    lines.push("garbage \u{1F600}".into());
    // The sketch restarts: millis() from 0.
    for k in 0..40 {
        lines.push(sample(10 * k, 100 + k));
    }
    let bad = vec![1, 2, 64, 69, 107];
    (lines.join("\n") + "\n", bad)
}

fn feed_in_chunks(text: &str, chunk: usize) -> (LiveStream, RateLog) {
    let mut live = LiveStream::new(ImuScales::default());
    let mut got = RateLog::default();
    for c in text.as_bytes().chunks(chunk) {
        live.push_bytes(c);
        append(&mut got, live.take_new());
    }
    live.finish();
    append(&mut got, live.take_new());
    (live, got)
}

fn append(all: &mut RateLog, new: RateLog) {
    all.t_s.extend(new.t_s);
    all.rate_rad_s.extend(new.rate_rad_s);
    all.accel_g.extend(new.accel_g);
    all.gyro_body_rad_s.extend(new.gyro_body_rad_s);
    all.errors = new.errors;
    all.counts = new.counts;
    all.gaps = new.gaps;
    all.period_s = new.period_s;
}

#[test]
fn a_glitchy_stream_reports_bad_lines_by_number_and_records_every_good_one() {
    let (text, bad) = glitchy_serial();
    let (live, got) = feed_in_chunks(&text, 37);
    let lines: Vec<usize> = got.errors.iter().map(|e| e.line).collect();
    assert_eq!(lines, bad, "{:#?}", got.errors);
    assert!(
        got.errors[2]
            .reason
            .to_string()
            .contains("expected 7 columns")
    );
    assert!(got.errors[3].reason.to_string().starts_with("time glitch"));
    // The record is the good lines as they came: every line of numbers of the right width.
    let record = live.record("test");
    let body: Vec<&str> = record.lines().skip(3).collect();
    let good: Vec<&str> = text
        .lines()
        .enumerate()
        .filter(|(i, l)| !bad.contains(&(i + 1)) || l.starts_with("429496"))
        .map(|(_, l)| l)
        .skip(1) // the header, written by the record itself
        .collect();
    assert_eq!(body, good);
    let p: f64 = record.lines().nth(1).unwrap()[PERIOD_DIRECTIVE.len()..]
        .parse()
        .unwrap();
    assert!((p - 0.01).abs() < 1e-15, "{p}");
    // 142 good lines: one merged, one the glitch; a stall and a reset joined.
    assert_eq!(
        (got.counts.kept, got.counts.merged, got.counts.reordered),
        (140, 1, 1)
    );
    assert_eq!(got.gaps.len(), 2, "{:?}", got.gaps);
}

#[test]
fn the_record_replays_to_the_very_samples_the_stream_handed_on() {
    let (text, _) = glitchy_serial();
    for chunk in [1, 5, 64, text.len()] {
        let (live, got) = feed_in_chunks(&text, chunk);
        let replayed = parse_imu_log(live.record("test"), ImuScales::default());
        assert_eq!(replayed.t_s, got.t_s, "chunks of {chunk}");
        assert_eq!(replayed.rate_rad_s, got.rate_rad_s);
        assert_eq!(replayed.accel_g, got.accel_g);
        // The same joins; the record numbers its lines its own way.
        let joins = |l: &RateLog| -> Vec<(f64, f64)> {
            l.gaps.iter().map(|g| (g.from_s, g.to_s)).collect()
        };
        assert_eq!(joins(&replayed), joins(&got));
        assert_eq!(replayed.period_s, got.period_s);
        assert_eq!(replayed.counts.kept, got.counts.kept);
    }
}

#[test]
fn a_sample_is_handed_on_only_once_nothing_later_can_move_it() {
    let mut live = LiveStream::new(ImuScales::default());
    let line = |t: f64| format!("{t},0,0,16384,0,0,0");
    for k in 0..PERIOD_ROWS {
        live.push_line(&line(10.0 * k as f64));
    }
    // Period 10 ms; the latest is 150 ms: up to 110 ms is final; a line 3 P back (120 ms)
    // could still merge into the sample there.
    let first = live.take_new();
    assert_eq!(first.t_s.len(), 12, "{:?}", first.t_s);
    // A late line 25 ms back is put in its place, before the held ones.
    live.push_line(&line(125.0));
    live.push_line(&line(160.0));
    let next = live.take_new();
    assert_eq!(next.t_s, vec![0.12, 0.125]);
    assert_eq!(next.counts.reordered, 1);
    // Nothing arrives: nothing is handed on; the end hands on the rest.
    assert!(live.take_new().t_s.is_empty());
    live.finish();
    assert_eq!(live.take_new().t_s, vec![0.13, 0.14, 0.15, 0.16]);
}

#[test]
fn a_stall_keeps_every_sample_and_a_jumped_time_waits_for_three_lines() {
    let mut live = LiveStream::new(ImuScales::default());
    let line = |t: f64| format!("{t},0,0,16384,0,0,0");
    for k in 0..20 {
        live.push_line(&line(10.0 * k as f64));
    }
    live.take_new();
    // 15 periods without a sample (a phone's tab in the background), then on.
    live.push_line(&line(340.0));
    assert!(
        live.take_new().t_s.iter().all(|t| *t < 0.2),
        "judged too early"
    );
    for k in 1..=4 {
        live.push_line(&line(340.0 + 10.0 * k as f64));
    }
    live.finish();
    let rest = live.take_new();
    assert!(rest.errors.is_empty(), "{:?}", rest.errors);
    assert_eq!(rest.gaps.len(), 1);
    assert_eq!(rest.counts.kept, 25);
}

#[test]
fn a_line_without_a_break_is_cut_and_reported_not_kept_growing() {
    let mut live = LiveStream::new(ImuScales::default());
    live.push_bytes(&vec![b'x'; 3 * MAX_LINE_BYTES]);
    assert_eq!(live.counts().data_lines, 3);
    assert_eq!(live.errors().len(), 3);
}

#[test]
fn a_phone_flat_reads_one_g_down_body_z_and_a_roll_turns_body_x() {
    let none = UnitQuaternion::identity();
    // Flat, screen up: the phone reads +9.81 m/s² on its z.
    let flat = phone_line(
        5.0,
        Vector3::new(0.0, 0.0, G_MPS2),
        Vector3::zeros(),
        1.0,
        &none,
    );
    assert_eq!(flat, "5,0,0,1,0,0,0");
    // Turning about the long axis (the phone's y) at 1 rad/s is a roll about body x.
    let roll = phone_line(
        5.0,
        Vector3::zeros(),
        Vector3::new(0.0, 1.0, 0.0),
        180.0 / std::f64::consts::PI,
        &none,
    );
    let gx: f64 = roll.split(',').nth(4).unwrap().parse().unwrap();
    assert!((gx - 57.29577951308232).abs() < 1e-12, "{roll}");
    // "Zero" while held tilted 30° makes that pose level.
    let tilted = Vector3::new(0.0, 0.5, 3f64.sqrt() / 2.0);
    let mount = zero_mount(tilted);
    assert!((mount * tilted - Vector3::z()).norm() < 1e-12);
    // A phone's own line reads back through the importer (ms, g, °/s).
    let mut live = LiveStream::new(PHONE_SCALES);
    live.push_line(&flat);
    live.finish();
    let log = live.take_new();
    assert_eq!(log.accel_g, vec![Vector3::new(0.0, 0.0, 1.0)]);
    assert_eq!(
        PHONE_SCALES.accel,
        AccelUnit::G,
        "the record names the units"
    );
    assert_eq!(PHONE_SCALES.gyro, GyroUnit::DegPerS);
}
