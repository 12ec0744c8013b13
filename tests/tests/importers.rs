//! The recorded-log importers fuzzed: arbitrary bytes never panic, every bad line is
//! reported by its number, every good line is kept, in order.
#![cfg(not(target_arch = "wasm32"))]

use attlab::sensors::{RateUnit, TimeUnit, parse_rate_log};
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
}
