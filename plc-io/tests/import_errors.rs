//! The JSON importer's errors: one test per error class, each naming the variable and field,
//! every error of a file at once, and warnings.
#![cfg(feature = "import")]

#[path = "common/json_lists.rs"]
mod json_lists;

use json_lists::{errors, vars};
use plc_io::import::{ImportErrors, Options, generate};

#[test]
fn syntax_errors_give_line_and_column() {
    let e = errors("{\n  \"variables\": {\n    \"a\": { \"type\": \"u8\" },,\n  }\n}");
    assert_eq!(e.len(), 1);
    assert!(e[0].starts_with("JSON error at line 3, column"), "{e:?}");
    // A fresh project's file has no variables: an empty struct, with a note.
    let g = generate("{ \"control\": {} }", &Options::default()).unwrap();
    assert!(g.code.contains("pub struct Gm {}"), "{}", g.code);
    assert!(
        g.warnings[0].contains("no \"variables\" object"),
        "{:?}",
        g.warnings
    );
}

#[test]
fn each_error_class_names_the_variable_and_field() {
    let cases = [
        (
            r#""a": { "type": "u8" }, "A": { "type": "u8" }"#,
            "variables.A: declared twice",
        ),
        (
            r#""ton": { "type": "bool" }"#,
            "variables.ton: invalid variable name",
        ),
        (
            r#""a__b": { "type": "bool" }"#,
            "two consecutive underscores",
        ),
        (
            r#""a": { "type": "u128" }"#,
            "variables.a.type: unknown type",
        ),
        (r#""a": { }"#, "variables.a.type: missing"),
        (
            r#""a": { "type": "u8", "colour": "red" }"#,
            "variables.a.colour: unknown field",
        ),
        (
            r#""a": { "type": "string", "max_length": 256 }"#,
            "variables.a.max_length: 256 is not a capacity",
        ),
        (
            r#""a": { "type": "u8", "max_length": 4 }"#,
            "only strings have a max_length",
        ),
        (
            r#""a": { "type": "u8", "dims": [2, 2, 2, 2] }"#,
            "1 to 3 dimensions",
        ),
        (
            r#""a": { "type": "u8", "dims": [300, 300] }"#,
            "at most 65535 items",
        ),
        (
            r#""a": { "type": "u8", "link": "ethercat.io" }"#,
            "variables.a.link: invalid link",
        ),
        (
            r#""a": { "type": "u8", "direction": "in" }"#,
            "variables.a.direction: unknown direction",
        ),
        (
            r#""a": { "type": "i16", "at": "%IX3.8" }"#,
            "bit 8 out of range",
        ),
        (r#""a": { "type": "i16", "at": "%MW4" }"#, "M area"),
        (
            r#""a": { "type": "f32", "at": "%IW4" }"#,
            "is 16 bits but a REAL has 32",
        ),
        (r#""a": { "type": "i16", "at": "%IW3" }"#, "not aligned"),
        (
            r#""a": { "type": "i16", "at": "%IW4", "direction": "output" }"#,
            "contradicts `at`",
        ),
        (
            r#""a": { "type": "i16", "at": "%IW4" }, "b": { "type": "u8", "at": "%IB5" }"#,
            "variables.b.at: %IB5 overlaps",
        ),
        (
            r#""a": { "type": "u8", "initial": 256 }"#,
            "variables.a.initial: 256 is out of range for USINT",
        ),
        (
            r#""a": { "type": "u8", "initial": 1.5 }"#,
            "not a whole number",
        ),
        (
            r#""a": { "type": "bool", "initial": 1 }"#,
            "is not a BOOL value",
        ),
        (
            r#""a": { "type": "string", "max_length": 2, "initial": "abc" }"#,
            "3 bytes do not fit max_length 2",
        ),
        (
            r#""w": { "type": "u16" }, "b": { "type": "bool", "source": "w" }"#,
            "variables.b.source: needs `bit`",
        ),
        (
            r#""w": { "type": "u16" }, "b": { "type": "bool", "bit": 1 }"#,
            "variables.b.bit: needs `source`",
        ),
        (
            r#""b": { "type": "bool", "source": "nope", "bit": 1 }"#,
            "\"nope\" names no variable",
        ),
        (
            r#""b": { "type": "bool", "source": "b", "bit": 1 }"#,
            "cannot be its own source",
        ),
        (
            r#""f": { "type": "f32" }, "b": { "type": "bool", "source": "f", "bit": 1 }"#,
            "a source must be an integer",
        ),
        (
            r#""w": { "type": "u16" }, "b": { "type": "u8", "source": "w", "bit": 1 }"#,
            "must be bool",
        ),
        (
            r#""w": { "type": "u16" }, "b": { "type": "bool", "source": "w", "bit": 1 }, "c": { "type": "bool", "source": "w", "bit": 1 }"#,
            "already mapped to \"b\"",
        ),
        (r#""self": { "type": "u8" }"#, "cannot be a Rust field"),
    ];
    for (body, expected) in cases {
        let e = errors(&vars(body));
        assert!(
            e.iter().any(|m| m.contains(expected)),
            "{body}\nexpected `{expected}` in {e:#?}"
        );
    }
}

/// Each class whose message must start with the variable and the field it is about.
#[test]
fn each_error_class_starts_with_the_variable_and_field() {
    let cases = [
        (r#""a": 5"#, "variables.a: expected an object such as"),
        (r#""a": [1]"#, "variables.a: expected an object such as"),
        (
            r#""a": { "type": 5 }"#,
            "variables.a.type: expected a string, found 5",
        ),
        (
            r#""a": { "type": "u8", "link": true }"#,
            "variables.a.link: expected a string, found true",
        ),
        (
            r#""a": { "type": "u8", "description": ["x"] }"#,
            "variables.a.description: expected a string, found [\"x\"]",
        ),
        (
            r#""a": { "type": "u8", "direction": 1 }"#,
            "variables.a.direction: expected a string, found 1",
        ),
        (
            r#""a": { "type": "u8", "at": null }"#,
            "variables.a.at: expected a string, found null",
        ),
        (
            r#""a": { "type": "u8", "nonvolatile": "yes" }"#,
            "variables.a.nonvolatile: expected true or false, found \"yes\"",
        ),
        (
            r#""a": { "type": "u8", "read_only": 1 }"#,
            "variables.a.read_only: expected true or false, found 1",
        ),
        (
            r#""a": { "type": "u8", "retain": "true" }"#,
            "variables.a.retain: expected true or false, found \"true\"",
        ),
        (
            r#""a": { "type": "u8", "dims": [0, 2] }"#,
            "variables.a.dims: an array needs at least one item in each dimension",
        ),
        (
            r#""a": { "type": "u8", "dims": [1.5] }"#,
            "variables.a.dims: [1.5] is not a list of whole numbers",
        ),
        (
            r#""a": { "type": "u8", "dims": [-2] }"#,
            "variables.a.dims: [-2] is not a list of whole numbers",
        ),
        (
            r#""a": { "type": "u8", "dims": 3 }"#,
            "variables.a.dims: expected a list such as [3, 4], found 3",
        ),
        (
            r#""a": { "type": "u8", "dims": "3x4" }"#,
            "variables.a.dims: expected a list such as [3, 4], found \"3x4\"",
        ),
        (
            r#""a": { "type": "u8", "dims": [] }"#,
            "variables.a.dims: 0 dimensions given: an array has 1 to 3",
        ),
        (
            r#""a": { "type": "u8", "dims": [2, 2, 2, 2] }"#,
            "variables.a.dims: 4 dimensions given: an array has 1 to 3",
        ),
        (
            r#""w": { "type": "u64" }, "b": { "type": "bool", "source": "w", "bit": 64 }"#,
            "variables.b.bit: 64 is not a bit number 0..=63",
        ),
        (
            r#""w": { "type": "u64" }, "b": { "type": "bool", "source": "w", "bit": "3" }"#,
            "variables.b.bit: \"3\" is not a bit number 0..=63",
        ),
        (
            r#""w": { "type": "u64" }, "b": { "type": "bool", "source": "w", "bit": -1 }"#,
            "variables.b.bit: -1 is not a bit number 0..=63",
        ),
        (
            r#""b": { "type": "bool", "source": 7, "bit": 1 }"#,
            "variables.b.source: expected a variable name, found 7",
        ),
        (
            r#""a": { "type": "f32", "initial": 1e39 }"#,
            "variables.a.initial: 1e+39 is out of range for REAL",
        ),
        (
            r#""a": { "type": "REAL", "initial": -3.5e38 }"#,
            "variables.a.initial: -3.5e+38 is out of range for REAL",
        ),
        (
            r#""a": { "type": "string", "at": "%IB4" }"#,
            "variables.a.at: a STRING cannot be located",
        ),
        (
            r#""a": { "type": "u8", "dims": [4], "at": "%IB4" }"#,
            "variables.a.at: an array cannot be located",
        ),
        (
            r#""w": { "type": "u16", "direction": "input" }, "b": { "type": "bool", "source": "w", "bit": 0, "direction": "output" }"#,
            "variables.b.direction: \"output\" contradicts the source \"w\", which is input",
        ),
    ];
    for (body, expected) in cases {
        let e = errors(&vars(body));
        assert!(
            e.iter().any(|m| m.starts_with(expected)),
            "{body}\nexpected a message starting `{expected}` in {e:#?}"
        );
    }
}

#[test]
fn a_struct_name_that_is_no_identifier_is_refused() {
    for bad in ["1Gm", "my struct", "", "Gm-2"] {
        assert_struct_name_refused(bad, "is not a Rust identifier");
    }
}

/// Importing a list as struct `name` fails with one error that starts `struct name "<name>"
/// <says>`.
fn assert_struct_name_refused(name: &str, says: &str) {
    let e = match generate(
        &vars(r#""a": { "type": "string" }"#),
        &Options {
            struct_name: name.into(),
            ..Options::default()
        },
    ) {
        Err(ImportErrors(e)) => e,
        Ok(_) => panic!("{name:?} was accepted"),
    };
    assert_eq!(e.len(), 1, "{e:?}");
    assert!(
        e[0].starts_with(&format!("struct name {name:?} {says}")),
        "{e:?}"
    );
}

/// The derive's rule (plc-derive `check.rs`): a bit-mapped bool takes its source's direction,
/// which is the source's own, or implied by its `at`, or internal; an explicit one must agree.
#[test]
fn a_mapped_bool_must_agree_with_its_sources_direction() {
    let e = errors(&vars(
        r#""w": { "type": "u16", "at": "%IW0" },
           "b": { "type": "bool", "source": "w", "bit": 0, "direction": "command" }"#,
    ));
    assert_eq!(
        e,
        [
            "variables.b.direction: \"command\" contradicts the source \"w\", which is input: a bit-mapped bool takes its source's direction; remove `direction`"
        ]
    );
    let e = errors(&vars(
        r#""w": { "type": "u16" }, "b": { "type": "bool", "source": "w", "bit": 0, "direction": "input" }"#,
    ));
    assert_eq!(e.len(), 1);
    assert!(e[0].contains("which is internal"), "{e:?}");
    // Agreeing with the source is fine, as is saying nothing.
    let ok = vars(
        r#""w": { "type": "u16", "direction": "output" },
           "b": { "type": "bool", "source": "w", "bit": 0, "direction": "output" },
           "c": { "type": "bool", "source": "w", "bit": 1 }"#,
    );
    generate(&ok, &Options::default()).unwrap();
}

/// A missing or unknown type does not stop the other checks of that variable, and a bool mapped
/// onto it is not told that its source "names no variable".
#[test]
fn a_variable_without_a_usable_type_still_gets_every_other_error() {
    let e = errors(&vars(
        r#""w": { "type": "u17", "link": "io" },
           "b": { "type": "bool", "source": "w", "bit": 1 },
           "n": { "initial": 300, "nonvolatile": "yes", "direction": "in" },
           "m": { "type": "bool", "source": "n", "bit": 99 }"#,
    ));
    let fields: Vec<&str> = e.iter().map(|m| m.split(':').next().unwrap()).collect();
    assert_eq!(
        fields,
        [
            "variables.w.type",
            "variables.w.link",
            "variables.n.type",
            "variables.n.direction",
            "variables.n.nonvolatile",
            "variables.m.bit",
        ],
        "{e:#?}"
    );
    assert!(!e.iter().any(|m| m.contains("names no variable")), "{e:#?}");
    // Not an object: still declared, so no "names no variable" either.
    let e = errors(&vars(
        r#""w": 16, "b": { "type": "bool", "source": "w", "bit": 1 }"#,
    ));
    assert_eq!(e.len(), 1, "{e:#?}");
    assert!(e[0].starts_with("variables.w: expected an object"));
}

#[test]
fn the_format_example_message_for_a_bit_out_of_range() {
    let e = errors(&vars(
        r#""impact67_0_digital_inputs": { "type": "u16" },
           "ls_lift_neg": { "type": "bool", "source": "impact67_0_digital_inputs", "bit": 16 }"#,
    ));
    assert_eq!(
        e,
        [
            "variables.ls_lift_neg.bit: 16 is out of range for source \"impact67_0_digital_inputs\" (u16 has bits 0..=15)"
        ]
    );
}

#[test]
fn every_error_of_a_file_is_listed_at_once() {
    let e = errors(&vars(
        r#""a": { "type": "u8", "initial": 300 }, "ton": { "type": "bool" }, "c": { "type": "x" }"#,
    ));
    assert_eq!(e.len(), 3, "{e:#?}");
}

#[test]
fn two_variables_on_one_link_are_a_warning() {
    let g = generate(
        &vars(r#""a": { "type": "u8", "link": "ethercat.io.x" }, "b": { "type": "u8", "link": "ethercat.io.x" }"#),
        &Options::default(),
    )
    .unwrap();
    assert_eq!(g.warnings.len(), 1);
    assert!(g.warnings[0].starts_with("variables.b.link:"));
}

/// The struct name must give code that compiles: not a keyword, not a name the generated
/// module imports or defines.
#[test]
fn a_struct_name_the_module_cannot_use_is_refused() {
    for bad in [
        "fn",
        "Self",
        "_",
        "self",
        "type",
        "FixedString",
        "GlobalMemory",
    ] {
        assert_struct_name_refused(bad, "is a Rust keyword or a name the generated module uses");
    }
}
