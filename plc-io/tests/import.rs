//! The JSON importer: one test per error class, every error of a file at once, warnings, the
//! emitted code, no panic on any input, and a 10,000-variable file.
#![cfg(feature = "import")]

use plc_io::import::{ImportErrors, Options, generate};
use proptest::prelude::*;

fn errors(json: &str) -> Vec<String> {
    match generate(json, &Options::default()) {
        Err(ImportErrors(e)) => e,
        Ok(g) => panic!("expected errors, got:\n{}", g.code),
    }
}

fn vars(body: &str) -> String {
    format!("{{ \"variables\": {{ {body} }} }}")
}

#[test]
fn syntax_errors_give_line_and_column() {
    let e = errors("{\n  \"variables\": {\n    \"a\": { \"type\": \"u8\" },,\n  }\n}");
    assert_eq!(e.len(), 1);
    assert!(e[0].starts_with("JSON error at line 3, column"), "{e:?}");
    assert!(errors("{}")[0].contains("no \"variables\" object"));
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

#[test]
fn the_seed_example_message_for_a_bit_out_of_range() {
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

/// The golden file is also compiled, with `#![deny(missing_docs)]` and clippy, by
/// `examples/tests/imported_golden.rs`: the emitted code passes the derive's checks.
#[test]
fn emitted_code_matches_the_golden_file() {
    let g = generate(
        include_str!("golden/press.json"),
        &Options {
            struct_name: "Press".into(),
            origin: "press.json".into(),
        },
    )
    .unwrap();
    if std::env::var_os("GOLDEN_OVERWRITE").is_some() {
        std::fs::write(
            concat!(env!("CARGO_MANIFEST_DIR"), "/tests/golden/press.rs"),
            &g.code,
        )
        .unwrap();
    }
    assert_eq!(g.code, include_str!("golden/press.rs"));
}

#[test]
fn a_ten_thousand_variable_file_imports() {
    let mut body = Vec::new();
    for i in 0..10_000 {
        body.push(match i % 4 {
            0 => format!("\"w{i}\": {{ \"type\": \"u16\", \"link\": \"ethercat.io{i}.inputs\" }}"),
            1 => format!("\"b{i}\": {{ \"type\": \"bool\", \"source\": \"w{}\", \"bit\": 3 }}", i - 1),
            2 => format!("\"s{i}\": {{ \"type\": \"string\", \"max_length\": 32, \"description\": \"text {i}\" }}"),
            _ => format!("\"r{i}\": {{ \"type\": \"f64\", \"nonvolatile\": true, \"initial\": 1.5 }}"),
        });
    }
    let json = vars(&body.join(",\n"));
    let start = std::time::Instant::now();
    let g = generate(&json, &Options::default()).unwrap();
    println!(
        "10,000 variables imported in {:?} (debug build)",
        start.elapsed()
    );
    assert_eq!(g.code.matches("pub ").count(), 10_001);
}

proptest! {
    #[test]
    fn no_input_makes_the_importer_panic(text in "\\PC{0,200}") {
        let _ = generate(&text, &Options::default());
    }

    #[test]
    fn no_variable_object_makes_it_panic(
        key in "[a-z_]{1,12}",
        field in prop::sample::select(vec!["type", "initial", "bit", "source", "dims", "at", "max_length", "link"]),
        value in prop_oneof![
            Just("null".to_string()), Just("-1".to_string()), Just("1e400".to_string()),
            Just("[]".to_string()), Just("{}".to_string()), "\"[^\"\\\\]{0,20}\"".prop_map(|s| s),
            any::<i64>().prop_map(|n| n.to_string()),
        ],
    ) {
        let json = vars(&format!("\"{key}\": {{ \"type\": \"u16\", \"{field}\": {value} }}"));
        let _ = generate(&json, &Options::default());
    }
}
