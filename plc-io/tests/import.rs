//! The JSON importer: the emitted code, the atomic write, no panic on any input, and a
//! 10,000-variable file. Its errors and warnings: `import_errors.rs`; the CSV front end:
//! `import_csv.rs`.
#![cfg(feature = "import")]

use plc_io::import::{ImportErrors, Options, generate};
use proptest::prelude::*;
use serde_json::{Value, json};

#[path = "common/json_lists.rs"]
mod json_lists;
use json_lists::{errors, vars};

/// The golden file is also compiled, with `#![deny(missing_docs)]` and clippy, by
/// `examples/tests/imported_golden.rs`: the emitted code passes the derive's checks.
#[test]
fn emitted_code_matches_the_golden_file() {
    let code = golden(
        "press",
        include_str!("golden/press.json"),
        "Press",
        "press.json",
    );
    assert_eq!(code, include_str!("golden/press.rs"));
}

/// A list with structure types (nested, in arrays, with a Rust name other than the type name):
/// the golden file is compiled and exported back by `examples/tests/imported_structures.rs`.
#[test]
fn emitted_structures_match_the_golden_file() {
    let json = include_str!("golden/axes.json");
    let code = golden("axes", json, "Machine", "axes.json");
    assert_eq!(code, include_str!("golden/axes.rs"));
    // Written directly, but as prettyplease prints the whole module (which drops the first,
    // plain comment).
    let file = syn::parse_file(&code).unwrap();
    let (comment, rest) = code.split_once("\n\n").unwrap();
    assert!(comment.starts_with("// Generated"));
    assert_eq!(rest, prettyplease::unparse(&file));
}

/// Imports `golden/<name>.json` (given as `json`) and returns the code; with
/// `GOLDEN_OVERWRITE` set, writes it to `golden/<name>.rs` first.
fn golden(name: &str, json: &str, struct_name: &str, origin: &str) -> String {
    let g = generate(
        json,
        &Options {
            struct_name: struct_name.into(),
            origin: origin.into(),
        },
    )
    .unwrap();
    if std::env::var_os("GOLDEN_OVERWRITE").is_some() {
        let path = format!("{}/tests/golden/{name}.rs", env!("CARGO_MANIFEST_DIR"));
        std::fs::write(path, &g.code).unwrap();
    }
    g.code
}

