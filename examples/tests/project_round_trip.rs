//! `project.json` -> Rust (build.rs) -> compiled -> `VARIABLES` -> JSON equals the input.

use examples::project::Gm;
use plc_core::GlobalMemory;
use serde_json::Value;

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
    let output: Value = serde_json::from_str(&plc_io::import::export_json::<Gm>()).unwrap();
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
}
