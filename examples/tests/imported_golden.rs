//! The importer's golden output (`plc-io/tests/golden/press.rs`, pinned by plc-io's import
//! test) compiled as a user's crate compiles it: it passes the derive's checks,
//! `#![deny(missing_docs)]` and clippy, and declares what `press.json` says.
#![deny(missing_docs)]
// No crate-wide allow of non-snake-case names: the emitted struct allows its own `Speed`, and
// the derive's image struct allows the names it repeats, so a warning here would be a bug.
#![deny(non_snake_case)]

include!("../../plc-io/tests/golden/press.rs");

use plc_core::{Access, Direction, IecType};

#[test]
fn the_golden_struct_declares_what_the_json_says() {
    let v = Press::VARIABLES;
    let names: Vec<&str> = v.iter().map(|x| x.name).collect();
    assert_eq!(
        names,
        [
            "Speed",
            "match",
            "label",
            "grid",
            "io_in",
            "door_closed",
            "analog_in",
            "lamp",
            "counter_total",
            "dwell"
        ]
    );
    assert_eq!(v[0].description, "Line speed in mm/s");
    assert_eq!(v[1].iec_type, IecType::Word);
    assert_eq!(v[1].access, Access::ReadOnly);
    assert_eq!(
        v[2].description, "",
        "the generated doc is not a description"
    );
    assert_eq!(v[3].dims, [2, 3]);
    assert_eq!(
        v[5].direction,
        Direction::Input,
        "a mapped bool takes its source's"
    );
    assert_eq!(v[7].direction, Direction::Output);
    assert_eq!(v[8].direction, Direction::Status);
    assert_eq!((v[9].iec_type, v[9].size), (IecType::Ltime, 8));
    let gm = Press::default();
    assert_eq!(
        (gm.Speed, gm.lamp, gm.label.as_str()),
        (-5, true, "a \"b\"")
    );
    assert_eq!(gm.dwell, plc_core::Time::from_millis(1500));
}

#[test]
fn the_golden_struct_exports_the_json_it_came_from() {
    let mut input: serde_json::Value =
        serde_json::from_str(include_str!("../../plc-io/tests/golden/press.json")).unwrap();
    // What the export writes differently: lines of a description joined by a space, and the
    // Rust name of a type that has one (IEC bit-string names stay).
    input["variables"]["Speed"]["description"] = "Line speed in mm/s".into();
    input["variables"]["Speed"]["type"] = "i32".into();
    input["variables"]["lamp"]["type"] = "bool".into();
    let output: serde_json::Value =
        serde_json::from_str(&plc_io::import::export_json::<Press>().unwrap()).unwrap();
    assert_eq!(output["variables"], input["variables"]);
}
