//! The recorded-log importers fuzzed: arbitrary bytes never panic, every bad line is
//! reported by its number, every good line is kept, in order; real-world clock trouble
//! (glitched times, a sketch's reset, jitter, duplicates, merged lines, a BOM, bytes that
//! are not UTF-8) loses no good sample, and a replay delivers every kept sample once.
#![cfg(not(target_arch = "wasm32"))]

use attlab::model::{ParamValues, RateLog};
use attlab::sensors::{ImuScales, RateUnit, TimeUnit, parse_imu_log, parse_rate_log};
use attlab::sim::{SimOptions, Simulation};
use proptest::prelude::*;

/// Every line that counts is kept, merged or rejected: no other fate.
fn accounted(log: &RateLog) -> bool {
    let c = log.counts;
    c.kept == log.t_s.len()
        && c.rejected == log.errors.len()
        && c.kept + c.merged + c.rejected == c.data_lines
}

/// The logged gyro readings (deg/s) a replay of `log` through `lab` delivers, one per step
/// that had a sample, until the log's last sample.
fn delivered_deg_s(lab: &str, log: RateLog) -> Vec<f64> {
    let lab = attlab_tests::lab(lab);
    let name = "sensors.gyro_deg_s";
    let span = log.span_s();
    let mut sim = Simulation::replay(
        lab,
        ParamValues::defaults(lab.params()),
        log,
        SimOptions::named(&[name]),
    )
    .expect("a replayable log");
    let mut out = Vec::new();
    while sim.t_s() < span - 1e-9 {
        sim.step();
        let v = sim.value(name).expect("the logged gyro series");
        if !v.is_nan() {
            out.push(v);
        }
    }
    out
}

/// One line of `columns` numbers at `t_ms` with a gyro reading `rate` (deg/s for a rate
/// log; the IMU's gx column in counts of ±250 °/s is 131.072 per deg/s, so `rate` there
/// is written as counts of `rate` deg/s).
fn sample_line(columns: usize, t_ms: i64, rate: f64) -> String {
    if columns == 2 {
        format!("{t_ms},{rate}")
    } else {
        format!("{t_ms},0,0,16384,{},0,0", rate * 131.072)
    }
}

/// What happens before or after a good sample.
#[derive(Clone, Copy, Debug)]
enum Trouble {
    None,
    /// A copy with its time corrupted (forward or back by 1000 s), before the sample.
    Glitch(bool),
    /// The same line twice.
    Duplicate,
    /// Two lines' numbers on one line, before the sample.
    Merged,
    /// A line with a byte that is not UTF-8, before the sample.
    BadByte,
}

fn trouble() -> impl Strategy<Value = Trouble> {
    prop_oneof![
        12 => Just(Trouble::None),
        1 => any::<bool>().prop_map(Trouble::Glitch),
        1 => Just(Trouble::Duplicate),
        1 => Just(Trouble::Merged),
        1 => Just(Trouble::BadByte),
    ]
}

