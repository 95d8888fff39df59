//! The importer's golden module with structure types (`plc-io/tests/golden/axes.rs`, pinned by
//! plc-io's import test) compiled as a user's crate compiles it: it passes the derive's checks
//! (PlcStruct types nested and in arrays, a type name other than its Rust name),
//! `#![deny(missing_docs)]` and clippy; and its export imports back to the same structs, as JSON
//! and as CSV.
#![deny(missing_docs)]
#![deny(non_snake_case)]

include!("../../plc-io/tests/golden/axes.rs");

use plc_io::import::{Options, export_csv, export_json, generate, generate_csv};
use serde_json::Value;

fn options() -> Options {
    Options {
        struct_name: "Machine".into(),
        origin: "axes.json".into(),
    }
}

#[test]
fn the_golden_structs_declare_what_the_json_says() {
    let v = Machine::VARIABLES;
    let names: Vec<&str> = v.iter().map(|x| x.name).collect();
    assert_eq!(
        names,
        [
            "speed",
            "lift",
            "axes",
            "grid",
            "station",
            "start_delay",
            "step_timeouts",
            "parts"
        ]
    );
    assert_eq!(v[1].type_name(), "axis_t");
    assert_eq!(v[2].dims, [3]);
    assert_eq!(v[3].dims, [2, 3]);
    let members: Vec<&str> = v[1].members().iter().map(|m| m.name).collect();
    assert_eq!(
        members,
        ["pos", "target", "label", "drive", "cycles", "history"]
    );
    assert_eq!(v[1].members()[3].type_name(), "Drive");
    let gm = Machine::default();
    assert_eq!(gm.axes[2].target, 250.0);
    assert_eq!(gm.station.axes[1].label.as_str(), "axis");
    assert_eq!(gm.lift.cycles, 7);
    assert!(Machine::find("station.axes[1].drive.speed").is_some());
    assert!(Machine::find("grid[1,2].ready").is_some());
    // The standard function blocks, by their IEC names, in a structure and at the top level.
    assert_eq!(v[5].type_name(), "TON");
    assert_eq!(v[6].dims, [2]);
    assert_eq!(v[4].members()[2].type_name(), "R_TRIG");
    assert!(Machine::find("start_delay.ET").is_some());
    assert!(Machine::find("step_timeouts[1].Q").is_some());
    assert!(Machine::find("parts.PV").is_some());
    assert!(Machine::find("station.part_sensor.CLK").is_some());
}

#[test]
fn the_json_export_imports_back_to_the_same_structs() {
    let exported = export_json::<Machine>().unwrap();
    let output: Value = serde_json::from_str(&exported).unwrap();
    let mut input: Value =
        serde_json::from_str(include_str!("../../plc-io/tests/golden/axes.json")).unwrap();
    // What the export writes differently: no type descriptions (the descriptor has none), the
    // Rust name of a type that has one.
    for ty in input["types"].as_object_mut().unwrap().values_mut() {
        ty.as_object_mut().unwrap().remove("description");
    }
    input["types"]["Station"]["variables"]["count"]["type"] = "i32".into();
    assert_eq!(output["types"], input["types"]);
    assert_eq!(output["variables"], input["variables"]);
    // Imported again, the same module (but for the type descriptions it did not keep), and
    // a fixed point from there on.
    let again = generate(&exported, &options()).unwrap().code;
    let golden = include_str!("../../plc-io/tests/golden/axes.rs")
        .replace(
            "/// A drive's command and feedback",
            "/// The structure Drive.",
        )
        .replace("/// Two axes and a counter", "/// The structure Station.");
    assert_eq!(again, golden);
}

#[test]
fn the_csv_export_imports_back_to_the_same_structs() {
    let csv = export_csv::<Machine>().unwrap();
    assert!(csv.contains("\r\naxis_t,STRUCT,"), "{csv}");
    assert!(csv.contains("\r\naxis_t.drive,Drive,"), "{csv}");
    let from_csv = generate_csv(&csv, &options()).unwrap().code;
    let from_json = generate(&export_json::<Machine>().unwrap(), &options())
        .unwrap()
        .code;
    assert_eq!(from_csv, from_json);
}
