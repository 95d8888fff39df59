//! Tests of the duration literal grammar, the display and the arithmetic of [`Time`].

use super::{Time, TimeError};
use proptest::prelude::*;
use std::string::ToString;

fn ms(n: i64) -> Result<Time, TimeError> {
    Ok(Time::from_millis(n))
}

#[test]
fn every_prefix_in_any_case() {
    for prefix in [
        "T#", "t#", "TIME#", "time#", "LT#", "lt#", "LTIME#", "LTime#",
    ] {
        assert_eq!(Time::parse(&std::format!("{prefix}1s500ms")), ms(1500));
    }
    for bad in ["1s", "#1s", "D#1s", "TOD#1s", "LTIMES#1s", "T1s", " T#1s"] {
        assert_eq!(Time::parse(bad), Err(TimeError::NoPrefix), "{bad}");
    }
}

#[test]
fn parts_signs_and_separators() {
    assert_eq!(Time::parse("LTIME#-2h_30m"), Ok(Time::from_secs(-9000)));
    assert_eq!(Time::parse("T#+1d"), Ok(Time::from_secs(86_400)));
    assert_eq!(Time::parse("T#1_000ms"), ms(1000));
    assert_eq!(
        Time::parse("LT#1d2h3m4s5ms6us7ns"),
        Ok(Time::from_nanos(
            ((((86_400 + 2 * 3600 + 3 * 60 + 4) * 1000 + 5) * 1000 + 6) * 1000) + 7
        ))
    );
    assert_eq!(Time::parse("T#1H_2M_3S"), Ok(Time::from_secs(3723)));
    assert_eq!(
        Time::parse("T#1MS"),
        ms(1),
        "ms is one unit, not minutes and s"
    );
    assert_eq!(Time::parse("T#-0s"), Ok(Time::ZERO));
}

#[test]
fn only_the_first_part_may_exceed_its_unit() {
    assert_eq!(Time::parse("T#90m"), Ok(Time::from_secs(5400)));
    assert_eq!(
        Time::parse("T#25h_15m"),
        Ok(Time::from_secs(25 * 3600 + 900))
    );
    assert_eq!(
        Time::parse("T#1h75m"),
        Err(TimeError::PartTooLarge {
            value: 75,
            unit: "m",
            limit: 60
        })
    );
    assert!(matches!(
        Time::parse("T#1s1000ms"),
        Err(TimeError::PartTooLarge { .. })
    ));
    assert_eq!(Time::parse("T#1s999ms"), ms(1999));
}

#[test]
fn units_in_order_each_once() {
    assert_eq!(
        Time::parse("T#1s1m"),
        Err(TimeError::UnitOrder {
            unit: "m",
            after: "s"
        })
    );
    assert_eq!(
        Time::parse("T#1s2s"),
        Err(TimeError::UnitOrder {
            unit: "s",
            after: "s"
        })
    );
}

#[test]
fn a_fraction_on_the_last_part_only() {
    assert_eq!(Time::parse("T#1.5s"), ms(1500));
    assert_eq!(Time::parse("T#0.25h"), Ok(Time::from_secs(900)));
    assert_eq!(Time::parse("T#1m0.5s"), ms(60_500));
    assert_eq!(Time::parse("T#1.000_000_000_0s"), ms(1000));
    assert_eq!(Time::parse("T#1.5us"), Ok(Time::from_nanos(1500)));
    assert_eq!(Time::parse("T#1.5m30s"), Err(TimeError::FractionNotLast));
    assert_eq!(Time::parse("T#1.5ns"), Err(TimeError::FinerThanNanosecond));
    assert_eq!(
        Time::parse("T#0.0000000001s"),
        Err(TimeError::FinerThanNanosecond)
    );
    // 5e-11 min is 3 ns exactly: not rounded, not refused.
    assert_eq!(Time::parse("T#0.00000000005m"), Ok(Time::from_nanos(3)));
    assert_eq!(Time::parse("T#1.s"), Err(TimeError::Unexpected { at: 4 }));
}