/// A 100-Hz log of 60 samples (time in ms, jittered) with `troubles`, an optional reset
/// (the clock restarts at 0 at sample `reset`) and BOM. Returns the bytes, the good rates
/// in order, and the lines that must be rejected.
fn troubled_log(
    columns: usize,
    troubles: &[Trouble],
    jitter: &[i64],
    reset: Option<usize>,
    bom: bool,
) -> (Vec<u8>, Vec<f64>, Vec<usize>) {
    let mut bytes = if bom {
        b"\xEF\xBB\xBF".to_vec()
    } else {
        Vec::new()
    };
    let (mut rates, mut bad, mut line) = (Vec::new(), Vec::new(), 0usize);
    let mut push = |bytes: &mut Vec<u8>, text: &[u8]| {
        bytes.extend_from_slice(text);
        bytes.push(b'\n');
        line += 1;
        line
    };
    for (k, trouble) in troubles.iter().enumerate() {
        let base = reset.filter(|r| k >= *r).map_or(k, |r| k - r) as i64;
        let t = 10 * base + jitter[k];
        let rate = k as f64 + 0.5;
        let good = sample_line(columns, t, rate);
        // A glitch needs the clock to go on after it: not first, last or at the reset.
        let glitch_ok =
            k > 0 && k + 1 < troubles.len() && reset.is_none_or(|r| k != r && k != r + 1);
        match *trouble {
            Trouble::Glitch(ahead) if glitch_ok => {
                let wrong = if ahead { t + 1_000_000 } else { t - 1_000_000 };
                bad.push(push(
                    &mut bytes,
                    sample_line(columns, wrong, 99.0).as_bytes(),
                ));
            }
            Trouble::Merged => {
                let two = format!("{good},{good}");
                bad.push(push(&mut bytes, two.as_bytes()));
            }
            Trouble::BadByte => {
                bad.push(push(&mut bytes, b"12,\xFF3"));
            }
            _ => {}
        }
        push(&mut bytes, good.as_bytes());
        if let Trouble::Duplicate = trouble {
            push(&mut bytes, good.as_bytes());
        }
        rates.push(rate);
    }
    (bytes, rates, bad)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1000))]

    #[test]
    fn arbitrary_text_never_panics_and_every_line_is_accounted_for(bytes in proptest::collection::vec(any::<u8>(), 0..400)) {
        let log = parse_rate_log(&bytes, RateUnit::DegPerS, TimeUnit::Seconds);
        prop_assert!(accounted(&log), "{:?}", log.counts);
        let lines = bytes.split(|b| *b == b'\n').count();
        prop_assert!(log.t_s.len() + log.errors.len() <= lines);
        prop_assert_eq!(log.t_s.len(), log.rate_rad_s.len());
        for e in &log.errors {
            prop_assert!(e.line >= 1 && e.line <= lines, "line {} of {}", e.line, lines);
        }
        prop_assert!(log.t_s.windows(2).all(|w| w[0] < w[1]));
    }

    #[test]
    fn good_lines_survive_any_mangled_lines_between_them(
        junk in proptest::collection::vec("[a-z;,%\\- \\t]{1,12}|[0-9]{1,3}|1e999|nan|;;", 0..30),
        positions in proptest::collection::vec(0usize..60, 0..30),
        sep in prop_oneof![Just(","), Just(";"), Just("\t"), Just(" ")],
    ) {
        // 60 good samples (t = 0.01 k, rate = k/10) with junk lines inserted before some.
        let mut text = format!("time{sep}rate\n");
        let mut expected_bad = Vec::new();
        let mut line = 1;
        for k in 0..60 {
            for (j, p) in junk.iter().zip(&positions) {
                if *p == k {
                    text += j;
                    text += "\n";
                    line += 1;
                    if !j.trim().is_empty() {
                        expected_bad.push(line);
                    }
                }
            }
            text += &format!("{}{sep}{}\n", 0.01 * k as f64, k as f64 / 10.0);
            line += 1;
        }
        let log = parse_rate_log(&text, RateUnit::DegPerS, TimeUnit::Seconds);
        let expected_t: Vec<f64> = (0..60).map(|k| 0.01 * k as f64).collect();
        prop_assert_eq!(&log.t_s, &expected_t, "every good line kept, in order; errors: {:?}", log.errors);
        let reported: Vec<usize> = log.errors.iter().map(|e| e.line).collect();
        prop_assert_eq!(reported, expected_bad);
    }

    #[test]
    fn arbitrary_text_never_panics_the_imu_importer(bytes in proptest::collection::vec(any::<u8>(), 0..600)) {
        let log = parse_imu_log(&bytes, ImuScales::default());
        prop_assert!(accounted(&log), "{:?}", log.counts);
        let lines = bytes.split(|b| *b == b'\n').count();
        prop_assert!(log.t_s.len() + log.errors.len() <= lines);
        prop_assert_eq!(log.t_s.len(), log.rate_rad_s.len());
        prop_assert_eq!(log.t_s.len(), log.accel_g.len());
        for e in &log.errors {
            prop_assert!(e.line >= 1 && e.line <= lines, "line {} of {}", e.line, lines);
        }
        prop_assert!(log.t_s.windows(2).all(|w| w[0] < w[1]));
    }

    #[test]
    fn good_imu_lines_survive_any_mangled_lines_between_them(
        junk in proptest::collection::vec("[a-z;,%\\- \\t]{1,12}|[0-9]{1,3}|1e999|nan|1,2,3,4,5", 0..30),
        positions in proptest::collection::vec(0usize..40, 0..30),
        sep in prop_oneof![Just(","), Just(";"), Just("\t"), Just(" ")],
    ) {
        // A banner, a header, then 40 good samples in counts with junk lines before some.
        let mut text = format!("MPU6050 connection successful\nms{sep}ax{sep}ay{sep}az{sep}gx{sep}gy{sep}gz\n");
        let mut expected_bad = vec![1];
        let mut line = 2;
        for k in 0..40 {
            for (j, p) in junk.iter().zip(&positions) {
                if *p == k {
                    text += j;
                    text += "\n";
                    line += 1;
                    if !j.trim().is_empty() {
                        expected_bad.push(line);
                    }
                }
            }
            text += &format!("{}{sep}0{sep}{}{sep}16384{sep}{}{sep}0{sep}0\n", 10 * k, 100 * k, 131 * k);
            line += 1;
        }
        let log = parse_imu_log(&text, ImuScales::default());
        let expected_t: Vec<f64> = (0..40).map(|k| f64::from(10 * k) * 1e-3).collect();
        prop_assert_eq!(&log.t_s, &expected_t, "every good line kept, in order; errors: {:?}", log.errors);
        let reported: Vec<usize> = log.errors.iter().map(|e| e.line).collect();
        prop_assert_eq!(reported, expected_bad);
    }

    #[test]
    fn clock_trouble_loses_no_good_sample_and_a_replay_delivers_each_once(
        troubles in proptest::collection::vec(trouble(), 60),
        jitter in proptest::collection::vec(-2i64..=2, 60),
        reset in proptest::option::of(20usize..40),
        bom in any::<bool>(),
        imu in any::<bool>(),
    ) {
        let columns = if imu { 7 } else { 2 };
        let (bytes, rates, bad) = troubled_log(columns, &troubles, &jitter, reset, bom);
        let log = if imu {
            parse_imu_log(&bytes, ImuScales::default())
        } else {
            parse_rate_log(&bytes, RateUnit::DegPerS, TimeUnit::Milliseconds)
        };
        prop_assert!(accounted(&log), "{:?}", log.counts);
        let rejected: Vec<usize> = log.errors.iter().map(|e| e.line).collect();
        prop_assert_eq!(&rejected, &bad, "errors: {:?}", log.errors);
        let duplicates = troubles.iter().filter(|t| matches!(t, Trouble::Duplicate)).count();
        prop_assert_eq!(log.counts.merged, duplicates);
        prop_assert_eq!(log.counts.reordered, 0);
        prop_assert_eq!(log.gaps.len(), usize::from(reset.is_some()));
        let kept: Vec<f64> = log.rate_rad_s.iter().map(|w| w.to_degrees()).collect();
        prop_assert_eq!(kept.len(), rates.len());
        for (got, want) in kept.iter().zip(&rates) {
            prop_assert!((got - want).abs() < 1e-3, "kept {got} where {want} was logged");
        }
        let delivered = delivered_deg_s(if imu { "p4" } else { "p1" }, log);
        prop_assert_eq!(delivered.len(), rates.len(), "n samples in, n delivered");
        for (got, want) in delivered.iter().zip(&rates) {
            prop_assert!((got - want).abs() < 1e-3, "delivered {got} where {want} was logged");
        }
    }
}

