//! `project.json` -> Rust (build.rs) -> compiled -> `VARIABLES` -> JSON equals the input;
//! `project.csv` likewise as CSV; and the JSON and CSV forms of one declaration are equivalent.

use examples::project::{Gm, from_csv};
use plc_core::GlobalMemory;
use plc_io::import::{Options, export_csv, generate, generate_csv};
use serde_json::Value;
use std::collections::BTreeMap;

/// The input with the defaults the export writes out (string capacity 64) filled in.
fn normalised(mut v: Value) -> Value {
    for (_, var) in v["variables"].as_object_mut().unwrap().iter_mut() {
        let o = var.as_object_mut().unwrap();
        if o["type"] == "string" && !o.contains_key("max_length") {
            o.insert("max_length".into(), 64.into());
        }
    }
    serde_json::json!({ "variables": v["variables"] })
}

#[test]
fn json_to_rust_to_json_is_the_identity() {
    let input: Value = serde_json::from_str(include_str!("../project.json")).unwrap();
    let output: Value =
        serde_json::from_str(&plc_io::import::export_json::<Gm>().unwrap()).unwrap();
    assert_eq!(output, normalised(input));
}

#[test]
fn the_generated_struct_works() {
    let mut gm = Gm::default();
    assert_eq!(
        (gm.press_home_offset_mm, gm.speed_setpoint, gm.mode_word),
        (12.5, 5.0, 3)
    );
    gm.impact67_0_digital_inputs = 0b100;
    gm.unpack_bits();
    assert!(gm.ls_lift_neg);
    assert_eq!(Gm::VARIABLES.len(), 18);
    assert_eq!(Gm::VARIABLES[15].iec_type, plc_core::IecType::Word);
    let var = |name: &str| Gm::VARIABLES.iter().find(|v| v.name == name).unwrap();
    assert_eq!(
        (var("force_kn").unit, var("force_kn").deadband),
        (Some("kN"), Some(0.05))
    );
    assert_eq!(
        (var("speed_setpoint").unit, var("speed_setpoint").deadband),
        (Some("mm/min"), None)
    );
}

/// The rows of a CSV table, each as column -> cell, with what the export writes differently
/// filled in: string capacity 64 where none is given, a description's lines joined by a
/// space as the derive joins a doc comment's, and the columns a table leaves out as empty
/// cells (a spreadsheet made before the `ux` and `quantity` columns, with rows that end before
/// the `unit` and `deadband` cells, as the importer allows).
fn csv_rows(text: &str) -> Vec<BTreeMap<String, String>> {
    let mut r = csv::ReaderBuilder::new()
        .flexible(true)
        .from_reader(text.as_bytes());
    let header: Vec<String> = r.headers().unwrap().iter().map(String::from).collect();
    r.records()
        .map(|rec| {
            let mut row: BTreeMap<String, String> = header
                .iter()
                .cloned()
                .zip(rec.unwrap().iter().map(String::from))
                .collect();
            for col in plc_io::import::COLUMNS {
                row.entry(col.to_string()).or_default();
            }
            if row["type"] == "string" && row["max_length"].is_empty() {
                row.insert("max_length".into(), "64".into());
            }
            let d = row["description"]
                .lines()
                .map(str::trim)
                .filter(|l| !l.is_empty())
                .collect::<Vec<_>>()
                .join(" ");
            row.insert("description".into(), d);
            row
        })
        .collect()
}

#[test]
fn csv_to_rust_to_csv_is_the_identity() {
    let input = include_str!("../project.csv");
    let output = export_csv::<from_csv::Gm>().unwrap();
    assert_eq!(csv_rows(&output), csv_rows(input));
    // Quoted cells came through as data: a comma and doubled quotes in a description, a line
    // break in a string's initial value.
    let gm = from_csv::Gm::default();
    assert_eq!(
        gm.operator_message.as_str(),
        "Close the door,\r\nthen press \"Start\""
    );
    assert_eq!(
        from_csv::Gm::VARIABLES[0].description,
        "Door switches, left and right"
    );
    assert!(
        gm.lamp_green && gm.lamp_outputs == 1,
        "a bool's initial is packed"
    );
}

/// `project.json` exported as CSV imports to the struct `project.json` itself imports to.
#[test]
fn json_and_csv_declare_the_same_struct() {
    let o = Options {
        origin: "project.json".into(),
        ..Options::default()
    };
    let from_json = generate(include_str!("../project.json"), &o).unwrap();
    let from_csv = generate_csv(&export_csv::<Gm>().unwrap(), &o).unwrap();
    assert_eq!(from_csv.code, from_json.code);
}
