//! Files in the shape the framework the JSON variable-list format comes from writes them (its
//! project template, tag lists with units, motion-axis links, its CSV export): each imports as
//! it is. The generated code is compiled and exported back by
//! `examples/tests/imported_framework.rs`.

use plc_io::import::{Options, generate, generate_csv};

fn options() -> Options {
    Options {
        struct_name: "Station".into(),
        origin: "project.json".into(),
    }
}

/// The project file imports with its `ux`, `quantity`, four-part links and `"initial": null`;
/// its other sections are not ours and are left alone. Its generated code is the golden file.
#[test]
fn a_project_file_of_the_framework_imports_as_it_is() {
    let g = generate(include_str!("framework/project.json"), &options()).unwrap();
    if std::env::var_os("GOLDEN_OVERWRITE").is_some() {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/golden/framework.rs");
        std::fs::write(path, &g.code).unwrap();
    }
    assert_eq!(g.code, include_str!("golden/framework.rs"));
    for key in [
        "ux",
        "quantity = \"force\"",
        "link = \"ethercat.motion.x.actual_velocity\"",
    ] {
        assert!(g.code.contains(key), "{key} missing:\n{}", g.code);
    }
    // `"initial": null` is no initial value.
    assert!(!g.code.contains("initial = null"));
    // Two links that differ only in case are one link: the shared-link warning says so.
    assert_eq!(g.warnings.len(), 1, "{:?}", g.warnings);
    assert!(
        g.warnings[0].starts_with("variables.rc8_status_copy.link: \"ethercat.rc8_0.statusword\" is also linked by \"rc8_statusword\""),
        "{:?}",
        g.warnings
    );
}

/// The framework's CSV export writes string initials as JSON text (`"abc"`, quotes included):
/// read as the text, so the CSV gives the code the project file gives.
#[test]
fn the_frameworks_csv_export_gives_the_code_of_its_project_file() {
    let csv = generate_csv(include_str!("framework/export.csv"), &options()).unwrap();
    let json = generate(include_str!("framework/project.json"), &options()).unwrap();
    assert_eq!(csv.code, json.code);
    assert!(csv.code.contains("initial = \"abc\""), "{}", csv.code);
}

/// Plain text in a CSV initial stays plain text, quotes inside included.
#[test]
fn plain_csv_initials_stay_text() {
    let csv = "name,type,initial\r\na,string,abc\r\nb,string,\"say \"\"hi\"\"\"\r\nc,string,\"\"\"x\"\r\n";
    let g = generate_csv(csv, &Options::default()).unwrap();
    assert!(g.code.contains("initial = \"abc\""), "{}", g.code);
    assert!(
        g.code.contains("initial = \"say \\\"hi\\\"\""),
        "{}",
        g.code
    );
    assert!(g.code.contains("initial = \"\\\"x\""), "{}", g.code);
}

/// A fresh project's file has no `variables` yet: an empty struct, and a note saying so.
#[test]
fn a_fresh_project_without_variables_gives_an_empty_struct() {
    let g = generate(include_str!("framework/fresh.json"), &options()).unwrap();
    assert!(g.code.contains("pub struct Station {}"), "{}", g.code);
    assert_eq!(g.warnings.len(), 1);
    assert!(g.warnings[0].contains("no \"variables\" object"));
}

/// An unknown field inside a variable is still an error that names it and lists the known ones.
#[test]
fn an_unknown_field_of_a_variable_is_still_an_error() {
    let e = generate(
        r#"{ "variables": { "a": { "type": "u8", "colour": "red" } } }"#,
        &Options::default(),
    )
    .unwrap_err();
    assert_eq!(e.0.len(), 1, "{e:?}");
    assert!(
        e.0[0].starts_with(
            "variables.a.colour: unknown field: use one of type, max_length, dims, link"
        ),
        "{e:?}"
    );
    assert!(e.0[0].contains("ux, quantity"), "{e:?}");
}

/// A tag list with engineering units and reporting deadbands beside the quantity: each
/// becomes its key of `#[plc(...)]`; on a structure as a whole they are refused.
#[test]
fn units_and_deadbands_import_beside_the_quantity() {
    let g = generate(
        r#"{ "variables": {
            "load_cell_force": { "type": "f64", "quantity": "force", "unit": "kN", "deadband": 0.05 },
            "x_position": { "type": "i32", "link": "ethercat.motion.x.position", "quantity": "length", "unit": "µm" }
        } }"#,
        &options(),
    )
    .unwrap();
    assert!(
        g.code
            .contains("#[plc(quantity = \"force\", unit = \"kN\", deadband = 0.05"),
        "{}",
        g.code
    );
    assert!(g.code.contains("unit = \"µm\""), "{}", g.code);
    let e = generate(
        r#"{ "types": { "Axis": { "variables": { "pos": { "type": "f64", "unit": "mm" } } } },
            "variables": { "x": { "type": "Axis", "unit": "mm", "deadband": 0.5 } } }"#,
        &options(),
    )
    .unwrap_err();
    assert_eq!(
        e.0,
        [
            "variables.x.unit: \"x\" is a structure: `unit` is for numbers; declare it on the \
             structure's members",
            "variables.x.deadband: \"x\" is a structure: `deadband` is for numbers; declare it \
             on the structure's members",
        ]
    );
}
