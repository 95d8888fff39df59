use super::*;
use crate::bus::{BusConfig, devices};

fn bus_with(dcs: &[Option<(&str, &str)>]) -> String {
    let mut text = String::new();
    for (i, dc) in dcs.iter().enumerate() {
        text.push_str(&format!(
            "[[devices]]\nname = \"d{i}\"\nidentity = {{ vendor = 2, product = 1 }}\n"
        ));
        if let Some((sync0, shift)) = dc {
            text.push_str(&format!(
                "dc = {{ sync0 = \"{sync0}\", shift = \"{shift}\" }}\n"
            ));
        }
    }
    text
}

fn problems_of(text: &str) -> Vec<String> {
    match BusConfig::from_toml_str(text) {
        Ok(_) => Vec::new(),
        Err(e) => e.problems,
    }
}

#[test]
fn dc_reads_plain_and_iec_durations_in_toml_and_json() {
    let bus = BusConfig::from_toml_str(&bus_with(&[None, Some(("1ms", "T#250us"))])).unwrap();
    let want = DcConfig {
        sync0: Time::from_millis(1),
        shift: Time::from_micros(250),
    };
    assert_eq!((bus.devices[0].dc, bus.devices[1].dc), (None, Some(want)));
    let json = BusConfig::from_json_str(
        r#"{"devices":[{"name":"a","identity":{"vendor":2,"product":1},
            "dc":{"sync0":"LTIME#1ms","shift":"250us"}}]}"#,
    )
    .unwrap();
    assert_eq!(json.dc(), Some(want));
}

#[test]
fn shift_defaults_to_zero_and_unknown_fields_are_refused() {
    let text = "[[devices]]\nname = \"a\"\nidentity = { vendor = 2, product = 1 }\n\
                dc = { sync0 = \"2ms\" }\n";
    let bus = BusConfig::from_toml_str(text).unwrap();
    assert_eq!(bus.dc().map(|d| d.shift), Some(Time::ZERO));
    let err = BusConfig::from_toml_str(&text.replace("sync0", "sync1")).unwrap_err();
    assert!(err.to_string().contains("unknown field `sync1`"), "{err}");
}

#[test]
fn a_duration_that_is_not_one_is_refused_with_an_example() {
    let err = BusConfig::from_toml_str(&bus_with(&[Some(("1 banana", "0s"))])).unwrap_err();
    let text = err.to_string();
    assert!(text.contains("`1 banana` is not a duration"), "{text}");
    assert!(text.contains("\"250us\""), "{text}");
}

#[test]
fn every_dc_problem_is_listed_at_once_naming_the_device() {
    let problems = problems_of(&bus_with(&[
        Some(("0s", "0s")),
        Some(("5s", "-1ms")),
        Some(("1ms", "1ms")),
        Some(("1ms", "2ms")),
    ]));
    let all = problems.join("\n");
    for needle in [
        "device 0 (`d0`), `dc`: sync0 = \"0s\" is not a period",
        "device 1 (`d1`), `dc`: sync0 = \"5s\" is longer than the 4.29 s",
        "device 1 (`d1`), `dc`: shift = \"-1ms\" is negative",
        "device 2 (`d2`), `dc`: shift = \"1ms\" is not less than sync0 = \"1ms\"",
        "device 3 (`d3`), `dc`: shift = \"2ms\" is not less than sync0",
    ] {
        assert!(all.contains(needle), "missing {needle:?} in\n{all}");
    }
}

#[test]
fn devices_with_different_sync0_or_shift_on_one_bus_are_refused() {
    let problems = problems_of(&bus_with(&[
        Some(("1ms", "250us")),
        None,
        Some(("2ms", "250us")),
        Some(("1ms", "100us")),
        Some(("1ms", "250us")),
    ]));
    assert_eq!(problems.len(), 2, "{problems:?}");
    assert!(
        problems[0].starts_with(
            "device 2 (`d2`), `dc`: sync0 = \"2ms\", shift = \"250us\" differ from device 0 (`d0`)"
        ),
        "{}",
        problems[0]
    );
    assert!(problems[0].contains("one SYNC0 period and shift per bus"));
    assert!(
        problems[1].starts_with("device 3 (`d3`)"),
        "{}",
        problems[1]
    );
}

#[test]
fn the_longest_sync0_is_u32_nanoseconds() {
    let ok = format!("{}ns", u32::MAX);
    assert!(problems_of(&bus_with(&[Some((&ok, "0s"))])).is_empty());
    let over = format!("{}ns", u64::from(u32::MAX) + 1);
    assert_eq!(problems_of(&bus_with(&[Some((&over, "0s"))])).len(), 1);
}

#[test]
fn dc_round_trips_through_toml_and_json() {
    let mut out = devices::el2004("outputs");
    out.dc = Some(DcConfig {
        sync0: Time::from_micros(2500),
        shift: Time::from_micros(500),
    });
    let bus = BusConfig {
        devices: vec![devices::ek1100("coupler"), out],
    };
    let text = bus.to_toml_string();
    assert!(text.contains("sync0 = \"2ms500us\""), "{text}");
    assert_eq!(BusConfig::from_toml_str(&text).unwrap(), bus, "{text}");
    let json = serde_json::to_string(&bus).unwrap();
    assert_eq!(BusConfig::from_json_str(&json).unwrap(), bus, "{json}");
}