/// Text rustc refuses in source (bidirectional controls in a description, a file name or a
/// string, other control characters) still gives code that compiles: the hostile golden file
/// is compiled by `examples/tests/imported_golden.rs`, where rustc denies such characters in
/// comments and literals by default.
#[test]
fn control_and_bidi_characters_give_code_that_compiles() {
    let json = include_str!("golden/hostile.json");
    let code = golden("hostile", json, "Hostile", "hostile\u{202e}nosj.json");
    assert_eq!(code, include_str!("golden/hostile.rs"));
    for c in ['\u{202e}', '\u{202c}', '\u{2066}', '\u{2069}', '\u{7}'] {
        assert!(!code.contains(c), "{c:?} written as it is");
    }
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

/// A write that fails half way (here: the file size limit, `RLIMIT_FSIZE`, with `SIGXFSZ`
/// ignored so `write` returns `EFBIG`) leaves the old file as it was and no temporary file.
/// The limit is set in a child process (this test binary, run again) so no other test feels it.
#[test]
fn a_failing_write_keeps_the_old_file_and_leaves_no_temporary_file() {
    let dir = std::env::temp_dir().join(format!("plc-import-atomic-{}", std::process::id()));
    if let Some(role) = std::env::var_os("PLC_ATOMIC_CHILD") {
        let path = std::path::Path::new(&role);
        let limit = libc::rlimit {
            rlim_cur: 4096,
            rlim_max: libc::RLIM_INFINITY,
        };
        // SAFETY: plain system calls on this (child) process's own limits and signal mask.
        unsafe {
            libc::signal(libc::SIGXFSZ, libc::SIG_IGN);
            assert_eq!(libc::setrlimit(libc::RLIMIT_FSIZE, &limit), 0);
        }
        let e = plc_io::import::write_atomically(path, &vec![b'x'; 64 * 1024]).unwrap_err();
        assert_eq!(e.raw_os_error(), Some(libc::EFBIG), "{e}");
        return;
    }
    std::fs::create_dir_all(&dir).unwrap();
    let out = dir.join("gm.rs");
    std::fs::write(&out, "// the old module\n").unwrap();
    use plc_test_support::SpawnGuarded;
    let status = std::process::Command::new(std::env::current_exe().unwrap())
        .args([
            "a_failing_write_keeps_the_old_file_and_leaves_no_temporary_file",
            "--exact",
        ])
        .env("PLC_ATOMIC_CHILD", &out)
        .stdout(std::process::Stdio::null())
        .spawn_guarded()
        .unwrap()
        .wait()
        .unwrap();
    assert!(status.success(), "the child's write did not fail as set up");
    assert_eq!(
        std::fs::read_to_string(&out).unwrap(),
        "// the old module\n"
    );
    let left: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(left, [std::ffi::OsString::from("gm.rs")]);
    // And a write that can succeed replaces the file whole.
    plc_io::import::write_atomically(&out, b"// the new module\n").unwrap();
    assert_eq!(
        std::fs::read_to_string(&out).unwrap(),
        "// the new module\n"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Any JSON value, a few levels deep: what a field can hold in a hostile file.
fn any_json() -> impl Strategy<Value = Value> {
    let leaf = prop_oneof![
        Just(Value::Null),
        any::<bool>().prop_map(Value::Bool),
        any::<i64>().prop_map(Value::from),
        any::<u64>().prop_map(Value::from),
        any::<f64>().prop_map(Value::from),
        (0u64..300).prop_map(Value::from),
        "\\PC{0,12}".prop_map(Value::String),
    ];
    leaf.prop_recursive(2, 8, 3, |inner| {
        prop_oneof![
            prop::collection::vec(inner.clone(), 0..4).prop_map(Value::Array),
            prop::collection::vec(("[a-z_]{1,6}", inner), 0..3)
                .prop_map(|kv| Value::Object(kv.into_iter().collect())),
        ]
    })
}

/// A field value that is usually of the right kind and often valid, sometimes anything.
fn field_value(field: &'static str) -> BoxedStrategy<Value> {
    let names = prop::sample::select(vec!["w", "b", "s", "W", "ton", "x_1", "self"]);
    let likely: BoxedStrategy<Value> = match field {
        "type" => prop::sample::select(vec![
            "bool", "u8", "u16", "i32", "u64", "f32", "LREAL", "WORD", "string", "STRING", "lword",
            "u128", "",
        ])
        .prop_map(Value::from)
        .boxed(),
        "link" => prop::sample::select(vec![
            "ethercat.io.inputs",
            "ethercat.io.outputs",
            "ethercat.io",
            "modbus.x.y",
        ])
        .prop_map(Value::from)
        .boxed(),
        "direction" => prop::sample::select(vec![
            "input", "output", "command", "status", "internal", "in",
        ])
        .prop_map(Value::from)
        .boxed(),
        "source" => names.prop_map(Value::from).boxed(),
        "bit" => (0u64..70).prop_map(Value::from).boxed(),
        "max_length" => (0u64..300).prop_map(Value::from).boxed(),
        "dims" => prop::collection::vec(0u64..400, 0..5)
            .prop_map(|d| json!(d))
            .boxed(),
        "at" => prop::sample::select(vec![
            "%IX0.0", "%QX0.1", "%IB1", "%IW4", "%IW3", "%QD8", "%IL16", "%MW4", "%I0.9", "%IX",
        ])
        .prop_map(Value::from)
        .boxed(),
        "nonvolatile" | "read_only" | "retain" => any::<bool>().prop_map(Value::Bool).boxed(),
        // Any characters, control characters included: they end up in doc comments.
        "description" => prop::collection::vec(any::<char>(), 0..8)
            .prop_map(|c| Value::String(c.into_iter().collect()))
            .boxed(),
        _ => any_json().boxed(),
    };
    prop_oneof![8 => likely, 1 => any_json()].boxed()
}

/// A structurally valid variable list: an object of variables whose fields have random values.
fn variable_list() -> impl Strategy<Value = String> {
    const FIELDS: [&str; 14] = [
        "type",
        "link",
        "description",
        "initial",
        "nonvolatile",
        "max_length",
        "source",
        "bit",
        "direction",
        "read_only",
        "at",
        "dims",
        "retain",
        "colour",
    ];
    let field = prop::sample::select(FIELDS.to_vec())
        .prop_flat_map(|f| field_value(f).prop_map(move |v| (f.to_string(), v)));
    let var =
        prop::collection::vec(field, 0..7).prop_map(|fs| Value::Object(fs.into_iter().collect()));
    let name = prop::sample::select(vec![
        "w", "b", "s", "W", "ton", "x_1", "self", "match", "a__b", "9x", "speed",
    ]);
    prop::collection::vec((name, var), 0..8).prop_map(|vs| {
        let vars: serde_json::Map<String, Value> =
            vs.into_iter().map(|(n, v)| (n.to_string(), v)).collect();
        json!({ "variables": vars }).to_string()
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    /// Well-formed JSON with random field values: always an answer, never a panic, and when the
    /// answer is code, it is code the emitter could format (no "please report this").
    #[test]
    fn no_variable_list_makes_the_importer_panic(json in variable_list()) {
        match generate(&json, &Options::default()) {
            Ok(g) => prop_assert!(g.code.contains("#[derive(GlobalMemory")),
            Err(ImportErrors(e)) => {
                prop_assert!(!e.is_empty());
                prop_assert!(!e.iter().any(|m| m.contains("please report")), "{e:?}");
            }
        }
    }
}

#[test]
fn durations_are_ltime_with_literal_initials_and_time_is_refused_with_the_fix() {
    let g = generate(
        &vars(r#""dwell": { "type": "LTIME", "initial": "T#1m30s" }, "steps": { "type": "ltime", "dims": [2] }"#),
        &Options::default(),
    )
    .unwrap();
    assert!(
        g.code.contains("use plc_core::{GlobalMemory, Time};"),
        "{}",
        g.code
    );
    assert!(g.code.contains("pub dwell: Time,"), "{}", g.code);
    assert!(g.code.contains("pub steps: [Time; 2],"), "{}", g.code);
    assert!(g.code.contains("initial = \"T#1m30s\""), "{}", g.code);
    let e = errors(&vars(
        r#""a": { "type": "LTIME", "initial": "T#1h75m" }, "b": { "type": "LTIME", "initial": 5000 }, "c": { "type": "LTIME", "initial": "T#106752d" }, "d": { "type": "TIME" }"#,
    ));
    assert_eq!(e.len(), 4, "{e:?}");
    assert!(
        e[0].starts_with("variables.a.initial: \"T#1h75m\" is not a duration literal: 75m after a larger unit must be below 60m"),
        "{e:?}"
    );
    assert!(
        e[1].contains("variables.b.initial: 5000 is not a LTIME value: `initial` must be a duration literal in double quotes, such as \"T#5s\""),
        "{e:?}"
    );
    assert!(
        e[2].contains("variables.c.initial: \"T#106752d\" is out of range for LTIME (Time holds LTIME#-106751d23h47m16s854ms775us808ns..=LTIME#106751d23h47m16s854ms775us807ns)"),
        "{e:?}"
    );
    assert!(
        e[3].contains("variables.d.type: unknown type \"TIME\""),
        "{e:?}"
    );
    assert!(
        e[3].contains("a duration is LTIME, 64-bit nanoseconds"),
        "{e:?}"
    );
}