#[test]
fn a_log_of_another_labs_format_is_refused_naming_it() {
    let imu = include_str!("../../../assets/p4-arduino-mpu6050.csv");
    let read = |lab: &str, bytes: &[u8]| {
        let lab = attlab_tests::lab(lab);
        let format = lab.page().log_format.expect("a lab that reads logs");
        attlab::labs::read_log(lab, bytes, &format.default_units())
    };
    let err = read("p1", imu.as_bytes()).unwrap_err().to_string();
    assert!(
        err.contains("have 7 numbers") && err.contains("MPU-6050") && err.contains("labs p3, p4"),
        "{err}"
    );
    let rate_log: String = (0..50).map(|k| format!("{},{}\n", 10 * k, k)).collect();
    let err = read("p4", rate_log.as_bytes()).unwrap_err().to_string();
    assert!(
        err.contains("one-axis gyro log") && err.contains("lab p1"),
        "{err}"
    );
    // The IMU log's accelerometer in g, read with the default unit (counts of ±2 g).
    let in_g: String = (0..50)
        .map(|k| format!("{},0,0,1.0,{},0,0\n", 10 * k, 131 * k))
        .collect();
    let err = read("p4", in_g.as_bytes()).unwrap_err().to_string();
    assert!(err.contains("the unit `g` gives 1.00 g"), "{err}");
    let lab = attlab_tests::lab("p2");
    let err = attlab::labs::read_log(lab, imu.as_bytes(), &ParamValues::defaults(&[]))
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("does not replay logs; these do: p1, p3, p4"),
        "{err}"
    );
    assert!(read("p4", imu.as_bytes()).is_ok());
}
