//! The code `plc import` makes of a project file in the framework's own shape
//! (`plc-io/tests/golden/framework.rs`, pinned by plc-io's `import_framework` test), compiled
//! as a user's crate compiles it: `ux` and `quantity` reach `VARIABLES`, four-part links are
//! accepted by the derive, and the export gives back the fields of the file.
#![deny(missing_docs)]

include!("../../plc-io/tests/golden/framework.rs");

#[test]
fn ux_and_quantity_reach_the_metadata() {
    let v = |name| &Station::VARIABLES[Station::index_of(name).unwrap()];
    assert!(v("cmd_start").ux);
    assert!(!v("x_position").ux);
    assert_eq!(v("load_cell_force").quantity, Some("force"));
    assert_eq!(v("cmd_start").quantity, None);
    assert_eq!(
        v("x_actual_velocity").link,
        Some("ethercat.motion.x.actual_velocity")
    );
}

#[test]
fn the_export_gives_back_the_variables_of_the_project_file() {
    let input: serde_json::Value =
        serde_json::from_str(include_str!("../../plc-io/tests/framework/project.json")).unwrap();
    let mut expected = input["variables"].clone();
    for (_, var) in expected.as_object_mut().unwrap() {
        let var = var.as_object_mut().unwrap();
        // `"initial": null` is no initial value, so the export leaves it out.
        if var.get("initial").is_some_and(serde_json::Value::is_null) {
            var.remove("initial");
        }
    }
    let output: serde_json::Value =
        serde_json::from_str(&plc_io::import::export_json::<Station>().unwrap()).unwrap();
    assert_eq!(output["variables"], expected);
}