#[test]
fn malformed_texts_are_errors() {
    assert_eq!(Time::parse("T#"), Err(TimeError::Empty));
    assert_eq!(Time::parse("T#-"), Err(TimeError::Empty));
    assert_eq!(Time::parse("T#5"), Err(TimeError::MissingUnit { at: 3 }));
    assert_eq!(Time::parse("T#5x"), Err(TimeError::Unexpected { at: 3 }));
    assert_eq!(Time::parse("T#_5s"), Err(TimeError::Unexpected { at: 2 }));
    assert_eq!(Time::parse("T#5_s"), Err(TimeError::Unexpected { at: 3 }));
    assert_eq!(Time::parse("T#5s_"), Err(TimeError::Unexpected { at: 5 }));
    assert_eq!(
        Time::parse("T#5s__3ms"),
        Err(TimeError::Unexpected { at: 5 })
    );
    assert_eq!(Time::parse("T#--5s"), Err(TimeError::Unexpected { at: 3 }));
    assert_eq!(Time::parse("T#5s "), Err(TimeError::Unexpected { at: 4 }));
}

#[test]
fn the_range_of_ltime_exactly() {
    let max = "LTIME#106751d23h47m16s854ms775us807ns";
    let min = "LTIME#-106751d23h47m16s854ms775us808ns";
    assert_eq!(Time::parse(max), Ok(Time::MAX));
    assert_eq!(Time::parse(min), Ok(Time::MIN));
    assert_eq!(
        (Time::MAX.to_string(), Time::MIN.to_string()),
        (max.into(), min.into())
    );
    assert_eq!(
        Time::parse("LTIME#106751d23h47m16s854ms775us808ns"),
        Err(TimeError::Overflow)
    );
    assert_eq!(Time::parse("T#106752d"), Err(TimeError::Overflow));
    assert_eq!(Time::parse("T#9223372036854775807ns"), Ok(Time::MAX));
    assert_eq!(Time::parse("T#-9223372036854775808ns"), Ok(Time::MIN));
    let huge = std::format!("T#{}s", "9".repeat(100));
    assert_eq!(Time::parse(&huge), Err(TimeError::Overflow));
}

#[test]
fn display_is_a_literal_of_every_non_zero_part() {
    assert_eq!(Time::ZERO.to_string(), "LTIME#0s");
    assert_eq!(Time::from_millis(-500).to_string(), "LTIME#-500ms");
    assert_eq!(Time::from_secs(86_400 + 7200).to_string(), "LTIME#1d2h");
    assert_eq!(Time::from_nanos(1_001).to_string(), "LTIME#1us1ns");
    assert_eq!(std::format!("{:?}", Time::from_secs(90)), "LTIME#1m30s");
}

#[test]
fn conversions_truncate_toward_zero_and_construction_saturates() {
    let t = Time::from_nanos(-1_999_999_999);
    assert_eq!(
        (t.as_secs(), t.as_millis(), t.as_micros()),
        (-1, -1999, -1_999_999)
    );
    assert_eq!(Time::from_millis(i64::MAX), Time::MAX);
    assert_eq!(Time::from_secs(i64::MIN), Time::MIN);
    assert_eq!(Time::MIN.checked_neg(), None);
    assert_eq!(Time::MIN.checked_sub(Time::from_nanos(1)), None);
    assert_eq!(Time::from_secs(2).checked_mul(3), Some(Time::from_secs(6)));
    assert_eq!(Time::MIN.saturating_sub(Time::MAX), Time::MIN);
    assert_eq!(
        Time::try_from(core::time::Duration::from_millis(1500)),
        Ok(Time::from_millis(1500))
    );
    assert_eq!(
        Time::try_from(core::time::Duration::from_secs(u64::MAX)),
        Err(TimeError::Overflow)
    );
}

#[test]
fn errors_say_what_to_write() {
    let order = TimeError::UnitOrder {
        unit: "m",
        after: "s",
    };
    assert!(order.to_string().contains("from days to nanoseconds"));
    let overflow = TimeError::Overflow.to_string();
    assert!(overflow.contains("LTIME#106751d"), "{overflow}");
}

proptest! {
    #[test]
    fn arbitrary_text_never_panics(text in "\\PC{0,40}") {
        let _ = Time::parse(&text);
    }

    #[test]
    fn literal_like_text_never_panics(
        text in "(T|LT|TIME|LTIME)#[+-]?([0-9_.]{0,25}(d|h|m|s|ms|us|ns|x)?_?){0,8}"
    ) {
        let _ = Time::parse(&text);
    }

    #[test]
    fn display_parses_back_to_the_same_value(ns in any::<i64>()) {
        let t = Time::from_nanos(ns);
        prop_assert_eq!(Time::parse(&t.to_string()), Ok(t));
    }

    #[test]
    fn a_fraction_of_seconds_is_its_milliseconds(s in 0i64..100_000, frac in 0i64..1000) {
        let text = std::format!("T#{s}.{frac:03}s");
        prop_assert_eq!(Time::parse(&text), Ok(Time::from_millis(s * 1000 + frac)));
    }
}
