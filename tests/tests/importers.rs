//! The recorded-log importers fuzzed: arbitrary bytes never panic, every bad line is
//! reported by its number, every good line is kept, in order.
#![cfg(not(target_arch = "wasm32"))]

use attlab::sensors::{ImuScales, RateUnit, TimeUnit, parse_imu_log, parse_rate_log};
use proptest::prelude::*;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    #[test]
    fn arbitrary_text_never_panics_and_every_line_is_accounted_for(bytes in proptest::collection::vec(any::<u8>(), 0..400)) {
        let text = String::from_utf8_lossy(&bytes);
        let log = parse_rate_log(&text, RateUnit::DegPerS, TimeUnit::Seconds);
        let lines = text.lines().count();
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
        let text = String::from_utf8_lossy(&bytes);
        let log = parse_imu_log(&text, ImuScales::default());
        let lines = text.lines().count();
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
}
